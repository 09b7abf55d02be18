r"""The note's elliptic integrals and Jacobi's elliptic functions.

Conventions
-----------
**Modulus k, not parameter m.** Like the note (whose alpha and gamma are
moduli), DLMF chapters 19 and 22 and Boost, every function here takes the
modulus ``k``; scipy and mpmath take the parameter ``m = k**2``. Every function
also accepts the complementary modulus ``kc = sqrt(1 - k**2)`` by keyword and
trusts it over ``k``: near the separatrix k rounds to 1.0 while kc still holds
every digit of the energy.

========================  =========================  ==================================
note                      here                       scipy / mpmath
========================  =========================  ==================================
E1(z, alpha)   (17)       ``incomplete_integral``    ``ellipkinc(arcsin(z), m)``
K1(alpha)      (18)       ``complete_integral``      ``ellipk(m)``
G(u, alpha)    (19)       ``inverse_integral``       sn restricted to [-K, K]
G-bar(u, alpha)           ``sn``                     ``ellipj(u, m)[0]``
I-hat(u, gamma)           ``am``                     ``ellipj(u, m)[3]``
========================  =========================  ==================================

Method
------
sn, cn and dn use the descending Landen (Gauss) transformation in the form of
GSL's ``gsl_sf_elljac_e``, seeded with kc, after an exact reduction of u by
multiples of the quarter period K (K from a double-double AGM, split in three
parts). The recurrence is free of cancellation, so sn, cn and dn carry small
relative errors for every kc in [0, 1]; scipy's ``ellipj`` (Cephes) is not
usable for 1 - m <= 1e-10 (scipy issue 8480). The limits k = 0 (sin, cos, 1)
and kc = 0 (tanh, sech, sech) are handled first, explicitly. E1 uses Carlson's
R_F (DLMF 19.25.5) with 1 - k^2 z^2 written as (1 - z)(1 + z) + kc^2 z^2.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
from scipy import special

from ._engine import jacobi as _jacobi
from ._engine import landen as _landen
from ._engine import quarter as _quarter
from ._validation import FloatOrArray, modulus_pair, real_array, scalar_or_array

__all__ = ["complete_integral", "incomplete_integral", "inverse_integral",
           "jacobi", "sn", "cn", "dn", "am"]


# --- the integrals: E1 (17), K1 (18) and G (19), the inverse of E1 -------------------------


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


# --- the Jacobi functions sn, cn, dn and the amplitude am (section 5 of the note) ----------


def jacobi(u: npt.ArrayLike, k: npt.ArrayLike,
           kc: npt.ArrayLike | None = None) -> tuple[FloatOrArray, FloatOrArray, FloatOrArray]:
    r"""Jacobi's sn, cn and dn at once (cheaper than three calls).

    .. math:: \operatorname{sn}^2 u + \operatorname{cn}^2 u = 1, \qquad
              \operatorname{dn}^2 u + k^2 \operatorname{sn}^2 u = 1

    Parameters
    ----------
    u : array_like
        Any real argument.
    k, kc : array_like
        Modulus, any real k: the functions are even in k, and k beyond 1 in
        size goes through the reciprocal modulus (DLMF 22.17). Or its complement kc in
        [0, 1] by keyword (trusted over k).

    Returns
    -------
    sn, cn, dn : float or ndarray
        Broadcast over ``u`` and the modulus.

    See Also
    --------
    sn, cn, dn, am

    Notes
    -----
    Against mpmath: sn and cn to about 1e-15 absolute and dn to a few
    1e-15 relative, for ``|u|`` up to 1e4 and every kc from 1 down to 0.
    The reduction by quarter periods is exact up to 2**26 quarter periods
    (about 6.7e7 K1); beyond, a ValueError names ``u`` (except at k = 0 and
    kc = 0, which need no reduction). For ``|k| > 1`` the argument is k u
    (DLMF 22.17), which must stay within 2**26 quarter periods K1(1/k) (except
    past ``|k| = 2**537``, where the functions are circular) and below 1e290;
    every finite k works, an infinite one is refused (ValueError naming k).

    Examples
    --------
    >>> s, c, d = jacobi(1.2, 0.7)
    >>> abs(s**2 + c**2 - 1) < 1e-15 and abs(d**2 + 0.49 * s**2 - 1) < 1e-15
    True

    Above k = 1 (DLMF 22.17.2): sn(u, k) = sn(k u, 1/k) / k, and dn^2 + k^2 sn^2 = 1 still:

    >>> s, c, d = jacobi(0.4, 2.5)
    >>> abs(s - sn(1.0, 0.4) / 2.5) < 1e-16 and abs(d**2 + 6.25 * s**2 - 1) < 1e-15
    True
    """
    if kc is None and type(u) is float and type(k) is float:  # one number: the fast path
        one = _jacobi.values_float(u, k)
        if one is not None:
            return one[0], one[1], one[2]
    u = real_array(u, "u")
    (s, c, d, _), modulus, kc = _values(u, k, kc, False)
    # Shaped like every argument broadcast together, k too where kc (trusted over k) is given,
    # and a Python float only when all were scalars (the package's scalar_or_array rule).
    shape = np.broadcast_shapes(u.shape, modulus.shape, np.shape(kc))
    return tuple(scalar_or_array(x if x.shape == shape else np.array(np.broadcast_to(x, shape)),
                                 u, modulus, kc) for x in (s, c, d))


def _values(u: np.ndarray, k: npt.ArrayLike, kc: npt.ArrayLike | None, amplitude: bool):
    """Return the kernel's (sn, cn, dn, am), |k| and kc as arrays (kc None: k alone, many)."""
    if kc is None:
        modulus = np.abs(real_array(k, "k"))
        return _jacobi.values_of_moduli(u, modulus, amplitude), modulus, None
    modulus, kc, _ = modulus_pair(k, kc, beyond_one=True)
    return _jacobi.values(u, modulus, kc, 0.0, amplitude), modulus, kc


def sn(u: npt.ArrayLike, k: npt.ArrayLike, kc: npt.ArrayLike | None = None) -> FloatOrArray:
    r"""Jacobi's sn(u, k): the note's G-bar, the periodic extension (20) of G.

    .. math:: u = \int_0^{\operatorname{sn} u}
              \frac{ds}{\sqrt{(1-s^2)(1-k^2 s^2)}}, \qquad
              \operatorname{sn}(u + 2K_1) = -\operatorname{sn} u

    Parameters
    ----------
    u : array_like
        Any real argument.
    k, kc : array_like
        Modulus (any real k; see :func:`jacobi`), or its complement
        kc = sqrt(1 - k**2) by keyword.

    Returns
    -------
    float or ndarray

    References
    ----------
    DLMF 22.2.4, 22.4.3, 22.20(ii).

    Examples
    --------
    The limits k = 0 and k = 1 are sin and tanh (DLMF 22.5(ii)):

    >>> import math
    >>> sn(0.5, 0.0) == math.sin(0.5), sn(0.5, 1.0) == math.tanh(0.5)
    (True, True)

    sn inverts E1 (19): E1(sn(u), k) = u on [-K1, K1].

    >>> abs(incomplete_integral(sn(0.9, 0.6), 0.6) - 0.9) < 1e-15
    True

    and it is periodic with period 4 K1 (Lemma 2.2):

    >>> K = complete_integral(0.6)
    >>> abs(sn(0.9 + 4 * K, 0.6) - sn(0.9, 0.6)) < 1e-15
    True
    """
    return jacobi(u, k, kc)[0]


def cn(u: npt.ArrayLike, k: npt.ArrayLike, kc: npt.ArrayLike | None = None) -> FloatOrArray:
    r"""Jacobi's cn(u, k), with cn^2 = 1 - sn^2 and cn(0) = 1.

    .. math:: \operatorname{cn} u = \cos \operatorname{am} u

    Parameters
    ----------
    u : array_like
    k, kc : array_like
        Modulus, or its complement by keyword.

    Returns
    -------
    float or ndarray

    Examples
    --------
    cn vanishes at the quarter period (DLMF 22.5.1):

    >>> abs(cn(complete_integral(0.9), 0.9)) < 1e-15
    True
    """
    return jacobi(u, k, kc)[1]


def dn(u: npt.ArrayLike, k: npt.ArrayLike, kc: npt.ArrayLike | None = None) -> FloatOrArray:
    r"""Jacobi's dn(u, k) = sqrt(1 - k^2 sn^2 u), between kc and 1.

    .. math:: \operatorname{dn} u = \frac{d}{du} \operatorname{am} u

    Parameters
    ----------
    u : array_like
    k, kc : array_like
        Modulus, or its complement by keyword.

    Returns
    -------
    float or ndarray

    Examples
    --------
    dn(K1) = kc (DLMF 22.5.1), to full relative accuracy even when tiny:

    >>> kc = 1e-12
    >>> K = complete_integral(1.0, kc=kc)
    >>> abs(dn(K, 1.0, kc=kc) / kc - 1) < 1e-13
    True
    """
    return jacobi(u, k, kc)[2]


def am(u: npt.ArrayLike, k: npt.ArrayLike, kc: npt.ArrayLike | None = None) -> FloatOrArray:
    r"""Jacobi's amplitude am(u, k): the note's I-hat, the staircase extension (21).

    .. math:: \operatorname{am} u = \int_0^u \operatorname{dn} v \, dv, \qquad
              \operatorname{am}(u + 2K_1) = \operatorname{am} u + \pi

    Parameters
    ----------
    u : array_like
    k, kc : array_like
        Modulus, or its complement by keyword.

    Returns
    -------
    float or ndarray
        An increasing, unbounded function of u; sin(am u) = sn u.

    Examples
    --------
    >>> import math
    >>> K = complete_integral(0.5)
    >>> abs(am(0.3 + 2 * K, 0.5) - am(0.3, 0.5) - math.pi) < 1e-15
    True
    >>> abs(math.sin(am(2.0, 0.5)) - sn(2.0, 0.5)) < 1e-15
    True
    """
    if kc is None and type(u) is float and type(k) is float:  # one number: the fast path
        one = _jacobi.values_float(u, k, amplitude=True)
        if one is not None:
            return one[3]
    u = real_array(u, "u")
    (_, _, _, a), modulus, kc = _values(u, k, kc, True)
    shape = np.broadcast_shapes(u.shape, modulus.shape, np.shape(kc))  # as in jacobi()
    return scalar_or_array(a if a.shape == shape else np.array(np.broadcast_to(a, shape)),
                           u, modulus, kc)
