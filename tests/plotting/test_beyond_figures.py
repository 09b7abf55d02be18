"""The figures of the chapters beyond the note draw what an independent computation gives.

Each figure's data, read back from the axes, is compared with mpmath (R, K1, the nome) or with
scipy's solve_ivp (the swing, the string's tension, the projectile, the backbone's period),
never with the library's own formula; each helper returns the axes it was given and leaves
matplotlib's rcParams as they were.
"""

from __future__ import annotations

import math

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import mpmath  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402

import elliptic_pendulum as ep  # noqa: E402
import elliptic_pendulum.plotting as epp  # noqa: E402
from tests import mpref  # noqa: E402


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


@pytest.fixture(scope="module")
def curve():
    return ep.response_curve(0.15, 0.05, frequencies=(0.6, 1.1), step=0.1)


def _pendulum(t, y):
    return [y[1], -math.sin(y[0])]




def test_approximation_errors_are_those_against_mpmath():
    x = np.radians([1, 30, 90, 150, 170, 179, 179.9, 179.999])
    ax = epp.approximation_error_plot(amplitudes=x)
    approximations = ep.ratio_approximations(x)
    assert [ln.get_label() for ln in ax.lines] == list(approximations)
    for line, values in zip(ax.lines, approximations.values(), strict=True):
        with mpmath.workdps(40):
            exact = np.array([float(abs(mpmath.mpf(float(v)) / mpref.ratio(a, 40) - 1))
                              for v, a in zip(values, x, strict=True)])
        drawn = np.nan_to_num(line.get_ydata(), nan=0.0)
        # the error of the figure's R (the AGM to convergence), relative
        assert np.max(np.abs(drawn - exact) / (1 + exact)) < 1e-14, line.get_label()
        assert np.array_equal(line.get_xdata(), x / math.pi)   # logit axis: theta0 / pi
    assert ax.get_xscale() == "logit" and ax.get_yscale() == "log"


def test_approximation_error_plot_default_range_and_bad_amplitudes():
    ax = epp.approximation_error_plot()
    x = ax.lines[0].get_xdata() * 180
    assert x[0] == pytest.approx(1) and x[-1] == pytest.approx(179.999, abs=1e-9)
    with pytest.raises(ValueError, match="amplitudes"):
        epp.approximation_error_plot(amplitudes=[0.5, math.pi])


def test_harmonics_swing_is_the_integrated_one_and_dots_match_mpmath_nome():
    degrees = [30, 150, 179]
    left, right = epp.harmonics_plot(degrees, n=8)
    for i, d in enumerate(degrees):
        a = math.radians(d)
        s, y = left.lines[i].get_data()
        # the integrator from the upward passage through the bottom, speed 2 sin(a/2) (9)
        T = float(4 * mpref.ratio(a, 40) * mpmath.pi / 2)
        every = slice(0, None, 100)
        run = solve_ivp(_pendulum, (0, T), [0.0, 2 * math.sin(a / 2)], method="DOP853",
                        rtol=1e-12, atol=1e-12, t_eval=s[every] * T)
        assert np.max(np.abs(run.y[0] / a - y[every])) < 1e-8
        with mpmath.workdps(30):
            q = mpmath.qfrom(m=mpmath.sin(mpmath.mpf(a) / 2) ** 2)
            b = [8 * q ** (j + mpmath.mpf(1) / 2) / ((2 * j + 1) * (1 + q ** (2 * j + 1)))
                 for j in range(8)]
            ratio = np.array([float(bj / b[0]) for bj in b])
        dots = right.lines[2 * i].get_ydata()
        crosses = right.lines[2 * i + 1]
        assert right.lines[2 * i].get_marker() == "o" and crosses.get_marker() == "x"
        assert np.max(np.abs(dots / ratio - 1)) < 1e-12
        # the FFT's crosses sit on the same values where they are above rounding
        j = (crosses.get_xdata().astype(int) - 1) // 2     # harmonic 2j + 1
        big = ratio[j] > 1e-10
        assert big.sum() >= 2
        assert np.max(np.abs(crosses.get_ydata()[big] / ratio[j][big] - 1)) < 1e-6


def test_harmonics_plot_rejects_bad_input():
    with pytest.raises(ValueError, match="amplitudes_deg"):
        epp.harmonics_plot([180])
    with pytest.raises(ValueError, match="n must"):
        epp.harmonics_plot([30], n=300)


def test_string_flight_is_the_integrated_projectile_from_the_integrated_slack_point():
    kick = 1.8
    ax = epp.string_flight_plot(0.0, kick)
    arc, flight, after, dot = ax.lines[1:5]

    def tension(t, y):          # T / (m l w0^2) on the circle
        return y[1] ** 2 + math.cos(y[0])

    tension.terminal, tension.direction = True, -1
    on = solve_ivp(_pendulum, (0, 20), [0.0, kick], method="DOP853", rtol=1e-13,
                   atol=1e-13, events=tension)
    th_s, w_s = on.y_events[0][0]
    assert np.allclose(dot.get_xydata()[0], [math.sin(th_s), -math.cos(th_s)], atol=1e-9)
    assert np.allclose(arc.get_xydata()[-1], dot.get_xydata()[0], atol=1e-9)
    vx, vy = w_s * math.cos(th_s), w_s * math.sin(th_s)
    fx, fy = flight.get_data()
    s = np.linspace(0.0, 4 * vy, len(fx))          # the flight lasts 4 v_y / g, g = 1
    fly = solve_ivp(lambda t, y: [y[2], y[3], 0.0, -1.0], (0, s[-1]),
                    [math.sin(th_s), -math.cos(th_s), vx, vy], method="DOP853",
                    rtol=1e-12, atol=1e-13, t_eval=s)
    assert np.max(np.hypot(fly.y[0] - fx, fly.y[1] - fy)) < 1e-8
    # after the jerk the bob is on the circle again, starting where the flight landed
    ax_, ay_ = after.get_data()
    assert np.allclose(np.hypot(ax_, ay_), 1.0, atol=1e-12)
    assert math.hypot(ax_[0] - fx[-1], ay_[0] - fy[-1]) < 1e-9


def test_string_flight_plot_returns_ax_and_refuses_a_taut_string():
    fig, ax = plt.subplots()
    assert epp.string_flight_plot(0.0, 2.0, ax=ax, legend=False) is ax
    assert ax.get_legend() is None
    with pytest.raises(ValueError, match="stays taut"):
        epp.string_flight_plot(0.0, 3.0)          # e = 7 >= 3: taut forever


def test_string_phase_plane_classes_agree_with_integrated_tension():
    ax = epp.string_phase_plane()
    mesh = ax.collections[0]
    kind = mesh.get_array().reshape(601, 601)
    th = np.linspace(-math.pi, math.pi, 601)
    v = np.linspace(-3.5, 3.5, 601)
    rng = np.random.default_rng(7)
    checked = 0
    for i, j in rng.integers(0, 601, size=(60, 2)):
        a, w = th[j], v[i]
        e = w * w - 2 * math.cos(a)
        if min(abs(e), abs(e - 3)) < 0.05:
            continue                       # a border: sampled times could miss a dip
        run = solve_ivp(_pendulum, (0, 30), [a, w], method="DOP853", rtol=1e-10,
                        atol=1e-10, t_eval=np.linspace(0, 30, 3001))
        T = run.y[1] ** 2 + np.cos(run.y[0])
        expected = 2 if T[0] < 0 else (0 if T.min() >= 0 else 1)
        assert kind[i, j] == expected, (a, w)
        checked += 1
    assert checked > 40


def test_backbone_against_the_integrated_period():
    w0 = 1.3
    ax = epp.backbone_plot(w0)
    deg, w = ax.lines[0].get_data()
    for i in (50, 400, 700):
        a = math.radians(deg[i])

        def up(t, y):
            return y[0]

        up.direction = 1
        run = solve_ivp(lambda t, y: [y[1], -w0**2 * math.sin(y[0])], (0, 200),
                        [0.0, 2 * w0 * math.sin(a / 2)], method="DOP853", rtol=1e-12,
                        atol=1e-13, events=up)
        returns = run.t_events[0][run.t_events[0] > 1e-9]
        assert w[i] * w0 == pytest.approx(2 * math.pi / returns[0], rel=1e-9)
    duffing = ax.lines[1].get_ydata()
    assert np.allclose(duffing, 1 - np.radians(deg) ** 2 / 16, rtol=1e-12)


def test_backbone_against_energy_rotations_by_mpmath():
    ax = epp.backbone_plot(against="energy", duffing=False, points=([0.0], [0.5]))
    h, w = ax.lines[1].get_data()          # the rotations
    for i in (0, 200, 399):
        # a rotation with h = beta: gamma^2 = 2 / (h + 1), omega = pi / (gamma K1(gamma))
        with mpmath.workdps(30):
            g2 = 2 / (mpmath.mpf(h[i]) + 1)
            expected = float(mpmath.pi / (mpmath.sqrt(g2) * mpmath.ellipk(g2)))
        assert w[i] == pytest.approx(expected, rel=1e-6 if i == 0 else 1e-12)
    assert ax.lines[2].get_label() == "solve_ivp"
    with pytest.raises(ValueError, match="against"):
        epp.backbone_plot(against="time")


def test_response_plot_draws_the_curve_its_folds_jumps_and_backbone(curve):
    fig, ax = plt.subplots()
    assert epp.response_plot(curve, ax=ax, duffing=True, linear=(0.15, 0.05),
                             points=([0.8], [0.5])) is ax
    n = len(curve.orbits) - 1
    stable = curve.stable
    for i, seg in enumerate(ax.lines[:n]):
        assert seg.get_linestyle() == ("-" if stable[i] and stable[i + 1] else "--")
        assert np.array_equal(seg.get_xdata(), curve.frequency[i:i + 2])
        assert np.array_equal(seg.get_ydata(), curve.amplitude[i:i + 2])
    lines = {ln.get_label(): ln for ln in ax.lines}
    bw, ba = lines["exact backbone"].get_data()
    for k in (100, 500):
        with mpmath.workdps(30):
            K = mpmath.ellipk(mpmath.sin(mpmath.mpf(ba[k]) / 2) ** 2)
            assert bw[k] == pytest.approx(float(mpmath.pi / (2 * K)), rel=1e-12)
    folds = lines["folds"].get_xydata()
    assert np.allclose(folds, curve.folds())
    lw, la = lines["small-angle response"].get_data()
    assert np.allclose(la * np.hypot(1 - lw**2, 0.1 * lw), 0.15)
    arrows = [(t.xy, t.xyann) for t in ax.texts if t.arrow_patch is not None]
    drawn = [(w, a0, a1) for (w, a1), (_, a0) in arrows]
    assert len(drawn) == 2 and np.allclose(drawn, curve.jumps(), rtol=0, atol=0)
    assert [t.get_text() for t in ax.get_legend().get_texts()][:2] == ["stable", "unstable"]


def test_response_plot_options_off(curve):
    ax = epp.response_plot(curve, backbone=False, folds=False, jumps=False, legend=None,
                           label="x", peak=True)
    assert ax.get_legend() is None and not ax.texts
    assert np.allclose(ax.lines[-1].get_xydata()[0], curve.peak())


def test_sweep_plot_draws_the_sweeps_over_the_curve(curve):
    up = (np.array([0.7, 0.8, 0.9]), np.array([0.4, 0.6, 1.8]))
    down = (np.array([0.95, 0.85, 0.75]), np.array([1.5, 1.85, 0.5]))
    fig, ax = plt.subplots()
    assert epp.sweep_plot(curve, up, down, ax=ax) is ax
    lines = {ln.get_label(): ln for ln in ax.lines}
    assert np.array_equal(lines["sweep up"].get_xydata(), np.column_stack(up))
    assert np.array_equal(lines["sweep down"].get_xydata(), np.column_stack(down))
    assert ax.get_xlim() == (0.7, 0.95) and ax.get_ylim()[1] == pytest.approx(1.1 * 1.85)

