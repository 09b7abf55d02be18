"""Build the book as PDFs: <build>/pdf/book.pdf (solutions open) and book-student.pdf, and
the Japanese edition's book-ja.pdf and book-student-ja.pdf.

Each is a Sphinx ``singlehtml`` build of the whole book (the student one with
``-D hide_solutions=1``, which book/_ext/classroom.py turns into "no solutions at all"; the
Japanese ones with ``-D language=ja``, book/locale's catalogs, whose print stylesheet sets
the body in IPA P Mincho and the headings in IPA P Gothic),
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
import hashlib
import importlib.metadata
import json
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from .printer import print_pdf

STUDENT = ["-D", "hide_solutions=1"]
# What each print saw (formulas typeset, solutions opened, images...), beside the PDFs.
REPORT = "report.json"
JAPANESE = ["-D", "language=ja", "-D", "reference_site=../reference"]
# name: (build subfolder, sphinx-build options, solutions open, language, the HTML edition
# whose doctrees it shares: <build>/doctrees/<name>, and whose reference it reads, in
# <build>/html/<site>/reference). The options are the HTML edition's (the Makefile's), so
# Sphinx finds the pages read and resolved already and only writes the single page.
EDITIONS = {
    "book": (".", [], True, "en", "book", "."),
    "book-student": ("student", STUDENT, False, "en", "student", "student"),
    "book-ja": ("ja", JAPANESE, True, "ja", "book-ja", "."),
    "book-student-ja": ("student-ja", [*STUDENT, *JAPANESE], False, "ja", "student-ja",
                        "student"),
}
# The title page says which edition, which version of the library the book was built with
# (its numbers come from that run), when, and the licences (book/about.md,
# book/_templates/licence.html), in the edition's language.
EDITION_NAMES = {"book": "Instructor edition, with the solutions",
                 "book-student": "Student edition",
                 "book-ja": "教員用（解答付き）",
                 "book-student-ja": "学生用"}
LICENCE = {"en": "Text and figures: CC BY 4.0; code: MIT",
           "ja": "本文と図：CC BY 4.0、コード：MIT"}
# The copyright line as book/about.md has it (the Japanese edition keeps it as it is).
COPYRIGHT = {"en": "\u00a9 2024-2026 elliptic-pendulum contributors. {licence}.",
             "ja": "\u00a9 2024-2026 elliptic-pendulum contributors. {licence}"}


def title_page(name: str, today: datetime.date | None = None) -> list[tuple[str, str]]:
    """The lines under the title on the PDF's first page, (CSS class, text).

    The date is today's, or SOURCE_DATE_EPOCH's (reproducible builds) if it is set."""
    language = EDITIONS[name][3]
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
            ("ep-licence", COPYRIGHT[language].format(licence=LICENCE[language]))]


def build(book: Path, build_dir: Path, cache: Path | None = None,
          env: dict[str, str] | None = None,
          names: tuple[str, ...] = tuple(EDITIONS), workers: int = 1) -> dict[str, dict]:
    """The single-page builds and the PDFs of the editions ``names``; return, per PDF, the
    seconds of each step and what the printer saw (formulas typeset, solutions opened,
    images).

    env: extra environment variables for sphinx-build (e.g. where the docs build is).
    workers: editions made at once (each a sphinx-build, then a Chromium: one core each);
    the builds only read the execution cache, and each has its own folder."""
    env = dict(os.environ, JUPYTER_PLATFORM_DIRS="1", **(env or {}))
    # The notebook kernel must see this interpreter's packages.
    env["PATH"] = str(Path(sys.executable).parent) + os.pathsep + env.get("PATH", "")

    def make(name: str) -> dict:
        sub, extra, solutions, _, doctrees, site = EDITIONS[name]
        out = build_dir / sub / "singlehtml"
        options = ["-D", f"nb_execution_cache_path={cache}"] if cache else []
        reference = (build_dir / "html" / site / "reference").resolve()
        start = time.perf_counter()
        subprocess.run(
            [sys.executable, "-m", "sphinx", "-n", "-W", "--keep-going", "-q", *options,
             "-d", str(build_dir / "doctrees" / doctrees), *extra, "-b", "singlehtml",
             str(book), str(out)],
            check=True, env={**env, "ELLIPTIC_PENDULUM_DOCS_HTML": str(reference)},
        )
        built = time.perf_counter() - start
        start = time.perf_counter()
        pdf = build_dir / "pdf" / f"{name}.pdf"
        # A page printed before, unchanged since (same HTML, same title page), is not
        # printed again: the PDF and what its print saw are kept.
        key = hashlib.sha256((out / "index.html").read_bytes()
                             + repr(title_page(name)).encode()).hexdigest()
        seen = previous.get(name, {})
        if not (pdf.is_file() and seen.get("key") == key):
            seen = {**print_pdf(out / "index.html", pdf, solutions,
                                title_page=title_page(name)), "key": key}
        return {**seen, "build s": built, "print s": time.perf_counter() - start}

    report_file = build_dir / "pdf" / REPORT
    previous = json.loads(report_file.read_text()) if report_file.is_file() else {}
    with ThreadPoolExecutor(max_workers=workers) as pool:
        report = dict(zip(names, pool.map(make, names), strict=True))
    report_file.parent.mkdir(parents=True, exist_ok=True)
    report_file.write_text(json.dumps({**previous, **report}, indent=1), encoding="utf-8")
    return report


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("book", type=Path, help="the book's source folder")
    parser.add_argument("build", type=Path, help="the build folder (book/_build)")
    parser.add_argument("--execution-cache", type=Path, help="myst-nb's cache folder")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                        help="editions made at once (default: one per core)")
    args = parser.parse_args(argv)
    report = build(args.book, args.build, args.execution_cache, workers=max(1, args.jobs))
    for name, seen in report.items():
        print(f"{name}.pdf: " + ", ".join(
            f"{k} {v:.1f}" if isinstance(v, float) else f"{k} {v}" for k, v in seen.items()))
    print(f"wrote {', '.join(f'{n}.pdf' for n in EDITIONS)} in {args.build / 'pdf'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
