"""Self-checks of the exercises of the chapter on the equation of motion (book/equation.md)."""

from __future__ import annotations

import math

from ._core import Exercise, Hint, Value, register


def _near(a: float, b: float, rtol: float = 1e-6) -> bool:
    return abs(a - b) <= rtol * abs(b)


def _period(theta0: float, omega0: float) -> float:
    # The exact period of a release at rest from theta0 (any angle, reduced to the swing's
    # amplitude), by the arithmetic-geometric mean: for the hints only.
    amplitude = abs(math.remainder(theta0, 2 * math.pi))
    a, b = 1.0, math.cos(amplitude / 2)
    for _ in range(40):
        a, b = (a + b) / 2, math.sqrt(a * b)
    return 2 * math.pi / (omega0 * a)


def _crossing(ratio: float) -> float:
    # The release angle, in degrees, where P / (2 pi / omega0) reaches ratio (bisection).
    low, high = 1.0, 179.0
    for _ in range(100):
        mid = (low + high) / 2
        low, high = (mid, high) if _period(math.radians(mid), 1.0) < 2 * math.pi * ratio \
            else (low, mid)
    return (low + high) / 2


def tension() -> dict[str, float]:
    # The closed form of part 3, T_min = mg cos(theta0) at the turning points: it changes sign
    # at cos(theta0) = 0 and is mg/2 from 60 degrees. The solution finds both by root finding
    # on the library's tension sampled over a period.
    import math

    return {"push_from": math.acos(0.0), "tmin60": math.cos(math.radians(60.0))}


def string() -> dict[str, float]:
    # solve_ivp on (3) from the kick 2 omega0 at the bottom, with an event where the tension
    # of (4), m l theta'^2 + m g cos(theta), vanishes: neither the closed form arccos(-2/3)
    # of part 2 nor the library's tension, which the solution root-finds.
    import math

    from scipy.integrate import solve_ivp

    w = math.sqrt(9.81 / 0.8)

    def slack(t, y):
        return y[1] ** 2 / w**2 + math.cos(y[0])  # T / (m g)

    slack.terminal = True  # type: ignore[attr-defined]  # scipy reads it
    run = solve_ivp(lambda t, y: (y[1], -w**2 * math.sin(y[0])), (0.0, 10 / w),
                    (0.0, 2 * w), method="DOP853", rtol=1e-13, atol=1e-14, events=slack)
    return {"theta_slack": float(run.y_events[0][0][0])}


def period() -> dict[str, float]:
    # The period by the arithmetic-geometric mean, P = 2 pi / (omega0 agm(1, cos(theta0/2))),
    # and the 1 % angle by bisection on it: no Pendulum.solve, whose closed form the
    # exercise asks for.
    import math

    w = math.sqrt(9.81 / 1.0)

    def ratio(theta0):
        a, b = 1.0, math.cos(theta0 / 2)
        for _ in range(40):
            a, b = (a + b) / 2, math.sqrt(a * b)
        return 1 / a  # P / (2 pi / omega0)

    P30 = 2 * math.pi / w * ratio(math.radians(30.0))
    low, high = 1.0, 90.0
    for _ in range(100):
        mid = (low + high) / 2
        # the shortfall 1 - P_8/P reaches 0.01 where P/P_8 = 1/0.99
        low, high = (mid, high) if ratio(math.radians(mid)) < 1 / 0.99 else (low, mid)
    return {"P30": P30, "short30": 1 - 1 / ratio(math.radians(30.0)),
            "one_percent": (low + high) / 2}


_W1 = math.sqrt(9.81)  # omega0 of the 1 m pendulum

register(
    Exercise(
        "ex-equation-tension",
        values=(
            Value("push_from", "the lower end of the set of release angles for which the rod "
                  "must push, in radians", rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: _near(a, math.degrees(e), 1e-4),
                              "Give the angle in radians, as `math` and `numpy` use them.",
                              lambda e: math.degrees(e)),
                         Hint(lambda a, e: _near(a, 2 * e, 1e-4),
                              "That is the upper end of the set, the release from the top. "
                              "Where does $\\cos\\theta_0$ first become negative?",
                              lambda e: 2 * e))),
            Value("tmin60", "the smallest tension over the swing released from 60 degrees, "
                  "in units of the weight $mg$", rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: _near(a, 3 - 2 * e, 1e-4),
                              "That is the tension at the bottom, the largest one. Where on "
                              "the swing is $\\cos\\theta$ smallest?",
                              lambda e: 3 - 2 * e),
                         Hint(lambda a, e: _near(a, math.cos(60.0), 1e-4),
                              "Did you give the cosine an angle in degrees? Python's "
                              "`math.cos` and `numpy.cos` take radians.",
                              lambda e: math.cos(60.0)),
                         Hint(lambda a, e: _near(a, 0.3 * 9.81 * e, 1e-4),
                              "That is a tension in newtons for the 0.3 kg bob; give it in "
                              "units of the weight $mg$.",
                              lambda e: 0.3 * 9.81 * e))),
        ),
        reference=tension,
        written="For part 1, $\\theta'\\theta''$ and $\\theta'\\sin\\theta$ are derivatives "
                "of simple functions of $t$; fix the constant at the release. For part 3, "
                "where on the swing is $\\cos\\theta$ smallest, and what is its sign there? "
                "Look closely at the release from exactly 90 degrees.",
    ),
    Exercise(
        "ex-equation-string",
        values=(
            Value("theta_slack", "the angle $\\theta$ at which the string goes slack after "
                  "the kick $v = 2\\omega_0$, in radians", rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: _near(a, math.degrees(e), 1e-4),
                              "Give the angle in radians, as `math` and `numpy` use them.",
                              lambda e: math.degrees(e)),
                         Hint(lambda a, e: _near(a, math.pi - e, 1e-4),
                              "Measure $\\theta$ from the bottom: the string goes slack above "
                              "the horizontal, where $\\cos\\theta < 0$.",
                              lambda e: math.pi - e))),
        ),
        reference=string,
        written="Part 1 is the previous exercise's energy equation with a different constant. "
                "For part 3: where on the circle is $\\cos\\theta$, hence $T$, smallest, and "
                "what does $T \\ge 0$ there say about $v$?",
    ),
    Exercise(
        "ex-equation-period",
        values=(
            Value("P30", "the period of the 1 m pendulum released from 30 degrees, in seconds",
                  rtol=1e-6, hidden_rtol=1e-10,
                  hints=(Hint(lambda a, e: _near(a, 2 * math.pi / _W1, 1e-5),
                              "That is the small-angle period (8); the exercise asks for the "
                              "exact period, the attribute `period` of the motion.",
                              lambda e: 2 * math.pi / _W1),
                         Hint(lambda a, e: _near(a, _period(30.0, _W1), 1e-5),
                              "Did you pass 30 to `solve`? The library takes radians.",
                              lambda e: _period(30.0, _W1)),
                         Hint(lambda a, e: _near(a, e / 2, 1e-5) or _near(a, e / 4, 1e-5),
                              "The period is a full swing, there and back: four times the time "
                              "from the turning point to the bottom.",
                              lambda e: e / 2))),
            Value("short30", "the fraction $1 - P_8/P$ by which the small-angle period (8) is "
                  "too short at 30 degrees", rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: _near(a, 1 / (1 - e) - 1, 1e-5),
                              "That is $P/P_8 - 1$, the excess measured in units of (8); "
                              "give it as a fraction of the exact period, $1 - P_8/P$.",
                              lambda e: 1 / (1 - e) - 1),
                         Hint(lambda a, e: _near(a, 1 - e, 1e-5),
                              "That is the ratio $P_8/P$; the fraction it is too short by is "
                              "what is missing to 1.",
                              lambda e: 1 - e),
                         Hint(lambda a, e: _near(a, 100 * e, 1e-5),
                              "Give a fraction, not a percentage.",
                              lambda e: 100 * e))),
            Value("one_percent", "the release angle, in degrees, from which (8) is too short by "
                  "more than 1 %, that is $1 - P_8/P > 0.01$", rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: _near(a, math.radians(e), 1e-4),
                              "Give the angle in degrees.",
                              lambda e: math.radians(e)),
                         Hint(lambda a, e: _near(a, math.degrees(4 * math.sqrt(0.01)), 1e-5),
                              "That is the two-term estimate $P/P_8 \\approx 1 + \\theta_0^2/16$; "
                              "the exercise asks for the exact period's crossing.",
                              lambda e: math.degrees(4 * math.sqrt(0.01))),
                         Hint(lambda a, e: _near(a, _crossing(1.01), 1e-5),
                              "Did you solve $P/P_8 = 1.01$? The 1 % here is the shortfall of "
                              "(8) as a fraction of the true period: $1 - P_8/P = 0.01$.",
                              lambda e: _crossing(1.01)))),
        ),
        reference=period,
    ),
    Exercise(
        "ex-equation-symmetry",
        written="Each claim of part 1 is one line of the chain rule: write $\\psi(t)$ for the "
                "new function and compute $\\psi''$. For parts 2 and 3, find two solutions with "
                "the same $\\theta$ and $\\theta'$ at one time, and let uniqueness do the rest.",
    ),
)
