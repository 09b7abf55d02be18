"""Self-checks of the book's exercises, for the classroom notebooks.

A student's notebook runs ``check("ex-energy-threshold", v_star=v_star)`` under an exercise:
it prints whether each answer is right and, if not, a hint that names the likely mistake
without giving the value away (_core.py), in the language asked for or the environment's.
One module per chapter, named after its page, registers that chapter's exercises; all are
imported here. It is part of the installed package, so a notebook opened wherever the
package is installed can check its answers; it computes its references without the rest of
the package (the standard library, numpy, scipy and mpmath only), by routes of its own.
"""

from __future__ import annotations

import importlib
import pkgutil

from ._core import EXERCISES, Exercise, Hint, Value, check, environment_language, expected, judge

for _module in pkgutil.iter_modules(__path__):
    if not _module.name.startswith("_"):
        importlib.import_module(f".{_module.name}", __name__)

__all__ = ["EXERCISES", "Exercise", "Hint", "Value", "check", "environment_language", "expected",
           "judge"]
