"""The contract every figure function keeps, run over ``elliptic_pendulum.plotting.FIGURES``.

A figure function draws on the axes it is given and returns them, draws something, leaves
matplotlib's rcParams as they were, and its text reads at 11 px or more once the figure is
scaled to the book's column, and at 9 px or more in a phone's. A function added to FIGURES
is held to all of this by default: it fails the first test below until it has an example
call here, as the book calls it.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import elliptic_pendulum as ep  # noqa: E402
import elliptic_pendulum.plotting as epp  # noqa: E402

# The book's text column is 672 CSS pixels wide at a 1280-pixel window (measured in
# Chromium); a figure of w inches is an SVG of 96 w pixels, scaled down to the column when
# wider. Text must stay at least 11 px there (the old 7-point legends of a 9-inch figure
# came out at 7 px).
COLUMN_PX = 672
MIN_TEXT_PX = 11.0
# On a phone the column is about 400 - 2 * 16 CSS pixels wide; text must stay at 9 px there.
PHONE_COLUMN_PX = 368
PHONE_MIN_TEXT_PX = 9.0

_K = 0.9
_U = np.linspace(-2, 2, 200) * float(ep.complete_integral(_K))


def _curve():
    return ep.response_curve(0.15, 0.05, frequencies=(0.6, 1.1), step=0.1)


def _panel(figsize=(8, 4.2)):
    """The left of two panels side by side, as the book draws its paired figures."""
    return plt.subplots(1, 2, figsize=figsize)[1][0]


# name -> (call on the given axes, the axes to give it), each as a page of the book calls it.
EXAMPLES = {
    "plot_pendulum": (lambda ax: epp.plot_pendulum(0.5, ax=ax),
                      lambda: plt.subplots(figsize=(4, 4))[1]),
    "plot_phase_portrait": (lambda ax: epp.plot_phase_portrait(ax=ax),
                            lambda: plt.subplots(figsize=(9, 5))[1]),
    "plot_motion": (lambda axes: epp.plot_motion(ep.solve(1.0), np.linspace(0, 10, 200), axes=axes,
                                                 compare=False),
                    lambda: plt.subplots(2, 1, figsize=(7, 5))[1]),
    "plot_jacobi": (lambda ax: epp.plot_jacobi(_K, _U, ax=ax), lambda: plt.subplots()[1]),
    "plot_integral": (lambda ax: epp.plot_integral(ax=ax), lambda: plt.subplots()[1]),
    "plot_inverse": (lambda ax: epp.plot_inverse(ax=ax), lambda: plt.subplots()[1]),
    "plot_amplitude": (lambda ax: epp.plot_amplitude(_K, _U, ax=ax), lambda: plt.subplots()[1]),
    "plot_period_ratio": (lambda ax: epp.plot_period_ratio(ax=ax), lambda: plt.subplots()[1]),
    "plot_tension": (lambda ax: epp.plot_tension(2.5, ax=ax), lambda: plt.subplots()[1]),
    "plot_extension": (lambda ax: epp.plot_extension(np.sin, 1.0, ax=ax),
                       lambda: plt.subplots()[1]),
    "plot_approximation_error": (lambda ax: epp.plot_approximation_error(ax=ax),
                                 lambda: plt.subplots()[1]),
    "plot_harmonics": (lambda axes: epp.plot_harmonics([30, 179], axes=axes),
                       lambda: plt.subplots(1, 2, figsize=(9, 3.8))[1]),
    "plot_string_flight": (lambda ax: epp.plot_string_flight(0.0, 1.8, ax=ax), _panel),
    "plot_string_phase_plane": (lambda ax: epp.plot_string_phase_plane(ax=ax),
                                lambda: plt.subplots()[1]),
    "plot_backbone": (lambda ax: epp.plot_backbone(ax=ax), lambda: _panel((9, 3.8))),
    "plot_response": (lambda ax: epp.plot_response(_curve(), ax=ax), lambda: plt.subplots()[1]),
    "plot_sweep": (lambda ax: epp.plot_sweep(_curve(), ([0.7], [0.3]), ([0.9], [1.0]), ax=ax),
                   lambda: plt.subplots()[1]),
}


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def _axes_of(result):
    return list(np.ravel(result)) if isinstance(result, np.ndarray) else [result]


def _texts(ax):
    texts = [ax.xaxis.label, ax.yaxis.label, ax.title, *ax.get_xticklabels(),
             *ax.get_yticklabels(), *ax.texts]
    legend = ax.get_legend()
    if legend is not None:
        texts += [*legend.get_texts(), legend.get_title()]
    return [t for t in texts if t.get_text()]


def _displayed_px(text, fig, column=None) -> float:
    column = COLUMN_PX if column is None else column
    return text.get_fontsize() * 96 / 72 * min(1.0, column / (96 * fig.get_figwidth()))


def test_every_figure_has_an_example_and_every_example_a_figure():
    assert sorted(EXAMPLES) == sorted(epp.FIGURES)
    # Every name of the public list is a figure or an alias of one.
    figures = {getattr(epp, name) for name in epp.FIGURES}
    assert {getattr(epp, name) for name in epp.__all__} == figures


@pytest.mark.parametrize("name", epp.FIGURES)
def test_draws_on_the_given_axes_returns_them_and_leaves_rcparams(name):
    call, make = EXAMPLES[name]
    before = {k: repr(v) for k, v in matplotlib.rcParams.items()}
    given = make()
    returned = call(given)
    assert returned is given
    for ax in _axes_of(returned):
        assert ax.lines or ax.collections or ax.images or ax.patches, f"{name} drew nothing"
    assert {k: repr(v) for k, v in matplotlib.rcParams.items()} == before


@pytest.mark.parametrize("name", epp.FIGURES)
def test_every_text_reads_at_display_size(name):
    call, make = EXAMPLES[name]
    small = [f"{t.get_text()!r}: {_displayed_px(t, ax.figure):.1f} px"
             for ax in _axes_of(call(make())) for t in _texts(ax)
             if _displayed_px(t, ax.figure) < MIN_TEXT_PX]
    assert small == []


@pytest.mark.parametrize("name", epp.FIGURES)
def test_every_text_reads_on_a_phone(name):
    call, make = EXAMPLES[name]
    small = [f"{t.get_text()!r}: {_displayed_px(t, ax.figure, PHONE_COLUMN_PX):.1f} px"
             for ax in _axes_of(call(make())) for t in _texts(ax)
             if _displayed_px(t, ax.figure, PHONE_COLUMN_PX) < PHONE_MIN_TEXT_PX]
    assert small == []
