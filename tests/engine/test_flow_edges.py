"""Edge cases of the flow (theta(t), theta'(t)) found by an adversarial run against mpmath.

Every expectation comes from outside the library: the initial state itself, closed forms
evaluated by mpmath at 50 digits or more in a private context (never ``mpmath.mp``), or
exact algebra.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

import elliptic_pendulum as ep


def _ctx(dps=60):
    ctx = mpmath.mp.clone()
    ctx.dps = dps
    return ctx


def test_small_states_come_back_at_t0_and_circular_dn_is_one():
    # Near the bottom (|theta0| ~ 1e-9, |theta0'| ~ 1e-7) the modulus is so small that the
    # AGM of kc had stopped before its first step, and cn = dn = kc at v = 0: theta(0) came
    # back up to 8 ulp from theta0 (the promise is 4). The reference is the initial state.
    rng = np.random.default_rng(5)
    n = 20_000
    theta0 = rng.uniform(-1, 1, n) * 10.0 ** rng.uniform(-10, -8, n)
    dtheta0 = rng.uniform(-1, 1, n) * 10.0 ** rng.uniform(-8, -6, n)
    omega0 = 10.0 ** rng.uniform(-1, 1, n)
    theta, dtheta = ep.solve(theta0, dtheta0, omega0).state(0.0)
    assert np.max(np.abs(theta - theta0) / np.spacing(np.abs(theta0))) <= 1
    assert np.max(np.abs(dtheta - dtheta0) / np.spacing(np.abs(dtheta0))) <= 1
    for i in range(0, n, 400):  # the scalar path, the same bits
        one = ep.solve(float(theta0[i]), float(dtheta0[i]), float(omega0[i]))
        assert one.state(0.0) == (theta[i], dtheta[i])
    # cn(0) = dn(0) = 1 exactly (DLMF 22.5.1), for a modulus whose kc is 4 ulp below 1.
    for k in (3e-8, -2e-8, 1e-9):
        assert ep.cn(0.0, k) == ep.dn(0.0, k) == 1.0
        assert ep.cn(np.zeros(2), k).tolist() == ep.dn(np.zeros(2), k).tolist() == [1.0, 1.0]
    # and dn elsewhere to 2 ulp of 1, its size (it was 2.5: the factor kc).
    ctx = _ctx(50)
    u = rng.uniform(-3, 3, 200)
    k = 10.0 ** rng.uniform(-9, -7.5, 200)
    ref = np.array([float(ctx.ellipfun("dn", ctx.mpf(a), m=ctx.mpf(b) ** 2))
                    for a, b in zip(u, k, strict=True)])
    assert np.max(np.abs(ep.dn(u, k) - ref)) <= 2.0 ** -51


def _top_reference(theta0, dtheta0, omega0, times):
    """theta, theta' of the push dtheta0 from exactly n pi (n odd, the double theta0), by
    mpmath: theta = (n - 1) pi + sigma 2 am(omega0 k t + sigma K, 1/k), theta' = sigma 2 omega0
    k dn(...), k^2 = 1 + (dtheta0 / (2 omega0))^2 (the note's (46) with c4 = sigma K, since
    am(K) = pi/2). 1 - 1/k^2 is about w^2: the context carries 2 |log10 w| + 60 digits."""
    w = abs(dtheta0) / (2 * omega0)
    ctx = _ctx(int(-2 * math.log10(w)) + 60 if w < 1 else 60)
    n = round(theta0 / math.pi)
    sigma = 1 if dtheta0 > 0 else -1
    wm = ctx.mpf(dtheta0) / (2 * ctx.mpf(omega0))
    k = ctx.sqrt(1 + wm * wm)
    m = 1 / (k * k)
    quarter = ctx.ellipk(m)
    theta, dtheta = [], []
    for t in times:
        u = ctx.mpf(omega0) * k * ctx.mpf(float(t)) + sigma * quarter
        j = ctx.nint(u / (2 * quarter))          # am(v + 2 j K) = am(v) + j pi
        v = u - 2 * quarter * j
        sn, cn, dn = (ctx.ellipfun(f, v, m=m) for f in ("sn", "cn", "dn"))
        theta.append(float((n - 1) * ctx.pi + sigma * 2 * (j * ctx.pi + ctx.atan2(sn, cn))))
        dtheta.append(float(sigma * 2 * ctx.mpf(omega0) * k * dn))
    return np.array(theta), np.array(dtheta)


@pytest.mark.parametrize(("theta0", "dtheta0", "omega0"), [
    (math.pi, 1e-200, 1.0), (math.pi, 1e-160, 1.0), (-math.pi, 1e-190, 1.0),
    (math.pi, 1e-60, 1e120), (-math.pi, -1e-100, 2.5),
    # mpmath needs 560 and 660 digits for these two: about 5 s each
    pytest.param(3 * math.pi, -1e-250, 1.0, marks=pytest.mark.slow),
    pytest.param(math.pi, -1e-299, 1.0, marks=pytest.mark.slow)])
def test_tiny_push_from_the_top_goes_round_once_per_period(theta0, dtheta0, omega0):
    # A push below 1e-155 rad/s from the top: d0 * d0 underflowed in the addition theorem of
    # regime IV, so theta(P/2) came back at the top (2 pi short; 8e-5 off at a push of
    # 1e-160) and theta'(P/2) was 0 / 0 (ZeroDivisionError on the scalar path, NaN in an
    # array). Reference: the closed form (46) in mpmath (see _top_reference).
    with np.errstate(all="raise"):
        m = ep.solve(theta0, dtheta0, omega0)
        period = m.period
        times = np.concatenate([np.linspace(0.0, 1.05 * period, 15),
                                np.linspace(0.45 * period, 0.55 * period, 15)])
        theta, dtheta = m.state(times)
        scalar = [m.state(float(t)) for t in times]
    ref_theta, ref_dtheta = _top_reference(theta0, dtheta0, omega0, times)
    size = 2 * omega0 * math.hypot(1.0, dtheta0 / (2 * omega0))  # max |theta'|
    assert np.max(np.abs(theta - ref_theta)) <= 4 * math.ulp(np.max(np.abs(ref_theta)))
    assert np.max(np.abs(dtheta - ref_dtheta)) <= 4 * math.ulp(size)
    assert scalar == list(zip(theta.tolist(), dtheta.tolist(), strict=True))


@pytest.mark.parametrize("theta0", [1e-310, -3e-320, 2.5e-308])
def test_subnormal_swing_is_silent_on_the_scalar_path(theta0):
    # solve(1e-310).theta(1.0) raised FloatingPointError (underflow in arctan2) on the
    # scalar path under np.errstate(all="raise"), where the array path returns the value.
    # Reference: a swing of amplitude a <= 1e-307 is a cos(t) to a relative a^2 / 16
    # (the note's (8); sn(u, k) = sin u + O(k^2)), here rounded to the subnormal grid.
    ctx = _ctx(40)
    for t in (1.0, 2.0, -7.5):
        expected = float(ctx.mpf(theta0) * ctx.cos(t))
        with np.errstate(all="raise"):
            m = ep.solve(theta0)
            got = m.theta(t)
            assert got == float(m.theta(np.array([t]))[0])
        assert abs(got - expected) <= 2 * math.ulp(theta0)


def test_an_element_does_not_overflow_for_its_companions():
    # solve([1e-300, 0], [0, 3], [1e90, 1]).dtheta([1e-90, 1]) overflowed (FloatingPointError
    # under errstate raise): the formula of regime IV, run over the whole chunk, overflowed
    # on the tiny swing, which alone is silent. References: the tiny swing is theta0 cos(w0 t)
    # to a relative theta0^2 (the note's (8)), so theta' = -theta0 w0 sin(w0 t); the
    # rotation (0, 3) is theta' = 2 k dn(k t, 1/k), k = 3/2 (the note's (46)), by mpmath.
    ctx = _ctx(50)
    with np.errstate(all="raise"):
        got = ep.solve([1e-300, 0.0], [0.0, 3.0], [1e90, 1.0]).dtheta([1e-90, 1.0])
    expected = [float(-ctx.mpf(1e-300) * ctx.mpf(1e90) * ctx.sin(ctx.mpf(1e90) * ctx.mpf(1e-90))),
                float(3 * ctx.ellipfun("dn", ctx.mpf(1.5), m=1 / ctx.mpf(2.25)))]
    assert abs(got[0] - expected[0]) <= 2 * math.ulp(1e-300 * 1e90)
    assert abs(got[1] - expected[1]) <= 2 * math.ulp(3.0)
    # Many such companions, bit for bit as alone (and silent) under errstate raise.
    rng = np.random.default_rng(4)
    n = 60
    omega0 = np.where(rng.random(n) < 0.5, 10.0 ** rng.uniform(40, 150, n), 1.0)
    theta0 = np.where(omega0 > 1, rng.choice([-1, 1], n) * 10.0 ** rng.uniform(-305, -250, n),
                      rng.choice([0.0, math.pi, 3.0, -2.0], n))
    dtheta0 = np.where(omega0 > 1, 0.0, rng.choice([3.0, -2.5, 1e-200, 2.0, 0.5], n))
    t = rng.uniform(-3, 3, n) / omega0
    with np.errstate(all="raise"):
        together = ep.solve(theta0, dtheta0, omega0).state(t)
        alone = [ep.solve(*x).state(np.array(y)) for *x, y in
                 zip(theta0.tolist(), dtheta0.tolist(), omega0.tolist(), t.tolist(), strict=True)]
    for i, (a, b) in enumerate(alone):
        assert together[0][i].tobytes() == np.float64(a).tobytes()
        assert together[1][i].tobytes() == np.float64(b).tobytes()


@pytest.mark.parametrize("n", [2, 4096, 4097, 8192, 8193])  # one chunk of states, and two
def test_a_motion_does_not_alias_its_callers_arrays(n):
    # Up to 4096 states a Motion kept views of the caller's arrays: writing into them after
    # solve changed m.theta0 and m.theta(1.0) (not the regimes). Reference: the same states
    # solved from private copies; and the stored arrays refuse writes.
    rng = np.random.default_rng(n)
    th, v, w0 = rng.uniform(-3, 3, n), rng.uniform(-3, 3, n), rng.uniform(0.5, 2, n)
    th[:2] = [0.0, math.pi]
    copies = [x.copy() for x in (th, v, w0)]
    m = ep.solve(th, v, w0)
    before = m.state(1.0)
    for x in (th, v, w0):
        x[:] = 5.0
    reference = ep.solve(*copies)
    for name in ("theta0", "dtheta0", "omega0", "energy_constant", "period", "phase"):
        np.testing.assert_array_equal(getattr(m, name), getattr(reference, name))
    np.testing.assert_array_equal(m.state(1.0), reference.state(1.0))
    np.testing.assert_array_equal(m.state(1.0), before)
    for value in (m.theta0, m.period, m.regime, m[1:].theta0, m[[0, 1]].dtheta0):
        with pytest.raises(ValueError, match="read-only"):
            value[0] = 1.0


@pytest.mark.parametrize("omega0", [1.0, 2.0, 1e-3, 1e10])
def test_separatrix_from_the_bottom_keeps_its_digits(omega0):
    # solve(0, 2 omega0) is exactly the separatrix. theta(1e-10) was off by 8e-8 relative
    # (1 - exp cancelled), theta(1e-17) was 0, theta'(372) was off by 13% and 0 for t in
    # 373..708 (exp(-2 t) underflowed, though 2 sech t is normal). Reference: the closed
    # form (28), theta = 2 gd(w0 t) = 2 atan(sinh(w0 t)), theta' = 2 w0 sech(w0 t) (it
    # solves theta'' = -w0^2 sin theta with theta(0) = 0, theta'(0) = 2 w0), by mpmath
    # at the exact product of the doubles w0 and t.
    ctx = _ctx(50)
    y = np.array([1e-300, 1e-17, 1e-12, 1e-10, 1e-5, 0.5, 3.0, 20.0, 372.0, 373.0, 400.0,
                  700.0, 708.0, -1e-12, -500.0, -1e-200])
    t = y / omega0
    with np.errstate(all="raise"):
        m = ep.solve(0.0, 2 * omega0, omega0)
        theta, dtheta = m.state(t)
    assert m.regime is ep.Regime.SEPARATRIX
    x = [ctx.mpf(omega0) * ctx.mpf(float(a)) for a in t]
    ref_theta = np.array([float(2 * ctx.atan(ctx.sinh(a))) for a in x])
    ref_dtheta = np.array([float(2 * ctx.mpf(omega0) * ctx.sech(a)) for a in x])
    assert np.all(np.abs(theta - ref_theta) <= 2 * np.spacing(np.abs(ref_theta)))
    assert np.all(np.abs(dtheta - ref_dtheta) <= 4 * np.spacing(np.abs(ref_dtheta)))


@pytest.mark.parametrize("m", [1, -1, 2, 3, -7, 100001, 160000, 10**6, -3 * 10**9])
def test_nearest_double_to_an_even_multiple_of_pi_is_the_bottom(m):
    # 2 * math.pi was taken as the double it is, 2.4e-16 short of 2 pi: a swing (regime II)
    # of that amplitude. Like the doubles nearest odd multiples (the top), it now means the
    # multiple: at rest at the bottom, regime I, c1 = -2 w0^2, theta(t) = theta0. Reference:
    # the double nearest 2 pi m from mpmath, and for a push w the closed form (25) about the
    # bottom, theta = 2 pi m + 2 asin(k sn(w0 t, k)), k = theta0' / (2 w0) (c2 = 0).
    ctx = _ctx(60)
    theta0 = float(2 * ctx.pi * m)
    omega0 = 1.5
    for one in (ep.solve(theta0, 0.0, omega0), ep.solve(np.array([theta0]), 0.0, omega0)[0]):
        assert one.regime is ep.Regime.REST
        assert one.energy_constant == -2 * omega0 ** 2
        assert one.theta(7.25) == theta0 and one.dtheta(7.25) == 0.0
        assert one.period == 2 * math.pi / omega0
    if m == 1:
        assert math.radians(360) == theta0 and ep.solve(math.radians(360)).regime is ep.Regime.REST
    push = 0.3
    k = ctx.mpf(push) / (2 * ctx.mpf(omega0))
    times = np.array([0.0, 0.4, 1.7, 5.0, -3.3])
    expected = np.array([float(2 * ctx.pi * m + 2 * ctx.asin(
        k * ctx.ellipfun("sn", ctx.mpf(omega0) * ctx.mpf(t), m=k * k))) for t in times])
    swing = ep.solve(theta0, push, omega0)
    assert swing.regime is ep.Regime.LIBRATION
    got = swing.theta(times)
    assert np.all(np.abs(got - expected) <= 4 * math.ulp(abs(theta0) + 0.1))
    assert [swing.theta(float(t)) for t in times] == got.tolist()
    assert ep.solve([theta0], push, omega0).theta(times[:, None])[:, 0].tolist() == got.tolist()


def test_sign_of_zero_is_the_same_on_both_paths():
    # solve(1e-300, 0, 4.909e-91).dtheta(6.11e89) was -0.0 on the scalar path and +0.0 in an
    # array (the true value, -theta0 w0 sin(w0 t) ~ -1.4e-391, rounds to -0.0); and
    # solve(-0.0).theta(t), which is theta0 = -0.0, came back +0.0 from an array call.
    # Reference for the first: the small-angle closed form (its sign is that of -sin(0.3)).
    m = ep.solve(1e-300, 0.0, 4.909e-91)
    assert math.copysign(1.0, m.dtheta(6.11e89)) == -1.0
    assert math.copysign(1.0, float(m.dtheta(np.array([6.11e89]))[0])) == -1.0
    assert math.copysign(1.0, float(ep.solve(-0.0).theta(np.array([1.0]))[0])) == -1.0
    rng = np.random.default_rng(3)
    n = 400
    theta0 = rng.choice([-1, 1], n) * 10.0 ** rng.uniform(-300, 0.4, n)
    theta0[::5] = rng.choice([0.0, -0.0, 2 * math.pi, -4 * math.pi], theta0[::5].size)
    dtheta0 = rng.choice([-1, 1], n) * 10.0 ** rng.uniform(-300, 0.5, n)
    dtheta0[::3] = rng.choice([0.0, -0.0], dtheta0[::3].size)
    omega0 = 10.0 ** rng.uniform(-90, 90, n)
    # a push whose w = dtheta0 / (2 omega0) has no normal double is refused: signed zeros there
    gone = np.abs(dtheta0 / (2 * omega0)) < 2.0**-1022
    dtheta0[gone] = np.copysign(0.0, dtheta0[gone])
    t = rng.choice([-1, 1], n) * 10.0 ** rng.uniform(-300, 0, n) * 30 / (omega0 + abs(dtheta0))
    t[::7] = rng.choice([0.0, -0.0], t[::7].size)
    many = ep.solve(theta0, dtheta0, omega0).state(t)
    for i in range(n):
        one = ep.solve(float(theta0[i]), float(dtheta0[i]), float(omega0[i]))
        for batch, alone in zip(many, one.state(float(t[i])), strict=True):
            assert batch[i].tobytes() == np.float64(alone).tobytes()


def test_a_time_that_does_not_broadcast_is_named():
    # numpy's own message ("shape mismatch: objects cannot be broadcast...") named neither t
    # nor the shapes as the caller knows them.
    m = ep.solve([0.1, 0.2])
    for call in (m.theta, m.dtheta, m.state):
        with pytest.raises(ValueError, match=r"t must broadcast .* shape \(3,\) .* \(2,\)"):
            call(np.zeros(3))
    assert m.theta(np.zeros((3, 1))).shape == (3, 2)  # what does broadcast still does


def test_truth_of_a_motion():
    # bool(solve(1.0)) raised TypeError (Python fell back on len, which a single state lacks).
    # Expected: a single state is true, an array of states is true when len(m) != 0 (the
    # rule of Python's sequences).
    assert bool(ep.solve(1.0)) and bool(ep.solve(np.array(1.0)))
    assert bool(ep.solve([1.0, 2.0])) and bool(ep.solve(np.zeros((1, 0))))
    assert not ep.solve(np.zeros(0)) and not ep.solve(np.zeros((0, 3)))


def test_pendulum_quantities_broadcast_over_an_array_motion():
    # Pendulum.position, tension and energy raised TypeError ("only 0-dimensional arrays can
    # be converted to Python scalars") for a Motion of many states. Reference: (1), (4) and
    # (10) evaluated here from theta and theta' of the states taken one at a time.
    p = ep.Pendulum(length=1.5, g=9.0, mass=2.0)
    theta0 = np.array([0.3, 2.0, -1.0])
    dtheta0 = np.array([0.0, 0.5, 6.0])
    many = p.solve(theta0[:, None], dtheta0[:, None])
    t = np.array([0.0, 0.7, 3.1, 10.0])
    x, y = p.position(many, t)
    tension = p.tension(many, t)
    energy = p.energy(many)
    assert x.shape == y.shape == tension.shape == (3, 4) and energy.shape == (3, 1)
    for i in range(3):
        one = p.solve(float(theta0[i]), float(dtheta0[i]))
        theta, dtheta = one.theta(t), one.dtheta(t)
        np.testing.assert_array_equal(x[i], p.length * np.sin(theta))
        np.testing.assert_array_equal(y[i], -p.length * np.cos(theta))
        np.testing.assert_array_equal(
            tension[i], p.mass * (p.length * dtheta ** 2 + p.g * np.cos(theta)))
        c1 = float(dtheta0[i]) ** 2 - 2 * p.omega0 ** 2 * math.cos(float(theta0[i]))
        assert energy[i, 0] == pytest.approx(0.5 * p.mass * p.length ** 2 * c1, rel=1e-14)
    other = ep.solve([0.3, 0.4], 0.0, [p.omega0, 2.0])
    with pytest.raises(ValueError, match="omega0=2.0"):
        p.energy(other)


def test_a_batch_accepts_every_time_its_states_accept_alone():
    # A state at rest or on the separatrix accepts any finite t alone, but beside a swing
    # the range check of the elliptic argument (|omega0 t| < 1e290) refused the whole call.
    # References: balanced at the top, theta = pi for ever; the separatrix (0, 2) is
    # 2 gd(t) (the note's (28)), -pi and 0 for t = -1e308; the swing from (1, 0) is
    # 2 asin(k sn(t + K, k)) with k = sin(1/2) (the note's (25), c2 = K), by mpmath.
    ctx = _ctx(50)
    with np.errstate(all="raise"):
        theta, dtheta = ep.solve([math.pi, 0.0, 1.0], [0.0, 2.0, 0.0]).state(
            [1e300, -1e308, 1.0])
        alone = [ep.solve(math.pi).state(1e300), ep.solve(0.0, 2.0).state(-1e308),
                 ep.solve(1.0).state(1.0)]
    assert np.array_equal(np.array(alone).T, [theta, dtheta])
    k = ctx.sin(ctx.mpf(0.5))
    swing = float(2 * ctx.asin(k * ctx.ellipfun("sn", 1 + ctx.ellipk(k * k), m=k * k)))
    assert theta[:2].tolist() == [math.pi, -math.pi] and dtheta[:2].tolist() == [0.0, 0.0]
    assert abs(theta[2] - swing) <= 2 * math.ulp(1.0)
    with pytest.raises(ValueError, match="t is too large"):
        ep.solve([0.0, 1.0]).theta([1e300, 1e300])
