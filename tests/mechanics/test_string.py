"""Tests of string_pendulum.py: when a string stays taut, where it goes slack, the free flight.

References: scipy's solve_ivp on (3) with the tension (4), T/(m l) = theta'^2 + w0^2 cos theta,
as an event (an integration that shares nothing with the elliptic closed form); the projectile
x'' = 0, y'' = -g integrated by solve_ivp with |r| = l as an event; numpy.roots of the full quartic
|r(s)|^2 = l^2; and the textbook slack condition cos(theta_s) = (2/3) cos(theta_max).
"""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import elliptic_pendulum as ep
from elliptic_pendulum.mechanics import (
    free_flight,
    slack_point,
    string_stays_taut,
)

RTOL, ATOL = 1e-12, 1e-14


def integrate_to_slack(theta0, dtheta0, omega0, horizon):
    """solve_ivp on (3) until the tension theta'^2 + w0^2 cos(theta) falls through zero."""
    w2 = omega0**2

    def rhs(_, y):
        return [y[1], -w2 * math.sin(y[0])]

    def tension(_, y):
        return y[1] ** 2 + w2 * math.cos(y[0])

    tension.terminal, tension.direction = True, -1
    sol = solve_ivp(rhs, (0, horizon), [theta0, dtheta0], method="DOP853", rtol=RTOL,
                    atol=ATOL, events=tension, dense_output=True)
    return sol


STATES = [  # (theta0, dtheta0, omega0): swings above 90 degrees started at various phases,
    (0.0, 1.6, 1.0), (0.0, -1.9, 1.0), (1.0, 1.2, 1.0), (1.0, -1.2, 1.0), (-0.3, 4.0, 2.5),
    (0.0, 1.999, 1.0),  # a swing to 175 degrees
    (0.0, 2.0, 1.0), (0.5, -2.0 * math.cos(0.25), 1.0),  # the separatrix
    (0.0, 2.1, 1.0), (0.0, -2.2, 1.0), (7.0, 1.4, 0.7),  # rotations slower than sqrt(5) w0
    (-7.0, -1.4, 0.7), (20.0, -1.9, 1.0),  # ... turning the other way, some turns from 0
    (2 * math.pi + 1.0, 1.2, 1.0),  # a swing about the bottom one turn up
]


@pytest.mark.parametrize("state", STATES)
def test_slack_point_matches_an_integration_with_a_tension_event(state):
    theta0, dtheta0, omega0 = state
    t, theta = slack_point(theta0, dtheta0, omega0)
    sol = integrate_to_slack(theta0, dtheta0, omega0, horizon=100 / omega0)
    (t_ref,), (y_ref,) = sol.t_events[0], sol.y_events[0]
    assert abs(t - t_ref) < 1e-9 * max(1, t_ref)
    assert abs(theta - y_ref[0]) < 1e-9
    # the slack angle of the energy: cos(theta_s) = -c1 / (3 w0^2)
    c1 = dtheta0**2 - 2 * omega0**2 * math.cos(theta0)
    assert abs(math.cos(theta) + c1 / (3 * omega0**2)) < 1e-12
    assert t > 0


@pytest.mark.parametrize("degrees", [95, 100, 120, 150, 170, 179])
def test_swings_go_slack_at_two_thirds_of_the_cosine_of_the_amplitude(degrees):
    # Pushed from the bottom to reach theta_max: slack where cos(theta) = (2/3) cos(theta_max).
    amplitude = math.radians(degrees)
    speed = 2 * math.sin(amplitude / 2)
    t, theta = slack_point(0.0, speed)
    assert abs(math.cos(theta) - 2 / 3 * math.cos(amplitude)) < 1e-12
    assert 0 < t < ep.period(amplitude) / 4  # before the turning point


def test_slack_at_once_when_the_string_would_have_to_push():
    assert slack_point(math.radians(120)) == (0.0, math.radians(120))  # released from rest
    assert slack_point(math.pi) == (0.0, math.pi)  # balanced upside down: a rod only
    assert slack_point(3.0, 0.5)[0] == 0.0  # near the top, too slow to be held
    assert slack_point(3.0, -0.5)[0] == 0.0


def test_taut_states_have_no_slack_point():
    for state in [(1.0, 0.0), (0.0, 1.41), (0.0, 2.3), (0.0, -2.3), (2.0, 2.3), (0.0, 0.0),
                  (math.pi / 2, 0.0)]:
        assert string_stays_taut(*state)
        assert slack_point(*state) is None
        assert free_flight(*state) is None


def min_tension_by_integration(theta0, dtheta0, omega0):
    """Least T/(m l) over two periods (or 40 / w0 on the separatrix) of an integration."""
    c1 = dtheta0**2 - 2 * omega0**2 * math.cos(theta0)
    span = 40 / omega0 if abs(c1 - 2 * omega0**2) < 1e-9 else 2 * ep.solve(
        theta0, dtheta0, omega0).period + 1
    t = np.linspace(0, span, 20001)
    sol = solve_ivp(lambda _, y: [y[1], -omega0**2 * math.sin(y[0])], (0, span),
                    [theta0, dtheta0], method="DOP853", rtol=RTOL, atol=ATOL, t_eval=t)
    return np.min(sol.y[1] ** 2 + omega0**2 * np.cos(sol.y[0]))


def test_taut_forever_agrees_with_the_integrated_tension():
    rng = np.random.default_rng(9)
    # states spread over the phase plane, plus ones a hair on each side of both borders
    states = [(th, v, w) for th, v, w in zip(rng.uniform(-3, 3, 40), rng.uniform(-3.5, 3.5, 40),
                                             rng.uniform(0.5, 2, 40), strict=True)]
    for w in (1.0, 1.7):
        for eps in (-1e-3, 1e-3):
            states += [(math.pi / 2 + eps, 0.0, w), (0.0, math.sqrt(5) * w + eps, w)]
    for theta0, dtheta0, omega0 in states:
        minimum = min_tension_by_integration(theta0, dtheta0, omega0)
        taut = string_stays_taut(theta0, dtheta0, omega0)
        # a sampled minimum lies a little above the true one; the margins here are 1e-3 w0^2
        assert taut == (minimum > -1e-6 * omega0**2), (theta0, dtheta0, omega0, minimum)


def test_string_stays_taut_is_vectorized_and_checks_input():
    grid = string_stays_taut(np.linspace(-3, 3, 5)[:, None], np.linspace(-3, 3, 7))
    assert grid.shape == (5, 7) and grid.dtype == bool
    with pytest.raises(ValueError, match="omega0"):
        string_stays_taut(0.1, 0.0, omega0=-1.0)
    with pytest.raises(ValueError, match="theta0"):
        string_stays_taut(math.nan)
    with pytest.raises(TypeError, match="theta0"):
        slack_point([0.1, 0.2])


def projectile_landing(x0, y0, vx, vy, g):
    """solve_ivp of the projectile until |r| = 1 is crossed outwards."""

    def outside(_, y):
        return y[0] ** 2 + y[1] ** 2 - 1.0

    outside.terminal, outside.direction = True, 1
    sol = solve_ivp(lambda _, y: [y[2], y[3], 0.0, -g], (0, 100), [x0, y0, vx, vy],
                    method="DOP853", rtol=RTOL, atol=ATOL, events=outside,
                    first_step=1e-3)
    return sol.t_events[0][0], sol.y_events[0][0]


@pytest.mark.parametrize("state", STATES + [(math.radians(120), 0.0, 1.0), (3.0, -0.5, 2.0)])
def test_free_flight_matches_an_integrated_projectile(state):
    flight = free_flight(*state)
    g = state[2] ** 2
    th, w = flight.theta_slack, flight.dtheta_slack
    x0, y0, vx, vy = math.sin(th), -math.cos(th), w * math.cos(th), w * math.sin(th)
    duration, landing = projectile_landing(x0, y0, vx, vy, g)
    assert abs(flight.duration - duration) < 1e-9 * max(1, duration)
    x, y = flight.position(flight.t_taut)
    assert abs(x - landing[0]) < 1e-9 and abs(y - landing[1]) < 1e-9
    assert np.allclose(flight.velocity_taut, landing[2:], atol=1e-9)
    assert abs(math.sin(flight.theta_taut) - x) < 1e-12
    assert abs(-math.cos(flight.theta_taut) - y) < 1e-12
    # inside the circle all the way between the two ends
    xs, ys = flight.position(np.linspace(flight.t_slack, flight.t_taut, 101)[1:-1])
    assert np.all(np.hypot(xs, ys) < 1)
    # the velocity splits into tangential and radial parts
    assert abs(flight.dtheta_taut**2 + flight.radial_speed**2 - vx**2
               - (vy - g * flight.duration) ** 2) < 1e-12 * (1 + vx**2 + vy**2)
    assert flight.radial_speed > 0


def test_flight_time_is_the_root_of_the_quartic():
    # |r(s)|^2 - 1 as a polynomial in s, solved by numpy: a triple root at 0 and 4 vy / g.
    flight = free_flight(0.0, 2.2, 1.3)
    g = 1.3**2
    th, w = flight.theta_slack, flight.dtheta_slack
    x0, y0, vx, vy = math.sin(th), -math.cos(th), w * math.cos(th), w * math.sin(th)
    quartic = np.polyadd(np.polymul([vx, x0], [vx, x0]),
                         np.polymul([-g / 2, vy, y0], [-g / 2, vy, y0]))
    quartic = np.polysub(quartic, [1.0])
    roots = np.roots(quartic)
    largest = max(roots, key=lambda r: r.real)
    assert abs(largest.imag) < 1e-12 and abs(largest.real - flight.duration) < 1e-9
    assert abs(flight.duration - 4 * vy / g) < 1e-14
    assert np.sum(np.abs(roots) < 1e-4) == 3  # the triple root at s = 0, to root-finding accuracy


def test_position_refuses_times_outside_the_flight():
    flight = free_flight(0.0, 2.0)
    with pytest.raises(ValueError, match="t must lie"):
        flight.position(flight.t_taut + 1)
