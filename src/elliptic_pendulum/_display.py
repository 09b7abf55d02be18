"""How a Motion shows itself: a one-line repr and a small table for Jupyter."""

from __future__ import annotations

import html as _html
import math
from typing import Any

import numpy as np

from .regimes import REGIMES, Regime

__all__ = ["html", "summary", "text"]


def summary(motion: Any) -> list[tuple[str, str]]:
    """Return (label, value) rows: regime, c1, amplitude or gamma, period; or counts."""
    if motion.shape != ():
        counts = {r: int(np.count_nonzero(motion._p.code == i)) for i, r in enumerate(REGIMES)}
        rows = [("states", f"{int(np.prod(motion.shape))} of shape {motion.shape}")]
        rows += [(f"regime {r.value} ({r.name.lower()})", str(n))
                 for r, n in counts.items() if n]
        return rows
    regime = motion.regime
    rows = [("regime", f"{regime.value} ({regime.name.lower()})"),
            ("theta0, theta0'", f"{motion.theta0:.6g}, {motion.dtheta0:.6g}"),
            ("omega0", f"{motion.omega0:.6g}"),
            ("c1", f"{motion.energy_constant:.10g}")]
    if regime is Regime.ROTATION:
        rows.append(("gamma", f"{motion.modulus:.10g}"))
        rows.append(("time per revolution", f"{motion.period:.10g}"))
    else:
        rows.append(("amplitude", f"{motion.amplitude:.10g}"))
        rows.append(("period", "inf" if math.isinf(motion.period) else f"{motion.period:.10g}"))
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


def html(motion: Any) -> str:
    """Return the HTML table."""
    body = "".join(f"<tr><th style='text-align:left'>{_html.escape(k)}</th>"
                   f"<td style='text-align:left'>{_html.escape(v)}</td></tr>"
                   for k, v in summary(motion))
    return f"<table><caption>elliptic_pendulum.Motion</caption>{body}</table>"
