"""Evaluate theta(t) and theta'(t) for many states at many times, in chunks.

The states' parameters (per element: regime, phase as whole quarter periods plus a
remainder, the Landen constants of its modulus) broadcast against t by numpy's rules. The
output is filled a chunk at a time (about 2**15 values), so the temporaries of the
evaluation stay a few megabytes however long t is, and theta and theta' come from one pass.

Every operation is elementwise: an element's value does not depend on the other elements
(the Landen constants are built so, see :func:`.landen.constants`).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from . import landen as _landen
from . import params as _params
from . import redo as _redo
from .codes import LIBRATION, ROTATION, SEPARATRIX
from .landen import _two_prod
from .params import Params

__all__ = ["Params", "evaluate", "CHUNK"]

CHUNK = 2 ** 15
# Below this d0 = dn(u0) (IV), the addition theorem is rescaled (see _rotation).
_DEEP = 2.0 ** -300
# Below this modulus (II), theta' is formed from s and w lifted by _LIFT (see _lifted).
_SMALL_K, _LIFT = 2.0 ** -500, 2.0 ** 600
# Below this |theta| a rotation's theta is evaluated again (see _kernel): pi / 64.
_NEAR_ZERO = 0.049


def _kernel(p: Params, t: np.ndarray, want_theta: bool, want_dtheta: bool, later=None):
    """Return theta and theta' of one chunk.

    With ``later`` (a list) the redo near theta = 0 is left to the caller: its points' mask
    is appended, and their theta is not final.
    """
    lib, rot = p.code == LIBRATION, p.code == ROTATION
    theta = dtheta = None
    t_all = t
    if np.any(lib | rot):
        with np.errstate(over="ignore"):  # an overflow here is exactly what is reported
            # Beyond 1e290, Dekker's split in the exact product overflows.
            big = (np.abs(t) > 1e290) | (np.abs(t) * p.rate > 1e290)
        if np.any(big):
            if np.any(big & (lib | rot)):
                raise ValueError("t is too large: |omega0 t| must stay below about 1e290 "
                                 "(the elliptic argument grows like omega0 t)")
            # Only states at rest or on the separatrix, whose values come from elsewhere:
            # they take t = 0 here, so that a batch refuses (or overflows) no t that each
            # of its states accepts alone.
            t = np.where(big, 0.0, t)
        # tau = rate t as a double-double (rate is known to 1e-32): the phase survives
        # thousands of periods. The argument is u = u0 + tau with sn, cn, dn of u0 known
        # exactly from the initial state, joined to those of tau by the addition theorem:
        # at t = 0 the initial state itself comes back.
        a, a_lo = _product(p.rate, t)
        any_rot = bool(np.any(rot))
        sn, cn, dn, am = _landen.evaluate(a, p.landen, a_lo + p.rate_lo * t,
                                          amplitude="split" if any_rot else False, name="t")
        any_lib = bool(np.any(lib))
        lib_yx: Any
        rot_yx: Any
        # Each formula runs over the whole chunk and np.where keeps it where its regime is:
        # elsewhere (a state at rest, say) it may divide 0 by 0, harmlessly.
        # The other regimes' states enter each formula as a harmless stand-in, so that no
        # element overflows for its companions (a tiny swing with a huge omega0 would in
        # the formula of IV): each element signals what it signals alone.
        with np.errstate(invalid="ignore", divide="ignore"):
            lib_yx, dtheta = (_libration(_alone(p, lib, 0.0, 1.0, 0.0), sn, cn, dn,
                                         want_theta, want_dtheta) if any_lib else (None, None))
            rot_yx, dth_r = (_rotation(_alone(p, rot, 0.0, 1.0, 1.0), sn, cn, dn,
                                       want_theta, want_dtheta) if any_rot else (None, None))
        if any_rot and want_dtheta:
            dtheta = dth_r if dtheta is None else np.where(rot, dth_r, dtheta)
        redo = None
        if want_theta:
            # One arctan2 pass for both regimes: theta/2 (II) or the angle delta (IV).
            y, x = ((np.where(rot, rot_yx[0], lib_yx[0]), np.where(rot, rot_yx[1], lib_yx[1]))
                    if any_lib and any_rot else (rot_yx if any_rot else lib_yx)[:2])
            angle = np.arctan2(y, x)
            if any_lib:
                theta = p.turns + 2.0 * angle
                # Where the two terms cancel, theta is near 0 and loses relative digits.
                redo = np.abs(lib_yx[0]) < lib_yx[2] * (1.0 / 64.0)
            if any_rot:
                quarters, rest = am
                th_r, small = _redo.turned(p, quarters, rest + angle)
                # theta near 0: where the part beside N pi cancels, or where it cancels N pi
                # itself (a rotation back to 0 from a quarter period away, N = +-1 or +-2:
                # |theta| below pi/64 <= |N pi| / 64; at N = 0 the redo costs no accuracy).
                redo_r = ((np.abs(small) < (np.abs(rest) + np.abs(angle)) * (1.0 / 64.0))
                          | (np.abs(th_r) < _NEAR_ZERO))
                theta = th_r if theta is None else np.where(rot, th_r, theta)
                redo = redo_r if redo is None else np.where(rot, redo_r, redo)
        if want_theta and np.any(redo & (lib | rot)):
            if later is None:
                theta = _redo.direct(p, t, redo & (lib | rot), theta)
            else:
                later.append(redo & (lib | rot))
    sep = (p.code == SEPARATRIX) & ~p.still
    if np.any(sep):
        with np.errstate(invalid="ignore", divide="ignore"):  # as above, for other regimes
            th_s, dth_s = _separatrix(_alone(p, sep, 0.0, 1.0, 1.0), t_all)
        theta = th_s if theta is None else np.where(sep, th_s, theta)
        dtheta = dth_s if dtheta is None else np.where(sep, dth_s, dtheta)
    shape = np.broadcast_shapes(np.shape(t_all), np.shape(p.code))
    theta = np.zeros(shape) if theta is None else theta
    dtheta = np.zeros(shape) if dtheta is None else dtheta
    if np.any(p.still):
        theta = np.where(p.still, p.theta0, theta)
        dtheta = np.where(p.still, 0.0, dtheta)
    return theta, dtheta


def _product(rate, t):
    """Return rate t as a double-double (:func:`.dd.two_prod`), compiled for a large chunk."""
    compiled = _landen.compiled_for(np.size(t) * np.size(rate))
    if compiled is not None:  # the same operations compiled
        return compiled.two_prod(rate, t)
    return _two_prod(rate, t)


def _alone(p: Params, keep, s: float, c: float, w: float) -> Params:
    """Return p with the states outside ``keep`` replaced by (s, c, w, k = 1, sigma = 1)."""
    if np.all(keep):
        return p
    return p._replace(s=np.where(keep, p.s, s), c=np.where(keep, p.c, c),
                      w=np.where(keep, p.w, w), k=np.where(keep, p.k, 1.0),
                      sigma=np.where(keep, p.sigma, 1.0))


def _lifted(k, s, w, theta0, turns):
    """Return (s, w, back) for theta' = 2 w0 (w cn - s c sn dn) / (c^2 + s^2 cn^2) * back.

    A swing with k < 2**-500 is linear to a relative k^2 / 4 < 2**-1000, and its s may be a
    subnormal double that has lost bits (half of an odd subnormal theta0 rounds): theta' =
    2 w0 (w cn - s sn) would carry that loss, multiplied by a large omega0, into a normal
    result (31780 ulp). There s = sin(theta0/2) = theta0/2 is taken from the exact theta0
    (the bottom 2 pi m of an even multiple has s = 0 exactly), s and w are lifted into the
    normal range by 2**600 (exact) and theta' is scaled back by 2**-600 (rounded once).
    Elsewhere s, w and back are the same values times 1: the same bits. Elementwise (arrays
    or Python floats: the scalar twin calls it too).
    """
    tiny = k < _SMALL_K
    # Only the tiny swings are lifted: a far angle or a large w beside them in a batch would
    # overflow (and signal, under np.errstate(all="raise")), so the others lift a zero.
    th = np.where(tiny & (turns == 0), theta0, 0.0)
    s_l = np.where(tiny, np.where(turns == 0, th * (0.5 * _LIFT), s * _LIFT), s)
    return s_l, np.where(tiny, np.where(tiny, w, 0.0) * _LIFT, w), np.where(tiny, 1.0 / _LIFT, 1.0)


def _libration(p: Params, sn, cn, dn, want_theta: bool, want_dtheta: bool):
    """(25) at u0 + tau, with sn u0 = s/alpha, cn u0 = w/alpha, dn u0 = c (DLMF 22.8.1-3).

    Returns (y, x, size) with theta/2 = atan2(y, x) = atan2(alpha sn u, dn u) (arcsin near 1
    would halve the digits), and theta'. The common
    denominator 1 - alpha^2 sn^2 u0 sn^2 tau = c^2 + s^2 cn^2 tau has no cancellation.
    """
    s, c, w = p.s, p.c, p.w
    yx = dtheta = None
    if want_theta:
        first, second = s * cn * dn, w * c * sn
        # alpha sn(u) and dn(u) times the denominator; and the size of the terms of the first
        yx = (first + second, c * dn - s * w * sn * cn, np.abs(first) + np.abs(second))
    if want_dtheta:                        # theta' = 2 w0 alpha cn(u)
        tiny = np.any(p.k < _SMALL_K)  # (only then the lifting, which elsewhere changes nothing)
        s_l, w_l, back = _lifted(p.k, s, w, p.theta0, p.turns) if tiny else (s, w, 1.0)
        dtheta = 2.0 * p.omega0 * (w_l * cn - s_l * c * sn * dn) / (c * c + s * s * cn * cn)
        if tiny:
            dtheta = dtheta * back
    return yx, dtheta


def _rotation(p: Params, sn, cn, dn, want_theta: bool, want_dtheta: bool):
    """(46) at u0 + tau, with sn u0 = sigma s, cn u0 = c, dn u0 = d0 = |w|/k (modulus 1/k).

    am(u) = am(tau) + delta, delta = atan2(y, x) in (-pi, pi) from sin and cos of
    am(u) - am(tau) by the addition theorem; d0 - 1 = -s^2 / (k (|w| + k)) without
    cancellation. Returns (y, x) and theta'.
    """
    s, c, w, k, sigma = p.s, p.c, p.w, p.k, p.sigma
    aw = np.abs(w)
    d0 = aw / k
    # Both pairs below share the factor (s^2 cn^2 + w^2) / k^2 >= d0^2, which leaves the
    # normal doubles when a tiny push leaves the top (d0 < 1e-154; theta went round once
    # too few, theta' was 0 / 0). Below d0 = 2**-300, c, d0 and one factor cn are multiplied
    # by lam = 2**-e ~ 1/d0 (exact): the factor is then >= d0 / 2 >= 5e-301, and the
    # products that still underflow are below its ulp. Elsewhere lam = 1: the same bits.
    c_l, d0_l, cn_l = c, d0, cn
    deep = d0 < _DEEP
    if np.any(deep):
        lam = np.where(deep, np.ldexp(1.0, -np.frexp(d0)[1]), 1.0)
        c_l, d0_l, cn_l = lam * c, lam * d0, lam * cn
    yx = dtheta = None
    if want_theta:
        d0m1 = -(s / k) * (s / (aw + k))
        spread = cn * cn_l + d0_l * sn * sn
        yx = (sigma * s * dn * spread + c_l * sn * cn * d0m1,
              c * spread - sigma * s * sn * cn_l * dn * d0m1)
    if want_dtheta:                        # theta' = +-2 (w0 / gamma) dn(u)
        # divided through by k^2, which may be huge when omega0 is tiny
        s_k = s / k
        dn_u = ((d0_l * dn - sigma * s_k * (c_l / k) * sn * cn)
                / (d0_l * d0 + s_k * s_k * cn * cn_l))
        dtheta = sigma * 2.0 * p.rate * dn_u
    return yx, dtheta


def _separatrix(p: Params, t: np.ndarray):
    """(28) by the addition theorem from the initial state: exact at t = 0.

    With y = w0 t, tanh x0 = sigma s and sech x0 = c at t = 0, theta/2 = sigma gd(x0 + y):
    sin(theta/2) ~ s + sigma tanh y and cos(theta/2) ~ c sech y, over 1 + sigma s tanh y
    (positive; formed as (1 - tanh|y|) + tanh|y| (1 - |s|) where the terms would cancel).
    """
    with np.errstate(over="ignore", invalid="ignore"):  # w0 t = +-inf: theta = +-pi
        # y = w0 t exactly as y + y_lo (where Dekker's split does not overflow): rounding
        # y alone would cost sech y, whose relative slope is tanh y, |y| ulp of y.
        y, y_lo = _two_prod(p.omega0, t)
        y_lo = np.where(np.isfinite(y_lo), y_lo, 0.0)
        # expm1, not 1 - exp, keeps tanh y to its last digits near y = 0 (it lost all of
        # them below 1e-17); and sech y = 2 h / (1 + h^2) with h = exp(-|y|), not
        # sqrt(exp(-2 |y|)), stays normal up to |y| = 708 (the square underflowed at 372).
        m = np.expm1(-2.0 * np.abs(y))                # e - 1, e = exp(-2 |y|)
        h = np.exp(-np.abs(y)) * (1.0 - np.sign(y) * y_lo)  # exp(-|y + y_lo|)
    e = h * h
    th = np.sign(y) * (-m / (2.0 + m))                # tanh y = (1 - e) / (1 + e)
    sech = 2.0 * h / (1.0 + e)
    one_minus = 2.0 * e / (1.0 + e)                   # 1 - tanh|y|
    ss = p.sigma * p.s
    denominator = np.where(ss * th >= 0, 1.0 + ss * th,
                           one_minus + np.abs(th) * (p.c * p.c / (1.0 + np.abs(p.s))))
    half = np.arctan2(p.s + p.sigma * th, p.c * sech)
    return p.turns + 2.0 * half, p.sigma * 2.0 * p.omega0 * p.c * sech / denominator


def evaluate(p: Params, t: np.ndarray, want_theta: bool = True, want_dtheta: bool = True):
    """theta(t) and theta'(t) (either None if not wanted), of shape broadcast(S, t.shape).

    Underflow to zero or a subnormal is the right answer here (theta' far along the
    separatrix, a tiny amplitude): it raises nothing even under np.seterr(all="raise").
    """
    with np.errstate(under="ignore"):
        return _evaluate(p, t, want_theta, want_dtheta)


def _evaluate(p: Params, t: np.ndarray, want_theta: bool, want_dtheta: bool):
    try:
        shape = np.broadcast_shapes(np.shape(p.code), t.shape)
    except ValueError:
        raise ValueError(f"t must broadcast against the states (numpy rules): got t of shape "
                         f"{t.shape} for states of shape {np.shape(p.code)}") from None
    size = math.prod(shape)
    if size <= CHUNK:
        theta, dtheta = _kernel(p, t, want_theta, want_dtheta)
        # Fresh arrays of the full shape; np.array, not + 0.0, which turns -0.0 into +0.0
        # (the scalar path, and theta0 = -0.0 at rest, keep the sign).
        return (np.array(np.broadcast_to(theta, shape)) if want_theta else None,
                np.array(np.broadcast_to(dtheta, shape)) if want_dtheta else None)
    _landen.load_compiled(size)
    nd = len(shape)
    pieces = [np.reshape(x, (1,) * (nd - np.ndim(x)) + np.shape(x)) for x in _params.pieces(p)]
    t = np.reshape(t, (1,) * (nd - t.ndim) + t.shape)
    levels = len(p.landen.mu)
    outs = [np.empty(shape) if want else None for want in (want_theta, want_dtheta)]
    axis = next(a for a in range(nd) if math.prod(shape[a + 1:]) <= CHUNK)
    step = max(1, CHUNK // math.prod(shape[axis + 1:]))
    # The redo near theta = 0 waits for the end: the remainder's low part is then made once
    # for every state that needs it in any chunk, and the points are evaluated again in one
    # call (not one per chunk: a state's many chunks share its low part, and a few hundred
    # operations cost less on one array).
    redo = None  # where theta is evaluated again, over the whole result (made when needed)
    for outer in np.ndindex(shape[:axis]):
        for start in range(0, shape[axis], step):
            # Slices only (an integer index would drop a dimension); a parameter of length 1
            # along a dimension broadcasts and is not cut.
            key = (*(slice(i, i + 1) for i in outer), slice(start, start + step))
            sub = _params.unpieces([_cut(x, key) for x in pieces], levels)
            masks: list = []
            theta, dtheta = _kernel(sub, _cut(t, key), want_theta, want_dtheta, masks)
            for out, value in zip(outs, (theta, dtheta), strict=True):
                if out is not None:
                    out[key] = value
            for mask in masks:
                if redo is None:
                    redo = np.zeros(shape, dtype=bool)
                redo[key] = mask
    if redo is not None:
        # The points of every chunk are redone together, in one call over the whole result.
        whole = _params.unpieces(pieces, levels)
        low = _redo.lows(whole, _redo.need(whole, redo))
        # in place: a copy of the whole result would double the memory of a long t
        _redo.direct(whole, t, redo, outs[0], low, in_place=True)
    return outs[0], outs[1]


def _cut(x, key):
    """Return x at the chunk ``key`` (slices); a dimension of length 1 broadcasts, uncut."""
    return x[tuple(k if n > 1 else slice(None) for k, n in zip(key, x.shape, strict=False))]


def state_float(p, t: float, want_theta: bool = True, want_dtheta: bool = True):
    """Compute :func:`evaluate` of one state (Params of Python floats) at one t (its twin).

    The caller keeps the separatrix (III, moving) on the array path.
    """
    if p.still:
        return p.theta0, 0.0
    if not (abs(t) <= 1e290 and abs(t) * p.rate <= 1e290):
        raise ValueError("t is too large: |omega0 t| must stay below about 1e290 "
                         "(the elliptic argument grows like omega0 t)")
    a, a_lo = _two_prod(p.rate, t)
    rot = p.code == ROTATION
    c = p.landen
    sn, cn, dn, am = _landen.evaluate_float(a, c, a_lo + p.rate_lo * t,
                                            amplitude="split" if rot else False, name="t")
    s, cs, w, k, sigma = p.s, p.c, p.w, p.k, p.sigma
    theta = dtheta = None
    if rot:
        aw = abs(w)
        d0 = aw / k
        c_l, d0_l, cn_l = cs, d0, cn
        if d0 < _DEEP:  # rescaled as in _rotation
            lam = math.ldexp(1.0, -math.frexp(d0)[1])
            c_l, d0_l, cn_l = lam * cs, lam * d0, lam * cn
        if want_theta:
            d0m1 = -(s / k) * (s / (aw + k))
            spread = cn * cn_l + d0_l * sn * sn
            y = sigma * s * dn * spread + c_l * sn * cn * d0m1
            x = cs * spread - sigma * s * sn * cn_l * dn * d0m1
            delta = _landen._f(np.arctan2, y, x)
            quarters, rest = am
            theta, small = _redo.turned_float(p, quarters, rest + delta)
            redo = (abs(small) < (abs(rest) + abs(delta)) * (1.0 / 64.0)
                    or abs(theta) < _NEAR_ZERO)  # as in _kernel
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
            theta = p.turns + 2.0 * _landen._f(np.arctan2, y, x)
            redo = abs(y) < (abs(first) + abs(second)) * (1.0 / 64.0)
        if want_dtheta:
            if k < _SMALL_K:  # a tiny swing: lifted as in _libration (see _lifted)
                s_l, w_l, back = (float(x) for x in _lifted(k, s, w, p.theta0, p.turns))
            else:
                s_l, w_l, back = s, w, 1.0
            dtheta = (2.0 * p.omega0 * (w_l * cn - s_l * cs * sn * dn)
                      / (cs * cs + s * s * cn * cn)) * back
    if want_theta and redo:
        theta = _redo.direct_float(p, t)
    return theta, dtheta
