"""The public name of :mod:`elliptic_pendulum.checks.errata` (the book imports it from here)."""

from .checks.errata import *  # noqa: F403 - a thin re-export of the whole public API
from .checks.errata import __all__ as __all__
