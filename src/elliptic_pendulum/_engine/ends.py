"""The two ends of the AGM on arrays, in place: its seed kc from k, and K from M.

:func:`complement` is kc = sqrt((1 - k)(1 + k)) and :func:`quarter_parts` is
K = pi / (2 M) split in three parts, both double-doubles, by the operations of
:mod:`.dd`'s two_sum, mul, sqrt and div in their order (so the bits are theirs), written
into a few arrays made once per call. As expressions, each of their thirty-odd temporaries
of a piece (2**14 doubles, 128 KiB) could be mapped afresh by glibc: measured on a piece,
the complement went from 49 to 16 ns per element and K from 60 to 42 (how much depends on
what the allocator holds at the time; never slower).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .dd import PI_HI, PI_LO, SPLIT

__all__ = ["complement", "quarter_parts"]

_add, _sub, _mul, _div = np.add, np.subtract, np.multiply, np.divide


def _split_into(x, hi, lo):
    """Dekker's split of x into hi (26 bits) + lo, in place (:func:`.dd.split`)."""
    _mul(x, SPLIT, out=hi)
    _sub(hi, x, out=lo)
    _sub(hi, lo, out=hi)
    _sub(x, hi, out=lo)


def _error_into(x1, x2, y1, y2, p, out, tmp):
    """Write the rounding error of p = fl(x y) into out: ((x1 y1 - p) + x1 y2 + x2 y1) + x2 y2."""
    _mul(x1, y1, out=out)
    _sub(out, p, out=out)
    _mul(x1, y2, out=tmp)
    _add(out, tmp, out=out)
    _mul(x2, y1, out=tmp)
    _add(out, tmp, out=out)
    _mul(x2, y2, out=tmp)
    _add(out, tmp, out=out)


def _two_sum_one(x, hi, lo, tmp):
    """(hi, lo) = two_sum(1.0, x), into hi and lo (:func:`.dd.two_sum`)."""
    _add(x, 1.0, out=hi)
    _sub(hi, 1.0, out=tmp)   # bb = s - a
    _sub(hi, tmp, out=lo)
    _sub(1.0, lo, out=lo)    # a - (s - bb)
    _sub(x, tmp, out=tmp)    # b - bb
    _add(lo, tmp, out=lo)


def complement(k: Any) -> tuple[Any, Any]:
    """Kc = sqrt((1 - k)(1 + k)) as (hi, lo) for an array k in [0, 1]; 0 where k = 1.

    The operations of two_sum(1, -k), two_sum(1, k), mul and sqrt of :mod:`.dd`.
    """
    shape = np.shape(k)
    a, a_lo, b, b_lo, p, t, u, w = (np.empty(shape) for _ in range(8))
    _two_sum_one(np.negative(k, out=w), a, a_lo, t)
    _two_sum_one(k, b, b_lo, t)
    _mul(a, b, out=p)                    # two_prod(a, b)
    _mul(a, b_lo, out=t)                 # the cross terms a b_lo + a_lo b
    _mul(a_lo, b, out=u)
    _add(t, u, out=t)
    _split_into(a, a_lo, b_lo)
    _split_into(b, u, w)
    _error_into(a_lo, b_lo, u, w, p, a, b)
    _add(a, t, out=a)                    # x = e + cross
    _add(p, a, out=b)                    # fast_two_sum(p, x): the product (b, t)
    _sub(b, p, out=t)
    _sub(a, t, out=t)
    np.sqrt(b, out=p)                    # sqrt of (b, t): x = p
    _mul(p, p, out=a)
    _split_into(p, u, w)
    _error_into(u, w, u, w, a, a_lo, b_lo)
    _sub(b, a, out=a)
    _sub(a, a_lo, out=a)
    _add(a, t, out=a)                    # r = ((b - x x) - e) + t
    _mul(p, 2.0, out=u)
    with np.errstate(divide="ignore", invalid="ignore"):  # k = 1: kc = 0 exactly
        _div(a, u, out=a)
    _add(p, a, out=u)                    # fast_two_sum(x, r / (2 x))
    _sub(u, p, out=w)
    _sub(a, w, out=w)
    zero = b == 0
    if np.any(zero):
        np.copyto(u, 0.0, where=zero)
        np.copyto(w, 0.0, where=zero)
    return u, w


def quarter_parts(mh: Any, ml: Any) -> tuple[Any, Any, Any, Any]:
    """K = pi / (2 M) rounded, and its three parts k_hi + k_mid + k_lo (Cody and Waite).

    The operations of div(pi/2, M) of :mod:`.dd` (its constant numerator pi/2 as a Python
    float: 0.5 PI_HI + 0 M is that float for the finite M > 0 here) and of the splits of
    :mod:`.agm`. k_hi and k_mid hold 26 bits each, so n k_hi and n k_mid are exact.
    """
    half, half_lo = 0.5 * PI_HI, 0.5 * PI_LO
    q, t, u, v, w, x, y, z = (np.empty(np.shape(mh)) for _ in range(8))
    _div(half, mh, out=q)
    _mul(q, mh, out=t)                   # two_prod(q, mh)
    _split_into(q, u, v)
    _split_into(mh, w, x)
    _error_into(u, v, w, x, t, y, z)
    _mul(q, ml, out=u)                   # q ml + (0 q) mh, the second term +0
    _add(u, 0.0, out=u)
    _add(y, u, out=y)                    # fast_two_sum(t, y + u): the product (v, w)
    _add(t, y, out=v)
    _sub(v, t, out=w)
    _sub(y, w, out=w)
    np.negative(v, out=x)                # two_sum(pi/2, -product)
    _add(x, half, out=u)
    _sub(u, half, out=t)
    _sub(u, t, out=y)
    _sub(half, y, out=y)
    _sub(x, t, out=t)
    _add(y, t, out=y)
    _sub(y, w, out=y)                    # r = s + ((f - e) + pi_lo/2)
    _add(y, half_lo, out=y)
    _add(u, y, out=y)
    _div(y, mh, out=y)                   # fast_two_sum(q, r / mh) = (t, u)
    _add(q, y, out=t)
    _sub(t, q, out=u)
    _sub(y, u, out=u)
    _mul(t, SPLIT, out=v)                # k_hi: the top 26 bits of t
    _sub(v, t, out=w)
    _sub(v, w, out=v)
    _sub(t, v, out=w)                    # k_mid: those of (t - k_hi) + u
    _add(w, u, out=w)
    _mul(w, SPLIT, out=x)
    _sub(x, w, out=y)
    _sub(x, y, out=x)
    _sub(t, v, out=y)                    # k_lo = ((t - k_hi) - k_mid) + u
    _sub(y, x, out=y)
    _add(y, u, out=y)
    _add(t, u, out=w)
    return w, v, x, y
