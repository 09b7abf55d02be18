"""The phase's remainder in double-double, for theta beside a zero crossing.

:func:`.classify.phases` gives the elliptic argument at t = 0 as quarters K + rem with rem a
double, within a few ulp. Beside a zero crossing of theta (in II at u = 2 n K, in IV where
am(u) = n pi) the argument u = rate t + rem + quarters K cancels to a small v, and rem's
rounding, an absolute few 1e-17, is a relative 1e-17 / |v| of theta: measured, 500 ulp at
|v| = 1e-4 and 1e9 ulp at |v| = 1e-10 (it is the distance from the initial state to the
crossing that must be known beyond a double, and t itself is exact). Here rem is recomputed
in double-double, as the same F(phi) = factor R_F(x, y, 1) of the same branch, from the
double-double s, c, w, k and kc of the classification, with Carlson's R_F carried in
double-double; what comes back is the low part rem_lo with rem + rem_lo within about 1e-32
of the exact remainder (the phase's own limit, docs/design.md "Never lose the energy").

It costs some thousand operations per state, several times the whole classification, so it
runs only where :mod:`.redo` evaluates theta near a crossing again, for the states that need
it. The double-double operations are plain arithmetic: :func:`rf` serves NumPy arrays and
Python floats alike, to the bit; the arguments of the branches have a twin on floats.
"""

from __future__ import annotations

import math

import numpy as np

from . import dd as _dd

__all__ = ["low_part", "low_part_float", "rf"]

# Each duplication step of R_F divides the spread of its arguments, |A - x| and the like, by
# 4; the mean A tends to R_F**-2. An element stops where that spread is below _EPS A, where
# the series of DLMF 19.36.1 to order 7 is off by about _EPS**8 < 1e-36: after 9 steps for
# arguments of one size, after up to 17 for x and y near 1e-600 (R_F ~ 700), where the first
# steps only bring them up to z. The count is the element's own: its bits do not depend on its
# companions.
_EPS = 3e-5
_MAX_STEPS = 40  # a guard; 17 steps reach R_F = 700, kc = 1e-300


def _sqrt(h, lo, root):
    """Square root of a double-double h + lo >= 0 (0 at 0, where dd.sqrt divides by it)."""
    x = root(h)
    p, e = _dd.two_prod(x, x)
    r = ((h - p) - e) + lo
    return _dd.fast_two_sum(x, r / (2.0 * x + (x == 0)))


def rf(xh, xl, yh, yl, root, select, alive):
    """Carlson's R_F(x, y, 1) (DLMF 19.16.1) for double-doubles x, y >= 0, not both 0.

    Duplication (DLMF 19.26.18) in double-double, then the series of DLMF 19.36.1: within
    6e-32 relative for x, y above 1e-200 (measured against mpmath; 5e-27 at 1e-300, where the
    exact products leave the normal doubles). ``root`` is math.sqrt or np.sqrt,
    ``select(c, a, b)`` a where c else b and ``alive(c)`` whether any c holds, for the type
    at hand.
    """
    zh, zl = 1.0 + 0.0 * xh, 0.0 * xh
    mean = (xh + yh + 1.0) / 3.0
    spread = abs(mean - 1.0)  # the largest of |A - x|, |A - y|, |A - z|
    for q in (xh, yh):
        spread = select(abs(mean - q) > spread, abs(mean - q), spread)
    for _ in range(_MAX_STEPS):
        going = spread > _EPS * ((xh + yh + zh) / 3.0)
        if not alive(going):
            break
        sx, sy, sz = _sqrt(xh, xl, root), _sqrt(yh, yl, root), _sqrt(zh, zl, root)
        lam = _dd.add(*_dd.mul(*sx, *sy), *_dd.mul(*sz, *_dd.add(*sx, *sy)))
        new = [0.25 * q for q in (*_dd.add(xh, xl, *lam), *_dd.add(yh, yl, *lam),
                                  *_dd.add(zh, zl, *lam))]
        xh, xl, yh, yl, zh, zl = (select(going, n, o) for n, o in
                                  zip(new, (xh, xl, yh, yl, zh, zl), strict=True))
        spread = select(going, 0.25 * spread, spread)
    ah, al = _dd.div(*_dd.add(*_dd.add(xh, xl, yh, yl), zh, zl), 3.0 + 0.0 * xh, 0.0 * xh)
    dx = _dd.div(*_dd.add(ah, al, -xh, -xl), ah, al)  # X = 1 - x / A
    dy = _dd.div(*_dd.add(ah, al, -yh, -yl), ah, al)
    dz = _dd.add(-dx[0], -dx[1], -dy[0], -dy[1])     # X + Y + Z = 0
    xy = _dd.mul(*dx, *dy)
    e2h, e2l = _dd.add(*xy, *(-q for q in _dd.mul(*dz, *dz)))
    e3h, e3l = _dd.mul(*xy, *dz)
    # 1 - E2/10 + E3/14 in double-double (E2 ~ eps^2, E3 ~ eps^3); the rest, below 2e-18,
    # in double.
    tail = (e2h * e2h / 24.0 - 3.0 * e2h * e3h / 44.0 - 5.0 * e2h * e2h * e2h / 208.0
            + 3.0 * e3h * e3h / 104.0 + e2h * e2h * e3h / 16.0)
    sh, sl = _dd.add(*_dd.div(-e2h, -e2l, 10.0 + 0.0 * xh, 0.0 * xh),
                     *_dd.div(e3h, e3l, 14.0 + 0.0 * xh, 0.0 * xh))
    sh, sl = _dd.add(sh, sl + tail, 1.0 + 0.0 * xh, 0.0 * xh)
    return _dd.div(sh, sl, *_sqrt(ah, al, root))


# root, select and alive of rf, for arrays and for Python floats
_ARRAYS = (np.sqrt, np.where, np.any)
_FLOATS = (math.sqrt, lambda c, a, b: a if c else b, bool)


def _square(h, lo):
    return _dd.mul(h, lo, h, lo)


def _finish(rem, sign, factor, x, y, kind):
    """rem_lo = sign factor R_F(x, y, 1) - rem, rounded once (0 where it is not finite)."""
    fh, fl = _dd.mul(*factor, *rf(*x, *y, *kind))
    return (sign * fh - rem) + sign * fl  # sign fh - rem is exact: they agree to a few ulp


def low_part(lib, q, rem, s, c, w, k, kc):
    """Rem_lo of states of regime II (``lib``) or IV, q and rem from :func:`.classify.phases`.

    s, c, w, k, kc are (hi, lo) pairs of arrays. The branch is read off q: odd at a turning
    point (II) or near the top (IV), even near the bottom; the arguments are those of
    ``phases``, each formed in double-double.
    """
    turn = (q == 1.0) | (q == -1.0)
    with np.errstate(all="ignore"):  # the branches np.where drops may divide by zero
        sk, wk = _dd.div(*s, *k), _dd.div(*w, *k)
        g = _dd.mul(*k, *c)
        ra = _dd.div(*k, *(np.abs(w[0]), np.where(w[0] < 0, -w[1], w[1])))  # k / |w|
        kcs = _dd.mul(*kc, *s)
        # II bottom: (s/k) R_F((w/k)^2, c^2); II turn: (w/(k c)) R_F((kc s/(k c))^2, (kc/c)^2)
        # IV bottom: s R_F(c^2, (w/k)^2) (sign of w); IV turn: (c k/|w|) R_F((kc s k/|w|)^2,
        # (kc k/|w|)^2)
        cases = {
            (True, False): (sk, _square(*wk), _square(*c)),
            (True, True): (_dd.div(*w, *g), _square(*_dd.div(*kcs, *g)),
                           _square(*_dd.div(*kc, *c))),
            (False, False): (s, _square(*c), _square(*wk)),
            (False, True): (_dd.mul(*c, *ra), _square(*_dd.mul(*kcs, *ra)),
                            _square(*_dd.mul(*kc, *ra))),
        }

        def choose(i, j):
            def part(key):
                return cases[key][i][j]
            return np.where(lib, np.where(turn, part((True, True)), part((True, False))),
                            np.where(turn, part((False, True)), part((False, False))))

        factor, x, y = ((choose(i, 0), choose(i, 1)) for i in range(3))
        sgn_w = np.where(w[0] < 0, -1.0, 1.0)
        sign = np.where(lib, np.where(turn, -q, np.where(q == 0.0, 1.0, -1.0)),
                        np.where(turn, -q, sgn_w))
        low = _finish(rem, sign, factor, x, y, _ARRAYS)
    return np.where(np.isfinite(low), low, 0.0)


def low_part_float(lib, q, rem, s, c, w, k, kc):
    """Compute :func:`low_part` of one state on Python floats (its twin: the same bits)."""
    turn = q in (1.0, -1.0)
    if lib and not turn:
        wk = _dd.div(*w, *k)
        factor, x, y = _dd.div(*s, *k), _square(*wk), _square(*c)
        sign = 1.0 if q == 0.0 else -1.0
    elif lib:
        g = _dd.mul(*k, *c)
        factor = _dd.div(*w, *g)
        x, y = _square(*_dd.div(*_dd.mul(*kc, *s), *g)), _square(*_dd.div(*kc, *c))
        sign = -q
    elif not turn:
        factor, x, y = s, _square(*c), _square(*_dd.div(*w, *k))
        sign = -1.0 if w[0] < 0 else 1.0
    else:
        ra = _dd.div(*k, *((-w[0], -w[1]) if w[0] < 0 else w))
        factor = _dd.mul(*c, *ra)
        x, y = _square(*_dd.mul(*_dd.mul(*kc, *s), *ra)), _square(*_dd.mul(*kc, *ra))
        sign = -q
    low = _finish(rem, sign, factor, x, y, _FLOATS)
    return low if math.isfinite(low) else 0.0
