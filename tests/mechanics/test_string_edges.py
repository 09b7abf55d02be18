"""Whether a string stays taut, far from the usual range, against mpmath's tension."""


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
