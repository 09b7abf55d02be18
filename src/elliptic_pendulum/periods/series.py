r"""The period and the swing as series: R(theta0) in powers of theta0, the nome, the overtones.

For the chapter "the period in depth" (beyond the note). Conventions as in :mod:`.period`:
amplitudes in radians, :math:`R(\theta_0) = (2/\pi) K_1(\sin(\theta_0/2))`, modulus k (the note's
alpha) with :math:`k_c = \sqrt{1 - k^2}` passed alongside where k is close to 1.

* :func:`period_series_coefficients` gives the exact rational coefficients :math:`a_n` of
  :math:`R(\theta_0) = \sum_n a_n \theta_0^{2n}` (OEIS A223067 / A223068), and
  :func:`period_series` sums them. The series converges for :math:`|\theta_0| < \pi` only:
  :math:`R` has a logarithmic singularity at :math:`\theta_0 = \pm\pi` (the separatrix), where
  :math:`R \approx -(2/\pi)\log(1 - \theta_0^2/\pi^2)`, so :math:`n\,\pi^{2n} a_n \to 2/\pi`.
* :func:`nome` is Jacobi's :math:`q = e^{-\pi K'/K}`, from its series in k (from two AGMs
  near k = 1) so that it keeps its relative accuracy for k small (:math:`q \approx k^2/16`)
  and for :math:`k_c` small.
* :func:`fourier_coefficients` gives the sine series of a swing (DLMF 22.11.1 with
  :math:`\theta/2 = \arcsin(k\,\mathrm{sn})`, integrated term by term):

  .. math:: \theta(t) = \sum_{j \ge 0} b_j \sin\frac{(2j+1)\,2\pi t}{T}, \qquad
            b_j = \frac{8\,q^{j+1/2}}{(2j+1)(1 + q^{2j+1})},

  with t measured from a passage through the bottom with :math:`\theta' > 0`. For the motion
  ``ep.solve(theta0)`` (released from rest at t = 0) that passage is at t = 3T/4.
"""

from __future__ import annotations

import functools
import math
import threading
from fractions import Fraction
from typing import Any

import numpy as np
import numpy.typing as npt

from .._validation import FloatOrArray, real_array, scalar_or_array
from ._nome import nome_from_pair, root_nome_from_pair
from ._scaled import MAX_TERMS, scaled_coefficients

__all__ = ["fourier_coefficients", "nome", "period_series", "period_series_coefficients"]


def _count(value: Any, name: str) -> int:
    """Return a positive number of terms, or raise naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be a positive integer (a number of terms), "
                        f"got {type(value).__name__}")
    if value < 1:
        raise ValueError(f"{name} must be a positive integer (a number of terms); got {value}")
    return int(value)


def period_series_coefficients(n: int) -> list[Fraction]:
    r"""Return the first n coefficients of the Maclaurin series of R(theta0), as exact fractions.

    .. math:: R(\theta_0) = \frac{2}{\pi} K_1\!\left(\sin\frac{\theta_0}{2}\right)
              = \sum_{j=0}^{\infty} a_j\,\theta_0^{2j}
              = 1 + \frac{\theta_0^2}{16} + \frac{11\,\theta_0^4}{3072}
                + \frac{173\,\theta_0^6}{737280} + \cdots

    Parameters
    ----------
    n : int
        How many coefficients, :math:`a_0, \dots, a_{n-1}`; ``n >= 1``.

    Returns
    -------
    list of fractions.Fraction
        :math:`a_0 = 1, a_1 = 1/16, \dots`, all positive.

    Raises
    ------
    ValueError
        If ``n < 1``. (TypeError if it is not an integer.)

    Notes
    -----
    Exact integer arithmetic, by a recurrence (below) that gives all n coefficients in
    :math:`O(n^2)` big-integer operations; they are kept, so a second call costs nothing and a
    longer one only continues from where the last stopped. The closed form they agree with:
    with :math:`m = \sin^2(\theta_0/2)`,
    :math:`(2/\pi)K_1 = \sum_i c_i m^i`, :math:`c_i = \binom{2i}{i}^2/16^i` (DLMF 19.5.1), and the
    power of a sine as cosines of multiples,

    .. math:: \sin^{2i}\frac{\theta_0}{2} = \frac{1}{4^i}\left[\binom{2i}{i}
              + 2\sum_{r=1}^{i}(-1)^r\binom{2i}{i-r}\cos r\theta_0\right],

    the coefficient of :math:`\theta_0^{2n}` (n >= 1) is the finite sum
    :math:`a_n = \frac{2(-1)^n}{(2n)!}\sum_{r \ge 1}(-1)^r r^{2n}\sum_{i \ge r}
    \frac{c_i}{4^i}\binom{2i}{i-r}`, where i may run to any bound :math:`\ge n` (the terms with
    i > n cancel: :math:`m^i = O(\theta_0^{2i})`). The recurrence: Legendre's equation for
    :math:`K` in m becomes, in :math:`\theta_0`,
    :math:`(\sin\theta_0\,R')' = \tfrac14\sin\theta_0\,R`; with
    :math:`E_j = 64^j (2j)!\,a_j` (integers) and :math:`\sigma = (-1)^{N-j}`,

    .. math:: 8(N+1)(2N+3)\,E_{N+1} &= \sum_{j=0}^{N} \sigma\,64^{N+1-j}\,E_j \\
              &\qquad \times \left[(2N+3)\binom{2N+1}{2j} + 8j\binom{2N+3}{2j}\right].

    Radius of convergence :math:`\pi` (in
    :math:`\theta_0`): the nearest singularities are the separatrix amplitudes :math:`\pm\pi`,
    where :math:`m = 1`.

    Examples
    --------
    The published numerators and denominators (OEIS A223067, A223068):

    >>> a = period_series_coefficients(5)
    >>> [(c.numerator, c.denominator) for c in a]
    [(1, 1), (1, 16), (11, 3072), (173, 737280), (22931, 1321205760)]

    The ratio test sees the radius pi (with the factor :math:`n/(n+1)` of a logarithmic
    singularity), and :math:`n\pi^{2n}a_n` approaches the :math:`2/\pi` of the logarithm at the
    separatrix:

    >>> a = period_series_coefficients(60)
    >>> round(math.sqrt(58 * a[58] / (59 * a[59])), 4)
    3.1416
    >>> round(59 * math.pi**118 * float(a[59]) * math.pi / 2, 2)
    1.0
    """
    # A new list each time: the cached tuple behind it must not be changed by the caller.
    return list(_coefficients(_count(n, "n")))


# E_j = 64^j (2j)! a_j, grown on demand by the recurrence of period_series_coefficients and
# kept: the coefficients are exact, so they never change. Recomputing them on every call made
# period_series(theta0, 400) take seconds each time.
_SCALED = [1]
_SCALED_LOCK = threading.Lock()


def _binomials(n: int) -> list[int]:
    """Return the row binom(n, 0..n), each from the last (the row costs what one comb does)."""
    row = [1]
    for k in range(n):
        row.append(row[-1] * (n - k) // (k + 1))
    return row


def _scaled(n: int) -> list[int]:
    """Return [E_0, ..., E_{n-1}], continuing the recurrence from the ones already known."""
    with _SCALED_LOCK:
        for order in range(len(_SCALED) - 1, n - 1):  # computes E_{order + 1}
            inner, outer = _binomials(2 * order + 1), _binomials(2 * order + 3)
            total = 0
            for j, e in enumerate(_SCALED):
                term = e * ((2 * order + 3) * inner[2 * j]
                            + 8 * j * outer[2 * j]) << 6 * (order + 1 - j)
                total += term if (order - j) % 2 == 0 else -term
            quotient, remainder = divmod(total, 8 * (order + 1) * (2 * order + 3))
            assert remainder == 0  # E_{N+1} is an integer: 64^n (2n)! a_n is one
            _SCALED.append(quotient)
        return _SCALED[:n]


@functools.lru_cache(maxsize=16)
def _coefficients(n: int) -> tuple[Fraction, ...]:
    """Return a_0, ..., a_{n-1} as an immutable tuple of exact fractions."""
    return tuple(Fraction(e, 64**j * math.factorial(2 * j)) for j, e in enumerate(_scaled(n)))


# period_series sums a_0 .. a_{_HEAD - 1} as doubles (exactly rounded, so that two terms are
# 1 + theta0^2 / 16 to the last bit), and the scaled coefficients of ._scaled after them.
_HEAD = 200


@functools.lru_cache(maxsize=16)
def _float_coefficients(n: int) -> tuple[float, ...]:
    """Return a_0, ..., a_{n-1} rounded to doubles, for summing the series."""
    # int / int is correctly rounded, as float(Fraction) is, without reducing the fraction.
    return tuple(e / (64**j * math.factorial(2 * j)) for j, e in enumerate(_scaled(n)))


def period_series(theta0: npt.ArrayLike, terms: int) -> FloatOrArray:
    r"""Sum the Maclaurin series of R(theta0) to ``terms`` terms.

    .. math:: R_N(\theta_0) = \sum_{j=0}^{N-1} a_j\,\theta_0^{2j}

    Parameters
    ----------
    theta0 : float or array_like
        Amplitude in radians, :math:`|\theta_0| < \pi` (the radius of convergence).
    terms : int
        N, the number of terms (``terms=1`` gives 1, the small-angle period (8)), at most
        1,000,000: enough for a sum within rounding of R up to :math:`\pi - 5\cdot10^{-5}`.

    Returns
    -------
    float or ndarray
        :math:`R_N(\theta_0)`, of the shape of ``theta0``.

    Raises
    ------
    ValueError
        If an amplitude is not finite or :math:`|\theta_0| \ge \pi`: there the series diverges;
        or if ``terms`` exceeds 1,000,000.

    Notes
    -----
    Beyond 200 terms the :math:`a_j` (which shrink like :math:`\pi^{-2j}` and leave the doubles
    near j = 330) are summed scaled, as :math:`a_j c^{2j}\,(\theta_0/c)^{2j}` with c the double
    nearest pi; the scaled coefficients come from a recurrence of fixed cost per term (the
    module ``_scaled``), computed once and kept.

    Examples
    --------
    Two terms are the classroom correction :math:`1 + \theta_0^2/16`; at 90 degrees six terms
    are good to 1e-4 and twenty to 1e-8, against :func:`.period_ratio`:

    >>> import elliptic_pendulum as ep
    >>> period_series(0.5, 2) == 1 + 0.5**2 / 16
    True
    >>> [bool(abs(period_series(math.pi / 2, n) - ep.period_ratio(math.pi / 2)) < tol)
    ...  for n, tol in [(6, 1e-4), (20, 1e-8)]]
    [True, True]
    """
    theta0 = real_array(theta0, "theta0")
    terms = _count(terms, "terms")
    if terms > MAX_TERMS:
        raise ValueError(f"terms must be at most {MAX_TERMS:,} (the series is summed term by "
                         f"term); got {terms}")
    if np.any(np.abs(theta0) >= math.pi):
        raise ValueError("theta0 must satisfy |theta0| < pi (the series of R converges only "
                         f"there); got {theta0.tolist()!r}")
    # Tiny amplitudes underflow in the powers; 0 is those terms' value to rounding.
    with np.errstate(under="ignore"):
        x = theta0 * theta0
        total = np.zeros_like(x)
        for coefficient in reversed(_float_coefficients(min(terms, _HEAD))):
            total = total * x + coefficient
        if terms > _HEAD:
            # Beyond _HEAD the a_j approach the bottom of the doubles (below 1e-308 from
            # j = 330 on, and they were summed as 0): the rest is sum_j b_j y^j with
            # b_j = a_j c^2j and y = (theta0 / c)^2 <= 1, c = math.pi, each factor a double.
            y = np.square(theta0 / math.pi)
            tail = np.zeros_like(y)
            for coefficient in scaled_coefficients(terms)[:_HEAD - 1:-1]:
                tail = tail * y + coefficient
            total = total + tail * y**_HEAD
    return scalar_or_array(total, theta0)


def _checked_pair(k: Any, kc: Any) -> tuple[np.ndarray, np.ndarray]:
    """(k, kc) with the modulus pair checked, the one not given formed from the other."""
    if kc is None:
        k = real_array(k, "k")
        if np.any((k < 0) | (k > 1)):
            raise ValueError("k (the modulus) must lie in [0, 1]")
        # (1 - k)(1 + k) keeps the digits of kc^2 that 1 - k*k loses near k = 1.
        kc = np.sqrt((1.0 - k) * (1.0 + k))
    else:
        kc = real_array(kc, "kc")
        if np.any((kc < 0) | (kc > 1)):
            raise ValueError("kc (the complementary modulus sqrt(1 - k**2)) must lie in [0, 1]")
        k = np.sqrt((1.0 - kc) * (1.0 + kc))
    return k, kc


def nome(k: npt.ArrayLike, kc: npt.ArrayLike | None = None) -> FloatOrArray:
    r"""Jacobi's nome q of the modulus k.

    .. math:: q = \exp\!\left(-\pi\,\frac{K_1(k_c)}{K_1(k)}\right)
              = \exp\!\left(-\pi\,\frac{\mathrm{AGM}(1, k_c)}{\mathrm{AGM}(1, k)}\right)

    Parameters
    ----------
    k : float or array_like
        Modulus in [0, 1] (the note's alpha). Ignored where ``kc`` is given.
    kc : float or array_like, optional
        Complementary modulus :math:`\sqrt{1-k^2}` in [0, 1], trusted over ``k``; pass it
        near k = 1.

    Returns
    -------
    float or ndarray
        q in [0, 1]: 0 at k = 0, 1 at k = 1.

    Notes
    -----
    :math:`K_1(k) = \pi/(2\,\mathrm{AGM}(1, k_c))` and
    :math:`K_1(k_c) = \pi/(2\,\mathrm{AGM}(1, k))`
    (DLMF 19.8.5), each from :func:`~elliptic_pendulum.elliptic.complete_integral` seeded with the
    complement it needs, so no difference :math:`1 - k^2` is ever formed and q has a small
    relative error for :math:`k_c` small. For k up to about 0.955 the exponent :math:`\pi K'/K`
    (up to 700) would pass its rounding on to q, so there q comes from its series in
    :math:`\varepsilon = (1 - \sqrt{k_c})/(2(1 + \sqrt{k_c}))`,
    :math:`q = \varepsilon + 2\varepsilon^5 + 15\varepsilon^9 + 150\varepsilon^{13} + \dots`
    (Abramowitz and Stegun 17.3.21, to :math:`\varepsilon^{33}`), :math:`\varepsilon`
    formed without cancellation: q to a few ulp for every k.

    Examples
    --------
    Small k: the leading term of the series in :math:`k^2/16`; and the value for
    :math:`k^2 = 1/2`, :math:`q = e^{-\pi}` (K' = K):

    >>> abs(nome(1e-5) / (1e-10 / 16) - 1) < 1e-10
    True
    >>> abs(nome(math.sqrt(0.5)) - math.exp(-math.pi)) < 1e-16
    True
    """
    k, kc = _checked_pair(k, kc)
    return scalar_or_array(nome_from_pair(k, kc), k)


def fourier_coefficients(theta0: npt.ArrayLike, n: int) -> npt.NDArray[np.float64]:
    r"""Sine coefficients of a swing of amplitude theta0, t from a passage through the bottom.

    .. math:: \theta(t) = \sum_{j=0}^{\infty} b_j \sin\frac{(2j+1)\,2\pi t}{T}, \qquad
              b_j = \frac{8\,q^{j+1/2}}{(2j+1)\,(1 + q^{2j+1})}

    with q = :func:`nome` of :math:`k = \sin(\theta_0/2)` and T the period (26).

    Parameters
    ----------
    theta0 : float or array_like
        Amplitude in radians, :math:`0 \le \theta_0 < \pi`.
    n : int
        Number of coefficients, :math:`b_0, \dots, b_{n-1}` (harmonics 1, 3, ..., 2n-1).

    Returns
    -------
    ndarray
        Shape ``np.shape(theta0) + (n,)``; zeros at :math:`\theta_0 = 0`.

    Raises
    ------
    ValueError
        If an amplitude is outside :math:`[0, \pi)` or ``n < 1``.

    Notes
    -----
    Only odd harmonics appear: a swing is odd about the bottom passage and has half-wave symmetry.
    :math:`q^{j+1/2}` is taken as a power of :math:`\sqrt q`, which stays a normal double for
    amplitudes down to 1e-150 rad. For small amplitudes :math:`b_0 \approx \theta_0` and
    :math:`b_1/b_0 \approx q/3 \approx \theta_0^2/192`.

    Examples
    --------
    The partial sums reproduce the exact motion (``ep.solve`` releases from rest at t = 0, so the
    bottom is passed upwards at 3T/4), here to 1e-14 with 16 terms at 120 degrees:

    >>> import elliptic_pendulum as ep
    >>> theta0 = math.radians(120)
    >>> b = fourier_coefficients(theta0, 16)
    >>> T = ep.period(theta0)
    >>> t = np.linspace(0, T, 101)
    >>> series = sum(bj * np.sin((2 * j + 1) * 2 * np.pi * t / T) for j, bj in enumerate(b))
    >>> bool(np.max(np.abs(series - ep.solve(theta0).theta(t + 0.75 * T))) < 1e-14)
    True
    """
    theta0 = real_array(theta0, "theta0")
    n = _count(n, "n")
    if np.any((theta0 < 0) | (theta0 >= math.pi)):
        raise ValueError("theta0 must be an amplitude in radians with 0 <= theta0 < pi; "
                         f"got {theta0.tolist()!r}")
    odd = 2.0 * np.arange(n) + 1.0
    # Tiny amplitudes underflow on the way (theta0 / 2 when subnormal, the high powers of sqrt(q)
    # always): those b_j are below the smallest double, and 0 is their value to rounding.
    with np.errstate(under="ignore"):
        half = 0.5 * theta0
        # k = sin(theta0/2) and kc = cos(theta0/2) both as computed, each to full precision:
        # recomputing k from kc (which rounds to 1 below theta0 ~ 2e-8) lost every digit of q.
        root = root_nome_from_pair(np.sin(half), np.cos(half))
        # q^(j + 1/2) as a power of sqrt(q): representable even where q itself would underflow.
        power = root[..., None] ** odd
        return 8.0 * power / (odd * (1.0 + power * power))
