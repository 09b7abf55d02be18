"""Self-checks of the exercises of the chapter on energy (book/energy.md)."""

from __future__ import annotations

import math

from ._core import Exercise, Hint, Value, register


def conservation() -> dict[str, float]:
    # The closed form of the solution, 1 - 8/pi^2, where the exercise integrates (3).
    import math

    return {"variation": 1 - 8 / math.pi**2}


def threshold() -> dict[str, float]:
    # c1 at the separatrix, solved for the speed by bisection on the regime's test
    # c1 > 2 omega0^2, not the half-angle formula the exercise asks for.
    import math

    low, high = 0.0, 4.0
    for _ in range(200):
        mid = (low + high) / 2
        low, high = (mid, high) if mid**2 - 2 * math.cos(2.0) < 2 else (low, mid)
    return {"v_star": (low + high) / 2}


def fastest() -> dict[str, float]:
    # The energy at the bottom, from c1 = -2 omega0^2 cos(theta0) (at rest), where the
    # exercise samples the motion.
    import math

    w, theta0 = 1.5, math.radians(150.0)
    c1 = -2 * w**2 * math.cos(theta0)
    return {"top_speed": math.sqrt(c1 + 2 * w**2)}


register(
    Exercise(
        "ex-energy-conservation",
        values=(
            Value("variation", "the fraction by which $Q$ varies along a swing of 90 degrees",
                  rtol=1e-3, hidden_rtol=1e-3,
                  hints=(Hint(lambda a, e: abs(a - (1 - e)) < 1e-3,
                              "That is the ratio of the smallest to the largest value of "
                              "$Q$; the fraction it varies by is what is missing to 1.",
                              lambda e: 1 - e),
                         Hint(lambda a, e: abs(a - e * 100) < 0.1,
                              "Give a fraction, not a percentage.",
                              lambda e: 100 * e))),
        ),
        reference=conservation,
        written="Differentiate $E$ along a solution and replace $\\theta''$ by what "
                "{ref}`(3) <eq-3>` says it is. For $Q$, do the same with each equation.",
    ),
    Exercise(
        "ex-energy-threshold",
        values=(
            Value("v_star", "the speed $v^*$ that separates swinging back from going over "
                  "the top, from $\\theta(0) = 2$", rtol=1e-6,
                  hints=(Hint(lambda a, e: abs(a - 2 * math.sin(1.0)) < 1e-6,
                              "Check the half-angle identity you used: "
                              "$1 + \\cos x$ is twice the square of which function of $x/2$?",
                              lambda e: 2 * math.sin(1.0)),
                         Hint(lambda a, e: abs(a - 2 * math.cos(2.0)) < 1e-6
                              or abs(a + 2 * math.cos(2.0)) < 1e-6,
                              "The speed involves half the angle, $\\theta(0)/2$.",
                              lambda e: -2 * math.cos(2.0)))),
        ),
        reference=threshold,
        written="Write $c_1$ for the state $(2, v)$ and compare it with its value on the "
                "separatrix, $2\\omega_0^2$.",
    ),
    Exercise(
        "ex-energy-fastest",
        values=(
            Value("top_speed", "the largest angular speed of the swing from 150 degrees, "
                  "$\\omega_0 = 1.5$", rtol=1e-5, hidden_rtol=1e-6,
                  hints=(Hint(lambda a, e: abs(a - 3 * abs(math.sin(75.0))) < 1e-4,
                              "Did you give the sine an angle in degrees? Python's "
                              "`math.sin` and `numpy.sin` take radians.",
                              lambda e: 3 * abs(math.sin(75.0))),
                         Hint(lambda a, e: abs(a - 1.5 * math.radians(150.0)) < 1e-4,
                              "That is the linearised pendulum's largest speed "
                              "$\\omega_0\\theta_0$; this swing is far from small.",
                              lambda e: 1.5 * math.radians(150.0)))),
        ),
        reference=fastest,
        written="On the swing, where is $\\cos\\theta$ largest?",
    ),
    Exercise(
        "ex-energy-revolution",
        written="By {ref}`(9) <eq-9>`, $(\\theta')^2$ lies between two constants; write "
                "$T_{\\mathrm{IV}}$ as an integral over $\\theta$ of $1/\\theta'$.",
    ),
)
