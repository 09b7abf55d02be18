"""Tests of elliptic.py: sn, cn, dn, am, K1 (18), E1 (17) and G (19) against mpmath.

References: mpmath (``ellipfun``, ``ellipf``, ``agm``) at 80 digits, with the parameter
m = 1 - kc**2 formed in high precision from the exact double kc, so that the reference knows the
modulus the library was given (near the separatrix k rounds to 1.0 and only kc carries it).
K is taken from the AGM (DLMF 19.8.5), not from ``mpmath.ellipk``, which is inaccurate near
m = 1 at modest precision. Identities cite DLMF chapter 22.
"""

import math

import mpmath
import numpy as np
import pytest
from scipy import special

from elliptic_pendulum.elliptic import (
    am,
    cn,
    complete_integral,
    dn,
    incomplete_integral,
    inverse_integral,
    jacobi,
    sn,
)
from tests import mpref

DPS = 80

# From k = 0 (kc = 1) to the separatrix: below kc ~ 1e-8 the modulus k is 1.0 in floating point.
KC_GRID = [1.0, 0.99, 0.9, 0.7, 0.5, 0.3, 0.1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12,
           1e-13, 1e-14, 1e-15]


def k_of(kc):
    """The double modulus that goes with kc (what a caller would pass as k)."""
    return math.sqrt((1.0 - kc) * (1.0 + kc))


def mp_parameter(kc):
    """mpmath's parameter m = 1 - kc**2, exact from the double kc."""
    return 1 - mpmath.mpf(kc) ** 2


def mp_quarter(kc):
    """K = pi / (2 AGM(1, kc)) (DLMF 19.8.5), accurate at every kc > 0."""
    return mpmath.pi / (2 * mpmath.agm(1, mpmath.mpf(kc)))


def mp_jacobi(us, kc):
    """sn, cn, dn from mpmath at DPS digits, for the parameter 1 - kc**2 exact from kc."""
    with mpmath.workdps(DPS):
        return mpref.jacobi(us, mp_parameter(kc), DPS)


def mp_am(u, kc):
    """am(u) = n pi + asin(sn(u - 2 n K)), n = round(u / 2K) (DLMF 22.16.1-2)."""
    with mpmath.workdps(DPS):
        m, K = mp_parameter(kc), mp_quarter(kc)
        u = mpmath.mpf(float(u))
        n = mpmath.nint(u / (2 * K))
        return float(n * mpmath.pi + mpmath.asin(mpmath.ellipfun("sn", u - 2 * n * K, m=m)))


def u_grid(umax, n=61):
    # Not symmetric and not on multiples of K, so no point is special by accident.
    rng = np.random.default_rng(int(umax))
    return np.concatenate([np.linspace(-umax, umax, n) + 0.1234567,
                           rng.uniform(-umax, umax, n // 2)])


WORST: dict[str, float] = {}


def _record(name, value):
    WORST[name] = max(WORST.get(name, 0.0), float(value))


# --- sn, cn, dn against mpmath over grids --------------------------------------------------

@pytest.mark.parametrize("kc", KC_GRID)
@pytest.mark.parametrize(("umax", "abs_tol", "rel_tol"), [(100.0, 1e-14, 1e-13),
                                                           (1e4, 1e-12, 1e-13)])
def test_sn_cn_dn_match_mpmath(kc, umax, abs_tol, rel_tol):
    # Issue requirement: sn, cn absolute error <= 1e-14 (|u| <= 100), <= 1e-12 (|u| <= 1e4);
    # dn relative error <= 1e-13 on both ranges, for kc from 1 down to 1e-15.
    us = u_grid(umax)
    s_ref, c_ref, d_ref = mp_jacobi(us, kc)
    s, c, d = jacobi(us, k_of(kc), kc=kc)
    err_s = np.max(np.abs(s - s_ref))
    err_c = np.max(np.abs(c - c_ref))
    err_d = np.max(np.abs(d - d_ref) / d_ref)
    _record(f"sn abs |u|<={umax:g}", err_s)
    _record(f"cn abs |u|<={umax:g}", err_c)
    _record(f"dn rel |u|<={umax:g}", err_d)
    assert err_s <= abs_tol, (kc, us[np.argmax(np.abs(s - s_ref))], err_s)
    assert err_c <= abs_tol, (kc, us[np.argmax(np.abs(c - c_ref))], err_c)
    assert err_d <= rel_tol, (kc, us[np.argmax(np.abs(d - d_ref) / d_ref)], err_d)
    # The single-function entry points return the same numbers as jacobi().
    np.testing.assert_array_equal(sn(us, k_of(kc), kc=kc), s)
    np.testing.assert_array_equal(cn(us, k_of(kc), kc=kc), c)
    np.testing.assert_array_equal(dn(us, k_of(kc), kc=kc), d)


@pytest.mark.parametrize("k", [0.3, 0.8, 0.999])
def test_modulus_given_as_k_only_matches_mpmath(k):
    # Without kc the library forms kc = sqrt((1-k)(1+k)); mpmath gets m = k**2 exactly.
    us = u_grid(100.0, 41)
    with mpmath.workdps(DPS):
        m = mpmath.mpf(k) ** 2
        ref = np.array([[float(mpmath.ellipfun(f, mpmath.mpf(float(u)), m=m))
                         for f in ("sn", "cn", "dn")] for u in us])
    s, c, d = jacobi(us, k)
    assert np.max(np.abs(s - ref[:, 0])) <= 1e-14
    assert np.max(np.abs(c - ref[:, 1])) <= 1e-14
    assert np.max(np.abs(d - ref[:, 2]) / ref[:, 2]) <= 1e-13


def test_k_zero_is_trigonometric_to_an_ulp():
    # DLMF 22.5(ii): sn(u, 0) = sin u, cn(u, 0) = cos u, dn(u, 0) = 1, am(u, 0) = u.
    us = u_grid(1e4)
    assert np.max(np.abs(sn(us, 0.0) - np.sin(us))) <= 2.3e-16
    assert np.max(np.abs(cn(us, 0.0) - np.cos(us))) <= 2.3e-16
    np.testing.assert_array_equal(dn(us, 0.0), np.ones_like(us))
    assert np.max(np.abs(am(us, 0.0) - us) / np.maximum(np.abs(us), 1)) <= 4.5e-16


def test_k_zero_is_exactly_trigonometric():
    # The module promises the k = 0 edge "handled first, explicitly": exactly numpy's values.
    us = u_grid(1e4)
    np.testing.assert_array_equal(sn(us, 0.0), np.sin(us))
    np.testing.assert_array_equal(cn(us, 0.0), np.cos(us))
    np.testing.assert_array_equal(sn(us, 0.0, kc=1.0), np.sin(us))
    np.testing.assert_array_equal(am(us, 0.0), us)


@pytest.mark.parametrize("kwargs", [{"k": 1.0}, {"k": 1.0, "kc": 0.0}, {"k": 0.5, "kc": 0.0}])
def test_kc_zero_is_exactly_hyperbolic(kwargs):
    # DLMF 22.5(ii): at k = 1, sn = tanh, cn = dn = sech, am = gd (the note's (28)).
    us = np.concatenate([u_grid(100.0), [0.0, 700.0, -700.0]])
    sech = 1.0 / np.cosh(us)
    s, c, d = jacobi(us, **kwargs)
    np.testing.assert_array_equal(s, np.tanh(us))
    np.testing.assert_array_equal(c, sech)
    np.testing.assert_array_equal(d, sech)
    np.testing.assert_array_equal(am(us, **kwargs), np.arctan(np.sinh(us)))


def test_kc_zero_large_argument_without_warnings():
    # tanh -> +-1, sech -> 0 and gd -> +-pi/2 as u -> +-inf: no overflow is involved.
    us = np.array([709.0, 711.0, -800.0, 1e4])
    s, c, d = jacobi(us, 1.0)
    np.testing.assert_array_equal(s, np.sign(us))
    assert np.all((c >= 0) & (c < 1e-300)) and np.all((d >= 0) & (d < 1e-300))
    np.testing.assert_array_equal(am(us, 1.0), np.sign(us) * math.pi / 2)


# --- am ------------------------------------------------------------------------------------

@pytest.mark.parametrize("kc", [1.0, 0.6, 0.1, 1e-4, 1e-8, 1e-12, 1e-15])
def test_am_matches_mpmath(kc):
    # am is unbounded (DLMF 22.16.2): compare relative to max(|am|, 1).
    us = u_grid(1e3, 41)
    ref = np.array([mp_am(u, kc) for u in us])
    ours = am(us, k_of(kc), kc=kc)
    err = np.max(np.abs(ours - ref) / np.maximum(np.abs(ref), 1.0))
    _record("am rel |u|<=1e3", err)
    assert err <= 1e-14, (kc, err)


# --- K1 (18), E1 (17), G (19) --------------------------------------------------------------

def test_complete_integral_to_a_few_ulp():
    kcs = np.array(KC_GRID + list(np.geomspace(1e-300, 1.0, 40)))
    with mpmath.workdps(DPS):
        ref = np.array([float(mp_quarter(kc)) for kc in kcs])
    ours = complete_integral(np.sqrt((1 - kcs) * (1 + kcs)), kc=kcs)
    rel = np.max(np.abs(ours - ref) / ref)
    _record("K1 rel", rel)
    assert rel <= 2.3e-16 * 2, rel
    assert complete_integral(0.0) == math.pi / 2


def test_complete_integral_is_infinite_at_k_one():
    # Its docstring: "inf at k = 1 (kc = 0)"; K1 diverges like log(4/kc) (DLMF 19.12.1).
    assert complete_integral(1.0) == math.inf
    assert complete_integral(0.3, kc=0.0) == math.inf
    assert inverse_integral(0.5, 1.0) == math.tanh(0.5)


def test_complete_integral_from_k_matches_mpmath_ellipk():
    ks = np.linspace(0.0, 0.99, 34)
    with mpmath.workdps(DPS):
        ref = np.array([float(mpmath.ellipk(mpmath.mpf(k) ** 2)) for k in ks])
    assert np.max(np.abs(complete_integral(ks) - ref) / ref) <= 1e-15


@pytest.mark.parametrize("kc", [1.0, 0.8, 0.2, 1e-3, 1e-8, 1e-12])
def test_incomplete_integral_matches_mpmath_ellipf(kc):
    # E1(z, k) = F(arcsin z | m) (DLMF 19.2.4); the note's (17).
    zs = np.concatenate([np.linspace(-1.0, 1.0, 41), 1 - np.geomspace(1e-14, 0.1, 10),
                         [1e-300, -1e-10]])
    with mpmath.workdps(DPS):
        m = mp_parameter(kc)
        ref = np.array([float(mpmath.ellipf(mpmath.asin(mpmath.mpf(z)), m)) for z in zs])
    ours = incomplete_integral(zs, k_of(kc), kc=kc)
    err = np.max(np.abs(ours - ref) / np.maximum(np.abs(ref), 1e-300))
    _record("E1 rel", err)
    assert err <= 1e-14, (kc, zs[np.argmax(np.abs(ours - ref) / np.maximum(np.abs(ref), 1e-300))])


def test_incomplete_integral_reaches_k1_and_infinity():
    assert incomplete_integral(1.0, 0.9) == pytest.approx(complete_integral(0.9), rel=1e-15)
    assert incomplete_integral(1.0, 1.0) == math.inf
    assert incomplete_integral(-1.0, 1.0) == -math.inf


@pytest.mark.parametrize("kc", [1.0, 0.5, 1e-4, 1e-12])
def test_inverse_integral_inverts_incomplete_integral(kc):
    # The note's (19): G(E1(z)) = z on [-1, 1] and E1(G(u)) = u on [-K1, K1].
    k = k_of(kc)
    K = complete_integral(k, kc=kc)
    zs = np.linspace(-0.999, 0.999, 51)
    assert np.max(np.abs(inverse_integral(incomplete_integral(zs, k, kc=kc), k, kc=kc) - zs)) \
        <= 1e-14 / max(kc, 1e-2)
    us = np.linspace(-K, K, 51)[1:-1]
    back = incomplete_integral(inverse_integral(us, k, kc=kc), k, kc=kc)
    # E1 is steep near z = 1 (dE1/dz = 1/(cn dn)): compare in the forward direction instead.
    np.testing.assert_allclose(inverse_integral(back, k, kc=kc), inverse_integral(us, k, kc=kc),
                               rtol=0, atol=1e-14)
    assert inverse_integral(K, k, kc=kc) == 1.0
    assert inverse_integral(-K, k, kc=kc) == -1.0


def test_inverse_integral_raises_beyond_k1():
    K = complete_integral(0.8)
    with pytest.raises(ValueError, match="K1"):
        inverse_integral(K * (1 + 1e-12), 0.8)
    with pytest.raises(ValueError, match="K1"):
        inverse_integral([0.0, -2 * K], 0.8)


# --- why the library exists: scipy's ellipj near m = 1 -------------------------------------

@pytest.mark.parametrize("one_minus_m", [1e-10, 1e-12, 1e-14])
def test_scipy_ellipj_fails_where_ours_holds(one_minus_m):
    # scipy.special.ellipj is unusable for 1 - m <= 1e-10 (scipy issue 8480).
    # Each is judged against mpmath at the parameter it was actually given.
    kc = math.sqrt(one_minus_m)
    m_scipy = 1.0 - one_minus_m
    us = np.linspace(-100.0, 100.0, 81) + 0.123
    with mpmath.workdps(DPS):
        ref_scipy = np.array([float(mpmath.ellipfun("sn", float(u), m=mpmath.mpf(m_scipy)))
                              for u in us])
    sn_scipy = special.ellipj(us, m_scipy)[0]
    scipy_err = np.where(np.isnan(sn_scipy), np.inf, np.abs(sn_scipy - ref_scipy))
    assert np.max(scipy_err) > 1e-3
    ref_ours, _, _ = mp_jacobi(us, kc)
    assert np.max(np.abs(sn(us, 1.0, kc=kc) - ref_ours)) <= 1e-14


# --- identities at random points (DLMF chapter 22) -----------------------------------------

RNG = np.random.default_rng(20240601)
U_RANDOM = RNG.uniform(-50, 50, 400)
KC_RANDOM = np.concatenate([RNG.uniform(0, 1, 200), 10.0 ** RNG.uniform(-15, 0, 200)])
K_RANDOM = np.sqrt((1 - KC_RANDOM) * (1 + KC_RANDOM))


def test_dlmf_22_6_1_squares():
    # DLMF 22.6.1: sn^2 + cn^2 = 1 and dn^2 + k^2 sn^2 = 1.
    s, c, d = jacobi(U_RANDOM, K_RANDOM, kc=KC_RANDOM)
    assert np.max(np.abs(s**2 + c**2 - 1)) <= 2e-15
    assert np.max(np.abs(d**2 + K_RANDOM**2 * s**2 - 1)) <= 2e-15


def test_dlmf_22_4_3_quarter_period_shift():
    # DLMF 22.4.3: sn(u + K) = cd u, cn(u + K) = -kc sd u, dn(u + K) = kc nd u.
    kc = np.geomspace(1e-6, 1.0, 400)
    k = np.sqrt((1 - kc) * (1 + kc))
    u = RNG.uniform(-3, 3, 400)
    K = complete_integral(k, kc=kc)
    s, c, d = jacobi(u, k, kc=kc)
    s1, c1, d1 = jacobi(u + K, k, kc=kc)
    # u + K is rounded, so allow for the slope (|sn'|, |cn'| <= 1, |dn'| <= k^2) times an ulp.
    slack = 4e-16 * (np.abs(u) + K)
    assert np.all(np.abs(s1 - c / d) <= 1e-15 + slack)
    assert np.all(np.abs(c1 + kc * s / d) <= 1e-15 + slack)
    assert np.all(np.abs(d1 - kc / d) <= 1e-15 * (kc / d) + slack)


def test_dlmf_22_4_periods_and_22_16_2_am_staircase():
    # sn, cn have period 4K, dn has period 2K (DLMF 22.4 Table 22.4.1); am(u + 2K) = am u + pi
    # (DLMF 22.16.2, the note's staircase (21)); sin am = sn, cos am = cn (DLMF 22.16.1).
    kc = 10.0 ** RNG.uniform(-12, 0, 200)
    k = np.sqrt((1 - kc) * (1 + kc))
    u = RNG.uniform(-5, 5, 200)
    K = complete_integral(k, kc=kc)
    s, c, d = jacobi(u, k, kc=kc)
    s4, c4, _ = jacobi(u + 4 * K, k, kc=kc)
    _, _, d2 = jacobi(u + 2 * K, k, kc=kc)
    slack = 1e-15 + 4e-16 * (np.abs(u) + 4 * K)
    assert np.all(np.abs(s4 - s) <= slack)
    assert np.all(np.abs(c4 - c) <= slack)
    assert np.all(np.abs(d2 - d) <= slack)
    a = am(u, k, kc=kc)
    assert np.all(np.abs(am(u + 2 * K, k, kc=kc) - a - math.pi) <= 2e-15 + slack)
    assert np.max(np.abs(np.sin(a) - s)) <= 1e-15
    assert np.max(np.abs(np.cos(a) - c)) <= 1e-15


def test_dlmf_22_13_derivatives():
    # DLMF 22.13.1-3: sn' = cn dn, cn' = -sn dn, dn' = -k^2 sn cn; and am' = dn (22.16.1).
    # Central differences with h = 1e-5: truncation h^2/6 |f'''| and rounding 1e-16/h,
    # both below 1e-9 for k^2 <= 1.
    h = 1e-5
    u = RNG.uniform(-20, 20, 200)
    kc = RNG.uniform(0, 1, 200)
    k = np.sqrt((1 - kc) * (1 + kc))
    s, c, d = jacobi(u, k, kc=kc)
    sp, cp, dp = jacobi(u + h, k, kc=kc)
    sm, cm, dm = jacobi(u - h, k, kc=kc)
    tol = 1e-9
    assert np.max(np.abs((sp - sm) / (2 * h) - c * d)) <= tol
    assert np.max(np.abs((cp - cm) / (2 * h) + s * d)) <= tol
    assert np.max(np.abs((dp - dm) / (2 * h) + k**2 * s * c)) <= tol
    amd = (am(u + h, k, kc=kc) - am(u - h, k, kc=kc)) / (2 * h)
    assert np.max(np.abs(amd - d)) <= tol


def test_odd_and_even_symmetry():
    # DLMF 22.4.2 (Table 22.4.3): sn is odd, cn and dn are even, am is odd.
    s, c, d = jacobi(U_RANDOM, K_RANDOM, kc=KC_RANDOM)
    sm, cmn, dmn = jacobi(-U_RANDOM, K_RANDOM, kc=KC_RANDOM)
    np.testing.assert_array_equal(sm, -s)
    np.testing.assert_array_equal(cmn, c)
    np.testing.assert_array_equal(dmn, d)
    np.testing.assert_array_equal(am(-U_RANDOM, K_RANDOM, kc=KC_RANDOM),
                                  -am(U_RANDOM, K_RANDOM, kc=KC_RANDOM))


def test_zz_report_worst_errors(capsys):
    # Not a check: prints the worst errors measured above (run with -s to see them).
    with capsys.disabled():
        for name, value in sorted(WORST.items()):
            print(f"\n  worst {name}: {value:.2e}", end="")


@pytest.mark.parametrize("kc", [1e-300, 1e-310, 1e-320, 5e-324])
def test_subnormal_kc_is_the_hyperbolic_limit(kc):
    # For kc below 2**-60 the functions on |v| <= K/2 are tanh, sech, sech to a relative
    # kc / 2 (DLMF 22.10.8-10), while the Landen recurrence would start from a subnormal kc.
    us = np.linspace(-30.0, 30.0, 61)
    s, c, d = jacobi(us, 1.0, kc=kc)
    np.testing.assert_allclose(s, np.tanh(us), rtol=4e-16, atol=0)
    np.testing.assert_allclose(c, 1 / np.cosh(us), rtol=4e-15, atol=0)
    np.testing.assert_allclose(d, 1 / np.cosh(us), rtol=4e-15, atol=0)


def test_modulus_from_k_alone_keeps_the_period_exact():
    # From k alone kc = sqrt((1-k)(1+k)) is formed as a double-double: rounded to a double it
    # moved K1 by an ulp, and dn(9413, 0.967) lost three digits (2.7e-13; the claim is 1e-13).
    # Reference: mpmath at 60 digits with m = k**2 from the exact double k.
    for u, k in [(-9413.21912212555, 0.9670360584102484), (9976.049752648036, 0.9028689008371945)]:
        with mpmath.workdps(60):
            m = mpmath.mpf(k) ** 2
            ref = [float(mpmath.ellipfun(f, mpmath.mpf(u), m=m)) for f in ("sn", "cn", "dn")]
        s, c, d = jacobi(u, k)
        assert abs(s - ref[0]) <= 1e-15 and abs(c - ref[1]) <= 1e-15
        assert abs(d / ref[2] - 1) <= 1e-15


def test_incomplete_integral_at_one_is_k1_even_for_tiny_kc():
    # E1(+-1, k) = +-K1 (18); Carlson's R_F underflows to inf for kc < 1.5e-154.
    K = complete_integral(1.0, kc=1e-300)
    assert incomplete_integral(1.0, 1.0, kc=1e-300) == K
    assert incomplete_integral(-1.0, 1.0, kc=1e-300) == -K
    assert K == pytest.approx(math.log(4 / 1e-300), rel=1e-15)  # DLMF 19.12.1
