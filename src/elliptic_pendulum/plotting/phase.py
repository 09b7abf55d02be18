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
from ._base import layout, legend_below, new_axes, place_legend, readable, text_size

__all__ = ["plot_pendulum", "plot_phase_portrait", "plot_motion", "pendulum_sketch",
           "phase_portrait"]

_axes = new_axes


def plot_pendulum(theta: float = 0.55, ax: Any = None) -> Any:
    """Draw Fig. 1: the pendulum with its angle, tension and weight.

    The rod of length l hangs from the origin, the bob sits at (l sin θ, -l cos θ) (1),
    the tension T points along the rod towards the pivot and the weight mg down.

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


def _arrowhead(ax: Any, th: np.ndarray, dth: np.ndarray, i: int, color: str) -> Any:
    """Draw an arrowhead on the curve at sample i, pointing to sample i + 1.

    The samples are in time order, so the head shows the direction of the motion itself.
    """
    return ax.annotate("", xy=(th[i + 1], dth[i + 1]), xytext=(th[i], dth[i]),
                       arrowprops=dict(arrowstyle="-|>", color=color, lw=0,
                                       mutation_scale=text_size(ax, 1.4), shrinkA=0,
                                       shrinkB=0))


def _visible(th: np.ndarray, dth: np.ndarray, view: Any) -> np.ndarray:
    (x0, x1), (y0, y1) = view
    return (th >= x0) & (th <= x1) & (dth >= y0) & (dth <= y1)


def _same_curve(a: tuple, b: tuple) -> bool:
    """Whether two (shift, theta, ...) entries are copies of one curve, 2 pi k apart."""
    return len(a[1]) == len(b[1]) and bool(np.allclose(a[1] - a[0], b[1] - b[0]))


def _curves(entries: list) -> list[list]:
    """The entries grouped by curve (its copies 2 pi k apart), in the order drawn."""
    groups: list[list] = []
    for entry in entries:
        for group in groups:
            if _same_curve(group[0], entry):
                group.append(entry)
                break
        else:
            groups.append([entry])
    return groups


# Offsets tried, in turn, from a head's chosen place when a label is in the way (radians of
# the swing's phase angle, or fractions of the view's width).
_NUDGES = (0.0, 0.25, -0.25, 0.5, -0.5, 0.75, -0.75, 1.0, -1.0)


def _arrowheads_in_view(ax: Any, drawn: dict, view: Any, labels: Sequence[Any] = ()) -> None:
    """Draw one arrowhead on each curve, where no two heads crowd each other.

    Nested swings would take their heads side by side if all sat at one place: so swing i
    goes on copy i mod 3 of those in view (the centre's, then its neighbours'), in the
    upper right of its oval for even i and the lower left for odd i, which leaves two heads
    per copy, three curves apart, on opposite sides. Each branch of the separatrix takes its
    head on the central copy, upper left and lower right, between those of the swings; the
    rotations above the axis near the view's left edge, those below near its right edge,
    where no label is. A head that would cover a label moves along its curve (_NUDGES).
    """
    renderer = layout(ax)
    # A head keeps half a letter's height from every label: touching, it reads as a sign.
    pad = text_size(ax) * ax.figure.dpi / 72 * 0.5
    boxes = [t.get_window_extent(renderer).padded(pad) for t in labels]
    (x0, x1), (y0, y1) = view
    centre, width = (x0 + x1) / 2, x1 - x0
    # Heads stay off the frame: a head in a corner is half cut and reads as clutter.
    inner = ((x0 + 0.06 * width, x1 - 0.06 * width),
             (y0 + 0.06 * (y1 - y0), y1 - 0.06 * (y1 - y0)))

    def put(th: np.ndarray, dth: np.ndarray, color: str, score: Any, near: float) -> bool:
        # The visible sample nearest the chosen place (score 0), if within ``near`` of it,
        # that covers no label.
        seen = np.flatnonzero(_visible(th, dth, inner))[:-1]
        if len(seen) == 0:
            return False
        for nudge in _NUDGES:
            scores = score(seen, nudge)
            if scores.min() > near:
                continue
            i = int(seen[np.argmin(scores)])
            head = _arrowhead(ax, th, dth, i, color)
            head.update_positions(renderer)
            extent = head.arrow_patch.get_window_extent(renderer)
            if not any(extent.overlaps(box) for box in boxes):
                boxes.append(extent)
                return True
            head.remove()
        return False

    def copies_of(group: list) -> list:
        # The copies with a part in view, the nearest the centre first.
        shown = [e for e in group if np.any(_visible(e[1], e[2], view))]
        return sorted(shown, key=lambda e: (abs(e[0] - centre), e[0]))

    def along(th: np.ndarray, where: float) -> Any:
        return lambda idx, n: np.abs(th[idx] - where - n * 0.1 * width)

    # A close-up may show no part of a curve near its chosen place: then the swings take
    # their heads at a turning point (where they cross the axis upright), the separatrix and
    # the rotations near the view's middle.
    odd_pi = math.pi * (2 * round((centre - math.pi) / (2 * math.pi)) + 1)
    for i, group in enumerate(_curves(drawn["II"])):
        shown = copies_of(group)
        order = shown[i % 3:] + shown[:i % 3] if shown else []
        targets = ((math.pi / 4, 0.0, math.pi) if i % 2 == 0
                   else (-3 * math.pi / 4, math.pi, 0.0))
        done = False
        for target in targets:
            for shift, th, dth, color in order:
                x, y = th - shift, dth
                phase = np.arctan2(y / np.max(np.abs(y)), x / np.max(np.abs(x)))
                if put(th, dth, color, lambda idx, n, ph=phase, tg=target: np.abs(
                        np.angle(np.exp(1j * (ph[idx] - tg - n)))), near=0.3):
                    done = True
                    break
            if done:
                break
    for group in _curves(drawn["III"]):
        for shift, th, dth, color in copies_of(group):
            upper = np.mean(dth) > 0
            places = (shift - math.pi / 2 if upper else shift + math.pi / 2,
                      odd_pi - width / 4 if upper else odd_pi + width / 4)
            if any(put(th, dth, color, along(th, w), near=0.05 * width) for w in places):
                break
    for group in _curves(drawn["IV"]):
        for shift, th, dth, color in copies_of(group):
            # Where the rotations lie farthest apart, at an odd multiple of pi: the upper ones
            # left of the labels there, the lower ones right (none is labelled below).
            upper = np.mean(dth) > 0
            places = (odd_pi - 2 * math.pi if upper else odd_pi, odd_pi) if width > 4 * math.pi \
                else (odd_pi,)
            if any(put(th, dth, color, along(th, w), near=0.05 * width) for w in places):
                break


def plot_phase_portrait(omega0: float = 1.0, ax: Any = None,
                   amplitudes_deg: Sequence[float] = (30, 60, 90, 120, 150, 175),
                   kicks: Sequence[float] = (1.1, 1.3, 1.6),
                   window: float = 3 * math.pi, label: bool = True, arrows: bool = True,
                   xlim: tuple[float, float] | None = None,
                   ylim: tuple[float, float] | None = None) -> Any:
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
             if any(np.any(_visible(th, dth, view)) for _, th, dth, _ in curves)]
    notes = ([r"labels on the curves: $c_1/\omega_0^2$"] if label else []) + (
        ["arrows: direction of motion"] if arrows else [])
    readable(ax)
    # Below the x label, in one row: inside, it would hide the rotations' curves.
    legend_below(ax, [handles[r] for r in shown], shown, ncol=4, frameon=False,
                 title="regime" + (" (" + "; ".join(notes) + ")" if notes else ""))
    labels = _label_curves(ax, swings, kicks, omega0, shifts, rest_ms) if label else []
    if arrows:
        _arrowheads_in_view(ax, drawn, view, labels)
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
                compare: bool = True, labels: Sequence[str] | None = None) -> Any:
    """Plot θ(t) and θ'(t) from the closed form, one line per motion.

    With ``compare``, the numerical integration (:func:`elliptic_pendulum.numerics.integrate`,
    DOP853) is drawn as dots on top. Returns the pair of axes.
    """
    if isinstance(motions, Motion):
        motions = [motions]
    if axes is None:
        import matplotlib.pyplot as plt
        _, axes = plt.subplots(2, 1, figsize=(7, 5), sharex=True, layout="constrained")
    refuse_masked(t, "t")
    t = np.asarray(t, dtype=float)
    dots = t[:: max(1, len(t) // 40)]
    for i, m in enumerate(motions):
        name = labels[i] if labels else f"{m.regime.value}, $c_1={m.energy_constant:.4g}$"
        axes[0].plot(t, m.theta(t), color=f"C{i}", label=name)
        axes[1].plot(t, m.dtheta(t), color=f"C{i}")
        if compare:
            th, dth = integrate(m.theta0, m.dtheta0, m.omega0, t=dots)
            axes[0].plot(dots, th, ".", color=f"C{i}", ms=4)
            axes[1].plot(dots, dth, ".", color=f"C{i}", ms=4)
    axes[0].set_ylabel(r"$\theta$")
    axes[1].set_ylabel(r"$\theta'$")
    axes[1].set_xlabel("$t$")
    for ax in axes:
        readable(ax)
    place_legend(axes[0])
    return axes


# The names of earlier releases.
pendulum_sketch = plot_pendulum
phase_portrait = plot_phase_portrait
