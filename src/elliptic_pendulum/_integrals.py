"""The note's elliptic integrals E1 (17), K1 (18) and G (19), the inverse of E1.

Published, with their conventions (the modulus k, the keyword kc), by
:mod:`elliptic_pendulum.elliptic`, where they are documented; this module holds them. K1
from the double-double AGM of the engine, E1 from Carlson's R_F (DLMF 19.25.5) with
1 - k^2 z^2 written as (1 - z)(1 + z) + kc^2 z^2, G from sn restricted to [-K1, K1].
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
from scipy import special

from ._engine import jacobi as _jacobi
from ._engine import landen as _landen
from ._engine import quarter as _quarter
from ._validation import FloatOrArray, modulus_pair, real_array, scalar_or_array

__all__ = ["complete_integral", "incomplete_integral", "inverse_integral"]


def complete_integral(k: npt.ArrayLike, kc: npt.ArrayLike | None = None) -> FloatOrArray:
    r"""Complete elliptic integral of the first kind K1(k), the note's (18).

    .. math:: K_1(k) = \int_0^1 \frac{ds}{\sqrt{(1-s^2)(1-k^2 s^2)}}
              = \frac{\pi}{2\,\mathrm{AGM}(1, k_c)}

    Parameters
    ----------
    k : array_like
        Modulus in [-1, 1] (the note's alpha; K1 is even in k). Ignored where
        ``kc`` is given.
    kc : array_like, optional
        Complementary modulus sqrt(1 - k**2) in [0, 1]; pass it near k = 1.

    Returns
    -------
    float or ndarray
        K1; ``inf`` at k = 1 (kc = 0).

    Notes
    -----
    From k alone: Cephes' rational approximation in m1 = 1 - k**2 and
    log(m1) (scipy's ``ellipkm1``), and log(4/kc) below kc = 2**-30 (DLMF
    19.12.1); within 2 ulp of mpmath (half the moduli exact, 99% within one
    ulp; 1.2 ulp at worst on Boost.Math's rows). Where ``kc`` is given:
    Gauss's arithmetic-geometric mean seeded with kc, in double-double
    arithmetic (DLMF 19.8.5), correctly rounded in practice: the K of the
    Jacobi functions and of a motion's period, to the bit.

    Examples
    --------
    K1(0) = pi/2 (Proposition 1.3), and the AGM agrees with the integral:

    >>> import math
    >>> from scipy.integrate import quad
    >>> complete_integral(0.0) == math.pi / 2
    True
    >>> k = 0.8
    >>> integral, _ = quad(lambda t: (1 - k**2 * math.sin(t)**2) ** -0.5, 0, math.pi / 2)
    >>> abs(complete_integral(k) - integral) < 1e-14
    True

    Near the separatrix only ``kc`` can say how close we are: k is 1.0 in
    floating point here, so the parameter m = k**2 has lost everything, while
    K1 from kc follows the logarithmic law K1 ~ log(4 / kc) (DLMF 19.12.1):

    >>> from scipy.special import ellipk
    >>> float(ellipk(1.0 - (1e-12) ** 2))
    inf
    >>> abs(complete_integral(1.0, kc=1e-12) - math.log(4 / 1e-12)) < 1e-14
    True
    """
    if kc is None:
        # m1 = 1 - k^2 = (1 - k)(1 + k), exact but for two roundings (1 - k is exact from
        # k = 1/2 on); modulus_pair's double-double kc is not needed for K alone.
        modulus = np.abs(real_array(k, "k"))
        if np.any(modulus > 1):
            modulus_pair(modulus)  # raises the usual message
        m1 = (1.0 - modulus) * (1.0 + modulus)
        K = _quarter.complete(m1, np.sqrt(m1))
        shape = modulus.shape
    else:
        # kc given (a motion's modulus, or the separatrix): the double-double AGM, the K of
        # the Jacobi functions and of solve's period, to the bit.
        modulus, kc, kc_lo = modulus_pair(k, kc)
        K = np.asarray(_landen.quarter_period(kc, kc_lo))
        # Shaped like k and kc broadcast together (k too, where kc is given and trusted).
        shape = np.broadcast_shapes(modulus.shape, np.shape(kc))
    return scalar_or_array(K if K.shape == shape else np.array(np.broadcast_to(K, shape)),
                           modulus, kc)


def incomplete_integral(z: npt.ArrayLike, k: npt.ArrayLike,
                        kc: npt.ArrayLike | None = None) -> FloatOrArray:
    r"""Incomplete elliptic integral of the first kind E1(z, k), the note's (17).

    .. math:: E_1(z, k) = \int_0^z \frac{ds}{\sqrt{(1-s^2)(1-k^2 s^2)}}
              = z\, R_F(1 - z^2,\ 1 - k^2 z^2,\ 1)

    Parameters
    ----------
    z : array_like
        Upper limit in [-1, 1].
    k, kc : array_like
        Modulus in [-1, 1] (E1 is even in k), or its complement
        kc = sqrt(1 - k**2) by keyword.

    Returns
    -------
    float or ndarray
        E1(z, k), an odd increasing function of z with E1(1, k) = K1(k).

    References
    ----------
    DLMF 19.2.4 and 19.25.5 (Carlson's symmetric form).

    Examples
    --------
    E1(z, 0) = arcsin(z) (Proposition 1.3) and E1(1, k) = K1(k):

    >>> import math
    >>> abs(incomplete_integral(0.5, 0.0) - math.asin(0.5)) <= math.ulp(math.asin(0.5))
    True
    >>> abs(incomplete_integral(1.0, 0.9) - complete_integral(0.9)) < 1e-15
    True
    """
    z = real_array(z, "z")
    if np.any(np.abs(z) > 1):
        raise ValueError("z must lie in [-1, 1]: E1(z, k) is the note's integral (17) up to z")
    quarter = complete_integral(k, kc)  # E1(+-1, k) = +-K1(k), to the bit
    k, kc, _ = modulus_pair(k, kc)
    # 1 - k^2 z^2 without cancellation at k ~ 1, z ~ 1. (kc z)^2 underflows only where it is
    # negligible beside (1 - z)(1 + z) >= 2**-53, or at z = +-1, which is overwritten below.
    with np.errstate(divide="ignore", invalid="ignore", under="ignore"):
        y = (1.0 - z) * (1.0 + z) + (kc * z) ** 2
        out = z * special.elliprf((1.0 - z) * (1.0 + z), y, 1.0)
    # At z = +-1, E1 = +-K1 (18): from the AGM, which also holds where y underflows. The sign
    # is copied, not multiplied in: z K1 would be 0 * inf = nan (and a warning) at z = 0, kc = 0.
    out = np.where(np.abs(z) == 1, np.copysign(quarter, z), out)
    shape = np.broadcast_shapes(z.shape, k.shape, np.shape(kc))  # k too, as in sn
    return scalar_or_array(out if out.shape == shape else np.array(np.broadcast_to(out, shape)),
                           z, k, kc)


def inverse_integral(u: npt.ArrayLike, k: npt.ArrayLike,
                     kc: npt.ArrayLike | None = None) -> FloatOrArray:
    r"""Invert E1 on [-K1(k), K1(k)]: the note's G(u, k) (19).

    .. math:: E_1(z, k) = u \iff z = G(u, k), \qquad |u| \le K_1(k)

    G is sn restricted to one rising branch; Lemma 2.2 extends it to sn.

    Parameters
    ----------
    u : array_like
        In [-K1(k), K1(k)]; ValueError outside.
    k, kc : array_like
        Modulus, or its complement by keyword.

    Returns
    -------
    float or ndarray
        In [-1, 1].

    Examples
    --------
    >>> K = complete_integral(0.8)
    >>> inverse_integral(K, 0.8)
    1.0
    >>> abs(incomplete_integral(inverse_integral(0.7, 0.8), 0.8) - 0.7) < 1e-15
    True
    """
    u = real_array(u, "u")
    K = np.asarray(complete_integral(k, kc))  # K1 as documented, to the bit
    k, kc, kc_lo = modulus_pair(k, kc)
    if np.any(np.abs(u) > K):
        raise ValueError("u must lie in [-K1(k), K1(k)]: G is the inverse of E1 on that "
                         "interval only (use sn for the extension to all u)")
    z = _jacobi.values(u, k, kc, kc_lo)[0]
    shape = np.broadcast_shapes(u.shape, k.shape, np.shape(kc))  # k too, as in sn
    return scalar_or_array(z if z.shape == shape else np.array(np.broadcast_to(z, shape)),
                           u, k, kc)
