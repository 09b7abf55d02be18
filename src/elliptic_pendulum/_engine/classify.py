r"""Classify initial states into the note's regimes I-IV and parametrize them, many at once.

The energy constant of (9) is :math:`c_1 = \theta'^2 - 2\omega_0^2\cos\theta`.
The note splits on it: I (c1 = -2 w0^2, rest), II (``|c1| < 2 w0^2``, swinging),
III (c1 = 2 w0^2, the separatrix) and IV (c1 > 2 w0^2, rotating).

Nothing here goes through c1, because c1 -> arccos -> sin loses every digit
at small amplitudes and near the top. With s = sin(theta/2), c = cos(theta/2)
and w = theta' / (2 omega0), the squared modulus and its complement are

.. math:: k^2 = s^2 + w^2, \qquad k_c^2 = 1 - k^2 = (c - |w|)(c + |w|),

each free of cancellation (the design note: "never lose the energy"). They are formed
in double-double arithmetic (:mod:`.dd`, about 32 digits) from the exact doubles
of the initial state, elementwise on arrays: near the separatrix kc^2 = c^2 - w^2
is a difference of nearly equal numbers, and rounding c or w to double first
would be multiplied by 1 / kc^2 there. Regime II has modulus alpha = k (14);
regime IV has gamma = 1/k, and beta = 2 k^2 - 1 (29).

The double nearest an odd multiple of pi (``math.pi``, ``3 * math.pi``, ...) is
taken to mean that multiple, so that ``solve(math.pi)`` is the pendulum balanced
upside down; likewise the double nearest a nonzero even multiple (``2 * math.pi``,
``math.radians(360)``, ``-4 * math.pi``, ...) means that multiple, the bottom, so that
``solve(2 * math.pi)`` is at rest (regime I). Every other angle is taken exactly as the
double it is.

No global state: states far outside the usual range (angles beyond 2**20 rad, or
theta'/(2 omega0) beyond 2**(+-300) in size) go through a private mpmath context made
for the call (:mod:`.farstates`), never through ``mpmath.mp``.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from scipy import special

from . import dd as _dd
from .codes import LIBRATION, REST, ROTATION, SEPARATRIX

__all__ = ["State", "classify", "phases"]


class State(NamedTuple):
    """Initial states reduced and parametrized (see :func:`classify`); arrays of one shape."""

    code: np.ndarray       # REST, LIBRATION, SEPARATRIX or ROTATION
    turns: np.ndarray      # 2 pi m, rounded once; theta0 = 2 pi m + r, |r| <= pi
    s: np.ndarray          # sin(r/2)
    c: np.ndarray          # cos(r/2) >= 0
    w: np.ndarray          # theta0' / (2 omega0)
    k: np.ndarray          # sqrt(s^2 + w^2): alpha in II; 1/gamma in IV
    mod_c: np.ndarray      # complement of the elliptic modulus: alpha_c (II), gamma_c (IV)
    mod_c_lo: np.ndarray   # its low part: mod_c + mod_c_lo to about 1e-32
    rate: np.ndarray       # d(argument)/dt: omega0 in II, omega0 / gamma = omega0 k in IV
    rate_lo: np.ndarray    # its low part
    beta: np.ndarray       # c1 / (2 omega0^2) = 2 k^2 - 1, the note's beta of (29)
    beta_lo: np.ndarray    # its low part
    s_lo: np.ndarray       # the low parts of s, c, w and k (double-doubles to about 1e-32)
    c_lo: np.ndarray
    w_lo: np.ndarray
    k_lo: np.ndarray


_TABLES = tuple(np.array(t) for t in (_dd.SIN_HI, _dd.SIN_LO, _dd.COS_HI, _dd.COS_LO))
_TWO_PI = (2 * _dd.PI_HI, 2 * _dd.PI_LO, 2 * _dd.PI_LO2)
_TWO_PI_HI = _dd.split(_TWO_PI[0])  # 26-bit pieces: m * piece is exact for |m| < 2**26
_NEAR = 2.0 ** 20                   # |theta0| below this reduces here; beyond, _farstates
_HUGE, _TINY = 2.0 ** 300, 2.0 ** -300
# Below this modulus (only far states: a tiny swing) k^2 and s^2 underflow, so the test for
# the branch in phases() is made on s and k times _LIFT (exact): k * _LIFT >= 2**-474, and
# s, k < 2**-500 keep the squares below 2**200.
_SMALL_K, _LIFT = 2.0 ** -500, 2.0 ** 600


def _take(table, j):
    return table[j.astype(np.intp)]


def _minus_turns(th, m):
    """theta0 - 2 pi m as a double-double, exact to about 2**-150 |m| (Cody and Waite)."""
    h, lo = th - m * _TWO_PI_HI[0], -m * _TWO_PI_HI[1]  # both exact
    rh, rl = _dd.two_sum(h, lo)
    p, e = _dd.two_prod(m, _TWO_PI[1])
    rh, rl = _dd.add(rh, rl, -p, -e - m * _TWO_PI[2])
    return rh, rl


def _minus_turns_float(th, m):
    """Compute :func:`_minus_turns` on Python floats (its twin: the same bits)."""
    h, lo = th - m * _TWO_PI_HI[0], -m * _TWO_PI_HI[1]
    rh, rl = _dd.two_sum(h, lo)
    p, e = _dd.two_prod(m, _TWO_PI[1])
    return _dd.add(rh, rl, -p, -e - m * _TWO_PI[2])


def _odd_pi(th):
    """Return where th is the double nearest an odd multiple of pi, and that odd integer."""
    # The double nearest n pi divides by pi to n itself (or within an ulp of n, which rint
    # gives back): rint, not floor, whose quotient may fall an ulp below the odd integer
    # (-13 * math.pi / math.pi is -13.000000000000002). An even n is no odd multiple: any
    # odd candidate then fails the exact comparison below.
    odd = np.rint(th / _dd.PI_HI)
    odd = np.where(np.fmod(odd, 2.0) == 0, odd + 1.0, odd)
    p, e = _dd.two_prod(odd, _dd.PI_HI)
    return th == p + (e + odd * _dd.PI_LO), odd


def _half_angle(th):
    """Return (turns, s, c) of theta0 = 2 pi m + r; s, c = sin(r/2), cos(r/2) double-double."""
    m = np.rint(th / _TWO_PI[0])
    rh, rl = _minus_turns(th, m)
    # rint(th / 2pi) in doubles can miss by one next to an odd multiple of pi: keep |r| <= pi.
    over = np.where(rh > _dd.PI_HI, 1.0, np.where(rh < -_dd.PI_HI, -1.0, 0.0))
    if np.any(over != 0):
        m = m + over
        rh, rl = _minus_turns(th, m)
    sign = np.where(rh < 0, -1.0, 1.0)
    ah, al = 0.5 * sign * rh, 0.5 * sign * rl          # |r| / 2 in [0, pi/2]
    top = ah > 0.25 * _dd.PI_HI
    # Above pi/4 use the distance to pi/2: c = sin(pi/2 - |r|/2) keeps its relative digits.
    dh, dl = _dd.add(0.5 * _dd.PI_HI, 0.5 * _dd.PI_LO, -ah, -al)
    dl = dl + 0.5 * _dd.PI_LO2
    yh, yl = np.where(top, dh, ah), np.where(top, dl, al)
    sh, sl, ch, cl = _dd.sincos(yh, yl, np.rint, _take, _TABLES)
    s = (sign * np.where(top, ch, sh), sign * np.where(top, cl, sl))
    c = (np.where(top, sh, ch), np.where(top, sl, cl))
    p, e = _dd.two_prod(m, _TWO_PI[0])
    turns = p + (e + m * _TWO_PI[1])
    # The double nearest a nonzero even multiple 2 pi m (2 * math.pi, -4 * math.pi, ...)
    # means that multiple, the bottom, as the doubles nearest odd multiples mean the top:
    # r = 0, s = 0, c = 1 (at rest there: regime I, theta = theta0 for ever).
    even = (m != 0) & (th == turns)
    if np.any(even):
        s = (np.where(even, 0.0, s[0]), np.where(even, 0.0, s[1]))
        c = (np.where(even, 1.0, c[0]), np.where(even, 0.0, c[1]))
    odd, n = _odd_pi(th)
    if np.any(odd):  # exactly upside down: r = +-pi (sign of theta0), s = +-1, c = 0
        up = np.where(th > 0, 1.0, -1.0)
        m_odd = 0.5 * (n - up)
        p, e = _dd.two_prod(m_odd, _TWO_PI[0])
        turns = np.where(odd, p + (e + m_odd * _TWO_PI[1]), turns)
        s = (np.where(odd, up, s[0]), np.where(odd, 0.0, s[1]))
        c = (np.where(odd, 0.0, c[0]), np.where(odd, 0.0, c[1]))
    return turns, s, c


def _half_angle_float(th):
    """Compute :func:`_half_angle` on Python floats (its twin: the same bits)."""
    m = float(round(th / _TWO_PI[0]))
    rh, rl = _minus_turns_float(th, m)
    over = 1.0 if rh > _dd.PI_HI else (-1.0 if rh < -_dd.PI_HI else 0.0)
    if over != 0:
        m = m + over
        rh, rl = _minus_turns_float(th, m)
    sign = -1.0 if rh < 0 else 1.0
    ah, al = 0.5 * sign * rh, 0.5 * sign * rl
    top = ah > 0.25 * _dd.PI_HI
    dh, dl = _dd.add(0.5 * _dd.PI_HI, 0.5 * _dd.PI_LO, -ah, -al)
    dl = dl + 0.5 * _dd.PI_LO2
    yh, yl = (dh, dl) if top else (ah, al)
    sh, sl, ch, cl = _dd.sincos(yh, yl, lambda x: float(round(x)), lambda t, j: t[int(j)])
    s = (sign * ch, sign * cl) if top else (sign * sh, sign * sl)
    c = (sh, sl) if top else (ch, cl)
    p, e = _dd.two_prod(m, _TWO_PI[0])
    turns = p + (e + m * _TWO_PI[1])
    if m != 0 and th == turns:  # the double nearest 2 pi m: the bottom exactly
        s, c = (0.0, 0.0), (1.0, 0.0)
    odd = float(round(th / _dd.PI_HI))
    odd = odd + 1.0 if math.fmod(odd, 2.0) == 0 else odd
    p, e = _dd.two_prod(odd, _dd.PI_HI)
    if th == p + (e + odd * _dd.PI_LO):
        up = 1.0 if th > 0 else -1.0
        m_odd = 0.5 * (odd - up)
        p, e = _dd.two_prod(m_odd, _TWO_PI[0])
        turns, s, c = p + (e + m_odd * _TWO_PI[1]), (up, 0.0), (0.0, 0.0)
    return turns, s, c


def _near(th, v, w0):
    """Classify in double-double arithmetic, for states in the usual range."""
    turns, (sh, sl), (ch, cl) = _half_angle(th)
    wh = v / (2.0 * w0)
    p, e = _dd.two_prod(wh, 2.0 * w0)
    wl = ((v - p) - e) / (2.0 * w0)
    k2 = _dd.add(*_dd.mul(sh, sl, sh, sl), *_dd.mul(wh, wl, wh, wl))
    aw = np.where(wh < 0, -1.0, 1.0)
    awh, awl = aw * wh, aw * wl
    kc2 = _dd.mul(*_dd.add(ch, cl, -awh, -awl), *_dd.add(ch, cl, awh, awl))
    code = np.where(kc2[0] > 0, LIBRATION, np.where(kc2[0] < 0, ROTATION, SEPARATRIX))
    code = np.where((sh == 0) & (wh == 0), REST, code)
    moving = code != REST
    k = _dd.sqrt(np.where(moving, k2[0], 1.0), np.where(moving, k2[1], 0.0), np.sqrt)
    kc_sq = np.abs(kc2[0]), np.where(kc2[0] < 0, -kc2[1], kc2[1])
    off = code != SEPARATRIX
    kc = _dd.sqrt(np.where(off, kc_sq[0], 1.0), np.where(off, kc_sq[1], 0.0), np.sqrt)
    rot = code == ROTATION
    gc = _dd.div(*kc, *k)                               # gamma_c = |kc| / k in IV
    rate = _dd.mul_d(*k, w0)                            # omega0 / gamma in IV
    mod_c = (np.where(rot, gc[0], kc[0]), np.where(rot, gc[1], kc[1]))
    mod_c = (np.where(off, mod_c[0], 0.0), np.where(off, mod_c[1], 0.0))
    rate = (np.where(rot, rate[0], w0), np.where(rot, rate[1], 0.0))
    beta = _dd.add(*k2, -kc2[0], -kc2[1])                # k^2 - kc^2 = 2 k^2 - 1
    k_out, k_lo = np.where(moving, k[0], 0.0), np.where(moving, k[1], 0.0)
    return State(code, turns, sh, ch, wh, k_out, *mod_c, *rate, *beta, sl, cl, wl, k_lo)


def classify(theta0: np.ndarray, dtheta0: np.ndarray, omega0: np.ndarray) -> State:
    """Reduce the initial states and find their regimes without cancellation.

    The arguments are float arrays of one shape (already checked: finite, omega0 > 0).
    Each element is classified on its own; the complement of the elliptic modulus and the
    rate of the elliptic argument are kept as double-doubles.

    The limit of the arithmetic: c - |w| is known to an absolute error of about 3e-32
    (measured up to 2.3e-32 against mpmath; 1e-50 for the far states), so
    kc^2 = (c - |w|)(c + |w|) has the relative error cond = 3e-32 / |c - |w||, the
    complement of the modulus half of it, K an absolute error of about cond / 2 and the
    period a relative one below cond. Off the separatrix (|c - |w|| of order 1) that fixes
    K, the period and the phase to about 1e-32 relative, and the phase stays right over
    thousands of periods; near it the elliptic argument drifts by up to about cond per
    quarter period. Where |c - |w|| is below about 3e-32 (cond >= 1) the sign of kc^2,
    hence the regime (II, III or IV), is not determined by the arithmetic. On the exact
    separatrix (r = 0 with |w| = 1, or the top at rest) everything is exact.
    """
    from . import farstates as _farstates  # mpmath only for the rare far states

    th, v, w0 = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in
                                      (theta0, dtheta0, omega0)))
    with np.errstate(all="ignore"):  # only to find the far states; nothing is kept from here
        w = np.abs(v / (2.0 * w0))
        far = ((np.abs(th) >= _NEAR) | ((th != 0) & (np.abs(th) < _TINY))
               | ((v != 0) & ((w >= _HUGE) | (w < _TINY))) | (w0 >= _HUGE) | (w0 < _TINY))
    if not np.any(far):
        return _near(th, v, w0)
    state = _near(np.where(far, 0.0, th), np.where(far, 0.0, v), np.where(far, 1.0, w0))
    fields = [np.array(f, dtype=float) for f in state]
    for flat in np.flatnonzero(far):
        index = np.unravel_index(flat, far.shape)
        for field, value in zip(fields, _farstates.classify(th[index], v[index], w0[index]),
                                strict=True):
            field[index] = value
    fields[0] = fields[0].astype(int)
    return State(*fields)


def _rf(x, y):
    """Carlson's R_F(x, y, 1) (DLMF 19.16.1); elementwise, each element on its own."""
    return special.elliprf(x, y, 1.0)


def phases(st: State, quarter: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return the elliptic argument at t = 0 as (q, rem): q quarter periods plus |rem| <~ K/2.

    II: am(c2, alpha) = atan2(s, w); IV: am(c4, gamma) = direction r / 2. Near a turning
    point (II) or the top (IV) the argument is K minus a small g, and g is computed directly,
    as F(phi', k) with sn, cn, dn of K - c from DLMF 22.4.3 (sn(K - c) = cd c, ...), so that
    theta'(0) comes back to full relative accuracy. F(phi) = sin(phi) R_F(cos^2 phi,
    1 - k^2 sin^2 phi, 1) (DLMF 19.25.5), with every argument formed without cancellation.
    Other regimes get (0, 0).
    """
    s, c, w, k, kc = st.s, st.c, st.w, st.k, st.mod_c
    lib, rot = st.code == LIBRATION, st.code == ROTATION
    sgn_s = np.where(s < 0, -1.0, 1.0)
    sgn_w = np.where(w < 0, -1.0, 1.0)
    with np.errstate(all="ignore"):  # the branch not taken may divide by zero; np.where drops it
        # |sn| < sn(K/2) = 1/sqrt(1 + kc): nearer the bottom than the turn (strictly, so that
        # a state at the turn itself, where 1 + kc may round to 1, is counted there). For a
        # tiny swing s^2 and k^2 underflow to 0 < 0, which sent every one of them to the turn
        # (where the phase K - g cancels to an absolute 1e-16, and theta near 0 after it):
        # there s and k are lifted by 2**600 first, an exact scaling (elsewhere by 1).
        lift = np.where(k < _SMALL_K, _LIFT, 1.0)
        sl, kl = s * lift, k * lift
        bottom = np.where(lib, sl * sl * (1.0 + kc) < kl * kl, s * s * (1.0 + kc) < 1.0)
        aw = np.abs(w)
        # One R_F per state, with the arguments of its branch:
        # II near the bottom: F(asin(s/k)) = (s/k) R_F((w/k)^2, c^2), from the upswing
        #   (w >= 0) or the downswing;
        # II near a turning point: K - c2 = g with sn g = w/(k c), cn g = kc s/(k c),
        #   dn g = kc/c;
        # IV near the bottom: c4 = direction F(r/2 | gamma) = direction s R_F(c^2, (w/k)^2);
        # IV near the top: K - |c4| = g, sn g = c k/|w|, cn g = gamma_c |s| k/|w|,
        #   dn g = gamma_c k/|w|.
        lib_x = np.where(bottom, (w / k) ** 2, (kc * s / (k * c)) ** 2)
        lib_y = np.where(bottom, c * c, (kc / c) ** 2)
        rot_x = np.where(bottom, c * c, (kc * s * k / aw) ** 2)
        rot_y = np.where(bottom, (w / k) ** 2, (kc * k / aw) ** 2)
        factor = np.where(lib, np.where(bottom, s / k, w / (k * c)),
                          np.where(bottom, sgn_w * s, c * k / aw))
        x, y = np.where(lib, lib_x, rot_x), np.where(lib, lib_y, rot_y)
        moving = lib | rot
        f = factor * _rf(np.where(moving, x, 1.0), np.where(moving, y, 1.0))
        q_lib = np.where(bottom, np.where(w >= 0, 0.0, 2.0 * sgn_s), sgn_s)
        r_lib = np.where(bottom, np.where(w >= 0, f, -f), -sgn_s * f)
        q_rot = np.where(bottom, 0.0, sgn_w * sgn_s)
        r_rot = np.where(bottom, f, -q_rot * f)
    q = np.where(lib, q_lib, np.where(rot, q_rot, 0.0))
    rem = np.where(lib, r_lib, np.where(rot, r_rot, 0.0))
    return q, rem



def _rf_float(x, y):
    return float(special.elliprf(x, y, 1.0))


def phase_float(s, c, w, k, kc, rot):
    """Compute :func:`phases` of one state of regime II or IV on Python floats (its twin)."""
    sgn_s = -1.0 if s < 0 else 1.0
    sgn_w = -1.0 if w < 0 else 1.0
    aw = abs(w)
    if not rot:
        lift = _LIFT if k < _SMALL_K else 1.0  # as in phases: a tiny swing's squares underflow
        if (s * lift) * (s * lift) * (1.0 + kc) < (k * lift) * (k * lift):
            x, y = w / k, c * c
            f = (s / k) * _rf_float(x * x, y)
            return (0.0, f) if w >= 0 else (2.0 * sgn_s, -f)
        x, y = kc * s / (k * c), kc / c
        f = (w / (k * c)) * _rf_float(x * x, y * y)
        return sgn_s, -sgn_s * f
    if s * s * (1.0 + kc) < 1.0:
        y = w / k
        return 0.0, (sgn_w * s) * _rf_float(c * c, y * y)
    x, y = kc * s * k / aw, kc * k / aw
    q = sgn_w * sgn_s
    return q, -q * ((c * k / aw) * _rf_float(x * x, y * y))
