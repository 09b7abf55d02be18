"""Japanese for the self-checks (_core.py).

What judge and check say, and each exercise's texts, for the notebooks of the Japanese
edition.

MESSAGES maps every ``Value.what`` and ``Hint.message`` of the chapter modules, exactly as
written there, to its Japanese; the terms are the book's (book/glossary.md and the chapters'
catalogs in book/locale/ja/LC_MESSAGES). A formula, a name in backticks or a role stays as
it is, so that the notebook typesets and links it as in English. Hints addressed to the
student end in 「…こと。」 or ask 「…か。」; the rest is in the book's である調.

The sentences of judge and check are here; a chapter's texts are in the module of the
chapter's name beside this one (``_ja/energy.py`` for ``energy.py``), so that a chapter and
its Japanese change together. MESSAGES joins those tables: a text that two chapters write
stands in one of them, and a text in two tables is an error, since the two could differ.
tests/selfcheck/test_selfcheck_ja.py keeps MESSAGES and each chapter's table in step with
the chapter modules.
"""

from __future__ import annotations

import importlib
import pkgutil

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


def _joined() -> dict[str, str]:
    messages: dict[str, str] = {}
    # Every module here is a chapter's table: a new chapter's joins without a list to edit.
    for module in pkgutil.iter_modules(__path__):
        table = importlib.import_module(f".{module.name}", __name__).MESSAGES
        twice = sorted(table.keys() & messages.keys())
        if twice:
            raise ValueError(f"_ja/{module.name}.py translates a text another table has: "
                             f"{twice[0]!r}")
        messages.update(table)
    return messages


MESSAGES = _joined()
