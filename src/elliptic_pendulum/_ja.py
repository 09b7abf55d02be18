"""Japanese for what the package's top-level modules show a reader: a Motion's table.

MESSAGES maps each English text of ``_display._summary`` (the first argument of each
``say(...)`` call there) and the regimes' names to its Japanese, with the same
``{placeholders}``, in the book's terms (book/glossary.md: 領域, 振動, 回転, セパラトリクス,
振幅, 周期, 第一積分). A symbol keeps its name as the one-line repr writes it (theta0,
omega0, c1, gamma), after the Japanese name of what it is. tests/test_motion_ja.py keeps the
table in step with _display.py.
"""

from __future__ import annotations

MESSAGES = {
    "states": "状態の数",
    "{count} of shape {shape}": "{count}（配列の形 {shape}）",
    "regime {numeral} ({name})": "領域 {numeral}（{name}）",
    "regime": "領域",
    "{numeral} ({name})": "{numeral}（{name}）",
    "theta0, theta0'": "初期状態 theta0, theta0'",
    "omega0": "固有角振動数 omega0",
    "c1": "第一積分 c1",
    "gamma": "母数 gamma",
    "time per revolution": "1 回転の時間",
    "amplitude": "振幅",
    "period": "周期",
    # Regime.name.lower(): the note's four kinds of motion.
    "rest": "静止",
    "libration": "振動",
    "separatrix": "セパラトリクス",
    "rotation": "回転",
}
