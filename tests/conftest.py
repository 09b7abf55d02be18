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
from collections.abc import Iterator
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import settings

# The property tests give the same answer on every run: hypothesis draws its examples from a
# fixed seed (a red run means changed behaviour, never a new draw) and keeps no database.
# HYPOTHESIS_PROFILE=explore draws fresh examples, for a developer hunting for new failures.
settings.register_profile("deterministic", derandomize=True, database=None)
settings.register_profile("explore", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "deterministic"))

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
    source: Path, outdir: Path, *extra: str, env: dict[str, str] | None = None,
    builder: str = "html",
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
        builder,
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


# The Japanese edition (book/_ext/i18n.py), as `make book` builds it: the same pages with
# book/locale's catalogs, in the site's ja/ folder, around the site's reference one folder up.
JAPANESE = ("-D", "language=ja", "-D", "reference_site=../reference")


def japanese_build(site: Path, name: str, *extra: str) -> Build:
    """The Japanese edition of a site built from clean into ``<site>/html/ja``."""
    return sphinx_build(
        BOOK, site / "html" / "ja", "-d", str(site / "doctrees" / name), *JAPANESE, *extra
    )


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
def after_book(
    tmp_path_factory: pytest.TempPathFactory, site_folder: Path, book_build: Build,
    execution_cache: Path,
) -> Iterator[dict[str, Future]]:
    """The builds that read the cache the book build filled, started together once it is
    done, in two chains at once (a Sphinx build uses one core; the machine has two):

    * "editions": the Japanese edition, in the book site's ja/ (`make book`), then the
      gettext builder's templates of the current pages (`make i18n-status`);
    * "students": the student site as `make book-student` builds it, its own reference first,
      in ``html/reference``, then the book without solutions around it (the student pages
      execute whole from the cache; book/_ext/classroom.py removes the solutions after), then
      its Japanese edition in ``html/ja``.

    None of them executes a cell the book build ran: every edition shows the same numbers.
    """
    cache = ("-D", f"nb_execution_cache_path={execution_cache}")
    student = tmp_path_factory.mktemp("student")
    gettext = tmp_path_factory.mktemp("gettext")

    def editions() -> tuple[Build, Build]:
        japanese = japanese_build(site_folder, "book-ja", *cache)
        pot = sphinx_build(
            BOOK, gettext / "pot", "-d", str(gettext / "doctrees"),
            "-D", f"reference_site={site_folder / 'html' / 'reference'}", *cache,
            builder="gettext",
        )
        return japanese, pot

    def students() -> tuple[Build, Build, Build]:
        reference = reference_build(student)
        if reference.returncode != 0:
            return reference, reference, reference
        book = book_site_build(student, "-D", "hide_solutions=1", *cache)
        japanese = japanese_build(student, "student-ja", "-D", "hide_solutions=1", *cache)
        return reference, book, japanese

    with ThreadPoolExecutor(max_workers=2) as pool:
        yield {"editions": pool.submit(editions), "students": pool.submit(students)}


@pytest.fixture(scope="session")
def book_ja_build(after_book: dict[str, Future]) -> Build:
    """The Japanese edition inside the book's site (see after_book)."""
    return after_book["editions"].result()[0]


@pytest.fixture(scope="session")
def gettext_build(after_book: dict[str, Future]) -> Build:
    """The gettext builder's templates of the current pages (see after_book)."""
    return after_book["editions"].result()[1]


@pytest.fixture(scope="session")
def student_book(after_book: dict[str, Future]) -> Build:
    """The student site (see after_book)."""
    reference, book, _ = after_book["students"].result()
    if reference.returncode != 0:
        pytest.fail("the student site's reference did not build:\n" + reference.output[-3000:])
    return book


@pytest.fixture(scope="session")
def student_ja_build(after_book: dict[str, Future]) -> Build:
    """The student site's Japanese edition, in its ja/ folder (see after_book)."""
    return after_book["students"].result()[2]


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
