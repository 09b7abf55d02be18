"""The environment is the one the book was built and checked with (constraints.txt).

`make venv` installs with ``-c constraints.txt``; this test reads the installed versions back
(importlib.metadata), so a venv made another way, or a constraint that pip could not honour,
shows up here instead of as a glued number that moved.
"""

from __future__ import annotations

import importlib.metadata
import re

from tests.conftest import ROOT


def _pins() -> dict[str, str]:
    pins = {}
    for line in (ROOT / "constraints.txt").read_text(encoding="utf-8").splitlines():
        m = re.fullmatch(r"([A-Za-z0-9_.-]+)==([^\s;]+)", line.strip())
        if m:
            pins[m[1]] = m[2]
    return pins


def test_every_pinned_package_is_installed_at_its_version() -> None:
    pins = _pins()
    assert {"numpy", "scipy", "sympy", "mpmath", "Sphinx", "myst-nb"} <= set(pins)
    wrong = {}
    for name, version in pins.items():
        try:
            got = importlib.metadata.version(name)
        except importlib.metadata.PackageNotFoundError:
            got = None
        if got != version:
            wrong[name] = (version, got)
    assert wrong == {}


def test_every_dependency_of_the_package_is_pinned() -> None:
    pins = {k.lower().replace("_", "-") for k in _pins()}
    requires = importlib.metadata.requires("elliptic-pendulum") or []
    names = {re.split(r"[<>=!~;\[ ]", r, maxsplit=1)[0].lower().replace("_", "-")
             for r in requires}
    assert names - pins == set()
