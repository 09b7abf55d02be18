"""Sphinx extension: what the kernels that execute the book's pages see; where outputs are kept.

The profile (``ipython_kernel_config.py`` beside this file) is copied next to the doctrees at
every build and passed to the kernels through ``IPYTHONDIR``, which they inherit from this
process's environment: SVG figures, no history database, and two log messages of ipykernel
that say nothing about the book dropped (see the comments in the file).

Each edition's kernels write in its language. The library reads the language of what it
writes (verdicts, tables, figures) from the environment when a function is called
(``elliptic_pendulum._i18n``), so the build sets ``LANGUAGE`` to the edition's, English
included: a machine whose locale is Japanese still builds an English book. A translated
edition also names, in ``ELLIPTIC_PENDULUM_MESSAGES``, the catalogs the library looks up the
texts its cells pass in: ``locale/<lang>/LC_MESSAGES/cells.po`` (a fact's sentence, a
figure's label) and the pages' own catalogs beside it (the registry of checks names each
check's section by its heading, which the page's catalog translates).

So the editions' outputs differ, and each has its own execution cache: myst-nb's cache keys a
notebook by its code alone, which is the same in every edition. A translated edition's cache
is named after its language and its catalogs (``.jupyter_cache-ja-<hash>``): a changed
translation runs the pages again rather than showing the old words. The builds of one
edition (the site, the student site, the PDFs' single pages) share its cache, so each
edition executes each page once.
"""

from __future__ import annotations

import hashlib
import os
import shutil
from pathlib import Path
from typing import Any

from sphinx.application import Sphinx
from sphinx.config import Config

_CONFIG = Path(__file__).with_name("ipython_kernel_config.py")
LOCALE = Path(__file__).resolve().parents[1] / "locale"
# elliptic_pendulum._i18n's names (the build reads the environment as the library does).
LANGUAGE = "LANGUAGE"
CATALOG = "ELLIPTIC_PENDULUM_MESSAGES"


def cells_catalog(language: str) -> Path:
    """Return the catalog of the texts the book's cells pass to the library, in ``language``."""
    return LOCALE / language / "LC_MESSAGES" / "cells.po"


def _edition_kernels(app: Sphinx, config: Config) -> None:
    language = str(config.language or "en")
    os.environ[LANGUAGE] = language
    os.environ.pop(CATALOG, None)
    if language == "en":
        return
    cells = cells_catalog(language)
    catalogs = [cells, *sorted(p for p in cells.parent.glob("*.po") if p != cells)]
    os.environ[CATALOG] = os.pathsep.join(map(str, catalogs))
    digest = hashlib.sha256(b"".join(p.read_bytes() for p in catalogs)).hexdigest()[:12]
    english = Path(config.nb_execution_cache_path)
    config.nb_execution_cache_path = str(english.with_name(f"{english.name}-{language}-{digest}"))
    # The caches of earlier translations of this language are no one's any more.
    for old in english.parent.glob(f"{english.name}-{language}-*"):
        if old.name != Path(config.nb_execution_cache_path).name:
            shutil.rmtree(old, ignore_errors=True)


def _kernel_profile(app: Sphinx) -> None:
    ipython_dir = Path(app.doctreedir) / "ipython"
    profile = ipython_dir / "profile_default"
    profile.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(_CONFIG, profile / "ipython_kernel_config.py")
    os.environ["IPYTHONDIR"] = str(ipython_dir)


def setup(app: Sphinx) -> dict[str, Any]:
    """Register the extension with Sphinx."""
    app.connect("config-inited", _edition_kernels)
    app.connect("builder-inited", _kernel_profile)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
