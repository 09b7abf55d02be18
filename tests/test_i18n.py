"""The language of a call (elliptic_pendulum._i18n) and a Motion's table in Japanese.

The expectations: gettext's order of the environment's variables (as ``gettext.find`` reads
them), the .po and .mo formats as GNU gettext defines them (a .mo written here by babel, the
book's own catalog tool), and _ja.py's table for a Motion's words.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

import elliptic_pendulum as ep
from elliptic_pendulum import _i18n, _ja, motion
from elliptic_pendulum.regimes import Regime
from tests.ja_text import (
    GETTEXT_ENVIRONMENTS,
    JAPANESE,
    check_translation,
    english_runs,
    say_literals,
)

SRC = Path(motion.__file__).parent


@pytest.fixture
def clean_environment(monkeypatch):
    """No language and no catalog named, whatever the machine running the tests says."""
    for variable in (*_i18n.LANGUAGE_VARIABLES, _i18n.CATALOG_VARIABLE):
        monkeypatch.delenv(variable, raising=False)
    return monkeypatch


@pytest.mark.parametrize(("environ", "language"), GETTEXT_ENVIRONMENTS)
def test_the_environment_names_the_language_as_for_gettext(environ, language) -> None:
    assert _i18n.environment_language(environ) == language


def test_an_unknown_language_gives_english(clean_environment) -> None:
    assert [_i18n.resolve(x) for x in ("xx", "fr_FR.UTF-8", "../ja", "en", "ja_JP")] == [
        "en", "en", "en", "en", "ja"]
    clean_environment.setenv("LANGUAGE", "xx")
    assert _i18n.resolve(None) == "en"


def _po(path: Path, entries: dict[str, str], language: str | None = "ja") -> Path:
    header = f"Language: {language}\\n" if language else ""
    body = "".join(f'\nmsgid "{k}"\nmsgstr "{v}"\n' for k, v in entries.items())
    path.write_text(f'msgid ""\nmsgstr ""\n"{header}"\n{body}', encoding="utf-8")
    return path


def test_a_po_catalog_extends_the_table_and_is_read_at_each_call(tmp_path, clean_environment):
    catalog = _po(tmp_path / "book.po", {"20 swings": "20 回の振動", "regime": "レジーム"})
    say = _i18n.say_for("elliptic_pendulum", "ja")
    assert say("20 swings") == "20 swings"  # no catalog named yet
    clean_environment.setenv(_i18n.CATALOG_VARIABLE, str(catalog))
    say = _i18n.say_for("elliptic_pendulum", "ja")
    assert say("20 swings") == "20 回の振動"
    assert say("regime") == "レジーム"  # the catalog's entry beats the package's
    assert say("period") == _ja.MESSAGES["period"]
    assert say("not in any table") == "not in any table"
    assert _i18n.say_for("elliptic_pendulum", "en")("20 swings") == "20 swings"
    # Edited: read again (the cache is keyed by modification time and size).
    _po(catalog, {"20 swings": "振動 20 回分"})
    os.utime(catalog, ns=(1, 1))
    assert _i18n.say_for("elliptic_pendulum", "ja")("20 swings") == "振動 20 回分"


def test_a_catalog_of_another_language_is_not_used(tmp_path, clean_environment) -> None:
    clean_environment.setenv(_i18n.CATALOG_VARIABLE, os.pathsep.join([
        str(_po(tmp_path / "fr.po", {"20 swings": "20 oscillations"}, "fr")),
        str(_po(tmp_path / "any.po", {"over": "にわたって"}, None))]))
    say = _i18n.say_for("elliptic_pendulum", "ja")
    assert say("20 swings") == "20 swings"
    assert say("over") == "にわたって"


def test_a_mo_catalog_is_read_with_gettext(tmp_path, clean_environment) -> None:
    from babel.messages.catalog import Catalog
    from babel.messages.mofile import write_mo

    catalog = Catalog(locale="ja")
    catalog.add("max relative error", "最大相対誤差")
    path = tmp_path / "book.mo"
    with path.open("wb") as file:
        write_mo(file, catalog)
    clean_environment.setenv(_i18n.CATALOG_VARIABLE, str(path))
    say = _i18n.say_for("elliptic_pendulum", "ja")
    assert say("max relative error") == "最大相対誤差"
    assert say("") == ""  # not the catalog's header


def test_the_po_reader_leaves_out_fuzzy_empty_and_obsolete_entries() -> None:
    text = ('msgid ""\nmsgstr "Language: ja_JP\\n"\n\n#, fuzzy\nmsgid "a"\nmsgstr "あ"\n\n'
            'msgid "b"\nmsgstr ""\n\n#~ msgid "c"\n#~ msgstr "し"\n\nmsgid "d \\"q\\""\n'
            'msgstr ""\n"で\\n"\n"す"\n')
    assert _i18n.read_po(text) == ({'d "q"': "で\nす"}, "ja")


# --- a Motion's table ---------------------------------------------------------------------

def test_a_field_meets_japanese_with_a_space_as_the_book_writes() -> None:
    # The book's Japanese sets a space between kana or kanji and Latin letters, digits or
    # math ("1e-9 以内", "20 回"); a template's field brings either, so the space is set at
    # the seam, and never doubled or put inside the field or between two Japanese letters.
    say = _i18n.Say("ja", {"{n} swings over {over}": "{n}回の振動、{over}にわたって",
                           "rejected: {label}": "変異式（{label}）は退けられる {x:.0e}"})
    assert say("{n} swings over {over}", n=20, over="mpmath.qfrom") == (
        "20 回の振動、mpmath.qfrom にわたって")
    assert say("{n} swings over {over}", n=20, over="振幅") == "20 回の振動、振幅にわたって"
    assert say("rejected: {label}", label="$8/\\pi$", x=1e-9) == (
        "変異式（$8/\\pi$）は退けられる 1e-09")
    # English (and a language without such seams) is str.format, exactly.
    english = _i18n.Say("en", {})
    assert english("{n} swings over {over}", n=20, over="x") == "20 swings over x"


def test_every_word_of_a_motions_table_has_japanese_and_no_other() -> None:
    # The English is _display.py's (its say(...) calls) and the regimes' names.
    english = say_literals(SRC / "_display.py") | {r.name.lower() for r in Regime}
    assert sorted(english - set(_ja.MESSAGES)) == [], "words without Japanese"
    assert sorted(set(_ja.MESSAGES) - english) == [], "Japanese for words no one writes"


@pytest.mark.parametrize(("english", "japanese"), sorted(_ja.MESSAGES.items()))
def test_each_word_keeps_its_placeholders(english, japanese) -> None:
    check_translation(english, japanese)


MOTIONS = [ep.solve(0.5), ep.solve(0.0, 3.0), ep.solve(0.0, 2.0), ep.solve(0.0),
           ep.solve([0.5, 0.0, 0.0], [0.0, 3.0, 0.0])]


def test_a_motions_table_in_japanese(clean_environment) -> None:
    # LANGUAGE=ja names Japanese (gettext's first variable); _repr_html_ reads it when called.
    before = dict(os.environ)
    english = [m._repr_html_() for m in MOTIONS]
    clean_environment.setenv("LANGUAGE", "ja")
    japanese = [m._repr_html_() for m in MOTIONS]
    for en, ja in zip(english, japanese, strict=True):
        assert english_runs(ja) == [], ja
        assert JAPANESE.search(ja) and ja != en
    assert "<th style='text-align:left'>周期</th>" in japanese[0]
    assert "II（振動）" in japanese[0] and "IV（回転）" in japanese[1]
    assert repr(MOTIONS[0]).startswith("Motion(regime='II', theta0=0.5")  # Python, as before
    clean_environment.setenv("LANGUAGE", "xx")
    assert [m._repr_html_() for m in MOTIONS] == english
    clean_environment.setenv("LANGUAGE", "ja")
    assert dict(os.environ) == {**before, "LANGUAGE": "ja"}


def test_english_is_as_before(clean_environment) -> None:
    # The table as the package wrote it before it had languages.
    assert MOTIONS[0]._repr_html_() == (
        "<table><caption>elliptic_pendulum.Motion</caption>"
        "<tr><th style='text-align:left'>regime</th><td style='text-align:left'>II (libration)"
        "</td></tr><tr><th style='text-align:left'>theta0, theta0&#x27;</th>"
        "<td style='text-align:left'>0.5, 0</td></tr><tr><th style='text-align:left'>omega0</th>"
        "<td style='text-align:left'>1</td></tr><tr><th style='text-align:left'>c1</th>"
        "<td style='text-align:left'>-1.755165124</td></tr><tr><th style='text-align:left'>"
        "amplitude</th><td style='text-align:left'>0.5</td></tr><tr><th style='text-align:left'>"
        "period</th><td style='text-align:left'>6.382789698</td></tr></table>")


def test_an_english_session_imports_no_japanese_table(tmp_path) -> None:
    code = ("import sys, elliptic_pendulum as ep\n"
            "from elliptic_pendulum.checks import verify\n"
            "ep.solve(0.5)._repr_html_(); str(verify.fact('(1)', True, 'x is fine'))\n"
            "print(ep.__file__.startswith(sys.argv[1]),\n"
            "      sorted(m for m in sys.modules if m.endswith('._ja')))\n")
    env = {k: v for k, v in os.environ.items()
           if k not in (*_i18n.LANGUAGE_VARIABLES, _i18n.CATALOG_VARIABLE)}
    run = subprocess.run([sys.executable, "-c", code, str(SRC)], cwd=tmp_path, capture_output=True,
                         text=True, timeout=300,
                         env={**env, "LANG": "en_US.UTF-8", "PYTHONPATH": str(SRC.parent)})
    assert run.returncode == 0, run.stderr
    assert run.stdout == "True []\n"
