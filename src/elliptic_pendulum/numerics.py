"""The reference numerical solution of the pendulum equation (3), to compare with the closed form.

The book and the benchmarks set the elliptic-function solution of :mod:`elliptic_pendulum.motion`
beside what a general ODE solver gives, :func:`scipy.integrate.solve_ivp` on (3) written as a
first-order system. Only the figures (:mod:`elliptic_pendulum.plotting`) use it, to draw the
integration beside the closed form.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from scipy import integrate as _integrate

from ._validation import FloatOrArray, positive_scalar, real_array, real_scalar, scalar_or_array

# A Python float for a scalar time, else an array.

__all__ = ["integrate"]


def _run(rhs, state, end, times, method, rtol, atol):
    """Integrate from t = 0 to ``end`` and return the state at ``times`` (ordered towards end)."""
    # solve_ivp's smallest step (nextafter(t, inf) - t) can be subnormal, and a tiny state
    # underflows in its arithmetic: scipy's own roundings to 0, silent whatever the caller's
    # np.errstate.
    with np.errstate(under="ignore"):
        solution = _integrate.solve_ivp(rhs, (0.0, end), state, method=method, t_eval=times,
                                        rtol=rtol, atol=atol)
    if not solution.success:
        raise RuntimeError(f"solve_ivp ({method}) failed: {solution.message}")
    return solution.y


def integrate(theta0: float, dtheta0: float = 0.0, omega0: float = 1.0, *, t: npt.ArrayLike,
              rtol: float = 1e-10, atol: float = 1e-12,
              method: str = "DOP853") -> tuple[FloatOrArray, FloatOrArray]:
    r"""Solve the pendulum equation (3) numerically from an initial state, at the times t.

    .. math:: \theta'' = -\omega_0^2 \sin\theta, \qquad \theta(0) = \theta_0,\;
              \theta'(0) = \dot\theta_0 \quad (3), (6)

    as the system :math:`(\theta, \theta')' = (\theta', -\omega_0^2\sin\theta)`.

    Parameters
    ----------
    theta0 : float
        Initial angle, radians (any real value).
    dtheta0 : float, optional
        Initial angular velocity; default 0.
    omega0 : float, optional
        :math:`\sqrt{g/\ell}` of (6), positive; default 1.
    t : float or array_like
        Output times (keyword-only), in any order and of any shape; negative times are reached by
        integrating backwards from 0.
    rtol, atol : float, optional
        Tolerances passed to :func:`scipy.integrate.solve_ivp`; defaults 1e-10 and 1e-12.
    method : str, optional
        A :func:`scipy.integrate.solve_ivp` method; default ``"DOP853"`` (Dormand-Prince 8(5,3)).

    Returns
    -------
    theta, dtheta : float or ndarray
        :math:`\theta(t)` and :math:`\theta'(t)`, of the shape of ``t``.

    Raises
    ------
    ValueError
        For NaN or infinite input, ``omega0``, ``rtol`` or ``atol`` not positive, or an array
        where one initial value is expected.
    RuntimeError
        If the solver gives up.

    Notes
    -----
    The times are sorted (and repeated ones merged) and handed to ``solve_ivp`` as
    ``t_eval``, so one integration per direction of time serves every point. A general
    solver's error grows with the time span (roughly linearly in the phase), which is the
    contrast the book draws with the closed form, exact at any t.

    Examples
    --------
    A swing of 170 degrees, checked against the closed form (25) over ten periods; close to
    the separatrix the solver's phase error shows at the default tolerances:

    >>> import elliptic_pendulum as ep
    >>> motion = ep.solve(math.radians(170))
    >>> t = np.linspace(-5 * motion.period, 5 * motion.period, 101)
    >>> theta, dtheta = integrate(math.radians(170), t=t)
    >>> bool(np.max(np.abs(theta - motion.theta(t))) < 1e-6)
    True

    and the energy (9), :math:`(\theta')^2 - 2\omega_0^2\cos\theta = c_1`, is kept:

    >>> c1 = dtheta**2 - 2 * np.cos(theta)
    >>> bool(np.max(np.abs(c1 - motion.energy_constant)) < 1e-8)
    True
    """
    theta0, dtheta0 = real_scalar(theta0, "theta0"), real_scalar(dtheta0, "dtheta0")
    omega0 = positive_scalar(omega0, "omega0")
    rtol, atol = positive_scalar(rtol, "rtol"), positive_scalar(atol, "atol")
    times = real_array(t, "t")
    squared = omega0 * omega0

    def rhs(_, y):
        # math.sin on the two scalars: solve_ivp calls this once per stage, and NumPy's
        # per-call overhead would dominate.
        return [y[1], -squared * math.sin(y[0])]

    unique, inverse = np.unique(times, return_inverse=True)
    theta = np.full(unique.shape, theta0)
    dtheta = np.full(unique.shape, dtheta0)
    forward, backward = unique > 0, unique < 0
    if forward.any():
        ahead = unique[forward]
        theta[forward], dtheta[forward] = _run(rhs, [theta0, dtheta0], ahead[-1], ahead,
                                               method, rtol, atol)
    if backward.any():
        # solve_ivp wants t_eval ordered in the direction of integration: descending here.
        behind = unique[backward][::-1]
        y = _run(rhs, [theta0, dtheta0], behind[-1], behind, method, rtol, atol)
        theta[backward], dtheta[backward] = y[0][::-1], y[1][::-1]
    theta = theta[inverse].reshape(times.shape)
    dtheta = dtheta[inverse].reshape(times.shape)
    return scalar_or_array(theta, times), scalar_or_array(dtheta, times)
