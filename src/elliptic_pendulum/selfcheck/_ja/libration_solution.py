"""Japanese of the texts of the self-checks in libration_solution.py (see __init__.py)."""

from __future__ import annotations

MESSAGES = {
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
}
