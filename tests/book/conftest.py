"""The book and docs tier: builds, notebooks in a fresh venv, the browser, the PDF.

Every test in this folder is marked ``slow`` (``make test-fast`` leaves them out, ``make
test`` runs them), whatever its own marks: the folder is the tier.
"""

from __future__ import annotations

import os
import shutil
from collections.abc import Iterator
from concurrent.futures import Future, ThreadPoolExecutor
from pathlib import Path
from typing import NoReturn

import pytest

from tests.book._buildcheck import BookIndex, book_index
from tests.conftest import BOOK, Build

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


@pytest.fixture(scope="session")
def index(built_book: Path) -> BookIndex:
    """The session's English book as Sphinx resolved it (order, titles, numbers)."""
    return book_index(built_book.parent / "doctrees" / "book")


@pytest.fixture(scope="session")
def tiny_sites(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """The small book of tests/book/test_notebooks.py (SYNTHETIC) built by Sphinx with the
    book's extensions, as the instructor site ("full") and the student site."""
    import subprocess
    import sys

    from tests.book.test_notebooks import SYNTHETIC

    root = tmp_path_factory.mktemp("tiny")
    book = root / "book"
    book.mkdir()
    for name, text in SYNTHETIC.items():
        (book / name).write_text(text, encoding="utf-8")
    sites = {}
    for name, extra in (("full", []), ("student", ["-D", "hide_solutions=1"])):
        proc = subprocess.run(
            [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-E", "-q", *extra,
             "-b", "html", str(book), str(root / name)],
            capture_output=True, text=True, timeout=600)
        assert proc.returncode == 0, proc.stdout + proc.stderr
        sites[name] = root / name
    return sites


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


@pytest.fixture(scope="session")
def background() -> Iterator[ThreadPoolExecutor]:
    """Work that waits for nothing of the browser survey, started beside it.

    A browser spends much of a page waiting (loads, MathJax's timers): across the tier one
    of the two cores sat idle about half the time, so the survey's fixture starts the PDFs
    and nbgrader's run here, and the classroom bundles' venv and notebooks (both venvs are
    mostly pip waiting for downloads); their tests take the results when their turn comes.
    """
    with ThreadPoolExecutor(max_workers=3) as pool:
        yield pool


@pytest.fixture(scope="session")
def pdf_job(background: ThreadPoolExecutor, tmp_path_factory: pytest.TempPathFactory,
            docs_build: Build, book_build: Build, execution_cache: Path) -> Future:
    """The four PDFs of `make pdf`, on the session's execution cache (no page runs again),
    two editions at a time: a Future of (folder, tools/pdf/build.py's report)."""
    from tools.pdf import build as build_pdf

    out = tmp_path_factory.mktemp("pdf")
    if docs_build.returncode != 0 or book_build.returncode != 0:
        failed: Future = Future()
        failed.set_exception(RuntimeError("the docs or the book did not build"))
        return failed
    env = {"ELLIPTIC_PENDULUM_DOCS_HTML": str(docs_build.outdir)}
    return background.submit(
        lambda: (out, build_pdf.build(BOOK, out, execution_cache, env, workers=2)))


@pytest.fixture(scope="session")
def nbgrader_job(background: ThreadPoolExecutor, built_book: Path,
                 tmp_path_factory: pytest.TempPathFactory) -> Future:
    """nbgrader's own run of the course made from the book's instructor notebooks
    (tests/book/test_nbgrader.py): a Future of what its tests look at."""
    from tests.book.test_nbgrader import grade

    return background.submit(grade, built_book, tmp_path_factory)


@pytest.fixture(scope="session")
def bundle_job(background: ThreadPoolExecutor, built_book: Path, student_book: Build,
               tmp_path_factory: pytest.TempPathFactory) -> Future:
    """The classroom zips of both sites unpacked alone, a fresh venv that their READMEs'
    install command filled, and every notebook run in it (tests/book/test_notebooks.py):
    a Future of (folders, venv, executed notebooks)."""
    from tests.book.test_notebooks import make_bundle_venv, run_all, unzip_bundles

    if student_book.returncode != 0:
        pytest.fail("the student site did not build; see test_student_book", pytrace=False)

    def job() -> tuple[dict[str, Path], Path, dict]:
        folders = unzip_bundles(built_book, student_book.outdir, tmp_path_factory)
        venv = make_bundle_venv(folders, tmp_path_factory)
        return folders, venv, run_all(folders, venv)

    return background.submit(job)
