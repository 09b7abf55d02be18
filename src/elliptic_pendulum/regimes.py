r"""The note's four kinds of motion, by the energy constant of (9).

The energy constant is :math:`c_1 = \theta'^2 - 2\omega_0^2\cos\theta`. The note splits
on it: I (c1 = -2 w0^2, rest), II (``|c1| < 2 w0^2``, swinging), III (c1 = 2 w0^2, the
separatrix, which also holds the pendulum balanced upside down) and IV (c1 > 2 w0^2,
rotating). :func:`elliptic_pendulum.motion.solve` finds the regime of each initial state without
going through c1 (see the design note of the reference site for how).

>>> import elliptic_pendulum as ep
>>> ep.solve(1.0).regime, ep.solve(0.0, 3.0).regime.value
(<Regime.LIBRATION: 'II'>, 'IV')
"""

from __future__ import annotations

import enum

from ._engine import codes

__all__ = ["Regime"]


class Regime(enum.Enum):
    """The note's four kinds of motion; ``.value`` is the note's numeral."""

    REST = "I"
    LIBRATION = "II"
    SEPARATRIX = "III"
    ROTATION = "IV"


# REGIMES[code] is the Regime of the engine's integer code (elliptic_pendulum._engine.codes).
_BY_CODE = {codes.REST: Regime.REST, codes.LIBRATION: Regime.LIBRATION,
            codes.SEPARATRIX: Regime.SEPARATRIX, codes.ROTATION: Regime.ROTATION}
REGIMES = tuple(_BY_CODE[code] for code in range(len(_BY_CODE)))
