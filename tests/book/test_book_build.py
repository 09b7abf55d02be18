"""The book builds from clean, every notebook re-executed, with no warning and no network."""

from __future__ import annotations

import html
import re

import pytest

from tests.book._buildcheck import (
    external_resources,
    links,
    links_with_spaces,
    pages_with_math,
    toctree_entries,
)
from tests.conftest import BOOK, Build

pytestmark = pytest.mark.slow


def test_book_builds_without_warnings(book_build: Build) -> None:
    print(f"\nbook build (from clean, every page executed): {book_build.seconds:.1f} s")
    assert book_build.returncode == 0, book_build.output[-8000:]
    assert book_build.warnings == [], "\n".join(book_build.warnings)


def test_book_loads_nothing_from_the_network(built_book) -> None:
    assert external_resources(built_book) == {}


def test_book_serves_mathjax_itself(built_book) -> None:
    # conf.py points mathjax_path at the copy shipped by sphinx-mathjax-offline.
    assert (built_book / "_static" / "mathjax" / "tex-chtml.js").is_file()
    pages = pages_with_math(built_book)
    assert pages, "no page with math to check"
    for page in pages:
        assert "_static/mathjax/tex-chtml.js" in page.read_text(encoding="utf-8"), page.name


def test_every_toctree_page_is_built(built_book) -> None:
    entries = toctree_entries(BOOK)
    assert entries, "the book's index has no toctree"
    missing = [e for e in ["index", *entries] if not (built_book / f"{e}.html").is_file()]
    assert missing == []


def test_no_link_contains_a_space(built_book) -> None:
    assert links_with_spaces(built_book) == {}


def test_library_names_link_to_the_reference_site(built_book, built_docs) -> None:
    # book/conf.py maps the docs build's objects.inv (intersphinx, offline) with a URI
    # relative to the book's output, so the links work from file:// and from a server.
    into_docs = {}
    for page, found in links(built_book).items():
        for link in found:
            if "/api.html#elliptic_pendulum." in link:
                into_docs.setdefault(page, []).append(link)
    assert into_docs, "no page of the book links a library name to the API reference"
    broken = []
    for page, found in into_docs.items():
        for link in found:
            path, anchor = link.split("#", 1)
            target = ((built_book / page).parent / path).resolve()
            if re.match(r"^([a-z]+:|/)", link) or target.parent != built_docs.resolve():
                broken.append(f"{page}: {link} (not relative to the docs build)")
            elif f'id="{anchor}"' not in target.read_text(encoding="utf-8"):
                broken.append(f"{page}: {link} (no such entry)")
    assert broken == []


def test_book_build_output_is_quiet(book_build: Build) -> None:
    # Nothing a reader of `make book` would take for trouble: no warning in any form (Sphinx's
    # "WARNING:", a kernel's "[IPKernelApp] WARNING |", a Python DeprecationWarning), no
    # traceback, and not the kernel's per-page notice about unencrypted TCP (book/conf.py).
    noisy = [
        line
        for line in book_build.output.splitlines()
        if re.search(r"WARNING|Warning\b|Traceback|ERROR|CRITICAL|without encryption", line)
    ]
    assert noisy == []


def test_every_page_states_the_licence(built_book) -> None:
    # book/_templates/licence.html, in every page's footer, links to the licence page.
    missing = [
        p.name for p in sorted(built_book.glob("*.html"))
        if "Text and figures: CC BY 4.0; code: MIT" not in p.read_text(encoding="utf-8")
    ]
    assert missing == []
    about = (built_book / "about.html").read_text(encoding="utf-8")
    assert 'id="licence"' in about and "https://creativecommons.org/licenses/by/4.0/" in about
    assert 'href="about.html#licence"' in (built_book / "energy.html").read_text(encoding="utf-8")


def test_each_browser_tab_names_the_page_then_the_book(built_book) -> None:
    # The tab is the page's <title>: "<page> — <book>", from conf.py's html_title; the cover,
    # headed by the book's own name, names it once (it read the name twice).
    html_title = re.search(r'^html_title = "(.+)"$', (BOOK / "conf.py").read_text(), re.M).group(1)

    def title(page: str) -> str:
        text = (built_book / page).read_text(encoding="utf-8")
        return html.unescape(re.search(r"<title>(.*?)</title>", text, re.S).group(1).strip())

    assert title("index.html") == html_title
    assert title("energy.html").endswith(" \N{EM DASH} " + html_title)


def test_citations_in_the_text_carry_the_numbers_of_the_reference_list(built_book) -> None:
    # The list is numbered in citation order (unsrt); the text must cite by the same number
    # (it cited author-year beside a numbered list). Expected: the label that
    # sphinxcontrib-bibtex prints in front of each entry of references.html.
    listed = dict(re.findall(
        r'<div class="citation" id="([^"]+)"[^>]*>\s*<span class="label">'
        r'<span class="fn-bracket">\[</span>([^<]+)<span class="fn-bracket">\]</span>',
        (built_book / "references.html").read_text(encoding="utf-8")))
    assert len(listed) >= 10, listed
    cited = 0
    for page in built_book.glob("*.html"):
        text = page.read_text(encoding="utf-8")
        for span in re.findall(r'<span class="bibtex-citation"[^>]*>(.*?)</span>', text, re.S):
            links = re.findall(r'href="references\.html#([^"]+)"[^>]*>([^<]*)</a>', span)
            assert links, (page.name, span)
            for target, shown in links:
                assert shown == listed[target], (page.name, span)
                cited += 1
    assert cited >= 30, cited
