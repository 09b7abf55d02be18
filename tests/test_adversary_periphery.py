"""Adversarial edge cases of the periphery: series, continuation, resonance, string, period, CLI.

Each expectation comes from an independent source named beside it: mpmath at high precision,
a direct scipy integration at tight tolerance, a brute-force search over the data, or the
documented contract (docs/cli.md: one line on stderr and exit status 2 for a bad argument).
"""

import math

import numpy as np
import pytest

import elliptic_pendulum as ep
from elliptic_pendulum.animation import animate
from elliptic_pendulum.cli import main


# --- counts: any integral type, bools and floats refused by name -----------------------------

def test_response_curve_accepts_numpy_integer_max_points():
    # A count read from an array is an np.int64; it means the same as the int 3, so the curve
    # must be the one that int gives.
    args = dict(frequencies=(1.2, 1.6), step=0.05)
    expected = ep.response_curve(0.1, 0.1, max_points=3, **args)
    curve = ep.response_curve(0.1, 0.1, max_points=np.int64(3), **args)
    assert len(curve.orbits) == 3
    assert np.array_equal(curve.frequency, expected.frequency)


@pytest.mark.parametrize("bad", [True, 3.0, np.float64(3.0), "3"])
def test_response_curve_refuses_non_integer_max_points(bad):
    with pytest.raises(TypeError, match="max_points"):
        ep.response_curve(0.1, 0.1, frequencies=(1.2, 1.6), step=0.05, max_points=bad)


def test_animate_accepts_numpy_integer_frames():
    import matplotlib.pyplot as plt

    anim = animate([ep.solve(1.0)], frames=np.int64(3))
    try:
        # The frames' times are a linspace of that many points, as for the int 3.
        assert len(anim.frame_times) == 3
    finally:
        anim._draw_was_started = True  # never rendered on purpose: no warning at deletion
        plt.close(anim._fig)


@pytest.mark.parametrize("bad", [True, 3.0, np.float64(3.0)])
def test_animate_refuses_non_integer_frames(bad):
    with pytest.raises(TypeError, match="frames"):
        animate([ep.solve(1.0)], frames=bad)


# --- errors name the parameter that is out of range ------------------------------------------

def test_solve_blames_omega0_not_dtheta0_for_a_huge_omega0():
    # At rest (dtheta0 = 0) only omega0 can make c1 = dtheta0**2 - 2 omega0**2 cos(theta0)
    # overflow; the message must name it.
    with pytest.raises(ValueError, match="omega0 is too large") as info:
        ep.solve(0.0, 0.0, 1e200)
    assert "dtheta0 is too large" not in str(info.value)
    with pytest.raises(ValueError, match="dtheta0 is too large"):
        ep.solve(0.0, 1e200, 1.0)
