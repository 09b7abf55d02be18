"""The book and docs tier: builds, notebooks in a fresh venv, the browser, the PDF.

Every test in this folder is marked ``slow`` (``make test-fast`` leaves them out, ``make
test`` runs them), whatever its own marks: the folder is the tier.
"""

from __future__ import annotations

from pathlib import Path

import pytest

_HERE = Path(__file__).resolve().parent


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    for item in items:
        if _HERE in Path(str(item.path)).resolve().parents:
            item.add_marker(pytest.mark.slow)
