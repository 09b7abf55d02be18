"""Sphinx extension: the kernels that execute the book's pages use a profile of the book's own.

The profile (``ipython_kernel_config.py`` beside this file) is copied next to the doctrees at
every build and passed to the kernels through ``IPYTHONDIR``, which they inherit from this
process's environment: SVG figures, no history database, and two log messages of ipykernel
that say nothing about the book dropped (see the comments in the file).
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path
from typing import Any

from sphinx.application import Sphinx

_CONFIG = Path(__file__).with_name("ipython_kernel_config.py")


def _kernel_profile(app: Sphinx) -> None:
    ipython_dir = Path(app.doctreedir) / "ipython"
    profile = ipython_dir / "profile_default"
    profile.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(_CONFIG, profile / "ipython_kernel_config.py")
    os.environ["IPYTHONDIR"] = str(ipython_dir)


def setup(app: Sphinx) -> dict[str, Any]:
    """Register the extension with Sphinx."""
    app.connect("builder-inited", _kernel_profile)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
