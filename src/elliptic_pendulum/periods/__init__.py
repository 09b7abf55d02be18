"""Periods: the exact period (26), its ratio to the small-angle period, series and approximations.

* :mod:`.period` -- T = 4 K1 / omega0, R(theta0), the amplitudes where R crosses a value, the AGM;
* :mod:`.series` -- the period's power series, the nome, the Fourier harmonics of a swing;
* :mod:`.approximations` -- the closed-form approximations a laboratory uses.
"""

from .approximations import (
    agm_ratio,
    kidd_fogg_ratio,
    lima_arun_ratio,
    log_ratio,
    ratio_approximations,
)
from .period import agm_period, crossing_angle, period, period_ratio, small_angle_period
from .series import fourier_coefficients, nome, period_series, period_series_coefficients

__all__ = [
    "period", "period_ratio", "small_angle_period", "crossing_angle", "agm_period",
    "period_series", "period_series_coefficients", "nome", "fourier_coefficients",
    "ratio_approximations", "agm_ratio", "kidd_fogg_ratio", "lima_arun_ratio", "log_ratio",
]
