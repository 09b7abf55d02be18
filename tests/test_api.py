"""The public API of release 0.1.0 is still there, and importing the package stays light.

The expectation is the contract itself: the names of ``elliptic_pendulum.__all__`` and
``elliptic_pendulum.plotting.__all__`` as release 0.1.0 listed them, and the module paths
the book, the notebooks and users import. What ``import elliptic_pendulum`` loads is read in
a fresh interpreter's ``sys.modules`` (one subprocess), not from the source.
"""

from __future__ import annotations

import importlib
import subprocess
import sys

import pytest

import elliptic_pendulum as ep
import elliptic_pendulum.plotting as epp

# elliptic_pendulum.__all__ of release 0.1.0
RELEASE_0_1_0 = [
    "Motion", "Pendulum", "Regime", "agm_period", "am", "cn", "complete_integral",
    "crossing_angle", "dn", "incomplete_integral", "integrate", "inverse_integral",
    "jacobi", "period", "period_ratio", "small_angle_period", "sn", "solve",
    "FreeFlight", "PeriodicOrbit", "ResponseCurve", "backbone_frequency", "duffing_backbone",
    "fourier_coefficients", "free_flight", "nome", "period_series", "period_series_coefficients",
    "periodic_orbit", "response_curve", "slack_point", "string_stays_taut",
    "agm_ratio", "kidd_fogg_ratio", "lima_arun_ratio", "log_ratio", "ratio_approximations",
    "settle", "sweep",
]
# elliptic_pendulum.plotting.__all__ of release 0.1.0
FIGURES_0_1_0 = [
    "pendulum_sketch", "phase_portrait", "plot_motion", "plot_jacobi", "plot_integral",
    "plot_inverse", "plot_amplitude", "period_ratio_plot", "tension_plot", "extension_plot",
    "approximation_error_plot", "harmonics_plot", "string_flight_plot", "string_phase_plane",
    "backbone_plot", "response_plot", "sweep_plot",
]
MODULES_0_1_0 = ["elliptic_pendulum.checks.verify", "elliptic_pendulum.checks.symbolic",
                 "elliptic_pendulum.checks.errata", "elliptic_pendulum.checks.registry",
                 "elliptic_pendulum.plotting.animation", "elliptic_pendulum.numerics",
                 "elliptic_pendulum.extension", "elliptic_pendulum.elliptic",
                 "elliptic_pendulum.motion", "elliptic_pendulum.regimes",
                 "elliptic_pendulum.mechanics", "elliptic_pendulum.cli"]


@pytest.mark.parametrize("name", RELEASE_0_1_0)
def test_every_name_of_release_0_1_0_is_public(name):
    assert name in ep.__all__
    assert callable(getattr(ep, name)) or isinstance(getattr(ep, name), type)


@pytest.mark.parametrize("name", FIGURES_0_1_0)
def test_every_figure_name_of_release_0_1_0_is_public(name):
    assert name in epp.__all__ and callable(getattr(epp, name))


@pytest.mark.parametrize("module", MODULES_0_1_0)
def test_the_modules_of_release_0_1_0_still_import(module):
    assert importlib.import_module(module).__all__


@pytest.mark.parametrize("old", ["symbolic", "verify", "errata", "registry", "animation"])
def test_one_path_per_module(old):
    # The checks live in elliptic_pendulum.checks and the animation in .plotting, under one
    # name each: the re-exports kept for an unpublished 0.1.0 are gone.
    with pytest.raises(ModuleNotFoundError):
        importlib.import_module(f"elliptic_pendulum.{old}")


def test_an_unknown_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'nonexistent'"):
        ep.nonexistent  # noqa: B018


def test_import_loads_no_plotting_algebra_integrator_or_optimizer():
    heavy = ["matplotlib", "sympy", "scipy.integrate", "scipy.optimize"]
    code = ("import sys, elliptic_pendulum as ep; m = ep.solve(1.0); m.theta(1.0); "
            f"print([n for n in {heavy!r} if n in sys.modules])")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "[]"
    # and the lazy names still arrive, with what they need, on first use
    code = ("import sys, elliptic_pendulum as ep; ep.settle; "
            "print('scipy.integrate' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "True"


def test_the_version_is_the_metadata_s():
    from importlib.metadata import version

    assert ep.__version__ == version("elliptic-pendulum")
