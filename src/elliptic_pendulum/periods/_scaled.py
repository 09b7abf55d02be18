r"""The coefficients of R(theta0)'s series scaled by :math:`c^{2j}`, c the double nearest pi.

:math:`a_j` shrinks like :math:`\pi^{-2j}` and leaves the doubles below :math:`10^{-308}` near
j = 330, where :math:`a_j\theta_0^{2j}` is still far from negligible for :math:`\theta_0` near
pi. The scaled :math:`b_j = a_j c^{2j}` stay between about :math:`2/(\pi j)` and 1, and
:math:`a_j\theta_0^{2j} = b_j y^j` with :math:`y = (\theta_0/c)^2 \le 1`: neither factor leaves
the doubles.

The :math:`b_j` come from the differential equation :math:`(\sin\theta\,R')' = \tfrac14
\sin\theta\,R` of R (Legendre's equation for K): with
:math:`\sigma_i = (-1)^i c^{2i}/(2i+1)!` (the sine's coefficients, scaled alike),

.. math:: 4N^2 b_N = \frac{c^2}{4}\sum_{i \ge 0} \sigma_i\,b_{N-1-i}
          - 4N \sum_{i \ge 1} \sigma_i\,(N-i)\,b_{N-i}, \qquad b_0 = 1.

:math:`\sigma_i` falls below :math:`2^{-128}` after two dozen terms, so each coefficient costs
a fixed amount of work (the exact recurrence of :func:`.series.period_series_coefficients`
costs more and more). In doubles the recurrence loses about one rounding per step, 1e-13 by
j = 1000; it is run in integers scaled by :math:`2^{128}` (c and the :math:`\sigma_i` exact
dyadic or rational numbers, rounded once), where that loss stays below :math:`10^{-30}` for
every j allowed, and each :math:`b_j` is rounded to a double at the end.
"""

from __future__ import annotations

import math
import threading
from fractions import Fraction
from operator import mul

import numpy as np

__all__ = ["MAX_TERMS", "scaled_coefficients"]

#: The most terms :func:`.series.period_series` sums. The coefficients cost about 10
#: microseconds each (once: they are kept), the sum a few more. A million terms bring the
#: partial sum within a rounding of R (tail/R below 1e-16) for every amplitude up to pi - 5e-5.
MAX_TERMS = 1_000_000

_BITS = 128
_PI = Fraction(math.pi)  # the double c, exactly: y = (theta0 / c)^2 uses the same one
# c^2 / 4 as an integer ratio; c has a power-of-two denominator.
_C2_NUM, _C2_DEN = _PI.numerator**2, 4 * _PI.denominator**2


def _kernel() -> list[int]:
    """Return the scaled sine coefficients sigma_i * 2^_BITS, until they round to 0."""
    kernel: list[int] = []
    i = 0
    while True:
        value = round(Fraction((-1) ** i) * _PI ** (2 * i) / math.factorial(2 * i + 1)
                      * 2**_BITS)
        if value == 0:
            return kernel
        kernel.append(value)
        i += 1


_SIGMA = _kernel()
# Grown on demand and kept under the lock: the doubles b_j, and the last len(_SIGMA) + 1 of
# the integers B_j = b_j 2^_BITS the recurrence continues from (newest first).
_FLOATS: list[float] = [1.0]
_RECENT: list[int] = [1 << _BITS]
_LOCK = threading.Lock()


def scaled_coefficients(n: int) -> np.ndarray:
    """Return the doubles b_0, ..., b_{n-1} (a new array; 1 <= n <= MAX_TERMS)."""
    with _LOCK:
        width = len(_SIGMA)
        for order in range(len(_FLOATS), n):
            # _RECENT[i] = B_{order-1-i}: the first sum takes B_{order-1-i} sigma_i, the
            # second (order - i) B_{order-i} sigma_i for i >= 1, i.e. _RECENT[i - 1].
            first = sum(map(mul, _RECENT, _SIGMA))
            second = sum((order - 1 - i) * b * s
                         for i, (b, s) in enumerate(zip(_RECENT, _SIGMA[1:], strict=False)))
            numerator = _C2_NUM * first - _C2_DEN * 4 * order * second
            value = numerator // (_C2_DEN * 4 * order * order << _BITS)
            _RECENT.insert(0, value)
            del _RECENT[width + 1:]
            # int / int is correctly rounded, and b_j >= 1e-7 here: a normal double.
            _FLOATS.append(value / (1 << _BITS))
        return np.array(_FLOATS[:n], dtype=float)
