"""One level of the double-double AGM, on Python floats and in place on arrays.

The level of :mod:`.agm` takes a = ah + al and b = bh + bl (a >= b > 0, Dekker's split
a1 + a2 of ah carried from the level before) to the mean c = (a + b)/2 and the product
p = a b (:func:`step`), then b' = sqrt(p) and the ratio b' / c rounded once (:func:`root`).
The operations are those of :mod:`.dd`'s two_sum, fast_two_sum, mul and sqrt, in their
order (two_sum's error as fast_two_sum gives it, the same exact error), so M and K come
out to the bit as from those functions.

Each has an array twin that does the same operations in the same order into buffers
given by the caller (``out=``): IEEE arithmetic rounds each operation alike either way, so
the bits are the same, and the arrays of a piece (2**14 doubles, 128 KiB) are not
allocated afresh for every one of the fifty-odd operations of a level, which glibc serves
by mapping new pages at that size (measured on a piece: 33 against 8 ns per element for
:func:`step`, though as little as 10 when the allocator happens to keep its pages).
"""

from __future__ import annotations

import math

import numpy as np

from .dd import SPLIT

__all__ = ["root", "root_into", "step", "step_into"]

_add, _sub, _mul, _div = np.add, np.subtract, np.multiply, np.divide


def step(ah, al, bh, bl, a1, a2):
    """Return s = fl(ah + bh), the mean c = (a + b)/2 and the product p = a b (ch, cl, ph, pl).

    The error of s comes from fast_two_sum, not two_sum: both give the exact error, hence
    the same double, as ah >= bh (or the two are within a factor 2, where ah - s and bh - z
    are exact by Sterbenz). p's low part keeps the cross terms to first order (the dropped
    al bl is below 1e-32 of p).
    """
    s = ah + bh
    z = s - ah
    t = 0.5 * (((bh - z) + al) + bl)
    h = 0.5 * s
    ch = h + t
    cl = t - (ch - h)
    ph = ah * bh
    u = SPLIT * bh
    b1 = u - (u - bh)
    b2 = bh - b1
    e = ((((a1 * b1 - ph) + a1 * b2 + a2 * b1) + a2 * b2) + (ah * bl + al * bh))
    x = ph + e
    return s, ch, cl, x, e - (x - ph)


def step_into(ah, al, bh, bl, a1, a2, work):
    """Compute :func:`step` on arrays into ``work`` (at least 9 buffers); s, ch, cl, ph, pl.

    The returned arrays are buffers of ``work`` (ch and cl are new: the caller keeps them).
    """
    s, z, t, h, u, b1, b2, e, f = work[:9]
    _add(ah, bh, out=s)
    _sub(s, ah, out=z)
    _sub(bh, z, out=t)
    _add(t, al, out=t)
    _add(t, bl, out=t)
    _mul(t, 0.5, out=t)
    _mul(s, 0.5, out=h)
    ch = _add(h, t)
    cl = _sub(ch, h)
    _sub(t, cl, out=cl)
    _mul(bh, SPLIT, out=u)
    _sub(u, bh, out=b1)
    _sub(u, b1, out=b1)
    _sub(bh, b1, out=b2)
    ph = _mul(ah, bh, out=z)
    _mul(a1, b1, out=e)
    _sub(e, ph, out=e)
    _mul(a1, b2, out=f)
    _add(e, f, out=e)
    _mul(a2, b1, out=f)
    _add(e, f, out=e)
    _mul(a2, b2, out=f)
    _add(e, f, out=e)
    _mul(ah, bl, out=f)
    _mul(al, bh, out=u)
    _add(f, u, out=f)
    _add(e, f, out=e)
    _add(ph, e, out=h)    # x
    _sub(h, ph, out=f)
    _sub(e, f, out=f)     # the low part
    return s, ch, cl, h, f


def root(ph, pl, ch, cl):
    """Return b = sqrt(p) (bh, bl), the split of ch, the ratio b / c rounded once, its delta.

    b as :func:`.dd.sqrt` gives it. The ratio is q = fl(bh / ch) corrected by the exact
    residual bh - q ch (bh - fl(q ch) is exact: Sterbenz), so it is b / c rounded once, as
    the double-double division gave it; delta is its relative rounding error, which the
    last level of :mod:`.agm` needs.
    """
    x = math.sqrt(ph)
    t = SPLIT * x
    x1 = t - (t - x)
    x2 = x - x1
    xx = x * x
    r = (((ph - xx) - (((x1 * x1 - xx) + x1 * x2 + x2 * x1) + x2 * x2)) + pl) / (2.0 * x)
    bh = x + r
    bl = r - (bh - x)
    q = bh / ch
    t = SPLIT * ch
    c1 = t - (t - ch)
    c2 = ch - c1
    t = SPLIT * q
    q1 = t - (t - q)
    q2 = q - q1
    t = q * ch
    corr = (((bh - t) - (((q1 * c1 - t) + q1 * c2 + q2 * c1) + q2 * c2)) + (bl - q * cl)) / ch
    ratio = q + corr
    return bh, bl, c1, c2, ratio, ((ratio - q) - corr) / ratio


def root_into(ph, pl, ch, cl, work):
    """Compute :func:`root` on arrays; ``work`` holds at least 6 buffers none of ph, pl.

    bh, bl, the split of ch and the ratio are new arrays (the caller keeps them); delta is a
    buffer of ``work``.
    """
    x, t, x1, x2, xx, g = work[:6]
    np.sqrt(ph, out=x)
    _mul(x, SPLIT, out=t)
    _sub(t, x, out=x1)
    _sub(t, x1, out=x1)
    _sub(x, x1, out=x2)
    _mul(x, x, out=xx)
    _mul(x1, x1, out=t)
    _sub(t, xx, out=t)
    _mul(x1, x2, out=g)
    _add(t, g, out=t)
    _mul(x2, x1, out=g)
    _add(t, g, out=t)
    _mul(x2, x2, out=g)
    _add(t, g, out=t)     # the rounding error of x * x
    _sub(ph, xx, out=g)
    _sub(g, t, out=g)
    _add(g, pl, out=g)
    _mul(x, 2.0, out=t)
    _div(g, t, out=g)     # r
    bh = _add(x, g)
    bl = _sub(bh, x)
    _sub(g, bl, out=bl)
    q = _div(bh, ch, out=x)
    c1 = _mul(ch, SPLIT)
    _sub(c1, ch, out=t)
    _sub(c1, t, out=c1)
    c2 = _sub(ch, c1)
    _mul(q, SPLIT, out=t)
    _sub(t, q, out=x1)
    _sub(t, x1, out=x1)   # q1
    _sub(q, x1, out=x2)   # q2
    _mul(q, ch, out=t)
    _mul(x1, c1, out=xx)
    _sub(xx, t, out=xx)
    _mul(x1, c2, out=g)
    _add(xx, g, out=xx)
    _mul(x2, c1, out=g)
    _add(xx, g, out=xx)
    _mul(x2, c2, out=g)
    _add(xx, g, out=xx)   # the rounding error of q * ch
    _sub(bh, t, out=t)
    _sub(t, xx, out=t)
    _mul(q, cl, out=g)
    _sub(bl, g, out=g)
    _add(t, g, out=t)
    _div(t, ch, out=t)    # corr
    ratio = _add(q, t)
    _sub(ratio, q, out=g)
    _sub(g, t, out=g)
    _div(g, ratio, out=g)
    return bh, bl, c1, c2, ratio, g
