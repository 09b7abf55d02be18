"""Build the book as two PDFs: <build>/pdf/book.pdf (solutions open) and book-student.pdf.

Each is a Sphinx ``singlehtml`` build of the whole book (the student one with
``-D hide_solutions=1``, which book/_ext/classroom.py turns into "no solutions at all"),
printed by headless Chromium (tools/pdf/printer.py) once MathJax has typeset it. Why Chromium
and not LaTeX: the tests already need Debian's chromium, the PDF then shows exactly what the
HTML book shows (myst-nb outputs, MathJax, the figures), and TeX Live would add a large
install to CI. ``make pdf`` runs this with the build folder book/_build.

Usage::

    python -m tools.pdf book book/_build [--execution-cache DIR]
"""

from __future__ import annotations

import argparse
import datetime
import importlib.metadata
import os
import subprocess
import sys
import time
from pathlib import Path

from .printer import print_pdf

EDITIONS = {"book": (".", [], True), "book-student": ("student", ["-D", "hide_solutions=1"], False)}
# The title page says which edition, which version of the library the book was built with
# (its numbers come from that run), when, and the licences (book/about.md,
# book/_templates/licence.html).
EDITION_NAMES = {"book": "Instructor edition, with the solutions",
                 "book-student": "Student edition"}
LICENCE = "Text and figures: CC BY 4.0; code: MIT"


def title_page(name: str, today: datetime.date | None = None) -> list[tuple[str, str]]:
    """The lines under the title on the PDF's first page, (CSS class, text).

    The date is today's, or SOURCE_DATE_EPOCH's (reproducible builds) if it is set."""
    if today is None:
        epoch = os.environ.get("SOURCE_DATE_EPOCH")
        today = (datetime.datetime.fromtimestamp(int(epoch), datetime.UTC).date() if epoch
                 else datetime.date.today())
    try:
        version = importlib.metadata.version("elliptic-pendulum")
    except importlib.metadata.PackageNotFoundError:
        version = "unknown"
    return [("ep-edition", EDITION_NAMES[name]),
            ("ep-version", f"elliptic-pendulum {version}"),
            ("ep-date", today.isoformat()),
            ("ep-licence", f"\u00a9 2024-2026 elliptic-pendulum contributors. {LICENCE}.")]


def build(book: Path, build_dir: Path, cache: Path | None = None,
          env: dict[str, str] | None = None) -> dict[str, dict]:
    """Both single-page builds and both PDFs; return, per PDF, the seconds of each step
    and what the printer saw (formulas typeset, solutions opened, images).

    env: extra environment variables for sphinx-build (e.g. where the docs build is)."""
    env = dict(os.environ, JUPYTER_PLATFORM_DIRS="1", **(env or {}))
    # The notebook kernel must see this interpreter's packages.
    env["PATH"] = str(Path(sys.executable).parent) + os.pathsep + env.get("PATH", "")
    report: dict[str, dict] = {}
    for name, (sub, extra, solutions) in EDITIONS.items():
        out = build_dir / sub / "singlehtml"
        options = ["-D", f"nb_execution_cache_path={cache}"] if cache else []
        start = time.perf_counter()
        subprocess.run(
            [sys.executable, "-m", "sphinx", "-n", "-W", "--keep-going", "-q", *options,
             *extra, "-b", "singlehtml", str(book), str(out)],
            check=True, env=env,
        )
        built = time.perf_counter() - start
        start = time.perf_counter()
        seen = print_pdf(out / "index.html", build_dir / "pdf" / f"{name}.pdf", solutions,
                         title_page=title_page(name))
        report[name] = {"build s": built, "print s": time.perf_counter() - start, **seen}
    return report


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("book", type=Path, help="the book's source folder")
    parser.add_argument("build", type=Path, help="the build folder (book/_build)")
    parser.add_argument("--execution-cache", type=Path, help="myst-nb's cache folder")
    args = parser.parse_args(argv)
    for name, seen in build(args.book, args.build, args.execution_cache).items():
        print(f"{name}.pdf: " + ", ".join(
            f"{k} {v:.1f}" if isinstance(v, float) else f"{k} {v}" for k, v in seen.items()))
    print(f"wrote {args.build / 'pdf' / 'book.pdf'} and book-student.pdf")
    return 0


if __name__ == "__main__":
    sys.exit(main())
