"""elliptic-pendulum: the exact simple pendulum through Jacobi's elliptic functions.

The public API (re-exports only; see each module for the mathematics):

>>> import elliptic_pendulum as ep
>>> m = ep.solve(2.0)           # released at rest from 2 rad
>>> m.regime
<Regime.LIBRATION: 'II'>
"""

from .elliptic import (am, cn, complete_integral, dn, incomplete_integral,
                       inverse_integral, jacobi, sn)
from .motion import Motion, solve
from .regimes import Regime

__all__ = [
    "Motion", "Regime", "am", "cn", "complete_integral", "dn",
    "incomplete_integral", "inverse_integral", "jacobi", "sn", "solve",
]
__version__ = "0.1.0"
