r"""Figures of the period: its ratio to the small-angle period, its approximations, its harmonics.

The period ratio R(θ0) with its crossings and its logarithmic growth near the top (section
4, :func:`plot_period_ratio`), the errors of the laboratory's approximations of R
(:func:`plot_approximation_error`) and the harmonics of a swing (:func:`plot_harmonics`).
Like every figure of :mod:`elliptic_pendulum.plotting`, which re-exports them, each takes an
optional ``ax`` (or ``axes``), returns it, and changes no rcParams; each writes its words
in ``language`` (None: the environment's; see ``plotting/_words.py``).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

from .._validation import refuse_masked
from ..motion import solve
from ..periods.approximations import ratio_approximations
from ..periods.period import agm_period, crossing_angle, period, period_ratio
from ..periods.series import fourier_coefficients
from ._base import legend_below, new_axes, place_legend, readable, text_size
from ._words import Words, words

__all__ = ["plot_period_ratio", "plot_approximation_error", "plot_harmonics", "period_ratio_plot",
           "approximation_error_plot", "harmonics_plot"]

_axes = new_axes

# label -> (colour, line style), in the order of ratio_approximations
_STYLES = {"small angle": ("0.4", "-"), "series 2": ("C0", "-"), "series 4": ("C0", "--"),
           "AGM 1": ("C1", "-"), "AGM 2": ("C1", "--"), "AGM 3": ("C1", ":"),
           "log": ("C2", "-"), "log 2": ("C2", "--"), "Kidd-Fogg": ("C3", "-"),
           "Lima-Arun": ("C4", "-")}


def _approximation(label: str, say: Words) -> str:
    """Return the legend entry of an approximation; its authors' names stay as they are."""
    return {"small angle": say("small angle"), "series 2": say("series 2"),
            "series 4": say("series 4"), "AGM 1": say("AGM 1"), "AGM 2": say("AGM 2"),
            "AGM 3": say("AGM 3"), "log": say("log"), "log 2": say("log 2")}.get(label, label)


def plot_period_ratio(ax: Any = None, crossings: Sequence[float] = (2.0, 3.0, 4.0), *,
                      language: str | None = None) -> Any:
    r"""Plot R(θ0), the period over the small-angle period, with crossings and asymptote.

    .. math:: R(\theta_0) = \frac{2}{\pi} K_1\!\left(\sin\frac{\theta_0}{2}\right)
              \sim \frac{2}{\pi}\ln\frac{4}{\cos(\theta_0/2)} \quad (\theta_0 \to \pi)

    R grows without bound towards 180°, but only logarithmically: it passes 2, 3 and 4
    (section 4 of the note) at the amplitudes :func:`.crossing_angle`
    returns, marked on the curve.

    Parameters
    ----------
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    crossings : list of float
        The values of R whose amplitudes are marked (each >= 1).
    language : str, optional
        The language of the figure's words ("en", "ja"); None: the environment's.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = plot_period_ratio()
    >>> x, y = ax.lines[-1].get_data()   # the crossings, in degrees, at R = 2, 3, 4
    >>> [round(float(v), 1) for v in x], [float(v) for v in y]
    ([159.8, 175.9, 179.1], [2.0, 3.0, 4.0])
    >>> import numpy as np                # the marks lie on the curve R(theta0)
    >>> bool(np.allclose(period_ratio(np.radians(x)), y, rtol=1e-12))
    True
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    say = words(language)
    ax = _axes(ax)
    # Dense towards 180 degrees, where R grows: equal steps in log(pi - theta0).
    gap = np.geomspace(math.pi, 1e-4, 600)
    theta0 = np.concatenate([np.linspace(0.0, math.pi / 2, 100, endpoint=False),
                             math.pi - gap[gap < math.pi / 2]])
    deg = np.degrees(theta0)
    ax.plot(deg, period_ratio(theta0), color="C0", lw=2, label=r"$R(\theta_0)$")
    near = theta0 > math.pi / 3  # the asymptote means nothing near theta0 = 0
    ax.plot(deg[near], 2 / math.pi * np.log(4 / np.cos(theta0[near] / 2)), "--", color="C3",
            label=r"$(2/\pi)\,\ln(4/\cos(\theta_0/2))$")
    refuse_masked(crossings, "crossings")
    values = np.asarray(crossings, dtype=float)
    angles = np.degrees(crossing_angle(values))
    for v, a in zip(values, angles, strict=True):
        ax.plot([0, a, a], [v, v, 0], ":", color="0.5", lw=1)
        # Left of the crossing, above its line, where the curve is still below that value.
        ax.annotate(say(r"$R = {value}$ at $\theta_0 = {angle}°$", value=f"{v:g}",
                        angle=f"{a:.1f}"), (a - 3, v), ha="right",
                    va="bottom", fontsize=text_size(ax, 0.9))
    ax.plot(angles, values, "o", color="C1", label=say("crossings"))
    ax.set_xlim(0, 180)
    ax.set_ylim(0, max(5.0, float(values.max()) + 1))
    ax.set_xticks(range(0, 181, 30))
    ax.set_xlabel(say(r"amplitude $\theta_0$ (degrees)"))
    ax.set_ylabel(r"$R = T / T_0$")
    say.dress(ax)
    place_legend(ax, loc="upper left", font=say.font)
    return readable(ax)


def plot_approximation_error(ax: Any = None, amplitudes: npt.ArrayLike | None = None, *,
                             language: str | None = None) -> Any:
    r"""Plot the relative error of the laboratory's approximations of R, on log scales.

    .. math:: \left|\frac{\tilde R(\theta_0)}{R(\theta_0)} - 1\right|, \qquad
              R = \frac{1}{\mathrm{AGM}(1, \cos(\theta_0/2))}

    One curve per entry of :func:`~elliptic_pendulum.periods.approximations.ratio_approximations`,
    against R from :func:`.agm_period` (the AGM to convergence). The
    amplitude axis is a logit scale in θ0/π, which stretches both the small swings and the
    approach to the top; an error of exactly 0 is left out (a log axis cannot show it).

    Parameters
    ----------
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    amplitudes : array_like, optional
        Amplitudes in radians, in (0, π); default 300 from 1 to 170 degrees and 199 closer and
        closer to the top, down to 179.999 degrees.
    language : str, optional
        The language of the figure's words ("en", "ja"); None: the environment's.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> import math, mpmath, matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = plot_approximation_error()
    >>> len(ax.lines), ax.lines[0].get_label()
    (10, 'small angle')

    The small-angle curve is 1 - 1/R; at 1 and 179.999 degrees, with R by mpmath:

    >>> x = [math.radians(1), math.radians(179.999)]
    >>> with mpmath.workdps(30):
    ...     R = [2 / mpmath.pi * mpmath.ellipk(mpmath.sin(mpmath.mpf(a) / 2) ** 2) for a in x]
    ...     expected = [float(1 - 1 / r) for r in R]
    >>> drawn = plot_approximation_error(amplitudes=x).lines[0].get_ydata()
    >>> bool(max(abs(drawn / expected - 1)) < 1e-12)
    True
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    from matplotlib.ticker import NullLocator

    if amplitudes is None:
        degrees = np.concatenate([np.linspace(1, 170, 300), 180 - np.geomspace(10, 1e-3, 200)[1:]])
        amplitudes = np.radians(degrees)
    refuse_masked(amplitudes, "amplitudes")
    x = np.asarray(amplitudes, dtype=float)
    if x.ndim != 1 or x.size == 0 or np.any((x <= 0) | (x >= math.pi)):
        raise ValueError("amplitudes must be a non-empty 1-d array of radians in (0, pi)")
    say = words(language)
    ax = new_axes(ax, figsize=(8, 5))
    exact = agm_period(x) / (2 * math.pi)
    for label, values in ratio_approximations(x).items():
        err = np.abs(values / exact - 1)
        color, ls = _STYLES[label]
        ax.plot(x / math.pi, np.where(err > 0, err, np.nan), color=color, ls=ls,
                label=_approximation(label, say))
    ax.set_xscale("logit")
    ticks = [1, 10, 90, 170, 179, 179.9, 179.999]  # 179.99 would run into its neighbours
    ax.set_xticks([d / 180 for d in ticks], [f"{d:g}°" for d in ticks])
    ax.xaxis.set_minor_locator(NullLocator())
    ax.set_yscale("log")
    ax.set_ylim(1e-16, 10)
    ax.set_xlabel(say(r"amplitude $\theta_0$"))
    ax.set_ylabel(say(r"relative error $|\tilde R/R - 1|$"))
    say.dress(ax)
    readable(ax)
    legend_below(ax, ncol=5, frameon=False, font=say.font)
    return ax


def _fft_coefficients(theta0: float, n: int, samples: int) -> np.ndarray:
    """b_j of θ(t) from an FFT of the library's motion over one period from the upward passage."""
    T = float(period(theta0))
    F = np.fft.rfft(solve(theta0).theta(np.arange(samples) * T / samples + 0.75 * T))
    return -2 * F.imag[1:2 * n:2] / samples


def plot_harmonics(amplitudes_deg: Sequence[float], n: int = 12, axes: Any = None,
                   samples: int = 1024, *, language: str | None = None) -> Any:
    r"""Plot swings flattening into a square wave, and their Fourier coefficients.

    .. math:: \theta(t) = \sum_{j \ge 0} b_j\sin\frac{(2j + 1)\,2\pi t}{T}, \qquad
              b_j = \frac{8\,q^{j + 1/2}}{(2j + 1)(1 + q^{2j + 1})}

    Left: one period of each swing, θ/θ0 against t/T from the upward passage through the
    bottom. Right: :math:`b_j/b_0` against the harmonic 2j + 1 on a log scale, from the formula
    (:func:`~elliptic_pendulum.periods.series.fourier_coefficients`, dots) and from an FFT of the
    motion :func:`~elliptic_pendulum.motion.solve` sampled at ``samples`` times (black crosses,
    those above 1e-16), with the square wave's 1/(2j + 1) (dashed).

    Parameters
    ----------
    amplitudes_deg : list of float
        Amplitudes in degrees, in (0, 180).
    n : int
        Number of coefficients, at most samples / 4.
    axes : tuple of matplotlib.axes.Axes, optional
        Where to draw; a new figure with two panels when None.
    samples : int
        FFT length.
    language : str, optional
        The language of the figure's words ("en", "ja"); None: the environment's.

    Returns
    -------
    tuple of matplotlib.axes.Axes

    Examples
    --------
    >>> import math, mpmath, matplotlib
    >>> matplotlib.use("Agg")
    >>> left, right = plot_harmonics([30, 179], n=6)
    >>> dots = [ln for ln in right.lines if ln.get_marker() == "o" and len(ln.get_xdata())]
    >>> len(left.lines), len(dots)
    (2, 2)

    The dot of the third harmonic at 179 degrees is q (1 + q) / (3 (1 + q^3)), q by mpmath:

    >>> q = mpmath.qfrom(m=mpmath.sin(math.radians(179) / 2) ** 2)
    >>> round(float(dots[1].get_ydata()[1] / (q * (1 + q) / (3 * (1 + q**3)))), 12)
    1.0
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    say = words(language)
    n, samples = int(n), int(samples)
    if not 1 <= n <= samples // 4:
        raise ValueError(f"n must be in [1, samples/4] = [1, {samples // 4}], got {n}")
    refuse_masked(amplitudes_deg, "amplitudes_deg")
    degrees = [float(d) for d in amplitudes_deg]
    if not degrees or any(not 0 < d < 180 for d in degrees):
        raise ValueError(f"amplitudes_deg must be degrees in (0, 180), got {amplitudes_deg!r}")
    if axes is None:
        import matplotlib.pyplot as plt

        _, axes = plt.subplots(1, 2, figsize=(9, 4), layout="constrained")
    ax1, ax2 = axes
    s = np.linspace(0, 1, 801)
    harm = 2 * np.arange(n) + 1
    for i, d in enumerate(degrees):
        x = math.radians(d)
        T = float(period(x))
        ax1.plot(s, solve(x).theta(s * T + 0.75 * T) / x, color=f"C{i}", label=f"{d:g}°")
        b = fourier_coefficients(x, n)
        ax2.semilogy(harm, b / b[0], "o", color=f"C{i}", ms=5)
        b_fft = _fft_coefficients(x, n, samples)
        keep = b_fft / b_fft[0] > 1e-16
        ax2.semilogy(harm[keep], (b_fft / b_fft[0])[keep], "x", color="k", ms=4)
    ax2.semilogy(harm, 1 / harm, "--", color="0.4", label=r"$1/(2j+1)$")
    ax2.plot([], [], "o", color="0.6", label=say("formula"))
    ax2.plot([], [], "x", color="k", label="FFT")
    ax1.set_xlabel(say(r"$t/T$ from the upward passage"))
    ax1.set_ylabel(r"$\theta/\theta_0$")
    ax2.set_xlabel(say(r"harmonic $2j + 1$"))
    ax2.set_ylabel(r"$b_j / b_0$")
    ax2.set_ylim(1e-16, 2)
    say.dress(*axes)
    for ax in axes:
        readable(ax)
    # Once both panels are drawn, the right one first: a legend beside it narrows the left one.
    place_legend(ax2, font=say.font)
    place_legend(ax1, title=say("amplitude"), font=say.font)
    return axes


# The names of earlier releases.
period_ratio_plot = plot_period_ratio
approximation_error_plot = plot_approximation_error
harmonics_plot = plot_harmonics
