"""The command-line examples in docs/cli.md are true: each is run and its output compared.

Every ``$ python -m elliptic_pendulum ...`` or ``$ elliptic-pendulum ...`` line inside a
``console`` block of the page is a command; the lines after it, up to the next ``$`` line or
the end of the block, are what it prints. An output that is one ``error:`` line is expected
on stderr with exit status 2 (the page's "Errors and exit status"); any other on stdout with
exit status 0.
"""

from __future__ import annotations

import os
import shlex
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

from tests.conftest import ROOT

CLI_PAGE = ROOT / "docs" / "cli.md"
PROGRAMS = ("python -m elliptic_pendulum", "elliptic-pendulum")


@dataclass(frozen=True)
class Example:
    line: int
    command: str
    output: str


def examples(page: Path = CLI_PAGE) -> list[Example]:
    """Return the commands of the page's console blocks with the output shown below each."""
    found: list[Example] = []
    inside = False
    current: tuple[int, str, list[str]] | None = None
    for number, text in enumerate(page.read_text(encoding="utf-8").splitlines(), start=1):
        if not inside:
            inside = text.strip() == "```console"
            continue
        if text.strip() == "```" or text.startswith("$ "):
            if current is not None:
                found.append(Example(current[0], current[1], "\n".join(current[2])))
                current = None
            if text.strip() == "```":
                inside = False
            else:
                current = (number, text[2:].strip(), [])
        elif current is not None:
            current[2].append(text.rstrip())
    assert not inside, f"{page.name}: a console block is not closed"
    return found


def _argv(command: str) -> list[str]:
    for program in PROGRAMS:
        if command == program or command.startswith(program + " "):
            args = shlex.split(command[len(program):])
            if program == "elliptic-pendulum":
                script = Path(sys.executable).parent / "elliptic-pendulum"
                found = str(script) if script.exists() else shutil.which("elliptic-pendulum")
                if found is None:
                    pytest.skip("the elliptic-pendulum script is not installed")
                return [found, *args]
            return [sys.executable, "-m", "elliptic_pendulum", *args]
    raise AssertionError(f"docs/cli.md runs an unknown program: $ {command}")


def _clean(text: str) -> str:
    return "\n".join(line.rstrip() for line in text.strip("\n").splitlines())


EXAMPLES = examples()


def test_the_page_has_examples_of_every_subcommand_and_of_an_error() -> None:
    commands = " ".join(e.command for e in EXAMPLES)
    for word in ("table", "period", "crossing", "solve", "elliptic-pendulum "):
        assert word in commands, word
    assert any(": error: " in e.output for e in EXAMPLES)
    assert all(e.output for e in EXAMPLES), "a command on the page shows no output"


@pytest.mark.parametrize("example", EXAMPLES, ids=[f"cli.md:{e.line}" for e in EXAMPLES])
def test_cli_example_prints_what_the_page_shows(example: Example) -> None:
    env = {**os.environ, "COLUMNS": "80", "NO_COLOR": "1", "PYTHONWARNINGS": "error"}
    result = subprocess.run(_argv(example.command), capture_output=True, text=True,
                            env=env, timeout=120, check=False)
    expected = _clean(example.output)
    if ": error: " in expected:
        assert result.returncode == 2, result.stderr
        assert result.stdout == ""
        assert _clean(result.stderr) == expected
        assert len(result.stderr.splitlines()) == 1, "the error is one line"
    else:
        assert result.returncode == 0, result.stderr
        assert result.stderr == ""
        assert _clean(result.stdout) == expected
