"""Sphinx configuration of the reference site (API, conventions, CLI)."""

from __future__ import annotations

import sys
from importlib.metadata import version as _version
from pathlib import Path

# The book's local extensions (book/_ext), found the way Sphinx documents for extensions
# that are not installed.
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "book" / "_ext"))

project = "elliptic-pendulum"
author = "elliptic-pendulum contributors"
copyright = "2024-2026, elliptic-pendulum contributors"
release = version = _version("elliptic-pendulum")  # written once, in pyproject.toml

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    # The docstrings are numpydoc style (CONTRIBUTING.md); napoleon reads them without the
    # stricter numpydoc extension, whose section checks would duplicate ruff's D rules.
    "sphinx.ext.napoleon",
    "sphinx.ext.doctest",
    # Copy buttons on code; its JavaScript and icons come from the wheel, not a CDN. Only
    # what follows a >>> or ... prompt is copied from an example.
    "sphinx_copybutton",
    "sphinx_book_theme",
    # book/_ext/offline.py: MathJax served from the build, as in the book.
    "offline",
    # book/_ext/a11y.py: WCAG 2.1 AA where docutils writes otherwise, as in the book.
    "a11y",
]

myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist"]
myst_heading_anchors = 3

copybutton_prompt_text = r">>> |\.\.\. "
copybutton_prompt_is_regexp = True
copybutton_exclude = ".linenos, .gp, .go"

napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_rtype = False
napoleon_preprocess_types = True
# numpydoc "Attributes" sections as :ivar: fields: as directives they would document the
# dataclass fields a second time next to autodoc's own entries (duplicate object warnings).
napoleon_use_ivar = True
# Short names of our own classes in docstring types, resolved to where they are documented.
napoleon_type_aliases = {
    "Regime": "~elliptic_pendulum.regimes.Regime",
    "Motion": "~elliptic_pendulum.motion.Motion",
    "Pendulum": "~elliptic_pendulum.mechanics.rod.Pendulum",
}

autodoc_typehints = "description"
# Signatures show the function's own name: its module is the section it is documented in,
# and a dotted path such as "elliptic_pendulum.periods.approximations." is one unbreakable
# token that a phone's screen cuts off.
add_module_names = False
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": True}

exclude_patterns = ["_build", "**.ipynb_checkpoints", "Thumbs.db", ".DS_Store"]

# --- Nitpicky references without the network -------------------------------------------
# intersphinx would fetch objects.inv from python.org, numpy.org and scipy.org, and the
# builds run offline; so references to types defined outside this package cannot resolve.
# Ignore exactly those, nothing of our own: a broken reference inside elliptic_pendulum
# still fails the build.
nitpick_ignore = [
    ("py:class", "array_like"),
    ("py:class", "array-like"),
    ("py:class", "ArrayLike"),
    ("py:class", "optional"),
    ("py:class", "callable"),
    # napoleon splits the numpydoc tuple type "(float, float)" into these two tokens
    ("py:class", "(float"),
    ("py:class", "float)"),
]
nitpick_ignore_regex = [
    # builtins and typing spelled in docstrings and annotations (float, int, ...)
    (
        r"py:(class|obj|data)",
        r"(builtins\.)?(float|int|bool|str|complex|tuple|list|dict|None|object|type)",
    ),
    (
        r"py:(class|obj|data)",
        r"(typing|collections\.abc|types|enum|dataclasses|fractions|decimal|pathlib)\..*",
    ),
    # third-party types: numpy, scipy, sympy, matplotlib
    (
        r"py:(class|obj|data|func|mod|meth|attr)",
        r"(numpy|np|numpy\.typing|npt|scipy|sympy|sp|matplotlib|mpmath)(\..*)?",
    ),
    (r"py:(class|obj)", r"(ndarray|NDArray|Axes|Figure|Expr|Symbol|Eq|Basic|ArrayLike)(\[.*\])?"),
    (r"py:(class|obj)", r"(numpy\.)?float64"),
]

html_theme = "sphinx_book_theme"
html_title = "elliptic-pendulum reference"
html_static_path = [
    "_static",
    # The book's reader.css and reader.js (wide formulas, signatures and tables scroll or
    # wrap on a phone), one copy for both sites.
    str(Path(__file__).resolve().parents[1] / "book" / "_static"),
]
html_css_files = ["reader.css", "a11y.css"]
html_js_files = ["reader.js"]
# The book's templates: its search button, named by its text (book/_static/a11y.css and
# book/_ext/a11y.py say why). The book's footer templates are there too, unused here.
templates_path = [str(Path(__file__).resolve().parents[1] / "book" / "_templates")]
html_theme_options = {"show_toc_level": 2}
html_last_updated_fmt = None
