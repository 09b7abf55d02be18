"""The public name of :mod:`elliptic_pendulum.plotting.animation` (the book imports it here)."""

from .plotting.animation import *  # noqa: F403 - a thin re-export of the whole public API
from .plotting.animation import __all__ as __all__
