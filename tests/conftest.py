"""Shared fixtures. The book and the docs are built once per session, from clean and with
every notebook re-executed, and the builds are reused by the build, browser and other tests.

They are built as `make book` builds them: one site folder, ``<tmp>/book<N>/html``, with the
reference site in its ``reference/`` folder (built first: the book reads its objects.inv
there, book/conf.py) and the doctrees beside it, not in it.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BOOK = ROOT / "book"
DOCS = ROOT / "docs"


@dataclass(frozen=True)
class Build:
    """The outcome of one sphinx-build run."""

    source: Path
    outdir: Path
    returncode: int
    output: str
    seconds: float

    @property
    def warnings(self) -> list[str]:
        return [
            line
            for line in self.output.splitlines()
            if re.search(r"\b(WARNING|ERROR|CRITICAL):", line)
        ]


def sphinx_build(
    source: Path, outdir: Path, *extra: str, env: dict[str, str] | None = None
) -> Build:
    """Run ``sphinx-build -n -W --keep-going -E`` (plus ``extra``) in a subprocess."""
    cmd = [
        sys.executable,
        "-m",
        "sphinx",
        "-n",
        "-W",
        "--keep-going",
        "-E",
        *extra,
        "-b",
        "html",
        str(source),
        str(outdir),
    ]
    env = dict(os.environ, JUPYTER_PLATFORM_DIRS="1", **(env or {}))
    # The notebook kernel must find this interpreter's packages (the editable install).
    env["PATH"] = str(Path(sys.executable).parent) + os.pathsep + env.get("PATH", "")
    start = time.perf_counter()
    proc = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True, timeout=1800)
    seconds = time.perf_counter() - start
    _TIMINGS.append(
        f"sphinx-build {source.name} -> {outdir.parent.name}/{outdir.name}: "
        f"{seconds:.1f} s (exit {proc.returncode})"
    )
    return Build(source, outdir, proc.returncode, proc.stdout + proc.stderr, seconds)


def reference_build(site: Path) -> Build:
    """The reference site built from clean into ``<site>/html/reference``, as `make book`
    and `make book-student` build it into theirs (doctrees in ``<site>/doctrees``)."""
    return sphinx_build(
        DOCS, site / "html" / "reference", "-d", str(site / "doctrees" / "reference")
    )


def book_site_build(site: Path, *extra: str) -> Build:
    """The book built from clean into ``<site>/html``, around its reference (built first)."""
    return sphinx_build(BOOK, site / "html", "-d", str(site / "doctrees" / "book"), *extra)


_TIMINGS: list[str] = []
# Lines for the terminal summary from other tests (the site check's counts), by section.
SUMMARY: dict[str, list[str]] = {}


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    """Report how long the builds took, so slow chapters are noticed, and what else the
    tests counted (the pages, links and anchors of each site)."""
    sections = {"build times": _TIMINGS, **SUMMARY}
    for title, lines in sections.items():
        if lines:
            terminalreporter.write_sep("-", title)
            for line in lines:
                terminalreporter.write_line(line)


@pytest.fixture(scope="session")
def site_folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The folder of this session's book site: ``html`` (the site) and ``doctrees``."""
    return tmp_path_factory.mktemp("book")


@pytest.fixture(scope="session")
def execution_cache(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """myst-nb's execution cache of this session, empty at its start: the book build fills
    it, so every page runs once, from clean; the student site, the PDFs' single-page builds
    and the notebooks' glue read it, as `make book`, `make book-student` and `make pdf`
    share book/_build/.jupyter_cache."""
    return tmp_path_factory.mktemp("jupyter-cache")


@pytest.fixture(scope="session")
def book_build(site_folder: Path, docs_build: Build, execution_cache: Path) -> Build:
    """The book built from clean, every page executed (what CI checks): the session's cache
    is empty when it starts, so "cache" mode runs every notebook, and keeps the results.

    It links to the API entries of this session's docs build, in its own ``reference/``
    folder (book/conf.py reads the objects.inv there), so the docs are built once, first.
    """
    return book_site_build(
        site_folder, "-D", "nb_execution_mode=cache",
        "-D", f"nb_execution_cache_path={execution_cache}",
    )


@pytest.fixture(scope="session")
def docs_build(site_folder: Path) -> Build:
    """The reference site built from clean, into the book site's ``reference/`` folder."""
    return reference_build(site_folder)


@pytest.fixture(scope="session")
def student_book(
    tmp_path_factory: pytest.TempPathFactory, book_build: Build, execution_cache: Path
) -> Build:
    """The student site as `make book-student` builds it: its own reference first, in
    ``html/reference``, then the book without solutions around it, from the cache the book
    build filled (the student pages execute whole; book/_ext/classroom.py removes the
    solutions after)."""
    site = tmp_path_factory.mktemp("student")
    reference = reference_build(site)
    if reference.returncode != 0:
        pytest.fail("the student site's reference did not build:\n" + reference.output[-3000:])
    return book_site_build(
        site, "-D", "hide_solutions=1", "-D", f"nb_execution_cache_path={execution_cache}"
    )


@pytest.fixture(scope="session")
def built_book(book_build: Build) -> Path:
    """The book's HTML folder, for tests that look at the pages; fails if the build failed."""
    if book_build.returncode != 0:
        pytest.fail("the book did not build; see test_book_build for the output", pytrace=False)
    return book_build.outdir


@pytest.fixture(scope="session")
def built_docs(docs_build: Build) -> Path:
    """The docs' HTML folder; fails if the build failed."""
    if docs_build.returncode != 0:
        pytest.fail("the docs did not build; see test_docs_build for the output", pytrace=False)
    return docs_build.outdir
