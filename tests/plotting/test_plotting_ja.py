"""The figures in Japanese (plotting/_ja.py, plotting/_words.py).

The English of each figure is the plotting modules' own (their ``say(...)`` calls, read from
the sources); each has its Japanese with the same placeholders and formulas. Every figure
function of ``FIGURES`` (and the animation) drawn with ``language="ja"``: no missing glyph
(matplotlib warns "Glyph ... missing from font(s)" for text outside math, and logs on
"matplotlib.mathtext" for text inside a $...$ label; the control test below shows both are
seen), no run of English words left in its texts, a PNG other than the English one;
rcParams and os.environ as they were, matplotlib-fontja never imported (its import changes
rcParams). LANGUAGE=ja in the environment draws the same Japanese figure; an unknown
language draws the English one.
"""

from __future__ import annotations

import functools
import io
import logging
import os
import re
import sys
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import elliptic_pendulum as ep  # noqa: E402
import elliptic_pendulum.plotting as epp  # noqa: E402
from elliptic_pendulum import _i18n  # noqa: E402
from elliptic_pendulum.plotting import _ja, _words  # noqa: E402
from elliptic_pendulum.plotting.animation import animate  # noqa: E402
from tests.ja_text import check_translation, english_runs, prose, say_literals  # noqa: E402

PLOTTING = Path(epp.__file__).parent
_K = 0.9
_U = np.linspace(-2, 2, 200) * float(ep.complete_integral(_K))


@functools.cache
def _curve():
    return ep.response_curve(0.15, 0.05, frequencies=(0.6, 1.1), step=0.1)


def _animation(language):
    anim = animate([ep.solve(2.0), ep.solve(0.0, 2.5), ep.solve(0.0)], frames=2,
                   language=language)
    # A frame drawn: an animation deleted unrendered warns, in whichever test collects it.
    anim.draw_frame(1)
    return anim._fig.axes[0]


# name -> a call with every option that writes words, in the given language; returns a figure.
EXAMPLES = {
    "plot_pendulum": lambda lang: epp.plot_pendulum(0.5, language=lang),
    "plot_phase_portrait": lambda lang: epp.plot_phase_portrait(language=lang),
    "plot_potential_well": lambda lang: epp.plot_potential_well(language=lang)[0],
    "plot_motion": lambda lang: epp.plot_motion(
        [ep.solve(1.0), ep.solve(0.0, 2.5)], np.linspace(0, 10, 100), language=lang)[0],
    "plot_jacobi": lambda lang: epp.plot_jacobi(_K, _U, language=lang),
    "plot_integral": lambda lang: epp.plot_integral(language=lang),
    "plot_inverse": lambda lang: epp.plot_inverse(language=lang),
    "plot_amplitude": lambda lang: epp.plot_amplitude(_K, _U, language=lang),
    "plot_period_ratio": lambda lang: epp.plot_period_ratio(language=lang),
    "plot_tension": lambda lang: epp.plot_tension(2.5, language=lang),
    "plot_extension": lambda lang: epp.plot_extension(np.sin, 1.0, language=lang),
    "plot_approximation_error": lambda lang: epp.plot_approximation_error(language=lang),
    "plot_harmonics": lambda lang: epp.plot_harmonics([30, 179], language=lang)[0],
    "plot_string_flight": lambda lang: epp.plot_string_flight(0.5, 1.8, language=lang),
    "plot_string_phase_plane": lambda lang: epp.plot_string_phase_plane(language=lang),
    "plot_backbone": lambda lang: epp.plot_backbone(points=([1.0], [0.9]), language=lang),
    "plot_response": lambda lang: epp.plot_response(
        _curve(), duffing=True, linear=(0.15, 0.05), points=([0.7], [0.5]), language=lang),
    "plot_sweep": lambda lang: epp.plot_sweep(_curve(), ([0.7], [0.3]), ([0.9], [1.0]),
                                              language=lang),
}
# The other branches that write words: their own figures.
MORE = {
    "plot_string_flight kicked": lambda lang: epp.plot_string_flight(0.0, 1.8, language=lang),
    "plot_backbone energy": lambda lang: epp.plot_backbone(against="energy", language=lang),
    "plot_phase_portrait bare": lambda lang: epp.plot_phase_portrait(
        label=False, language=lang),
    "plot_response labelled": lambda lang: epp.plot_response(_curve(), label="F = 0.15",
                                                             language=lang),
    "plot_extension staircase": lambda lang: epp.plot_extension(np.arctan, 1.0, "staircase",
                                                                language=lang),
    "animate": lambda lang: _animation(lang),
}
ALL = {**EXAMPLES, **MORE}
# Written in Latin letters in Japanese too, as the Japanese chapters write them: the names of
# methods and people, and a function's name (plot_backbone's default points_label).
LATIN = {"FFT", "Kidd-Fogg", "Lima-Arun", "solve_ivp"}


@pytest.fixture(autouse=True)
def _clean(monkeypatch):
    for variable in (*_i18n.LANGUAGE_VARIABLES, _i18n.CATALOG_VARIABLE):
        monkeypatch.delenv(variable, raising=False)
    yield
    plt.close("all")


def test_every_message_has_japanese_and_no_other() -> None:
    english = say_literals(*sorted(PLOTTING.glob("*.py")))
    assert sorted(english - set(_ja.MESSAGES)) == [], "words without Japanese"
    assert sorted(set(_ja.MESSAGES) - english) == [], "Japanese for words no figure writes"


@pytest.mark.parametrize(("english", "japanese"), sorted(_ja.MESSAGES.items()))
def test_each_translation_keeps_placeholders_and_formulas(english, japanese) -> None:
    check_translation(english, japanese)


def test_every_figure_has_a_japanese_example() -> None:
    assert sorted(EXAMPLES) == sorted(epp.FIGURES)


def _draw(call, language):
    """Draw, render to PNG; return (png, texts, glyph complaints)."""
    complaints: list[str] = []

    class Listen(logging.Handler):
        def emit(self, record: logging.LogRecord) -> None:
            complaints.append(record.getMessage())

    mathtext = logging.getLogger("matplotlib.mathtext")
    listen = Listen(logging.WARNING)
    mathtext.addHandler(listen)
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            ax = call(language)
            fig = ax.figure
            buffer = io.BytesIO()
            fig.savefig(buffer, format="png", dpi=40)
    finally:
        mathtext.removeHandler(listen)
    complaints += [str(w.message) for w in caught if "Glyph" in str(w.message)]
    texts = [t.get_text() for t in fig.findobj(matplotlib.text.Text) if t.get_text()]
    plt.close(fig)
    return buffer.getvalue(), texts, [c for c in complaints if "glyph" in c.lower()]


@pytest.mark.parametrize("name", sorted(ALL))
def test_a_japanese_figure_has_every_glyph_and_no_english(name) -> None:
    rc = {k: repr(v) for k, v in matplotlib.rcParams.items()}
    environ = dict(os.environ)
    png_en, texts_en, complaints_en = _draw(ALL[name], "en")
    png_ja, texts_ja, complaints_ja = _draw(ALL[name], "ja")
    assert complaints_ja == [] and complaints_en == []
    assert png_ja != png_en
    for text in texts_ja:
        assert english_runs(text) == [], text
    # No English text with a word in it is left as it was, but names (LATIN), code and the
    # regimes' numerals (III).
    left = [t for t in texts_en if t in texts_ja and t not in LATIN
            and not re.fullmatch(r"[IV]+", t) and re.search(r"[A-Za-z]{3,}", prose(t))]
    assert left == []
    assert {k: repr(v) for k, v in matplotlib.rcParams.items()} == rc
    assert dict(os.environ) == environ
    assert "matplotlib_fontja" not in sys.modules


def test_the_environment_chooses_and_an_unknown_language_is_english(monkeypatch) -> None:
    call = EXAMPLES["plot_response"]
    english, japanese = _draw(call, "en")[:2], _draw(call, "ja")[:2]
    monkeypatch.setenv("LANGUAGE", "ja")
    assert _draw(call, None)[:2] == japanese
    monkeypatch.setenv("LANGUAGE", "xx")
    assert _draw(call, None)[:2] == english
    assert _draw(call, "xx")[:2] == english


def test_the_glyph_check_sees_a_missing_glyph() -> None:
    # The control: Japanese without the font, outside math and inside a mathtext label.
    def plain(language):
        ax = plt.subplots()[1]
        ax.set_xlabel("振幅")
        return ax

    def mixed(language):
        ax = plt.subplots()[1]
        ax.set_xlabel("$x$ 振幅")
        return ax

    assert any("missing from font" in c for c in _draw(plain, "ja")[2])
    assert any("does not have a glyph" in c for c in _draw(mixed, "ja")[2])


def test_the_font_comes_from_matplotlib_fontja_else_debian_else_a_clear_error(
        monkeypatch, tmp_path) -> None:
    assert Path(_words.japanese_font()).name == "ipaexg.ttf"
    assert "matplotlib_fontja" not in sys.modules
    _words.japanese_font.cache_clear()
    monkeypatch.setattr(_words.importlib.util, "find_spec", lambda name: None)
    system = tmp_path / "ipag.ttf"
    system.write_bytes(b"")
    monkeypatch.setattr(_words, "_SYSTEM_FONTS", (str(tmp_path / "none.ttf"), str(system)))
    try:
        assert _words.japanese_font() == str(system)
        _words.japanese_font.cache_clear()
        monkeypatch.setattr(_words, "_SYSTEM_FONTS", ())
        with pytest.raises(RuntimeError, match="pip install matplotlib-fontja"):
            _words.japanese_font()
    finally:
        _words.japanese_font.cache_clear()


# A figure drawn by hand, as a book's cell draws it: its words from a caller's catalog (the
# book's, ELLIPTIC_PENDULUM_MESSAGES) or the package's own, a legend, an annotation.
HAND_CATALOG = """msgid ""
msgstr ""
"Language: ja\\n"

msgid "time $t$ (s)"
msgstr "時刻 $t$（s）"

msgid "the exact motion"
msgstr "厳密な運動"

msgid "first turning point"
msgstr "最初の折り返し点"
"""


def _by_hand(language):
    fig, ax = plt.subplots(figsize=(6, 3))
    t = np.linspace(0, 6, 50)
    ax.plot(t, np.sin(t), label="the exact motion")
    ax.plot(t, np.cos(t), label="a curve no catalog has")
    ax.set_xlabel("time $t$ (s)")
    ax.set_ylabel(r"amplitude $\theta_0$ (degrees)")  # the package's own message
    ax.annotate("first turning point", (np.pi / 2, 1))
    ax.legend()
    epp.localize(fig, language=language)
    return ax


def test_localize_translates_a_hand_drawn_figure_in_a_japanese_font(
        monkeypatch, tmp_path) -> None:
    catalog = tmp_path / "cells.po"
    catalog.write_text(HAND_CATALOG, encoding="utf-8")
    monkeypatch.setenv(_i18n.CATALOG_VARIABLE, str(catalog))
    rc = {k: repr(v) for k, v in matplotlib.rcParams.items()}
    png_en, texts_en, complaints_en = _draw(_by_hand, "en")
    png_ja, texts_ja, complaints_ja = _draw(_by_hand, "ja")
    # The expectation is the catalog above and plotting/_ja.py, entry by entry.
    for english, japanese in (("time $t$ (s)", "時刻 $t$（s）"),
                              ("the exact motion", "厳密な運動"),
                              ("first turning point", "最初の折り返し点"),
                              (r"amplitude $\theta_0$ (degrees)", r"振幅 $\theta_0$（度）")):
        assert english in texts_en and english not in texts_ja
        assert japanese in texts_ja and japanese not in texts_en
    # A text no catalog has stays as drawn; every glyph is found, and the English figure is
    # untouched (the same texts, no complaint).
    assert "a curve no catalog has" in texts_ja
    assert complaints_ja == [] == complaints_en and png_ja != png_en
    assert {k: repr(v) for k, v in matplotlib.rcParams.items()} == rc
    monkeypatch.setenv("LANGUAGE", "ja")
    assert _draw(_by_hand, None)[1] == texts_ja
    with pytest.raises(TypeError, match="figure must be a matplotlib Figure"):
        epp.localize(plt.subplots()[1])
    plt.close("all")
