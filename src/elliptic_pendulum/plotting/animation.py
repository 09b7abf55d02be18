r"""The pendulum in motion: an animation of pendulums beside their points on the phase plane.

For the chapter "the pendulum in motion". :func:`animate` draws, for each given
:class:`~elliptic_pendulum.motion.Motion`, a pendulum (rod and bob, pivots side by side) in the top
panel and, in the bottom panel, its point moving along its curve (9) in the :math:`(\theta,
\theta')` plane, with the separatrix :math:`\theta' = \pm 2\omega_0\cos(\theta/2)` for reference;
angles on the phase plane are reduced to :math:`(-\pi, \pi]`. The frames come from the closed form,
so a rotation keeps turning and a swing near the separatrix lingers at the top as it should.

The result is a :class:`matplotlib.animation.FuncAnimation`; :func:`animation_html` turns it into
matplotlib's self-contained JavaScript player (``to_jshtml``: frames embedded as PNG, no network),
which a notebook shows with ``IPython.display.HTML`` and which Sphinx/myst-nb keeps in the HTML
book. Nothing global is touched (no rcParams, no pyplot state beyond the figure it creates and,
in :func:`animation_html`, closes).

Sixty to 120 frames keep a page light (about 25 kB per frame).
"""

from __future__ import annotations

import math
import operator
import re
from collections.abc import Sequence
from typing import Any

import numpy as np

from .._validation import positive_scalar
from ..motion import Motion
from ._base import legend_below, readable, text_size
from ._words import words

__all__ = ["animate", "animation_html"]

# matplotlib's player draws its buttons with Font Awesome, linked from a CDN; the book loads
# nothing from the network, so the link goes and each icon becomes a plain character.
_ICONS = {
    "fa fa-minus": "\u2212", "fa fa-plus": "+", "fa fa-fast-backward": "\u25c0\u25c0",
    "fa fa-step-backward": "|\u25c0", "fa fa-play fa-flip-horizontal": "\u25c0",
    "fa fa-pause": "||", "fa fa-play": "\u25b6", "fa fa-step-forward": "\u25b6|",
    "fa fa-fast-forward": "\u25b6\u25b6",
}
_COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown")


def _regime_name(motion: Motion, say: Any) -> str:
    """Return the name of a motion's regime, in the language of ``say``."""
    return {"rest": say("rest"), "libration": say("libration"), "separatrix": say("separatrix"),
            "rotation": say("rotation")}[motion.regime.name.lower()]


def _wrapped(theta: np.ndarray) -> np.ndarray:
    """Reduce angles to (-pi, pi], the window of the phase plane."""
    return math.pi - np.mod(math.pi - theta, 2 * math.pi)


def _default_duration(motions: Sequence[Motion]) -> float:
    """Return the longest finite period among the motions, else two small-angle periods."""
    finite = [m.period for m in motions if math.isfinite(m.period) and m.period > 0]
    fallback = 2 * 2 * math.pi / max(m.omega0 for m in motions)
    return max(finite) if finite else fallback


def animate(motions: Motion | Sequence[Motion], duration: float | None = None, frames: int = 90,
            interval: float = 50.0, *, language: str | None = None) -> Any:
    r"""Animate pendulums beside their points on the phase plane.

    .. math:: (x, y) = (\sin\theta(t), -\cos\theta(t)), \qquad
              (\theta(t) \bmod 2\pi,\; \theta'(t)), \qquad t = \frac{j}{J}\,t_{\mathrm{end}}

    Parameters
    ----------
    motions : Motion or list of Motion
        From :func:`~elliptic_pendulum.motion.solve`; up to six, all scalar.
    duration : float, optional
        :math:`t_{\mathrm{end}}`; default the longest finite period among the motions (so
        that each periodic one closes its loop), or two small-angle periods if none is finite.
    frames : int, optional
        Number of frames J (>= 2); default 90.
    interval : float, optional
        Milliseconds between frames in the player; default 50.
    language : str, optional
        The language of the figure's words ("en", "ja"); None: the environment's.

    Returns
    -------
    matplotlib.animation.FuncAnimation
        Its figure has two axes, the pendulums and the phase plane. Added attributes:
        ``frame_times`` (the times of the frames), ``bobs`` and ``points`` (the moving artists,
        one per motion) and ``draw_frame(j)`` (draws frame j).

    Raises
    ------
    ValueError
        If there is no motion or more than six, ``frames < 2``, or ``duration`` is not positive.
    TypeError
        If ``frames`` is not an integer (a bool or a float, say).

    Examples
    --------
    A swing and a rotation; once the frames are rendered, the last one shows the bobs where the
    closed form puts them at the last time:

    >>> import elliptic_pendulum as ep
    >>> motions = [ep.solve(2.0), ep.solve(0.0, 2.5)]
    >>> anim = animate(motions, frames=4)
    >>> html = anim.to_jshtml()  # renders every frame
    >>> theta = motions[1].theta(anim.frame_times[-1])
    >>> bool(np.allclose(anim.bobs[1].get_data(), ([2.5 + np.sin(theta)], [-np.cos(theta)])))
    True
    >>> import matplotlib.pyplot as plt
    >>> plt.close(anim._fig)
    """
    from matplotlib import animation
    from matplotlib import pyplot as plt

    motions = [motions] if isinstance(motions, Motion) else list(motions)
    if not 1 <= len(motions) <= len(_COLOURS):
        raise ValueError(f"motions must hold between 1 and {len(_COLOURS)} motions")
    if any(not isinstance(m, Motion) or np.ndim(m.theta0) != 0 for m in motions):
        raise TypeError("motions must be scalar Motion objects from ep.solve")
    # Any integral count (an np.int64 read from an array, say), but not a bool or a float.
    if isinstance(frames, (bool, np.bool_)):
        raise TypeError("frames must be an integer >= 2, got a bool")
    try:
        frames = operator.index(frames)
    except TypeError:
        raise TypeError(f"frames must be an integer >= 2, got {type(frames).__name__}") from None
    if frames < 2:
        raise ValueError(f"frames must be an integer >= 2; got {frames!r}")
    end = _default_duration(motions) if duration is None else positive_scalar(duration,
                                                                               "duration")
    interval = positive_scalar(interval, "interval")
    say = words(language)
    times = np.linspace(0.0, end, frames)
    states = [(m.theta(times), m.dtheta(times)) for m in motions]
    spacing = 2.5  # pivots side by side, one rod length and a margin apart

    # The pendulums in a row above the phase plane, their panel fitted to the rods (length 1)
    # with a small margin for the bobs and the regimes' names: large enough to watch.
    margin = 0.2
    xlim = (-1 - margin, spacing * (len(motions) - 1) + 1 + margin)
    ylim = (-1 - margin, 1.35)
    fig = plt.figure(figsize=(8, 6.8), layout="constrained")
    left, right = fig.subplots(2, 1, height_ratios=[(ylim[1] - ylim[0]) / (xlim[1] - xlim[0]),
                                                    0.5])
    left.set_aspect("equal")
    left.set_xlim(*xlim)
    left.set_ylim(*ylim)
    left.set_axis_off()
    w0 = max(m.omega0 for m in motions)
    grid = np.linspace(-math.pi, math.pi, 401)
    for sign in (1, -1):
        right.plot(grid, sign * 2 * w0 * np.cos(grid / 2), color="0.6", lw=1, ls="--",
                   label=say("separatrix") if sign == 1 else None)
    speeds = max(2.2 * w0, *(np.max(np.abs(s[1])) * 1.1 for s in states))
    right.set_xlim(-math.pi, math.pi)
    right.set_ylim(-speeds, speeds)
    right.set_xlabel(say(r"$\theta$ (reduced to $(-\pi, \pi]$)"))
    right.set_ylabel(r"$\theta'$")

    rods, bobs, points = [], [], []
    for i, m in enumerate(motions):
        colour, x0 = _COLOURS[i], spacing * i
        left.plot([x0], [0.0], "k.", ms=4)
        left.text(x0, 1.1, f"{m.regime.value}", ha="center", va="bottom", color=colour,
                  fontsize=text_size(left))
        rods.append(left.plot([], [], color=colour, lw=2)[0])
        bobs.append(left.plot([], [], "o", color=colour, ms=14)[0])
        # the curve traced over the whole duration, faintly and densely sampled, broken where the
        # reduced angle jumps by 2 pi
        dense = np.linspace(0.0, end, 1501)
        wrapped, speed = _wrapped(m.theta(dense)), m.dtheta(dense)
        jumps = np.concatenate([[False], np.abs(np.diff(wrapped)) > math.pi])
        right.plot(np.where(jumps, np.nan, wrapped), speed, color=colour, lw=1, alpha=0.5,
                   label=say("{name} ({numeral})", name=_regime_name(m, say),
                             numeral=m.regime.value))
        points.append(right.plot([], [], "o", color=colour, ms=7)[0])
    say.dress(left, right)
    readable(right)
    legend_below(right, ncol=3, frameon=False, font=say.font)

    def draw(j: int) -> list[Any]:
        for i, (theta, dtheta) in enumerate(states):
            x0, th = spacing * i, theta[j]
            x, y = x0 + math.sin(th), -math.cos(th)
            rods[i].set_data([x0, x], [0.0, y])
            bobs[i].set_data([x], [y])
            points[i].set_data([_wrapped(np.asarray(th))], [dtheta[j]])
        return rods + bobs + points

    anim = animation.FuncAnimation(fig, draw, frames=frames, interval=interval, blit=False)
    # For the caller and the tests: the frames' times, their artists, and the drawing function.
    anim.frame_times, anim.bobs, anim.points = times, bobs, points  # type: ignore[attr-defined]

    def draw_frame(j: int) -> list[Any]:
        # Frames drawn by hand count as rendering: matplotlib's Animation.__del__ warns
        # ("deleted without rendering anything") while its _draw_was_started is False.
        anim._draw_was_started = True  # type: ignore[attr-defined]
        return draw(j)

    anim.draw_frame = draw_frame  # type: ignore[attr-defined]
    return anim


def animation_html(motions: Motion | Sequence[Motion], duration: float | None = None,
                   frames: int = 90,
                   interval: float = 50.0, *, language: str | None = None) -> str:
    r"""Render :func:`animate` as matplotlib's self-contained JavaScript player, then close it.

    .. math:: \text{frames } j = 0, \dots, J - 1 \text{ at } t_j = j\,t_{\mathrm{end}}/(J - 1)

    Parameters
    ----------
    motions, duration, frames, interval, language
        As for :func:`animate`. The player's own controls keep matplotlib's English names
        ("Play", "Frame"), which a screen reader reads; the figure's words are in ``language``.

    Returns
    -------
    str
        HTML with the frames embedded (base64 PNG) and the player's script inline; the CDN link
        of the player's icon font is removed and its icons replaced by plain characters, so it
        loads nothing from the network. Every control is a button or an input, reached with
        the keyboard, and has a name (the frame slider "Frame"). Show it with
        ``IPython.display.HTML``.

    Examples
    --------
    >>> import elliptic_pendulum as ep
    >>> html = animation_html([ep.solve(1.0)], frames=3)
    >>> html.count("data:image/png;base64"), "https://" in html, "fa fa-" in html
    (3, False, False)
    >>> 'type="range" aria-label="Frame"' in html
    True
    """
    from matplotlib import pyplot as plt

    anim = animate(motions, duration, frames, interval, language=language)
    try:
        html = str(anim.to_jshtml(default_mode="loop"))
    finally:
        plt.close(anim._fig)
    html = re.sub(r"<link[^>]*font-awesome[^>]*>", "", html)
    # Each button keeps its aria-label and title ("Play", "Next frame"); its character is a
    # picture of that name, hidden from screen readers, which would otherwise read the
    # characters out. The frame slider gets a name: matplotlib gives it none (WCAG 4.1.2).
    for icon, text in _ICONS.items():
        html = html.replace(f'<i class="{icon}"></i>', f'<span aria-hidden="true">{text}</span>')
    html, sliders = re.subn(r'(<input id="_anim_slider\w*" type="range")',
                            r'\1 aria-label="Frame"', html)
    if sliders != 1:  # a matplotlib whose player no longer looks the same
        raise RuntimeError("matplotlib's player has no frame slider to label")
    return html
