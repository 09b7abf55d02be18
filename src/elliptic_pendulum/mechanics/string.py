r"""Rod or string: when a string pendulum stays taut, where it goes slack, and its free flight.

For the chapter "rod or string?" (beyond the note). The note takes a rod because a string can only
pull. Along a motion of (3) the force (4) per unit mass and length is, with the energy constant (9)
:math:`c_1 = \theta'^2 - 2\omega_0^2\cos\theta`,

.. math:: \frac{T}{m\ell} = \theta'^2 + \omega_0^2\cos\theta = c_1 + 3\omega_0^2\cos\theta,

which for a swing of amplitude :math:`\theta_0` is the note's :math:`T = mg(3\cos\theta -
2\cos\theta_0)`. A string is a rod that cannot push: it follows the same motion while
:math:`T \ge 0`. So (in :math:`e = c_1/\omega_0^2`, a function of the state alone)

* it stays taut forever iff :math:`e \le 0` (swings of amplitude up to 90 degrees; at 90 degrees
  T touches 0 at the turning points) or :math:`e \ge 3` (rotations whose speed at the bottom
  satisfies :math:`\theta'^2 \ge 5\omega_0^2`; at equality T touches 0 at the top);
* otherwise it goes slack where :math:`\cos\theta = -e/3` (so between 90 and 180 degrees; for a
  swing :math:`\cos\theta = \tfrac23\cos\theta_0`), while climbing;
* then the bob flies freely on a parabola, with the string's length as its distance from the pivot
  only at the two ends; at the slack point T = 0 makes the first three derivatives of that
  distance vanish, and what remains of the quartic gives the flight time
  :math:`4\,v_y/g` exactly (:math:`v_y` the upward speed at the slack point).

Units: lengths in units of :math:`\ell` (pivot at the origin, y up, the bob at
:math:`(\sin\theta, -\cos\theta)`), so :math:`g = \omega_0^2`; angles in radians.

:func:`string_stays_taut` is vectorized; :func:`slack_point` and :func:`free_flight` take one
initial state, and the flight's :meth:`FreeFlight.position` traces the parabola. What happens when
the string snaps taut again is a modelling choice left to the caller: an inelastic jerk removes
the radial velocity, ``FreeFlight.radial_speed``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from .._validation import positive_scalar, real_array, real_scalar, scalar_or_array
from ..elliptic import incomplete_integral
from ..motion import Motion, solve
from ..regimes import Regime

__all__ = ["FreeFlight", "free_flight", "slack_point", "string_stays_taut"]


def string_stays_taut(theta0: npt.ArrayLike, dtheta0: npt.ArrayLike = 0.0,
                      omega0: float = 1.0) -> bool | npt.NDArray[np.bool_]:
    r"""Tell whether a string pendulum started from this state stays taut for all time.

    .. math:: T \ge 0 \text{ along the motion} \iff e \le 0 \text{ or } e \ge 3, \qquad
              e = \frac{c_1}{\omega_0^2} = \frac{\theta_0'^2}{\omega_0^2} - 2\cos\theta_0

    Parameters
    ----------
    theta0, dtheta0 : float or array_like
        Initial angle (radians) and angular velocity; they broadcast.
    omega0 : float, optional
        :math:`\sqrt{g/\ell}` of (6), positive; default 1.

    Returns
    -------
    bool or ndarray of bool
        True where the tension (4) never becomes negative: swings up to 90 degrees, rest at the
        bottom, and rotations with :math:`\theta'^2 \ge 5\omega_0^2` at the bottom.

    Notes
    -----
    The minimum of :math:`T/(m\ell) = c_1 + 3\omega_0^2\cos\theta` over a motion is at its
    highest point: :math:`\omega_0^2\cos\theta_{\max}` for a swing (where
    :math:`c_1 = -2\omega_0^2\cos\theta_{\max}`), :math:`c_1 - 3\omega_0^2` for a rotation, and
    :math:`-\omega_0^2` on the separatrix. The borderline cases (T touching zero) count as taut.

    Examples
    --------
    Released from rest: taut up to 90 degrees only; pushed from the bottom: taut below
    :math:`\sqrt 2\,\omega_0` (swings under 90 degrees) and from :math:`\sqrt 5\,\omega_0` on:

    >>> import numpy as np
    >>> string_stays_taut(np.radians([45, 89.9, 90.1, 120])).tolist()
    [True, True, False, False]
    >>> string_stays_taut(0.0, [1.4, 1.5, 2.2, 2.25], omega0=1.0).tolist()
    [True, False, False, True]
    """
    theta0, dtheta0 = real_array(theta0, "theta0"), real_array(dtheta0, "dtheta0")
    omega0 = positive_scalar(omega0, "omega0")
    # e = r^2 - 2 cos(theta0) with r = |dtheta0| / omega0. Beyond r = 1e10, e > 3 whatever the
    # angle, so r is capped there and its square cannot overflow (dtheta0 = 1e200 is a fast
    # rotation, taut). A quotient or square that underflows is 0 to rounding next to
    # 2 cos(theta0), which is at least 6e-17 in size for every double angle.
    with np.errstate(over="ignore", under="ignore"):
        r = np.minimum(np.abs(dtheta0) / omega0, 1e10)
        e = r * r - 2.0 * np.cos(theta0)
    taut = (e <= 0.0) | (e >= 3.0)
    if np.ndim(taut) == 0:
        return bool(taut)
    return taut


def _first_root(f, start: float, step: float, limit: int = 4096) -> float:
    """First t > start where f changes sign, from a grid of ``step`` then Brent's method."""
    from scipy import optimize  # only here: importing the package stays light
    left, f_left = start, f(start)
    for _ in range(limit):
        right = left + step
        f_right = f(right)
        if f_right == 0.0:
            return right
        if np.sign(f_right) != np.sign(f_left) and f_left != 0.0:
            return float(optimize.brentq(f, left, right, xtol=1e-300,
                                         rtol=4 * np.finfo(float).eps))
        left, f_left = right, f_right
    raise RuntimeError("no sign change found")  # pragma: no cover - every caller brackets one


def _slack(motion: Motion) -> float | None:
    """Time of the first zero of the tension with T turning negative, or None if it never does."""
    from scipy import optimize  # only here: importing the package stays light
    w2 = motion.omega0**2
    c1 = motion.energy_constant

    def tension(t: float) -> float:
        return c1 + 3.0 * w2 * math.cos(motion.theta(t))

    theta0, dtheta0 = motion.theta0, motion.dtheta0
    if string_stays_taut(theta0, dtheta0, motion.omega0):
        return None
    start = tension(0.0)
    # Slack at once: pushing already (released from rest above the horizontal, say), or at zero
    # tension and climbing (dT/dt = -3 w0^2 sin(theta) theta' < 0).
    if start < 0.0 or (start == 0.0 and math.sin(theta0) * dtheta0 > 0.0):
        return 0.0
    # T decreases only while the bob climbs: the first zero lies before the next highest point,
    # where T < 0, and T has one sign change on [0, that point].
    if motion.regime is Regime.LIBRATION:
        top = _first_root(motion.dtheta, 0.0, motion.period / 64)  # the next turning point
    elif motion.regime is Regime.ROTATION:
        direction = 1.0 if dtheta0 > 0 else -1.0
        # The next odd multiple of pi ahead in the direction of motion.
        turns = (math.floor if direction > 0 else math.ceil)((theta0 - math.pi) / (2 * math.pi))
        target = math.pi + 2 * math.pi * (turns + direction)
        top = _first_root(lambda t: motion.theta(t) - target, 0.0, motion.period / 16)
    else:  # the separatrix: the top is approached for ever; T < 0 well before it
        top = 1.0 / motion.omega0
        while tension(top) >= 0.0:
            top *= 2.0
        return float(optimize.brentq(tension, 0.0, top, xtol=1e-300,
                                     rtol=4 * np.finfo(float).eps))
    # The rounding of T (a few ulp of 3 w0^2) moves its computed zero by that over |dT/dt| =
    # 3 w0^3 sin(theta_s) sqrt(e/3), e = c1 / w0^2 (theta'^2 = w0^2 e / 3 at the slack point).
    # Near 90 degrees (e -> 0) or near the top (e -> 3) that slope vanishes: T is flat within
    # its rounding over a stretch of time where Brent's method lands anywhere, or finds no sign
    # change at all. The time back from the top, in closed form, is good to a few ulp of top.
    e = c1 / w2
    slope = math.sqrt(e / 3.0) * math.sqrt(max(0.0, 1.0 - (e / 3.0) ** 2))
    if slope * motion.omega0 * top < 1.0:
        return max(0.0, top - _before_top(motion, e))
    return float(optimize.brentq(tension, 0.0, top, xtol=1e-300, rtol=4 * np.finfo(float).eps))


def _before_top(motion: Motion, e: float) -> float:
    r"""Return the time from the slack point, cos(theta_s) = -e/3, to the next highest point.

    Counted back from the top by the elliptic argument v, :math:`\sin(\theta_s/2) =
    k\,\mathrm{cd}(v)` in a swing (modulus k, :math:`k^2 = (2 + e)/4`) and
    :math:`\mathrm{cd}(v)` in a rotation (modulus :math:`\gamma^2 = 4/(2 + e)`, argument
    :math:`\omega_0 t/\gamma`), since :math:`\mathrm{sn}(K - v) = \mathrm{cd}(v)`. Solved for sn:

    .. math:: \mathrm{sn}^2 v = \frac{2e}{(2 + e)(3 - e)} \text{ (swing)}, \qquad
              \mathrm{sn}^2 v = \frac{(3 - e)(2 + e)}{2e} \text{ (rotation)},

    free of cancellation where e is small or near 3, and v = E1(sn v) by (17).
    """
    if motion.regime is Regime.LIBRATION:
        square, scale = 2.0 * e / ((2.0 + e) * (3.0 - e)), 1.0
    else:
        square, scale = (3.0 - e) * (2.0 + e) / (2.0 * e), motion.modulus
    v = incomplete_integral(math.sqrt(min(square, 1.0)), motion.modulus,
                            kc=motion.complementary_modulus)
    return float(scale * v / motion.omega0)


def slack_point(theta0: float, dtheta0: float = 0.0,
                omega0: float = 1.0) -> tuple[float, float] | None:
    r"""Find the first time and angle at which a string pendulum's string goes slack.

    .. math:: T(t) = m\ell\,(c_1 + 3\omega_0^2\cos\theta(t)) = 0, \qquad
              \cos\theta_s = -\frac{c_1}{3\omega_0^2}

    along the exact motion :func:`~elliptic_pendulum.motion.solve`, where T turns negative.

    Parameters
    ----------
    theta0, dtheta0 : float
        The initial state, string taut (radians, radians per unit time).
    omega0 : float, optional
        :math:`\sqrt{g/\ell}`, positive; default 1.

    Returns
    -------
    tuple of float, or None
        ``(t, theta)``: the time :math:`t \ge 0` and the angle :math:`\theta(t)` there, or None when
        :func:`string_stays_taut`. ``t = 0`` when the string would have to push at once.

    Notes
    -----
    T decreases only while the bob climbs, so the first zero lies between t = 0 and the next
    highest point of the motion (turning point, top, or, on the separatrix, a time found by
    doubling); Brent's method finds it to a few ulp. Where T falls too slowly for its rounding
    (swings that pass 90 degrees by a hair, rotations that nearly stay taut) the time is
    counted back from the highest point in closed form instead (the elliptic argument between
    the two, from sn^2 as a rational function of c1).

    Examples
    --------
    Released from rest at 120 degrees it falls freely at once; pushed from the bottom at
    :math:`2\omega_0` (the separatrix) it goes slack at :math:`\cos\theta = -2/3`:

    >>> slack_point(2 * math.pi / 3)
    (0.0, 2.0943951023931953)
    >>> t, theta = slack_point(0.0, 2.0)
    >>> round(math.cos(theta), 12), round(t, 6)
    (-0.666666666667, 1.544485)
    """
    theta0, dtheta0 = real_scalar(theta0, "theta0"), real_scalar(dtheta0, "dtheta0")
    motion = solve(theta0, dtheta0, omega0)
    t = _slack(motion)
    if t is None:
        return None
    return t, (theta0 if t == 0.0 else float(motion.theta(t)))


@dataclass(frozen=True)
class FreeFlight:
    r"""The parabola of a string pendulum's bob between going slack and the string snapping taut.

    Lengths in units of the string's length :math:`\ell`, pivot at the origin, y up; times as
    in :func:`~elliptic_pendulum.motion.solve`; :math:`g = \omega_0^2`.

    Attributes
    ----------
    t_slack, theta_slack, dtheta_slack : float
        Time, angle and angular velocity where the string goes slack (:func:`slack_point`).
    t_taut, theta_taut : float
        Time and angle (continued from ``theta_slack`` through the flight) where it is taut again.
    velocity_taut : tuple of float
        The bob's velocity (vx, vy) at ``t_taut``.
    omega0 : float
        :math:`\sqrt{g/\ell}`.
    """

    t_slack: float
    theta_slack: float
    dtheta_slack: float
    t_taut: float
    theta_taut: float
    velocity_taut: tuple[float, float]
    omega0: float

    @property
    def duration(self) -> float:
        """Return the time of flight, ``t_taut - t_slack``."""
        return self.t_taut - self.t_slack

    @property
    def dtheta_taut(self) -> float:
        r"""Return the angular velocity at ``t_taut`` from the tangential part of the velocity."""
        vx, vy = self.velocity_taut
        return math.sin(self.theta_taut) * vy + math.cos(self.theta_taut) * vx

    @property
    def radial_speed(self) -> float:
        """Return the outward speed at ``t_taut``: what the string's jerk must take away."""
        vx, vy = self.velocity_taut
        return math.sin(self.theta_taut) * vx - math.cos(self.theta_taut) * vy

    def position(self, t: Any) -> tuple[Any, Any]:
        r"""Return the bob's position (x, y) at time(s) t in ``[t_slack, t_taut]``.

        .. math:: x = \sin\theta_s + v_x s, \quad y = -\cos\theta_s + v_y s - \tfrac12 g s^2,
                  \quad s = t - t_s
        """
        t = real_array(t, "t")
        if np.any((t < self.t_slack) | (t > self.t_taut)):
            raise ValueError(f"t must lie in the flight, [{self.t_slack}, {self.t_taut}]")
        s = t - self.t_slack
        th, w = self.theta_slack, self.dtheta_slack
        x = math.sin(th) + w * math.cos(th) * s
        y = -math.cos(th) + w * math.sin(th) * s - 0.5 * self.omega0**2 * s * s
        return scalar_or_array(x, t), scalar_or_array(y, t)


def free_flight(theta0: float, dtheta0: float = 0.0, omega0: float = 1.0) -> FreeFlight | None:
    r"""Follow the bob of a string pendulum from where the string goes slack until it is taut again.

    From the slack point :math:`(x_0, y_0) = (\sin\theta_s, -\cos\theta_s)` with velocity
    :math:`v = \theta_s'(\cos\theta_s, \sin\theta_s)`, the distance to the pivot on the parabola
    is 1 again when

    .. math:: &s^2\left(\tfrac{g^2}{4}s^2 - g v_y s + \frac{T_s}{m\ell}\right) = 0, \\
              &s = \frac{2}{g}\left(v_y + \sqrt{v_y^2 - T_s/(m\ell)}\right) \;
              \Bigl(= \frac{4 v_y}{g} \text{ when } T_s = 0\Bigr)

    (the cross term :math:`x_0 v_x + y_0 v_y` vanishes: the velocity is tangent).

    Parameters
    ----------
    theta0, dtheta0 : float
        The initial state, string taut.
    omega0 : float, optional
        :math:`\sqrt{g/\ell}`, positive; default 1.

    Returns
    -------
    FreeFlight or None
        None when :func:`string_stays_taut`.

    Examples
    --------
    From the separatrix (pushed at :math:`2\omega_0` from the bottom): slack at
    :math:`\cos\theta_s = -2/3` (131.8 degrees), then a flight of :math:`4 v_y / g` over the
    pivot, landing on the circle at 324.6 degrees, on the other side:

    >>> flight = free_flight(0.0, 2.0)
    >>> vy = flight.dtheta_slack * math.sin(flight.theta_slack)
    >>> abs(flight.duration - 4 * vy) < 1e-15
    True
    >>> x, y = flight.position(flight.t_taut)
    >>> round(math.hypot(x, y), 14), round(math.degrees(flight.theta_taut), 4)
    (1.0, 324.5691)
    """
    theta0, dtheta0 = real_scalar(theta0, "theta0"), real_scalar(dtheta0, "dtheta0")
    omega0 = positive_scalar(omega0, "omega0")
    motion = solve(theta0, dtheta0, omega0)
    t_slack = _slack(motion)
    if t_slack is None:
        return None
    if t_slack == 0.0:
        theta, w = theta0, dtheta0
    else:
        # At the slack point theta'^2 = c1 - 2 w0^2 cos(theta_s) = c1 / 3 exactly: near 90
        # degrees theta' is tiny there, and dtheta(t) would carry its absolute rounding.
        theta = float(motion.theta(t_slack))
        w = math.copysign(math.sqrt(motion.energy_constant / 3.0), motion.dtheta(t_slack))
    g = omega0**2
    vx, vy = w * math.cos(theta), w * math.sin(theta)
    # T / (m l); at a slack point after t = 0 it is zero by definition (its computed value is
    # rounding), and the flight time is exactly 4 vy / g.
    t_rel = w * w + g * math.cos(theta) if t_slack == 0.0 else 0.0
    root = math.sqrt(vy * vy - t_rel)
    # The positive root of (g^2/4) s^2 - g vy s + t_rel (t_rel <= 0), without cancellation.
    s = 2.0 * (vy + root) / g if vy >= 0.0 else 2.0 * t_rel / (g * (vy - root))
    flight = FreeFlight(t_slack, theta, w, t_slack + s, theta, (vx, vy - g * s), omega0)
    # The landing angle, continued from theta_s along the path (it stays inside the circle).
    x, y = flight.position(np.linspace(flight.t_slack, flight.t_taut, 257))
    polar = np.unwrap(np.arctan2(x, -y))
    landing = theta + float(polar[-1] - polar[0])
    return FreeFlight(t_slack, theta, w, t_slack + s, landing, (vx, vy - g * s), omega0)
