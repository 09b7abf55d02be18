"""The elliptic functions at the extremes: huge and near-1 moduli, warnings, return types.

References, each independent of the code under test: mpmath in a private context (never the
process-wide mpmath.mp) at 40 to 60 digits. mpmath takes the parameter m = k**2, formed
exactly from the double k.
"""

# Each lambda below is called at once, inside its loop (by quietly): the late binding B023
# warns of cannot happen.
# ruff: noqa: B023

import math

import mpmath
import numpy as np
import pytest

import elliptic_pendulum as ep
from tests.strict import quietly


def _context(dps):
    ctx = mpmath.MPContext()
    ctx.dps = dps
    return ctx


MP60 = _context(60)


# --- no spurious floating-point warnings at the edges --------------------------

EDGE_K = [0.0, -0.0, 1.0, -1.0, 5e-324, 1e-300, 1e-170, 1e-9, 0.5, 1 - 2.0 ** -53]
EDGE_KC = [0.0, 5e-324, 1e-300, 1e-170, 1e-9, 0.5, 1.0]
EDGE_Z = [0.0, -0.0, 5e-324, 1e-300, 0.5, -1.0, 1.0]
EDGE_U = [0.0, -0.0, 5e-324, 1e-300, 1.0, 700.0, 1e4, 1e7]


def test_integrals_are_silent_at_the_edges():
    # E1(0, 1) was 0 * K1 = 0 * inf (invalid), E1(1e-300, k) squared kc z (underflow).
    for k in EDGE_K:
        quietly(lambda: ep.complete_integral(k))
        for z in EDGE_Z:
            quietly(lambda: ep.incomplete_integral(z, k))
            quietly(lambda: ep.incomplete_integral(np.array([z, 0.3]), k))
    for kc in EDGE_KC:
        quietly(lambda: ep.complete_integral(1.0, kc=kc))
        for z in EDGE_Z:
            quietly(lambda: ep.incomplete_integral(z, 1.0, kc=kc))
        for u in (0.0, -0.0, 1e-300, 0.5):
            quietly(lambda: ep.inverse_integral(u, 1.0, kc=kc))
    # the values there: E1(+-0, k) = +-0 (an odd function), E1(z, 0) = asin z (DLMF 19.6.8)
    for k in (1.0, 0.5):
        assert math.copysign(1.0, quietly(lambda: ep.incomplete_integral(0.0, k))) == 1.0
        assert math.copysign(1.0, quietly(lambda: ep.incomplete_integral(-0.0, k))) == -1.0
    assert quietly(lambda: ep.incomplete_integral(1e-300, 0.5)) == 1e-300
    assert ep.incomplete_integral(1.0, 1.0, kc=0.0) == math.inf


def test_jacobi_functions_are_silent_at_the_edges():
    # am(5e-324, 0.5) took the scalar path's arctan2 of a subnormal (underflow).
    for u in EDGE_U:
        for k in EDGE_K:
            quietly(lambda: (ep.jacobi(u, k), ep.am(u, k), ep.sn(np.array([u, 0.3]), k),
                            ep.am(np.array([u, 0.3]), k)))
        for kc in EDGE_KC:
            quietly(lambda: (ep.jacobi(u, 1.0, kc=kc), ep.am(u, 1.0, kc=kc),
                            ep.am(np.array([u, 0.3]), 1.0, kc=np.array([kc, 0.8]))))
    # am(u) = u (1 + O(u^2)) at a subnormal u, and the scalar path gives the array's bits
    assert quietly(lambda: ep.am(5e-324, 0.5)) == 5e-324 == ep.am(np.array([5e-324]), 0.5)[0]


# --- return types follow scalar_or_array (float only if every input is scalar) --

def _parts(f):
    """f as a list of functions of (u, k, kc=None), one per output (jacobi has three)."""
    if f is ep.jacobi:
        return [lambda *a, i=i, **kw: ep.jacobi(*a, **kw)[i] for i in range(3)]
    return [f]


@pytest.mark.parametrize("f", [ep.sn, ep.cn, ep.dn, ep.am, ep.jacobi])
def test_scalar_arguments_give_python_floats(f):
    for g in _parts(f):
        for args, kwargs in [((0.5, 0.3), {}), ((0.5, 0.3), {"kc": 0.9}), ((0.5, 2.5), {}),
                             ((np.float64(0.5), np.array(0.3)), {}), ((1, 0), {}),
                             ((0.5, 1.0), {"kc": np.float32(0.0)})]:
            assert type(g(*args, **kwargs)) is float, (args, kwargs)


@pytest.mark.parametrize("f", [ep.sn, ep.cn, ep.dn, ep.am, ep.jacobi])
def test_any_array_argument_gives_the_broadcast_array(f):
    # am(0.5, [.3, .4], kc=.9) was np.float64 while sn gave a float: k was forgotten.
    u_col = np.array([0.1, -0.7, 2.0, 30.0])[:, None]
    cases = [
        ((0.5, np.array([0.3, 0.4])), {"kc": 0.9}, (2,)),      # k array, kc trusted over it
        ((0.5, 0.3), {"kc": np.array([0.9, 0.2])}, (2,)),
        ((0.5, np.array([0.3, 0.4])), {"kc": np.array([0.9, 0.2])}, (2,)),
        ((u_col, np.array([0.0, 0.5, 1.0])), {}, (4, 3)),
        ((u_col, 1.0), {"kc": np.array([1.0, 1e-9, 0.0])}, (4, 3)),
        ((u_col, np.array([0.5, 1.0, 3.0])), {}, (4, 3)),     # k > 1 beside k <= 1
        ((np.array(0.5), np.array([[0.2], [0.9]])), {"kc": 0.5}, (2, 1)),
    ]
    for g in _parts(f):
        for args, kwargs, shape in cases:
            out = g(*args, **kwargs)
            assert isinstance(out, np.ndarray) and out.dtype == float and out.shape == shape
            # each element is the scalar call's, bit for bit (kc, when given, decides)
            u, k = (np.broadcast_to(a, shape) for a in args)
            kc = np.broadcast_to(kwargs["kc"], shape) if "kc" in kwargs else None
            for i in np.ndindex(shape):
                extra = {"kc": float(kc[i])} if kc is not None else {}
                assert out[i] == g(float(u[i]), float(k[i]), **extra), (args, kwargs, i)


def test_integrals_follow_the_same_rule():
    k, kc = np.array([0.3, 0.4]), 0.9
    for out in (ep.complete_integral(k, kc=kc), ep.incomplete_integral(0.5, k, kc=kc),
                ep.inverse_integral(0.5, k, kc=kc)):
        assert isinstance(out, np.ndarray) and out.shape == (2,) and out[0] == out[1]
    assert type(ep.complete_integral(0.3, kc=0.9)) is float


# --- kc = 1 with a low part is not k = 0 ----------------------------------------------------

def _mp_jacobi(u, k):
    """sn, cn, dn at 50 digits with m = k^2 exact from the double k (k <= 1 or k > 1).

    For k > 1 mpmath is asked for the reciprocal modulus' functions, DLMF 22.17.2-4:
    sn(u, k) = sn(k u, 1/k) / k, cn(u, k) = dn(k u, 1/k), dn(u, k) = cn(k u, 1/k), with
    k u and 1/k^2 formed in 50 digits (m = k^2 > 1 directly is slow and complex in mpmath).
    """
    ctx = _context(50)
    K, U = ctx.mpf(k), ctx.mpf(u)
    if k <= 1:
        return [float(ctx.ellipfun(f, U, m=K * K)) for f in ("sn", "cn", "dn")]
    x, m = K * U, 1 / (K * K)
    return [float(ctx.ellipfun("sn", x, m=m) / K), float(ctx.ellipfun("dn", x, m=m)),
            float(ctx.ellipfun("cn", x, m=m))]


def _ulps(got, exact):
    return abs(got - exact) / math.ulp(exact)


@pytest.mark.parametrize(("u", "k"), [
    (1e6, 1e-9), (3e4, 3e-9), (1e5, 1e-8),     # tiny k: kc rounds to 1, kc_lo = -k^2/2
    (1e-2, 1e10), (5.000000000001e-8, 1e15), (1.0, 1e8), (-3e-9, 2.0 ** 40)])  # through 1/k
def test_modulus_whose_complement_rounds_to_one(u, k):
    # kc = 1.0 (+ kc_lo) was taken for k = 0, sin and cos: but K exceeds pi/2 by k^2 pi/8 and
    # the phase slips by k^2 u / 4: sn(1e6, 1e-9) was off by 4219 ulp, sn(1e-2, 1e10) by
    # 5.9e6 and dn by 3.5e7. Reference: mpmath at 50 digits.
    got = ep.jacobi(u, k)
    for value, exact in zip(got, _mp_jacobi(u, k), strict=True):
        assert _ulps(value, exact) <= 2, (u, k, got)
    assert [ep.sn(np.array([u]), k)[0], ep.am(np.array([u]), k)[0]] == [got[0], ep.am(u, k)]


def test_tiny_modulus_beyond_exact_reduction_raises():
    # Beyond 2**26 quarter periods the reduction is no longer exact (now that tiny k takes it).
    with pytest.raises(ValueError, match="^u is too large"):
        ep.sn(1e9, 1e-9)
    assert ep.sn(1e9, 0.0) == math.sin(1e9)  # k = 0 exactly needs no reduction


# --- every finite k, however large ---------------------------------------------

def test_huge_modulus_example():
    # sn(1e-155, 1e155) raised "AGM did not converge" ((k - 1)(k + 1) overflowed). DLMF 22.17:
    # sn(u, k) = sn(k u, 1/k) / k = sn(1, 1e-155) / 1e155 = sin(1) / 1e155 to 1e-310.
    exact = float(MP60.sin(1) / MP60.mpf(1e155))
    assert quietly(lambda: ep.sn(1e-155, 1e155)) == exact
    assert quietly(lambda: ep.cn(1e-155, 1e155)) == 1.0  # dn(1, 1e-155) = 1 - 3.5e-311
    # dn = cn(1, 1e-155) = cos(1) - 1e-310: the recurrence's 1/hypot(1, tan 1) is an ulp off
    assert _ulps(quietly(lambda: ep.dn(1e-155, 1e155)), float(MP60.cos(1))) <= 1


def test_huge_modulus_matches_mpmath():
    # k from 2 to 1.7e308, k u from 1e-5 to 8e7 (below 2**26 quarter periods): sn, cn, dn and
    # am within 4 ulp (measured 3) of mpmath at 50 digits through DLMF 22.17 (_mp_jacobi).
    rng = np.random.default_rng(104)
    k = 10.0 ** rng.uniform(0.3, 308.2, 150)
    u = rng.choice([-1.0, 1.0], 150) * 10.0 ** rng.uniform(-5, 7.9, 150) / k
    s, c, d = quietly(lambda: ep.jacobi(u, k))
    a = quietly(lambda: ep.am(u, k))
    ctx = _context(50)
    for i in range(k.size):
        exact = _mp_jacobi(u[i], k[i])
        for value, e in zip((s[i], c[i], d[i]), exact, strict=True):
            assert _ulps(value, e) <= 4, (u[i], k[i])
        # am = atan2(sn, cn), in (-pi/2, pi/2) for k > 1 (cn = dn(k u, 1/k) > 0)
        exact_am = float(ctx.atan2(ctx.ellipfun("sn", ctx.mpf(k[i]) * ctx.mpf(u[i]),
                                                m=1 / ctx.mpf(k[i]) ** 2) / ctx.mpf(k[i]),
                                   ctx.mpf(exact[1])))
        assert _ulps(a[i], exact_am) <= 4, (u[i], k[i])
        # alone and in the batch, and on the scalar path: the same bits
        assert ep.jacobi(float(u[i]), float(k[i])) == (s[i], c[i], d[i])
        assert ep.am(float(u[i]), float(k[i])) == a[i]


def test_huge_modulus_does_not_poison_an_array():
    u = np.array([1e-155, 0.3, 1e-299, -2.0, 5e-324])
    k = np.array([1e155, 0.5, 1e300, 1.0, 1.7e308])
    s, c, d = quietly(lambda: ep.jacobi(u, k))
    for i in range(u.size):
        assert ep.jacobi(float(u[i]), float(k[i])) == (s[i], c[i], d[i])
    # DLMF 22.17.2 in 60 digits; sin(k u) / k rounds twice (1/k^2 underflows: sn = sin here)
    assert s[0] == float(MP60.sin(1) / MP60.mpf(1e155))
    assert _ulps(s[2], float(MP60.sin(MP60.mpf(1e-299) * MP60.mpf(1e300)) / MP60.mpf(1e300))) <= 1


def test_modulus_limits_are_value_errors():
    with pytest.raises(ValueError, match=r"^k must be finite"):
        ep.sn(0.5, math.inf)
    with pytest.raises(ValueError, match=r"^u is too large"):
        ep.sn(1.0, 1e10)       # k u = 1e10: beyond 2**26 quarter periods K(1/k) = pi/2
    # past k = 2**537, 1/k^2 underflows: sn(k u, 1/k) = sin(k u) (the phase slip k u / (4 k^2)
    # is below 1e-35 for k u <= 1e290) needs no reduction
    assert _ulps(ep.sn(1e-100, 1e300),
                 float(MP60.sin(MP60.mpf(1e-100) * MP60.mpf(1e300)) / MP60.mpf(1e300))) <= 1
    with pytest.raises(ValueError, match=r"^u is too large"):
        ep.sn(1.0, 1e300)      # k u = 1e300 > 1e290


# --- just above k = 1: the Landen recurrence's last level must be circular to 2.5e-17 ----

def test_landen_levels_end_circular():
    # `core` starts the descending recurrence from the last AGM level as if its modulus were 0;
    # that level's k_n^2 = 1 - (b_n/a_n)^2 is the relative error made there. GSL's stop (a, b
    # agreeing to 4e-16) left up to 1.6e-15, 7 ulp in cn and dn. Reference: the AGM of the
    # exact double kc, run in mpmath at 60 digits for as many steps as the library took.
    from elliptic_pendulum._engine import landen as _landen

    rng = np.random.default_rng(105)
    for kc in np.concatenate([rng.uniform(0.0, 1.0, 300), 10.0 ** rng.uniform(-17, 0, 300)]):
        c = _landen.constants(float(kc))
        steps = len(c.mu) - 1  # one modulus alone: its last level is where it froze
        a, b = MP60.mpf(1), MP60.mpf(float(kc))
        for _ in range(steps):
            a, b = (a + b) / 2, MP60.sqrt(a * b)
        assert 1 - (b / a) ** 2 <= 2.5e-17, (kc, steps)
        assert _landen.constants_float(float(kc), 0.0) == c  # the float twin, to the bit


def test_near_one_from_above_boost_like_rows():
    # Rows in the style of Boost's jacobi_near_1 table (k = 1 + small, u ~ +-4): cn and dn
    # were 15 ulp off at worst; the circular last level brought them to 12 (mean 1.7 ulp), and
    # the recurrence's d = rho + (1 - rho) s (a sum of positive terms, in place of
    # (r + b_n) / (r + a_n)) to 8 (mean 1.5 ulp). The rest is the rounding of the
    # double-precision recurrence at kc(1/k) ~ 1e-3. Reference: mpmath, 50 digits.
    ks = [1.000000476837158203125, 1.000003337860107421875, 1.000029087066650390625,
          1.0000996589660644531250, 1.00026798248291015625, 1.00124835968017578125]
    us = np.array([-4.02459716796875, -3.73013210296630859375]
                  + list(np.linspace(-4.5, 4.5, 37) + 0.0123))
    for k in ks:
        s, c, d = ep.jacobi(us, k)
        for i, u in enumerate(us):
            exact = _mp_jacobi(u, k)
            assert _ulps(s[i], exact[0]) <= 5 and _ulps(c[i], exact[1]) <= 8
            assert _ulps(d[i], exact[2]) <= 8, (u, k)


# --- a long array of moduli: those near 1 are gathered and written back -------------------

def test_moduli_near_one_in_a_long_array_keep_their_values():
    # An array of moduli longer than one piece (2**14) has those above 0.998 (kc below 1/16,
    # the double-double recurrence, and k > 1) done apart and written back into place. Both
    # sides of 0.998 in one array: each element must be its own call's bits and within 8 ulp
    # of mpmath at 50 digits (_mp_jacobi, through DLMF 22.17 above 1), the bound of the rows
    # just above k = 1 (test_near_one_from_above_boost_like_rows); measured 5 at worst, at
    # k = 1 - 2**-40 where cn and dn are small. A value written to the wrong element, or a
    # stand-in left in place, would be off by far more.
    rng = np.random.default_rng(2026)
    n = 2**14 + 300
    k = rng.uniform(0.0, 1.0, n)
    u = rng.uniform(-10.0, 10.0, n)
    near = [0.9979, 0.99805, 0.9981, 0.999, 0.99999, 1 - 2.0**-40, 1.0, 1.00001, 1.0005, 3.0]
    spots = rng.choice(n, len(near) * 3, replace=False)
    k[spots] = near * 3
    s, c, d = ep.jacobi(u, k)
    a = ep.am(u, k)
    for i in [*spots, *rng.choice(n, 40, replace=False)]:
        assert ep.jacobi(float(u[i]), float(k[i])) == (s[i], c[i], d[i]), (u[i], k[i])
        assert ep.am(float(u[i]), float(k[i])) == a[i], (u[i], k[i])
        exact = _mp_jacobi(float(u[i]), float(k[i]))
        for got, ref in zip((s[i], c[i], d[i]), exact, strict=True):
            assert _ulps(got, ref) <= 8, (u[i], k[i], got, ref)
