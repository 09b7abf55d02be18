"""The contract every figure function keeps, run over ``elliptic_pendulum.plotting.FIGURES``.

A figure function draws on the axes it is given and returns them, draws something, leaves
matplotlib's rcParams as they were, and its text reads at 11 px or more once the figure is
scaled to the book's column, and at 9 px or more in a phone's. A function added to FIGURES
is held to all of this by default: it fails the first test below until it has an example
call here, as the book calls it.
"""

from __future__ import annotations

import functools

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


@functools.cache
def _curve():
    # Computed once for the module (a continuation of periodic orbits takes seconds); the
    # plotting functions only read it.
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
    "plot_potential_well": (lambda axes: epp.plot_potential_well(axes=axes),
                            lambda: plt.subplots(2, 1, figsize=(9, 8.5), sharex=True,
                                                 height_ratios=(2, 3))[1]),
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
    # Every name of the public list is a figure or an alias of one, or localize (which
    # draws nothing: it translates a figure drawn by hand).
    figures = {getattr(epp, name) for name in epp.FIGURES}
    assert {getattr(epp, name) for name in epp.__all__} == figures | {epp.localize}


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


# The book's figures whose layout a reader reported, as their cells draw them (the cover and
# the phase portrait of the energy chapter, Lemma 2's extensions, the four swings in time).
def _extensions():
    a = 0.8
    axes = plt.subplots(2, 1, figsize=(6.4, 7.6), layout="constrained")[1]
    epp.plot_extension(lambda v: ep.inverse_integral(v, a), float(ep.complete_integral(a)),
                       ax=axes[0])
    epp.plot_extension(np.sin, 1.0, ax=axes[1])
    return axes


def _swings():
    motions = [ep.solve(np.radians(d)) for d in (30, 90, 150, 179)]
    t = np.linspace(0.0, 2 * motions[-1].period, 1201)
    axes = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True, layout="constrained")[1]
    return epp.plot_motion(motions, t, axes=axes,
                           labels=[f"$\\theta_0 = {d}°$" for d in (30, 90, 150, 179)])


def _constrained(axes):
    """The axes of an example, in a constrained layout: the figure as the book lays it out."""
    _axes_of(axes)[0].figure.set_layout_engine("constrained")
    return axes


LAYOUTS = {
    **{name: (lambda call=call, make=make: call(_constrained(make()))) for name, (call, make)
       in EXAMPLES.items()},
    "cover": lambda: epp.plot_phase_portrait(
        ax=plt.subplots(figsize=(8, 4), layout="constrained")[1]),
    "phase portrait, constrained": lambda: epp.plot_phase_portrait(
        ax=plt.subplots(figsize=(9, 5), layout="constrained")[1]),
    "extensions": _extensions,
    "swings": _swings,
}


def _drawn(make):
    axes = _axes_of(make())
    fig = axes[0].figure
    fig.canvas.draw()
    return fig, axes, fig.canvas.get_renderer()


def _drawn_tick(ax, text, kind) -> bool:
    """False for a tick label outside the view: it exists, but matplotlib does not draw it."""
    if kind is None:
        return True
    axis = ax.xaxis if kind == "x" else ax.yaxis
    lo, hi = sorted(axis.get_view_interval())
    tol = 1e-9 * max(1.0, abs(hi - lo))
    value = text.get_position()[0 if kind == "x" else 1]
    trans = axis.get_transform()
    if value != value or not np.isfinite(trans.transform([value])[0]):
        return False
    a, b, v = trans.transform([lo, hi, value])
    return min(a, b) - tol <= v <= max(a, b) + tol


def _boxes(axes, renderer, kinds=False):
    """(text, window extent) of every text of the axes, legends' entries included; with
    ``kinds``, (text, extent, "x" or "y" for a tick label, else "")."""
    out = []
    for ax in axes:
        ticks = {id(t): k for k, labels in (("x", ax.get_xticklabels()),
                                            ("y", ax.get_yticklabels())) for t in labels}
        for t in _texts(ax):
            if t.get_visible() and _drawn_tick(ax, t, ticks.get(id(t))):
                box = t.get_window_extent(renderer)
                out.append((t.get_text(), box, ticks.get(id(t), "")) if kinds else
                           (t.get_text(), box))
    return out


def _overlap(a, b) -> bool:
    return a.x0 < b.x1 and b.x0 < a.x1 and a.y0 < b.y1 and b.y0 < a.y1


def _line_points(ax, line, every=2.0):
    """A line's vertices in pixels, and points every few pixels between them when it is drawn."""
    xy = ax.transData.transform(np.column_stack([np.asarray(v, float) for v in line.get_data()]))
    xy = xy[np.all(np.isfinite(xy), axis=1)] if line.get_linestyle() in ("None", "none") else xy
    pts = [xy[np.all(np.isfinite(xy), axis=1)]]
    if line.get_linestyle() not in ("None", "none") and len(xy) > 1:
        for a, b in zip(xy[:-1], xy[1:], strict=True):
            if np.all(np.isfinite(a)) and np.all(np.isfinite(b)):
                n = int(np.hypot(*(b - a)) // every) + 1
                pts.append(a + np.linspace(0, 1, n + 1)[1:-1, None] * (b - a))
    return np.concatenate(pts)


def _inside(box, points, margin=0.0):
    return ((points[:, 0] > box.x0 - margin) & (points[:, 0] < box.x1 + margin)
            & (points[:, 1] > box.y0 - margin) & (points[:, 1] < box.y1 + margin))


@pytest.mark.parametrize("name", LAYOUTS)
def test_no_text_covers_another(name):
    _, axes, renderer = _drawn(LAYOUTS[name])
    boxes = _boxes(axes, renderer, kinds=True)
    # An x and a y tick label may touch at a corner of the axes, as matplotlib draws them.
    hits = [(s, t) for i, (s, a, k) in enumerate(boxes) for t, b, m in boxes[i + 1:]
            if _overlap(a, b) and {k, m} != {"x", "y"}]
    assert hits == []


@pytest.mark.parametrize("name", LAYOUTS)
def test_no_text_covers_an_arrow_or_a_marker(name):
    _, axes, renderer = _drawn(LAYOUTS[name])
    boxes = _boxes(axes, renderer)
    hits = []
    for ax in axes:
        for ann in ax.texts:
            patch = getattr(ann, "arrow_patch", None)
            if patch is None:
                continue
            tip = ax.transData.transform([ann.xy])
            head = patch.get_window_extent(renderer)
            hits += [(s, "arrow") for s, box in boxes
                     if s != ann.get_text() and (_inside(box, tip).any() or _overlap(box, head))]
        for line in ax.lines:
            if line.get_marker() in (None, "None", "none", "") or line.get_transform() \
                    is not ax.transData:
                continue
            centres = _line_points(ax, line, every=np.inf)
            half = line.get_markersize() / 2 * ax.figure.dpi / 72
            hits += [(s, f"marker of {line.get_label()}") for s, box in boxes
                     if _inside(box, centres, half).any()]
    assert hits == []


@pytest.mark.parametrize("name", LAYOUTS)
def test_no_legend_covers_data(name):
    _, axes, renderer = _drawn(LAYOUTS[name])
    hits = []
    for ax in axes:
        legend = ax.get_legend()
        if legend is None:
            continue
        box = legend.get_window_extent(renderer)
        for line in ax.lines:
            if line.get_transform() is ax.transData and line.get_visible():
                if _inside(box, _line_points(ax, line)).any():
                    hits.append(line.get_label())
        for coll in ax.collections:
            for path in coll.get_paths():
                xy = coll.get_transform().transform(path.vertices)
                if coll.get_transform() == ax.transData and _inside(box, xy).any():
                    hits.append(str(coll.get_label()))
    assert hits == []


def test_the_animation_reads_on_a_phone_and_its_pendulums_fill_their_panel():
    from elliptic_pendulum.plotting.animation import animate

    anim = animate([ep.solve(0.0), ep.solve(2.0), ep.solve(0.0, 2.0), ep.solve(0.0, 2.6)],
                   frames=2)
    try:
        fig = anim._fig
        fig.canvas.draw()
        small = [f"{t.get_text()!r}: {_displayed_px(t, fig, PHONE_COLUMN_PX):.1f} px"
                 for ax in fig.axes for t in (_texts(ax) if ax.axison else ax.texts)
                 if _displayed_px(t, fig, PHONE_COLUMN_PX) < PHONE_MIN_TEXT_PX]
        assert small == []
        # A rod (length 1) spans at least 8 % of the figure's width (it was 5 %).
        pendulums = fig.axes[0]
        (x0, _), (x1, _) = pendulums.transData.transform([(0.0, 0.0), (1.0, 0.0)])
        assert (x1 - x0) / fig.bbox.width >= 0.08
    finally:
        anim._draw_was_started = True
        plt.close(anim._fig)


@pytest.mark.parametrize("name", [n for n in epp.FIGURES if n not in (
    "plot_motion", "plot_harmonics", "plot_potential_well")])
def test_draws_on_a_figure_made_without_pyplot(name):
    # A matplotlib.figure.Figure() has a bare FigureCanvasBase, with no renderer of its own:
    # the legend and label placement must still measure its text (the book makes one so).
    from matplotlib.figure import Figure

    call, _ = EXAMPLES[name]
    ax = Figure(figsize=(8, 4.4)).subplots()
    assert call(ax) is ax


@pytest.mark.parametrize("name", epp.FIGURES)
def test_its_own_figure_keeps_its_layout_when_shown_twice(name):
    # Called without axes, a function makes its own constrained-layout figure; a notebook
    # shows it with IPython's print_figure (bbox "tight"), and may show it again. A legend
    # wider than the figure once made constrained layout squeeze the axes to a third of the
    # width on the first draw and to nothing on the second, with a UserWarning that the book
    # printed on its page. Each draw must warn of nothing and leave every axes as it was.
    import warnings
    from io import BytesIO

    call, _ = EXAMPLES[name]
    fig = _axes_of(call(None))[0].figure
    positions = []
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for fmt in ("png", "svg", "svg"):
            fig.canvas.print_figure(BytesIO(), format=fmt, bbox_inches="tight")
            positions.append([ax.get_position().bounds for ax in fig.axes])
    assert np.allclose(positions[1], positions[2], atol=1e-3)
    assert np.allclose(positions[0], positions[1], atol=1e-2)
    # The data, not the legends, take the figure: the squeezed phase plane of the string
    # had its one axes at 31 % of the width after the first draw (two panels of the
    # harmonics, each with its legend beside it, take 20 % each).
    width = sum(b[2] for b in positions[-1])
    assert width >= 1 / 3, f"the axes span {width:.0%} of their figure"
