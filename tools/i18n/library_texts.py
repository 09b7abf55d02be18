"""The texts the book's cells pass to the library for a reader, as a gettext template.

A verdict or a figure in the Japanese edition is written by the library in Japanese, but the
words a cell passes in are the cell's: a fact's sentence, a numerical check's ``over``,
``measure`` and ``mutant_label``, a statement's ``mutant_label`` and ``domain_md``, a claim
named in words ("§3, case II"), a figure's ``labels``, ``label`` or ``points_label``. The
library looks each up, exact English to Japanese, in the catalog that the environment
variable ``ELLIPTIC_PENDULUM_MESSAGES`` names (see ``elliptic_pendulum.checks.verify``).
The texts a cell draws itself with matplotlib (an axis label, a title, a legend's labels,
a ``label=``, a ``text`` or ``annotate``) are translated after drawing, from the same
catalogs, by ``elliptic_pendulum.plotting.localize(fig)``; they are found too.
This finds them in the pages' code cells and writes them as a .pot file, one message per
distinct text, with the pages and lines that pass it (and, as a comment, what receives
it). A text built by an f-string cannot be a catalog's key: it is listed apart, to become
a template with ``values=`` (or, in a figure, a literal with the number drawn apart).

    python -m tools.i18n.library_texts book out.pot
"""

from __future__ import annotations

import ast
import re
import sys
from dataclasses import dataclass
from pathlib import Path


def _cells(source: str):
    """Yield (line before the code's first line, code) for each code cell of a page.

    The cell's options (a ``---`` block or ``:key:`` lines) are left out, so that a line of
    the code is the returned line plus its line number in the code.
    """
    lines = source.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("```{code-cell}"):
            j = i + 1
            while j < len(lines) and not lines[j].startswith("```"):
                j += 1
            body, start = lines[i + 1:j], i + 1  # start: the 1-based line of the fence
            if body and body[0].strip() == "---" and "---" in body[1:]:
                end = body.index("---", 1) + 1
                body, start = body[end:], start + end
            while body and body[0].startswith(":"):
                body, start = body[1:], start + 1
            yield start, "\n".join(body)
            i = j
        i += 1

# (receiver or None, function) -> the arguments that carry text: positions and keywords.
_VERIFY = {"fact": ((2,), ()), "numeric": ((), ("over", "measure", "mutant_label"))}
_STATEMENT = ("mutant_label", "domain_md")
_FIGURE = ("labels", "label", "points_label")
# matplotlib's methods (of Axes, Figure, pyplot, a Colorbar) that draw a text a cell passes:
# the argument positions and keywords that carry it. ``label=`` of any other call (plot,
# scatter, fill_between, axhline, colorbar...) is a legend's or a colour bar's label.
_MATPLOTLIB = {
    "set_xlabel": ((0,), ("xlabel",)), "set_ylabel": ((0,), ("ylabel",)),
    "set_title": ((0,), ("label",)), "suptitle": ((0,), ("t",)), "set_label": ((0,), ()),
    "xlabel": ((0,), ("xlabel",)), "ylabel": ((0,), ("ylabel",)), "title": ((0,), ("label",)),
    "text": ((2,), ("s",)), "figtext": ((2,), ("s",)), "annotate": ((0,), ("text",)),
    "set": ((), ("xlabel", "ylabel", "title")),
    "legend": ((), ("labels", "title")),
}


@dataclass(frozen=True)
class Text:
    """A text a cell passes: where, to what, and whether it is a literal (else an f-string)."""

    text: str
    page: str
    line: int
    argument: str
    literal: bool


def _words(text: str) -> bool:
    # Text outside math with a word in it: "$4\\pi/\\omega_0$" or "(26)" needs no translation.
    return re.search(r"[A-Za-z]{2,}", re.sub(r"\$[^$]*\$", "", text)) is not None


def _texts_of(node: ast.AST) -> list[tuple[str, bool]]:
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return [(node.value, True)]
    if isinstance(node, ast.JoinedStr):
        return [(ast.unparse(node), False)]
    if isinstance(node, (ast.List, ast.Tuple)):
        return [t for e in node.elts for t in _texts_of(e)]
    return []


def _figure_functions() -> set[str]:
    import elliptic_pendulum.plotting as epp

    return {*epp.__all__, "animate", "animation_html"}


def _drawn(name: str, call: ast.Call) -> list[tuple[str, ast.AST]]:
    """The texts a matplotlib call in a cell draws: (what receives it, its node)."""
    carried: list[tuple[str, ast.AST]] = []
    if name in _MATPLOTLIB:
        positions, keywords = _MATPLOTLIB[name]
        if name == "legend" and call.args:  # legend(labels) or legend(handles, labels)
            positions = (len(call.args) - 1,) if len(call.args) <= 2 else ()
        carried += [(name, call.args[i]) for i in positions if i < len(call.args)]
        carried += [(f"{name} {k.arg}", k.value) for k in call.keywords if k.arg in keywords]
    if name not in ("set_title", "title"):
        carried += [(f"{name} label", k.value) for k in call.keywords if k.arg == "label"]
    return carried


def code_texts(code: str, page: str = "", first: int = 0) -> list[Text]:
    """Return the texts one cell's ``code`` passes to the library (its lines from ``first``)."""
    try:
        tree = ast.parse(code)
    except SyntaxError:
        return []
    figures = _figure_functions()
    found = []
    calls = sorted((n for n in ast.walk(tree) if isinstance(n, ast.Call)),
                   key=lambda n: (n.lineno, n.col_offset))
    for call in calls:
        func = call.func
        name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
        owner = ast.unparse(func.value) if isinstance(func, ast.Attribute) else ""
        carried: list[tuple[str, ast.AST]] = []
        if owner == "verify" and name in _VERIFY:
            positions, keywords = _VERIFY[name]
            carried += [("claim", call.args[0])] if call.args else []
            carried += [(name, call.args[i]) for i in positions if i < len(call.args)]
            carried += [(k.arg, k.value) for k in call.keywords if k.arg in keywords]
        elif name == "Identity":
            carried += [(f"Identity {k.arg}", k.value) for k in call.keywords
                        if k.arg in _STATEMENT]
            carried += [("claim", call.args[1])] if len(call.args) > 1 else []
        elif name in figures:
            carried += [(f"{name} {k.arg}", k.value) for k in call.keywords
                        if k.arg in _FIGURE]
        else:
            carried += _drawn(name, call)
        for argument, node in carried:
            for text, literal in _texts_of(node):
                if _words(text):
                    found.append(Text(text, page, first + call.lineno, argument, literal))
    return found


def texts(book: Path) -> list[Text]:
    """Return the texts the cells of the pages directly in ``book`` pass to the library."""
    found = []
    for page in sorted(book.glob("*.md")):
        for first, code in _cells(page.read_text(encoding="utf-8")):
            found += code_texts(code, page.stem, first)
    return found


def _quoted(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def pot(found: list[Text]) -> str:
    """Return the literal texts as a gettext template, each once, with where it is passed.

    A comment (``#.``) says what receives it: ``fact``, ``over``, ``set_xlabel``...
    """
    where: dict[str, list[str]] = {}
    receivers: dict[str, list[str]] = {}
    for t in found:
        if t.literal:
            where.setdefault(t.text, []).append(f"{t.page}.md:{t.line}")
            if t.argument not in receivers.setdefault(t.text, []):
                receivers[t.text].append(t.argument)
    out = ['msgid ""', 'msgstr ""', '"Content-Type: text/plain; charset=UTF-8\\n"', ""]
    for text, places in where.items():
        out += [f"#. {', '.join(receivers[text])}", f"#: {' '.join(places)}",
                f"msgid {_quoted(text)}", 'msgstr ""', ""]
    return "\n".join(out)


def main(argv: list[str]) -> int:
    book, target = Path(argv[0]), Path(argv[1])
    found = texts(book)
    target.write_text(pot(found), encoding="utf-8")
    literal = {t.text for t in found if t.literal}
    print(f"{len(found)} texts passed, {len(literal)} distinct literals written to {target}")
    built = [t for t in found if not t.literal]
    for t in built:
        print(f"f-string (make it a template with values=, or a literal): "
              f"{t.page}.md:{t.line} {t.argument}: {t.text}")
    # A text no catalog can key would stay English in a translated edition: `make gettext`
    # (and so `make i18n-status`) fails on it.
    return 1 if built else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
