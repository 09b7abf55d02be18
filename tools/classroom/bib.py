"""A small reader of the book's references.bib for the classroom notebooks.

The notebooks cannot run sphinxcontrib-bibtex, so a citation becomes a link to a short
reference list at the end of the notebook. The labels are author-year ("Takeno, 2024";
"Abramowitz and Stegun, 1964"): the book's pages cite by the numbers of the book's one list,
which a notebook does not carry, so its own short list names the works. The entries give
authors, title, where it appeared and the year. Only the plain BibTeX the book uses is
understood: ``@type{key,`` then ``field = {value}`` or ``"value"`` or a bare number, braces
nested.
"""

from __future__ import annotations

import re
from pathlib import Path

ENTRY = re.compile(r"@(?P<type>\w+)\s*\{\s*(?P<key>[^,\s]+)\s*,", re.MULTILINE)
FIELD = re.compile(r"\s*(?P<name>\w+)\s*=\s*")


def _value(text: str, i: int) -> tuple[str, int]:
    """Read one field value starting at text[i]; return it and the index after it."""
    if text[i] == "{":
        depth, j = 0, i
        while True:
            if text[j] == "{":
                depth += 1
            elif text[j] == "}":
                depth -= 1
                if depth == 0:
                    return text[i + 1 : j], j + 1
            j += 1
    if text[i] == '"':
        j = text.index('"', i + 1)
        return text[i + 1 : j], j + 1
    m = re.compile(r"[^,}\s]+").match(text, i)
    if m is None:
        raise ValueError(f"bibliography: cannot read a value at {text[i:i + 40]!r}")
    return m.group(), m.end()


def parse_bib(text: str) -> dict[str, dict[str, str]]:
    """Return ``{key: {field: value}}`` for every entry of a BibTeX text."""
    entries: dict[str, dict[str, str]] = {}
    for m in ENTRY.finditer(text):
        fields = {"ENTRYTYPE": m["type"].lower()}
        i = m.end()
        while True:
            f = FIELD.match(text, i)
            if f is None:
                break
            value, i = _value(text, f.end())
            fields[f["name"].lower()] = value
            comma = re.compile(r"\s*,").match(text, i)
            if comma is None:
                break
            i = comma.end()
        entries[m["key"]] = fields
    return entries


def plain(value: str) -> str:
    """Remove BibTeX markup: \\url{...} keeps its argument, braces go."""
    value = re.sub(r"\\url\{([^}]*)\}", r"\1", value)
    return re.sub(r"\s+", " ", value.replace("{", "").replace("}", "")).strip()


def _last_names(people: str) -> list[str]:
    names = []
    for person in re.split(r"\s+and\s+", people.strip()):
        if person.startswith("{") and person.endswith("}"):  # a corporate author, kept whole
            names.append(plain(person))
        elif "," in person:
            names.append(plain(person.split(",")[0]))
        else:
            names.append(plain(person.split()[-1]))
    return names


def _full_names(people: str) -> str:
    out = []
    for person in re.split(r"\s+and\s+", people.strip()):
        if "," in person and not person.startswith("{"):
            last, first = person.split(",", 1)
            out.append(f"{plain(first)} {plain(last)}")
        else:
            out.append(plain(person))
    return ", ".join(out)


def label(entry: dict[str, str]) -> tuple[str, str]:
    """Return (who, year) of an entry as the book's author-year citations show them."""
    people = entry.get("author") or entry.get("editor")
    if people:
        last = _last_names(people)
        who = last[0] if len(last) == 1 else (
            f"{last[0]} and {last[1]}" if len(last) == 2 else f"{last[0]} et al."
        )
    else:
        who = plain(entry.get("key", entry.get("title", "")))
    return who, plain(entry.get("year", "n.d."))


def reference_line(key: str, entry: dict[str, str]) -> str:
    """One Markdown line of the reference list, with the anchor that citations link to."""
    who, year = label(entry)
    parts = []
    people = entry.get("author") or entry.get("editor")
    if people:
        parts.append(_full_names(people) + (" (ed.)" if "author" not in entry else ""))
    parts.append(f"*{plain(entry.get('title', key))}*")
    for name in ("series", "publisher", "howpublished", "journal", "booktitle"):
        if name in entry:
            parts.append(plain(entry[name]))
    parts.append(year)
    if "note" in entry:
        parts.append(plain(entry["note"]))
    return f'- <a id="ref-{key}"></a>**[{who}, {year}]** ' + ". ".join(parts) + "."


def load(path: Path) -> dict[str, dict[str, str]]:
    """Read a .bib file; an absent file gives no entries."""
    return parse_bib(path.read_text(encoding="utf-8")) if path.exists() else {}
