r"""The words of a figure in the language of the call, and a font that has their letters.

Each figure function takes ``language=None``: the environment's language as gettext reads it
(LANGUAGE, LC_ALL, LC_MESSAGES, LANG), read when it is called; ``"ja"`` for Japanese; a
language without messages gives English. Its English words are translated by ``_ja.py``
beside this module (the symbols inside ``$...$`` stay as they are: ``"$\theta$（rad）"``).

matplotlib's default font (DejaVu Sans) has no Japanese letters, so a Japanese figure sets a
Japanese font on each text it writes, by the file's path (``FontProperties(fname=...)``):
nothing is registered with matplotlib's font manager and no rcParams change, so a figure in
English drawn afterwards is as before. Mathematics inside ``$...$`` keeps matplotlib's
mathtext fonts; the words around it are set in the Japanese font, which has Latin letters
and digits too. The font is IPAexGothic from the PyPI package matplotlib-fontja (a dependency),
found without importing it (its import would call ``japanize()``, which changes rcParams);
without it, the IPA Gothic that Debian's fonts-ipafont-gothic installs; without either, a
Japanese figure raises RuntimeError and says what to install.
"""

from __future__ import annotations

import importlib.util
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

from .._i18n import Say, say_for

# Where Debian and Ubuntu put IPA Gothic (fonts-ipafont-gothic), if matplotlib-fontja is absent.
_SYSTEM_FONTS = ("/usr/share/fonts/opentype/ipafont-gothic/ipag.ttf",
                 "/usr/share/fonts/truetype/fonts-japanese-gothic.ttf")


@cache
def japanese_font() -> str:
    """Return the path of a font file with Japanese letters (IPAexGothic, else IPA Gothic).

    Raises RuntimeError when there is none.
    """
    spec = importlib.util.find_spec("matplotlib_fontja")  # finds, does not import
    for folder in (spec.submodule_search_locations or []) if spec else []:
        path = Path(folder) / "fonts" / "ipaexg.ttf"
        if path.is_file():
            return str(path)
    for system in _SYSTEM_FONTS:
        if Path(system).is_file():
            return system
    raise RuntimeError("a figure in Japanese needs a Japanese font: pip install "
                       "matplotlib-fontja (or, on Debian, apt install fonts-ipafont-gothic)")


@dataclass(frozen=True)
class Words:
    """A figure's words in one language: ``words("amplitude")``; ``font`` the font's path.

    ``font`` is None in English: matplotlib's default font, as before.
    """

    say: Say
    font: str | None = None

    def __call__(self, english: str, /, **fields: Any) -> str:
        return self.say(english, **fields)

    @property
    def language(self) -> str:
        return self.say.language

    def properties(self, size: float | None = None) -> Any:
        """Return the FontProperties of the font at ``size``, or None in English."""
        if self.font is None:
            return None
        from matplotlib.font_manager import FontProperties

        return FontProperties(fname=self.font, size=size)

    def dress(self, *axes: Any) -> None:
        """Set the font on the axis labels, title and texts of each axes, at their sizes.

        Called before the figure is laid out or measured, so that the words are measured
        (and drawn) in the font that has their letters.
        """
        if self.font is None:
            return
        for ax in axes:
            for text in (ax.xaxis.label, ax.yaxis.label, ax.title, ax._left_title,
                         ax._right_title, *ax.texts):
                text.set_fontproperties(self.properties(text.get_fontsize()))


def words(language: str | None) -> Words:
    """Return the :class:`Words` of a figure drawn in ``language`` (None: the environment's)."""
    say = say_for(__package__, language)
    return Words(say, japanese_font() if say.language == "ja" else None)
