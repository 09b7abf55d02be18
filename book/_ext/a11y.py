"""Sphinx extension: HTML that meets WCAG 2.1 AA where docutils writes otherwise.

Shared by the book and the reference site (``book/conf.py`` and ``docs/conf.py`` list it),
with the template ``book/_templates/search-button-field.html`` and the stylesheet
``book/_static/a11y.css``, which both sites load. tests/book/test_browser.py runs axe-core
on every page of both.

* Citations. docutils writes a bibliography (sphinxcontrib-bibtex's, on the references page)
  as ``<div role="list">`` holding ``<div role="doc-biblioentry">`` entries. DPUB-ARIA 1.1
  deprecates ``doc-biblioentry`` (axe-core: aria-deprecated-role), and without it a list's
  entries are no list items (aria-required-children). The entries are written as
  ``role="listitem"`` instead: the same list, in ARIA that is current.
* Hidden code cells. myst-nb writes the toggle of a hidden cell as ``<summary
  aria-label="Toggle hidden content">`` around its visible text "Show code cell source":
  a name that is not the visible text breaks WCAG 2.5.3, label in name (axe-core:
  label-content-name-mismatch). The summary is written without it, so its name is the
  text it shows ("Show ..." or "Hide ...", whichever the theme displays).
"""

from __future__ import annotations

from html import escape
from typing import Any

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.writers.html5 import HTML5Translator


def _visit_citation(self: HTML5Translator, node: nodes.citation) -> None:
    # docutils' own visit_citation, with the entry's role changed (see the module docstring).
    if not isinstance(node.previous_sibling(), type(node)):
        self.body.append('<div role="list" class="citation-list">\n')
    self.body.append(self.starttag(node, "div", classes=[node.tagname], role="listitem"))


def _visit_hidden_cell(self: HTML5Translator, node: nodes.Element) -> None:
    # myst_nb.sphinx_.visit_HideCellInput without the summary's aria-label.
    classes = " ".join(node["classes"])
    self.body.append(f'<details class="admonition hide {classes}">\n<summary>\n')
    self.body.append(f'<p class="collapsed admonition-title">{escape(node["prompt_show"])}</p>\n')
    self.body.append(f'<p class="expanded admonition-title">{escape(node["prompt_hide"])}</p>\n')
    self.body.append("</summary>\n")


def _depart_hidden_cell(self: HTML5Translator, node: nodes.Element) -> None:
    self.body.append("</details>\n")


def setup(app: Sphinx) -> dict[str, Any]:
    """Register the extension with Sphinx (after myst_nb, in the book)."""
    app.add_node(
        nodes.citation, override=True,
        html=(_visit_citation, HTML5Translator.depart_citation),
    )
    if "myst_nb" in app.extensions:
        from myst_nb.sphinx_ import HideCodeCellNode

        app.add_node(HideCodeCellNode, override=True,
                     html=(_visit_hidden_cell, _depart_hidden_cell))
    return {"parallel_read_safe": True, "parallel_write_safe": True}
