"""Tests of series.py: the Maclaurin series of R, its radius, the nome, the Fourier series.

References: the published sequences OEIS A223067 (numerators) and A223068 (denominators);
sympy's series of (2/pi) K(sin^2(x/2)) (sympy's elliptic_k takes the parameter m); Luschny's
formula on OEIS A223067, a(n) = (2n)!^-1 [x^n] exp(sum_k (-1)^k E_2k x^k / (2k)) with Euler
numbers E (a derivation that shares nothing with ours); mpmath.ellipk and mpmath.qfrom at 40-60
digits; numpy's FFT of the library's exact theta(t).
"""

import math
from fractions import Fraction

import mpmath
import numpy as np
import pytest
import sympy as sp

import elliptic_pendulum as ep
from elliptic_pendulum.periods import (
    fourier_coefficients,
    nome,
    period_series,
    period_series_coefficients,
)
from tests import mpref

# OEIS A223067 and A223068 (Johannes W. Meijer, 2013), as published.
OEIS_NUMERATORS = [
    1, 1, 11, 173, 22931, 1319183, 233526463, 2673857519, 39959591850371, 8797116290975003,
    4872532317019728133, 1657631603843299234219, 247098748783812523360613,
    77729277912104164732573547, 1503342018433974345747514544039,
]
OEIS_DENOMINATORS = [
    1, 16, 3072, 737280, 1321205760, 951268147200, 2009078326886400, 265928913086054400,
    44931349155019751424000, 109991942731488351485952000, 668751011807449177034588160000,
    2471703739640332158319837839360000,
]


def test_coefficients_match_the_published_sequences():
    a = period_series_coefficients(len(OEIS_NUMERATORS))
    assert [c.numerator for c in a] == OEIS_NUMERATORS
    assert [c.denominator for c in a[: len(OEIS_DENOMINATORS)]] == OEIS_DENOMINATORS
    assert all(isinstance(c, Fraction) for c in a)


def test_coefficients_match_sympys_series():
    x = sp.symbols("x")
    n = 7  # sympy's series takes 0.7 s to x^14, 7 s to x^16
    series = sp.series(2 / sp.pi * sp.elliptic_k(sp.sin(x / 2) ** 2), x, 0, 2 * n).removeO()
    expected = [sp.Rational(series.coeff(x, 2 * j)) for j in range(n)]
    got = period_series_coefficients(n)
    assert [sp.Rational(c.numerator, c.denominator) for c in got] == expected


def luschny(n):
    """OEIS A223067 (Peter Luschny, 2017): exp of a series in Euler numbers, then / (2n)!.

    His formula gives the numerators; the coefficient itself also carries 1/4^n (the series is
    in (theta0/2)^2 there), which a_1 = 1/16 fixes.
    """
    s = [Fraction(0)] + [Fraction((-1) ** k * int(sp.euler(2 * k)), 2 * k) for k in range(1, n)]
    # e = exp(s) as a power series: e' = s' e, i.e. i e_i = sum_j j s_j e_(i-j).
    e = [Fraction(1)] + [Fraction(0)] * (n - 1)
    for i in range(1, n):
        e[i] = sum(j * s[j] * e[i - j] for j in range(1, i + 1)) / i
    return [e[i] / (math.factorial(2 * i) * 4**i) for i in range(n)]


def test_sixty_coefficients_match_luschnys_formula():
    assert period_series_coefficients(60) == luschny(60)


def test_radius_of_convergence_is_pi():
    # A logarithmic singularity at +-pi, -(2/pi) log(1 - x^2/pi^2): a_n ~ (2/pi) / (n pi^(2n)).
    # Exact rationals, so the ratio test is free of rounding: at n = 150 the ratio sits 7e-5
    # from pi and the constant 9e-6 from 2/pi, both shrinking like 1/n.
    a = period_series_coefficients(151)
    n = 150
    assert abs(math.sqrt(n * a[n - 1] / ((n + 1) * a[n])) - math.pi) < 1e-4
    assert abs(n * float(a[n] * Fraction(math.pi) ** (2 * n)) - 2 / math.pi) < 2e-5




@pytest.mark.parametrize("degrees, terms", [(10, 4), (45, 6), (90, 12), (150, 30), (170, 40)])
def test_partial_sums_miss_r_by_their_tail(degrees, terms):
    # Positive coefficients whose ratio a_(n+1)/a_n rises toward 1/pi^2: the tail lies between
    # its first term and that term / (1 - theta0^2/pi^2).
    theta0 = math.radians(degrees)
    error = float(mpref.ratio(theta0, 40)) - period_series(theta0, terms)
    first = float(period_series_coefficients(terms + 1)[-1]) * theta0 ** (2 * terms)
    rounding = 4e-16 * float(mpref.ratio(theta0, 40))
    assert first - rounding <= error <= first / (1 - (theta0 / math.pi) ** 2) + rounding


def test_period_series_is_even_and_vectorized():
    theta0 = np.array([[-1.0, 0.5], [0.0, 3.0]])
    got = period_series(theta0, 10)
    assert got.shape == (2, 2)
    assert got[0, 0] == period_series(1.0, 10)
    assert got[1, 0] == 1.0


@pytest.mark.parametrize("bad", [math.pi, -math.pi, 4.0, math.inf, math.nan])
def test_period_series_refuses_amplitudes_outside_the_disc(bad):
    with pytest.raises(ValueError, match="theta0"):
        period_series(bad, 3)


@pytest.mark.parametrize("bad, error", [(0, ValueError), (-2, ValueError), (2.0, TypeError),
                                        (True, TypeError)])
def test_number_of_terms_is_a_positive_integer(bad, error):
    with pytest.raises(error, match="n"):
        period_series_coefficients(bad)
    with pytest.raises(error, match="terms"):
        period_series(0.1, bad)


def digits(x):
    """Enough digits for mpmath's qfrom, which forms 1 - k^2 (and k from 1 - kc^2) itself."""
    return 60 + int(2 * abs(math.log10(x)))


def mp_nome_from_k(k):
    with mpmath.workdps(digits(k)):
        return mpmath.qfrom(k=mpmath.mpf(float(k)))


def mp_nome_from_kc(kc):
    with mpmath.workdps(digits(kc)):
        kc = mpmath.mpf(float(kc))
        return mpmath.qfrom(m=1 - kc * kc)


def test_nome_matches_mpmath_for_small_k():
    k = np.concatenate([np.geomspace(1e-150, 0.9, 80), [0.5**0.5, 0.99]])
    got = nome(k)
    rel = [abs(g / float(mp_nome_from_k(x)) - 1) for g, x in zip(got, k, strict=True)]
    # exp(-x) with x = pi K'/K up to 700: a relative error of x * eps would show as 1e-13.
    assert max(rel) < 2e-15


def test_nome_matches_mpmath_for_small_kc():
    kc = np.geomspace(1e-300, 0.5, 80)
    got = nome(np.sqrt((1 - kc) * (1 + kc)), kc=kc)
    rel = [abs(g / float(mp_nome_from_kc(x)) - 1) for g, x in zip(got, kc, strict=True)]
    assert max(rel) < 1e-15
    # 1 - q carries the information near the separatrix: it must be right too, to rounding of q.
    one_minus = [abs((1 - g) - float(1 - mp_nome_from_kc(x))) for g, x in zip(got, kc,
                                                                             strict=True)]
    assert max(one_minus) < 2e-16


def test_nome_edges_and_errors():
    assert nome(0.0) == 0.0
    assert nome(1.0) == 1.0
    assert nome(None, kc=0.0) == 1.0
    assert np.shape(nome([0.1, 0.2])) == (2,)
    with pytest.raises(ValueError, match="k"):
        nome(1.5)
    with pytest.raises(ValueError, match="kc"):
        nome(0.5, kc=-0.1)


def fft_sine_coefficients(theta0, count, samples=256):
    """b_j from an FFT of the exact motion, time shifted so that t = 0 is the upward bottom
    passage (ep.solve releases from rest at t = 0 and passes the bottom upwards at 3T/4)."""
    motion = ep.solve(theta0)
    T = motion.period
    t = np.arange(samples) * T / samples
    spectrum = np.fft.rfft(motion.theta(t + 0.75 * T))
    harmonics = 2 * np.arange(count) + 1
    return -2 * spectrum[harmonics].imag / samples, spectrum


@pytest.mark.parametrize("degrees", [1, 30, 90, 150, 179, 179.999])
def test_fourier_coefficients_match_an_fft_of_the_motion(degrees):
    theta0 = math.radians(degrees)
    samples = 4096 if degrees > 178 else 256
    fft_b, spectrum = fft_sine_coefficients(theta0, 20, samples)
    b = fourier_coefficients(theta0, 20)
    assert np.max(np.abs(b - fft_b)) < 2e-14
    # the even harmonics and every cosine part vanish (odd about the passage, half-wave symmetry)
    assert np.max(np.abs(spectrum[0::2])) / samples < 1e-13 * max(1, samples / 256)
    assert np.max(np.abs(spectrum.real)) / samples < 1e-13 * max(1, samples / 256)


def test_fourier_coefficients_limits():
    # small amplitude: b_0 -> theta0 and b_1 / b_0 -> q / 3 ~ theta0^2 / 192 (q ~ k^2/16)
    theta0 = 1e-3
    b = fourier_coefficients(theta0, 3)
    assert abs(b[0] / theta0 - 1) < 1e-7
    assert abs(b[1] / b[0] / (theta0**2 / 192) - 1) < 1e-3
    # toward the separatrix the swing tends to a square wave of height pi, b_j = 4/(2j+1), slowly
    # (b_j (2j+1)/4 = sech((j+1/2) pi K'/K) and K ~ log(4/kc)): monotone, above 0.9 at the top
    scaled = [fourier_coefficients(a, 3) * (2 * np.arange(3) + 1) / 4
              for a in (3.0, math.pi - 1e-8, math.nextafter(math.pi, 0))]
    assert np.all(np.diff(scaled, axis=0) > 0) and np.all(scaled[-1] > 0.9)
    assert np.all(scaled[-1] < 1)
    assert np.all(fourier_coefficients(0.0, 4) == 0)
    assert fourier_coefficients([[0.1, 0.2]], 5).shape == (1, 2, 5)


@pytest.mark.parametrize("bad", [-0.1, math.pi, 4.0])
def test_fourier_coefficients_refuse_non_swings(bad):
    with pytest.raises(ValueError, match="theta0"):
        fourier_coefficients(bad, 3)


def test_nome_is_good_to_a_few_ulp_for_every_modulus():
    # Just above k = 1/2 q came from exp(-pi K'/K) with an exponent near 4, whose rounding
    # left q 5 ulp off (1.1e-15). Reference: mpmath's qfrom at 60+ digits.
    rng = np.random.default_rng(20240)
    k = np.concatenate([rng.uniform(0.5, 0.52, 600), rng.uniform(0.0, 1.0, 600),
                        1 - np.geomspace(1e-12, 0.5, 100)])
    got = nome(k)
    rel = [abs(g / float(mp_nome_from_k(x)) - 1) for g, x in zip(got, k, strict=True)]
    assert max(rel) < 3 * 2.0**-52
