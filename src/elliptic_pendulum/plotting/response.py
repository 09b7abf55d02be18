r"""Figures of the chapter toward nonlinear resonance: backbones and response curves.

The backbone of free motion against amplitude or energy (:func:`plot_backbone`), the
response curve of the driven pendulum with its stable and unstable branches, folds and jumps
(:func:`plot_response`), and a slow sweep over it (:func:`plot_sweep`). Like
:mod:`elliptic_pendulum.plotting`, which re-exports them, every helper takes an optional
``ax``, returns it, and changes no rcParams, and writes its words in ``language`` (None: the
environment's; see ``plotting/_words.py``).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import numpy.typing as npt

from .._validation import refuse_masked
from ..driven.continuation import ResponseCurve
from ..driven.resonance import backbone_frequency, duffing_backbone
from ._base import new_axes, place_legend, readable
from ._words import words

__all__ = ["plot_backbone", "plot_response", "plot_sweep", "backbone_plot", "response_plot",
           "sweep_plot"]


def plot_backbone(omega0: float = 1.0, ax: Any = None, against: str = "amplitude",
                  duffing: bool = True, points: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
                  points_label: str = "solve_ivp", *, language: str | None = None) -> Any:
    r"""Plot the backbone, the frequency of free motion, against amplitude or energy.

    .. math:: \omega(A) = \frac{\pi\,\omega_0}{2K_1(\sin(A/2))}, \qquad
              \omega_{\text{Duffing}}(A) = \omega_0\Bigl(1 - \frac{A^2}{16}\Bigr)

    ``against="amplitude"``: ω/ω0 of the swings
    (:func:`~elliptic_pendulum.driven.resonance.backbone_frequency`) against the amplitude in
    degrees, 0 to 180, with Duffing's backbone
    (:func:`~elliptic_pendulum.driven.resonance.duffing_backbone`, dashed) when ``duffing``.
    ``against="energy"``: against :math:`h = c_1/(2\omega_0^2)`, the swings (h < 1, h = -cos A)
    and the rotations (1 < h ≤ 4, one full turn per period), with the separatrix h = 1 dotted.

    Parameters
    ----------
    omega0 : float
        ω0 = sqrt(g/ℓ).
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    against : {"amplitude", "energy"}
        The horizontal axis.
    duffing : bool
        Draw Duffing's backbone (amplitude only: it has no energy form for rotations).
    points : tuple of array_like, optional
        Measured (x, ω) drawn as black dots: x the amplitude in radians, or h.
    points_label : str
        Their legend entry (looked up in the language's catalog, as a caller's text).
    language : str, optional
        The language of the figure's words ("en", "ja"); None: the environment's.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> import math, matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = plot_backbone()
    >>> [ln.get_label() for ln in ax.lines]
    ['exact', 'Duffing, $1 - A^2/16$']

    The exact curve starts at 1 and ends just below 180 degrees at pi / (2 K1), K1 by mpmath;
    Duffing's ends near 1 - pi^2/16:

    >>> import mpmath
    >>> deg, w = ax.lines[0].get_data()
    >>> with mpmath.workdps(30):
    ...     K = mpmath.ellipk(mpmath.sin(mpmath.mpf(math.radians(deg[-1])) / 2) ** 2)
    ...     end = float(mpmath.pi / (2 * K))
    >>> float(w[0]), round(float(w[-1] / end), 6)
    (1.0, 1.0)
    >>> round(float(ax.lines[1].get_ydata()[-1]), 6) == round(1 - math.pi**2 / 16, 6)
    True
    >>> [ln.get_label() for ln in plot_backbone(against="energy").lines]
    ['swings', 'rotations', '_child2']
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    if against not in ("amplitude", "energy"):
        raise ValueError(f'against must be "amplitude" or "energy", got {against!r}')
    refuse_masked(points, "points")
    w0 = float(omega0)
    say = words(language)
    ax = new_axes(ax, figsize=(4.5, 3.8))
    A = np.linspace(0.0, math.pi * (1 - 1e-9), 800)
    exact = backbone_frequency(A, w0) / w0
    if against == "amplitude":
        ax.plot(np.degrees(A), exact, color="C0", lw=2, label=say("exact"))
        if duffing:
            ax.plot(np.degrees(A), duffing_backbone(A, w0) / w0, "--", color="C3",
                    label=say(r"Duffing, $1 - A^2/16$"))
        if points is not None:
            ax.plot(np.degrees(points[0]), np.asarray(points[1]) / w0, "o", color="k", ms=5,
                    label=say(points_label))
        ax.set(xlim=(0, 180), ylim=(0, 1.05), xticks=range(0, 181, 30),
               xlabel=say("amplitude $A$ (degrees)"), ylabel=r"$\omega / \omega_0$")
        say.dress(ax)
        place_legend(ax, loc="lower left", font=say.font)
        return readable(ax)
    ax.plot(-np.cos(A), exact, color="C0", lw=2, label=say("swings"))
    v = w0 * np.sqrt(2 * (1 + np.geomspace(1 + 1e-9, 4.0, 400)))
    ax.plot(v**2 / (2 * w0**2) - 1, backbone_frequency(bottom_speed=v, omega0=w0) / w0,
            color="C2", lw=2, label=say("rotations"))
    if points is not None:
        ax.plot(points[0], np.asarray(points[1]) / w0, "o", color="k", ms=5,
                label=say(points_label))
    ax.axvline(1.0, color="0.6", ls=":", lw=1)
    ax.set(xlim=(-1, 4), ylim=(0, None), xlabel=say(r"energy $h = c_1/(2\omega_0^2)$"),
           ylabel=r"$\omega / \omega_0$")
    say.dress(ax)
    place_legend(ax, loc="upper left", font=say.font)
    return readable(ax)


def plot_response(curve: ResponseCurve, ax: Any = None, *, color: str = "C0",
                  label: str | None = None, omega0: float = 1.0, backbone: bool = True,
                  duffing: bool = False, linear: tuple[float, float] | None = None,
                  points: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
                  folds: bool = True, jumps: bool = True,
                  peak: bool = False, legend: str | None = "upper left",
                  language: str | None = None) -> Any:
    r"""Plot the response curve: periodic motions' amplitude against forcing frequency.

    .. math:: \theta'' + 2\zeta\omega_0\theta' + \omega_0^2\sin\theta = F\cos\Omega t

    Segments between two stable orbits of ``curve`` solid (thick), the others dashed. With
    the options: the exact backbone (thin black) and Duffing's (red, dashed) as Ω = ω(A) over
    the amplitudes drawn; the small-angle response :math:`F/|\omega_0^2 - \Omega^2 +
    2i\zeta\omega_0\Omega|` (dotted grey) for ``linear = (F, zeta)``; measured points (open
    circles, "long integration"); the folds (crosses); the jumps of a slow sweep (orange
    arrows, :meth:`~elliptic_pendulum.driven.continuation.ResponseCurve.jumps`); the peak (a dot).

    Parameters
    ----------
    curve : elliptic_pendulum.driven.continuation.ResponseCurve
        From :func:`~elliptic_pendulum.driven.continuation.response_curve`.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    color, label : str
        The curve's colour; its legend entry (default "stable" and "unstable"; a label given is
        looked up in the language's catalog, as a caller's text).
    omega0 : float
        ω0 of the curve, for the backbones and the small-angle response.
    backbone, duffing, folds, jumps, peak : bool
        What to draw besides the curve.
    linear : (float, float), optional
        (F, zeta) of the small-angle response to draw.
    points : tuple of array_like, optional
        (Ω, A) from long integrations.
    legend : str or None
        Where the legend goes (a matplotlib location), or None for none.
    language : str, optional
        The language of the figure's words ("en", "ja"); None: the environment's.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> import numpy as np, matplotlib
    >>> matplotlib.use("Agg")
    >>> import elliptic_pendulum as ep
    >>> curve = ep.response_curve(0.15, 0.05, frequencies=(0.6, 1.1), step=0.1)
    >>> ax = plot_response(curve)

    One segment per pair of neighbouring orbits, dashed unless both are stable:

    >>> segments = ax.lines[:len(curve.orbits) - 1]
    >>> st = curve.stable
    >>> all((s.get_linestyle() == "-") == bool(st[i] and st[i + 1])
    ...     for i, s in enumerate(segments))
    True
    >>> bool(np.all(np.concatenate([s.get_xdata() for s in segments])
    ...             == np.repeat(curve.frequency, 2)[1:-1]))
    True
    >>> len([t for t in ax.texts if t.arrow_patch is not None])   # the two jumps
    2
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    refuse_masked(points, "points")
    say = words(language)
    ax = new_axes(ax, figsize=(8, 4.6))
    w0 = float(omega0)
    omega, amp, st = curve.frequency, curve.amplitude, curve.stable
    for i in range(len(omega) - 1):  # segment by segment, by stability
        both = bool(st[i] and st[i + 1])
        ax.plot(omega[i:i + 2], amp[i:i + 2], "-" if both else "--", color=color,
                lw=2 if both else 1.5)
    if label is None:
        ax.plot([], [], "-", color=color, lw=2, label=say("stable"))
        ax.plot([], [], "--", color=color, lw=1.5, label=say("unstable"))
    else:
        ax.plot([], [], "-", color=color, lw=2, label=say(label))
    top = 1.12 * float(amp.max())  # headroom above the peak for the legend
    A = np.linspace(0.0, min(top, math.pi * (1 - 1e-9)), 600)
    if backbone:
        ax.plot(backbone_frequency(A, w0), A, color="k", lw=1.2, label=say("exact backbone"))
    if duffing:
        ax.plot(duffing_backbone(A, w0), A, "--", color="C3", lw=1.2,
                label=say("Duffing's backbone"))
    if linear is not None:
        F, zeta = linear
        w = np.linspace(omega.min(), omega.max(), 400)
        ax.plot(w, F / np.abs(w0**2 - w**2 + 2j * zeta * w0 * w), ":", color="0.5",
                label=say("small-angle response"))
    if points is not None:
        ax.plot(points[0], points[1], "o", mfc="none", color="C3", ms=7,
                label=say("long integration"))
    if folds and curve.folds():
        fw, fa = zip(*curve.folds(), strict=True)
        ax.plot(fw, fa, "x", color="k", ms=8, label=say("folds"))
    if jumps:
        for w_f, a_from, a_to in curve.jumps():
            ax.annotate("", xy=(w_f, a_to), xytext=(w_f, a_from),
                        arrowprops=dict(arrowstyle="->", color="C1", lw=1.5))
    if peak:
        ax.plot(*curve.peak(), "o", color=color, ms=6)
    pad = 0.02 * float(omega.max() - omega.min())  # markers at the ends stay whole
    ax.set(xlim=(omega.min() - pad, omega.max() + pad), ylim=(0, top),
           xlabel=say(r"forcing frequency $\Omega$"),
           ylabel=say("amplitude $A$ (rad)"))
    say.dress(ax)
    if legend is not None:
        place_legend(ax, loc=legend, font=say.font)
    return readable(ax)


def plot_sweep(curve: ResponseCurve, up: tuple[npt.ArrayLike, npt.ArrayLike],
               down: tuple[npt.ArrayLike, npt.ArrayLike], ax: Any = None, *,
               language: str | None = None) -> Any:
    r"""Plot a slow sweep of the forcing frequency, up and down, over the response curve.

    .. math:: \Omega(t) = \Omega_{\text{start}} \pm r\,t

    The curve in grey (thick where stable, dashed where not), the sweeps' half-swing
    amplitudes as dots: up orange, down green; the view spans the swept frequencies.

    Parameters
    ----------
    curve : elliptic_pendulum.driven.continuation.ResponseCurve
        From :func:`~elliptic_pendulum.driven.continuation.response_curve`.
    up, down : tuple of array_like
        (Ω, A) of each half swing of the sweep up and of the sweep down.
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
    >>> import elliptic_pendulum as ep
    >>> curve = ep.response_curve(0.15, 0.05, frequencies=(0.6, 1.1), step=0.1)
    >>> ax = plot_sweep(curve, ([0.7, 0.8], [0.5, 0.6]), ([0.9, 0.8], [1.8, 1.9]))
    >>> [ln.get_label() for ln in ax.lines[-4:]]
    ['stable motions', 'unstable motions', 'sweep up', 'sweep down']
    >>> ax.lines[-1].get_ydata().tolist()
    [1.8, 1.9]
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    refuse_masked(up, "up")
    refuse_masked(down, "down")
    say = words(language)
    ax = new_axes(ax, figsize=(8, 4.4))
    omega, amp, st = curve.frequency, curve.amplitude, curve.stable
    for i in range(len(omega) - 1):
        both = bool(st[i] and st[i + 1])
        ax.plot(omega[i:i + 2], amp[i:i + 2], "-" if both else "--", color="0.6",
                lw=3 if both else 1.5)
    ax.plot([], [], "-", color="0.6", lw=3, label=say("stable motions"))
    ax.plot([], [], "--", color="0.6", lw=1.5, label=say("unstable motions"))
    ax.plot(*up, ".", color="C1", ms=3, label=say("sweep up"))
    ax.plot(*down, ".", color="C2", ms=3, label=say("sweep down"))
    swept = np.concatenate([np.ravel(up[0]), np.ravel(down[0])])
    top = np.concatenate([np.ravel(up[1]), np.ravel(down[1])]).max()
    ax.set(xlim=(swept.min(), swept.max()), ylim=(0, 1.1 * top),
           xlabel=say(r"forcing frequency $\Omega$"), ylabel=say("amplitude $A$ (rad)"))
    say.dress(ax)
    place_legend(ax, loc="lower right", markerscale=4, font=say.font)
    return readable(ax)


# The names of earlier releases.
backbone_plot = plot_backbone
response_plot = plot_response
sweep_plot = plot_sweep
