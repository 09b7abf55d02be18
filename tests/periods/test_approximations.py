"""Tests of approximations.py: each lab formula against R from mpmath, at the order it claims.

References: mpmath.ellipk at 50 digits from the exact double amplitude; the small-amplitude
errors from sympy's series of each formula against R's (OEIS A223067: 1 + x^2/16 + 11 x^4/3072);
DLMF 19.12.1 for the logarithmic law; the AGM's quadratic convergence (DLMF 19.8.1).
"""

import math

import numpy as np
import pytest
import sympy as sp

from elliptic_pendulum.periods import (
    agm_ratio,
    kidd_fogg_ratio,
    lima_arun_ratio,
    log_ratio,
    ratio_approximations,
)
from tests import mpref
from tests.strict import quietly as _silently


def test_agm_steps_converge_quadratically():
    for degrees in (30, 90, 150, 175):
        a = math.radians(degrees)
        exact = mpref.ratio(a, 50)
        errors = [float(exact - agm_ratio(a, n)) for n in range(6)]
        useful = [e for e in errors if e > 1e-13]
        assert all(e > -1e-15 for e in errors)  # 1/a_n increases toward R (to rounding)
        # each error at most the square of the previous (times a constant below 1): digits double
        assert all(b < a**2 for a, b in zip(useful, useful[1:], strict=False)), errors
        assert errors[-1] < 1e-14 * float(exact)


def test_agm_ratio_first_steps():
    a = np.radians([0, 40, 100])
    assert np.all(agm_ratio(a, 0) == 1)
    assert np.allclose(agm_ratio(a, 1), 2 / (1 + np.cos(a / 2)), rtol=1e-15)


def test_log_law_errors_shrink_like_powers_of_kc():
    # DLMF 19.12.1: one term errs by O(kc^2 log kc), two terms by O(kc^4 log kc)
    for kc in (1e-1, 1e-2, 1e-3):
        a = 2 * math.acos(kc)
        exact = mpref.ratio(a, 50)
        kc_true = math.cos(a / 2)
        one, two = float(exact - log_ratio(a, 1)), float(exact - log_ratio(a, 2))
        scale = kc_true**2 * math.log(4 / kc_true)
        assert 0.1 * scale < abs(one) < scale
        assert abs(two) < kc_true**4 * math.log(4 / kc_true) + 1e-15


x = sp.symbols("x", positive=True)
R_SERIES = 1 + x**2 / 16 + sp.Rational(11, 3072) * x**4


@pytest.mark.parametrize("function, formula", [
    (kidd_fogg_ratio, 1 / sp.sqrt(sp.cos(x / 2))),
    (lima_arun_ratio, -sp.log(sp.cos(x / 2)) / (1 - sp.cos(x / 2))),
])
def test_small_amplitude_error_is_the_fourth_order_gap(function, formula):
    # the x^4 gap between the formula's series (sympy) and R's: 1/1024 and 1/3072
    gap = sp.series(formula, x, 0, 6).removeO() - R_SERIES
    assert sp.expand(gap).coeff(x, 2) == 0
    c4 = float(sp.expand(gap).coeff(x, 4))
    for a in (0.02, 0.05):
        measured = float(function(a) - mpref.ratio(a, 50)) / a**4
        assert abs(measured / c4 - 1) < 0.01


def test_lima_arun_and_kidd_fogg_at_large_amplitude():
    # Lima and Arun quote below 0.25%: true at 90 degrees, not at 120
    rel = [float(lima_arun_ratio(math.radians(d)) / mpref.ratio(math.radians(d), 50) - 1)
           for d in (30, 60, 90, 120)]
    assert all(0 < r < 0.0025 for r in rel[:3]) and rel[3] > 0.0025
    # near the top Lima-Arun overshoots by a factor tending (slowly, like 1/log kc) to pi/2,
    # Kidd-Fogg without bound
    a = math.pi - 1e-12
    assert abs(float(lima_arun_ratio(a) / mpref.ratio(a, 50)) - math.pi / 2) < 0.1
    assert kidd_fogg_ratio(a) > 100 * float(mpref.ratio(a, 50))


def test_lima_arun_keeps_its_digits_at_small_amplitude():
    # -log(a)/(1-a) formed naively loses everything below 1e-8 rad; the log1p form does not
    for a in (1e-9, 1e-5):
        assert abs(lima_arun_ratio(a) - (1 + a**2 / 16)) < 1e-15
    assert lima_arun_ratio(0.0) == 1.0


def test_ratio_approximations_table():
    a = np.radians([10, 90, 170])
    table = ratio_approximations(a)
    assert set(table) == {"small angle", "series 2", "series 4", "AGM 1", "AGM 2", "AGM 3",
                          "log", "log 2", "Kidd-Fogg", "Lima-Arun"}
    assert all(np.shape(v) == (3,) for v in table.values())
    assert np.all(table["AGM 3"] <= [float(mpref.ratio(t, 50)) for t in a])


@pytest.mark.parametrize("function", [kidd_fogg_ratio, lima_arun_ratio, ratio_approximations,
                                      lambda a: agm_ratio(a, 2), lambda a: log_ratio(a, 1)])
@pytest.mark.parametrize("bad", [-0.1, math.pi, math.nan])
def test_approximations_refuse_non_swings(function, bad):
    with pytest.raises(ValueError, match="theta0"):
        function(bad)


def test_steps_and_terms_are_checked():
    with pytest.raises(ValueError, match="steps"):
        agm_ratio(1.0, -1)
    with pytest.raises(ValueError, match="terms"):
        log_ratio(1.0, 3)


@pytest.mark.parametrize("theta0", [math.pi - 1e-12, math.nextafter(math.pi, 0), 3.0, 2.5,
                                    2.0943951023931953, 2.0, 1.0, 1e-3, 1e-8])
def test_lima_arun_ratio_is_its_formula_to_a_few_ulp(theta0):
    # Near the top 1 - x (x = 2 sin^2(theta0/4)) kept only x's absolute rounding: at
    # pi - 1e-12 the result was 4.3e-6 off. Reference: -log(a)/(1 - a), a = cos(theta0/2) of
    # the exact double theta0, in mpmath at 60 digits.
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 60
    a = ctx.cos(ctx.mpf(theta0) / 2)
    expected = -ctx.log(a) / (1 - a)
    got = _silently(lima_arun_ratio, theta0)
    assert abs(got - expected) <= 4 * 2.0**-52 * expected
