"""The exercises' self-checks (elliptic_pendulum.selfcheck) on wrong answers, and their registry
against the book.

Right answers are the instructor's: tests/book/test_notebooks.py runs every instructor
notebook, where a self-check cell follows each worked solution and must say it is right
(the solution and the self-check's reference are two independent computations). Here, the
wrong answers: each hint's own example must bring out that hint, a value 3% off the
reference must be called 3% off, and an untouched answer cell (``...``) must say so.
"""

from __future__ import annotations

import math
import re

import pytest

from elliptic_pendulum import selfcheck
from tests.conftest import BOOK

VALUES = [(label, value) for label, ex in sorted(selfcheck.EXERCISES.items())
          for value in ex.values]
HINTS = [(label, value, i) for label, value in VALUES for i in range(len(value.hints))]


def _said(capsys: pytest.CaptureFixture[str]) -> str:
    return capsys.readouterr().out


def _exercises_of_the_pages() -> dict[str, str]:
    """label -> page, from the {exercise} directives of the book's sources."""
    found = {}
    for path in sorted(BOOK.glob("*.md")):
        text = path.read_text(encoding="utf-8")
        for m in re.finditer(r"^:{3,}\{exercise\}[^\n]*\n:label: (\S+)", text, re.M):
            found[m[1]] = path.stem
    return found


def test_every_exercise_of_the_book_has_a_self_check_in_its_chapters_module() -> None:
    # The labels come from the book's pages, the registry from the modules: one module per
    # chapter, named after its page.
    exercises = _exercises_of_the_pages()
    assert exercises, "no exercise found in the book"
    assert set(selfcheck.EXERCISES) == set(exercises)
    for label, exercise in selfcheck.EXERCISES.items():
        module = exercise.reference.__module__ if exercise.reference else None
        if module is not None:
            assert module.rsplit(".", 1)[1] == exercises[label], label


def test_references_give_every_value_of_its_kind() -> None:
    for label, exercise in selfcheck.EXERCISES.items():
        if not exercise.values:
            continue
        got = selfcheck.expected(label)
        assert set(got) == {v.name for v in exercise.values}, label
        for value in exercise.values:
            assert isinstance(got[value.name], value.kind), (label, value.name)
            if value.kind is float:
                assert math.isfinite(got[value.name]), (label, value.name)


@pytest.mark.parametrize(("label", "value", "i"), HINTS,
                         ids=[f"{lab}-{v.name}-{i}" for lab, v, i in HINTS])
def test_each_hint_answers_its_own_mistake(label, value, i, capsys) -> None:
    hint = value.hints[i]
    wrong = hint.example(selfcheck.expected(label)[value.name])
    assert selfcheck.check(label, **{value.name: wrong}) is False
    said = _said(capsys)
    assert hint.message in said, said
    # Hints name the mistake, not the value: the reference's digits are not in the message.
    want = selfcheck.expected(label)[value.name]
    if value.kind is float and want not in (0.0, 1.0):
        assert f"{want:.4g}" not in hint.message


@pytest.mark.parametrize(("label", "value"), VALUES, ids=[f"{lab}-{v.name}" for lab, v in VALUES])
def test_a_value_three_percent_off_is_called_so(label, value, capsys) -> None:
    if value.kind is not float:
        pytest.skip("not a number")
    want = selfcheck.expected(label)[value.name]
    wrong = want * 1.03 if want else 0.03
    assert selfcheck.check(label, **{value.name: wrong}) is False
    said = _said(capsys)
    assert f"`{value.name}`" in said and "\u2718" in said
    if not any(h.when(wrong, want) for h in value.hints) and want:
        assert "3% too large" in said, said


@pytest.mark.parametrize(("label", "value"), VALUES, ids=[f"{lab}-{v.name}" for lab, v in VALUES])
def test_an_untouched_answer_cell_is_told_to_answer(label, value, capsys) -> None:
    assert selfcheck.check(label, **{value.name: ...}) is False
    assert re.search(rf"`{value.name}` is still `\.\.\.`", _said(capsys))


def test_the_reference_itself_is_right(capsys) -> None:
    # The check accepts what its reference computes (a harness test: the comparison,
    # not the reference, is what is tested here).
    for label, exercise in selfcheck.EXERCISES.items():
        if exercise.values:
            assert selfcheck.check(label, **selfcheck.expected(label)), label
    assert "\u2718" not in _said(capsys)


def test_bad_use_is_a_clear_error() -> None:
    with pytest.raises(ValueError, match="label must be one of"):
        selfcheck.check("ex-no-such-exercise", x=1.0)
    label = next(lab for lab, ex in selfcheck.EXERCISES.items() if ex.values)
    with pytest.raises(TypeError, match="has no answer named"):
        selfcheck.check(label, no_such_name=1.0)


def test_the_package_shares_no_line_with_a_worked_solution() -> None:
    # It ships in the student bundle: the snippets by which tests/book/test_site.py finds a
    # solution in a file (its code lines and prose) must not be in it.
    from pathlib import Path

    from tests.book.test_site import _squash, solution_snippets

    text = _squash("\n".join(p.read_text(encoding="utf-8")
                             for p in sorted(Path(selfcheck.__file__).parent.rglob("*.py"))))
    text += _squash("\n".join(e.written or "" for e in selfcheck.EXERCISES.values()))
    leaks = {s: sorted(p for p in pieces if p in text)
             for s, pieces in solution_snippets().items()}
    assert {s: p for s, p in leaks.items() if p} == {}
