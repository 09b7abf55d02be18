"""The merge of the catalogs with the current pages (tools/i18n/update.py), with babel.

The expectations are GNU msgmerge's documented behaviour, which the tool replaces: an
unchanged message keeps its translation, a changed one keeps it marked fuzzy with the old
English as ``#|`` (msgmerge --previous), a new one is added empty (or as itself when it has
no prose), and one that no page holds any more is dropped (msgattrib --no-obsolete).
"""

from __future__ import annotations

from pathlib import Path

from babel.messages.catalog import Catalog
from babel.messages.pofile import read_po, write_po

from tools.i18n.update import update


def _write(path: Path, messages: dict[str, str], locale: str | None = None) -> None:
    catalog = Catalog(locale=locale)
    for msgid, msgstr in messages.items():
        catalog.add(msgid, msgstr)
    with path.open("wb") as f:
        write_po(f, catalog)


def test_the_merge_keeps_marks_adds_and_drops(tmp_path: Path) -> None:
    pots, locale = tmp_path / "pot", tmp_path / "locale"
    pots.mkdir()
    (locale / "ja" / "LC_MESSAGES").mkdir(parents=True)
    _write(locale / "ja" / "LC_MESSAGES" / "page.po", {
        "The pendulum swings.": "振り子は振動する。",
        "The bob goes over the top quickly.": "おもりは最高点をすばやく越える。",
        "Zeta: gone from every page.": "もうない文。",
    }, "ja")
    _write(pots / "page.pot", {"The pendulum swings.": "",
                               "The bob goes over the top slowly.": "",
                               "A new sentence of the page.": "",
                               "$\\theta_0$": ""})
    (written,) = update(pots, locale, "ja")
    text = written.read_text(encoding="utf-8")
    with written.open("rb") as f:
        catalog = read_po(f)
    assert catalog["The pendulum swings."].string == "振り子は振動する。"
    changed = catalog["The bob goes over the top slowly."]
    assert changed.fuzzy and changed.string == "おもりは最高点をすばやく越える。"
    assert '#| msgid "The bob goes over the top quickly."' in text
    assert catalog["A new sentence of the page."].string == ""
    assert catalog["$\\theta_0$"].string == "$\\theta_0$"  # no prose: its own translation
    assert "Zeta: gone" not in text and "もうない文" not in text
