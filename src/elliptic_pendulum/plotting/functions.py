r"""Figures of the elliptic functions and of Lemma 2's extensions.

The functions of sections 3 and 5 (sn, cn, dn with :func:`plot_jacobi`, E1 with
:func:`plot_integral`, its inverse G with :func:`plot_inverse`, am with
:func:`plot_amplitude`), and Lemma 2's extensions (20) and (21) (:func:`plot_extension`).
Like every figure of :mod:`elliptic_pendulum.plotting`, which re-exports them, each takes an
optional ``ax``, returns it, and changes no rcParams; each writes its words in
``language`` (None: the environment's; see ``plotting/_words.py``).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

from .._validation import refuse_masked
from ..elliptic import am, complete_integral, incomplete_integral, inverse_integral, jacobi
from ..extension import periodic_extension, staircase_extension
from ._base import legend_below, new_axes, place_legend, readable
from ._words import words

__all__ = ["plot_jacobi", "plot_integral", "plot_inverse", "plot_amplitude", "plot_extension",
           "extension_plot"]

_axes = new_axes


def plot_jacobi(k: float, u: npt.ArrayLike, ax: Any = None, kc: float | None = None, *,
                language: str | None = None) -> Any:
    """Plot sn, cn and dn over the given u (several periods), modulus k (or kc)."""
    say = words(language)
    refuse_masked(u, "u")
    ax = _axes(ax)
    u = np.asarray(u, dtype=float)
    for name, values in zip(("sn", "cn", "dn"), jacobi(u, k, kc=kc), strict=True):
        ax.plot(u, values, label=rf"$\mathrm{{{name}}}(u, {k:g})$")
    K = complete_integral(k, kc=kc)
    for j in range(int(u.min() // K), int(u.max() // K) + 1):
        ax.axvline(j * K, color="0.85", lw=0.8, zorder=0)
    ax.set_xlabel(say("$u$ (grey lines: multiples of $K_1$)"))
    say.dress(ax)
    place_legend(ax, font=say.font)
    return readable(ax)


def plot_integral(moduli: Sequence[float] = (0.5, 0.9, 0.99), ax: Any = None, *,
                  language: str | None = None) -> Any:
    """Plot E1(z, k) of (17) on [-1, 1] beside arcsin z = E1(z, 0) (Proposition 1).

    Its labels are symbols only; ``language`` sets their font, as in every figure.
    """
    say = words(language)
    ax = _axes(ax)
    z = np.linspace(-1, 1, 401)
    ax.plot(z, np.arcsin(z), "k--", label=r"$\arcsin z$")
    for k in moduli:
        ax.plot(z, incomplete_integral(z, k), label=rf"$E_1(z, {k:g})$")
    ax.set_xlabel("$z$")
    say.dress(ax)
    place_legend(ax, loc="upper left", font=say.font)
    return readable(ax)


def plot_inverse(moduli: Sequence[float] = (0.5, 0.9, 0.99), ax: Any = None, *,
                 language: str | None = None) -> Any:
    """Plot G(u, k) of (19) on [-K1, K1] beside sin u on [-π/2, π/2].

    Its labels are symbols only; ``language`` sets their font, as in every figure.
    """
    say = words(language)
    ax = _axes(ax)
    u = np.linspace(-math.pi / 2, math.pi / 2, 201)
    ax.plot(u, np.sin(u), "k--", label=r"$\sin u$")
    for k in moduli:
        K = complete_integral(k)
        u = np.linspace(-K, K, 401)
        ax.plot(u, inverse_integral(u, k), label=rf"$G(u, {k:g})$")
    ax.set_xlabel("$u$")
    say.dress(ax)
    place_legend(ax, loc="upper left", font=say.font)
    return readable(ax)


def plot_amplitude(k: float, u: npt.ArrayLike, ax: Any = None, *,
                   language: str | None = None) -> Any:
    r"""Plot am(u, k) = Î of (41) with its linear part and its periodic remainder.

    The linear part is τu with τ = π/(2K1) (45); the remainder am(u) - τu has period 2K1.
    """
    say = words(language)
    refuse_masked(u, "u")
    ax = _axes(ax)
    u = np.asarray(u, dtype=float)
    tau = math.pi / (2 * complete_integral(k))
    a = am(u, k)
    ax.plot(u, a, label=rf"$\hat I(u, {k:g}) = \mathrm{{am}}$")
    ax.plot(u, tau * u, "--", label=r"$\tau u$")
    ax.plot(u, a - tau * u, label=say(r"$\hat I - \tau u$ (periodic)"))
    ax.set_xlabel("$u$")
    say.dress(ax)
    place_legend(ax, loc="upper left", font=say.font)
    return readable(ax)


def plot_extension(f: Callable, a: float, kind: str = "odd", ax: Any = None,
                   periods: float = 2.0, *, language: str | None = None) -> Any:
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
    language : str, optional
        The language of the legend ("en", "ja"); None: the environment's.

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
    >>> ax = plot_extension(np.sin, 1.0)          # the cornered sine
    >>> x, y = ax.lines[0].get_data()            # the extension, over [-4, 4]
    >>> mid = (x > 1) & (x < 3)                  # (20): -f(x - 2a) on [a, 3a]
    >>> float(x.min()), float(x.max()), bool(np.allclose(y[mid], -np.sin(x[mid] - 2)))
    (-4.0, 4.0, True)
    >>> ax = plot_extension(np.arctan, 1.0, kind="staircase")
    >>> round(float(ax.lines[0].get_ydata().max()), 12) == round(float(np.arctan(1) * 4), 12)
    True
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    if kind not in ("odd", "staircase"):
        raise ValueError(f'kind must be "odd" (20) or "staircase" (21), got {kind!r}')
    extend = periodic_extension if kind == "odd" else staircase_extension
    g = extend(f, a)  # validates f and a
    a = float(a)
    say = words(language)
    ax = _axes(ax)
    x = np.linspace(-2 * periods * a, 2 * periods * a, 1601)
    equation = "(20)" if kind == "odd" else "(21)"
    ax.plot(x, g(x), color="C0", lw=1.5,
            label=say("the extension {equation}", equation=equation))
    inside = np.linspace(-a, a, 401)
    ax.plot(inside, np.asarray(f(inside), dtype=float), color="C1", lw=3.5, alpha=0.8,
            label=say(r"$f$ on $[-a, a]$"))
    joints = np.arange(-2 * periods + 1, 2 * periods, 2) * a
    for j in joints:
        ax.axvline(j, color="0.8", lw=0.8, zorder=0)
    ax.plot(joints, g(joints), "o", color="C3", ms=5,
            label=say(r"joints $x = \pm a, \pm 3a, \ldots$"))
    ax.set_xlim(x[0], x[-1])
    ax.set_xlabel("$x$")
    # Below the x label: any corner inside may cover the extension.
    say.dress(ax)
    readable(ax)
    legend_below(ax, ncol=2, frameon=False, font=say.font)
    return ax


# The names of earlier releases.
extension_plot = plot_extension
