r"""Figures of the elliptic functions, and the ones a teacher asks for beyond the note.

The functions of sections 3 and 5 (sn, cn, dn, E1, G, am) and three figures the note argues
in words: the period ratio R(θ0) with its crossings and its logarithmic growth near the top
(section 4), the rod's tension along a swing and where the rod pushes (4), and Lemma 2's
extensions (20) and (21). Like :mod:`elliptic_pendulum.plotting`, which re-exports them,
every helper takes an optional ``ax``, returns it, and changes no rcParams.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from ._plotbase import new_axes, readable, text_size
from .elliptic import am, complete_integral, incomplete_integral, inverse_integral, jacobi
from .extension import periodic_extension, staircase_extension
from .mechanics import Pendulum
from .period import crossing_angle, period_ratio

__all__ = ["plot_jacobi", "plot_integral", "plot_inverse", "plot_amplitude",
           "period_ratio_plot", "tension_plot", "extension_plot"]

_axes = new_axes


def plot_jacobi(k: float, u: Any, ax: Any = None, kc: float | None = None) -> Any:
    """Plot sn, cn and dn over the given u (several periods), modulus k (or kc)."""
    ax = _axes(ax)
    u = np.asarray(u, dtype=float)
    for name, values in zip(("sn", "cn", "dn"), jacobi(u, k, kc=kc), strict=True):
        ax.plot(u, values, label=rf"$\mathrm{{{name}}}(u, {k:g})$")
    K = complete_integral(k, kc=kc)
    for j in range(int(u.min() // K), int(u.max() // K) + 1):
        ax.axvline(j * K, color="0.85", lw=0.8, zorder=0)
    ax.set_xlabel("$u$ (grey lines: multiples of $K_1$)")
    ax.legend()
    return readable(ax)


def plot_integral(moduli: Sequence[float] = (0.5, 0.9, 0.99), ax: Any = None) -> Any:
    """Plot E1(z, k) of (17) on [-1, 1] beside arcsin z = E1(z, 0) (Proposition 1)."""
    ax = _axes(ax)
    z = np.linspace(-1, 1, 401)
    ax.plot(z, np.arcsin(z), "k--", label=r"$\arcsin z$")
    for k in moduli:
        ax.plot(z, incomplete_integral(z, k), label=rf"$E_1(z, {k:g})$")
    ax.set_xlabel("$z$")
    ax.legend()
    return readable(ax)


def plot_inverse(moduli: Sequence[float] = (0.5, 0.9, 0.99), ax: Any = None) -> Any:
    """Plot G(u, k) of (19) on [-K1, K1] beside sin u on [-π/2, π/2]."""
    ax = _axes(ax)
    u = np.linspace(-math.pi / 2, math.pi / 2, 201)
    ax.plot(u, np.sin(u), "k--", label=r"$\sin u$")
    for k in moduli:
        K = complete_integral(k)
        u = np.linspace(-K, K, 401)
        ax.plot(u, inverse_integral(u, k), label=rf"$G(u, {k:g})$")
    ax.set_xlabel("$u$")
    ax.legend()
    return readable(ax)


def plot_amplitude(k: float, u: Any, ax: Any = None) -> Any:
    r"""Plot am(u, k) = Î of (41) with its linear part and its periodic remainder.

    The linear part is τu with τ = π/(2K1) (45); the remainder am(u) - τu has period 2K1.
    """
    ax = _axes(ax)
    u = np.asarray(u, dtype=float)
    tau = math.pi / (2 * complete_integral(k))
    a = am(u, k)
    ax.plot(u, a, label=rf"$\hat I(u, {k:g}) = \mathrm{{am}}$")
    ax.plot(u, tau * u, "--", label=r"$\tau u$")
    ax.plot(u, a - tau * u, label=r"$\hat I - \tau u$ (periodic)")
    ax.set_xlabel("$u$")
    ax.legend()
    return readable(ax)


def period_ratio_plot(ax: Any = None, crossings: Sequence[float] = (2.0, 3.0, 4.0)) -> Any:
    r"""Plot R(θ0), the period over the small-angle period, with crossings and asymptote.

    .. math:: R(\theta_0) = \frac{2}{\pi} K_1\!\left(\sin\frac{\theta_0}{2}\right)
              \sim \frac{2}{\pi}\ln\frac{4}{\cos(\theta_0/2)} \quad (\theta_0 \to \pi)

    R grows without bound towards 180°, but only logarithmically: it passes 2, 3 and 4
    (section 4 of the note) at the amplitudes :func:`~elliptic_pendulum.period.crossing_angle`
    returns, marked on the curve.

    Parameters
    ----------
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    crossings : list of float
        The values of R whose amplitudes are marked (each >= 1).

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = period_ratio_plot()
    >>> x, y = ax.lines[-1].get_data()   # the crossings, in degrees, at R = 2, 3, 4
    >>> [round(float(v), 1) for v in x], [float(v) for v in y]
    ([159.8, 175.9, 179.1], [2.0, 3.0, 4.0])
    >>> import numpy as np                # the marks lie on the curve R(theta0)
    >>> bool(np.allclose(period_ratio(np.radians(x)), y, rtol=1e-12))
    True
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
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
    values = np.asarray(crossings, dtype=float)
    angles = np.degrees(crossing_angle(values))
    for v, a in zip(values, angles, strict=True):
        ax.plot([0, a, a], [v, v, 0], ":", color="0.5", lw=1)
        # Left of the crossing, above its line, where the curve is still below that value.
        ax.annotate(rf"$R = {v:g}$ at $\theta_0 = {a:.1f}°$", (a - 3, v), ha="right",
                    va="bottom", fontsize=text_size(ax, 0.85))
    ax.plot(angles, values, "o", color="C1", label="crossings")
    ax.set_xlim(0, 180)
    ax.set_ylim(0, max(5.0, float(values.max()) + 1))
    ax.set_xticks(range(0, 181, 30))
    ax.set_xlabel(r"amplitude $\theta_0$ (degrees)")
    ax.set_ylabel(r"$R = T / T_0$")
    ax.legend(loc="upper left")
    return readable(ax)


def tension_plot(theta0: float, omega0: float = 1.0, ax: Any = None) -> Any:
    r"""Plot the rod's tension T/(mg) along one period of a swing released at rest from θ0.

    .. math:: T = m\ell(\theta')^2 + mg\cos\theta \quad (4), \qquad
              \frac{T}{mg} = 3\cos\theta - 2\cos\theta_0 \text{ (released at rest)}

    Where T < 0 (shaded) the rod pushes the bob outwards: above 90° near the turning points.
    A string would go slack there. The tension is that of
    :meth:`~elliptic_pendulum.mechanics.Pendulum.tension`, for ℓ = 1 and g = ω0².

    Parameters
    ----------
    theta0 : float
        Amplitude in radians, 0 < theta0 < π.
    omega0 : float
        ω0 = sqrt(g/ℓ); time on the axis is in units of the period.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.

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
    >>> ax = tension_plot(math.radians(120))
    >>> t = ax.lines[0].get_ydata()      # T/(mg) from 3 cos 120° - 2 cos 120° to 3 + 1
    >>> round(float(t.min()), 6), round(float(t.max()), 6)
    (-0.5, 4.0)
    >>> len(ax.collections)              # two shaded intervals where the rod pushes
    1
    >>> len(tension_plot(math.radians(60)).collections)   # below 90 degrees it never pushes
    0
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    try:
        theta0 = float(theta0)
    except (TypeError, ValueError):
        raise TypeError(f"theta0 must be a real number (radians), got {theta0!r}") from None
    if not 0.0 < theta0 < math.pi:
        raise ValueError(f"theta0 must be in (0, pi) (a swing released at rest), got {theta0!r}")
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
                        label=r"$T < 0$: the rod pushes")
    ax.set_xlim(0, 1)
    low, high = float(ratio.min()), float(ratio.max())
    # Headroom above the curve for the legend.
    ax.set_ylim(min(low, 0.0) - 0.1 * (high - low), high + 0.4 * (high - low))
    ax.set_xlabel(r"time $t$ / period (released at $t = 0$ from $\theta_0$)")
    ax.set_ylabel(r"$T/(mg)$")
    ax.set_title(rf"$\theta_0 = {math.degrees(theta0):.0f}°$")
    ax.legend(loc="upper center", ncol=2)
    return readable(ax)


def extension_plot(f: Callable, a: float, kind: str = "odd", ax: Any = None,
                   periods: float = 2.0) -> Any:
    r"""Plot an odd f on [-a, a] and its extension (20) or (21) of Lemma 2.

    .. math:: \bar f(x + 2a) = -\bar f(x) \quad (20), \qquad
              \hat f(x + 2a) = \hat f(x) + 2f(a) \quad (21)

    The joints x = ±a, ±3a, ... are marked: there the extension is smooth only under the
    lemma's hypothesis (f'(a) = 0 for (20), f''(a) = 0 for (21)); otherwise a corner or a jump
    of curvature shows. sin on [-π/2, π/2] extends to sin; on [-1, 1] it gets corners.

    Parameters
    ----------
    f : callable
        Vectorized odd function on [-a, a].
    a : float
        Half-width a > 0.
    kind : {"odd", "staircase"}
        (20), from :func:`~elliptic_pendulum.extension.periodic_extension`, or (21), from
        :func:`~elliptic_pendulum.extension.staircase_extension`.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    periods : float
        How many periods 4a of (20) (steps of width 4a of (21)) to show, centred at 0.

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    ValueError
        If kind is not "odd" or "staircase", or a is not finite and > 0.
    TypeError
        If f is not callable.

    Examples
    --------
    >>> import numpy as np, matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = extension_plot(np.sin, 1.0)          # the cornered sine
    >>> x, y = ax.lines[0].get_data()            # the extension, over [-4, 4]
    >>> mid = (x > 1) & (x < 3)                  # (20): -f(x - 2a) on [a, 3a]
    >>> float(x.min()), float(x.max()), bool(np.allclose(y[mid], -np.sin(x[mid] - 2)))
    (-4.0, 4.0, True)
    >>> ax = extension_plot(np.arctan, 1.0, kind="staircase")
    >>> round(float(ax.lines[0].get_ydata().max()), 12) == round(float(np.arctan(1) * 4), 12)
    True
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    if kind not in ("odd", "staircase"):
        raise ValueError(f'kind must be "odd" (20) or "staircase" (21), got {kind!r}')
    extend = periodic_extension if kind == "odd" else staircase_extension
    g = extend(f, a)  # validates f and a
    a = float(a)
    ax = _axes(ax)
    x = np.linspace(-2 * periods * a, 2 * periods * a, 1601)
    equation = "(20)" if kind == "odd" else "(21)"
    ax.plot(x, g(x), color="C0", lw=1.5, label=f"the extension {equation}")
    inside = np.linspace(-a, a, 401)
    ax.plot(inside, np.asarray(f(inside), dtype=float), color="C1", lw=3.5, alpha=0.8,
            label=r"$f$ on $[-a, a]$")
    joints = np.arange(-2 * periods + 1, 2 * periods, 2) * a
    for j in joints:
        ax.axvline(j, color="0.8", lw=0.8, zorder=0)
    ax.plot(joints, g(joints), "o", color="C3", ms=5, label=r"joints $x = \pm a, \pm 3a, \ldots$")
    ax.set_xlim(x[0], x[-1])
    ax.set_xlabel("$x$")
    # Below the axes: any corner inside may cover the extension.
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.15), ncol=2, frameon=False)
    return readable(ax)
