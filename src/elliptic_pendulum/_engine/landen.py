"""The numerical kernel behind :mod:`elliptic_pendulum.elliptic`.

Three pieces, each chosen for the separatrix, where k rounds to 1.0 and only
the complementary modulus kc carries information:

1. The arithmetic-geometric mean M(1, kc), seeded with kc (never with
   1 - k**2), in double-double arithmetic: the quarter period K = pi / (2 M)
   to about 1e-32 relative, and the descending Landen sequence (its levels
   a_n and ratios b_n / a_n, rounded to double). In :mod:`.agm`, whose names
   this module passes on.
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

from typing import Any

import numpy as np

from . import careful as _careful
from .agm import (
    SCALARS,
    Constants,
    _constants_float,
    compiled_for,
    complement,
    constants,
    constants_float,
    load_compiled,
    quarter_period,
)
from .dd import PI_HI as _PI_HI
from .dd import PI_LO as _PI_LO
from .dd import two_prod as _two_prod
from .dd import two_sum as _two_sum

__all__ = ["SCALARS", "Constants", "compiled_for", "complement", "constants", "constants_float",
           "core", "evaluate", "load_compiled", "quarter_period", "reduce", "sech",
           "gudermannian", "_PI_HI", "_PI_LO", "_constants_float", "_two_prod", "_two_sum"]


def reduce(u, c: Constants, u_lo=0.0, quarters=0.0, split=True):
    """Split u (+ u_lo) + quarters K = n K + v with n an integer-valued float, |v| <= K/2.

    ``quarters`` (whole quarter periods) lets a caller hold an argument as a multiple of K
    plus an exact remainder: the remainder then keeps its relative accuracy at t = 0.
    Returns (n mod 4 as float, n, v, v_lo): v + v_lo is the remainder as a double-double
    (the first two products are exact, the rest is rounded far below v's last bit); without
    ``split``, v alone (the same v) and v_lo None.
    """
    compiled = compiled_for(np.size(u))
    if compiled is not None:  # the same operations compiled
        return compiled.reduce(u, c, u_lo, quarters, split)
    n = np.rint(u / c.quarter)
    if split:
        v, v_lo = _two_sum((u - n * c.k_hi) - n * c.k_mid, u_lo - n * c.k_lo)
    else:
        v, v_lo = ((u - n * c.k_hi) - n * c.k_mid) + (u_lo - n * c.k_lo), None
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


def core(v, c: Constants, v_lo=None):
    """sn, cn, dn and kc sc at |v| <= K/2 (plus a hair) by the descending Landen recurrence.

    Relative accuracy: every operation after the tangent multiplies or
    divides positive numbers or adds numbers of one sign. With ``v_lo`` (the remainder's
    low part) the phase is a double-double (:func:`phase_tangent`); without, v M rounded.
    """
    if v_lo is None:
        t = np.tan(v * c.scale)
    else:
        t = phase_tangent(v, v_lo, c.scale, c.scale_lo, np.tan)
    mu, rho = c.mu, c.rho
    cc = np.multiply(mu[-1], t, out=np.empty(np.broadcast_shapes(np.shape(mu[-1]), np.shape(t))))
    r, x = np.empty(cc.shape), np.empty(cc.shape)
    compiled = compiled_for(cc.size)
    if compiled is not None:  # the same operations compiled
        cc, d = compiled.recurrence(cc, mu, rho)
    else:
        d = _recurrence(cc, mu, rho, r, x)
    # Here cc = kc * sc(v) and d = kc / dn(v) (GSL's first branch). The operations are
    # those of the expressions, in their order; written into arrays made once, as a
    # piece's temporaries (2**14 doubles or more) would each be mapped afresh by glibc.
    dn = np.divide(c.kc, d)
    cn = np.divide(dn, np.hypot(1.0, cc, out=x))
    sn = np.multiply(cn, cc, out=r)
    np.divide(sn, c.kc, out=sn)
    tiny = c.kc < _TINY_KC
    if np.any(tiny):
        sech_v = sech(v)
        sn = np.where(tiny, np.tanh(v), sn)
        cn = np.where(tiny, sech_v, cn)
        dn = np.where(tiny, sech_v, dn)
        with np.errstate(over="ignore"):  # |v| > 710 only for |u| past exact reduction
            cc = np.where(tiny, c.kc * np.sinh(v), cc)
    return sn, cn, dn, cc


def _recurrence(cc, mu, rho, r, x):
    """Run the recurrence of :func:`core` as NumPy passes: cc in place, d returned.

    d = rho + (1 - rho) (r / (r + a_n)) for (r + b_n) / (r + a_n), in place; r and x are
    work arrays of cc's shape. The first step's cc = d cc with d = 1 is an identity, left out.
    """
    d: Any = 1.0
    for n in range(len(mu) - 2, -1, -1):
        np.multiply(cc, cc, out=r)
        np.divide(r, mu[n + 1], out=r)
        if n < len(mu) - 2:
            np.multiply(d, cc, out=cc)
        else:
            d = np.empty(cc.shape)
        np.add(r, mu[n], out=x)
        np.divide(r, x, out=r)
        np.subtract(1.0, rho[n], out=x)
        np.multiply(x, r, out=x)
        np.add(rho[n], x, out=d)
    return d


def evaluate(u, c: Constants, u_lo=0.0, amplitude: bool | str = False, name: str = "u",
             quarters=0.0, careful: bool = False):
    """sn, cn, dn (and am if ``amplitude``; as (n, rest) if it is "split") at u + u_lo.

    For kc in (0, 1].

    Reduces u by quarter periods, evaluates at |v| <= K/2 and shifts back by
    DLMF 22.4.3: sn(v + K) = cd v, cn(v + K) = -kc sd v, dn(v + K) = kc nd v,
    and sn, cn change sign under v -> v + 2K. The reduction is exact for fewer
    than 2**26 quarter periods; beyond, a ValueError names the argument
    (``name``) rather than returning digits that are not there. With ``careful`` the
    elements with kc below 1/16 take the double-double recurrence of :mod:`.careful` and
    every element a double-double phase (the public Jacobi functions: within 4 ulp on the
    Boost/GSL rows); a motion's theta(t) does without (and keeps its speed).
    """
    q, n, v, v_lo = reduce(u, c, u_lo, quarters, split=careful)
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
    if careful:
        v, v_lo = _two_sum((u - n * c.k_hi) - n * c.k_mid, u_lo - n * c.k_lo)
    else:
        v = ((u - n * c.k_hi) - n * c.k_mid) + (u_lo - n * c.k_lo)
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
        if careful:
            cc = mu[-1] * phase_tangent(v, v_lo, c.scale, c.scale_lo, lambda x: _f(np.tan, x))
        else:
            cc = mu[-1] * _f(np.tan, v * c.scale)
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
