"""Mechanics: the forces on the bob, for a rod and for a string.

* :mod:`.rod` -- :class:`.Pendulum`, a rod of length l: position, tension, energy of (4);
* :mod:`.string` -- a string, which goes slack where the rod would push: when it does, the
  free flight, and whether it stays taut.
"""

from .rod import Pendulum
from .string import FreeFlight, free_flight, slack_point, string_stays_taut

__all__ = ["Pendulum", "FreeFlight", "free_flight", "slack_point", "string_stays_taut"]
