"""Sphinx extension: the book's checks found once per build, for the registry page.

tools/checks/scan.py reads every page's source and finds its ``verify`` calls; the list is
written as JSON next to the doctrees, and its path handed to the kernels that execute the
pages through the environment (they inherit this process's, as ``IPYTHONDIR`` in kernels.py).
The registry page (checks.md) reads it with ``elliptic_pendulum.checks.registry.load``.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from sphinx.application import Sphinx

from tools.checks.scan import scan, write

#: The environment variable that holds the path of the JSON list of checks.
VARIABLE = "ELLIPTIC_PENDULUM_BOOK_CHECKS"


def _scan(app: Sphinx) -> None:
    path = write(scan(Path(app.srcdir)), Path(app.doctreedir) / "checks.json")
    os.environ[VARIABLE] = str(path)


def setup(app: Sphinx) -> dict[str, Any]:
    """Register the extension with Sphinx."""
    app.connect("builder-inited", _scan)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
