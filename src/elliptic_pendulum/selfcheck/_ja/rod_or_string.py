"""Japanese of the texts of the self-checks in rod_or_string.py (see __init__.py)."""

from __future__ import annotations

MESSAGES = {
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
}
