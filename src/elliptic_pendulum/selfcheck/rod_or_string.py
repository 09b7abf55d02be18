"""Self-checks of the exercises of the chapter on a rod or a string (book/rod_or_string.md)."""

from __future__ import annotations

import math

from ._core import Exercise, Hint, Value, register


def loop() -> dict[str, float]:
    # The tension at the top, T = m(l theta'^2 - g), is zero for theta'_top^2 = 1 (omega0 = 1),
    # and the energy adds 4 at the bottom: v = sqrt(5), a closed form where the exercise
    # bisects on ep.string_stays_taut. The speed at the top from solve_ivp, stopped at
    # theta = pi, where the exercise uses the library's closed-form motion.
    import math

    from scipy.integrate import solve_ivp

    def top(t, y):
        return y[0] - math.pi

    def rhs(t, y):
        return [y[1], -math.sin(y[0])]

    top.terminal = True  # type: ignore[attr-defined]  # scipy reads it
    v = math.sqrt(5)
    sol = solve_ivp(rhs, [0.0, 30.0], [0.0, v], method="DOP853", rtol=3e-13, atol=3e-13,
                    events=top)
    return {"v_loop": v, "top_speed": float(sol.y_events[0][0][1])}


def six() -> dict[str, float]:
    # Newton's law along the radius, T = m (l theta'^2 + g cos theta), on solve_ivp's motion
    # of a 1.2 m pendulum at the bottom and where it passes the top, for three kicks; the
    # exercise asks for the library's Pendulum.tension.
    import math

    from scipy.integrate import solve_ivp

    g, length = 9.80665, 1.2
    w2 = g / length

    def top(t, y):
        return y[0] - math.pi

    def rhs(t, y):
        return [y[1], -w2 * math.sin(y[0])]

    top.terminal = True  # type: ignore[attr-defined]  # scipy reads it
    gaps = []
    kicks = [2.3, 3.0, 5.0]
    for kick in kicks:
        v = kick * math.sqrt(w2)
        sol = solve_ivp(rhs, [0.0, 30.0], [0.0, v], method="DOP853", rtol=3e-13, atol=3e-13,
                        events=top)
        th, w = sol.y_events[0][0]
        bottom = length * v**2 + g
        gaps.append((bottom - (length * w**2 + g * math.cos(th))) / g)
    return {"gap_max": float(max(gaps))}


def inside() -> dict[str, bool]:
    # The slack points from the energy (cos theta_s = -e/3, theta_s'^2 = e/3 with
    # e = v^2 - 2, omega0 = 1) and the parabola written out, sampled inside the flight
    # 0 < s < 4 v_y; the exercise asks for the library's FreeFlight.
    import math

    import numpy as np

    climbing = strictly = True
    for v in (1.5, 1.8, 2.0, 2.1, 2.2):
        e = v**2 - 2
        th, w = math.acos(-e / 3), math.sqrt(e / 3)
        vy = w * math.sin(th)
        climbing = climbing and vy > 0
        s = np.linspace(0.0, 4 * vy, 401)[1:-1]
        x = math.sin(th) + w * math.cos(th) * s
        y = -math.cos(th) + vy * s - s**2 / 2
        strictly = strictly and bool(np.all(np.hypot(x, y) < 1))
    return {"climbing": bool(climbing), "strictly": bool(strictly)}


register(
    Exercise(
        "ex-string-loop",
        values=(
            Value("v_loop", "the smallest speed at the bottom that keeps the string taut all "
                  "the way round ($\\omega_0 = 1$)", rtol=1e-6, hidden_rtol=1e-10,
                  hints=(Hint(lambda a, e: abs(a - 2) < 1e-6,
                              "That speed just reaches the top, enough for a rod; a string "
                              "goes slack before it: ask for the tension to stay positive "
                              "(`ep.string_stays_taut`).",
                              lambda e: 2.0),
                         Hint(lambda a, e: abs(a - math.sqrt(2)) < 1e-6,
                              "That speed only lifts the bob to the height of the pivot, "
                              "the widest swing a string allows; the exercise asks for a "
                              "full turn.",
                              lambda e: math.sqrt(2)))),
            Value("top_speed", "the angular speed at the top of that motion",
                  rtol=1e-6, hidden_rtol=1e-8,
                  hints=(Hint(lambda a, e: abs(a) < 1e-6,
                              "At the top the bob cannot be at rest: gravity alone must "
                              "supply the centripetal force there, "
                              "$m\\ell\\theta'^2 = mg$.",
                              lambda e: 0.0),
                         Hint(lambda a, e: abs(a - math.sqrt(5)) < 1e-6,
                              "That is the speed at the bottom; the energy says how much of "
                              "it is left at the top, $2\\ell$ higher.",
                              lambda e: math.sqrt(5)),
                         Hint(lambda a, e: abs(a - math.sqrt(3)) < 1e-6,
                              "The top is $2\\ell$ above the bottom, not $\\ell$.",
                              lambda e: math.sqrt(3)))),
        ),
        reference=loop,
        written="At the top, the tension and gravity both point to the pivot: write Newton's "
                "law along the string there, ask for a tension $\\ge 0$, and carry the speed "
                "down to the bottom with the energy.",
    ),
    Exercise(
        "ex-string-six",
        values=(
            Value("gap_max", "the largest of your values of $(T_\\mathrm{bottom} - "
                  "T_\\mathrm{top})/(mg)$ for the rotations of the 1.2 m pendulum",
                  rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: abs(a / e - 9.80665) < 1e-3,
                              "Divide the difference by the weight $mg$, not by the mass "
                              "alone.",
                              lambda e: 9.80665 * e),
                         Hint(lambda a, e: abs(a) < 1e-6 * e,
                              "The top is half a revolution after the bottom: the `period` "
                              "of a rotation is the time of a full turn, back at the bottom.",
                              lambda e: 0.0),
                         Hint(lambda a, e: abs(a - e / 2) < 1e-6 * e,
                              "A quarter of the `period` of a rotation puts the bob at the "
                              "height of the pivot, not at the top: take half of it.",
                              lambda e: e / 2))),
        ),
        reference=six,
        written="For 1, write the tension as $T = m\\ell(c_1 + 3\\omega_0^2\\cos\\theta)$ "
                "(Newton's law along the string, with the energy for $\\theta'^2$): which "
                "terms change between the bottom and the top? For 2, put the swing's $c_1$ "
                "in the same formula, at $\\theta = 0$; when does a swing keep its string "
                "taut?",
    ),
    Exercise(
        "ex-string-inside",
        values=(
            Value("climbing", "whether $v_y > 0$ at all five slack points (True or False)",
                  kind=bool,
                  hints=(Hint(lambda a, e: a != e,
                              "With $y = -\\ell\\cos\\theta$, $v_y = \\ell\\theta'\\sin\\theta$: "
                              "check the sine and that its angle is in radians; a slack point "
                              "lies above the pivot's height.",
                              lambda e: not e),)),
            Value("strictly", "whether the bob stays strictly inside the circle during all "
                  "five flights (True or False)", kind=bool,
                  hints=(Hint(lambda a, e: a != e,
                              "Leave out the two ends of each flight, the slack and the taut "
                              "instants: there the bob is on the circle, and rounding can put "
                              "it a hair outside.",
                              lambda e: not e),)),
        ),
        reference=inside,
        written="For 1, at a slack point the tension is zero: what does that give "
                "$\\cos\\theta_s$, and so which quadrant is $\\theta_s$ in, and how did the "
                "bob get there? For 2, use the factorization of $x^2 + y^2 - 1$ along the "
                "parabola from the free-flight section, with the tension zero at the start.",
    ),
)
