"""Is every message of the current English pages translated, and is each translation whole?

``python -m tools.i18n.status book/_build/gettext book/locale ja`` compares the templates that
Sphinx's gettext builder has just extracted from the pages (``<pot>/<page>.pot``: the current
messages) with the catalogs (``<locale>/ja/LC_MESSAGES/<page>.po``), and fails unless

* every current message is in its catalog, translated, and not fuzzy (a .po alone cannot say
  this: after an English change its entry is simply missing until the catalog is merged);
* each translation keeps what the build needs from its message and what no builder checks
  (``msgfmt -c`` does not): the same roles with the same targets, glue keys and formats, the
  same inline formulas and code spans, no blank line (only its first paragraph would be
  kept), closed roles, and no ``**`` emphasis against a CJK bracket (shown as asterisks).

The catalog ``cells`` holds the texts that the pages' code cells pass to the library (a
fact's sentence, a figure's label: ``tools/i18n/library_texts.py`` writes its template beside
the pages'); the library fills those that are templates with ``str.format``, so each of its
translations also keeps the template's fields.

``--catalogs-only`` runs the second part on the catalogs alone, without templates.
"""

from __future__ import annotations

import argparse
import re
import string
import sys
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

from babel.messages.pofile import read_po
from markdown_it import MarkdownIt

_MD = MarkdownIt("commonmark")

# {role}`target` and {role}`text <target>`: the role and what it points to must survive.
ROLE = re.compile(r"\{([\w:-]+)\}`([^`]*)`")
MATH = re.compile(r"(?<![\\$])\$(?!\$)((?:\\.|[^$\\])+)\$")
CODE = re.compile(r"(?<![`}])``?([^`]+)``?")
# Roles whose text is prose that is translated; for the others the whole content is kept.
TEXT_ROLES = {"ref", "numref", "doc", "prf:ref", "term"}
# The catalog of the cells' texts, whose templates str.format fills.
CELLS = "cells"


@dataclass
class Problem:
    catalog: str
    msgid: str
    what: str

    def __str__(self) -> str:
        return f"{self.catalog}: {self.what}: {self.msgid[:100]!r}"


def _targets(text: str) -> Counter[str]:
    """The roles of a message with what each points to (a text role's text may change)."""
    found: Counter[str] = Counter()
    for role, content in ROLE.findall(text):
        if role in TEXT_ROLES:
            m = re.search(r"<([^<>]+)>\s*$", content)
            content = m.group(1) if m else content
            if role in ("ref", "numref", "doc", "term") and not m:
                content = "=" + content  # an implicit title: the translation may not add one
        found[f"{{{role}}}{content.strip()}"] += 1
    return found


def _stray_asterisks(text: str) -> int:
    """Asterisks left as text by CommonMark's flanking rules, as next to a CJK bracket
    (``は**「特異」**解``), which no builder reports."""
    tokens = _MD.parseInline(text)
    return sum(child.content.count("*") for token in tokens for child in token.children or []
               if child.type == "text")


def check_entry(msgid: str, msgstr: str) -> list[str]:
    """What is wrong with one translation (empty: nothing)."""
    faults = []
    if _targets(msgid) != _targets(msgstr):
        lost = _targets(msgid) - _targets(msgstr)
        extra = _targets(msgstr) - _targets(msgid)
        faults.append(f"roles differ (lost {sorted(lost)}, added {sorted(extra)})")
    # Sets: a translation may name a symbol once more, or once less, than its message.
    if set(MATH.findall(msgid)) != set(MATH.findall(msgstr)):
        faults.append("inline formulas differ")
    plain_id, plain_str = ROLE.sub("", msgid), ROLE.sub("", msgstr)
    if set(CODE.findall(plain_id)) != set(CODE.findall(plain_str)):
        faults.append("code spans differ")
    if plain_str.count("`") % 2:
        faults.append("an unclosed role or code span")
    if re.search(r"\n\s*\n", msgstr):
        faults.append("a blank line (only the first paragraph would be kept)")
    if _stray_asterisks(msgstr) > _stray_asterisks(msgid):
        faults.append("** that CommonMark does not read as emphasis (shown as asterisks)")
    return faults


def _fields(text: str) -> Counter[str] | None:
    """The fields of a str.format template with their formats, or None if it is malformed."""
    try:
        return Counter(f"{name}:{spec}" for _, name, spec, _ in string.Formatter().parse(text)
                       if name is not None)
    except ValueError:
        return None


def check_template(msgid: str, msgstr: str) -> list[str]:
    """What a translation of a cell's text must also keep: its template's fields."""
    if _fields(msgstr) is None:
        return ["a lone brace (write {{ or }} for a brace of the text)"]
    if _fields(msgstr) != _fields(msgid):
        return [f"template fields differ ({sorted(_fields(msgid) or [])} in the message)"]
    return []


def _read(path: Path):
    with path.open("rb") as f:
        return read_po(f, abort_invalid=True)


def check(pot_dir: Path | None, locale: Path, language: str) -> tuple[list[Problem], dict]:
    """The problems, and counts: messages, translated, per catalog."""
    folder = locale / language / "LC_MESSAGES"
    problems: list[Problem] = []
    counts: dict[str, tuple[int, int]] = {}
    names = (sorted(p.stem for p in pot_dir.glob("*.pot")) if pot_dir is not None
             else sorted(p.stem for p in folder.glob("*.po")))
    for name in names:
        po_path = folder / f"{name}.po"
        if not po_path.exists():
            problems.append(Problem(name, "", "no catalog"))
            continue
        po = _read(po_path)
        entries = {m.id: m for m in po if m.id}
        wanted = ([m.id for m in _read(pot_dir / f"{name}.pot") if m.id]
                  if pot_dir is not None else list(entries))
        done = 0
        for msgid in wanted:
            entry = entries.get(msgid)
            if entry is None:
                problems.append(Problem(name, msgid, "not in the catalog (merge it)"))
                continue
            if entry.fuzzy:
                problems.append(Problem(name, msgid, "fuzzy"))
                continue
            if not entry.string:
                problems.append(Problem(name, msgid, "untranslated"))
                continue
            faults = check_entry(msgid, str(entry.string))
            if name == CELLS:
                faults += check_template(msgid, str(entry.string))
            problems.extend(Problem(name, msgid, f) for f in faults)
            done += not faults
        counts[name] = (len(wanted), done)
    return problems, counts


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pot", type=Path, help="the gettext builder's output folder")
    parser.add_argument("locale", type=Path)
    parser.add_argument("language")
    parser.add_argument("--catalogs-only", action="store_true")
    args = parser.parse_args(argv)
    problems, counts = check(None if args.catalogs_only else args.pot, args.locale,
                             args.language)
    total = sum(n for n, _ in counts.values())
    done = sum(d for _, d in counts.values())
    for name, (n, d) in counts.items():
        print(f"{name:24} {d:5}/{n:<5}")
    print(f"{args.language}: {done} of {total} messages translated and whole "
          f"({100 * done / max(total, 1):.1f}%), {len(counts)} catalogs")
    for problem in problems:
        print(problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
