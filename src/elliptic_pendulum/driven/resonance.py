r"""Toward nonlinear resonance: the backbone curve and the periodic orbits of the driven pendulum.

For the chapter "toward nonlinear resonance" (beyond the note, which ends by pointing there).

* The backbone: the angular frequency :math:`2\pi/P` of free motion against its size.
  For swings of amplitude :math:`A \in [0, \pi)`, :math:`\omega(A) = \omega_0/R(A)
  = \pi\omega_0 / (2K_1(\sin(A/2)))`; for rotations, parametrized by the speed v at the bottom
  (:math:`v > 2\omega_0`), :math:`\omega = \pi v / (2K_1(2\omega_0/v))`, the rate of one full turn.
  The weakly nonlinear (Duffing) approximation is :math:`\omega_0(1 - A^2/16)`.
* The damped, driven pendulum

  .. math:: \theta'' + 2\zeta\omega_0\theta' + \omega_0^2\sin\theta = F\cos\Omega t

  has periodic orbits of the forcing period :math:`2\pi/\Omega`. :func:`periodic_orbit` finds one
  by shooting: Newton's method (:func:`scipy.optimize.root`, with the exact Jacobian) on the
  Poincare map :math:`P(y_0) = y(2\pi/\Omega)`, integrated by :func:`scipy.integrate.solve_ivp`
  together with its variational equations. The monodromy matrix :math:`M = \partial P/\partial
  y_0` gives the Floquet multipliers; the orbit is stable when both lie inside the unit circle.
  Their product is :math:`\det M = e^{-2\zeta\omega_0 \cdot 2\pi/\Omega}` (Liouville).

The integration runs in the forcing phase :math:`\tau = \Omega t \in [0, 2\pi]`, so the
sensitivity to :math:`\Omega` (which :mod:`.continuation` needs) comes out of the same run.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt
from scipy import integrate, optimize

from .._validation import FloatOrArray, positive_scalar, real_array, real_scalar, scalar_or_array
from ..elliptic import complete_integral
from ..periods.period import period_ratio

__all__ = ["PeriodicOrbit", "backbone_frequency", "duffing_backbone", "periodic_orbit"]


def backbone_frequency(amplitude: npt.ArrayLike | None = None, omega0: float = 1.0, *,
                       bottom_speed: npt.ArrayLike | None = None) -> FloatOrArray:
    r"""Angular frequency :math:`2\pi/P` of free motion: swings by amplitude, rotations by speed.

    .. math:: \omega(A) = \frac{\pi\,\omega_0}{2K_1(\sin(A/2))}, \qquad
              \omega(v) = \frac{\pi v}{2K_1(2\omega_0/v)}

    Parameters
    ----------
    amplitude : float or array_like, optional
        Amplitude A of a swing, radians, :math:`0 \le A < \pi`.
    omega0 : float, optional
        :math:`\sqrt{g/\ell}`, positive; default 1.
    bottom_speed : float or array_like, optional
        Keyword-only, instead of ``amplitude``: the speed :math:`|\theta'|` at the bottom of a
        rotation, :math:`v > 2\omega_0`; the frequency is that of one full turn.

    Returns
    -------
    float or ndarray
        :math:`\omega`, falling from :math:`\omega_0` at A = 0 to 0 at the separatrix, and rising
        from 0 to :math:`\approx v` on the rotation side.

    Raises
    ------
    ValueError
        If neither or both of ``amplitude`` and ``bottom_speed`` are given, or one is out of range.

    Examples
    --------
    Small swings keep :math:`\omega_0`; a swing of 90 degrees is 15% slower; fast rotations
    turn at about their speed:

    >>> backbone_frequency(0.0, omega0=2.0)
    2.0
    >>> round(backbone_frequency(math.pi / 2), 4)
    0.8472
    >>> round(backbone_frequency(bottom_speed=100.0) / 100, 4)
    0.9999
    """
    omega0 = positive_scalar(omega0, "omega0")
    if (amplitude is None) == (bottom_speed is None):
        raise ValueError("give exactly one of amplitude (a swing) and bottom_speed (a rotation)")
    if amplitude is not None:
        # period() checks 0 <= amplitude < pi and names theta0; say "amplitude" instead.
        a = real_array(amplitude, "amplitude")
        if np.any((a < 0) | (a >= math.pi)):
            raise ValueError(f"amplitude must lie in [0, pi) (a swing); got {a.tolist()!r}")
        # omega0 / R, not 2 pi / period: the period overflows for omega0 below ~1e-308 while the
        # frequency itself is a double (subnormal at worst, hence no underflow trap).
        with np.errstate(under="ignore"):
            return scalar_or_array(omega0 / np.asarray(period_ratio(a)), a)
    v = real_array(bottom_speed, "bottom_speed")
    if np.any(np.abs(v) <= 2 * omega0):
        raise ValueError("bottom_speed must exceed 2 * omega0 in size (a rotation); "
                         f"got {v.tolist()!r}")
    speed = np.abs(v)
    # gamma = 2 w0 / v and its complement sqrt((1 - gamma)(1 + gamma)), with 1 - gamma formed as
    # (v - 2 w0) / v, free of cancellation; the quotients (not (v - 2 w0)(v + 2 w0)) keep every
    # speed up to the largest double in range. A gamma that underflows is 0 to rounding: there
    # the frequency is the speed itself.
    with np.errstate(under="ignore"):
        gamma = 2 * omega0 / speed
        gamma_c = np.sqrt((speed - 2 * omega0) / speed * (1.0 + gamma))
    # speed * (pi / 2K) rather than pi * speed / 2K: the latter overflows beyond 5.7e307. For a
    # subnormal speed (omega0 subnormal too) the frequency is subnormal: rounded, not an error.
    turn = (0.5 * math.pi) / np.asarray(complete_integral(gamma, kc=gamma_c))
    with np.errstate(under="ignore"):
        return scalar_or_array(speed * turn, v)


def duffing_backbone(amplitude: npt.ArrayLike, omega0: float = 1.0) -> FloatOrArray:
    r"""Return the weakly nonlinear (Duffing) backbone, from sin(theta) ~ theta - theta^3/6.

    .. math:: \omega(A) \approx \omega_0\left(1 - \frac{A^2}{16}\right)

    Parameters
    ----------
    amplitude : float or array_like
        Amplitude A, radians, :math:`A \ge 0`.
    omega0 : float, optional
        :math:`\sqrt{g/\ell}`, positive; default 1.

    Returns
    -------
    float or ndarray
        The approximate frequency (negative beyond A = 4, where it means nothing).

    Notes
    -----
    Lindstedt-Poincare (or harmonic balance) on :math:`\theta'' + \omega_0^2(\theta - \theta^3/6)
    = 0`; it agrees with :func:`backbone_frequency` to :math:`O(A^4)`, as
    :math:`1/R = 1 - A^2/16 + A^4/3072 + \dots`.

    Examples
    --------
    >>> duffing_backbone(1.0)
    0.9375

    The two differ by :math:`A^4/3072` at small amplitude:

    >>> difference = backbone_frequency(0.1) - duffing_backbone(0.1)
    >>> abs(difference / (0.1**4 / 3072) - 1) < 1e-3
    True
    """
    a = real_array(amplitude, "amplitude")
    if np.any(a < 0):
        raise ValueError(f"amplitude must be >= 0; got {a.tolist()!r}")
    omega0 = positive_scalar(omega0, "omega0")
    # omega0 - (omega0 A/4)(A/4): no square of A on the way, which overflows from A ~ 1e154
    # even where the result is a double. What underflows (A^2 of a tiny A, a subnormal
    # omega0) is below the rounding of omega0 or rounds to a subnormal: not an error.
    quarter = 0.25 * a
    with np.errstate(under="ignore", over="ignore"):
        result = omega0 - (omega0 * quarter) * quarter
    if not np.all(np.isfinite(result)):
        raise ValueError("amplitude is too large: omega0 (1 - amplitude**2/16) lies beyond the "
                         f"range of doubles; got amplitude {a.tolist()!r}")
    return scalar_or_array(result, a)


@dataclass(frozen=True)
class PeriodicOrbit:
    r"""A periodic orbit of the driven pendulum, of the forcing's period (:func:`periodic_orbit`).

    Attributes
    ----------
    frequency, forcing, damping, omega0 : float
        :math:`\Omega, F, \zeta, \omega_0`.
    state : tuple of float
        :math:`(\theta, \theta')` at t = 0, where the forcing :math:`F\cos\Omega t` peaks.
    amplitude : float
        Half the peak-to-peak swing, :math:`(\max\theta - \min\theta)/2`, over one period.
    multipliers : ndarray
        The two Floquet multipliers (eigenvalues of the monodromy matrix), complex.
    monodromy : ndarray
        The 2x2 matrix :math:`\partial P/\partial y_0`.
    """

    frequency: float
    forcing: float
    damping: float
    omega0: float
    state: tuple[float, float]
    amplitude: float
    # Arrays take no part in ==: the orbit is identified by its parameters and state.
    multipliers: np.ndarray = field(compare=False)
    monodromy: np.ndarray = field(compare=False)

    @property
    def stable(self) -> bool:
        """Return whether both Floquet multipliers lie inside the unit circle."""
        return bool(np.max(np.abs(self.multipliers)) < 1.0)


_RTOL, _ATOL = 1e-11, 1e-12
# Beyond this damping rate per unit of forcing phase, 2 zeta omega0 / Omega, the flow is stiff:
# DOP853's steps are held to ~1/(rate) by stability, not accuracy, so its cost grew linearly
# with the damping (periodic_orbit took 2.5 s at zeta = 100, 10 s at 1000). LSODA with the
# exact Jacobian takes a few thousand evaluations whatever the damping; at the tighter
# tolerances below, its orbits agree with DOP853's where both are affordable (rate 25 to 120:
# states to 2e-11 of the swing, amplitudes to 3e-13, multipliers to 1e-14). Below the
# threshold nothing changes.
_STIFF_RATE = 50.0
_STIFF_RTOL, _STIFF_ATOL = 3e-14, 1e-15
# The absolute tolerance of the state scales with its size down to this (a normal double even
# times 1e-15); a swing below it would be lost in the tolerance.
_SMALLEST_SIZE = 1e-280
# The smallest nonzero linear response (radians) periodic_orbit resolves: room above
# _SMALLEST_SIZE for the nonlinear and transient parts of the swing.
_SMALLEST_RESPONSE = 1e-270


def _flow(y0, frequency, forcing, damping, omega0, dense=False):
    """Integrate state, monodromy and d/dOmega over one forcing period, in tau = Omega t."""
    w2, c = omega0 * omega0, 2.0 * damping * omega0
    inv = 1.0 / frequency

    def rhs(tau, y):
        th, v, a, b, cc, d, zt, zv = y
        f0 = v * inv
        f1 = (forcing * math.cos(tau) - c * v - w2 * math.sin(th)) * inv
        j10 = -w2 * math.cos(th) * inv
        j11 = -c * inv
        # Phi' = J Phi (rows (a, b), (cc, d)); z' = J z + df/dOmega with df/dOmega = -f/Omega.
        return [f0, f1, inv * cc, inv * d, j10 * a + j11 * cc, j10 * b + j11 * d,
                inv * zv - f0 * inv, j10 * zt + j11 * zv - f1 * inv]

    def jacobian(tau, y):
        th, _, a, b, _, _, zt, _ = y
        j10 = -w2 * math.cos(th) * inv
        j11 = -c * inv
        bend = w2 * math.sin(th) * inv  # d(j10)/d(theta)
        jac = np.zeros((8, 8))
        jac[0, 1] = inv
        jac[1, 0], jac[1, 1] = j10, j11
        jac[2, 4] = jac[3, 5] = inv
        jac[4, 0], jac[4, 2], jac[4, 4] = bend * a, j10, j11
        jac[5, 0], jac[5, 3], jac[5, 5] = bend * b, j10, j11
        jac[6, 1], jac[6, 7] = -inv * inv, inv
        jac[7, 0], jac[7, 1], jac[7, 6], jac[7, 7] = bend * zt - j10 * inv, -j11 * inv, j10, j11
        return jac

    start = [y0[0], y0[1], 1.0, 0.0, 0.0, 1.0, 0.0, 0.0]
    # The absolute tolerance of the state follows its size (the linear response plus the
    # start), or a swing of 1e-8 would be resolved to 1e-15 only, a relative 1e-7, and one
    # below the tolerance not at all (forcing 1e-20 at zeta = 3 gave 114 times the swing).
    # The sensitivities are O(1).
    size = min(1.0, abs(forcing) / abs(complex(w2 - frequency**2, c * frequency)) +
               math.hypot(y0[0], y0[1]))
    if c * inv > _STIFF_RATE:
        atol = [_STIFF_ATOL * max(size, _SMALLEST_SIZE)] * 2 + [_STIFF_ATOL] * 6
        options = {"method": "LSODA", "jac": jacobian, "rtol": _STIFF_RTOL, "atol": atol}
    else:
        atol = [_ATOL * max(size, _SMALLEST_SIZE)] * 2 + [_ATOL] * 6
        options = {"method": "DOP853", "rtol": _RTOL, "atol": atol}
    # solve_ivp's first step size is bounded below by nextafter(0) - 0, a subnormal: an
    # underflow of scipy's own that is no concern of the caller's np.errstate.
    with np.errstate(under="ignore"):
        sol = integrate.solve_ivp(rhs, (0.0, 2 * math.pi), start, dense_output=dense, **options)
    if not sol.success:  # pragma: no cover - a smooth bounded field
        raise RuntimeError(f"solve_ivp failed: {sol.message}")
    end = sol.y[:, -1]
    return end[:2], end[2:6].reshape(2, 2), end[6:], sol


def _amplitude(sol) -> float:
    """Half of max - min of theta over the period, the extrema refined on the dense output."""
    step = 2 * math.pi / 256

    def theta(tau):  # the orbit is periodic: read tau modulo the period
        return float(sol.sol(tau % (2 * math.pi))[0])

    # A swing of 1e-300 (forcing 1e-300) underflows in the dense output's polynomial: its
    # roundings to 0 are below the swing's own, no concern of the caller's np.errstate.
    with np.errstate(under="ignore"):
        samples = sol.sol(np.arange(256) * step)[0]
        extremes = []
        for sign, index in ((1.0, int(np.argmax(samples))), (-1.0, int(np.argmin(samples)))):
            centre = index * step
            found = optimize.minimize_scalar(lambda s, sg=sign: -sg * theta(s),
                                             bounds=(centre - step, centre + step),
                                             method="bounded", options={"xatol": 1e-10})
            extremes.append(sign * max(sign * samples[index], -found.fun))
    return float(0.5 * (extremes[0] - extremes[1]))


def _linear_guess(frequency, forcing, damping, omega0):
    """Return the state at t = 0 of the linear response theta = A cos(Omega t - phi)."""
    response = forcing / complex(omega0**2 - frequency**2, 2 * damping * omega0 * frequency)
    return (response.real, -frequency * response.imag)


def _orbit(state, frequency, forcing, damping, omega0, flow=None) -> PeriodicOrbit:
    """Build the PeriodicOrbit through a converged state (``flow``: its dense _flow, if known)."""
    _, monodromy, _, sol = flow or _flow(state, frequency, forcing, damping, omega0, dense=True)
    return PeriodicOrbit(frequency, forcing, damping, omega0, (float(state[0]), float(state[1])),
                         _amplitude(sol), np.linalg.eigvals(monodromy), monodromy)


def periodic_orbit(frequency: float, forcing: float, damping: float, omega0: float = 1.0, *,
                   guess: npt.ArrayLike | None = None, tol: float = 1e-10) -> PeriodicOrbit:
    r"""Find a periodic orbit of the damped, driven pendulum by shooting.

    .. math:: \theta'' + 2\zeta\omega_0\theta' + \omega_0^2\sin\theta = F\cos\Omega t, \qquad
              P(y_0) = y_0, \quad P = \text{flow over } 2\pi/\Omega

    Parameters
    ----------
    frequency : float
        Forcing frequency :math:`\Omega > 0`.
    forcing : float
        Forcing amplitude F (per unit moment of inertia), real.
    damping : float
        Damping ratio :math:`\zeta > 0`.
    omega0 : float, optional
        :math:`\sqrt{g/\ell}`, positive; default 1.
    guess : (float, float), optional
        Starting state :math:`(\theta, \theta')` at t = 0 for Newton; default: the linear response.
    tol : float, optional
        Tolerance on :math:`|P(y_0) - y_0|`; default 1e-10.

    Returns
    -------
    PeriodicOrbit
        With its amplitude, Floquet multipliers and stability.

    Raises
    ------
    ValueError
        For a parameter out of range; for a forcing whose linear response
        :math:`|F|/|\omega_0^2 - \Omega^2 + 2i\zeta\omega_0\Omega|` is nonzero but below
        1e-270, which the integration cannot resolve.
    RuntimeError
        If Newton's method does not converge from the guess.

    Examples
    --------
    Weak forcing gives the linear response
    :math:`F/|\omega_0^2 - \Omega^2 + 2i\zeta\omega_0\Omega|`, and the multipliers multiply to
    :math:`e^{-2\zeta\omega_0 \cdot 2\pi/\Omega}` (Liouville):

    >>> orbit = periodic_orbit(0.8, 1e-4, 0.1)
    >>> linear = 1e-4 / abs(complex(1 - 0.8**2, 2 * 0.1 * 0.8))
    >>> bool(abs(orbit.amplitude / linear - 1) < 1e-6), orbit.stable
    (True, True)
    >>> bool(abs(np.prod(orbit.multipliers) - np.exp(-0.2 * 2 * np.pi / 0.8)) < 1e-9)
    True
    """
    frequency = positive_scalar(frequency, "frequency")
    forcing = real_scalar(forcing, "forcing")
    damping = positive_scalar(damping, "damping")
    omega0 = positive_scalar(omega0, "omega0")
    tol = positive_scalar(tol, "tol")
    response = abs(forcing) / abs(complex(omega0 * omega0 - frequency * frequency,
                                          2 * damping * omega0 * frequency))
    if 0.0 < response < _SMALLEST_RESPONSE:
        raise ValueError(f"forcing must be 0 or give a linear response |F| / |omega0^2 - "
                         f"Omega^2 + 2i zeta omega0 Omega| of at least {_SMALLEST_RESPONSE:g}; "
                         f"got forcing={forcing!r}, whose response is {response:.3g}")
    start = (_linear_guess(frequency, forcing, damping, omega0) if guess is None
             else real_array(guess, "guess"))
    if np.shape(start) != (2,):
        raise ValueError("guess must be one state (theta, theta')")

    def residual(y):
        end, monodromy, _, _ = _flow(y, frequency, forcing, damping, omega0)
        return end - y, monodromy - np.eye(2)

    found = optimize.root(residual, np.asarray(start, float), jac=True, method="hybr",
                          options={"xtol": 1e-13})
    if np.max(np.abs(residual(found.x)[0])) > tol:
        raise RuntimeError(f"shooting did not converge from {tuple(start)}: {found.message}")
    return _orbit(found.x, frequency, forcing, damping, omega0)
