"""Find every check the book's pages run: the registry behind book/checks.md.

Reads the pages' MyST sources (``*.md`` directly in the book's folder) and finds, in each
code cell, the calls ``verify.identity``, ``verify.numeric`` and ``verify.fact`` of
:mod:`elliptic_pendulum.checks.verify` (the forms are listed in
:mod:`elliptic_pendulum.checks.registry`). The book's Sphinx extension ``checks_scan`` runs
it once per build and writes the result as JSON, which the registry page's cell reads with
:func:`elliptic_pendulum.checks.registry.load`: the package reads no file of the book.

    python -m tools.checks.scan book out.json
"""

from __future__ import annotations

import ast
import dataclasses
import json
import re
import sys
from pathlib import Path

from elliptic_pendulum.checks.registry import Check

_KIND_OF_CALL = {"identity": "sympy identity", "numeric": "independent numerical check",
                 "fact": "numerical fact"}


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
    from elliptic_pendulum.checks.errata import printed_errata
    from elliptic_pendulum.checks.identities import identities

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


def write(checks: list[Check], path: Path) -> Path:
    """Write the checks as the JSON list that :func:`registry.load` reads."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps([dataclasses.asdict(c) for c in checks], ensure_ascii=False,
                               indent=0), encoding="utf-8")
    return path


def main(argv: list[str] | None = None) -> int:
    book, out = (argv if argv is not None else sys.argv[1:])
    write(scan(Path(book)), Path(out))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
