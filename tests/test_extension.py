"""Lemma 2 as code: the extensions (20) and (21) against mpmath's sn and am.

References are mpmath at mp.dps = 30: ``mpmath.ellipfun('sn', u, m=k**2)`` (mpmath takes the
parameter m = k^2), and am from mpmath's sn, cn, checked in turn by ``mpmath.ellipf(am, m) == u``.
"""

import math

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from elliptic_pendulum.elliptic import cn, complete_integral, inverse_integral
from elliptic_pendulum.extension import (
    derivative_jump,
    one_sided_derivatives,
    periodic_extension,
    staircase_extension,
)

MODULI = [0.0, 0.1, 0.5, 0.9, 0.999]


def _mp_k_pair(k):
    """K1(k) as a float pair (hi, lo), hi the library's K1, hi + lo the true K1 (mpmath)."""
    hi = float(complete_integral(k))
    with mpmath.workdps(30):
        lo = float(mpmath.ellipk(mpmath.mpf(k) ** 2) - hi)
    return hi, lo


def _G(k):
    """The note's G (19) on [-K1, K1]; the clip keeps an r one ulp past the library's K1 legal."""
    K = float(complete_integral(k))
    return lambda r: inverse_integral(np.clip(r, -K, K), k)


def _I(k):
    """The note's I = arcsin G (40), written atan2(G, cn): arcsin near 1 would halve the digits."""
    K = float(complete_integral(k))

    def amplitude(r):
        r = np.clip(r, -K, K)
        return np.arctan2(inverse_integral(r, k), cn(r, k))

    return amplitude


def _mp_sn(u, k):
    with mpmath.workdps(30):
        return np.array([float(mpmath.ellipfun("sn", mpmath.mpf(x), m=mpmath.mpf(k) ** 2))
                         for x in np.ravel(u)])


def _mp_am(u, k):
    """am(u) = atan2(sn, cn) + 2 pi n, with n keeping am within pi of its secular part pi u / 2K."""
    out = []
    with mpmath.workdps(30):
        m = mpmath.mpf(k) ** 2
        K = mpmath.ellipk(m)
        for x in np.ravel(u):
            x = mpmath.mpf(x)
            phi = mpmath.atan2(mpmath.ellipfun("sn", x, m=m), mpmath.ellipfun("cn", x, m=m))
            phi += 2 * mpmath.pi * mpmath.nint((mpmath.pi * x / (2 * K) - phi) / (2 * mpmath.pi))
            # Independent check of the reference itself: am inverts the incomplete F (DLMF 22.16.1).
            assert abs(mpmath.ellipf(phi, m) - x) < mpmath.mpf(10) ** -20 * max(1, abs(x))
            out.append(float(phi))
    return np.array(out)


@pytest.mark.parametrize("k", MODULI)
@pytest.mark.parametrize(("umax", "tol"), [(100.0, 1e-14), (1e4, 1e-12)])
def test_periodic_extension_of_G_is_sn(k, umax, tol):
    # Note, after Lemma 2: G-bar, the extension (20) of G, is sn. Reference: mpmath sn.
    rng = np.random.default_rng(20)
    u = np.concatenate([rng.uniform(-umax, umax, 150), [0.0, umax, -umax]])
    Gbar = periodic_extension(_G(k), _mp_k_pair(k))
    np.testing.assert_allclose(Gbar(u), _mp_sn(u, k), rtol=0, atol=tol)


@pytest.mark.parametrize("k", [0.5, 0.9])
def test_periodic_extension_with_float_K_is_sn_for_moderate_u(k):
    # With a plain float K1 the reduction is exact for that float; |u| <= 100 keeps n dK tiny.
    u = np.random.default_rng(21).uniform(-100.0, 100.0, 150)
    Gbar = periodic_extension(_G(k), float(complete_integral(k)))
    np.testing.assert_allclose(Gbar(u), _mp_sn(u, k), rtol=0, atol=1e-14)


@pytest.mark.parametrize("k", MODULI)
@pytest.mark.parametrize("umax", [100.0, 1e4])
def test_staircase_extension_of_I_is_am(k, umax):
    # Note (40)-(41), (43): I-hat, the extension (21) of I = arcsin G, is am. Reference: mpmath.
    u = np.random.default_rng(22).uniform(-umax, umax, 150)
    Ihat = staircase_extension(_I(k), _mp_k_pair(k))
    expected = _mp_am(u, k)
    np.testing.assert_allclose(Ihat(u), expected, rtol=2e-15, atol=1e-14)


def test_staircase_extension_of_literal_arcsin_G_loses_half_the_digits_near_K():
    # The note's I = arcsin G, taken literally: arcsin'(1) is infinite, so near u = K1 an ulp in G
    # costs sqrt(ulp) ~ 1e-8 in I. Still am to 1e-7; the atan2 form above is the accurate one.
    k = 0.9
    K = _mp_k_pair(k)
    u = np.random.default_rng(23).uniform(-100.0, 100.0, 150)
    u = np.concatenate([u, K[0] * np.arange(-9.0, 10.0)])
    Ihat = staircase_extension(lambda r: np.arcsin(_G(k)(r)), K)
    np.testing.assert_allclose(Ihat(u), _mp_am(u, k), rtol=0, atol=1e-7)


def test_periodic_extension_follows_definition_20_piecewise():
    # (20) literally: f on [-a, a], -f(x - 2a) on [a, 3a], then period 4a.
    a = 0.75
    f = np.arctan
    x = np.linspace(a, 3 * a, 101)
    fbar = periodic_extension(f, a)
    np.testing.assert_allclose(fbar(x), -f(x - 2 * a), rtol=0, atol=1e-15)
    np.testing.assert_allclose(fbar(x - 2 * a), f(x - 2 * a), rtol=0, atol=1e-15)
    np.testing.assert_allclose(fbar(x + 8 * a), -f(x - 2 * a), rtol=0, atol=1e-14)


def test_staircase_extension_follows_definition_21_piecewise():
    # (21) literally: f(x - 2ma) + 2m f(a) on [(2m-1)a, (2m+1)a], here m = -3 and m = 2.
    a = 1.3
    f = np.arctan
    fhat = staircase_extension(f, a)
    for m in (-3, 2):
        x = np.linspace((2 * m - 1) * a, (2 * m + 1) * a, 51)
        np.testing.assert_allclose(fhat(x), f(x - 2 * m * a) + 2 * m * f(a), rtol=0, atol=1e-14)


# Lemma 2.2 and 2.3: the hypotheses are what make the extensions smooth.


def test_periodic_extension_of_G_is_C2_at_K():
    # G'(K1-0) = 0 (Prop. 1.3), G''(K1-0) = alpha^2 - 1 (after (23)): one-sided limits agree.
    k = 0.8
    K = float(complete_integral(k))
    Gbar = periodic_extension(_G(k), _mp_k_pair(k))
    assert abs(derivative_jump(Gbar, K)) < 1e-8
    left, right = one_sided_derivatives(Gbar, K, order=2)
    assert left == pytest.approx(k**2 - 1, abs=1e-5)
    assert right == pytest.approx(k**2 - 1, abs=1e-5)


@pytest.mark.parametrize(("f", "a"), [(lambda x: x, 1.0), (np.sin, 1.0), (np.arctan, 2.0)])
def test_periodic_extension_without_zero_slope_has_a_corner(f, a):
    # f'(a-0) != 0 violates Lemma 2.2's hypothesis: f-bar is continuous at a but its slope flips
    # from f'(a) to -f'(a). Expected slopes: calculus (1, cos 1, 1/(1 + a^2)).
    fbar = periodic_extension(f, a)
    h = 1e-9
    assert abs(fbar(a + h) - fbar(a - h)) < 1e-8  # continuous
    left, right = one_sided_derivatives(fbar, a)
    slope = (f(a + 1e-6) - f(a - 1e-6)) / 2e-6
    assert left == pytest.approx(slope, rel=1e-6)
    assert right == pytest.approx(-slope, rel=1e-6)
    assert derivative_jump(fbar, a) == pytest.approx(-2 * slope, rel=1e-6)


def test_staircase_extension_of_I_is_C2_at_K():
    # I'(K1-0) = sqrt(1 - k^2) = kc and I''(K1-0) = 0 ((42) and the line after it).
    k = 0.8
    K = float(complete_integral(k))
    Ihat = staircase_extension(_I(k), _mp_k_pair(k))
    left, right = one_sided_derivatives(Ihat, K)
    assert left == pytest.approx(0.6, abs=1e-8)
    assert right == pytest.approx(0.6, abs=1e-8)
    assert abs(derivative_jump(Ihat, K, order=2)) < 1e-5


def test_staircase_extension_without_zero_curvature_is_only_C1():
    # f = sin on [-1, 1]: f'(1) = cos 1 is finite but f''(1-0) = -sin 1 != 0, so Lemma 2.3 gives C1
    # only: f-hat'' jumps from -sin 1 to +sin 1.
    fhat = staircase_extension(np.sin, 1.0)
    assert abs(derivative_jump(fhat, 1.0)) < 1e-8
    left, right = one_sided_derivatives(fhat, 1.0, order=2)
    assert left == pytest.approx(-math.sin(1.0), abs=1e-5)
    assert right == pytest.approx(math.sin(1.0), abs=1e-5)


# Properties (hypothesis): oddness (Lemma 2.2 and 2.3) and the period 4a / step 2 f(a).

finite_x = st.floats(-1e3, 1e3, allow_nan=False)
half_width = st.floats(0.1, 10.0)


@settings(max_examples=200, deadline=None)
@given(x=finite_x, a=half_width)
def test_periodic_extension_is_odd_and_4a_periodic(x, a):
    fbar = periodic_extension(np.sin, a)
    assert fbar(-x) == -fbar(x)  # exact: the reduction is symmetric and np.sin is odd
    y = x + 4 * a
    # y is x + 4a rounded: the quotient sees that rounding, |f'| <= 1 times ulp(y).
    assert abs(fbar(y) - fbar(x)) <= abs(y - 4 * a - x) + 4e-16 * (abs(x) + 4 * a) + 1e-300


@settings(max_examples=200, deadline=None)
@given(x=finite_x, a=half_width)
def test_staircase_extension_is_odd_and_steps_by_2fa(x, a):
    fhat = staircase_extension(np.arctan, a)
    assert fhat(-x) == -fhat(x)
    y = x + 2 * a
    expected = fhat(x) + 2 * np.arctan(a)
    assert abs(fhat(y) - expected) <= 4e-16 * (abs(x) + abs(expected) + 2 * a) + abs(y - 2 * a - x)


@settings(max_examples=50, deadline=None)
@given(x=finite_x, k=st.floats(0.0, 0.99))
def test_extended_G_is_odd_and_bounded(x, k):
    Gbar = periodic_extension(_G(k), float(complete_integral(k)))
    v = Gbar(x)
    assert -1.0 <= v <= 1.0
    assert Gbar(-x) == pytest.approx(-v, abs=1e-15)


def test_shapes_and_non_finite_input():
    fbar = periodic_extension(_G(0.5), float(complete_integral(0.5)))
    assert isinstance(fbar(1.0), float)
    assert fbar(np.zeros((2, 3))).shape == (2, 3)
    # inf and nan give nan, and G (which raises outside [-K1, K1]) is never called with them.
    out = fbar(np.array([np.inf, -np.inf, np.nan, 0.0]))
    assert np.isnan(out[:3]).all() and out[3] == 0.0


@pytest.mark.parametrize("a", [0.0, -1.0, math.nan, math.inf, (1.0, 1.0)])
def test_bad_half_width_raises_value_error_naming_a(a):
    with pytest.raises(ValueError, match=r"\ba must be"):
        periodic_extension(np.sin, a)
    with pytest.raises(ValueError, match=r"\ba must be"):
        staircase_extension(np.sin, a)


def test_non_callable_and_non_numeric_raise_type_error():
    with pytest.raises(TypeError, match="f must be a callable"):
        periodic_extension(3.0, 1.0)
    with pytest.raises(TypeError, match="f must be a callable"):
        staircase_extension(None, 1.0)
    with pytest.raises(TypeError, match=r"\ba must be"):
        periodic_extension(np.sin, "one")


@pytest.mark.parametrize(("kwargs", "name"), [({"order": 3}, "order"), ({"h": -1.0}, "h")])
def test_bad_difference_quotient_options_raise(kwargs, name):
    with pytest.raises(ValueError, match=rf"\b{name} must be"):
        one_sided_derivatives(np.sin, 0.0, **kwargs)
