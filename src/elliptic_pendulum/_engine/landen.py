"""The numerical kernel behind :mod:`elliptic_pendulum.elliptic`.

Three pieces, each chosen for the separatrix, where k rounds to 1.0 and only
the complementary modulus kc carries information:

1. The arithmetic-geometric mean M(1, kc), seeded with kc (never with
   1 - k**2), once in double precision for the descending Landen sequence and
   once in double-double arithmetic for the quarter period K = pi / (2 M), so
   that K is known to about 1e-32 relative.
2. Quarter-period reduction u = n K + v, |v| <= K/2, with K split into three
   parts (Cody and Waite): n K_hi and n K_mid are exact, so v keeps its
   digits even after thousands of periods.
3. The descending Landen (Gauss) recurrence of GSL's ``gsl_sf_elljac_e``
   [Abramowitz & Stegun 16.12, DLMF 22.20(ii)] started from t = tan(pi v /
   (2 K)), |t| <= 1. It multiplies and divides positive numbers only, so
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

from . import dd as _dd
from .dd import PI_HI as _PI_HI
from .dd import PI_LO as _PI_LO
from .dd import fast_two_sum as _fast_two_sum
from .dd import two_prod as _two_prod
from .dd import two_sum as _two_sum

__all__ = ["Constants", "complement", "constants", "core", "evaluate", "quarter_period",
           "reduce", "sech", "gudermannian", "_PI_HI", "_PI_LO", "_two_prod", "_two_sum"]


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
    scale: Any  # pi / (2 K) = M(1, kc)
    mu: tuple          # the AGM sequences a_0 = 1, ..., a_N and b_0 = kc, ..., b_N
    nu: tuple


def _constants(kc: Any, kc_lo: Any = 0.0) -> Constants:
    kc = np.asarray(kc, dtype=float)
    top = kc == 0  # the separatrix: K = inf; run the AGM on a harmless stand-in
    kc_lo = np.where(top, 0.0, kc_lo)
    kc = np.where(top, 1.0, kc)
    # Double precision AGM for the Landen recurrence. The recurrence in `core` starts from the
    # last level as if it were circular, which is off by that level's k_n^2 = 1 - (b_n/a_n)^2
    # ~ 2 (a_n - b_n)/a_n: GSL's stop, once a_n and b_n agree to a few ulp, leaves up to
    # 1.6e-15 (7 ulp in dn and cn, measured near k = 1). So an element stops one step after
    # its a and b agree to 1e-8, where a_n - b_n ~ (a - b)^2 / (8 a) puts k_n^2 below 2.5e-17
    # (kc = 1 is circular at once). From there on its levels repeat a_n with b = a, which
    # makes the extra steps of the recurrence exact identities (d = 1). So an element gets
    # the same bits alone or beside a slower modulus (no dependence on the batch).
    a, b = np.ones_like(kc), kc.copy()
    # Every kc < 1 takes at least one step (`near` is tested before the step): stopped at
    # level 0 (1 - kc <= 8e-16), the recurrence would give dn = cn = kc at v = 0 instead of 1.
    done = a == b
    mu, nu = [a], [np.where(done, a, b)]
    while not np.all(done):
        near = np.abs(a - b) <= 1e-8 * a
        a, b = np.where(done, a, 0.5 * (a + b)), np.where(done, b, np.sqrt(a * b))
        done = done | near
        mu.append(a)
        nu.append(np.where(done, a, b))
        if len(mu) > 40:  # cannot happen for kc in (0, 1]; guards a bug
            raise RuntimeError("AGM did not converge")
    # Double-double AGM for K itself, seeded with kc + kc_lo when the caller knows kc beyond
    # double precision (an initial state of the pendulum); again each element stops alone.
    ah, al = np.ones_like(kc), np.zeros_like(kc)
    bh, bl = _fast_two_sum(kc, kc_lo + 0.0 * kc)
    for _ in range(60):
        dh, dl = _two_sum(ah, -bh)
        done = np.abs(dh + (dl + al - bl)) <= 1e-31 * ah
        if np.all(done):
            break
        sh, sl = _two_sum(ah, bh)
        ph, pl = _dd.mul(ah, al, bh, bl)
        gh, gl = _dd.sqrt(ph, pl, np.sqrt)
        nh, nl = _fast_two_sum(0.5 * sh, 0.5 * (sl + al + bl))
        ah, al = np.where(done, ah, nh), np.where(done, al, nl)
        bh, bl = np.where(done, bh, gh), np.where(done, bl, gl)
    kh, kl = _dd.div(0.5 * _PI_HI + 0.0 * ah, 0.5 * _PI_LO + 0.0 * ah, ah, al)
    k_hi = _chop(kh)
    k_mid = _chop(kh - k_hi + kl)
    k_lo = (kh - k_hi - k_mid) + kl
    return Constants(np.where(top, 0.0, kc), np.where(top, np.inf, kh + kl),
                     np.where(top, np.inf, k_hi), np.where(top, 0.0, k_mid),
                     np.where(top, 0.0, k_lo), ah, tuple(mu), tuple(nu))


@lru_cache(maxsize=256)
def _constants_float(kc: float, kc_lo: float) -> Constants:
    """Compute :func:`_constants` of one modulus on Python floats (its twin: the same bits)."""
    a, b = 1.0, kc
    done = a == b  # as in landen._constants: at least one step, and one past a, b within 1e-8
    mu, nu = [a], [a if done else b]
    while not done:
        done = abs(a - b) <= 1e-8 * a
        a, b = 0.5 * (a + b), math.sqrt(a * b)
        mu.append(a)
        nu.append(a if done else b)
    ah, al = 1.0, 0.0
    bh, bl = _fast_two_sum(kc, kc_lo + 0.0 * kc)
    for _ in range(60):
        dh, dl = _two_sum(ah, -bh)
        if abs(dh + (dl + al - bl)) <= 1e-31 * ah:
            break
        sh, sl = _two_sum(ah, bh)
        ph, pl = _dd.mul(ah, al, bh, bl)
        gh, gl = _dd.sqrt(ph, pl, math.sqrt)
        ah, al = _fast_two_sum(0.5 * sh, 0.5 * (sl + al + bl))
        bh, bl = gh, gl
    kh, kl = _dd.div(0.5 * _PI_HI + 0.0 * ah, 0.5 * _PI_LO + 0.0 * ah, ah, al)
    k_hi = _dd.split(kh)[0]
    k_mid = _dd.split(kh - k_hi + kl)[0]
    k_lo = (kh - k_hi - k_mid) + kl
    return Constants(kc, kh + kl, k_hi, k_mid, k_lo, ah, tuple(mu), tuple(nu))


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
    Returns (n mod 4 as float, n, v).
    """
    n = np.rint(u / c.quarter)
    v = ((u - n * c.k_hi) - n * c.k_mid) + (u_lo - n * c.k_lo)
    n = n + quarters
    return np.mod(n, 4.0), n, v


# Below this kc, sn, cn, dn on |v| <= K/2 are tanh v, sech v, sech v to a relative
# kc/2 (DLMF 22.10.8-10: the corrections are kc^2 sinh^2 v <= kc), while the
# recurrence would start from a subnormal kc and lose its digits.
_TINY_KC = 2.0 ** -60
# n * k_hi and n * k_mid are exact while |n| < 2**26 (they have 26 significant bits).
_MAX_QUARTERS = 2.0 ** 26


def core(v, c: Constants):
    """sn, cn, dn and kc sc at |v| <= K/2 (plus a hair) by the descending Landen recurrence.

    Relative accuracy: every operation after the tangent multiplies or
    divides positive numbers or adds numbers of one sign.
    """
    t = np.tan(v * c.scale)
    mu, nu = c.mu, c.nu
    cc = mu[-1] * t
    d = 1.0
    for n in range(len(mu) - 2, -1, -1):
        r = cc * cc / mu[n + 1]
        cc = d * cc
        d = (r + nu[n]) / (r + mu[n])
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
             quarters=0.0):
    """sn, cn, dn (and am if ``amplitude``; as (n, rest) if it is "split") at u + u_lo.

    For kc in (0, 1].

    Reduces u by quarter periods, evaluates at |v| <= K/2 and shifts back by
    DLMF 22.4.3: sn(v + K) = cd v, cn(v + K) = -kc sd v, dn(v + K) = kc nd v,
    and sn, cn change sign under v -> v + 2K. The reduction is exact for fewer
    than 2**26 quarter periods; beyond, a ValueError names the argument
    (``name``) rather than returning digits that are not there.
    """
    q, n, v = reduce(u, c, u_lo, quarters)
    if np.any(np.abs(n) >= _MAX_QUARTERS):
        raise ValueError(f"{name} is too large: the elliptic argument must stay below "
                         "2**26 quarter periods (about 6.7e7 K1) for an exact reduction")
    s, cn_v, dn_v, ratio = core(v, c)
    odd = (q == 1.0) | (q == 3.0)
    sign = np.where(q >= 2.0, -1.0, 1.0)
    sn = sign * np.where(odd, cn_v / dn_v, s)
    cn = sign * np.where(odd, -c.kc * s / dn_v, cn_v)
    dn = np.where(odd, c.kc / dn_v, dn_v)
    if not amplitude:
        return sn, cn, dn, None
    # am(v + n K) = n pi/2 + (am v, or arctan(kc sc v) for odd n); ratio = kc sc v.
    # One arctan2 pass for both cases (arctan r = arctan2(r, 1)).
    am = np.arctan2(np.where(odd, ratio, s), np.where(odd, 1.0, cn_v))
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


def evaluate_float(u, c, u_lo=0.0, amplitude=False, name="u", quarters=0.0):
    """Compute :func:`evaluate` of one u (kc > 0) on Python floats (its twin: the same bits)."""
    n = float(round(u / c.quarter))
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
        mu, nu = c.mu, c.nu
        cc = mu[-1] * _f(np.tan, v * c.scale)
        d = 1.0
        for i in range(len(mu) - 2, -1, -1):
            r = cc * cc / mu[i + 1]
            cc = d * cc
            d = (r + nu[i]) / (r + mu[i])
        dn_v = c.kc / d
        cn_v = dn_v / _f(np.hypot, 1.0, cc)
        s = cn_v * cc / c.kc
        ratio = cc
    odd = q in (1.0, 3.0)
    sign = -1.0 if q >= 2.0 else 1.0
    sn = sign * (cn_v / dn_v if odd else s)
    cn = sign * (-c.kc * s / dn_v if odd else cn_v)
    dn = c.kc / dn_v if odd else dn_v
    if not amplitude:
        return sn, cn, dn, None
    y, x = (ratio, 1.0) if odd else (s, cn_v)
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
