"""Self-checks of the exercises of the chapter on libration (book/libration.md)."""

from __future__ import annotations

import math

from ._core import Exercise, Hint, Value, register


def _near(a: float, b: float, rtol: float = 1e-6) -> bool:
    return abs(a - b) <= rtol * abs(b)


def _partial(alpha2: float, terms: int) -> float:
    # The first terms of the series of R = (2/pi) K1 in alpha^2: for the hints only.
    return sum((math.comb(2 * n, n) / 4**n) ** 2 * alpha2**n for n in range(terms))


# The moduli a student may take by mistake for the swing of 90 degrees.
_WRONG_ALPHA2 = (
    ((math.pi / 4) ** 2, "The modulus is $\\alpha = \\sin(\\theta_0/2)$, not $\\theta_0/2$."),
    (math.sin(45.0) ** 2, "Did you give the sine an angle in degrees? Python's `math.sin` and "
                          "`numpy.sin` take radians."),
)


def series() -> dict[str, float]:
    # The partial sums in exact rational arithmetic (alpha^2 = 1/2 exactly), and R(90 degrees)
    # from the closed form K1(1/sqrt 2) = Gamma(1/4)^2 / (4 sqrt(pi)): not the floating partial
    # sums nor ep.period_ratio that the exercise uses.
    import math
    from fractions import Fraction

    sums = [sum(Fraction(math.comb(2 * n, n), 4**n) ** 2 * Fraction(1, 2) ** n
                for n in range(terms)) for terms in (2, 3)]
    return {"two_terms": float(sums[0]), "three_terms": float(sums[1]),
            "R90": math.gamma(0.25) ** 2 / (2 * math.pi ** 1.5)}


def _sum_hints(terms: int) -> tuple[Hint, ...]:
    hints = [Hint(lambda a, e, x=x: _near(a, _partial(x, terms), 1e-8), message,  # type: ignore[misc]
                  lambda e, x=x: _partial(x, terms)) for x, message in _WRONG_ALPHA2]  # type: ignore[misc]
    hints.append(Hint(lambda a, e: _near(a, math.pi / 2 * e, 1e-8),
                      "That estimates $K_1$; the period ratio is $R = (2/\\pi)K_1$.",
                      lambda e: math.pi / 2 * e))
    if terms == 3:
        hints.append(Hint(lambda a, e: _near(a, 9 / 8 + 9 / 64 / 2, 1e-8),
                          "The third term has $\\alpha^4$, not $\\alpha^2$.",
                          lambda e: 9 / 8 + 9 / 64 / 2))
    return tuple(hints)


register(
    Exercise(
        "ex-libration-series",
        values=(
            Value("two_terms", "the estimate of $R$ at 90 degrees from the first two terms of "
                  "the series", rtol=1e-8, hidden_rtol=1e-12, hints=_sum_hints(2)),
            Value("three_terms", "the estimate of $R$ at 90 degrees from the first three terms",
                  rtol=1e-8, hidden_rtol=1e-12, hints=_sum_hints(3)),
            Value("R90", "the period ratio $R$ of the swing of 90 degrees, from "
                  "`ep.period_ratio`", rtol=1e-8, hidden_rtol=1e-12,
                  hints=(Hint(lambda a, e: _near(a, math.pi / 2 * e, 1e-8),
                              "That is $K_1(\\alpha)$; the period ratio is $R = (2/\\pi)K_1$.",
                              lambda e: math.pi / 2 * e),
                         Hint(lambda a, e: _near(a, 2 * math.pi * e, 1e-8),
                              "That is the period for $\\omega_0 = 1$; the ratio $R$ divides "
                              "it by the small-swing period $2\\pi/\\omega_0$.",
                              lambda e: 2 * math.pi * e),
                         Hint(lambda a, e: _near(a, 297 / 256, 1e-8) or _near(a, 9 / 8, 1e-8),
                              "That is a partial sum of the series; $R$ is the library's "
                              "`ep.period_ratio`.",
                              lambda e: 297 / 256))),
        ),
        reference=series,
        written="Look at the signs of the series' coefficients: what does adding a term do to "
                "a partial sum, for any $\\alpha$ between 0 and 1?",
    ),
)
