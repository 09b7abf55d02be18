"""The nbgrader course folder (tools/classroom/nbgrader.py, `make nbgrader`), run through
nbgrader's own commands: the expectations are nbgrader's, not ours.

From this session's book build (its instructor notebooks), the course is written into a
temporary folder with its own sqlite gradebook. nbgrader runs in a venv of its own, as on a
teacher's JupyterHub: nbgrader from the package index and the instructor bundle installed by
its README's command (the project's venv stays without it: nbgrader brings ipywidgets, which
would change what the book's cells draw). Then, per assignment:

* ``nbgrader generate_assignment`` releases it, and the release holds no solution, no hidden
  test and no model answer;
* ``nbgrader autograde`` of the instructor's own notebook (the source, submitted as the
  student "solutions") gives full marks on every autograded cell, and of the untouched
  release (the student "blank") none.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from concurrent.futures import Future
from pathlib import Path

import nbformat
import pytest

from tests.book._buildcheck import BookIndex
from tools.classroom import nbgrader as course

pytestmark = pytest.mark.slow


GRADES = """
import json, sys
from nbgrader.api import Gradebook
db, course, names = sys.argv[1], sys.argv[2], sys.argv[3:]
out = {}
with Gradebook(db, course) as gb:
    for name in names:
        for student in ("solutions", "blank"):
            sub = gb.find_submission_notebook(name, name, student)
            # The autograded cells (nbgrader also scores an untouched written answer 0).
            out.setdefault(name, {})[student] = {
                g.name: (g.score, g.max_score) for g in sub.grades if g.cell.cell_type == "code"}
print(json.dumps(out))
"""


def make_grader_venv(built_book: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A fresh venv with nbgrader and the instructor bundle (its README's install command)."""
    import zipfile

    from tests.book.test_notebooks import readme_install
    from tools.classroom import bundle

    unzipped = tmp_path_factory.mktemp("grader-bundle")
    archive = built_book / "classroom" / f"{bundle.bundle_name('instructor')}.zip"
    with zipfile.ZipFile(archive) as z:
        z.extractall(unzipped)
    (folder,) = unzipped.iterdir()
    venv = tmp_path_factory.mktemp("grader-venv") / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    python = venv / "bin" / "python"
    argv = readme_install(folder)
    assert argv[:4] == ["python", "-m", "pip", "install"], argv
    proc = subprocess.run([str(python), *argv[1:4], "--quiet", "nbgrader>=0.9", *argv[4:]],
                          cwd=folder, capture_output=True, text=True, timeout=1800)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return venv


def _nbgrader(venv: Path, folder: Path, *args: str) -> subprocess.CompletedProcess[str]:
    # nbgrader runs the `alembic` script of its environment to create the gradebook, and
    # the notebooks' kernel is its interpreter's: its bin folder first on the PATH.
    env = dict(os.environ, PATH=str(venv / "bin") + os.pathsep + os.environ.get("PATH", ""))
    env.pop("VIRTUAL_ENV", None)
    proc = subprocess.run([str(venv / "bin" / "python"), "-m", "nbgrader", *args], cwd=folder,
                          env=env, capture_output=True, text=True, timeout=1800)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-5000:]
    return proc


def _points(folder: Path) -> dict[str, tuple[int, int]]:
    """assignment -> (autograded points, points graded by hand), from nbgrader's metadata."""
    points = {}
    for path in sorted((folder / "source").glob("*/*.ipynb")):
        cells = nbformat.read(path, as_version=4).cells
        graded = [(c.cell_type, c.metadata["nbgrader"].get("points", 0)) for c in cells
                  if c.metadata.get("nbgrader", {}).get("grade")]
        points[path.stem] = (sum(n for kind, n in graded if kind == "code"),
                             sum(n for kind, n in graded if kind == "markdown"))
    return points


def grade(build: Path, tmp_path_factory: pytest.TempPathFactory) -> dict:
    """The course that `make nbgrader` wrote in ``build``/nbgrader, released and autograded by
    nbgrader, in a venv of its own with the instructor bundle of ``build``/html."""
    grader_venv = make_grader_venv(build / "html", tmp_path_factory)
    folder = tmp_path_factory.mktemp("nbgrader") / "course"
    shutil.copytree(build / "nbgrader", folder)
    points = _points(folder)
    for name in points:
        _nbgrader(grader_venv, folder, "generate_assignment", name, "--force")
        for student, origin in (("solutions", "source"), ("blank", "release")):
            target = folder / "submitted" / student / name
            shutil.copytree(folder / origin / name, target)
        # Both submissions in one run (each student's notebook in a kernel of its own).
        _nbgrader(grader_venv, folder, "autograde", name, "--create", "--force")
    proc = subprocess.run(
        [str(grader_venv / "bin" / "python"), "-c", GRADES, f"sqlite:///{folder / 'gradebook.db'}",
         course.COURSE_ID, *points], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    scores = json.loads(proc.stdout)
    return {"folder": folder, "points": points, "scores": scores, "venv": grader_venv}


@pytest.fixture(scope="session")
def graded(nbgrader_job: Future) -> dict:
    # Run beside the browser survey (tests/book/conftest.py), or now if it did not run.
    return dict(nbgrader_job.result())




def test_one_assignment_per_chapter_with_exercises(graded: dict, built_book: Path,
                                                   index: BookIndex) -> None:
    from tests.conftest import BOOK

    with_exercises = {index.files[p].removesuffix(".ipynb") for p in index.exported
                      if ":::{exercise}" in (BOOK / f"{p}.md").read_text(encoding="utf-8")}
    assert set(graded["points"]) == with_exercises
    assert all(auto + manual > 0 for auto, manual in graded["points"].values())


def test_the_release_holds_no_solution_hidden_test_or_model_answer(graded: dict) -> None:
    folder = graded["folder"]
    for name in graded["points"]:
        source = nbformat.read(folder / "source" / name / f"{name}.ipynb", as_version=4)
        text = (folder / "release" / name / f"{name}.ipynb").read_text(encoding="utf-8")
        for marker in ("BEGIN SOLUTION", "END SOLUTION", "BEGIN HIDDEN TESTS", "_expected"):
            assert marker not in text, (name, marker)
        release = nbformat.read(folder / "release" / name / f"{name}.ipynb", as_version=4)
        for cell in source.cells:
            meta = cell.metadata.get("nbgrader", {})
            if meta.get("solution") and cell.cell_type == "markdown":
                # The model answer's longest line must not survive into the release.
                longest = max(cell.source.splitlines(), key=len)
                assert longest not in text, (name, longest[:80])
        stubs = [c.source for c in release.cells
                 if c.metadata.get("nbgrader", {}).get("solution")]
        assert stubs and all("YOUR CODE HERE" in s or "YOUR ANSWER HERE" in s for s in stubs)
        # The self-checks come with the installed package: nothing is copied beside it.
        assert sorted(p.name for p in (folder / "release" / name).iterdir()) == [f"{name}.ipynb"]


def test_autograde_gives_the_solutions_full_marks_and_the_blank_release_none(
        graded: dict) -> None:
    total = 0
    for name, by_student in graded["scores"].items():
        solutions, blank = by_student["solutions"], by_student["blank"]
        assert solutions.keys() == blank.keys()
        for cell, (score, most) in solutions.items():
            assert most > 0 and score == most, (name, cell, score, most)
            assert blank[cell][0] == 0, (name, cell, blank[cell])
            total += 1
    auto = sum(a for a, _ in graded["points"].values())
    assert total > 0 and auto == sum(
        most for s in graded["scores"].values() for _, most in s["solutions"].values())
    print(json.dumps({"assignments": len(graded["points"]), "autograded cells": total,
                      "autograded points": auto,
                      "manual points": sum(m for _, m in graded["points"].values())}))


SETTING = """
import sys
from nbgrader.preprocessors import Execute
from traitlets.config.loader import PyFileConfigLoader
config = PyFileConfigLoader("nbgrader_config.py", path=sys.argv[1]).load_config()
print(Execute().iopub_timeout, Execute(config=config).iopub_timeout)
"""


def test_nbgrader_reads_the_course_s_wait_for_a_kernel_s_output(graded: dict) -> None:
    """The course folder's config, as nbgrader's own loader and class read it, waits 30 s
    for a kernel's output after a cell (nbgrader's default, 4 s, once failed a notebook on
    a busy machine); a misspelt class or setting would leave the default."""
    proc = subprocess.run([str(graded["venv"] / "bin" / "python"), "-c", SETTING,
                           str(graded["folder"])], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr[-3000:]
    default, course_value = map(int, proc.stdout.split())
    assert default < course_value == 30
