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

from ._engine import jacobi as _jacobi
from ._engine import scalar as _scalar
from ._integrals import complete_integral, incomplete_integral, inverse_integral
from ._validation import FloatOrArray, modulus_pair, real_array, scalar_or_array

__all__ = ["complete_integral", "incomplete_integral", "inverse_integral",
           "jacobi", "sn", "cn", "dn", "am"]


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
        one = _scalar.jacobi(u, k)
        if one is not None:
            return one[0], one[1], one[2]
    u = real_array(u, "u")
    k, kc, kc_lo = modulus_pair(k, kc, beyond_one=True)
    s, c, d, _ = _jacobi.values(u, k, kc, kc_lo)
    # Shaped like every argument broadcast together, k too where kc (trusted over k) is given,
    # and a Python float only when all were scalars (the package's scalar_or_array rule).
    shape = np.broadcast_shapes(u.shape, k.shape, np.shape(kc))
    return tuple(scalar_or_array(x if x.shape == shape else np.array(np.broadcast_to(x, shape)),
                                 u, k, kc) for x in (s, c, d))


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
        one = _scalar.jacobi(u, k, amplitude=True)
        if one is not None:
            return one[3]
    u = real_array(u, "u")
    k, kc, kc_lo = modulus_pair(k, kc, beyond_one=True)
    a = _jacobi.values(u, k, kc, kc_lo, amplitude=True)[3]
    shape = np.broadcast_shapes(u.shape, k.shape, np.shape(kc))  # as in jacobi()
    return scalar_or_array(a if a.shape == shape else np.array(np.broadcast_to(a, shape)),
                           u, k, kc)
