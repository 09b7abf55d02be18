"""The potential well draws -2 cos(theta) and the energies of (9) computed by hand.

Divided by m l^2 w0^2 / 2, the potential energy m g y = -m g l cos(theta) is -2 cos(theta)
and the energy of a motion is c1 / w0^2 = (theta'(0) / w0)^2 - 2 cos(theta(0)), (9) at
t = 0: -2 at rest, -2 cos(theta0) for a release at rest from theta0, 4 kick^2 - 2 for
theta'(0) = 2 w0 kick at the bottom, and 2 on the separatrix. None of these numbers is taken
from the library.
"""

from __future__ import annotations

import math

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import elliptic_pendulum.plotting as epp  # noqa: E402


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def _levels(ax):
    """The solid level lines of the well panel, by regime: (theta where drawn, level)."""
    out = {}
    for line in ax.lines:
        if line.get_label() in ("I", "II", "III", "IV"):
            y = np.asarray(line.get_ydata(), dtype=float)
            x = np.asarray(line.get_xdata(), dtype=float)
            out[line.get_label()] = (x[np.isfinite(y)], y[np.isfinite(y)])
    return out


@pytest.mark.parametrize(("omega0", "swing_deg", "kick"), [(1.0, 90.0, 1.3),
                                                           (1.7, 135.0, 1.05)])
def test_levels_are_the_energies_of_9_by_hand(omega0, swing_deg, kick):
    well, phase = epp.plot_potential_well(omega0, swing_deg=swing_deg, kick=kick)
    levels = _levels(well)
    by_hand = {"I": -2.0, "II": -2 * math.cos(math.radians(swing_deg)),
               "III": 2.0, "IV": 4 * kick**2 - 2}
    assert sorted(levels) == sorted(by_hand)
    for regime, value in by_hand.items():
        _, y = levels[regime]
        assert len(y) > 0 and np.max(np.abs(y - value)) < 1e-12, regime
    # the swing's level is drawn solid exactly between its turning angles, +- theta0
    # (and their copies 2 pi away)
    x, _ = levels["II"]
    centre = x[np.abs(x) < math.pi]
    theta0 = math.radians(swing_deg)
    step = 5 * math.pi / 1200
    assert abs(centre.max() - theta0) <= step and abs(centre.min() + theta0) <= step
    # the rotation's level is drawn everywhere: it lies above the whole well
    assert len(levels["IV"][0]) == 1201
    # both panels show the same range of theta
    assert well.get_xlim() == phase.get_xlim()


def test_the_well_is_one_minus_cos_theta_shifted():
    well, _ = epp.plot_potential_well()
    (curve,) = [line for line in well.lines if line.get_label() == "_well"]
    th, u = (np.asarray(v, dtype=float) for v in curve.get_data())
    # U / (m g l) = 1 - cos(theta) with its zero at the bottom; in the units of c1 / w0^2
    # and with the zero at the pivot's height it is 2 (1 - cos(theta)) - 2.
    assert np.max(np.abs(u - (2 * (1 - np.cos(th)) - 2))) < 1e-14
    assert u.min() == pytest.approx(-2.0) and u.max() == pytest.approx(2.0, abs=1e-4)


def test_thick_curves_in_the_phase_panel_keep_their_energy():
    omega0 = 1.3
    well, phase = epp.plot_potential_well(omega0)
    thick = [line for line in phase.lines if line.get_linewidth() == 2.5]
    c1s = set()
    for line in thick:
        th, dth = (np.asarray(v, dtype=float) for v in line.get_data())
        c1 = (dth / omega0) ** 2 - 2 * np.cos(th)          # (9), divided by w0^2
        assert np.ptp(c1) < 1e-9
        c1s.add(round(float(c1[0]), 6))
    assert c1s == {0.0, 2.0, round(4 * 1.3**2 - 2, 6)}


def test_draws_on_two_axes_of_a_figure_made_without_pyplot():
    from matplotlib.figure import Figure

    axes = Figure(figsize=(9, 8.5)).subplots(2, 1, sharex=True)
    assert epp.plot_potential_well(axes=axes) is axes


def test_refuses_a_swing_that_is_not_one():
    with pytest.raises(ValueError):
        epp.plot_potential_well(swing_deg=180.0)
    with pytest.raises(ValueError):
        epp.plot_potential_well(kick=1.0)
