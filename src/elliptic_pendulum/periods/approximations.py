r"""The approximations of the period ratio R(theta0) that a laboratory uses, each as a function.

For the chapter "the period in depth": the exact ratio is
:func:`~elliptic_pendulum.periods.period.period_ratio`, :math:`R = (2/\pi) K_1(\sin(\theta_0/2))
= 1/\mathrm{AGM}(1, \cos(\theta_0/2))`; these are what one uses without elliptic integrals.
Each agrees with R to the order stated, which the tests measure against mpmath:

========================  ====================================================  =================
function                  formula                                               error, small A
========================  ====================================================  =================
series (2 or 4 terms)     :func:`.period_series`                                next term
``agm_ratio(A, n)``       :math:`1/a_n`, n steps of the AGM from (1, cos(A/2))  squares each step
``log_ratio(A, terms)``   :math:`(2/\pi)\log(4/k_c)` (+ the next term)          exact at the top
``kidd_fogg_ratio``       :math:`1/\sqrt{\cos(A/2)}` (Kidd and Fogg, 2002)      :math:`A^4/1024`
``lima_arun_ratio``       :math:`-\log(a)/(1 - a)`, a = cos(A/2) (Lima, Arun)   :math:`A^4/3072`
========================  ====================================================  =================

with :math:`k_c = \cos(A/2)`. :func:`ratio_approximations` gives them all
at once, keyed by a short label. Kidd and Fogg (Phys. Teach. 40, 81 (2002)) and Lima and Arun
(Am. J. Phys. 74, 892 (2006)); the latter quote an error below 0.25%, which is 0.2487% at 90
degrees and grows beyond (1% at 120 degrees).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import numpy.typing as npt

from .._validation import FloatOrArray, real_array, scalar_or_array
from .series import period_series

__all__ = ["agm_ratio", "kidd_fogg_ratio", "lima_arun_ratio", "log_ratio",
           "ratio_approximations"]


def _amplitudes(theta0: Any) -> np.ndarray:
    theta0 = real_array(theta0, "theta0")
    if np.any((theta0 < 0) | (theta0 >= math.pi)):
        raise ValueError("theta0 must be an amplitude in radians with 0 <= theta0 < pi; "
                         f"got {theta0.tolist()!r}")
    return theta0


def agm_ratio(theta0: npt.ArrayLike, steps: int) -> FloatOrArray:
    r"""Approximate R by ``steps`` steps of Gauss's arithmetic-geometric mean.

    .. math:: a_0 = 1,\; b_0 = \cos\frac{\theta_0}{2},\quad
              a_{n+1} = \frac{a_n + b_n}{2},\; b_{n+1} = \sqrt{a_n b_n},\qquad
              R \approx \frac{1}{a_n}

    Parameters
    ----------
    theta0 : float or array_like
        Amplitude in radians, :math:`0 \le \theta_0 < \pi`.
    steps : int
        n >= 0. ``steps=0`` is the small-angle ratio 1; ``steps=1`` gives
        :math:`2/(1 + \cos(\theta_0/2)) = 1 + \theta_0^2/16 + \dots`.

    Returns
    -------
    float or ndarray
        :math:`1/a_n`, of the shape of ``theta0``; it increases with n toward R.

    Notes
    -----
    :math:`a_n - b_n` is squared at every step
    (:math:`a_{n+1} - b_{n+1} = (a_n - b_n)^2 / (2(\sqrt{a_n} + \sqrt{b_n})^2)`), so the number of
    correct digits about doubles per step: the quadratic convergence (DLMF 19.8.1).

    Examples
    --------
    At 90 degrees three steps give R to 1e-10:

    >>> import elliptic_pendulum as ep
    >>> [f"{abs(agm_ratio(math.pi / 2, n) - ep.period_ratio(math.pi / 2)):.0e}" for n in range(4)]
    ['2e-01', '9e-03', '2e-05', '6e-11']
    """
    theta0 = _amplitudes(theta0)
    if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)) or steps < 0:
        raise ValueError(f"steps must be an integer >= 0; got {steps!r}")
    a, b = np.ones_like(theta0), np.cos(0.5 * theta0)
    for _ in range(int(steps)):
        a, b = 0.5 * (a + b), np.sqrt(a * b)
    return scalar_or_array(1.0 / a, theta0)


def log_ratio(theta0: npt.ArrayLike, terms: int = 2) -> FloatOrArray:
    r"""Approximate R near the top by its logarithmic law.

    .. math:: R \approx \frac{2}{\pi}\left[\log\frac{4}{k_c}
              + \frac{k_c^2}{4}\left(\log\frac{4}{k_c} - 1\right)\right], \qquad
              k_c = \cos\frac{\theta_0}{2}

    (DLMF 19.12.1); ``terms=1`` keeps the first term only.

    Parameters
    ----------
    theta0 : float or array_like
        Amplitude in radians, :math:`0 \le \theta_0 < \pi`.
    terms : {1, 2}, optional
        How many terms of the expansion in :math:`k_c`; default 2.

    Returns
    -------
    float or ndarray
        The approximation, of the shape of ``theta0``.

    Notes
    -----
    The error of one term is :math:`O(k_c^2\log k_c)`, of two :math:`O(k_c^4\log k_c)`; with
    :math:`k_c \approx (\pi - \theta_0)/2` near the top. The distance to the top is better
    passed as :math:`\pi - \theta_0` computed exactly; here :math:`k_c` comes from the double
    ``theta0``, so closer than about 1e-9 rad to pi the input's rounding dominates.

    Examples
    --------
    At 179 degrees two terms are good to 1e-8, one to 1e-4:

    >>> import elliptic_pendulum as ep
    >>> a = math.radians(179)
    >>> [bool(abs(log_ratio(a, n) - ep.period_ratio(a)) < tol) for n, tol in [(1, 1e-4),
    ...                                                                    (2, 1e-8)]]
    [True, True]
    """
    theta0 = _amplitudes(theta0)
    if terms not in (1, 2) or isinstance(terms, bool):
        raise ValueError(f"terms must be 1 or 2; got {terms!r}")
    kc = np.cos(0.5 * theta0)
    logarithm = np.log(4.0 / kc)
    k_integral = logarithm if terms == 1 else logarithm + 0.25 * kc * kc * (logarithm - 1.0)
    return scalar_or_array(k_integral / (0.5 * math.pi), theta0)


def kidd_fogg_ratio(theta0: npt.ArrayLike) -> FloatOrArray:
    r"""Kidd and Fogg's approximation of R, a pocket-calculator formula.

    .. math:: R \approx \frac{1}{\sqrt{\cos(\theta_0/2)}}

    Parameters
    ----------
    theta0 : float or array_like
        Amplitude in radians, :math:`0 \le \theta_0 < \pi`.

    Returns
    -------
    float or ndarray
        The approximation, of the shape of ``theta0``.

    Notes
    -----
    Its series is :math:`1 + \theta_0^2/16 + 7\theta_0^4/1536 + \dots` against R's
    :math:`11\theta_0^4/3072`: it runs high by :math:`\theta_0^4/1024` at small amplitude.

    Examples
    --------
    >>> import elliptic_pendulum as ep
    >>> a = 0.05
    >>> round((kidd_fogg_ratio(a) - ep.period_ratio(a)) / (a**4 / 1024), 3)
    1.0
    """
    theta0 = _amplitudes(theta0)
    return scalar_or_array(1.0 / np.sqrt(np.cos(0.5 * theta0)), theta0)


def lima_arun_ratio(theta0: npt.ArrayLike) -> FloatOrArray:
    r"""Lima and Arun's logarithmic approximation of R.

    .. math:: R \approx \frac{-\log a}{1 - a}, \qquad a = \cos\frac{\theta_0}{2}

    Parameters
    ----------
    theta0 : float or array_like
        Amplitude in radians, :math:`0 \le \theta_0 < \pi`.

    Returns
    -------
    float or ndarray
        The approximation, of the shape of ``theta0``; 1 at 0.

    Notes
    -----
    Evaluated as :math:`-\mathrm{log1p}(-x)/x` with :math:`x = 1 - a = 2\sin^2(\theta_0/4)`, free
    of cancellation at small amplitude, and from a itself where :math:`a < 1/2` (beyond 120
    degrees), where :math:`1 - x` would keep only the absolute rounding of x. Its series is
    :math:`1 + \theta_0^2/16 + \theta_0^4/256 + \dots`, high by :math:`\theta_0^4/3072`; near
    the top it grows like :math:`\log(1/k_c)`, above R's :math:`(2/\pi)\log(4/k_c)` by a factor
    tending (slowly) to :math:`\pi/2`.

    Examples
    --------
    >>> import elliptic_pendulum as ep
    >>> round(100 * (lima_arun_ratio(math.pi / 2) / ep.period_ratio(math.pi / 2) - 1), 4)
    0.2487
    """
    theta0 = _amplitudes(theta0)
    x = 2.0 * np.sin(0.25 * theta0) ** 2
    a = np.cos(0.5 * theta0)
    safe = np.where(x > 0, x, 0.5)  # any value that keeps log1p finite where x = 0
    # Near the top a = 1 - x is small and 1 - x keeps only x's absolute rounding (4e-6 of the
    # result at pi - 1e-12): there log(a) takes a itself, which cos gives to full precision.
    near_top = a < 0.5
    logarithm = np.where(near_top, np.log(np.where(near_top, a, 1.0)), np.log1p(-safe))
    return scalar_or_array(np.where(x > 0, -logarithm / np.where(near_top, 1.0 - a, safe), 1.0),
                           theta0)


def ratio_approximations(theta0: npt.ArrayLike) -> dict[str, FloatOrArray]:
    r"""Every approximation of R in this module and the series, keyed by a short label.

    .. math:: R(\theta_0) = \frac{2}{\pi}K_1\!\left(\sin\frac{\theta_0}{2}\right) \approx \dots

    Parameters
    ----------
    theta0 : float or array_like
        Amplitude(s) in radians, :math:`0 \le \theta_0 < \pi`.

    Returns
    -------
    dict of str to float or ndarray
        ``"small angle"``, ``"series 2"``, ``"series 4"``, ``"AGM 1"``, ``"AGM 2"``, ``"AGM 3"``,
        ``"log"``, ``"log 2"``, ``"Kidd-Fogg"``, ``"Lima-Arun"``.

    Examples
    --------
    At 60 degrees all but the logarithmic laws are within 0.5% (the log law is for the top):

    >>> import elliptic_pendulum as ep
    >>> a = math.radians(60)
    >>> errors = {k: abs(v / ep.period_ratio(a) - 1) for k, v in ratio_approximations(a).items()}
    >>> sorted(k for k, e in errors.items() if e > 0.005)
    ['log', 'log 2', 'small angle']
    """
    theta0 = _amplitudes(theta0)
    small = scalar_or_array(np.ones_like(theta0), theta0)
    return {
        "small angle": small,
        "series 2": period_series(theta0, 2),
        "series 4": period_series(theta0, 4),
        **{f"AGM {n}": agm_ratio(theta0, n) for n in (1, 2, 3)},
        "log": log_ratio(theta0, 1),
        "log 2": log_ratio(theta0, 2),
        "Kidd-Fogg": kidd_fogg_ratio(theta0),
        "Lima-Arun": lima_arun_ratio(theta0),
    }
