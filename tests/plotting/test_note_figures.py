"""The figures: what they draw matches the mathematics, the legends match what is drawn (the
contract every figure keeps, readable text and no global change, is in plotting/test_contract.py).

References are independent of the plotted code: mpmath for K1, the integrator for theta(t),
the definitions (20) and (21) written out by hand for Lemma 2's extensions.
"""

from __future__ import annotations

import math

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import mpmath  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import elliptic_pendulum as ep  # noqa: E402
import elliptic_pendulum.plotting as epp  # noqa: E402


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def heads(ax):
    """The arrowheads of a phase portrait (annotations with an arrow and no text)."""
    return [a for a in ax.texts if a.arrow_patch is not None]


# --- the phase portrait's arrows and legend ---------------------------------------------


def test_phase_portrait_arrows_show_the_clockwise_motion() -> None:
    ax = epp.phase_portrait()
    found = heads(ax)
    # one on each curve: the 6 swings, the separatrix's two branches, the 3 x 2 rotations
    assert len(found) == 6 + 2 + 3 * 2
    for head in found:
        (x1, y1), (x0, y0) = head.xy, head.xyann
        # theta increases where theta' > 0 (the motion is clockwise): (9) with theta' = d theta/dt
        assert (x1 - x0) * y0 > 0, (head.xyann, head.xy)
        # the head sits on a curve of (9): c1 = theta'^2 - 2 cos theta is the same at both ends
        assert abs((y1**2 - 2 * math.cos(x1)) - (y0**2 - 2 * math.cos(x0))) < 0.05


def test_phase_portrait_arrows_do_not_crowd() -> None:
    # No two heads closer than 1/36 of the figure's width (25 px of 900): four heads side by
    # side on nested swings, about 15 px apart, was the fault of the cover figure; the three
    # rotations' heads, one above another on curves well apart, are 36 px apart.
    ax = epp.phase_portrait()
    at = np.array([ax.transData.transform(h.xy) for h in heads(ax)])
    gaps = np.hypot(*(at[:, None, :] - at[None, :, :]).transpose(2, 0, 1))
    np.fill_diagonal(gaps, np.inf)
    assert gaps.min() > ax.figure.bbox.width / 36


def test_phase_portrait_without_arrows_draws_none_and_says_none() -> None:
    ax = epp.phase_portrait(arrows=False)
    assert heads(ax) == []
    assert "arrow" not in ax.get_legend().get_title().get_text()


@pytest.mark.parametrize("label", [True, False])
def test_phase_portrait_legend_promises_labels_only_when_drawn(label: bool) -> None:
    # the close-up of book/separatrix.md
    ax = epp.phase_portrait(amplitudes_deg=(150, 170, 178, 179.9), kicks=(1.0005, 1.01, 1.05),
                            label=label)
    labels = [t for t in ax.texts if t.get_text() and t.arrow_patch is None]
    promised = "c_1" in ax.get_legend().get_title().get_text()
    assert promised == bool(labels) == label


def test_phase_portrait_close_up_lists_only_the_regimes_in_view() -> None:
    ax = epp.phase_portrait(amplitudes_deg=(150, 170, 178, 179.9), kicks=(1.0005, 1.01, 1.05),
                            label=False, xlim=(1.5, 4.8), ylim=(-1.2, 1.2))
    # the rest points I sit at 0 and 2 pi, outside the view
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["II", "III", "IV"]
    assert ax.get_xlim() == (1.5, 4.8)
    x0, x1 = ax.get_xlim()
    assert all(x0 <= h.xy[0] <= x1 for h in heads(ax)) and len(heads(ax)) >= 4
    full = epp.phase_portrait()
    assert [t.get_text() for t in full.get_legend().get_texts()] == ["I", "II", "III", "IV"]


# --- every helper: readable, returns its axes, changes nothing global -------------------


def test_plotting_keeps_its_names() -> None:
    for name in epp.__all__:
        assert callable(getattr(epp, name)), name
    assert {"phase_portrait", "period_ratio_plot", "tension_plot", "extension_plot"} <= set(
        epp.__all__
    )


# --- the teacher's figures against independent references ------------------------------


def test_period_ratio_plot_marks_the_crossings_on_the_curve() -> None:
    ax = epp.period_ratio_plot()
    x, y = ax.lines[-1].get_data()
    assert list(y) == [2.0, 3.0, 4.0]
    for deg, value in zip(x, y, strict=True):
        # R = K(m) / K(0) with m = sin^2(theta0/2), mpmath's K in the parameter m
        s = mpmath.sin(mpmath.radians(mpmath.mpf(float(deg))) / 2)
        assert abs(mpmath.ellipk(s**2) * 2 / mpmath.pi - value) < 1e-9
    # the note's section 4: near 160, 176 and 179.2 degrees (to the note's rounding)
    assert np.allclose(x, [160, 176, 179.2], atol=0.3)


def test_period_ratio_plot_asymptote_is_the_logarithm() -> None:
    ax = epp.period_ratio_plot()
    deg, asym = ax.lines[1].get_data()
    th = np.radians(deg)
    assert np.allclose(asym, 2 / np.pi * np.log(4 / np.cos(th / 2)), rtol=1e-14)
    # and it is an asymptote: R minus it vanishes towards the top (K1 ~ ln(4/kc))
    top = th > np.radians(179.9)
    ref = np.array([float(mpmath.ellipk(mpmath.sin(t / 2) ** 2) * 2 / mpmath.pi) for t in th[top]])
    assert top.any() and np.max(np.abs(ref - asym[top])) < 1e-5


def test_tension_plot_follows_energy_conservation() -> None:
    theta0 = math.radians(150)
    ax = epp.tension_plot(theta0, omega0=1.7)
    frac, ratio = ax.lines[0].get_data()
    period = ep.solve(theta0, 0.0, 1.7).period
    # T/(mg) = 3 cos theta - 2 cos theta0 along a swing from rest, theta from the integrator
    th, _ = ep.integrate(theta0, 0.0, 1.7, t=frac * period)
    assert np.allclose(ratio, 3 * np.cos(th) - 2 * math.cos(theta0), atol=1e-8)
    (shade,) = ax.collections
    xs = np.concatenate([p.vertices[:, 0] for p in shade.get_paths()])
    negative = frac[ratio < 0]
    # the shading covers where the rod pushes, and only there
    assert xs.min() <= negative.min() + 1e-9 and xs.max() >= negative.max() - 1e-9
    assert len(epp.tension_plot(math.radians(80)).collections) == 0


@pytest.mark.parametrize("theta0", [0.0, math.pi, -1.0, 4.0, math.nan])
def test_tension_plot_refuses_amplitudes_that_do_not_swing(theta0: float) -> None:
    with pytest.raises(ValueError, match="theta0"):
        epp.tension_plot(theta0)


def test_tension_plot_refuses_a_non_number() -> None:
    with pytest.raises(TypeError, match="theta0"):
        epp.tension_plot("steep")


@pytest.mark.parametrize("kind", ["odd", "staircase"])
def test_extension_plot_draws_the_definitions(kind: str) -> None:
    a = 1.0
    ax = epp.extension_plot(np.arctan, a, kind=kind)
    x, y = ax.lines[0].get_data()
    # (20) and (21) written out: x = 2 m a + r with |r| <= a
    m = np.floor((x + a) / (2 * a))
    r = x - 2 * m * a
    if kind == "odd":
        expected = np.where(m % 2 == 0, 1.0, -1.0) * np.arctan(r)
    else:
        expected = np.arctan(r) + 2 * m * np.arctan(a)
    assert np.allclose(y, expected, atol=1e-12)
    xf, yf = ax.lines[1].get_data()
    assert xf.min() == -a and xf.max() == a and np.allclose(yf, np.arctan(xf))
    joints = np.asarray(ax.lines[-1].get_xdata())
    assert np.allclose(joints / a % 2, 1.0)


def test_extension_plot_refuses_bad_input() -> None:
    with pytest.raises(ValueError, match="kind"):
        epp.extension_plot(np.sin, 1.0, kind="even")
    with pytest.raises(ValueError, match="a must"):
        epp.extension_plot(np.sin, -1.0)
    with pytest.raises(TypeError, match="f must"):
        epp.extension_plot("sin", 1.0)
