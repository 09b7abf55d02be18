"""One number in, one number out: the array kernels again, on Python floats.

A NumPy call on a single number costs about a microsecond of dispatch, and the kernels of
:mod:`.landen` and :mod:`.flow` make dozens of them. Here the same operations, in the same
order, run on Python floats (whose +, -, *, / and sqrt are the same IEEE operations), and the
transcendental functions are NumPy's own ufuncs, called once each: so a scalar call gives
the very bits of the array call (the tests check it), several times faster.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from scipy import special

from . import landen as _landen
from .codes import LIBRATION, ROTATION, SEPARATRIX
from .dd import (
    PI_HI,
    PI_LO,
    PI_LO2,
    add,
    div,
    fast_two_sum,
    mul,
    mul_d,
    sincos,
    split,
    sqrt,
    two_prod,
    two_sum,
)
from .flow import _DEEP

__all__ = ["jacobi", "landen", "state"]


def _f(ufunc, *args):
    # Underflow to a subnormal or zero is the right answer, and the array path ignores it
    # (np.errstate(under="ignore")); so here, whatever the caller's np.seterr or warning
    # filters. Entering np.errstate costs a microsecond: only on the rare call that signals.
    try:
        return float(ufunc(*args))
    except (FloatingPointError, RuntimeWarning):
        with np.errstate(under="ignore"):
            return float(ufunc(*args))


@lru_cache(maxsize=256)
def landen(kc: float, kc_lo: float) -> _landen.Constants:
    """Return the Landen constants of one modulus as Python floats (cached)."""
    return _agm(kc, kc_lo)


def evaluate(u, c, u_lo=0.0, amplitude=False, name="u", quarters=0.0):
    """Mirror of :func:`.landen.evaluate` for one float (kc > 0)."""
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
    y, x = (ratio, 1.0) if odd else (s, cn_v)
    if abs(y) < 1e-300:  # a subnormal amplitude is right; the array path ignores underflow too
        with np.errstate(under="ignore"):
            am = _f(np.arctan2, y, x)
    else:
        am = _f(np.arctan2, y, x)
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
        d0 = aw / k
        c_l, d0_l, cn_l = cs, d0, cn
        if d0 < _DEEP:  # rescaled as in _flow._rotation
            lam = math.ldexp(1.0, -math.frexp(d0)[1])
            c_l, d0_l, cn_l = lam * cs, lam * d0, lam * cn
        if want_theta:
            d0m1 = -(s / k) * (s / (aw + k))
            spread = cn * cn_l + d0_l * sn * sn
            y = sigma * s * dn * spread + c_l * sn * cn * d0m1
            x = cs * spread - sigma * s * sn * cn_l * dn * d0m1
            delta = _f(np.arctan2, y, x)
            quarters, rest = am
            theta, small = _turned(p, quarters, rest + delta)
            redo = abs(small) < (abs(rest) + abs(delta)) * (1.0 / 64.0)
        if want_dtheta:
            s_k = s / k
            dn_u = ((d0_l * dn - sigma * s_k * (c_l / k) * sn * cn)
                    / (d0_l * d0 + s_k * s_k * cn * cn_l))
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


# --- one initial state: mirrors of classify._near, landen._constants, classify.phases and
# states._chunk, for a state in the usual range (else None: the array path decides) -------

_TWO_PI = (2 * PI_HI, 2 * PI_LO, 2 * PI_LO2)
_TWO_PI_HI = split(_TWO_PI[0])


def _minus_turns(th, m):
    h, lo = th - m * _TWO_PI_HI[0], -m * _TWO_PI_HI[1]
    rh, rl = two_sum(h, lo)
    p, e = two_prod(m, _TWO_PI[1])
    return add(rh, rl, -p, -e - m * _TWO_PI[2])


def _half_angle(th):
    m = float(round(th / _TWO_PI[0]))
    rh, rl = _minus_turns(th, m)
    over = 1.0 if rh > PI_HI else (-1.0 if rh < -PI_HI else 0.0)
    if over != 0:
        m = m + over
        rh, rl = _minus_turns(th, m)
    sign = -1.0 if rh < 0 else 1.0
    ah, al = 0.5 * sign * rh, 0.5 * sign * rl
    top = ah > 0.25 * PI_HI
    dh, dl = add(0.5 * PI_HI, 0.5 * PI_LO, -ah, -al)
    dl = dl + 0.5 * PI_LO2
    yh, yl = (dh, dl) if top else (ah, al)
    sh, sl, ch, cl = sincos(yh, yl, lambda x: float(round(x)), lambda t, j: t[int(j)])
    s = (sign * ch, sign * cl) if top else (sign * sh, sign * sl)
    c = (sh, sl) if top else (ch, cl)
    p, e = two_prod(m, _TWO_PI[0])
    turns = p + (e + m * _TWO_PI[1])
    if m != 0 and th == turns:  # the double nearest 2 pi m: the bottom exactly
        s, c = (0.0, 0.0), (1.0, 0.0)
    odd = 2.0 * math.floor(0.5 * (th / PI_HI + 1.0)) - 1.0
    odd = 1.0 if odd == 0 else odd
    p, e = two_prod(odd, PI_HI)
    if th == p + (e + odd * PI_LO):
        up = 1.0 if th > 0 else -1.0
        m_odd = 0.5 * (odd - up)
        p, e = two_prod(m_odd, _TWO_PI[0])
        turns, s, c = p + (e + m_odd * _TWO_PI[1]), (up, 0.0), (0.0, 0.0)
    return turns, s, c


@lru_cache(maxsize=256)
def _agm(kc: float, kc_lo: float) -> _landen.Constants:
    a, b = 1.0, kc
    done = a == b  # as in landen._constants: at least one step, and one past a, b within 1e-8
    mu, nu = [a], [a if done else b]
    while not done:
        done = abs(a - b) <= 1e-8 * a
        a, b = 0.5 * (a + b), math.sqrt(a * b)
        mu.append(a)
        nu.append(a if done else b)
    ah, al = 1.0, 0.0
    bh, bl = fast_two_sum(kc, kc_lo + 0.0 * kc)
    for _ in range(60):
        dh, dl = two_sum(ah, -bh)
        if abs(dh + (dl + al - bl)) <= 1e-31 * ah:
            break
        sh, sl = two_sum(ah, bh)
        ph, pl = mul(ah, al, bh, bl)
        gh, gl = sqrt(ph, pl, math.sqrt)
        ah, al = fast_two_sum(0.5 * sh, 0.5 * (sl + al + bl))
        bh, bl = gh, gl
    kh, kl = div(0.5 * PI_HI + 0.0 * ah, 0.5 * PI_LO + 0.0 * ah, ah, al)
    k_hi = split(kh)[0]
    k_mid = split(kh - k_hi + kl)[0]
    k_lo = (kh - k_hi - k_mid) + kl
    return _landen.Constants(kc, kh + kl, k_hi, k_mid, k_lo, ah, tuple(mu), tuple(nu))


def _rf(x, y):
    return float(special.elliprf(x, y, 1.0))


def solve(th: float, v: float, w0: float):
    """Public values and Params (Python scalars) of one state, or None for the array path."""
    if not 2.0 ** -300 < w0 < 2.0 ** 300:
        return None
    wh = v / (2.0 * w0)
    if not ((th == 0 or 2.0 ** -300 < abs(th) < 2.0 ** 20)
            and (v == 0 or 2.0 ** -300 <= abs(wh) < 2.0 ** 300)):
        return None
    turns, (sh, sl), (ch, cl) = _half_angle(th)
    p, e = two_prod(wh, 2.0 * w0)
    wl = ((v - p) - e) / (2.0 * w0)
    k2 = add(*mul(sh, sl, sh, sl), *mul(wh, wl, wh, wl))
    aw = -1.0 if wh < 0 else 1.0
    kc2 = mul(*add(ch, cl, -aw * wh, -aw * wl), *add(ch, cl, aw * wh, aw * wl))
    code = LIBRATION if kc2[0] > 0 else (ROTATION if kc2[0] < 0 else SEPARATRIX)
    if sh == 0 and wh == 0:
        return None  # at rest at the bottom: the array path
    k = sqrt(k2[0], k2[1], math.sqrt)
    beta = add(k2[0], k2[1], -kc2[0], -kc2[1])
    if code == SEPARATRIX:
        return None
    kc = sqrt(abs(kc2[0]), -kc2[1] if kc2[0] < 0 else kc2[1], math.sqrt)
    rot = code == ROTATION
    mod_c = div(*kc, *k) if rot else kc
    rate = mul_d(k[0], k[1], w0) if rot else (w0, 0.0)
    if not (rate[0] < 1e290 and mod_c[0] >= 1e-300 and 2.0 ** -400 < w0 < 2.0 ** 400):
        return None
    c1 = mul(*two_prod(w0, 2.0 * w0), *beta)[0]
    if not math.isfinite(c1):
        return None
    landen = _agm(*mod_c)
    q, rem = _phase(sh, ch, wh, k[0], mod_c[0], rot)
    quarter = landen.quarter
    sigma = -1.0 if rot and wh < 0 else 1.0
    if rot:
        period, modulus, amplitude = 2.0 * quarter / rate[0], 1.0 / k[0], math.inf
    else:
        period, modulus = 4.0 * quarter / w0, k[0]
        amplitude = 2.0 * float(np.arctan2(k[0], mod_c[0]))
    public = [th, v, w0, c1, modulus, mod_c[0], amplitude, q * quarter + rem, int(sigma),
              period, beta[0]]
    params = (code, False, th, turns, w0, sigma, k[0], sh, ch, wh, rate[0], rate[1], q, rem,
              landen)
    return public, params


def _phase(s, c, w, k, kc, rot):
    """Mirror of classify.phases for one state of regime II or IV."""
    sgn_s = -1.0 if s < 0 else 1.0
    sgn_w = -1.0 if w < 0 else 1.0
    aw = abs(w)
    if not rot:
        if s * s * (1.0 + kc) < k * k:
            x, y = w / k, c * c
            f = (s / k) * _rf(x * x, y)
            return (0.0, f) if w >= 0 else (2.0 * sgn_s, -f)
        x, y = kc * s / (k * c), kc / c
        f = (w / (k * c)) * _rf(x * x, y * y)
        return sgn_s, -sgn_s * f
    if s * s * (1.0 + kc) < 1.0:
        y = w / k
        return 0.0, (sgn_w * s) * _rf(c * c, y * y)
    x, y = kc * s * k / aw, kc * k / aw
    q = sgn_w * sgn_s
    return q, -q * ((c * k / aw) * _rf(x * x, y * y))
