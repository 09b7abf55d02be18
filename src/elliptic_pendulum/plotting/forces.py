r"""Figures of the forces: the rod's tension, the string's slack and the bob's free flight.

The rod's tension along a swing and where the rod pushes, (4) (:func:`plot_tension`); a
string pendulum's bob on its circle, in free flight after the string goes slack, and on the
circle again after the jerk (:func:`plot_string_flight`); the phase plane shaded by what a
string does (:func:`plot_string_phase_plane`). Like every figure of
:mod:`elliptic_pendulum.plotting`, which re-exports them, each takes an optional ``ax``,
returns it, and changes no rcParams; each writes its words in ``language`` (None: the
environment's; see ``plotting/_words.py``).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..mechanics.rod import Pendulum
from ..mechanics.string import free_flight, string_stays_taut
from ..motion import solve
from ._base import legend_below, new_axes, place_legend, readable
from ._words import words
from .phase import plot_phase_portrait

__all__ = ["plot_tension", "plot_string_flight", "plot_string_phase_plane", "tension_plot",
           "string_flight_plot", "string_phase_plane"]

_axes = new_axes


def plot_tension(theta0: float, omega0: float = 1.0, ax: Any = None, *,
                 language: str | None = None) -> Any:
    r"""Plot the rod's tension T/(mg) along one period of a swing released at rest from θ0.

    .. math:: T &= m\ell(\theta')^2 + mg\cos\theta \quad (4), \\
              \frac{T}{mg} &= 3\cos\theta - 2\cos\theta_0 \text{ (released at rest)}

    Where T < 0 (shaded) the rod pushes the bob outwards: above 90° near the turning points.
    A string would go slack there. The tension is that of
    :meth:`~elliptic_pendulum.mechanics.rod.Pendulum.tension`, for ℓ = 1 and g = ω0².

    Parameters
    ----------
    theta0 : float
        Amplitude in radians, 0 < theta0 < π.
    omega0 : float
        ω0 = sqrt(g/ℓ); time on the axis is in units of the period.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    language : str, optional
        The language of the figure's words ("en", "ja"); None: the environment's.

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    ValueError
        If theta0 is not in (0, π).

    Examples
    --------
    >>> import math, matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = plot_tension(math.radians(120))
    >>> t = ax.lines[0].get_ydata()      # T/(mg) from 3 cos 120° - 2 cos 120° to 3 + 1
    >>> round(float(t.min()), 6), round(float(t.max()), 6)
    (-0.5, 4.0)
    >>> len(ax.collections)              # two shaded intervals where the rod pushes
    1
    >>> len(plot_tension(math.radians(60)).collections)   # below 90 degrees it never pushes
    0
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    try:
        theta0 = float(theta0)
    except (TypeError, ValueError):
        raise TypeError(f"theta0 must be a real number (radians), got {theta0!r}") from None
    if not 0.0 < theta0 < math.pi:
        raise ValueError(f"theta0 must be in (0, pi) (a swing released at rest), got {theta0!r}")
    say = words(language)
    ax = _axes(ax)
    pendulum = Pendulum(length=1.0, g=float(omega0) ** 2, mass=1.0)
    swing = pendulum.solve(theta0)
    t = np.linspace(0.0, swing.period, 1201)
    ratio = pendulum.tension(swing, t) / (pendulum.mass * pendulum.g)
    ax.plot(t / swing.period, ratio, color="C0", lw=2, label=r"$T/(mg)$")
    ax.axhline(0.0, color="0.3", lw=0.8)
    pushes = ratio < 0
    if pushes.any():
        ax.fill_between(t / swing.period, ratio, 0.0, where=pushes, color="C3", alpha=0.3,
                        label=say(r"$T < 0$: the rod pushes"))
    ax.set_xlim(0, 1)
    low, high = float(ratio.min()), float(ratio.max())
    # Headroom above the curve for the legend.
    ax.set_ylim(min(low, 0.0) - 0.1 * (high - low), high + 0.4 * (high - low))
    ax.set_xlabel(say(r"time $t$ / period (released at $t = 0$ from $\theta_0$)"))
    ax.set_ylabel(r"$T/(mg)$")
    ax.set_title(rf"$\theta_0 = {math.degrees(theta0):.0f}°$")
    say.dress(ax)
    place_legend(ax, loc="upper center", ncol=2, font=say.font)
    return readable(ax)


def plot_string_flight(theta0: float, dtheta0: float, omega0: float = 1.0, ax: Any = None,
                       legend: bool = True, *, language: str | None = None) -> Any:
    r"""Draw the bob of a string pendulum: on the circle, in free flight, on the circle again.

    .. math:: x = \sin\theta_s + v_x s, \qquad y = -\cos\theta_s + v_y s - \tfrac12 g s^2

    In units of the length, pivot at the origin (+), y up, :math:`g = \omega_0^2`. Blue: the
    circular motion from the initial state until the string goes slack (black dot); red: the
    parabola of :func:`~elliptic_pendulum.mechanics.string.free_flight`; green: half a period
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
    language : str, optional
        The language of the figure's words ("en", "ja"); None: the environment's.

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
    >>> ax = plot_string_flight(0.0, 1.8)
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
    >>> plot_string_flight(0.0, 1.0)
    Traceback (most recent call last):
    ...
    ValueError: the string stays taut from (theta0, dtheta0) = (0.0, 1.0): there is no flight
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    flight = free_flight(theta0, dtheta0, omega0)
    if flight is None:
        raise ValueError(f"the string stays taut from (theta0, dtheta0) = ({theta0!r}, "
                         f"{dtheta0!r}): there is no flight")
    say = words(language)
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
            label=say("on the circle"))
    ax.plot(fx, fy, color="C3", lw=2, label=say("free flight"))
    ax.plot(np.sin(after.theta(t_after)), -np.cos(after.theta(t_after)), color="C2", lw=2,
            label=say("after the jerk"))
    ax.plot([math.sin(flight.theta_slack)], [-math.cos(flight.theta_slack)], "o", color="k",
            ms=5, label=say("slack"))
    ax.plot([0], [0], "+", color="k", ms=10)
    ax.set_aspect("equal")
    ax.set_xlim(-1.25, 1.25)
    ax.set_ylim(-1.25, 1.25)
    w = float(dtheta0) / float(omega0)
    if theta0 != 0:
        title = say(r"$\theta(0) = {angle}°$, $\theta'(0) = {speed}\,\omega_0$",
                    angle=f"{math.degrees(float(theta0)):g}", speed=f"{w:g}")
    else:
        title = say(r"kick $\theta'(0) = {speed}\,\omega_0$", speed=f"{w:g}")
    ax.set_title(title)
    say.dress(ax)
    if legend:
        place_legend(ax, loc="upper left", framealpha=0.9, font=say.font)
    return readable(ax)


def plot_string_phase_plane(omega0: float = 1.0, ax: Any = None, *,
                            language: str | None = None) -> Any:
    r"""Shade the phase plane by what a string does, with the phase portrait on top.

    .. math:: e = \frac{(\theta')^2}{\omega_0^2} - 2\cos\theta, \qquad
              \frac{T}{m\ell\omega_0^2} = \frac{(\theta')^2}{\omega_0^2} + \cos\theta

    Light: taut forever (:func:`~elliptic_pendulum.mechanics.string.string_stays_taut`,
    e ≤ 0 or e ≥ 3); orange: taut now, slack later; red: slack now (T < 0). The borders
    e = 0 (solid) and e = 3 (dashed) in black, and the curves of constant energy of
    :func:`.plot_phase_portrait` (swings of 45, 90, 120 and 150 degrees,
    the separatrix, rotations kicked at 2.1, 2.2 and 2.6 ω0), for θ in [-π, π] and θ' in
    [-3.5 ω0, 3.5 ω0].

    Parameters
    ----------
    omega0 : float
        ω0 = sqrt(g/ℓ).
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    language : str, optional
        The language of the figure's words ("en", "ja"); None: the environment's.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> import numpy as np, matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = plot_string_phase_plane()
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


    w0 = float(omega0)
    say = words(language)
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
    plot_phase_portrait(omega0=w0, ax=ax, window=math.pi, label=False, arrows=False,
                   xlim=(-math.pi, math.pi), ylim=(-3.5 * w0, 3.5 * w0),
                   amplitudes_deg=(45, 90, 120, 150), kicks=(1.05, 1.1, 1.3),
                   language=language)
    handles: list[Any] = [Patch(color=c, label=t) for c, t in zip(colors, (
        say("taut forever"), say("taut now, slack later"), say("slack now (T < 0)")),
        strict=True)]
    handles += [Line2D([], [], color="k", lw=1.2, label="e = 0"),
                Line2D([], [], color="k", ls="--", lw=1.2, label="e = 3")]
    handles += [Line2D([], [], color=c, lw=1.2, label=t) for c, t in (
        ("C0", say("swings")), ("C3", say("separatrix")), ("C2", say("rotations")))]
    handles.append(Line2D([], [], color="C3", marker="o", ls="none", label=say("rest")))
    readable(ax)
    legend_below(ax, handles=handles, ncol=5, frameon=False, font=say.font)
    return ax


# The names of earlier releases.
tension_plot = plot_tension
string_flight_plot = plot_string_flight
string_phase_plane = plot_string_phase_plane
