"""The self-checks in Japanese (elliptic_pendulum/selfcheck/_ja), and English unchanged.

Asked for Japanese (``language="ja"``, as the Japanese notebooks ask, or an environment whose
LANGUAGE, LC_ALL, LC_MESSAGES or LANG names it), judge and check must say everything in
Japanese: the exercises' texts through MESSAGES, the core's sentences through TEMPLATES.
Otherwise they must say exactly what they said before the package had languages, and not
even import _ja.
"""

from __future__ import annotations

import importlib
import math
import os
import pkgutil
import re
import string
import subprocess
import sys
from collections import Counter
from pathlib import Path
from typing import Any

import pytest

from elliptic_pendulum import selfcheck
from elliptic_pendulum.selfcheck import _core, _ja
from tests.ja_text import GETTEXT_ENVIRONMENTS

VALUES = [(label, value) for label, ex in sorted(selfcheck.EXERCISES.items())
          for value in ex.values]
HINTS = [(label, value, i) for label, value in VALUES for i in range(len(value.hints))]
# The formulas, names and MyST roles a translation must carry over as they are; a role first,
# so that its backticked target is not taken for a name.
SPAN = re.compile(r"\{[\w:-]+\}`[^`]*`|`[^`]*`|\$[^$]*\$")
JAPANESE = re.compile(r"[\u3040-\u30ff\u4e00-\u9fff]")


def _texts_of_exercises() -> set[str]:
    return {text for _, value in VALUES for text in (value.what, *(h.message for h in value.hints))}


def _placeholders(template: str) -> Counter[str]:
    return Counter(field for _, field, _, _ in string.Formatter().parse(template)
                   if field is not None)


def _english_fragments() -> list[str]:
    # The literal words of each English template, between its placeholders: none of them
    # may be left in a Japanese message.
    found = []
    for template in (*_core.ENGLISH.values(), *_core.ENGLISH_KINDS.values()):
        for literal, _, _, _ in string.Formatter().parse(template):
            words = literal.strip(" .:()")
            if len(words) >= 4:
                found.append(words)
    return found


# --- English as before -------------------------------------------------------------------
# The reference: judge, _kind_words and check's sentences copied from _core.py as they were
# before the package had languages (the English templates of today, written out as
# f-strings), so that any change to what an English notebook prints fails here.

def _kind_words_before(kind: type) -> str:
    return {float: "a number", int: "a whole number", bool: "True or False",
            str: "a string"}.get(kind, f"a {kind.__name__}")


def _judge_before(value: selfcheck.Value, answer: Any, want: Any) -> tuple[bool, str]:
    name = f"`{value.name}`"
    if answer is Ellipsis:
        return False, f"{name} is still `...`: put your answer ({value.what}) in its place."
    try:
        got = _core._as_kind(value, answer)
    except (TypeError, ValueError, OverflowError):
        shown = type(answer).__name__
        return False, (f"{name} should be {_kind_words_before(value.kind)} ({value.what}), "
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
            off = (abs(got) - abs(want)) / abs(want)
            size = "too large" if off > 0 else "too small"
            size += " in magnitude" if want < 0 else ""
            return False, f"{name} is {100 * abs(off):.2g}% {size}."
    return False, f"{name} is not right yet: look again at {value.what}."


def _report_before(label: str, answers: dict[str, Any]) -> tuple[bool, str]:
    want = selfcheck.expected(label)
    lines, ok = [], True
    for value in selfcheck.EXERCISES[label].values:
        if value.name not in answers:
            right, message = False, f"`{value.name}` is missing: pass {value.name}={value.name}."
        else:
            right, message = _judge_before(value, answers[value.name], want[value.name])
        ok &= right
        lines.append(f"{'✔' if right else '✘'} {message}")
    if ok:
        lines.append("All right.")
    return ok, "\n\n".join(lines)


def _wrong_answers(value: selfcheck.Value, want: Any) -> list[Any]:
    # Every branch of judge: each hint's example, the untouched cell, an answer of the wrong
    # kind, and (numbers) off by a few percent either way and of the wrong sign.
    answers: list[Any] = [h.example(want) for h in value.hints]
    answers += [..., "abc", [1.0, 2.0], None]
    if value.kind is float:
        answers += [want * 1.03, want * 0.97, -want, want + 0.5, float("nan"), 0.0, want]
    elif value.kind is int:
        answers += [want + 1, want - 1, 2.5, want]
    elif value.kind is bool:
        answers += [not want, 1, want]
    return answers


@pytest.mark.parametrize(("label", "value"), VALUES, ids=[f"{lab}-{v.name}" for lab, v in VALUES])
def test_english_judge_says_what_it_said_before(label, value) -> None:
    want = selfcheck.expected(label)[value.name]
    for answer in _wrong_answers(value, want):
        before = _judge_before(value, answer, want)
        assert _core.judge(value, answer, want) == before, answer
        assert _core.judge(value, answer, want, language="en") == before, answer


def test_english_check_says_what_it_said_before(capsys, monkeypatch) -> None:
    # The same reference for whole reports: all right, one wrong, one missing; in an
    # environment that names English (whatever the machine running the tests says).
    for variable in _core.LANGUAGE_VARIABLES:
        monkeypatch.delenv(variable, raising=False)
    monkeypatch.setenv("LANG", "en_US.UTF-8")
    for label, exercise in sorted(selfcheck.EXERCISES.items()):
        if not exercise.values:
            continue
        right = dict(selfcheck.expected(label))
        first = exercise.values[0]
        wrong = dict(right, **{first.name: _wrong_answers(first, right[first.name])[0]})
        missing = {k: v for k, v in right.items() if k != first.name}
        for answers in (right, wrong, missing):
            before = _report_before(label, answers)
            assert _core.report(label, answers) == before
            assert selfcheck.check(label, **answers) is before[0]
            assert capsys.readouterr().out == before[1] + "\n"


# --- The Japanese texts ------------------------------------------------------------------

def test_every_text_of_every_exercise_has_japanese_and_no_other() -> None:
    # The texts come from the registry (the chapter modules); MESSAGES from _ja's tables. A
    # text changed in a chapter module shows up here twice: untranslated, and stale.
    texts = _texts_of_exercises()
    assert sorted(texts - set(_ja.MESSAGES)) == [], "texts without Japanese"
    assert sorted(set(_ja.MESSAGES) - texts) == [], "Japanese for texts no exercise has"


def _texts_by_chapter() -> dict[str, set[str]]:
    # A chapter's texts: those of the exercises whose reference its module defines (an
    # exercise with values has one, beside its hints).
    found: dict[str, set[str]] = {}
    for exercise in selfcheck.EXERCISES.values():
        if exercise.reference is not None:
            chapter = exercise.reference.__module__.rpartition(".")[2]
            found.setdefault(chapter, set()).update(
                text for v in exercise.values for text in (v.what, *(h.message for h in v.hints)))
    return found


def test_each_chapters_japanese_is_in_the_table_of_its_name() -> None:
    # _ja/<chapter>.py beside <chapter>.py, holding texts of that chapter only (a text two
    # chapters write stands in one of their tables).
    texts = _texts_by_chapter()
    tables = {m.name for m in pkgutil.iter_modules(_ja.__path__)}
    assert tables == set(texts)
    for chapter in sorted(tables):
        table = importlib.import_module(f"{_ja.__name__}.{chapter}").MESSAGES
        assert sorted(set(table) - texts[chapter]) == [], f"not texts of {chapter}.py"


def test_a_text_in_two_tables_is_an_error(tmp_path, monkeypatch) -> None:
    # The two could say it differently, and joining would keep one without a word.
    for name, japanese in (("one", "一"), ("two", "二")):
        (tmp_path / f"{name}.py").write_text(f"MESSAGES = {{'a text': {japanese!r}}}\n",
                                            encoding="utf-8")
    monkeypatch.setattr(_ja, "__path__", [str(tmp_path)])
    try:
        with pytest.raises(ValueError, match="two.py translates a text another table has"):
            _ja._joined()
    finally:
        for name in ("one", "two"):
            sys.modules.pop(f"{_ja.__name__}.{name}", None)


@pytest.mark.parametrize(("english", "japanese"), sorted(_ja.MESSAGES.items()),
                         ids=[f"{i}" for i in range(len(_ja.MESSAGES))])
def test_japanese_keeps_the_formulas_names_and_roles(english, japanese) -> None:
    # The English text is the reference: the notebook typesets and links the same spans.
    assert Counter(SPAN.findall(japanese)) == Counter(SPAN.findall(english))
    assert not re.search(r"[$`]", SPAN.sub("", japanese)), "an unbalanced $ or backtick"
    assert JAPANESE.search(SPAN.sub("", japanese)), "no Japanese outside the spans"
    assert japanese == japanese.strip() and "  " not in japanese


def test_japanese_templates_have_the_english_placeholders() -> None:
    # _core.ENGLISH is the reference: judge fills the same names into either language.
    assert set(_ja.TEMPLATES) == set(_core.ENGLISH)
    for key, template in _ja.TEMPLATES.items():
        assert _placeholders(template) == _placeholders(_core.ENGLISH[key]), key
        assert JAPANESE.search(template), key
    assert set(_ja.KINDS) == set(_core.ENGLISH_KINDS)
    assert _placeholders(_ja.OTHER_KIND) == _placeholders(_core.ENGLISH_OTHER_KIND)


def _english_left(message: str) -> list[str]:
    return [words for words in _english_fragments() if words in message]


@pytest.mark.parametrize(("label", "value", "i"), HINTS,
                         ids=[f"{lab}-{v.name}-{i}" for lab, v, i in HINTS])
def test_each_hint_answers_its_own_mistake_in_japanese(label, value, i) -> None:
    # The hint English picks for the example (the English message names it) is the one whose
    # Japanese the Japanese message must hold, after the Japanese sentence of a hint.
    want = selfcheck.expected(label)[value.name]
    wrong = value.hints[i].example(want)
    right_en, said_en = _core.judge(value, wrong, want, language="en")
    picked = [h for h in value.hints
              if said_en == _core.ENGLISH["hint"].format(name=f"`{value.name}`", hint=h.message)]
    assert not right_en and picked, said_en
    right_ja, said_ja = _core.judge(value, wrong, want, language="ja")
    assert not right_ja
    assert said_ja == _ja.TEMPLATES["hint"].format(name=f"`{value.name}`",
                                                   hint=_ja.MESSAGES[picked[0].message])
    assert _english_left(said_ja) == []


@pytest.mark.parametrize(("label", "value"), VALUES, ids=[f"{lab}-{v.name}" for lab, v in VALUES])
def test_every_other_verdict_is_japanese(label, value) -> None:
    # Each branch of judge (the answers of _wrong_answers) in Japanese: no sentence of the
    # English templates is left, and a message that names the value names it in Japanese.
    want = selfcheck.expected(label)[value.name]
    for answer in _wrong_answers(value, want):
        right_en, said_en = _core.judge(value, answer, want, language="en")
        right_ja, said_ja = _core.judge(value, answer, want, language="ja")
        assert right_ja is right_en, answer
        assert _english_left(said_ja) == [], (answer, said_ja)
        assert JAPANESE.search(said_ja), said_ja
        if value.what in said_en:
            assert _ja.MESSAGES[value.what] in said_ja, said_ja
    _, untouched = _core.judge(value, ..., want, language="ja")
    assert untouched.startswith(f"`{value.name}` はまだ `...` のまま")


def test_a_value_three_percent_off_is_called_so_in_japanese() -> None:
    # The wording is _ja.TEMPLATES' own (大きすぎる / 小さすぎる, 絶対値 for a negative value).
    value = selfcheck.Value("x", "the speed $v^*$ that separates swinging back from going "
                                 "over the top, from $\\theta(0) = 2$")
    assert _core.judge(value, 1.03, 1.0, language="ja") == (False, "`x` は 3% 大きすぎる。")
    assert _core.judge(value, 0.97, 1.0, language="ja") == (False, "`x` は 3% 小さすぎる。")
    assert _core.judge(value, -1.03, -1.0, language="ja") == (
        False, "`x` は絶対値が 3% 大きすぎる。")
    assert _core.judge(value, -1.0, 1.0, language="ja") == (False, "`x` は符号が逆である。")
    assert _core.judge(value, 1.0, 1.0, language="ja") == (True, "`x` は正しい。")


def test_a_whole_japanese_report() -> None:
    # What check prints for an exercise of two values: _ja.TEMPLATES for the core's
    # sentences, MESSAGES for the exercise's texts.
    label = "ex-equation-period"
    values = selfcheck.EXERCISES[label].values
    right = dict(selfcheck.expected(label))
    ok, text = _core.report(label, right, language="ja")
    assert ok and text.endswith("すべて正しい。")
    assert text.count("は正しい。") == len(values)
    first = values[0].name
    ok, text = _core.report(label, {k: v for k, v in right.items() if k != first},
                            language="ja")
    assert not ok
    assert f"✘ `{first}` が渡されていない。{first}={first} として渡すこと。" in text
    assert "すべて正しい。" not in text and _english_left(text) == []


def test_an_unknown_language_is_a_clear_error() -> None:
    value = selfcheck.EXERCISES["ex-energy-threshold"].values[0]
    with pytest.raises(ValueError, match="no self-check messages"):
        _core.judge(value, 1.0, 1.0, language="xx")
    with pytest.raises(ValueError, match="no self-check messages"):
        _core.judge(value, 1.0, 1.0, language="../en")


@pytest.mark.parametrize(("environ", "language"), GETTEXT_ENVIRONMENTS)
def test_the_environment_names_the_language_as_for_gettext(environ, language) -> None:
    # The package's rule, with the languages that have self-check messages (Japanese here).
    assert _core.environment_language(environ) == language


def test_an_explicit_language_beats_the_environment(monkeypatch, capsys) -> None:
    monkeypatch.setenv("LANGUAGE", "ja")
    assert selfcheck.check("ex-energy-threshold", v_star=...) is False
    assert "`v_star` はまだ `...` のままである。" in capsys.readouterr().out
    assert selfcheck.check("ex-energy-threshold", language="en", v_star=...) is False
    assert "`v_star` is still `...`" in capsys.readouterr().out


# --- As a notebook's kernel runs it: the installed package, anywhere ----------------------

def _run_check(folder: Path, code: str, **env: str) -> subprocess.CompletedProcess[str]:
    # From an empty folder: the check comes with the installed package, nothing beside it.
    environ = {k: v for k, v in os.environ.items()
               if k not in _core.LANGUAGE_VARIABLES}
    return subprocess.run([sys.executable, "-c", code], cwd=folder, capture_output=True,
                          text=True, timeout=300, encoding="utf-8", env={**environ, **env})


CHECK = ("import sys\n"
         "from elliptic_pendulum.selfcheck import check\n"
         "check('ex-energy-threshold', {language}v_star={v_star!r})\n"
         "check('ex-energy-threshold', {language}v_star=...)\n"
         "print('imported _ja:', 'elliptic_pendulum.selfcheck._ja' in sys.modules)\n")


@pytest.mark.parametrize(("how", "env"), [("language='ja', ", {}),
                                          ("", {"LANG": "ja_JP.UTF-8"})])
def test_asked_for_japanese_it_prints_japanese(tmp_path, how, env) -> None:
    # The expected text is the in-process report in "ja" (tested above); the installed
    # package must choose it by the argument or the environment alone.
    v_star = selfcheck.expected("ex-energy-threshold")["v_star"]
    run = _run_check(tmp_path, CHECK.format(v_star=v_star, language=how), **env)
    assert run.returncode == 0, run.stderr
    right = _core.report("ex-energy-threshold", {"v_star": v_star}, language="ja")[1]
    untouched = _core.report("ex-energy-threshold", {"v_star": ...}, language="ja")[1]
    assert run.stdout == f"{right}\n{untouched}\nimported _ja: True\n"
    assert "すべて正しい。" in run.stdout


def test_otherwise_it_prints_english_without_the_japanese_module(tmp_path) -> None:
    # English as before (the reference of _report_before), with _ja not imported.
    v_star = selfcheck.expected("ex-energy-threshold")["v_star"]
    run = _run_check(tmp_path, CHECK.format(v_star=v_star, language=""), LANG="en_US.UTF-8")
    assert run.returncode == 0, run.stderr
    right = _report_before("ex-energy-threshold", {"v_star": v_star})[1]
    untouched = _report_before("ex-energy-threshold", {"v_star": ...})[1]
    assert run.stdout == f"{right}\n{untouched}\nimported _ja: False\n"
    assert "All right." in run.stdout
