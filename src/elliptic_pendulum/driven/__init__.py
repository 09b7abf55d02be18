"""The pendulum driven and damped, toward nonlinear resonance (numerical, beyond the note).

* :mod:`.resonance` -- the backbone of free motion, periodic orbits of the driven pendulum;
* :mod:`.continuation` -- response curves by pseudo-arclength continuation;
* :mod:`.sweep` -- long runs and slow frequency sweeps.

These need scipy.integrate and scipy.optimize, so ``import elliptic_pendulum`` loads them
only when one of their names is first used.
"""

from .continuation import ResponseCurve, response_curve
from .resonance import PeriodicOrbit, backbone_frequency, duffing_backbone, periodic_orbit
from .sweep import settle, sweep

__all__ = [
    "backbone_frequency", "duffing_backbone", "PeriodicOrbit", "periodic_orbit",
    "ResponseCurve", "response_curve", "settle", "sweep",
]
