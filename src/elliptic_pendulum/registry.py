"""The public name of :mod:`elliptic_pendulum.checks.registry` (the book imports it from here)."""

from .checks.registry import *  # noqa: F403 - a thin re-export of the whole public API
from .checks.registry import __all__ as __all__
