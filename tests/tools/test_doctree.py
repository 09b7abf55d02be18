"""The notebook writer (tools/classroom/doctree.py) on doctrees made here, node by node.

The trees are what Sphinx hands the writer after resolving a page: docutils' reStructuredText
parser makes the ordinary nodes (sections, lists, tables, math, admonitions, links), and the
nodes of myst-nb (a code cell's containers), sphinx-exercise and sphinx-proof are built as
those packages build them. The expectations are the Markdown a reader of Jupyter needs, written
out by hand. tests/book/test_notebooks.py checks the writer on the real book and on a small
book that Sphinx builds.
"""

from __future__ import annotations

import nbformat
import pytest
from docutils import nodes
from docutils.core import publish_doctree
from sphinx_exercise.nodes import exercise_enumerable_node, exercise_title, solution_node
from sphinx_proof.nodes import proposition_node

from tools.classroom import doctree
from tools.classroom.words import ENGLISH, JAPANESE

FILES = {"index": "00-index.ipynb", "zeta": "01-zeta.ipynb", "alpha": "02-alpha.ipynb"}


def page(edition: str = "instructor", words=ENGLISH, **kw) -> doctree.Page:
    """Page alpha of a three-page book whose figure fig-a is Fig. 3 and exercise ex-a is 2."""
    return doctree.Page("alpha", edition, words, FILES, {"fig-a": "3", "prop-a": "1"},
                        exercises={"ex-a": "2"}, **kw)


def markdown(tree: nodes.Node, p: doctree.Page | None = None) -> str:
    """The Markdown of a tree, or of one node as a page's body holds it."""
    if not isinstance(tree, nodes.document):
        tree = nodes.container("", tree)
    cells = doctree.cells(tree, p or page())
    assert all(c.cell_type == "markdown" for c in cells)
    return "\n\n".join(c.source for c in cells)


def rst(text: str) -> nodes.document:
    return publish_doctree(text, settings_overrides={"report_level": 5, "doctitle_xform": False})


def test_sections_become_headings_with_their_anchors() -> None:
    tree = rst("Title\n=====\n\nText.\n\nPart\n----\n\nMore.\n")
    text = markdown(tree)
    assert "# Title" in text and "\n## Part" in text
    assert '<a id="part"></a>\n\n## Part' in text  # links to #part land here


def test_inline_markup_math_and_escapes() -> None:
    para = nodes.paragraph("", "", nodes.Text("Take "), nodes.math("", r"\alpha^2"),
                           nodes.Text(", "), nodes.emphasis("", "not"), nodes.Text(" "),
                           nodes.strong("", "all"), nodes.Text(" of "),
                           nodes.literal("", "ep.solve"), nodes.Text(" * 2 [sic]"))
    assert markdown(para) == r"Take $\alpha^2$, *not* **all** of `ep.solve` \* 2 \[sic\]"


def test_display_math_keeps_its_tag_and_gets_its_label_as_anchor() -> None:
    block = nodes.math_block("", r"x = 1 \tag{7}", ids=["eq-7"])
    assert markdown(block) == '<a id="eq-7"></a>\n\n$$\nx = 1 \\tag{7}\n$$'


@pytest.mark.parametrize(("attributes", "expected"), [
    ({"refid": "eq-7"}, "[(7)](#eq-7)"),  # the same page
    ({"refuri": "zeta.html#eq-7"}, "[(7)](01-zeta.ipynb#eq-7)"),  # a page with a notebook
    ({"refuri": "zeta.html"}, "[(7)](01-zeta.ipynb)"),
    ({"refuri": "glossary.html#term-k"}, "(7)"),  # no notebook: the text only
    ({"refuri": "reference/api.html#ep.solve"}, "(7)"),  # the reference site
    ({"refuri": "https://dlmf.nist.gov/22"}, "[(7)](https://dlmf.nist.gov/22)"),
])
def test_links_go_to_the_notebooks(attributes: dict, expected: str) -> None:
    para = nodes.paragraph("", "", nodes.reference("", "(7)", **attributes))
    assert markdown(para) == expected


def test_citations_are_listed_under_references() -> None:
    ref = nodes.reference("", "1", refuri="references.html#id3",
                          reftitle="S. Takeno. The simple pendulum. 2024.")
    text = markdown(nodes.paragraph("", "", nodes.Text("["), ref, nodes.Text("]")))
    assert text.startswith(r"\[[1](#ref-1)\]")
    assert text.endswith('## References\n\n<a id="ref-1"></a>\\[1\\] S. Takeno. The simple '
                         'pendulum. 2024.  ')


def test_lists_tables_and_boxes() -> None:
    tree = rst("- one\n- two\n\n  continued\n\n3. three\n4. four\n\n"
               "=====  =====\nhead   more\n=====  =====\na      b|c\n=====  =====\n\n"
               ".. note::\n\n   Careful.\n")
    text = markdown(tree)
    assert "- one\n- two\n\n  continued" in text
    assert "3. three\n4. four" in text
    assert "| head | more |\n|---|---|\n| a | b\\|c |" in text
    assert "> **Note**\n>\n> Careful." in text


def test_a_folded_box_is_a_details_element() -> None:
    box = nodes.admonition("", nodes.title("", "Hint"), nodes.paragraph("", "Look."),
                           classes=["dropdown", "hint"])
    assert markdown(box) == "<details><summary><b>Hint</b></summary>\n\nLook.\n\n</details>"


def cell(source: str, index: int, **metadata) -> nodes.container:
    """A myst-nb code cell as it stands in a doctree: input, then output."""
    return nodes.container(
        "", nodes.container("", nodes.literal_block("", source), nb_element="cell_code_source"),
        nodes.container("", nb_element="cell_code_output"),
        nb_element="cell_code", cell_index=index, cell_metadata=metadata)


def test_code_cells_come_from_the_notebook_and_carry_their_figure_caption() -> None:
    figure = nodes.figure("", nodes.caption("", "A line."), ids=["fig-a"])
    code = cell("shown", 1, tags=["hide-input"])
    code[1] += figure
    tree = nodes.section("", nodes.paragraph("", "Before."), code,
                         nodes.paragraph("", "After."))
    # The sources by cell_index are myst-nb's (a removed input is not in the tree).
    cells = doctree.cells(tree, page(sources=["zero", "from the notebook"]))
    assert [c.cell_type for c in cells] == ["markdown", "code", "markdown", "markdown"]
    assert cells[1].source == "from the notebook"
    assert cells[1].metadata == {"tags": ["hide-input"]}
    assert cells[2].source == '<a id="fig-a"></a>\n\n**Fig. 3.** A line.'
    assert cells[3].source == "After."


def test_a_check_is_its_note_folded_then_its_cell_collapsed() -> None:
    # What book/_ext/checkmarks.py makes of a check cell and the {check} note before it.
    note = nodes.container("", nodes.paragraph("", "A common slip is 2v/g."),
                           classes=["check-note"])
    mark = nodes.container("", note, cell("verify.fact(...)", 0, tags=["hide-input"]),
                           classes=["check-mark", "margin"])
    kept = nodes.container("", nodes.figure("", nodes.caption("", "A line."), ids=["fig-a"]),
                           classes=["cell_output", "check-kept"])
    cells = doctree.cells(nodes.section("", nodes.paragraph("", "Before."), mark, kept),
                          page(sources=["verify.fact(...)"]))
    assert [c.cell_type for c in cells] == ["markdown", "code", "markdown"]
    assert cells[0].source == ("Before.\n\n<details><summary>✔ What the next cell checks"
                               "</summary>\n\nA common slip is 2v/g.\n\n</details>")
    assert cells[1].metadata["jupyter"] == {"source_hidden": True}
    # The figure the check drew stays in the thread, with its caption.
    assert cells[2].source == '<a id="fig-a"></a>\n\n**Fig. 3.** A line.'


def exercise() -> exercise_enumerable_node:
    return exercise_enumerable_node(
        "", exercise_title("", "Exercise"), nodes.title("", "Exercise 2"),
        nodes.section("", nodes.paragraph("", "Compute."), ids=["exercise-content"]),
        ids=["ex-a"], label="ex-a")


def solution() -> solution_node:
    return solution_node(
        "", nodes.title("", "Solution to Exercise 2"),
        nodes.section("", nodes.paragraph("", "Worked."), cell("answer = 42", 0)),
        ids=["alpha-solution-1"], target_label="ex-a")


def test_an_exercise_with_its_solution_for_the_instructor() -> None:
    tree = nodes.section("", exercise(), solution())
    cells = doctree.cells(tree, page(check_cells=lambda label: [
        nbformat.v4.new_code_cell(f"check({label!r})")], sources=["answer = 42"]))
    assert cells[0].source == '<a id="ex-a"></a>\n\n#### Exercise 2\n\nCompute.'
    assert cells[1].source == ('<a id="alpha-solution-1"></a>\n\n#### Solution to Exercise 2'
                               "\n\nWorked.")
    assert cells[1].metadata["classroom"] == {"solution": "ex-a"}
    assert cells[2].source == "answer = 42"
    assert cells[2].metadata["classroom"] == {"solution": "ex-a"}
    assert cells[3].source == "check('ex-a')" and "solution" not in cells[3].metadata.get(
        "classroom", {})


def test_the_student_gets_answer_cells_and_no_solution() -> None:
    tree = nodes.section("", exercise(), solution())
    doctree.remove_solutions(tree)  # as the student site's pages are stripped
    cells = doctree.cells(tree, page("student", answer_cells=lambda label: [
        nbformat.v4.new_code_cell(f"{label} = ...")]))
    assert [c.source for c in cells] == ['<a id="ex-a"></a>\n\n#### Exercise 2\n\nCompute.',
                                         "ex-a = ..."]


def test_answer_cells_wait_for_the_exercise_hint() -> None:
    hint = nodes.admonition("", nodes.title("", "Hint"), nodes.paragraph("", "Look."),
                            classes=["dropdown", "hint"])
    tree = nodes.section("", exercise(), hint, nodes.paragraph("", "Next."))
    cells = doctree.cells(tree, page("student", answer_cells=lambda label: [
        nbformat.v4.new_code_cell("answer")]))
    assert [c.cell_type for c in cells] == ["markdown", "code", "markdown"]
    assert cells[0].source.endswith("</details>") and cells[2].source == "Next."


def test_statements_in_each_language() -> None:
    prop = proposition_node("", nodes.title("", " (Name)"),
                            nodes.section("", nodes.paragraph("", "True.")),
                            ids=["prop-a"], realtype="proposition")
    assert markdown(prop) == '<a id="prop-a"></a>\n\n**Proposition 1 (Name).** True.'
    ja = page(words=JAPANESE)
    assert markdown(prop.deepcopy(), ja) == '<a id="prop-a"></a>\n\n**命題 1（Name）** True.'


def test_a_code_cell_inside_a_box_is_refused() -> None:
    box = nodes.note("", cell("x = 1", 0))
    with pytest.raises(ValueError, match="code cell inside"):
        doctree.cells(nodes.container("", box), page())


def test_a_toctree_is_a_nested_list_of_links_to_the_notebooks() -> None:
    # Sphinx resolves a toctree into a paragraph that holds its caption and a nested list.
    from sphinx import addnodes

    def item(text: str, uri: str, *sub: nodes.Node) -> nodes.list_item:
        return nodes.list_item("", addnodes.compact_paragraph(
            "", "", nodes.reference("", text, refuri=uri)), *sub)

    toc = nodes.compound("", addnodes.compact_paragraph(
        "", "", nodes.title("", "Contents"), nodes.bullet_list("", item(
            "Zeta first", "zeta.html", nodes.bullet_list("", item("Part", "zeta.html#part"))),
            item("Alpha", "alpha.html"))), classes=["toctree-wrapper"])
    assert markdown(toc) == ("**Contents**\n\n- [Zeta first](01-zeta.ipynb)\n"
                             "  - [Part](01-zeta.ipynb#part)\n- [Alpha](02-alpha.ipynb)")
