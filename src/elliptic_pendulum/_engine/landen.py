"""The numerical kernel behind :mod:`elliptic_pendulum.elliptic`.

Three pieces, each chosen for the separatrix, where k rounds to 1.0 and only
the complementary modulus kc carries information:

1. The arithmetic-geometric mean M(1, kc), seeded with kc (never with
   1 - k**2), in double-double arithmetic: the quarter period K = pi / (2 M)
   to about 1e-32 relative, and the descending Landen sequence (its levels
   a_n and ratios b_n / a_n, rounded to double).
2. Quarter-period reduction u = n K + v, |v| <= K/2, with K split into three
   parts (Cody and Waite): n K_hi and n K_mid are exact, so v keeps its
   digits even after thousands of periods.
3. The descending Landen (Gauss) recurrence of GSL's ``gsl_sf_elljac_e``
   [Abramowitz & Stegun 16.12, DLMF 22.20(ii)] started from t = tan(pi v /
   (2 K)), |t| <= 1, the phase v M = pi v / (2 K) formed as a double-double
   (v keeps the low part of the reduction, M that of the AGM). Below kc = 1/16
   the recurrence runs in double-double arithmetic (:mod:`.careful`). It
   multiplies and divides positive numbers only, so
   sn(v), cn(v) and dn(v) come out with small *relative* error; the shift by
   n K is exact algebra (DLMF 22.4.3). One tangent and a few multiplications
   per point, and no branch on the size of t: this is why it is faster than
   scipy's ``ellipj``, which calls arcsin at every Landen step.
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import Any, NamedTuple

import numpy as np

from . import careful as _careful
from . import dd as _dd
from .dd import PI_HI as _PI_HI
from .dd import PI_LO as _PI_LO
from .dd import fast_two_sum as _fast_two_sum
from .dd import two_prod as _two_prod
from .dd import two_sum as _two_sum

__all__ = ["SCALARS", "Constants", "complement", "constants", "core", "evaluate",
           "quarter_period", "reduce", "sech", "gudermannian", "_PI_HI", "_PI_LO",
           "_two_prod", "_two_sum"]


def _chop(x):
    """Keep the top 26 bits of x, so that n * chop(x) is exact for |n| < 2**26."""
    return _dd.split(x)[0]


class Constants(NamedTuple):
    """What the recurrence needs for one complementary modulus (or an array of them).

    Arrays, or Python floats on the fast path of one number (the private ``_scalar``).
    """

    kc: Any
    quarter: Any  # K rounded to double
    k_hi: Any   # K = k_hi + k_mid + k_lo (quarter period), n*k_hi and n*k_mid exact
    k_mid: Any
    k_lo: Any
    scale: Any  # pi / (2 K) = M(1, kc) = scale + scale_lo (a double-double)
    scale_lo: Any
    mu: tuple   # the AGM sequence a_0 = 1, ..., a_N (a_N: see `_piece`)
    rho: tuple  # b_0 / a_0 = kc, ..., b_N / a_N = 1 (the last level is circular)


#: How many of the fields of Constants are one number per modulus (the rest: mu, rho).
SCALARS = 7

# An element's AGM stops where a - b <= 1e-8 a: there r = (a - b)/(a + b) <= 5e-9, and
# M(a, b) = c (1 - r^2/4 - 5 r^4/64 - ...) with c = (a + b)/2 (from Gauss's
# M(1 + r, 1 - r) = pi / (2 K(r)) and K(r) = pi/2 (1 + r^2/4 + 9 r^4/64 + ...)) is
# c (1 - r^2/4) to 5e-35: two double-double steps fewer than iterating to 1e-32.
_NEAR = 1e-8
# Arrays longer than this are done in pieces that stay in the processor's cache (a piece of
# 2**14 doubles is 128 KiB): the double-double AGM runs about 2.5 times faster so.
CHUNK = 2 ** 14


def _constants(kc: Any, kc_lo: Any = 0.0) -> Constants:
    kc = np.asarray(kc, dtype=float)
    kc_lo = np.broadcast_to(np.asarray(kc_lo, dtype=float), np.broadcast_shapes(
        kc.shape, np.shape(kc_lo)))
    kc = np.broadcast_to(kc, kc_lo.shape)
    if kc.size <= CHUNK:
        return _piece(kc, kc_lo)
    shape = kc.shape
    flat, flat_lo = kc.ravel(), kc_lo.ravel()
    parts = [_piece(flat[i:i + CHUNK], flat_lo[i:i + CHUNK])
             for i in range(0, flat.size, CHUNK)]
    levels = max(len(c.mu) for c in parts)

    def join(arrays):
        return np.concatenate(arrays).reshape(shape)

    # Repeating an element's last level (where b = a) is an exact identity of the
    # recurrence in `core`, so pieces that converged in fewer steps can share one length.
    mu = [join(column) for column in zip(*(pad(c.mu, levels) for c in parts), strict=True)]
    rho = [join(column) for column in zip(*(pad(c.rho, levels) for c in parts), strict=True)]
    return Constants._make([*(join([c[j] for c in parts]) for j in range(SCALARS)), tuple(mu),
                            tuple(rho)])


def pad(levels: tuple, n: int) -> tuple:
    """Repeat the last of the AGM levels up to ``n`` of them (an exact identity in `core`)."""
    return tuple(levels) + (levels[-1],) * (n - len(levels))


def _piece(kc: Any, kc_lo: Any) -> Constants:
    """Compute :func:`_constants` of one piece: one double-double AGM serves K and `core`.

    The AGM M(1, kc + kc_lo) runs in double-double arithmetic, seeded with kc (never with
    1 - k**2), for K = pi / (2 M) to about 1e-32 relative; its levels give the descending
    Landen sequence a_n (``mu``, rounded to double) and the ratios b_n / a_n (``rho``, each
    rounded once from the double-double quotient), and `core` takes d = rho + (1 - rho) s,
    a sum of two positive terms, where GSL has (r + b_n) / (r + a_n) (measured: cn and dn
    just above k = 1 from 14 ulp to 8). The recurrence starts from the last level as if it
    were circular, which is off by that level's k_n^2 ~ 4 (a_n - b_n) / (a_n + b_n): an
    element stops where a - b <= 1e-8 a, and its next level, one step on (k^2 below
    2.5e-17), is made circular, rho = 1; so are all levels after it, which makes the extra
    steps of the recurrence exact identities (d = 1). That last a_N, free to within k_N^2,
    is chosen so that the recurrence's slope at v = 0 is one on the rounded levels,
    M a_N rho_1 ... rho_(N-1) = kc in double-double (else the roundings of the levels add
    up in sn(u) ~ u: 4.7 ulp at u = 3e-8 on GSL's rows). An element gets the same bits alone
    or beside a slower modulus (no dependence on the batch).
    """
    shape = kc.shape
    top = kc == 0  # the separatrix: K = inf; run the AGM on a harmless stand-in
    kc_lo = np.where(top, 0.0, kc_lo).ravel()
    kc = np.where(top, 1.0, kc).ravel()
    size = kc.size
    # The elements still iterating, by index (the others have their M): each step works on
    # those alone, with the same operations as on the whole piece (the same bits).
    idx = np.arange(size)
    ah, al = np.ones(size), np.zeros(size)
    bh, bl = _fast_two_sum(kc, kc_lo)
    mu, rho, stop = [ah], [bh], np.zeros(size)  # stop: the level N of each element
    mh, ml = np.empty(size), np.empty(size)
    # rho_1 ... rho_j in double-double (ph, pl), and its value where an element stopped (qh, ql)
    ph, pl = np.ones(size), np.zeros(size)
    qh, ql = np.empty(size), np.empty(size)
    for level in range(1, 61):  # 12 steps at kc = 1e-300; the cap guards a bug
        dh, dl = _two_sum(ah, -bh)
        diff = dh + (dl + (al - bl))  # a - b >= 0
        sh, sl = _two_sum(ah, bh)
        ch, cl = _fast_two_sum(0.5 * sh, 0.5 * (sl + al + bl))  # c = (a + b)/2
        near = diff <= _NEAR * ah
        r = diff / sh
        nh, nl = _fast_two_sum(ch, cl - ch * (0.25 * r * r))  # M = c (1 - r^2/4)
        here = idx[near]
        mh[here], ml[here], qh[here], ql[here] = nh[near], nl[near], ph[near], pl[near]
        stop[here] = level
        a_level = np.empty(size)  # where stopped, the last level: a_N is set below
        a_level[idx] = ch
        mu.append(a_level)
        go = ~near
        if not np.any(go):
            rho.append(np.ones(size))
            break
        if not np.all(go):
            idx, ah, al, bh, bl, ch, cl, ph, pl = (x[go] for x in (idx, ah, al, bh, bl, ch, cl,
                                                                   ph, pl))
        xh, xl = _dd.mul(ah, al, bh, bl)
        bh, bl = _dd.sqrt(xh, xl, np.sqrt)
        ah, al = ch, cl
        ratio = _dd.div(bh, bl, ah, al)[0]
        ph, pl = _dd.mul_d(ph, pl, ratio)
        rho_level = np.ones(size)
        rho_level[idx] = ratio
        rho.append(rho_level)
    else:
        raise RuntimeError("AGM did not converge")
    last = _dd.div(kc, 0.0 * kc, *_dd.mul(mh, ml, qh, ql))[0]  # a_N = kc / (M rho_1 ...)
    mu = [mu[0], *(np.where(stop <= n, last, a) for n, a in enumerate(mu[1:], 1))]
    mu, rho = [x.reshape(shape) for x in mu], [x.reshape(shape) for x in rho]
    kc, mh, ml = kc.reshape(shape), mh.reshape(shape), ml.reshape(shape)
    kh, kl = _dd.div(0.5 * _PI_HI + 0.0 * mh, 0.5 * _PI_LO + 0.0 * mh, mh, ml)
    k_hi = _chop(kh)
    k_mid = _chop(kh - k_hi + kl)
    k_lo = (kh - k_hi - k_mid) + kl
    return Constants(np.where(top, 0.0, kc), np.where(top, np.inf, kh + kl),
                     np.where(top, np.inf, k_hi), np.where(top, 0.0, k_mid),
                     np.where(top, 0.0, k_lo), mh, ml, tuple(mu), tuple(rho))


@lru_cache(maxsize=256)
def _constants_float(kc: float, kc_lo: float) -> Constants:
    """Compute :func:`_constants` of one modulus on Python floats (its twin: the same bits)."""
    ah, al = 1.0, 0.0
    bh, bl = _fast_two_sum(kc, kc_lo + 0.0 * kc)
    mu, rho = [ah], [bh]
    ph, pl = 1.0, 0.0
    while True:
        dh, dl = _two_sum(ah, -bh)
        diff = dh + (dl + (al - bl))
        sh, sl = _two_sum(ah, bh)
        ch, cl = _fast_two_sum(0.5 * sh, 0.5 * (sl + al + bl))
        if diff <= _NEAR * ah:
            r = diff / sh
            mh, ml = _fast_two_sum(ch, cl - ch * (0.25 * r * r))
            mu.append(_dd.div(kc, 0.0 * kc, *_dd.mul(mh, ml, ph, pl))[0])
            rho.append(1.0)
            break
        xh, xl = _dd.mul(ah, al, bh, bl)
        bh, bl = _dd.sqrt(xh, xl, math.sqrt)
        ah, al = ch, cl
        ratio = _dd.div(bh, bl, ah, al)[0]
        ph, pl = _dd.mul_d(ph, pl, ratio)
        mu.append(ah)
        rho.append(ratio)
    kh, kl = _dd.div(0.5 * _PI_HI + 0.0 * mh, 0.5 * _PI_LO + 0.0 * mh, mh, ml)
    k_hi = _dd.split(kh)[0]
    k_mid = _dd.split(kh - k_hi + kl)[0]
    k_lo = (kh - k_hi - k_mid) + kl
    return Constants(kc, kh + kl, k_hi, k_mid, k_lo, mh, ml, tuple(mu), tuple(rho))


@lru_cache(maxsize=256)
def _scalar_constants(kc: float, kc_lo: float) -> Constants:
    return _constants(np.float64(kc), kc_lo)


def constants(kc: Any, kc_lo: Any = 0.0) -> Constants:
    """Landen constants for kc (+ kc_lo); cached for a scalar kc (one modulus, many u)."""
    with np.errstate(under="ignore"):  # a tiny kc_lo squared underflows, harmlessly
        if np.ndim(kc) == 0 and np.ndim(kc_lo) == 0:
            return _scalar_constants(float(kc), float(kc_lo))
        return _constants(kc, kc_lo)


@lru_cache(maxsize=256)
def constants_float(kc: float, kc_lo: float) -> Constants:
    """Return the Landen constants of one modulus as Python floats (cached)."""
    return _constants_float(kc, kc_lo)


def complement(k: Any) -> tuple[Any, Any]:
    """Kc = sqrt((1 - k)(1 + k)) as a double-double (hi, lo), for a modulus given as k.

    Rounding kc to a double moves K by about one ulp, and that error grows with
    every period of u: sn(1e4, k) would lose three digits. With the low part
    the AGM is seeded with kc to about 1e-32.
    """
    k = np.asarray(k, dtype=float)
    a, a_lo = _two_sum(1.0, -k)
    b, b_lo = _two_sum(1.0, k)
    p, p_lo = _dd.mul(a, a_lo, b, b_lo)
    with np.errstate(divide="ignore", invalid="ignore"):  # k = 1: kc = 0 exactly
        hi, lo = _dd.sqrt(p, p_lo, np.sqrt)
    return np.where(p == 0, 0.0, hi), np.where(p == 0, 0.0, lo)


def quarter_period(kc: Any, kc_lo: Any = 0.0) -> Any:
    """K(k) from kc (+ kc_lo), correctly rounded in practice (double-double AGM)."""
    return constants(kc, kc_lo).quarter


def reduce(u, c: Constants, u_lo=0.0, quarters=0.0):
    """Split u (+ u_lo) + quarters K = n K + v with n an integer-valued float, |v| <= K/2.

    ``quarters`` (whole quarter periods) lets a caller hold an argument as a multiple of K
    plus an exact remainder: the remainder then keeps its relative accuracy at t = 0.
    Returns (n mod 4 as float, n, v, v_lo): v + v_lo is the remainder as a double-double
    (the first two products are exact, the rest is rounded far below v's last bit).
    """
    n = np.rint(u / c.quarter)
    v, v_lo = _two_sum((u - n * c.k_hi) - n * c.k_mid, u_lo - n * c.k_lo)
    n = n + quarters
    return np.mod(n, 4.0), n, v, v_lo


# Below this kc, sn, cn, dn on |v| <= K/2 are tanh v, sech v, sech v to a relative
# kc/2 (DLMF 22.10.8-10: the corrections are kc^2 sinh^2 v <= kc), while the
# recurrence would start from a subnormal kc and lose its digits.
_TINY_KC = 2.0 ** -60
# n * k_hi and n * k_mid are exact while |n| < 2**26 (they have 26 significant bits).
_MAX_QUARTERS = 2.0 ** 26


def phase_tangent(v, v_lo, scale, scale_lo, tan):
    """Tan(phi) for the phase phi = (v + v_lo)(scale + scale_lo) held as a double-double.

    The product is exact (Dekker) and the low part enters to first order, tan(phi + e) =
    tan(phi) + e (1 + tan^2 phi): one rounding of the phase, scaled by |v| at the far end of
    a quarter period near k = 1 (K ~ log(4/kc)), would cost up to four ulp in cn and dn.
    """
    phi, e = _two_prod(v, scale)
    e = e + (v * scale_lo + v_lo * scale)
    t = tan(phi)
    return t + e * (1.0 + t * t)


def core(v, c: Constants, v_lo=0.0):
    """sn, cn, dn and kc sc at |v| <= K/2 (plus a hair) by the descending Landen recurrence.

    Relative accuracy: every operation after the tangent multiplies or
    divides positive numbers or adds numbers of one sign.
    """
    t = phase_tangent(v, v_lo, c.scale, c.scale_lo, np.tan)
    mu, rho = c.mu, c.rho
    cc = mu[-1] * t
    d = 1.0
    for n in range(len(mu) - 2, -1, -1):
        r = cc * cc / mu[n + 1]
        cc = d * cc
        d = rho[n] + (1.0 - rho[n]) * (r / (r + mu[n]))  # (r + b_n) / (r + a_n)
    # Here cc = kc * sc(v) and d = kc / dn(v) (GSL's first branch).
    dn = c.kc / d
    cn = dn / np.hypot(1.0, cc)
    sn = cn * cc / c.kc
    tiny = c.kc < _TINY_KC
    if np.any(tiny):
        sech_v = sech(v)
        sn = np.where(tiny, np.tanh(v), sn)
        cn = np.where(tiny, sech_v, cn)
        dn = np.where(tiny, sech_v, dn)
        with np.errstate(over="ignore"):  # |v| > 710 only for |u| past exact reduction
            cc = np.where(tiny, c.kc * np.sinh(v), cc)
    return sn, cn, dn, cc


def evaluate(u, c: Constants, u_lo=0.0, amplitude: bool | str = False, name: str = "u",
             quarters=0.0, careful: bool = False):
    """sn, cn, dn (and am if ``amplitude``; as (n, rest) if it is "split") at u + u_lo.

    For kc in (0, 1].

    Reduces u by quarter periods, evaluates at |v| <= K/2 and shifts back by
    DLMF 22.4.3: sn(v + K) = cd v, cn(v + K) = -kc sd v, dn(v + K) = kc nd v,
    and sn, cn change sign under v -> v + 2K. The reduction is exact for fewer
    than 2**26 quarter periods; beyond, a ValueError names the argument
    (``name``) rather than returning digits that are not there. With ``careful`` the
    elements with kc below 1/16 take the double-double recurrence of :mod:`.careful`
    (the public Jacobi functions: within 4 ulp there; a motion's theta(t) does without).
    """
    q, n, v, v_lo = reduce(u, c, u_lo, quarters)
    if np.any(np.abs(n) >= _MAX_QUARTERS):
        raise ValueError(f"{name} is too large: the elliptic argument must stay below "
                         "2**26 quarter periods (about 6.7e7 K1) for an exact reduction")
    s, cn_v, dn_v, ratio = core(v, c, v_lo)
    odd = (q == 1.0) | (q == 3.0)
    sign = np.where(q >= 2.0, -1.0, 1.0)
    sn = sign * np.where(odd, cn_v / dn_v, s)
    cn = sign * np.where(odd, -c.kc * s / dn_v, cn_v)
    dn = np.where(odd, c.kc / dn_v, dn_v)
    careful = careful & (c.kc < _careful.SMALL_KC) & (c.kc >= _TINY_KC)
    if np.any(careful):
        sn, cn, dn, s, cn_v, ratio = _careful.overwrite(careful, q, v, v_lo, c,
                                                        (sn, cn, dn, s, cn_v, ratio))
    if not amplitude:
        return sn, cn, dn, None
    # am(v + n K) = n pi/2 + (am v = arctan(sc v), or arctan(kc sc v) for odd n), from
    # ratio = kc sc v alone (fewer roundings than sn and cn): one arctan2 pass for both
    # cases, arctan2(ratio, kc) and arctan2(ratio, 1).
    am = np.arctan2(ratio, np.where(odd, 1.0, c.kc))
    if amplitude == "split":  # am = n pi/2 + am, for a caller that adds n pi/2 exactly
        return sn, cn, dn, (n, am)
    return sn, cn, dn, (n * (0.5 * _PI_HI) + am) + n * (0.5 * _PI_LO)


def _f(ufunc, *args):
    """One NumPy ufunc on Python floats, as a float (the bits of the array call)."""
    # Underflow to a subnormal or zero is the right answer, and the array path ignores it
    # (np.errstate(under="ignore")); so here, whatever the caller's np.seterr or warning
    # filters. Entering np.errstate costs a microsecond: only on the rare call that signals.
    try:
        return float(ufunc(*args))
    except (FloatingPointError, RuntimeWarning):
        with np.errstate(under="ignore"):
            return float(ufunc(*args))


def evaluate_float(u, c, u_lo=0.0, amplitude=False, name="u", quarters=0.0, careful=False):
    """Compute :func:`evaluate` of one u (kc > 0) on Python floats (its twin: the same bits)."""
    n = float(round(u / c.quarter))
    v, v_lo = _two_sum((u - n * c.k_hi) - n * c.k_mid, u_lo - n * c.k_lo)
    n = n + quarters
    if abs(n) >= _MAX_QUARTERS:
        raise ValueError(f"{name} is too large: the elliptic argument must stay below "
                         "2**26 quarter periods (about 6.7e7 K1) for an exact reduction")
    q = n % 4.0
    if c.kc < _TINY_KC:
        sech_v = _f(sech, v)
        s, cn_v, dn_v, ratio = _f(np.tanh, v), sech_v, sech_v, c.kc * _f(np.sinh, v)
    else:
        mu, rho = c.mu, c.rho
        cc = mu[-1] * phase_tangent(v, v_lo, c.scale, c.scale_lo, lambda x: _f(np.tan, x))
        d = 1.0
        for i in range(len(mu) - 2, -1, -1):
            r = cc * cc / mu[i + 1]
            cc = d * cc
            d = rho[i] + (1.0 - rho[i]) * (r / (r + mu[i]))
        dn_v = c.kc / d
        cn_v = dn_v / _f(np.hypot, 1.0, cc)
        s = cn_v * cc / c.kc
        ratio = cc
    odd = q in (1.0, 3.0)
    sign = -1.0 if q >= 2.0 else 1.0
    sn = sign * (cn_v / dn_v if odd else s)
    cn = sign * (-c.kc * s / dn_v if odd else cn_v)
    dn = c.kc / dn_v if odd else dn_v
    if careful and _TINY_KC <= c.kc < _careful.SMALL_KC:
        sn, cn, dn, s, cn_v, ratio = _careful.values_float(q, v, v_lo, c)
    if not amplitude:
        return sn, cn, dn, None
    y, x = (ratio, 1.0) if odd else (ratio, c.kc)
    if abs(y) < 1e-300:  # a subnormal amplitude is right; the array path ignores underflow too
        with np.errstate(under="ignore"):
            am = _f(np.arctan2, y, x)
    else:
        am = _f(np.arctan2, y, x)
    if amplitude == "split":
        return sn, cn, dn, (n, am)
    return sn, cn, dn, (n * (0.5 * _PI_HI) + am) + n * (0.5 * _PI_LO)


def sech(x):
    """Return 1 / cosh x; past |x| = 710 cosh overflows to inf and the quotient is 0."""
    with np.errstate(over="ignore"):
        return 1.0 / np.cosh(x)


def gudermannian(x):
    """Return gd x = arctan(sinh x); past |x| = 710 sinh is +-inf and arctan gives +-pi/2."""
    with np.errstate(over="ignore"):
        return np.arctan(np.sinh(x))
