"""Shared fixtures. The build tier runs the README's commands, exactly as the README writes
them, on a fresh copy of the repository (the files a clone has, none of the build products),
once per session and in the README's order: `make book`, `make book-student`, `make pdf`,
... (tests/readme.py reads them from the README). The builds the tests look at are those
commands' outputs, in the copy's book/_build; the Makefile is the one place that says how the
book is built.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import settings

from tests.readme import Runs, commands, fresh_copy

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
    """The outcome of one sphinx-build run (one recipe line of a make command)."""

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


_BUILD_TIER = Path(__file__).resolve().parent / "book"


def _in_build_tier(item: pytest.Item) -> bool:
    return _BUILD_TIER in Path(str(item.path)).resolve().parents


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """The build tier's tests last (in their order): the others run first, while the README's
    commands build the book in the background (``_builds_start_first``), on the core that
    sphinx and one notebook kernel leave idle."""
    items.sort(key=_in_build_tier)


@pytest.fixture(scope="session", autouse=True)
def _builds_start_first(request: pytest.FixtureRequest) -> None:
    """Start the README's commands with the session's first test when the build tier is
    selected, rather than with the build tier's first test."""
    if any(_in_build_tier(item) for item in request.session.items):
        request.getfixturevalue("readme_runs")


@pytest.fixture(scope="session")
def readme_runs(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Runs]:
    """The README's commands, run in its order on a fresh copy, one after the other in the
    background (tests/readme.py): each test waits only for the command it looks at."""
    copy = fresh_copy(tmp_path_factory.mktemp("clone") / "elliptic-pendulum")
    runs = Runs(copy, commands())
    try:
        yield runs
    finally:
        runs.close()
        _TIMINGS.extend(runs.timings())


@pytest.fixture(scope="session")
def site_folder(readme_runs: Runs) -> Path:
    """The copy's build folder: ``html`` (the site) and ``doctrees``, as `make book` left it."""
    return readme_runs.copy / "book" / "_build"


@pytest.fixture(scope="session")
def execution_cache(site_folder: Path) -> Path:
    """myst-nb's execution cache, empty before `make book` filled it on the fresh copy."""
    return site_folder / ".jupyter_cache"


def _build(runs: Runs, command: str, builder: str, source: str, outdir: str) -> Build:
    """The sphinx-build of ``source`` into ``outdir`` (relative to the copy) that the README's
    ``command`` ran."""
    part = runs.result(command).part(f"-b {builder} {source} {outdir}")
    return Build(runs.copy / source, runs.copy / outdir, part.returncode, part.output,
                 part.seconds)


@pytest.fixture(scope="session")
def docs_build(readme_runs: Runs) -> Build:
    """The reference site built from clean into the site's ``reference/`` (`make book`)."""
    return _build(readme_runs, "make book", "html", "docs", "book/_build/html/reference")


@pytest.fixture(scope="session")
def book_build(readme_runs: Runs) -> Build:
    """The book built from clean, every page executed (`make book` on a fresh copy: its
    execution cache was empty), linking the reference built before it."""
    return _build(readme_runs, "make book", "html", "book", "book/_build/html")


@pytest.fixture(scope="session")
def book_ja_build(readme_runs: Runs) -> Build:
    """The Japanese edition, in the site's ja/ (`make book`): it runs its own cells, in Japanese."""
    return _build(readme_runs, "make book", "html", "book", "book/_build/html/ja")


@pytest.fixture(scope="session")
def gettext_build(readme_runs: Runs) -> Build:
    """The gettext builder's templates of the current pages (`make i18n-status`)."""
    return _build(readme_runs, "make i18n-status", "gettext", "book", "book/_build/gettext")


@pytest.fixture(scope="session")
def student_book(readme_runs: Runs) -> Build:
    """The student site (`make book-student`), inside the site's student/ folder."""
    reference = _build(readme_runs, "make book-student", "html", "docs",
                       "book/_build/html/student/reference")
    if reference.returncode != 0:
        pytest.fail("the student site's reference did not build:\n" + reference.output[-3000:])
    return _build(readme_runs, "make book-student", "html", "book", "book/_build/html/student")


@pytest.fixture(scope="session")
def student_ja_build(readme_runs: Runs) -> Build:
    """The student site's Japanese edition, in its ja/ folder (`make book-student`)."""
    return _build(readme_runs, "make book-student", "html", "book",
                  "book/_build/html/student/ja")


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
