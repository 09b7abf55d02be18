r"""Figures of the chapters beyond the note: the period in depth, and rod or string.

The laboratory's approximations of R(θ0) and their errors, the harmonics of a swing, the
flight of a string pendulum's bob and the phase plane shaded by what a string does. The
figures of the driven pendulum are in :mod:`elliptic_pendulum.plotting_resonance`. Like
:mod:`elliptic_pendulum.plotting`, which re-exports them, every helper takes an optional
``ax`` (or ``axes``), returns it, and changes no rcParams.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ._plotbase import new_axes, readable, text_size
from .approximations import ratio_approximations
from .motion import solve
from .period import agm_period, period
from .series import fourier_coefficients
from .string_pendulum import free_flight, string_stays_taut

__all__ = ["approximation_error_plot", "harmonics_plot", "string_flight_plot",
           "string_phase_plane"]

# label -> (colour, line style), in the order of ratio_approximations
_STYLES = {"small angle": ("0.4", "-"), "series 2": ("C0", "-"), "series 4": ("C0", "--"),
           "AGM 1": ("C1", "-"), "AGM 2": ("C1", "--"), "AGM 3": ("C1", ":"),
           "log": ("C2", "-"), "log 2": ("C2", "--"), "Kidd-Fogg": ("C3", "-"),
           "Lima-Arun": ("C4", "-")}


def approximation_error_plot(ax: Any = None, amplitudes: Any = None) -> Any:
    r"""Plot the relative error of the laboratory's approximations of R, on log scales.

    .. math:: \left|\frac{\tilde R(\theta_0)}{R(\theta_0)} - 1\right|, \qquad
              R = \frac{1}{\mathrm{AGM}(1, \cos(\theta_0/2))}

    One curve per entry of :func:`~elliptic_pendulum.approximations.ratio_approximations`,
    against R from :func:`~elliptic_pendulum.period.agm_period` (the AGM to convergence). The
    amplitude axis is a logit scale in θ0/π, which stretches both the small swings and the
    approach to the top; an error of exactly 0 is left out (a log axis cannot show it).

    Parameters
    ----------
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    amplitudes : array_like, optional
        Amplitudes in radians, in (0, π); default 300 from 1 to 170 degrees and 199 closer and
        closer to the top, down to 179.999 degrees.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> import math, mpmath, matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = approximation_error_plot()
    >>> len(ax.lines), ax.lines[0].get_label()
    (10, 'small angle')

    The small-angle curve is 1 - 1/R; at 1 and 179.999 degrees, with R by mpmath:

    >>> x = [math.radians(1), math.radians(179.999)]
    >>> with mpmath.workdps(30):
    ...     R = [2 / mpmath.pi * mpmath.ellipk(mpmath.sin(mpmath.mpf(a) / 2) ** 2) for a in x]
    ...     expected = [float(1 - 1 / r) for r in R]
    >>> drawn = approximation_error_plot(amplitudes=x).lines[0].get_ydata()
    >>> bool(max(abs(drawn / expected - 1)) < 1e-12)
    True
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    if amplitudes is None:
        degrees = np.concatenate([np.linspace(1, 170, 300), 180 - np.geomspace(10, 1e-3, 200)[1:]])
        amplitudes = np.radians(degrees)
    x = np.asarray(amplitudes, dtype=float)
    if x.ndim != 1 or x.size == 0 or np.any((x <= 0) | (x >= math.pi)):
        raise ValueError("amplitudes must be a non-empty 1-d array of radians in (0, pi)")
    ax = new_axes(ax, figsize=(8, 5))
    exact = agm_period(x) / (2 * math.pi)
    for label, values in ratio_approximations(x).items():
        err = np.abs(values / exact - 1)
        color, ls = _STYLES[label]
        ax.plot(x / math.pi, np.where(err > 0, err, np.nan), color=color, ls=ls, label=label)
    ax.set_xscale("logit")
    ticks = [1, 10, 90, 170, 179, 179.9, 179.99, 179.999]
    ax.set_xticks([d / 180 for d in ticks], [f"{d:g}°" for d in ticks])
    ax.xaxis.set_minor_locator(_null_locator())
    ax.set_yscale("log")
    ax.set_ylim(1e-16, 10)
    ax.set_xlabel(r"amplitude $\theta_0$")
    ax.set_ylabel(r"relative error $|\tilde R/R - 1|$")
    ax.legend(ncol=5, loc="upper center", bbox_to_anchor=(0.5, -0.14), frameon=False)
    return readable(ax)


def _null_locator() -> Any:
    from matplotlib.ticker import NullLocator

    return NullLocator()


def _fft_coefficients(theta0: float, n: int, samples: int) -> np.ndarray:
    """b_j of θ(t) from an FFT of the library's motion over one period from the upward passage."""
    T = float(period(theta0))
    F = np.fft.rfft(solve(theta0).theta(np.arange(samples) * T / samples + 0.75 * T))
    return -2 * F.imag[1:2 * n:2] / samples


def harmonics_plot(amplitudes_deg: Sequence[float], n: int = 12, axes: Any = None,
                   samples: int = 1024) -> Any:
    r"""Plot swings flattening into a square wave, and their Fourier coefficients.

    .. math:: \theta(t) = \sum_{j \ge 0} b_j\sin\frac{(2j + 1)\,2\pi t}{T}, \qquad
              b_j = \frac{8\,q^{j + 1/2}}{(2j + 1)(1 + q^{2j + 1})}

    Left: one period of each swing, θ/θ0 against t/T from the upward passage through the
    bottom. Right: :math:`b_j/b_0` against the harmonic 2j + 1 on a log scale, from the formula
    (:func:`~elliptic_pendulum.series.fourier_coefficients`, dots) and from an FFT of the
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

    Returns
    -------
    tuple of matplotlib.axes.Axes

    Examples
    --------
    >>> import math, mpmath, matplotlib
    >>> matplotlib.use("Agg")
    >>> left, right = harmonics_plot([30, 179], n=6)
    >>> dots = [ln for ln in right.lines if ln.get_marker() == "o" and len(ln.get_xdata())]
    >>> len(left.lines), len(dots)
    (2, 2)

    The dot of the third harmonic at 179 degrees is q (1 + q) / (3 (1 + q^3)), q by mpmath:

    >>> q = mpmath.qfrom(m=mpmath.sin(math.radians(179) / 2) ** 2)
    >>> round(float(dots[1].get_ydata()[1] / (q * (1 + q) / (3 * (1 + q**3)))), 12)
    1.0
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    n, samples = int(n), int(samples)
    if not 1 <= n <= samples // 4:
        raise ValueError(f"n must be in [1, samples/4] = [1, {samples // 4}], got {n}")
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
    ax2.plot([], [], "o", color="0.6", label="formula")
    ax2.plot([], [], "x", color="k", label="FFT")
    ax1.set_xlabel(r"$t/T$ from the upward passage")
    ax1.set_ylabel(r"$\theta/\theta_0$")
    ax1.legend(title="amplitude")
    ax2.set_xlabel(r"harmonic $2j + 1$")
    ax2.set_ylabel(r"$b_j / b_0$")
    ax2.set_ylim(1e-16, 2)
    ax2.legend()
    for ax in axes:
        readable(ax)
    return axes


def string_flight_plot(theta0: float, dtheta0: float, omega0: float = 1.0, ax: Any = None,
                       legend: bool = True) -> Any:
    r"""Draw the bob of a string pendulum: on the circle, in free flight, on the circle again.

    .. math:: x = \sin\theta_s + v_x s, \qquad y = -\cos\theta_s + v_y s - \tfrac12 g s^2

    In units of the length, pivot at the origin (+), y up, :math:`g = \omega_0^2`. Blue: the
    circular motion from the initial state until the string goes slack (black dot); red: the
    parabola of :func:`~elliptic_pendulum.string_pendulum.free_flight`; green: half a period
    (or 4 time units if it has none) of the motion on the circle after the jerk, from the
    landing angle with the tangential velocity.

    Parameters
    ----------
    theta0, dtheta0 : float
        The initial state; the string must go slack (0 < e < 3).
    omega0 : float
        ω0 = sqrt(g/ℓ).
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    legend : bool
        Draw the legend.

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    ValueError
        If the string stays taut (no flight to draw).

    Examples
    --------
    >>> import math, matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = string_flight_plot(0.0, 1.8)
    >>> [ln.get_label() for ln in ax.lines[1:5]]
    ['on the circle', 'free flight', 'after the jerk', 'slack']

    The flight leaves the circle at the slack dot, moves uniformly in x, falls with
    y'' = -g (second differences of equally spaced times), and ends on the circle:

    >>> import numpy as np
    >>> fx, fy = ax.lines[2].get_data()
    >>> bool(np.allclose(ax.lines[4].get_xydata()[0], (fx[0], fy[0])))
    True
    >>> bool(np.allclose(np.diff(fx, 2), 0, atol=1e-12)), float(np.ptp(np.diff(fy, 2))) < 1e-12
    (True, True)
    >>> abs(math.hypot(fx[-1], fy[-1]) - 1) < 1e-9
    True
    >>> string_flight_plot(0.0, 1.0)
    Traceback (most recent call last):
    ...
    ValueError: the string stays taut from (theta0, dtheta0) = (0.0, 1.0): there is no flight
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    flight = free_flight(theta0, dtheta0, omega0)
    if flight is None:
        raise ValueError(f"the string stays taut from (theta0, dtheta0) = ({theta0!r}, "
                         f"{dtheta0!r}): there is no flight")
    ax = new_axes(ax, figsize=(4.5, 4.2))
    motion = solve(theta0, dtheta0, omega0)
    ring = np.linspace(0, 2 * np.pi, 400)
    t_on = np.linspace(0.0, flight.t_slack, 200)
    fx, fy = flight.position(np.linspace(flight.t_slack, flight.t_taut, 200))
    after = solve(flight.theta_taut, flight.dtheta_taut, omega0)
    span = 0.5 * after.period if math.isfinite(after.period) else 4.0
    t_after = np.linspace(0.0, span, 200)
    ax.plot(np.sin(ring), np.cos(ring), ":", color="0.6", lw=1)
    ax.plot(np.sin(motion.theta(t_on)), -np.cos(motion.theta(t_on)), color="C0", lw=2,
            label="on the circle")
    ax.plot(fx, fy, color="C3", lw=2, label="free flight")
    ax.plot(np.sin(after.theta(t_after)), -np.cos(after.theta(t_after)), color="C2", lw=2,
            label="after the jerk")
    ax.plot([math.sin(flight.theta_slack)], [-math.cos(flight.theta_slack)], "o", color="k",
            ms=5, label="slack")
    ax.plot([0], [0], "+", color="k", ms=10)
    ax.set_aspect("equal")
    ax.set_xlim(-1.25, 1.25)
    ax.set_ylim(-1.25, 1.25)
    w = float(dtheta0) / float(omega0)
    start = (rf"$\theta(0) = {math.degrees(float(theta0)):g}°$, " if theta0 != 0 else "kick ")
    ax.set_title(start + rf"$\theta'(0) = {w:g}\,\omega_0$")
    if legend:
        ax.legend(loc="upper left", framealpha=0.9)
    return readable(ax)


def string_phase_plane(omega0: float = 1.0, ax: Any = None) -> Any:
    r"""Shade the phase plane by what a string does, with the phase portrait on top.

    .. math:: e = \frac{(\theta')^2}{\omega_0^2} - 2\cos\theta, \qquad
              \frac{T}{m\ell\omega_0^2} = \frac{(\theta')^2}{\omega_0^2} + \cos\theta

    Light: taut forever (:func:`~elliptic_pendulum.string_pendulum.string_stays_taut`,
    e ≤ 0 or e ≥ 3); orange: taut now, slack later; red: slack now (T < 0). The borders
    e = 0 (solid) and e = 3 (dashed) in black, and the curves of constant energy of
    :func:`~elliptic_pendulum.plotting.phase_portrait` (swings of 45, 90, 120 and 150 degrees,
    the separatrix, rotations kicked at 2.1, 2.2 and 2.6 ω0), for θ in [-π, π] and θ' in
    [-3.5 ω0, 3.5 ω0].

    Parameters
    ----------
    omega0 : float
        ω0 = sqrt(g/ℓ).
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> import numpy as np, matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = string_phase_plane()
    >>> kind = ax.collections[0].get_array().reshape(601, 601)

    At rest at the bottom (the grid's centre) the string is taut forever (class 0); at rest
    upside down (θ = π, the right edge) it is slack now (class 2):

    >>> int(kind[300, 300]), int(kind[300, -1])
    (0, 2)
    >>> len(ax.get_legend().get_texts())
    9
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    from matplotlib.colors import ListedColormap
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    from .plotting import phase_portrait

    w0 = float(omega0)
    ax = new_axes(ax, figsize=(9, 5.6))
    gx, gy = np.meshgrid(np.linspace(-math.pi, math.pi, 601),
                         np.linspace(-3.5 * w0, 3.5 * w0, 601))
    taut = string_stays_taut(gx, gy, w0)
    slack_now = gy**2 + w0**2 * np.cos(gx) < 0
    kind = np.where(taut, 0, np.where(slack_now, 2, 1))
    colors = ["#f2f2f2", "#fdd49e", "#f4a582"]
    ax.pcolormesh(gx, gy, kind, cmap=ListedColormap(colors), vmin=-0.5, vmax=2.5,
                  shading="auto", rasterized=True)
    xs = np.linspace(-math.pi, math.pi, 400)
    for level, style in ((0, "-"), (3, "--")):
        inside = level + 2 * np.cos(xs) >= 0
        border = w0 * np.sqrt(np.clip(level + 2 * np.cos(xs), 0, None))
        for sign in (1, -1):
            ax.plot(xs[inside], sign * border[inside], style, color="k", lw=1.2)
    phase_portrait(omega0=w0, ax=ax, window=math.pi, label=False, arrows=False,
                   xlim=(-math.pi, math.pi), ylim=(-3.5 * w0, 3.5 * w0),
                   amplitudes_deg=(45, 90, 120, 150), kicks=(1.05, 1.1, 1.3))
    handles: list[Any] = [Patch(color=c, label=t) for c, t in zip(colors, (
        "taut forever", "taut now, slack later", "slack now (T < 0)"), strict=True)]
    handles += [Line2D([], [], color="k", lw=1.2, label="e = 0"),
                Line2D([], [], color="k", ls="--", lw=1.2, label="e = 3")]
    handles += [Line2D([], [], color=c, lw=1.2, label=t) for c, t in (
        ("C0", "swings"), ("C3", "separatrix"), ("C2", "rotations"))]
    handles.append(Line2D([], [], color="C3", marker="o", ls="none", label="rest"))
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=5,
              frameon=False, fontsize=text_size(ax, 0.9))
    return readable(ax)
