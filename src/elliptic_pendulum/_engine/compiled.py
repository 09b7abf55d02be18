"""The engine's loops over many elements, compiled: the AGM, the recurrence, the reduction.

Written as NumPy passes, one level of the double-double AGM is about ninety passes over
the array (:mod:`.levels`) and one step of the recurrence seven: most of the time of sn on
many moduli, and of a motion's theta(t) on many states, went there. numba compiles each
loop into one pass per level, whose body runs in the processor's vector registers (about
four times faster on the AGM, measured in ``benchmarks/bench_engine.py``); the reduction by
quarter periods and the exact product rate t are compiled too, as generalized ufuncs.

The bits are those of the NumPy path and of the scalar twins: the loops call the Python
functions of :mod:`.levels`, :mod:`.agm` and :mod:`.dd` themselves (compiled from their
source, not copied), in the same order, and numba without ``fastmath`` neither reassociates
nor fuses a multiply and an add, so every operation rounds as IEEE arithmetic does
(`tests/engine/test_compiled.py` compares the two paths bit for bit). Only +, -, *, / and
sqrt are here; tan, hypot and arctan2 stay NumPy's, whose SIMD loops may round otherwise
than the C library that compiled code would call. ``error_model="numpy"`` makes a division
the IEEE one (Python's checks for zero first, a branch that stops the vectorizer).

This module imports numba (0.35 s with the machine code from numba's cache; the first
time, compiling, about 7.5 s), so the engine loads it only for a call on at least
:data:`.agm.LOAD_FROM` elements (:func:`.agm.load_compiled`); from then on every piece of at
least :data:`.agm.COMPILED_FROM` runs here. A scalar call, the CLI, or the arrays of a lesson
never pay for it. Every loop is compiled at import,
for its one signature, under a lock file (:func:`_one_at_a_time`): numba's cache written by
two processes at once crashed the next process that loaded it.
"""

from __future__ import annotations

import contextlib
import hashlib
import math
import os
import pathlib
import sys
import tempfile

import numba
import numba.extending
import numpy as np

from . import agm as _agm
from . import dd as _dd
from . import levels as _levels

__all__ = ["agm", "recurrence", "reduce", "two_prod"]


def _inline(function):
    # Compiled into the loops that call it (numba's IR inlining), never on its own.
    return numba.njit(function, error_model="numpy", inline="always")


_step = _inline(_levels.step)
_root = _inline(_levels.root)
_mean = _inline(_agm._mean)
_last = _inline(_agm._last)
_fast_two_sum = _inline(_dd.fast_two_sum)
_two_sum = _inline(_dd.two_sum)
# two_prod calls dd.split: registered so that compiled code calls its compiled twin.
numba.extending.register_jitable(inline="always")(_dd.split)
_two_prod = _inline(_dd.two_prod)
_NEAR = _agm._NEAR
# The AGM's levels are at most a dozen for any double kc > 0 (12 steps at kc = 1e-300);
# the rows grow past this, and the cap of 60 steps, as in agm._piece, guards a bug.
_ROWS = 16


def _loops(stamp):
    """Return the loops to compile, each closed over ``stamp``.

    numba keys its cache on a function's own bytecode and closure, not on the functions it
    inlines (:mod:`.levels`, :mod:`.agm`, :mod:`.dd`): ``stamp``, a digest of their sources,
    makes an edit there compile the loops again instead of loading the old machine code.
    """
    def _levels_loop(kc, kc_lo):
        _ = stamp
        n = kc.size
        mu = np.empty((_ROWS, n))
        rho = np.empty((_ROWS, n))
        ah, al, bh, bl = np.ones(n), np.zeros(n), np.empty(n), np.empty(n)
        a1, a2, drift = np.ones(n), np.zeros(n), np.empty(n)
        # What an element keeps from the level where it stops: M, the product p and the drift.
        kmh, kml, kph, kpl, kdr = np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n)
        near = np.empty(n)
        a_level, rho_level = np.empty(n), np.empty(n)
        mh, ml = np.empty(n), np.empty(n)
        stop = np.zeros(n, dtype=np.int64)
        idx = np.arange(n)  # the elements still iterating, by position in kc
        for i in range(n):
            h, lo = _fast_two_sum(kc[i], kc_lo[i])
            bh[i], bl[i] = h, lo
            drift[i] = kc_lo[i] / kc[i]
            mu[0, i], rho[0, i] = 1.0, h
        live = n
        level = 1
        while live > 0:
            if level > 60:
                raise RuntimeError("AGM did not converge")
            if level >= mu.shape[0]:
                grown_mu, grown_rho = np.empty((2 * mu.shape[0], n)), np.empty((2 * mu.shape[0], n))
                grown_mu[:level], grown_rho[:level] = mu[:level], rho[:level]
                mu, rho = grown_mu, grown_rho
            # One level for every element still iterating: no branch, so the loop vectorizes.
            for j in range(live):
                diff = (ah[j] - bh[j]) + (al[j] - bl[j])
                s, ch, cl, ph, pl = _step(ah[j], al[j], bh[j], bl[j], a1[j], a2[j])
                near[j] = 1.0 if diff <= _NEAR * ah[j] else 0.0
                kmh[j], kml[j] = _mean(diff, s, ch, cl)
                kph[j], kpl[j], kdr[j] = ph, pl, drift[j]
                b_h, b_l, c1, c2, ratio, delta = _root(ph, pl, ch, cl)
                a_level[j], rho_level[j] = ch, ratio
                ah[j], al[j], bh[j], bl[j], a1[j], a2[j] = ch, cl, b_h, b_l, c1, c2
                drift[j] = drift[j] + delta
            # Write the level out, and move the elements still iterating to the front.
            kept = 0
            for j in range(live):
                i = idx[j]
                if near[j] != 0.0:
                    mh[i], ml[i] = kmh[j], kml[j]
                    mu[level, i] = _last(kph[j], kpl[j], kmh[j], kml[j], kdr[j])
                    rho[level, i] = 1.0
                    stop[i] = level
                else:
                    mu[level, i], rho[level, i] = a_level[j], rho_level[j]
                    idx[kept] = i
                    ah[kept], al[kept], bh[kept], bl[kept] = ah[j], al[j], bh[j], bl[j]
                    a1[kept], a2[kept], drift[kept] = a1[j], a2[j], drift[j]
                    kept += 1
            live = kept
            level += 1
        top = 0
        for i in range(n):
            top = max(top, stop[i])
        # Repeating an element's last level is an exact identity of the recurrence (rho = 1).
        for i in range(n):
            for j in range(stop[i] + 1, top + 1):
                mu[j, i], rho[j, i] = mu[stop[i], i], 1.0
        return mh, ml, mu[:top + 1], rho[:top + 1]


    def _recurrence(cc, mu, rho):
        _ = stamp
        # cc is (states, times): the levels are one column per state, shared by its times.
        levels = mu.shape[0]
        d = np.ones(cc.shape)
        # Level by level over all the points (the points are independent, the levels are not):
        # the inner loop vectorizes.
        for n in range(levels - 2, -1, -1):
            first = n == levels - 2
            for i in range(cc.shape[0]):
                a_next, a_n, r_n = mu[n + 1, i], mu[n, i], rho[n, i]
                for j in range(cc.shape[1]):
                    c = cc[i, j]
                    r = c * c / a_next
                    if not first:
                        cc[i, j] = d[i, j] * c
                    d[i, j] = r_n + (1.0 - r_n) * (r / (r + a_n))
        return d

    # The reduction of :func:`.landen.reduce` as generalized ufuncs: NumPy broadcasts u
    # against the constants (a state's modulus at many times) and calls the loop once.
    def _reduce_split(u, u_lo, quarters, quarter, k_hi, k_mid, k_lo, q, n, v, v_lo):
        _ = stamp
        m = np.rint(u / quarter)
        v[0], v_lo[0] = _two_sum((u - m * k_hi) - m * k_mid, u_lo - m * k_lo)
        m = m + quarters
        q[0], n[0] = np.mod(m, 4.0), m

    def _reduce_sum(u, u_lo, quarters, quarter, k_hi, k_mid, k_lo, q, n, v):
        _ = stamp
        m = np.rint(u / quarter)
        v[0] = ((u - m * k_hi) - m * k_mid) + (u_lo - m * k_lo)
        m = m + quarters
        q[0], n[0] = np.mod(m, 4.0), m

    def _product(a, b, p, e):
        _ = stamp
        p[0], e[0] = _two_prod(a, b)

    return _levels_loop, _recurrence, _reduce_split, _reduce_sum, _product


_STAMP = hashlib.sha256(b"".join(pathlib.Path(m.__file__).read_bytes()
                                 for m in (_levels, _agm, _dd) if m.__file__)).hexdigest()
_levels_loop, _recurrence, _reduce_split, _reduce_sum, _product = _loops(_STAMP)


@contextlib.contextmanager
def _one_at_a_time():
    """Hold a lock file while numba loads this module's machine code, or compiles and saves it.

    numba writes its cache without a lock: two processes compiling at once (two pytest
    workers, two notebooks opened together) can leave an index that names the other's
    code, and every process that loads it afterwards crashes (a segmentation fault, seen on
    a fresh clone). So one process at a time loads or compiles; the others wait, then load
    what it saved. Every function is compiled here, for its one signature, and never later.
    """
    key = hashlib.sha256(os.fsencode(__file__)).hexdigest()[:16]
    try:
        handle = open(os.path.join(tempfile.gettempdir(), f"elliptic-pendulum-{key}.lock"), "ab")
    except OSError:  # no lock to be had here: compile as numba does alone
        yield
        return
    with handle:
        _lock(handle.fileno(), True)
        try:
            yield
        finally:
            _lock(handle.fileno(), False)


if sys.platform == "win32":
    import msvcrt

    def _lock(fd, take):
        os.lseek(fd, 0, os.SEEK_SET)
        if not take:
            msvcrt.locking(fd, msvcrt.LK_UNLCK, 1)
            return
        while True:
            try:
                msvcrt.locking(fd, msvcrt.LK_LOCK, 1)  # retries for 10 s, then raises
                return
            except OSError:
                continue
else:
    import fcntl

    def _lock(fd, take):
        fcntl.flock(fd, fcntl.LOCK_EX if take else fcntl.LOCK_UN)


_VECTOR, _TABLE = "float64[::1]", "float64[:, ::1]"
_GUFUNC = {"nopython": True, "cache": True}
with _one_at_a_time():
    _agm_loop = numba.njit(f"({_VECTOR}, {_VECTOR})", error_model="numpy", cache=True,
                           nogil=True)(_levels_loop)
    _recurrence_loop = numba.njit(f"({_TABLE}, {_TABLE}, {_TABLE})", error_model="numpy",
                                  cache=True, nogil=True)(_recurrence)
    _reduce_split_ufunc = numba.guvectorize(
        ["void(f8,f8,f8,f8,f8,f8,f8,f8[:],f8[:],f8[:],f8[:])"],
        "(),(),(),(),(),(),()->(),(),(),()", **_GUFUNC)(_reduce_split)
    _reduce_sum_ufunc = numba.guvectorize(
        ["void(f8,f8,f8,f8,f8,f8,f8,f8[:],f8[:],f8[:])"],
        "(),(),(),(),(),(),()->(),(),()", **_GUFUNC)(_reduce_sum)
    _product_ufunc = numba.guvectorize(["void(f8,f8,f8[:],f8[:])"], "(),()->(),()",
                                       **_GUFUNC)(_product)


def agm(kc, kc_lo):
    """Run the AGM of :func:`.agm._piece` on flat arrays: M (mh, ml), the levels mu, rho (2-D)."""
    return _agm_loop(np.ascontiguousarray(kc, dtype=float),
                     np.ascontiguousarray(kc_lo, dtype=float))


def recurrence(cc, mu, rho):
    """Run the loop of :func:`.landen.core`: cc = kc sc(v), d = kc / dn(v) from cc = a_N tan.

    cc (a contiguous array of the caller's own) is overwritten and returned.
    """
    shape = cc.shape
    levels = len(mu)
    table = np.stack(np.broadcast_arrays(*mu, *rho))
    # The levels of the states against the points: where they vary along the leading axes
    # only (a state's modulus at many times), one column per state serves all its points;
    # otherwise they are laid out beside the points, one pass each.
    given = (1,) * (len(shape) - table.ndim + 1) + table.shape[1:]
    lead = len(given)
    while lead > 0 and given[lead - 1] == 1:
        lead -= 1
    inner = math.prod(shape[lead:]) if given[:lead] == shape[:lead] else 0
    if inner:
        table = table.reshape(2 * levels, -1)
    else:
        table = np.broadcast_to(table.reshape(2 * levels, *given), (2 * levels, *shape))
        table, inner = np.ascontiguousarray(table).reshape(2 * levels, -1), 1
    out = np.ascontiguousarray(cc, dtype=float).reshape(-1, inner)  # core's own: in place
    d = _recurrence_loop(out, table[:levels], table[levels:])
    return out.reshape(shape), d.reshape(shape)


def reduce(u, c, u_lo, quarters, split):
    """Reduce as :func:`.landen.reduce` does, compiled: (n mod 4, n, v, v_lo or None)."""
    args = (u, u_lo, quarters, c.quarter, c.k_hi, c.k_mid, c.k_lo)
    if split:
        return _reduce_split_ufunc(*args)
    q, n, v = _reduce_sum_ufunc(*args)
    return q, n, v, None


def two_prod(a, b):
    """Return :func:`.dd.two_prod` compiled: the product a b and its exact rounding error."""
    return _product_ufunc(a, b)
