"""How a Motion shows itself: a one-line repr and a small table for Jupyter.

The repr stays Python (it is what a reader types back); the table's words are the reader's
language, by the ``say`` that :class:`~elliptic_pendulum.motion.Motion` passes in (its
English is every first argument of ``say(...)`` below, and ``_ja.py`` has their Japanese).
Both read only a Motion's public values and its regime codes.
"""

from __future__ import annotations

import html as _html
import math
from typing import Any

import numpy as np

from ._i18n import Say
from .regimes import REGIMES, Regime

__all__ = ["html", "text"]


def _summary(motion: Any, say: Say) -> list[tuple[str, str]]:
    """Return (label, value) rows: regime, c1, amplitude or gamma, period; or counts."""
    if motion.shape != ():
        counts = {r: int(np.count_nonzero(motion._p.code == i)) for i, r in enumerate(REGIMES)}
        rows = [(say("states"), say("{count} of shape {shape}", count=int(np.prod(motion.shape)),
                                    shape=motion.shape))]
        rows += [(say("regime {numeral} ({name})", numeral=r.value, name=say(r.name.lower())),
                  str(n)) for r, n in counts.items() if n]
        return rows
    regime = motion.regime
    rows = [(say("regime"), say("{numeral} ({name})", numeral=regime.value,
                                name=say(regime.name.lower()))),
            (say("theta0, theta0'"), f"{motion.theta0:.6g}, {motion.dtheta0:.6g}"),
            (say("omega0"), f"{motion.omega0:.6g}"),
            (say("c1"), f"{motion.energy_constant:.10g}")]
    if regime is Regime.ROTATION:
        rows.append((say("gamma"), f"{motion.modulus:.10g}"))
        rows.append((say("time per revolution"), f"{motion.period:.10g}"))
    else:
        rows.append((say("amplitude"), f"{motion.amplitude:.10g}"))
        rows.append((say("period"),
                     "inf" if math.isinf(motion.period) else f"{motion.period:.10g}"))
    return rows


def text(motion: Any) -> str:
    """Return the one-line repr."""
    if motion.shape != ():
        counts = {r.value: int(np.count_nonzero(motion._p.code == i))
                  for i, r in enumerate(REGIMES)}
        regimes = {k: n for k, n in counts.items() if n}
        return f"Motion(shape={motion.shape}, regimes={regimes})"
    size = ("gamma", motion.modulus) if motion.regime is Regime.ROTATION else \
        ("amplitude", motion.amplitude)
    fields = [("theta0", motion.theta0), ("dtheta0", motion.dtheta0), ("omega0", motion.omega0),
              ("c1", motion.energy_constant), size, ("period", motion.period)]
    return (f"Motion(regime='{motion.regime.value}', "
            + ", ".join(f"{k}={v:.10g}" for k, v in fields) + ")")


def html(motion: Any, say: Say) -> str:
    """Return the HTML table, its words by ``say``."""
    body = "".join(f"<tr><th style='text-align:left'>{_html.escape(k)}</th>"
                   f"<td style='text-align:left'>{_html.escape(v)}</td></tr>"
                   for k, v in _summary(motion, say))
    return f"<table><caption>elliptic_pendulum.Motion</caption>{body}</table>"
