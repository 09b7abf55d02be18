"""Self-checks of the exercises of the chapter on rotation (book/rotation.md)."""

from __future__ import annotations

import math

from ._core import Exercise, Hint, Value, register


def _near(a: float, b: float, rtol: float = 1e-6) -> bool:
    return abs(a - b) <= rtol * abs(b)


def _wobble(modulus: float) -> float:
    # The largest W = am(u) - tau u, where dn(u) = tau (mpmath): for the hints only.
    import mpmath

    m = mpmath.mpf(modulus) ** 2
    tau = mpmath.pi / (2 * mpmath.ellipk(m))
    phi = mpmath.asin(mpmath.sqrt((1 - tau**2) / m))
    return float(phi - tau * mpmath.ellipf(phi, m))


def speed() -> dict[str, float]:
    # Energy conservation, theta'^2 - 2 omega0^2 cos(theta) constant, from the kick 2.5 at the
    # bottom: theta'^2 = 2.5^2 - 4 at the top. No gamma, no sampling of ep.solve.
    import math

    return {"bottom_speed": 2.5, "top_speed": math.sqrt(2.5**2 - 4.0)}


def mean() -> dict[str, float]:
    # solve_ivp on (3) from (0.4, 2.6 omega0), the time of one turn from an event where theta
    # has grown by 2 pi: not the closed form 2 gamma K1 / omega0, nor the quadrature of (30),
    # that the exercise asks for.
    import math

    from scipy.integrate import solve_ivp

    w = 1.7

    def turned(t, y):
        return y[0] - 0.4 - 2 * math.pi

    turned.terminal = True  # type: ignore[attr-defined]  # scipy reads it
    run = solve_ivp(lambda t, y: (y[1], -w**2 * math.sin(y[0])), (0.0, 10.0),
                    (0.4, 2.6 * w), method="DOP853", rtol=1e-13, atol=1e-13, events=turned)
    T = float(run.t_events[0][0])
    return {"T_quad": T, "mean_formula": 2 * math.pi / T}


def fast() -> dict[str, float]:
    # mpmath's quadrature at 30 digits of the time of one turn,
    # T_IV = int_0^(2 pi) dtheta / sqrt(v^2 - 4 sin^2(theta/2)) (omega0 = 1), where the exercise
    # uses ep.solve and checks with mpmath's ellipk.
    import mpmath

    out = {}
    with mpmath.workdps(30):
        for v in (10, 30):
            T = 2 * mpmath.quad(lambda th, v=v: 1 / mpmath.sqrt(v**2 - 4 * mpmath.sin(th / 2) ** 2),
                                [0, mpmath.pi])
            out[v] = 2 * mpmath.pi / T
        coef = (out[30] - (30 - mpmath.mpf(1) / 30)) * 30**3
    return {"mean10": float(out[10]), "coef30": float(coef)}


def wobble() -> dict[str, float]:
    # The exact maximum of W = am(u) - tau u: there W' = dn(u) - tau = 0, so
    # sn^2 = (1 - tau^2) / gamma^2, am = arcsin(sn) and u = F(am, gamma) (mpmath's ellipf and
    # ellipk, parameter m = gamma^2). The exercise samples ep.am on a grid.
    import mpmath

    out = {}
    with mpmath.workdps(30):
        for name, g in (("wobble2", 0.2), ("wobble3", 0.3)):
            m = mpmath.mpf(g) ** 2
            tau = mpmath.pi / (2 * mpmath.ellipk(m))
            phi = mpmath.asin(mpmath.sqrt((1 - tau**2) / m))
            out[name] = float(phi - tau * mpmath.ellipf(phi, m))
    return out


# The rotation of ex-rotation-mean: beta from (29), gamma^2 = 2 / (beta + 1).
_W_MEAN = 1.7
_GAMMA_MEAN = math.sqrt(2 / ((2.6**2 / 2 - math.cos(0.4)) + 1))


def _wobble_hints(g: float) -> tuple[Hint, ...]:
    return (
        Hint(lambda a, e: _near(a, g**2 / 8, 1e-6),
             "That is the estimate $\\gamma^2/8$ of part 1; part 2 asks for the maximum of "
             "$W$ computed with `ep.am`.",
             lambda e: g**2 / 8),
        Hint(lambda a, e: _near(a, 2 * e, 1e-4),
             "The amplitude is the largest value of $W$, not the difference between its largest "
             "and smallest values.",
             lambda e: 2 * e),
        Hint(lambda a, e: _near(a, _wobble(g**2), 1e-4),
             "`ep.am` takes the modulus $\\gamma$, not the parameter $m = \\gamma^2$.",
             lambda e: _wobble(g**2)),
    )


register(
    Exercise(
        "ex-rotation-speed",
        values=(
            Value("bottom_speed", "the largest angular velocity over the turn", rtol=1e-6,
                  hidden_rtol=1e-12,
                  hints=(Hint(lambda a, e: _near(a, 4 / e, 1e-5),
                              "The largest speed is $2\\omega_0/\\gamma$, not "
                              "$2\\omega_0\\gamma$.",
                              lambda e: 4 / e),)),
            Value("top_speed", "the smallest angular velocity over the turn", rtol=1e-4,
                  hidden_rtol=1e-12,
                  hints=(Hint(lambda a, e: _near(a, 2 * math.sqrt(1 - 0.8**2), 1e-4),
                              "Did you drop the $1/\\gamma$? The smallest speed is "
                              "$2\\omega_0\\gamma'/\\gamma$.",
                              lambda e: 2 * math.sqrt(1 - 0.8**2)),
                         Hint(lambda a, e: _near(a, math.sqrt(2.5**2 - 2), 1e-4),
                              "The top is $2\\ell$ above the bottom: $\\cos\\theta$ goes from 1 "
                              "to $-1$ on the way up.",
                              lambda e: math.sqrt(2.5**2 - 2)),
                         Hint(lambda a, e: _near(a, 1 / math.sqrt(1 - 0.8**2), 1e-4),
                              "That is the ratio of the largest to the smallest speed, "
                              "$1/\\gamma'$; give the smallest speed itself.",
                              lambda e: 1 / math.sqrt(1 - 0.8**2)))),
        ),
        reference=speed,
        written="Write $\\cos\\theta = 1 - 2\\sin^2(\\theta/2)$ inside the root of "
                "{ref}`(30) <eq-30>` and factor out $2/\\gamma$ with "
                "$\\gamma^2 = 2/(\\beta + 1)$; then ask where $\\sin^2(\\theta/2)$ is 0 and "
                "where it is 1.",
    ),
    Exercise(
        "ex-rotation-mean",
        values=(
            Value("T_quad", "the time $P_{IV}$ of one turn", rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: _near(a, e / 2, 1e-5),
                              "That is half a turn: $\\operatorname{am}$ must grow by $\\pi$, "
                              "so $\\theta$ grows by $2\\pi$.",
                              lambda e: e / 2),
                         Hint(lambda a, e: _near(a, e * _W_MEAN, 1e-5),
                              "Did you leave out $\\omega_0 = 1.7$? "
                              "$P_{IV} = 2\\gamma K_1(\\gamma)/\\omega_0$.",
                              lambda e: e * _W_MEAN))),
            Value("mean_formula", "the mean angular velocity $(2\\omega_0/\\gamma)\\,\\tau$",
                  rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: _near(a, e / (2 * math.pi), 1e-5),
                              "That counts turns per unit time; an angular velocity counts "
                              "radians, $2\\pi$ for each turn.",
                              lambda e: e / (2 * math.pi)),
                         Hint(lambda a, e: _near(a, 2 * _W_MEAN / _GAMMA_MEAN, 1e-5),
                              "That is the largest speed $2\\omega_0/\\gamma$, at the bottom; "
                              "the mean is $\\tau$ times it.",
                              lambda e: 2 * _W_MEAN / _GAMMA_MEAN),
                         Hint(lambda a, e: _near(a, 2.6 * _W_MEAN, 1e-5),
                              "That is the speed $\\theta'(0)$ at the start, not the mean over "
                              "a turn.",
                              lambda e: 2.6 * _W_MEAN))),
        ),
        reference=mean,
        written="For part 1, compare $\\theta(t + nP_{IV})$ with $\\theta(t)$. For part 2, "
                "by how much must the argument of $\\operatorname{am}$ in {ref}`(46) <eq-46>` "
                "grow for $\\theta$ to gain $2\\pi$? Then recall what {ref}`(45) <eq-45>` says "
                "$\\tau$ is the mean of.",
    ),
    Exercise(
        "ex-rotation-fast",
        values=(
            Value("mean10", "the mean angular velocity for $v = 10$", rtol=1e-7,
                  hidden_rtol=1e-12,
                  hints=(Hint(lambda a, e: _near(a, 10 - 1 / 10, 1e-8),
                              "That is the estimate $v - \\omega_0^2/v$; the exercise asks for "
                              "the mean $2\\pi/P_{IV}$ of the motion.",
                              lambda e: 10 - 1 / 10),
                         Hint(lambda a, e: _near(a, 10.0, 1e-8),
                              "That is the kick $v$ itself; gravity slows the rotation on "
                              "average.",
                              lambda e: 10.0),
                         Hint(lambda a, e: _near(a, e / (2 * math.pi), 1e-6),
                              "That counts turns per unit time; an angular velocity counts "
                              "radians, $2\\pi$ for each turn.",
                              lambda e: e / (2 * math.pi)))),
            Value("coef30", "the remainder of the mean after $v - 1/v$, times $v^3$, for "
                  "$v = 30$", rtol=1e-6, hidden_rtol=1e-8,
                  hints=(Hint(lambda a, e: _near(a, -1.25, 1e-9),
                              "That is the coefficient $-5/4$ of the series; the exercise "
                              "asks for the remainder of the motion's mean, which differs a "
                              "little from it.",
                              lambda e: -1.25),
                         Hint(lambda a, e: _near(a, e / 30, 1e-5),
                              "Multiply the remainder by $v^3$, not $v^2$.",
                              lambda e: e / 30))),
        ),
        reference=fast,
        written="At the bottom, {ref}`(29) <eq-29>` gives $\\beta$ in terms of $v$. For the "
                "mean, write $1/K_1$ as $\\frac{2}{\\pi}(1 + x)^{-1}$ with $x$ small and expand "
                "to first order in $\\gamma^2$.",
    ),
    Exercise(
        "ex-rotation-wobble",
        values=(
            Value("wobble2", "the largest value of $W$ over a period for $\\gamma = 0.2$",
                  rtol=1e-5, hidden_rtol=1e-6, hints=_wobble_hints(0.2)),
            Value("wobble3", "the largest value of $W$ over a period for $\\gamma = 0.3$",
                  rtol=1e-5, hidden_rtol=1e-6, hints=_wobble_hints(0.3)),
        ),
        reference=wobble,
        written="Expand $\\sqrt{1 - \\gamma^2\\operatorname{sn}^2 u}$ to first order in "
                "$\\gamma^2$ with $\\operatorname{sn} u \\approx \\sin u$, integrate it from 0 "
                "using $\\sin^2 u = (1 - \\cos 2u)/2$, and compare the term in $u$ with "
                "$\\tau u$.",
    ),
)
