"""Self-checks of the problems for pencil and paper (book/problems.md).

The problems are worked by hand: each has a written part with its hint, and a problem whose
result is a number (an amplitude, a coefficient, a count of swings) has a self-check of that
number too.
"""

from __future__ import annotations

import math

from ._core import Exercise, Hint, Value, register


def _near(a: float, b: float, rtol: float = 1e-6) -> bool:
    return abs(a - b) <= rtol * abs(b)


def inversion() -> dict[str, float]:
    # The root of s/16 + 11 s^2/3072 = epsilon expanded by sympy to first and second order
    # in epsilon (the solution inverts the series by hand), at epsilon = 0.01, in degrees.
    import math

    import sympy as sp

    e, s = sp.symbols("epsilon s", positive=True)
    root = sp.solve(sp.Eq(s / 16 + sp.Rational(11, 3072) * s**2, e), s)[0]
    series = sp.series(root, e, 0, 3).removeO()
    first, second = series.coeff(e, 1) * e, series

    def degrees(square):
        return math.degrees(math.sqrt(float(square.subs(e, sp.Rational(1, 100)))))

    return {"amp1": degrees(first), "amp2": degrees(second)}


def lindstedt() -> dict[str, float]:
    # omega2 as the limit of (1/R(eps) - 1)/eps^2 for the exact pendulum, R = (2/pi) K(m)
    # with m = sin^2(eps/2), by mpmath at 40 digits and eps = 1e-8 (the error is of the
    # order eps^2): the truncated equation and the exact one agree to this order.
    import mpmath

    with mpmath.workdps(40):
        eps = mpmath.mpf("1e-8")
        ratio = 2 / mpmath.pi * mpmath.ellipk(mpmath.sin(eps / 2) ** 2)
        return {"omega2": float((1 / ratio - 1) / eps**2)}


def damped() -> dict[str, float]:
    # The two estimates by other routes than the solution's formulas: the time at which the
    # small-swing envelope 170 exp(-gamma t/2) reaches 90, by Brent's method, in swings of
    # pi/omega0 (gamma = 0.05, omega0 = 1); the energy lost on a swing along the separatrix by
    # mpmath's quadrature of gamma * int theta' dtheta over (-pi, pi).
    import math

    import mpmath
    from scipy.optimize import brentq

    gamma = 0.05
    n_small = brentq(lambda t: 170 * math.exp(-gamma * t / 2) - 90, 0.0, 1e3,
                     xtol=1e-14) / math.pi
    loss = gamma * float(mpmath.quad(lambda x: 2 * mpmath.cos(x / 2), [-mpmath.pi, mpmath.pi]))
    drop = (1 - math.cos(math.radians(170))) - (1 - math.cos(math.radians(90)))
    return {"n_small": n_small, "n_energy": drop / loss}

register(
    Exercise(
        "ex-problems-inversion",
        values=(
            Value("amp1", "the amplitude, in degrees, whose period is 1% longer, to first order",
                  hints=(Hint(lambda a, e: _near(a, math.radians(e), 1e-4),
                              "The question asks for degrees, not radians.",
                              lambda e: math.radians(e)),)),
            Value("amp2", "the same amplitude to second order, in degrees",
                  rtol=1e-5,
                  hints=(Hint(lambda a, e: _near(a, math.radians(e), 1e-4),
                              "The question asks for degrees, not radians.",
                              lambda e: math.radians(e)),
                         Hint(lambda a, e: _near(a, 22.918311805232932, 1e-5),
                              "That is the first order $4\\sqrt{\\varepsilon}$: the term in "
                              "$\\varepsilon^2$ is still to be added.",
                              lambda e: 22.918311805232932),
                         Hint(lambda a, e: _near(a, math.degrees(math.sqrt(
                                  0.16 + 44 / 3 * 1e-4)), 1e-5),
                              "The correction has the wrong sign: a longer period needs a "
                              "larger amplitude, but less than the first order says.",
                              lambda e: math.degrees(math.sqrt(0.16 + 44 / 3 * 1e-4))))),
        ),
        reference=inversion,
        written="Put $s = \\theta_0^2$ and $s = 16\\varepsilon + b\\varepsilon^2$ into the "
                "first two terms of the series; the terms in $\\varepsilon^2$ must cancel.",
    ),
    Exercise(
        "ex-problems-am",
        written="Show first that $\\operatorname{dn}$ has the period $2K$ and is symmetric "
                "about $K$. Then split $\\int_u^{u+2K}$ and move the pieces onto $[0, K]$.",
    ),
    Exercise(
        "ex-problems-nome",
        written="Write the two series as $K_1(k) = \\pi A/2$ and "
                "$K_1(k_c) = A\\log(4/k) - B$: the logarithm then leaves the exponential as a "
                "power of $k$. Expand the rest to the order $k^4$, minding the factor "
                "$\\pi/K_1(k) = 2/A$.",
    ),
    Exercise(
        "ex-problems-lindstedt",
        values=(
            Value("omega2", "the coefficient $\\omega_2$ that keeps $\\theta_3$ bounded",
                  hidden_rtol=1e-6,
                  hints=(Hint(lambda a, e: _near(a, 2 * e),
                              "Mind the factor 2 of $\\omega^2 = \\omega_0^2(1 + "
                              "2\\omega_2\\varepsilon^2 + \\cdots)$.",
                              lambda e: 2 * e),
                         Hint(lambda a, e: _near(a, -e),
                              "The frequency falls as the amplitude grows: the period of a "
                              "larger swing is longer.",
                              lambda e: -e))),
        ),
        reference=lindstedt,
        written="With $d/dt = \\omega\\,d/d\\tau$, collect the terms in $\\varepsilon^3$. A "
                "forcing at the natural frequency, $\\cos\\tau$ on the right of "
                "$\\theta_3'' + \\theta_3$, makes the solution grow: its coefficient must be "
                "zero.",
    ),
    Exercise(
        "ex-problems-damped",
        values=(
            Value("n_small", "the number of swings from 170 to 90 degrees by the law of "
                  "part 2", rtol=2e-3, hidden_rtol=1e-6,
                  hints=(Hint(lambda a, e: _near(a, e / 2, 1e-3),
                              "The amplitude decays like $e^{-\\gamma t/2}$, not "
                              "$e^{-\\gamma t}$.",
                              lambda e: e / 2),)),
            Value("n_energy", "the number of swings from 170 to 90 degrees by the energy "
                  "lost along the separatrix", rtol=2e-3, hidden_rtol=1e-6,
                  hints=(Hint(lambda a, e: _near(a, 2 * e, 1e-3),
                              "One swing runs over the whole separatrix, from $-\\pi$ to "
                              "$\\pi$: $\\int 2\\omega_0\\cos(\\theta/2)\\,d\\theta "
                              "= 8\\omega_0$.",
                              lambda e: 2 * e),
                         Hint(lambda a, e: _near(a, e * (1 - math.cos(math.radians(170)))
                                                 / -math.cos(math.radians(170)), 1e-3),
                              "The pendulum stops at 90 degrees, where the energy measured "
                              "from the bottom is 1, not 0.",
                              lambda e: e * (1 - math.cos(math.radians(170)))
                              / -math.cos(math.radians(170))))),
        ),
        reference=damped,
        written="For 1, differentiate $E$ and use the equation. For 2, try "
                "$e^{\\lambda t}$. For 3, measure the energy from the bottom, in units of "
                "$m\\ell^2\\omega_0^2$; on one swing it loses $(\\gamma/\\omega_0^2)\\int\\theta'"
                "\\,d\\theta$, and the separatrix gives $\\theta'$ near the top.",
    ),
    Exercise(
        "ex-problems-fall",
        written="Solve $\\sin(\\theta/2) = \\tanh x$ for $x$ at both ends. Near the top, "
                "$\\operatorname{artanh}\\cos(\\delta/2)$ simplifies with the half-angle "
                "formulas $1 \\pm \\cos y$.",
    ),
    Exercise(
        "ex-problems-rotation",
        written="Write $(\\theta')^2$ with $1 - \\cos\\theta = 2\\sin^2(\\theta/2)$, divide "
                "$d\\theta$ by $\\theta'$ over one turn and substitute $\\varphi = \\theta/2$. "
                "For the limit, the series of $K_1$ for a small modulus.",
    ),
    Exercise(
        "ex-problems-chaos",
        written="The section maps the state at $t_n$ to the state at $t_{n+1}$, one and the "
                "same map every time because the drive repeats. What does a fixed point of "
                "that map mean, what an invariant closed curve on which it turns by an "
                "irrational angle?",
    ),
)
