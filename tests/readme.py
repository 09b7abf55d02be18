"""The README's commands, as a newcomer runs them: on a fresh copy, in the README's order.

:func:`commands` reads every ``make <target>`` the README shows (in its code blocks and in its
text), in order, but ``make test``, which is what runs this. :func:`fresh_copy` makes the copy
a clone would be: the files git tracks or would track (those of the working tree, so that an
uncommitted change is tested too), none that it ignores (no build, no cache, no notebooks),
with the project's virtual environment and node_modules linked in, as `make test` made them
(the README's commands would make the same). :class:`Runs` runs the commands one after the
other in a background thread, so a test waits only for the command whose output it reads.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import threading
import time
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
# What `make test` is, and what its tiers are: not run from inside it.
NOT_RUN = {"make test", "make test-fast"}
# Run after `make book` as well: the catalogs' gate, which the Japanese edition's test reads.
ALSO = {"make book": ["make i18n-status"]}
# A line of make's output that is a recipe line it echoes (where one step's output starts).
RECIPE = re.compile(r"^(\.venv/bin/|rm |mkdir |cp |test |touch |npm |ELLIPTIC_PENDULUM_)")


def commands(readme: Path = ROOT / "README.md") -> list[str]:
    """Every ``make <target>`` of the README, in order, once each, but ``make test``."""
    found = re.findall(r"(?<![\w-])make ([a-z][\w-]*)", readme.read_text(encoding="utf-8"))
    ordered = list(dict.fromkeys(f"make {target}" for target in found))
    runs = []
    for command in ordered:
        if command not in NOT_RUN:
            runs += [command, *ALSO.get(command, [])]
    return runs


def fresh_copy(dest: Path, root: Path = ROOT) -> Path:
    """``dest``: the repository's files as a clone has them, plus the environment links."""
    listed = subprocess.run(
        ["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
        cwd=root, capture_output=True, check=True).stdout.decode().split("\0")
    for name in filter(None, listed):
        source = root / name
        if source.is_file():  # a tracked file deleted in the working tree is not copied
            target = dest / name
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, target)  # times kept: make sees the venv's stamp as newer
    for link in (".venv", "node_modules"):
        if (root / link).exists():
            (dest / link).symlink_to(root / link, target_is_directory=True)
    stamp = root / ".venv" / ".installed"
    inputs = [dest / "pyproject.toml", dest / "constraints.txt"]  # the Makefile's for it
    if not stamp.exists() or any(stamp.stat().st_mtime < p.stat().st_mtime for p in inputs):
        raise RuntimeError("the virtual environment is older than pyproject.toml or "
                           "constraints.txt: run `make venv` (or `make test`, which does)")
    return dest


@dataclass
class Part:
    """One recipe line of a make command and what it printed."""

    line: str
    output: str
    seconds: float
    returncode: int


@dataclass
class Run:
    """One command: its exit code, its output and time, and its recipe lines' parts."""

    command: str
    returncode: int
    output: str
    seconds: float
    parts: list[Part] = field(default_factory=list)

    def part(self, ending: str) -> Part:
        """The recipe line that ends with ``ending`` (e.g. ``-b html book book/_build/html``)."""
        found = [p for p in self.parts if p.line.rstrip().endswith(ending)]
        if not found:
            return Part(ending, f"{self.command} ran no line ending with {ending!r}:\n"
                        + self.output[-5000:], self.seconds, self.returncode or 1)
        return found[-1]


def run(command: str, cwd: Path) -> Run:
    """Run ``command`` (``make <target>``) in ``cwd``; time each recipe line it echoes."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    start = time.perf_counter()
    lines: list[tuple[float, str]] = []
    with subprocess.Popen(command.split(), cwd=cwd, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, encoding="utf-8",
                          errors="replace") as proc:
        assert proc.stdout is not None
        for line in proc.stdout:
            lines.append((time.perf_counter(), line))
        returncode = proc.wait()
    end = time.perf_counter()
    parts: list[Part] = []
    starts = [i for i, (_, line) in enumerate(lines) if RECIPE.match(line)]
    for n, i in enumerate(starts):
        j = starts[n + 1] if n + 1 < len(starts) else len(lines)
        t_end = lines[j][0] if j < len(lines) else end
        last = n + 1 == len(starts)
        # A recipe line continued with a backslash is echoed on several lines: one command.
        k, command = i, lines[i][1]
        while command.rstrip().endswith("\\") and k + 1 < j:
            k += 1
            command = command.rstrip()[:-1] + " " + lines[k][1].strip()
        parts.append(Part(" ".join(command.split()), "".join(text for _, text in lines[i:j]),
                          t_end - lines[i][0], returncode if last else 0))
    return Run(command, returncode, "".join(text for _, text in lines), end - start, parts)


class Runs:
    """The commands, run one after the other in the background, in order."""

    def __init__(self, copy: Path, commands: list[str]) -> None:
        self.copy = copy
        self.commands = commands
        self._pool = ThreadPoolExecutor(max_workers=1)
        self._lock = threading.Lock()
        self._futures: dict[str, Future[Run]] = {
            command: self._pool.submit(run, command, copy) for command in commands}

    def result(self, command: str) -> Run:
        """The run of ``command``, once it has finished."""
        if command not in self._futures:
            raise KeyError(f"{command!r} is not one of the commands run: {self.commands}")
        return self._futures[command].result()

    def timings(self) -> list[str]:
        lines = []
        for command, future in self._futures.items():
            if future.done() and future.exception() is None:
                got = future.result()
                lines.append(f"{command}: {got.seconds:.1f} s (exit {got.returncode})")
                lines += [f"    {p.line.strip()[:110]}: {p.seconds:.1f} s" for p in got.parts
                          if p.seconds >= 1]
        return lines

    def close(self) -> None:
        self._pool.shutdown(wait=True, cancel_futures=True)
