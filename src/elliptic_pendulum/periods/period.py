r"""Periods of the simple pendulum: (8), (26), the ratio R of section 4, where R crosses a value.

The small-angle period is (8), :math:`P_\ell = 2\pi/\omega_0`; a libration (regime II) of
amplitude :math:`\theta_0` has the period (26),
:math:`P_{II} = 4 K_1(\sin(\theta_0/2))/\omega_0`, and section 4 of the note tabulates their ratio
:math:`R(\theta_0) = (2/\pi) K_1(\sin(\theta_0/2))`.

Amplitudes are in radians, in :math:`[0, \pi)`. Near :math:`\theta_0 = \pi` the modulus
:math:`\sin(\theta_0/2)` rounds to 1 while :math:`K_1` grows like :math:`\log(4/k_c)`, so every
function here hands the complementary modulus :math:`k_c = \cos(\theta_0/2)` to
:func:`~elliptic_pendulum.elliptic.complete_integral` instead of forming :math:`1 - \sin^2`.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from .._engine import quarter as _quarter
from .._engine.landen import _PI_LO
from .._validation import FloatOrArray, positive_scalar, real_array, scalar_or_array
from ..elliptic import complete_integral

# What the functions return: a Python float for a scalar argument, else an array.

__all__ = ["agm_period", "crossing_angle", "period", "period_ratio", "small_angle_period"]

# pi - np.pi: the part of pi a double cannot hold. Adding it back turns a distance x from the
# true pi into the correctly rounded amplitude pi - x, which matters within 1e-9 degrees of 180.
# Distance to pi of the largest double below it; R there (23.67) is the largest R whose
# crossing angle a double resolves.
_SMALLEST_DISTANCE = math.pi - math.nextafter(math.pi, 0.0) + _PI_LO


def _finite_period(periods: np.ndarray, ratio: np.ndarray, omega0: float) -> np.ndarray:
    """``periods`` (computed with overflow silenced), or a ValueError naming omega0 if one is inf.

    The period 2 pi R / omega0 leaves the doubles for omega0 below 2 pi R / 1.8e308 (about
    3.5e-308 for small swings); an infinite period would be a silent wrong answer there.
    """
    if not np.all(np.isfinite(periods)):
        largest = float(np.max(ratio))
        least = 2 * math.pi * largest / np.finfo(float).max
        raise ValueError(f"omega0 must exceed about {least:.3g} here (for R = {largest:.6g}): "
                         "below that the period 2 pi R / omega0 is larger than the largest "
                         f"double; got {omega0!r}")
    return periods


def _checked(value: npt.ArrayLike, name: str, valid: str) -> np.ndarray:
    """``value`` as a finite float array; a NaN or infinity is reported with the valid range."""
    try:
        return real_array(value, name)
    except ValueError:
        raise ValueError(f"{name} must be {valid}; got {value!r}") from None


def _amplitudes(theta0: npt.ArrayLike) -> np.ndarray:
    valid = "an amplitude in radians with 0 <= theta0 < pi"
    theta0 = _checked(theta0, "theta0", valid)
    # The double np.pi lies 1.2e-16 below pi, but whoever passes it means the inverted pendulum,
    # whose period (regime III) is infinite, so it is refused with pi itself.
    if np.any((theta0 < 0) | (theta0 >= math.pi)):
        raise ValueError(f"theta0 must be {valid}; got {theta0.tolist()!r}")
    return theta0


def period_ratio(theta0: npt.ArrayLike) -> FloatOrArray:
    r"""Ratio R of the period of a swing of amplitude theta0 to the small-angle period.

    .. math:: R(\theta_0) = \frac{K_1(\sin(\theta_0/2))}{K_1(0)}
              = \frac{2}{\pi} K_1\!\left(\sin\frac{\theta_0}{2}\right)

    the quotient of (26) by (8), tabulated in section 4 of the note.

    Parameters
    ----------
    theta0 : float or array_like
        Amplitude in radians, ``0 <= theta0 < pi``.

    Returns
    -------
    float or ndarray
        :math:`R(\theta_0) \ge 1`, of the shape of ``theta0``.

    Raises
    ------
    ValueError
        If an amplitude is negative, not finite, or ``>= pi`` (``np.pi`` too: regime III).

    See Also
    --------
    period : the period (26) itself.
    agm_period : the same period by the arithmetic-geometric mean.
    crossing_angle : the inverse function.

    Notes
    -----
    The complementary modulus :math:`k_c = \cos(\theta_0/2)` is passed to
    :func:`~elliptic_pendulum.elliptic.complete_integral`; it carries the distance to the top
    in full precision, so R is accurate to a few ulp even 1e-9 degrees below 180 degrees.

    Examples
    --------
    The note's table (section 4), to its three decimals:

    >>> import numpy as np
    >>> degrees = [30, 45, 60, 90, 120, 135, 150]
    >>> np.round(period_ratio(np.radians(degrees)), 3).tolist()
    [1.017, 1.04, 1.073, 1.18, 1.373, 1.528, 1.762]

    Small swings keep the period (8), and the series
    :math:`R = 1 + \theta_0^2/16 + 11\theta_0^4/3072 + \dots` (DLMF 19.5.1) fits:

    >>> period_ratio(0.0)
    1.0
    >>> a = 0.01
    >>> abs(period_ratio(a) - (1 + a**2 / 16 + 11 * a**4 / 3072)) < 1e-13
    True

    Near the top R grows like :math:`(2/\pi)\log(8/(\pi - \theta_0))` (DLMF 19.12.1):

    >>> x = 2.0**-30  # np.pi - x is exact, and pi lies 1.2246e-16 above np.pi
    >>> distance = x + 1.2246467991473532e-16
    >>> bool(abs(period_ratio(np.pi - x) - 2 / np.pi * np.log(8 / distance)) < 1e-14)
    True
    """
    amplitudes = _amplitudes(theta0)
    # A subnormal amplitude (1e-320) underflows in theta0/2 and its sine; R - 1 ~ theta0^2/16
    # is far below rounding there, so the underflow is harmless and not worth a warning.
    # Only kc = cos(theta0/2) is needed (libm's cosine keeps its relative digits up to the
    # top), and K straight from the engine's double-precision path (complete_integral's).
    with np.errstate(under="ignore"):
        kc = np.cos(0.5 * amplitudes)
        k_integral = _quarter.complete(kc * kc, kc)
    # Dividing by the double pi/2 (not multiplying by 2/pi) gives R(0) == 1.0 exactly.
    return scalar_or_array(np.asarray(k_integral) / (0.5 * math.pi), amplitudes)


def small_angle_period(omega0: float) -> float:
    r"""Period (8) of the linearised pendulum (5).

    .. math:: P_\ell = \frac{2\pi}{\omega_0} = 2\pi\sqrt{\frac{\ell}{g}}

    Parameters
    ----------
    omega0 : float
        Angular frequency (6), :math:`\omega_0 = \sqrt{g/\ell} > 0`, in rad/s.

    Returns
    -------
    float
        The period in seconds.

    Raises
    ------
    ValueError
        If omega0 is not a finite number > 0, or so small (below about 3.5e-308) that the
        period exceeds the largest double.

    Examples
    --------
    A one-metre pendulum beats close to seconds, which is how the metre was once proposed:

    >>> import math
    >>> round(small_angle_period(math.sqrt(9.80665 / 1.0)), 4)
    2.0064
    """
    omega0 = positive_scalar(omega0, "omega0")
    return float(_finite_period(np.asarray(2 * math.pi / omega0), np.asarray(1.0), omega0))


def period(theta0: npt.ArrayLike, omega0: float = 1.0) -> FloatOrArray:
    r"""Period (26) of a libration (regime II) of amplitude theta0.

    .. math:: P_{II} = \frac{4}{\omega_0} K_1\!\left(\sin\frac{\theta_0}{2}\right)
              = 4 K_1\!\left(\sin\frac{\theta_0}{2}\right)\sqrt{\frac{\ell}{g}}

    Parameters
    ----------
    theta0 : float or array_like
        Amplitude in radians, ``0 <= theta0 < pi``.
    omega0 : float, optional
        Angular frequency (6), positive; default 1.

    Returns
    -------
    float or ndarray
        The period, of the shape of ``theta0``.

    Raises
    ------
    ValueError
        If an amplitude is out of range, or omega0 is not a finite number > 0 or so small
        (below about 3.5e-308 R(theta0)) that the period exceeds the largest double.

    Examples
    --------
    At amplitude 0 it is the period (8); a swing of 90 degrees takes 18% longer:

    >>> import numpy as np
    >>> period(0.0, omega0=2.0) == small_angle_period(2.0)
    True
    >>> round(period(np.pi / 2) / (2 * np.pi), 3)
    1.18
    """
    omega0 = positive_scalar(omega0, "omega0")
    ratio = np.asarray(period_ratio(theta0))
    with np.errstate(over="ignore"):
        periods = ratio * (2 * math.pi / omega0)
    return scalar_or_array(_finite_period(periods, ratio, omega0), ratio)


def _agm(a, b):
    """Arithmetic-geometric mean of arrays ``a >= b > 0``, elementwise."""
    a, b = np.broadcast_arrays(np.asarray(a, float), np.asarray(b, float))
    a, b = a.copy(), b.copy()
    # Quadratic convergence: from b/a = 1e-17 about 8 steps reach full precision. Rounding can
    # make a and b trade the last ulp forever, hence the tolerance and the cap.
    for _ in range(64):
        if np.all(np.abs(a - b) <= 4 * np.finfo(float).eps * a):
            break
        a, b = 0.5 * (a + b), np.sqrt(a * b)
    return 0.5 * (a + b)


def agm_period(theta0: npt.ArrayLike, omega0: float = 1.0) -> FloatOrArray:
    r"""Period (26) by Gauss's arithmetic-geometric mean, an independent check of (26).

    .. math:: P_{II} = \frac{2\pi}{\omega_0\,\mathrm{AGM}(1, \cos(\theta_0/2))}

    since :math:`K_1(k) = \pi / (2\,\mathrm{AGM}(1, k_c))` (DLMF 19.8.5).

    Parameters
    ----------
    theta0 : float or array_like
        Amplitude in radians, ``0 <= theta0 < pi``.
    omega0 : float, optional
        Angular frequency (6), positive; default 1.

    Returns
    -------
    float or ndarray
        The period, of the shape of ``theta0``.

    Notes
    -----
    The AGM is iterated in NumPy on the whole array: :math:`a_{n+1} = (a_n + b_n)/2`,
    :math:`b_{n+1} = \sqrt{a_n b_n}` from :math:`a_0 = 1, b_0 = \cos(\theta_0/2)`. It shares no
    code with :func:`~elliptic_pendulum.elliptic.complete_integral`.

    Raises
    ------
    ValueError
        If an amplitude is out of range, or omega0 is not a finite number > 0 or so small
        (below about 3.5e-308 R(theta0)) that the period exceeds the largest double.

    Examples
    --------
    It agrees with (26) to rounding, also close to the top:

    >>> import numpy as np
    >>> theta0 = np.radians([1, 30, 90, 150, 179.9999])
    >>> bool(np.allclose(agm_period(theta0), period(theta0), rtol=1e-14, atol=0))
    True
    """
    amplitudes = _amplitudes(theta0)
    omega0 = positive_scalar(omega0, "omega0")
    with np.errstate(under="ignore"):  # theta0/2 of a subnormal amplitude: cos is 1 anyway
        mean = _agm(1.0, np.cos(0.5 * amplitudes))
    # Where omega0 * mean underflows (omega0 ~ 1e-308) the period is beyond the doubles anyway
    # (2 pi / 2.2e-308 > 1.8e308): _finite_period reports that instead of a warning and inf.
    with np.errstate(over="ignore", under="ignore"):
        periods = 2 * math.pi / (omega0 * mean)
    return scalar_or_array(_finite_period(periods, 1.0 / mean, omega0), amplitudes)


def _ratio_near_top(x):
    """R at the amplitude pi - x, for a distance 0 < x <= pi from the (true) top."""
    # cos((pi - x)/2) = sin(x/2) keeps every digit of the small complementary modulus.
    return float(complete_integral(math.cos(0.5 * x), kc=math.sin(0.5 * x))) / (0.5 * math.pi)


def _ratio_excess(theta0: float) -> float:
    """R - 1 at the amplitude theta0 in [0, pi), to a few ulp even where R rounds to 1."""
    # R = 1/M, M = AGM(1, cos(theta0/2)), so R - 1 = (1 - M)/M, and 1 - M is the sum of the
    # steps a_n - a_(n+1) = d_n/2, d_n = a_n - b_n, each formed without cancellation:
    # d_0 = 1 - cos(theta0/2) = 2 sin^2(theta0/4), d_(n+1) = (sqrt a_n - sqrt b_n)^2 / 2.
    a, b = 1.0, math.cos(0.5 * theta0)
    d = 2.0 * math.sin(0.25 * theta0) ** 2
    drop = 0.0
    while d > 1e-17 * drop:
        drop += 0.5 * d
        root_a, root_b = math.sqrt(a), math.sqrt(b)
        a, b = 0.5 * (a + b), root_a * root_b
        d = d * d / (2.0 * (root_a + root_b) ** 2)
    return drop / a


def crossing_angle(value: npt.ArrayLike) -> FloatOrArray:
    r"""Find the amplitude at which the period ratio R reaches a given value.

    Solves :math:`R(\theta_0) = \frac{2}{\pi} K_1(\sin(\theta_0/2)) = v` for
    :math:`\theta_0 \in [0, \pi)`; section 4 of the note says R exceeds 2, 3 and 4 near
    160, 176 and 179.2 degrees.

    Parameters
    ----------
    value : float or array_like
        Target ratio(s) :math:`v \ge 1`. R(0) = 1, so ``value == 1`` gives 0.

    Returns
    -------
    float or ndarray
        The amplitude(s) in radians, of the shape of ``value``.

    Raises
    ------
    ValueError
        If a value is below 1, not finite, or so large (above 23.67) that its amplitude
        lies closer to pi than the spacing of doubles there.

    Notes
    -----
    R increases from 1 to infinity on :math:`[0, \pi)`, so there is one root;
    :func:`scipy.optimize.brentq` finds it. From ``value`` 2 on it works in the distance
    :math:`x = \pi - \theta_0` from the top, where :math:`k_c = \sin(x/2)` and the relative
    tolerance apply to x itself, and the amplitude is then rounded from :math:`\pi - x` with
    pi's lost low-order bits added back. Below 2 it solves :math:`R - 1 = v - 1` in
    :math:`\theta_0` itself, R - 1 from the AGM's steps (no difference of nearly equal
    numbers), so an amplitude near 0 keeps its relative accuracy.

    Examples
    --------
    The exact crossing angles, in degrees:

    >>> import numpy as np
    >>> [round(float(d), 9) for d in np.degrees(crossing_angle([2, 3, 4]))]
    [159.753875718, 175.876521811, 179.143956246]

    The note read them off a grid, reporting the first grid angle past the crossing
    (1 degree steps, then 0.1 degree):

    >>> r = period_ratio(np.radians([159, 160, 175, 176, 179.1, 179.2]))
    >>> bool(r[0] < 2 < r[1] and r[2] < 3 < r[3] and r[4] < 4 < r[5])
    True
    """
    from scipy import optimize  # only here: importing the package stays light
    values = _checked(value, "value", "a finite period ratio >= 1")
    largest = _ratio_near_top(_SMALLEST_DISTANCE)
    if np.any((values < 1) | (values > largest)):
        raise ValueError(
            f"value must be a period ratio with 1 <= value <= {largest:.4f} (beyond that the "
            f"amplitude is closer to pi than doubles resolve); got {values.tolist()!r}"
        )
    angles = np.zeros(values.shape)  # R(0) = 1 exactly: value 1 keeps its 0
    for index, target in np.ndenumerate(values):
        if 1.0 < target < 2.0:
            # Near 1, R - v cancels and pi - x keeps only the absolute accuracy of x: solved
            # instead in theta0 for R - 1 = v - 1 (exact), bracketed by R - 1 >= theta0^2/16
            # (positive coefficients), so theta0 <= 4 sqrt(v - 1), and R - 1 at half of theta0
            # is at most a quarter of it; R(2.8) > 2.
            excess = target - 1.0
            high = min(4.0 * (1.0 + 1e-6) * math.sqrt(excess), 2.8)
            angles[index] = optimize.brentq(lambda t, v=excess: _ratio_excess(t) - v,
                                            0.5 * high, high, xtol=1e-300,
                                            rtol=4 * np.finfo(float).eps)
        elif target >= 2.0:
            x = optimize.brentq(lambda x, v=target: _ratio_near_top(x) - v, _SMALLEST_DISTANCE,
                                math.pi, xtol=1e-300, rtol=4 * np.finfo(float).eps)
            angles[index] = (math.pi - x) + _PI_LO
    return scalar_or_array(angles, values)
