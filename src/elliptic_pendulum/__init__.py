"""elliptic-pendulum: the exact simple pendulum through Jacobi's elliptic functions.

The public API (re-exports only; see each module for the mathematics):

>>> import elliptic_pendulum as ep
>>> m = ep.solve(2.0)           # released at rest from 2 rad
>>> m.regime
<Regime.LIBRATION: 'II'>

The driven pendulum (:mod:`elliptic_pendulum.driven`) and the numerical reference
integration (:mod:`elliptic_pendulum.numerics`) need scipy.integrate and scipy.optimize; they
are imported when one of their names is first used, so that ``import elliptic_pendulum`` and
every command of the CLI stay quick.
"""

from __future__ import annotations

import importlib
from importlib.metadata import PackageNotFoundError, version
from typing import TYPE_CHECKING, Any

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
from .mechanics import FreeFlight, Pendulum, free_flight, slack_point, string_stays_taut
from .motion import Motion, solve
from .periods import (
    agm_period,
    agm_ratio,
    crossing_angle,
    fourier_coefficients,
    kidd_fogg_ratio,
    lima_arun_ratio,
    log_ratio,
    nome,
    period,
    period_ratio,
    period_series,
    period_series_coefficients,
    ratio_approximations,
    small_angle_period,
)
from .regimes import Regime

if TYPE_CHECKING:
    from .driven import (
        PeriodicOrbit,
        ResponseCurve,
        backbone_frequency,
        duffing_backbone,
        periodic_orbit,
        response_curve,
        settle,
        sweep,
    )
    from .numerics import integrate

# name -> the module that defines it, imported on first use (PEP 562)
_LAZY = {
    "integrate": ".numerics",
    **dict.fromkeys(("PeriodicOrbit", "ResponseCurve", "backbone_frequency", "duffing_backbone",
                     "periodic_orbit", "response_curve", "settle", "sweep"), ".driven"),
}


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name], __name__), name)
        globals()[name] = value  # once: later lookups are plain attribute reads
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))


try:
    __version__ = version("elliptic-pendulum")  # the one place it is written: pyproject.toml
except PackageNotFoundError:  # pragma: no cover - a source tree that was never installed
    __version__ = "0+unknown"

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
