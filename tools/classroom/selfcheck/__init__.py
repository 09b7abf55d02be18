"""Self-checks of the book's exercises, for the classroom notebooks.

A student's notebook runs ``check("ex-energy-threshold", v_star=v_star)`` under an exercise:
it prints whether each answer is right and, if not, a hint that names the likely mistake
without giving the value away (_core.py). One module per chapter, named after its page,
registers that chapter's exercises; all are imported here. The classroom bundle
(tools/classroom/bundle.py) ships this folder beside the notebooks as the package
``selfcheck``, so it imports only the standard library, numpy, scipy, mpmath and
elliptic_pendulum, and itself relatively.
"""

from __future__ import annotations

import importlib
import pkgutil

from ._core import EXERCISES, Exercise, Hint, Value, check, expected, judge

for _module in pkgutil.iter_modules(__path__):
    if not _module.name.startswith("_"):
        importlib.import_module(f".{_module.name}", __name__)

__all__ = ["EXERCISES", "Exercise", "Hint", "Value", "check", "expected", "judge"]
