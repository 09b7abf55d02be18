"""Tests of motion.py: solve() against mpmath through the note's closed forms.

Reference: mpmath at 40 digits, with the energy formed exactly from the double initial state
(theta0, theta0', omega0): r = theta0 reduced mod 2 pi in mpmath, s = sin(r/2), w = theta0'/(2 w0),
k^2 = s^2 + w^2. Regime II is the note's (25), theta = 2 pi n + 2 asin(k sn(w0 t + c2, k)) with
c2 = F(atan2(s, w) | k^2); regime IV is (46), theta = 2 pi n + d 2 am(k w0 t + c4, 1/k) with
c4 = F(d r/2 | 1/k^2); regime III is (28). Periods: (26) for II.
"""

import math

import mpmath
import numpy as np
import pytest
from scipy import special

import elliptic_pendulum as ep
from elliptic_pendulum import Regime
from tests import mpref

DPS = 40
reference = mpref.motion  # the shared mpmath reference, tests/mpref.py




def times(period, periods=100, n=61):
    """n times spread over +-periods periods, off the special points."""
    return np.linspace(-periods * period, periods * period, n) + 0.3719 * period


WORST: dict[str, float] = {}


def compare(theta0, dtheta0, omega0, periods=100, n=61, record=True):
    m = ep.solve(theta0, dtheta0, omega0)
    ts = times(m.period, periods, n)
    th_ref, dth_ref, amplitude = reference(theta0, dtheta0, omega0, ts, DPS)
    th, dth = m.theta(ts), m.dtheta(ts)
    err_th = np.max(np.abs(th - th_ref) / np.maximum(np.abs(th_ref), amplitude))
    err_dth = np.max(np.abs(dth - dth_ref)) / np.max(np.abs(dth_ref))
    key = m.regime.value
    if not record:
        return m, err_th, err_dth
    WORST[f"theta rel {key}"] = max(WORST.get(f"theta rel {key}", 0.0), err_th)
    WORST[f"dtheta rel {key}"] = max(WORST.get(f"dtheta rel {key}", 0.0), err_dth)
    return m, err_th, err_dth


# Amplitudes from 1e-8 rad to pi - 1e-10 rad, including the two places 1e-6 and
# pi - 1e-6 where the naive method fails (see test_naive_method_fails_where_it_loses_digits).
AMPLITUDES = [1e-8, 1e-6, 1e-4, 0.01, 0.5, 1.0, 2.0, 2.5, 3.0, 3.1, math.pi - 1e-6,
              math.pi - 1e-8, math.pi - 1e-10]


@pytest.mark.parametrize("omega0", [1.0, 2.5, 0.3])
@pytest.mark.parametrize("amplitude", AMPLITUDES)
def test_libration_from_rest_matches_mpmath(amplitude, omega0):
    # Regime II released at rest, the note's (25); t within +-100 periods.
    m, err_th, err_dth = compare(amplitude, 0.0, omega0)
    assert m.regime is Regime.LIBRATION
    assert err_th <= 1e-12, err_th
    assert err_dth <= 1e-12, err_dth


@pytest.mark.parametrize(("theta0", "dtheta0", "omega0"), [
    (1e-6, 1e-6, 1.0), (1e-8, -3e-8, 2.0), (-2.0, 0.7, 1.0), (0.4, -1.2, 1.3),
    (3.0, 0.05, 1.0), (-3.1, -0.01, 0.5),
    (7.0, -0.3, 1.7), (-20.0, 0.5, 3.0), (7.0, 0.0, 1.0), (-20.0, 0.0, 1.0),
    (0.0, 1.0, 1.0), (0.0, -1.999, 1.0),
])
def test_libration_with_velocity_and_winding_matches_mpmath(theta0, dtheta0, omega0):
    # Regime II from any state: phase c2 of (25), angles outside (-pi, pi], both directions.
    m, err_th, err_dth = compare(theta0, dtheta0, omega0)
    assert m.regime is Regime.LIBRATION
    assert err_th <= 1e-12 and err_dth <= 1e-12, (err_th, err_dth)


ROTATIONS = [
    (0.0, 2 * (1 + 1e-6), 1.0), (0.0, -2 * (1 + 1e-6), 1.0),
    (0.0, 2 * (1 + 1e-12), 1.0), (0.0, -2 * (1 + 1e-12), 1.0),
    (0.0, 8 * (1 + 1e-6), 4.0), (0.0, 1 * (1 + 1e-12), 0.5),
    (0.3, 10.0, 1.0), (7.0, -50.0, 4.0), (-20.0, 3.0, 1.0), (-20.0, -3.0, 1.0),
    (2.0, 1.5, 1.0), (3.1, -0.2, 1.0), (1e-8, 1e3, 7.0),
]


@pytest.mark.parametrize(("theta0", "dtheta0", "omega0"), ROTATIONS)
def test_rotation_matches_mpmath(theta0, dtheta0, omega0):
    # Regime IV, the note's (46), just above the separatrix and far above, both directions.
    m, err_th, err_dth = compare(theta0, dtheta0, omega0)
    assert m.regime is Regime.ROTATION
    assert m.direction == (1 if dtheta0 > 0 else -1)
    assert err_th <= 1e-12 and err_dth <= 1e-12, (err_th, err_dth)


@pytest.mark.parametrize(("theta0", "dtheta0", "omega0"), [
    (0.0, 2 * 2.5 * (1 + 1e-6), 2.5), (0.0, -2 * 2.5 * (1 + 1e-6), 2.5),
    (0.0, 2 * 0.3 * (1 + 1e-6), 0.3), (0.0, 2 * 2.5 * (1 - 1e-6), 2.5),
])
def test_near_separatrix_with_omega0_not_a_power_of_two(theta0, dtheta0, omega0):
    # The exact energy of the double state: k^2 = (theta0' / (2 omega0))^2 with no rounding.
    _, err_th, err_dth = compare(theta0, dtheta0, omega0, record=False)
    assert err_th <= 1e-12 and err_dth <= 1e-12, (err_th, err_dth)


# --- the naive method, for contrast --------------------------------------------------------

def naive_theta(theta0, omega0, ts):
    """m = sin^2(amplitude/2) via c1 -> arccos, scipy's ellipj, arcsin at the end."""
    c1 = -2 * omega0**2 * math.cos(theta0)
    amplitude = math.acos(-c1 / (2 * omega0**2))
    m = math.sin(amplitude / 2) ** 2
    with np.errstate(all="ignore"):
        sn = special.ellipj(omega0 * ts + special.ellipk(m), m)[0]
        return 2 * np.arcsin(np.sqrt(m) * sn)


@pytest.mark.parametrize(("amplitude", "naive_error_at_least"), [
    (1e-6, 1e-5),             # arccos(cos 1e-6) keeps 4-5 digits: 3e-5 relative measured
    (math.pi - 1e-6, 1.9),    # scipy's ellipj at 1 - m = 2.5e-13: sn off by ~2 (or NaN),
                              # theta off by ~2 pi, i.e. ~2 relative to the amplitude
])
def test_naive_method_fails_where_it_loses_digits(amplitude, naive_error_at_least):
    # The naive method is badly wrong at 1e-6 rad (lost digits) and by 2 pi at
    # pi - 1e-6; solve() is right to 1e-12 relative at both (against mpmath).
    m, err_th, err_dth = compare(amplitude, 0.0, 1.0, periods=10, n=41)
    assert err_th <= 1e-12 and err_dth <= 1e-12
    ts = times(m.period, 10, 41)
    th_ref, _, _ = reference(amplitude, 0.0, 1.0, ts)
    naive = naive_theta(amplitude, 1.0, ts)
    naive_err = np.max(np.where(np.isnan(naive), np.inf, np.abs(naive - th_ref))) / amplitude
    assert naive_err >= naive_error_at_least, naive_err


# --- regimes I and III, singular solutions --------------------------------------------------

@pytest.mark.parametrize("omega0", [1.0, 0.7, 3.0])
@pytest.mark.parametrize("direction", [1, -1])
def test_separatrix_is_the_notes_28(omega0, direction):
    # Regime III from theta0 = 0, theta0' = +-2 omega0: theta = +-2 asin(tanh(w0 t)) (28),
    # computed in the library as 2 atan(sinh(w0 t)); theta' = +-2 w0 sech(w0 t).
    m = ep.solve(0.0, direction * 2.0 * omega0, omega0)
    assert m.regime is Regime.SEPARATRIX and m.period == math.inf
    ts = np.linspace(-30.0, 30.0, 121) / omega0 + 0.013
    th, dth = m.theta(ts), m.dtheta(ts)
    with mpmath.workdps(DPS):
        ref = np.array([float(direction * 2 * mpmath.asin(mpmath.tanh(omega0 * mpmath.mpf(t))))
                        for t in ts])
        dref = np.array([float(direction * 2 * omega0 * mpmath.sech(omega0 * mpmath.mpf(t)))
                         for t in ts])
    assert np.max(np.abs(th - ref) / np.pi) <= 1e-15 * 4
    # theta' decays like e^{-w0 t}: relative to its own size, up to the conditioning of sech
    # in its argument (|x| ulp(w0 t)).
    assert np.all(np.abs(dth - dref) <= 1e-15 * np.abs(dref) * (2 + omega0 * np.abs(ts)))


def test_separatrix_at_long_times_without_warnings():
    # theta -> +-pi and theta' -> 0 as t -> +-inf on the separatrix (28); nothing overflows.
    m = ep.solve(0.0, 2.0)
    np.testing.assert_array_equal(m.theta(np.array([1e3, -1e3])), [math.pi, -math.pi])
    np.testing.assert_array_equal(m.dtheta(np.array([1e3, -1e3])), [0.0, 0.0])


@pytest.mark.parametrize("theta0", [math.pi, -math.pi])
def test_singular_solution_stays_at_the_top(theta0):
    # Regime III's singular solution: at rest upside down it stays there.
    # The double math.pi means pi itself (regimes.py); so do the doubles nearest the other
    # odd multiples of pi (test_odd_multiples_of_pi_are_the_top).
    m = ep.solve(theta0, 0.0, 1.3)
    assert m.regime is Regime.SEPARATRIX
    ts = np.array([-1e6, -1.0, 0.0, 2.5, 1e3, 1e9])
    th = m.theta(ts)
    assert np.all(th == th[0]) and abs(th[0] - theta0) <= 4e-16 * abs(theta0)
    np.testing.assert_array_equal(m.dtheta(ts), np.zeros_like(ts))


@pytest.mark.parametrize("dtheta0", [1e-160, -1e-170, 1e-299])
def test_tiny_push_at_the_top(dtheta0):
    # Any push at the top, however small, makes it go over (IV, c1 > 2 w0^2); here
    # 1 - k^2 = -w^2 underflows, so it must be compared as c against |w| (regression test).
    m = ep.solve(math.pi, dtheta0)
    assert m.regime is Regime.ROTATION
    assert m.theta(0.0) == math.pi
    assert abs(m.dtheta(0.0) - dtheta0) <= 4 * math.ulp(dtheta0)


@pytest.mark.parametrize("theta0", [0.0, -0.0])
def test_rest_at_the_bottom(theta0):
    # Regime I (c1 = -2 w0^2): theta stays at theta0, theta' = 0.
    m = ep.solve(theta0, 0.0, 2.0)
    assert m.regime is Regime.REST
    ts = np.array([-1e6, 0.0, 3.3, 1e9])
    np.testing.assert_array_equal(m.dtheta(ts), np.zeros(4))
    np.testing.assert_array_equal(m.theta(ts), np.zeros(4))
    assert ep.solve(0.0).theta(5.0) == 0.0


def test_two_pi_as_a_double_is_rest_at_the_bottom():
    # 2 * math.pi is the double nearest 2 pi (2.4e-16 below it): like the doubles nearest odd
    # multiples of pi (the top), regimes.py takes it to mean 2 pi, the bottom, at rest.
    assert 2 * math.pi == float(2 * mpmath.pi)
    m = ep.solve(2 * math.pi)
    assert m.regime is Regime.REST
    assert m.amplitude == 0.0
    assert m.theta(123.4) == 2 * math.pi


# --- periods ---------------------------------------------------------------------------------

@pytest.mark.parametrize("amplitude", [1e-8, 0.1, 1.0, 2.0, 3.0, math.pi - 1e-6, math.pi - 1e-10])
@pytest.mark.parametrize("omega0", [1.0, 2.5])
def test_libration_period_is_the_notes_26(amplitude, omega0):
    # (26): T = 4 K1(alpha) / w0, alpha = sin(theta0 / 2); K1 from mpmath's AGM.
    m = ep.solve(amplitude, 0.0, omega0)
    with mpmath.workdps(DPS):
        kc = mpmath.cos(mpmath.mpf(amplitude) / 2)
        ref = float(4 * mpmath.pi / (2 * mpmath.agm(1, kc)) / omega0)
    assert m.period == pytest.approx(ref, rel=1e-15 * 4, abs=0)
    assert m.amplitude == pytest.approx(amplitude, rel=1e-15, abs=0)


@pytest.mark.parametrize(("theta0", "dtheta0", "omega0"), ROTATIONS)
def test_rotation_advances_two_pi_per_period(theta0, dtheta0, omega0):
    # IV: theta(t + T) = theta(t) +- 2 pi, theta'(t + T) = theta'(t).
    m = ep.solve(theta0, dtheta0, omega0)
    ts = np.linspace(-3, 3, 13) * m.period + 0.17
    shift = 2 * math.pi * m.direction
    scale = np.abs(m.theta(ts)) + 2 * math.pi + np.abs(ts) * abs(dtheta0)
    assert np.all(np.abs(m.theta(ts + m.period) - m.theta(ts) - shift) <= 1e-13 * scale)
    np.testing.assert_allclose(m.dtheta(ts + m.period), m.dtheta(ts),
                               rtol=0, atol=1e-12 * np.max(np.abs(m.dtheta(ts))))


def test_initial_state_and_regime_classification():
    # (9) c1 = theta'^2 - 2 w0^2 cos theta decides the regime: II below 2 w0^2, IV above.
    cases = {(0.5, 0.0, 1.0): "II", (0.0, 2.0, 1.0): "III", (0.0, 3.0, 1.0): "IV",
             (0.0, 0.0, 1.0): "I", (math.pi, 0.0, 1.0): "III", (7.0, -0.3, 1.7): "II"}
    for (t0, d0, w0), regime in cases.items():
        m = ep.solve(t0, d0, w0)
        assert m.regime.value == regime
        assert m.theta0 == t0 and m.dtheta0 == d0 and m.omega0 == w0
        assert m.energy_constant == pytest.approx(d0**2 - 2 * w0**2 * math.cos(t0), abs=1e-15)


def test_zz_report_worst_errors(capsys):
    with capsys.disabled():
        for name, value in sorted(WORST.items()):
            print(f"\n  worst {name}: {value:.2e}", end="")


# --- regressions from the review: odd multiples of pi, extreme scales, huge angles ----------

@pytest.mark.parametrize("theta0", [math.nextafter(3 * math.pi, 0),
                                    -math.nextafter(3 * math.pi, 10),
                                    math.nextafter(7 * math.pi, 30), 1e3, -1e6 + 0.5])
def test_winding_number_of_far_angles_matches_mpmath(theta0, monkeypatch):
    # theta0 = 2 pi m + r with m = nint(theta0 / 2 pi) taken exactly: next to 3 pi,
    # theta0 / (2 pi) rounds to 1.5 in floating point, and round-half-even once picked the
    # wrong turn (the pendulum then swung about 4 pi instead of 2 pi). (The doubles nearest
    # 3 pi and 7 pi themselves mean those multiples: test_odd_multiples_of_pi_are_the_top.)
    # Reference: mpmath through (25), at 90 digits: these states are within 2e-15 of the
    # top, where mpmath's K near m = 1 needs them.
    monkeypatch.setitem(globals(), "DPS", 90)
    _, err_th, err_dth = compare(theta0, 0.0, 1.0, periods=3, record=False)
    assert err_th <= 1e-12 and err_dth <= 1e-12, (err_th, err_dth)


def test_amplitude_of_a_huge_angle_is_exact():
    # 1e50 rad taken as the exact double it is: r = 1e50 - 2 pi m at 120 digits (mpmath).
    with mpmath.workdps(120):
        x = mpmath.mpf(1e50)
        r = float(abs(x - 2 * mpmath.pi * mpmath.nint(x / (2 * mpmath.pi))))
    assert ep.solve(1e50).amplitude == pytest.approx(r, rel=1e-15)


def test_tiny_omega0_is_a_free_rotation():
    # omega0 = 1e-302: gravity is negligible and theta(t) = theta0 + theta0' t; the rate
    # omega0 / gamma is formed at 50 digits (a double product would overflow in Dekker's split).
    m = ep.solve(1.0, 1.0, 1e-302)
    assert m.regime is Regime.ROTATION
    assert m.theta(1.0) == pytest.approx(2.0, rel=1e-15)
    assert m.period == pytest.approx(2 * math.pi, rel=1e-15)


@pytest.mark.parametrize(("theta0", "dtheta0", "omega0", "gamma_c"), [
    (1e-200, 2.0, 1.0, 5e-201),
    (-1e-200, -2.0, 1.0, 5e-201),
    (8.892898100017254e-42, 2.1800754380841732e-106, 1.0900377190420866e-106,
     4.446449050008627e-42),
])
def test_tiny_angle_beside_the_separatrix_rotates(theta0, dtheta0, omega0, gamma_c):
    # |w| = 1 exactly and a tiny angle (a far state, classified in mpmath): kc^2 = -sin^2(r/2)
    # and gamma_c = |sin(r/2)|. cos(r/2) = 1 - r^2/8 rounds to 1 at 50 digits, so
    # c - |w| is formed as (1 - |w|) - 2 sin^2(r/4); the mutant (c - |w|)(c + |w|) made it III.
    m = ep.solve(theta0, dtheta0, omega0)
    assert m.regime is Regime.ROTATION
    assert m.complementary_modulus == pytest.approx(gamma_c, rel=1e-15)


@pytest.mark.parametrize(("theta0", "dtheta0", "omega0", "t"), [
    (1.0, 0.0, 1.0, 1e302), (1.0, 5.0, 1.0, -1e300), (0.1, 0.0, 1e10, 1e300)])
def test_times_beyond_range_raise(theta0, dtheta0, omega0, t):
    # Beyond |omega0 t| ~ 1e290 the elliptic argument cannot be formed: a ValueError naming t,
    # not an overflow warning and a NaN.
    with pytest.raises(ValueError, match="t is too large"):
        ep.solve(theta0, dtheta0, omega0).theta(t)


@pytest.mark.parametrize("dtheta0", [5e-324, 1e-310, -1e-301])
def test_push_below_the_double_range_at_the_top_raises(dtheta0):
    # kc = |theta0'| / (2 omega0) would be subnormal: its period cannot be computed in double.
    with pytest.raises(ValueError, match="dtheta0"):
        ep.solve(math.pi, dtheta0)


@pytest.mark.parametrize(("dtheta0", "omega0"), [(1e-250, 1e100), (1e-300, 1e10),
                                                 (-5e-324, 1.0), (1e-300, 1e300)])
@pytest.mark.parametrize("convert", [float, np.array])
def test_push_without_a_double_w_raises(dtheta0, omega0, convert):
    # w = dtheta0 / (2 omega0) below 2**-1022: it would underflow (theta' would come back 0)
    # or lose its digits as a subnormal (279 ulp off); refused on both paths.
    with pytest.raises(ValueError, match=r"dtheta0.*omega0.*2\*\*-1022"):
        ep.solve(convert(0.0), convert(dtheta0), convert(omega0))
    assert ep.solve(0.0, 2.0 ** -1021, 1.0).dtheta(0.0) == 2.0 ** -1021


@pytest.mark.parametrize("multiple", [3, -3, 5, 7, -101, 2**19 + 1])
def test_odd_multiples_of_pi_are_the_top(multiple):
    # The convention of the engine: the double nearest an odd multiple of pi means that
    # multiple, as math.pi means pi. Reference: that double from mpmath; its neighbours are
    # taken exactly as they are and swing (II) about the bottom with an amplitude a hair
    # below pi.
    with mpmath.workdps(60):
        theta0 = float(multiple * mpmath.pi)
    m = ep.solve(theta0, 0.0, 1.3)
    assert m.regime is Regime.SEPARATRIX and m.period == math.inf
    ts = np.array([-1e6, 0.0, 2.5, 1e9])
    np.testing.assert_array_equal(m.theta(ts), np.full(4, theta0))
    np.testing.assert_array_equal(m.dtheta(ts), np.zeros(4))
    for neighbour in (math.nextafter(theta0, 0.0), math.nextafter(theta0, 2 * theta0)):
        assert ep.solve(neighbour).regime is Regime.LIBRATION
    # the mutant "only math.pi is pi" would make 3 * math.pi a libration
    assert ep.solve(3 * math.pi).regime is Regime.SEPARATRIX
    # math.pi * n whose quotient by math.pi rounds an ulp off n (-13 * math.pi / math.pi is
    # -13.000000000000002): the mutant "floor(x/2 + 1/2)" picked the next odd integer
    for theta0 in (13 * math.pi, -13 * math.pi, -34.55751918948773):  # 13 pi, -13 pi, -11 pi
        assert ep.solve(theta0).regime is Regime.SEPARATRIX, theta0
        assert ep.solve(np.array([theta0])).regime[0] is Regime.SEPARATRIX, theta0
