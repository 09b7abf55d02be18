"""What the plotting helpers share: a fresh axes when none is given, and text sizes.

A figure is shown scaled to the width of the page's text column, so text drawn at a fixed
size in points shrinks with a wide figure: a 9-inch phase portrait with 8-point labels ends up
with legends about 7 pixels high. Sizes here grow with the figure's width instead. A figure of
w inches is an SVG of 96 w pixels scaled to the column, so s points show at
s * 96/72 * min(1, column / (96 w)) pixels; at 2 points per inch of width, the smallest text
(0.9 of :func:`text_size`: tick labels, legends, labels on curves) reads at 9 px or more in a
phone's column of 368 pixels and at about 17 px in the book's 672-pixel column. Sizes are
applied to the axes drawn on, never through rcParams: the library changes no global state.
Legends go where they hide no data (:func:`place_legend`). A legend in a language whose
letters matplotlib's default font lacks gets the path of a font that has them (``font``), as
a property of that legend only.
"""

from __future__ import annotations

from typing import Any

import numpy as np

#: Text size in points per inch of figure width, and the smallest size used. The smallest
#: scale of text_size that a figure uses is SMALLEST_SCALE.
_POINTS_PER_INCH = 2.0
_MIN_POINTS = 11.0
SMALLEST_SCALE = 0.9


def new_axes(ax: Any = None, figsize: tuple[float, float] = (6.4, 4.2)) -> Any:
    """Return ``ax``, or the axes of a new constrained-layout figure when it is None."""
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=figsize, layout="constrained")
    return ax


def text_size(ax: Any, scale: float = 1.0) -> float:
    """Text size in points for the figure of ``ax``: readable once the figure is scaled.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots(figsize=(12, 4))
    >>> text_size(ax) > text_size(plt.subplots(figsize=(5, 4))[1]) == 11.0
    True
    >>> plt.close("all")
    """
    width = float(ax.figure.get_figwidth())
    return scale * max(_MIN_POINTS, _POINTS_PER_INCH * width)


def readable(ax: Any) -> Any:
    """Size the axis labels, tick labels, title and legend of ``ax`` for display; return ax."""
    size = text_size(ax)
    ax.xaxis.label.set_fontsize(size)
    ax.yaxis.label.set_fontsize(size)
    ax.title.set_fontsize(size * 1.1)
    ax.tick_params(labelsize=size * 0.9)
    legend = ax.get_legend()
    if legend is not None:
        for text in legend.get_texts():
            text.set_fontsize(size * 0.9)
        legend.get_title().set_fontsize(size * 0.9)
    return ax


#: Where :func:`place_legend` looks for room inside the axes, after the caller's choice.
_CORNERS = ("upper right", "upper left", "lower right", "lower left", "center right",
            "center left", "upper center", "lower center")


def data_points_px(ax: Any, step: float = 3.0) -> np.ndarray:
    """Return the plotted data of ``ax`` in display pixels, as an (n, 2) array.

    The vertices of its lines and the offsets of its collections in data coordinates, with
    points every ``step`` pixels along each segment of a line, so that a box can be tested for
    crossing a curve. Guides drawn in axes coordinates (``axhline``, ``axvline``) are not data.
    """
    out = [np.empty((0, 2))]
    for line in ax.lines:
        if line.get_transform() is not ax.transData or not line.get_visible():
            continue
        xy = np.column_stack([np.asarray(v, dtype=float) for v in line.get_data()])
        if len(xy) == 0:
            continue
        px = ax.transData.transform(xy)
        ok = np.all(np.isfinite(px), axis=1)
        out.append(px[ok])
        if line.get_linestyle() in ("None", "none", " ", "") or len(px) < 2:
            continue
        a, b = px[:-1], px[1:]
        seg = ok[:-1] & ok[1:]
        a, b = a[seg], b[seg]
        n = np.ceil(np.hypot(*(b - a).T) / step).astype(int)
        long = n > 1
        if long.any():
            reps = n[long]
            frac = np.concatenate([np.arange(1, k) / k for k in reps])
            start = np.repeat(a[long], reps - 1, axis=0)
            end = np.repeat(b[long], reps - 1, axis=0)
            out.append(start + frac[:, None] * (end - start))
    for coll in ax.collections:
        offsets = np.asarray(coll.get_offsets(), dtype=float)
        if coll.get_offset_transform() is ax.transData and offsets.size:
            out.append(ax.transData.transform(offsets))
    return np.concatenate(out)


def _covers(box: Any, points: np.ndarray, margin: float) -> bool:
    x0, y0, x1, y1 = box.x0 - margin, box.y0 - margin, box.x1 + margin, box.y1 + margin
    return bool(np.any((points[:, 0] >= x0) & (points[:, 0] <= x1)
                       & (points[:, 1] >= y0) & (points[:, 1] <= y1)))


def _legend_font(kwargs: dict[str, Any], size: float, font: str | None) -> None:
    """Set the legend's text size, and its font when ``font`` (a file's path) is given."""
    if font is None:
        kwargs.setdefault("fontsize", size)
        kwargs.setdefault("title_fontsize", size)
        return
    from matplotlib.font_manager import FontProperties

    kwargs.setdefault("prop", FontProperties(fname=font, size=size))
    kwargs.setdefault("title_fontproperties", FontProperties(fname=font, size=size))


def place_legend(ax: Any, *args: Any, loc: str = "upper right", font: str | None = None,
                 **kwargs: Any) -> Any:
    """Draw the legend of ``ax`` where it hides no data; return it.

    The first of ``loc`` and the corners (then the middles of the sides) of the axes where the
    legend's box holds no plotted point (see :func:`data_points_px`), measured after the
    figure's layout; when there is none, beside the axes, right of their top. Its text is sized
    by :func:`text_size` before it is measured, in the font at the path ``font`` if given.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> import numpy as np
    >>> fig, ax = plt.subplots(layout="constrained")
    >>> _ = ax.plot([0, 1], [0, 1], label="rising")   # the diagonal through upper right
    >>> place_legend(ax)._loc                           # so: upper left
    2
    >>> g = np.linspace(0, 1, 40)
    >>> _ = ax.plot(*np.meshgrid(g, g), ".", color="0.5")  # data everywhere: beside the axes
    >>> bool(place_legend(ax).get_bbox_to_anchor().x0 > ax.bbox.x1)
    True
    >>> plt.close("all")
    """
    size = text_size(ax, 0.9)
    _legend_font(kwargs, size, font)
    for where in dict.fromkeys((loc, *_CORNERS)):
        legend = ax.legend(*args, loc=where, **kwargs)
        renderer = layout(ax)
        if not _covers(legend.get_window_extent(renderer), data_points_px(ax), 0.3 * size):
            return legend
    return ax.legend(*args, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0,
                     **kwargs)


def layout(ax: Any) -> Any:
    """Lay out the figure of ``ax`` as it will be drawn; return the renderer that measures text.

    The figure's layout engine, if any, places the axes as a draw would.
    """
    fig = ax.figure
    engine = fig.get_layout_engine()
    if engine is not None:
        engine.execute(fig)
    canvas = fig.canvas
    if hasattr(canvas, "get_renderer"):  # Agg and the backends built on it (inline, SVG)
        return canvas.get_renderer()
    # A Figure made without pyplot has a bare FigureCanvasBase: measure with Agg, which
    # matplotlib's own tight layout does the same way, and leave the figure's canvas alone.
    from matplotlib.backends.backend_agg import RendererAgg

    return RendererAgg(fig.bbox.width, fig.bbox.height, fig.dpi)


def legend_below(ax: Any, *args: Any, gap: float = 4.0, font: str | None = None,
                 **kwargs: Any) -> Any:
    """Draw the legend of ``ax`` centred under its x axis; return it.

    Below the tick labels and the x label, ``gap`` points lower, wherever the layout puts the
    axes; in the font at the path ``font`` if given.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots(layout="constrained")
    >>> _ = ax.plot([0, 1], [0, 1], label="rising")
    >>> _ = ax.set_xlabel("x")
    >>> legend = legend_below(ax, frameon=False)
    >>> fig.canvas.draw()
    >>> r = fig.canvas.get_renderer()
    >>> bool(legend.get_window_extent(r).y1 < ax.xaxis.label.get_window_extent(r).y0)
    True
    >>> plt.close("all")
    """
    from matplotlib.transforms import ScaledTranslation

    fig = ax.figure
    _legend_font(kwargs, text_size(ax, 0.9), font)
    renderer = layout(ax)
    below = max(0.0, ax.bbox.y0 - ax.xaxis.get_tightbbox(renderer).y0)  # pixels
    drop = below / fig.dpi + gap / 72  # inches
    anchor = ax.transAxes + ScaledTranslation(0.0, -drop, fig.dpi_scale_trans)
    legend = ax.legend(*args, loc="upper center", bbox_to_anchor=(0.5, 0.0),
                       bbox_transform=anchor, borderaxespad=0.0, **kwargs)
    # A legend wider than the figure makes constrained layout squeeze the axes to leave room
    # for it on both sides, to nothing by the second draw: fewer columns, more rows instead.
    ncol = int(kwargs.get("ncol", 1))
    while ncol > 1 and legend.get_window_extent(renderer).width > 0.95 * fig.bbox.width:
        ncol -= 1
        kwargs["ncol"] = ncol
        legend = ax.legend(*args, loc="upper center", bbox_to_anchor=(0.5, 0.0),
                           bbox_transform=anchor, borderaxespad=0.0, **kwargs)
    return legend
