"""The verdicts and the registry in Japanese (checks/_ja.py).

The English of each message is the modules' own (their ``say(...)`` calls, read from the
sources, and the package's fragments: the identities' mutant labels and domains, the kinds
of check, the registry's statuses); each has its Japanese, with the same placeholders and
formulas. A verdict and the registry in Japanese leave no run of English words outside math
and code, once the texts a caller passes are in a catalog (ELLIPTIC_PENDULUM_MESSAGES, here a
.po file written by the test); without it those texts stay English. English is as before:
the sentences below are verify.py's and registry.py's before they had languages.
"""

from __future__ import annotations

import ast
import inspect
import math
import os
import re
from pathlib import Path

import pytest

from elliptic_pendulum import _i18n
from elliptic_pendulum.checks import _ja, registry, verify
from elliptic_pendulum.checks.identities import identity
from tests.ja_text import MATH, check_translation, english_runs, prose, say_literals

CHECKS = Path(verify.__file__).parent


def _fragments_of_identities() -> set[str]:
    # The words a verdict quotes from identities.py: mutant labels and domains with prose,
    # and the claims named in words ("§3, after (10)", "Proposition 1.2").
    def words(node: ast.AST) -> bool:
        return (isinstance(node, ast.Constant) and isinstance(node.value, str)
                and any(ch.isalpha() for ch in MATH.sub("", node.value)))

    found = set()
    for node in ast.walk(ast.parse((CHECKS / "identities.py").read_text(encoding="utf-8"))):
        if (isinstance(node, ast.keyword) and node.arg in ("mutant_label", "domain_md")
                and words(node.value)):
            found.add(node.value.value)
        if (isinstance(node, ast.Call) and getattr(node.func, "id", "") == "Identity"
                and len(node.args) > 1 and words(node.args[1])
                and re.search(r"[A-Za-z]{2,}", node.args[1].value)):
            found.add(node.args[1].value)
    return found


def _english() -> set[str]:
    statuses = {text for pair in registry.STATUS.values() for text in pair}
    default_measure = inspect.signature(verify.numeric).parameters["measure"].default
    return (say_literals(CHECKS / "verify.py", CHECKS / "registry.py")
            | _fragments_of_identities() | set(registry.KINDS) | statuses | {default_measure})


def test_every_message_has_japanese_and_no_other() -> None:
    english = _english()
    assert sorted(english - set(_ja.MESSAGES)) == [], "messages without Japanese"
    assert sorted(set(_ja.MESSAGES) - english) == [], "Japanese for messages no one writes"


@pytest.mark.parametrize(("english", "japanese"), sorted(_ja.MESSAGES.items()))
def test_each_translation_keeps_placeholders_and_formulas(english, japanese) -> None:
    check_translation(english, japanese)


# --- whole verdicts -----------------------------------------------------------------------

# The texts the calls below pass in, as a book's catalog would translate them.
CALLERS = {"one period": "1 周期", "4 pi": "4π", "max relative error": "最大相対誤差",
           "xi stays in [-1, 1]": "ξ は [-1, 1] にとどまる", "§3, case II": "§3、領域 II",
           "over {n} rotations, theta' >= {closest:.6f}":
               "{n} 回の回転にわたって theta' >= {closest:.6f}",
           "{n} swings": "{n} 回の振動"}


@pytest.fixture
def catalog(tmp_path, monkeypatch):
    for variable in (*_i18n.LANGUAGE_VARIABLES, _i18n.CATALOG_VARIABLE):
        monkeypatch.delenv(variable, raising=False)
    body = "".join(f'\nmsgid "{k}"\nmsgstr "{v}"\n' for k, v in CALLERS.items())
    path = tmp_path / "fragments.po"
    path.write_text(f'msgid ""\nmsgstr "Language: ja\\n"\n{body}', encoding="utf-8")
    monkeypatch.setenv(_i18n.CATALOG_VARIABLE, str(path))
    return monkeypatch


def _period_error(T):
    return abs(T() - 2 * math.pi)


def _verdicts(language):
    # Every branch of the three kinds: a plain identity, one on a domain with a point beyond
    # it and a worded mutant, one on a worded domain, an arithmetic step; a numerical check
    # with a named mutant, with an unnamed one and with none; a fact.
    return [
        verify.identity(identity("eq13"), language=language),
        verify.identity(identity("eq13_root"), language=language),
        verify.identity(identity("eq28_solves_eq3"), language=language),
        verify.identity(identity("eq26"), language=language),
        *(verify.identity(ident, language=language) for ident in _arithmetic()),
        verify.numeric("(8)", _period_error, lambda: 2 * math.pi, lambda: 4 * math.pi,
                       tol=1e-12, over="one period", mutant_label="4 pi", language=language),
        verify.numeric("(8)", _period_error, lambda: 2 * math.pi, lambda: 4 * math.pi,
                       tol=1e-12, over="one period", measure="max relative error",
                       language=language),
        verify.numeric("(8)", _period_error, lambda: 2 * math.pi, tol=1e-12, over="one period",
                       language=language),
        verify.fact("(14)", True, "xi stays in [-1, 1]", language=language),
        verify.fact("§3, case II", True, "over {n} rotations, theta' >= {closest:.6f}",
                    values={"n": 12, "closest": 0.5}, language=language),
        verify.numeric("(8)", _period_error, lambda: 2 * math.pi, tol=1e-12, over="{n} swings",
                       values={"n": 20}, language=language),
    ]


def _arithmetic():
    from elliptic_pendulum.checks.identities import identities

    return [i for i in identities() if i.kind == "arithmetic"][:1]


def test_a_japanese_verdict_leaves_no_english(catalog) -> None:
    for v in _verdicts("ja"):
        for shown in (str(v), v._repr_markdown_()):
            assert english_runs(shown) == [], shown
        assert str(v).endswith("。"), str(v)
        if v.details:
            assert "<summary>どのように検証したか</summary>" in v._repr_markdown_()


def test_the_environment_names_japanese_and_an_unknown_language_english(catalog) -> None:
    before = dict(os.environ)
    english = [str(v) for v in _verdicts("en")]
    catalog.setenv("LANGUAGE", "ja")
    japanese = [str(v) for v in _verdicts(None)]
    assert japanese == [str(v) for v in _verdicts("ja")] != english
    catalog.setenv("LANGUAGE", "xx")
    assert [str(v) for v in _verdicts(None)] == english == [str(v) for v in _verdicts("xx")]
    assert dict(os.environ) == {**before, "LANGUAGE": "xx"}


def test_a_text_the_catalog_lacks_stays_english(catalog) -> None:
    v = verify.fact("(14)", True, "theta stays below pi here", language="ja")
    assert str(v) == "✔ (14) theta stays below pi here。"


def test_english_is_as_before(catalog) -> None:
    # The sentences of verify.py before it had languages, written out.
    plain, domain, worded, _, *rest = _verdicts("en")
    assert str(plain) == ("✔ (13) holds identically: sympy reduces the difference of its two "
                          "sides to 0.")
    assert plain.details.startswith("A wrong version, $") and plain.details.endswith(
        "$, is rejected: sympy does not reduce it to 0.")
    assert str(domain) == ("✔ (13) holds for $- \\pi < \\theta < \\pi$, not beyond: sympy "
                           "reduces the difference of its two sides to 0 there.")
    assert domain.details.startswith(
        "Sympy splits square roots as if their radicands were positive, which is true for "
        "$- \\pi < \\theta < \\pi$ only; without that step the difference is below $10^{-20}$ "
        "at ")
    assert " points of it. Beyond it the statement is false: at $" in domain.details
    assert domain.details.endswith(", is rejected: sympy does not reduce it to 0.")
    assert str(worded).startswith("✔ (28) holds for all real $t$: sympy reduces")
    arithmetic, named, unnamed, bare, fact, templated, counted = rest
    assert str(arithmetic).endswith(
        "follows by arithmetic: sympy evaluates both sides to the same value.")
    assert str(named) == "✔ (8) holds: max |residual| 0 over one period."
    assert named.details == ("Measured against an independent computation; the tolerance is "
                             "1.0e-12. A wrong version, 4 pi, is rejected: its max |residual| "
                             "is 6.3.")
    assert unnamed.details.endswith(
        " A wrong version, a changed formula, is rejected: its max relative error is 6.3.")
    assert bare.details.endswith("1.0e-12. No wrong version is tried.")
    assert str(fact) == "✔ (14) xi stays in [-1, 1]."
    # A template with values reads as the f-string it replaces.
    assert str(templated) == f"✔ §3, case II over {12} rotations, theta' >= {0.5:.6f}."
    assert templated.claim == "§3, case II"
    assert str(counted) == f"✔ (8) holds: max |residual| 0 over {20} swings."
    assert "<summary>How it was checked</summary>" in named._repr_markdown_()


def test_a_claim_and_a_template_in_japanese(catalog) -> None:
    *_, templated, counted = _verdicts("ja")
    assert str(templated) == "✔ §3、領域 II 12 回の回転にわたって theta' >= 0.500000。"
    assert templated.claim == "§3, case II"  # the literal the registry reads
    assert templated._repr_markdown_().startswith("✔ **§3、領域 II**")
    assert str(counted) == ("✔ (8) は成り立つ。20 回の振動にわたって、残差の絶対値の最大値は "
                            "0 である。")


# --- the registry -------------------------------------------------------------------------

FOUND = [
    registry.Check("(8)", "independent numerical check", "equation", "one period", "period", 3,
                   mutant="4 pi"),
    registry.Check("(13)", "sympy identity", "energy", "one period", "", 5, mutant="4 pi",
                   name="eq13"),
    registry.Check("xi stays in [-1, 1]", "numerical fact", "rotation", "one period", "xi", 9),
    registry.Check("", "arithmetic", "rotation", "one period", "", 12, name="eq30_half_angle"),
]


def test_the_registry_in_japanese_leaves_no_english(catalog) -> None:
    for table in (registry.markdown(FOUND, language="ja"),
                  registry.markdown_other(FOUND, language="ja")):
        assert english_runs(table) == [], table
    whole = registry.markdown(FOUND, language="ja")
    assert whole.startswith("| 主張 | 検証の種類 | 退けた変異式 | 場所 |")
    # Every status is in the table, in Japanese.
    for kind, why in registry.STATUS.values():
        assert f"{_ja.MESSAGES[kind]}：{_ja.MESSAGES[why]}" in whole
    assert "[equation：1 周期](equation.md#period)" in whole
    assert "| 数値的事実 | なし |" in registry.markdown_other(FOUND, language="ja")


def test_the_registry_in_english_is_as_before(catalog) -> None:
    lines = registry.markdown(FOUND, language="en").splitlines()
    assert lines[0] == "| claim | kind of check | mutants rejected | where |"
    assert lines[1 + 8] == ("| {ref}`(8) <eq-8>` | independent numerical check | 4 pi | "
                            "[equation: one period](equation.md#period) |")
    assert lines[1 + 1] == ("| {ref}`(1) <eq-1>` | definition: the bob's position and the "
                            "rod's pull, read off the figure | none | - |")
    other = registry.markdown_other(FOUND, language="en").splitlines()
    assert other[:4] == ["### {doc}`rotation`", "", "| check | kind | mutant rejected | where |",
                         "|---|---|---|---|"]
    assert other[4] == ("| xi stays in [-1, 1] | numerical fact | none | "
                        "[one period](rotation.md#xi) |")
    assert other[5] == "| eq30_half_angle | arithmetic | none | one period |"
    assert prose(lines[3]) == prose(registry.markdown(FOUND).splitlines()[3])
