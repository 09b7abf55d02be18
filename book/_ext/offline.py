"""Sphinx extension: a built site loads nothing from the network, and links the reference locally.

Shared by the book and the reference site (``book/conf.py`` and ``docs/conf.py`` list it):

* MathJax. Sphinx 9 loads MathJax 3 from a CDN by default; the sites must render offline.
  The wheel ``sphinx-mathjax-offline`` (a book extra in pyproject.toml) ships MathJax 3.2.2
  (tex-chtml.js and its woff fonts) as plain files. Its own Sphinx hook sets ``mathjax_path``
  from inside ``setup()``, which is fragile, so it is not loaded as an extension: its files
  are copied with ``html_static_path`` (to ``_static/mathjax/``) and ``mathjax_path`` points
  at that copy. tests/book/test_book_build.py checks that no script or stylesheet comes from
  http(s); tests/book/test_browser.py that the math is typeset offline.
* The reference site. With ``reference_site`` set to a built reference (a folder holding
  ``objects.inv``; a relative path is taken from this build's output folder, so the book's
  default ``"reference"`` is ``<outdir>/reference``, where ``make book`` builds the docs),
  ``{py:func}`` roles link to its API entries through intersphinx, reading the inventory
  from disk, never from the network, with links relative to this build's output folder, so
  that they work from file:// and need no server. A reference inside the output folder
  makes one self-contained site that can be copied, zipped or served as it is; one outside
  it (the PDF's single-page builds) gives links that leave the folder.
  Only Python objects resolve implicitly: a ``{ref}`` or ``{doc}`` never lands in the
  reference by accident.
"""

from __future__ import annotations

import importlib.util
import os
from pathlib import Path
from typing import Any

from sphinx.application import Sphinx
from sphinx.config import Config


def _mathjax_files() -> str:
    spec = importlib.util.find_spec("sphinx-mathjax-offline")
    if spec is None or spec.origin is None:
        raise RuntimeError(
            "The offline MathJax files are missing: install the book extra, "
            "`pip install -e '.[book]'` (or run `make book`, which does it)."
        )
    return str(Path(spec.origin).parent / "static")


def _configure(app: Sphinx, config: Config) -> None:
    config.html_static_path = [*config.html_static_path, _mathjax_files()]
    config.mathjax_path = "mathjax/tex-chtml.js"
    if config.reference_site:
        # The inventory is read from the reference site beside this build, or from the one
        # ELLIPTIC_PENDULUM_DOCS_HTML names (the PDFs' single pages, built elsewhere, read
        # the site's). The links stay relative to reference_site either way, so the mapping
        # (a setting Sphinx keeps with its doctrees) is the same for the HTML page and its
        # single-page print, which then share their doctrees: nothing is read twice.
        named = os.environ.get("ELLIPTIC_PENDULUM_DOCS_HTML")
        site = (Path(named) if named else Path(app.outdir) / config.reference_site).resolve()
        if not (site / "objects.inv").is_file():
            raise RuntimeError(
                f"The reference site's inventory {site / 'objects.inv'} is missing: the book "
                "links to it. Build the docs into the book's output folder first (`make book` "
                f"does: sphinx-build docs {Path(app.outdir) / 'reference'}), or set "
                "ELLIPTIC_PENDULUM_DOCS_HTML to a docs build."
            )
        relative = config.reference_site.replace(os.sep, "/").rstrip("/")
        config.intersphinx_mapping["api"] = (relative + "/", str(site / "objects.inv"))
        config.intersphinx_disabled_reftypes = ["std:*"]


def setup(app: Sphinx) -> dict[str, Any]:
    """Register the extension with Sphinx."""
    app.add_config_value("reference_site", None, "env", types=frozenset({str, type(None)}))
    # Before intersphinx normalises its mapping (its own handler runs at priority 800).
    app.connect("config-inited", _configure, priority=100)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
