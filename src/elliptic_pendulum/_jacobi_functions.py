"""Jacobi's elliptic functions sn, cn, dn and the amplitude am (section 5 of the note).

Published, with their conventions (the modulus k, the keyword kc, k > 1 by DLMF 22.17), by
:mod:`elliptic_pendulum.elliptic`, where they are documented; this module holds them. The
values come from the engine's descending Landen kernel after an exact reduction by quarter
periods (``_engine/landen.py``), the edges k = 0, kc = 0 and k > 1 from ``_engine/jacobi.py``.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ._engine import jacobi as _jacobi
from ._validation import FloatOrArray, modulus_pair, real_array, scalar_or_array

__all__ = ["jacobi", "sn", "cn", "dn", "am"]


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

    >>> from elliptic_pendulum.elliptic import complete_integral, incomplete_integral
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

    >>> from elliptic_pendulum.elliptic import complete_integral
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

    >>> from elliptic_pendulum.elliptic import complete_integral
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
    >>> from elliptic_pendulum.elliptic import complete_integral
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
