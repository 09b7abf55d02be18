"""The Japanese catalogs keep the glossary's rule: one term for each concept.

Where the expectation comes from: the glossary page, book/glossary.md, says "The Japanese
edition uses one term for each concept, the note's own where the note has one", and its table
(English | 日本語 | symbol) gives that term. The test reads the table, so the term it requires
is the glossary's, and changes with it:

* an English term of the table, where a message's prose says it (TERMS: regime, resonance,
  nonlinear resonance, separatrix, modulus, wobble), has the table's Japanese in the
  translation (領域, 共鳴, 非線形共鳴 (the note's words), セパラトリクス, 母数, 周期的なずれ), but
  for the few messages in OTHER_SENSE, where the English word means something else;
* no translation uses a variant that the rule excludes (VARIANTS): 共振 for 共鳴, 場合 I–IV for
  the note's 領域 I–IV, 揺らぎ/ゆらぎ (which read as "fluctuation") for a rotation's wobble,
  一周期 or 1周期 where the catalogs write 1 周期 (a numeral set off by spaces, as the table's
  第 1 種楕円積分), or a note "written for students" (it calls itself a memo, book/intro.md);
* no translation quotes in English a label that the library writes in Japanese (its
  ``_ja`` tables: "How it was checked" is どのように検証したか, "none" is なし).

The checks can fail: each finds the slip it is there for in a message as an earlier catalog
had it (BROKEN, test_each_check_finds_its_slip). Run on the catalogs of commit 6c0481d, before
they were made to keep the rule, the three checks report 21 terms missing, 29 variants and
「none」; on intro.po before 7397c43, 「How it was checked」 and the note "学生向けに…書いた".
"""

from __future__ import annotations

import re

import pytest

from elliptic_pendulum import _ja as motion_ja
from elliptic_pendulum.checks import _ja as checks_ja
from elliptic_pendulum.plotting import _ja as plotting_ja
from elliptic_pendulum.selfcheck import _ja as selfcheck_ja
from tests.i18n.test_catalogs import ROOT, translations

GLOSSARY = ROOT / "book" / "glossary.md"

Entry = tuple[str, str, str]  # (page, msgid, msgstr)

# English glossary term (its table cell, exactly) -> how a message's prose says it.
TERMS = {
    "regime (I-IV)": r"\bregimes?\b",
    "resonance": r"\bresonances?\b",
    "nonlinear resonance": r"\bnonlinear resonances?\b",
    "separatrix": r"\bseparatri(?:x|ces)\b",
    "modulus": r"\bmodul(?:us|i)\b",
    "wobble (of a rotation)": r"\bwobbles?\b",
}

# Messages where the English word is another concept than the glossary's, by the start of
# the msgid: the term, and why the glossary's Japanese does not apply.
OTHER_SENSE = {
    ("modulus", "The modulus of $\\operatorname{sn}(u, 0.8)$"): "|sn|, 絶対値",
    ("modulus", "So the two multipliers cannot both leave"): "a multiplier's |μ|, 絶対値",
    ("modulus", "Show that its Floquet multipliers tend"): "a multiplier's |μ|, 絶対値",
    ("wobble (of a rotation)", "A string shortened from"): "the action's, 揺れ",
    ("wobble (of a rotation)", "Two panels of an increasing curve"): "a curve's look, 波打つ",
    ("wobble (of a rotation)", "Two panels, theta and theta'"): "a curve's look, 波打つ",
}

# What the rule excludes -> (the English glossary term whose Japanese is required instead,
# or the required form itself in quotes when the table has no row for it, why).
VARIANTS = {
    r"共振": ("resonance", "共鳴, and the note's 非線形共鳴"),
    r"場合\s*(?:IV|I{1,3})(?![A-Za-z])": ("regime (I-IV)", "the note's 領域 I–IV"),
    r"揺らぎ|ゆらぎ": ("wobble (of a rotation)", "揺らぎ reads as fluctuation"),
    r"一周期|(?<=[0-9０-９])周期|[０-９]\s*周期": ("'1 周期'", "numerals spaced, as 第 1 種"),
    r"学生(?:向け|のため)に[^。、]{0,10}書": ("'メモ'", "the note calls itself a memo"),
}

ROLE = re.compile(r"\{([\w:-]+)\}`([^`]*)`")
TITLED = re.compile(r"^(.*?)\s*<[^<>]*>$", re.S)
TEXT_ROLES = {"doc", "ref", "numref", "prf:ref", "term"}


def prose(text: str) -> str:
    """Return a message without its code, formulas and targets: the words a reader reads.

    A cross-reference keeps its title ({doc}`Resonance <resonance>` is "Resonance"); other
    roles ({py:func}, {glue:text}, a bare {ref}`label`), inline code and $...$ go.
    """
    def role(match: re.Match[str]) -> str:
        titled = TITLED.match(match.group(2))
        return titled.group(1) if titled and match.group(1) in TEXT_ROLES else " "
    text = ROLE.sub(role, text)
    text = re.sub(r"`[^`]*`", " ", text)
    return re.sub(r"\$\$.*?\$\$|\$[^$]*\$", " ", text, flags=re.S)


def glossary() -> dict[str, str]:
    """Return the glossary table, {English cell: Japanese term} (a parenthesis dropped)."""
    table = {}
    for line in GLOSSARY.read_text(encoding="utf-8").splitlines():
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if (line.startswith("|") and len(cells) == 3 and cells[0] != "English"
                and not set(cells[0]) <= set("-")):
            table[cells[0]] = re.sub(r"（[^）]*）", "", cells[1])
    return table


def required(term: str, table: dict[str, str]) -> str:
    return term.strip("'") if term.startswith("'") else table[term]


def term_faults(entries: list[Entry], table: dict[str, str]) -> list[tuple[str, ...]]:
    faults: list[tuple[str, ...]] = []
    for term, pattern in TERMS.items():
        japanese = table[term]
        for page, msgid, msgstr in entries:
            if msgid == msgstr or not re.search(pattern, prose(msgid), re.I):
                continue
            if any(t == term and msgid.startswith(start) for t, start in OTHER_SENSE):
                continue
            if japanese not in msgstr:
                faults.append((page, term, japanese, msgid[:70]))
    return faults


def variant_faults(entries: list[Entry], table: dict[str, str]) -> list[tuple[str, ...]]:
    return [(page, found.group(), required(term, table), msgstr[:70])
            for pattern, (term, _) in VARIANTS.items()
            for page, _, msgstr in entries
            for found in re.finditer(pattern, msgstr)]


def library_labels() -> set[str]:
    """The English texts the library writes in Japanese, without placeholders or formulas."""
    labels = set()
    for table in (motion_ja.MESSAGES, checks_ja.MESSAGES, plotting_ja.MESSAGES,
                  selfcheck_ja.MESSAGES, selfcheck_ja.TEMPLATES):
        labels |= {english for english in table
                   if isinstance(english, str) and len(english) >= 4
                   and not set("{$") & set(english)}
    return labels


def label_faults(entries: list[Entry], labels: set[str]) -> list[tuple[str, ...]]:
    """A label quoted (「none」, "none"), or one of two words or more anywhere in the prose.

    A single English word unquoted may be a gloss (振動（libration）); quoted, it is a label
    the reader is told to look for, and the library writes it in Japanese.
    """
    patterns = {}
    for label in labels:
        quoted = "|".join(re.escape(q[0] + label + q[1]) for q in ("「」", '""', "“”"))
        bare = rf"(?<![A-Za-z]){re.escape(label)}(?![A-Za-z])"
        patterns[label] = re.compile(f"{quoted}|{bare}" if " " in label else quoted)
    return [(page, label, msgstr[:70]) for page, msgid, msgstr in entries
            if msgid != msgstr for label, pattern in patterns.items()
            if pattern.search(prose(msgstr))]


@pytest.fixture(scope="module")
def table() -> dict[str, str]:
    return glossary()


@pytest.fixture(scope="module")
def entries() -> list[Entry]:
    return translations()


def test_the_glossary_has_the_terms_the_test_holds(table: dict[str, str]) -> None:
    assert len(table) > 50
    for term in TERMS:
        assert table[term], term
    for term, _ in VARIANTS.values():
        assert required(term, table)
    # The glossary's own Japanese is the first place the rule holds.
    assert variant_faults([("glossary.md", english, japanese)
                           for english, japanese in table.items()], table) == []
    assert table["resonance"] == "共鳴" and table["nonlinear resonance"] == "非線形共鳴"
    assert table["regime (I-IV)"] == "領域"
    assert table["elliptic integral of the first kind"] == "第 1 種楕円積分"


def test_every_glossary_term_keeps_its_japanese(entries: list[Entry],
                                                table: dict[str, str]) -> None:
    assert term_faults(entries, table) == []


def test_the_other_senses_are_still_in_the_catalogs(entries: list[Entry]) -> None:
    # An exception whose message is gone is stale: it would excuse the next one silently.
    stale = [key for key in OTHER_SENSE
             if not any(msgid.startswith(key[1]) for _, msgid, _ in entries)]
    assert stale == []


def test_no_translation_uses_a_variant_the_glossary_excludes(entries: list[Entry],
                                                             table: dict[str, str]) -> None:
    assert variant_faults(entries, table) == []


def test_no_translation_quotes_a_library_label_in_english(entries: list[Entry]) -> None:
    labels = library_labels()
    assert {"How it was checked", "none", "numerical fact"} <= labels
    assert label_faults(entries, labels) == []


# Each check against a message as an earlier catalog had it (shortened): the slip it is for.
BROKEN: dict[str, tuple[str, Entry]] = {
    "共振 for resonance": ("term", (
        "resonance", "Near resonance the curve folds over.", "共振の近くでは曲線が折れ重なる。")),
    "共振 attributed to the note": ("variant", (
        "resonance", "It was written on the way to a paper on nonlinear resonance.",
        "原ノートは非線形共振に関する論文の準備として書かれた。")),
    "場合 for a regime": ("variant", (
        "notes_on_original", "Section 3, case III: $\\omega$ for $\\omega_0$",
        "第 3 節、場合 III：$\\omega_0$ のところが $\\omega$")),
    "a regime without 領域": ("term", (
        "intro", "the four regimes", "4 つの場合")),
    "揺らぎ for the wobble": ("term", (
        "rotation", "A uniform rotation plus a wobble", "等速回転と揺らぎ")),
    "ゆらぎ": ("variant", (
        "teachers_guide", "the amplitude of the wobble", "ゆらぎの振幅")),
    "一周期": ("variant", (
        "equation", "this tension over a period", "一周期にわたるこの張力")),
    "1周期 unspaced": ("variant", (
        "equation", "this tension over a period", "1周期にわたるこの張力")),
    "separatrix transliterated otherwise": ("term", (
        "separatrix", "near the separatrix", "分離線の近くで")),
    "modulus as parameter": ("term", (
        "libration", "the modulus $\\alpha$", "パラメータ $\\alpha$")),
    "written for students": ("variant", (
        "intro", "a short note by Takeno",
        "竹野が学生向けに日本語で書いた短いノート")),
    "「none」": ("label", (
        "checks", "(\"none\" for a numerical fact)", "（数値的事実には「none」と記す）")),
    "How it was checked": ("label", (
        "intro", "how it was checked opens under \"How it was checked\"",
        "どのように検証したかは「How it was checked」を開くと表示される。")),
}


@pytest.mark.parametrize("slip", sorted(BROKEN))
def test_each_check_finds_its_slip(slip: str, table: dict[str, str]) -> None:
    check, entry = BROKEN[slip]
    if check == "term":
        assert term_faults([entry], table) != []
    elif check == "variant":
        assert variant_faults([entry], table) != []
    else:
        assert label_faults([entry], library_labels()) != []


def test_prose_keeps_a_titles_words_and_drops_code() -> None:
    text = ("{doc}`Resonance <resonance>` and {py:attr}`m.modulus <x.Motion.modulus>`, "
            "{ref}`ex-rotation-wobble`, `wobble2`, $\\mathrm{regime}$")
    words = prose(text)
    assert "Resonance" in words
    assert not re.search("modulus|wobble|regime", words)
