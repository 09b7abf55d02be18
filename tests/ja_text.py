"""What the tests of the library's Japanese share: finding English left in a Japanese text,
reading the English messages a module writes from its source, and the environments in which
gettext names a language.

A module writes a message as ``say("English", ...)``; :func:`say_literals` reads those first
arguments with the ast module, as xgettext would, so a message added to a module without its
Japanese fails the tables' tests (and one removed leaves a stale translation, which fails
too).
"""

from __future__ import annotations

import ast
import re
import string
from collections import Counter
from pathlib import Path

# Spans that are not prose: display and inline math, a role with its target, inline code,
# an HTML tag, a Markdown link's target.
SPANS = re.compile(r"\$\$.*?\$\$|\$[^$]*\$|\{[\w:-]+\}`[^`]*`|`[^`]*`|<[^>]+>|\]\([^)]*\)",
                   re.DOTALL)
MATH = re.compile(r"\$[^$]*\$")
# Kana, kanji, and the Japanese punctuation and full-width forms (（）：、).
JAPANESE = re.compile(r"[\u3000-\u30ff\u4e00-\u9fff\uff00-\uffef]")
_WORD = r"[A-Za-z][A-Za-z0-9'\u2019-]*"
# Three or more English words in a row, with only spaces and ASCII punctuation between them.
_RUN = re.compile(rf"{_WORD}(?:[ \t,;:/.()]+{_WORD}){{2,}}")
# (environment, the language it names) in gettext.find's order: the first of LANGUAGE,
# LC_ALL, LC_MESSAGES and LANG that is set decides (an empty one is skipped), and its first
# entry in a language with messages wins; both the package's rule (_i18n) and the
# self-checks' (selfcheck._core) are held to it, where Japanese has messages.
GETTEXT_ENVIRONMENTS = [
    ({}, "en"),
    ({"LANG": "ja_JP.UTF-8"}, "ja"),
    ({"LANG": "C"}, "en"),
    ({"LC_ALL": "ja_JP.eucJP", "LANG": "en_GB.UTF-8"}, "ja"),
    ({"LC_MESSAGES": "en_US.UTF-8", "LANG": "ja_JP.UTF-8"}, "en"),
    ({"LANGUAGE": "de:ja", "LANG": "en_US.UTF-8"}, "ja"),
    ({"LANGUAGE": "de:fr", "LANG": "ja_JP.UTF-8"}, "en"),
    ({"LANGUAGE": "", "LANG": "ja_JP"}, "ja"),
]


def english_runs(text: str) -> list[str]:
    """Return the runs of three or more English words in ``text`` outside math and code."""
    return _RUN.findall(SPANS.sub(" \u3000 ", text))


def prose(text: str) -> str:
    """Return ``text`` without its math and code."""
    return SPANS.sub("", text)


def placeholders(template: str) -> Counter[str]:
    return Counter(name for _, name, _, _ in string.Formatter().parse(template)
                   if name is not None)


def say_literals(*paths: Path) -> set[str]:
    """Return the literal first arguments of the ``say(...)`` calls in the given sources."""
    found = set()
    for path in paths:
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if not isinstance(node, ast.Call) or not node.args:
                continue
            name = node.func.id if isinstance(node.func, ast.Name) else (
                node.func.attr if isinstance(node.func, ast.Attribute) else "")
            first = node.args[0]
            if name == "say" and isinstance(first, ast.Constant) and isinstance(first.value, str):
                found.add(first.value)
    return found


def check_translation(english: str, japanese: str) -> None:
    """Assert what every entry of a Japanese table keeps and what it changes.

    The English message is the reference: the same placeholders, the same formulas and code
    (the reader's notebook typesets the same spans), the same table columns; Japanese outside
    them, and no run of English words left.
    """
    assert placeholders(japanese) == placeholders(english)
    assert Counter(MATH.findall(japanese)) == Counter(MATH.findall(english))
    assert Counter(re.findall(r"`[^`]*`", japanese)) == Counter(re.findall(r"`[^`]*`", english))
    if english.startswith("|"):  # a table's row: the same columns
        assert japanese.count("|") == english.count("|")
    assert JAPANESE.search(prose(japanese)), "no Japanese outside the formulas"
    assert english_runs(japanese) == []
    assert japanese == japanese.strip() and "  " not in japanese
