"""Properties of solve() over random initial states (hypothesis).

theta0 in [-10, 10], theta0' in [-5, 5], omega0 in [0.1, 10], t in [-20, 20]. Each property is a
statement of the note: the equation of motion (3) theta'' = -w0^2 sin theta, the first integral (9)
c1 = theta'^2 - 2 w0^2 cos theta, the period (26) and the turn of (46), and the symmetries of
(3) (time reversal, time shift). The regimes meet at the separatrix (28).
"""

import math

import mpmath
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import elliptic_pendulum as ep
from elliptic_pendulum import Regime

# Angles far out and the odd multiples of pi (as doubles, within 1e-15 of the top) too.
# A theta0 below 1e-323 released at rest is refused (sin(theta0/2) underflows: test_motion.py
# tests that), so the draws keep |theta0| = 0 or above 1e-300: only inputs the library takes.
theta0s = st.one_of(st.floats(-10.0, 10.0, allow_nan=False), st.floats(-1e3, 1e3),
                    st.sampled_from([3 * math.pi, -3 * math.pi, 7 * math.pi, -math.pi])
                    ).filter(lambda x: x == 0 or abs(x) > 1e-300)
# Pushes below 1e-290 at the top are refused with a ValueError (test_motion.py tests that).
dtheta0s = st.floats(-5.0, 5.0, allow_nan=False).filter(lambda x: x == 0 or abs(x) > 1e-290)
omega0s = st.floats(0.1, 10.0, allow_nan=False)
times = st.floats(-20.0, 20.0, allow_nan=False)

SETTINGS = settings(max_examples=80, deadline=None)


def speed_scale(m):
    """max |theta'| over the motion: 2 w0 k with k^2 = sin^2(theta0/2) + (theta0'/(2 w0))^2."""
    k = math.hypot(math.sin(m.theta0 / 2), m.dtheta0 / (2 * m.omega0))
    return 2 * m.omega0 * k


def difference_step(m):
    """(rate, h): rate = max(w0, max|theta'|) sets the time scale, h = 1e-5 / rate the step."""
    rate = max(m.omega0, speed_scale(m))
    return rate, 1e-5 / rate


def kc2(m):
    """1 - k^2, the distance from the separatrix in the energy (sign: + for II, - for IV)."""
    return 1 - (math.sin(m.theta0 / 2) ** 2 + (m.dtheta0 / (2 * m.omega0)) ** 2)


@SETTINGS
@given(theta0s, dtheta0s, omega0s, times)
def test_equation_of_motion_3(theta0, dtheta0, omega0, t):
    # (3): theta'' = -w0^2 sin theta, theta'' from a central difference of dtheta.
    # Step h = 1e-5 / rate with rate = max(w0, max|theta'|): truncation h^2/6 |theta''''| with
    # |theta''''| <= w0^2 (v^2 + w0^2) <= 2 rate^4 is < 1e-10 rate^2 / 3; rounding is
    # ulp(theta') / h, about 1e-16 v * rate / 1e-5 <= 1e-11 rate^2 (plus dtheta's own 1e-15).
    m = ep.solve(theta0, dtheta0, omega0)
    rate, h = difference_step(m)
    second = (m.dtheta(t + h) - m.dtheta(t - h)) / (2 * h)
    expected = -omega0**2 * math.sin(m.theta(t))
    assert abs(second - expected) <= 1e-8 * rate**2


@SETTINGS
@given(theta0s, dtheta0s, omega0s, times)
def test_dtheta_is_the_derivative_of_theta(theta0, dtheta0, omega0, t):
    # dtheta = d theta / dt; central difference, same step and error budget as above, with
    # theta's rounding ulp(|theta|) / h for |theta| <= 10 + 20 v.
    m = ep.solve(theta0, dtheta0, omega0)
    rate, h = difference_step(m)
    first = (m.theta(t + h) - m.theta(t - h)) / (2 * h)
    size = abs(m.theta(t)) + 1.0
    assert abs(first - m.dtheta(t)) <= 1e-8 * rate + 4e-16 * size / h


@SETTINGS
@given(theta0s, dtheta0s, omega0s, times)
def test_energy_9_is_conserved(theta0, dtheta0, omega0, t):
    # (9): c1 = theta'^2 - 2 w0^2 cos theta is the same at t as at 0 (energy_constant).
    # Scale 2 w0^2 + v^2 bounds both terms; theta's absolute rounding grows with |theta|.
    m = ep.solve(theta0, dtheta0, omega0)
    th, dth = m.theta(t), m.dtheta(t)
    c1 = dth**2 - 2 * omega0**2 * math.cos(th)
    scale = 2 * omega0**2 + speed_scale(m) ** 2
    assert abs(c1 - m.energy_constant) <= 1e-12 * scale * (1 + abs(th) / 10)
    # energy_constant itself is (9) at t = 0, correctly rounded: mpmath at 50 digits.
    with mpmath.workdps(50):
        exact = (mpmath.mpf(dtheta0) ** 2
                 - 2 * mpmath.mpf(omega0) ** 2 * mpmath.cos(mpmath.mpf(theta0)))
    assert abs(m.energy_constant - float(exact)) <= math.ulp(float(exact)) + 1e-300


@SETTINGS
@given(theta0s, dtheta0s, omega0s, times)
def test_period(theta0, dtheta0, omega0, t):
    # II: theta(t + T) = theta(t) with T of (26); IV: theta(t + T) = theta(t) +- 2 pi (46).
    m = ep.solve(theta0, dtheta0, omega0)
    assume(m.regime in (Regime.LIBRATION, Regime.ROTATION))
    assume(m.period < 1e6)
    turn = 0.0 if m.regime is Regime.LIBRATION else 2 * math.pi * m.direction
    v = speed_scale(m)
    # t + T is rounded: ulp(|t| + T) times the speed, on top of 1e-12 relative.
    tol = 1e-12 * (math.pi + abs(m.theta(t))) + 4e-16 * (abs(t) + m.period) * v
    assert abs(m.theta(t + m.period) - m.theta(t) - turn) <= tol
    assert abs(m.dtheta(t + m.period) - m.dtheta(t)) <= 1e-12 * v + tol * omega0**2


@SETTINGS
@given(theta0s, dtheta0s, omega0s, times)
def test_time_reversal(theta0, dtheta0, omega0, t):
    # (3) is invariant under t -> -t: solve(theta0, -theta0') at -t is theta(t), theta' negated.
    m = ep.solve(theta0, dtheta0, omega0)
    r = ep.solve(theta0, -dtheta0, omega0)
    v = speed_scale(m)
    assert abs(r.theta(-t) - m.theta(t)) <= 1e-12 * (math.pi + abs(m.theta(t)))
    assert abs(r.dtheta(-t) + m.dtheta(t)) <= 1e-12 * max(v, omega0)


@SETTINGS
@given(theta0s, dtheta0s, omega0s)
def test_initial_state_is_reproduced(theta0, dtheta0, omega0):
    # theta(0) = theta0 and theta'(0) = theta0' to a few ulp of the motion's scale: the
    # amplitude (or pi for a rotation) and |theta0| for the angle (theta0 = 0 swinging through
    # comes back as sn(2K) ~ 1e-16 amplitude), max |theta'| for the speed.
    m = ep.solve(theta0, dtheta0, omega0)
    amplitude = 2 * math.asin(min(1.0, math.hypot(math.sin(theta0 / 2), dtheta0 / (2 * omega0))))
    assert abs(m.theta(0.0) - theta0) <= 4 * math.ulp(max(abs(theta0), amplitude)) + 1e-300
    assert abs(m.dtheta(0.0) - dtheta0) <= 8 * math.ulp(speed_scale(m)) + 1e-300


@SETTINGS
@given(omega0s, st.floats(-3.0, 3.0, allow_nan=False))
def test_regimes_meet_at_the_separatrix_28(omega0, x):
    # II at theta0' = 2 w0 (1 - eps) and IV at 2 w0 (1 + eps) approach (28),
    # theta = 2 atan(sinh(w0 t)), as eps -> 0, at fixed w0 t = x (modest: the periods diverge).
    # Perturbation theory: the deviation is O(eps cosh^2(w0 t)) <= 1e3 eps for |x| <= 3.
    t = x / omega0
    sep = 2 * math.atan(math.sinh(omega0 * t))
    previous = None
    for eps in (1e-3, 1e-6, 1e-9, 1e-12):
        below = ep.solve(0.0, 2 * omega0 * (1 - eps), omega0)
        above = ep.solve(0.0, 2 * omega0 * (1 + eps), omega0)
        assert below.regime is Regime.LIBRATION and above.regime is Regime.ROTATION
        dev = max(abs(below.theta(t) - sep), abs(above.theta(t) - sep))
        assert dev <= 1e3 * eps + 1e-13
        if previous is not None:  # monotone approach, down to rounding
            assert dev <= previous + 1e-13
        previous = dev


@SETTINGS
@given(theta0s, dtheta0s, omega0s, st.floats(-10.0, 10.0), st.floats(-10.0, 10.0))
def test_time_shift(theta0, dtheta0, omega0, t1, t):
    # (3) is autonomous: the motion started from (theta(t1), theta'(t1)) is theta(. + t1).
    # The restarted state carries rounding errors of relative size 1e-16 into the energy;
    # near the separatrix they change the period by ~1e-16 / |kc^2|, so keep |kc^2| >= 1e-6
    # and allow 1e-16 / |kc^2| times the phase travelled on top of the usual 1e-12.
    m = ep.solve(theta0, dtheta0, omega0)
    assume(abs(kc2(m)) >= 1e-6)
    th1, dth1 = m.theta(t1), m.dtheta(t1)
    # A restart the library takes: it refuses a speed whose w = dtheta0/(2 omega0) is
    # subnormal (a ValueError by design, tests/test_motion.py); a t1 of 1e-311 from rest
    # gives one.
    assume(dth1 == 0 or abs(dth1 / (2 * omega0)) >= 2.0**-1022)
    shifted = ep.solve(th1, dth1, omega0)
    v = speed_scale(m)
    travel = omega0 * (abs(t) + abs(t1)) + 1
    tol_th = 1e-12 * (math.pi + abs(th1)) + 1e-14 / abs(kc2(m)) * travel
    assert abs(shifted.theta(t) - m.theta(t + t1)) <= tol_th + 4e-16 * abs(t + t1) * v
    assert abs(shifted.dtheta(t) - m.dtheta(t + t1)) <= 1e-12 * v + tol_th * max(omega0, v)


def test_the_draws_are_the_same_on_every_run():
    # tests/conftest.py's default profile: a fixed seed, no example database.
    assert settings.default.derandomize and settings.default.database is None
