r"""Figures of the pendulum itself: its sketch, its phase portrait, its motion in time.

Fig. 1 of the note (:func:`plot_pendulum`), the phase portrait of (9) (Fig. 2,
:func:`plot_phase_portrait`), and theta(t) beside a numerical integration (:func:`plot_motion`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

from .._validation import refuse_masked
from ..motion import Motion, solve
from ..numerics import integrate
from ._arrows import arrowheads_in_view, visible
from ._base import layout, legend_below, new_axes, place_legend, readable, text_size
from ._words import words

__all__ = ["plot_pendulum", "plot_phase_portrait", "plot_motion", "pendulum_sketch",
           "phase_portrait"]

_axes = new_axes


def plot_pendulum(theta: float = 0.55, ax: Any = None, *, language: str | None = None) -> Any:
    """Draw Fig. 1: the pendulum with its angle, tension and weight.

    The rod of length l hangs from the origin, the bob sits at (l sin θ, -l cos θ) (1),
    the tension T points along the rod towards the pivot and the weight mg down. Its labels
    are symbols only; ``language`` (None: the environment's) sets their font, as in every
    figure.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = plot_pendulum(0.5)
    >>> len(ax.lines) >= 2
    True
    """
    ax = _axes(ax)
    x, y = math.sin(theta), -math.cos(theta)
    ax.plot([0, 0], [0, -1.15], ls=":", color="0.5")
    ax.plot([0, x], [0, y], color="0.2", lw=2)
    ax.plot([0], [0], marker="o", color="k", ms=5)
    ax.plot([x], [y], marker="o", color="C0", ms=18)
    arc = np.linspace(0, theta, 40)
    ax.plot(0.3 * np.sin(arc), -0.3 * np.cos(arc), color="C3")
    big = text_size(ax, 1.3)
    # Labels beside what they name, clear of the arrows and of one another: the angle beyond
    # its arc, T and l right of the rod (across its normal n), the weight right of its arrow.
    nx, ny = math.cos(theta), math.sin(theta)
    centred = dict(ha="center", va="center", fontsize=big)
    ax.annotate(r"$\theta$", (0.45 * math.sin(theta / 2), -0.45 * math.cos(theta / 2)),
                color="C3", **centred)
    ax.annotate("", xy=(0.62 * x, 0.62 * y), xytext=(x, y),
                arrowprops=dict(arrowstyle="->", color="C2", lw=2))
    ax.annotate(r"$\mathbf{T}$", (0.8 * x + 0.17 * nx, 0.8 * y + 0.17 * ny), color="C2",
                **centred)
    ax.annotate("", xy=(x, y - 0.4), xytext=(x, y),
                arrowprops=dict(arrowstyle="->", color="C1", lw=2))
    ax.annotate(r"$mg$", (x + 0.05, y - 0.35), color="C1", fontsize=big)
    ax.annotate(r"$\ell$", (0.4 * x + 0.13 * nx, 0.4 * y + 0.13 * ny), **centred)
    ax.annotate(r"$(x, y)$", (x + 0.1, y + 0.05), fontsize=text_size(ax, 1.1))
    ax.set_xlim(-0.8, 1.2)
    ax.set_ylim(-1.6, 0.3)
    ax.set_aspect("equal")
    ax.set_xlabel("$x$")
    ax.set_ylabel("$y$")
    words(language).dress(ax)
    return readable(ax)


def _orbit(motion: Motion, n: int = 600) -> tuple[np.ndarray, np.ndarray]:
    """One closed orbit (II) or one turn (IV) of the motion, as (θ, θ')."""
    t = np.linspace(0.0, motion.period, n)
    return motion.theta(t), motion.dtheta(t)


def _c1_text(value: float) -> str:
    """c1 / w0^2 to two decimals, without a '-0.00' from rounding noise."""
    return f"{round(value, 2) + 0.0:.2f}"


def _inline(ax: Any, color: str) -> dict:
    """Keyword arguments of an inline curve label: centred on the curve, on a white patch."""
    return dict(fontsize=text_size(ax, 0.9), color=color, ha="center", va="center",
                bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.9))


def plot_phase_portrait(omega0: float = 1.0, ax: Any = None,
                   amplitudes_deg: Sequence[float] = (30, 60, 90, 120, 150, 175),
                   kicks: Sequence[float] = (1.1, 1.3, 1.6),
                   window: float = 3 * math.pi, label: bool = True, arrows: bool = True,
                   xlim: tuple[float, float] | None = None,
                   ylim: tuple[float, float] | None = None, *,
                   language: str | None = None) -> Any:
    r"""Fig. 2: curves (9) in the (θ, θ') plane, each labelled by c1 / ω0².

    .. math:: (\theta')^2 - 2\omega_0^2\cos\theta = c_1 \quad (9)

    I (the point c1 = -2 ω0²), II (closed curves, from swings of the given
    amplitudes), III (the separatrix, c1 = 2 ω0²) and IV (rotations started at
    the bottom with θ' = 2 ω0 × kick, both directions). Every curve is a
    computed motion, not a contour of the energy.

    Parameters
    ----------
    omega0 : float
        ω0 = sqrt(g/ℓ).
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    amplitudes_deg, kicks : list of float
        The swings (II) by amplitude in degrees, and the rotations (IV) by θ'(0) / (2 ω0) > 1.
    window : float
        Half-width of the θ range drawn; the curves repeat with period 2π.
    label : bool
        Write c1 / ω0² on the curves (near θ = 0 and θ = ±π), and say so in the legend.
    arrows : bool
        Arrowheads in the direction of the motion, taken from consecutive times of each
        motion: clockwise, rightwards where θ' > 0 and leftwards where θ' < 0.
    xlim, ylim : (float, float), optional
        A close-up. The legend then lists only the regimes with a curve in view.
    language : str, optional
        The language of the legend's words ("en", "ja"); None: the environment's.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = plot_phase_portrait()
    >>> ax.get_xlabel()
    '$\\theta$'

    One arrowhead on each of the six swings, each branch of the separatrix and each of the
    three rotations in either direction, all clockwise:

    >>> heads = [a for a in ax.texts if a.arrow_patch is not None]
    >>> len(heads)
    14
    >>> all((a.xy[0] > a.xyann[0]) == (a.xy[1] > 0) for a in heads)
    True
    >>> close = plot_phase_portrait(xlim=(1.5, 4.8), ylim=(-1.2, 1.2), label=False)
    >>> [t.get_text() for t in close.get_legend().get_texts()]
    ['II', 'III', 'IV']
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    say = words(language)
    ax = _axes(ax, figsize=(9, 5))
    w2 = omega0 ** 2
    shifts = 2 * math.pi * np.arange(-math.floor(window / (2 * math.pi) + 0.5),
                                     math.floor(window / (2 * math.pi) + 0.5) + 1)
    # regime -> [(copy shift, theta, theta' in time order, colour)]
    drawn: dict[str, list[tuple[float, np.ndarray, np.ndarray, str]]] = {
        "I": [], "II": [], "III": [], "IV": []}
    handles: dict[str, Any] = {}

    def curve(regime: str, th: Any, dth: Any, color: str, shift: float = 0.0,
              **style: Any) -> None:
        (line,) = ax.plot(th, dth, color=color, **style)
        handles.setdefault(regime, line)
        drawn[regime].append((shift, np.atleast_1d(th), np.atleast_1d(dth), color))

    rest_ms = 5.0
    for s in shifts:
        curve("I", [s], [0], "C3", marker="o", ls="none", ms=rest_ms)
    swings = []  # (c1 / w0^2, largest theta') of each swing, for its label
    for deg in amplitudes_deg:
        m = solve(math.radians(deg), 0.0, omega0)
        th, dth = _orbit(m)
        for s in shifts:
            curve("II", th + s, dth, "C0", s, lw=1)
        swings.append((m.energy_constant / w2, float(dth.max())))
    # The separatrix: theta = 2 gd(w0 t) from theta = -pi to pi, both branches. The lower one,
    # theta = -2 gd(w0 t), is the upper one's samples in reverse order with theta' negated.
    x = np.linspace(-12, 12, 800)
    th, dth = 2 * np.arctan(np.sinh(x)), 2 * omega0 / np.cosh(x)
    for s in shifts:
        curve("III", th + s, dth, "C3", s, lw=1.5)
        curve("III", th[::-1] + s, -dth[::-1], "C3", s, lw=1.5)
    for kick in kicks:
        for sign in (1, -1):
            m = solve(0.0, sign * 2 * omega0 * kick, omega0)
            turns = window / (2 * math.pi) + 1  # enough turns to cross the window
            t = np.linspace(-turns * m.period, turns * m.period, 1500)
            th, dth = m.theta(t), m.dtheta(t)
            keep = np.abs(th) <= window
            curve("IV", th[keep], dth[keep], "C2", lw=1)
    ax.set_xlim(*(xlim or (-window, window)))
    if ylim is not None:
        ax.set_ylim(*ylim)
    ax.set_xlabel(r"$\theta$")
    ax.set_ylabel(r"$\theta'$")
    ax.set_xticks(np.arange(-3, 4) * math.pi,
                  [rf"${i}\pi$" if i not in (0, 1, -1) else ("0", r"$\pi$", r"$-\pi$")[i]
                   for i in range(-3, 4)])
    if xlim is not None:
        ax.set_xlim(*xlim)  # set_xticks may widen the view to its ticks
    view = (ax.get_xlim(), ax.get_ylim())
    shown = [r for r, curves in drawn.items()
             if any(np.any(visible(th, dth, view)) for _, th, dth, _ in curves)]
    # The legend's title, whole, for each choice of notes: a translation sees the sentence.
    title = {(True, True): say(r"regime (labels on the curves: $c_1/\omega_0^2$; arrows: "
                               "direction of motion)"),
             (True, False): say(r"regime (labels on the curves: $c_1/\omega_0^2$)"),
             (False, True): say("regime (arrows: direction of motion)"),
             (False, False): say("regime")}[bool(label), bool(arrows)]
    say.dress(ax)
    readable(ax)
    # Below the x label, in one row: inside, it would hide the rotations' curves.
    legend_below(ax, [handles[r] for r in shown], shown, ncol=4, frameon=False, title=title,
                 font=say.font)
    labels = _label_curves(ax, swings, kicks, omega0, shifts, rest_ms) if label else []
    if arrows:
        arrowheads_in_view(ax, drawn, view, labels)
    return ax


def _label_curves(ax: Any, swings: Sequence[tuple[float, float]], kicks: Sequence[float],
                  omega0: float, shifts: np.ndarray, rest_ms: float) -> list[Any]:
    """Write c1 / w0^2 on the curves of the phase portrait; return the labels.

    No label covers another or a rest point.

    The rest at the bottom just below its point; the rotations at theta = pi, where they come
    closest to the axis; the separatrix at its top on the copy left of the centre (at 0 when
    the window holds one copy). Each swing at theta = 0, on the upper and the lower half of
    the curves in turn; near the separatrix the curves are too close for one label above
    another, so a label that would cover one already written, or a rest point, moves to the
    other half, then to the copies at 2 pi and -2 pi, as laid out.
    """
    labels = [ax.annotate(_c1_text(-2.0), (0.0, 0.0), xytext=(0.0, -(rest_ms / 2 + 4)),
                          textcoords="offset points", **dict(_inline(ax, "C3"), va="top"))]
    for kick in kicks:
        c1 = solve(0.0, 2 * omega0 * kick, omega0).energy_constant / omega0 ** 2
        labels.append(ax.annotate(_c1_text(c1), (math.pi, 2 * omega0 * math.sqrt(kick ** 2 - 1)),
                                  **_inline(ax, "C2")))
    copies = [0.0] + [c for c in (2 * math.pi, -2 * math.pi) if np.any(np.isclose(shifts, c))]
    labels.append(ax.annotate(_c1_text(2.0), (-2 * math.pi if len(copies) > 1 else 0.0,
                                              2 * omega0), **_inline(ax, "C3")))
    renderer = layout(ax)
    pad = text_size(ax) * ax.figure.dpi / 72 * 0.15
    rests = ax.transData.transform(np.column_stack([shifts, np.zeros_like(shifts)]))
    radius = rest_ms / 2 * ax.figure.dpi / 72 + pad
    boxes = [t.get_window_extent(renderer).padded(pad) for t in labels]

    def free(box: Any) -> bool:
        near = ((rests[:, 0] > box.x0 - radius) & (rests[:, 0] < box.x1 + radius)
                & (rests[:, 1] > box.y0 - radius) & (rests[:, 1] < box.y1 + radius))
        return not near.any() and not any(box.overlaps(b) for b in boxes)

    for i, (c1, top) in enumerate(swings):
        side = 1 if i % 2 == 0 else -1
        slots = [(c, sd) for c in copies for sd in (side, -side)]
        for copy, sd in slots:
            text = ax.annotate(_c1_text(c1), (copy, sd * top), **_inline(ax, "C0"))
            box = text.get_window_extent(renderer).padded(pad)
            if free(box) or (copy, sd) == slots[-1]:
                break
            text.remove()
        labels.append(text)
        boxes.append(box)
    return labels


def plot_motion(motions: Motion | Sequence[Motion], t: npt.ArrayLike, axes: Any = None,
                compare: bool = True, labels: Sequence[str] | None = None, *,
                language: str | None = None) -> Any:
    """Plot θ(t) and θ'(t) from the closed form, one line per motion.

    With ``compare``, the numerical integration (:func:`elliptic_pendulum.numerics.integrate`,
    DOP853) is drawn as dots on top. Returns the pair of axes. ``labels`` (default: each
    motion's regime and c1) are looked up in the language ``language`` (None: the
    environment's) as :mod:`elliptic_pendulum.checks.verify` describes for a caller's texts.
    """
    say = words(language)
    if isinstance(motions, Motion):
        motions = [motions]
    if axes is None:
        import matplotlib.pyplot as plt
        _, axes = plt.subplots(2, 1, figsize=(7, 5), sharex=True, layout="constrained")
    refuse_masked(t, "t")
    t = np.asarray(t, dtype=float)
    dots = t[:: max(1, len(t) // 40)]
    for i, m in enumerate(motions):
        name = say(labels[i]) if labels else f"{m.regime.value}, $c_1={m.energy_constant:.4g}$"
        axes[0].plot(t, m.theta(t), color=f"C{i}", label=name)
        axes[1].plot(t, m.dtheta(t), color=f"C{i}")
        if compare:
            th, dth = integrate(m.theta0, m.dtheta0, m.omega0, t=dots)
            axes[0].plot(dots, th, ".", color=f"C{i}", ms=4)
            axes[1].plot(dots, dth, ".", color=f"C{i}", ms=4)
    axes[0].set_ylabel(r"$\theta$")
    axes[1].set_ylabel(r"$\theta'$")
    axes[1].set_xlabel("$t$")
    say.dress(*axes)
    for ax in axes:
        readable(ax)
    place_legend(axes[0], font=say.font)
    return axes


# The names of earlier releases.
pendulum_sketch = plot_pendulum
phase_portrait = plot_phase_portrait
