"""Every command of the README succeeds on a fresh copy, in the README's order, and makes
what the README says it makes (tests/readme.py runs them; the other tests of this tier read
their outputs)."""

from __future__ import annotations

import re
import zipfile

import pytest

from tests.readme import Runs, commands

# What each command leaves, as the README describes it (paths in the copy).
MADE = {
    "make book": ["book/_build/html/index.html", "book/_build/html/ja/index.html",
                  "book/_build/html/reference/index.html"],
    "make i18n-status": ["book/_build/gettext/index.pot"],
    "make docs": ["docs/_build/html/index.html"],
    "make notebooks": ["notebooks/student/00-index.ipynb", "notebooks/instructor/00-index.ipynb",
                       "notebooks/elliptic-pendulum-notebooks-student.zip",
                       "notebooks/elliptic-pendulum-notebooks-instructor.zip"],
    "make notebooks-ja": ["notebooks/ja/student/00-index.ipynb",
                          "notebooks/ja/instructor/00-index.ipynb",
                          "notebooks/ja/elliptic-pendulum-notebooks-student.zip"],
    "make book-student": ["book/_build/html/student/index.html",
                          "book/_build/html/student/ja/index.html"],
    "make pdf": [f"book/_build/pdf/{n}.pdf"
                 for n in ("book", "book-student", "book-ja", "book-student-ja")],
    "make nbgrader": ["book/_build/nbgrader/nbgrader_config.py"],
    "make site": ["book/_build/html/pdf/book.pdf", "book/_build/html/student/pdf/book-student.pdf",
                  "book/_build/html/student/index.html"],
}


@pytest.mark.parametrize("command", commands())
def test_the_command_succeeds_on_a_fresh_copy(command: str, readme_runs: Runs) -> None:
    run = readme_runs.result(command)
    print(f"{command}: {run.seconds:.1f} s")
    assert run.returncode == 0, run.output[-8000:]
    for path in MADE.get(command, []):
        assert (readme_runs.copy / path).is_file(), (command, path)


def test_the_later_commands_reuse_the_book(readme_runs: Runs) -> None:
    # `make book` built the site; the commands after it read it and build it again only if
    # a source changed (none did): no page of the book is read twice.
    for command in commands()[commands().index("make book") + 1:]:
        run = readme_runs.result(command)
        rebuilt = [p.line for p in run.parts if re.search(r"-b html (book|docs) book/_build/"
                                                         r"html(/ja|/reference)?\s*$", p.line)]
        assert rebuilt == [], (command, rebuilt)


def test_the_notebooks_are_the_ones_the_book_wrote(readme_runs: Runs) -> None:
    # `make notebooks` hands out what `make book` exported, byte for byte.
    readme_runs.result("make notebooks-ja")
    copy = readme_runs.copy
    for language, site in (("", "book/_build/html"), ("ja/", "book/_build/html/ja")):
        for edition in ("student", "instructor"):
            made = sorted((copy / f"notebooks/{language}{edition}").glob("*.ipynb"))
            assert made, (language, edition)
            for path in made:
                built = copy / site / "classroom" / edition / path.name
                assert path.read_bytes() == built.read_bytes(), path


def test_the_published_folder_links_every_part_from_its_home_page(readme_runs: Runs) -> None:
    run = readme_runs.result("make site")
    assert run.returncode == 0, run.output[-5000:]
    site = readme_runs.copy / "book" / "_build" / "html"
    for home, parts in (
        ("index.html", ["student/index.html", "pdf/book.pdf", "pdf/book-student.pdf",
                        "classroom/elliptic-pendulum-notebooks-student.zip",
                        "classroom/elliptic-pendulum-notebooks-instructor.zip",
                        "reference/index.html", "ja/index.html"]),
        ("ja/index.html", ["../student/ja/index.html", "../pdf/book-ja.pdf",
                           "../pdf/book-student-ja.pdf",
                           "classroom/elliptic-pendulum-notebooks-student.zip",
                           "../reference/index.html", "../index.html"]),
        ("student/index.html", ["pdf/book-student.pdf",
                                "classroom/elliptic-pendulum-notebooks-student.zip",
                                "reference/index.html", "ja/index.html"]),
    ):
        page = site / home
        html = page.read_text(encoding="utf-8")
        for part in parts:
            assert f'href="{part}"' in html, (home, part)
            assert (page.parent / part).resolve().is_file(), (home, part)
    # The student folder, served alone, holds no solution and no link out of itself.
    student = (site / "student" / "index.html").read_text(encoding="utf-8")
    assert not re.search(r'href="\.\./', student)
    with zipfile.ZipFile(site / "classroom" / "elliptic-pendulum-notebooks-student.zip") as z:
        assert all("instructor" not in name for name in z.namelist())
