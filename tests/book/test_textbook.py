"""The chapters read as a textbook: the thread teaches, the evidence is one click away.

Measured on the built English site (tests/book/prose.py says what a reader sees without
opening anything). The expectations come from the book's own sources, not from the build:
how many check cells a page has is counted in its Markdown, and the chapters are the
toctree's pages less the reference matter.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from tests.book import prose
from tests.book._buildcheck import toctree_entries
from tests.conftest import BOOK

pytestmark = pytest.mark.slow

REFERENCE_MATTER = {"checks", "glossary", "references", "about", "teachers_guide"}
CELL = re.compile(r"^```\{code-cell\}[^\n]*\n(.*?)^```\s*$", re.M | re.S)


def check_cells(page: Path) -> list[str]:
    """The page's check cells, read from its source as book/_ext/checkmarks.py tells them:
    a folded input (tag hide-input) that calls ``verify``, or the tag ``check``."""
    found = []
    for cell in CELL.findall(page.read_text(encoding="utf-8")):
        tags = re.search(r"^:tags: \[(.*)\]", cell, re.M)
        names = {t.strip() for t in tags.group(1).split(",")} if tags else set()
        if "check" in names or ("hide-input" in names and "verify." in cell):
            found.append(cell)
    return found


def test_the_measured_chapters_are_the_books_chapters() -> None:
    # A chapter added to the book is measured too.
    assert set(prose.CHAPTERS) == set(toctree_entries(BOOK)) - REFERENCE_MATTER


@pytest.mark.parametrize("chapter", prose.CHAPTERS)
def test_each_chapter_speaks_of_its_subject(built_book: Path, chapter: str) -> None:
    text = prose.read(built_book / f"{chapter}.html")
    assert len(text.sentences) > 20  # the measure read the chapter
    assert text.share <= prose.MAX_MACHINERY, "\n".join(text.machinery)


@pytest.mark.parametrize("chapter", prose.CHAPTERS)
def test_each_chapter_takes_one_sitting(built_book: Path, chapter: str) -> None:
    assert prose.read(built_book / f"{chapter}.html").words <= prose.MAX_WORDS


@pytest.mark.parametrize("chapter", prose.CHAPTERS)
def test_every_check_is_one_mark_beside_the_thread(built_book: Path, chapter: str) -> None:
    html = (built_book / f"{chapter}.html").read_text(encoding="utf-8")
    marks = html.count('<div class="check-mark margin')
    assert marks == len(check_cells(BOOK / f"{chapter}.md"))
    # Each mark opens to its verdicts: no verdict is left in the column, and no check cell
    # keeps myst-nb's own "Show code cell source" toggle.
    column = re.sub(r'<div class="check-mark margin.*?</details>\n</div>', "", html, flags=re.S)
    assert "✔ <strong>" not in column
    for mark in re.findall(r'<div class="check-mark margin.*?</details>\n</div>', html, re.S):
        assert "✔ <strong>" in mark and 'class="check-code"' in mark
        assert "Show code cell" not in mark


def test_a_notebook_collapses_its_checks(built_book: Path) -> None:
    # In a notebook nothing is in a margin: a check is its cell, source collapsed, after its
    # paragraph, and its note (when the page wrote one) is a fold above it.
    notebook = next((built_book / "classroom" / "instructor").glob("*-libration_solution.ipynb"))
    cells = json.loads(notebook.read_text(encoding="utf-8"))["cells"]
    checks = [c for c in cells if c["cell_type"] == "code" and "verify." in "".join(c["source"])]
    assert len(checks) == len(check_cells(BOOK / "libration_solution.md"))
    assert all(c["metadata"].get("jupyter", {}).get("source_hidden") for c in checks)
