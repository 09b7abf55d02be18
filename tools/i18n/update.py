"""Merge the catalogs with the messages of the current English pages.

``python -m tools.i18n.update book/_build/gettext book/locale ja``: for each template that
Sphinx's gettext builder wrote (``<page>.pot``), merge it into
``<locale>/ja/LC_MESSAGES/<page>.po`` with babel (a new page gets a new catalog), as GNU
``msgmerge --previous`` would: a changed English message keeps its old translation marked
fuzzy, with the old English as ``#|`` lines, so the translator sees what changed (``make
i18n-status`` fails until it is done); a message no page holds any more goes (git keeps its
history). babel is a dependency of Sphinx already, so no GNU gettext is needed.

A message with no prose (only roles, formulas and code: ``{ref}`ex-energy-fastest```,
``$\\theta_0$``) is its own translation, and is filled in as such.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

from babel.messages.catalog import Catalog
from babel.messages.pofile import read_po, write_po

NOT_PROSE = re.compile(r"\{[\w:-]+\}`[^`]*`|`[^`]*`|\$[^$]*\$|[\W\d_]")


def fill_neutral(catalog: Catalog) -> int:
    """Give each message without prose itself as translation; how many were filled."""
    filled = 0
    for message in catalog:
        if (isinstance(message.id, str) and message.id and not message.string
                and not NOT_PROSE.sub("", message.id)):
            message.string = message.id
            filled += 1
    return filled


def update(pot_dir: Path, locale: Path, language: str) -> list[Path]:
    folder = locale / language / "LC_MESSAGES"
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for pot in sorted(pot_dir.glob("*.pot")):
        po = folder / f"{pot.stem}.po"
        with pot.open("rb") as f:
            template = read_po(f)
        if po.exists():
            with po.open("rb") as f:
                catalog = read_po(f, locale=language)
        else:
            catalog = Catalog(locale=language, project=template.project,
                              version=template.version)
        catalog.update(template, update_header_comment=False)
        catalog.obsolete.clear()
        fill_neutral(catalog)
        # Written once: babel reads no "#|" lines back, so a second pass would lose them.
        with po.open("wb") as f:
            write_po(f, catalog, width=0, omit_header=False, include_previous=True,
                     ignore_obsolete=True)
        written.append(po)
    return written


if __name__ == "__main__":
    pot_dir, locale, language = Path(sys.argv[1]), Path(sys.argv[2]), sys.argv[3]
    for path in update(pot_dir, locale, language):
        print(path)
