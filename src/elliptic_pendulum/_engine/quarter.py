"""K(k) in double precision for many moduli at once, from m1 = kc**2 (never from 1 - k**2).

The Jacobi functions need K to double-double precision (n K must stay exact over many
periods: :mod:`.landen`), but K itself is a double: here it comes from Cephes' ``ellpk``
(scipy.special.ellipkm1, a polynomial in m1 minus log(m1) times another), within 2 ulp of
mpmath over k in [0, 1) and kc down to 1e-300 (measured; half the points are exact, 99% within
one ulp), at about one scipy.special.ellipk call per point instead of a double-double AGM.

Seeded with m1 = kc**2 it keeps the separatrix: K ~ log(4/kc) there and m1's rounding moves K
by a fraction of an ulp (dK/K = -(dm1/m1) / (2 K)). Below kc = 2**-30 the expansion
K = log(4/kc) + (kc^2/4) (log(4/kc) - 1) + ... (DLMF 19.12.1) is log 4 - log kc to
1e-17 relative, which also serves kc whose square would underflow (kc < 1.5e-154).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from scipy import special

__all__ = ["complete"]

_LOG4 = math.log(4.0)
_SMALL = 2.0 ** -30


def complete(m1: Any, kc: Any) -> Any:
    """K from m1 = kc**2 in [0, 1] and kc = sqrt(m1) (either may be the rounded other).

    K = inf at kc = 0. Elementwise: an element's value depends on its own m1 and kc only.
    """
    m1 = np.asarray(m1, dtype=float)
    kc = np.asarray(kc, dtype=float)
    small = kc < _SMALL
    with np.errstate(divide="ignore", under="ignore"):  # kc = 0: log 0 = -inf, K = inf
        if not np.any(small):  # the usual case: one ellipkm1 pass, no stand-ins to place
            return special.ellipkm1(m1)
        quarter = special.ellipkm1(np.where(small, 1.0, m1))
        return np.where(small, _LOG4 - np.log(kc), quarter)
