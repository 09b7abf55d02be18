r"""Figures for the book, the README and the classroom, drawn from the library.

Every helper takes an optional matplotlib ``ax`` (or ``axes``), draws on it and
returns it; none calls ``plt.show()`` or changes rcParams. matplotlib is
imported inside the functions, so importing :mod:`elliptic_pendulum` does not
select a backend.

Figures of the note: the pendulum (Fig. 1, :func:`pendulum_sketch`) and the
phase portrait of (9) (Fig. 2, :func:`phase_portrait`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from .elliptic import am, complete_integral, incomplete_integral, inverse_integral, jacobi
from .motion import Motion, solve
from .numerics import integrate

__all__ = ["pendulum_sketch", "phase_portrait", "plot_motion", "plot_jacobi",
           "plot_integral", "plot_inverse", "plot_amplitude"]


def _axes(ax: Any = None) -> Any:
    if ax is None:
        import matplotlib.pyplot as plt
        _, ax = plt.subplots(figsize=(6, 4), layout="constrained")
    return ax


def pendulum_sketch(theta: float = 0.55, ax: Any = None) -> Any:
    """Draw Fig. 1: the pendulum with its angle, tension and weight.

    The rod of length l hangs from the origin, the bob sits at (l sin θ, -l cos θ) (1),
    the tension T points along the rod towards the pivot and the weight mg down.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = pendulum_sketch(0.5)
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
    ax.annotate(r"$\theta$", (0.32 * math.sin(theta / 2), -0.36 * math.cos(theta / 2)),
                color="C3", fontsize=13)
    ax.annotate("", xy=(0.62 * x, 0.62 * y), xytext=(x, y),
                arrowprops=dict(arrowstyle="->", color="C2", lw=2))
    ax.annotate(r"$\mathbf{T}$", (0.7 * x + 0.05, 0.7 * y), color="C2", fontsize=13)
    ax.annotate("", xy=(x, y - 0.4), xytext=(x, y),
                arrowprops=dict(arrowstyle="->", color="C1", lw=2))
    ax.annotate(r"$mg$", (x + 0.05, y - 0.35), color="C1", fontsize=13)
    ax.annotate(r"$\ell$", (0.5 * x - 0.1, 0.5 * y), fontsize=13)
    ax.annotate(r"$(x, y)$", (x + 0.1, y + 0.05), fontsize=12)
    ax.set_xlim(-0.8, 1.2)
    ax.set_ylim(-1.6, 0.3)
    ax.set_aspect("equal")
    ax.set_xlabel("$x$")
    ax.set_ylabel("$y$")
    return ax


def _orbit(motion: Motion, n: int = 600) -> tuple[np.ndarray, np.ndarray]:
    """One closed orbit (II) or one turn (IV) of the motion, as (θ, θ')."""
    t = np.linspace(0.0, motion.period, n)
    return motion.theta(t), motion.dtheta(t)


def _c1_text(value: float) -> str:
    """c1 / w0^2 to two decimals, without a '-0.00' from rounding noise."""
    return f"{round(value, 2) + 0.0:.2f}"


def _inline(color: str) -> dict:
    """Keyword arguments of an inline curve label: centred on the curve, on a white patch."""
    return dict(fontsize=7, color=color, ha="center", va="center",
                bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.9))


def phase_portrait(omega0: float = 1.0, ax: Any = None,
                   amplitudes_deg: Sequence[float] = (30, 60, 90, 120, 150, 175),
                   kicks: Sequence[float] = (1.1, 1.3, 1.6),
                   window: float = 3 * math.pi, label: bool = True) -> Any:
    r"""Fig. 2: curves (9) in the (θ, θ') plane, each labelled by c1 / ω0².

    I (the point c1 = -2 ω0²), II (closed curves, from swings of the given
    amplitudes), III (the separatrix, c1 = 2 ω0²) and IV (rotations started at
    the bottom with θ' = 2 ω0 × kick, both directions). Every curve is a
    computed motion, not a contour of the energy.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> ax = phase_portrait()
    >>> ax.get_xlabel()
    '$\\theta$'
    """
    ax = _axes(ax)
    w2 = omega0 ** 2
    shifts = 2 * math.pi * np.arange(-math.floor(window / (2 * math.pi) + 0.5),
                                     math.floor(window / (2 * math.pi) + 0.5) + 1)
    for s in shifts:
        ax.plot([s], [0], "o", color="C3", ms=5, label="I" if s == 0 else None)
    if label:
        ax.annotate(_c1_text(-2.0), (0.0, -0.12), **dict(_inline("C3"), va="top"))
    for i, deg in enumerate(amplitudes_deg):
        m = solve(math.radians(deg), 0.0, omega0)
        th, dth = _orbit(m)
        for s in shifts:
            first = s == 0 and i == 0
            ax.plot(th + s, dth, color="C0", lw=1, label="II" if first else None)
        if label:
            # Inline labels at theta = 0, alternately on the upper and the lower half of the
            # curves: near the separatrix the curves are too close for one label above another.
            side = 1 if i % 2 == 0 else -1
            ax.annotate(_c1_text(m.energy_constant / w2), (0.0, side * dth.max()), **_inline("C0"))
    # The separatrix: theta = 2 gd(w0 t) from theta = -pi to pi, both branches.
    x = np.linspace(-12, 12, 800)
    th, dth = 2 * np.arctan(np.sinh(x)), 2 * omega0 / np.cosh(x)
    for s in shifts:
        for sign in (1, -1):
            ax.plot(th + s, sign * dth, color="C3", lw=1.5,
                    label="III" if (s == 0 and sign == 1) else None)
    for kick in kicks:
        for sign in (1, -1):
            m = solve(0.0, sign * 2 * omega0 * kick, omega0)
            turns = window / (2 * math.pi) + 1  # enough turns to cross the window
            t = np.linspace(-turns * m.period, turns * m.period, 1500)
            th, dth = m.theta(t), m.dtheta(t)
            keep = np.abs(th) <= window
            ax.plot(th[keep], dth[keep], color="C2", lw=1,
                    label="IV" if (kick == kicks[0] and sign == 1) else None)
        if label:
            c1 = solve(0.0, 2 * omega0 * kick, omega0).energy_constant / w2
            ax.annotate(_c1_text(c1), (math.pi, 2 * omega0 * math.sqrt((kick ** 2) - 1)),
                        **_inline("C2"))
    if label:  # the separatrix, on the copy left of the centre when the window shows it
        ax.annotate(_c1_text(2.0), (-2 * math.pi if window >= 2 * math.pi else 0.0, 2 * omega0),
                    **_inline("C3"))
    ax.set_xlim(-window, window)
    ax.set_xlabel(r"$\theta$")
    ax.set_ylabel(r"$\theta'$")
    ax.set_xticks(np.arange(-3, 4) * math.pi,
                  [rf"${i}\pi$" if i not in (0, 1, -1) else ("0", r"$\pi$", r"$-\pi$")[i]
                   for i in range(-3, 4)])
    # Below the axes, in one row: inside, it would hide the rotations' curves.
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=4, fontsize=8, frameon=False,
              title=r"regime (the labels on the curves are $c_1/\omega_0^2$)", title_fontsize=8)
    return ax


def plot_motion(motions: Motion | Sequence[Motion], t: Any, axes: Any = None,
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
    axes[0].legend(fontsize=8)
    return axes


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
    ax.legend(fontsize=8)
    return ax


def plot_integral(moduli: Sequence[float] = (0.5, 0.9, 0.99), ax: Any = None) -> Any:
    """Plot E1(z, k) of (17) on [-1, 1] beside arcsin z = E1(z, 0) (Proposition 1)."""
    ax = _axes(ax)
    z = np.linspace(-1, 1, 401)
    ax.plot(z, np.arcsin(z), "k--", label=r"$\arcsin z$")
    for k in moduli:
        ax.plot(z, incomplete_integral(z, k), label=rf"$E_1(z, {k:g})$")
    ax.set_xlabel("$z$")
    ax.legend(fontsize=8)
    return ax


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
    ax.legend(fontsize=8)
    return ax


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
    ax.legend(fontsize=8)
    return ax
