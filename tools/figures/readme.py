"""Draw the README's figure, the phase portrait (the note's Fig. 2), from the library.

Run from the repository root: ``python -m tools.figures.readme``. The PNG is committed so
that the README shows it on any code host; rerun this after changing the plotting code.
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402 - after choosing the backend

import elliptic_pendulum.plotting as epp  # noqa: E402

OUT = Path(__file__).resolve().parents[2] / "docs" / "_static" / "phase_portrait.png"

fig, ax = plt.subplots(figsize=(9, 4.2), layout="constrained")
epp.phase_portrait(ax=ax)
ax.set_title("The simple pendulum's phase plane: every curve is a closed-form motion")
OUT.parent.mkdir(parents=True, exist_ok=True)
fig.savefig(OUT, dpi=110)
print(OUT)
