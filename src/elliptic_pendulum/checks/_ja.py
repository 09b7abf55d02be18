r"""Japanese for the book's checks: the verdicts (verify.py) and the registry (registry.py).

MESSAGES maps each English text those modules write, exactly as written there (the first
argument of each ``say(...)`` call), to its Japanese with the same ``{placeholders}``; and the
package's own fragments a verdict quotes: the labels and domains of the note's identities
(identities.py), the kinds of check and the justifications of ``registry.STATUS``. The texts
a book's cell passes in are not here: the book's catalog translates them
(``ELLIPTIC_PENDULUM_MESSAGES``).

The terms are the book's (book/glossary.md, the catalog of checks.md): 検証 (check), 判定
(verdict), 変異式 (mutant), 恒等式, 数値的事実, 許容誤差, 定義域; the sentences are in
である調. A verdict's sentence follows its claim ("(13) は恒等的に成り立つ。"), so those that
follow a claim begin with 「は」. tests/checks/test_checks_ja.py keeps this table in step with
the modules.
"""

from __future__ import annotations

MESSAGES = {
    # --- verify.py: the verdict's sentence, after its claim --------------------------------
    "follows by arithmetic: sympy evaluates both sides to the same value":
        "は計算から従う。sympy は両辺を同じ値に評価する",
    "holds for {domain}, not beyond: sympy reduces the difference of its two sides to 0 there":
        "は {domain} で成り立ち、その外では成り立たない。そこでは sympy が両辺の差を 0 に簡約する",
    "holds for {domain}: sympy reduces the difference of its two sides to 0 there":
        "は {domain} で成り立つ。そこでは sympy が両辺の差を 0 に簡約する",
    "holds identically: sympy reduces the difference of its two sides to 0":
        "は恒等的に成り立つ。sympy は両辺の差を 0 に簡約する",
    "holds: {measure} {error} over {over}":
        "は成り立つ。{over}にわたって、{measure}は {error} である",
    # --- verify.py: how it was checked ------------------------------------------------------
    "How it was checked": "どのように検証したか",
    ("Sympy splits square roots as if their radicands were positive, which is true for "
     "{domain} only; without that step the difference is below $10^{{-20}}$ at {count} "
     "points of it."):
        ("sympy は根号の中身が正であるかのように平方根を分解するが、それが正しいのは "
         "{domain} においてのみである。その段階を使わずに計算しても、そこにある {count} 個の"
         "点で差は $10^{{-20}}$ 未満である。"),
    "Beyond it the statement is false: at {point} the two sides differ by {difference}.":
        "その外では主張は成り立たない。{point} では両辺の差は {difference} である。",
    "A wrong version, {label}, is rejected: sympy does not reduce it to 0.":
        "変異式（{label}）は退けられる。sympy はその差を 0 に簡約しない。",
    "No wrong version is tried.": "変異式は試していない。",
    "Measured against an independent computation; the tolerance is {tolerance}.":
        "独立な計算と比べて測った。許容誤差は {tolerance} である。",
    "A wrong version, {label}, is rejected: its {measure} is {error}.":
        "変異式（{label}）は退けられる。その{measure}は {error} である。",
    "A wrong version, a changed formula, is rejected: its {measure} is {error}.":
        "式を変えた変異式は退けられる。その{measure}は {error} である。",
    # numeric's default measure
    "max |residual|": "残差の絶対値の最大値",
    # --- identities.py: the labels of mutants and the domains a verdict quotes --------------
    # The claims named in words (the book's mark of checked claims quotes them too).
    "§3, after (10)": "§3、(10) の後",
    "§3, case I": "§3、領域 I",
    "§3, case II, direction": "§3、領域 II、向き",
    "§4, before (14)": "§4、(14) の前",
    "Proposition 1.2": "命題 1.2",
    "Proposition 1.3": "命題 1.3",
    "the opposite sense of rotation": "逆向きの回転",
    "the other branch, $-2\\omega_0\\cos\\frac{\\theta}{2}$":
        "もう一方の枝 $-2\\omega_0\\cos\\frac{\\theta}{2}$",
    "the modulus for the parameter, $1/\\sqrt{(1-z^2)(1-\\alpha z^2)}$":
        "パラメータの代わりに母数を用いた $1/\\sqrt{(1-z^2)(1-\\alpha z^2)}$",
    "$(E_1)_z$ itself, $1/\\sqrt{(1-G^2)(1-\\alpha^2G^2)}$":
        "$(E_1)_z$ そのもの、すなわち $1/\\sqrt{(1-G^2)(1-\\alpha^2G^2)}$",
    "$\\alpha^2 - 2\\alpha - 1$, the value of the printed $-(1+\\alpha)^2 + 2\\alpha^2$":
        "$\\alpha^2 - 2\\alpha - 1$（印刷された $-(1+\\alpha)^2 + 2\\alpha^2$ の値）",
    "the note's printed difference": "原ノートに印刷された差",
    "the minus branch of (13)": "(13) の負の枝",
    "all real $t$": "すべての実数 $t$",
    "$2(E_1)_z$, as if $E_1$ were even": "$E_1$ が偶関数であるかのような $2(E_1)_z$",
    "the minus branch": "負の枝",
    "$\\hat I(u) - \\tau u + \\pi$ (no period)": "$\\hat I(u) - \\tau u + \\pi$（周期的でない）",
    # --- registry.py: the tables ------------------------------------------------------------
    "| claim | kind of check | mutants rejected | where |":
        "| 主張 | 検証の種類 | 退けた変異式 | 場所 |",
    "| check | kind | mutant rejected | where |": "| 検証 | 種類 | 退けた変異式 | 場所 |",
    "{kind}: {why}": "{kind}：{why}",
    "{page}: {section}": "{page}：{section}",
    "none": "なし",
    "**none**": "**なし**",
    "(unnamed)": "（名前なし）",
    # registry.KINDS
    "sympy identity": "sympy による恒等式",
    "independent numerical check": "独立な数値検証",
    "numerical fact": "数値的事実",
    "arithmetic": "計算",
    "proof in the text only": "本文中の証明のみ",
    "definition": "定義",
    # registry.STATUS: why a claim is a definition or proved in the text only
    "the bob's position and the rod's pull, read off the figure":
        "おもりの位置と棒が引く力。図から読み取る",
    "Newton's second law for the bob: the model itself":
        "おもりに対するニュートンの第 2 法則。モデルそのものである",
    "the small-angle model $\\sin\\theta \\approx \\theta$, an approximation of (3)":
        "微小振動のモデル $\\sin\\theta \\approx \\theta$。(3) の近似である",
    "names $\\omega_0 = \\sqrt{g/\\ell}$": "$\\omega_0 = \\sqrt{g/\\ell}$ と名づける",
    "names $\\theta_0$ by $\\cos\\theta_0 = -c_1/(2\\omega_0^2)$":
        "$\\cos\\theta_0 = -c_1/(2\\omega_0^2)$ によって $\\theta_0$ を名づける",
    "names $\\xi = \\sin(\\theta/2)/\\alpha$": "$\\xi = \\sin(\\theta/2)/\\alpha$ と名づける",
    "names $E_1$, the incomplete elliptic integral": "第 1 種楕円積分 $E_1$ を名づける",
    "names $K_1 = E_1(1)$": "$K_1 = E_1(1)$ と名づける",
    "names $G$, the inverse of $E_1$": "$E_1$ の逆関数 $G$ を名づける",
    "the periodic extension $\\bar f$ of Lemma 2.2": "補題 2.2 の周期的な拡張 $\\bar f$",
    "the staircase extension $\\hat f$ of Lemma 2.3": "補題 2.3 の階段状の拡張 $\\hat f$",
    ("that every solution of (3) with this energy is (25), so its $\\xi$ is (24): uniqueness "
     "for (3); the constants $\\xi = \\pm 1$ solve (15) but not (3)"):
        ("このエネルギーをもつ (3) の解はすべて (25) であり、したがってその $\\xi$ は (24) で"
         "あること。(3) の解の一意性による。定数 $\\xi = \\pm 1$ は (15) を満たすが (3) は"
         "満たさない"),
    "names $H_0$, an integral": "積分 $H_0$ を名づける",
    "names $H_1$, an integral": "積分 $H_1$ を名づける",
    "names $I = \\arcsin G$": "$I = \\arcsin G$ と名づける",
    "that every rotation is $\\pm 2\\hat I(\\omega_0 t/\\gamma + c_4)$: uniqueness for (3)":
        ("すべての回転が $\\pm 2\\hat I(\\omega_0 t/\\gamma + c_4)$ であること。(3) の解の"
         "一意性による"),
    "the mean value theorem; a statement about all f":
        "平均値の定理。すべての f についての主張である",
}
