r"""The potential well above the phase portrait: each regime as a level of energy.

Divided by :math:`m\ell^2\omega_0^2/2`, the energy of (9) is :math:`c_1/\omega_0^2`: the
kinetic part :math:`(\theta'/\omega_0)^2` plus the potential :math:`-2\cos\theta` (zero at
the pivot's height, as in the energy chapter). A motion of energy :math:`c_1` can be only
where the well lies below its level, so the rest sits at the bottom, a swing between the two
angles where its level meets the well, the separatrix at the height of the tops, and a
rotation above them.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..motion import solve
from ._base import readable, text_size
from ._words import words
from .phase import plot_phase_portrait

__all__ = ["plot_potential_well"]


def plot_potential_well(omega0: float = 1.0, axes: Any = None, swing_deg: float = 90.0,
                        kick: float = 1.3, window: float = 2.5 * math.pi, *,
                        language: str | None = None) -> Any:
    r"""Draw the well :math:`-2\cos\theta` above the phase portrait, with four energy levels.

    The upper axes show the potential energy :math:`-2\cos\theta` and, as horizontal lines,
    the energies :math:`c_1/\omega_0^2` of four motions: the rest at the bottom (−2), a swing
    released at rest from ``swing_deg`` degrees, the separatrix (2, the tops of the well) and
    a rotation kicked at the bottom with :math:`\theta'(0) = 2\omega_0\,\mathrm{kick}`. Each
    level is solid where the motion can be (the level above the well) and dotted where it
    cannot. The lower axes hold
    :func:`~elliptic_pendulum.plotting.phase.plot_phase_portrait` on the same θ range, with the same
    four motions drawn thick in the colours of their levels; dotted verticals through both
    panels mark the swing's turning angles and the tops :math:`\pm\pi`.

    Parameters
    ----------
    omega0 : float
        ω0 = sqrt(g/ℓ). The upper panel does not depend on it (energies are in units of
        :math:`m\ell^2\omega_0^2/2`); the lower one does, through θ'.
    axes : tuple of matplotlib.axes.Axes, optional
        Upper and lower axes; a new figure of two panels sharing the θ axis when None.
    swing_deg : float
        Amplitude of the swing, in degrees (0 < swing_deg < 180).
    kick : float
        θ'(0) / (2 ω0) of the rotation started at the bottom (kick > 1).
    window : float
        Half-width of the θ range drawn.
    language : str, optional
        The language of the figure's words ("en", "ja"); None: the environment's.

    Returns
    -------
    numpy.ndarray of matplotlib.axes.Axes
        The upper (well) and lower (phase portrait) axes.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> well, phase = plot_potential_well()
    >>> [line.get_label() for line in well.lines if line.get_label()[0] in "IV"]
    ['I', 'II', 'III', 'IV']
    >>> import numpy as np
    >>> [round(float(np.nanmax(line.get_ydata())), 2) + 0.0 for line in well.lines
    ...  if line.get_label()[0] in "IV"]
    [-2.0, 0.0, 2.0, 4.76]
    >>> phase.get_xlim() == well.get_xlim()
    True
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    if not 0 < swing_deg < 180:
        raise ValueError(f"swing_deg must lie in (0, 180), got {swing_deg}")
    if not kick > 1:
        raise ValueError(f"kick must exceed 1 (a rotation), got {kick}")
    if axes is None:
        import matplotlib.pyplot as plt

        _, axes = plt.subplots(2, 1, figsize=(9, 8.5), sharex=True, layout="constrained",
                               height_ratios=(2, 3))
    say = words(language)
    axes = np.asarray(axes)
    well, phase = axes.ravel()
    w2 = omega0 ** 2
    theta0 = math.radians(swing_deg)
    swing = solve(theta0, 0.0, omega0)
    spin = solve(0.0, 2 * omega0 * kick, omega0)
    # (regime, name, c1 / w0^2, colour): the colours of the regimes in plot_phase_portrait.
    levels = [("I", say("rest"), -2.0, "C3"),
              ("II", say("swing"), swing.energy_constant / w2, "C0"),
              ("III", say("separatrix"), 2.0, "C3"),
              ("IV", say("rotation"), spin.energy_constant / w2, "C2")]

    th = np.linspace(-window, window, 1201)
    u = -2.0 * np.cos(th)
    well.plot(th, u, color="k", lw=2, label="_well")
    size = text_size(well, 0.9)
    for regime, name, c1, color in levels:
        inside = np.where(u <= c1 + 1e-12, c1, np.nan)
        outside = np.where(u <= c1 + 1e-12, np.nan, c1)
        well.plot(th, inside, color=color, lw=2.5, label=regime)
        well.plot(th, outside, color=color, lw=1, ls=":", label="_" + regime)
        place = ("top", -0.25) if regime == "I" else ("bottom", 0.12)
        well.text(0.0, c1 + place[1], say("{numeral}: {name}", numeral=regime, name=name),
                  color=color, fontsize=size,
                  ha="center", va=place[0],
                  bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.9))
    well.plot([0.0], [-2.0], "o", color="C3", ms=7, label="_rest")
    well.annotate(r"$-2\cos\theta$", (-0.75 * math.pi, -2 * math.cos(0.75 * math.pi)),
                  fontsize=size, ha="center", va="center",
                  bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.9))
    top = max(c1 for *_, c1, _ in levels)
    well.set_ylim(-3.1, top + 1.2)
    well.set_ylabel(r"$c_1/\omega_0^2$")

    say.dress(well)
    plot_phase_portrait(omega0, ax=phase, window=window, xlim=(-window, window),
                        language=language)
    shifts = 2 * math.pi * np.arange(-math.floor(window / (2 * math.pi) + 0.5),
                                     math.floor(window / (2 * math.pi) + 0.5) + 1)
    t = np.linspace(0.0, swing.period, 600)
    for s in shifts:
        phase.plot(swing.theta(t) + s, swing.dtheta(t), color="C0", lw=2.5)
        phase.plot([s], [0.0], "o", color="C3", ms=8)
    turns = window / (2 * math.pi) + 1
    t = np.linspace(-turns * spin.period, turns * spin.period, 1500)
    keep = np.abs(spin.theta(t)) <= window
    phase.plot(spin.theta(t)[keep], spin.dtheta(t)[keep], color="C2", lw=2.5)
    x = np.linspace(-12, 12, 800)
    phase.plot(2 * np.arctan(np.sinh(x)), 2 * omega0 / np.cosh(x), color="C3", lw=2.5)
    for ax in (well, phase):
        for edge in (-theta0, theta0):
            ax.axvline(edge, color="C0", lw=1, ls=":")
        for edge in (-math.pi, math.pi):
            ax.axvline(edge, color="C3", lw=1, ls=":")
        ax.set_xlim(-window, window)
    well.tick_params(labelbottom=False)
    well.set_xlabel("")
    readable(well)
    return axes
