r"""Classify an initial state into the note's regimes I-IV and parametrize it.

The energy constant of (9) is :math:`c_1 = \theta'^2 - 2\omega_0^2\cos\theta`.
The note splits on it: I (c1 = -2 w0^2, rest), II (``|c1| < 2 w0^2``, swinging),
III (c1 = 2 w0^2, the separatrix) and IV (c1 > 2 w0^2, rotating).

Nothing here goes through c1, because c1 -> arccos -> sin loses every digit
at small amplitudes and near the top. With s = sin(theta/2), c = cos(theta/2)
and w = theta' / (2 omega0), the squared modulus and its complement are

.. math:: k^2 = s^2 + w^2, \qquad k_c^2 = 1 - k^2 = (c - |w|)(c + |w|),

each free of cancellation (DESIGN.md, "Never lose the energy"). They are formed
once per initial state with mpmath at 50 digits, so that even the rounding of
cos(theta/2) and of theta'/(2 omega0) to double does not reach kc. Regime II has
modulus alpha = k (14); regime IV has gamma = 1/k, and beta = 2 k^2 - 1 (29).

The double nearest pi (``math.pi``) is taken to mean pi itself, so that
``solve(math.pi)`` is the pendulum balanced upside down; every other angle is
taken exactly as the double it is, measured against the true pi.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass

import mpmath
from scipy import special

from ._landen import _PI_HI

__all__ = ["Regime", "State", "classify"]

_TWO_PI_HI = 6.283185307179586
_TWO_PI_LO = 2.4492935982947064e-16


class Regime(enum.Enum):
    """The note's four kinds of motion; ``.value`` is the note's numeral."""

    REST = "I"
    LIBRATION = "II"
    SEPARATRIX = "III"
    ROTATION = "IV"


@dataclass(frozen=True)
class State:
    """An initial state reduced and parametrized (see :func:`classify`)."""

    regime: Regime
    winding: float      # theta0 = 2 pi winding + r with r in [-pi, pi]
    r: float            # rounded to double
    s: float            # sin(r/2)
    c: float            # cos(r/2) >= 0
    w: float            # theta0' / (2 omega0)
    k: float            # sqrt(s^2 + w^2): alpha in II; 1/gamma in IV
    k_lo: float         # its low part (k + k_lo to about 1e-32)
    kc: float           # sqrt(|1 - k^2|) = sqrt(|c - |w||) sqrt(c + |w|)
    mod_c: float        # complement of the elliptic modulus: alpha_c (II), gamma_c (IV)
    mod_c_lo: float     # its low part: mod_c + mod_c_lo to about 1e-32


def _reduce(theta: float) -> tuple[float, float]:
    """Winding number m and r = theta - 2 pi m (as a double), |r| <= pi."""
    m = float(round(theta / _TWO_PI_HI))
    # Cody-Waite: m * 2pi_hi is exact for the |m| < 2**26 a pendulum ever needs.
    return m, (theta - m * _TWO_PI_HI) - m * _TWO_PI_LO


def classify(theta0: float, dtheta0: float, omega0: float) -> State:
    """Reduce (theta0, theta0') and find its regime without cancellation.

    k^2 and kc^2 are formed once, at 50 digits, from the exact doubles of the
    initial state: near the separatrix kc^2 = c^2 - w^2 is a difference of
    nearly equal numbers, and rounding c or w to double first would be
    multiplied by 1 / kc^2 there. The complement of the elliptic modulus is
    kept as a double-double (kc_hi, kc_lo), which fixes K, hence the period,
    to about 1e-32: the phase then stays right over thousands of periods.
    """
    m, r = _reduce(theta0)
    with mpmath.workdps(50):
        w = mpmath.mpf(dtheta0) / (2 * mpmath.mpf(omega0))
        # The double nearest pi (and -pi) means pi: exactly upside down. Decided on
        # theta0 itself: the reduced r of a neighbouring double can round to pi too.
        if abs(theta0) == _PI_HI:
            r = math.copysign(_PI_HI, theta0)
            s, c = mpmath.mpf(math.copysign(1.0, r)), mpmath.mpf(0)
        else:
            half = (mpmath.mpf(theta0) - 2 * mpmath.pi * m) / 2
            s, c = mpmath.sin(half), mpmath.cos(half)
        k2, kc2 = s * s + w * w, (c - abs(w)) * (c + abs(w))
        k, kc = mpmath.sqrt(k2), mpmath.sqrt(abs(kc2))
        k_hi = float(k)
        # The elliptic modulus: alpha = k in II (14); gamma = 1/k in IV.
        mod_c = kc if kc2 > 0 else kc / k
        if s == 0 and w == 0:
            regime = Regime.REST
        elif kc2 == 0:
            regime = Regime.SEPARATRIX
        elif kc2 > 0:
            regime = Regime.LIBRATION
        else:
            regime = Regime.ROTATION
        mod_c_hi = float(mod_c)
        mod_c_lo = float(mod_c - mod_c_hi)
        return State(regime, m, r, float(s), float(c), float(w), k_hi, float(k - k_hi),
                     float(kc), mod_c_hi, mod_c_lo)


def libration_phase(st: State, quarter: float) -> float:
    """c2 with am(c2, alpha) = atan2(s, w), i.e. alpha sn(c2) = s and alpha cn(c2) = w.

    F(phi) = sin(phi) R_F(cos^2 phi, 1 - alpha^2 sin^2 phi, 1) (DLMF 19.25.5),
    where alpha sin(phi) = s and 1 - alpha^2 sin^2 phi = c^2: no cancellation.
    """
    if st.w == 0.0:  # a turning point: F(pi/2) = K, even where c*c underflows
        f = quarter
    else:
        f = abs(st.s) / st.k * float(special.elliprf((st.w / st.k) ** 2, st.c * st.c, 1.0))
    sign = -1.0 if st.s < 0 else 1.0
    return sign * f if st.w >= 0 else sign * (2.0 * quarter - f)


def rotation_phase(st: State, direction: float, quarter: float) -> float:
    """c4 with am(c4, gamma) = direction * r / 2 (theta = direction * 2 am).

    With gamma = 1/k: 1 - gamma^2 sin^2(r/2) = w^2 / k^2, again no cancellation.
    """
    if st.c == 0.0:  # passing the top: F(+-pi/2) = +-K, even where w*w underflows
        return direction * st.s * quarter
    return direction * st.s * float(special.elliprf(st.c * st.c, (st.w / st.k) ** 2, 1.0))
