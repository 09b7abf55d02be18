"""The scan of the book's pages for their checks (tools/checks/scan.py), which the book's
build hands to the registry page (book/_ext/checks_scan.py, registry.load)."""

import textwrap

import pytest

from elliptic_pendulum.checks import registry
from tests.conftest import ROOT
from tools.checks.scan import scan, write

CHECKS = scan(ROOT / "book")


def test_the_scanner_finds_the_books_checks():
    assert len(CHECKS) > 100
    assert {c.kind for c in CHECKS} == set(registry.KINDS[:4])


def test_the_scanner_reads_loops_assignments_and_inline_identities(tmp_path):
    # A page with each form a chapter uses; the scanner must see all of them, and the mutant
    # (or its absence) of each.
    page = textwrap.dedent('''
        # A page

        ## First section

        ```{code-cell} ipython3
        :tags: [hide-input]

        for name in ("eq13", "eq13_root"):
            display(verify.identity(ids[name]))
        e16 = sym.Identity("eq16x", "(16)", lhs, rhs, mutant=wrong)
        display(verify.identity(e16))
        verify.identity(sym.Identity("bare", "(17)", lhs, rhs))
        ```

        ### Deeper

        ```{code-cell} ipython3
        verify.numeric("(26)", res, f, m, tol=1e-12, over="x", mutant_label="$8K_1$")
        verify.numeric("(8)", res, f, tol=1e-12, over="x")
        verify.fact("Lemma 2.3", ok, "text")
        ```
        ''')
    (tmp_path / "page.md").write_text(page)
    found = scan(tmp_path)
    got = [(c.claim, c.kind.split()[0], bool(c.mutant), c.anchor) for c in found]
    assert got == [
        ("(13)", "sympy", True, "first-section"),
        ("(13)", "sympy", True, "first-section"),
        ("(16)", "sympy", True, "first-section"),
        ("(17)", "sympy", False, "first-section"),
        ("(26)", "independent", True, "deeper"),
        ("(8)", "independent", False, "deeper"),
        ("Lemma 2.3", "numerical", False, "deeper"),
    ]
    assert found[4].mutant == "$8K_1$" and found[0].name == "eq13"


def test_an_unknown_identity_name_is_an_error(tmp_path):
    (tmp_path / "p.md").write_text('```{code-cell} ipython3\nverify.identity(ids["nope"])\n```\n')
    with pytest.raises(KeyError):
        scan(tmp_path)


def test_the_package_reads_back_what_the_build_wrote(tmp_path):
    # The book's build writes the scan as JSON (book/_ext/checks_scan.py); the registry page
    # reads it with registry.load: the same checks, field for field, in the same order.
    assert registry.load(write(CHECKS, tmp_path / "checks.json")) == CHECKS
