r"""The response curve of the driven pendulum by pseudo-arclength continuation in the frequency.

For the chapter "toward nonlinear resonance". The periodic orbits of

.. math:: \theta'' + 2\zeta\omega_0\theta' + \omega_0^2\sin\theta = F\cos\Omega t

(see :mod:`.resonance`) form a curve in :math:`(\theta(0), \theta'(0), \Omega)`. Near resonance it
folds over (the pendulum softens: the peak leans toward low frequencies along the backbone), so
:math:`\Omega` is not a good parameter there; pseudo-arclength continuation follows the curve by
its arclength s instead, through both folds: predictor along the tangent (the null vector of
:math:`[M - I \mid \partial P/\partial\Omega]`, the cross product of its two rows), corrector by
Newton's method on the shooting equations plus :math:`\mathbf t\cdot(X - X_{pred}) = 0`, the step
halved when Newton struggles and lengthened when it converges fast.

Between the two folds three orbits coexist: the upper and lower branches are stable, the middle
one is a saddle (a Floquet multiplier outside the unit circle). A slow sweep of the frequency
follows a stable branch to its fold and jumps to the other: :meth:`ResponseCurve.jumps`.

Each orbit costs about 40 ms of solve_ivp; linear interpolation between the orbits of a curve
is good to about 1e-2, the shooting at a given frequency to 1e-10 against a long run.
"""

from __future__ import annotations

import operator
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from .._validation import positive_scalar, real_array, real_scalar
from .resonance import PeriodicOrbit, _flow, _orbit, periodic_orbit

__all__ = ["ResponseCurve", "response_curve"]


def _count(value: Any, name: str, least: int) -> int:
    """Return an integral ``value`` >= ``least`` as an int, or raise naming ``name``.

    Any integral type is welcome (numpy's too: a count read from an array is an np.int64), but
    not a bool or a float, which would be a mistake rather than a count.
    """
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be an integer >= {least}, got a bool")
    try:
        number = operator.index(value)
    except TypeError:
        raise TypeError(f"{name} must be an integer >= {least}, "
                        f"got {type(value).__name__}") from None
    if number < least:
        raise ValueError(f"{name} must be an integer >= {least}, got {number}")
    return number


@dataclass(frozen=True)
class ResponseCurve:
    r"""Periodic orbits along a continuation in the forcing frequency; from :func:`response_curve`.

    Attributes
    ----------
    orbits : tuple
        The :class:`~elliptic_pendulum.driven.resonance.PeriodicOrbit` objects, in the order of the
        arclength.
    frequency, amplitude : ndarray
        :math:`\Omega` and the orbits' amplitudes, along the curve.
    stable : ndarray of bool
        Whether each orbit is stable (both Floquet multipliers inside the unit circle).
    """

    orbits: tuple[PeriodicOrbit, ...]

    @property
    def frequency(self) -> np.ndarray:  # noqa: D102 - documented as an attribute
        return np.array([o.frequency for o in self.orbits])

    @property
    def amplitude(self) -> np.ndarray:  # noqa: D102
        return np.array([o.amplitude for o in self.orbits])

    @property
    def stable(self) -> np.ndarray:  # noqa: D102
        return np.array([o.stable for o in self.orbits])

    def _vertex(self, i: int, values: np.ndarray) -> tuple[float, float, float]:
        """Vertex of the parabola of ``values`` against chord length through orbits i-1..i+1.

        Returns (frequency, amplitude, values) interpolated at the vertex.
        """
        i = min(max(i, 1), len(self.orbits) - 2)
        x = np.array([o.state + (o.frequency,) for o in self.orbits[i - 1:i + 2]])
        s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(x, axis=0), axis=1))])
        c = np.polyfit(s, values[i - 1:i + 2], 2)
        # values[i] is the extreme of the three, so the vertex lies between the neighbours; the
        # clip keeps a flat or rounded-off parabola from reaching past them all the same.
        vertex = float(np.clip(-c[1] / (2 * c[0]), s[0], s[2])) if c[0] != 0 else s[1]
        at = [float(np.polyval(np.polyfit(s, v[i - 1:i + 2], 2), vertex))
              for v in (self.frequency, self.amplitude)]
        return at[0], at[1], float(np.polyval(c, vertex))

    def peak(self) -> tuple[float, float]:
        """Return (frequency, amplitude) of the largest amplitude, interpolated between orbits.

        An interior maximum is refined by the parabola through it and its two neighbours,
        never beyond them. A maximum at an end of the curve (the peak lies outside the range of
        frequencies) is that end orbit itself: there is nothing to interpolate toward, and a
        parabola would extrapolate. So is the largest of one or two orbits.
        """
        amplitude = self.amplitude
        i = int(np.argmax(amplitude))
        if not 0 < i < len(self.orbits) - 1:
            return float(self.frequency[i]), float(amplitude[i])
        omega, top, _ = self._vertex(i, amplitude)
        # The parabola through a maximum rises to at least the largest sample.
        return omega, max(top, float(amplitude[i]))

    def folds(self) -> list[tuple[float, float]]:
        r"""Return the turning points (frequency, amplitude) where :math:`\Omega` reverses.

        Each is the vertex of the parabola :math:`\Omega(s)` through the three orbits around the
        reversal (s the chord length along the curve), with the amplitude interpolated there.
        """
        omega = self.frequency
        turns = np.nonzero(np.diff(np.sign(np.diff(omega))) != 0)[0] + 1
        return [self._vertex(int(i), omega)[:2] for i in turns]

    def jumps(self) -> list[tuple[float, float, float]]:
        r"""Return the jumps of a slow frequency sweep: (frequency, amplitude before, after).

        At each fold a stable branch ends; the sweep lands on the stable orbit of another part
        of the curve at the same frequency (interpolated linearly between two stable orbits).
        """
        omega, amp, stable = self.frequency, self.amplitude, self.stable
        out = []
        for fold_omega, fold_amp in self.folds():
            landing = []
            for i in range(len(omega) - 1):
                if stable[i] and stable[i + 1] and (omega[i] - fold_omega) * (
                        omega[i + 1] - fold_omega) <= 0 and omega[i] != omega[i + 1]:
                    w = (fold_omega - omega[i]) / (omega[i + 1] - omega[i])
                    landing.append(float(amp[i] + w * (amp[i + 1] - amp[i])))
            if landing:
                target = max(landing, key=lambda a: abs(a - fold_amp))
                out.append((fold_omega, fold_amp, target))
        return out


def _correct(x, tangent, forcing, damping, omega0, tol, max_iter=8):
    """Newton on [P(y) - y; t.(X - X0)] = 0 from X0 = x.

    Returns (X, iterations, flow) with the dense flow of the last iteration (which moved X by
    less than tol, so it serves the tangent and the orbit's amplitude), or (None, max_iter, None).
    """
    x0 = x.copy()
    for iteration in range(1, max_iter + 1):
        if x[2] <= 0:
            break
        flow = _flow(x[:2], x[2], forcing, damping, omega0, dense=True)
        end, monodromy, sensitivity, _ = flow
        residual = np.concatenate([end - x[:2], [tangent @ (x - x0)]])
        jacobian = np.vstack([np.column_stack([monodromy - np.eye(2), sensitivity]), tangent])
        delta = np.linalg.solve(jacobian, -residual)
        if np.max(np.abs(delta)) < tol and np.max(np.abs(residual[:2])) < 1e3 * tol:
            return x, iteration, flow
        x = x + delta
    return None, max_iter, None


def _tangent(flow, previous):
    """Return the unit null vector of [M - I | dP/dOmega], on the side of ``previous``."""
    _, monodromy, sensitivity, _ = flow
    rows = np.column_stack([monodromy - np.eye(2), sensitivity])
    t = np.cross(rows[0], rows[1])
    # Under a tiny forcing the state's components are tiny beside the frequency's, and their
    # products in the norm and the dot product underflow: negligible there, not an error.
    with np.errstate(under="ignore"):
        t /= np.linalg.norm(t)
        return t if t @ previous >= 0 else -t


def response_curve(forcing: float, damping: float, omega0: float = 1.0, *,
                   frequencies: npt.ArrayLike = (0.5, 1.5), step: float = 0.02,
                   max_points: int = 2000, tol: float = 1e-10) -> ResponseCurve:
    r"""Continue the periodic orbit of the driven pendulum across a range of frequencies.

    .. math:: P(y_0; \Omega) = y_0, \qquad \mathbf t\cdot\Delta X = h, \quad
              X = (\theta(0), \theta'(0), \Omega)

    Parameters
    ----------
    forcing : float
        F, real.
    damping : float
        :math:`\zeta > 0`.
    omega0 : float, optional
        :math:`\sqrt{g/\ell}`, positive; default 1.
    frequencies : (float, float), optional
        The range of :math:`\Omega`, ``0 < low < high``; the curve starts at ``low`` from the
        linear response and stops when it leaves the range.
    step : float, optional
        Largest arclength step; default 0.02 (steps shrink to ``step / 1000`` where needed).
    max_points : int, optional
        Cap on the number of orbits; default 2000.
    tol : float, optional
        Newton tolerance; default 1e-10.

    Returns
    -------
    ResponseCurve

    Raises
    ------
    ValueError
        For a parameter out of range. RuntimeError if the step collapses. TypeError if
        ``max_points`` is not an integer.

    Examples
    --------
    Forced hard enough to fold: the frequency turns back twice, the middle branch is unstable,
    and a slow sweep jumps at each fold; the pendulum softens, so the peak leans to low
    frequency:

    >>> curve = response_curve(0.15, 0.05, frequencies=(0.6, 1.1), step=0.15)
    >>> [(round(w, 3), round(a, 1)) for w, a in curve.folds()]
    [(0.872, 0.9), (0.781, 1.9)]
    >>> [(round(w, 3), round(a, 1), round(b, 1)) for w, a, b in curve.jumps()]
    [(0.872, 0.9, 1.6), (0.781, 1.9, 0.4)]
    >>> bool(np.any(~curve.stable)), round(curve.peak()[0], 2)
    (True, 0.78)
    """
    forcing = real_scalar(forcing, "forcing")
    damping = positive_scalar(damping, "damping")
    omega0 = positive_scalar(omega0, "omega0")
    bounds = real_array(frequencies, "frequencies")
    if bounds.shape != (2,) or not 0 < bounds[0] < bounds[1]:
        raise ValueError("frequencies must be a range (low, high) with 0 < low < high")
    step = positive_scalar(step, "step")
    tol = positive_scalar(tol, "tol")
    max_points = _count(max_points, "max_points", 2)
    low, high = float(bounds[0]), float(bounds[1])
    first = periodic_orbit(low, forcing, damping, omega0, tol=tol)
    orbits = [first]
    x = np.array([*first.state, low])
    flow = _flow(x[:2], low, forcing, damping, omega0)
    tangent = _tangent(flow, np.array([0.0, 0.0, 1.0]))
    h = step
    while len(orbits) < max_points:
        corrected, iterations, flow = _correct(x + h * tangent, tangent, forcing, damping,
                                               omega0, tol)
        if corrected is None:
            h *= 0.5
            if h < step * 1e-3:
                raise RuntimeError(f"continuation stalled near Omega = {x[2]:.6g}")
            continue
        x = corrected
        tangent = _tangent(flow, tangent)
        if not low <= x[2] <= high:
            break
        orbits.append(_orbit(x[:2], float(x[2]), forcing, damping, omega0, flow))
        if iterations <= 3:
            h = min(step, 1.5 * h)
    return ResponseCurve(tuple(orbits))

