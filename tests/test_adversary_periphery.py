"""Adversarial edge cases of the periphery: series, continuation, resonance, string, period, CLI.

Each expectation comes from an independent source named beside it: mpmath at high precision,
a direct scipy integration at tight tolerance, a brute-force search over the data, or the
documented contract (docs/cli.md: one line on stderr and exit status 2 for a bad argument).
"""

import math

import numpy as np
import pytest

import elliptic_pendulum as ep
from elliptic_pendulum.animation import animate
from elliptic_pendulum.cli import main

# --- counts: any integral type, bools and floats refused by name -----------------------------

def test_response_curve_accepts_numpy_integer_max_points():
    # A count read from an array is an np.int64; it means the same as the int 3, so the curve
    # must be the one that int gives.
    args = dict(frequencies=(1.2, 1.6), step=0.05)
    expected = ep.response_curve(0.1, 0.1, max_points=3, **args)
    curve = ep.response_curve(0.1, 0.1, max_points=np.int64(3), **args)
    assert len(curve.orbits) == 3
    assert np.array_equal(curve.frequency, expected.frequency)


@pytest.mark.parametrize("bad", [True, 3.0, np.float64(3.0), "3"])
def test_response_curve_refuses_non_integer_max_points(bad):
    with pytest.raises(TypeError, match="max_points"):
        ep.response_curve(0.1, 0.1, frequencies=(1.2, 1.6), step=0.05, max_points=bad)


def test_animate_accepts_numpy_integer_frames():
    import matplotlib.pyplot as plt

    anim = animate([ep.solve(1.0)], frames=np.int64(3))
    try:
        # The frames' times are a linspace of that many points, as for the int 3.
        assert len(anim.frame_times) == 3
    finally:
        anim._draw_was_started = True  # never rendered on purpose: no warning at deletion
        plt.close(anim._fig)


@pytest.mark.parametrize("bad", [True, 3.0, np.float64(3.0)])
def test_animate_refuses_non_integer_frames(bad):
    with pytest.raises(TypeError, match="frames"):
        animate([ep.solve(1.0)], frames=bad)


# --- errors name the parameter that is out of range ------------------------------------------

def test_solve_blames_omega0_not_dtheta0_for_a_huge_omega0():
    # At rest (dtheta0 = 0) only omega0 can make c1 = dtheta0**2 - 2 omega0**2 cos(theta0)
    # overflow; the message must name it.
    with pytest.raises(ValueError, match="omega0 is too large") as info:
        ep.solve(0.0, 0.0, 1e200)
    assert "dtheta0 is too large" not in str(info.value)
    with pytest.raises(ValueError, match="dtheta0 is too large"):
        ep.solve(0.0, 1e200, 1.0)


def _backbone_reference(speed=None, amplitude=None, omega0=1.0):
    """omega = pi v / (2 K(2 omega0 / v)) or pi omega0 / (2 K(sin(A/2))), mpmath at 50 digits."""
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 50
    if speed is not None:
        gamma = 2 * ctx.mpf(omega0) / ctx.mpf(speed)
        return ctx.pi * ctx.mpf(speed) / (2 * ctx.ellipk(gamma**2))
    return ctx.pi * ctx.mpf(omega0) / (2 * ctx.ellipk(ctx.sin(ctx.mpf(amplitude) / 2) ** 2))


@pytest.mark.parametrize("speed, omega0", [(1e200, 1.0), (1.7e308, 1.0), (1e10, 1e-300),
                                           (1e308, 1e307), (2 + 1e-12, 1.0), (3.0, 1.0)])
def test_backbone_frequency_of_fast_rotations(speed, omega0):
    # A rotation at 1e200 rad/s turns at about 1e200 rad/s: a double answer exists, and it
    # was refused as "kc must be finite" ((v - 2)(v + 2) overflowed).
    with np.errstate(all="raise"):
        got = ep.backbone_frequency(bottom_speed=speed, omega0=omega0)
    expected = _backbone_reference(speed=speed, omega0=omega0)
    assert abs(got - float(expected)) <= 4e-16 * float(expected)


def test_backbone_frequency_of_a_swing_at_tiny_omega0():
    # omega0 / R is a double (9.4e-309) although the period 2 pi R / omega0 overflows; going
    # through the period gave 0.0.
    with np.errstate(all="raise"):
        got = ep.backbone_frequency(1.0, omega0=1e-308)
    expected = float(_backbone_reference(amplitude=1.0, omega0=1e-308))
    # Subnormal: the spacing of doubles there is 4.9e-324, i.e. 5e-16 relative.
    assert abs(got - expected) <= 4 * 5e-324


# --- valid input, no spurious warning -----------------------------------------------------------

def _silently(f, *args, **kwargs):
    """Call f with every floating-point trap and every warning turned into an error."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with np.errstate(all="raise"):
            return f(*args, **kwargs)


@pytest.mark.parametrize("theta0, dtheta0, omega0", [(1.0, 1e200, 1.0), (0.0, 1.0, 1e-300),
                                                     (3.0, -1e300, 1e-5), (2.0, 1e-200, 1.0),
                                                     (1.0, 1e-200, 1e200)])
def test_string_stays_taut_far_out(theta0, dtheta0, omega0):
    # Expectation from the tension T/(m l) = c1 + 3 omega0^2 cos(theta) at the highest point of
    # the motion (c1 = dtheta0^2 - 2 omega0^2 cos(theta0)), in exact mpmath arithmetic, which
    # does not overflow: a rotation (c1 > 2 omega0^2) has its top at theta = pi, a swing its
    # turning point where cos(theta) = -c1 / (2 omega0^2).
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 60
    w2 = ctx.mpf(omega0) ** 2
    c1 = ctx.mpf(dtheta0) ** 2 - 2 * w2 * ctx.cos(ctx.mpf(theta0))
    lowest = c1 - 3 * w2 if c1 > 2 * w2 else c1 + 3 * w2 * (-c1 / (2 * w2))
    assert _silently(ep.string_stays_taut, theta0, dtheta0, omega0) is bool(lowest >= 0)


def _period_reference(theta0, omega0):
    """2 pi R / omega0 = 4 K(sin^2(theta0/2)) / omega0, mpmath at 50 digits."""
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 50
    return 4 * ctx.ellipk(ctx.sin(ctx.mpf(theta0) / 2) ** 2) / ctx.mpf(omega0)


@pytest.mark.parametrize("name", ["period", "agm_period"])
@pytest.mark.parametrize("omega0", [1e-308, 3e-308, 1e-320])
def test_period_beyond_the_doubles_is_refused_naming_omega0(name, omega0):
    # The true period is larger than the largest double (mpmath says so), so neither inf
    # (period) nor an underflow warning (agm_period) is a right answer: a ValueError is.
    assert _period_reference(1.0, omega0) > np.finfo(float).max
    with pytest.raises(ValueError, match="omega0 must exceed"):
        _silently(getattr(ep, name), 1.0, omega0)


def test_small_angle_period_beyond_the_doubles_is_refused_naming_omega0():
    # 2 pi / 1e-308 = 6.3e308 > 1.8e308.
    with pytest.raises(ValueError, match="omega0 must exceed"):
        _silently(ep.small_angle_period, 1e-308)


@pytest.mark.parametrize("name", ["period", "agm_period"])
def test_period_just_inside_the_doubles(name):
    # 4e-308 leaves the period 1.67e308 representable: it must come out right (mpmath), and
    # quietly.
    got = _silently(getattr(ep, name), 1.0, 4e-308)
    expected = float(_period_reference(1.0, 4e-308))
    assert abs(got - expected) <= 4e-16 * expected


# --- ResponseCurve.peak stays within the data -------------------------------------------------

def test_peak_at_the_end_of_the_curve_is_the_end_orbit():
    # Above resonance the amplitude falls along the whole range, so the largest orbit is the
    # first (brute-force max over the data), and a long run from rest (settle, an independent
    # solve_ivp) settles to the same swing there. A parabola through the first three orbits put
    # its vertex at Omega = 1.568 with amplitude 0.086, smaller than the data's own maximum.
    curve = ep.response_curve(0.1, 0.1, frequencies=(1.2, 1.6), step=0.05)
    largest = int(np.argmax(curve.amplitude))
    assert largest == 0
    omega, amplitude = curve.peak()
    assert (omega, amplitude) == (curve.frequency[0], curve.amplitude[0])
    _, settled = ep.settle(1.2, 0.1, 0.1)
    assert abs(amplitude - settled) < 1e-6


@pytest.mark.parametrize("count", [1, 2])
def test_peak_of_one_or_two_orbits(count):
    # With fewer than three orbits there is no parabola: the peak is the largest orbit (the
    # brute-force max), not a LinAlgError with a LAPACK message on stderr.
    from elliptic_pendulum.continuation import ResponseCurve

    orbits = tuple(ep.periodic_orbit(w, 0.1, 0.1) for w in (1.2, 1.25)[:count])
    best = max(orbits, key=lambda o: o.amplitude)
    assert _silently(ResponseCurve(orbits).peak) == (best.frequency, best.amplitude)


def test_interior_peak_is_refined_between_its_neighbours():
    # Below resonance and through it: the maximum is interior. Its refinement must stay between
    # the neighbouring orbits, at least as high as the largest, and agree with a brute-force
    # max over periodic orbits on a fine grid of frequencies around it (spacing 5e-4).
    curve = ep.response_curve(0.1, 0.1, frequencies=(0.6, 1.0), step=0.05)
    i = int(np.argmax(curve.amplitude))
    assert 0 < i < len(curve.orbits) - 1
    omega, amplitude = curve.peak()
    around = curve.frequency[i - 1:i + 2]
    assert around.min() <= omega <= around.max()
    assert amplitude >= curve.amplitude[i]
    grid = np.linspace(0.970, 0.977, 15)
    fine = [ep.periodic_orbit(w, 0.1, 0.1).amplitude for w in grid]
    assert abs(omega - grid[int(np.argmax(fine))]) < 1e-3
    assert abs(amplitude - max(fine)) < 1e-5


# --- the command line: one line on stderr and status 2 for every bad argument ------------------

def _cli_fails(capsys, *argv):
    """Run the CLI in-process; docs/cli.md promises exit status 2, nothing on stdout and one
    line on stderr for a bad argument. Returns that line."""
    with pytest.raises(SystemExit) as info:
        _silently(main, list(argv))
    out, err = capsys.readouterr()
    assert info.value.code == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "error:" in lines[0]
    return lines[0]


def _cli_runs(capsys, *argv):
    status = _silently(main, list(argv))
    out, err = capsys.readouterr()
    assert status == 0 and err == ""
    return out.splitlines()


@pytest.mark.parametrize("times", [("0", "1e300", "1e-300"), ("-1e308", "1e308", "1e307"),
                                   ("0", "1", "1e-320"), ("0", "1e-10", "-1e-320")])
def test_cli_times_that_overflow_fail_in_one_line(capsys, times):
    # These raised OverflowError (math.floor of inf) or an overflow in step * k: a traceback
    # and status 1.
    _cli_fails(capsys, "solve", "--theta0", "170", "--t", *times)


@pytest.mark.parametrize("argv", [("crossing", "1", "1e-3"), ("crossing", "2", "3", "nan"),
                                  ("period", "0", "170", "--omega0", "3.6e-308")])
def test_cli_checks_every_value_before_printing_any(capsys, argv):
    # The last value is refused by the library (R < 1; NaN; a period of 170 degrees beyond
    # the doubles at this omega0, while that of 0 degrees, 2 pi / 3.6e-308, is not); the
    # answers for the good ones used to be printed first, then the error.
    line = _cli_fails(capsys, *argv)
    assert "value" in line or "omega0" in line


@pytest.mark.parametrize("typed", ["179.9999", "179.99999999999997", "90", "1e-05", "0.1",
                                   "33.333333333333336"])
def test_cli_period_label_reads_back_as_the_amplitude(capsys, typed):
    # The label must name the amplitude that was computed: read back, it is the same double
    # ('{:g}' printed 179.9999 as "R(180 deg)", the one amplitude the command refuses).
    import re

    (line,) = _cli_runs(capsys, "period", typed)
    label = re.fullmatch(r"R\((\S+) deg\) = \d+\.\d{6}", line).group(1)
    assert float(label) == float(typed)


@pytest.mark.parametrize("typed", ["3.0000000000000004", "2.123456789", "23.6"])
def test_cli_crossing_label_reads_back_as_the_value(capsys, typed):
    import re

    (line,) = _cli_runs(capsys, "crossing", typed)
    label = re.fullmatch(r"R = (\S+) at theta0 = \d+\.\d{9} deg", line).group(1)
    assert float(label) == float(typed)


def test_cli_degrees_are_converted_to_the_nearest_double():
    # Reference: mpmath at 60 digits, rounded once to a double. math.radians rounds twice
    # (pi / 180, then the product) and misses the nearest double for about one angle in nine,
    # among them multiples of 180 degrees (3960 = 11 turns).
    import random

    import mpmath

    from elliptic_pendulum import cli

    ctx = mpmath.MPContext()
    ctx.dps = 60
    rng = random.Random(20240611)
    angles = [180.0 * n for n in range(-50, 200)] + [rng.uniform(-1e4, 1e4) for _ in range(500)]
    angles += [1e-320, 5e-324, 1e308, -1e308, 179.9999, 33.333333333333336]
    for degrees in angles:
        assert cli._radians(degrees) == float(ctx.mpf(degrees) * ctx.pi / 180), degrees
    assert cli._radians(360.0) == 2 * math.pi  # 2 * (the double nearest pi) is exact


@pytest.mark.parametrize("degrees", ["180", "540", "-180"])
def test_cli_odd_multiples_of_180_degrees_are_the_top(capsys, degrees):
    # Released at rest upside down: the separatrix (regime III), as docs/cli.md shows for 180.
    lines = _cli_runs(capsys, "solve", "--theta0", degrees, "--t", "0", "1", "1")
    assert lines[0] == "# regime III (separatrix), period infinite"


@pytest.mark.xfail(strict=True, reason="the library classifies the double nearest 2 pi n as a "
                   "swing of amplitude ~2e-16 rad; the fix in regimes/_states is on another "
                   "branch")
@pytest.mark.parametrize("degrees", ["360", "720", "1080", "-360"])
def test_cli_even_multiples_of_180_degrees_are_the_bottom(capsys, degrees):
    # Released at rest hanging straight down, as for 0 degrees: regime I (rest), whatever the
    # number of turns the angle counts.
    lines = _cli_runs(capsys, "solve", "--theta0", degrees, "--t", "0", "1", "1")
    assert lines[0] == _cli_runs(capsys, "solve", "--theta0", "0", "--t", "0", "1", "1")[0]
    assert lines[0].startswith("# regime I (rest)")


@pytest.mark.parametrize("name", ["period_ratio", "period", "agm_period"])
@pytest.mark.parametrize("theta0", [1e-320, 5e-324, 3e-323])
def test_periods_of_subnormal_amplitudes_are_quiet(name, theta0):
    # R = 1 + theta0^2/16 + ... (DLMF 19.5.1) is 1 to rounding for theta0 < 1e-8; the
    # underflow of theta0 / 2 on the way is no reason for a warning.
    expected = 1.0 if name == "period_ratio" else 2 * math.pi
    assert _silently(getattr(ep, name), theta0) == expected


def test_cli_swing_whose_period_overflows_is_not_called_infinite(capsys):
    # At omega0 = 1e-320 the period 4 K(sin 15 deg) / omega0 (mpmath) is finite, 6.4e320, but
    # beyond the doubles; "infinite" is what docs/cli.md reserves for the separatrix.
    assert math.isfinite(float(_period_reference(math.radians(30), 1e-320) / 1e300))
    lines = _cli_runs(capsys, "solve", "--theta0", "30", "--omega0", "1e-320", "--t", "0", "1", "1")
    assert lines[0].startswith("# regime II (libration), period ")
    assert "infinite" not in lines[0] and "largest double" in lines[0]


@pytest.mark.parametrize("argv", [("--theta0", "1e-320"), ("--theta0", "30", "--dtheta0", "1e-320"),
                                  ("--theta0", "30", "--length", "1", "--g", "1e-320"),
                                  ("--theta0", "30", "--t", "1e-320", "1", "1")])
def test_cli_tiny_angles_and_rates_print_quietly(capsys, argv):
    # Subnormal angles or rates converted to degrees underflow; they print as 0.000000000
    # (rounded to nine decimals) all the same, so no FloatingPointError under errstate(raise).
    lines = _cli_runs(capsys, "solve", *argv)
    assert lines[0].startswith("# regime")


# --- series: the Fourier coefficients of small swings ----------------------------------------

def _fourier_reference(theta0, n):
    """b_j = 8 q^(j+1/2) / ((2j+1)(1 + q^(2j+1))), q from mpmath.qfrom of m = sin^2(theta0/2).

    The working precision grows with -log10(theta0), so that mpmath's own K(1 - m) keeps its
    digits (at 50 digits qfrom returns 0 for theta0 = 1e-150)."""
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 50 + 2 * max(0, int(-math.log10(theta0)))
    k = ctx.sin(ctx.mpf(theta0) / 2)
    q = ctx.qfrom(m=k * k)
    return [8 * q ** (j + ctx.mpf(1) / 2) / ((2 * j + 1) * (1 + q ** (2 * j + 1)))
            for j in range(n)]


@pytest.mark.parametrize("theta0", [1e-150, 1e-50, 1e-10, 2e-8, 1e-8, 1e-7, 1e-6, 1e-4, 0.01,
                                    0.5, 1.0, 2.0, 3.0, 3.14, math.nextafter(math.pi, 0)])
def test_fourier_coefficients_against_mpmath(theta0):
    # Small swings lost every digit: kc = cos(theta0/2) rounds to 1 below theta0 ~ 2e-8, and
    # k was recomputed from it (b = [0, 0] at 1e-8; b0 off by 1.2e-2 at 1e-7, 4.4e-5 at 1e-6).
    got = _silently(ep.fourier_coefficients, theta0, 4)
    for j, (b, expected) in enumerate(zip(got, _fourier_reference(theta0, 4), strict=True)):
        if expected >= np.finfo(float).tiny:
            # b_j goes with sqrt(q)^(2j+1): 2j+1 times the relative error of sqrt(q).
            assert abs(b - expected) <= (2 * j + 1) * 4 * 2.0**-52 * expected, (j, b)
        else:  # below the normal doubles: 0 or the nearest subnormals
            assert abs(b - expected) <= 4 * 2.0**-1074, (j, b)


@pytest.mark.parametrize("theta0", [1e-8, 1e-6])
def test_fourier_coefficients_of_small_swings_against_the_exact_motion(theta0):
    # The closed form itself checked against the motion: theta(t) = 2 asin(k sn(omega0 t, k))
    # from the upward passage through the bottom, so by quarter-wave symmetry
    # b_j = (2/K) int_0^K 2 asin(k sn(u)) sin((2j+1) pi u / (2K)) du (mpmath quadrature).
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 40
    k = ctx.sin(ctx.mpf(theta0) / 2)
    m = k * k
    big = ctx.ellipk(m)
    got = ep.fourier_coefficients(theta0, 2)
    for j in range(2):
        def integrand(u, j=j):
            return 2 * ctx.asin(k * ctx.ellipfun("sn", u, m=m)) * ctx.sin(
                (2 * j + 1) * ctx.pi * u / (2 * big))
        expected = 2 / big * ctx.quad(integrand, [0, big])
        assert abs(got[j] - expected) <= (2 * j + 1) * 4 * 2.0**-52 * expected


@pytest.mark.parametrize("k", [1e-100, 1e-160, 1e-300, 0.3])
def test_nome_of_a_tiny_modulus_is_quiet(k):
    # mpmath's qfrom at a precision that holds 1 - k^2; q ~ k^2/16 underflows below k ~ 1e-154,
    # where 0 (or the nearest subnormal) is the right double.
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 50 + 2 * int(-math.log10(k))
    expected = ctx.qfrom(k=ctx.mpf(k))
    got = _silently(ep.nome, k)
    if expected >= np.finfo(float).tiny:
        assert abs(got - expected) <= 4 * 2.0**-52 * expected
    else:
        assert abs(got - expected) <= 4 * 2.0**-1074


# --- series: the exact coefficients are computed once ------------------------------------------

def _composed_coefficients(n):
    """a_0..a_{n-1} from DLMF 19.5.1, (2/pi) K = sum_i binom(2i, i)^2 m^i / 16^i, with
    m = sin^2(theta0/2) = (1 - cos theta0)/2 = sum_{r>=1} (-1)^(r+1) x^r / (2 (2r)!), x = theta0^2,
    composed by exact truncated power-series arithmetic: independent of the recurrence."""
    from fractions import Fraction

    m = [Fraction(0)] + [Fraction((-1) ** (r + 1), 2 * math.factorial(2 * r)) for r in range(1, n)]
    total = [Fraction(0)] * n
    power = [Fraction(1)] + [Fraction(0)] * (n - 1)  # m^0
    for i in range(n):  # m^i = O(x^i): terms i >= n do not reach x^(n-1)
        c = Fraction(math.comb(2 * i, i) ** 2, 16**i)
        total = [t + c * p for t, p in zip(total, power, strict=True)]
        power = [sum(power[a] * m[d - a] for a in range(d + 1)) for d in range(n)]
    return total


def test_period_series_coefficients_match_the_composed_series():
    a = ep.period_series_coefficients(40)
    assert a == _composed_coefficients(40)
    # A longer call continues the kept ones; a shorter one is their prefix.
    longer = ep.period_series_coefficients(61)
    assert longer[:40] == a and ep.period_series_coefficients(7) == a[:7]


def test_period_series_coefficients_cache_is_not_the_callers_list():
    # The coefficients are kept between calls; the list handed out must be a copy of them.
    first = ep.period_series_coefficients(5)
    first[1] = 99
    first.append(0)
    assert ep.period_series_coefficients(5) == _composed_coefficients(5)


def test_period_series_coefficients_from_threads_agree():
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(4) as pool:
        results = list(pool.map(ep.period_series_coefficients, [90, 70, 90, 80, 90, 85]))
    reference = _composed_coefficients(30)
    assert all(r[:30] == reference for r in results)
    assert results[0] == results[2] == results[4]


def test_period_series_with_many_terms_against_mpmath():
    # 400 terms at 3 rad: the tail beyond is below 1e-17 (the terms shrink by (3/pi)^2 = 0.91
    # each); the rest is the rounding of 400 Horner steps. Reference R = (2/pi) K(sin^2(1.5))
    # from mpmath at 40 digits.
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 40
    expected = 2 / ctx.pi * ctx.ellipk(ctx.sin(ctx.mpf(1.5)) ** 2)
    assert abs(ep.period_series(3.0, 400) - expected) < 1e-13


def test_period_series_does_not_recompute_kept_coefficients(monkeypatch):
    # The cost that grew like n^3 on every call (period_series(theta0, 400) took seconds each
    # time): once computed, the coefficients are kept, so repeated and shorter calls build no
    # binomial row at all. Checked by making that work impossible after a first call.
    from elliptic_pendulum import series

    expected = ep.period_series(0.5, 150)
    coefficients = ep.period_series_coefficients(150)

    def forbidden(n):
        raise AssertionError("the exact coefficients were recomputed")

    monkeypatch.setattr(series, "_binomials", forbidden)
    assert ep.period_series(0.5, 150) == expected
    assert ep.period_series_coefficients(150) == coefficients
    assert ep.period_series_coefficients(120) == coefficients[:120]


# --- resonance: quiet, and heavy damping at a bounded cost ------------------------------------

def test_periodic_orbit_and_response_curve_are_quiet_under_errstate_raise():
    # scipy's solve_ivp bounds its first step by nextafter(0) - 0, a subnormal, which raised
    # FloatingPointError under np.errstate(all='raise') on every call. The expectation for the
    # orbit itself: the linear response, as in the docstring, at weak forcing.
    orbit = _silently(ep.periodic_orbit, 0.8, 1e-4, 0.1)
    linear = 1e-4 / abs(complex(1 - 0.8**2, 2 * 0.1 * 0.8))
    assert abs(orbit.amplitude / linear - 1) < 1e-6
    curve = _silently(ep.response_curve, 0.1, 0.1, frequencies=(1.2, 1.3), step=0.05)
    assert len(curve.orbits) >= 2


def _independent_period_map(frequency, forcing, damping, state):
    """One forcing period of theta'' + 2 zeta theta' + sin(theta) = F cos(Omega t) (omega0 = 1),
    by scipy's Radau on the plain 2-D system at rtol 1e-13: none of the library's code."""
    from scipy import integrate

    def field(t, y):
        return [y[1], forcing * math.cos(frequency * t) - 2 * damping * y[1] - math.sin(y[0])]

    def jacobian(t, y):
        return [[0.0, 1.0], [-math.cos(y[0]), -2 * damping]]

    return integrate.solve_ivp(field, (0.0, 2 * math.pi / frequency), list(state),
                               method="Radau", jac=jacobian, rtol=1e-13, atol=1e-22,
                               dense_output=True)


@pytest.mark.parametrize("damping", [100.0, 1000.0])
def test_periodic_orbit_under_heavy_damping_against_an_independent_integration(damping):
    orbit = ep.periodic_orbit(0.8, 0.2, damping)
    run = _independent_period_map(0.8, 0.2, damping, orbit.state)
    swing = orbit.amplitude
    # Periodic: back where it started after one period, to far below the shooting's 1e-10.
    assert np.max(np.abs(run.y[:, -1] - orbit.state)) < 1e-11 * swing
    # The amplitude: half of max - min over the period, brute force over 20001 samples.
    theta = run.sol(np.linspace(0.0, 2 * math.pi / 0.8, 20001))[0]
    assert abs(swing - 0.5 * (theta.max() - theta.min())) < 1e-8 * swing
    # The slow Floquet multiplier (the other is ~exp(-2 zeta 2 pi / Omega), 0 in doubles):
    # the largest eigenvalue of the monodromy by central differences of the independent map.
    h = 1e-4 * swing
    columns = []
    for e in np.eye(2):
        plus = _independent_period_map(0.8, 0.2, damping, orbit.state + h * e).y[:, -1]
        minus = _independent_period_map(0.8, 0.2, damping, orbit.state - h * e).y[:, -1]
        columns.append((plus - minus) / (2 * h))
    expected = np.max(np.abs(np.linalg.eigvals(np.column_stack(columns))))
    assert abs(np.max(np.abs(orbit.multipliers)) - expected) < 1e-7


def test_periodic_orbit_cost_does_not_grow_with_the_damping(monkeypatch):
    # The explicit integrator's steps are bounded by stability to ~1/(2 zeta omega0 / Omega):
    # at zeta = 1000 one period took ~1e5 evaluations of the field. Counted here (not timed):
    # each period must take fewer than 1e4, as at light damping.
    from elliptic_pendulum import resonance

    counts = []
    real = resonance.integrate.solve_ivp

    def counting(*args, **kwargs):
        sol = real(*args, **kwargs)
        counts.append(sol.nfev)
        return sol

    monkeypatch.setattr(resonance.integrate, "solve_ivp", counting)
    ep.periodic_orbit(0.8, 0.2, 1000.0)
    assert counts and max(counts) < 10_000
