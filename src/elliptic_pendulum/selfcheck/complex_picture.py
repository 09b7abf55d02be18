"""Self-checks of the exercises of the chapter on the complex picture (book/complex_picture.md)."""

from __future__ import annotations

from ._core import Exercise, Hint, Value, register


def agm_hand() -> dict[str, float]:
    # K'/K for k = sin 75 degrees from mpmath's complete integral at 30 digits (itself an AGM,
    # but not the student's: the exercise asks for a few steps by hand).
    import mpmath

    with mpmath.workdps(30):
        m = mpmath.sin(mpmath.radians(75)) ** 2
        return {"hand": float(mpmath.ellipk(1 - m) / mpmath.ellipk(m))}


register(
    Exercise(
        "ex-complex-theta-period",
        written="Under $u \\to u + 2iK'$, that is $z \\to z + \\pi\\tau$, write the factor "
                "each of $\\vartheta_1, \\vartheta_2, \\vartheta_4$ takes, then divide.",
    ),
    Exercise(
        "ex-complex-agm-hand",
        values=(
            # The worked solution's three steps by hand hold four digits, no more: the
            # hidden test asks what the exercise asks.
            Value("hand", "the ratio $K'/K$ for $k = \\sin 75^\\circ$, to four digits",
                  rtol=2e-4, hidden_rtol=2e-4,
                  hints=(Hint(lambda a, e: abs(a * e - 1) < 1e-3,
                              "That is $K/K'$: $K'$ comes from the mean that starts at "
                              "$k_c = \\cos 75^\\circ$, and $K = \\pi/(2\\operatorname{AGM}"
                              "(1, k_c))$.",
                              lambda e: 1 / e),)),
        ),
        reference=agm_hand,
        written="Count the steps until $a_n$ and $b_n$ agree to five decimals, for each mean.",
    ),
    Exercise(
        "ex-complex-residues",
        written="Write $\\operatorname{cn}$ and $\\operatorname{dn}$ near $u = iK'$ through the "
                "imaginary transformation, as the text does for $\\operatorname{sn}$, and use "
                "$\\operatorname{cn}(u + 2K) = -\\operatorname{cn}u$.",
    ),
)
