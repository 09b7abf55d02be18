"""Shared fixtures. The book and the docs are built once per session, from clean and with
every notebook re-executed, and the builds are reused by the build, browser and other tests.
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
    _TIMINGS.append(f"sphinx-build {source.name}: {seconds:.1f} s (exit {proc.returncode})")
    return Build(source, outdir, proc.returncode, proc.stdout + proc.stderr, seconds)


_TIMINGS: list[str] = []


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    """Report how long the builds took, so slow chapters are noticed."""
    if _TIMINGS:
        terminalreporter.write_sep("-", "build times")
        for line in _TIMINGS:
            terminalreporter.write_line(line)


@pytest.fixture(scope="session")
def book_build(tmp_path_factory: pytest.TempPathFactory, docs_build: Build) -> Build:
    """The book built from clean with forced execution (what CI checks).

    It links to the API entries of this session's docs build (book/conf.py reads its
    objects.inv from ELLIPTIC_PENDULUM_DOCS_HTML), so the docs are built once, first.
    """
    return sphinx_build(
        BOOK,
        tmp_path_factory.mktemp("book") / "html",
        "-D",
        "nb_execution_mode=force",
        env={"ELLIPTIC_PENDULUM_DOCS_HTML": str(docs_build.outdir)},
    )


@pytest.fixture(scope="session")
def docs_build(tmp_path_factory: pytest.TempPathFactory) -> Build:
    """The reference site built from clean."""
    return sphinx_build(DOCS, tmp_path_factory.mktemp("docs") / "html")


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
