r"""Japanese for the figures' words (the modules of this package).

MESSAGES maps each English text a figure writes (the first argument of each ``say(...)``
call in the plotting modules: axis labels, legend entries and titles, annotations) to its
Japanese, with the same ``{placeholders}`` and the same mathematics: a symbol inside
``$...$`` stays as it is, and a unit or a remark in parentheses takes full-width ones
("$\theta$（rad）"). The terms are the book's (book/glossary.md and the chapters' catalogs:
領域, 振動, 回転, セパラトリクス, 振幅, 骨格曲線, 折れ曲がり点, 掃引, 自由飛行, 高調波);
names of people and of methods in Latin letters stay in them, as in the Japanese chapters
(Kidd-Fogg, AGM, FFT). tests/plotting/test_plotting_ja.py keeps the table in step with the
modules and draws every figure with it.
"""

from __future__ import annotations

MESSAGES = {
    # phase.py: the phase portrait's legend title, for each choice of notes
    "regime": "領域",
    "regime (labels on the curves: $c_1/\\omega_0^2$)": "領域（曲線上の数値：$c_1/\\omega_0^2$）",
    "regime (arrows: direction of motion)": "領域（矢印：運動の向き）",
    "regime (labels on the curves: $c_1/\\omega_0^2$; arrows: direction of motion)":
        "領域（曲線上の数値：$c_1/\\omega_0^2$、矢印：運動の向き）",
    # functions.py
    "$u$ (grey lines: multiples of $K_1$)": "$u$（灰色の線：$K_1$ の整数倍）",
    "$\\hat I - \\tau u$ (periodic)": "$\\hat I - \\tau u$（周期的）",
    "the extension {equation}": "拡張 {equation}",
    "$f$ on $[-a, a]$": "$[-a, a]$ 上の $f$",
    "joints $x = \\pm a, \\pm 3a, \\ldots$": "つなぎ目 $x = \\pm a, \\pm 3a, \\ldots$",
    # harmonics.py: the period ratio
    "$R = {value}$ at $\\theta_0 = {angle}°$": "$\\theta_0 = {angle}°$ で $R = {value}$",
    "crossings": "交差角",
    "amplitude $\\theta_0$ (degrees)": "振幅 $\\theta_0$（度）",
    # harmonics.py: the approximations of R, as ratio_approximations names them
    "small angle": "微小振動の近似",
    "series 2": "級数（2 項）",
    "series 4": "級数（4 項）",
    "AGM 1": "AGM（1 ステップ）",
    "AGM 2": "AGM（2 ステップ）",
    "AGM 3": "AGM（3 ステップ）",
    "log": "対数近似",
    "log 2": "対数近似（2 項）",
    "amplitude $\\theta_0$": "振幅 $\\theta_0$",
    "relative error $|\\tilde R/R - 1|$": "相対誤差 $|\\tilde R/R - 1|$",
    # harmonics.py: the harmonics
    "formula": "公式",
    "$t/T$ from the upward passage": "最下点を上向きに通過してからの $t/T$",
    "harmonic $2j + 1$": "高調波の次数 $2j + 1$",
    "amplitude": "振幅",
    # forces.py
    "$T < 0$: the rod pushes": "$T < 0$：棒が押す",
    "time $t$ / period (released at $t = 0$ from $\\theta_0$)":
        "時間 $t$ / 周期（$t = 0$ に $\\theta_0$ から放す）",
    "on the circle": "円周上",
    "free flight": "自由飛行",
    "after the jerk": "衝撃の後",
    "slack": "ひもがたるむ点",
    "$\\theta(0) = {angle}°$, $\\theta'(0) = {speed}\\,\\omega_0$":
        "$\\theta(0) = {angle}°$、$\\theta'(0) = {speed}\\,\\omega_0$",
    "kick $\\theta'(0) = {speed}\\,\\omega_0$": "最下点から $\\theta'(0) = {speed}\\,\\omega_0$",
    "taut forever": "ずっと張ったまま",
    "taut now, slack later": "いまは張り、のちにたるむ",
    "slack now (T < 0)": "いまたるんでいる（T < 0）",
    "swings": "振動",
    "separatrix": "セパラトリクス",
    "rotations": "回転",
    "rest": "静止",
    # response.py
    "exact": "厳密",
    "Duffing, $1 - A^2/16$": "ダフィング $1 - A^2/16$",
    "amplitude $A$ (degrees)": "振幅 $A$（度）",
    "energy $h = c_1/(2\\omega_0^2)$": "エネルギー $h = c_1/(2\\omega_0^2)$",
    "stable": "安定",
    "unstable": "不安定",
    "exact backbone": "厳密な骨格曲線",
    "Duffing's backbone": "ダフィングの骨格曲線",
    "small-angle response": "微小振幅の応答",
    "long integration": "長時間の積分",
    "folds": "折れ曲がり点",
    "forcing frequency $\\Omega$": "外力の角振動数 $\\Omega$",
    "amplitude $A$ (rad)": "振幅 $A$（rad）",
    "stable motions": "安定な運動",
    "unstable motions": "不安定な運動",
    "sweep up": "上向きの掃引",
    "sweep down": "下向きの掃引",
    # well.py: each level of energy, after its regime's numeral
    "{numeral}: {name}": "{numeral}：{name}",
    "swing": "振動",
    "rotation": "回転",
    # animation.py
    "$\\theta$ (reduced to $(-\\pi, \\pi]$)": "$\\theta$（$(-\\pi, \\pi]$ に還元）",
    "{name} ({numeral})": "{name}（{numeral}）",
    "libration": "振動",
}
