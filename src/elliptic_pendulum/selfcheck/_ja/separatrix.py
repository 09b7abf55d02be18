"""Japanese of the texts of the self-checks in separatrix.py (see __init__.py)."""

from __future__ import annotations

MESSAGES = {
    "the time $P_{IV}$ of one turn for $\\varepsilon = 10^{-2}$, $\\omega_0 = 1$":
        "$\\varepsilon = 10^{-2}$、$\\omega_0 = 1$ のときの 1 回転の時間 $P_{IV}$",
    ("That is the estimate $\\log(8/\\varepsilon)$ of part 2; part 1 asks for the time of "
     "`ep.solve`."):
        ("その値は小問 2 の見積もり $\\log(8/\\varepsilon)$ である。小問 1 が求めているのは "
         "`ep.solve` による時間である。"),
    "The kick is $2\\omega_0(1 + \\varepsilon)$, not $2\\omega_0 + \\varepsilon$.":
        "初速は $2\\omega_0 + \\varepsilon$ ではなく $2\\omega_0(1 + \\varepsilon)$ である。",
    ("That is half a turn, from the bottom to the top; $P_{IV}$ takes the pendulum from the "
     "bottom round to the bottom again."):
        ("その値は最下点から最高点までの半回転の時間である。$P_{IV}$ は、"
         "振り子が最下点から一周して再び最下点に戻るまでの時間である。"),
    "the time $P_{IV}$ of one turn for $\\varepsilon = 10^{-8}$, $\\omega_0 = 1$":
        "$\\varepsilon = 10^{-8}$、$\\omega_0 = 1$ のときの 1 回転の時間 $P_{IV}$",
    "the exact time $t_\\delta$ for $\\delta = 10^{-2}$, $\\omega_0 = 1.3$":
        "$\\delta = 10^{-2}$、$\\omega_0 = 1.3$ のときの正確な時刻 $t_\\delta$",
    ("That is the estimate $\\log(4/\\delta)/\\omega_0$, too large by about "
     "$\\delta^2/(48\\omega_0)$; part 1 asks for the exact time."):
        ("その値は見積もり $\\log(4/\\delta)/\\omega_0$ であり、およそ "
         "$\\delta^2/(48\\omega_0)$ だけ大きすぎる。小問 1 が求めているのは正確な時刻である。"),
    ("Did you leave out $\\omega_0 = 1.3$? The time is $1/\\omega_0$ times a function of "
     "$\\delta$."):
        ("$\\omega_0 = 1.3$ を入れ忘れていないか。時刻は $\\delta$ の関数の $1/\\omega_0$ "
         "倍である。"),
    ("Check the half-angle step: $\\sin((\\pi - \\delta)/2) = \\cos(\\delta/2)$, and "
     "$\\operatorname{artanh}\\cos x$ is $\\log\\cot$ of half of $x$."):
        ("半角の変形を確かめること。$\\sin((\\pi - \\delta)/2) = \\cos(\\delta/2)$ であり、"
         "$\\operatorname{artanh}\\cos x$ は $x$ の半分の $\\log\\cot$ である。"),
    ("That is when the pendulum is $\\delta$ from the bottom; the exercise asks when it is "
     "$\\delta$ from the top, $\\theta = \\pi - \\delta$."):
        ("その値は振り子が最下点から $\\delta$ の位置にある時刻である。演習が求めているのは、"
         "最高点から $\\delta$ の位置、すなわち $\\theta = \\pi - \\delta$ にある時刻である。"),
    "the exact time $t_\\delta$ for $\\delta = 10^{-8}$, $\\omega_0 = 1.3$":
        "$\\delta = 10^{-8}$、$\\omega_0 = 1.3$ のときの正確な時刻 $t_\\delta$",
    "the period for $\\varepsilon = 10^{-2}$, $\\omega_0 = 1$":
        "$\\varepsilon = 10^{-2}$、$\\omega_0 = 1$ のときの周期",
    "That is the estimate $4\\log(8/\\varepsilon)$ of part 1; part 3 asks for `ep.period`.":
        ("その値は小問 1 の見積もり $4\\log(8/\\varepsilon)$ である。小問 3 が求めているのは "
         "`ep.period` による値である。"),
    ("That is the period ratio $R$, the period in units of the small-swing period "
     "$2\\pi/\\omega_0$; the exercise asks for the period itself."):
        ("その値は周期比 $R$、すなわち微小振動の周期 $2\\pi/\\omega_0$ を単位とした周期である。"
         "演習が求めているのは周期そのものである。"),
    "The period is four quarter swings, $4K_1(\\alpha)/\\omega_0$.":
        "周期は 4 分の 1 周期の 4 つ分、すなわち $4K_1(\\alpha)/\\omega_0$ である。",
    "the period for $\\varepsilon = 10^{-6}$, $\\omega_0 = 1$":
        "$\\varepsilon = 10^{-6}$、$\\omega_0 = 1$ のときの周期",
    "the integral of $\\theta'$ over the whole real line, $\\omega_0 = 1.3$":
        "$\\omega_0 = 1.3$ のときの、実数直線全体にわたる $\\theta'$ の積分",
    ("That is half of it: did you integrate from $0$ only? The motion runs from $t = -\\infty$ "
     "to $+\\infty$."):
        ("その値は半分である。$0$ からだけ積分していないか。運動は $t = -\\infty$ から "
         "$+\\infty$ まで続く。"),
    "Check the factor in front: $\\theta' = 2\\omega_0/\\cosh(\\omega_0 t)$.":
        "前の係数を確かめること。$\\theta' = 2\\omega_0/\\cosh(\\omega_0 t)$ である。",
}
