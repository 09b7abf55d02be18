r"""The exact motion theta(t) of the simple pendulum from any initial state.

The closed forms are the note's (25) for regime II, (28) for III and (46) for
IV, evaluated so that no digit is lost near the bottom or the top:

* II:  theta = 2 arcsin(alpha sn(w0 t + c2, alpha)), computed as
  2 atan2(alpha sn, dn) (arcsin near 1 would halve the digits), and
  theta' = 2 w0 alpha cn(w0 t + c2, alpha);
* III: theta = 2 gd(w0 t + c3) = 2 arctan(sinh(w0 t + c3)) (the tanh form (28)),
  theta' = 2 w0 sech(w0 t + c3); or the singular solution at rest at the top;
* IV:  theta = +-2 am(w0 t / gamma + c4, gamma), theta' = +-(2 w0 / gamma) dn(...).

(Our c3 is the note's -c3, so that every phase is added to w0 t.)
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any, cast, overload

import numpy as np
import numpy.typing as npt

from . import _display
from ._engine import flow as _flow
from ._engine import states as _states
from ._engine.codes import SEPARATRIX
from ._i18n import say_for
from ._validation import FloatOrArray, positive_array, real_array, scalar_or_array
from .regimes import REGIMES, Regime

__all__ = ["Motion", "solve"]

# What a time or an array of times may be; a float or an ndarray comes back.
ArrayLike = npt.ArrayLike


@dataclass(frozen=True, eq=False, repr=False)
class Motion:
    r"""Solutions of (3), theta'' = -w0^2 sin theta, one per initial state; made by :func:`solve`.

    A Motion holds one state (its attributes are Python floats) or an array of states of
    shape ``S`` (its attributes are arrays of that shape; ``regime`` an array of
    :class:`~elliptic_pendulum.regimes.Regime`). ``m[i]``, ``len(m)`` and iteration give
    the Motions of single states. Its arrays are its own (copies of the initial states)
    and read-only: a Motion does not change when the caller's arrays do.

    Attributes
    ----------
    regime : Regime
        I, II, III or IV (``regime.value``).
    theta0, dtheta0, omega0 : float
        The initial state at t = 0 and omega0 = sqrt(g / l) of (6).
    energy_constant : float
        c1 = theta'^2 - 2 w0^2 cos theta of (9).
    modulus, complementary_modulus : float
        alpha = sin(theta0/2) for II (14), gamma = sqrt(2 / (beta + 1)) for IV;
        1 and 0 on the separatrix, 0 and 1 at rest. The complement is computed
        directly, never as sqrt(1 - modulus**2).
    amplitude : float
        The turning angle of (11) for II; 0 for I, pi for III, inf for IV.
    phase : float
        c2, c3 or c4: the elliptic (or hyperbolic) argument at t = 0.
    direction : int
        +1 or -1: the sign in (28) and (46); +1 for I and II.
    period : float
        (26) for II; the time of one full turn for IV; inf for III; for I the
        limit of (26) at zero amplitude, 2 pi / w0 of (8).
    """

    regime: Any
    theta0: Any
    dtheta0: Any
    omega0: Any
    energy_constant: Any
    modulus: Any
    complementary_modulus: Any
    amplitude: Any
    phase: Any
    direction: Any
    period: Any
    _beta: Any = field(repr=False)
    _p: Any = field(repr=False)  # the evaluation's parameters (_flow.Params)

    @property
    def shape(self) -> tuple[int, ...]:
        """The shape S of the array of states; () for a single state."""
        return np.shape(self._p.code)

    @property
    def beta(self) -> FloatOrArray:
        """Return the note's beta = c1 / (2 w0^2) of (29), greater than 1 in regime IV.

        Raises ValueError (naming omega0) where beta exceeds the range of doubles, which
        only a tiny omega0 beside a real push can do: never a silent inf.
        """
        if not np.all(np.isfinite(self._beta)):
            raise ValueError("beta = c1 / (2 omega0**2) exceeds the range of doubles: omega0 "
                             "is too small for this dtheta0 (the motion itself is fine)")
        return self._beta

    @property
    def alpha(self) -> Any:
        """The note's alpha = sin(theta0/2) of (14) in regime II, else None (NaN in an array)."""
        return self._named(Regime.LIBRATION)

    @property
    def gamma(self) -> Any:
        """The note's gamma = sqrt(2/(beta + 1)) of §6 in regime IV, else None (NaN in an array)."""
        return self._named(Regime.ROTATION)

    def _named(self, regime: Regime) -> Any:
        if self.shape == ():
            return self.modulus if self.regime is regime else None
        return np.where(self._p.code == REGIMES.index(regime), self.modulus, np.nan)

    @overload
    def theta(self, t: float) -> float: ...
    @overload
    def theta(self, t: npt.NDArray[Any] | list[float]) -> npt.NDArray[np.float64]: ...
    @overload
    def theta(self, t: ArrayLike) -> FloatOrArray: ...

    def theta(self, t: ArrayLike) -> FloatOrArray:
        """Return the angle theta(t) in radians; float, or an array of shape broadcast(S, t).

        Any real t up to about 6.7e7 quarter periods (2**26) from 0; beyond, the
        reduction of the elliptic argument is not exact and a ValueError names t.
        """
        if (type(t) is float and math.isfinite(t) and type(self._p.code) is int
                and self._p.code != SEPARATRIX):  # one state at one time: the fast path
            return _flow.state_float(self._p, t, True, False)[0]
        t = real_array(t, "t")
        return scalar_or_array(_flow.evaluate(self._p, t, True, False)[0], t, self._p.code)

    @overload
    def dtheta(self, t: float) -> float: ...
    @overload
    def dtheta(self, t: npt.NDArray[Any] | list[float]) -> npt.NDArray[np.float64]: ...
    @overload
    def dtheta(self, t: ArrayLike) -> FloatOrArray: ...

    def dtheta(self, t: ArrayLike) -> FloatOrArray:
        """Return the angular velocity theta'(t); float, or an array of shape broadcast(S, t)."""
        if (type(t) is float and math.isfinite(t) and type(self._p.code) is int
                and self._p.code != SEPARATRIX):  # one state at one time: the fast path
            return _flow.state_float(self._p, t, False, True)[1]
        t = real_array(t, "t")
        return scalar_or_array(_flow.evaluate(self._p, t, False, True)[1], t, self._p.code)

    def state(self, t: ArrayLike) -> tuple[FloatOrArray, FloatOrArray]:
        """Return (theta(t), theta'(t)) from one evaluation (cheaper than the two calls).

        Examples
        --------
        >>> m = solve(1.0, 0.5)
        >>> m.state(2.0) == (m.theta(2.0), m.dtheta(2.0))
        True
        """
        if (type(t) is float and math.isfinite(t) and type(self._p.code) is int
                and self._p.code != SEPARATRIX):  # one state at one time: the fast path
            return _flow.state_float(self._p, t)
        t = real_array(t, "t")
        theta, dtheta = _flow.evaluate(self._p, t)
        return (scalar_or_array(theta, t, self._p.code),
                scalar_or_array(dtheta, t, self._p.code))

    def __repr__(self) -> str:
        """Return a one-line summary: the initial state, its regime, c1, size and period.

        Examples
        --------
        The line is wrapped here to fit the page; the directive tells doctest so.

        >>> solve(0.5)  # doctest: +NORMALIZE_WHITESPACE
        Motion(regime='II', theta0=0.5, dtheta0=0, omega0=1, c1=-1.755165124,
               amplitude=0.5, period=6.382789698)
        >>> solve(0.0, 3.0)  # doctest: +NORMALIZE_WHITESPACE
        Motion(regime='IV', theta0=0, dtheta0=3, omega0=1, c1=7, gamma=0.6666666667,
               period=2.412889994)
        >>> solve([0.5, 0.0], [0.0, 3.0])
        Motion(shape=(2,), regimes={'II': 1, 'IV': 1})
        """
        return _display.text(self)

    def _repr_html_(self) -> str:
        """Return a small HTML table for Jupyter: regime, c1, amplitude or gamma, period.

        Its words are in the environment's language as gettext reads it (Japanese for
        LANGUAGE=ja), read at each display; the one-line repr stays Python.
        """
        return _display.html(self, say_for(__package__, None))

    def __bool__(self) -> bool:
        """Return True for a single state; for an array of states, ``len(m) != 0``.

        A Motion is an object, not a truth value: one state is always true (``len`` of it
        raises TypeError, which ``bool`` would otherwise pass on), and an array of states
        is true as a Python sequence is, when its first axis is not empty.
        """
        return self.shape == () or self.shape[0] != 0

    def __len__(self) -> int:
        """Return the number of states along the first axis of S."""
        if self.shape == ():
            raise TypeError("len() of a Motion of a single state")
        return self.shape[0]

    def __getitem__(self, index: Any) -> Motion:
        """Return the Motion of the states ``S[index]``: one state for an integer index."""
        if self.shape == ():
            raise TypeError("a Motion of a single state cannot be indexed")
        values = (self.regime, self.theta0, self.dtheta0, self.omega0, self.energy_constant,
                  self.modulus, self.complementary_modulus, self.amplitude, self.phase,
                  self.direction, self.period, self._beta)
        return Motion(*_frozen(_states.pick(values, self._p, self.shape, index)))

    def __iter__(self) -> Iterator[Motion]:
        """Yield the Motions of the states along the first axis of S."""
        for i in range(len(self)):
            yield self[i]


_PLAIN = (float, int)  # exact types: a bool is refused on the array path


def solve(theta0: ArrayLike, dtheta0: ArrayLike = 0.0, omega0: ArrayLike = 1.0) -> Motion:
    r"""Solve (3) exactly from the initial state (theta0, theta0') at t = 0.

    .. math:: \theta'' = -\omega_0^2 \sin\theta, \qquad
              \theta(0) = \theta_0, \quad \theta'(0) = \theta_0'

    Parameters
    ----------
    theta0 : float or array_like
        Initial angle in radians from the downward vertical; any real value
        (2 pi m is carried along). ``math.pi`` (the double nearest any odd
        multiple of pi) means exactly upside down; ``2 * math.pi`` (the double
        nearest any nonzero even multiple) exactly at the bottom.
    dtheta0 : float or array_like, default 0.0
        Initial angular velocity in rad per unit time; either sign.
    omega0 : float or array_like, default 1.0
        sqrt(g / l) of (6), > 0. With omega0 = 1, t is measured in units of
        sqrt(l / g). The three broadcast (numpy rules) to the shape S of the
        states.

    Returns
    -------
    Motion
        Of one state (Python floats) or of the array of states, each with its
        own regime; each state is computed on its own, bit for bit as alone.

    Raises
    ------
    TypeError
        For a non-number.
    ValueError
        For NaN, infinities, omega0 <= 0, shapes that do not broadcast, or an
        energy beyond the range of doubles (naming the parameter). For a push
        too small for omega0 (naming dtheta0 and omega0): w = dtheta0 / (2 omega0)
        is what the motion carries, and ``abs(dtheta0 / (2 omega0))`` must be 0 or at
        least 2**-1022 (below, w would underflow or lose its digits). For a push
        so small, this close to the top, that the complementary modulus falls
        below 1e-300 (naming dtheta0): K = log(4/kc), hence the period, would
        lose its digits; use dtheta0 = 0 (balanced at the top) or
        ``abs(dtheta0) >= 2e-300 omega0``. For theta0 = +-5e-324 at rest (naming theta0):
        the modulus sin(theta0 / 2) rounds to 0 while the state swings.

    Notes
    -----
    The regime and the modulus come from k^2 = s^2 + w^2 and
    kc^2 = 1 - k^2 = (c - abs(w)) (c + abs(w)), with s, c = sin, cos of half of theta0
    reduced by 2 pi m and w = dtheta0 / (2 omega0), formed from the exact doubles
    in double-double arithmetic, where c - abs(w) is known to an absolute error of
    about 3e-32. Off the separatrix that is far below a double's rounding. Near
    it kc^2 has the relative error cond = 3e-32 / abs(c - abs(w)), the complementary
    modulus half of it and the period less than cond, and the phase drifts by up
    to about cond per quarter period: after N quarter periods theta may be off by
    2 k cond (N + 3) beyond its few ulp, theta' by 2 omega0 k times that. Within
    about 3e-32 of the separatrix (cond >= 1) the regime itself (II, III or IV)
    is not determined by the arithmetic. The exact separatrix (theta0 = 2 pi m
    with abs(dtheta0) = 2 omega0, or at rest at the top) is exact.

    Examples
    --------
    A 170 degree swing from rest: regime II, and the period is (26).

    >>> import math
    >>> m = solve(math.radians(170))
    >>> m.regime.value, round(math.degrees(m.amplitude), 12)
    ('II', 170.0)
    >>> from elliptic_pendulum.elliptic import complete_integral
    >>> m.period == 4 * complete_integral(math.sin(m.amplitude / 2),
    ...                                    kc=math.cos(m.amplitude / 2))
    True
    >>> abs(m.theta(m.period) - m.theta0) < 1e-12
    True

    Kicked hard enough at the bottom it goes over the top (IV); exactly
    hard enough (theta' = 2 omega0), it creeps up the separatrix (III):

    >>> solve(0.0, 2.5).regime.value, solve(0.0, 2.0).regime.value
    ('IV', 'III')

    Many states at once, one row of times per state:

    >>> import numpy as np
    >>> swings = solve(np.radians([10.0, 90.0, 170.0])[:, None])
    >>> swings.theta(np.linspace(0.0, 1.0, 5)).shape
    (3, 5)
    >>> [m.regime.value for m in swings[:, 0]]
    ['II', 'II', 'II']

    Released at rest exactly upside down it stays there (the singular solution):

    >>> solve(math.pi).theta(100.0) == math.pi
    True
    """
    if all(type(x) in _PLAIN for x in (theta0, dtheta0, omega0)):
        try:
            plain = [float(cast(float, x)) for x in (theta0, dtheta0, omega0)]
        except OverflowError:  # an int beyond doubles: the array path says so
            plain = []
        one = _states.solve_float(*plain) if plain else None
        if one is not None:  # one state in the usual range: the fast path, the same bits
            public, params = one
            return Motion(REGIMES[params[0]], *public,  # type: ignore[call-arg]
                          _flow.Params(*params))
    th = real_array(theta0, "theta0")
    v = real_array(dtheta0, "dtheta0")
    w0 = positive_array(omega0, "omega0")
    try:
        shape = np.broadcast_shapes(th.shape, v.shape, w0.shape)
    except ValueError:
        raise ValueError(f"theta0, dtheta0 and omega0 must broadcast together (numpy rules); "
                         f"got shapes {th.shape}, {v.shape}, {w0.shape}") from None
    # Copies (np.asarray and broadcast_to may alias the caller's arrays), made read-only
    # below with everything else: a Motion must not change when its caller's arrays do.
    public, p = _states.solve(*(np.array(np.broadcast_to(x, shape)) for x in (th, v, w0)))
    regime = np.empty(shape, dtype=object)
    for number, member in enumerate(REGIMES):
        regime[p.code == number] = member
    return Motion(*_frozen(_states.plain([regime, *public], p)))


def _frozen(fields: Any) -> Any:
    """Return ``fields`` with every array in it (nested in tuples too) made read-only."""
    if isinstance(fields, np.ndarray):
        fields.flags.writeable = False
    elif isinstance(fields, (tuple, list)):
        for x in fields:
            _frozen(x)
    return fields
