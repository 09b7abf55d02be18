"""Whether a string stays taut, far from the usual range, and where it goes slack within rounding
of the horizontal, against mpmath's tension and exact motion."""

import math

import pytest

import elliptic_pendulum as ep
from tests.strict import quietly as _silently


@pytest.mark.parametrize("theta0, dtheta0, omega0", [(1.0, 1e200, 1.0), (0.0, 1.0, 1e-300),
                                                     (3.0, -1e300, 1e-5), (2.0, 1e-200, 1.0),
                                                     (1.0, 1e-200, 1e200)])
def test_string_stays_taut_far_out(theta0, dtheta0, omega0):
    # Expectation from the tension T/(m l) = c1 + 3 omega0^2 cos(theta) at the highest point of
    # the motion (c1 = dtheta0^2 - 2 omega0^2 cos(theta0)), in exact mpmath arithmetic, which
    # does not overflow: a rotation (c1 > 2 omega0^2) has its top at theta = pi, a swing its
    # turning point where cos(theta) = -c1 / (2 omega0^2).
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 60
    w2 = ctx.mpf(omega0) ** 2
    c1 = ctx.mpf(dtheta0) ** 2 - 2 * w2 * ctx.cos(ctx.mpf(theta0))
    lowest = c1 - 3 * w2 if c1 > 2 * w2 else c1 + 3 * w2 * (-c1 / (2 * w2))
    assert _silently(ep.string_stays_taut, theta0, dtheta0, omega0) is bool(lowest >= 0)


def _slack_reference(theta0, dtheta0):
    """(t_s, theta_s, theta'_s) in mpmath at 60 digits, omega0 = 1, from the note's motion.

    cos(theta_s) = -e/3 with e = c1 = dtheta0^2 - 2 cos(theta0), and theta'_s^2 = e/3. A swing
    (25) has sin(theta/2) = k sn(t + c2), c2 = F(atan2(s, w), k^2), so the slack point climbing
    toward +theta_max is at F(asin(sin(theta_s/2) / k), k^2) - c2; a rotation (46) has
    theta/2 = am(t / gamma + c4, gamma), c4 = F(theta0/2, gamma^2).
    """
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 60
    th, v = ctx.mpf(theta0), ctx.mpf(dtheta0)
    e = v**2 - 2 * ctx.cos(th)
    angle = ctx.acos(-e / 3)
    s, w = ctx.sin(th / 2), v / 2
    k2 = s**2 + w**2
    if k2 < 1:
        t = ctx.ellipf(ctx.asin(ctx.sin(angle / 2) / ctx.sqrt(k2)), k2) - ctx.ellipf(
            ctx.atan2(s, w), k2)
    else:
        t = ctx.sqrt(1 / k2) * (ctx.ellipf(angle / 2, 1 / k2) - ctx.ellipf(th / 2, 1 / k2))
    return t, angle, ctx.sqrt(e / 3)


@pytest.mark.parametrize("theta0, dtheta0", [
    (-1.3151688112335174, 0.7111294997490709),  # e = 6.0e-17: a swing to 90 degrees + 3e-17
    (-0.6053185607821009, 1.2824358624192067),  # e = 1.8e-15
    (0.0, 1.4142135623730954),  # a push from the bottom to just past 90 degrees: e = 1.3e-15
    (0.0, 1.4142135747144364),  # e = 3.5e-8: Brent's method still resolves it
])
def test_slack_point_within_rounding_of_the_horizontal(theta0, dtheta0):
    # Where the swing only just passes 90 degrees the tension falls too slowly for its
    # rounding: Brent's method found no sign change ("f(a) and f(b) must have different signs")
    # or did not converge. Reference: the slack time from the exact motion in mpmath.
    t_ref, angle, speed = _slack_reference(theta0, dtheta0)
    t, theta = _silently(ep.slack_point, theta0, dtheta0)
    assert abs(t - t_ref) <= 8 * 2.0**-52 * t_ref
    assert abs(theta - angle) <= 4 * 2.0**-52
    flight = _silently(ep.free_flight, theta0, dtheta0)
    assert flight.t_slack == t
    # The flight takes 4 v_y / g, v_y = theta'_s sin(theta_s); duration = t_taut - t_slack
    # carries the rounding of t_taut.
    expected = 4 * speed * _mp_sin(angle)
    assert abs(flight.duration - expected) <= 1e-12 * expected + 2 * math.ulp(flight.t_taut)


def _mp_sin(x):
    import mpmath

    return mpmath.sin(x)
