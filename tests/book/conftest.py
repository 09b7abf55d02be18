"""The book and docs tier: builds, notebooks in a fresh venv, the browser, the PDF.

Every test in this folder is marked ``slow`` (``make test-fast`` leaves them out, ``make
test`` runs them), whatever its own marks: the folder is the tier.
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

_HERE = Path(__file__).resolve().parent


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    for item in items:
        if _HERE in Path(str(item.path)).resolve().parents:
            item.add_marker(pytest.mark.slow)


BROWSERS = ["chromium", "chromium-browser", "google-chrome", "google-chrome-stable"]


@pytest.fixture(scope="session")
def chromium() -> str:
    """The headless browser of test_browser and test_site (Debian's chromium)."""
    for name in BROWSERS:
        path = shutil.which(name)
        if path:
            return path
    message = "no Chromium found (apt-get install chromium)"
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail(message + "; CI must run the browser check", pytrace=False)
    pytest.skip(message)
