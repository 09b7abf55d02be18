"""Arrays of states: broadcasting, accuracy in one array call, exactness at t = 0,
values independent of their batch, no floating-point exceptions, memory.

References: mpmath through the note's closed forms (test_motion.reference, at 40 digits);
single-state calls for the independence; tracemalloc for the memory.
"""

import math
import tracemalloc

import numpy as np
import pytest

import elliptic_pendulum as ep
from elliptic_pendulum import Regime
from tests.mpref import motion as reference


def random_states(n, rng, near_fraction=0.05):
    """States over several turns and both directions; a fraction within 1e-12 of (28)."""
    theta0 = rng.uniform(-7.0, 7.0, n)
    omega0 = rng.choice([1.0, 0.7, 2.5], n)
    dtheta0 = rng.uniform(-4.0, 4.0, n)
    near = rng.random(n) < near_fraction
    r = np.mod(theta0 + np.pi, 2 * np.pi) - np.pi
    edge = rng.choice([-1.0, 1.0], n) * 2 * omega0 * np.cos(r / 2)
    dtheta0[near] = (edge * (1 + rng.uniform(-1e-12, 1e-12, n)))[near]
    return theta0, dtheta0, omega0


@pytest.mark.slow  # 10,000 mpmath references at 40 digits: some 15 s
def test_ten_thousand_states_in_one_call_match_mpmath():
    # 10,000 random states (5% within 1e-12 of the separatrix) in ONE call, each at its own
    # time. theta to 1e-13 relative wherever |theta| >= 1e-3 of the motion's size (the
    # promise of Motion.theta), and to 1e-14 of the size everywhere; theta' to 1e-14 of its
    # maximum.
    rng = np.random.default_rng(20261201)
    theta0, dtheta0, omega0 = random_states(10_000, rng)
    t = rng.uniform(-20.0, 20.0, theta0.size)
    theta, dtheta = ep.solve(theta0, dtheta0, omega0).state(t)
    refs = [reference(*state, [time]) for *state, time in zip(theta0, dtheta0, omega0, t,
                                                                strict=True)]
    th_ref = np.array([r[0][0] for r in refs])
    dth_ref = np.array([r[1][0] for r in refs])
    size = np.array([r[2] for r in refs])
    regimes = ep.solve(theta0, dtheta0, omega0).regime
    assert {Regime.LIBRATION, Regime.ROTATION} <= set(regimes)
    error = np.abs(theta - th_ref)
    large = np.abs(th_ref) >= 1e-3 * size
    assert np.max(error[large] / np.abs(th_ref[large])) <= 1e-13
    assert np.max(error / np.maximum(size, np.abs(th_ref))) <= 1e-14
    r = np.mod(theta0 + np.pi, 2 * np.pi) - np.pi
    top_speed = 2 * omega0 * np.hypot(np.sin(r / 2), dtheta0 / (2 * omega0))
    assert np.max(np.abs(dtheta - dth_ref) / top_speed) <= 1e-14


def test_broadcasting_one_row_per_state():
    th0 = np.array([0.5, 2.0, -3.0])
    v0 = np.array([0.0, 1.0, 2.5])
    t = np.linspace(0.0, 5.0, 7)
    m = ep.solve(th0[:, None], v0[:, None])
    assert m.shape == (3, 1) and len(m) == 3
    grid = m.theta(t[None, :])
    assert grid.shape == (3, 7)
    for i in range(3):
        np.testing.assert_array_equal(grid[i], ep.solve(th0[i], v0[i]).theta(t))
    # omega0 broadcasts too, and a scalar time gives one value per state
    m = ep.solve(0.3, 0.0, np.array([1.0, 2.0]))
    assert m.theta(1.0).shape == (2,)
    assert m.theta(1.0)[1] == ep.solve(0.3, 0.0, 2.0).theta(1.0)


def test_indexing_length_iteration_and_state():
    m = ep.solve([0.5, 0.0, math.pi, 0.0], [0.0, 2.0, 0.0, 3.0])
    assert len(m) == 4
    assert [x.regime.value for x in m] == ["II", "III", "III", "IV"]
    single = m[3]
    assert single.shape == () and type(single.period) is float
    assert type(single.theta(0.5)) is float
    one = ep.solve(0.0, 3.0)
    assert single.period == one.period and single.theta(1.7) == one.theta(1.7)
    assert m[1:3].shape == (2,)
    t = np.array([0.0, 1.0, 2.5])
    theta, dtheta = m[0].state(t)
    np.testing.assert_array_equal(theta, m[0].theta(t))
    np.testing.assert_array_equal(dtheta, m[0].dtheta(t))
    with pytest.raises(TypeError):
        len(one)
    with pytest.raises(TypeError):
        one[0]
    assert isinstance(m.period, np.ndarray) and m.period.shape == (4,)
    np.testing.assert_array_equal(m.regime == Regime.SEPARATRIX, [False, True, True, False])


def test_value_does_not_depend_on_the_batch():
    # bitwise, a state alone and beside 999 others (with moduli that need many more
    # AGM steps) gives the same theta; and sn of one modulus alone and in an array.
    rng = np.random.default_rng(11)
    theta0, dtheta0, omega0 = random_states(1000, rng, near_fraction=0.2)
    t = rng.uniform(-50.0, 50.0, theta0.size)
    together = ep.solve(theta0, dtheta0, omega0).theta(t)
    alone = np.array([ep.solve(*state).theta(time) for *state, time in
                      zip(theta0, dtheta0, omega0, t, strict=True)])
    np.testing.assert_array_equal(together, alone)
    u = rng.uniform(-100.0, 100.0, 500)
    kc = np.concatenate([[0.8], 10.0 ** rng.uniform(-15, 0, 499)])
    batch = ep.sn(u, 1.0, kc=kc)
    assert batch[0] == ep.sn(u[0], 1.0, kc=0.8)
    np.testing.assert_array_equal(batch[::37], [ep.sn(a, 1.0, kc=b) for a, b in
                                                zip(u[::37], kc[::37], strict=True)])


@pytest.mark.parametrize(("theta0", "dtheta0"), [
    (-1.9387685504279077, 4.350670292531149e-12),  # theta'(0) was once off by 1.5e-4
    (1e-12, -0.5),                                  # theta(0) was once off by 2.7e-5
    (2.5, 0.0), (3.1, 1e-9), (0.3, 1.9), (-1.0, -2.7), (math.pi - 1e-9, 1e-7)])
def test_initial_state_comes_back_exactly(theta0, dtheta0):
    # theta(0) and theta'(0) to 4 ulp of themselves (not of the motion's size).
    m = ep.solve(theta0, dtheta0)
    assert abs(m.theta(0.0) - theta0) <= 4 * math.ulp(theta0)
    assert abs(m.dtheta(0.0) - dtheta0) <= 4 * math.ulp(dtheta0) + 1e-15 * (dtheta0 == 0)


def test_initial_states_come_back_in_one_array_call():
    rng = np.random.default_rng(5)
    theta0, dtheta0, omega0 = random_states(20_000, rng, near_fraction=0.1)
    turning = rng.random(theta0.size) < 0.1
    dtheta0[turning] = 0.0
    theta, dtheta = ep.solve(theta0, dtheta0, omega0).state(0.0)
    ulp = np.spacing(np.abs(theta0))
    assert np.all(np.abs(theta - theta0) <= 4 * ulp)
    moving = dtheta0 != 0
    assert np.all(np.abs(dtheta - dtheta0)[moving] <= 4 * np.spacing(np.abs(dtheta0[moving])))
    assert np.all(np.abs(dtheta[~moving]) <= 1e-15 * omega0[~moving])


def test_clean_under_numpy_raise():
    # no floating-point exception escapes, whatever the caller's np.seterr.
    with np.errstate(all="raise"):
        states = ([0.0, math.pi, 3 * math.pi, 1e-300, 1e50, 2.0, 0.0, math.pi, 1.0, 0.1],
                  [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 2.0, 1e-160, 1.0, 1e-200],
                  [1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1e-302, 1.0])
        m = ep.solve(*states)
        t = np.array([-1e6, -1.0, 0.0, 1e-300, 3.0, 1e4])
        theta, dtheta = m[:, None].state(t[None, :])
        assert np.all(np.isfinite(theta)) and np.all(np.isfinite(dtheta))
        for one in m:
            one.theta(2.0), one.period, one.energy_constant
        for k in (0.0, 0.5, 1.0):
            ep.jacobi(t, k), ep.am(t[1:5], k), ep.complete_integral(k)
        ep.jacobi(t, 1.0, kc=1e-300), ep.jacobi(t, 1.0, kc=0.0)
        ep.period_ratio(np.array([0.0, 1.0, math.pi - 1e-15]))


def test_no_silent_infinity():
    # solve(1, 1e200) once gave energy_constant = inf; now a ValueError names dtheta0.
    with pytest.raises(ValueError, match="dtheta0"):
        ep.solve(1.0, 1e200)
    m = ep.solve(1.0, 1.0, 1e-302)       # a free rotation: c1 is fine, beta is beyond doubles
    assert math.isfinite(m.energy_constant)
    with pytest.raises(ValueError, match="omega0"):
        _ = m.beta
    assert all(math.isfinite(x) for x in (m.period, m.phase, m.modulus))


def test_memory_of_theta_stays_near_its_result():
    # theta(t) peaks at <= 4 times its result (chunked evaluation).
    m = ep.solve(2.0, 0.3)
    t = np.linspace(0.0, 1e3, 2_000_000)
    tracemalloc.start()
    try:
        result = m.theta(t)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak <= 4 * result.nbytes, peak / result.nbytes


def test_repr_and_html_summary():
    # A readable repr (one state, or the regimes of an array) and a table
    # for Jupyter with the regime, c1, the amplitude (or gamma) and the period.
    swing = ep.solve(0.5)
    assert repr(swing).startswith("Motion(regime='II', theta0=0.5")
    assert f"period={swing.period:.10g}" in repr(swing)
    html = swing._repr_html_()
    for word in ("II (libration)", "c1", "amplitude", "period", f"{swing.period:.10g}"):
        assert word in html
    turning = ep.solve(0.0, 3.0)._repr_html_()
    assert "gamma" in turning and "amplitude" not in turning
    assert "time per revolution" in turning
    many = ep.solve([0.5, 0.0, 0.1], [0.0, 3.0, 0.0])
    assert repr(many) == "Motion(shape=(3,), regimes={'II': 2, 'IV': 1})"
    assert "regime II (libration)</th><td style='text-align:left'>2" in many._repr_html_()


def test_scalar_calls_give_the_array_bits():
    # The fast path of one number (the engine's <name>_float twins): one state at one time,
    # and sn, cn, dn, am of one u and k, give the very bits of the array call.
    rng = np.random.default_rng(17)
    theta0, dtheta0, omega0 = random_states(300, rng, near_fraction=0.2)
    t = rng.uniform(-40.0, 40.0, theta0.size)
    t[::7] = 0.0
    m = ep.solve(theta0, dtheta0, omega0)
    theta, dtheta = m.state(t)
    for i in range(theta0.size):
        one = m[i]
        assert one.theta(float(t[i])) == theta[i]
        assert one.dtheta(float(t[i])) == dtheta[i]
        assert one.state(float(t[i])) == (theta[i], dtheta[i])
    u, k = rng.uniform(-200.0, 200.0, 2000), rng.uniform(0.0, 1.0, 2000)
    k[::5] = 1 - 10.0 ** rng.uniform(-16, -1, 400)
    for f in (ep.sn, ep.cn, ep.dn, ep.am):
        np.testing.assert_array_equal(f(u, k), [f(float(a), float(b)) for a, b in zip(u, k,
                                                                                    strict=True)])


def test_scalar_solve_gives_the_array_bits():
    # solve() of one state takes a fast path on Python floats; every public value and the
    # motion itself must be the array call's, bit for bit (mutant: math.sin for the dd sine).
    rng = np.random.default_rng(23)
    theta0, dtheta0, omega0 = random_states(500, rng, near_fraction=0.2)
    theta0[::9] = rng.uniform(-1e5, 1e5, theta0[::9].size)
    dtheta0[::13] = 0.0
    many = ep.solve(theta0, dtheta0, omega0)
    names = ("regime", "energy_constant", "modulus", "complementary_modulus", "amplitude",
             "phase", "direction", "period")
    for i in range(theta0.size):
        one, row = ep.solve(float(theta0[i]), float(dtheta0[i]), float(omega0[i])), many[i]
        assert [getattr(one, n) for n in names] == [getattr(row, n) for n in names]
        assert one.state(1.3) == row.state(1.3)
