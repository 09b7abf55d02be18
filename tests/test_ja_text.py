"""The checkers of tests/ja_text.py can fail: each is shown the mistake it is there to catch;
and its gettext environments name the language that gettext itself finds in them."""

from __future__ import annotations

import gettext
from pathlib import Path

import pytest

from tests.ja_text import GETTEXT_ENVIRONMENTS, check_translation, english_runs, say_literals


def test_a_run_of_english_words_is_found_outside_math_and_code_only() -> None:
    assert english_runs("は恒等的に成り立つ。sympy reduces the difference") == [
        "sympy reduces the difference"]
    assert english_runs("変異式（$a + b + c$）と `the code is here` と {ref}`a b c <x>`") == []
    assert english_runs("初期状態 theta0, theta0'") == []
    assert english_runs("[energy：節](energy.md#the-long-anchor-here)") == []


def test_say_literals_reads_the_first_argument_of_each_say_call(tmp_path) -> None:
    source = tmp_path / "m.py"
    source.write_text('x = say("one {a}", a=1)\ny = f"{say(\'two\')}"\nz = say(name)\n'
                      'w = words.say("three")\n', encoding="utf-8")
    assert say_literals(source) == {"one {a}", "two", "three"}


@pytest.mark.parametrize(("english", "japanese"), [
    ("holds: {measure}", "成り立つ"),                      # a placeholder lost
    ("the branch $-a$", "枝 $a$"),                         # a formula changed
    ("| a | b |", "| あ | い"),                           # a column lost
    ("stable", "stable"),                                  # not translated
    ("relative error of it", "相対誤差 of the result"),   # English left
])
def test_check_translation_rejects_each_kind_of_mistake(english, japanese) -> None:
    with pytest.raises(AssertionError):
        check_translation(english, japanese)


@pytest.mark.parametrize(("environ", "language"), GETTEXT_ENVIRONMENTS)
def test_each_gettext_environment_names_what_gettext_finds(tmp_path, monkeypatch, environ,
                                                           language) -> None:
    # gettext.find is the reference, over a folder with messages in English and Japanese
    # (it asks only whether the file exists); finding none means English.
    for code in ("en", "ja"):
        (tmp_path / code / "LC_MESSAGES").mkdir(parents=True)
        (tmp_path / code / "LC_MESSAGES" / "x.mo").touch()
    for variable in ("LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"):
        monkeypatch.delenv(variable, raising=False)
    for variable, value in environ.items():
        monkeypatch.setenv(variable, value)
    found = gettext.find("x", str(tmp_path))
    assert (Path(found).parts[-3] if found else "en") == language
