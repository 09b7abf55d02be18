"""Tests of period.py: R(theta0) of section 4, the periods (8) and (26), the AGM form, crossings.

References: mpmath.ellipk at 50 digits from the exact double theta0 (independent of our
elliptic.py and of scipy); the AGM (DLMF 19.8.5); the note's table (section 4); DLMF 19.5.1
(the small-amplitude series) and the monotonicity of K.
"""

import math

import mpmath
import numpy as np
import pytest

from elliptic_pendulum.periods import (
    agm_period,
    crossing_angle,
    period,
    period_ratio,
    small_angle_period,
)
from tests import mpref

# Amplitudes spread over the whole range: tiny, moderate, and approaching 180 degrees, where the
# distance to pi runs down to 1e-10 rad and 1e-9 degree.
GRID = np.unique(np.concatenate([
    np.geomspace(1e-8, 1.0, 40),
    np.linspace(0.05, 3.1, 60),
    math.pi - np.geomspace(1e-10, 1.0, 60),
    [math.radians(180 - 1e-9), math.radians(179.9999), math.radians(179.2), 1e-300, 0.0],
]))


def test_period_ratio_matches_mpmath_to_a_few_ulp():
    ours = period_ratio(GRID)
    reference = np.array([float(mpref.ratio(t, 50)) for t in GRID])
    relative = np.abs(ours - reference) / reference
    assert relative.max() <= 1e-15, (GRID[relative.argmax()], relative.max())


def test_period_ratio_one_degree_from_nine_nines():
    # 180 - 1e-9 degrees is the accuracy promise of the module; mpmath gives the value.
    theta0 = math.radians(180 - 1e-9)
    assert period_ratio(theta0) == pytest.approx(float(mpref.ratio(theta0, 50)), rel=1e-15, abs=0)


def test_note_table_three_decimals():
    # The note, section 4 (computed there with gnuplot's complete elliptic integral).
    table = {30: 1.017, 45: 1.040, 60: 1.073, 90: 1.180, 120: 1.373, 135: 1.528, 150: 1.762}
    ours = period_ratio(np.radians(list(table)))
    assert np.round(ours, 3).tolist() == list(table.values())


def test_small_amplitude_series():
    # DLMF 19.5.1: K(k) = pi/2 (1 + k^2/4 + 9 k^4/64 + ...), k = sin(theta0/2).
    theta0 = np.geomspace(1e-6, 1e-2, 9)
    k = np.sin(theta0 / 2)
    series = 1 + k**2 / 4 + 9 * k**4 / 64 + 25 * k**6 / 256
    np.testing.assert_allclose(period_ratio(theta0), series, rtol=3e-16, atol=0)
    assert period_ratio(0.0) == 1.0


def test_monotone_and_unbounded():
    theta0 = np.linspace(0, math.pi, 10001)[:-1]
    assert np.all(np.diff(period_ratio(theta0)) > 0)
    assert period_ratio(math.nextafter(math.pi, 0)) > 23


def test_period_is_ratio_times_small_angle_period():
    theta0 = np.radians([0, 10, 90, 170, 179.9])
    for omega0 in (0.5, 1.0, math.sqrt(9.80665)):
        expected = period_ratio(theta0) * 2 * math.pi / omega0
        np.testing.assert_allclose(period(theta0, omega0), expected, rtol=1e-15)
        # (8) and (26) at zero amplitude agree exactly.
        assert period(0.0, omega0) == small_angle_period(omega0) == 2 * math.pi / omega0


def test_agm_form_agrees_with_26():
    # An independent formula (DLMF 19.8.5) against (26), down to 1e-9 degree below the top.
    assert np.allclose(agm_period(GRID, 2.0), period(GRID, 2.0), rtol=3e-15, atol=0)


def test_agm_form_matches_mpmath():
    theta0 = math.pi - 1e-7
    with mpmath.workdps(50):
        expected = 2 * mpmath.pi / mpmath.agm(1, mpmath.cos(mpmath.mpf(theta0) / 2))
    assert agm_period(theta0) == pytest.approx(float(expected), rel=1e-15)


def test_shapes_broadcast():
    theta0 = np.full((2, 3), 0.5)
    assert period_ratio(theta0).shape == (2, 3)
    assert agm_period(theta0).shape == (2, 3)
    assert isinstance(period_ratio(0.5), float)
    assert crossing_angle(np.array([[2.0, 3.0]])).shape == (1, 2)


@pytest.mark.parametrize("value", [1.0001, 1.5, 2.0, 3.0, 4.0])
def test_crossing_angle_solves(value):
    theta = crossing_angle(value)
    assert 0 < theta < math.pi
    assert period_ratio(theta) == pytest.approx(value, rel=1e-12, abs=0)


@pytest.mark.parametrize("value", [2.0, 4.0, 10.0, 20.0, 23.5])
def test_crossing_angle_is_bracketed_by_its_neighbours(value):
    # Within 1e-6 rad of pi one ulp of theta0 moves R by more than 1e-12, so the honest claim
    # is that R (by mpmath, not by our code) crosses the value within a few doubles of theta.
    theta = crossing_angle(value)
    step = 4 * (math.nextafter(theta, 4) - theta)
    top = math.nextafter(math.pi, 0)  # beyond it the double would be past 180 degrees
    below, above = mpref.ratio(theta - step, 50), mpref.ratio(min(theta + step, top), 50)
    assert float(below) < value < float(above)


def test_crossing_angles_in_the_note():
    # Section 4: R exceeds 2, 3, 4 "at" 160, 176, 179.2 degrees; the exact crossings lie just
    # below these grid angles. The mpmath root of (2/pi) K(sin^2(theta/2)) = v decides.
    degrees = np.degrees(crossing_angle([2, 3, 4]))
    notes = [(160, 1), (176, 1), (179.2, 0.1)]  # (grid angle, grid step) for R = 2, 3, 4
    for value, ours, (note, step) in zip([2, 3, 4], degrees, notes, strict=True):
        assert note - step < ours < note
        with mpmath.workdps(40):
            x = mpmath.findroot(
                lambda x, v=value: 2 / mpmath.pi * mpmath.ellipk(mpmath.cos(x / 2) ** 2) - v,
                (mpmath.mpf("1e-4"), mpmath.mpf(1)), solver="anderson")
            reference = float(180 - mpmath.degrees(x))
        assert ours == pytest.approx(reference, rel=1e-15)


def test_crossing_angle_edges():
    assert crossing_angle(1.0) == 0.0
    assert crossing_angle(1 + 1e-12) > 0


@pytest.mark.parametrize("bad", [-0.1, math.pi, 4.0, float("nan"), float("inf"), [0.1, -1]])
def test_period_ratio_rejects_out_of_range(bad):
    with pytest.raises(ValueError, match="theta0"):
        period_ratio(bad)
    with pytest.raises(ValueError, match="theta0"):
        agm_period(bad)


@pytest.mark.parametrize("bad", ["1", True, 1j, None])
def test_period_ratio_rejects_non_numbers(bad):
    with pytest.raises(TypeError, match="theta0"):
        period_ratio(bad)


@pytest.mark.parametrize("bad", [0.0, -1.0, float("nan"), float("inf")])
def test_omega0_must_be_positive(bad):
    for function in (small_angle_period, lambda w: period(0.5, w), lambda w: agm_period(0.5, w)):
        with pytest.raises(ValueError, match="omega0"):
            function(bad)
    with pytest.raises(TypeError, match="omega0"):
        small_angle_period("2")


@pytest.mark.parametrize("bad", [0.999, 30.0, float("nan"), float("inf")])
def test_crossing_angle_rejects(bad):
    with pytest.raises(ValueError, match="value"):
        crossing_angle(bad)
