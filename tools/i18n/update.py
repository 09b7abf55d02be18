"""Merge the catalogs with the messages of the current English pages.

``python -m tools.i18n.update book/_build/gettext book/locale ja``: for each template that
Sphinx's gettext builder wrote (``<page>.pot``), ``msgmerge --previous`` into
``<locale>/ja/LC_MESSAGES/<page>.po`` (a new page gets a new catalog, ``msginit``). A changed
English message keeps its old translation marked fuzzy, with the old English as ``#|`` lines,
so the translator sees what changed; ``make i18n-status`` fails until it is done.

A message with no prose (only roles, formulas and code: ``{ref}`ex-energy-fastest```,
``$\\theta_0$``) is its own translation, and is filled in as such.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

from babel.messages.pofile import read_po, write_po

NOT_PROSE = re.compile(r"\{[\w:-]+\}`[^`]*`|`[^`]*`|\$[^$]*\$|[\W\d_]")


def fill_neutral(po: Path) -> int:
    """Give each message without prose itself as translation; how many were filled."""
    with po.open("rb") as f:
        catalog = read_po(f)
    filled = 0
    for message in catalog:
        if message.id and not message.string and not NOT_PROSE.sub("", message.id):
            message.string = message.id
            filled += 1
    if filled:
        with po.open("wb") as f:
            write_po(f, catalog, width=0, omit_header=False)
    return filled


def update(pot_dir: Path, locale: Path, language: str) -> list[Path]:
    folder = locale / language / "LC_MESSAGES"
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for pot in sorted(pot_dir.glob("*.pot")):
        po = folder / f"{pot.stem}.po"
        if po.exists():
            cmd = ["msgmerge", "--quiet", "--previous", "--no-wrap", "--update",
                   "--backup=none", str(po), str(pot)]
        else:
            cmd = ["msginit", "--no-translator", "--no-wrap", f"--locale={language}",
                   f"--input={pot}", f"--output-file={po}"]
        subprocess.run(cmd, check=True)
        # Messages that no page holds any more go: git keeps their history.
        subprocess.run(["msgattrib", "--no-obsolete", "--no-wrap", f"--output-file={po}",
                        str(po)], check=True)
        fill_neutral(po)
        written.append(po)
    return written


if __name__ == "__main__":
    pot_dir, locale, language = Path(sys.argv[1]), Path(sys.argv[2]), sys.argv[3]
    for path in update(pot_dir, locale, language):
        print(path)
