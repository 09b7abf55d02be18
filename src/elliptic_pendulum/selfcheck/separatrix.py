"""Self-checks of the exercises of the chapter on the separatrix (book/separatrix.md)."""

from __future__ import annotations

import math

from ._core import Exercise, Hint, Value, register


def _near(a: float, b: float, rtol: float = 1e-6) -> bool:
    return abs(a - b) <= rtol * abs(b)


def _turn(v: float) -> float:
    # T_IV = 2 gamma K1(gamma) of the kick v at the bottom (omega0 = 1), gamma = 2/v, K1 by
    # the arithmetic-geometric mean: for the hints only.
    gamma = 2 / v
    a, b = 1.0, math.sqrt(1 - gamma**2)
    for _ in range(40):
        a, b = (a + b) / 2, math.sqrt(a * b)
    return 2 * gamma * math.pi / (2 * a)


def turn() -> dict[str, float]:
    # The closed form T_IV = 2 gamma K1(gamma) / omega0 of part 2, with gamma = 2/v from the
    # double v = 2(1 + eps) and mpmath's ellipk (parameter m = gamma^2) at 30 digits; the
    # exercise takes T_IV from ep.solve.
    import mpmath

    out = {}
    for name, eps in (("T_eps2", 1e-2), ("T_eps8", 1e-8)):
        with mpmath.workdps(30):
            gamma = 2 / mpmath.mpf(2 * (1 + eps))
            out[name] = float(2 * gamma * mpmath.ellipk(gamma**2))
    return out


def delta() -> dict[str, float]:
    # The integral t = int_0^(pi - delta) dtheta / theta' of (13), theta' = 2 omega0 cos(theta/2),
    # by scipy's quad in s = log(pi - theta), where the integrand is smooth: not the closed
    # form log cot(delta/4) / omega0 that the exercise derives.
    import math

    from scipy.integrate import quad

    w = 1.3

    def integrand(s):
        phi = math.exp(s)  # pi - theta; dtheta = -phi ds
        return phi / (2 * w * math.sin(phi / 2))

    return {name: quad(integrand, math.log(d), math.log(math.pi), epsabs=0, epsrel=1e-13,
                       limit=200)[0]
            for name, d in (("t_delta2", 1e-2), ("t_delta8", 1e-8))}


def period() -> dict[str, float]:
    # Gauss's arithmetic-geometric mean at 30 digits, P = 2 pi / agm(1, cos(theta0/2)), for the
    # double theta0 = pi - eps: not the library's K1, which ep.period uses.
    import math

    import mpmath

    out = {}
    for name, eps in (("P_eps2", 1e-2), ("P_eps6", 1e-6)):
        with mpmath.workdps(30):
            kc = mpmath.cos(mpmath.mpf(math.pi - eps) / 2)
            out[name] = float(2 * mpmath.pi / mpmath.agm(1, kc))
    return out


def sech() -> dict[str, float]:
    # The closed form: the integral of theta' is theta(+inf) - theta(-inf) = pi - (-pi); the
    # exercise integrates 2 omega0 sech numerically.
    import math

    return {"total": 2 * math.pi}


def _turn_hints(eps: float) -> tuple[Hint, ...]:
    hints = [Hint(lambda a, e: _near(a, _turn(2 + eps), 1e-5),
                  "The kick is $2\\omega_0(1 + \\varepsilon)$, not $2\\omega_0 + \\varepsilon$.",
                  lambda e: _turn(2 + eps)),
             Hint(lambda a, e: _near(a, e / 2, 1e-5),
                  "That is half a turn, from the bottom to the top; $P_{IV}$ takes the "
                  "pendulum from the bottom round to the bottom again.",
                  lambda e: e / 2)]
    if eps > 1e-6:  # for eps = 1e-8 the estimate is right to 1e-8
        hints.insert(0, Hint(lambda a, e: _near(a, math.log(8 / eps), 1e-7),
                             "That is the estimate $\\log(8/\\varepsilon)$ of part 2; part 1 "
                             "asks for the time of `ep.solve`.",
                             lambda e: math.log(8 / eps)))
    return tuple(hints)


def _delta_hints(d: float) -> tuple[Hint, ...]:
    w = 1.3
    hints = [Hint(lambda a, e: _near(a, e * w, 1e-6),
                  "Did you leave out $\\omega_0 = 1.3$? The time is $1/\\omega_0$ times a "
                  "function of $\\delta$.",
                  lambda e: e * w),
             Hint(lambda a, e: _near(a, math.log(1 / math.tan(d / 2)) / w, 1e-6),
                  "Check the half-angle step: $\\sin((\\pi - \\delta)/2) = \\cos(\\delta/2)$, and "
                  "$\\operatorname{artanh}\\cos x$ is $\\log\\cot$ of half of $x$.",
                  lambda e: math.log(1 / math.tan(d / 2)) / w),
             Hint(lambda a, e: _near(a, math.atanh(math.sin(d / 2)) / w, 1e-6),
                  "That is when the pendulum is $\\delta$ from the bottom; the exercise asks "
                  "when it is $\\delta$ from the top, $\\theta = \\pi - \\delta$.",
                  lambda e: math.atanh(math.sin(d / 2)) / w)]
    if d > 1e-6:  # for delta = 1e-8 the estimate is right to rounding
        hints.insert(0, Hint(lambda a, e: _near(a, math.log(4 / d) / w, 1e-9),
                             "That is the estimate $\\log(4/\\delta)/\\omega_0$, too large by "
                             "about $\\delta^2/(48\\omega_0)$; part 1 asks for the exact time.",
                             lambda e: math.log(4 / d) / w))
    return tuple(hints)


def _period_hints(eps: float) -> tuple[Hint, ...]:
    hints = [Hint(lambda a, e: _near(a, e / (2 * math.pi), 1e-6),
                  "That is the period ratio $R$, the period in units of the small-swing period "
                  "$2\\pi/\\omega_0$; the exercise asks for the period itself.",
                  lambda e: e / (2 * math.pi)),
             Hint(lambda a, e: _near(a, e / 4, 1e-6) or _near(a, e / 2, 1e-6),
                  "The period is four quarter swings, $4K_1(\\alpha)/\\omega_0$.",
                  lambda e: e / 4)]
    if eps > 1e-4:  # for eps = 1e-6 the estimate is right to 1e-12
        hints.insert(0, Hint(lambda a, e: _near(a, 4 * math.log(8 / eps), 1e-7),
                             "That is the estimate $4\\log(8/\\varepsilon)$ of part 1; part 3 "
                             "asks for `ep.period`.",
                             lambda e: 4 * math.log(8 / eps)))
    return tuple(hints)


register(
    Exercise(
        "ex-separatrix-turn",
        values=(
            Value("T_eps2", "the time $P_{IV}$ of one turn for $\\varepsilon = 10^{-2}$, "
                  "$\\omega_0 = 1$", rtol=1e-6, hidden_rtol=1e-12, hints=_turn_hints(1e-2)),
            Value("T_eps8", "the time $P_{IV}$ of one turn for $\\varepsilon = 10^{-8}$, "
                  "$\\omega_0 = 1$", rtol=1e-6, hidden_rtol=1e-8, hints=_turn_hints(1e-8)),
        ),
        reference=turn,
        written="At the bottom, {ref}`(29) <eq-29>` ties $\\beta$ to the kick; then "
                "$\\gamma'^2 = 1 - \\gamma^2$ is $2\\varepsilon$ plus a term of higher order, "
                "and $\\log(4/\\gamma')$ is half of $\\log(8/\\varepsilon)$.",
    ),
    Exercise(
        "ex-separatrix-delta",
        values=(
            Value("t_delta2", "the exact time $t_\\delta$ for $\\delta = 10^{-2}$, "
                  "$\\omega_0 = 1.3$", rtol=1e-8, hidden_rtol=1e-12, hints=_delta_hints(1e-2)),
            Value("t_delta8", "the exact time $t_\\delta$ for $\\delta = 10^{-8}$, "
                  "$\\omega_0 = 1.3$", rtol=1e-8, hidden_rtol=1e-12, hints=_delta_hints(1e-8)),
        ),
        reference=delta,
        written="Solve $\\sin(\\theta/2) = \\tanh\\omega_0 t$ at $\\theta = \\pi - \\delta$ and "
                "use $1 \\pm \\cos x = 2\\cos^2(x/2),\\ 2\\sin^2(x/2)$; for part 2, expand "
                "$x\\cot x$ for small $x$.",
    ),
    Exercise(
        "ex-separatrix-period",
        values=(
            Value("P_eps2", "the period for $\\varepsilon = 10^{-2}$, $\\omega_0 = 1$",
                  rtol=1e-7, hidden_rtol=1e-12, hints=_period_hints(1e-2)),
            Value("P_eps6", "the period for $\\varepsilon = 10^{-6}$, $\\omega_0 = 1$",
                  rtol=1e-7, hidden_rtol=1e-12, hints=_period_hints(1e-6)),
        ),
        reference=period,
        written="Here $k_c = \\cos(\\theta_0/2) = \\sin(\\varepsilon/2)$. For part 2, compare "
                "with $t_{\\varepsilon/2}$ of the previous exercise, and ask where the swing "
                "spends its quarter period.",
    ),
    Exercise(
        "ex-separatrix-sech",
        values=(
            Value("total", "the integral of $\\theta'$ over the whole real line, "
                  "$\\omega_0 = 1.3$", rtol=1e-5, hidden_rtol=1e-12,
                  hints=(Hint(lambda a, e: _near(a, e / 2, 1e-4),
                              "That is half of it: did you integrate from $0$ only? The "
                              "motion runs from $t = -\\infty$ to $+\\infty$.",
                              lambda e: e / 2),
                         Hint(lambda a, e: _near(a, e / 1.3, 1e-4) or _near(a, e / 2.6, 1e-4),
                              "Check the factor in front: "
                              "$\\theta' = 2\\omega_0/\\cosh(\\omega_0 t)$.",
                              lambda e: e / 2.6))),
        ),
        reference=sech,
        written="Differentiate $2\\arcsin(\\tanh x)$ with the chain rule; "
                "$1 - \\tanh^2 = \\operatorname{sech}^2$. For part 2, {ref}`(13) <eq-13>` gives "
                "$\\theta'$ as a function of $\\theta$ on the separatrix. For part 3, what "
                "are $\\theta(-\\infty)$ and $\\theta(+\\infty)$?",
    ),
)
