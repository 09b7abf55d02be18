"""Tiny swings against mpmath: |theta0| and |theta0' / (2 omega0)| far below 2**-500.

Found by the adversarial search (test_extreme_search): theta0 = -2.2e-313 at rest with omega0 =
6.2e32 gave theta' 31780 ulp off at omega0 t = -1. Half of a subnormal theta0 (the modulus
k = sin(theta0/2) = theta0/2 to a relative 2**-1000) is a subnormal double that had lost its
last bits before omega0 multiplied it into a normal theta'. And where k^2 underflowed, the
branch of the phase at t = 0 took every tiny swing for one at its turning point: theta beside
its zero crossing came back 1e32 ulp of itself off.

Every expectation comes from outside the library: :class:`tests.mpref.Exact`, the note's (25)
and (46) evaluated by mpmath at 40 digits (more where 1 - k^2 needs them) from the exact doubles
of the state and of t, each value rounded once to a double; and the bits of the same state
given alone (for the array, scalar and batch paths). The bounds are the "few ulp" of the
docstrings: theta within 4 ulp of max(amplitude, |theta|) and 8 ulp of |theta| itself,
theta' within 4 ulp of its maximum 2 omega0 k (measured over 2700 random tiny states: 2, 3
and 2 ulp). Beside a zero crossing theta is held to 256 ulp of itself, test_extreme_search's
C_POINT: there the elliptic argument u = omega0 t + c2 cancels, and an ulp of omega0 t is
many of u (measured: 150; before the fix 1e32).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import elliptic_pendulum as ep
from tests.mpref import Exact
from tests.strict import quietly

TINY = 5e-324  # the smallest subnormal; odd multiples of it have no exact half
# omega0 stays below 9e153 (solve's documented limit: c1 = -2 omega0^2 cos(theta0) must not
# overflow); 1e-300 to 5e153 spans what is left.
STATES = [
    pytest.param(-2.2e-313, 0.0, 6.186400751363438e+32, id="found-by-the-search"),
    pytest.param(-2.2e-313, 0.0, 1e10, id="subnormal-angle-moderate-omega0"),
    pytest.param(3 * TINY, 0.0, 1e100, id="odd-subnormal-3"),
    pytest.param(-7 * TINY, 0.0, 1e150, id="odd-subnormal-minus-7"),
    pytest.param(1234567 * TINY, 0.0, 1e20, id="odd-subnormal-1234567"),
    pytest.param(-(2**40 + 1) * TINY, 0.0, 1e10, id="odd-subnormal-2**40+1"),
    pytest.param(math.ldexp(2**52 + 1, -1074), 0.0, 1e100, id="normal-angle-subnormal-half"),
    pytest.param(-3e-315, 0.0, 5e153, id="largest-omega0"),
    pytest.param(1e-310, 0.0, 1e-300, id="smallest-omega0"),
    pytest.param(0.0, 99 * TINY, 1e-200, id="subnormal-speed-from-the-bottom"),
    pytest.param(-0.0, -3e-320, 1e-300, id="subnormal-speed-minus-zero-angle"),
    pytest.param(3e-320, -5e-321, 1e-160, id="subnormal-angle-and-speed"),
    pytest.param(-7.4e-320, 2e-60, 1e120, id="subnormal-angle-tiny-push-huge-omega0"),
    pytest.param(3e-318, 2e-300, 1.0, id="subnormal-angle-tiny-push"),
    pytest.param(1e-200, 2e-170, 1.0, id="tiny-swing"),
    pytest.param(-1e-200, -2e-170, 1e-100, id="tiny-swing-negative"),
    # beside them, regimes II and IV near the bottom with a subnormal angle
    pytest.param(1e-310, 1.0, 1.0, id="II-subnormal-angle-real-swing"),
    pytest.param(3e-320, 3.0, 1.0, id="IV-subnormal-angle"),
    pytest.param(-11 * TINY, -1e150, 1e100, id="IV-subnormal-angle-huge-omega0"),
]


def _times(ex):
    """Times on the motion's own scale, and beside each zero crossing of theta near t = 0.

    In a tiny swing theta = theta0 cos(omega0 t) + (theta0' / omega0) sin(omega0 t), zero at
    omega0 t = -atan(theta0 omega0 / theta0'); 1/200 beside it flow evaluates theta again
    from the phase (redo.direct), which the wrong branch had spoiled.
    """
    scale = 1.0 / max(ex.omega0, ex.speed)
    ts = [0.0, -scale, 0.3 * scale, 2.5 * scale, 1e-20 * scale, -40.0 * scale]
    # |t| below 1e290, the documented limit of Motion.theta (omega0 = 1e-300 reaches no more)
    ts = [math.copysign(min(abs(t), 1e289), t) for t in ts]
    crossings = []
    if ex.dtheta0 != 0 and ex.regime == "II" and ex.size < 1e-150:
        zero = -float(ex.s / ex.w) / ex.omega0
        crossings = [zero * (1 + 1 / 200), zero * (1 - 1 / 300)]
    return ts, crossings


def _ulp(x):
    return math.ulp(abs(x))


@pytest.mark.parametrize(("theta0", "dtheta0", "omega0"), STATES)
def test_a_tiny_swing_matches_mpmath(theta0, dtheta0, omega0):
    ex = Exact(theta0, dtheta0, omega0, dps=40)
    ts, crossings = _times(ex)
    ts += crossings
    theta_ref, dtheta_ref = ex.at(ts)
    m = quietly(ep.solve, theta0, dtheta0, omega0)
    assert m.regime.value == ex.regime
    theta, dtheta = quietly(m.state, np.array(ts))
    for t, a, b, da, db in zip(ts, theta, theta_ref, dtheta, dtheta_ref, strict=True):
        where = (t, float(a), float(b), float(da), float(db))
        assert abs(a - b) <= 4 * _ulp(max(ex.size, abs(b))), where
        assert abs(a - b) <= (256 if t in crossings else 8) * _ulp(b), where
        assert abs(da - db) <= 4 * _ulp(ex.speed), where
        # the scalar path: the same bits
        one = quietly(m.state, float(t))
        assert np.float64(one[0]).tobytes() == a.tobytes(), where
        assert np.float64(one[1]).tobytes() == da.tobytes(), where


def test_tiny_swings_in_a_batch_keep_their_bits():
    # One array call on all the states above and a few ordinary ones, each at its own times:
    # each element has the bits of the same state alone (0-d arrays, and Python floats).
    # Ordinary companions, and far ones that the lifting by 2**600 must not overflow.
    states = [p.values for p in STATES] + [(0.5, 0.1, 1.0), (2.0, 3.0, 1.0), (math.pi, 0.0, 1.0),
                                           (6.605619048531127e+137, 2.0272093537308443e+52,
                                            3.6654390894655275e+125), (1e-300, 1e150, 1.0)]
    th0, v0, w0 = (np.array(column)[:, None] for column in zip(*states, strict=True))
    t = np.array([[0.0, -1.0, 0.3, 2.5]]) / np.maximum(w0, 2 * np.abs(v0) + w0)
    t = np.clip(t, -1e289, 1e289)  # the documented limit of t
    many = quietly(ep.solve, th0, v0, w0)
    theta, dtheta = quietly(many.state, t)
    for i, state in enumerate(states):
        alone = quietly(ep.solve, *(np.float64(x) for x in state))
        scalar = quietly(ep.solve, *(float(x) for x in state))
        for j, time in enumerate(t[i]):
            for m, at in ((alone, np.float64(time)), (scalar, float(time))):
                a_th, a_dth = quietly(m.state, at)
                assert np.float64(a_th).tobytes() == theta[i, j].tobytes(), (state, time)
                assert np.float64(a_dth).tobytes() == dtheta[i, j].tobytes(), (state, time)
