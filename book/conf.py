"""Sphinx configuration of the book "The simple pendulum and elliptic functions"."""

from __future__ import annotations

import importlib.util
import os
import sys
from pathlib import Path

project = "The simple pendulum and elliptic functions"
author = "elliptic-pendulum contributors, after S. Takeno (2024)"
copyright = "2024-2026, elliptic-pendulum contributors"

# book/_ext/classroom.py: the classroom notebooks in the build, the student book.
sys.path.insert(0, str(Path(__file__).parent / "_ext"))
extensions = [
    "myst_nb",
    "sphinx_proof",
    "sphinx_exercise",
    "sphinx_togglebutton",
    "sphinx_copybutton",
    "sphinx.ext.intersphinx",
    "sphinxcontrib.bibtex",
    "sphinx_book_theme",
    "classroom",
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

# --- Links into the reference site, offline ---------------------------------------------
# {py:func}`ep.solve <elliptic_pendulum.motion.solve>` links to the API entry of the docs
# build. Its objects.inv is read from disk, never fetched, and the links are written relative
# to this build's output folder, so they work from file:// and need no server. The docs build
# defaults to docs/_build/html (`make book` runs `make docs` first); the tests build it
# elsewhere and say where with ELLIPTIC_PENDULUM_DOCS_HTML.
_DOCS_HTML = Path(
    os.environ.get("ELLIPTIC_PENDULUM_DOCS_HTML")
    or Path(__file__).resolve().parents[1] / "docs" / "_build" / "html"
).resolve()
if not (_DOCS_HTML / "objects.inv").is_file():
    raise RuntimeError(
        f"The reference site's inventory {_DOCS_HTML / 'objects.inv'} is missing: the book "
        "links to it. Build the docs first (`make docs`, which `make book` does), or set "
        "ELLIPTIC_PENDULUM_DOCS_HTML to a docs build."
    )
intersphinx_mapping: dict[str, tuple[str, str]] = {}
# Only Python objects resolve implicitly: a {ref} or {doc} of the book never lands in the docs
# by accident (an explicit `api:` prefix still can).
intersphinx_disabled_reftypes = ["std:*"]


def _link_reference_site(app, config) -> None:
    # The relative URI needs the output folder, which is known only once Sphinx runs.
    relative = os.path.relpath(_DOCS_HTML, app.outdir).replace(os.sep, "/")
    config.intersphinx_mapping["api"] = (relative + "/", str(_DOCS_HTML / "objects.inv"))


# --- The kernels that execute the pages --------------------------------------------------
# An IPython profile of the book's own, written next to the doctrees and passed to the
# kernels through IPYTHONDIR (they inherit this process's environment):
# * figures as SVG, sharp on any screen (HiDPI) and zoomable; the library leaves rcParams alone;
# * ipykernel 7 logs, once per page, that its local TCP sockets are unencrypted. The kernel
#   lives as long as one page and talks only to this process on localhost; the message is
#   dropped, by its exact text, and every other log line of the kernel still shows;
# * the kernel's own shutdown race on a closed socket (ENOTSOCK) is not reported as an error;
# * no IPython history database for the throw-away kernels.
_KERNEL_CONFIG = """\
# Written by book/conf.py at every build; edits are lost.
import logging


class _DropUnencryptedTcpNotice(logging.Filter):
    def filter(self, record):
        return not str(record.msg).startswith("Kernel is running over TCP without encryption")


logging.getLogger("IPKernelApp").addFilter(_DropUnencryptedTcpNotice())


class _DropShutdownRace(logging.Filter):
    # A finished kernel shutting down can run a ZMQStream callback on a socket it has just
    # closed (ZMQError ENOTSOCK, logged with a traceback by tornado). ipykernel 7.4 demotes the
    # iopub case of this race to debug (ipykernel PR 1518); this drops the same error on the
    # other streams, and nothing else that tornado logs.
    def filter(self, record):
        import zmq

        error = record.exc_info[1] if record.exc_info else None
        return not (isinstance(error, zmq.ZMQError) and error.errno == zmq.ENOTSOCK)


logging.getLogger("tornado.general").addFilter(_DropShutdownRace())
c.InlineBackend.figure_formats = {"svg"}
c.HistoryManager.enabled = False
"""


def _kernel_profile(app) -> None:
    ipython_dir = Path(app.doctreedir) / "ipython"
    profile = ipython_dir / "profile_default"
    profile.mkdir(parents=True, exist_ok=True)
    (profile / "ipython_kernel_config.py").write_text(_KERNEL_CONFIG, encoding="utf-8")
    os.environ["IPYTHONDIR"] = str(ipython_dir)


def setup(app):
    # Before intersphinx normalises the mapping (its own handler runs at priority 800).
    app.connect("config-inited", _link_reference_site, priority=100)
    app.connect("builder-inited", _kernel_profile)
    return {"parallel_read_safe": True}


# --- Copy buttons -----------------------------------------------------------------------
# sphinx-copybutton ships its JavaScript and icons in the wheel (nothing from a CDN). Only
# what follows a prompt is copied from a doctest, and cell outputs have no button.
copybutton_prompt_text = r">>> |\.\.\. "
copybutton_prompt_is_regexp = True
copybutton_exclude = ".linenos, .gp, .go"
copybutton_selector = "div:not(.output) > div.highlight pre"

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
# Wide formulas scroll in their own block on a phone; see the comments in the files.
html_css_files = ["reader.css"]
html_js_files = ["reader.js"]
