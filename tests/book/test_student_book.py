"""The student book (`make book-student`, ``-D hide_solutions=1``) and the classroom files
inside the HTML build (book/_ext/classroom.py).

sphinx-exercise's own hide_solutions crashes the HTML writer on a gated solution
(``departing unknown node type: solution_end_node``) and would leave the solution's text and
cells in the page; the extension takes the option over, executes each page whole (the cache
of the instructor site's build serves) and removes the solutions from the doctree.
"""

from __future__ import annotations

import re
import zipfile
from pathlib import Path

import pytest

from tests.book._buildcheck import BookIndex
from tests.conftest import Build
from tools.classroom import bundle

EXERCISE = re.compile(
    r'<div class="exercise[^"]*" id="(?P<label>[^"]+)">\s*<p class="admonition-title">'
    r'\s*<span class="caption-number">Exercise (?P<number>\d+) </span>'
)


@pytest.mark.slow
def test_hide_solutions_builds_and_drops_gated_solutions(tiny_sites: dict) -> None:
    shown, hidden = (
        re.sub(r"<[^>]+>", "", (tiny_sites[b] / "alpha.html").read_text(encoding="utf-8"))
        for b in ("full", "student")
    )
    for text in ("Worked.", "answer = 42"):  # the solution's text and its cell
        assert text in shown and text not in hidden
    assert "Compute." in hidden and "Exercise 2" in hidden
    # The student build holds only the student edition.
    assert (tiny_sites["student"] / "classroom" / "student" / "02-alpha.ipynb").exists()
    assert not (tiny_sites["student"] / "classroom" / "instructor").exists()


@pytest.mark.slow
def test_student_book_has_exercises_and_no_solutions(student_book: Build,
                                                     index: BookIndex) -> None:
    assert student_book.returncode == 0, student_book.output[-3000:]
    assert student_book.warnings == []
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
        student_book: Build, built_book: Path, index: BookIndex) -> None:
    # book/_ext/classroom.py adds a dropdown "Hint" under each exercise, from its self-check
    # (elliptic_pendulum.selfcheck): as many per page as the page has exercises.
    from elliptic_pendulum import selfcheck

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
def test_book_offers_each_chapter_notebook(built_book: Path, index: BookIndex) -> None:
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
def test_notebooks_in_the_build_paste_every_glued_value(built_book: Path,
                                                         index: BookIndex) -> None:
    # Every value a page glues (myst-nb's <page>.glue.json of this build) is pasted into its
    # notebooks' text as the page shows it: the page's text and the notebook's agree.
    import json

    import nbformat

    glued = 0
    for page in index.exported:
        path = built_book.parent / "jupyter_execute" / f"{page}.glue.json"
        keys = json.loads(path.read_text(encoding="utf-8")) if path.exists() else {}
        html = re.sub(r"<[^>]+>", "", (built_book / f"{page}.html").read_text(encoding="utf-8"))
        for edition in ("student", "instructor"):
            nb = nbformat.read(built_book / "classroom" / edition / index.files[page], 4)
            text = "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")
            assert "glue:" not in text and "{glue" not in text, (page, edition)
        # One glued number, as the page shows it, is in the instructor's notebook.
        for key, value in keys.items():
            shown = value.get("data", {}).get("text/plain", "")
            if re.fullmatch(r"-?\d+", shown) and len(shown) >= 3 and shown in html:
                assert shown in text, (page, key)
        glued += len(keys)
    assert glued > 50  # the values came from this build's jupyter_execute folder
