r"""What the book claims and how each claim is checked: the registry behind ``book/checks.md``.

The book's check cells call :mod:`elliptic_pendulum.checks.verify` with the claim as a literal first
argument, or with a named sympy statement of :mod:`elliptic_pendulum.checks.symbolic`.
:func:`scan` reads the pages' sources (MyST Markdown) and finds, in each code cell,

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

Standard library only, plus :mod:`.symbolic` and :mod:`.errata`
for the named statements.
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass
from pathlib import Path

__all__ = ["CLAIMS", "KINDS", "STATUS", "Check", "claims_of", "coverage", "markdown",
           "markdown_other", "scan"]

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

_KIND_OF_CALL = {"identity": "sympy identity", "numeric": "independent numerical check",
                 "fact": "numerical fact"}


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


def _slug(title: str) -> str:
    """GitHub-style slug of a heading as myst-parser makes it (text only, math dropped)."""
    text = re.sub(r"\$[^$]*\$|\{[\w:-]+\}`[^`]*`", "", title)
    return re.sub(r"[^\w\- ]", "", text.lower().replace(" ", "-"))


def _cells(source: str):
    """Yield (first line number, code, section title, anchor) for each code cell of a page."""
    section, anchor, slugs = "", "", set()
    lines = source.splitlines()
    i = 0
    while i < len(lines):
        heading = re.match(r"(#{1,6}) (.*)", lines[i])
        if heading:
            section, anchor = heading.group(2).strip(), ""
            if len(heading.group(1)) <= 3:  # myst makes anchors for levels 1-3 only
                base = _slug(section)
                anchor, n = base, 0
                while anchor in slugs:
                    n += 1
                    anchor = f"{base}-{n}"
                slugs.add(anchor)
        if lines[i].startswith("```{code-cell}"):
            j, body = i + 1, []
            while j < len(lines) and not lines[j].startswith("```"):
                body.append(lines[j])
                j += 1
            yield i + 1, _strip_options(body), section, anchor
            i = j
        i += 1


def _strip_options(body: list[str]) -> str:
    if body and body[0].strip() == "---":
        end = body.index("---", 1) if "---" in body[1:] else 0
        body = body[end + 1:]
    while body and body[0].startswith(":"):
        body = body[1:]
    return "\n".join(body)


def _verify_calls(tree: ast.AST) -> list[tuple[str, ast.Call]]:
    """Return (function, call) of the calls verify.identity/numeric/fact, in source order."""
    calls = [(node.func.attr, node) for node in ast.walk(tree)
             if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
             and isinstance(node.func.value, ast.Name) and node.func.value.id == "verify"
             and node.func.attr in _KIND_OF_CALL]
    return sorted(calls, key=lambda fc: (fc[1].lineno, fc[1].col_offset))


def _loop_names(tree: ast.AST) -> dict[str, list[str]]:
    """Loop variables over literal tuples or lists of strings: {variable: [values]}."""
    names: dict[str, list[str]] = {}
    for node in ast.walk(tree):
        if (isinstance(node, ast.For) and isinstance(node.target, ast.Name)
                and isinstance(node.iter, (ast.Tuple, ast.List))):
            values = [e.value for e in node.iter.elts if isinstance(e, ast.Constant)]
            names.setdefault(node.target.id, []).extend(v for v in values if isinstance(v, str))
    return names


def _assigned_calls(tree: ast.AST) -> dict[str, ast.Call]:
    return {t.id: node.value for node in ast.walk(tree) if isinstance(node, ast.Assign)
            and isinstance(node.value, ast.Call) for t in node.targets if isinstance(t, ast.Name)}


def _literal(node: ast.AST | None) -> str | None:
    return node.value if isinstance(node, ast.Constant) and isinstance(node.value, str) else None


def _keyword(call: ast.Call, name: str) -> ast.AST | None:
    return next((k.value for k in call.keywords if k.arg == name), None)


def _mutant_label(call: ast.Call, position: int) -> str:
    """Return a call's mutant as a label: its ``mutant_label``, else its source."""
    node = call.args[position] if len(call.args) > position else _keyword(call, "mutant")
    if node is None or (isinstance(node, ast.Constant) and node.value is None):
        return ""
    return _literal(_keyword(call, "mutant_label")) or ast.unparse(node)


def _identities_of(arg: ast.AST, loops, assigned, stmts) -> list[tuple[str, str, str, str]]:
    """Return (name, claim, mutant label, kind) of the statements a verify.identity names."""
    from sympy import latex

    def named(name: str) -> tuple[str, str, str, str]:
        e = stmts()[name]  # KeyError for an unknown name: the registry test reports it
        label = e.mutant_label or (f"${latex(e.mutant)}$" if e.mutant is not None else "")
        return name, e.equation, label, e.kind

    if isinstance(arg, ast.Name) and arg.id in assigned:
        arg = assigned[arg.id]
    if isinstance(arg, ast.Subscript):  # ids["eq15"] or ids[name] in a loop
        key = arg.slice
        literal = _literal(key)
        if literal:
            return [named(literal)]
        if isinstance(key, ast.Name):
            return [named(n) for n in loops.get(key.id, [])]
    if isinstance(arg, ast.Call) and isinstance(arg.func, (ast.Attribute, ast.Name)):
        func = arg.func.attr if isinstance(arg.func, ast.Attribute) else arg.func.id
        literal = _literal(arg.args[0] if arg.args else None)
        if func == "identity" and literal:
            return [named(literal)]
        if func == "Identity" and len(arg.args) >= 2:
            return [(_literal(arg.args[0]) or "", _literal(arg.args[1]) or "",
                     _mutant_label(arg, 7), _literal(_keyword(arg, "kind")) or "sympy identity")]
    return []


def _statements() -> dict:
    """Return the named statements a page may check: the note's and the errata's corrections."""
    from .errata import printed_errata
    from .identities import identities

    stmts = {e.name: e for e in identities()}
    stmts.update({e.corrected.name: e.corrected for e in printed_errata() if e.corrected})
    return stmts


def scan(book: str | Path) -> list[Check]:
    """Return every check in the book's pages (``*.md`` directly in ``book``), in page order.

    A ``verify.identity`` whose statement cannot be named from the cell's source (for
    instance an erratum's ``e.corrected``) is recorded with an empty claim.
    """
    found = []
    cache: dict = {}

    def stmts() -> dict:  # built once, and only if a page names a statement
        if not cache:
            cache.update(_statements())
        return cache

    for path in sorted(Path(book).glob("*.md")):
        for line, code, section, anchor in _cells(path.read_text(encoding="utf-8")):
            try:
                tree = ast.parse(code)
            except SyntaxError:  # IPython magics: no verify calls are hidden behind them
                continue
            loops, assigned = _loop_names(tree), _assigned_calls(tree)
            for func, call in _verify_calls(tree):
                kind = _KIND_OF_CALL[func]
                where = dict(page=path.stem, section=section, anchor=anchor,
                             line=line + call.lineno)
                if func == "identity":
                    named = (_identities_of(call.args[0], loops, assigned, stmts)
                             if call.args else [])
                    for name, label, mutant, of in named or [("", "", "", kind)]:
                        found.append(Check(label, of, mutant=mutant, name=name, **where))
                else:
                    label = _literal(call.args[0] if call.args else None) or ""
                    mutant = _mutant_label(call, 3) if func == "numeric" else ""
                    found.append(Check(label, kind, mutant=mutant, **where))
    return found


def coverage(checks: list[Check]) -> dict[str, list[Check]]:
    """Return {claim: checks of it} for every claim of ``CLAIMS`` (lists may be empty)."""
    table: dict[str, list[Check]] = {c: [] for c in CLAIMS}
    for check in checks:
        for claim in claims_of(check.claim):
            table[claim].append(check)
    return table


def markdown(checks: list[Check]) -> str:
    """Return the registry as a MyST table: claim, kinds, mutants rejected, where checked."""
    rows = ["| claim | kind of check | mutants rejected | where |", "|---|---|---|---|"]
    for claim, found in coverage(checks).items():
        kinds = sorted({c.kind for c in found}, key=KINDS.index)
        if claim in STATUS:
            kinds.append(f"{STATUS[claim][0]}: {STATUS[claim][1]}")
        mutants = "; ".join(dict.fromkeys(c.mutant.replace("|", "\\|") for c in found
                                          if c.mutant)) or "none"
        places = dict.fromkeys(
            f"[{c.page}: {c.section}]({c.page}.md#{c.anchor})" if c.anchor
            else f"[{c.page}]({c.page}.md)" for c in found)
        link = claim
        if claim.startswith("("):
            link = f"{{ref}}`{claim} <eq-{claim.strip('()')}>`"
        rows.append(f"| {link} | {'; '.join(kinds) or '**none**'} | {mutants} | "
                    f"{'; '.join(places) or '-'} |")
    return "\n".join(rows)


def markdown_other(checks: list[Check]) -> str:
    """Return the checks of no numbered claim (remarks, exercises, the chapters beyond the note).

    One MyST table per page, in the order of ``checks``: label, kind, mutant rejected, section.
    """
    pages: dict[str, list[Check]] = {}
    for c in checks:
        if not claims_of(c.claim):
            pages.setdefault(c.page, []).append(c)
    out = []
    for page, found in pages.items():
        out += [f"### {{doc}}`{page}`", "", "| check | kind | mutant rejected | where |",
                "|---|---|---|---|"]
        for c in found:
            where = f"[{c.section}]({c.page}.md#{c.anchor})" if c.anchor else c.section
            label = (c.claim or c.name or "(unnamed)").replace("|", "\\|")
            mutant = c.mutant.replace("|", "\\|") or "none"
            out.append(f"| {label} | {c.kind} | {mutant} | {where} |")
        out.append("")
    return "\n".join(out)
