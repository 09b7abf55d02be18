"""Sphinx extension: each check's evidence as one mark beside the thread it backs.

The book checks every derivation in a code cell (``elliptic_pendulum.checks.verify``), and the
check runs in every build. The reader of the main column should meet the mathematics, not the
check: so a *check cell* (a cell whose input is folded, tag ``hide-input``, and which calls
``verify``; or one tagged ``check``) is written as one compact mark, ``✔ (24), (25)``, that
sits in the page's right margin on a wide screen (sphinx-book-theme's ``margin`` class) and
under its paragraph on a narrow one or in print. Opened, it shows in the column:

1. what the check does and which mistake it rejects, in words: the content of a ``{check}``
   directive written just before the cell (translated like any paragraph);
2. the verdicts the cell printed, each with how it was checked (unfolded: the mark is the fold);
3. the code, folded once more.

A figure or a table the cell draws stays in the column, after the mark: it is content.

The notebooks (tools/classroom/doctree.py) write the same mark as a note in a ``<details>``
element and the code cell with its source collapsed. The registry page (``checks``) lists the
checks themselves and is left as it is.
"""

from __future__ import annotations

from typing import Any

from docutils import nodes
from docutils.parsers.rst import Directive
from sphinx.application import Sphinx
from sphinx.transforms.post_transforms import SphinxPostTransform
from sphinx.util import logging
from sphinx.writers.html5 import HTML5Translator

logger = logging.getLogger(__name__)

# Pages whose check cells are the subject itself.
UNMARKED = {"checks"}
# The summary's label and the code's, per language (the mark is written after the catalogs
# are applied, so its words are chosen here).
WORDS = {
    "en": {"mark": "✔ checked: {claims}", "bare": "✔ checked", "sep": ", ",
           "more": " and {n} more", "code": "The code of this check"},
    "ja": {"mark": "✔ 検証済み：{claims}", "bare": "✔ 検証済み", "sep": "、",
           "more": " ほか {n} 件", "code": "この検証のコード"},
}
# A mark names at most this many claims, each at most this long (an equation number, a
# lemma's part); the others are counted.
NAMED, SHORT = 3, 16


class check_mark(nodes.General, nodes.Element):
    """A folded mark: ``<details>`` whose summary names the claims checked."""


class check_code(nodes.General, nodes.Element):
    """The check's code, folded inside the mark."""


class CheckNote(Directive):
    """``{check}``: what the next check cell checks, and the mistake it rejects."""

    has_content = True

    def run(self) -> list[nodes.Node]:
        """Parse the note into a container that the transform moves into the mark."""
        node = nodes.container(classes=["check-note"])
        self.state.nested_parse(self.content, self.content_offset, node)
        return [node]


def _is_check(cell: nodes.Element) -> bool:
    tags = (cell.get("cell_metadata") or {}).get("tags", [])
    if "check" in tags:
        return True
    if "hide-input" not in tags:
        return False
    source = next((c for c in cell.children if c.get("nb_element") == "cell_code_source"), None)
    return source is not None and "verify." in source.astext()


def _claims(output: nodes.Element) -> list[tuple[str, bool]]:
    """Return the claims of the verdicts in a cell's output: the bold text after each ✔.

    Each comes with whether a summary can name it: a claim with a formula in it would show
    its LaTeX there (a summary is plain text), and is counted instead.
    """
    claims: list[tuple[str, bool]] = []
    for para in output.findall(nodes.paragraph):
        first = para.children[0] if para.children else None
        if isinstance(first, nodes.Text) and first.astext().startswith("✔"):
            strong = next(iter(para.findall(nodes.strong)), None)
            if strong is None:
                continue
            claim = (" ".join(strong.astext().split()),
                     not any(True for _ in strong.findall(nodes.math)))
            if claim not in claims:
                claims.append(claim)
    return claims


def _kept(bundle: nodes.Node) -> bool:
    """Tell whether an output is content, not evidence: a figure or a table."""
    return isinstance(bundle, nodes.Element) and any(
        True for _ in bundle.findall(lambda n: isinstance(n, (nodes.image, nodes.figure,
                                                               nodes.table))))


def _unfold_verdicts(output: nodes.Element) -> None:
    # Each verdict folds its "how it was checked" (checks/verify.py) for a reader of a bare
    # notebook; inside the mark, already a fold, it is shown at once.
    for raw in list(output.findall(nodes.raw)):
        text = raw.astext().strip()
        if text.startswith("<details><summary>") or text == "</details>":
            raw.parent.remove(raw)


class CheckMarks(SphinxPostTransform):
    """Turn each check cell, with the ``{check}`` note before it, into a mark."""

    # Before myst-nb wraps hidden inputs in its own toggles (priority 199).
    default_priority = 150
    formats = ("html",)

    def run(self, **kwargs: Any) -> None:
        """Mark every check cell of the page; warn of a note with no check after it."""
        if self.env.docname in UNMARKED:
            for note in list(self.document.findall(_is_note)):
                note.replace_self(note.children)
            return
        words = WORDS.get(str(self.config.language or "en"), WORDS["en"])
        for note in list(self.document.findall(_is_note)):
            cell = note.next_node(nodes.Element, siblings=True, descend=False)
            while cell is not None and _is_note(cell):
                cell = cell.next_node(nodes.Element, siblings=True, descend=False)
            if cell is None or not _is_cell(cell) or not _is_check(cell):
                logger.warning("a {check} note must come just before the check cell it "
                               "describes", location=note)
        for cell in list(self.document.findall(_is_cell)):
            if _is_check(cell):
                self.mark(cell, words)

    def mark(self, cell: nodes.Element, words: dict[str, str]) -> None:
        """Replace one check cell, and the notes just before it, by its mark."""
        parent = cell.parent
        notes: list[nodes.Node] = []
        previous = cell.previous_sibling()
        while previous is not None and _is_note(previous):
            notes.insert(0, previous)
            previous = previous.previous_sibling()
        for note in notes:
            parent.remove(note)
        source = next((c for c in cell.children if c.get("nb_element") == "cell_code_source"),
                      None)
        output = next((c for c in cell.children if c.get("nb_element") == "cell_code_output"),
                      None)
        kept = nodes.container(classes=["cell_output", "check-kept"])
        if output is not None:
            for bundle in list(output.children):
                if _kept(bundle):
                    output.remove(bundle)
                    kept.append(bundle)
            _unfold_verdicts(output)
        cell.attributes.pop("hide_mode", None)  # the mark is the fold
        mark = check_mark(classes=["check-mark", "margin"],
                          summary=_summary(_claims(output) if output is not None else [], words))
        if source is not None:  # after the verdicts: the last thing a reader asks for
            code = check_code(summary=words["code"])
            cell.remove(source)
            code.append(source)
            cell.append(code)
        parent.replace(cell, mark)
        mark.extend(notes)
        mark.append(cell)
        if kept.children:
            mark.parent.insert(mark.parent.index(mark) + 1, kept)


def _summary(claims: list[tuple[str, bool]], words: dict[str, str]) -> str:
    named = [c for c, nameable in claims if nameable and len(c) <= SHORT][:NAMED]
    if not named:
        return words["bare"]
    more = len(claims) - len(named)
    return (words["mark"].format(claims=words["sep"].join(named))
            + (words["more"].format(n=more) if more else ""))


def _is_note(node: nodes.Node) -> bool:
    return isinstance(node, nodes.container) and "check-note" in node.get("classes", [])


def _is_cell(node: nodes.Node) -> bool:
    return isinstance(node, nodes.container) and node.get("nb_element") == "cell_code"


def _visit_mark(self: HTML5Translator, node: check_mark) -> None:
    self.body.append(self.starttag(node, "div"))
    self.body.append('<details class="check-details">\n<summary>'
                     f'{self.encode(node["summary"])}</summary>\n')


def _depart_mark(self: HTML5Translator, node: check_mark) -> None:
    self.body.append("</details>\n</div>\n")


def _visit_code(self: HTML5Translator, node: check_code) -> None:
    self.body.append(f'<details class="check-code">\n<summary>'
                     f'{self.encode(node["summary"])}</summary>\n')


def _depart_code(self: HTML5Translator, node: check_code) -> None:
    self.body.append("</details>\n")


def _skip(self: Any, node: nodes.Node) -> None:
    raise nodes.SkipNode


def setup(app: Sphinx) -> dict[str, Any]:
    """Register the directive, the nodes and the transform."""
    app.add_directive("check", CheckNote)
    app.add_node(check_mark, html=(_visit_mark, _depart_mark),
                 text=(_skip, None), latex=(_skip, None), man=(_skip, None),
                 texinfo=(_skip, None))
    app.add_node(check_code, html=(_visit_code, _depart_code),
                 text=(_skip, None), latex=(_skip, None), man=(_skip, None),
                 texinfo=(_skip, None))
    app.add_post_transform(CheckMarks)
    app.add_css_file("checkmarks.css")
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
