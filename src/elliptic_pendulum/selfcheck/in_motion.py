"""Self-checks of the exercises of the chapter on the pendulum in motion (book/in_motion.md)."""

from __future__ import annotations

import math
from functools import cache

from ._core import Exercise, Hint, Value, register


def crowd() -> dict[str, float]:
    # The closed form by mpmath's incomplete integral: from the bottom, sin(theta/2) =
    # k sn(u | k^2), so theta0/2 is reached at u = F(phi | k^2), sin(phi) = sin(theta0/4)/k,
    # and the fraction beyond it is 1 - F/K. The exercise asks for the library's motion
    # (ep.solve) and a root finder.
    import mpmath

    with mpmath.workdps(30):
        k = mpmath.sin(1)  # theta0 = 2
        m = k**2
        phi = mpmath.asin(mpmath.sin(mpmath.mpf(2) / 4) / k)
        return {"fraction": float(1 - mpmath.ellipf(phi, m) / mpmath.ellipk(m))}


def one_turn() -> dict[str, float]:
    # The time of one turn from the bottom speed v by mpmath's complete integral,
    # int_0^2pi dtheta / sqrt(v^2 - 4 sin^2(theta/2)) = (4/v) K(4/v^2), set equal to the
    # swing's period 4 K(sin^2 1) and solved by bisection; the exercise asks for the
    # library's ep.solve and brentq.
    import mpmath

    with mpmath.workdps(30):
        P = 4 * mpmath.ellipk(mpmath.sin(1) ** 2)
        low, high = mpmath.mpf(2) + mpmath.mpf("1e-20"), mpmath.mpf(3)
        for _ in range(100):  # the time of a turn falls with v
            mid = (low + high) / 2
            low, high = (mid, high) if 4 / mid * mpmath.ellipk(4 / mid**2) > P else (low, mid)
        once = (low + high) / 2
        return {"once": float(once), "eps": float(once / 2 - 1)}


@cache
def _twice() -> float:
    # The bottom speed of the rotation that turns once in P/2 (the figure's, turning twice).
    from scipy.optimize import brentq
    from scipy.special import ellipk

    P = 4 * ellipk(math.sin(1.0) ** 2)
    return brentq(lambda v: 4 / v * ellipk(4 / v**2) - P / 2, 2 + 1e-12, 10.0, xtol=1e-15)


def _estimate() -> float:
    from scipy.special import ellipk

    return 8 * math.exp(-4 * ellipk(math.sin(1.0) ** 2))


register(
    Exercise(
        "ex-motion-crowd",
        values=(
            Value("fraction", "the fraction of the time spent beyond half the amplitude, "
                  "$|\\theta| > \\theta_0/2$, for $\\theta_0 = 2$ rad", rtol=1e-6,
                  hidden_rtol=1e-10,
                  hints=(Hint(lambda a, e: abs(a - 2 / 3) < 1e-6,
                              "That is the fraction of a small swing, "
                              "$\\theta = \\theta_0\\cos\\omega_0 t$; this swing is wide: "
                              "use its exact motion.",
                              lambda e: 2 / 3),
                         Hint(lambda a, e: abs(a - (1 - e)) < 1e-6,
                              "That is the share of the time within half the amplitude; the "
                              "exercise asks for the time beyond it.",
                              lambda e: 1 - e),
                         Hint(lambda a, e: abs(a - e / 2) < 1e-6 or abs(a - e / 4) < 1e-6,
                              "The time $t_1$ to reach $\\theta_0/2$ lies in one quarter of "
                              "the period: divide it by $P/4$, not by $P/2$ or $P$.",
                              lambda e: e / 2))),
        ),
        reference=crowd,
        written="Released at rest, the swing goes from $\\theta_0$ to the bottom in a quarter "
                "period, and the three other quarters are its mirror images in time or in "
                "angle: the fraction over a whole period is that of the first quarter. For "
                "small swings, solve $\\cos\\omega_0 t = 1/2$.",
    ),
    Exercise(
        "ex-motion-one-turn",
        values=(
            Value("once", "the speed $\\theta'(0)$ at the bottom of the rotation that turns "
                  "once in one period $P$ of the swing from 2 rad", rtol=1e-8,
                  hidden_rtol=1e-12,
                  hints=(Hint(lambda a, e: abs(a - _twice()) < 1e-7,
                              "That rotation turns once in $P/2$, twice in $P$ (the "
                              "figure's): set the time of one turn equal to $P$.",
                              lambda e: _twice()),
                         Hint(lambda a, e: abs(a - 2 * (1 + _estimate())) < 1e-7,
                              "That is the estimate $2\\omega_0(1 + 8e^{-\\omega_0 P})$ of "
                              "part 2; part 1 asks for the exact root.",
                              lambda e: 2 * (1 + _estimate())))),
            Value("eps", "the excess $\\varepsilon$ in $\\theta'(0) = 2\\omega_0(1 + "
                  "\\varepsilon)$", rtol=1e-5, hidden_rtol=1e-8,
                  hints=(Hint(lambda a, e: abs(a - _estimate()) < 1e-5 * a,
                              "That is the estimate $8e^{-\\omega_0 P}$ of part 2; part 1 "
                              "asks for the exact $\\varepsilon$ of the speed you found.",
                              lambda e: _estimate()),
                         Hint(lambda a, e: abs(a - 2 * e) < 1e-5 * a,
                              "$\\varepsilon$ is relative to the separatrix speed: "
                              "$\\varepsilon = \\theta'(0)/(2\\omega_0) - 1$.",
                              lambda e: 2 * e))),
        ),
        reference=one_turn,
        written="By the estimate, the time of a turn is $\\log(8/\\varepsilon)/\\omega_0$: "
                "compare the $\\varepsilon$ that makes it $P/2$ with the one that makes it "
                "$P$ (what happens to $\\varepsilon$ when the logarithm doubles?), and solve "
                "$\\log(8/\\varepsilon) = \\omega_0 P$ for $\\varepsilon$.",
    ),
    Exercise(
        "ex-motion-half",
        written="Show that $\\varphi(t) = -\\theta(t + P/2)$ solves {ref}`(3) <eq-3>` (where "
                "does the oddness of $\\sin$ come in?), and compare its state at $t = 0$ with "
                "that of $\\theta$; then let uniqueness do the rest. For the figure: what is "
                "the pendulum at $-\\theta$ to the pendulum at $\\theta$?",
    ),
)
