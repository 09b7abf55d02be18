"""From initial states to everything a Motion holds, in chunks of a few thousand states.

Working on a few thousand states at a time keeps every temporary of the double-double
classification in the processor's cache (and below the size at which the allocator maps
fresh pages for each one), which makes a large ensemble several times faster than one pass.
Each state is computed on its own, so the chunking changes no bit of any result.
"""

from __future__ import annotations

import math

import numpy as np

from . import classify as _classify
from . import dd as _dd
from . import flow as _flow
from . import landen as _landen
from .classify import classify, phases
from .codes import LIBRATION, REST, ROTATION, SEPARATRIX

__all__ = ["solve"]

# 2**13 states: their temporaries (64 KiB) stay below the 128 KiB at which glibc maps fresh
# pages for each allocation; measured, a tenth faster than 4096 on the benchmark ensemble.
CHUNK = 8192


def _reject(bad: np.ndarray, message: str) -> None:
    if np.any(bad):
        raise ValueError(message)


def _chunk(th, v, w0):
    """Return the public values and the Params of 1-D arrays of states.

    The public values: theta0, dtheta0, omega0, c1, modulus, complement, amplitude, phase,
    direction, period, beta.
    """
    # w = theta' / (2 omega0) is what the engine carries (and theta' = 2 omega0 w comes back
    # from it): a push that leaves no normal double w (it would underflow to 0 or lose its
    # digits as a subnormal) is refused, not turned into rest or a wrong theta'. A 2 omega0
    # beyond the doubles is left to the energy's error below.
    with np.errstate(over="ignore"):
        two_w0 = 2.0 * w0
        gone = (v != 0) & (np.abs(v / two_w0) < 2.0**-1022) & np.isfinite(two_w0)
    _reject(gone, "dtheta0 is too small for omega0: w = dtheta0 / (2 omega0) would be "
            "below the normal doubles; |dtheta0 / (2 omega0)| must be 0 or at least 2**-1022")
    st = classify(th, v, w0)
    code = st.code
    elliptic = (code == LIBRATION) | (code == ROTATION)
    _reject(~(st.rate < 1e290), "dtheta0 / omega0 and omega0 are too large together: the "
            "rate omega0 * max(1, |dtheta0| / (2 omega0)) must stay below 1e290")
    # Only a push of under 1e-300 rad/s at the very top gets here: kc would be subnormal
    # and K = log(4/kc) (hence the period) would lose its digits.
    _reject(elliptic & (st.mod_c < 1e-300), "dtheta0 is too small for a state this close to "
            "the top: the complementary modulus falls below 1e-300; use dtheta0 = 0 (balanced "
            "at the top) or |dtheta0| >= 2e-300 * omega0")
    with np.errstate(all="ignore"):
        # c1 = 2 w0^2 beta in double-double, rounded once. Where that leaves the range of
        # the exact products (a tiny or huge omega0), c1 = theta'^2 - 2 w0^2 cos r has no
        # cancellation left to fear: one of its terms dominates.
        c1 = _dd.mul(*_dd.two_prod(w0, 2.0 * w0), st.beta, st.beta_lo)[0]
        c1 = np.where(np.isfinite(c1) & (w0 > 2.0 ** -400) & (w0 < 2.0 ** 400), c1,
                      v * v - 2.0 * w0 * w0 * (st.c - st.s) * (st.c + st.s))
    # Name the term that overflows: omega0 = 1e200 at rest is not a large dtheta0.
    with np.errstate(over="ignore"):
        fast, stiff = ~np.isfinite(v * v), ~np.isfinite(2.0 * w0 * w0)
    bad = ~np.isfinite(c1)
    _reject(bad & fast, "dtheta0 is too large: the energy constant "
            "c1 = dtheta0**2 - 2 omega0**2 cos(theta0) would overflow (|dtheta0| < 1e154)")
    _reject(bad & stiff, "omega0 is too large: the energy constant "
            "c1 = dtheta0**2 - 2 omega0**2 cos(theta0) would overflow (omega0 < 9e153)")
    _reject(bad, "dtheta0 and omega0 are too large together: the energy constant "
            "c1 = dtheta0**2 - 2 omega0**2 cos(theta0) would overflow")
    # The smallest subnormal angle, +-5e-324, at rest: its half angle, hence the modulus
    # k = sin(theta0/2), rounds to 0 while the state still swings; no double holds k.
    _reject(elliptic & (st.k == 0), "theta0 is too small: the modulus sin(theta0 / 2) "
            "underflows; |theta0| must be 0 or at least 1e-323 (or give dtheta0)")
    landen = _landen.constants(np.where(elliptic, st.mod_c, 1.0),
                               np.where(elliptic, st.mod_c_lo, 0.0))
    quarter = landen.quarter
    quarters, rem = phases(st, quarter)
    lib, rot, sep = code == LIBRATION, code == ROTATION, code == SEPARATRIX
    still = (code == REST) | (sep & (st.w == 0))
    sigma = np.where((sep | rot) & (st.w < 0), -1.0, 1.0)
    with np.errstate(all="ignore"):  # branches that np.where drops may divide by zero
        x0 = sigma * np.arcsinh(st.s / st.c)
        phase = np.where(elliptic, quarters * quarter + rem, np.where(sep & ~still, x0, 0.0))
        gamma = 1.0 / st.k
        period = np.where(lib, 4.0 * quarter / w0,
                          np.where(rot, 2.0 * quarter / st.rate, 2.0 * math.pi / w0))
    period = np.where(sep, math.inf, period)
    modulus = np.where(lib, st.k, np.where(rot, gamma, np.where(sep, 1.0, 0.0)))
    complement = np.where(elliptic, st.mod_c, np.where(sep, 0.0, 1.0))
    amplitude = np.where(lib, 2.0 * np.arctan2(st.k, st.mod_c),
                         np.where(rot, math.inf, np.where(sep, math.pi, 0.0)))
    p = _flow.Params(code, still, th, st.turns, w0, sigma, np.where(elliptic, st.k, 1.0),
                     st.s, st.c, st.w, np.where(elliptic, st.rate, 0.0),
                     np.where(elliptic, st.rate_lo, 0.0), quarters, rem, st.s_lo, st.c_lo,
                     st.w_lo, st.k_lo, st.mod_c_lo, landen)
    public = [th, v, w0, c1, modulus, complement, amplitude, phase, sigma.astype(int),
              period, st.beta]
    return public, p


def _pad(levels, n):
    # Repeating the last level (where every element has b = a) is an exact identity of the
    # Landen recurrence, so chunks that converged in fewer steps can share one length.
    return tuple(levels) + (levels[-1],) * (n - len(levels))


def solve(th, v, w0):
    """Return the public values and Params of states of any shape (th, v, w0 broadcast).

    Underflow (a tiny amplitude squared) is the right answer and raises nothing, even
    under np.seterr(all="raise").
    """
    with np.errstate(under="ignore"):
        return _solve(th, v, w0)


def _solve(th, v, w0):
    shape = th.shape
    size = th.size
    if size <= CHUNK:
        public, p = _chunk(th, v, w0)
        return public, p
    _landen.load_compiled(size)
    flat = [np.ravel(x) for x in (th, v, w0)]
    parts = [_chunk(*(x[i:i + CHUNK] for x in flat)) for i in range(0, size, CHUNK)]
    levels = max(len(p.landen.mu) for _, p in parts)

    def join(arrays):
        return np.concatenate(arrays).reshape(shape)

    public = [join([pub[j] for pub, _ in parts]) for j in range(len(parts[0][0]))]
    scalars = [join([p[j] for _, p in parts]) for j in range(len(_flow.Params._fields) - 1)]
    c = [join([p.landen[j] for _, p in parts]) for j in range(_landen.SCALARS)]
    mu = [join(column) for column in zip(*(_pad(p.landen.mu, levels) for _, p in parts),
                                         strict=True)]
    rho = [join(column) for column in zip(*(_pad(p.landen.rho, levels) for _, p in parts),
                                         strict=True)]
    return public, _flow.Params(*scalars, _landen.Constants(*c, tuple(mu), tuple(rho)))


def solve_float(th: float, v: float, w0: float):
    """Compute :func:`solve` of one state in the usual range on Python floats (its twin).

    Public values and Params (Python scalars), the bits of the array call; or None where the
    array path decides (far states, rest, the separatrix).
    """
    if not 2.0 ** -300 < w0 < 2.0 ** 300:
        return None
    wh = v / (2.0 * w0)
    if not ((th == 0 or 2.0 ** -300 < abs(th) < 2.0 ** 20)
            and (v == 0 or 2.0 ** -300 <= abs(wh) < 2.0 ** 300)):
        return None
    turns, (sh, sl), (ch, cl) = _classify._half_angle_float(th)
    p, e = _dd.two_prod(wh, 2.0 * w0)
    wl = ((v - p) - e) / (2.0 * w0)
    k2 = _dd.add(*_dd.mul(sh, sl, sh, sl), *_dd.mul(wh, wl, wh, wl))
    aw = -1.0 if wh < 0 else 1.0
    kc2 = _dd.mul(*_dd.add(ch, cl, -aw * wh, -aw * wl), *_dd.add(ch, cl, aw * wh, aw * wl))
    code = LIBRATION if kc2[0] > 0 else (ROTATION if kc2[0] < 0 else SEPARATRIX)
    if sh == 0 and wh == 0:
        return None  # at rest at the bottom: the array path
    k = _dd.sqrt(k2[0], k2[1], math.sqrt)
    beta = _dd.add(k2[0], k2[1], -kc2[0], -kc2[1])
    if code == SEPARATRIX:
        return None
    kc = _dd.sqrt(abs(kc2[0]), -kc2[1] if kc2[0] < 0 else kc2[1], math.sqrt)
    rot = code == ROTATION
    mod_c = _dd.div(*kc, *k) if rot else kc
    rate = _dd.mul_d(k[0], k[1], w0) if rot else (w0, 0.0)
    if not (rate[0] < 1e290 and mod_c[0] >= 1e-300 and 2.0 ** -400 < w0 < 2.0 ** 400):
        return None
    c1 = _dd.mul(*_dd.two_prod(w0, 2.0 * w0), *beta)[0]
    if not math.isfinite(c1):
        return None
    landen = _landen._constants_float(*mod_c)
    q, rem = _classify.phase_float(sh, ch, wh, k[0], mod_c[0], rot)
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
              sl, cl, wl, k[1], mod_c[1], landen)
    return public, params


def plain(values: list, p: _flow.Params) -> list:
    """Return a Motion's fields (public values, beta, Params); Python scalars for one state.

    Python scalars throughout a single state, for the fast path of one state at one time.
    """
    if np.ndim(p.code) != 0:
        return [*values, p]
    regime = values[0].item() if isinstance(values[0], np.ndarray) else values[0]
    public = [regime, *(float(x) for x in values[1:9]), int(values[9]), float(values[10]),
              float(values[11])]
    c = p.landen
    landen = _landen.Constants._make([*(float(x) for x in c[:-2]),  # all but mu and rho
                                      tuple(float(x) for x in c.mu),
                                      tuple(float(x) for x in c.rho)])
    return [*public, _flow.Params._make([int(p.code), bool(p.still),
                                         *(float(x) for x in p[2:-1]), landen])]


def pick(values: tuple, p: _flow.Params, shape: tuple, index) -> list:
    """Return the fields of the Motion of the states ``S[index]`` (see :func:`plain`)."""

    def one(x):
        return np.broadcast_to(x, shape)[index]

    c = p.landen
    landen = _landen.Constants._make([*(one(x) for x in c[:_landen.SCALARS]),
                                      tuple(one(x) for x in c.mu),
                                      tuple(one(x) for x in c.rho)])
    return plain([one(x) for x in values], _flow.Params._make([*(one(x) for x in p[:-1]),
                                                               landen]))
