"""The reference docs build from clean with no warning and no network."""

from __future__ import annotations

import pytest

from tests.book._buildcheck import (
    external_resources,
    links_with_spaces,
    pages_with_math,
    toctree_entries,
)
from tests.conftest import DOCS, Build

pytestmark = pytest.mark.slow


def test_docs_builds_without_warnings(docs_build: Build) -> None:
    print(f"\ndocs build (from clean): {docs_build.seconds:.1f} s")
    assert docs_build.returncode == 0, docs_build.output[-8000:]
    assert docs_build.warnings == [], "\n".join(docs_build.warnings)


def test_docs_loads_nothing_from_the_network(built_docs) -> None:
    assert external_resources(built_docs) == {}


def test_docs_serves_mathjax_itself(built_docs) -> None:
    # conf.py points mathjax_path at the copy shipped by sphinx-mathjax-offline.
    assert (built_docs / "_static" / "mathjax" / "tex-chtml.js").is_file()
    pages = pages_with_math(built_docs)
    assert pages, "no page with math to check"
    for page in pages:
        assert "_static/mathjax/tex-chtml.js" in page.read_text(encoding="utf-8"), page.name


def test_every_toctree_page_is_built(built_docs) -> None:
    entries = toctree_entries(DOCS)
    assert entries, "the docs index has no toctree"
    missing = [e for e in ["index", *entries] if not (built_docs / f"{e}.html").is_file()]
    assert missing == []


def test_no_link_contains_a_space(built_docs) -> None:
    assert links_with_spaces(built_docs) == {}
