"""The classroom notebooks: each book page exported to plain Jupyter runs in a fresh kernel
and shows no MyST markup (tools/export_notebooks.py).
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest
from conftest import BOOK, ROOT

pytestmark = pytest.mark.slow

_spec = importlib.util.spec_from_file_location(
    "export_notebooks", ROOT / "tools" / "export_notebooks.py"
)
assert _spec is not None and _spec.loader is not None
export_notebooks = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(export_notebooks)

PAGES = export_notebooks.book_pages(BOOK)
# Markup that Jupyter would show raw.
MYST_LEFTOVERS = [
    "{glue",
    "{prf",
    ":::{",
    "```{",
    "{eq}`",
    "{ref}`",
    "{numref}`",
    "{cite",
    "{math}`",
]


def test_the_book_has_notebook_pages() -> None:
    assert PAGES, "no book page with a jupytext header was found"


@pytest.mark.parametrize("page", PAGES, ids=[p.stem for p in PAGES])
def test_notebook_runs_in_a_fresh_kernel(page: Path, tmp_path: Path) -> None:
    (written,) = export_notebooks.export(BOOK, tmp_path, run=True, timeout=600, pages=[page])
    nb = export_notebooks.nbformat.read(written, as_version=4)
    markdown = "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")
    leftovers = [s for s in MYST_LEFTOVERS if s in markdown]
    assert leftovers == [], f"MyST markup left in {written.name}: {leftovers}"
    errors = [o for c in nb.cells for o in c.get("outputs", []) if o.get("output_type") == "error"]
    assert errors == []
