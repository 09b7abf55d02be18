"""A page's notebook, written from the doctree Sphinx resolved for the page.

The book's HTML build (book/_ext/classroom.py) hands each page's resolved doctree here: the
same tree its HTML is written from, so the notebook has what the page has, and nothing is
parsed a second time. Roles, references and their numbers, citations, glued values,
directives and (in a translated edition) the translation are already resolved in it; this
module only writes them as Jupyter Markdown:

- each myst-nb code cell becomes a code cell (its source as the page has it, outputs left
  to the reader's run; the glue import replaced by a stand-in, export.py), followed by its
  figure's numbered caption;
- the text between them becomes Markdown cells: headings, paragraphs, lists, tables, display
  math (its ``\\tag`` as in the page), admonitions as quotes (folded ones as ``<details>``),
  the statements of sphinx-proof and the exercises of sphinx-exercise with the numbers Sphinx
  gave them (``env.toc_fignumbers``), and an anchor ``<a id>`` for every label, so that a
  link ``NN-page.ipynb#eq-25`` lands where the page's ``page.html#eq-25`` does;
- a link into another page becomes a link to its notebook; a link to a page without one (the
  registry, the glossary, the reference site) keeps its text only.

The editions differ in what the doctree holds: the student notebooks are written from a tree
whose solutions :func:`book/_ext/classroom.remove_solutions` removed (the function that removes
them from the student site), and get answer cells under each exercise (export.py).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field

import nbformat
from docutils import nodes

from .words import Words

# myst-nb's cell containers.
CELL, SOURCE, OUTPUT = "cell_code", "cell_code_source", "cell_code_output"


@dataclass
class Page:
    """What the writer needs to know beyond the tree: the page, its edition and language,
    where each page's notebook is, and the numbers Sphinx gave the page's labelled nodes."""

    docname: str
    edition: str
    words: Words
    files: dict[str, str]  # docname -> its notebook's file name, for pages with one
    numbers: dict[str, str]  # node id -> its number as Sphinx shows it ("6", "2.1")
    # Cells under an exercise (label) in the student edition, and after a solution.
    answer_cells: Callable[[str], list[nbformat.NotebookNode]] = lambda label: []
    check_cells: Callable[[str], list[nbformat.NotebookNode]] = lambda label: []
    code_cell: Callable[[str, dict], nbformat.NotebookNode] = (
        lambda source, metadata: nbformat.v4.new_code_cell(source, metadata=metadata))
    exercises: dict[str, str] = field(default_factory=dict)  # exercise label -> number
    # The page's notebook cells' sources by myst-nb's cell_index: a cell whose input the
    # page removes (remove-input, remove-cell) has none in the doctree, but runs.
    sources: list[str] = field(default_factory=list)


def _escape(text: str) -> str:
    # Only what Jupyter's Markdown would take for markup in running text.
    return re.sub(r"([\\`*<>\[\]])", r"\\\1", text).replace("$", r"\$")


def _code(text: str) -> str:
    fence = "`" * (max((len(m) for m in re.findall(r"`+", text)), default=0) + 1)
    pad = " " if text.startswith("`") or text.endswith("`") else ""
    return f"{fence}{pad}{text}{pad}{fence}"


def _anchors(node: nodes.Element) -> str:
    return "".join(f'<a id="{i}"></a>' for i in node.get("ids", []))


class Writer:
    """Walks one resolved doctree and collects the notebook's cells."""

    def __init__(self, page: Page) -> None:
        self.page = page
        self.cells: list[nbformat.NotebookNode] = []
        self.blocks: list[str] = []
        self.solution = ""  # the exercise whose solution is being written
        self.answer = ""  # the exercise whose answer cells wait for its hint
        self.depth = 0
        self.cited: dict[str, str] = {}  # a citation's label -> the work, as Sphinx resolved it

    # --- cells --------------------------------------------------------------------------
    def _mark(self, cell: nbformat.NotebookNode) -> nbformat.NotebookNode:
        # The instructor's solution cells say whose they are (nbgrader.py reads it).
        if self.solution:
            cell.metadata.setdefault("classroom", {})["solution"] = self.solution
        return cell

    def flush(self) -> None:
        text = "\n\n".join(b for b in self.blocks if b.strip()).strip("\n")
        self.blocks = []
        if text:
            self.cells.append(self._mark(nbformat.v4.new_markdown_cell(text)))

    def add(self, cells: list[nbformat.NotebookNode]) -> None:
        self.flush()
        self.cells.extend(self._mark(c) for c in cells)

    # --- blocks -------------------------------------------------------------------------
    def body(self, node: nodes.Element) -> None:
        for child in node.children:
            self.block(child)

    def render(self, children: list[nodes.Node]) -> str:
        """The Markdown of block nodes that hold no code cell (a quote, a list item)."""
        sub = Writer(self.page)
        sub.depth, sub.cited = self.depth, self.cited
        for child in children:
            sub.block(child)
        sub.flush()
        if any(c.cell_type != "markdown" for c in sub.cells):
            raise ValueError(f"{self.page.docname}: a code cell inside a quote or list: "
                             f"{[type(c).__name__ for c in children]}")
        return "\n\n".join(c.source for c in sub.cells)

    def block(self, node: nodes.Node) -> None:
        name = type(node).__name__
        if isinstance(node, (nodes.comment, nodes.substitution_definition, nodes.raw)):
            return
        if isinstance(node, nodes.Element) and "site-links" in node.get("classes", []):
            return  # the published site's downloads: a notebook is one of them
        if isinstance(node, nodes.Text):
            self.blocks.append(_escape(node.astext()))
            return
        assert isinstance(node, nodes.Element)
        if isinstance(node, nodes.container) and node.get("nb_element") == CELL:
            self.code(node)
        elif "check-mark" in node.get("classes", []):
            self.check(node)
        elif "check-kept" in node.get("classes", []):
            self.captions(node)
        elif isinstance(node, nodes.section):
            self.section(node)
        elif isinstance(node, nodes.paragraph) and any(
                isinstance(c, (nodes.title, nodes.Sequential)) for c in node.children):
            self.body(node)  # Sphinx's toctree: a "paragraph" that holds its caption and list
        elif isinstance(node, (nodes.paragraph, nodes.rubric)):
            text = _anchors(node) + self.inline(node)
            self.blocks.append(f"**{text}**" if isinstance(node, nodes.rubric) else text)
        elif isinstance(node, nodes.math_block):
            latex = node.astext().strip()
            self.blocks.append(f"{_anchors(node)}\n\n$$\n{latex}\n$$" if node.get("ids")
                               else f"$$\n{latex}\n$$")
        elif isinstance(node, (nodes.bullet_list, nodes.enumerated_list)):
            self.blocks.append(self.list(node))
        elif isinstance(node, nodes.definition_list):
            for item in node.children:
                term = self.inline(next(iter(item.findall(nodes.term))))
                text = self.render(list(next(iter(item.findall(nodes.definition))).children))
                self.blocks.append(f"**{term}**: {text}")
        elif isinstance(node, nodes.table):
            self.blocks.append(self.table(node))
        elif isinstance(node, nodes.figure):
            self.figure(node)
        elif isinstance(node, nodes.literal_block):
            self.blocks.append(f"```\n{node.astext()}\n```")
        elif isinstance(node, nodes.target):
            if node.get("refid") and not isinstance(node.next_node(siblings=True), nodes.Element):
                self.blocks.append(f'<a id="{node["refid"]}"></a>')
        # sphinx-exercise's and sphinx-proof's nodes are admonitions too: they come first.
        elif name in ("exercise_enumerable_node", "exercise_unenumerable_node"):
            self.exercise(node)
        elif name == "solution_node":
            self.solution_(node)
        elif type(node).__module__.startswith("sphinx_proof"):
            self.statement(node)
        elif isinstance(node, nodes.Admonition):
            self.admonition(node)
        elif isinstance(node, (nodes.title, nodes.caption)):
            if self.inline(node):
                self.blocks.append(f"**{self.inline(node)}**")
        else:  # containers, compounds, toctree wrappers, topics: their content
            if node.get("ids"):
                self.blocks.append(_anchors(node))
            self.body(node)

    def section(self, node: nodes.section) -> None:
        title = next((c for c in node.children if isinstance(c, nodes.title)), None)
        if title is None:  # the content of an exercise, a solution, a statement
            self.body(node)
            return
        self.depth += 1
        heading = "#" * min(self.depth, 6)
        ids = "".join(f'<a id="{i}"></a>' for i in node.get("ids", []))
        self.blocks.append(f"{ids}\n\n{heading} {self.inline(title)}" if ids
                           else f"{heading} {self.inline(title)}")
        for child in node.children:
            if child is not title:
                self.block(child)
        self.depth -= 1

    def code(self, node: nodes.container, hidden: bool = False) -> None:
        index = node.get("cell_index")
        if isinstance(index, int) and index < len(self.page.sources):
            text = self.page.sources[index]
        else:
            source = next(iter(node.findall(lambda n: isinstance(n, nodes.Element)
                                            and n.get("nb_element") == SOURCE)), None)
            text = source.astext() if source is not None else ""
        metadata = dict(node.get("cell_metadata") or {})
        if hidden:  # JupyterLab and Notebook 7 show a collapsed source as one line
            metadata["jupyter"] = {**metadata.get("jupyter", {}), "source_hidden": True}
        self.add([self.page.code_cell(text, metadata)])
        self.captions(node)

    def captions(self, node: nodes.Element) -> None:
        """The figure a cell draws: its caption, numbered, in a Markdown cell under it."""
        for figure in node.findall(nodes.figure):
            caption = next(iter(figure.findall(nodes.caption)), None)
            if caption is not None:
                self.blocks.append(self.caption(figure, caption, bold=True))
        self.flush()

    def check(self, node: nodes.Element) -> None:
        """A check (book/_ext/checkmarks.py): its note folded, then its cell, source collapsed.

        The verdicts are the cell's own outputs when the reader runs it, one line each.
        """
        notes = [c for c in node.children if "check-note" in c.get("classes", [])]
        if notes:
            text = "\n\n".join(self.render(list(n.children)) for n in notes)
            self.blocks.append(self.page.words.check.format(note=text))
        for cell in node.findall(lambda n: isinstance(n, nodes.container)
                                 and n.get("nb_element") == CELL):
            self.code(cell, hidden=True)

    def caption(self, figure: nodes.Element, caption: nodes.Element, bold: bool) -> str:
        w = self.page.words
        number = next((self.page.numbers[i] for i in figure.get("ids", [])
                       if i in self.page.numbers), "")
        text = self.inline(caption)
        if number:
            text = (w.figure_caption if bold else "*" + w.figure_italic + "{caption}*").format(
                number=number, caption=text)
        return _anchors(figure) + ("\n\n" if figure.get("ids") else "") + text

    def figure(self, node: nodes.figure) -> None:
        image = next(iter(node.findall(nodes.image)), None)
        if image is not None and "://" in image.get("uri", ""):
            self.blocks.append(f"![{image.get('alt', '')}]({image['uri']})")
        caption = next(iter(node.findall(nodes.caption)), None)
        if caption is not None:
            self.blocks.append(self.caption(node, caption, bold=False))

    def list(self, node: nodes.Element) -> str:
        items = []
        start = int(node.get("start", 1))
        for i, item in enumerate(node.children):
            marker = f"{start + i}." if isinstance(node, nodes.enumerated_list) else "-"
            # A nested list follows its item's text without a blank line (a tight list).
            text = re.sub(r"\n\n(?=- |\d+\. )", "\n", self.render(list(item.children)))
            pad = " " * (len(marker) + 1)
            lines = text.splitlines() or [""]
            items.append(f"{marker} {lines[0]}" + "".join(
                f"\n{pad}{line}" if line else "\n" for line in lines[1:]))
        return "\n".join(items)

    def table(self, node: nodes.table) -> str:
        rows = []
        for part in node.findall(lambda n: isinstance(n, (nodes.thead, nodes.tbody))):
            for row in part.children:
                cells = [self.render(list(entry.children)).replace("\n\n", "<br>")
                         .replace("\n", " ").replace("|", r"\|") for entry in row.children]
                rows.append("| " + " | ".join(cells) + " |")
                if isinstance(part, nodes.thead) and len(rows) == 1:
                    rows.append("|" + "---|" * len(cells))
        if rows and not next(iter(node.findall(nodes.thead)), None):
            width = rows[0].count(" | ") + 1
            rows[1:1] = ["|" + "---|" * width]
        title = next((c for c in node.children if isinstance(c, nodes.title)), None)
        head = f"**{self.inline(title)}**\n\n" if title is not None else ""
        return _anchors(node) + head + "\n".join(rows)

    def admonition(self, node: nodes.Element) -> None:
        title = next((c for c in node.children if isinstance(c, nodes.title)), None)
        kind = next((c for c in node["classes"] if c in self.page.words.boxes), "")
        heading = self.inline(title) if title is not None else self.page.words.boxes.get(
            kind, type(node).__name__.capitalize())
        text = self.render([c for c in node.children if c is not title])
        if "dropdown" in node["classes"]:
            self.blocks.append(f"<details><summary><b>{heading}</b></summary>\n\n{text}\n\n"
                               "</details>")
        else:
            quoted = "\n".join(("> " + line).rstrip() for line in text.splitlines())
            self.blocks.append(f"> **{heading}**\n>\n{quoted}")
        if self.answer:
            self.add(self.page.answer_cells(self.answer))
            self.answer = ""

    def statement(self, node: nodes.Element) -> None:
        w = self.page.words
        title = next((c for c in node.children if isinstance(c, nodes.title)), None)
        content = [c for c in node.children if c is not title]
        if type(node).__name__ == "proof_node":
            heading = w.proof
        else:
            number = next((self.page.numbers[i] for i in node.get("ids", [])
                           if i in self.page.numbers), "")
            heading = " ".join(p for p in (w.statement(str(node.get("realtype", ""))), number)
                               if p)
        if title is not None and self.inline(title).strip(" ()（）"):
            heading = w.titled.format(heading=heading,
                                      title=self.inline(title).strip(" ()（）"))
        text = self.render(content)
        # Run in with the first paragraph; a list or a display stands below the heading.
        first = next((n for c in content for n in c.findall(nodes.Element)
                      if not isinstance(n, (nodes.section, nodes.container))), None)
        joint = " " if isinstance(first, nodes.paragraph) else "\n\n"
        self.blocks.append(
            f"{_anchors(node)}\n\n**{heading}{w.heading_end}**{joint}{text}".strip())

    def exercise(self, node: nodes.Element) -> None:
        w = self.page.words
        label = str(node.get("label", ""))
        number = self.page.exercises.get(label, "")
        title_node = next((c for c in node.children if type(c).__name__ == "exercise_title"),
                          None)
        title = "".join(self.inline(c) for c in (title_node.children[1:] if title_node else [])
                        if isinstance(c, nodes.Element))
        heading = w.exercise.format(number=number).strip()
        if title.strip(" ()（）"):
            heading = w.titled.format(heading=heading, title=title.strip(" ()（）"))
        # The heading above replaces the node's own titles (sphinx-exercise's, and the
        # resolved "Exercise N" that the HTML writer would show).
        content = [c for c in node.children
                   if c is not title_node and not isinstance(c, nodes.title)]
        self.blocks.append(f"{_anchors(node)}\n\n#### {heading}")
        for child in content:
            self.block(child)
        if self.page.edition == "student":
            # Under the exercise's folded hint, if the page gives one (book/_ext/classroom.py).
            hint = node.next_node(siblings=True, descend=False)
            if isinstance(hint, nodes.Admonition) and "hint" in hint["classes"]:
                self.answer = label
            else:
                self.add(self.page.answer_cells(label))

    def solution_(self, node: nodes.Element) -> None:
        label = str(node.get("target_label", ""))
        number = self.page.exercises.get(label, "")
        w = self.page.words
        heading = w.solution.format(number=number) if number else w.solution_unnumbered
        self.flush()
        self.solution = label
        self.blocks.append(f"{_anchors(node)}\n\n#### {heading}")
        for child in node.children:
            if type(child).__name__ != "solution_title" and not isinstance(child, nodes.title):
                self.block(child)
        self.flush()
        self.solution = ""
        self.add(self.page.check_cells(label))

    # --- inline -------------------------------------------------------------------------
    def inline(self, node: nodes.Node | None) -> str:
        if node is None:
            return ""
        return "".join(self._inline(c) for c in node.children).strip()

    def _inline(self, node: nodes.Node) -> str:
        if isinstance(node, nodes.Text):
            return _escape(node.astext()).replace("\n", " ")
        assert isinstance(node, nodes.Element)
        if isinstance(node, nodes.math):
            return f"${node.astext()}$"
        if isinstance(node, nodes.literal):
            return _code(node.astext())
        if isinstance(node, nodes.emphasis):
            return f"*{self._children(node)}*"
        if isinstance(node, nodes.strong):
            return f"**{self._children(node)}**"
        if isinstance(node, nodes.reference):
            return self.link(node)
        if isinstance(node, (nodes.image, nodes.raw, nodes.footnote_reference, nodes.target,
                             nodes.substitution_reference)):
            return ""
        return self._children(node)  # inline containers: glued values, roles' spans

    def _children(self, node: nodes.Element) -> str:
        return "".join(self._inline(c) for c in node.children)

    def link(self, node: nodes.Element) -> str:
        text = self._children(node)
        if node.get("refid"):
            return f"[{text}](#{node['refid']})"
        uri = str(node.get("refuri", ""))
        if re.match(r"[a-z]+:", uri):
            return f"[{text}]({uri})"
        path, _, fragment = uri.partition("#")
        page = re.sub(r"(\.html)?$", "", path, count=1).lstrip("./")
        if not path:
            return f"[{text}](#{fragment})" if fragment else text
        target = self.page.files.get(page)
        if target is None and page == "references" and node.get("reftitle"):
            # A citation: its label here, the work in the notebook's list of references.
            self.cited[node.astext()] = str(node["reftitle"])
            return f"[{text}](#ref-{node.astext()})"
        if target is None:  # a page without a notebook, the reference site: the text only
            return text
        return f"[{text}]({target}{'#' + fragment if fragment else ''})"


def remove_solutions(tree: nodes.Node) -> None:
    """Remove every solution from a doctree: the student site's pages and notebooks.

    sphinx-exercise has merged each gated solution into one node by the time a page is read,
    so removing those nodes removes the solutions' text and cells.
    """
    for node in list(tree.findall(lambda n: type(n).__name__ == "solution_node")):
        node.parent.remove(node)


def cells(tree: nodes.document, page: Page) -> list[nbformat.NotebookNode]:
    """The notebook cells of one resolved doctree (see the module docstring)."""
    writer = Writer(page)
    writer.body(tree)
    if writer.cited:
        writer.blocks.append(f"## {page.words.references}\n\n" + "\n".join(
            f'<a id="ref-{label}"></a>\\[{label}\\] {_escape(work)}  '
            for label, work in writer.cited.items()))
    writer.flush()
    return writer.cells
