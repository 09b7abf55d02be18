r"""The driven pendulum run the long way: to a steady state, and through a slow frequency sweep.

For the chapter "toward nonlinear resonance": what a laboratory sees, against what
:mod:`.resonance` and :mod:`.continuation` compute. :func:`settle` integrates

.. math:: \theta'' + 2\zeta\omega_0\theta' + \omega_0^2\sin\theta = F\cos\Omega t

with :func:`scipy.integrate.solve_ivp` over many forcing periods, until the transient (which decays
like :math:`e^{-\zeta\omega_0 t}`) is gone, and measures the swing over the last period;
:func:`sweep` does so at a sequence of frequencies, each run starting where the previous one ended,
as when a motor's speed is turned slowly: up through the bistable range the amplitude stays on the
lower branch and jumps up at the fold, down it stays on the upper one and jumps down at the other.

This module shares no code with the shooting of :mod:`.resonance`: the right-hand side is written
out again, and no Newton step or variational equation is involved, so agreement between the two is
a check. With :math:`\zeta = 0.05` some 80 periods
suffice (the transient falls by :math:`e^{-25}`).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import numpy.typing as npt
from scipy import integrate

from .._validation import positive_scalar, real_array, real_scalar

__all__ = ["settle", "sweep"]


def _check_periods(periods: Any) -> int:
    if isinstance(periods, bool) or not isinstance(periods, (int, np.integer)) or periods < 1:
        raise ValueError(f"periods must be a positive integer; got {periods!r}")
    return int(periods)


def settle(frequency: float, forcing: float, damping: float, omega0: float = 1.0, *,
           state: npt.ArrayLike = (0.0, 0.0),
           periods: int = 80) -> tuple[tuple[float, float], float]:
    r"""Integrate the driven pendulum for whole forcing periods; return the end and the swing.

    .. math:: y(N\,T_F), \qquad \tfrac12\left(\max\theta - \min\theta\right)
              \text{ over } [(N-1)T_F, N T_F], \qquad T_F = \frac{2\pi}{\Omega}

    Parameters
    ----------
    frequency : float
        :math:`\Omega > 0`.
    forcing : float
        F, real.
    damping : float
        :math:`\zeta > 0`.
    omega0 : float, optional
        :math:`\sqrt{g/\ell}`, positive; default 1.
    state : (float, float), optional
        :math:`(\theta, \theta')` at t = 0 (keyword); default at rest at the bottom.
    periods : int, optional
        N (keyword); default 80.

    Returns
    -------
    state : tuple of float
        :math:`(\theta, \theta')` at :math:`t = N T_F`, where the forcing's phase is 0 again.
    amplitude : float
        Half the peak-to-peak swing over the last period (from 4001 samples of the dense
        output), comparable with ``PeriodicOrbit.amplitude``.

    Examples
    --------
    Far below resonance the pendulum follows the force, with the linear amplitude
    :math:`F/|\omega_0^2 - \Omega^2 + 2i\zeta\omega_0\Omega|`:

    >>> _, amplitude = settle(0.3, 1e-3, 0.1)
    >>> linear = 1e-3 / abs(complex(1 - 0.3**2, 2 * 0.1 * 0.3))
    >>> bool(abs(amplitude / linear - 1) < 1e-4)
    True
    """
    frequency = positive_scalar(frequency, "frequency")
    forcing = real_scalar(forcing, "forcing")
    damping = positive_scalar(damping, "damping")
    omega0 = positive_scalar(omega0, "omega0")
    start = real_array(state, "state")
    if start.shape != (2,):
        raise ValueError("state must be one state (theta, theta')")
    count = _check_periods(periods)
    w2, c = omega0 * omega0, 2.0 * damping * omega0

    def rhs(t, y):
        return [y[1], forcing * math.cos(frequency * t) - c * y[1] - w2 * math.sin(y[0])]

    span = 2 * math.pi / frequency
    end = count * span
    # solve_ivp's smallest step (nextafter(t, inf) - t) can be subnormal, and a tiny swing
    # (forcing 1e-300) underflows in its arithmetic and its dense output: scipy's own
    # roundings to 0, no concern of the caller's np.errstate.
    with np.errstate(under="ignore"):
        sol = integrate.solve_ivp(rhs, (0.0, end), start.tolist(), method="DOP853", rtol=1e-11,
                                  atol=1e-12, dense_output=True)
        if not sol.success:  # pragma: no cover - DOP853 on a smooth bounded field
            raise RuntimeError(f"solve_ivp failed: {sol.message}")
        theta = sol.sol(np.linspace(end - span, end, 4001))[0]
    final = sol.y[:, -1]
    return (float(final[0]), float(final[1])), float(0.5 * (theta.max() - theta.min()))


def sweep(frequencies: npt.ArrayLike, forcing: float, damping: float, omega0: float = 1.0, *,
          state: npt.ArrayLike = (0.0, 0.0), periods: int = 80) -> np.ndarray:
    r"""Settle at each frequency in turn, each run starting from where the last one ended.

    .. math:: y_{k+1}(0) = y_k(N\,T_{F,k}), \qquad A_k = \tfrac12(\max\theta - \min\theta)_k

    Parameters
    ----------
    frequencies : array_like
        The frequencies :math:`\Omega_k > 0`, in the order of the sweep (increasing or
        decreasing, or both: a loop).
    forcing, damping, omega0
        As for :func:`settle`.
    state : (float, float), optional
        The state the first run starts from; default at rest.
    periods : int, optional
        Forcing periods per frequency; default 80.

    Returns
    -------
    ndarray
        The amplitudes :math:`A_k`, one per frequency.

    Notes
    -----
    The angle is reduced to :math:`(-\pi, \pi]` between runs (it only matters if a run ends in
    a rotation). A sweep holds each frequency for a whole number of its periods, so every run
    starts at the forcing's phase 0.

    Examples
    --------
    Across the fold of the lower branch (near 0.872 for these parameters) the amplitude jumps up:

    >>> amplitudes = sweep([0.86, 0.88], forcing=0.15, damping=0.05, periods=60)
    >>> bool(amplitudes[0] < 1 < amplitudes[1])
    True
    """
    values = real_array(frequencies, "frequencies")
    if values.ndim != 1 or values.size == 0 or np.any(values <= 0):
        raise ValueError("frequencies must be a non-empty sequence of positive numbers")
    current = real_array(state, "state")
    out = np.empty(values.size)
    for k, frequency in enumerate(values):
        (theta, dtheta), out[k] = settle(frequency, forcing, damping, omega0, state=current,
                                         periods=periods)
        current = np.array([math.pi - (math.pi - theta) % (2 * math.pi), dtheta])
    return out
