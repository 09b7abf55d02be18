"""The physical pendulum of section 2: a bob of mass m on a rigid massless rod of length l.

It turns the angle theta(t) of :mod:`elliptic_pendulum.motion` back into the quantities of the
note's figure 1: the angular frequency (6), the small-angle period (8), the bob's position (1),
the rod's tension from (4) and the mechanical energy, (m/2) l^2 c1 by (10). The rod is rigid
(the note's choice), so the tension may turn negative: a string would then go slack.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, overload

import numpy as np
import numpy.typing as npt

from .. import motion as _motion
from .._validation import FloatOrArray, positive_scalar, scalar_or_array
from ..periods.period import small_angle_period

# A Python float for a scalar time, else an array.

__all__ = ["Pendulum"]


@dataclass(frozen=True)
class Pendulum:
    r"""A simple pendulum: length, gravity and mass, checked once.

    .. math:: \omega_0 = \sqrt{g/\ell} \quad (6), \qquad
              x = \ell\sin\theta,\; y = -\ell\cos\theta \quad (1)

    Parameters
    ----------
    length : float
        Rod length :math:`\ell > 0`, in metres.
    g : float, optional
        Gravitational acceleration, :math:`g > 0`; default the standard 9.80665 m/s^2.
    mass : float, optional
        Mass of the bob, :math:`m > 0`, in kg; default 1.

    Raises
    ------
    TypeError
        If a parameter is not a real number (strings and booleans included).
    ValueError
        If a parameter is zero, negative, NaN or infinite.

    Examples
    --------
    A seconds pendulum (half-period one second) is a little shorter than a metre:

    >>> p = Pendulum(length=9.80665 / math.pi**2)
    >>> round(p.small_angle_period, 12)
    2.0
    >>> Pendulum(length=0.0)
    Traceback (most recent call last):
    ...
    ValueError: length must be a finite number > 0, got 0.0
    """

    length: float
    g: float = 9.80665
    mass: float = 1.0

    def __post_init__(self) -> None:
        """Check the three parameters: finite real numbers > 0, stored as floats."""
        for name in ("length", "g", "mass"):
            # object.__setattr__: the dataclass is frozen, and the check stores plain floats.
            object.__setattr__(self, name, positive_scalar(getattr(self, name), name))
        # g / length can overflow or underflow although each is fine: say so in their names.
        ratio = self.g / self.length
        if not (0.0 < ratio < math.inf):
            raise ValueError("g / length must be a finite number > 0 (omega0 = sqrt(g / length)), "
                             f"got g = {self.g!r}, length = {self.length!r}")

    @property
    def omega0(self) -> float:
        r"""Angular frequency (6), :math:`\omega_0 = \sqrt{g/\ell}`.

        Examples
        --------
        >>> Pendulum(length=2.0, g=8.0).omega0
        2.0
        """
        return math.sqrt(self.g / self.length)

    @property
    def small_angle_period(self) -> float:
        r"""Small-angle period (8), :math:`P_\ell = 2\pi\sqrt{\ell/g}`.

        Examples
        --------
        >>> Pendulum(length=1.0, g=1.0).small_angle_period == 2 * math.pi
        True
        """
        return small_angle_period(self.omega0)

    def solve(self, theta0: npt.ArrayLike, dtheta0: npt.ArrayLike = 0.0) -> _motion.Motion:
        r"""Solve for the exact motion from theta(0) = theta0, theta'(0) = dtheta0.

        .. math:: \theta'' = -\frac{g}{\ell}\sin\theta \quad (3)

        Calls :func:`elliptic_pendulum.motion.solve` with this pendulum's :math:`\omega_0`.

        Parameters
        ----------
        theta0 : float
            Initial angle from the downward vertical, radians.
        dtheta0 : float, optional
            Initial angular velocity, rad/s; default 0.

        Returns
        -------
        Motion
            With ``theta(t)``, ``dtheta(t)``, ``regime``, ``period``, ``energy_constant``.

        Examples
        --------
        Released from 90 degrees, a 1 m pendulum takes 18% longer than (8) says:

        >>> p = Pendulum(length=1.0)
        >>> round(p.solve(math.pi / 2).period / p.small_angle_period, 3)
        1.18
        """
        return _motion.solve(theta0, dtheta0, omega0=self.omega0)

    def _check(self, motion: _motion.Motion) -> None:
        # A Motion solved for another omega0 would give tensions and energies of a pendulum
        # that is not this one, silently: refuse it.
        omega0 = getattr(motion, "omega0", None)
        if omega0 is None or (np.ndim(omega0) == 0
                              and math.isclose(omega0, self.omega0, rel_tol=1e-12)):
            return
        # math.isclose(omega0, self.omega0, rel_tol=1e-12) for every state of an array
        omega0 = np.asarray(omega0, dtype=float)
        off = np.abs(omega0 - self.omega0) > 1e-12 * np.maximum(np.abs(omega0), self.omega0)
        if np.any(off):
            bad = float(omega0[off][0]) if omega0.ndim else float(omega0)
            raise ValueError(
                f"motion was solved with omega0={bad!r}, but this pendulum has "
                f"omega0=sqrt(g/length)={self.omega0!r}; use pendulum.solve(theta0, dtheta0)"
            )

    def position(self, motion: _motion.Motion,
                 t: npt.ArrayLike) -> tuple[FloatOrArray, FloatOrArray]:
        r"""Position (1) of the bob at time(s) t, with the pivot at the origin.

        .. math:: x = \ell\sin\theta(t), \qquad y = -\ell\cos\theta(t) \quad (1)

        Parameters
        ----------
        motion : Motion
            From :meth:`solve`.
        t : float or array_like
            Time(s) in seconds.

        Returns
        -------
        x, y : float or ndarray
            Coordinates in metres, of the shape broadcast(S, t) (as ``motion.theta(t)``).

        Examples
        --------
        The bob stays on the circle of radius l:

        >>> p = Pendulum(length=2.0)
        >>> x, y = p.position(p.solve(2.0), [0.0, 0.7, 3.1])
        >>> bool(np.allclose(np.hypot(x, y), 2.0))
        True
        """
        self._check(motion)
        theta = motion.theta(t)
        x, y = self.length * np.sin(theta), -self.length * np.cos(theta)
        return scalar_or_array(x, theta), scalar_or_array(y, theta)

    @overload
    def tension(self, motion: _motion.Motion, t: float) -> float: ...
    @overload
    def tension(self, motion: _motion.Motion,
                t: npt.NDArray[Any] | list[float]) -> npt.NDArray[np.float64]: ...
    @overload
    def tension(self, motion: _motion.Motion, t: npt.ArrayLike) -> FloatOrArray: ...

    def tension(self, motion: _motion.Motion, t: npt.ArrayLike) -> FloatOrArray:
        r"""Tension T of the rod at time(s) t, from (4).

        .. math:: (\theta')^2 = \frac{T}{\ell m} - \frac{g}{\ell}\cos\theta \quad (4)
                  \quad\Longrightarrow\quad T = m\ell(\theta')^2 + mg\cos\theta

        The rod pulls the bob with :math:`\mathbf{T} = T(-\sin\theta, \cos\theta)` (1), towards
        the pivot when T > 0; T < 0 means the rod pushes.

        Parameters
        ----------
        motion : Motion
            From :meth:`solve`.
        t : float or array_like
            Time(s) in seconds.

        Returns
        -------
        float or ndarray
            T in newtons, of the shape broadcast(S, t) (as ``motion.theta(t)``).

        Examples
        --------
        Released from 90 degrees, the bob passes the bottom under three times its weight,
        :math:`T = mg(3 - 2\cos\theta_0)`:

        >>> p = Pendulum(length=1.0, mass=2.0)
        >>> swing = p.solve(math.pi / 2)
        >>> round(p.tension(swing, swing.period / 4) / (p.mass * p.g), 9)
        3.0
        """
        self._check(motion)
        theta, dtheta = motion.theta(t), motion.dtheta(t)
        tension = self.mass * (self.length * dtheta**2 + self.g * np.cos(theta))
        return scalar_or_array(tension, theta)

    def energy(self, motion: _motion.Motion) -> FloatOrArray:
        r"""Total mechanical energy of the motion, kinetic plus potential (pivot at y = 0).

        .. math:: \frac{m}{2}|\mathbf{v}|^2 + m g y
                  = \frac{m}{2}\ell^2\{(\theta')^2 - 2\omega_0^2\cos\theta\}
                  = \frac{m}{2}\ell^2 c_1 \quad (10), (9)

        Parameters
        ----------
        motion : Motion
            From :meth:`solve`; its ``energy_constant`` is :math:`c_1` of (9).

        Returns
        -------
        float or ndarray
            The energy in joules (an array of the states' shape S for an array of states);
            :math:`-mg\ell` at rest at the bottom, :math:`+mg\ell` on the separatrix
            (regime III).

        Examples
        --------
        >>> p = Pendulum(length=1.5, g=10.0, mass=2.0)
        >>> round(p.energy(p.solve(0.0)) / (p.mass * p.g * p.length), 12)
        -1.0
        >>> abs(p.energy(p.solve(math.pi / 2))) < 1e-12   # released at the horizontal
        True
        """
        self._check(motion)
        c1 = motion.energy_constant
        return 0.5 * self.mass * self.length**2 * (c1 if np.ndim(c1) else float(c1))
