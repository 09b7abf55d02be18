"""Tests of mechanics.py: the Pendulum's omega0 (6), period (8), position (1), tension (4), energy.

References: Newton's law (2) for the bob, checked with central differences of the position (1)
(independent of the formula for T); the energy (10) evaluated from theta and theta' along the
motion; the textbook tension at the bottom of a swing, m g (3 - 2 cos theta0).
"""

import dataclasses
import math

import numpy as np
import pytest

from elliptic_pendulum.mechanics import Pendulum

STATES = [  # (theta0, dtheta0): a small swing, 170 degrees, a rotation, backwards rotation
    (0.1, 0.0),
    (math.radians(170), 0.0),
    (0.5, 3.0),
    (-2.0, -4.0),
]


def test_omega0_and_small_angle_period():
    p = Pendulum(length=0.5, g=9.81, mass=3.0)
    assert p.omega0 == pytest.approx(math.sqrt(9.81 / 0.5), rel=1e-15)  # (6)
    assert p.small_angle_period == pytest.approx(2 * math.pi * math.sqrt(0.5 / 9.81), rel=1e-15)
    assert Pendulum(1.0).g == 9.80665  # standard gravity by default


def test_frozen_and_plain_floats():
    p = Pendulum(np.float32(2.0), g=10, mass=1)
    assert type(p.length) is float and type(p.g) is float
    with pytest.raises(dataclasses.FrozenInstanceError):
        p.length = 3.0


@pytest.mark.parametrize("name", ["length", "g", "mass"])
@pytest.mark.parametrize("bad", [0.0, -1.0, float("nan"), float("inf"), -float("inf")])
def test_rejects_non_positive_and_non_finite(name, bad):
    with pytest.raises(ValueError, match=name):
        Pendulum(**{"length": 1.0, name: bad})


@pytest.mark.parametrize("name", ["length", "g", "mass"])
@pytest.mark.parametrize("bad", ["1.0", True, None, 1 + 0j, [1.0]])
def test_rejects_non_numbers(name, bad):
    with pytest.raises(TypeError, match=name):
        Pendulum(**{"length": 1.0, name: bad})


def test_solve_uses_omega0():
    p = Pendulum(length=2.0, g=8.0)
    motion = p.solve(1.0, 0.5)
    assert motion.omega0 == p.omega0 == 2.0
    assert motion.theta(0.0) == pytest.approx(1.0) and motion.dtheta(0.0) == pytest.approx(0.5)


@pytest.mark.parametrize("theta0, dtheta0", STATES)
def test_position_on_the_circle_and_matches_1(theta0, dtheta0):
    p = Pendulum(length=1.7)
    motion = p.solve(theta0, dtheta0)
    t = np.linspace(-3, 7, 41)
    x, y = p.position(motion, t)
    np.testing.assert_allclose(np.hypot(x, y), 1.7, rtol=1e-14)
    theta = motion.theta(t)
    np.testing.assert_allclose(x, 1.7 * np.sin(theta), rtol=0, atol=1e-15)
    np.testing.assert_allclose(y, -1.7 * np.cos(theta), rtol=0, atol=1e-15)
    x0, y0 = p.position(motion, 0.0)
    assert isinstance(x0, float)
    assert (x0, y0) == pytest.approx((1.7 * math.sin(theta0), -1.7 * math.cos(theta0)))


@pytest.mark.parametrize("theta0, dtheta0", STATES)
def test_tension_satisfies_newtons_law_2(theta0, dtheta0):
    # (2): m (x, y)'' = T (-sin, cos) + m g (0, -1). The acceleration comes from a 4th-order
    # central difference of the position (1), which never uses the formula for T.
    p = Pendulum(length=0.8, g=9.81, mass=2.5)
    motion = p.solve(theta0, dtheta0)
    t = np.linspace(-2.0, 5.0, 29)
    h = 1e-3

    def pos(s):
        return np.array(p.position(motion, s))

    accel = (-pos(t + 2 * h) + 16 * pos(t + h) - 30 * pos(t) + 16 * pos(t - h)
             - pos(t - 2 * h)) / (12 * h * h)
    theta = motion.theta(t)
    tension = p.tension(motion, t)
    weight = p.mass * p.g * np.array([0.0, -1.0])[:, None]
    force = tension * np.array([-np.sin(theta), np.cos(theta)]) + weight
    scale = p.mass * (p.g + p.length * np.max(np.abs(motion.dtheta(t))) ** 2)
    np.testing.assert_allclose(p.mass * accel, force, rtol=0, atol=1e-6 * scale)


def test_tension_at_rest_and_at_the_bottom_of_a_swing():
    p = Pendulum(length=1.3, g=9.8, mass=0.7)
    assert p.tension(p.solve(0.0), [0.0, 5.0]) == pytest.approx([0.7 * 9.8] * 2, rel=1e-15)
    for degrees in (10, 90, 150, 179):
        theta0 = math.radians(degrees)
        motion = p.solve(theta0)
        bottom = motion.period / 4  # released at rest: the bottom a quarter period later
        expected = 0.7 * 9.8 * (3 - 2 * math.cos(theta0))
        assert p.tension(motion, bottom) == pytest.approx(expected, rel=1e-9)
        # At the turning point theta' = 0, so T = m g cos(theta0), negative above the axis.
        assert p.tension(motion, 0.0) == pytest.approx(0.7 * 9.8 * math.cos(theta0), rel=1e-12)


@pytest.mark.parametrize("theta0, dtheta0", STATES)
def test_energy_is_conserved_and_equals_10(theta0, dtheta0):
    p = Pendulum(length=0.6, g=9.81, mass=1.5)
    motion = p.solve(theta0, dtheta0)
    t = np.linspace(-10, 10, 201)
    x, y = p.position(motion, t)
    speed2 = (p.length * motion.dtheta(t)) ** 2  # (10): |v|^2 = l^2 theta'^2
    energy = 0.5 * p.mass * speed2 + p.mass * p.g * y
    assert np.allclose(energy, p.energy(motion), rtol=1e-12, atol=1e-12 * p.mass * p.g * p.length)
    direct = 0.5 * p.mass * (p.length * dtheta0) ** 2 - p.mass * p.g * p.length * math.cos(theta0)
    assert p.energy(motion) == pytest.approx(direct, rel=1e-13, abs=1e-13)


def test_small_angle_limit_is_the_harmonic_oscillator():
    # (5), (7): theta = theta0 cos(omega0 t) for small theta0, with the (8) period.
    p = Pendulum(length=2.0)
    theta0 = 1e-6
    motion = p.solve(theta0)
    t = np.linspace(0, 10, 11)
    x, _ = p.position(motion, t)
    np.testing.assert_allclose(x, 2.0 * theta0 * np.cos(p.omega0 * t), rtol=0, atol=1e-17)
    assert motion.period == pytest.approx(p.small_angle_period, rel=1e-12)


def test_refuses_a_motion_of_another_pendulum():
    p, q = Pendulum(1.0), Pendulum(2.0)
    with pytest.raises(ValueError, match="omega0"):
        p.tension(q.solve(1.0), 0.0)


@pytest.mark.parametrize(("length", "g"), [(1e-320, 9.81), (1e300, 1e-300)])
def test_omega0_out_of_range_names_length_and_g(length, g):
    # Each parameter is fine on its own, but omega0 = sqrt(g / length) would be inf or 0.
    with pytest.raises(ValueError, match="g / length"):
        Pendulum(length, g=g)
