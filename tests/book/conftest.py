"""The book and docs tier: builds, notebooks in a fresh venv, the browser, the PDF.

Every test in this folder is marked ``slow`` (``make test-fast`` leaves them out, ``make
test`` runs them), whatever its own marks: the folder is the tier.
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path
from typing import NoReturn

import pytest

_HERE = Path(__file__).resolve().parent
ROOT = _HERE.parents[1]


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    for item in items:
        if _HERE in Path(str(item.path)).resolve().parents:
            item.add_marker(pytest.mark.slow)


def unavailable(message: str, remedy: str) -> NoReturn:
    """Skip a test that lacks a tool of the machine, except under CI=true, where it fails:
    .ci/run installs the tool, so a CI run that misses it is broken, not incomplete."""
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail(f"{message}; {remedy}", pytrace=False)
    pytest.skip(message)


BROWSERS = ["chromium", "chromium-browser", "google-chrome", "google-chrome-stable"]


@pytest.fixture(scope="session")
def chromium() -> str:
    """The headless browser of test_browser and test_site (Debian's chromium)."""
    for name in BROWSERS:
        path = shutil.which(name)
        if path:
            return path
    unavailable("no Chromium found (apt-get install chromium)", "CI must run the browser check")


@pytest.fixture(scope="session")
def axe_script() -> str:
    """The source of axe-core's axe.min.js, which test_browser injects into every page.

    The version is the one package-lock.json pins (package.json at the repository's root
    names it). `make test` installs exactly that, checked against the lock's sha512, with
    `npm ci` into node_modules/ (kept out of git) when it is missing or older than the
    lock. Without it the test is skipped, but fails under CI=true (.ci/run installs npm).
    """
    script = ROOT / "node_modules" / "axe-core" / "axe.min.js"
    if not script.is_file():
        unavailable(
            "axe-core is not installed (npm ci --ignore-scripts, which `make test` runs)",
            "CI must run the accessibility check",
        )
    return script.read_text(encoding="utf-8")
