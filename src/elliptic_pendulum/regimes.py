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
    turns: float        # 2 pi winding, rounded once
    r: float            # rounded to double
    s: float            # sin(r/2)
    c: float            # cos(r/2) >= 0
    w: float            # theta0' / (2 omega0)
    k: float            # sqrt(s^2 + w^2): alpha in II; 1/gamma in IV
    s_k: float          # s / k and w / k: sin and cos of the initial elliptic amplitude
    w_k: float
    mod_c: float        # complement of the elliptic modulus: alpha_c (II), gamma_c (IV)
    mod_c_lo: float     # its low part: mod_c + mod_c_lo to about 1e-32
    rate: float         # d(argument)/dt: omega0 in II, omega0 / gamma = omega0 k in IV
    rate_lo: float      # its low part
    c1: float           # the energy constant (9), 2 omega0^2 (2 k^2 - 1)
    beta: float         # c1 / (2 omega0^2) = 2 k^2 - 1, the note's beta of (29)


def _split(x: mpmath.mpf) -> tuple[float, float]:
    hi = float(x)
    return hi, float(x - hi)


def classify(theta0: float, dtheta0: float, omega0: float) -> State:
    """Reduce (theta0, theta0') and find its regime without cancellation.

    k^2 and kc^2 are formed once, at 50 digits beyond the size of theta0, from
    the exact doubles of the initial state: near the separatrix kc^2 = c^2 - w^2
    is a difference of nearly equal numbers, and rounding c or w to double
    first would be multiplied by 1 / kc^2 there. The complement of the elliptic
    modulus and the rate of the elliptic argument are kept as double-doubles,
    which fix K, hence the period, and the phase to about 1e-32: the phase then
    stays right over thousands of periods.
    """
    digits = 50 + int(max(0.0, mpmath.mag(theta0)) * 0.302)  # 2 pi m must be exact too
    with mpmath.workdps(digits):
        w0 = mpmath.mpf(omega0)
        w = mpmath.mpf(dtheta0) / (2 * w0)
        m = mpmath.nint(mpmath.mpf(theta0) / (2 * mpmath.pi))
        # The double nearest pi (and -pi) means pi: exactly upside down. Decided on
        # theta0 itself: the reduced r of a neighbouring double can round to pi too.
        if abs(theta0) == _PI_HI:
            r = mpmath.pi if theta0 > 0 else -mpmath.pi
            s, c = mpmath.mpf(math.copysign(1.0, theta0)), mpmath.mpf(0)
        else:
            r = mpmath.mpf(theta0) - 2 * mpmath.pi * m
            s, c = mpmath.sin(r / 2), mpmath.cos(r / 2)
        k2, kc2 = s * s + w * w, (c - abs(w)) * (c + abs(w))
        k, kc = mpmath.sqrt(k2), mpmath.sqrt(abs(kc2))
        if s == 0 and w == 0:
            regime = Regime.REST
        elif kc2 == 0:
            regime = Regime.SEPARATRIX
        elif kc2 > 0:
            regime = Regime.LIBRATION
        else:
            regime = Regime.ROTATION
        # The elliptic modulus: alpha = k in II (14); gamma = 1/k in IV.
        mod_c, rate = (kc, w0) if kc2 > 0 else (kc / k, w0 * k)
        ratio = (s / k, w / k) if k != 0 else (mpmath.mpf(0), mpmath.mpf(1))
        return State(regime, float(m), float(2 * mpmath.pi * m),
                     float(r) if regime is not Regime.REST else 0.0,
                     float(s), float(c), float(w), float(k), float(ratio[0]),
                     float(ratio[1]), *_split(mod_c), *_split(rate),
                     float(2 * w0 * w0 * (2 * k2 - 1)), float(2 * k2 - 1))


def libration_phase(st: State, quarter: float) -> float:
    """c2 with am(c2, alpha) = atan2(s, w), i.e. alpha sn(c2) = s and alpha cn(c2) = w.

    F(phi) = sin(phi) R_F(cos^2 phi, 1 - alpha^2 sin^2 phi, 1) (DLMF 19.25.5),
    where alpha sin(phi) = s and 1 - alpha^2 sin^2 phi = c^2: no cancellation.
    """
    if st.w == 0.0:  # a turning point: F(pi/2) = K, even where c*c underflows
        f = quarter
    else:
        f = abs(st.s_k) * float(special.elliprf(st.w_k ** 2, st.c * st.c, 1.0))
    sign = -1.0 if st.s < 0 else 1.0
    return sign * f if st.w >= 0 else sign * (2.0 * quarter - f)


def rotation_phase(st: State, direction: float, quarter: float) -> float:
    """c4 with am(c4, gamma) = direction * r / 2 (theta = direction * 2 am).

    With gamma = 1/k: 1 - gamma^2 sin^2(r/2) = w^2 / k^2, again no cancellation.
    """
    if st.c == 0.0:  # passing the top: F(+-pi/2) = +-K, even where w*w underflows
        return direction * st.s * quarter
    return direction * st.s * float(special.elliprf(st.c * st.c, st.w_k ** 2, 1.0))
