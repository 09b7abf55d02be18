"""What the evaluation of theta(t) needs per state: the Params, and their flat list for chunks.

:mod:`.states` fills them from the initial states; :mod:`.flow` evaluates them at times t,
a chunk at a time (cutting the flat list of :func:`pieces` along the axes of the result), and
:mod:`.redo` evaluates theta near 0 again from them.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from . import landen as _landen

__all__ = ["N", "Params", "pieces", "unpieces"]


class Params(NamedTuple):
    """Per-state arrays (one shape S), everything the evaluation needs."""

    code: np.ndarray
    still: np.ndarray     # at rest (I) or balanced at the top (III): theta = theta0 forever
    theta0: np.ndarray
    turns: np.ndarray
    omega0: np.ndarray
    sigma: np.ndarray     # direction +-1 (III, IV); +1 otherwise
    k: np.ndarray         # sqrt(s^2 + w^2): alpha (II), 1/gamma (IV)
    s: np.ndarray         # sin(r/2), cos(r/2) and theta'/(2 omega0) of the initial state
    c: np.ndarray
    w: np.ndarray
    rate: np.ndarray      # d(argument)/dt as a double-double; 0 outside II and IV
    rate_lo: np.ndarray
    quarters: np.ndarray  # the argument at t = 0 as quarters K + rem (|rem| <~ K/2), exactly
    rem: np.ndarray
    s_lo: np.ndarray      # the low parts of s, c, w, k and kc (the Landen constants' kc):
    c_lo: np.ndarray      # what the remainder in double-double is formed from (redo)
    w_lo: np.ndarray
    k_lo: np.ndarray
    kc_lo: np.ndarray
    landen: _landen.Constants


#: How many of the fields of Params are per-state arrays (all but the Landen constants).
N = len(Params._fields) - 1


def pieces(p: Params) -> list[Any]:
    """Return the per-state arrays of p and of its Landen constants, as one flat list."""
    c = p.landen
    return [*p[:N], c.kc, c.quarter, c.k_hi, c.k_mid, c.k_lo, c.scale, c.scale_lo, *c.mu, *c.rho]


def unpieces(pieces: list[Any], levels: int) -> Params:
    """Return the Params of :func:`pieces` (cut alike), with ``levels`` Landen levels."""
    m = N + _landen.SCALARS
    c = _landen.Constants._make([*pieces[N:m], tuple(pieces[m:m + levels]),
                                 tuple(pieces[m + levels:])])
    return Params._make([*pieces[:N], c])
