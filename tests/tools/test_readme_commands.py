"""tests/readme.py, which the build tier uses to run the README's commands."""

from __future__ import annotations

import re

from tests.book.test_readme import MADE
from tests.readme import ROOT, Run, commands, run


def test_every_command_of_the_readme_is_run() -> None:
    # The README's own list, read here as a reader reads it, against what the tier runs.
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    shown = set(re.findall(r"\bmake [a-z][\w-]*", text)) - {"make test"}
    assert shown <= set(commands()) and shown, sorted(shown - set(commands()))
    assert set(MADE) == set(commands()) - {"make bench"}


def test_a_run_is_cut_into_the_recipe_lines_it_echoes(tmp_path) -> None:
    # A Makefile of two recipe lines in the form of the project's: each line's output is
    # its own, and the exit code belongs to the line that failed.
    (tmp_path / "Makefile").write_text(
        "all:\n\tmkdir -p out\n\tcp Makefile out/ && echo \\\n\t  copied\n\ttest -f missing\n")
    got = run("make all", tmp_path)
    assert isinstance(got, Run) and got.returncode != 0
    assert [p.line.split()[0] for p in got.parts] == ["mkdir", "cp", "test"]
    assert "copied" in got.part("out/ && echo copied").output
    assert got.part("test -f missing").returncode == got.returncode
    assert got.part("mkdir -p out").returncode == 0
    assert got.part("no such line").returncode != 0
