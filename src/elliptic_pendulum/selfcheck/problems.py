"""Self-checks of the problems for pencil and paper (book/problems.md).

The problems are worked by hand: each has a written part only, with its hint.
"""

from __future__ import annotations

from ._core import Exercise, register

register(
    Exercise(
        "ex-problems-inversion",
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
        written="With $d/dt = \\omega\\,d/d\\tau$, collect the terms in $\\varepsilon^3$. A "
                "forcing at the natural frequency, $\\cos\\tau$ on the right of "
                "$\\theta_3'' + \\theta_3$, makes the solution grow: its coefficient must be "
                "zero.",
    ),
    Exercise(
        "ex-problems-damped",
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
