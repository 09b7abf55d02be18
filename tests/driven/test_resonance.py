"""Tests of resonance.py and continuation.py: the backbone, shooting, Floquet, the response curve.

References: periods measured by solve_ivp with turning-point and full-turn events, and mpmath's
ellipk at 60 digits (the backbone); the linear response F / |w0^2 - W^2 + 2 i z w0 W| (weak
forcing); Liouville's formula det M = exp(-2 z w0 T); long solve_ivp runs of the driven pendulum,
written here with their own right-hand side, run until the transient has decayed (steady states,
stability, jumps).
"""

import math

import mpmath
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from elliptic_pendulum.driven import (
    backbone_frequency,
    duffing_backbone,
    periodic_orbit,
    response_curve,
    settle,
    sweep,
)

# A curve that folds under light damping: the peak near 1.86 rad, where the exact backbone and the
# Duffing one differ by 2e-3, a hundred times the peak's distance from the backbone.
F, ZETA, W0 = 0.015, 0.005, 1.0
# A curve that folds under ten times more damping, whose transients die within 80 periods: the
# one compared with long runs.
F_FAST, ZETA_FAST = 0.15, 0.05


@pytest.fixture(scope="module")
def curve():
    return response_curve(F, ZETA, W0, frequencies=(0.6, 1.1), step=0.05)


@pytest.fixture(scope="module")
def fast_curve():
    return response_curve(F_FAST, ZETA_FAST, W0, frequencies=(0.4, 1.2), step=0.12)


def free_period(theta0, dtheta0, omega0):
    """Period by solve_ivp: a swing's turning points, or a rotation's full turn."""
    rhs = lambda _, y: [y[1], -omega0**2 * math.sin(y[0])]  # noqa: E731
    if dtheta0 == 0.0:
        event = lambda _, y: y[1]  # noqa: E731
        event.direction = 1  # the turning point at -theta0, half a period on
        factor = 2.0
    else:
        event = lambda _, y: y[0] - theta0 - 2 * math.pi  # noqa: E731
        factor = 1.0
    event.terminal = True
    sol = solve_ivp(rhs, (0, 1000), [theta0, dtheta0], method="DOP853", rtol=1e-12,
                    atol=1e-14, events=event, first_step=1e-6)
    return factor * sol.t_events[0][0]


# Up to 3 rad: closer to the top the integrator's own error over the long period exceeds 1e-9.
@pytest.mark.parametrize("amplitude", [0.1, 1.0, 2.0, 3.0])
def test_backbone_of_swings_matches_integrated_periods(amplitude):
    expected = 2 * math.pi / free_period(amplitude, 0.0, 1.3)
    assert abs(backbone_frequency(amplitude, 1.3) / expected - 1) < 1e-9


@pytest.mark.parametrize("speed", [2.05, 2.5, 4.0, 20.0])
def test_backbone_of_rotations_matches_integrated_turns(speed):
    expected = 2 * math.pi / free_period(0.0, speed * 0.7, 0.7)
    assert abs(backbone_frequency(bottom_speed=speed * 0.7, omega0=0.7) / expected - 1) < 1e-9
    assert backbone_frequency(bottom_speed=-speed) == backbone_frequency(bottom_speed=speed)


def test_backbone_matches_mpmath_up_to_the_separatrix():
    amplitudes = np.concatenate([np.linspace(0, 3, 31), math.pi - np.geomspace(1e-12, 0.1, 12)])
    speeds = 2 + np.geomspace(1e-12, 10, 20)
    got_a = backbone_frequency(amplitudes)
    got_v = backbone_frequency(bottom_speed=speeds)
    with mpmath.workdps(60):  # 1 - m down to 1e-25 needs more than 30 digits
        want_a = [float(mpmath.pi / (2 * mpmath.ellipk(mpmath.sin(mpmath.mpf(a) / 2) ** 2)))
                  for a in amplitudes]
        want_v = [float(mpmath.pi * mpmath.mpf(v) / (2 * mpmath.ellipk(4 / mpmath.mpf(v) ** 2)))
                  for v in speeds]
    assert np.allclose(got_a, want_a, rtol=1e-13, atol=0)
    assert np.allclose(got_v, want_v, rtol=1e-13, atol=0)


def test_duffing_backbone_is_the_exact_one_to_order_four():
    a = np.linspace(0.02, 0.2, 10)
    gap = backbone_frequency(a) - duffing_backbone(a)
    # 1/R = 1 - A^2/16 + A^4/3072 + O(A^6) (the series of R, OEIS A223067)
    assert np.allclose(gap / (a**4 / 3072), 1, rtol=0.01)
    # and at large amplitude it is off: by 9.7% at 170 degrees
    assert duffing_backbone(math.radians(170)) / backbone_frequency(math.radians(170)) > 1.09


@pytest.mark.parametrize("bad", [{"amplitude": math.pi}, {"amplitude": -0.1},
                                 {"bottom_speed": 2.0}, {"bottom_speed": 1.0}, {},
                                 {"amplitude": 1.0, "bottom_speed": 3.0}])
def test_backbone_refuses_bad_input(bad):
    with pytest.raises(ValueError):
        backbone_frequency(**bad)


def driven_rhs(frequency, forcing, damping, omega0):
    def rhs(t, y):
        return [y[1], forcing * math.cos(frequency * t) - 2 * damping * omega0 * y[1]
                - omega0**2 * math.sin(y[0])]
    return rhs


def long_run(frequency, state, periods, forcing=F_FAST, damping=ZETA_FAST, omega0=W0):
    """State after whole forcing periods, and the half peak-to-peak over the last one."""
    period = 2 * math.pi / frequency
    rhs = driven_rhs(frequency, forcing, damping, omega0)
    end = periods * period
    sol = solve_ivp(rhs, (0, end), list(state), method="DOP853", rtol=1e-11, atol=1e-12,
                    dense_output=True)
    theta = sol.sol(np.linspace(end - period, end, 20001))[0]
    return sol.y[:, -1], 0.5 * (theta.max() - theta.min())


@pytest.mark.parametrize("frequency", [0.3, 0.8, 0.97, 1.0, 1.05, 2.0])
def test_weak_forcing_gives_the_linear_response(frequency):
    forcing, damping = 1e-4, 0.05
    orbit = periodic_orbit(frequency, forcing, damping)
    linear = forcing / abs(complex(1 - frequency**2, 2 * damping * frequency))
    # the first nonlinear correction is relative O(A^2 / 8) < 1e-5 here
    assert abs(orbit.amplitude / linear - 1) < 1e-5
    assert orbit.stable


@pytest.mark.parametrize("frequency, damping", [(0.5, 0.1), (0.9, 0.005), (1.3, 0.2)])
def test_floquet_multipliers_obey_liouville(frequency, damping):
    orbit = periodic_orbit(frequency, 0.01, damping, omega0=1.2)
    expected = math.exp(-2 * damping * 1.2 * 2 * math.pi / frequency)
    assert abs(np.prod(orbit.multipliers).real / expected - 1) < 1e-7
    assert abs(np.linalg.det(orbit.monodromy) / expected - 1) < 1e-7


def test_shooting_orbit_is_where_a_long_run_from_rest_settles():
    frequency, forcing, damping = 0.7, 0.05, 0.05
    orbit = periodic_orbit(frequency, forcing, damping)
    # the transient decays like exp(-z w0 t): 150 periods take it below 1e-12
    end, amplitude = long_run(frequency, (0.0, 0.0), 150, forcing, damping)
    assert np.max(np.abs(end - orbit.state)) < 1e-8
    assert abs(amplitude - orbit.amplitude) < 1e-8


def test_curve_folds_twice_with_an_unstable_middle_branch(curve):
    folds = curve.folds()
    assert len(folds) == 2
    # stable, unstable, stable along the arclength, switching at the folds
    changes = np.nonzero(np.diff(curve.stable.astype(int)))[0]
    assert len(changes) == 2
    assert not curve.stable[changes[0] + 1] and curve.stable[changes[1] + 1]
    # the pendulum softens: the upper fold lies at the lower frequency
    (w_low_amp, a_low), (w_high_amp, a_high) = sorted(folds, key=lambda f: f[1])
    assert w_high_amp < w_low_amp and a_high > a_low


def test_peak_bends_along_the_exact_backbone_not_duffings(curve):
    omega, amplitude = curve.peak()
    exact = abs(omega - backbone_frequency(amplitude))
    duffing = abs(omega - duffing_backbone(amplitude))
    # light damping puts the peak O(zeta^2) from the backbone: 3e-5 here
    assert exact < 10 * ZETA**2 < duffing


def test_curve_points_are_periodic_orbits_with_the_right_stability(fast_curve):
    # orbits of the bistable range, on all three branches, against runs from nearby states
    fold_omegas = [f[0] for f in fast_curve.folds()]
    inside = [i for i, w in enumerate(fast_curve.frequency)
              if min(fold_omegas) + 0.01 < w < max(fold_omegas) - 0.01]
    assert not all(fast_curve.stable[inside]) and any(fast_curve.stable[inside])
    unstable = [i for i in inside if not fast_curve.stable[i]]
    chosen = inside[:: max(1, len(inside) // 5)] + unstable[len(unstable) // 2:][:1]
    for i in chosen:
        orbit = fast_curve.orbits[i]
        start = np.array(orbit.state) + 1e-6
        end, _ = long_run(orbit.frequency, start, 60)
        distance = np.max(np.abs(end - orbit.state))
        if orbit.stable:
            assert distance < 1e-7, i  # the perturbation decays like exp(-z w0 t)
        else:
            assert distance > 1e-3, i  # a saddle: the perturbation grows away


@pytest.mark.parametrize("frequency", [0.5, 0.75, 0.82, 0.9, 1.1])
def test_curve_amplitude_matches_a_long_run(fast_curve, frequency):
    # the long run starts at rest; in the bistable range it picks one of the stable orbits
    state, amplitude = long_run(frequency, (0.0, 0.0), 80)
    omega, stable = fast_curve.frequency, fast_curve.stable
    # shooting at this very frequency from the nearest stable orbit of the curve
    near = min((i for i in range(len(omega)) if stable[i]),
               key=lambda i: abs(omega[i] - frequency) + abs(
                   fast_curve.amplitude[i] - amplitude))
    orbit = periodic_orbit(frequency, F_FAST, ZETA_FAST, guess=fast_curve.orbits[near].state)
    assert np.max(np.abs(state - orbit.state)) < 1e-8
    assert abs(orbit.amplitude - amplitude) < 1e-8
    assert orbit.stable


def test_jumps_land_where_a_sweep_across_the_fold_lands(fast_curve):
    jumps = fast_curve.jumps()
    assert len(jumps) == 2
    for omega, before, after in jumps:
        # start on the branch that ends at this fold, just inside it ...
        inward = 0.003 if after > before else -0.003
        branch = min((o for o in fast_curve.orbits if o.stable),
                     key=lambda o: abs(o.frequency - omega) + abs(o.amplitude - before))
        orbit = periodic_orbit(omega - inward, F_FAST, ZETA_FAST, guess=branch.state)
        # (the branch is steep near its fold: the amplitude moves like the root of the distance)
        assert orbit.stable and abs(orbit.amplitude - before) < abs(orbit.amplitude - after) / 3
        # ... and step the frequency past the fold: the run ends on the other branch
        _, amplitude = long_run(omega + inward, orbit.state, 150)
        assert abs(amplitude - after) < 0.02


def test_settle_reaches_the_shooting_orbit():
    # sweep.settle shares no code with the shooting: two routes to one steady state
    orbit = periodic_orbit(1.1, F_FAST, ZETA_FAST)
    state, amplitude = settle(1.1, F_FAST, ZETA_FAST, periods=100)
    assert np.max(np.abs(np.subtract(state, orbit.state))) < 1e-9
    assert abs(amplitude - orbit.amplitude) < 1e-7  # 4001 samples of the last period
    # and too short a run is still in its transient: the comparison can fail
    short, _ = settle(1.1, F_FAST, ZETA_FAST, periods=3)
    assert np.max(np.abs(np.subtract(short, orbit.state))) > 1e-3


def test_a_slow_sweep_jumps_at_the_folds_of_the_curve(fast_curve):
    jumps = {("up" if after > before else "down"): (omega, before, after)
             for omega, before, after in fast_curve.jumps()}
    # up through the bistable range from rest: on the lower branch until its fold, then up
    omega, before, after = jumps["up"]
    grid = np.round(omega + np.arange(-3, 3) * 0.01 + 0.005, 4)  # no point on the fold itself
    amplitudes = sweep(grid, F_FAST, ZETA_FAST, periods=60)
    below, above = grid < omega, grid > omega
    middle = 0.5 * (before + after)
    assert np.all(amplitudes[below] < before + 1e-3) and np.all(amplitudes[above] > middle)
    assert abs(amplitudes[above][0] - after) < 0.05  # the first step past the fold lands there
    # down from the upper branch: on it until its fold, then down
    omega, before, after = jumps["down"]
    grid = np.round(omega + np.arange(2, -4, -1) * 0.01 + 0.005, 4)
    upper = periodic_orbit(grid[0], F_FAST, ZETA_FAST, guess=max(
        (o for o in fast_curve.orbits if o.stable), key=lambda o: o.amplitude).state)
    amplitudes = sweep(grid, F_FAST, ZETA_FAST, state=upper.state, periods=60)
    below, above = grid < omega, grid > omega
    middle = 0.5 * (before + after)
    assert np.all(amplitudes[above] > middle) and np.all(amplitudes[below] < middle)
    assert abs(amplitudes[below][0] - after) < 0.05


def test_sweep_refuses_bad_input():
    with pytest.raises(ValueError, match="frequencies"):
        sweep([], 0.1, 0.1)
    with pytest.raises(ValueError, match="frequencies"):
        sweep([1.0, -1.0], 0.1, 0.1)
    with pytest.raises(ValueError, match="periods"):
        settle(1.0, 0.1, 0.1, periods=0)
    with pytest.raises(ValueError, match="state"):
        settle(1.0, 0.1, 0.1, state=(1.0, 2.0, 3.0))


def test_orbits_compare_by_parameters_and_state():
    assert periodic_orbit(0.8, 0.01, 0.1) == periodic_orbit(0.8, 0.01, 0.1)
    assert periodic_orbit(0.8, 0.01, 0.1) != periodic_orbit(0.8, 0.02, 0.1)


def test_periodic_orbit_refuses_bad_input():
    with pytest.raises(ValueError, match="frequency"):
        periodic_orbit(0.0, 0.1, 0.1)
    with pytest.raises(ValueError, match="damping"):
        periodic_orbit(1.0, 0.1, -0.1)
    with pytest.raises(ValueError, match="frequencies"):
        response_curve(0.1, 0.1, frequencies=(1.0, 0.5))
