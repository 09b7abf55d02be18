"""Sphinx configuration of the book "The simple pendulum and elliptic functions"."""

from __future__ import annotations

import sys
from pathlib import Path

project = "The simple pendulum and elliptic functions"
author = "elliptic-pendulum contributors, after S. Takeno (2024)"
# The footer (_templates/licence.html) adds the licences: text and figures CC BY 4.0
# (book/LICENSE), code MIT (LICENSE); about.md says so in full.
copyright = "2024-2026 elliptic-pendulum contributors"

# Local extensions (book/_ext: the classroom editions, the kernels' profile, the offline
# assets, shared with docs/conf.py) and the repository's tools (tools.classroom), found the
# way Sphinx documents for extensions that are not installed.
_HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(_HERE / "_ext"), str(_HERE.parent)]
extensions = [
    "myst_nb",
    # book/_ext/i18n.py: the Japanese edition from book/locale (its parser replaces
    # myst-nb's, so it comes after it; its exercise catalog is read before sphinx-exercise's).
    "i18n",
    # book/_ext/ja_search.py: Japanese search queries split into words as the index is.
    "ja_search",
    "sphinx_proof",
    "sphinx_exercise",
    "sphinx_togglebutton",
    "sphinx_copybutton",
    "sphinx.ext.intersphinx",
    "sphinxcontrib.bibtex",
    "sphinx_book_theme",
    "classroom",
    "kernels",
    # book/_ext/checks_scan.py: the checks of all pages, for the registry page.
    "checks_scan",
    # book/_ext/site_links.py: the home page's links to the site's editions and downloads.
    "site_links",
    # book/_ext/checkmarks.py: each check cell as one folded mark in the margin.
    "checkmarks",
    # book/_ext/numref_cache.py: {numref} without unpickling its target's page each time.
    "numref_cache",
    "offline",
    # book/_ext/a11y.py: WCAG 2.1 AA where docutils and myst-nb write otherwise (citations,
    # the code cells' toggles); after myst_nb, whose toggle it rewrites.
    "a11y",
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
# One cache for every build of the book: the site, the student site (which executes the
# pages whole and removes the solutions afterwards, book/_ext/classroom.py) and the PDFs'
# single-page builds run each notebook once between them, and show the same numbers.
nb_execution_cache_path = str(_HERE / "_build" / ".jupyter_cache")
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
bibtex_reference_style = "label"

# --- Cross references -------------------------------------------------------------------
numfig = True
math_numfig = True
math_eqref_format = "({number})"

# --- Links into the reference site, offline (book/_ext/offline.py) ---------------------
# {py:func}`ep.solve <elliptic_pendulum.motion.solve>` links to the API entry of the docs
# build, read from its objects.inv on disk, relative to this build. The docs are built into
# the book's own output folder, <outdir>/reference (`make book` and the tests do), so the
# book and its reference are one folder that can be copied or served as it is. A relative
# path is taken from the output folder; ELLIPTIC_PENDULUM_DOCS_HTML may name the build whose
# inventory to read (the PDF's single-page builds, `make pdf`).
reference_site = "reference"
intersphinx_mapping: dict[str, tuple[str, str]] = {}

# --- Copy buttons -----------------------------------------------------------------------
# sphinx-copybutton ships its JavaScript and icons in the wheel (nothing from a CDN). Only
# what follows a prompt is copied from a doctest, and cell outputs have no button.
copybutton_prompt_text = r">>> |\.\.\. "
copybutton_prompt_is_regexp = True
copybutton_exclude = ".linenos, .gp, .go"
copybutton_selector = "div:not(.output) > div.highlight pre"

exclude_patterns = ["_build", "**.ipynb_checkpoints", "Thumbs.db", ".DS_Store", "jupyter_execute"]

# --- Translations (book/_ext/i18n.py) ----------------------------------------------------
# `make book-ja`: sphinx-build -D language=ja into <site>/ja. One catalog per page, messages
# with their source lines (a translator sees the English in context).
language = "en"
locale_dirs = ["locale"]
gettext_compact = False
gettext_uuid = False
gettext_last_translator = "elliptic-pendulum contributors"
# The gettext builder renders outputs by its own MIME priority, without images, so the alt
# texts of figures would not reach the catalogs.
nb_mime_priority_overrides = [("gettext", "image/svg+xml", 1), ("gettext", "image/png", 2)]

# --- HTML -------------------------------------------------------------------------------
html_theme = "sphinx_book_theme"
html_title = "The simple pendulum and elliptic functions"
# MathJax is served from the build too (book/_ext/offline.py adds its files).
html_static_path = ["_static"]
templates_path = ["_templates"]
html_theme_options = {
    "show_toc_level": 2,
    # The theme's footer with the licences (_templates/licence.html, in place of the
    # theme's copyright.html), and which edition this is (_templates/edition.html): the
    # instructor site holds the solutions and is for the teacher only.
    "footer_content_items": ["author.html", "licence.html", "edition.html",
                             "last-updated.html", "extra-footer.html"],
    # No launch buttons, repository buttons or analytics: each would link to or load from
    # the network, and the book must work offline.
    "use_download_button": True,
    "use_fullscreen_button": False,
    # The language switch (_templates/language-switch.html) before the theme's buttons.
    "article_header_end": ["language-switch.html", "article-header-buttons.html"],
}
html_last_updated_fmt = None
# Wide formulas scroll in their own block on a phone; see the comments in the files.
# a11y.css: contrast, and inline formulas that are never cut off (WCAG 2.1 AA).
html_css_files = ["reader.css", "a11y.css"]
html_js_files = ["reader.js"]
