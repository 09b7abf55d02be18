"""The public name of :mod:`elliptic_pendulum.checks.verify` (the book imports it from here)."""

from .checks.verify import *  # noqa: F403 - a thin re-export of the whole public API
from .checks.verify import __all__ as __all__
