r"""Figures for the book, the README and the classroom, drawn from the library.

Every figure function takes an optional matplotlib ``ax`` (or ``axes``), draws on it and
returns it; none calls ``plt.show()`` or changes rcParams. Text is sized from the figure's
width, so it stays readable when the figure is scaled to a page. matplotlib is imported only
by the functions that draw, so importing :mod:`elliptic_pendulum` does not select a backend.
Each writes its words in the language of its keyword ``language`` ("en", "ja"; None, the
default, is the environment's as gettext reads it), Japanese in a Japanese font set on each
of its texts, never through rcParams (``plotting/_words.py``).

The functions are named ``plot_<what it shows>``, and grouped by subject in the modules of
this package: the pendulum and its phase plane (:mod:`.phase`), the elliptic functions and
Lemma 2's extensions (:mod:`.functions`), the period and its harmonics (:mod:`.harmonics`),
the forces of rod and string (:mod:`.forces`), the driven pendulum (:mod:`.response`), the
potential well above the phase portrait (:mod:`.well`), and the animation
(:mod:`.animation`); :func:`.language.localize` puts a figure a notebook drew itself in the
reader's language. The names of earlier releases (``phase_portrait``, ``tension_plot``, ...)
stay as aliases of the same functions.

>>> import elliptic_pendulum.plotting as epp
>>> epp.tension_plot is epp.plot_tension
True
"""

from .forces import (
    plot_string_flight,
    plot_string_phase_plane,
    plot_tension,
    string_flight_plot,
    string_phase_plane,
    tension_plot,
)
from .functions import (
    extension_plot,
    plot_amplitude,
    plot_extension,
    plot_integral,
    plot_inverse,
    plot_jacobi,
)
from .harmonics import (
    approximation_error_plot,
    harmonics_plot,
    period_ratio_plot,
    plot_approximation_error,
    plot_harmonics,
    plot_period_ratio,
)
from .language import localize
from .phase import (
    pendulum_sketch,
    phase_portrait,
    plot_motion,
    plot_pendulum,
    plot_phase_portrait,
)
from .response import (
    backbone_plot,
    plot_backbone,
    plot_response,
    plot_sweep,
    response_plot,
    sweep_plot,
)
from .well import plot_potential_well

#: The figure functions, one name each, in the order of the book.
FIGURES = (
    "plot_pendulum", "plot_phase_portrait", "plot_potential_well", "plot_motion", "plot_jacobi",
    "plot_integral", "plot_inverse", "plot_amplitude", "plot_period_ratio", "plot_tension",
    "plot_extension", "plot_approximation_error", "plot_harmonics", "plot_string_flight",
    "plot_string_phase_plane", "plot_backbone", "plot_response", "plot_sweep",
)

__all__ = [
    "plot_pendulum", "plot_phase_portrait", "plot_potential_well", "plot_motion", "plot_jacobi",
    "plot_integral", "plot_inverse", "plot_amplitude", "plot_period_ratio", "plot_tension",
    "plot_extension", "plot_approximation_error", "plot_harmonics", "plot_string_flight",
    "plot_string_phase_plane", "plot_backbone", "plot_response", "plot_sweep",
    # the names of earlier releases, aliases of the functions above
    "pendulum_sketch", "phase_portrait", "period_ratio_plot", "tension_plot", "extension_plot",
    "approximation_error_plot", "harmonics_plot", "string_flight_plot", "string_phase_plane",
    "backbone_plot", "response_plot", "sweep_plot",
    # a figure drawn by hand, in the reader's language
    "localize",
]
