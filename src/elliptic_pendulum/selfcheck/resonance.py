"""Self-checks of the exercises of the chapter toward nonlinear resonance (book/resonance.md)."""

from __future__ import annotations

import math
from functools import cache

from ._core import Exercise, Hint, Value, register


def half() -> dict[str, float]:
    # Bisection on the period ratio R(A) = (2/pi) K(sin^2(A/2)) = 2 with mpmath's K, where
    # the exercise asks for the library's ep.backbone_frequency and a root finder.
    import mpmath

    with mpmath.workdps(30):
        low, high = mpmath.mpf(1), mpmath.pi - mpmath.mpf("1e-9")
        for _ in range(110):  # R increases with A
            mid = (low + high) / 2
            ratio = 2 / mpmath.pi * mpmath.ellipk(mpmath.sin(mid / 2) ** 2)
            low, high = (mid, high) if ratio < 2 else (low, mid)
        return {"half": float((low + high) / 2)}


def weak() -> dict[str, float]:
    # The limits F -> 0 in closed form, the linear response F/|w0^2 - W^2 + 2i zeta w0 W|
    # and the modulus e^(-zeta w0 T) that Liouville's formula gives each of a complex pair,
    # where the exercise asks for the library's shooting, ep.periodic_orbit.
    import math

    forcing, zeta, frequency = 1e-6, 0.1, 0.8
    return {"weak_amp": forcing / abs(complex(1 - frequency**2, 2 * zeta * frequency)),
            "weak_mu": math.exp(-zeta * 2 * math.pi / frequency)}


def cross() -> dict[str, float]:
    # Bisection with mpmath's K on the sign of pi/(2K(sin^2(A/2))) - (1 - A^2/16), where the
    # exercise asks for the library's ep.backbone_frequency and ep.duffing_backbone.
    import mpmath

    def gap(x):
        return mpmath.pi / (2 * mpmath.ellipk(mpmath.sin(x / 2) ** 2)) - (1 - x**2 / 16)

    with mpmath.workdps(30):
        low, high = mpmath.mpf(2), mpmath.mpf(3)  # gap > 0 at 2, < 0 at 3
        for _ in range(110):
            mid = (low + high) / 2
            low, high = (mid, high) if gap(mid) > 0 else (low, mid)
        return {"cross": float((low + high) / 2)}


@cache
def _k_for_m() -> float:
    # The amplitude of half the frequency with K of k = sin(A/2) where scipy's and mpmath's
    # ellipk take m = k^2. (With Duffing's backbone, that mistake finds no crossing at all.)
    from scipy.optimize import brentq
    from scipy.special import ellipk

    return brentq(lambda x: math.pi / (2 * ellipk(math.sin(x / 2))) - 0.5, 1.0, 3.14,
                  xtol=1e-15)


_DEGREES = ("Give the amplitude in radians: `math.degrees` is for showing it.",
            lambda e: math.degrees(e))
_MODULUS = ("$K_1$ takes the modulus $k = \\sin(A/2)$, and `scipy.special.ellipk` and "
            "`mpmath.ellipk` take the parameter $m = k^2$: did you pass them $k$?")

register(
    Exercise(
        "ex-resonance-half",
        values=(
            Value("half", "the amplitude (in radians) at which a swing's frequency is "
                  "$\\omega_0/2$", rtol=1e-9, hidden_rtol=1e-12,
                  hints=(Hint(lambda a, e: abs(a - math.degrees(e)) < 1e-6 * a,
                              _DEGREES[0], _DEGREES[1]),
                         Hint(lambda a, e: abs(a - math.sqrt(8)) < 1e-6,
                              "That is where Duffing's backbone $\\omega_0(1 - A^2/16)$ is "
                              "$\\omega_0/2$; the exercise asks for the exact one, "
                              "`ep.backbone_frequency`.",
                              lambda e: math.sqrt(8)),
                         Hint(lambda a, e: abs(a - _k_for_m()) < 1e-6,
                              _MODULUS, lambda e: _k_for_m()))),
        ),
        reference=half,
        written="Write the frequency of a swing through its period, $2\\pi/P$, and $P$ "
                "through the period ratio $R$ and the small-angle period.",
    ),
    Exercise(
        "ex-resonance-weak",
        values=(
            Value("weak_amp", "the amplitude of the library's periodic orbit for $F = 10^{-6}$, "
                  "$\\zeta = 0.1$, $\\Omega = 0.8$", rtol=1e-5, hidden_rtol=1e-8,
                  hints=(Hint(lambda a, e: abs(a - 1e-6 / abs(1 - 0.8**2)) < 1e-5 * a,
                              "That is the undamped response: the damping term "
                              "$2i\\zeta\\omega_0\\Omega$ belongs in the denominator.",
                              lambda e: 1e-6 / abs(1 - 0.8**2)),
                         Hint(lambda a, e: abs(a - 1e-6 / abs(complex(1 - 0.8**2, 0.1 * 0.8)))
                              < 1e-5 * a,
                              "The damping term of the equation is $2\\zeta\\omega_0\\theta'$: "
                              "did you drop its factor 2?",
                              lambda e: 1e-6 / abs(complex(1 - 0.8**2, 0.1 * 0.8))))),
            Value("weak_mu", "the modulus $|\\mu|$ of its Floquet multipliers",
                  rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: abs(a - e**2) < 1e-6 * a,
                              "That is the product of the two multipliers, $\\det M$; each "
                              "of a complex pair has the square root of its modulus.",
                              lambda e: e**2),
                         Hint(lambda a, e: abs(a - math.exp(-0.1 * 2 * math.pi)) < 1e-6 * a,
                              "The period of the orbit is that of the force, "
                              "$P_\\Omega = 2\\pi/\\Omega$, not $2\\pi/\\omega_0$.",
                              lambda e: math.exp(-0.1 * 2 * math.pi)))),
        ),
        reference=weak,
        written="For 1, the motion is of size $F$: expand $\\sin\\theta$ and keep the first "
                "order, then try $\\theta = \\operatorname{Re}(a e^{i\\Omega t})$. For 2, "
                "linearise about the orbit ($\\cos\\theta \\approx 1$) and solve the constant-"
                "coefficient equation with $e^{\\lambda t}$; Liouville's formula gives the "
                "product of the multipliers.",
    ),
    Exercise(
        "ex-resonance-cross",
        values=(
            Value("cross", "the amplitude (in radians) where Duffing's backbone crosses the "
                  "exact one", rtol=1e-9, hidden_rtol=1e-12,
                  hints=(Hint(lambda a, e: abs(a - math.degrees(e)) < 1e-6 * a,
                              _DEGREES[0], _DEGREES[1]),)),
        ),
        reference=cross,
        written="Near 0, use the series of $\\omega(A)$ to the order $A^4$; near $\\pi$, "
                "follow $K_1(\\sin(A/2))$. Then the intermediate value theorem.",
    ),
)
