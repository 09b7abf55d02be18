"""What a reader of a chapter reads in its main column: its visible prose, as sentences.

The book's evidence (every check, its verdict, its code) is one click away from the thread
(book/_ext/checkmarks.py); the thread itself should teach the subject. This module reads a
built page the way that claim is measured: the text of the article that shows without
opening anything, that is without

* folds (``<details>``: the checks' marks, hidden code, solutions, hints), margin notes;
* cell inputs and outputs (code, verdicts, printed tables), code blocks;
* mathematics (replaced by a placeholder word, so that a sentence stays one sentence).

A sentence *talks about the machinery* when it names checks, mutants, residuals, tolerances,
verdicts, sympy or the cells that run them. tests/book/test_book_build.py holds each chapter
to at most 5 % of such sentences and 2,000 visible words.

Run as a script on a built site to see the figures and the sentences, page by page::

    .venv/bin/python -m tests.book.prose book/_build/html
"""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass
from html.parser import HTMLParser
from pathlib import Path

# The chapters: the book's pages that teach (the registry of checks, the glossary, the
# references, the licence and the teacher's guide are reference matter).
CHAPTERS = ("intro", "equation", "energy", "libration", "libration_extension",
            "libration_solution", "separatrix", "rotation", "period_in_depth", "complex_picture",
            "action_angle", "rod_or_string", "resonance", "in_motion", "closing", "problems",
            "notes_on_original")

MACHINERY = re.compile(
    r"\b(checks?|checked|checking|mutants?|residuals?|tolerances?|verdicts?|sympy|"
    r"cells?|assert(s|ed|ion)?)\b", re.IGNORECASE)
MAX_MACHINERY = 0.05
MAX_WORDS = 2000

_HIDDEN_TAGS = {"details", "pre", "script", "style", "mjx-container", "nav", "button",
                "template", "svg"}
_HIDDEN_CLASSES = {"margin", "check-mark", "cell_input", "cell_output", "headerlink",
                   "toggle-hidden", "toggle-details__container", "dropdown"}
_MATH = {"math"}
_VOID = {"br", "img", "meta", "link", "input", "hr", "wbr", "source", "col", "area"}
_BLOCKS = {"p", "li", "dt", "dd", "h1", "h2", "h3", "h4", "h5", "h6", "td", "th",
           "figcaption", "caption", "div", "section", "blockquote", "table", "tr"}


class _Thread(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.blocks: list[str] = []
        self._text: list[str] = []
        self._stack: list[tuple[str, bool, bool]] = []  # tag, hidden, math
        self._in_article = 0

    def _hidden(self) -> bool:
        return any(h for _, h, _ in self._stack)

    def _math(self) -> bool:
        return any(m for _, _, m in self._stack)

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if tag in _VOID:
            return
        classes = set((dict(attrs).get("class") or "").split())
        if tag == "article" and "bd-article" in classes:
            self._in_article += 1
        hidden = tag in _HIDDEN_TAGS or bool(classes & _HIDDEN_CLASSES)
        math = bool(classes & _MATH)
        if tag in _BLOCKS:
            self._flush()
        if math and not self._math() and not self._hidden():
            self._text.append(" x ")
        self._stack.append((tag, hidden, math))

    def handle_endtag(self, tag: str) -> None:
        if tag in _VOID:
            return
        while self._stack:
            popped = self._stack.pop()[0]
            if popped == "article" and self._in_article:
                self._in_article -= 1
            if popped == tag:
                break
        if tag in _BLOCKS:
            self._flush()

    def handle_data(self, data: str) -> None:
        if self._in_article and not self._hidden() and not self._math():
            self._text.append(data)

    def _flush(self) -> None:
        text = re.sub(r"\s+", " ", "".join(self._text)).strip()
        self._text = []
        if text:
            self.blocks.append(text)


# A sentence ends at . ! ? (or a Japanese 。) followed by a space and a capital, a digit,
# a parenthesis or the end.
_SENTENCE_END = re.compile(r"(?<=[.!?])\s+(?=[A-Z0-9(“\"])|(?<=。)")


@dataclass
class Prose:
    """A page's visible prose."""

    blocks: list[str]

    @property
    def sentences(self) -> list[str]:
        return [s.strip() for b in self.blocks for s in _SENTENCE_END.split(b)
                if len(s.strip().split()) >= 3 or "。" in s]

    @property
    def words(self) -> int:
        return sum(len(re.findall(r"[A-Za-z][A-Za-z'’-]*", b)) for b in self.blocks)

    @property
    def machinery(self) -> list[str]:
        return [s for s in self.sentences if MACHINERY.search(s)]

    @property
    def share(self) -> float:
        return len(self.machinery) / max(1, len(self.sentences))


def read(path: Path) -> Prose:
    """The visible prose of a built page."""
    parser = _Thread()
    parser.feed(path.read_text(encoding="utf-8"))
    parser._flush()
    return Prose(parser.blocks)


def main(site: str) -> None:
    print(f"{'chapter':22} {'words':>6} {'sentences':>9} {'machinery':>9} {'share':>6}")
    for name in CHAPTERS:
        prose = read(Path(site) / f"{name}.html")
        flag = " <" if prose.share > MAX_MACHINERY or prose.words > MAX_WORDS else ""
        print(f"{name:22} {prose.words:6} {len(prose.sentences):9} {len(prose.machinery):9} "
              f"{prose.share:6.1%}{flag}")
    if "-v" in sys.argv:
        for name in CHAPTERS:
            for s in read(Path(site) / f"{name}.html").machinery:
                print(f"{name}: {s}")


if __name__ == "__main__":
    main(sys.argv[1])
