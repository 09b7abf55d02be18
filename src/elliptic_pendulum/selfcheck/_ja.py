"""Japanese for the self-checks (_core.py).

What judge and check say, and each exercise's texts, for the notebooks of the Japanese
edition.

MESSAGES maps every ``Value.what`` and ``Hint.message`` of the chapter modules, exactly as
written there, to its Japanese; the terms are the book's (book/glossary.md and the chapters'
catalogs in book/locale/ja/LC_MESSAGES). A formula, a name in backticks or a role stays as
it is, so that the notebook typesets and links it as in English. Hints addressed to the
student end in 「…こと。」 or ask 「…か。」; the rest is in the book's である調.
tests/selfcheck/test_selfcheck_ja.py keeps MESSAGES in step with the chapter modules.
"""

from __future__ import annotations

# The sentences of _core.judge and _core.check, with the placeholders of _core.ENGLISH.
TEMPLATES = {
    "still": "{name} はまだ `...` のままである。その場所に答え（{what}）を入れること。",
    "kind": "{name} には{kind}（{what}）を入れること。いまの値は {type} 型の {answer} である。",
    "right": "{name} は正しい。",
    "hint": "{name} はまだ正しくない。{hint}",
    "sign": "{name} は符号が逆である。",
    "too_large": "{name} は {percent}% 大きすぎる。",
    "too_small": "{name} は {percent}% 小さすぎる。",
    "too_large_in_magnitude": "{name} は絶対値が {percent}% 大きすぎる。",
    "too_small_in_magnitude": "{name} は絶対値が {percent}% 小さすぎる。",
    "look_again": "{name} はまだ正しくない。求める量（{what}）を見直すこと。",
    "missing": "`{var}` が渡されていない。{var}={var} として渡すこと。",
    "all_right": "すべて正しい。",
}
# What an answer should be, after 「には」: each begins with a Japanese word, so that the
# sentence needs no space before it.
KINDS = {float: "数値", int: "整数", bool: "真偽値 True または False", str: "文字列"}
OTHER_KIND = "型 {kind} の値"

MESSAGES = {
    # complex_picture.py
    "the ratio $K'/K$ for $k = \\sin 75^\\circ$, to four digits":
        "$k = \\sin 75^\\circ$ に対する比 $K'/K$（4 桁まで）",
    ("That is $K/K'$: $K'$ comes from the mean that starts at $k_c = \\cos 75^\\circ$, and "
     "$K = \\pi/(2\\operatorname{AGM}(1, k_c))$."):
        ("それは $K/K'$ である。$K'$ は $k_c = \\cos 75^\\circ$ から始まる平均から得られ、"
         "$K = \\pi/(2\\operatorname{AGM}(1, k_c))$ であることに注意すること。"),
    # action_angle.py
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
    # energy.py
    "the fraction by which $Q$ varies along a swing of 90 degrees":
        "振幅 90 度の振動に沿って $Q$ が変化する割合",
    ("That is the ratio of the smallest to the largest value of $Q$; the fraction it varies by "
     "is what is missing to 1."):
        "その値は $Q$ の最小値と最大値の比である。変化の割合は、その比が 1 に足りない分である。",
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
    ("Did you give the sine an angle in degrees? Python's `math.sin` and `numpy.sin` take "
     "radians."):
        ("正弦に度で表した角度を与えていないか。Python の `math.sin` と `numpy.sin` "
         "はラジアンを引数にとる。"),
    ("That is the linearised pendulum's largest speed $\\omega_0\\theta_0$; this swing is far "
     "from small."):
        ("その値は線形化した振り子の最大の速さ $\\omega_0\\theta_0$ である。"
         "この振動は微小振動からほど遠い。"),
    # equation.py
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
    # in_motion.py
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
    # libration.py
    "the estimate of $R$ at 90 degrees from the first two terms of the series":
        "級数の最初の 2 項による、90 度での $R$ の見積もり",
    "The modulus is $\\alpha = \\sin(\\theta_0/2)$, not $\\theta_0/2$.":
        "母数は $\\theta_0/2$ ではなく $\\alpha = \\sin(\\theta_0/2)$ である。",
    "That estimates $K_1$; the period ratio is $R = (2/\\pi)K_1$.":
        "その値は $K_1$ の見積もりである。周期比は $R = (2/\\pi)K_1$ である。",
    "the estimate of $R$ at 90 degrees from the first three terms":
        "最初の 3 項による、90 度での $R$ の見積もり",
    "The third term has $\\alpha^4$, not $\\alpha^2$.":
        "第 3 項に含まれるのは $\\alpha^2$ ではなく $\\alpha^4$ である。",
    "the period ratio $R$ of the swing of 90 degrees, from `ep.period_ratio`":
        "`ep.period_ratio` による、振幅 90 度の振動の周期比 $R$",
    "That is $K_1(\\alpha)$; the period ratio is $R = (2/\\pi)K_1$.":
        "その値は $K_1(\\alpha)$ である。周期比は $R = (2/\\pi)K_1$ である。",
    ("That is the period for $\\omega_0 = 1$; the ratio $R$ divides it by the small-swing "
     "period $2\\pi/\\omega_0$."):
        ("その値は $\\omega_0 = 1$ のときの周期である。比 $R$ は、それを微小振動の周期 "
         "$2\\pi/\\omega_0$ で割ったものである。"),
    "That is a partial sum of the series; $R$ is the library's `ep.period_ratio`.":
        "その値は級数の部分和である。$R$ はライブラリの `ep.period_ratio` の値である。",
    # libration_solution.py
    "the seconds a day the clock loses at an amplitude of 5 degrees":
        "振幅 5 度のときに時計が 1 日に遅れる秒数",
    ("In a real day the pendulum makes $86400/P_{II}$ swings and the clock shows $86400/R$ "
     "seconds: the loss is $86400(1 - 1/R)$, not $86400(R - 1)$."):
        ("実際の 1 日の間に振り子は $86400/P_{II}$ 回往復し、時計は $86400/R$ 秒を示す。遅れは "
         "$86400(R - 1)$ ではなく $86400(1 - 1/R)$ である。"),
    "That is the two-term estimate of part 3; part 1 asks for `ep.period_ratio`.":
        ("その値は小問 3 の 2 項による見積もりである。小問 1 が求めているのは `ep.period_ratio` "
         "による値である。"),
    "the amplitude, in degrees, at which the clock loses one minute a day":
        "時計が 1 日に 1 分遅れる振幅（度）",
    "Give the amplitude in degrees.":
        "振幅は度で答えること。",
    ("Losing a minute a day means the clock shows 86340 s while a day of 86400 s passes: $R = "
     "86400/86340$."):
        ("1 日に 1 分遅れるとは、86400 s の 1 日が過ぎる間に時計が 86340 s を示すことであり、$R "
         "= 86400/86340$ である。"),
    ("That is the two-term estimate $R \\approx 1 + \\theta_0^2/16$ solved for $\\theta_0$; "
     "part 2 asks for `ep.crossing_angle`."):
        ("その値は 2 項による見積もり $R \\approx 1 + \\theta_0^2/16$ を $\\theta_0$ "
         "について解いたものである。小問 2 が求めているのは `ep.crossing_angle` による値である。"),
    # period_in_depth.py
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
    # resonance.py
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
    # rod_or_string.py
    ("the smallest speed at the bottom that keeps the string taut all the way round ($\\omega_0 "
     "= 1$)"):
        "一周の間ずっとひもを張ったままにする、最下点での最小の速さ（$\\omega_0 = 1$）",
    ("That speed just reaches the top, enough for a rod; a string goes slack before it: ask for "
     "the tension to stay positive (`ep.string_stays_taut`)."):
        ("その速さはちょうど最高点に届く速さであり、棒なら十分である。"
         "ひもはその手前でたるむので、"
         "張力が正のままであることを条件とすること（`ep.string_stays_taut`）。"),
    ("That speed only lifts the bob to the height of the pivot, the widest swing a string "
     "allows; the exercise asks for a full turn."):
        ("その速さでは、おもりは支点の高さまでしか上がらない。"
         "これはひもで可能な最も大きな振動である。演習が求めているのは一周する運動である。"),
    "the angular speed at the top of that motion":
        "その運動の最高点での角速度の大きさ",
    ("At the top the bob cannot be at rest: gravity alone must supply the centripetal force "
     "there, $m\\ell\\theta'^2 = mg$."):
        ("最高点でおもりが静止していることはありえない。"
         "そこでは重力だけで向心力をまかなわなければならず、$m\\ell\\theta'^2 = mg$ である。"),
    ("That is the speed at the bottom; the energy says how much of it is left at the top, "
     "$2\\ell$ higher."):
        ("その値は最下点での速さである。$2\\ell$ 高い最高点でそのうちどれだけが残るかは、"
         "エネルギーからわかる。"),
    "The top is $2\\ell$ above the bottom, not $\\ell$.":
        "最高点は最下点より $\\ell$ ではなく $2\\ell$ 高い。",
    ("the largest of your values of $(T_\\mathrm{bottom} - T_\\mathrm{top})/(mg)$ for the "
     "rotations of the 1.2 m pendulum"):
        ("長さ 1.2 m の振り子の回転について求めた $(T_\\mathrm{bottom} - T_\\mathrm{top})/(mg)$ "
         "の値のうち最大のもの"),
    "Divide the difference by the weight $mg$, not by the mass alone.":
        "差は質量だけで割るのではなく、重力 $mg$ で割ること。",
    ("The top is half a revolution after the bottom: the `period` of a rotation is the time of "
     "a full turn, back at the bottom."):
        ("最高点は最下点から半回転後である。回転の `period` は、最下点に戻るまでの 1 "
         "回転の時間である。"),
    ("A quarter of the `period` of a rotation puts the bob at the height of the pivot, not at "
     "the top: take half of it."):
        ("回転の `period` の 4 分の 1 では、おもりは最高点ではなく支点の高さにある。"
         "周期の半分をとること。"),
    "whether $v_y > 0$ at all five slack points (True or False)":
        "5 つのたるむ点のすべてで $v_y > 0$ となるかどうか（True または False）",
    ("With $y = -\\ell\\cos\\theta$, $v_y = \\ell\\theta'\\sin\\theta$: check the sine and that "
     "its angle is in radians; a slack point lies above the pivot's height."):
        ("$y = -\\ell\\cos\\theta$ のとき $v_y = \\ell\\theta'\\sin\\theta$ である。正弦と、"
         "その角度がラジアンであることを確かめること。たるむ点は支点の高さより上にある。"),
    "whether the bob stays strictly inside the circle during all five flights (True or False)":
        "5 つの飛行のすべての間、おもりが円の真に内側にとどまるかどうか（True または False）",
    ("Leave out the two ends of each flight, the slack and the taut instants: there the bob is "
     "on the circle, and rounding can put it a hair outside."):
        ("各飛行の両端、すなわちひもがたるむ瞬間と再び張る瞬間は除くこと。"
         "そこではおもりは円周上にあり、丸め誤差でわずかに外側に出ることがある。"),
    # problems.py
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
    # rotation.py
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
    # separatrix.py
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
