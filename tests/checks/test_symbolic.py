"""The note's identities (symbolic.py): sympy checks them, and so does arithmetic at random points.

Every correct statement must check True and every printed erratum False, as the book shows. Because
``check`` relies on ``sympy.simplify`` and, on stated domains, on splitting radicals as if their
factors were positive, each statement is also evaluated numerically (mpmath through sympy's evalf at
30 digits) at random points of its domain *without* that radical splitting: principal square roots
of positive numbers, so the sign questions are settled by arithmetic, not by assumption.
"""

import ast
import dataclasses
import pathlib

import numpy as np
import pytest
import sympy as sp

from elliptic_pendulum.checks import symbolic
from elliptic_pendulum.checks.errata import printed_errata
from elliptic_pendulum.checks.identities import identities, identity
from elliptic_pendulum.checks.symbolic import Identity

IDENTITIES = identities()
ERRATA = printed_errata()
PRINTED = [e for e in ERRATA if e.printed is not None]


@pytest.mark.parametrize("stmt", IDENTITIES, ids=[e.name for e in IDENTITIES])
def test_identity_checks_true(stmt):
    # The note's statement at stmt.equation, as sympy sees it.
    assert stmt.check(), f"{stmt.equation}: {stmt.latex()}"


@pytest.mark.parametrize("stmt", IDENTITIES, ids=[e.name for e in IDENTITIES])
def test_every_identity_rejects_its_mutant(stmt):
    # A check worth its name fails on the slip a reader could make.
    assert stmt.mutant is not None, f"{stmt.name} has no mutant"
    assert stmt.check(), stmt.name
    assert not stmt.mutant_identity().check(), f"{stmt.name}: the mutant passes too"


@pytest.mark.parametrize("name,mutant", [("eq26", 8 * symbolic.K1 / symbolic.omega0),
                                         ("eq8", 4 * sp.pi / symbolic.omega0)])
def test_the_doubled_periods_are_rejected(name, mutant):
    # (26) with 8 K1 and (8) with 4 pi / omega_0 must fail, whatever mutant
    # the identity happens to carry (both doubled periods are periods of the motion too).
    stmt = identity(name)
    assert stmt.check()
    assert not dataclasses.replace(stmt, rhs=mutant).check()


@pytest.mark.parametrize("stmt", IDENTITIES, ids=[e.name for e in IDENTITIES])
def test_no_display_reads_x_equals_x(stmt):
    # The displayed left side must show the step, not sympy's evaluation of it.
    left, right = (sp.latex(side) for side in (stmt.lhs, stmt.rhs))
    assert left != right, f"{stmt.name}: {left} = {right}"


def test_the_misprinted_expression_is_displayed():
    # The correct G_uu(K1 - 0) shows -(1 + alpha^2) + 2 alpha^2 itself, the expression the note
    # prints as -(1 + alpha)^2 + 2 alpha^2; sympy would otherwise collapse it to alpha^2 - 1.
    left = sp.latex(identity("eq23_at_K1").lhs)
    assert r"\left(\alpha^{2} + 1\right)" in left and "2 \\alpha^{2}" in left


@pytest.mark.parametrize("err", PRINTED, ids=[e.printed.name for e in PRINTED])
def test_printed_erratum_fails_and_its_correction_holds(err):
    assert not err.printed.check(), err.location
    assert err.corrected.check(), err.location


def test_errata_catalogue():
    # The two mathematical slips found in the note (§4 after (23), §5 partial fractions) are
    # refuted by sympy; the two undefined symbols (§3 omega, §5 w_0) are typos that cannot be
    # refuted (a new symbol would fail by construction), so only their corrections are checked.
    kinds = [(e.location, e.kind) for e in ERRATA]
    assert ("§4, after (23)", "error") in kinds
    assert ("§5, between (13) and (27)", "error") in kinds
    typos = [e for e in ERRATA if e.kind == "typo"]
    assert len(typos) == 2 and all(e.printed is None and e.corrected for e in typos)
    assert {e.location for e in PRINTED} == {"§4, after (23)", "§5, between (13) and (27)"}
    for e in ERRATA:
        assert e.printed_text != e.corrected_text and e.comment
        assert e.kind in {"error", "typo", "notation", "statement", "transcription"}


@pytest.mark.parametrize("err", [e for e in ERRATA if e.corrected is not None],
                         ids=[e.corrected.name for e in ERRATA if e.corrected is not None])
def test_every_correction_rejects_its_mutant(err):
    assert err.corrected.check() and err.corrected.mutant is not None
    assert not err.corrected.mutant_identity().check(), err.location


def test_the_general_solution_statement():
    # Not "(25) is the general non-constant solution of (12)".
    statement = next(e for e in ERRATA if e.location == "§4, after (25)")
    assert "(12)" not in statement.corrected_text and "unique" in statement.corrected_text
    assert "rest at theta_0 for a while" in statement.comment


def test_the_silent_repairs_are_listed_and_the_constant_of_41_is_not():
    # A reading of the book against the note found four places that the book repaired without
    # listing them: the signed tension, Lemma 2's missing continuity at +-a, "smooth" in §6
    # where Lemma 2.3 gives C^2 (§4 says "at least C^2"), and the upside-down equilibrium
    # dropped with z = +-1 in §5 (singular solutions, as the note says, but motions). The
    # page's list (book/notes_on_original.md) has more, (41)'s c_{4,1} among them; the
    # library holds these, whose statements it can test.
    statements = {e.location: e for e in ERRATA if e.kind == "statement"}
    assert {"§2, (1)", "Lemma 2, parts 2 and 3", "§6", "§5, before (27)"} <= set(statements)
    lemma = statements["Lemma 2, parts 2 and 3"]
    assert "closed" in lemma.corrected_text and "closed" not in lemma.printed_text
    assert "at least C^2" in statements["§6"].comment
    singular = statements["§5, before (27)"]
    assert "equilibri" in singular.comment and "singular solutions, as the note says" in (
        singular.comment)
    assert "2n" in next(e for e in ERRATA if e.location == "§4, after (25)").corrected_text
    assert all(e.location != "(41)" for e in ERRATA)
    locations = [(e.location, e.kind) for e in ERRATA]
    assert len(locations) == len(set(locations))  # the book's page looks entries up by them


def test_no_transcription_claim_about_5():
    # The note's text copy has the approximate-equality sign before (5) (sin theta \doteq theta);
    # only after (26) does it show a division sign.
    entry = next(e for e in ERRATA if e.kind == "transcription")
    assert "likewise" not in entry.comment.lower() and "before (5)" in entry.comment


def test_names_are_unique_and_every_statement_renders():
    names = [e.name for e in IDENTITIES]
    assert len(names) == len(set(names))
    for e in IDENTITIES + [x.printed for x in PRINTED]:
        assert e.equation and " = " in e.latex() and e._repr_latex_().startswith("$$")


def test_every_numbered_equation_the_brief_lists_is_covered():
    covered = " ".join(e.equation for e in IDENTITIES)
    for eq in ["(3)", "(4)", "(8)", "(9)", "(10)", "(13)", "(15)", "(16)", "(22)", "(23)", "(26)",
               "(27)", "(28)", "(29)", "(32)", "(33)", "(34)", "(37)", "(38)", "(42)", "(43)",
               "(45)", "Proposition 1.2"]:
        assert eq in covered, eq


def test_identity_lookup():
    assert identity("eq23").equation == "(23)"
    with pytest.raises(ValueError, match="name must be one of"):
        identity("no-such-equation")


def test_a_wrong_statement_fails():
    # The checker is not a rubber stamp: (23) with the sign of the cubic term flipped fails.
    a, Gu = symbolic.alpha, symbolic.G(symbolic.u, symbolic.alpha)
    wrong = Identity("wrong", "(23)", sp.Derivative(Gu, (symbolic.u, 2)),
                     -(1 + a**2) * Gu - 2 * a**2 * Gu**3)
    assert not wrong.check()


@pytest.mark.parametrize("module", ["symbolic", "identities", "errata"])
def test_symbolic_imports_sympy_only(module):
    # symbolic imports sympy and nothing numeric from the package; its statements
    # (identities) and the errata import sympy and each other only (the import-linter
    # contract in pyproject.toml says the same of the whole checks package).
    path = pathlib.Path(symbolic.__file__).with_name(f"{module}.py")
    modules = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            modules |= {a.name.split(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            modules.add((node.module or ".").split(".")[0])
    assert modules <= {"__future__", "dataclasses", "sympy", "symbolic", "identities"}, modules


# Numerical check, independent of simplify and of the radical splitting.


def _sample(sym, rng):
    """A random value on the note's domain for each symbol, by name, as an exact rational."""
    return sp.Rational(_sample_float(sym, rng))


def _sample_float(sym, rng):
    name = sym.name
    if sym.is_integer:
        return int(rng.integers(-3, 4))
    if name in {"alpha", "gamma"}:
        return rng.uniform(0.3, 0.95)  # 0 < alpha, gamma < 1
    if name == "beta":
        return rng.uniform(1.1, 3.0)  # regime IV: beta > 1
    if name in {"z", "s", "G"}:
        return rng.uniform(-0.9, 0.9)  # inside (-1, 1)
    if name in {r"\ell", "m", "g", "omega_0", "omega", "w_0", "K_1"}:
        return rng.uniform(0.5, 3.0)
    if sym.is_positive:
        return rng.uniform(0.1, 3.0)
    return rng.uniform(-2.0, 2.0)


def _numeric_residual(stmt, rng):
    r = dataclasses.replace(stmt, positive_radicands=False).residual()
    # Derivatives of theta(t) (highest order first), then theta(t), G(.,.), I(.), then symbols.
    for d in sorted(r.atoms(sp.Derivative), key=lambda d: -d.derivative_count):
        r = r.subs(d, sp.Rational(rng.uniform(-1.0, 1.0)))
    for f in r.atoms(sp.core.function.AppliedUndef) | r.atoms(symbolic.G):
        # theta in (-0.5, 0.5) keeps alpha^2 - sin^2(theta/2) > 0 (regime II) and |theta| < pi;
        # G in (-0.9, 0.9) is inside (-1, 1).
        w = 0.5 if f.func.__name__ == "theta" else 0.9
        r = r.subs(f, sp.Rational(rng.uniform(-w, w)))
    # Exact rationals: evalf at 30 digits then sees no 16-digit float inputs to cancel.
    r = r.subs({sym: _sample(sym, rng) for sym in r.free_symbols})
    value = complex(sp.N(r, 30))
    return abs(value)


@pytest.mark.parametrize("stmt", IDENTITIES, ids=[e.name for e in IDENTITIES])
def test_identity_holds_numerically_at_random_points(stmt):
    rng = np.random.default_rng(sum(map(ord, stmt.name)))
    for _ in range(3):
        assert _numeric_residual(stmt, rng) < 1e-20, stmt.name


# (26)'s mutant takes sympy about 40 s to evaluate at the random points (an elliptic
# integral with a symbolic modulus): it runs in the slow tier, the others in the quick one.
_SLOW_MUTANTS = {"eq26"}


@pytest.mark.parametrize("stmt", [
    pytest.param(e, id=e.name, marks=[pytest.mark.slow] if e.name in _SLOW_MUTANTS else [])
    for e in IDENTITIES])
def test_mutant_fails_numerically_at_random_points(stmt):
    # The mutant is wrong by arithmetic too, not just beyond what simplify can prove.
    rng = np.random.default_rng(sum(map(ord, stmt.name)))
    for _ in range(3):
        assert _numeric_residual(stmt.mutant_identity(), rng) > 1e-6, stmt.name


@pytest.mark.parametrize("err", PRINTED, ids=[e.printed.name for e in PRINTED])
def test_printed_erratum_fails_numerically(err):
    rng = np.random.default_rng(7)
    assert _numeric_residual(err.printed, rng) > 1e-6
    assert _numeric_residual(err.corrected, rng) < 1e-20


@pytest.mark.parametrize("stmt", [e for e in IDENTITIES if e.positive_radicands],
                         ids=[e.name for e in IDENTITIES if e.positive_radicands])
def test_every_statement_that_splits_radicals_has_a_domain_checked_by_arithmetic(stmt):
    # The splitting is true on the domain only: the domain must be stated as intervals that
    # verify.identity samples, and the statement must hold at those points without it.
    assert stmt.where, stmt.name
    assert max(stmt.domain_residuals()) < 1e-20, stmt.name
