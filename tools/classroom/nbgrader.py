"""The classroom as an nbgrader course folder: one assignment per chapter with exercises.

Made from the instructor notebooks that the book build exports (export.py: each solution's
cells carry ``metadata.classroom.solution = <exercise label>``, and a self-check cell follows),
so no exercise is written twice. Under each exercise of a chapter's assignment:

- its results (tools/classroom/selfcheck): an answer cell holding the worked solution's code
  between ``### BEGIN SOLUTION`` and ``### END SOLUTION``, then a locked, autograded test cell
  worth one point per result: the visible test is the student's self-check, the hidden tests
  (``### BEGIN HIDDEN TESTS``) paste the self-check's independent reference computation and
  hold the results to its tighter ``hidden_rtol``;
- what it asks to prove or explain: the folded hint, and a manually graded Markdown answer
  cell (``written_points``) holding the worked solution, the grader's model answer, which
  ``nbgrader generate_assignment`` replaces by "YOUR ANSWER HERE" in the release.

nbgrader's own commands read the folder (tests/book/test_nbgrader.py runs them): the layout
is ``nbgrader_config.py`` and ``source/<assignment>/<assignment>.ipynb``, with the
``selfcheck`` package beside each notebook.

Usage (``make nbgrader``)::

    python -m tools.classroom.nbgrader book/_build/html/classroom/instructor book/_build/nbgrader
"""

from __future__ import annotations

import argparse
import ast
import builtins
import inspect
import re
import shutil
import sys
import textwrap
from pathlib import Path

import nbformat

from elliptic_pendulum import selfcheck

COURSE_ID = "elliptic-pendulum"
CONFIG = '''\
# nbgrader's configuration of the course folder (written by tools/classroom/nbgrader.py).
# Run nbgrader's commands in this folder; the gradebook is gradebook.db here.
c = get_config()  # noqa: F821
c.CourseDirectory.course_id = "{course}"
# Each assignment's folder holds its notebook and the self-check package it imports.
c.CourseDirectory.root = "."
# After a cell's reply, the kernel's "idle" can reach a busy grading machine later than
# the 4 s nbgrader waits by default, and nbgrader then fails the whole notebook (seen once
# in this project's tests); a cell's own limit stays nbgrader's 30 s.
c.Execute.iopub_timeout = 30
'''


def _nbgrader(cell: nbformat.NotebookNode, grade_id: str, *, solution: bool, grade: bool,
              locked: bool, points: int = 0) -> nbformat.NotebookNode:
    meta = {"grade": grade, "grade_id": grade_id, "locked": locked, "schema_version": 3,
            "solution": solution, "task": False}
    if grade:
        meta["points"] = points
    cell.metadata["nbgrader"] = meta
    cell.metadata.pop("classroom", None)
    return cell


def hidden_tests(label: str) -> str:
    """The hidden part of an exercise's test cell: its reference, pasted, and the results
    held to it at ``hidden_rtol``."""
    exercise = selfcheck.EXERCISES[label]
    assert exercise.reference is not None
    source = textwrap.dedent(inspect.getsource(exercise.reference))
    # Inside a function of its own, so that the reference's name cannot hide a result of
    # the same name (a reference "half" for the result "half").
    lines = ["import math", "", "", "def _reference():",
             textwrap.indent(source.rstrip(), "    "), "",
             f"    return {exercise.reference.__name__}()", "", "",
             "_expected = _reference()"]
    for v in exercise.values:
        if v.kind is float:
            lines.append(
                f"assert math.isclose(float({v.name}), _expected[{v.name!r}], "
                f"rel_tol={v.hidden_rtol!r}, abs_tol={v.atol!r}), {v.name!r}")
        else:
            lines.append(f"assert {v.kind.__name__}({v.name}) == _expected[{v.name!r}], "
                         f"{v.name!r}")
    return "\n".join(lines)


SOLUTION_HEADING = re.compile(r'^\s*(<a id="[^"]*"></a>\s*)*#+ [^\n]*\n*')


def _exercise_cells(label: str, solution: list[nbformat.NotebookNode]) -> tuple[list, int, int]:
    """The cells that replace one worked solution; and its autograded and manual points."""
    exercise = selfcheck.EXERCISES[label]
    code = [c for c in solution if c.cell_type == "code"]
    text = [c.source for c in solution if c.cell_type == "markdown"]
    # The first Markdown cell opens with the solution's anchor and its "#### Solution to
    # Exercise N" heading: the model answer is what follows.
    if text:
        text[0] = SOLUTION_HEADING.sub("", text[0], count=1)
    cells, auto, manual = [], 0, 0
    if exercise.values:
        names = ", ".join(f"`{v.name}` ({v.what})" for v in exercise.values)
        cells.append(nbformat.v4.new_markdown_cell(
            f"**Your results.** In the cell below, compute and leave {names}. The test "
            "cell under it runs the self-check and nbgrader's hidden tests."))
        body = "\n\n".join(c.source for c in code)
        cells.append(_nbgrader(nbformat.v4.new_code_cell(
            "# " + ", ".join(v.name for v in exercise.values) + "\n### BEGIN SOLUTION\n"
            + body + "\n### END SOLUTION"), f"{label}-answer",
            solution=True, grade=False, locked=False))
        args = ", ".join(f"{v.name}={v.name}" for v in exercise.values)
        auto = len(exercise.values)
        cells.append(_nbgrader(nbformat.v4.new_code_cell(
            f"from elliptic_pendulum.selfcheck import check\n\nassert check({label!r}, {args}), "
            "\"the self-check's message says what is not right yet\"\n"
            "### BEGIN HIDDEN TESTS\n" + hidden_tests(label) + "\n### END HIDDEN TESTS"),
            f"{label}-tests", solution=False, grade=True, locked=True, points=auto))
    if exercise.written is not None:
        manual = exercise.written_points
        model = "\n\n".join(t for t in text if t.strip())
        if not exercise.values and code:  # the solution's computations, for the grader
            model += "".join(f"\n\n```python\n{c.source}\n```" for c in code)
        cells.append(_nbgrader(nbformat.v4.new_markdown_cell(
            model.strip() or "(no model answer)"), f"{label}-written",
            solution=True, grade=True, locked=False, points=manual))
    return cells, auto, manual


def _names(source: str) -> tuple[set[str], set[str]]:
    """(names a cell defines, names it reads and does not define); a cell that is not plain
    Python (a magic) defines and reads nothing."""
    try:
        tree = ast.parse(source)
    except SyntaxError:
        return set(), set()
    stored: set[str] = set()
    loaded: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            (stored if isinstance(node.ctx, (ast.Store, ast.Del)) else loaded).add(node.id)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            stored.add(node.name)
        elif isinstance(node, ast.arg):
            stored.add(node.arg)
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            stored |= {(a.asname or a.name).split(".")[0] for a in node.names}
    return stored, loaded - stored - set(dir(builtins))


def exercises_only(cells: list[nbformat.NotebookNode]) -> list[nbformat.NotebookNode]:
    """The chapter's first cell (what it is), its first code cell (the imports every later
    cell needs), the earlier code cells that the exercises' solutions build on (a name they
    read and do not define, found by its last definition, and what that cell reads in
    turn), and its "Exercises" section: an assignment is the exercises; the chapter itself
    is read in the book (and runs, whole, in the classroom notebooks)."""
    heading = re.compile(r"^## Exercises\s*$", re.M)
    start = next((k for k, c in enumerate(cells)
                  if c.cell_type == "markdown" and heading.search(c.source)), None)
    if start is None:
        raise ValueError("the notebook has solutions but no '## Exercises' section")
    code = [k for k, c in enumerate(cells[:start]) if c.cell_type == "code"]
    setup = code[0]
    wanted: set[str] = set()
    defined = set(_names(cells[setup].source)[0])
    for c in cells[start:]:
        if c.cell_type == "code":
            stores, loads = _names(c.source)
            wanted |= loads
            defined |= stores
    wanted -= defined
    needed: list[int] = []
    for k in reversed(code[1:]):
        stores, loads = _names(cells[k].source)
        if stores & wanted:
            needed.insert(0, k)
            wanted = (wanted - stores) | (loads - defined)
    found = heading.search(cells[start].source)
    assert found is not None  # the cell was chosen for its heading
    first = nbformat.v4.new_markdown_cell(cells[start].source[found.start():])
    first.metadata = cells[start].metadata
    kept = [cells[0], cells[setup]]
    if needed:
        kept.append(nbformat.v4.new_markdown_cell(
            "The chapter's cells that the exercises build on (run them first):"))
        for k in needed:
            cell = cells[k]
            cell.metadata.setdefault("jupyter", {})["source_hidden"] = True
            kept.append(cell)
    return [*kept, first, *cells[start + 1:]]


def assignment(instructor: nbformat.NotebookNode, name: str) -> tuple[nbformat.NotebookNode,
                                                                       int, int]:
    """One chapter's instructor notebook as an nbgrader source notebook, with its points."""
    out: list[nbformat.NotebookNode] = []
    auto = manual = 0
    i, cells = 0, exercises_only(instructor.cells)
    while i < len(cells):
        label = cells[i].metadata.get("classroom", {}).get("solution")
        if label is None:
            if not cells[i].metadata.get("classroom", {}).get("self_check"):
                out.append(cells[i])
            i += 1
            continue
        solution = []
        while i < len(cells) and cells[i].metadata.get("classroom", {}).get("solution") == label:
            solution.append(cells[i])
            i += 1
        if label in selfcheck.EXERCISES:
            more, a, m = _exercise_cells(label, solution)
            out += more
            auto, manual = auto + a, manual + m
    out[0] = nbformat.v4.new_markdown_cell(out[0].source.replace(
        "(instructor edition)", f"the exercises as nbgrader assignment `{name}`: {auto} "
        f"points graded by its tests, {manual} by hand", 1))
    nb = nbformat.v4.new_notebook(metadata=instructor.metadata)
    nb.cells = out
    for k, c in enumerate(nb.cells):
        c["id"] = f"cell-{k}"
    return nb, auto, manual


def write_course(instructor_dir: Path, out: Path) -> dict[str, tuple[int, int]]:
    """out/nbgrader_config.py and out/source/<NN-page>/<NN-page>.ipynb for every chapter
    whose notebook has a solution; return {assignment: (autograded, manual points)}."""
    shutil.rmtree(out / "source", ignore_errors=True)
    out.mkdir(parents=True, exist_ok=True)
    (out / "nbgrader_config.py").write_text(CONFIG.format(course=COURSE_ID), encoding="utf-8")
    points = {}
    for path in sorted(instructor_dir.glob("*.ipynb")):
        instructor = nbformat.read(path, as_version=4)
        if not any(c.metadata.get("classroom", {}).get("solution") for c in instructor.cells):
            continue
        name = path.stem
        nb, auto, manual = assignment(instructor, name)
        folder = out / "source" / name
        folder.mkdir(parents=True)
        nbformat.write(nb, folder / f"{name}.ipynb")
        points[name] = (auto, manual)
    if not points:
        raise ValueError(f"no instructor notebook with solutions in {instructor_dir}")
    return points


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("instructor", type=Path, help="the instructor notebooks' folder")
    parser.add_argument("out", type=Path, help="the course folder to write")
    args = parser.parse_args(argv)
    points = write_course(args.instructor, args.out)
    for name, (auto, manual) in points.items():
        print(f"{name}: {auto} points autograded, {manual} by hand")
    total = [sum(p[k] for p in points.values()) for k in (0, 1)]
    print(f"wrote {args.out}: {len(points)} assignments, {total[0]} points autograded, "
          f"{total[1]} by hand")
    return 0


if __name__ == "__main__":
    sys.exit(main())
