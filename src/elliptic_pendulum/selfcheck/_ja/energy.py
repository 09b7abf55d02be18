"""Japanese of the texts of the self-checks in energy.py (see __init__.py)."""

from __future__ import annotations

MESSAGES = {
    "the fraction by which $Q$ varies along a swing of 90 degrees":
        "振幅 90 度の振動に沿って $Q$ が変化する割合",
    ("That is the ratio of the smallest to the largest value of $Q$; the fraction it varies by "
     "is what is missing to 1."):
        "その値は $Q$ の最小値と最大値の比である。変化の割合は、その比が 1 に足りない分である。",
    # equation.py writes it too: it stands in one table, this one.
    "Give a fraction, not a percentage.":
        "百分率ではなく、割合で答えること。",
    "the speed $v^*$ that separates swinging back from going over the top, from $\\theta(0) = 2$":
        ("$\\theta(0) = 2$ から押し出したとき、"
         "振り戻される運動と最高点を越える運動とを分ける速さ $v^*$"),
    ("Check the half-angle identity you used: $1 + \\cos x$ is twice the square of which "
     "function of $x/2$?"):
        "用いた半角の公式を確かめること。$1 + \\cos x$ は、$x/2$ のどの関数の 2 乗の 2 倍か。",
    "The speed involves half the angle, $\\theta(0)/2$.":
        "速さには角度の半分 $\\theta(0)/2$ が現れる。",
    "the largest angular speed of the swing from 150 degrees, $\\omega_0 = 1.5$":
        "150 度から放した振動（$\\omega_0 = 1.5$）の角速度の大きさの最大値",
    # libration.py writes it too: it stands in one table, this one.
    ("Did you give the sine an angle in degrees? Python's `math.sin` and `numpy.sin` take "
     "radians."):
        ("正弦に度で表した角度を与えていないか。Python の `math.sin` と `numpy.sin` "
         "はラジアンを引数にとる。"),
    ("That is the linearised pendulum's largest speed $\\omega_0\\theta_0$; this swing is far "
     "from small."):
        ("その値は線形化した振り子の最大の速さ $\\omega_0\\theta_0$ である。"
         "この振動は微小振動からほど遠い。"),
}
