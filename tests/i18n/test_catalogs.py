"""The Japanese catalogs, without a build: each translation keeps what its message needs,
the checker that says so can fail, and the wording is ours, not the note's.

Whether every message of the current pages is translated needs the gettext builder's
templates: tests/book/test_japanese.py runs that (`make i18n-status`).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from babel.messages.pofile import read_po

from tools.i18n import overlap, status

ROOT = Path(__file__).resolve().parents[2]
LOCALE = ROOT / "book" / "locale"
CATALOGS = sorted((LOCALE / "ja" / "LC_MESSAGES").glob("*.po"))


def translations() -> list[tuple[str, str, str]]:
    found = []
    for path in CATALOGS:
        with path.open("rb") as f:
            found += [(path.stem, m.id, str(m.string)) for m in read_po(f)
                      if m.id and m.string and not m.fuzzy]
    return found


def test_there_are_catalogs_with_translations() -> None:
    assert len(CATALOGS) >= 19
    assert len(translations()) > 1000


def test_every_translation_keeps_its_roles_formulas_and_paragraph() -> None:
    faults = [(name, msgid[:80], fault) for name, msgid, msgstr in translations()
              for fault in status.check_entry(msgid, msgstr)]
    assert faults == []


# The mistakes a translator makes that no builder reports (a dropped glue role loses its
# number silently; a blank line keeps only the first paragraph; ** next to a CJK bracket
# shows the asterisks), each of which the check must find.
MSGID = "The period {glue:text}`p:.3f` of {ref}`(9) <eq-9>` is $T = 4K/\\omega_0$, **long**."
EQ, P, T = "{ref}`(9) <eq-9>`", "{glue:text}`p:.3f`", "$T = 4K/\\omega_0$"
BROKEN = {
    "dropped glue": f"{EQ} の周期は {T} であり、**長い**。",
    "other target": f"{EQ.replace('eq-9', 'eq-8')} の周期 {P} は {T}、**長い**。",
    "other format": f"{EQ} の周期 {P.replace('.3f', '.2f')} は {T}、**長い**。",
    "lost formula": f"{EQ} の周期 {P} は $T$、**長い**。",
    "unclosed role": f"{EQ} の周期 {P[:-1]} は {T}、**長い**。",
    "blank line": f"{EQ} の周期 {P} は\n\n{T}、**長い**。",
    "asterisks": f"{EQ} の周期 {P} は {T} で**「長い」**と言う。",
}


def test_a_whole_translation_passes() -> None:
    good = f"{EQ} の周期 {P} は {T} であり、「**長い**」。"
    assert status.check_entry(MSGID, good) == []


@pytest.mark.parametrize("mistake", sorted(BROKEN))
def test_the_check_finds_each_silent_mistake(mistake: str) -> None:
    assert status.check_entry(MSGID, BROKEN[mistake]) != []


def test_the_cells_texts_keep_their_template_fields() -> None:
    # The library fills a cell's template with str.format after translating it
    # (checks.verify, values=): a translation without a field, or with a lone brace, fails
    # when the Japanese edition runs the cell.
    cells = [(msgid, msgstr) for name, msgid, msgstr in translations() if name == status.CELLS]
    assert len(cells) > 400
    assert [(msgid, f) for msgid, msgstr in cells
            for f in status.check_template(msgid, msgstr)] == []
    template = "the energy changes by {drift:.0e} over {n} swings"
    assert status.check_template(template, "{n} 回の振動で、エネルギーは {drift:.0e} 変わる") == []
    assert status.check_template(template, "{n} 回の振動で、エネルギーは {drift} 変わる") != []
    assert status.check_template(template, "振動で、エネルギーは {drift:.0e} 変わる") != []
    assert status.check_template(template, "{n} 回の振動で { エネルギーは {drift:.0e}") != []


def test_status_reports_a_message_missing_from_its_catalog(tmp_path: Path) -> None:
    # A current template with one message more than the catalog: what an English change
    # leaves until `make i18n-update` merges it.
    pot, locale = tmp_path / "pot", tmp_path / "locale"
    (locale / "ja" / "LC_MESSAGES").mkdir(parents=True)
    pot.mkdir()
    head = 'msgid ""\nmsgstr ""\n"Content-Type: text/plain; charset=utf-8\\n"\n\n'
    (pot / "page.pot").write_text(head + 'msgid "One."\nmsgstr ""\n\nmsgid "Two."\nmsgstr ""\n')
    (locale / "ja" / "LC_MESSAGES" / "page.po").write_text(
        head + 'msgid "One."\nmsgstr "一つ。"\n', encoding="utf-8")
    problems, counts = status.check(pot, locale, "ja")
    assert [(p.msgid, p.what) for p in problems] == [("Two.", "not in the catalog (merge it)")]
    assert counts == {"page": (2, 1)}


def test_the_translation_is_in_our_own_words() -> None:
    # The note's prose, as a fingerprint of its 20-character runs (tools/i18n/overlap.py):
    # the share of them that reappears in our Japanese, below 2%.
    fraction, found, runs = overlap.share(text for _, _, text in translations())
    print(f"note's prose runs found in the translations: {found} of {runs} ({fraction:.2%})")
    assert runs > 2000
    assert fraction < 0.02


def test_the_overlap_measure_finds_copied_prose() -> None:
    # The measure must see a copy: a sentence's own runs are all found in itself, and in a
    # text that quotes it; none in an unrelated one.
    sentence = ("単振り子の運動は楕円関数を用いて厳密に表すことができ、"
                "その周期は完全楕円積分で与えられる。")
    note = overlap.runs(sentence)
    assert overlap.share([f"前置き。{sentence}後書き。"], note)[0] == 1.0
    other = "まったく別の文章であり、同じ言い回しはどこにも現れない。"
    assert overlap.share([other], note)[0] == 0.0
