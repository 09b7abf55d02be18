"""Japanese of the texts of the self-checks in equation.py (see __init__.py)."""

from __future__ import annotations

MESSAGES = {
    "the lower end of the set of release angles for which the rod must push, in radians":
        "棒が押す必要が生じる放す角度の集合の下端（ラジアン）",
    "Give the angle in radians, as `math` and `numpy` use them.":
        "`math` や `numpy` と同じく、角度はラジアンで答えること。",
    ("That is the upper end of the set, the release from the top. Where does $\\cos\\theta_0$ "
     "first become negative?"):
        ("その値は集合の上端、すなわち最高点から放す場合である。$\\cos\\theta_0$ "
         "が初めて負になるのはどこか。"),
    "the smallest tension over the swing released from 60 degrees, in units of the weight $mg$":
        "60 度から放した振動における張力の最小値（重力 $mg$ を単位とする）",
    ("That is the tension at the bottom, the largest one. Where on the swing is $\\cos\\theta$ "
     "smallest?"):
        ("その値は最下点での張力、すなわち最大の張力である。振動の途中で $\\cos\\theta$ "
         "が最小になるのはどこか。"),
    ("Did you give the cosine an angle in degrees? Python's `math.cos` and `numpy.cos` take "
     "radians."):
        ("余弦に度で表した角度を与えていないか。Python の `math.cos` と `numpy.cos` "
         "はラジアンを引数にとる。"),
    "That is a tension in newtons for the 0.3 kg bob; give it in units of the weight $mg$.":
        ("その値は 0.3 kg のおもりについてニュートン単位で表した張力である。重力 $mg$ "
         "を単位として答えること。"),
    ("the angle $\\theta$ at which the string goes slack after the kick $v = 2\\omega_0$, in "
     "radians"):
        "初速 $v = 2\\omega_0$ を与えたあとでひもがたるむ角度 $\\theta$（ラジアン）",
    ("Measure $\\theta$ from the bottom: the string goes slack above the horizontal, where "
     "$\\cos\\theta < 0$."):
        ("$\\theta$ は最下点から測ること。ひもがたるむのは水平より上、すなわち $\\cos\\theta < "
         "0$ となるところである。"),
    "the period of the 1 m pendulum released from 30 degrees, in seconds":
        "30 度から放した長さ 1 m の振り子の周期（秒）",
    ("That is the small-angle period (8); the exercise asks for the exact period, the attribute "
     "`period` of the motion."):
        ("その値は微小振動の周期 (8) である。演習が求めているのは厳密な周期、すなわち運動の属性 "
         "`period` である。"),
    "Did you pass 30 to `solve`? The library takes radians.":
        "`solve` に 30 を渡していないか。ライブラリはラジアンを引数にとる。",
    ("The period is a full swing, there and back: four times the time from the turning point to "
     "the bottom."):
        "周期は行って戻る一往復の振動の時間であり、折り返し点から最下点までの時間の 4 倍である。",
    "the fraction $1 - P_8/P$ by which the small-angle period (8) is too short at 30 degrees":
        "30 度において微小振動の周期 (8) が短すぎる割合 $1 - P_8/P$",
    ("That is $P/P_8 - 1$, the excess measured in units of (8); give it as a fraction of the "
     "exact period, $1 - P_8/P$."):
        ("その値は (8) を単位として測った超過分 $P/P_8 - 1$ である。厳密な周期に対する割合 $1 - "
         "P_8/P$ として答えること。"),
    "That is the ratio $P_8/P$; the fraction it is too short by is what is missing to 1.":
        "その値は比 $P_8/P$ である。短すぎる割合は、その比が 1 に足りない分である。",
    ("the release angle, in degrees, from which (8) is too short by more than 1 %, that is "
     "$1 - P_8/P > 0.01$"):
        "(8) の不足が 1 % を超える、すなわち $1 - P_8/P > 0.01$ となる放す角度の下限（度）",
    "Give the angle in degrees.":
        "角度は度で答えること。",
    ("That is the two-term estimate $P/P_8 \\approx 1 + \\theta_0^2/16$; the exercise asks for "
     "the exact period's crossing."):
        ("その値は 2 項による見積もり $P/P_8 \\approx 1 + \\theta_0^2/16$ から求めた角度である。"
         "演習が求めているのは、厳密な周期が境目を越える角度である。"),
    ("Did you solve $P/P_8 = 1.01$? The 1 % here is the shortfall of (8) as a fraction of the "
     "true period: $1 - P_8/P = 0.01$."):
        ("$P/P_8 = 1.01$ を解いていないか。ここでの 1 % は、真の周期に対する (8) "
         "の不足の割合であり、$1 - P_8/P = 0.01$ である。"),
}
