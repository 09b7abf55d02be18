"""The registry of the book's claims (registry.py, book/checks.md): every claim has a check or a
stated status, and every check that can carry a mutant carries one."""



from elliptic_pendulum.checks import registry
from elliptic_pendulum.checks.identities import identities
from elliptic_pendulum.checks.registry import _RANGE
from tests.conftest import ROOT
from tools.checks.scan import scan

BOOK = ROOT / "book"
CHECKS = scan(BOOK)


def test_every_claim_has_a_check_or_a_justified_status():
    table = registry.coverage(CHECKS)
    uncovered = [c for c, found in table.items() if not found and c not in registry.STATUS]
    assert not uncovered, f"claims with neither a check nor a stated status: {uncovered}"


def test_every_status_is_justified():
    for claim, (kind, why) in registry.STATUS.items():
        assert claim in registry.CLAIMS, claim
        assert kind in {"definition", "proof in the text only"}, claim
        assert len(why.split()) >= 3, claim


def test_every_identity_the_book_checks_is_named_and_has_a_mutant():
    for c in CHECKS:
        if c.kind in {"sympy identity", "arithmetic"}:
            assert c.name, f"{c.page}.md:{c.line}: verify.identity of a statement without a name"
            assert c.mutant, f"{c.page}.md:{c.line}: {c.name} has no mutant"


def test_every_numerical_check_in_the_book_passes_a_mutant():
    for c in CHECKS:
        if c.kind == "independent numerical check":
            assert c.mutant, f"{c.page}.md:{c.line}: verify.numeric({c.claim!r}) has no mutant"


def test_every_identity_of_the_library_has_a_mutant():
    assert all(e.mutant is not None for e in identities())


def test_claim_labels():
    assert registry.claims_of("(5)-(7)") == ["(5)", "(6)", "(7)"]
    assert registry.claims_of("(35), (41)") == ["(35)", "(41)"]
    assert registry.claims_of("Proposition 1.2") == ["Proposition 1.2"]
    assert registry.claims_of("§4, after (23)") == []  # a remark after (23), not (23)
    assert registry.claims_of("(47)") == []
    assert len(registry.CLAIMS) == 46 + 3 + 3 + 2


def test_the_table_has_one_row_per_claim():
    rows = registry.markdown(CHECKS).splitlines()
    assert len(rows) == 2 + len(registry.CLAIMS)
    assert all(row.count(" | ") >= 3 for row in rows[2:])


def test_each_check_is_credited_to_the_one_claim_it_checks():
    # A range such as "(14)-(15)" credited the definition (14) with the identity of (15); a
    # check now names the equation it checks ("(35), (41)": one formula that is both).
    ranges = [f"{c.page}.md:{c.line}: {c.claim}" for c in CHECKS
              if _RANGE.search(c.claim) and _RANGE.search(c.claim).group(2)]
    assert ranges == []


def test_the_one_line_evaluations_are_not_counted_as_identities():
    # The statements that are an evaluation or a substitution (a value at G = 1, a shift by
    # 2 pi, (45) once its two premises are substituted) are of kind "arithmetic".
    kinds = {e.name: e.kind for e in identities()}
    for name in ("eq22_at_K1", "eq23_at_K1", "eq42_at_K1", "I_uu_at_K1", "eq38", "eq45"):
        assert kinds[name] == "arithmetic", name
    assert {c.kind for c in CHECKS if c.name == "eq45"} == {"arithmetic"}


def test_every_check_of_no_numbered_claim_has_a_row_of_its_own():
    # The second table of book/checks.md: one row per check that names no claim of CLAIMS,
    # so the chapters beyond the note and the exercises are in the registry too.
    others = [c for c in CHECKS if not registry.claims_of(c.claim)]
    table = registry.markdown_other(CHECKS)
    rows = [r for r in table.splitlines() if r.startswith("| ") and not r.startswith("| check")]
    assert others and len(rows) == len(others)
    for page in {"period_in_depth", "rod_or_string", "resonance", "in_motion"}:
        assert f"{{doc}}`{page}`" in table


