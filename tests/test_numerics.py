"""Tests of numerics.py: the solve_ivp reference solution of (3).

References: the closed form of motion.py (an independent method: elliptic functions, no time
stepping); the energy integral (9); the harmonic solution (7) of the linearised equation (5);
mpmath's own ODE solver (Taylor series, mpmath.odefun) at 30 digits for one state.
"""

import math

import mpmath
import numpy as np
import pytest

import elliptic_pendulum as ep
from elliptic_pendulum.numerics import integrate


@pytest.mark.parametrize("theta0, dtheta0, omega0", [
    (0.3, 0.0, 1.0), (math.radians(170), 0.0, 2.0), (0.2, 2.5, 1.0), (-1.0, -3.0, 0.5),
])
def test_agrees_with_the_closed_form(theta0, dtheta0, omega0):
    motion = ep.solve(theta0, dtheta0, omega0)
    t = np.linspace(-20, 20, 81)
    theta, dtheta = integrate(theta0, dtheta0, omega0, t=t)
    assert np.max(np.abs(theta - motion.theta(t))) < 1e-6
    assert np.max(np.abs(dtheta - motion.dtheta(t))) < 1e-6 * omega0


def test_tighter_tolerance_is_more_accurate():
    # The error must respond to rtol: a sign that the comparison measures the solver.
    motion = ep.solve(2.5)
    t = np.linspace(0, 30, 7)
    loose = np.abs(integrate(2.5, t=t, rtol=1e-6, atol=1e-8)[0] - motion.theta(t)).max()
    tight = np.abs(integrate(2.5, t=t, rtol=1e-12, atol=1e-14)[0] - motion.theta(t)).max()
    assert tight < loose / 100


def test_matches_mpmath_taylor_integrator():
    with mpmath.workdps(30):
        f = mpmath.odefun(lambda _, y: [y[1], -mpmath.sin(y[0])], 0, [mpmath.mpf(2), mpmath.mpf(0)])
        expected = [float(v) for v in f(3)]
    theta, dtheta = integrate(2.0, t=3.0, rtol=1e-12, atol=1e-14)
    assert (theta, dtheta) == pytest.approx(expected, abs=1e-10)


def test_energy_integral_9():
    theta, dtheta = integrate(1.0, 0.7, 1.5, t=np.linspace(-40, 40, 161))
    c1 = dtheta**2 - 2 * 1.5**2 * np.cos(theta)
    c1_0 = 0.7**2 - 2 * 1.5**2 * math.cos(1.0)
    assert np.max(np.abs(c1 - c1_0)) < 1e-8


def test_small_angle_harmonic_7():
    t = np.linspace(-5, 5, 21)
    theta, _ = integrate(1e-5, 0.0, 3.0, t=t, atol=1e-17)  # atol scaled to the amplitude
    np.testing.assert_allclose(theta, 1e-5 * np.cos(3.0 * t), rtol=0, atol=1e-14)


def test_unsorted_repeated_and_shaped_times():
    t = np.array([[3.0, -1.0, 0.0], [3.0, 2.0, -4.0]])
    theta, dtheta = integrate(1.2, 0.1, t=t)
    assert theta.shape == dtheta.shape == (2, 3)
    assert theta[0, 0] == theta[1, 0]
    assert (theta[0, 2], dtheta[0, 2]) == (1.2, 0.1)  # t = 0 is the initial state itself
    for index in np.ndindex(t.shape):  # one time at a time gives the same
        single = integrate(1.2, 0.1, t=t[index])
        assert single == pytest.approx((theta[index], dtheta[index]), abs=1e-9)
    assert isinstance(integrate(1.2, t=1.0)[0], float)


def test_only_negative_times():
    theta, dtheta = integrate(0.5, 0.0, t=[-1.0, -2.0])
    motion = ep.solve(0.5)
    assert theta == pytest.approx(motion.theta(np.array([-1.0, -2.0])), abs=1e-9)


def test_other_methods():
    theta, _ = integrate(0.5, t=[1.0], method="Radau", rtol=1e-9, atol=1e-11)
    assert theta == pytest.approx([ep.solve(0.5).theta(1.0)], abs=1e-7)


@pytest.mark.parametrize("kwargs, error, name", [
    ({"theta0": float("nan")}, ValueError, "theta0"),
    ({"theta0": [1.0, 2.0]}, TypeError, "theta0"),  # as solve(): one state, not an array
    ({"theta0": "1"}, TypeError, "theta0"),
    ({"dtheta0": float("inf")}, ValueError, "dtheta0"),
    ({"omega0": 0.0}, ValueError, "omega0"),
    ({"omega0": -1.0}, ValueError, "omega0"),
    ({"t": [0.0, float("nan")]}, ValueError, "t"),
    ({"t": "now"}, TypeError, "t"),
    ({"rtol": 0.0}, ValueError, "rtol"),
    ({"atol": -1.0}, ValueError, "atol"),
])
def test_bad_input(kwargs, error, name):
    arguments = {"theta0": 1.0, "t": [1.0]} | kwargs
    with pytest.raises(error, match=name):
        integrate(**arguments)


def test_t_is_required():
    with pytest.raises(TypeError):
        integrate(1.0)
