"""Masked arrays (numpy.ma) are refused by every public entry point that takes arrays.

np.asarray drops a mask: solve(np.ma.masked_array([1.0, 2.0], mask=[False, True])).theta(0.0)
returned the plain array [1, 2], computing the masked entry as data. The convention
(``elliptic_pendulum._validation`` and docs/conventions.md): a TypeError naming the parameter.
"""

import math

import numpy as np
import pytest

import elliptic_pendulum as ep
from elliptic_pendulum import extension, numerics
from elliptic_pendulum.driven import resonance
from elliptic_pendulum.driven.sweep import settle, sweep


def masked(values):
    """The values with the last one masked."""
    return np.ma.masked_array(values, mask=[False] * (len(values) - 1) + [True])


SWING = ep.solve(1.0)
CALLS = {  # name of the parameter -> a call that passes it masked
    "theta0 of solve": ("theta0", lambda: ep.solve(masked([1.0, 2.0])).theta(0.0)),
    "dtheta0 of solve": ("dtheta0", lambda: ep.solve(1.0, masked([0.0, 0.5]))),
    "omega0 of solve": ("omega0", lambda: ep.solve(1.0, 0.0, masked([1.0, 2.0]))),
    "a masked constant": ("omega0", lambda: ep.solve(1.0, 0.0, np.ma.masked)),
    "a list holding one": ("theta0", lambda: ep.solve([1.0, np.ma.masked])),
    "t of theta": ("t", lambda: SWING.theta(masked([0.0, 1.0]))),
    "t of state": ("t", lambda: SWING.state(masked([0.0, 1.0]))),
    "u of sn": ("u", lambda: ep.sn(masked([0.1, 0.2]), 0.5)),
    "k of sn": ("k", lambda: ep.sn(0.1, masked([0.1, 0.2]))),
    "kc of complete_integral": ("kc", lambda: ep.complete_integral(None, kc=masked([0.1, 0.2]))),
    "z of incomplete_integral": ("z", lambda: ep.incomplete_integral(masked([0.1, 0.2]), 0.5)),
    "theta0 of period": ("theta0", lambda: ep.period(masked([0.1, 0.2]))),
    "value of crossing_angle": ("value", lambda: ep.crossing_angle(masked([2.0, 3.0]))),
    "theta0 of period_series": ("theta0", lambda: ep.period_series(masked([0.1, 0.2]), 3)),
    "k of nome": ("k", lambda: ep.nome(masked([0.1, 0.2]))),
    "theta0 of fourier": ("theta0", lambda: ep.fourier_coefficients(masked([0.1, 0.2]), 3)),
    "theta0 of lima_arun": ("theta0", lambda: ep.lima_arun_ratio(masked([0.1, 0.2]))),
    "theta0 of string_stays_taut": ("theta0", lambda: ep.string_stays_taut(masked([1.0, 2.0]))),
    "t of FreeFlight.position": ("t", lambda: ep.free_flight(0.0, 2.0).position(
        masked([1.6, 1.7]))),
    "t of integrate": ("t", lambda: numerics.integrate(1.0, t=masked([0.0, 1.0, 2.0]))),
    "amplitude of backbone": ("amplitude", lambda: resonance.backbone_frequency(
        masked([0.1, 0.2]))),
    "amplitude of duffing": ("amplitude", lambda: resonance.duffing_backbone(masked([0.1, 0.2]))),
    "frequencies of sweep": ("frequencies", lambda: sweep(masked([0.9, 1.0]), 0.1, 0.1)),
    "state of settle": ("state", lambda: settle(0.9, 0.1, 0.1, state=masked([0.0, 0.0]))),
    "x of periodic_extension": ("x", lambda: extension.periodic_extension(np.sin, 1.0)(
        masked([0.1, 0.2]))),
    "x of staircase_extension": ("x", lambda: extension.staircase_extension(np.sin, 1.0)(
        masked([0.1, 0.2]))),
}


@pytest.mark.parametrize("name, call", CALLS.values(), ids=list(CALLS))
def test_masked_input_is_refused_naming_the_parameter(name, call):
    with pytest.raises(TypeError, match=rf"^{name} must not be a masked array"):
        call()


def _plotting_calls():
    import matplotlib

    matplotlib.use("Agg")
    from elliptic_pendulum import plotting as pl

    return {
        "u of plot_jacobi": ("u", lambda: pl.plot_jacobi(0.5, masked([0.1, 0.2]))),
        "u of plot_amplitude": ("u", lambda: pl.plot_amplitude(0.5, masked([0.1, 0.2]))),
        "t of plot_motion": ("t", lambda: pl.plot_motion(SWING, masked([0.0, 1.0]))),
        "amplitudes": ("amplitudes", lambda: pl.plot_approximation_error(
            amplitudes=masked([0.1, 0.2]))),
        "crossings": ("crossings", lambda: pl.plot_period_ratio(crossings=masked([2.0, 3.0]))),
        "amplitudes_deg": ("amplitudes_deg", lambda: pl.plot_harmonics(masked([10.0, 20.0]))),
        "points of plot_backbone": ("points", lambda: pl.plot_backbone(
            points=(masked([0.1, 0.2]), [1.0, 1.0]))),
        # Refused before the curve is read: None stands in for a ResponseCurve.
        "points of plot_response": ("points", lambda: pl.plot_response(
            None, points=(masked([0.1, 0.2]), [1.0, 1.0]))),
        "up of plot_sweep": ("up", lambda: pl.plot_sweep(None, (masked([0.7, 0.8]), [0.5, 0.6]),
                                                         ([0.9, 0.8], [1.8, 1.9]))),
        "down of plot_sweep": ("down", lambda: pl.plot_sweep(None, ([0.7, 0.8], [0.5, 0.6]),
                                                             ([0.9, 0.8], masked([1.8, 1.9])))),
    }


def test_plotting_refuses_masked_input_naming_the_parameter():
    import matplotlib.pyplot as plt

    try:
        for name, call in _plotting_calls().values():
            with pytest.raises(TypeError, match=rf"^{name} must not be a masked array"):
                call()
    finally:
        plt.close("all")


def test_plain_arrays_and_filled_masked_arrays_still_work():
    data = masked([1.0, 2.0])
    assert ep.solve(data.filled(0.0)).theta(0.0).tolist() == [1.0, 0.0]
    assert ep.solve(data.compressed()).theta(0.0).tolist() == [1.0]
    assert math.isclose(ep.period_ratio(np.ma.getdata(data)[0]), ep.period_ratio(1.0))
