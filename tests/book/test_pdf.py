"""The book as PDF (tools/pdf, `make pdf`): a single-page build of each edition
printed by headless Chromium after MathJax. The PDFs are read back with pypdf: every chapter
title and every equation number of the note is there as text, the figures and formulas were
drawn, the instructor's copy has every solution open and the student's none.
"""

from __future__ import annotations

import importlib.util
import os
import re
import shutil
from pathlib import Path

import pytest

from tests.conftest import BOOK, Build
from tools.classroom.labels import scan
from tools.pdf import build as build_pdf

pytestmark = pytest.mark.slow
REQUIRED = os.environ.get("CI") == "true"


def _need(what: str, ok: bool) -> None:
    if not ok:
        if REQUIRED:
            pytest.fail(f"{what} is required under CI=true", pytrace=False)
        pytest.skip(f"{what} is not installed")


@pytest.fixture(scope="session")
def pdfs(tmp_path_factory: pytest.TempPathFactory, docs_build: Build, book_build: Build,
         execution_cache: Path) -> dict:
    _need("chromium", shutil.which("chromium") is not None or "CHROMIUM" in os.environ)
    _need("pypdf", importlib.util.find_spec("pypdf") is not None)
    if docs_build.returncode != 0:
        pytest.fail("the docs did not build (the book links to them)", pytrace=False)
    out = tmp_path_factory.mktemp("pdf")
    # The session's execution cache, which the book build filled: no page runs again.
    report = build_pdf.build(BOOK, out, execution_cache,
                             {"ELLIPTIC_PENDULUM_DOCS_HTML": str(docs_build.outdir)})
    print({k: {n: round(v, 1) if isinstance(v, float) else v for n, v in r.items()}
           for k, r in report.items()})
    from pypdf import PdfReader

    texts = {}
    for name in report:
        reader = PdfReader(out / "pdf" / f"{name}.pdf")
        pages = [p.extract_text() for p in reader.pages]
        # Ligatures back to letters, so "ﬁrst" reads "first".
        texts[name] = [p.replace("\ufb01", "fi").replace("\ufb02", "fl") for p in pages]
    return {"report": report, "texts": texts}


def test_both_pdfs_have_a_plausible_length(pdfs: dict) -> None:
    teacher, student = pdfs["texts"]["book"], pdfs["texts"]["book-student"]
    chapters = len(scan(BOOK).pages)
    # Every chapter starts on a new page and runs over several; the solutions add pages.
    assert 3 * chapters < len(student) < len(teacher) < 1000


def test_chapter_titles_are_text(pdfs: dict) -> None:
    titles = scan(BOOK).titles
    for name, pages in pdfs["texts"].items():
        text = re.sub(r"\s+", " ", " ".join(pages))
        missing = [t for t in titles.values() if re.sub(r"\s+", " ", t) not in text]
        assert missing == [], (name, missing)


def _tags() -> set[str]:
    tags: set[str] = set()
    for page in BOOK.glob("*.md"):
        tags |= set(re.findall(r"\\tag\{([^}]*)\}", page.read_text(encoding="utf-8")))
    return tags


def test_equation_numbers_are_text(pdfs: dict) -> None:
    tags = _tags()
    assert len(tags) >= 40  # the note numbers (1)-(46)
    for name, pages in pdfs["texts"].items():
        lines = [line.strip() for page in pages for line in page.splitlines()]
        # A typeset tag ends a line of formula (or stands alone), right of the equation;
        # a raw "\tag{9}" (MathJax not run) or a verdict line "✔ (9) ..." does not count.
        found = {
            n for n in tags for line in lines
            if line.endswith(f"({n})") and not line.startswith("\u2714")
            and (line == f"({n})" or re.search(r"[=<>\u2264\u2265\u221a\u222b]|\S\s+\S", line))
        }
        assert tags - found == set(), (name, sorted(tags - found, key=int))


def test_formulas_and_figures_were_drawn(pdfs: dict) -> None:
    for name, seen in pdfs["report"].items():
        assert seen["formulas"] > 500, (name, seen)  # MathJax typeset the whole book
        assert seen["images"] > 5, (name, seen)  # and print_pdf refuses an image not loaded
    figures = {t.number for t in scan(BOOK).targets.values() if t.kind == "figure" and t.number}
    text = "\n".join(pdfs["texts"]["book"])
    assert {n for n in figures if f"Fig. {n}" in text} == figures


def test_solutions_open_for_instructors_absent_for_students(pdfs: dict) -> None:
    exercises = len(scan(BOOK).exercise_numbers)
    teacher = "\n".join(pdfs["texts"]["book"])
    student = "\n".join(pdfs["texts"]["book-student"])
    assert pdfs["report"]["book"]["solutions"] == exercises
    assert len(re.findall(r"Solution to\s*Exercise \d+", teacher)) == exercises
    assert "Solution" not in re.sub(r"Solutions? of", "", student)
    for number in scan(BOOK).exercise_numbers.values():  # the exercises stay, same numbers
        assert f"Exercise {number}" in student
