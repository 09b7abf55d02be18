"""A person's view of the built book: headless Chromium opens pages with no network,
MathJax (served from the build) typesets every formula, the pictures are there, and a
screenshot is saved to <build>/_screenshots/ for a human to look at.

Skipped when no Chromium is installed, except under CI=true, where it fails instead
(.ci/run installs Debian's chromium).
"""

from __future__ import annotations

import os
import shutil
import subprocess
from html.parser import HTMLParser
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

# libration.html is the richest chapter (equations, figures, a proof, the period table).
PAGES = ["libration.html"]
BROWSERS = ["chromium", "chromium-browser", "google-chrome", "google-chrome-stable"]


@pytest.fixture(scope="module")
def chromium() -> str:
    for name in BROWSERS:
        path = shutil.which(name)
        if path:
            return path
    message = "no Chromium found (apt-get install chromium)"
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail(message + "; CI must run the browser check", pytrace=False)
    pytest.skip(message)


def run_chromium(binary: str, profile: Path, *args: str) -> str:
    cmd = [
        binary,
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-dev-shm-usage",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--no-first-run",
        "--hide-scrollbars",
        f"--user-data-dir={profile}",
        "--virtual-time-budget=10000",
        *args,
    ]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=180)
    assert proc.returncode == 0, proc.stderr[-4000:]
    return proc.stdout


class _Text(HTMLParser):
    """Visible prose (no code, scripts or styles), math elements, and image sources."""

    SKIP = {"script", "style", "pre", "code", "textarea", "mjx-assistive-mml", "noscript"}

    def __init__(self) -> None:
        super().__init__()
        self.depth = 0
        self.text: list[str] = []
        self.tags: dict[str, int] = {}
        self.math_spans = 0
        self.images: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags[tag] = self.tags.get(tag, 0) + 1
        attributes = dict(attrs)
        if "math" in (attributes.get("class") or "").split():
            self.math_spans += 1
        if tag == "img" and attributes.get("src"):
            self.images.append(attributes["src"] or "")
        if tag in self.SKIP:
            self.depth += 1

    def handle_endtag(self, tag: str) -> None:
        if tag in self.SKIP and self.depth:
            self.depth -= 1

    def handle_data(self, data: str) -> None:
        if not self.depth:
            self.text.append(data)


def parse(html: str) -> _Text:
    parser = _Text()
    parser.feed(html)
    return parser


@pytest.mark.parametrize("page", PAGES)
def test_page_renders_math_and_images(
    page: str, built_book: Path, chromium: str, tmp_path: Path
) -> None:
    path = built_book / page
    assert path.is_file(), f"{page} was not built"
    static = parse(path.read_text(encoding="utf-8"))

    dom = parse(run_chromium(chromium, tmp_path / "profile", "--dump-dom", path.as_uri()))
    text = "".join(dom.text)
    for raw in ["\\(", "\\[", "$$"]:
        assert raw not in text, f"untypeset TeX {raw!r} left in {page}"
    typeset = dom.tags.get("mjx-container", 0)
    assert typeset >= static.math_spans, (
        f"MathJax typeset {typeset} of {static.math_spans} formulas"
    )

    for src in static.images:
        if not src.startswith("data:"):
            image = (path.parent / src.split("?")[0]).resolve()
            assert image.is_file() and image.stat().st_size > 0, f"missing image {src}"

    shots = built_book / "_screenshots"
    shots.mkdir(exist_ok=True)
    shot = shots / page.replace(".html", ".png")
    run_chromium(
        chromium,
        tmp_path / "profile",
        f"--screenshot={shot}",
        "--window-size=1200,2000",
        path.as_uri(),
    )
    assert shot.is_file() and shot.stat().st_size > 10_000
    print(f"\nscreenshot: {shot}")
