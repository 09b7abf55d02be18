"""The periods at their edges: limits named by omega0, subnormal amplitudes, the Fourier
coefficients of tiny swings, the exact series coefficients computed once.

References: mpmath at high precision (closed forms and quadrature of the exact motion), the
series composed from DLMF 19.5.1."""

import math

import numpy as np
import pytest

import elliptic_pendulum as ep
from tests import mpref
from tests.strict import quietly as _silently


@pytest.mark.parametrize("name", ["period", "agm_period"])
@pytest.mark.parametrize("omega0", [1e-308, 3e-308, 1e-320])
def test_period_beyond_the_doubles_is_refused_naming_omega0(name, omega0):
    # The true period is larger than the largest double (mpmath says so), so neither inf
    # (period) nor an underflow warning (agm_period) is a right answer: a ValueError is.
    assert mpref.period(1.0, omega0) > np.finfo(float).max
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
    expected = float(mpref.period(1.0, 4e-308))
    assert abs(got - expected) <= 4e-16 * expected


@pytest.mark.parametrize("name", ["period_ratio", "period", "agm_period"])
@pytest.mark.parametrize("theta0", [1e-320, 5e-324, 3e-323])
def test_periods_of_subnormal_amplitudes_are_quiet(name, theta0):
    # R = 1 + theta0^2/16 + ... (DLMF 19.5.1) is 1 to rounding for theta0 < 1e-8; the
    # underflow of theta0 / 2 on the way is no reason for a warning.
    expected = 1.0 if name == "period_ratio" else 2 * math.pi
    assert _silently(getattr(ep, name), theta0) == expected


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
    from elliptic_pendulum.periods import series

    expected = ep.period_series(0.5, 150)
    coefficients = ep.period_series_coefficients(150)

    def forbidden(n):
        raise AssertionError("the exact coefficients were recomputed")

    monkeypatch.setattr(series, "_binomials", forbidden)
    assert ep.period_series(0.5, 150) == expected
    assert ep.period_series_coefficients(150) == coefficients
    assert ep.period_series_coefficients(120) == coefficients[:120]


def _exact_partial_sum(theta0, terms):
    """sum_{j < terms} a_j theta0^2j from the exact fractions, in mpmath at 60 digits."""
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 60
    x = ctx.mpf(theta0) ** 2
    total = ctx.mpf(0)
    for a in reversed(ep.period_series_coefficients(terms)):
        total = total * x + ctx.mpf(a.numerator) / a.denominator
    return total


@pytest.mark.parametrize("terms", [331, 400, 700])
def test_period_series_beyond_330_terms_against_the_exact_partial_sums(terms):
    # The coefficients a_j ~ pi^(-2j) leave the doubles near j = 330: summed as doubles, every
    # term from there on was 0 and period_series(3.14, 400) was the 330-term sum 4.8889.
    # Reference: the exact rational coefficients summed in mpmath at 60 digits. The tolerance
    # is the conditioning of the sum near the radius (theta0 d log R_N / d theta0 ~ 400),
    # times a few roundings.
    expected = float(_exact_partial_sum(3.14, terms))
    assert abs(_silently(ep.period_series, 3.14, terms) / expected - 1) < 2e-13


def test_period_series_with_very_many_terms_reaches_r():
    # 60,000 terms at 3.14 rad: the tail beyond is about r^60000 / (1 - r) with
    # r = (3.14/pi)^2, below 1e-24. Reference R = (2/pi) K(sin^2(1.57)) from mpmath at 50 digits.
    got = _silently(ep.period_series, np.array([3.14, -1.0]), 60_000)
    expected = np.array([float(mpref.ratio(3.14)), float(mpref.ratio(-1.0))])
    assert np.all(np.abs(got / expected - 1) < 1e-12)


def test_scaled_coefficients_against_the_exact_ones():
    # b_j = a_j c^2j (c = math.pi) from the fixed-point recurrence, against the exact rational
    # a_j times the exact dyadic c^2j, rounded once: the same double up to an ulp.
    from fractions import Fraction

    from elliptic_pendulum.periods._scaled import scaled_coefficients

    exact = ep.period_series_coefficients(700)
    got = scaled_coefficients(700)
    c2 = Fraction(math.pi) ** 2
    for j in (0, 1, 2, 50, 329, 330, 331, 500, 699):
        expected = float(exact[j] * c2**j)
        assert abs(got[j] - expected) <= 2.0**-52 * expected, j


def test_period_series_refuses_more_terms_than_it_sums():
    from elliptic_pendulum.periods._scaled import MAX_TERMS

    with pytest.raises(ValueError, match=r"terms must be at most 1,000,000.*got 1000001"):
        ep.period_series(3.0, MAX_TERMS + 1)


def test_period_series_of_a_tiny_amplitude_is_quiet():
    # theta0^2 underflows; the sum is 1 to rounding (a_1 theta0^2 < 1e-400).
    assert _silently(ep.period_series, 1e-200, 400) == 1.0


@pytest.mark.parametrize("value", [1 + 2.0**-52, 1 + 1e-12, 1 + 1e-8, 1.001, 1.3, 1.9999])
def test_crossing_angle_near_one_keeps_its_relative_accuracy(value):
    # R - v cancelled near v = 1, and theta0 = pi - x kept only the absolute accuracy of x:
    # crossing_angle(1 + 1e-12) was 4.0001225e-06 for 4.0001778e-06. Reference: the root of
    # (2/pi) K(sin^2(theta/2)) = v by mpmath at 60 digits, bracketed by R - 1 >= theta^2/16.
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 60
    v = ctx.mpf(value)
    high = min(4 * ctx.sqrt(v - 1) * (1 + ctx.mpf("1e-6")), ctx.mpf("2.8"))
    expected = ctx.findroot(lambda t: 2 / ctx.pi * ctx.ellipk(ctx.sin(t / 2) ** 2) - v,
                            (high / 2, high), solver="anderson")
    got = _silently(ep.crossing_angle, value)
    assert abs(got - expected) <= 4 * 2.0**-52 * expected
