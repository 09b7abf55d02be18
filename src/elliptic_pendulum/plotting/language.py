r"""A figure drawn by hand, in the reader's language.

The figure functions of this package write their own words in the language of the call. A
figure that a notebook draws itself with matplotlib (its axis labels, legend, title,
annotations) is written in English; :func:`localize` puts it in the reader's language
afterwards, with the same rules as the figure functions: each of its texts that the
catalogs of ``ELLIPTIC_PENDULUM_MESSAGES`` (or the package's own messages) translate is
replaced by its translation, exactly as written (symbols inside ``$...$`` stay as they
are), and a text with Japanese letters gets a Japanese font, set on that text only.
"""

from __future__ import annotations

import re
from typing import Any

from ._words import words

__all__ = ["localize"]

# Kana, kanji and full-width forms: the letters matplotlib's default font lacks.
_JAPANESE = re.compile(r"[\u3000-\u30ff\u4e00-\u9fff\uff00-\uffef]")


def localize(figure: Any, language: str | None = None) -> Any:
    r"""Translate the texts of a matplotlib figure into ``language``; return the figure.

    Parameters
    ----------
    figure : matplotlib.figure.Figure
        A figure drawn in English: its axis labels, titles, legends and annotations are
        looked up, whole, in the catalogs (tick labels are numbers, left as drawn).
    language : str, optional
        ``"en"`` or ``"ja"``; None (the default) is the environment's language as gettext
        reads it (LANGUAGE, LC_ALL, LC_MESSAGES, LANG), read at the call. In English the
        figure is returned unchanged.

    Returns
    -------
    matplotlib.figure.Figure
        ``figure`` itself, changed in place.

    Raises
    ------
    TypeError
        If ``figure`` is not a matplotlib Figure.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from elliptic_pendulum.plotting import localize
    >>> fig, ax = plt.subplots()
    >>> _ = ax.set_xlabel(r"amplitude $\theta_0$ (degrees)")
    >>> localize(fig, language="ja") is fig
    True
    >>> ax.get_xlabel()
    '振幅 $\\theta_0$（度）'
    >>> plt.close(fig)
    """
    from matplotlib.figure import Figure
    from matplotlib.text import Text

    if not isinstance(figure, Figure):
        raise TypeError(f"figure must be a matplotlib Figure, not {type(figure).__name__}")
    w = words(language)
    if w.font is None:
        return figure
    for text in figure.findobj(Text):
        english = text.get_text()
        if not english:
            continue
        translated = w(english)
        if translated != english:
            text.set_text(translated)
        if _JAPANESE.search(translated):
            text.set_fontproperties(w.properties(float(text.get_fontsize())))
    return figure
