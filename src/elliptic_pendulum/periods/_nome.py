r"""Jacobi's nome q (and its square root) from a modulus pair, for :mod:`.series`.

Two routes. For :math:`k \lesssim 0.955` the series of Abramowitz and Stegun 17.3.21,
continued (OEIS A005797),

.. math:: q = \varepsilon + 2\varepsilon^5 + 15\varepsilon^9 + 150\varepsilon^{13}
          + 1707\varepsilon^{17} + 20910\varepsilon^{21} + 268616\varepsilon^{25}
          + 3567400\varepsilon^{29} + 48555069\varepsilon^{33} + \cdots, \qquad
          \varepsilon = \frac{1 - \sqrt{k_c}}{2(1 + \sqrt{k_c})}
          = \frac{k^2}{2(1 + k_c)(1 + \sqrt{k_c})^2},

all terms positive and :math:`\varepsilon` formed without cancellation: q to about 2 ulp.
Beyond, :math:`q = e^{-\pi K'/K}` from two AGMs: the exponent is below 3 there, so its
rounding costs q little, and neither K is formed from a difference :math:`1 - k^2`. (From
the exponential alone q was 5 ulp off just above k = 1/2, where the exponent is near 4.)
"""

from __future__ import annotations

import math

import numpy as np

from ..elliptic import complete_integral

__all__ = ["nome_from_pair", "root_nome_from_pair"]

# The coefficients of q in powers of epsilon^4 (after the leading epsilon), checked against
# mpmath's qfrom at 400 digits.
_SERIES = (2.0, 15.0, 150.0, 1707.0, 20910.0, 268616.0, 3567400.0, 48555069.0)
# The first term left out is 673458874 epsilon^37: below 1e-22 of q for epsilon <= 0.15, which
# holds for k up to about 0.955.
_SERIES_LIMIT = 0.15


def _series(k: np.ndarray, kc: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Return (epsilon, sqrt(epsilon), t) with q = epsilon (1 + t)."""
    half_sum, root_sum = 2.0 * (1.0 + kc), 1.0 + np.sqrt(kc)
    # epsilon from k^2 directly, not as the square of sqrt(epsilon): one rounding fewer.
    epsilon = k * k / (half_sum * root_sum**2)
    power = epsilon**4
    tail = np.zeros_like(epsilon)
    for coefficient in reversed(_SERIES):
        tail = tail * power + coefficient
    return epsilon, k / (np.sqrt(half_sum) * root_sum), power * tail


def _exponent(k: np.ndarray, kc: np.ndarray) -> np.ndarray:
    """Return pi K'/K, K = K1(k) and K' = K1(kc), each seeded with the other's complement."""
    big = np.asarray(complete_integral(k, kc=kc), dtype=float)
    prime = np.asarray(complete_integral(kc, kc=k), dtype=float)
    exponent = np.zeros(k.shape)  # k = 1: K = inf, q = 1
    np.divide(math.pi * prime, big, out=exponent, where=np.isfinite(big))
    return exponent


def _routes(k: np.ndarray, kc: np.ndarray, root: bool) -> np.ndarray:
    k, kc = np.broadcast_arrays(np.asarray(k, dtype=float), np.asarray(kc, dtype=float))
    out = np.empty(k.shape)
    # For k below 1e-154, q ~ k^2/16 is below the doubles: 0 to rounding, without a warning.
    with np.errstate(under="ignore"):
        epsilon, root_epsilon, tail = _series(k, kc)
        near = epsilon <= _SERIES_LIMIT
        if root:
            out[near] = (root_epsilon * np.sqrt(1.0 + tail))[near]
        else:
            out[near] = (epsilon + epsilon * tail)[near]
        if not np.all(near):
            exponent = _exponent(k[~near], kc[~near])
            out[~near] = np.exp(-0.5 * exponent if root else -exponent)
    return out


def nome_from_pair(k: np.ndarray, kc: np.ndarray) -> np.ndarray:
    """Return q from a modulus pair each known to full relative precision (already checked)."""
    return _routes(k, kc, root=False)


def root_nome_from_pair(k: np.ndarray, kc: np.ndarray) -> np.ndarray:
    """Return sqrt(q) likewise: a normal double where q itself would underflow."""
    return _routes(k, kc, root=True)
