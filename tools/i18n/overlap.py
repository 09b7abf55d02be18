"""How much of the note's own wording reappears in the Japanese edition.

The book follows S. Takeno's note (references.bib: takeno2024), which is Japanese; its facts,
formulas and numbers carry over, its sentences do not. The note itself is not part of the
repository: ``tools/i18n/note_runs.txt`` holds a fingerprint of it, a 40-bit hash of each of
its 20-character runs of prose (formulas, which carry over, left out: a run never spans
a ``$...$``; NFKC, all white space removed), made by
``python -m tools.i18n.overlap --fingerprint NOTE.txt``. ``share()`` is the fraction of those
runs that reappear in the catalogs' translations (runs inside one message), which the tests
hold below 2%.
"""

from __future__ import annotations

import hashlib
import re
import sys
import unicodedata
from collections.abc import Iterable
from pathlib import Path

RUN = 20
MATH = re.compile(r"\$\$.*?\$\$|\$[^$]*\$", re.DOTALL)
FINGERPRINT = Path(__file__).with_name("note_runs.txt")


def normalise(text: str) -> str:
    return "".join(unicodedata.normalize("NFKC", text).split())


def runs(text: str) -> set[str]:
    """The 40-bit hashes of every 20-character run of the prose of ``text``, normalised."""
    found = set()
    for part in MATH.split(text):
        part = normalise(part)
        found |= {hashlib.blake2b(part[i:i + RUN].encode(), digest_size=5).hexdigest()
                  for i in range(len(part) - RUN + 1)}
    return found


def fingerprint() -> set[str]:
    lines = FINGERPRINT.read_text().splitlines()
    return {line for line in lines if line and not line.startswith("#")}


def share(texts: Iterable[str], note: set[str] | None = None) -> tuple[float, int, int]:
    """(fraction, runs found, runs of the note): the note's runs that reappear in ``texts``."""
    note = fingerprint() if note is None else note
    ours: set[str] = set()
    for text in texts:
        ours |= runs(text)
    found = len(note & ours)
    return found / len(note), found, len(note)


if __name__ == "__main__":
    if sys.argv[1:2] == ["--fingerprint"]:
        hashes = sorted(runs(Path(sys.argv[2]).read_text(encoding="utf-8")))
        FINGERPRINT.write_text(
            "# 40-bit blake2b hashes of the 20-character runs of the note (tools/i18n/overlap.py)\n"
            + "\n".join(hashes) + "\n")
        print(f"{len(hashes)} runs")
