"""Japanese of the texts of the self-checks in rotation.py (see __init__.py)."""

from __future__ import annotations

MESSAGES = {
    "the largest angular velocity over the turn":
        "1 回転の間の角速度の最大値",
    "The largest speed is $2\\omega_0/\\gamma$, not $2\\omega_0\\gamma$.":
        "最大の速さは $2\\omega_0\\gamma$ ではなく $2\\omega_0/\\gamma$ である。",
    "the smallest angular velocity over the turn":
        "1 回転の間の角速度の最小値",
    "Did you drop the $1/\\gamma$? The smallest speed is $2\\omega_0\\gamma'/\\gamma$.":
        "$1/\\gamma$ を落としていないか。最小の速さは $2\\omega_0\\gamma'/\\gamma$ である。",
    "The top is $2\\ell$ above the bottom: $\\cos\\theta$ goes from 1 to $-1$ on the way up.":
        "最高点は最下点より $2\\ell$ 高い。上る間に $\\cos\\theta$ は 1 から $-1$ まで変わる。",
    ("That is the ratio of the largest to the smallest speed, $1/\\gamma'$; give the smallest "
     "speed itself."):
        ("その値は最大の速さと最小の速さの比 $1/\\gamma'$ である。"
         "最小の速さそのものを答えること。"),
    "the time $P_{IV}$ of one turn":
        "1 回転の時間 $P_{IV}$",
    ("That is half a turn: $\\operatorname{am}$ must grow by $\\pi$, so $\\theta$ grows by "
     "$2\\pi$."):
        ("その値は半回転の時間である。$\\operatorname{am}$ が $\\pi$ 増えなければならず、"
         "そのとき $\\theta$ は $2\\pi$ 増える。"),
    "Did you leave out $\\omega_0 = 1.7$? $P_{IV} = 2\\gamma K_1(\\gamma)/\\omega_0$.":
        ("$\\omega_0 = 1.7$ を入れ忘れていないか。$P_{IV} = 2\\gamma K_1(\\gamma)/\\omega_0$ "
         "である。"),
    "the mean angular velocity $(2\\omega_0/\\gamma)\\,\\tau$":
        "平均角速度 $(2\\omega_0/\\gamma)\\,\\tau$",
    "That counts turns per unit time; an angular velocity counts radians, $2\\pi$ for each turn.":
        ("その値は単位時間あたりの回転数である。角速度はラジアンで数え、1 回転ごとに $2\\pi$ "
         "である。"),
    ("That is the largest speed $2\\omega_0/\\gamma$, at the bottom; the mean is $\\tau$ times "
     "it."):
        "その値は最下点での最大の速さ $2\\omega_0/\\gamma$ である。平均はその $\\tau$ 倍である。",
    "That is the speed $\\theta'(0)$ at the start, not the mean over a turn.":
        "その値は出発時の速さ $\\theta'(0)$ であり、1 回転にわたる平均ではない。",
    "the mean angular velocity for $v = 10$":
        "$v = 10$ のときの平均角速度",
    ("That is the estimate $v - \\omega_0^2/v$; the exercise asks for the mean $2\\pi/P_{IV}$ "
     "of the motion."):
        ("その値は見積もり $v - \\omega_0^2/v$ である。演習が求めているのは、運動の平均 "
         "$2\\pi/P_{IV}$ である。"),
    "That is the kick $v$ itself; gravity slows the rotation on average.":
        "その値は初速 $v$ そのものである。重力は平均して回転を遅くする。",
    "the remainder of the mean after $v - 1/v$, times $v^3$, for $v = 30$":
        "$v = 30$ のとき、平均から $v - 1/v$ を引いた残りに $v^3$ を掛けたもの",
    ("That is the coefficient $-5/4$ of the series; the exercise asks for the remainder of the "
     "motion's mean, which differs a little from it."):
        ("その値は級数の係数 $-5/4$ である。演習が求めているのは運動の平均の残りであり、"
         "それはこの係数とわずかに異なる。"),
    "Multiply the remainder by $v^3$, not $v^2$.":
        "残りには $v^2$ ではなく $v^3$ を掛けること。",
    "the largest value of $W$ over a period for $\\gamma = 0.2$":
        "$\\gamma = 0.2$ のときの 1 周期にわたる $W$ の最大値",
    ("That is the estimate $\\gamma^2/8$ of part 1; part 2 asks for the maximum of $W$ computed "
     "with `ep.am`."):
        ("その値は小問 1 の見積もり $\\gamma^2/8$ である。小問 2 が求めているのは、`ep.am` "
         "で計算した $W$ の最大値である。"),
    ("The amplitude is the largest value of $W$, not the difference between its largest and "
     "smallest values."):
        "振幅は $W$ の最大値であり、最大値と最小値の差ではない。",
    "`ep.am` takes the modulus $\\gamma$, not the parameter $m = \\gamma^2$.":
        "`ep.am` はパラメータ $m = \\gamma^2$ ではなく、母数 $\\gamma$ を引数にとる。",
    "the largest value of $W$ over a period for $\\gamma = 0.3$":
        "$\\gamma = 0.3$ のときの 1 周期にわたる $W$ の最大値",
}
