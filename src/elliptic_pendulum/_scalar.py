"""One number in, one number out: the array kernels again, on Python floats.

A NumPy call on a single number costs about a microsecond of dispatch, and the kernels of
:mod:`._landen` and :mod:`._flow` make dozens of them. Here the same operations, in the same
order, run on Python floats (whose +, -, *, / and sqrt are the same IEEE operations), and the
transcendental functions are NumPy's own ufuncs, called once each: so a scalar call gives
the very bits of the array call (the tests check it), several times faster.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from . import _landen
from ._dd import PI_HI, PI_LO, mul, sqrt, two_prod, two_sum

__all__ = ["jacobi", "landen", "state"]

LIBRATION, SEPARATRIX, ROTATION = 1, 2, 3


def _f(ufunc, *args):
    return float(ufunc(*args))


@lru_cache(maxsize=256)
def landen(kc: float, kc_lo: float) -> _landen.Constants:
    """Return the Landen constants of one modulus as Python floats (cached)."""
    c = _landen.constants(kc, kc_lo)
    return _landen.Constants._make([*(float(x) for x in c[:6]), tuple(float(x) for x in c.mu),
                                    tuple(float(x) for x in c.nu)])


def evaluate(u, c, u_lo=0.0, amplitude=False, name="u", quarters=0.0):
    """Mirror of :func:`._landen.evaluate` for one float (kc > 0)."""
    n = float(round(u / c.quarter))
    v = ((u - n * c.k_hi) - n * c.k_mid) + (u_lo - n * c.k_lo)
    n = n + quarters
    if abs(n) >= _landen._MAX_QUARTERS:
        raise ValueError(f"{name} is too large: the elliptic argument must stay below "
                         "2**26 quarter periods (about 6.7e7 K1) for an exact reduction")
    q = n % 4.0
    if c.kc < _landen._TINY_KC:
        sech_v = _f(_landen.sech, v)
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
    am = _f(np.arctan, ratio) if odd else _f(np.arctan2, s, cn_v)
    if amplitude == "split":
        return sn, cn, dn, (n, am)
    return sn, cn, dn, (n * (0.5 * PI_HI) + am) + n * (0.5 * PI_LO)


def _turned(p, quarters, rest):
    count = 2.0 * float(round(p.turns / (2.0 * PI_HI))) + p.sigma * quarters
    big, err = two_prod(count, PI_HI)
    small = (err + count * PI_LO) + p.sigma * 2.0 * rest
    return big + small, small


def state(p, t: float, want_theta: bool = True, want_dtheta: bool = True):
    """theta(t) and theta'(t) of one state (Params of Python floats) at one time t.

    The caller keeps the separatrix (III, moving) on the array path.
    """
    if p.still:
        return p.theta0, 0.0
    if not (abs(t) <= 1e290 and abs(t) * p.rate <= 1e290):
        raise ValueError("t is too large: |omega0 t| must stay below about 1e290 "
                         "(the elliptic argument grows like omega0 t)")
    a, a_lo = two_prod(p.rate, t)
    rot = p.code == ROTATION
    c = p.landen
    sn, cn, dn, am = evaluate(a, c, a_lo + p.rate_lo * t, amplitude="split" if rot else False,
                              name="t")
    s, cs, w, k, sigma = p.s, p.c, p.w, p.k, p.sigma
    theta = dtheta = None
    if rot:
        aw = abs(w)
        if want_theta:
            d0 = aw / k
            d0m1 = -(s / k) * (s / (aw + k))
            spread = cn * cn + d0 * sn * sn
            y = sigma * s * dn * spread + cs * sn * cn * d0m1
            x = cs * spread - sigma * s * sn * cn * dn * d0m1
            delta = _f(np.arctan2, y, x)
            quarters, rest = am
            theta, small = _turned(p, quarters, rest + delta)
            redo = abs(small) < (abs(rest) + abs(delta)) * (1.0 / 64.0)
        if want_dtheta:
            d0, s_k = aw / k, s / k
            dn_u = (d0 * dn - sigma * s_k * (cs / k) * sn * cn) / (d0 * d0 + s_k * s_k * cn * cn)
            dtheta = sigma * 2.0 * p.rate * dn_u
    else:
        if want_theta:
            first, second = s * cn * dn, w * cs * sn
            y = first + second
            x = cs * dn - s * w * sn * cn
            theta = p.turns + 2.0 * _f(np.arctan2, y, x)
            redo = abs(y) < (abs(first) + abs(second)) * (1.0 / 64.0)
        if want_dtheta:
            dtheta = 2.0 * p.omega0 * (w * cn - s * cs * sn * dn) / (cs * cs + s * s * cn * cn)
    if want_theta and redo:
        u, u_lo = two_sum(a, p.rem)
        u_lo = u_lo + (a_lo + p.rate_lo * t)
        sn, _, dn, (quarters, rest) = evaluate(u, c, u_lo, amplitude="split", name="t",
                                               quarters=p.quarters)
        theta = _turned(p, quarters, rest)[0] if rot else \
            p.turns + 2.0 * _f(np.arctan2, k * sn, dn)
    return theta, dtheta


def jacobi(u: float, k: float, amplitude: bool = False):
    """sn, cn, dn (and am) of one u and one modulus 0 < k < 1 given as k; else None."""
    if not 0.0 < k < 1.0 or not math.isfinite(u):
        return None
    a, a_lo = two_sum(1.0, -k)
    b, b_lo = two_sum(1.0, k)
    p, p_lo = mul(a, a_lo, b, b_lo)
    kc, kc_lo = sqrt(p, p_lo, math.sqrt)
    if kc == 1.0:
        return None  # k so small that kc rounds to 1: the circular edge, on the array path
    return evaluate(u, landen(kc, kc_lo), amplitude=amplitude)
