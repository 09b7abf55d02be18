"""elliptic-pendulum: the exact simple pendulum through Jacobi's elliptic functions.

The public API (re-exports only; see each module for the mathematics):

>>> import elliptic_pendulum as ep
>>> m = ep.solve(2.0)           # released at rest from 2 rad
>>> m.regime
<Regime.LIBRATION: 'II'>
"""

from .approximations import (
    agm_ratio,
    kidd_fogg_ratio,
    lima_arun_ratio,
    log_ratio,
    ratio_approximations,
)
from .continuation import ResponseCurve, response_curve
from .elliptic import (
                       am,
                       cn,
                       complete_integral,
                       dn,
                       incomplete_integral,
                       inverse_integral,
                       jacobi,
                       sn,
)
from .mechanics import Pendulum
from .motion import Motion, solve
from .numerics import integrate
from .period import agm_period, crossing_angle, period, period_ratio, small_angle_period
from .regimes import Regime
from .resonance import PeriodicOrbit, backbone_frequency, duffing_backbone, periodic_orbit
from .series import fourier_coefficients, nome, period_series, period_series_coefficients
from .string_pendulum import FreeFlight, free_flight, slack_point, string_stays_taut
from .sweep import settle, sweep

__all__ = [
    "Motion", "Pendulum", "Regime", "agm_period", "am", "cn", "complete_integral",
    "crossing_angle", "dn", "incomplete_integral", "integrate", "inverse_integral",
    "jacobi", "period", "period_ratio", "small_angle_period", "sn", "solve",
    # beyond the note: the period in depth, rod or string, toward nonlinear resonance
    "FreeFlight", "PeriodicOrbit", "ResponseCurve", "backbone_frequency", "duffing_backbone",
    "fourier_coefficients", "free_flight", "nome", "period_series", "period_series_coefficients",
    "periodic_orbit", "response_curve", "slack_point", "string_stays_taut",
    "agm_ratio", "kidd_fogg_ratio", "lima_arun_ratio", "log_ratio", "ratio_approximations",
    "settle", "sweep",
]
__version__ = "0.1.0"
