"""What the plotting helpers share: a fresh axes when none is given, and text sizes.

A figure is shown scaled to the width of the page's text column, so text drawn at a fixed
size in points shrinks with a wide figure: a 9-inch phase portrait with 8-point labels ends up
with legends about 7 pixels high. Sizes here grow with the figure's width instead. A figure of
w inches is an SVG of 96 w pixels scaled to the column, so s points show at
s * 96/72 * min(1, column / (96 w)) pixels; at 2 points per inch of width, the smallest text
(0.9 of :func:`text_size`: tick labels, legends, labels on curves) reads at 9 px or more in a
phone's column of 368 pixels and at about 17 px in the book's 672-pixel column. Sizes are
applied to the axes drawn on, never through rcParams: the library changes no global state.
"""

from __future__ import annotations

from typing import Any

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

