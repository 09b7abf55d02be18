"""Japanese of the texts of the self-checks in complex_picture.py (see __init__.py)."""

from __future__ import annotations

MESSAGES = {
    "the ratio $K'/K$ for $k = \\sin 75^\\circ$, to four digits":
        "$k = \\sin 75^\\circ$ に対する比 $K'/K$（4 桁まで）",
    ("That is $K/K'$: $K'$ comes from the mean that starts at $k_c = \\cos 75^\\circ$, and "
     "$K = \\pi/(2\\operatorname{AGM}(1, k_c))$."):
        ("それは $K/K'$ である。$K'$ は $k_c = \\cos 75^\\circ$ から始まる平均から得られ、"
         "$K = \\pi/(2\\operatorname{AGM}(1, k_c))$ であることに注意すること。"),
}
