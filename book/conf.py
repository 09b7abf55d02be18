"""Sphinx configuration of the book "The simple pendulum and elliptic functions"."""

from __future__ import annotations

import importlib.util
from pathlib import Path

project = "The simple pendulum and elliptic functions"
author = "elliptic-pendulum contributors, after S. Takeno (2024)"
copyright = "2024-2026, elliptic-pendulum contributors"

extensions = [
    "myst_nb",
    "sphinx_proof",
    "sphinx_exercise",
    "sphinx_togglebutton",
    "sphinxcontrib.bibtex",
    "sphinx_book_theme",
]

# --- MyST -------------------------------------------------------------------------------
# dollarmath: $...$ and $$...$$ (label); amsmath: \begin{align} and \tag{N} as in the note;
# colon_fence: :::{prf:proposition} blocks that stay readable as plain Markdown.
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist"]
myst_dmath_double_inline = True
myst_heading_anchors = 3

# --- Execution (myst-nb) ----------------------------------------------------------------
# "cache" keeps `make book` fast; the cache keys only on cell source, so `make book-strict`
# and the tests override it with -D nb_execution_mode=force.
nb_execution_mode = "cache"
nb_execution_raise_on_error = True
nb_execution_show_tb = True
# Per cell, seconds: the slowest cells (mpmath references, solve_ivp comparisons) take a few s.
nb_execution_timeout = 120
nb_merge_streams = True
# Markdown that a cell displays (the errata catalogue) is parsed as MyST, so its $...$ is math.
nb_render_markdown_format = "myst"

# --- sphinx-proof ----------------------------------------------------------------------
# The note numbers its statements in one sequence (Proposition 1, Lemma 2): lemmas share the
# propositions' counter.
prf_realtyp_to_countertyp = {"lemma": "proposition"}

# --- Bibliography -----------------------------------------------------------------------
bibtex_bibfiles = ["references.bib"]
bibtex_default_style = "unsrt"
bibtex_reference_style = "author_year"

# --- Cross references -------------------------------------------------------------------
numfig = True
math_numfig = True
math_eqref_format = "({number})"

exclude_patterns = ["_build", "**.ipynb_checkpoints", "Thumbs.db", ".DS_Store", "jupyter_execute"]

# --- Offline MathJax --------------------------------------------------------------------
# Sphinx 9 loads MathJax 3 from a CDN by default; the book must render with no network.
# The wheel `sphinx-mathjax-offline` (a book extra in pyproject.toml) ships MathJax 3.2.2
# (tex-chtml.js plus its woff fonts) as plain files. Its own Sphinx hook sets mathjax_path from
# inside setup(), which is fragile, so we do not load it as an extension: we only take its
# files, copy them with html_static_path (to _build/html/_static/mathjax/) and point
# mathjax_path at the local copy. tests/test_book_build.py checks no script or stylesheet
# comes from http(s); tests/test_browser.py checks the math is typeset offline.
_mathjax_spec = importlib.util.find_spec("sphinx-mathjax-offline")
if _mathjax_spec is None or _mathjax_spec.origin is None:
    raise RuntimeError(
        "The offline MathJax files are missing: install the book extra, "
        "`pip install -e '.[book]'` (or run `make book`, which does it)."
    )
_MATHJAX_STATIC = str(Path(_mathjax_spec.origin).parent / "static")
mathjax_path = "mathjax/tex-chtml.js"

# --- HTML -------------------------------------------------------------------------------
html_theme = "sphinx_book_theme"
html_title = "The simple pendulum and elliptic functions"
html_static_path = ["_static", _MATHJAX_STATIC]
html_theme_options = {
    "show_toc_level": 2,
    # No launch buttons, repository buttons or analytics: each would link to or load from
    # the network, and the book must work offline.
    "use_download_button": True,
    "use_fullscreen_button": False,
}
html_last_updated_fmt = None
