"""Japanese of the texts of the self-checks in action_angle.py (see __init__.py)."""

from __future__ import annotations

MESSAGES = {
    ("the relative error $|E_b/(\\omega_0 J) - 1|$ of the oscillator's action for a swing of "
     "30 degrees"):
        "振幅 30 度の振動に対する調和振動子の作用変数の相対誤差 $|E_b/(\\omega_0 J) - 1|$",
    ("Measure the energy from the bottom: $E_b = E + mg\\ell$, not the energy $E$ of the book, "
     "whose zero is at the pivot."):
        ("エネルギーは最下点から測ること。支点を基準とする本書のエネルギー $E$ ではなく、"
         "$E_b = E + mg\\ell$ を用いる。"),
    ("`scipy.special.ellipk` and `ellipe` take the parameter $m = \\alpha^2$, not the modulus "
     "$\\alpha$."):
        ("`scipy.special.ellipk` と `ellipe` は母数 $\\alpha$ ではなく、パラメータ "
         "$m = \\alpha^2$ を引数にとる。"),
    ("the amplitude, in degrees, of a swing of 40 degrees once its string is slowly shortened to "
     "half"):
        "振幅 40 度の振動で、ひもをゆっくり半分の長さに縮めた後の振幅（度）",
    ("That is the small-swing law $\\theta_0 \\propto \\ell^{-3/4}$; the exercise asks for the "
     "exact action to stay constant."):
        ("その値は微小振動の法則 $\\theta_0 \\propto \\ell^{-3/4}$ による値である。"
         "演習が求めているのは、厳密な作用変数が一定に保たれるとした値である。"),
    ("A shortened string swings wider: with $J = m\\sqrt{g}\\,\\ell^{3/2}j(\\alpha)$ constant, $j$ "
     "must grow by $2^{3/2}$."):
        ("ひもを縮めると振幅は大きくなる。$J = m\\sqrt{g}\\,\\ell^{3/2}j(\\alpha)$ が一定なので、"
         "$j$ は $2^{3/2}$ 倍にならなければならない。"),
    ("the fraction $\\ell/\\ell_0$ of the string left when a swing of 90 degrees reaches the "
     "separatrix"):
        "振幅 90 度の振動がセパラトリクスに達するときに残っているひもの割合 $\\ell/\\ell_0$",
    ("The action is $m\\sqrt{g}\\,\\ell^{3/2}$ times a function of $\\alpha$: the length comes "
     "from the power $2/3$ of a ratio of actions, not $3/2$."):
        ("作用変数は $m\\sqrt{g}\\,\\ell^{3/2}$ と $\\alpha$ の関数との積である。"
         "長さは作用変数の比の $3/2$ 乗ではなく $2/3$ 乗で与えられる。"),
    "That is the rotation's action at the separatrix, $4/\\pi$; the swing reaches $8/\\pi$.":
        ("その値はセパラトリクスでの回転の作用変数 $4/\\pi$ による値である。"
         "振動の作用変数は $8/\\pi$ に達する。"),
}
