"""The language of what the library writes for a reader, chosen per call.

A function that writes text for a reader (a verdict of :mod:`.checks.verify`, the registry's
tables, a Motion's table in Jupyter, the words of a figure) takes ``language=`` where it is
public. ``None`` means the environment's language as gettext reads it
(:func:`environment_language`), read when the function is called; a language the package has
no messages in gives English. Nothing global is set: each call chooses, and a :class:`Say`
carries the choice through one call.

English is written where it is used, as the key of its translation (as with gettext): each
module calls ``say("English text", **fields)``. The Japanese of a subpackage is its module
``_ja`` (``checks/_ja.py``, ``plotting/_ja.py``, this package's ``_ja.py``), a table
``MESSAGES`` from each exact English text to its Japanese, imported only when Japanese is
asked for.

The texts a caller passes in (a book's fact, "20 swings", a mutant's label) are looked up
the same way, in a catalog from outside the package: the environment variable
``ELLIPTIC_PENDULUM_MESSAGES`` names one or more gettext catalogs (``.po`` or ``.mo``
files, separated by ``os.pathsep``), read when a text is looked up (each file parsed once
per modification time). A catalog whose header names a language (``Language: ja``) serves
that language only; one without serves every language but English. Its entries take
precedence over the package's own, so a translator can also correct those without a
release; fuzzy and empty entries are ignored. A text found nowhere stays English.

Standard library only: every part of the package may use it.
"""

from __future__ import annotations

import gettext
import importlib
import os
import re
import string
from collections.abc import Callable, Collection, Iterable, Mapping
from dataclasses import dataclass
from functools import cache, lru_cache
from pathlib import Path
from types import MappingProxyType
from typing import Any

__all__ = ["CATALOG_VARIABLE", "LANGUAGES", "LANGUAGE_VARIABLES", "Say", "catalog",
           "environment_language", "read_po", "resolve", "say_for"]

# Where gettext looks for the language of messages, in its order.
LANGUAGE_VARIABLES = ("LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG")
# The languages the package writes: English, and those with _<language>.py tables.
LANGUAGES = ("en", "ja")
CATALOG_VARIABLE = "ELLIPTIC_PENDULUM_MESSAGES"
# How a language joins two sentences of one paragraph: Japanese runs them on.
_SENTENCE_GAP = {"ja": ""}
# Japanese sets a space between its own letters and Latin letters, digits or math ("1e-9
# 以内", "振幅 $A$"); a template cannot know what a field brings, so the space is set where
# a field meets the template's text.
_JAPANESE_LETTER = re.compile(r"[\u3040-\u30ff\u4e00-\u9fff]")
_LATIN_EDGE = re.compile(r"[A-Za-z0-9$()|]")


def _code(entry: str) -> str:
    """Return the language of a locale name: "ja_JP.UTF-8" and "ja@x" are "ja"."""
    return entry.split(".")[0].split("@")[0].split("_")[0]


def environment_language(environ: Mapping[str, str] | None = None,
                         known: Collection[str] | Callable[[str], bool] = LANGUAGES) -> str:
    """Return the language of the messages as gettext would choose it from the environment.

    The first of LANGUAGE (a colon-separated list), LC_ALL, LC_MESSAGES and LANG that is set
    decides: its first entry in a ``known`` language wins ("ja_JP.UTF-8" is "ja"); "C",
    "POSIX" or an entry in none gives English. ``known`` is a collection of languages, or a
    test of one (the self-checks ask whether they have messages in it).

    >>> environment_language({"LANG": "ja_JP.UTF-8"}), environment_language({})
    ('ja', 'en')
    >>> environment_language({"LANGUAGE": "fr:ja", "LANG": "en_US.UTF-8"})
    'ja'
    """
    env: Mapping[str, str] = os.environ if environ is None else environ
    has = known if callable(known) else known.__contains__
    for variable in LANGUAGE_VARIABLES:
        value = env.get(variable, "")
        if not value:
            continue
        for entry in value.split(":"):
            code = _code(entry)
            if code == "en" or (code.isidentifier() and has(code)):
                return code
        return "en"
    return "en"


def resolve(language: str | None) -> str:
    """Return the language to write in: ``language`` if the package writes it, else English.

    ``None`` is the environment's (:func:`environment_language`); a locale name counts as
    its language ("ja_JP.UTF-8" is "ja").

    >>> resolve("ja_JP.UTF-8"), resolve("xx"), resolve("en")
    ('ja', 'en', 'en')
    """
    if language is None:
        return environment_language()
    code = _code(str(language))
    return code if code in LANGUAGES else "en"


@cache
def _package_messages(package: str, language: str) -> Mapping[str, str]:
    # Imported on first use: an English session never loads a _ja module.
    module = importlib.import_module(f"{package}._{language}")
    return MappingProxyType(dict(module.MESSAGES))


# --- catalogs from outside the package --------------------------------------------------

_PO_LINE = re.compile(r'^(msgctxt|msgid|msgid_plural|msgstr(?:\[\d+\])?)\s+"(.*)"\s*$')
_PO_ESCAPES = {"n": "\n", "t": "\t", '"': '"', "\\": "\\", "r": "\r"}


def _unquote(text: str) -> str:
    return re.sub(r"\\(.)", lambda m: _PO_ESCAPES.get(m.group(1), "\\" + m.group(1)), text)


def read_po(text: str) -> tuple[dict[str, str], str]:
    r"""Return a .po file's translations {msgid: msgstr} and the language of its header.

    A minimal reader: plain and continued strings, the header's ``Language``; entries that
    are fuzzy, untranslated, plural or obsolete (``#~``) are left out, and a context
    (``msgctxt``) is ignored.

    >>> read_po('msgid ""\nmsgstr "Language: ja\\n"\n\n#, fuzzy\nmsgid "a"\nmsgstr "b"\n'
    ...         '\nmsgid "max"\n"imum"\nmsgstr "最大"\n"値"\n')
    ({'maximum': '最大値'}, 'ja')
    """
    messages: dict[str, str] = {}
    header = ""
    entries: list[dict[str, str]] = [{}]
    key = ""
    for line in text.splitlines():
        line = line.strip()
        if not line:
            entries.append({})
            continue
        if line.startswith("#"):
            if line.startswith("#,") and "fuzzy" in line:
                entries[-1]["fuzzy"] = "1"
            continue
        match = _PO_LINE.match(line)
        if match:
            if match.group(1) in ("msgctxt", "msgid") and "msgstr" in entries[-1]:
                entries.append({})  # a new entry without a blank line before it
            key = match.group(1)
            entries[-1][key] = entries[-1].get(key, "") + _unquote(match.group(2))
        elif line.startswith('"') and line.endswith('"') and key:
            entries[-1][key] = entries[-1].get(key, "") + _unquote(line[1:-1])
    for entry in entries:
        if "msgid" not in entry or "msgstr" not in entry:
            continue
        if entry["msgid"] == "":
            header = entry["msgstr"]
        elif entry["msgstr"] and "fuzzy" not in entry and "msgid_plural" not in entry:
            messages[entry["msgid"]] = entry["msgstr"]
    found = re.search(r"^Language:\s*(\S*)\s*$", header, re.MULTILINE)
    return messages, _code(found.group(1)) if found else ""


@lru_cache(maxsize=64)
def _read_catalog(path: str, mtime_ns: int, size: int) -> tuple[Callable[[str], str | None], str]:
    # Keyed by the file's modification time and size: an edited catalog is read again.
    del mtime_ns, size
    if path.endswith(".mo"):
        with open(path, "rb") as file:
            translations = gettext.GNUTranslations(file)

        def lookup(text: str) -> str | None:
            found = translations.gettext(text)
            return found if found != text else None

        return lookup, _code(translations.info().get("language", ""))
    messages, language = read_po(Path(path).read_text(encoding="utf-8"))
    return messages.get, language


def catalog(language: str, environ: Mapping[str, str] | None = None,
            ) -> Callable[[str], str | None]:
    """Return a lookup of the catalogs that ``ELLIPTIC_PENDULUM_MESSAGES`` names, for ``language``.

    The lookup gives a text's translation, or None when no catalog has it. English has none.
    A named file that does not exist raises FileNotFoundError: a catalog that was meant to
    be read is not silently skipped.
    """
    env: Mapping[str, str] = os.environ if environ is None else environ
    paths = [p for p in env.get(CATALOG_VARIABLE, "").split(os.pathsep) if p]
    if language == "en" or not paths:
        return _nothing
    lookups = []
    for path in paths:
        stat = os.stat(path)
        lookup, its_language = _read_catalog(os.path.abspath(path), stat.st_mtime_ns,
                                             stat.st_size)
        if its_language in ("", language):
            lookups.append(lookup)

    def first(text: str) -> str | None:
        for lookup in lookups:
            found = lookup(text)
            if found is not None:
                return found
        return None

    return first


def _nothing(text: str) -> str | None:
    return None


# --- one call's language ------------------------------------------------------------------

@dataclass(frozen=True)
class Say:
    """The texts of one call in one language: ``say("English {x}", x=...)``.

    ``say(text)`` is the translation of ``text`` (the catalog's, else the package's, else
    ``text`` itself); with fields, the translation is then formatted with them (a template
    with fields writes a literal brace as ``{{``; a text without fields is never formatted).
    """

    language: str
    messages: Mapping[str, str]
    extra: Callable[[str], str | None] = _nothing

    def __call__(self, english: str, /, **fields: Any) -> str:
        text = english
        # "" is no message (a gettext catalog keeps its header there).
        if self.language != "en" and english:
            found = self.extra(english)
            text = found if found is not None else self.messages.get(english, english)
        if not fields:
            return text
        if self.language != "ja":
            return text.format(**fields)
        return _spaced(text, fields)

    def sentences(self, parts: Iterable[str]) -> str:
        """Join sentences as the language does (a space in English, none in Japanese)."""
        return _SENTENCE_GAP.get(self.language, " ").join(parts)


def _spaced(template: str, fields: Mapping[str, Any]) -> str:
    """Fill a Japanese template, spacing a field from the kana and kanji around it.

    A space is set where a field's Latin edge meets a kana or kanji of the template or of
    another field, and none where there is a space already.
    """
    pieces: list[tuple[bool, str]] = []  # (a field's value?, text)
    for literal, name, spec, conversion in string.Formatter().parse(template):
        if literal:
            pieces.append((False, literal))
        if name is not None:
            field = "{" + name + (f"!{conversion}" if conversion else "") + (
                f":{spec}" if spec else "") + "}"
            pieces.append((True, field.format(**fields)))
    out = ""
    for i, (is_field, text) in enumerate(pieces):
        if out and text and (is_field or pieces[i - 1][0]) and (
                _JAPANESE_LETTER.match(out[-1]) and _LATIN_EDGE.match(text[0])
                or _LATIN_EDGE.match(out[-1]) and _JAPANESE_LETTER.match(text[0])):
            out += " "
        out += text
    return out


def say_for(package: str, language: str | None) -> Say:
    """Return the :class:`Say` of a call in ``language`` (None: the environment's).

    ``package`` holds the table: its module ``_<language>`` (``MESSAGES``).
    """
    chosen = resolve(language)
    if chosen == "en":
        return Say("en", MappingProxyType({}))
    return Say(chosen, _package_messages(package, chosen), catalog(chosen))
