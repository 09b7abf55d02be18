"""Errors name the parameter that is out of range, not its innocent neighbour."""


import math

import numpy as np
import pytest

import elliptic_pendulum as ep
from tests.strict import quietly as _silently


def test_solve_blames_omega0_not_dtheta0_for_a_huge_omega0():
    # At rest (dtheta0 = 0) only omega0 can make c1 = dtheta0**2 - 2 omega0**2 cos(theta0)
    # overflow; the message must name it.
    with pytest.raises(ValueError, match="omega0 is too large") as info:
        ep.solve(0.0, 0.0, 1e200)
    assert "dtheta0 is too large" not in str(info.value)
    with pytest.raises(ValueError, match="dtheta0 is too large"):
        ep.solve(0.0, 1e200, 1.0)


def test_the_smallest_subnormal_swing_is_refused_naming_theta0():
    # sin(5e-324 / 2) = 2.5e-324 rounds to 0: the swing's modulus has no double (it was
    # returned as 0 with a NaN phase). Twice the angle, 1e-323, still has one: its modulus
    # is 5e-324 and its amplitude 1e-323 (the truth to the last subnormal bit).
    for theta0 in (5e-324, -5e-324, np.array([5e-324, 1.0])):
        with pytest.raises(ValueError, match=r"\btheta0\b"):
            _silently(ep.solve, theta0)
    m = _silently(ep.solve, 1e-323)
    assert m.amplitude == 1e-323 and m.modulus == 5e-324 and math.isfinite(m.phase)
