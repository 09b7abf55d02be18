"""The integer code of each regime, as the engine stores it per element of an array of states.

Defined once here, and mapped to the public :class:`elliptic_pendulum.regimes.Regime` by
``elliptic_pendulum.regimes.REGIMES[code]``: the engine works on small integers in arrays,
never on enum members.
"""

REST, LIBRATION, SEPARATRIX, ROTATION = range(4)

__all__ = ["LIBRATION", "REST", "ROTATION", "SEPARATRIX"]
