"""The book and docs tier: builds, notebooks in a fresh venv, the browser, the PDF.

Every test in this folder is marked ``slow`` (``make test-fast`` leaves them out, ``make
test`` runs them), whatever its own marks: the folder is the tier.
"""

from __future__ import annotations

import json
import os
import shutil
from collections.abc import Iterator
from concurrent.futures import Future, ThreadPoolExecutor
from pathlib import Path
from typing import Any, NoReturn

import pytest

from tests.book._buildcheck import BookIndex, book_index

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
def pdf_job(background: ThreadPoolExecutor, readme_runs: Any) -> Future:
    """`make pdf` on the fresh copy (the README's command, in its turn): a Future of (the
    build folder, what each print saw: tools/pdf/build.py's report.json, and each PDF's
    text read back: tests/book/test_pdf.py's read_pdf).

    pypdf reads the four PDFs as soon as they are printed, two at a time in processes of
    their own (each a core's work for half a minute or more), not in the tier's tail."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    from tests.book.test_pdf import read_pdf
    from tools.pdf import build as build_pdf

    def job() -> tuple[Path, dict, dict]:
        run = readme_runs.result("make pdf")
        assert run.returncode == 0, run.output[-5000:]
        out = readme_runs.copy / "book" / "_build"
        report = json.loads((out / "pdf" / build_pdf.REPORT).read_text(encoding="utf-8"))
        # Spawned, not forked: this process runs threads (the browsers' and the builds').
        with ProcessPoolExecutor(max_workers=2,
                                 mp_context=multiprocessing.get_context("spawn")) as pool:
            read = dict(zip(report, pool.map(read_pdf, [out / "pdf" / f"{name}.pdf"
                                                        for name in report]), strict=True))
        return out, report, read

    return background.submit(job)


@pytest.fixture(scope="session")
def nbgrader_job(background: ThreadPoolExecutor, readme_runs: Any,
                 tmp_path_factory: pytest.TempPathFactory) -> Future:
    """nbgrader's own run of the course that `make nbgrader` wrote from the book's instructor
    notebooks (tests/book/test_nbgrader.py): a Future of what its tests look at."""
    from tests.book.test_nbgrader import grade

    def job() -> dict:
        run = readme_runs.result("make nbgrader")
        assert run.returncode == 0, run.output[-5000:]
        return grade(readme_runs.copy / "book" / "_build", tmp_path_factory)

    return background.submit(job)


@pytest.fixture(scope="session")
def bundle_job(background: ThreadPoolExecutor, built_book: Path, readme_runs: Any,
               tmp_path_factory: pytest.TempPathFactory) -> Future:
    """The classroom zips of both sites unpacked alone, a fresh venv that their READMEs'
    install command filled, and every notebook run in it (tests/book/test_notebooks.py):
    a Future of (folders, venv, executed notebooks). It waits for `make book-student` in
    the background, so the survey that starts it does not."""
    from tests.book.test_notebooks import make_bundle_venv, run_all, unzip_bundles

    def job() -> tuple[dict[str, Path], Path, dict]:
        run = readme_runs.result("make book-student")
        assert run.returncode == 0, "the student site did not build; see test_student_book"
        student = readme_runs.copy / "book" / "_build" / "html" / "student"
        folders = unzip_bundles(built_book, student, tmp_path_factory)
        venv = make_bundle_venv(folders, tmp_path_factory)
        return folders, venv, run_all(folders, venv)

    return background.submit(job)
