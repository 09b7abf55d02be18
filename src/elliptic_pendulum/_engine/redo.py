"""Theta near 0 (mod 2 pi) evaluated again, from the elliptic argument itself.

Where theta is near 0 the two terms of the addition theorem in :mod:`.flow` cancel; at those
points only, :func:`direct` evaluates again from u = rate t + rem + quarters K, reduced
exactly, with the remainder's low part (:mod:`.remainder`, made once per state by
:func:`lows`): sn(u) (II) or am(u) (IV) to full relative accuracy. :func:`turned` adds the
multiple of pi of a rotation exactly, for :mod:`.flow` and for the redo alike. Each has its
twin on Python floats right below it.
"""

from __future__ import annotations

import numpy as np

from . import landen as _landen
from . import remainder as _remainder
from .codes import LIBRATION, ROTATION
from .landen import _PI_HI, _PI_LO, _two_prod, _two_sum
from .params import N, Params

__all__ = ["direct", "direct_float", "lows", "need", "turned", "turned_float"]

# Up to this many states, the remainder's low part is formed on Python floats (see lows).
_FEW = 4


def turned(p: Params, quarters, rest):
    """Theta = 2 pi m + sigma 2 (quarters pi/2 + rest) with the multiple of pi added exactly.

    N pi (N = 2 m + sigma quarters) as a double-double, so that a theta near 0 after many
    turns keeps its relative digits. Returns theta and its part beside N pi's double.
    """
    count = 2.0 * np.rint(p.turns / (2.0 * _PI_HI)) + p.sigma * quarters
    big, err = _two_prod(count, _PI_HI)
    small = (err + count * _PI_LO) + p.sigma * 2.0 * rest
    return big + small, small


def turned_float(p, quarters, rest):
    """Compute :func:`turned` of one state on Python floats (its twin)."""
    count = 2.0 * float(round(p.turns / (2.0 * _PI_HI))) + p.sigma * quarters
    big, err = _two_prod(count, _PI_HI)
    small = (err + count * _PI_LO) + p.sigma * 2.0 * rest
    return big + small, small


def direct(p: Params, t, redo, theta, low=None, in_place=False):
    """Theta at the points ``redo`` from u = tau + rem + quarters K, reduced exactly.

    Near theta = 0 (mod 2 pi) the addition theorem cancels; there the argument itself, with
    the phase held as whole quarter periods plus an exact remainder, gives sn(u) (II) and
    am(u) (IV) to full relative accuracy. Only these few points are evaluated again. ``low``
    is the remainder's low part per state (:func:`lows`), made here if not given. With
    ``in_place`` theta (a writable array of the result's shape) is written into and returned.
    """
    shape = theta.shape
    mask = np.broadcast_to(redo, shape)
    # Integer indices: gathering costs only as many as are redone (a 0-d mask indexes itself).
    where = np.nonzero(mask) if mask.ndim else mask

    def pick(x):
        return np.broadcast_to(x, shape)[where]

    c = p.landen
    landen = _landen.Constants._make([*(pick(x) for x in c[:_landen.SCALARS]),
                                      tuple(pick(x) for x in c.mu),
                                      tuple(pick(x) for x in c.rho)])
    if low is None:
        low = lows(p, need(p, mask))
    # tau = rate t as a double-double, as in _kernel (elementwise: the same bits)
    t_at = pick(t)
    a, a_lo = _two_prod(pick(p.rate), t_at)
    u, u_lo = _two_sum(a, pick(p.rem))
    u_lo = u_lo + ((a_lo + pick(p.rate_lo) * t_at) + pick(low))
    sn, _, dn, (quarters, rest) = _landen.evaluate(u, landen, u_lo, amplitude="split",
                                                   name="t", quarters=pick(p.quarters))
    sub = Params._make([*(pick(x) for x in p[:N]), landen])
    th_turned, _ = turned(sub, quarters, rest)
    again = np.where(sub.code == LIBRATION, sub.turns + 2.0 * np.arctan2(sub.k * sn, dn),
                     th_turned)
    if not in_place:
        theta = np.array(theta)  # a writable copy (a 0-d result may be a numpy scalar)
    theta[where] = again
    return theta


def need(p: Params, mask):
    """Return, in the shape of the states, where a state of II or IV has a point in ``mask``."""
    shape = np.shape(p.code)
    full = np.shape(mask)
    padded = (1,) * (len(full) - len(shape)) + shape
    axes = tuple(i for i, (n, m) in enumerate(zip(padded, full, strict=True)) if n == 1 < m)
    need = np.reshape(np.any(mask, axis=axes, keepdims=True) if axes else mask, shape)
    return need & ((p.code == LIBRATION) | (p.code == ROTATION))


def lows(p: Params, which):
    """Return the remainder's low part (:mod:`.remainder`) where ``which``, in the states' shape.

    Once per state, not per point (a state's many times share it); on Python floats where
    only a few states need it (the same bits as on arrays, faster). Elsewhere 0.
    """
    shape = np.shape(p.code)
    count = int(np.count_nonzero(which))
    if count == 0:
        return 0.0
    where = np.nonzero(which) if shape else ()
    fields = [np.broadcast_to(x, shape)[where] for x in (
        p.code == LIBRATION, p.quarters, p.rem, p.s, p.s_lo, p.c, p.c_lo, p.w, p.w_lo, p.k,
        p.k_lo, p.landen.kc, p.kc_lo)]
    if count <= _FEW:
        low = np.array([_remainder.low_part_float(
            bool(f[0]), float(f[1]), float(f[2]), *(
                (float(f[i]), float(f[i + 1])) for i in range(3, 13, 2)))
            for f in zip(*(np.atleast_1d(x) for x in fields), strict=True)])
    else:
        low = _remainder.low_part(fields[0], fields[1], fields[2],
                                  *((fields[i], fields[i + 1]) for i in range(3, 13, 2)))
    out = np.zeros(shape)
    out[where] = np.reshape(low, np.shape(out[where]))
    return out


def direct_float(p, t: float) -> float:
    """Compute :func:`direct` of one state (Params of Python floats) at one t (its twin)."""
    a, a_lo = _two_prod(p.rate, t)
    c = p.landen
    lib = p.code == LIBRATION
    u, u_lo = _two_sum(a, p.rem)
    low = _remainder.low_part_float(lib, p.quarters, p.rem, (p.s, p.s_lo), (p.c, p.c_lo),
                                    (p.w, p.w_lo), (p.k, p.k_lo), (c.kc, p.kc_lo))
    u_lo = u_lo + ((a_lo + p.rate_lo * t) + low)
    sn, _, dn, (quarters, rest) = _landen.evaluate_float(u, c, u_lo, amplitude="split",
                                                         name="t", quarters=p.quarters)
    return p.turns + 2.0 * _landen._f(np.arctan2, p.k * sn, dn) if lib else \
        turned_float(p, quarters, rest)[0]
