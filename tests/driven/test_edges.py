"""The driven pendulum at its edges: counts of any integral type, the peak within the data,
the backbone of fast rotations, heavy damping at a bounded cost, silence under errstate.

References: mpmath at high precision, settle() and a brute-force search over a fine grid,
an independent Radau integration of the plain two-dimensional system."""

import math

import numpy as np
import pytest

import elliptic_pendulum as ep
from tests.strict import quietly as _silently


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


def _backbone_reference(speed=None, amplitude=None, omega0=1.0):
    """omega = pi v / (2 K(2 omega0 / v)) or pi omega0 / (2 K(sin(A/2))), mpmath at 50 digits."""
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 50
    if speed is not None:
        gamma = 2 * ctx.mpf(omega0) / ctx.mpf(speed)
        return ctx.pi * ctx.mpf(speed) / (2 * ctx.ellipk(gamma**2))
    return ctx.pi * ctx.mpf(omega0) / (2 * ctx.ellipk(ctx.sin(ctx.mpf(amplitude) / 2) ** 2))


@pytest.mark.parametrize("speed, omega0", [(1e200, 1.0), (1.7e308, 1.0), (1e10, 1e-300),
                                           (1e308, 1e307), (2 + 1e-12, 1.0), (3.0, 1.0)])
def test_backbone_frequency_of_fast_rotations(speed, omega0):
    # A rotation at 1e200 rad/s turns at about 1e200 rad/s: a double answer exists, and it
    # was refused as "kc must be finite" ((v - 2)(v + 2) overflowed).
    with np.errstate(all="raise"):
        got = ep.backbone_frequency(bottom_speed=speed, omega0=omega0)
    expected = _backbone_reference(speed=speed, omega0=omega0)
    assert abs(got - float(expected)) <= 4e-16 * float(expected)


def test_backbone_frequency_of_a_swing_at_tiny_omega0():
    # omega0 / R is a double (9.4e-309) although the period 2 pi R / omega0 overflows; going
    # through the period gave 0.0.
    with np.errstate(all="raise"):
        got = ep.backbone_frequency(1.0, omega0=1e-308)
    expected = float(_backbone_reference(amplitude=1.0, omega0=1e-308))
    # Subnormal: the spacing of doubles there is 4.9e-324, i.e. 5e-16 relative.
    assert abs(got - expected) <= 4 * 5e-324


def test_peak_at_the_end_of_the_curve_is_the_end_orbit():
    # Above resonance the amplitude falls along the whole range, so the largest orbit is the
    # first (brute-force max over the data), and a long run from rest (settle, an independent
    # solve_ivp) settles to the same swing there. A parabola through the first three orbits put
    # its vertex at Omega = 1.568 with amplitude 0.086, smaller than the data's own maximum.
    curve = ep.response_curve(0.1, 0.1, frequencies=(1.2, 1.6), step=0.05)
    largest = int(np.argmax(curve.amplitude))
    assert largest == 0
    omega, amplitude = curve.peak()
    assert (omega, amplitude) == (curve.frequency[0], curve.amplitude[0])
    _, settled = ep.settle(1.2, 0.1, 0.1)
    assert abs(amplitude - settled) < 1e-6


@pytest.mark.parametrize("count", [1, 2])
def test_peak_of_one_or_two_orbits(count):
    # With fewer than three orbits there is no parabola: the peak is the largest orbit (the
    # brute-force max), not a LinAlgError with a LAPACK message on stderr.
    from elliptic_pendulum.driven.continuation import ResponseCurve

    orbits = tuple(ep.periodic_orbit(w, 0.1, 0.1) for w in (1.2, 1.25)[:count])
    best = max(orbits, key=lambda o: o.amplitude)
    assert _silently(ResponseCurve(orbits).peak) == (best.frequency, best.amplitude)


def test_interior_peak_is_refined_between_its_neighbours():
    # Below resonance and through it: the maximum is interior. Its refinement must stay between
    # the neighbouring orbits, at least as high as the largest, and agree with a brute-force
    # max over periodic orbits on a fine grid of frequencies around it (spacing 5e-4).
    curve = ep.response_curve(0.1, 0.1, frequencies=(0.6, 1.0), step=0.05)
    i = int(np.argmax(curve.amplitude))
    assert 0 < i < len(curve.orbits) - 1
    omega, amplitude = curve.peak()
    around = curve.frequency[i - 1:i + 2]
    assert around.min() <= omega <= around.max()
    assert amplitude >= curve.amplitude[i]
    grid = np.linspace(0.970, 0.977, 15)
    fine = [ep.periodic_orbit(w, 0.1, 0.1).amplitude for w in grid]
    assert abs(omega - grid[int(np.argmax(fine))]) < 1e-3
    assert abs(amplitude - max(fine)) < 1e-5


def test_periodic_orbit_and_response_curve_are_quiet_under_errstate_raise():
    # scipy's solve_ivp bounds its first step by nextafter(0) - 0, a subnormal, which raised
    # FloatingPointError under np.errstate(all='raise') on every call. The expectation for the
    # orbit itself: the linear response, as in the docstring, at weak forcing.
    orbit = _silently(ep.periodic_orbit, 0.8, 1e-4, 0.1)
    linear = 1e-4 / abs(complex(1 - 0.8**2, 2 * 0.1 * 0.8))
    assert abs(orbit.amplitude / linear - 1) < 1e-6
    curve = _silently(ep.response_curve, 0.1, 0.1, frequencies=(1.2, 1.3), step=0.05)
    assert len(curve.orbits) >= 2


def _independent_period_map(frequency, forcing, damping, state):
    """One forcing period of theta'' + 2 zeta theta' + sin(theta) = F cos(Omega t) (omega0 = 1),
    by scipy's Radau on the plain 2-D system at rtol 1e-13: none of the library's code."""
    from scipy import integrate

    def field(t, y):
        return [y[1], forcing * math.cos(frequency * t) - 2 * damping * y[1] - math.sin(y[0])]

    def jacobian(t, y):
        return [[0.0, 1.0], [-math.cos(y[0]), -2 * damping]]

    return integrate.solve_ivp(field, (0.0, 2 * math.pi / frequency), list(state),
                               method="Radau", jac=jacobian, rtol=1e-13, atol=1e-22,
                               dense_output=True)


@pytest.mark.parametrize("damping", [100.0, 1000.0])
def test_periodic_orbit_under_heavy_damping_against_an_independent_integration(damping):
    orbit = ep.periodic_orbit(0.8, 0.2, damping)
    run = _independent_period_map(0.8, 0.2, damping, orbit.state)
    swing = orbit.amplitude
    # Periodic: back where it started after one period, to far below the shooting's 1e-10.
    assert np.max(np.abs(run.y[:, -1] - orbit.state)) < 1e-11 * swing
    # The amplitude: half of max - min over the period, brute force over 20001 samples.
    theta = run.sol(np.linspace(0.0, 2 * math.pi / 0.8, 20001))[0]
    assert abs(swing - 0.5 * (theta.max() - theta.min())) < 1e-8 * swing
    # The slow Floquet multiplier (the other is ~exp(-2 zeta 2 pi / Omega), 0 in doubles):
    # the largest eigenvalue of the monodromy by central differences of the independent map.
    h = 1e-4 * swing
    columns = []
    for e in np.eye(2):
        plus = _independent_period_map(0.8, 0.2, damping, orbit.state + h * e).y[:, -1]
        minus = _independent_period_map(0.8, 0.2, damping, orbit.state - h * e).y[:, -1]
        columns.append((plus - minus) / (2 * h))
    expected = np.max(np.abs(np.linalg.eigvals(np.column_stack(columns))))
    assert abs(np.max(np.abs(orbit.multipliers)) - expected) < 1e-7


def test_periodic_orbit_cost_does_not_grow_with_the_damping(monkeypatch):
    # The explicit integrator's steps are bounded by stability to ~1/(2 zeta omega0 / Omega):
    # at zeta = 1000 one period took ~1e5 evaluations of the field. Counted here (not timed):
    # each period must take fewer than 1e4, as at light damping.
    from elliptic_pendulum.driven import resonance

    counts = []
    real = resonance.integrate.solve_ivp

    def counting(*args, **kwargs):
        sol = real(*args, **kwargs)
        counts.append(sol.nfev)
        return sol

    monkeypatch.setattr(resonance.integrate, "solve_ivp", counting)
    ep.periodic_orbit(0.8, 0.2, 1000.0)
    assert counts and max(counts) < 10_000


def test_backbone_frequency_of_a_subnormal_speed_is_quiet():
    # v = 3 * 2^-1074, omega0 = 2^-1074: gamma = 2/3, and the frequency pi v / (2 K) is a
    # subnormal, rounded to the grid of 2^-1074. speed * turn raised FloatingPointError
    # (underflow) under np.errstate(all="raise"). Reference: mpmath at 50 digits.
    got = _silently(ep.backbone_frequency, bottom_speed=1.5e-323, omega0=5e-324)
    expected = _backbone_reference(speed=1.5e-323, omega0=5e-324)
    assert abs(got - expected) <= 2.0**-1074


@pytest.mark.parametrize("amplitude, omega0", [(1e-200, 1.0), (1.0, 5e-324), (0.5, 1e-310),
                                               (1e155, 1e-10), (3.0, 2.0)])
def test_duffing_backbone_is_quiet_wherever_it_is_a_double(amplitude, omega0):
    # A^2 underflowed (tiny A), omega0 (1 - A^2/16) underflowed (subnormal omega0), and A^2
    # overflowed at 1e155 though the result, -6.25e298, is a double. Reference: the exact
    # rational omega0 (1 - A^2/16) of the two doubles, rounded once.
    from fractions import Fraction

    expected = float(Fraction(omega0) * (1 - Fraction(amplitude) ** 2 / 16))
    got = _silently(ep.duffing_backbone, amplitude, omega0)
    assert abs(got - expected) <= 2 * math.ulp(expected)


@pytest.mark.parametrize("amplitude, omega0", [(1e200, 1.0), (1e150, 1e100)])
def test_duffing_backbone_beyond_the_doubles_is_refused_naming_amplitude(amplitude, omega0):
    with pytest.raises(ValueError, match="amplitude is too large"):
        _silently(ep.duffing_backbone, amplitude, omega0)


def _driven_module(name):
    import importlib

    return importlib.import_module(f"elliptic_pendulum.driven.{name}")


def test_settle_and_integrate_with_a_slow_pendulum_are_quiet():
    # omega0 = 1e-3: solve_ivp's smallest step, nextafter(t, inf) - t, underflowed inside scipy
    # and the caller's np.errstate(all="raise") made it an error. The values must be those
    # computed without the trap.
    settle = _driven_module("sweep").settle
    expected = settle(0.5, 0.1, 0.1, omega0=1e-3, periods=3)
    assert _silently(settle, 0.5, 0.1, 0.1, omega0=1e-3, periods=3) == expected
    from elliptic_pendulum import numerics

    times = [0.0, 1.0, 50.0]
    expected = numerics.integrate(1.0, omega0=1e-3, t=times)
    got = _silently(numerics.integrate, 1.0, omega0=1e-3, t=times)
    assert all(np.array_equal(a, b) for a, b in zip(got, expected, strict=True))


def test_response_curve_under_a_tiny_forcing_is_quiet():
    # F = 1e-200: the state's components are 1e-200 beside the frequency's 1, and their
    # products underflowed in the tangent's norm and the dense output's polynomials.
    # Reference: the linear response F / |omega0^2 - Omega^2 + 2i zeta omega0 Omega|, exact to
    # rounding at a swing of 1e-200 (sin(theta) = theta there).
    curve = _silently(ep.response_curve, 1e-200, 0.1, frequencies=(0.6, 0.7), step=0.05)
    omega = curve.frequency
    linear = 1e-200 / np.abs(1 - omega**2 + 2j * 0.1 * omega)
    assert len(omega) >= 2
    assert abs(curve.amplitude[0] / linear[0] - 1) < 1e-9


@pytest.mark.parametrize("damping", [0.1, 3.0, 40.0])
@pytest.mark.parametrize("forcing", [1e-20, 1e-100, 1e-260])
def test_periodic_orbit_of_a_tiny_swing_is_the_linear_response(forcing, damping):
    # The state's absolute tolerance was 1e-12 (DOP853) or floored at 1e-165 (LSODA): a swing
    # below it was not resolved, and forcing 1e-20 at zeta = 3 gave 114 times the swing.
    # Reference: the linear response F / |omega0^2 - Omega^2 + 2i zeta omega0 Omega|, exact to
    # rounding at these swings (sin(theta) = theta to 1e-40 and better).
    orbit = _silently(ep.periodic_orbit, 0.5, forcing, damping)
    linear = forcing / abs(complex(1 - 0.25, 2 * damping * 0.5))
    assert abs(orbit.amplitude / linear - 1) < 1e-9


def test_periodic_orbit_refuses_a_forcing_too_small_to_resolve_naming_forcing():
    with pytest.raises(ValueError, match=r"forcing must be 0 or give a linear response"):
        ep.periodic_orbit(0.5, 1e-300, 0.1)
    assert ep.periodic_orbit(0.5, 0.0, 0.1).amplitude == 0.0
