"""What a self-check knows about an exercise, and how it answers a student.

An :class:`Exercise` names the values its computational parts ask for (:class:`Value`: a
name the student's answer cell defines, what it is, how close counts as right, and the
:class:`Hint` for each mistake we expect) and a ``reference`` that computes them by a route
other than the one the exercise asks for (an integrator where the exercise asks for the
closed form, a series where it asks for the library, ...). :func:`check` compares and prints,
for each value, either that it is right or what is wrong with it, with the hint of the first
expected mistake it matches: the hint names the mistake, never the value.

A ``reference`` imports what it needs inside its own body: nbgrader's hidden tests
(tools/classroom/nbgrader.py) paste its source into the test cell, where nothing else of this
package exists.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache
from typing import Any

# Exercise label -> Exercise, filled by the chapter modules.
EXERCISES: dict[str, Exercise] = {}
RIGHT = "\u2714"  # check mark
WRONG = "\u2718"  # heavy ballot x


@dataclass(frozen=True)
class Hint:
    """An expected mistake: ``when(answer, expected)`` is true for it, ``message`` says what
    to look at; ``example(expected)`` is an answer that makes it (the tests feed it)."""

    when: Callable[[Any, Any], bool]
    message: str
    example: Callable[[Any], Any]


@dataclass(frozen=True)
class Value:
    """One answer of an exercise: the variable ``name`` the answer cell defines."""

    name: str
    what: str
    kind: type = float
    # Right when |answer - expected| <= rtol |expected| + atol (numbers only).
    rtol: float = 1e-4
    atol: float = 0.0
    hints: tuple[Hint, ...] = ()
    # nbgrader's hidden test is tighter: the instructor's solution must meet it.
    hidden_rtol: float = 1e-8

    def close(self, answer: float, expected: float, rtol: float) -> bool:
        return abs(answer - expected) <= rtol * abs(expected) + self.atol


@dataclass(frozen=True)
class Exercise:
    """The self-check of one exercise (its label in the book)."""

    label: str
    values: tuple[Value, ...] = ()
    reference: Callable[[], dict[str, Any]] | None = None
    # For the parts to prove or explain: one hint (Markdown), shown folded under the
    # student's answer cell; nbgrader grades these parts by hand.
    written: str | None = None
    written_points: int = 2
    tags: tuple[str, ...] = field(default=())

    def __post_init__(self) -> None:
        if self.values and self.reference is None:
            raise ValueError(f"{self.label}: values need a reference")
        if not self.values and self.written is None:
            raise ValueError(f"{self.label}: neither values nor a written part")


def register(*exercises: Exercise) -> None:
    for exercise in exercises:
        if exercise.label in EXERCISES:
            raise ValueError(f"{exercise.label} is registered twice")
        EXERCISES[exercise.label] = exercise


@cache
def expected(label: str) -> dict[str, Any]:
    """The reference values of an exercise (computed once per session)."""
    exercise = EXERCISES[label]
    assert exercise.reference is not None
    return exercise.reference()


def _as_kind(value: Value, answer: Any) -> Any:
    if value.kind is float:
        if isinstance(answer, bool):
            raise TypeError
        result = float(answer)  # a numpy scalar or a 0-d array is fine; an array is not
        if not math.isfinite(result):
            raise ValueError
        return result
    if value.kind is int:
        if isinstance(answer, bool) or float(answer) != int(answer):
            raise TypeError
        return int(answer)
    if value.kind is bool:
        if not isinstance(answer, (bool,)) and type(answer).__name__ != "bool_":
            raise TypeError
        return bool(answer)
    return value.kind(answer)


def judge(value: Value, answer: Any, want: Any) -> tuple[bool, str]:
    """(right, message) for one answer."""
    name = f"`{value.name}`"
    if answer is Ellipsis:
        return False, f"{name} is still `...`: put your answer ({value.what}) in its place."
    try:
        got = _as_kind(value, answer)
    except (TypeError, ValueError, OverflowError):
        shown = type(answer).__name__
        return False, (f"{name} should be {_kind_words(value.kind)} ({value.what}), "
                       f"not the {shown} {answer!r:.60}.")
    if value.kind is float:
        right = value.close(got, want, value.rtol)
    else:
        right = got == want
    if right:
        return True, f"{name} is right."
    for hint in value.hints:
        try:
            matched = bool(hint.when(got, want))
        except (TypeError, ValueError, ArithmeticError):
            matched = False
        if matched:
            return False, f"{name} is not right yet. {hint.message}"
    if value.kind is float:
        if want != 0 and got != 0 and math.copysign(1, got) != math.copysign(1, want):
            return False, f"{name} has the wrong sign."
        if want != 0:
            # Same sign here: for a negative value, "too large" means in magnitude.
            off = (abs(got) - abs(want)) / abs(want)
            size = "too large" if off > 0 else "too small"
            size += " in magnitude" if want < 0 else ""
            return False, f"{name} is {100 * abs(off):.2g}% {size}."
    return False, f"{name} is not right yet: look again at {value.what}."


def _kind_words(kind: type) -> str:
    return {float: "a number", int: "a whole number", bool: "True or False",
            str: "a string"}.get(kind, f"a {kind.__name__}")


def check(label: str, /, **answers: Any) -> bool:
    """Print, for each answer of exercise ``label``, whether it is right (and a hint if not);
    return True when all are. ``check("ex-energy-threshold", v_star=v_star)``."""
    if label not in EXERCISES:
        raise ValueError(f"label must be one of the exercises with a self-check, not {label!r}")
    exercise = EXERCISES[label]
    unknown = set(answers) - {v.name for v in exercise.values}
    if unknown:
        raise TypeError(f"{label} has no answer named {', '.join(sorted(unknown))}")
    want = expected(label)
    lines, ok = [], True
    for value in exercise.values:
        if value.name not in answers:
            right, message = False, f"`{value.name}` is missing: pass {value.name}={value.name}."
        else:
            right, message = judge(value, answers[value.name], want[value.name])
        ok &= right
        lines.append(f"{RIGHT if right else WRONG} {message}")
    if ok:
        lines.append("All right.")
    _show("\n\n".join(lines))
    return ok


def _show(text: str) -> None:
    # In Jupyter, as Markdown, so the formulas of the messages are typeset; else as text.
    try:
        from IPython import get_ipython
        from IPython.display import Markdown, display
    except ImportError:
        get_ipython = None  # type: ignore[assignment]
    if get_ipython is not None and get_ipython() is not None:
        display(Markdown(text))
    else:
        print(text)
