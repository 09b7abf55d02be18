"""Japanese of the texts of the self-checks in in_motion.py (see __init__.py)."""

from __future__ import annotations

MESSAGES = {
    ("the fraction of the time spent beyond half the amplitude, $|\\theta| > \\theta_0/2$, for "
     "$\\theta_0 = 2$ rad"):
        ("$\\theta_0 = 2$ rad の振動で、振り子が振幅の半分より外側 $|\\theta| > \\theta_0/2$ "
         "にいる時間の割合"),
    ("That is the fraction of a small swing, $\\theta = \\theta_0\\cos\\omega_0 t$; this swing "
     "is wide: use its exact motion."):
        ("その値は微小振動 $\\theta = \\theta_0\\cos\\omega_0 t$ の場合の割合である。"
         "この振動は振幅が大きいので、その厳密な運動を用いること。"),
    ("That is the share of the time within half the amplitude; the exercise asks for the time "
     "beyond it."):
        ("その値は振幅の半分より内側にいる時間の割合である。演習が求めているのは、"
         "その外側にいる時間である。"),
    ("The time $t_1$ to reach $\\theta_0/2$ lies in one quarter of the period: divide it by "
     "$P/4$, not by $P/2$ or $P$."):
        ("$\\theta_0/2$ に達するまでの時間 $t_1$ は 4 分の 1 周期の中にある。$P/2$ や $P$ "
         "ではなく $P/4$ で割ること。"),
    ("the speed $\\theta'(0)$ at the bottom of the rotation that turns once in one period $P$ "
     "of the swing from 2 rad"):
        ("2 rad から放した振動の 1 周期 $P$ の間にちょうど 1 回だけ回転する回転の、"
         "最下点での速さ $\\theta'(0)$"),
    ("That rotation turns once in $P/2$, twice in $P$ (the figure's): set the time of one turn "
     "equal to $P$."):
        ("その回転は $P/2$ で 1 回転し、$P$ の間に 2 回転する（図の回転である）。1 回転の時間を "
         "$P$ に等しくおくこと。"),
    ("That is the estimate $2\\omega_0(1 + 8e^{-\\omega_0 P})$ of part 2; part 1 asks for the "
     "exact root."):
        ("その値は小問 2 の見積もり $2\\omega_0(1 + 8e^{-\\omega_0 P})$ である。小問 1 "
         "が求めているのは厳密な根である。"),
    "the excess $\\varepsilon$ in $\\theta'(0) = 2\\omega_0(1 + \\varepsilon)$":
        "$\\theta'(0) = 2\\omega_0(1 + \\varepsilon)$ における超過分 $\\varepsilon$",
    ("That is the estimate $8e^{-\\omega_0 P}$ of part 2; part 1 asks for the exact "
     "$\\varepsilon$ of the speed you found."):
        ("その値は小問 2 の見積もり $8e^{-\\omega_0 P}$ である。小問 1 が求めているのは、"
         "求めた速さに対する厳密な $\\varepsilon$ である。"),
    ("$\\varepsilon$ is relative to the separatrix speed: $\\varepsilon = "
     "\\theta'(0)/(2\\omega_0) - 1$."):
        ("$\\varepsilon$ はセパラトリクスの速さに対する相対値であり、$\\varepsilon = "
         "\\theta'(0)/(2\\omega_0) - 1$ である。"),
}
