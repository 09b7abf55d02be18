"""What a self-check knows about an exercise, and how it answers a student.

An :class:`Exercise` names the values its computational parts ask for (:class:`Value`: a
name the student's answer cell defines, what it is, how close counts as right, and the
:class:`Hint` for each mistake we expect) and a ``reference`` that computes them by a route
other than the one the exercise asks for (an integrator where the exercise asks for the
closed form, a series where it asks for the library, ...). :func:`check` compares and prints,
for each value, either that it is right or what is wrong with it, with the hint of the first
expected mistake it matches: the hint names the mistake, never the value.

It says so in the language it is asked for (``language="ja"``), else in the one the
environment names as gettext reads it (the first of LANGUAGE, LC_ALL, LC_MESSAGES and LANG
that is set; ``ja_JP.UTF-8`` names Japanese), else in English. Nothing global is set: each
call chooses. English is written here, another language in its own module, ``_ja`` for
Japanese, which translates this module's sentences and the exercises' texts (a table per
chapter, ``_ja/<chapter>.py``).

A ``reference`` imports what it needs inside its own body: nbgrader's hidden tests (the
repository's tools/classroom/nbgrader.py) paste its source into the test cell, where nothing
else of this package exists.
"""

from __future__ import annotations

import importlib
import importlib.util
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache
from typing import Any

from .. import _i18n

# Exercise label -> Exercise, filled by the chapter modules.
EXERCISES: dict[str, Exercise] = {}
RIGHT = "\u2714"  # check mark
WRONG = "\u2718"  # heavy ballot x


@dataclass(frozen=True)
class Hint:
    """An expected mistake, what to look at, and an answer that makes it.

    ``when(answer, expected)`` is true for it, ``message`` says what to look at;
    ``example(expected)`` is an answer that makes it (the tests feed it).
    """

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
    """Return the reference values of an exercise (computed once per session)."""
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


def judge(value: Value, answer: Any, want: Any, *,
          language: str | None = None) -> tuple[bool, str]:
    """Return (right, message) for one answer.

    In ``language``; by default the environment's (see :func:`environment_language`).
    """
    texts = _texts(language or environment_language())
    say = texts.templates
    what = texts.translate(value.what)
    name = f"`{value.name}`"
    if answer is Ellipsis:
        return False, say["still"].format(name=name, what=what)
    try:
        got = _as_kind(value, answer)
    except (TypeError, ValueError, OverflowError):
        return False, say["kind"].format(name=name, kind=texts.kind_words(value.kind), what=what,
                                         type=type(answer).__name__, answer=f"{answer!r:.60}")
    if value.kind is float:
        right = value.close(got, want, value.rtol)
    else:
        right = got == want
    if right:
        return True, say["right"].format(name=name)
    for hint in value.hints:
        try:
            matched = bool(hint.when(got, want))
        except (TypeError, ValueError, ArithmeticError):
            matched = False
        if matched:
            return False, say["hint"].format(name=name, hint=texts.translate(hint.message))
    if value.kind is float:
        if want != 0 and got != 0 and math.copysign(1, got) != math.copysign(1, want):
            return False, say["sign"].format(name=name)
        if want != 0:
            # Same sign here: for a negative value, "too large" means in magnitude.
            off = (abs(got) - abs(want)) / abs(want)
            size = "too_large" if off > 0 else "too_small"
            size += "_in_magnitude" if want < 0 else ""
            return False, say[size].format(name=name, percent=f"{100 * abs(off):.2g}")
    return False, say["look_again"].format(name=name, what=what)


def check(label: str, /, *, language: str | None = None, **answers: Any) -> bool:
    """Print whether each answer of exercise ``label`` is right; return True when all are.

    A wrong answer gets a hint that names the likely mistake, never the value:
    ``check("ex-energy-threshold", v_star=v_star)``; in Japanese,
    ``check("ex-energy-threshold", language="ja", v_star=v_star)``.
    """
    ok, text = report(label, answers, language=language)
    _show(text)
    return ok


def report(label: str, answers: dict[str, Any], *,
           language: str | None = None) -> tuple[bool, str]:
    """Return whether all answers are right, and what :func:`check` prints (Markdown)."""
    if label not in EXERCISES:
        raise ValueError(f"label must be one of the exercises with a self-check, not {label!r}")
    exercise = EXERCISES[label]
    unknown = set(answers) - {v.name for v in exercise.values}
    if unknown:
        raise TypeError(f"{label} has no answer named {', '.join(sorted(unknown))}")
    texts = _texts(language or environment_language())
    want = expected(label)
    lines, ok = [], True
    for value in exercise.values:
        if value.name not in answers:
            right, message = False, texts.templates["missing"].format(var=value.name)
        else:
            right, message = judge(value, answers[value.name], want[value.name],
                                   language=texts.language)
        ok &= right
        lines.append(f"{RIGHT if right else WRONG} {message}")
    if ok:
        lines.append(texts.templates["all_right"])
    return ok, "\n\n".join(lines)


# What judge and check say in English; another language's module (_ja for "ja") has the
# same keys and placeholders, and MESSAGES for the exercises' own texts.
ENGLISH = {
    "still": "{name} is still `...`: put your answer ({what}) in its place.",
    "kind": "{name} should be {kind} ({what}), not the {type} {answer}.",
    "right": "{name} is right.",
    "hint": "{name} is not right yet. {hint}",
    "sign": "{name} has the wrong sign.",
    "too_large": "{name} is {percent}% too large.",
    "too_small": "{name} is {percent}% too small.",
    "too_large_in_magnitude": "{name} is {percent}% too large in magnitude.",
    "too_small_in_magnitude": "{name} is {percent}% too small in magnitude.",
    "look_again": "{name} is not right yet: look again at {what}.",
    "missing": "`{var}` is missing: pass {var}={var}.",
    "all_right": "All right.",
}
ENGLISH_KINDS = {float: "a number", int: "a whole number", bool: "True or False",
                 str: "a string"}
ENGLISH_OTHER_KIND = "a {kind}"
# Where gettext looks for the language of messages, in its order (the package's one list).
LANGUAGE_VARIABLES = _i18n.LANGUAGE_VARIABLES


def environment_language(environ: dict[str, str] | None = None) -> str:
    """Return the language of the messages as gettext would choose it from the environment.

    The first of LANGUAGE (a colon-separated list), LC_ALL, LC_MESSAGES and LANG that is set
    decides: its first entry with self-check messages here wins ("ja_JP.UTF-8" is "ja");
    "C", "POSIX" or an entry with none gives English. The package's rule
    (``elliptic_pendulum._i18n.environment_language``), with the self-checks' languages.

    >>> environment_language({"LANG": "ja_JP.UTF-8"}), environment_language({})
    ('ja', 'en')
    >>> environment_language({"LANGUAGE": "fr:ja", "LANG": "en_US.UTF-8"})
    'ja'
    """
    return _i18n.environment_language(environ, _has_messages)


def _has_messages(language: str) -> bool:
    return importlib.util.find_spec(f"._{language}", __package__) is not None


@dataclass(frozen=True)
class _Texts:
    language: str
    templates: dict[str, str]
    kinds: dict[type, str]
    other_kind: str
    messages: dict[str, str] = field(default_factory=dict)

    def translate(self, text: str) -> str:
        # An exercise changed since the translation: its English text beats no message.
        return self.messages.get(text, text)

    def kind_words(self, kind: type) -> str:
        return self.kinds.get(kind, self.other_kind.format(kind=kind.__name__))


@cache
def _texts(language: str) -> _Texts:
    if language == "en":
        # English is this module's own: a package without _<language>.py modules works.
        return _Texts("en", ENGLISH, ENGLISH_KINDS, ENGLISH_OTHER_KIND)
    if not language.isidentifier():
        raise ValueError(f"no self-check messages in the language {language!r}")
    try:
        module = importlib.import_module(f"._{language}", __package__)
    except ModuleNotFoundError:
        raise ValueError(f"no self-check messages in the language {language!r}") from None
    return _Texts(language, module.TEMPLATES, module.KINDS, module.OTHER_KIND, module.MESSAGES)


def _show(text: str) -> None:
    # In Jupyter, as Markdown, so the formulas of the messages are typeset; else as text.
    try:
        from IPython import get_ipython
        from IPython.display import Markdown, display
    except ImportError:
        get_ipython = None
    if get_ipython is not None and get_ipython() is not None:
        display(Markdown(text))
    else:
        print(text)
