"""Self-checks of the exercises of the chapter on the solution of libration."""

from __future__ import annotations

import math

from ._core import Exercise, Hint, Value, register

DAY = 86400.0


def _near(a: float, b: float, rtol: float = 1e-6) -> bool:
    return abs(a - b) <= rtol * abs(b)


def _ratio(theta0: float) -> float:
    # R = 1 / agm(1, cos(theta0/2)): for the hints only.
    a, b = 1.0, math.cos(theta0 / 2)
    for _ in range(40):
        a, b = (a + b) / 2, math.sqrt(a * b)
    return 1 / a


def _crossing_deg(ratio: float) -> float:
    low, high = 0.0, 90.0
    for _ in range(100):
        mid = (low + high) / 2
        low, high = (mid, high) if _ratio(math.radians(mid)) < ratio else (low, mid)
    return (low + high) / 2


def clock() -> dict[str, float]:
    # R by Gauss's arithmetic-geometric mean, R = 1 / agm(1, cos(theta0/2)), and the angle of
    # one minute a day by bisection on it: neither ep.period_ratio nor ep.crossing_angle,
    # which the exercise uses.
    import math

    def ratio(theta0):
        a, b = 1.0, math.cos(theta0 / 2)
        for _ in range(40):
            a, b = (a + b) / 2, math.sqrt(a * b)
        return 1 / a

    low, high = 0.0, 90.0
    for _ in range(100):
        mid = (low + high) / 2
        low, high = (mid, high) if ratio(math.radians(mid)) < 86400 / 86340 else (low, mid)
    return {"loss5": 86400 * (1 - 1 / ratio(math.radians(5.0))),
            "theta_minute": (low + high) / 2}


_THETA5 = math.radians(5.0)

register(
    Exercise(
        "ex-libration-clock",
        values=(
            Value("loss5", "the seconds a day the clock loses at an amplitude of 5 degrees",
                  rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: _near(a, DAY * (1 / (1 - e / DAY) - 1), 1e-6),
                              "In a real day the pendulum makes $86400/P_{II}$ swings and the "
                              "clock shows $86400/R$ seconds: the loss is "
                              "$86400(1 - 1/R)$, not $86400(R - 1)$.",
                              lambda e: DAY * (1 / (1 - e / DAY) - 1)),
                         Hint(lambda a, e: _near(a, DAY * (1 - 1 / (1 + _THETA5**2 / 16)), 1e-6),
                              "That is the two-term estimate of part 3; part 1 asks for "
                              "`ep.period_ratio`.",
                              lambda e: DAY * (1 - 1 / (1 + _THETA5**2 / 16))))),
            Value("theta_minute", "the amplitude, in degrees, at which the clock loses one "
                  "minute a day", rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: _near(a, math.radians(e), 1e-5),
                              "Give the amplitude in degrees.",
                              lambda e: math.radians(e)),
                         Hint(lambda a, e: _near(a, _crossing_deg(1 + 60 / DAY), 1e-7),
                              "Losing a minute a day means the clock shows 86340 s while a "
                              "day of 86400 s passes: $R = 86400/86340$.",
                              lambda e: _crossing_deg(1 + 60 / DAY)),
                         Hint(lambda a, e: _near(a, math.degrees(4 * math.sqrt(DAY / 86340 - 1)),
                                                 1e-6),
                              "That is the two-term estimate $R \\approx 1 + \\theta_0^2/16$ "
                              "solved for $\\theta_0$; part 2 asks for `ep.crossing_angle`.",
                              lambda e: math.degrees(4 * math.sqrt(DAY / 86340 - 1))))),
        ),
        reference=clock,
    ),
    Exercise(
        "ex-libration-dn",
        written="For part 1, start from the definitions of $\\operatorname{cn}$ and "
                "$\\operatorname{dn}$ as square roots. For part 2, the chain rule gives a "
                "square root in the denominator: part 1 says which function it is. At the "
                "bottom, $\\operatorname{sn} = 0$.",
    ),
    Exercise(
        "ex-libration-monotone",
        written="In {ref}`(18) <eq-18>` only the factor $1/\\sqrt{1 - \\alpha^2 s^2}$ depends "
                "on $\\alpha$: how does it change when $\\alpha$ grows, and how does "
                "$\\alpha = \\sin(\\theta_0/2)$ change with $\\theta_0$? For the bound, apply "
                "the inequality with $x = \\alpha^2 s^2$ and substitute $s = \\sin\\phi$.",
    ),
)
