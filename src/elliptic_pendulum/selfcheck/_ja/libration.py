"""Japanese of the texts of the self-checks in libration.py (see __init__.py)."""

from __future__ import annotations

MESSAGES = {
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
}
