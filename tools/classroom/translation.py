"""Apply a page's gettext catalog to its MyST source, as Sphinx applies it to the page.

The Japanese edition of the book is the English pages plus ``book/locale/<lang>/LC_MESSAGES/
<page>.po`` (book/_ext/i18n.py). The classroom notebooks of that edition come from the same
two: the exporter translates each Markdown cell here and then converts the translated MyST
as it converts the English. So a notebook says what the page says, and a changed English
paragraph cannot reach a Japanese notebook without its catalog entry (:class:`Untranslated`).

A message is what Sphinx's gettext builder extracts: the text of one paragraph, heading,
list item, table cell, definition term, directive title or figure caption, its lines joined
by spaces. myst-parser makes those nodes from markdown-it's ``inline`` tokens, whose
``content`` is exactly that text, so the source is parsed here with myst-parser's own
markdown-it set-up and each inline token's lines are replaced by its translation. Directive
bodies are not parsed by markdown-it (a fence is one token): they are translated
recursively, their titles and ``:alt:`` / ``:caption:`` options looked up too.
sphinx-proof adds two messages of its own making: a statement's title in parentheses and a
proof's first paragraph behind "Proof. "; both are looked up that way as well.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

from markdown_it import MarkdownIt

# Bodies that hold no messages: display math (book/_ext/i18n.py keeps it out of the
# catalogs), code, and navigation (a toctree's caption option is one, its entries are not).
NO_MESSAGES = {"math", "code", "code-block", "sourcecode", "toctree", "raw", "glue",
               "glue:any", "glue:figure", "glue:math", "glue:md", "bibliography", "index"}
# Arguments that are no title: a solution's is its exercise's label, a figure's its file.
NOT_A_TITLE = {"solution", "solution-start", "solution-end", "exercise-end", "figure",
               "image", *NO_MESSAGES}
TRANSLATED_OPTIONS = ("alt", "caption")
OPTION = re.compile(r"^(?P<indent>\s*):(?P<key>[\w-]+):(?P<space>\s*)(?P<value>.*)$")
FENCE_INFO = re.compile(r"^\{(?P<name>[^}]+)\}\s*(?P<arg>.*)$")
# What sphinx-proof puts before a proof's first paragraph, and what its translation begins
# with (the catalogs translate "Proof." as 証明。).
PROOF_PREFIX = "Proof. "
PROOF_TRANSLATED = re.compile(r"^\s*(証明[。．.:：]?\s*)")
PARENS = re.compile(r"^\s*[（(](?P<inner>.*)[）)]\s*$", re.S)


class Untranslated(ValueError):
    """A message of the English source that the catalog does not translate."""


@dataclass
class Catalog:
    """One page's translations, msgid -> msgstr (translated, not fuzzy, entries only)."""

    page: str
    messages: dict[str, str] = field(default_factory=dict)
    missing: list[str] = field(default_factory=list)

    def get(self, msgid: str) -> str | None:
        return self.messages.get(msgid)

    def need(self, msgid: str) -> str:
        """The translation of msgid; an English text that has none is remembered."""
        found = self.get(msgid)
        if found is None:
            self.missing.append(msgid)
            return msgid
        return found

    def check(self) -> None:
        """Raise Untranslated if any message looked up had no translation."""
        if self.missing:
            shown = "; ".join(repr(m[:80]) for m in self.missing[:5])
            raise Untranslated(
                f"page {self.page!r}: {len(self.missing)} message(s) not in its catalog "
                f"(run `make i18n-update`, then translate): {shown}")


def load(locale_dir: Path, language: str, page: str) -> Catalog:
    """The catalog ``<locale_dir>/<language>/LC_MESSAGES/<page>.po`` (empty if there is none)."""
    from babel.messages.pofile import read_po

    catalog = Catalog(page)
    path = locale_dir / language / "LC_MESSAGES" / f"{page}.po"
    if not path.exists():
        return catalog
    with path.open("rb") as src:
        for message in read_po(src, locale=language):
            if message.id and message.string and not message.fuzzy:
                catalog.messages[str(message.id)] = str(message.string)
    return catalog


@cache
def _parser() -> MarkdownIt:
    # The book's MyST set-up (book/conf.py's myst_enable_extensions and dmath option), so
    # that the blocks found here are the ones myst-parser makes nodes of.
    from markdown_it.renderer import RendererHTML
    from myst_parser.config.main import MdParserConfig
    from myst_parser.parsers.mdit import create_md_parser

    config = MdParserConfig(enable_extensions={"dollarmath", "amsmath", "colon_fence",
                                               "deflist"}, dmath_double_inline=True)
    return create_md_parser(config, RendererHTML)


def _message(text: str) -> str:
    # Sphinx's extract_messages: the raw source with its line breaks as spaces.
    return text.replace("\n", " ").strip()


def _replace_inline(lines: list[str], start: int, end: int, content: str, new: str,
                    column: dict[int, int]) -> None:
    """Put ``new`` where ``content`` (the inline token's text) stands in lines[start:end]."""
    parts = [p.strip() for p in content.strip().split("\n")]
    first = lines[start].find(parts[0], column.get(start, 0))
    if first < 0:
        raise ValueError(f"cannot place a message in the source: {parts[0][:80]!r}")
    if len(parts) == 1:  # a cell of a table may share its line with others
        stop = first + len(parts[0])
        lines[start] = lines[start][:first] + new + lines[start][stop:]
        column[start] = first + len(new)
        return
    last = start + len(parts) - 1
    if last >= end or lines[last].strip().find(parts[-1]) < 0:
        raise ValueError(f"cannot place a message in the source: {parts[0][:80]!r}")
    tail = lines[last][lines[last].find(parts[-1]) + len(parts[-1]):]
    lines[start] = lines[start][:first] + new + tail
    for i in range(start + 1, last + 1):
        lines[i] = None  # type: ignore[call-overload]


def translate(text: str, catalog: Catalog, proof: bool = False) -> str:
    """``text`` (MyST Markdown) with every message replaced by its translation.

    A message without one stays English and is remembered in ``catalog.missing``.
    """
    lines: list[str | None] = list(text.split("\n"))
    column: dict[int, int] = {}
    first_paragraph = proof
    for token in _parser().parse(text):
        if token.map is None:
            continue
        start, end = token.map
        if token.type == "inline" and token.content.strip():
            msgid = _message(token.content)
            found = catalog.get(msgid)
            if found is None and first_paragraph:
                prefixed = catalog.get(PROOF_PREFIX + msgid)
                if prefixed is not None:
                    found = PROOF_TRANSLATED.sub("", prefixed, count=1)
            new = found if found is not None else catalog.need(msgid)
            first_paragraph = False
            _replace_inline(lines, start, end, token.content, new, column)  # type: ignore[arg-type]
        elif token.type in ("fence", "colon_fence"):
            _directive(lines, start, end, token.info, token.markup, catalog)
    return "\n".join(line for line in lines if line is not None)


def _directive(lines: list[str | None], start: int, end: int, info: str, markup: str,
               catalog: Catalog) -> None:
    opened = FENCE_INFO.match(info.strip())
    if opened is None:  # a plain code block
        return
    name, arg = opened["name"].strip(), opened["arg"].strip()
    head = lines[start]
    assert head is not None
    if arg and name not in NOT_A_TITLE:
        found = catalog.get(arg)
        if found is None and name.startswith("prf:"):
            # sphinx-proof's title node holds the title in parentheses.
            around = catalog.get(f"({arg})")
            inner = PARENS.match(around) if around is not None else None
            found = inner["inner"] if inner else None
        new = found if found is not None else catalog.need(arg)
        lines[start] = head[: head.rindex(arg)] + new + head[head.rindex(arg) + len(arg):]
    if name in {"code", "code-block", "sourcecode"}:
        return
    # The body: options first, then MyST; the closing fence (if any) is the last line.
    closes = end - 1 if end - 1 > start and (lines[end - 1] or "").strip().startswith(
        markup) else end
    body = start + 1
    while body < closes:
        option = OPTION.match(lines[body] or "")
        if option is None:
            break
        if option["key"] in TRANSLATED_OPTIONS and option["value"].strip():
            value = option["value"].strip()
            new = catalog.need(value)
            lines[body] = f"{option['indent']}:{option['key']}:{option['space']}{new}"
        body += 1
    if body == closes or name in NO_MESSAGES:
        return
    inner = "\n".join(line for line in lines[body:closes] if line is not None)
    # One entry for the whole body, so that the lines of the tokens after it keep their
    # indices (markdown-it's maps count the lines of the untranslated text).
    lines[body] = translate(inner, catalog, proof=name == "prf:proof")
    for i in range(body + 1, closes):
        lines[i] = None
