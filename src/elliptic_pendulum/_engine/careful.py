"""The Landen recurrence in double-double arithmetic, for small kc (a modulus near 1).

Near k = 1 the quarter period K ~ log(4/kc) is long, and at the far end of the reduced
range, |v| ~ K/2, cn and dn move by |v| times any relative error of the phase: measured,
one ulp of tan(phi) moved dn(v) by 3.4 ulp and the recurrence's own roundings by up to 5
more (cn(u, k) = dn(k u, 1/k) 7.6 ulp off just above k = 1 on the Boost.Math rows). Here
the phase phi = v M and its tangent (sin / cos from :func:`.dd.sincos`, |phi| <= pi/4), the
recurrence and the final quotients are carried as double-doubles and rounded once at the
end; what is left is the rounding of the Landen levels (about an ulp). It costs a few
hundred operations per element, so only elements with kc below ``SMALL_KC`` take it.

Written in plain arithmetic, so the same code serves NumPy arrays and Python floats (the
float twin of the kernel), given the ``rint`` and ``take`` of :func:`.dd.sincos`.
"""

from __future__ import annotations

import math

import numpy as np

from . import dd as _dd

__all__ = ["SMALL_KC", "overwrite", "values", "values_float"]

#: Below this kc (k above 0.998) the kernel takes the double-double recurrence.
SMALL_KC = 2.0 ** -4

_TABLES = tuple(np.array(t) for t in (_dd.SIN_HI, _dd.SIN_LO, _dd.COS_HI, _dd.COS_LO))


def _take(table, j):
    return table[j.astype(np.intp)]


def _core(v, v_lo, kc, scale, scale_lo, mu, rho, sign, sincos, root):
    # The phase as a double-double, its tangent from the double-double sine and cosine of
    # |phi| (the recurrence runs on positive numbers; the sign returns in cc).
    ph, pl = _dd.mul(v, v_lo, scale, scale_lo)
    neg = sign(ph)
    sh, sl, ch, cl = sincos(neg * ph, neg * pl)
    th, tl = _dd.div(sh, sl, ch, cl)
    cc = _dd.mul_d(th, tl, mu[-1])
    d = (1.0 + 0.0 * v, 0.0 * v)
    for n in range(len(mu) - 2, -1, -1):
        r = _dd.div(*_dd.mul(*cc, *cc), mu[n + 1], 0.0 * v)
        cc = _dd.mul(*d, *cc)
        x = _dd.div(*r, *_dd.add(*r, mu[n], 0.0 * v))
        d = _dd.add(*_dd.mul(*x, *_dd.two_sum(1.0, -rho[n])), rho[n], 0.0 * v)
    h = _dd.sqrt(*_dd.add(*_dd.mul(*cc, *cc), 1.0, 0.0 * v), root)
    return neg, cc, d, h


def _finish(q, kc, neg, cc, d, h):
    """sn, cn, dn (each rounded once) and the am inputs s, c and kc sc at n K + v."""
    g = _dd.mul(*d, *h)
    s_v = _dd.div(*cc, *g)[0]
    c_v = _dd.div(kc, 0.0 * kc, *g)[0]
    dn_v = _dd.div(kc, 0.0 * kc, *d)[0]
    odd_sn = _dd.div(1.0, 0.0 * kc, *h)[0]
    odd_cn = _dd.div(*cc, *h)[0]
    return s_v, c_v, dn_v, odd_sn, odd_cn, d[0] + d[1], neg * (cc[0] + cc[1])


def values(q, v, v_lo, c):
    """sn, cn, dn at n K + v (q = n mod 4) and s, cn_v, kc sc v for am, on arrays."""
    neg, cc, d, h = _core(v, v_lo, c.kc, c.scale, c.scale_lo, c.mu, c.rho,
                          lambda x: np.copysign(1.0, x),
                          lambda yh, yl: _dd.sincos(yh, yl, np.rint, _take, _TABLES), np.sqrt)
    s_v, c_v, dn_v, odd_sn, odd_cn, odd_dn, ratio = _finish(q, c.kc, neg, cc, d, h)
    s_v = neg * s_v
    odd = (q == 1.0) | (q == 3.0)
    sign = np.where(q >= 2.0, -1.0, 1.0)
    sn = sign * np.where(odd, odd_sn, s_v)
    cn = sign * np.where(odd, -neg * odd_cn, c_v)
    dn = np.where(odd, odd_dn, dn_v)
    return sn, cn, dn, s_v, c_v, ratio


def values_float(q, v, v_lo, c):
    """Compute :func:`values` of one element on Python floats (its twin: the same bits)."""
    neg, cc, d, h = _core(v, v_lo, c.kc, c.scale, c.scale_lo, c.mu, c.rho,
                          lambda x: math.copysign(1.0, x),
                          lambda yh, yl: _dd.sincos(yh, yl, lambda x: float(round(x)),
                                                    lambda t, j: t[int(j)]), math.sqrt)
    s_v, c_v, dn_v, odd_sn, odd_cn, odd_dn, ratio = _finish(q, c.kc, neg, cc, d, h)
    s_v = neg * s_v
    odd = q in (1.0, 3.0)
    sign = -1.0 if q >= 2.0 else 1.0
    if odd:
        return sign * odd_sn, sign * (-neg * odd_cn), odd_dn, s_v, c_v, ratio
    return sign * s_v, sign * c_v, dn_v, s_v, c_v, ratio


def overwrite(mask, q, v, v_lo, c, outs):
    """Return ``outs`` (sn, cn, dn, s, cn_v, kc sc v) with :func:`values` where ``mask``.

    ``c`` is the Landen constants (:class:`.landen.Constants`); only the masked elements
    are gathered and computed.
    """
    shape = np.broadcast_shapes(np.shape(v), np.shape(mask), *(np.shape(x) for x in outs))
    where = np.nonzero(np.broadcast_to(mask, shape)) if shape else ()

    def pick(x):
        return np.broadcast_to(x, shape)[where]

    sub = c._make([*(pick(x) for x in c[:-2]), tuple(pick(x) for x in c.mu),
                   tuple(pick(x) for x in c.rho)])
    new = values(pick(q), pick(v), pick(v_lo), sub)
    result = []
    for old, x in zip(outs, new, strict=True):
        # The kernel's own fresh arrays are written in place; a broadcast one is copied.
        owned = isinstance(old, np.ndarray) and old.shape == shape and old.base is None
        full = old if owned else np.array(np.broadcast_to(old, shape))
        full[where] = x
        result.append(full)
    return result
