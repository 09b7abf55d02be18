"""Evaluate theta(t) and theta'(t) for many states at many times, in chunks.

The states' parameters (per element: regime, phase as whole quarter periods plus a
remainder, the Landen constants of its modulus) broadcast against t by numpy's rules. The
output is filled a chunk at a time (about 2**15 values), so the temporaries of the
evaluation stay a few megabytes however long t is, and theta and theta' come from one pass.

Every operation is elementwise: an element's value does not depend on the other elements
(the Landen constants are built so, see :func:`._landen.constants`).
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np

from . import _landen
from ._landen import _two_prod, _two_sum
from .regimes import LIBRATION, ROTATION, SEPARATRIX

__all__ = ["Params", "evaluate", "CHUNK"]

CHUNK = 2 ** 15


class Params(NamedTuple):
    """Per-state arrays (one shape S), everything the evaluation needs."""

    code: np.ndarray
    still: np.ndarray     # at rest (I) or balanced at the top (III): theta = theta0 forever
    theta0: np.ndarray
    turns: np.ndarray
    omega0: np.ndarray
    sigma: np.ndarray     # direction +-1 (III, IV); +1 otherwise
    k: np.ndarray         # alpha (II); used in theta = 2 atan2(alpha sn, dn)
    s: np.ndarray         # sin(r/2), cos(r/2) of the initial state (III)
    c: np.ndarray
    rate: np.ndarray      # d(argument)/dt as a double-double; 0 outside II and IV
    rate_lo: np.ndarray
    quarters: np.ndarray  # the argument at t = 0 is quarters K + rem
    rem: np.ndarray
    landen: _landen.Constants


def _pieces(p: Params) -> list[Any]:
    c = p.landen
    return [*p[:13], c.kc, c.quarter, c.k_hi, c.k_mid, c.k_lo, c.scale, *c.mu, *c.nu]


def _unpieces(pieces: list[Any], levels: int) -> Params:
    c = _landen.Constants._make([*pieces[13:19], tuple(pieces[19:19 + levels]),
                                 tuple(pieces[19 + levels:])])
    return Params._make([*pieces[:13], c])


def _kernel(p: Params, t: np.ndarray, want_theta: bool, want_dtheta: bool):
    lib, rot = p.code == LIBRATION, p.code == ROTATION
    theta = dtheta = None
    if np.any(lib | rot):
        with np.errstate(over="ignore"):  # an overflow here is exactly what is reported
            # Beyond 1e290, Dekker's split in the exact product overflows.
            fine = np.all((np.abs(t) <= 1e290) & (np.abs(t) * p.rate <= 1e290))
        if not fine:
            raise ValueError("t is too large: |omega0 t| must stay below about 1e290 "
                             "(the elliptic argument grows like omega0 t)")
        # u = rate t + rem (+ quarters K) as a double-double: the phase survives thousands
        # of periods, and at t = 0 it is the exact remainder.
        a, a_lo = _two_prod(p.rate, t)
        u, u_lo = _two_sum(a, p.rem)
        u_lo = u_lo + (a_lo + p.rate_lo * t)
        any_rot = bool(np.any(rot))
        sn, cn, dn, am = _landen.evaluate(u, p.landen, u_lo, amplitude=any_rot, name="t",
                                          quarters=p.quarters)
        if want_theta:
            # (25) as theta / 2 = atan2(alpha sn, dn): arcsin near 1 would halve the digits;
            # (46): theta = +-2 am.
            half = np.arctan2(p.k * sn, dn)
            if any_rot:
                half = np.where(rot, p.sigma * am, half)
            theta = p.turns + 2.0 * half
        if want_dtheta:
            dtheta = 2.0 * p.rate * np.where(rot, p.sigma * dn, p.k * cn)
    sep = (p.code == SEPARATRIX) & ~p.still
    if np.any(sep):
        th_s, dth_s = _separatrix(p, t)
        theta = th_s if theta is None else np.where(sep, th_s, theta)
        dtheta = dth_s if dtheta is None else np.where(sep, dth_s, dtheta)
    shape = np.broadcast_shapes(np.shape(t), np.shape(p.code))
    theta = np.zeros(shape) if theta is None else theta
    dtheta = np.zeros(shape) if dtheta is None else dtheta
    if np.any(p.still):
        theta = np.where(p.still, p.theta0, theta)
        dtheta = np.where(p.still, 0.0, dtheta)
    return theta, dtheta


def _separatrix(p: Params, t: np.ndarray):
    """(28) by the addition theorem from the initial state: exact at t = 0.

    With y = w0 t, tanh x0 = sigma s and sech x0 = c at t = 0, theta/2 = sigma gd(x0 + y):
    sin(theta/2) ~ s + sigma tanh y and cos(theta/2) ~ c sech y, over 1 + sigma s tanh y
    (positive; formed as (1 - tanh|y|) + tanh|y| (1 - |s|) where the terms would cancel).
    """
    with np.errstate(over="ignore"):  # w0 t = +-inf still means theta = +-pi
        y = p.omega0 * t
        e = np.exp(-2.0 * np.abs(y))
    th = np.sign(y) * (1.0 - e) / (1.0 + e)           # tanh y
    sech = 2.0 * np.sqrt(e) / (1.0 + e)
    one_minus = 2.0 * e / (1.0 + e)                   # 1 - tanh|y|
    ss = p.sigma * p.s
    denominator = np.where(ss * th >= 0, 1.0 + ss * th,
                           one_minus + np.abs(th) * (p.c * p.c / (1.0 + np.abs(p.s))))
    half = np.arctan2(p.s + p.sigma * th, p.c * sech)
    return p.turns + 2.0 * half, p.sigma * 2.0 * p.omega0 * p.c * sech / denominator


def evaluate(p: Params, t: np.ndarray, want_theta: bool = True, want_dtheta: bool = True):
    """theta(t) and theta'(t) (either None if not wanted), of shape broadcast(S, t.shape)."""
    shape = np.broadcast_shapes(np.shape(p.code), t.shape)
    size = math.prod(shape)
    if size <= CHUNK:
        theta, dtheta = _kernel(p, t, want_theta, want_dtheta)
        return (np.broadcast_to(theta, shape) + 0.0 if want_theta else None,
                np.broadcast_to(dtheta, shape) + 0.0 if want_dtheta else None)
    nd = len(shape)
    pieces = [np.reshape(x, (1,) * (nd - np.ndim(x)) + np.shape(x)) for x in _pieces(p)]
    t = np.reshape(t, (1,) * (nd - t.ndim) + t.shape)
    levels = len(p.landen.mu)
    outs = [np.empty(shape) if want else None for want in (want_theta, want_dtheta)]
    axis = next(a for a in range(nd) if math.prod(shape[a + 1:]) <= CHUNK)
    step = max(1, CHUNK // math.prod(shape[axis + 1:]))
    for outer in np.ndindex(shape[:axis]):
        for start in range(0, shape[axis], step):
            # Slices only (an integer index would drop a dimension); a parameter of length 1
            # along a dimension broadcasts and is not cut.
            key = (*(slice(i, i + 1) for i in outer), slice(start, start + step))

            def cut(x, key=key):
                return x[tuple(k if n > 1 else slice(None)
                               for k, n in zip(key, x.shape, strict=False))]

            sub = _unpieces([cut(x) for x in pieces], levels)
            theta, dtheta = _kernel(sub, cut(t), want_theta, want_dtheta)
            for out, value in zip(outs, (theta, dtheta), strict=True):
                if out is not None:
                    out[key] = value
    return outs[0], outs[1]
