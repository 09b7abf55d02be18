"""Theta beside its zero crossings against mpmath, relative to theta itself.

Found by the adversarial search (test_extreme_search, HYPOTHESIS_PROFILE=explore): the state
(theta0, dtheta0, omega0) = (-0.1, -1.0, 1.0) at t = -0.0995 gave theta 501 ulp of itself off,
beside the zero crossing at t = -0.09967. There the elliptic argument u = omega0 t + c2
cancels to a small v, and c2 (whole quarter periods plus a remainder) had its remainder only
to a double: its rounding, a few 1e-17, is a relative 1e-17 / |v| of theta, 1e9 ulp at
|t - t_c| = 1e-9 |t_c|. The remainder is now carried in double-double where theta is
evaluated again near 0 (redo.direct, _engine/remainder.py).

Every expectation comes from outside the library: :class:`tests.mpref.Exact`, the note's (25)
and (46) in mpmath at 40 digits (more where the state needs them) from the exact doubles of
the state and of t, each value rounded once; and the crossing times t_c themselves, found in
mpmath from the state (u = 2 n K in II, am(u) = n pi with theta's winding 0 in IV). The times
are doubles near t_c, within the band where flow evaluates theta again (|theta| below 1/64 of
the size): there theta is held to 8 ulp of itself, the bound test_tiny_states holds theta to
away from crossings (measured here: 3 ulp; before the fix up to 1.4e9).
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

import elliptic_pendulum as ep
from tests.mpref import Exact
from tests.strict import quietly

# (theta0, dtheta0, omega0): II near the bottom on the upswing and the downswing (q = 0 and
# q = +-2), II nearer a turning point (q = +-1), a large swing, a small one, a faster omega0;
# beside the separatrix; IV from near the bottom.
STATES = [
    pytest.param(-0.1, -1.0, 1.0, id="found-by-the-search"),
    pytest.param(0.3, 0.5, 1.0, id="II-upswing"),
    pytest.param(-0.7, 0.2, 1.0, id="II-near-the-turn"),
    pytest.param(1.2, -0.4, 2.0, id="II-downswing-near-the-turn"),
    pytest.param(2.5, 0.3, 1.0, id="II-large-swing"),
    pytest.param(0.05, 0.01, 3.0, id="II-small-swing"),
    # 1e-9 and 1e-15 from the separatrix: both arguments of R_F small, its slowest case
    pytest.param(0.5, 2 * math.cos(0.25) * (1 - 1e-9), 1.0, id="II-beside-the-separatrix"),
    pytest.param(-1.0, 2 * math.cos(0.5) * (1 - 1e-15), 1.0, id="II-1e-15-from-the-separatrix"),
    pytest.param(0.5, -2 * math.cos(0.25) * (1 + 1e-9), 1.0, id="IV-beside-the-separatrix"),
    pytest.param(-0.4, 2.5, 1.0, id="IV-forward"),
    pytest.param(0.6, -3.0, 1.0, id="IV-backward"),
    # IV back to 0 from more than a quarter period away: theta = N pi + 2 am cancels N pi
    # itself (N = +-1), which flow's test for the redo did not see (1e9 ulp at 1e-9 of t_c)
    pytest.param(2.0, 1.5, 0.5, id="IV-from-a-quarter-period-away"),
    pytest.param(3.0, 0.2, 1.0, id="IV-from-near-the-top"),
]

# Relative offsets of t from t_c: inside the band of redo.direct (|theta| < size / 64).
OFFSETS = [1e-3, -1e-3, 3e-5, -1e-7, 1e-9, -1e-12]


def crossing(ex, n=0):
    """The n-th time after the one nearest t = 0 at which theta is 0 (mpmath, 50 digits)."""
    with mpmath.workdps(50):
        if ex.regime == "II":  # theta = 2 asin(k sn u): 0 where u = 2 m K
            big_k = mpmath.ellipk(ex.k2)
            u0 = mpmath.ellipf(mpmath.atan2(ex.s, ex.w), ex.k2)
            rate = mpmath.mpf(ex.omega0)
        else:  # theta = 2 d am(u, 1/k) with no winding: 0 where u = 0
            assert ex.winding == 0
            g2 = 1 / ex.k2
            big_k = mpmath.ellipk(g2)
            d = 1 if ex.w > 0 else -1
            u0 = mpmath.ellipf(d * mpmath.atan2(ex.s, ex.c), g2)
            rate = mpmath.sqrt(ex.k2) * ex.omega0
            assert n == 0  # the later zeros of theta - 2 pi m are not crossings of 0
        m = mpmath.nint(u0 / (2 * big_k)) - n
        return (2 * m * big_k - u0) / rate


def ulps(a, b):
    return abs(float(a) - float(b)) / math.ulp(abs(float(b)))


def check(theta0, dtheta0, omega0, ts):
    ex = Exact(theta0, dtheta0, omega0, dps=40)
    expected = ex.at(ts)[0]
    m = quietly(ep.solve, theta0, dtheta0, omega0)
    theta = quietly(m.theta, np.array(ts))
    for t, a, b in zip(ts, theta, expected, strict=True):
        assert abs(b) < ex.size / 64  # the band of redo.direct, where this bound is promised
        assert ulps(a, b) <= 8, (theta0, dtheta0, omega0, t, float(a), float(b), ulps(a, b))
        # the scalar path: the same bits
        assert np.float64(quietly(m.theta, float(t))).tobytes() == a.tobytes(), (t, a)


def test_the_state_found_by_the_search():
    check(-0.1, -1.0, 1.0, [-0.0995])


@pytest.mark.parametrize(("theta0", "dtheta0", "omega0"), STATES)
def test_theta_beside_the_crossing_nearest_t0(theta0, dtheta0, omega0):
    ex = Exact(theta0, dtheta0, omega0, dps=40)
    t_c = crossing(ex)
    check(theta0, dtheta0, omega0, [float(t_c * (1 + eps)) for eps in OFFSETS])


@pytest.mark.parametrize(("theta0", "dtheta0", "omega0"),
                         [p for p in STATES if p.id.startswith(("II", "found"))
                          and "separatrix" not in p.id])
def test_theta_beside_crossings_many_periods_away(theta0, dtheta0, omega0):
    # The remainder's error would be the same at every crossing; the rate's (1e-32 relative)
    # grows with t and stays far below. Not beside the separatrix, where the phase drifts by
    # up to 3e-32 / |c - |w|| per quarter period (docs/design.md, "Never lose the energy").
    ex = Exact(theta0, dtheta0, omega0, dps=40)
    ts = []
    for n in (1, -7, 2001):
        t_c = crossing(ex, n)
        ts += [float(t_c + eps * ex.quarter) for eps in (1e-4, -1e-8)]
    check(theta0, dtheta0, omega0, ts)


def test_a_batch_gives_each_state_its_bits_alone():
    # One array call on every state at its own times beside its crossing: each element has
    # the bits of the same state alone (the low part of the remainder is made once per state,
    # on floats for a few states and on arrays for more).
    rows = [p.values for p in STATES]
    times = [[float(crossing(Exact(*r, dps=20)) * (1 + eps)) for eps in OFFSETS] for r in rows]
    th0, v0, w0 = (np.array(column)[:, None] for column in zip(*rows, strict=True))
    many = quietly(ep.solve, th0, v0, w0)
    theta = quietly(many.theta, np.array(times))
    for i, row in enumerate(rows):
        alone = quietly(ep.solve, *(np.float64(x) for x in row))
        np.testing.assert_array_equal(quietly(alone.theta, np.array(times[i])), theta[i])


def test_many_chunks_give_the_bits_of_one_time_each():
    # Over 100,000 times (flow evaluates them in chunks and redoes the points near theta = 0
    # after all chunks, with the remainder's low part made once): the points beside the
    # crossings have the bits of the scalar path, and the accuracy above.
    theta0, dtheta0, omega0 = -0.1, -1.0, 1.0
    ex = Exact(theta0, dtheta0, omega0, dps=40)
    near = [float(crossing(ex, n) * (1 + eps)) for n in (0, 3) for eps in OFFSETS]
    t = np.linspace(-5.0, 40.0, 100_000)
    t[::9000] = near + [0.0] * (len(t[::9000]) - len(near))
    m = quietly(ep.solve, theta0, dtheta0, omega0)
    theta = quietly(m.theta, t)
    for i in range(0, len(t), 9000)[:len(near)]:
        assert np.float64(quietly(m.theta, float(t[i]))).tobytes() == theta[i].tobytes()
    check(theta0, dtheta0, omega0, near)
    # and a batch of states, each at many times: every element as the state alone
    rows = [p.values for p in STATES[:6]]
    th0, v0, w0 = (np.array(column)[:, None] for column in zip(*rows, strict=True))
    crossings = [crossing(Exact(*r, dps=20)) for r in rows]
    times = np.array([[float(t_c * (1 + eps)) for eps in OFFSETS * 1000] for t_c in crossings])
    many = quietly(quietly(ep.solve, th0, v0, w0).theta, times)
    for i, row in enumerate(rows):
        alone = quietly(ep.solve, *row)
        np.testing.assert_array_equal(
            [quietly(alone.theta, float(x)) for x in times[i, :len(OFFSETS)]],
            many[i, :len(OFFSETS)])
