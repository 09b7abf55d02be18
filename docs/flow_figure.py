"""Draw docs/_static/flow.png: 10,000 states carried along the flow of the phase plane.

One call solves all of them (``ep.solve`` on arrays) and one call per instant evaluates
them; the states start in a small disk that straddles the separatrix, so the flow draws it
out along the separatrix into swings (II), which stay, and turns (IV), which leave.

    python docs/flow_figure.py
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # a file, no window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import elliptic_pendulum as ep  # noqa: E402

OUT = Path(__file__).resolve().parent / "_static" / "flow.png"


def main() -> None:
    """Solve the cloud once, draw it at five instants, write the PNG."""
    rng = np.random.default_rng(2026)
    n = 10_000
    radius = 0.45 * np.sqrt(rng.random(n))
    angle = 2 * np.pi * rng.random(n)
    theta0 = -1.6 + radius * np.cos(angle)
    dtheta0 = 1.45 + radius * np.sin(angle)
    motion = ep.solve(theta0, dtheta0)
    fig, ax = plt.subplots(figsize=(8, 4.2), dpi=110)
    grid = np.linspace(-np.pi, np.pi, 400)
    for sign in (1, -1):  # the separatrix theta' = +-2 cos(theta/2)
        ax.plot(grid, sign * 2 * np.abs(np.cos(grid / 2)), color="0.6", lw=0.8,
                label="separatrix (28)" if sign == 1 else None)
    for t, color in zip((0.0, 2.0, 4.0, 8.0, 16.0), ("C0", "C1", "C2", "C3", "C4"),
                        strict=True):
        theta, dtheta = motion.state(t)
        wrapped = np.mod(theta + np.pi, 2 * np.pi) - np.pi  # the phase plane is a cylinder
        ax.scatter(wrapped, dtheta, s=0.3, color=color, label=f"t = {t:g}", rasterized=True)
    ax.set_xlim(-np.pi, np.pi)
    ax.set_ylim(-2.6, 2.6)
    ax.set_xlabel(r"$\theta$ (rad, modulo $2\pi$)")
    ax.set_ylabel(r"$\theta'$ (rad per unit time, $\omega_0 = 1$)")
    ax.legend(loc="lower right", markerscale=12, fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(OUT)
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
