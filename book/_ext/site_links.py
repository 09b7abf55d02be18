"""Sphinx extension: the home page's list of everything the published site holds.

``make site`` puts one folder together (the Makefile says where each part goes)::

    index.html, <chapters>       the book with its solutions, for the teacher
    ja/                          its Japanese edition
    reference/                   the library's reference
    classroom/, ja/classroom/    the notebook bundles (zips) of both editions, per language
    pdf/                         the four PDFs
    student/                     the student edition: its own ja/, reference/, classroom/ and
                                 pdf/ (its two PDFs), so that it can also be served alone

The directive ``{site-links}`` on the home page becomes a list of links to them, relative to
the page, for the edition and language being built (the student site lists only what is
inside its own folder). Builders other than HTML (the PDFs' single pages, gettext) drop it, as
does a notebook (its class ``site-links``, tools/classroom/doctree.py).
"""

from __future__ import annotations

from typing import Any

from docutils import nodes
from i18n import label
from sphinx.application import Sphinx
from sphinx.util.docutils import SphinxDirective

ZIP = "elliptic-pendulum-notebooks-{}.zip"


class site_links(nodes.General, nodes.Element):  # noqa: N801 - docutils' naming of nodes
    """Where the list goes; replaced when the page is resolved."""


class SiteLinks(SphinxDirective):
    """``{site-links}``: the list of the site's editions, downloads and reference."""

    def run(self) -> list[nodes.Node]:
        """Return the placeholder that the page's resolution replaces."""
        return [site_links()]


def links(edition: str, language: str) -> list[tuple[str, str]]:
    """(English text, href relative to the home page) of each part of the published site."""
    up = "../" if language != "en" else ""  # the Japanese edition is one folder down
    if edition == "student":
        rows = [("The PDF of this edition", f"{up}pdf/book-student{'-ja' if up else ''}.pdf"),
                ("The notebooks of this edition (zip)", f"classroom/{ZIP.format('student')}")]
    else:
        rows = [
            ("The student edition (no solutions), to give to students",
             f"{up}student/{'ja/' if up else ''}index.html"),
            ("The PDF of this edition, with the solutions",
             f"{up}pdf/book{'-ja' if up else ''}.pdf"),
            ("The PDF of the student edition",
             f"{up}pdf/book-student{'-ja' if up else ''}.pdf"),
            ("The student notebooks (zip)", f"classroom/{ZIP.format('student')}"),
            ("The notebooks with their solutions (zip)",
             f"classroom/{ZIP.format('instructor')}"),
        ]
    rows.append(("The reference of the library", f"{up}reference/index.html"))
    rows.append(("日本語版", "ja/index.html") if language == "en"
                else ("The English edition", "../index.html"))
    return rows


def _resolve(app: Sphinx, doctree: nodes.document, docname: str) -> None:
    for node in list(doctree.findall(site_links)):
        if app.builder.format != "html" or app.builder.name == "singlehtml":
            node.parent.remove(node)
            continue
        language = str(app.config.language or "en")
        items = nodes.bullet_list(classes=["site-links"])
        for text, href in links(app.config.classroom_edition, language):
            ref = nodes.reference("", label(language, text), refuri=href, internal=False)
            items += nodes.list_item("", nodes.paragraph("", "", ref))
        node.replace_self(items)


def _skip(self: Any, node: nodes.Element) -> None:
    raise nodes.SkipNode


def setup(app: Sphinx) -> dict[str, Any]:
    """Register the directive and its resolution."""
    app.add_node(site_links, html=(_skip, None), singlehtml=(_skip, None),
                 text=(_skip, None), latex=(_skip, None))
    app.add_directive("site-links", SiteLinks)
    app.connect("doctree-resolved", _resolve)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
