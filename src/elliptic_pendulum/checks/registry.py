r"""What the book claims and how each claim is checked: the registry behind ``book/checks.md``.

The book's check cells call :mod:`elliptic_pendulum.checks.verify` with the claim as a literal first
argument, or with a named sympy statement of :mod:`elliptic_pendulum.checks.symbolic`.
The book's build reads the pages' sources (MyST Markdown: ``tools/checks/scan.py`` in the
repository) and hands this module the list of checks it found (:func:`load`); in each code
cell it finds

- ``verify.identity(ids["name"])`` (also through ``for name in ("a", "b")`` loops and
  ``sym.identity("name")``): a *sympy identity*; the claim is ``Identity.equation``;
- ``verify.identity(sym.Identity("name", "(16)", lhs, rhs, mutant=...))``, inline or assigned to
  a name in the same cell: a sympy identity, the claim its second argument;
- ``verify.numeric("(26)", ...)``: an *independent numerical check*, with its mutant (the 4th
  positional argument or ``mutant=``);
- ``verify.fact("Lemma 2.3", ...)``: a *numerical fact*.

``STATUS`` lists, with a one-line justification each, the claims
that are definitions or are proved in the text only. ``tests/checks/test_registry.py`` asserts that
every claim of ``CLAIMS`` has a check or a status, and that every check found carries a
mutant where one is required.

The tables are written in the language asked for (``language="ja"``), else in the
environment's as gettext reads it; the module's own words are translated by
``checks/_ja.py``, the texts of the checks found (sections, labels, mutants) by the catalog
of the environment, as :mod:`elliptic_pendulum.checks.verify` describes.

Standard library only (and the package's ``_i18n``, which is).
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from pathlib import Path

from .._i18n import Say, say_for

__all__ = ["CLAIMS", "KINDS", "STATUS", "Check", "claims_of", "coverage", "load", "markdown",
           "markdown_other"]

# --- the claims of the note and the statuses that are not computations --------------------

#: The claims a reader of the note can point at (its 46 numbered equations, the parts of
#: Proposition 1 and Lemma 2, the table of R(theta_0) and the three crossing angles).
CLAIMS: tuple[str, ...] = (
    *(f"({n})" for n in range(1, 47)),
    *(f"Proposition 1.{i}" for i in (1, 2, 3)),
    *(f"Lemma 2.{i}" for i in (1, 2, 3)),
    "R table",
    "crossing angles",
)

#: The kinds of check and of status. An arithmetic step is a one-line evaluation that sympy
#: does (a value at an end point, a shift by 2 pi), counted apart from the identities.
KINDS = ("sympy identity", "independent numerical check", "numerical fact", "arithmetic",
         "proof in the text only", "definition")

#: Claims whose status is not a computation, with why (kind, justification).
STATUS: dict[str, tuple[str, str]] = {
    "(1)": ("definition", "the bob's position and the rod's pull, read off the figure"),
    "(2)": ("definition", "Newton's second law for the bob: the model itself"),
    "(5)": ("definition", r"the small-angle model $\sin\theta \approx \theta$, an approximation "
                          "of (3)"),
    "(6)": ("definition", r"names $\omega_0 = \sqrt{g/\ell}$"),
    "(11)": ("definition", r"names $\theta_0$ by $\cos\theta_0 = -c_1/(2\omega_0^2)$"),
    "(14)": ("definition", r"names $\xi = \sin(\theta/2)/\alpha$"),
    "(17)": ("definition", r"names $E_1$, the incomplete elliptic integral"),
    "(18)": ("definition", r"names $K_1 = E_1(1)$"),
    "(19)": ("definition", r"names $G$, the inverse of $E_1$"),
    "(20)": ("definition", r"the periodic extension $\bar f$ of Lemma 2.2"),
    "(21)": ("definition", r"the staircase extension $\hat f$ of Lemma 2.3"),
    "(24)": ("proof in the text only",
             r"that every solution of (3) with this energy is (25), so its $\xi$ is (24): "
             r"uniqueness for (3); the constants $\xi = \pm 1$ solve (15) but not (3)"),
    "(31)": ("definition", r"names $H_0$, an integral"),
    "(36)": ("definition", r"names $H_1$, an integral"),
    "(40)": ("definition", r"names $I = \arcsin G$"),
    "(46)": ("proof in the text only",
             r"that every rotation is $\pm 2\hat I(\omega_0 t/\gamma + c_4)$: uniqueness "
             "for (3)"),
    "Lemma 2.1": ("proof in the text only", "the mean value theorem; a statement about all f"),
}


# --- the checks the pages run ----------------------------------------------------------

@dataclass(frozen=True)
class Check:
    """One check found in the book: which claim, what kind, where, and the mutant it rejects.

    ``mutant`` is the mutant's label ("" when the check has none); ``name`` is the identity's
    name for sympy checks, else ""; ``line`` is the line of the call in the page's source.
    """

    claim: str
    kind: str
    page: str
    section: str
    anchor: str
    line: int
    mutant: str = ""
    name: str = ""


_RANGE = re.compile(r"\((\d+)\)(?:\s*[-–]\s*\((\d+)\))?")
_PART = re.compile(r"(Proposition 1|Lemma 2)\.([123])")


def claims_of(label: str) -> list[str]:
    """Return the claims of ``CLAIMS`` that a check's label names.

    Only a label that *starts* with an equation number or with "Proposition"/"Lemma" names
    numbered claims: "§4, after (23)" is about a remark after (23), not (23) itself.

    Examples
    --------
    >>> claims_of("(5)-(7)"), claims_of("(35), (41)"), claims_of("Lemma 2.3")
    (['(5)', '(6)', '(7)'], ['(35)', '(41)'], ['Lemma 2.3'])
    >>> claims_of("§4, after (23)"), claims_of("R table")
    ([], ['R table'])
    """
    label = label.strip()
    if label in CLAIMS and not label.startswith("("):
        return [label]
    if label.startswith(("Proposition", "Lemma")):
        return [f"{a}.{b}" for a, b in _PART.findall(label)]
    if not label.startswith("("):
        return []
    found = []
    for first, last in _RANGE.findall(label):
        found += [f"({n})" for n in range(int(first), int(last or first) + 1)]
    return [c for c in found if c in CLAIMS]


def load(path: str | Path) -> list[Check]:
    """Return the checks the book's build found in its pages, from the JSON file it wrote.

    The book's build (its Sphinx extension ``checks_scan``, with ``tools/checks``) reads the
    pages' sources; the package knows nothing of the book's files and only reads that list
    of records, one object per check with the fields of :class:`Check`.
    """
    records = json.loads(Path(path).read_text(encoding="utf-8"))
    return [Check(**record) for record in records]


def coverage(checks: list[Check]) -> dict[str, list[Check]]:
    """Return {claim: checks of it} for every claim of ``CLAIMS`` (lists may be empty)."""
    table: dict[str, list[Check]] = {c: [] for c in CLAIMS}
    for check in checks:
        for claim in claims_of(check.claim):
            table[claim].append(check)
    return table


def _say(language: str | None) -> Say:
    return say_for(__package__, language)


def markdown(checks: list[Check], *, language: str | None = None) -> str:
    """Return the registry as a MyST table: claim, kinds, mutants rejected, where checked.

    In ``language`` ("en", "ja"); by default the environment's.
    """
    say = _say(language)
    rows = [say("| claim | kind of check | mutants rejected | where |"), "|---|---|---|---|"]
    for claim, found in coverage(checks).items():
        kinds = [say(kind) for kind in sorted({c.kind for c in found}, key=KINDS.index)]
        if claim in STATUS:
            kinds.append(say("{kind}: {why}", kind=say(STATUS[claim][0]),
                             why=say(STATUS[claim][1])))
        mutants = "; ".join(dict.fromkeys(say(c.mutant).replace("|", "\\|") for c in found
                                          if c.mutant)) or say("none")
        places = dict.fromkeys(
            f"[{say('{page}: {section}', page=c.page, section=say(c.section))}]"
            f"({c.page}.md#{c.anchor})" if c.anchor
            else f"[{c.page}]({c.page}.md)" for c in found)
        link = claim
        if claim.startswith("("):
            link = f"{{ref}}`{claim} <eq-{claim.strip('()')}>`"
        rows.append(f"| {link} | {'; '.join(kinds) or say('**none**')} | {mutants} | "
                    f"{'; '.join(places) or '-'} |")
    return "\n".join(rows)


def markdown_other(checks: list[Check], *, language: str | None = None) -> str:
    """Return the checks of no numbered claim (remarks, exercises, the chapters beyond the note).

    One MyST table per page, in the order of ``checks``: label, kind, mutant rejected, section.
    In ``language`` ("en", "ja"); by default the environment's.
    """
    say = _say(language)
    pages: dict[str, list[Check]] = {}
    for c in checks:
        if not claims_of(c.claim):
            pages.setdefault(c.page, []).append(c)
    out = []
    for page, found in pages.items():
        out += [f"### {{doc}}`{page}`", "", say("| check | kind | mutant rejected | where |"),
                "|---|---|---|---|"]
        for c in found:
            where = f"[{say(c.section)}]({c.page}.md#{c.anchor})" if c.anchor else say(c.section)
            label = (say(c.claim or c.name) if c.claim or c.name
                     else say("(unnamed)")).replace("|", "\\|")
            mutant = say(c.mutant).replace("|", "\\|") or say("none")
            out.append(f"| {label} | {say(c.kind)} | {mutant} | {where} |")
        out.append("")
    return "\n".join(out)
