"""The Jacobi functions on validated arrays: the edges first, then the Landen kernel.

k = 0 gives sin, cos, 1 and kc = 0 gives tanh, sech, sech (DLMF 22.5(ii)), exactly, for any
u. A modulus k > 1 goes through the reciprocal modulus mu = 1/k (DLMF 22.17.2-4):

    sn(u, k) = mu sn(k u, mu),   cn(u, k) = dn(k u, mu),   dn(u, k) = cn(k u, mu),

and am(u, k) = atan2(mu sn(k u, mu), dn(k u, mu)), bounded for k > 1. The product k u is
kept as a double-double and mu_c = sqrt((k - 1)(k + 1)) / k is formed in double-double
arithmetic, so the reduction by quarter periods is as exact as for k <= 1. Every finite k
works: past k = 2**27 mu_c is 1 - 1/(2 k^2) to 2**-108 (the product overflows past 1e154),
and past 2**900 k u is formed from k 2**-100 and u 2**100 (Dekker's split overflows past
1e300). k u must stay within 2**26 quarter periods K(mu) like any argument, except past
k = 2**537, where 1/k^2 underflows and sn(k u, mu) is sin(k u) (plus its low part) to 1e-35
for any |k u| <= 1e290. Measured against mpmath over k in [2, 1.7e308]: within 3 ulp.
"""

from __future__ import annotations

import math

import numpy as np

from . import dd as _dd
from . import landen as _landen

__all__ = ["values", "values_of_moduli"]

# Many moduli are done in pieces of this many elements, from kc to the result: every
# temporary of the complement, the AGM and the recurrence then stays in the processor's cache.
CHUNK = 2 ** 14
# Above this modulus kc < 1/16 (k > sqrt(1 - 2**-8) = 0.99805) and the double-double
# recurrence takes over (:data:`.careful.SMALL_KC`), or k > 1 takes the reciprocal modulus.
_NEAR_ONE = 0.998


def _ordinary(u, kc, kc_lo, amplitude, u_lo=0.0):
    """sn, cn, dn (and am) for kc (+ kc_lo) in [0, 1]."""
    c = _landen.constants(np.where(kc == 0, 1.0, kc), np.where(kc == 0, 0.0, kc_lo))
    # The edges k = 0 and kc = 0 are overwritten below, for any u: keep them out of the reduction.
    # kc = 1 with a low part is not k = 0 (a tiny k, or a huge one through 1/k): its K exceeds
    # pi/2 by k^2 pi/8, which shifts the phase by k^2 u / 4, so it takes the recurrence.
    circular = (kc == 1) & (kc_lo == 0)
    edge = (kc == 0) | circular
    sn_, cn_, dn_, am_ = _landen.evaluate(np.where(edge, 0.0, u), c, np.where(edge, 0.0, u_lo),
                                          amplitude=amplitude, careful=True)
    if np.any(kc == 0):
        # kc = 0 is the separatrix: sn = tanh, cn = dn = sech, am = gd.
        sech = _landen.sech(u)
        sn_ = np.where(kc == 0, np.tanh(u), sn_)
        cn_ = np.where(kc == 0, sech, cn_)
        dn_ = np.where(kc == 0, sech, dn_)
        if amplitude:
            am_ = np.where(kc == 0, _landen.gudermannian(u), am_)
    if np.any(circular):
        # k = 0: the circular functions, exactly; of u + u_lo where a low part is given (k u
        # for a k so large that 1/k^2 underflows), by the addition theorem.
        s, c = np.sin(u), np.cos(u)
        if np.any(circular & (u_lo != 0)):
            s_lo, c_lo = np.sin(u_lo), np.cos(u_lo)
            s, c = (np.where(u_lo == 0, s, s * c_lo + c * s_lo),
                    np.where(u_lo == 0, c, c * c_lo - s * s_lo))
        sn_ = np.where(circular, s, sn_)
        cn_ = np.where(circular, c, cn_)
        dn_ = np.where(circular, 1.0, dn_)
        if amplitude:
            am_ = np.where(circular, u, am_)
    return sn_, cn_, dn_, am_


def _reciprocal(u, k, amplitude):
    """DLMF 22.17 for k > 1 (elsewhere a harmless stand-in k = 2)."""
    with np.errstate(over="ignore"):
        fine = np.all(np.abs(k * u) <= 1e290)
    if not fine:
        raise ValueError("u is too large: k u must stay below 1e290 for k > 1")
    # k u exactly, as a double-double. Dekker's split overflows past 1e300, so a k beyond 2**900
    # is scaled down by 2**-100 and u up by 2**100 (exact; |u| < 1e19 there, as |k u| <= 1e290).
    scale = np.where(k > 2.0 ** 900, 2.0 ** 100, 1.0)
    x, x_lo = _dd.two_prod(k / scale, u * scale)
    # mu_c = sqrt((k - 1)(k + 1)) / k, whose product overflows past 1e154. Beyond k = 2**27 it
    # is 1 - 1/(2 k^2) to 2**-108 (the next term is 1/(8 k^4)): held as (1, -1/(2 k^2)).
    huge = k > 2.0 ** 27
    kk = np.where(huge, 2.0, k)
    a, a_lo = _dd.two_sum(kk, -1.0)
    b, b_lo = _dd.two_sum(kk, 1.0)
    ph, pl = _dd.mul(a, a_lo, b, b_lo)
    rh, rl = _dd.sqrt(ph, pl, np.sqrt)
    mu_c, mu_c_lo = _dd.div(rh, rl, kk, 0.0 * kk)
    mu = 1.0 / k
    mu_c, mu_c_lo = np.where(huge, 1.0, mu_c), np.where(huge, -0.5 * (mu * mu), mu_c_lo)
    s, c, d, _ = _ordinary(x, mu_c, mu_c_lo, False, x_lo)
    s = s / k  # one rounding (mu s would add the rounding of 1/k, and lose 1/k subnormal)
    am = np.arctan2(s, d) if amplitude else None
    return s, d, c, am


def values(u, k, kc, kc_lo, amplitude=False):
    """sn, cn, dn (and am if asked, else None) for validated float arrays.

    k = |k| may exceed 1 only where kc is 0 (kc cannot be given for k > 1).
    """
    with np.errstate(under="ignore"):  # a subnormal or zero is the right answer there
        return _values(u, k, kc, kc_lo, amplitude)


def values_of_moduli(u, k, amplitude=False):
    """Compute :func:`values` for |k| given alone (kc from k, as modulus_pair forms it).

    Many elements at once go in pieces of CHUNK, each from its complement (one for one
    modulus) to its result (each element's bits are those of one call on the whole array:
    nothing here looks across elements). The moduli above ``_NEAR_ONE`` (kc below 1/16,
    where :mod:`.careful` takes over, and k > 1) are gathered from the whole array and
    done together: the double-double recurrence then runs once on all of them, not once
    per piece on a handful (each such call costs the same few hundred NumPy calls).
    """
    shape = np.broadcast_shapes(u.shape, k.shape)
    size = math.prod(shape)
    if size <= CHUNK:
        return values(u, k, *_landen.complement(np.minimum(k, 1.0)), amplitude)
    _landen.load_compiled(size)
    flat_u = np.broadcast_to(u, shape).ravel()
    count = 4 if amplitude else 3
    if k.ndim == 0:  # one modulus: its kc once, and u in pieces
        outs = _pieces(flat_u, k, amplitude)
    else:
        flat_k = np.broadcast_to(k, shape).ravel()
        near = flat_k > _NEAR_ONE
        if np.any(near):
            where = np.nonzero(near)[0]
            # A harmless stand-in in the pieces; the real values are written below.
            outs = _pieces(np.where(near, 0.0, flat_u), np.where(near, 0.5, flat_k), amplitude)
            got = _pieces(flat_u[where], flat_k[where], amplitude)
            for out, x in zip(outs, got, strict=True):
                out[where] = x
        else:
            outs = _pieces(flat_u, flat_k, amplitude)
    result = [out.reshape(shape) for out in outs[:count]]
    return result[0], result[1], result[2], result[3] if amplitude else None


def _pieces(flat_u, k, amplitude):
    """:func:`values` of flat u and k (or one modulus k) in pieces of CHUNK, as new arrays."""
    one = k.ndim == 0
    pair = _landen.complement(np.minimum(k, 1.0)) if one else None
    outs = [np.empty(flat_u.size) for _ in range(4 if amplitude else 3)]
    for i in range(0, flat_u.size, CHUNK):
        piece = slice(i, i + CHUNK)
        kk = k if one else k[piece]
        kc = pair if pair is not None else _landen.complement(np.minimum(kk, 1.0))
        got = values(flat_u[piece], kk, *kc, amplitude)
        for out, x in zip(outs, got, strict=False):
            out[piece] = x
    return outs


def _values(u, k, kc, kc_lo, amplitude):
    big = k > 1
    sn_, cn_, dn_, am_ = _ordinary(u, kc, kc_lo, amplitude)
    if np.any(big):
        r = _reciprocal(np.where(big, u, 0.0), np.where(big, k, 2.0), amplitude)
        sn_, cn_, dn_ = (np.where(big, x, y) for x, y in zip(r[:3], (sn_, cn_, dn_),
                                                             strict=True))
        if amplitude:
            am_ = np.where(big, r[3], am_)
    return sn_, cn_, dn_, am_



def values_float(u: float, k: float, amplitude: bool = False):
    """Compute :func:`values` of one u and one modulus 0 < k < 1 on Python floats (its twin).

    sn, cn, dn (and am), the bits of the array call; None where the array path decides.
    """
    if not 0.0 < k < 1.0 or not math.isfinite(u):
        return None
    a, a_lo = _dd.two_sum(1.0, -k)
    b, b_lo = _dd.two_sum(1.0, k)
    p, p_lo = _dd.mul(a, a_lo, b, b_lo)
    kc, kc_lo = _dd.sqrt(p, p_lo, math.sqrt)
    if kc == 1.0:
        return None  # k so small that kc rounds to 1: the circular edge, on the array path
    return _landen.evaluate_float(u, _landen.constants_float(kc, kc_lo), amplitude=amplitude,
                                  careful=True)
