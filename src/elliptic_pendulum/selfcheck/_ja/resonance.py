"""Japanese of the texts of the self-checks in resonance.py (see __init__.py)."""

from __future__ import annotations

MESSAGES = {
    "the amplitude (in radians) at which a swing's frequency is $\\omega_0/2$":
        "振動の振動数が $\\omega_0/2$ となる振幅（ラジアン）",
    "Give the amplitude in radians: `math.degrees` is for showing it.":
        "振幅はラジアンで答えること。`math.degrees` は表示のためのものである。",
    ("That is where Duffing's backbone $\\omega_0(1 - A^2/16)$ is $\\omega_0/2$; the exercise "
     "asks for the exact one, `ep.backbone_frequency`."):
        ("その値はダフィングの骨格曲線 $\\omega_0(1 - A^2/16)$ が $\\omega_0/2$ "
         "となる振幅である。演習が求めているのは、厳密な骨格曲線 `ep.backbone_frequency` "
         "によるものである。"),
    ("$K_1$ takes the modulus $k = \\sin(A/2)$, and `scipy.special.ellipk` and `mpmath.ellipk` "
     "take the parameter $m = k^2$: did you pass them $k$?"):
        ("$K_1$ は母数 $k = \\sin(A/2)$ を引数にとり、`scipy.special.ellipk` と `mpmath.ellipk` "
         "はパラメータ $m = k^2$ を引数にとる。これらに $k$ を渡していないか。"),
    ("the amplitude of the library's periodic orbit for $F = 10^{-6}$, $\\zeta = 0.1$, $\\Omega "
     "= 0.8$"):
        "$F = 10^{-6}$、$\\zeta = 0.1$、$\\Omega = 0.8$ に対するライブラリの周期軌道の振幅",
    ("That is the undamped response: the damping term $2i\\zeta\\omega_0\\Omega$ belongs in the "
     "denominator."):
        "その値は減衰のない場合の応答である。減衰項 $2i\\zeta\\omega_0\\Omega$ も分母に入る。",
    "The damping term of the equation is $2\\zeta\\omega_0\\theta'$: did you drop its factor 2?":
        "方程式の減衰項は $2\\zeta\\omega_0\\theta'$ である。その因子 2 を落としていないか。",
    "the modulus $|\\mu|$ of its Floquet multipliers":
        "そのフロケ乗数の絶対値 $|\\mu|$",
    ("That is the product of the two multipliers, $\\det M$; each of a complex pair has the "
     "square root of its modulus."):
        ("その値は 2 つの乗数の積 $\\det M$ である。複素共役の組の各乗数の絶対値は、"
         "その積の絶対値の平方根である。"),
    ("The period of the orbit is that of the force, $P_\\Omega = 2\\pi/\\Omega$, not "
     "$2\\pi/\\omega_0$."):
        "軌道の周期は $2\\pi/\\omega_0$ ではなく、外力の周期 $P_\\Omega = 2\\pi/\\Omega$ である。",
    "the amplitude (in radians) where Duffing's backbone crosses the exact one":
        "ダフィングの骨格曲線が厳密な骨格曲線と交わる振幅（ラジアン）",
}
