"""Errors name the parameter that is out of range, not its innocent neighbour."""


import pytest

import elliptic_pendulum as ep


def test_solve_blames_omega0_not_dtheta0_for_a_huge_omega0():
    # At rest (dtheta0 = 0) only omega0 can make c1 = dtheta0**2 - 2 omega0**2 cos(theta0)
    # overflow; the message must name it.
    with pytest.raises(ValueError, match="omega0 is too large") as info:
        ep.solve(0.0, 0.0, 1e200)
    assert "dtheta0 is too large" not in str(info.value)
    with pytest.raises(ValueError, match="dtheta0 is too large"):
        ep.solve(0.0, 1e200, 1.0)
