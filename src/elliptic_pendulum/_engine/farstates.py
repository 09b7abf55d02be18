"""Classification of initial states outside the range of the double-double path.

Angles beyond 2**20 rad (whose reduction by 2 pi needs more than three parts of pi), and
speeds ``theta'/(2 omega0)`` beyond 2**(+-300) (whose squares leave the range of doubles)
are rare; each is classified on its own in a private mpmath context made for the call, at 50
digits beyond the size of the angle. A private context (``mpmath.MPContext()``) is used and
never ``mpmath.mp``, whose precision is shared by the whole process and all of its threads.
"""

from __future__ import annotations

import math

import mpmath

from . import codes as regimes

__all__ = ["classify"]


def _split(x) -> tuple[float, float]:
    hi = float(x)
    return hi, float(x - hi)


def classify(theta0: float, dtheta0: float, omega0: float) -> tuple:
    """Return the fields of :class:`.classify.State` for one state, in order."""
    ctx = mpmath.MPContext()
    ctx.dps = 50 + int(max(0.0, math.log10(abs(theta0) + 1.0)))  # 2 pi m must be exact too
    w0 = ctx.mpf(omega0)
    w = ctx.mpf(dtheta0) / (2 * w0)
    m = ctx.nint(ctx.mpf(theta0) / (2 * ctx.pi))
    odd = ctx.nint((ctx.mpf(theta0) / ctx.pi - 1) / 2) * 2 + 1
    # The double nearest an odd (or even) multiple of pi means that multiple, below 2**50
    # only (docs/conventions.md): there doubles are at most 1/4 apart, so each multiple has
    # a nearest double of its own, far from every other multiple. From 2**53 the spacing is
    # 2 and from 2**54 above pi (a double may be the nearest to no multiple, or to two);
    # 2**50 keeps a margin below that, and beyond it every double is taken as it is.
    if 0 < abs(theta0) < 2.0**50 and float(odd * ctx.pi) == theta0:
        up = 1 if theta0 > 0 else -1
        m = (odd - up) / 2
        s, c, one_minus_c = ctx.mpf(up), ctx.mpf(0), ctx.mpf(1)
    elif m != 0 and abs(theta0) < 2.0**50 and float(2 * ctx.pi * m) == theta0:
        s, c = ctx.mpf(0), ctx.mpf(1)  # the double nearest an even multiple: the bottom
        one_minus_c = ctx.mpf(0)
    else:
        r = ctx.mpf(theta0) - 2 * ctx.pi * m
        s, c = ctx.sin(r / 2), ctx.cos(r / 2)
        one_minus_c = 2 * ctx.sin(r / 4) ** 2
    # kc^2 = (c - |w|)(c + |w|). Beside the bottom (c >= 1/2) c - |w| is formed as
    # (1 - |w|) - (1 - c): at a tiny angle c = cos(r/2) = 1 - r^2/8 rounds to 1 at any fixed
    # precision (r = 1e-200 and |w| = 1 would make a rotation a separatrix), while 1 - c =
    # 2 sin^2(r/4) keeps its digits and 1 - |w| = (2 omega0 - |theta'|) / (2 omega0) is
    # rounded once from the exact difference. Nearer the top (c < 1/2, |w| < 1/2 where
    # they meet) the direct difference keeps its relative digits and the other would not.
    if c >= 0.5:
        gap = ctx.fsub(2 * w0, abs(ctx.mpf(dtheta0)), exact=True) / (2 * w0)
        below = gap - one_minus_c
    else:
        below = c - abs(w)
    k2, kc2 = s * s + w * w, below * (c + abs(w))
    k, kc = ctx.sqrt(k2), ctx.sqrt(abs(kc2))
    if s == 0 and w == 0:
        code = regimes.REST
    elif kc2 == 0:
        code = regimes.SEPARATRIX
    elif kc2 > 0:
        code = regimes.LIBRATION
    else:
        code = regimes.ROTATION
    # The elliptic modulus: alpha = k in II (14); gamma = 1/k in IV.
    mod_c, rate = (kc, w0) if kc2 >= 0 else (kc / k, w0 * k)
    (s, s_lo), (c, c_lo), (w, w_lo), (k, k_lo) = (_split(x) for x in (s, c, w, k))
    return (code, float(2 * ctx.pi * m), s, c, w, k, *_split(mod_c), *_split(rate),
            *_split(2 * k2 - 1), s_lo, c_lo, w_lo, k_lo)
