"""The double-double arithmetic of the engine, against exact fractions and mpmath.

Error-free sums and products, add, mul, div and sqrt against exact rational arithmetic
(fractions.Fraction); the sine and cosine against mpmath at 40 digits; and what their
precision buys: no phase drift over 1e4 and 1e7 periods 3e-8 from the separatrix (mpmath at
60 digits). mpmath in private contexts, never the process-wide mpmath.mp.
"""

import math
from fractions import Fraction

import mpmath
import numpy as np
import pytest

import elliptic_pendulum as ep
from elliptic_pendulum._engine import dd as _dd


def _context(dps):
    ctx = mpmath.MPContext()
    ctx.dps = dps
    return ctx


MP40 = _context(40)
MP60 = _context(60)


def _exact(pair):
    return Fraction(pair[0]) + Fraction(pair[1])


def _rel(pair, exact):
    return float(abs(_exact(pair) - exact) / abs(exact))


def _random_dd(rng, spread=30):
    hi = float(rng.uniform(0.5, 2.0)) * 2.0 ** int(rng.integers(-spread, spread))
    hi = hi if rng.random() < 0.5 else -hi
    return _dd.fast_two_sum(hi, float(rng.uniform(-0.5, 0.5)) * math.ulp(hi))


# --- the double-double primitives ----------------------------------------------

def test_dd_error_free_transformations_are_exact():
    # Knuth's two_sum and Dekker's two_prod: s + e = a + b and p + e = a b exactly (Fraction).
    rng = np.random.default_rng(101)
    for _ in range(3000):
        a = float(rng.uniform(-1, 1)) * 2.0 ** int(rng.integers(-200, 200))
        b = float(rng.uniform(-1, 1)) * 2.0 ** int(rng.integers(-200, 200))
        s, e = _dd.two_sum(a, b)
        assert s == a + b and Fraction(s) + Fraction(e) == Fraction(a) + Fraction(b)
        p, e = _dd.two_prod(a, b)
        assert p == a * b and Fraction(p) + Fraction(e) == Fraction(a) * Fraction(b)


def test_dd_arithmetic_against_fractions():
    # The bounds the module docstring states: add, mul, sqrt within 2**-104 relative, div
    # within 8e-32; the reference is the exact rational result of the two double-doubles.
    rng = np.random.default_rng(102)
    bound = 2.0 ** -104
    worst = dict.fromkeys(("add", "mul", "mul_d", "div", "sqrt"), 0.0)
    for i in range(4000):
        a, b = _random_dd(rng), _random_dd(rng)
        if i % 3 == 0:  # heavy cancellation: b = -a (1 + 1e-10 r) plus a low part
            b = _dd.fast_two_sum(-a[0] * (1 + float(rng.uniform(-1e-10, 1e-10))),
                                 float(rng.uniform(-1, 1)) * math.ulp(a[0]))
        fa, fb = _exact(a), _exact(b)
        if fa + fb != 0:
            worst["add"] = max(worst["add"], _rel(_dd.add(*a, *b), fa + fb))
        worst["mul"] = max(worst["mul"], _rel(_dd.mul(*a, *b), fa * fb))
        worst["mul_d"] = max(worst["mul_d"], _rel(_dd.mul_d(*a, b[0]), fa * Fraction(b[0])))
        worst["div"] = max(worst["div"], _rel(_dd.div(*a, *b), fa / fb))
        x = (abs(a[0]), math.copysign(a[1], a[1] * a[0]))
        r = _exact(_dd.sqrt(*x, math.sqrt))
        # |r / sqrt(x) - 1| = |r^2 / x - 1| / 2 to first order, all in exact arithmetic
        worst["sqrt"] = max(worst["sqrt"], float(abs(r * r / _exact(x) - 1)) / 2)
    assert worst["add"] <= bound and worst["mul"] <= bound and worst["mul_d"] <= bound
    assert worst["sqrt"] <= bound and worst["div"] <= 8e-32, worst


def _sincos(y, y_lo=0.0):
    return _dd.sincos(y, y_lo, lambda x: float(round(x)), lambda t, j: t[int(j)])


def test_dd_series_reaches_z12_term():
    # At |z| = 0.999/64 the cosine series stopped at z^10/10! was off by z^12/12! = 4.4e-31;
    # the sine by z^13/13! / z = 3.4e-32. Reference: mpmath at 40 digits.
    for z in (0.999 / 64, -0.999 / 64, 1 / 64, 0.7 / 64):
        sh, sl, ch, cl = _dd._series(z, 0.0)
        exact_s, exact_c = MP40.sin(MP40.mpf(z)), MP40.cos(MP40.mpf(z))
        assert abs(MP40.mpf(sh) + MP40.mpf(sl) - exact_s) / abs(exact_s) <= 4e-32
        assert abs(MP40.mpf(ch) + MP40.mpf(cl) - exact_c) / exact_c <= 1e-32


def test_dd_sincos_against_mpmath():
    # The bound sincos's docstring states, 6e-32 relative, over [0, pi/4] (the old series:
    # 8.8e-31 for sin near y = 1/64 and 4.4e-31 for cos). Reference: mpmath at 40 digits of
    # the exact double-double angle.
    rng = np.random.default_rng(103)
    ys = list(rng.uniform(0.0, math.pi / 4, 1500)) + list(rng.uniform(0.0, 1 / 32, 300))
    ys += [0.999 / 64, 1 / 64 + 1e-12, 3 / 64 - 1e-9, math.pi / 4, 1e-5, 2.0 ** -40]
    for y in ys:
        y_lo = float(rng.uniform(-0.5, 0.5)) * math.ulp(y)
        sh, sl, ch, cl = _sincos(y, y_lo)
        angle = MP40.mpf(y) + MP40.mpf(y_lo)
        exact_s, exact_c = MP40.sin(angle), MP40.cos(angle)
        assert abs(MP40.mpf(sh) + MP40.mpf(sl) - exact_s) / exact_s <= 6e-32, y
        assert abs(MP40.mpf(ch) + MP40.mpf(cl) - exact_c) / exact_c <= 6e-32, y


# A state 3e-8 from the separatrix: kc = 2.9e-8, so k^2 = sin^2(theta0/2) + (theta0'/(2 w0))^2
# cancels against 1 to 8.3e-16 and K = log(4/kc) + ... magnifies each error of the
# double-double sine.
DRIFT_STATE = (1.0915042891720557, 172.98311073409428, 101.19082578893949)


def _bottom_passage(periods):
    """The double time of the bottom passage after ``periods`` periods, and theta there.

    Reference: mpmath at 60 digits. From the exact doubles, s = sin(theta0/2), w =
    theta0'/(2 w0), m = k^2 = s^2 + w^2; sin(theta/2) = k sn(w0 t + phi | m) with sn(phi) =
    s/k, cn(phi) = w/k (both > 0), so phi = F(atan2(s, w) | m). The passage is at w0 t + phi
    = 4 N K(m); t is rounded to a double and theta is evaluated there, after subtracting
    4 N K in 60 digits.
    """
    th, v, w0 = (MP60.mpf(x) for x in DRIFT_STATE)
    s, w = MP60.sin(th / 2), v / (2 * w0)
    m = s * s + w * w
    K, phi = MP60.ellipk(m), MP60.ellipf(MP60.atan2(s, w), m)
    t = float((4 * periods * K - phi) / w0)
    x = w0 * MP60.mpf(t) + phi - 4 * periods * K
    return t, float(2 * MP60.asin(MP60.sqrt(m) * MP60.ellipfun("sn", x, m=m)))


@pytest.mark.parametrize("periods", [10**4, 10**7])
def test_no_phase_drift_near_the_separatrix(periods):
    # With the short cosine series K was off by 8.7e-18 relative and theta at the bottom by
    # 1.3e-11 after 1e4 periods, 1.3e-8 after 1e7. Now K is off by 4.3e-20, which is the
    # double-double limit for this state (a 2**-106 rounding of sin^2(theta0/2) ~ 0.27 moves
    # kc^2 = 8.3e-16 by 1.4e-17 relative and K by up to 4e-19). The bound allows a relative
    # 1e-19 of the phase, times theta' = 2 k w0 at the bottom, plus 4 ulp of pi.
    t, truth = _bottom_passage(periods)
    motion = ep.solve(*DRIFT_STATE)
    slope = 2 * DRIFT_STATE[2]  # theta' at the bottom, 2 k w0 with k = 1 - 4e-16
    bound = slope * t * 1e-19 + 4 * math.ulp(math.pi)
    assert abs(motion.theta(t) - truth) <= bound, (motion.theta(t) - truth, bound)
    assert motion.theta(np.array([t]))[0] == motion.theta(t)  # array path, same bits
