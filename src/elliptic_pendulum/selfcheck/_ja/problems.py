"""Japanese of the texts of the self-checks in problems.py (see __init__.py)."""

from __future__ import annotations

MESSAGES = {
    "the amplitude, in degrees, whose period is 1% longer, to first order":
        "周期が 1% 長くなる振幅の 1 次の近似（度）",
    "The question asks for degrees, not radians.":
        "問いが求めるのはラジアンではなく度である。",
    "the same amplitude to second order, in degrees":
        "同じ振幅の 2 次の近似（度）",
    ("That is the first order $4\\sqrt{\\varepsilon}$: the term in $\\varepsilon^2$ is still to "
     "be added."):
        ("それは 1 次の近似 $4\\sqrt{\\varepsilon}$ である。$\\varepsilon^2$ の項を"
         "まだ加える必要がある。"),
    ("The correction has the wrong sign: a longer period needs a larger amplitude, but less "
     "than the first order says."):
        ("補正の符号が逆である。周期が長くなるには振幅が大きくなる必要があるが、"
         "その大きさは 1 次の近似が与えるより小さい。"),
    "the coefficient $\\omega_2$ that keeps $\\theta_3$ bounded":
        "$\\theta_3$ を有界に保つ係数 $\\omega_2$",
    ("Mind the factor 2 of $\\omega^2 = \\omega_0^2(1 + 2\\omega_2\\varepsilon^2 + "
     "\\cdots)$."):
        ("$\\omega^2 = \\omega_0^2(1 + 2\\omega_2\\varepsilon^2 + \\cdots)$ の因子 2 に"
         "注意すること。"),
    ("The frequency falls as the amplitude grows: the period of a larger swing is "
     "longer."):
        "振幅が大きくなると振動数は下がる。大きな振動ほど周期は長い。",
    "the number of swings from 170 to 90 degrees by the law of part 2":
        "問 2 の法則による、170 度から 90 度までの振れの回数",
    "The amplitude decays like $e^{-\\gamma t/2}$, not $e^{-\\gamma t}$.":
        "振幅は $e^{-\\gamma t}$ ではなく $e^{-\\gamma t/2}$ のように減衰する。",
    ("the number of swings from 170 to 90 degrees by the energy lost along the "
     "separatrix"):
        "セパラトリクスに沿って失われるエネルギーによる、170 度から 90 度までの振れの回数",
    ("One swing runs over the whole separatrix, from $-\\pi$ to $\\pi$: "
     "$\\int 2\\omega_0\\cos(\\theta/2)\\,d\\theta = 8\\omega_0$."):
        ("1 回の振れはセパラトリクス全体、$-\\pi$ から $\\pi$ までを通る。"
         "$\\int 2\\omega_0\\cos(\\theta/2)\\,d\\theta = 8\\omega_0$ である。"),
    ("The pendulum stops at 90 degrees, where the energy measured from the bottom is 1, "
     "not 0."):
        "振り子が止まるのは 90 度であり、そこで最下点から測ったエネルギーは 0 ではなく 1 である。",
}
