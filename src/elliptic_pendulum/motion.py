r"""The exact motion theta(t) of the simple pendulum from any initial state.

The closed forms are the note's (25) for regime II, (28) for III and (46) for
IV, evaluated so that no digit is lost near the bottom or the top:

* II:  theta = 2 arcsin(alpha sn(w0 t + c2, alpha)), computed as
  2 atan2(alpha sn, dn) (arcsin near 1 would halve the digits), and
  theta' = 2 w0 alpha cn(w0 t + c2, alpha);
* III: theta = 2 gd(w0 t + c3) = 2 arctan(sinh(w0 t + c3)) (the tanh form (28)),
  theta' = 2 w0 sech(w0 t + c3); or the singular solution at rest at the top;
* IV:  theta = +-2 am(w0 t / gamma + c4, gamma), theta' = +-(2 w0 / gamma) dn(...).

(Our c3 is the note's -c3, so that every phase is added to w0 t.)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from . import _landen
from ._landen import _two_prod, _two_sum, gudermannian, sech
from ._validation import positive_scalar, real_array, real_scalar, scalar_or_array
from .regimes import (
    Regime,
    State,
    classify,
    libration_phase,
    rotation_phase,
)

__all__ = ["Motion", "solve"]


@dataclass(frozen=True)
class Motion:
    r"""One solution of (3), theta'' = -w0^2 sin theta; made by :func:`solve`.

    Attributes
    ----------
    regime : Regime
        I, II, III or IV (``regime.value``).
    theta0, dtheta0, omega0 : float
        The initial state at t = 0 and omega0 = sqrt(g / l) of (6).
    energy_constant : float
        c1 = theta'^2 - 2 w0^2 cos theta of (9).
    modulus, complementary_modulus : float
        alpha = sin(theta0/2) for II (14), gamma = sqrt(2 / (beta + 1)) for IV;
        1 and 0 on the separatrix, 0 and 1 at rest. The complement is computed
        directly, never as sqrt(1 - modulus**2).
    amplitude : float
        The turning angle of (11) for II; 0 for I, pi for III, inf for IV.
    phase : float
        c2, c3 or c4: the elliptic (or hyperbolic) argument at t = 0.
    direction : int
        +1 or -1: the sign in (28) and (46); +1 for I and II.
    period : float
        (26) for II; the time of one full turn for IV; inf for III; for I the
        limit of (26) at zero amplitude, 2 pi / w0 of (8).
    """

    regime: Regime
    theta0: float
    dtheta0: float
    omega0: float
    energy_constant: float
    modulus: float
    complementary_modulus: float
    amplitude: float
    phase: float
    direction: int
    period: float
    _state: State = field(repr=False, compare=False)

    @property
    def beta(self) -> float:
        """Return the note's beta = c1 / (2 w0^2) of (29), greater than 1 in regime IV."""
        return self._state.beta

    @property
    def alpha(self) -> float | None:
        """The note's alpha = sin(theta0/2) of (14) in regime II, else None."""
        return self.modulus if self.regime is Regime.LIBRATION else None

    @property
    def gamma(self) -> float | None:
        """The note's gamma = sqrt(2/(beta + 1)) of §6 in regime IV, else None."""
        return self.modulus if self.regime is Regime.ROTATION else None

    def theta(self, t: Any) -> Any:
        """Return the angle theta(t) in radians; float or array like ``t``.

        Any real t up to about 6.7e7 quarter periods (2**26) from 0; beyond, the
        reduction of the elliptic argument is not exact and a ValueError names t.
        """
        t = real_array(t, "t")
        return scalar_or_array(self._evaluate(t)[0], t)

    def dtheta(self, t: Any) -> Any:
        """Return the angular velocity theta'(t); float or array like ``t``."""
        t = real_array(t, "t")
        return scalar_or_array(self._evaluate(t)[1], t)

    def _evaluate(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        st, w0, sgn = self._state, self.omega0, self.direction
        if self.regime is Regime.REST or (self.regime is Regime.SEPARATRIX
                                          and st.w == 0.0):
            return np.full(t.shape, st.turns + st.r), np.zeros(t.shape)
        if self.regime is Regime.SEPARATRIX:
            with np.errstate(over="ignore"):  # w0 t = +-inf still means theta = +-pi
                x = w0 * t + self.phase
            return st.turns + sgn * 2.0 * gudermannian(x), sgn * 2.0 * w0 * sech(x)
        # u = rate t + phase, with rate = w0 (II) or w0 / gamma = w0 k (IV) known to
        # 1e-32, carried as a double-double: the phase survives thousands of periods.
        with np.errstate(over="ignore"):  # an overflow here is exactly what is reported
            # Beyond 1e290, Dekker's split in the exact product overflows.
            in_range = np.all((np.abs(t) <= 1e290) & (np.abs(t) * st.rate <= 1e290))
        if not in_range:
            raise ValueError("t is too large: |omega0 t| must stay below about 1e290 "
                             "(the elliptic argument grows like omega0 t)")
        p, p_lo = _two_prod(st.rate, t)
        u, u_lo = _two_sum(p, self.phase)
        u_lo = u_lo + (p_lo + st.rate_lo * t)
        c = _landen.constants(self.complementary_modulus, st.mod_c_lo)
        rotation = self.regime is Regime.ROTATION
        sn, cn, dn, am = _landen.evaluate(u, c, u_lo, amplitude=rotation, name="t")
        if rotation:  # (46): theta = +-2 am, theta' = +-2 (w0 / gamma) dn
            return st.turns + sgn * 2.0 * am, sgn * 2.0 * st.rate * dn
        # (25) as theta / 2 = atan2(alpha sn, dn): arcsin near 1 would halve the digits.
        k = self.modulus
        return st.turns + 2.0 * np.arctan2(k * sn, dn), 2.0 * w0 * k * cn


def solve(theta0: Any, dtheta0: Any = 0.0, omega0: Any = 1.0) -> Motion:
    r"""Solve (3) exactly from the initial state (theta0, theta0') at t = 0.

    .. math:: \theta'' = -\omega_0^2 \sin\theta, \qquad
              \theta(0) = \theta_0, \quad \theta'(0) = \theta_0'

    Parameters
    ----------
    theta0 : float
        Initial angle in radians from the downward vertical; any real value
        (2 pi m is carried along). ``math.pi`` means exactly upside down.
    dtheta0 : float, default 0.0
        Initial angular velocity in rad per unit time; either sign.
    omega0 : float, default 1.0
        sqrt(g / l) of (6), > 0. With omega0 = 1, t is measured in units of
        sqrt(l / g).

    Returns
    -------
    Motion

    Raises
    ------
    TypeError
        For a non-number.
    ValueError
        For NaN, infinities or omega0 <= 0.

    Examples
    --------
    A 170 degree swing from rest: regime II, and the period is (26).

    >>> import math
    >>> m = solve(math.radians(170))
    >>> m.regime.value, round(math.degrees(m.amplitude), 12)
    ('II', 170.0)
    >>> from elliptic_pendulum.elliptic import complete_integral
    >>> m.period == 4 * complete_integral(math.sin(m.amplitude / 2),
    ...                                    kc=math.cos(m.amplitude / 2))
    True
    >>> abs(m.theta(m.period) - m.theta0) < 1e-12
    True

    Kicked hard enough at the bottom it goes over the top (IV); exactly
    hard enough (theta' = 2 omega0), it creeps up the separatrix (III):

    >>> solve(0.0, 2.5).regime.value, solve(0.0, 2.0).regime.value
    ('IV', 'III')

    Released at rest exactly upside down it stays there (the singular solution):

    >>> solve(math.pi).theta(100.0) == math.pi
    True
    """
    theta0 = real_scalar(theta0, "theta0")
    dtheta0 = real_scalar(dtheta0, "dtheta0")
    omega0 = positive_scalar(omega0, "omega0")
    st = classify(theta0, dtheta0, omega0)
    if not st.rate < 1e290:
        raise ValueError("dtheta0 / omega0 and omega0 are too large together: the rate "
                         "omega0 * max(1, |dtheta0| / (2 omega0)) must stay below 1e290")
    if st.regime in (Regime.LIBRATION, Regime.ROTATION) and st.mod_c < 1e-300:
        # Only a push of under 1e-300 rad/s at the very top gets here: kc would be subnormal
        # and K = log(4/kc) (hence the period) would lose its digits.
        raise ValueError("dtheta0 is too small for a state this close to the top: the "
                         "complementary modulus falls below 1e-300; use dtheta0 = 0 "
                         "(balanced at the top) or |dtheta0| >= 2e-300 * omega0")
    c1 = st.c1
    if st.regime is Regime.REST:
        return Motion(st.regime, theta0, dtheta0, omega0, c1, 0.0, 1.0, 0.0, 0.0, 1,
                      2.0 * math.pi / omega0, st)
    if st.regime is Regime.SEPARATRIX:
        sgn = 1 if st.w > 0 else -1
        phase = 0.0 if st.w == 0 else sgn * math.asinh(st.s / st.c)
        return Motion(st.regime, theta0, dtheta0, omega0, c1, 1.0, 0.0, math.pi, phase,
                      sgn, math.inf, st)
    if st.regime is Regime.LIBRATION:
        kc = st.mod_c
        quarter = float(_landen.constants(kc, st.mod_c_lo).quarter)
        return Motion(st.regime, theta0, dtheta0, omega0, c1, st.k, kc,
                      2.0 * math.atan2(st.k, kc), libration_phase(st, quarter), 1,
                      4.0 * quarter / omega0, st)
    sgn = 1 if st.w > 0 else -1
    gamma, gamma_c = 1.0 / st.k, st.mod_c
    quarter = float(_landen.constants(gamma_c, st.mod_c_lo).quarter)
    return Motion(st.regime, theta0, dtheta0, omega0, c1, gamma, gamma_c, math.inf,
                  rotation_phase(st, sgn, quarter), sgn, 2.0 * quarter / st.rate, st)
