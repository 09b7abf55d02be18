"""The student book (`make book-student`, ``-D hide_solutions=1``) and the classroom files
inside the HTML build (book/_ext/classroom.py).

sphinx-exercise's own hide_solutions crashes the HTML writer on a gated solution
(``departing unknown node type: solution_end_node``) and would leave the solution's text and
cells in the page; the extension takes the option over, executes each page whole (the cache
of the instructor site's build serves) and removes the solutions from the doctree.
"""

from __future__ import annotations

import re
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

from tests.book.test_notebooks import SYNTHETIC
from tests.conftest import BOOK, Build
from tools.classroom import bundle
from tools.classroom import export as ex
from tools.classroom.labels import scan

EXERCISE = re.compile(
    r'<div class="exercise[^"]*" id="(?P<label>[^"]+)">\s*<p class="admonition-title">'
    r'\s*<span class="caption-number">Exercise (?P<number>\d+) </span>'
)


def _tiny(tmp_path: Path) -> Path:
    book = tmp_path / "tiny"
    book.mkdir()
    for name, text in SYNTHETIC.items():
        (book / name).write_text(text, encoding="utf-8")
    return book


def _build_tiny(book: Path, out: Path, *extra: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-E", "-q", *extra,
         "-b", "html", str(book), str(out)],
        capture_output=True, text=True, timeout=600,
    )


@pytest.mark.slow
def test_hide_solutions_builds_and_drops_gated_solutions(tmp_path: Path) -> None:
    book = _tiny(tmp_path)
    full = _build_tiny(book, tmp_path / "full")
    student = _build_tiny(book, tmp_path / "student", "-D", "hide_solutions=1")
    assert full.returncode == 0, full.stdout + full.stderr
    assert student.returncode == 0, student.stdout + student.stderr
    shown, hidden = (
        re.sub(r"<[^>]+>", "", (tmp_path / b / "alpha.html").read_text(encoding="utf-8"))
        for b in ("full", "student")
    )
    for text in ("Worked.", "answer = 42"):  # the solution's text and its cell
        assert text in shown and text not in hidden
    assert "Compute." in hidden and "Exercise 2" in hidden
    # The student build holds only the student edition.
    assert (tmp_path / "student" / "classroom" / "student" / "02-alpha.ipynb").exists()
    assert not (tmp_path / "student" / "classroom" / "instructor").exists()


@pytest.mark.slow
def test_student_book_has_exercises_and_no_solutions(student_book: Build) -> None:
    assert student_book.returncode == 0, student_book.output[-3000:]
    assert student_book.warnings == []
    index = scan(BOOK)
    seen = {}
    for page in index.pages:
        html = (student_book.outdir / f"{page}.html").read_text(encoding="utf-8")
        assert 'class="solution' not in html and "Solution to" not in html, page
        seen |= {m["label"]: m["number"] for m in EXERCISE.finditer(html)}
    # Every exercise is there, numbered as the notebooks number it.
    assert seen == index.exercise_numbers
    assert not (student_book.outdir / "classroom" / "instructor").exists()
    assert not list((student_book.outdir / "classroom").glob("*instructor*"))
    assert "A teacher keeps it private" not in html  # the footer of the instructor site


@pytest.mark.slow
def test_every_exercise_has_its_folded_hint_in_both_sites(
        student_book: Build, built_book: Path) -> None:
    # book/_ext/classroom.py adds a dropdown "Hint" under each exercise, from its self-check
    # (tools/classroom/selfcheck): as many per page as the page has exercises.
    from elliptic_pendulum import selfcheck

    index = scan(BOOK)
    for site in (student_book.outdir, built_book):
        for page in index.pages:
            html = (site / f"{page}.html").read_text(encoding="utf-8")
            exercises = len(EXERCISE.findall(html))
            assert html.count('<p class="admonition-title">Hint</p>') == exercises, page
            for label, exercise in selfcheck.EXERCISES.items():
                if f'id="{label}"' in html and exercise.values:
                    names = "; ".join(f"{v.name}" for v in exercise.values)
                    text = re.sub(r"<[^>]+>", "", html)
                    assert f"checks your results ({names})" in text, (page, label)


@pytest.mark.slow
def test_the_teachers_guide_is_in_the_instructor_site_only(
        student_book: Build, built_book: Path) -> None:
    # book/_ext/classroom.py: INSTRUCTOR_ONLY pages and their toctree entries are left out.
    assert (built_book / "teachers_guide.html").is_file()
    assert 'href="teachers_guide.html"' in (built_book / "index.html").read_text(encoding="utf-8")
    site = student_book.outdir
    assert not (site / "teachers_guide.html").exists()
    assert not list(site.rglob("teachers_guide*"))
    mentions = [p.name for p in site.rglob("*") if p.is_file() and p.suffix in {".html", ".js",
                ".txt", ".md"} and "teachers_guide" in p.read_text(encoding="utf-8")]
    assert mentions == []


@pytest.mark.slow
def test_book_offers_each_chapter_notebook(built_book: Path) -> None:
    index = scan(BOOK)
    for page in index.exported:
        html = (built_book / f"{page}.html").read_text(encoding="utf-8")
        # The instructor site (the default build) offers both editions, and says it is
        # the teacher's (book/_templates/edition.html).
        for edition in ("student", "instructor"):
            link = f"classroom/{edition}/{index.files[page]}"
            assert f'href="{link}"' in html, (page, edition)
            assert (built_book / link).is_file()
            assert f'href="classroom/elliptic-pendulum-notebooks-{edition}.zip"' in html, page
        assert "A teacher keeps it private" in html, page
    for edition in ("student", "instructor"):
        archive = built_book / "classroom" / f"elliptic-pendulum-notebooks-{edition}.zip"
        with zipfile.ZipFile(archive) as z:
            names = sorted(z.namelist())
        # One folder: the notebooks and what installs them (tools/classroom/bundle.py).
        files = [*index.files.values(), bundle.README, bundle.REQUIREMENTS, bundle.wheel_name()]
        assert names == sorted(f"{bundle.bundle_name(edition)}/{f}" for f in files), edition


@pytest.mark.slow
def test_notebooks_in_the_build_paste_every_glued_value(built_book: Path) -> None:
    import nbformat

    index = scan(BOOK)
    glued = 0
    for page in index.exported:
        keys = ex.glue_from_build(built_book.parent / "jupyter_execute", page)
        for edition in ("student", "instructor"):
            nb = nbformat.read(built_book / "classroom" / edition / index.files[page], 4)
            text = "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")
            assert [k for k in keys if f"`{k}`" in text] == [], (page, edition)
        glued += len(keys)
    assert glued > 50  # the values came from this build's jupyter_execute folder
