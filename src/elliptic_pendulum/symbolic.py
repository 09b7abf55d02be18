"""The public name of the note's sympy statements, which live in the checks package.

:mod:`elliptic_pendulum.checks.symbolic` holds the symbols and ``Identity``, and
:mod:`elliptic_pendulum.checks.identities` the list of the note's statements.

>>> import elliptic_pendulum.symbolic as sym
>>> sym.identity("eq27").check()
True
"""

from .checks.identities import identities, identity
from .checks.symbolic import *  # noqa: F403 - a thin re-export of the whole public API
from .checks.symbolic import __all__ as _symbolic_all

__all__ = [*_symbolic_all, "identities", "identity"]

from .checks import symbolic as _impl


def __getattr__(name: str):
    """Return the note's symbol ``name`` (``t``, ``theta``, ...) from the module that holds it."""
    return getattr(_impl, name)
