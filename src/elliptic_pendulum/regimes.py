r"""Classify an initial state into the note's regimes I-IV and parametrize it.

The energy constant of (9) is :math:`c_1 = \theta'^2 - 2\omega_0^2\cos\theta`.
The note splits on it: I (c1 = -2 w0^2, rest), II (|c1| < 2 w0^2, swinging),
III (c1 = 2 w0^2, the separatrix) and IV (c1 > 2 w0^2, rotating).

Nothing here goes through c1, because c1 -> arccos -> sin loses every digit
at small amplitudes and near the top. With s = sin(theta/2), c = cos(theta/2)
and w = theta' / (2 omega0), the squared modulus and its complement are

.. math:: k^2 = s^2 + w^2, \qquad k_c^2 = 1 - k^2 = (c - |w|)(c + |w|),

each free of cancellation (DESIGN.md, "Never lose the energy"). Regime II has
modulus alpha = k (14); regime IV has gamma = 1/k, and beta = 2 k^2 - 1 (29).

The double nearest pi (``math.pi``) is taken to mean pi itself, so that
``solve(math.pi)`` is the pendulum balanced upside down; every other angle is
taken exactly as the double it is, measured against the true pi.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass

from scipy import special

from ._landen import _PI_HI, _PI_LO

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
    r: float
    s: float            # sin(r/2)
    c: float            # cos(r/2) >= 0
    w: float            # theta0' / (2 omega0)
    k: float            # sqrt(s^2 + w^2): alpha in II; 1/gamma in IV
    kc: float           # sqrt(|1 - k^2|) = sqrt(|c - |w||) sqrt(c + |w|)


def _half_angle(theta: float) -> tuple[float, float, float]:
    """Winding number m and (sin, cos) of r/2 where theta = 2 pi m + r, |r| <= pi."""
    m = float(round(theta / _TWO_PI_HI))
    # Cody-Waite: m * 2pi_hi is exact for the |m| < 2**26 a pendulum ever needs.
    r = (theta - m * _TWO_PI_HI) - m * _TWO_PI_LO
    if abs(r) == _PI_HI:
        return m, math.copysign(1.0, r), 0.0
    # pi - |r| exactly (Sterbenz), then the true pi's tail: cos(r/2) keeps its
    # relative accuracy up to 1e-16 rad below the top.
    delta = (_PI_HI - abs(r)) + _PI_LO
    return m, math.sin(0.5 * r), math.sin(0.5 * delta)


def classify(theta0: float, dtheta0: float, omega0: float) -> State:
    """Reduce (theta0, theta0') and find its regime without cancellation."""
    m, s, c = _half_angle(theta0)
    w = dtheta0 / (2.0 * omega0)
    aw = abs(w)
    # Compare c with |w| rather than test the sign of kc^2: the product can
    # underflow to zero (w = 1e-300 at the top is a rotation, not the separatrix).
    kc = math.sqrt(abs(c - aw)) * math.sqrt(c + aw)
    k = math.hypot(s, w)
    r = 2.0 * math.atan2(s, c)
    if s == 0.0 and w == 0.0:
        regime = Regime.REST
    elif c == aw:
        regime = Regime.SEPARATRIX
    elif c > aw:
        regime = Regime.LIBRATION
    else:
        regime = Regime.ROTATION
    return State(regime, m, r, s, c, w, k, kc)


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
