"""The book's check helper (verify.py): each check passes on the truth, fails on a wrong formula,
and fails when its mutant would pass too (a check that cannot fail is caught where written)."""

import dataclasses
import math

import pytest
import sympy as sp

from elliptic_pendulum.checks import verify
from elliptic_pendulum.checks.identities import identity
from elliptic_pendulum.checks.symbolic import Identity

x = sp.Symbol("x", real=True)


def test_identity_passes_and_names_its_mutant():
    v = verify.identity(identity("eq26"))
    assert v.claim == "(26)" and v.kind == "sympy identity"
    assert "8K_1" in v.details
    assert str(v).startswith("✔ (26) holds for $0 < \\alpha < 1$")
    assert "<details>" in v._repr_markdown_()  # the details one click away
    # The reader has just read the equation: it is not displayed again, unless asked for.
    assert not v.display and v._repr_markdown_().startswith("✔ **(26)**")
    shown = verify.identity(identity("eq26"), show=True)
    assert shown.display and shown._repr_markdown_().startswith("$$\n")


def test_identity_fails_when_sympy_does_not_confirm_it():
    wrong = Identity("wrong", "(0)", sp.sin(x) ** 2, 1 - sp.sin(x) ** 2)
    with pytest.raises(AssertionError, match="sympy does not confirm it"):
        verify.identity(wrong)


def test_identity_fails_when_its_mutant_passes_too():
    # sin^2 + cos^2 = 1 with the "mutant" 1: the check cannot tell them apart.
    vacuous = Identity("vacuous", "(0)", sp.sin(x) ** 2 + sp.cos(x) ** 2, sp.Integer(1),
                       mutant=sp.cos(2 * x) + 2 * sp.sin(x) ** 2)
    with pytest.raises(AssertionError, match="cannot tell the mutant apart"):
        verify.identity(vacuous)


def _period_error(T):
    # The zeros of sin(t) a period apart, found independently: 0 and 2 pi.
    return abs(T() - 2 * math.pi)


def test_numeric_passes_rejects_and_reports_its_mutant():
    v = verify.numeric("(8)", _period_error, lambda: 2 * math.pi, lambda: 4 * math.pi,
                       tol=1e-12, over="one period", mutant_label="4 pi")
    assert v.kind == "numerical" and str(v) == "✔ (8) holds: max |residual| 0 over one period."
    assert "A wrong version, 4 pi, is rejected" in v.details


def test_numeric_without_a_mutant_says_so():
    v = verify.numeric("(8)", _period_error, lambda: 2 * math.pi, tol=1e-12, over="x")
    assert v.details.endswith("No wrong version is tried.")


def test_numeric_fails_on_a_wrong_formula():
    with pytest.raises(AssertionError, match="> tolerance"):
        verify.numeric("(8)", _period_error, lambda: 4 * math.pi, tol=1e-12, over="x")


def test_numeric_fails_when_the_mutant_is_within_tolerance():
    with pytest.raises(AssertionError, match="the mutant passes too"):
        verify.numeric("(8)", _period_error, lambda: 2 * math.pi,
                       lambda: 2 * math.pi + 1e-14, tol=1e-12, over="x")


def test_numeric_treats_nan_as_failure():
    # A residual of nan is not <= tol: a broken computation must not pass.
    with pytest.raises(AssertionError):
        verify.numeric("(8)", lambda f: f(), lambda: math.nan, tol=1.0, over="x")


def test_fact():
    assert str(verify.fact("(14)", True, "xi stays in [-1, 1]")) == "✔ (14) xi stays in [-1, 1]."
    with pytest.raises(AssertionError, match="not so"):
        verify.fact("(14)", False, "xi stays in [-1, 1]")


def test_a_statement_on_a_domain_is_checked_there_and_fails_beyond():
    # (13)'s root 2 omega_0 cos(theta/2) holds for |theta| < pi only: sympy's radical
    # splitting assumes it; the verdict states the domain, and arithmetic without the
    # splitting confirms it inside and finds 4 cos(1/4) = 3.88 at theta = 2 pi + 1/2.
    e = identity("eq13_root")
    v = verify.identity(e)
    assert "holds for $- \\pi < \\theta < \\pi$, not beyond" in str(v)
    assert "differ by 3.9" in v.details
    assert abs(e.value_at(dict(e.outside)) - 4 * math.cos(0.25)) < 1e-12
    # With the domain widened to (-pi, 3 pi), the check must fail.
    wide = dataclasses.replace(e, where=((e.where[0][0], -sp.pi, 3 * sp.pi),))
    with pytest.raises(AssertionError, match="fails at a point of its domain"):
        verify.identity(wide)
    # With its outside point moved inside, the check must fail too.
    inside = dataclasses.replace(e, outside=((e.where[0][0], sp.Rational(1, 2)),))
    with pytest.raises(AssertionError, match="holds outside its domain"):
        verify.identity(inside)


def test_an_evaluation_says_it_is_arithmetic():
    v = verify.identity(identity("eq38"))
    assert v.kind == "arithmetic" and "follows by arithmetic" in str(v)


def test_an_identity_is_shown_on_two_lines():
    # The book's column holds about 700 px and MathJax 3 does not break a line, so the longer
    # identities (rod_or_string's free flight, libration's G'') ran past it: the verdict
    # shows "= rhs" under the left side, in an aligned environment, with the same LaTeX.
    v = verify.Verdict("(1)", "sympy identity", "holds", r"\sin^{2}{x} + \cos^{2}{x} = 1")
    shown = v._repr_markdown_().split("$$")[1].strip()
    assert shown == (
        "\\begin{aligned}\n&\\sin^{2}{x} + \\cos^{2}{x} \\\\\n&\\quad = 1\n\\end{aligned}"
    )
    # An equation of more than two members stays on one line, as written.
    chain = verify.Verdict("(1)", "sympy identity", "holds", "a = b = c")
    assert chain._repr_markdown_().split("$$")[1].strip() == "a = b = c"


def test_a_number_in_e_notation_is_kept_in_one_piece():
    # Chromium broke "(relative 1e-12)" after the hyphen in the PDF ("1e-" / "12"): the
    # Markdown wraps each e-notation number outside math in a span that does not break;
    # math and plain text are left as they are.
    v = verify.fact("(0)", True, "agrees (relative 1e-12) with $10^{-20}$ and $x_1e-3$")
    md = v._repr_markdown_()
    assert '<span style="white-space: nowrap">1e-12</span>' in md
    assert "$10^{-20}$" in md and "$x_1e-3$" in md
    assert str(v) == "✔ (0) agrees (relative 1e-12) with $10^{-20}$ and $x_1e-3$."
