"""Japanese of the texts of the self-checks in period_in_depth.py (see __init__.py)."""

from __future__ import annotations

MESSAGES = {
    ("the number of terms of `ep.period_series` that give $R$ to a relative $10^{-6}$ at 120 "
     "degrees"):
        "120 度で $R$ を相対誤差 $10^{-6}$ まで与える `ep.period_series` の項数",
    ("Count every term, the leading term (the small-angle ratio) too: `ep.period_series(x, n)` "
     "sums `n` terms."):
        ("初項（微小振動の比）も含めて、すべての項を数えること。`ep.period_series(x, n)` は `n` "
         "項の和をとる。"),
    "Too many: stop at the first count whose relative error is below the target.":
        "多すぎる。相対誤差が目標を初めて下回った項数で止めること。",
    ("the number of AGM steps (`ep.agm_ratio`) that give $R$ to a relative $10^{-6}$ at 120 "
     "degrees"):
        "120 度で $R$ を相対誤差 $10^{-6}$ まで与える AGM のステップ数（`ep.agm_ratio`）",
    "`ep.agm_ratio(x, 0)` is the small-angle ratio, before any step: did you count it as a step?":
        ("`ep.agm_ratio(x, 0)` は、まだ 1 ステップも進めていない微小振動の比である。これを 1 "
         "ステップと数えていないか。"),
    ("Too few: is your error relative, $|R_n/R - 1|$, and is $R$ the exact ratio at 120 "
     "degrees, in radians?"):
        ("少なすぎる。誤差は相対誤差 $|R_n/R - 1|$ になっているか。また $R$ は、"
         "ラジアンで与えた 120 度での厳密な比になっているか。"),
    "the relative error $|R_1/R - 1|$ of one AGM step at 120 degrees":
        "120 度での AGM 1 ステップの相対誤差 $|R_1/R - 1|$",
    "That is the error of $1/b_1$ (Kidd and Fogg's); one AGM step gives $R_1 = 1/a_1$.":
        ("その値は $1/b_1$（Kidd と Fogg の式）の誤差である。AGM の 1 ステップが与えるのは $R_1 "
         "= 1/a_1$ である。"),
    "Give the relative error: divide the difference by $R$.":
        "差を $R$ で割って、相対誤差で答えること。",
    "whether $1/a_1 < R < 1/b_1$ at every amplitude you checked (True or False)":
        "調べたすべての振幅で $1/a_1 < R < 1/b_1$ が成り立つかどうか（True または False）",
    ("Look again at the exact $R = (2/\\pi)K_1(\\sin(\\theta_0/2))$: `scipy.special.ellipk` and "
     "`mpmath.ellipk` take $m = k^2$, not $k$; and the amplitudes must be in radians, below "
     "$\\pi$."):
        ("厳密な $R = (2/\\pi)K_1(\\sin(\\theta_0/2))$ を見直すこと。`scipy.special.ellipk` と "
         "`mpmath.ellipk` は $k$ ではなく $m = k^2$ を引数にとる。また振幅はラジアンで表し、"
         "$\\pi$ より小さくなければならない。"),
    ("the relative error $|\\bar R/R - 1|$ of the mean $\\bar R$ of the two one-step values at "
     "90 degrees"):
        "90 度での 1 ステップ後の 2 つの値の平均 $\\bar R$ の相対誤差 $|\\bar R/R - 1|$",
    "That is the error of one AGM step alone; average it with Kidd and Fogg's value first.":
        ("その値は AGM の 1 ステップだけの誤差である。先にその値と Kidd と Fogg "
         "の式の値との平均をとること。"),
    "Did you give the cosine an angle in degrees? `math.cos` and `numpy.cos` take radians.":
        ("余弦に度で表した角度を与えていないか。`math.cos` と `numpy.cos` "
         "はラジアンを引数にとる。"),
    "the largest cosine coefficient $|a_n|$ of your FFT of the swing of 150 degrees":
        "振幅 150 度の振動の FFT で得た余弦の係数の絶対値 $|a_n|$ の最大値",
    ("Start the swing at the bottom on the way up, $\\theta(0) = 0$, $\\theta'(0) > 0$ (from a "
     "turning point $\\theta$ is even: all cosines), and sample exactly one period, at $kP_{II}/N$ "
     "for $k = 0, \\ldots, N - 1$ (not $P_{II}$ itself)."):
        ("振動は最下点から上向きに、$\\theta(0) = 0$、$\\theta'(0) > 0$ "
         "で始めること（折り返し点から始めると $\\theta$ は偶関数になり、すべて余弦の項になる）"
         "。また、ちょうど 1 周期を $k = 0, \\ldots, N - 1$ に対する $kP_{II}/N$ "
         "で標本化すること（$P_{II}$ 自身は含めない）。"),
    ("Coefficients this small but not tiny are the integrator's error: tighten its tolerances "
     "(`rtol`, `atol`), or use `ep.integrate`."):
        ("この程度に小さいが、ごく小さくはない係数は積分器の誤差である。許容誤差（`rtol`、"
         "`atol`）を厳しくするか、`ep.integrate` を用いること。"),
    "the largest sine coefficient $|b_n|$ of an even harmonic $n$ in your FFT":
        "FFT で得た偶数次の高調波 $n$ の正弦の係数の絶対値 $|b_n|$ の最大値",
    ("Sample exactly one period, at $kP_{II}/N$ for $k = 0, \\ldots, N - 1$ (not $P_{II}$ "
     "itself), with $P_{II}$ the period of this amplitude, not $2\\pi/\\omega_0$; and take the "
     "even harmonics $n = "
     "2, 4, \\ldots$ (index $n$ of `rfft`)."):
        ("ちょうど 1 周期を $k = 0, \\ldots, N - 1$ に対する $kP_{II}/N$ で標本化すること"
         "（$P_{II}$ 自身は含めない）。ここで $P_{II}$ は $2\\pi/\\omega_0$ ではなく、"
         "この振幅での周期である。"
         "また偶数次の高調波 $n = 2, 4, \\ldots$（`rfft` の添字 $n$）をとること。"),
    "the sine coefficient $b_1$ of the fundamental, from your FFT":
        "FFT で得た基本波の正弦の係数 $b_1$",
    ("`numpy.fft.rfft` turns $b\\sin(2\\pi kn/N)$ into $-ibN/2$: the sine coefficient is minus "
     "the imaginary part."):
        ("`numpy.fft.rfft` は $b\\sin(2\\pi kn/N)$ を $-ibN/2$ に変換する。"
         "正弦の係数は虚部の符号を変えたものである。"),
    ("Normalise the FFT: divide `rfft` by $N/2$ for the coefficients of $\\sin$ and $\\cos$ (by "
     "$N$ gives half of them)."):
        ("FFT を規格化すること。$\\sin$ と $\\cos$ の係数を得るには `rfft` を $N/2$ で割る（$N$ "
         "で割るとその半分になる）。"),
    ("That is the amplitude $\\theta_0$, the fundamental of a small swing; a wide swing is not "
     "a sine: take its FFT."):
        ("その値は振幅 $\\theta_0$、すなわち微小振動の基本波である。"
         "振幅の大きな振動は正弦波ではないので、その FFT をとること。"),
}
