"""The AGM behind the Jacobi kernel: K in double-double and the descending Landen levels.

The arithmetic-geometric mean M(1, kc), seeded with kc (never with 1 - k**2), in
double-double arithmetic: the quarter period K = pi / (2 M) to about 1e-32 relative (split in
three parts for an exact reduction, Cody and Waite), M itself as a double-double for the
phase, and the descending Landen sequence (its levels a_n and ratios b_n / a_n, rounded to
double) that :mod:`.landen`'s recurrence runs on. Arrays go in cache-sized pieces; one
modulus has a cached twin on Python floats, to the bit.
"""

from __future__ import annotations

import importlib
from functools import lru_cache
from typing import Any, NamedTuple

import numpy as np

from . import dd as _dd
from . import ends as _ends
from .dd import PI_HI as _PI_HI
from .dd import PI_LO as _PI_LO
from .dd import SPLIT as _SPLIT
from .dd import fast_two_sum as _fast_two_sum
from .levels import root, root_into, step, step_into

__all__ = ["CHUNK", "COMPILED_FROM", "LOAD_FROM", "SCALARS", "Constants", "compiled_for",
           "complement", "constants", "constants_float", "load_compiled", "pad", "quarter_period"]


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
    scale: Any  # pi / (2 K) = M(1, kc) = scale + scale_lo (a double-double)
    scale_lo: Any
    mu: tuple   # the AGM sequence a_0 = 1, ..., a_N (a_N: see `_piece`)
    rho: tuple  # b_0 / a_0 = kc, ..., b_N / a_N = 1 (the last level is circular)


#: How many of the fields of Constants are one number per modulus (the rest: mu, rho).
SCALARS = 7

# An element's AGM stops where a - b <= 1e-8 a: there r = (a - b)/(a + b) <= 5e-9, and
# M(a, b) = c (1 - r^2/4 - 5 r^4/64 - ...) with c = (a + b)/2 (from Gauss's
# M(1 + r, 1 - r) = pi / (2 K(r)) and K(r) = pi/2 (1 + r^2/4 + 9 r^4/64 + ...)) is
# c (1 - r^2/4) to 5e-35: two double-double steps fewer than iterating to 1e-32.
_NEAR = 1e-8
# Arrays longer than this are done in pieces that stay in the processor's cache (a piece of
# 2**14 doubles is 128 KiB): the double-double AGM runs about 2.5 times faster so.
CHUNK = 2 ** 14
#: A piece of this many elements runs the compiled loops of :mod:`.compiled` (the AGM here,
#: the recurrence and the reduction in :mod:`.landen`, the product in :mod:`.flow`) once that
#: module is loaded; a smaller one NumPy's passes, with the same bits.
COMPILED_FROM = 2048
#: A call on this many elements loads :mod:`.compiled`, and numba with it. The first process
#: after an install compiles (about 7.5 s on the 2-core test machine) and every later one
#: loads the machine code (0.35 s), while a call on 4096 points gains about 1 ms, on 65536
#: points 3 to 15 ms: so the plots and grids of a lesson (up to some 20000 points) never wait
#: for numba, and a large computation, or any piece after it, runs compiled.
LOAD_FROM = 2 ** 16
# The compiled loops once their import has finished (another thread may still be inside it:
# the module is in sys.modules from its first line, its loops only from its last).
_compiled: Any = None


def load_compiled(size: int) -> None:
    """Load the compiled loops for a call on ``size`` elements, if it is that large."""
    global _compiled
    if size >= LOAD_FROM and _compiled is None:
        _compiled = importlib.import_module(f"{__package__}.compiled")


def compiled_for(size: int) -> Any:
    """Return :mod:`.compiled` if a piece of ``size`` elements is to run it, else None."""
    return _compiled if size >= COMPILED_FROM else None


def _constants(kc: Any, kc_lo: Any = 0.0) -> Constants:
    kc = np.asarray(kc, dtype=float)
    kc_lo = np.broadcast_to(np.asarray(kc_lo, dtype=float), np.broadcast_shapes(
        kc.shape, np.shape(kc_lo)))
    kc = np.broadcast_to(kc, kc_lo.shape)
    if kc.size <= CHUNK:
        return _piece(kc, kc_lo)
    load_compiled(kc.size)
    shape = kc.shape
    flat, flat_lo = kc.ravel(), kc_lo.ravel()
    parts = [_piece(flat[i:i + CHUNK], flat_lo[i:i + CHUNK])
             for i in range(0, flat.size, CHUNK)]
    levels = max(len(c.mu) for c in parts)

    def join(arrays):
        return np.concatenate(arrays).reshape(shape)

    # Repeating an element's last level (where b = a) is an exact identity of the
    # recurrence in `core`, so pieces that converged in fewer steps can share one length.
    mu = [join(column) for column in zip(*(pad(c.mu, levels) for c in parts), strict=True)]
    rho = [join(column) for column in zip(*(pad(c.rho, levels) for c in parts), strict=True)]
    return Constants._make([*(join([c[j] for c in parts]) for j in range(SCALARS)), tuple(mu),
                            tuple(rho)])


def pad(levels: tuple, n: int) -> tuple:
    """Repeat the last of the AGM levels up to ``n`` of them (an exact identity in `core`)."""
    return tuple(levels) + (levels[-1],) * (n - len(levels))


def _mean(diff, s, ch, cl):
    """M = c (1 - r^2/4), r = (a - b)/(a + b), where a - b <= 1e-8 a (see _NEAR)."""
    r = diff / s
    lo = cl - ch * (0.25 * r * r)
    mh = ch + lo
    return mh, lo - (mh - ch)


def _last(ph, pl, mh, ml, drift):
    """Return the last level a_N = kc / (M rho_1 ... rho_(N-1)) on the rounded ratios.

    The exact ratios telescope: b_n / a_n = b_n^2 / b_(n+1)^2 (as b_(n+1)^2 = a_n b_n), so
    rho_1 ... rho_(N-1) = b_1^2 / (a_(N-1) b_(N-1)) = (kc + kc_lo) / p with p the product of
    the stopping level; the rounded ratios are that times (1 + sum of their deltas). So
    a_N = (p / M) (1 - kc_lo/kc - sum delta) (the square of the deltas is below 1e-32):
    ``drift`` is kc_lo/kc + sum delta. p / M as a double-double (ph - fl(q mh) is exact).
    """
    q = ph / mh
    t = _SPLIT * q
    q1 = t - (t - q)
    q2 = q - q1
    t = _SPLIT * mh
    m1 = t - (t - mh)
    m2 = mh - m1
    t = q * mh
    ql = (((ph - t) - (((q1 * m1 - t) + q1 * m2 + q2 * m1) + q2 * m2)) + (pl - q * ml)) / mh
    return q + (ql - q * drift)


def _quarters(mh, ml):
    """K = pi / (2 M) as a double-double, split in three parts (Cody and Waite), on floats.

    Arrays take :func:`.ends.quarter_parts`, the same operations in place.
    """
    kh, kl = _dd.div(0.5 * _PI_HI + 0.0 * mh, 0.5 * _PI_LO + 0.0 * mh, mh, ml)
    k_hi = _chop(kh)
    k_mid = _chop(kh - k_hi + kl)
    k_lo = (kh - k_hi - k_mid) + kl
    return kh + kl, k_hi, k_mid, k_lo


def _piece(kc: Any, kc_lo: Any) -> Constants:
    """Compute :func:`_constants` of one piece: one double-double AGM serves K and `core`.

    The AGM M(1, kc + kc_lo) runs in double-double arithmetic (:mod:`.levels`),
    seeded with kc (never with 1 - k**2), for K = pi / (2 M) to about 1e-32 relative; its
    levels give the descending Landen sequence a_n (``mu``, rounded to double) and the
    ratios b_n / a_n (``rho``, each rounded once), and `core` takes d = rho + (1 - rho) s,
    a sum of two positive terms, where GSL has (r + b_n) / (r + a_n) (measured: cn and dn
    just above k = 1 from 14 ulp to 8). The recurrence starts from the last level as if it
    were circular, which is off by that level's k_n^2 ~ 4 (a_n - b_n) / (a_n + b_n): an
    element stops where a - b <= 1e-8 a, and its next level, one step on (k^2 below
    2.5e-17), is made circular, rho = 1; so are all levels after it, which makes the extra
    steps of the recurrence exact identities (d = 1). That last a_N, free to within k_N^2,
    is chosen so that the recurrence's slope at v = 0 is one on the rounded levels,
    M a_N rho_1 ... rho_(N-1) = kc (:func:`_last`; else the roundings of the levels add
    up in sn(u) ~ u: 4.7 ulp at u = 3e-8 on GSL's rows).

    A piece of at least :data:`COMPILED_FROM` elements runs the AGM compiled
    (:func:`.compiled.agm`) once a large call has loaded it, a smaller one as NumPy passes
    (:func:`_levels`). Every element
    goes through the same operations whatever its companions and whichever the path: the
    same bits alone or beside a slower modulus (no dependence on the batch), and those of
    :func:`_constants_float`.
    """
    shape = kc.shape
    top = kc == 0  # the separatrix: K = inf; run the AGM on a harmless stand-in
    kc_lo = np.where(top, 0.0, kc_lo).ravel()
    kc = np.where(top, 1.0, kc).ravel()
    compiled = compiled_for(kc.size)
    if compiled is not None:
        mh, ml, mu_rows, rho_rows = compiled.agm(kc, kc_lo)
        mu, rho = list(mu_rows), list(rho_rows)
    else:
        mh, ml, mu, rho = _levels(kc, kc_lo)
    mu, rho = [x.reshape(shape) for x in mu], [x.reshape(shape) for x in rho]
    kc, mh, ml = kc.reshape(shape), mh.reshape(shape), ml.reshape(shape)
    quarter, k_hi, k_mid, k_lo = _ends.quarter_parts(mh, ml)
    if np.any(top):
        kc, quarter, k_hi = np.where(top, 0.0, kc), np.where(top, np.inf, quarter), \
            np.where(top, np.inf, k_hi)
        k_mid, k_lo = np.where(top, 0.0, k_mid), np.where(top, 0.0, k_lo)
    return Constants(kc, quarter, k_hi, k_mid, k_lo, mh, ml, tuple(mu), tuple(rho))


def _levels(kc, kc_lo):
    """Run the AGM of :func:`_piece` on flat arrays as NumPy passes: M (mh, ml), mu, rho.

    Elements that have stopped ride along with the others (their values are kept from
    the level where they stopped) until at most half of the piece still iterates; then the
    rest are gathered, so a few slow moduli cost only their own steps.
    """
    size = kc.size
    bh, bl = _fast_two_sum(kc, kc_lo)
    ah, al = np.ones(size), np.zeros(size)
    a1, a2 = ah, al
    drift = kc_lo / kc
    mu, rho = [ah], [bh]
    stop = np.full(size, 61.0)  # the level N of each element (61: not yet)
    # What an element keeps from its last level: M, the product p and the drift there.
    kept = [np.empty(size) for _ in range(5)]
    idx = None  # the elements still in the arrays, by position (None: all, in order)
    buffers = [np.empty(size) for _ in range(16)]
    work = buffers
    done = np.zeros(size, dtype=bool)  # by position in the arrays, like them
    for level in range(1, 61):  # 12 steps at kc = 1e-300; the cap guards a bug
        diff = np.subtract(ah, bh, out=work[9])  # a - b >= 0 (exact at the top: Sterbenz)
        np.add(diff, np.subtract(al, bl, out=work[10]), out=diff)
        s, ch, cl, ph, pl = step_into(ah, al, bh, bl, a1, a2, work)
        near = diff <= np.multiply(ah, _NEAR, out=work[10])
        new = near & ~done
        if np.any(new):
            where = np.nonzero(new)[0]
            at = where if idx is None else idx[where]
            kept[0][at], kept[1][at] = _mean(diff[where], s[where], ch[where], cl[where])
            for out, x in zip(kept[2:], (ph, pl, drift), strict=True):
                out[at] = x[where]
            stop[at] = level
        done |= near
        live = ~done
        count = int(np.count_nonzero(live))
        if idx is None:
            mu.append(ch)
        else:
            a_level = np.empty(size)
            a_level[idx] = ch
            mu.append(a_level)
        if count == 0:
            rho.append(np.ones(size))
            break
        if 2 * count <= live.size:  # gather the elements still iterating
            keep = np.nonzero(live)[0]
            idx = keep if idx is None else idx[keep]
            ch, cl, drift = ch[keep], cl[keep], drift[keep]
            ph, pl = ph[keep], pl[keep]
            work = [x[:count] for x in buffers]
            done = np.zeros(count, dtype=bool)
        bh, bl, a1, a2, ratio, delta = root_into(ph, pl, ch, cl, work[10:])
        ah, al = ch, cl
        np.add(drift, delta, out=drift)
        if idx is None:
            rho.append(ratio)
        else:
            rho_level = np.ones(size)
            rho_level[idx] = ratio
            rho.append(rho_level)
    else:
        raise RuntimeError("AGM did not converge")
    mh, ml, ph, pl, drift = kept
    last = _last(ph, pl, mh, ml, drift)
    first = int(stop.min(initial=61.0))  # below it no element has stopped: nothing to mend
    for n in range(first, len(mu)):  # each level array is the piece's own
        np.copyto(mu[n], last, where=stop <= n)
        np.copyto(rho[n], 1.0, where=stop <= n)
    return mh, ml, mu, rho


@lru_cache(maxsize=256)
def _constants_float(kc: float, kc_lo: float) -> Constants:
    """Compute :func:`_constants` of one modulus on Python floats (its twin: the same bits)."""
    bh, bl = _fast_two_sum(kc, kc_lo + 0.0 * kc)
    ah, al, a1, a2 = 1.0, 0.0, 1.0, 0.0
    drift = kc_lo / kc
    mu, rho = [ah], [bh]
    while True:
        diff = (ah - bh) + (al - bl)
        s, ch, cl, ph, pl = step(ah, al, bh, bl, a1, a2)
        if diff <= _NEAR * ah:
            mh, ml = _mean(diff, s, ch, cl)
            mu.append(_last(ph, pl, mh, ml, drift))
            rho.append(1.0)
            break
        bh, bl, a1, a2, ratio, delta = root(ph, pl, ch, cl)
        ah, al = ch, cl
        drift = drift + delta
        mu.append(ah)
        rho.append(ratio)
    quarter, k_hi, k_mid, k_lo = _quarters(mh, ml)
    return Constants(kc, quarter, k_hi, k_mid, k_lo, mh, ml, tuple(mu), tuple(rho))


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
    return _ends.complement(np.asarray(k, dtype=float))  # the operations of dd, in place


def quarter_period(kc: Any, kc_lo: Any = 0.0) -> Any:
    """K(k) from kc (+ kc_lo), correctly rounded in practice (double-double AGM)."""
    return constants(kc, kc_lo).quarter
