"""Self-checks of the exercises of the chapter on action and angle (book/action_angle.md)."""

from __future__ import annotations

import math
from functools import cache

from ._core import Exercise, Hint, Value, register


def small() -> dict[str, float]:
    # J by quadrature of the loop integral (not the closed form the exercise asks for); the
    # energy from the bottom is 2 sin^2(theta0/2) in units of m g ell.
    import mpmath

    def action(theta0):
        # J / (m ell^2 omega0) of a swing of amplitude theta0 (an mpf), by mpmath's
        # tanh-sinh quadrature of the loop integral over the angle: four times the upper
        # branch. (Inside each reference: nbgrader's hidden test pastes its source.)
        return 4 * mpmath.quad(lambda th: mpmath.sqrt(2 * mpmath.cos(th) - 2 * mpmath.cos(theta0)),
                               [0, theta0]) / (2 * mpmath.pi)

    with mpmath.workdps(30):
        x = mpmath.radians(30)
        return {"small_error": float(abs(2 * mpmath.sin(x / 2) ** 2 / action(x) - 1))}


def shorten() -> dict[str, float]:
    # The amplitude whose action, by quadrature, is 2^(3/2) that of 40 degrees, by mpmath's
    # root finder; the exercise asks for the closed form and a bracketing solver.
    import mpmath

    def action(theta0):
        # J / (m ell^2 omega0) of a swing of amplitude theta0 (an mpf), by mpmath's
        # tanh-sinh quadrature of the loop integral over the angle: four times the upper
        # branch. (Inside each reference: nbgrader's hidden test pastes its source.)
        return 4 * mpmath.quad(lambda th: mpmath.sqrt(2 * mpmath.cos(th) - 2 * mpmath.cos(theta0)),
                               [0, theta0]) / (2 * mpmath.pi)

    with mpmath.workdps(30):
        target = 2 ** mpmath.mpf(1.5) * action(mpmath.radians(40))
        root = mpmath.findroot(lambda x: action(x) - target, mpmath.radians(69))
        return {"theta_end": float(mpmath.degrees(root))}


def separatrix() -> dict[str, float]:
    # The separatrix's action by quadrature of its eye, 2 * 2 cos(theta/2) over (-pi, pi);
    # the swing's by quadrature of its loop.
    import mpmath

    def action(theta0):
        # J / (m ell^2 omega0) of a swing of amplitude theta0 (an mpf), by mpmath's
        # tanh-sinh quadrature of the loop integral over the angle: four times the upper
        # branch. (Inside each reference: nbgrader's hidden test pastes its source.)
        return 4 * mpmath.quad(lambda th: mpmath.sqrt(2 * mpmath.cos(th) - 2 * mpmath.cos(theta0)),
                               [0, theta0]) / (2 * mpmath.pi)

    with mpmath.workdps(30):
        eye = 2 * mpmath.quad(lambda th: 2 * mpmath.cos(th / 2), [-mpmath.pi, mpmath.pi])
        eye /= 2 * mpmath.pi
        return {"ell_ratio": float((action(mpmath.pi / 2) / eye) ** (mpmath.mpf(2) / 3))}


@cache
def _wrong(label: str) -> float:
    # The answers the expected mistakes give, from the closed form (scipy takes m = k^2).
    from scipy.special import ellipe, ellipk

    def action(alpha: float, parameter_as_modulus: bool = False) -> float:
        m = alpha if parameter_as_modulus else alpha**2
        return 8 / math.pi * (ellipe(m) - (1 - alpha**2) * ellipk(m))

    a30 = math.sin(math.radians(15))
    if label == "total energy":
        return abs((2 * a30**2 - 1) / action(a30) - 1)
    if label == "modulus":
        return abs(2 * a30**2 / action(a30, True) - 1)
    j90 = action(math.sin(math.radians(45)))
    if label == "exponent":
        return (math.pi * j90 / 8) ** 1.5
    if label == "rotation":
        return (math.pi * j90 / 4) ** (2 / 3)
    raise ValueError(label)


register(
    Exercise(
        "ex-action-small",
        values=(
            Value("small_error", "the relative error $|E_b/(\\omega_0 J) - 1|$ of the "
                  "oscillator's action for a swing of 30 degrees", rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: abs(a - _wrong("total energy")) < 1e-4 * a,
                              "Measure the energy from the bottom: $E_b = E + mg\\ell$, not the "
                              "energy $E$ of the book, whose zero is at the pivot.",
                              lambda e: _wrong("total energy")),
                         Hint(lambda a, e: abs(a - _wrong("modulus")) < 1e-4 * a,
                              "`scipy.special.ellipk` and `ellipe` take the parameter "
                              "$m = \\alpha^2$, not the modulus $\\alpha$.",
                              lambda e: _wrong("modulus")))),
        ),
        reference=small,
        written="Use $K_1 = \\frac{\\pi}{2}(1 + \\frac{\\alpha^2}{4} + \\frac{9\\alpha^4}{64} + "
                "\\cdots)$ and $K_2 = \\frac{\\pi}{2}(1 - \\frac{\\alpha^2}{4} - "
                "\\frac{3\\alpha^4}{64} - \\cdots)$, and $E_b = 2mg\\ell\\,\\alpha^2$.",
    ),
    Exercise(
        "ex-action-shorten",
        values=(
            Value("theta_end", "the amplitude, in degrees, of a swing of 40 degrees once its "
                  "string is slowly shortened to half", rtol=1e-5, hidden_rtol=1e-8,
                  hints=(Hint(lambda a, e: abs(a - 40 * 2**0.75) < 1e-3 * a,
                              "That is the small-swing law $\\theta_0 \\propto \\ell^{-3/4}$; "
                              "the exercise asks for the exact action to stay constant.",
                              lambda e: 40 * 2**0.75),
                         Hint(lambda a, e: a < 40,
                              "A shortened string swings wider: with $J = m\\sqrt{g}\\,"
                              "\\ell^{3/2}j(\\alpha)$ constant, $j$ must grow by $2^{3/2}$.",
                              lambda e: 40 * 2**-0.75))),
        ),
        reference=shorten,
        written="Write $E_b$ and $\\omega = \\sqrt{g/\\ell}$ in terms of $\\ell$ and "
                "$\\theta_0$ and ask that $E_b/\\omega$ stay constant.",
    ),
    Exercise(
        "ex-action-separatrix",
        values=(
            Value("ell_ratio", "the fraction $\\ell/\\ell_0$ of the string left when a swing "
                  "of 90 degrees reaches the separatrix", rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: abs(a - _wrong("exponent")) < 1e-4 * a,
                              "The action is $m\\sqrt{g}\\,\\ell^{3/2}$ times a function of "
                              "$\\alpha$: the length comes from the power $2/3$ of a ratio of "
                              "actions, not $3/2$.",
                              lambda e: _wrong("exponent")),
                         Hint(lambda a, e: abs(a - _wrong("rotation")) < 1e-4 * a,
                              "That is the rotation's action at the separatrix, $4/\\pi$; "
                              "the swing reaches $8/\\pi$.",
                              lambda e: _wrong("rotation")))),
        ),
        reference=separatrix,
        written="$K_2(1) = 1$, and $K_1$ grows only like a logarithm as $\\alpha \\to 1$. Draw "
                "the separatrix and the rotations just above and below it.",
    ),
)
