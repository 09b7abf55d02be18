r"""Checks with a verdict a student reads at a glance, for the book's cells.

A book page shows a derivation, and beside it a check: a cell whose input is folded (tag
``hide-input``), which the book writes as one mark in the margin (book/_ext/checkmarks.py).
Its output is the outcome of the check: one sentence that says what holds and how well, and,
one click away (a ``<details>`` element), how it was checked::

    ✔ (15) holds identically: sympy reduces the difference of its two sides to 0.
    ✔ (26) holds: max relative error 2.0e-16 over 20 swings.

Every check here *asserts*: a failing check raises ``AssertionError`` and stops the build. A
check of a formula may also run a *mutant* of it (a changed coefficient, sign, exponent or
argument: the mistake a reader could make) and then asserts that the check rejects it, so that
a check which cannot fail is caught where it is written; a check with no mutant says so in its
details.

Three kinds, named after what backs the claim:

- :func:`identity`: a :class:`.Identity` that sympy reduces to 0, and its mutant
  (``Identity.mutant``) that sympy does not; a statement that holds on a domain only is also
  evaluated at points of it, and beyond it where a point is given;
- :func:`numeric`: a residual function applied to the formula and to its mutant, with a tolerance
  between the two;
- :func:`fact`: a numerical fact that is not a formula with a natural mutant (a range, a sign,
  a count); its condition is asserted and stated.

The book's registry of claims (``book/checks.md``) finds these calls in the pages' sources by
their first argument, the claim (``"(26)"``, ``"Lemma 2.3"``), so that argument is a literal.

Each function writes its verdict in the language it is asked for (``language="ja"``), else
in the environment's as gettext reads it (LANGUAGE, LC_ALL, LC_MESSAGES, LANG), read at the
call; a language without messages gives English. The module's own sentences are translated by
``checks/_ja.py``. The texts a caller passes (a fact's sentence, ``over``, ``measure``,
``mutant_label``, an identity's ``mutant_label`` and ``domain_md``) are looked up, exact
English to its translation, in the catalog that the environment variable
``ELLIPTIC_PENDULUM_MESSAGES`` names (a gettext ``.po`` or ``.mo`` file; several separated by
``os.pathsep``), read at the call; a text it does not hold stays English. So is the claim as
the verdict shows it ("§3, case II"), while ``Verdict.claim`` stays the literal. A text with
a number computed in the cell is passed as a template with its ``values``, so that one
catalog entry serves every value. So the book's
Japanese edition translates its cells' fragments in a catalog of its own, and runs the same
cells::

    ELLIPTIC_PENDULUM_MESSAGES=book/locale/ja/checks-fragments.po LANGUAGE=ja ...

This module changes no global state and imports nothing beyond the standard library and the
package's ``_i18n`` (standard library only).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any, Protocol

from .._i18n import Say, say_for

__all__ = ["Verdict", "fact", "identity", "numeric"]


class _Identity(Protocol):
    name: str
    equation: str

    def check(self) -> bool: ...  # pragma: no cover - protocol
    def latex(self) -> str: ...  # pragma: no cover - protocol


@dataclass(frozen=True)
class Verdict:
    """The outcome of one passed check: what was claimed, by which kind of check, and how.

    ``text`` is the sentence a reader sees; ``details`` how it was checked (tolerances, the
    mutant rejected, the domain). Jupyter and myst-nb show it as Markdown
    (``_repr_markdown_``): the displayed equation when there is one, the sentence, then the
    details folded in a ``<details>`` element; ``str`` gives the sentence as plain text.
    """

    claim: str
    kind: str
    text: str
    display: str = ""
    details: str = ""
    # The language of text and details, for the words the displays add ("How it was checked").
    language: str = "en"
    # The claim as the reader sees it, in that language ("" when it is ``claim`` itself);
    # ``claim`` stays the book's literal, which the registry reads from the pages' sources.
    shown: str = ""

    def __str__(self) -> str:
        """Return the verdict's sentence as plain text."""
        return f"✔ {self.shown or self.claim} {self._sentence()}"

    def _sentence(self) -> str:
        if self.text.endswith((".", "!", "?", "。")):
            return self.text
        return self.text + ("。" if self.language == "ja" else ".")

    def __repr__(self) -> str:
        """Return the same line: a verdict at the end of a cell reads as text."""
        return str(self)

    def _repr_markdown_(self) -> str:
        line = f"✔ **{self.shown or self.claim}** {_unbroken(self._sentence())}"
        if self.details:
            say = _say(self.language)
            line += (f"\n\n<details><summary>{say('How it was checked')}</summary>\n\n"
                     f"{_unbroken(self.details)}\n\n</details>")
        if not self.display:
            return line
        # An identity "lhs = rhs" is shown on two lines, "= rhs" under the left side: on one
        # line the longer ones are wider than the book's column, and MathJax 3 does not break
        # lines. The same LaTeX, only aligned.
        lhs, equals, rhs = self.display.partition(" = ")
        shown = (f"\\begin{{aligned}}\n&{lhs} \\\\\n&\\quad = {rhs}\n\\end{{aligned}}"
                 if equals and " = " not in rhs else self.display)
        return f"$$\n{shown}\n$$\n\n{line}"


# A number in e-notation, outside math: browsers may break a line after its hyphen
# ("1e-" / "12", seen in the PDF), so it is kept in one piece.
_E_NUMBER = re.compile(r"(?<![\w$\\])(\d+(?:\.\d+)?e[-+]\d+)(?![\w$])")


def _unbroken(text: str) -> str:
    """Wrap each e-notation number outside ``$...$`` in a span that does not break."""
    parts = text.split("$")
    for i in range(0, len(parts), 2):  # the even parts lie outside math
        parts[i] = _E_NUMBER.sub(r'<span style="white-space: nowrap">\1</span>', parts[i])
    return "$".join(parts)


def _say(language: str | None) -> Say:
    return say_for(__package__, language)


def _require(ok: bool, message: str) -> None:
    # Not an assert statement: ``python -O`` would strip the checks.
    if not ok:
        raise AssertionError(message)


def _fmt(x: float) -> str:
    """Two significant digits, as the book prints errors (0 stays 0)."""
    return "0" if x == 0 else f"{x:.1e}" if abs(x) < 1e-3 or abs(x) >= 1e4 else f"{x:.2g}"


def identity(ident: _Identity, *, show: bool = False, language: str | None = None) -> Verdict:
    r"""Assert that a sympy identity holds and that its mutant does not; return the verdict.

    A statement with a domain (``ident.where``) is also evaluated, its radicals as principal
    roots, at points of the domain (each difference below 1e-20), and at ``ident.outside``
    (where it must fail): sympy's radical splitting, true on the domain only, is then checked
    by arithmetic. A statement of kind ``"arithmetic"`` (a value at an end point, a shift)
    says that it is no more than that.

    Parameters
    ----------
    ident : elliptic_pendulum.checks.symbolic.Identity
        The statement; ``ident.mutant_identity()`` (when ``ident.mutant`` is set) is the same
        statement with the mutated right-hand side.
    show : bool
        Display the statement itself above the verdict (off by default: on a page the
        verdict follows the equation the reader has just read).
    language : str, optional
        The language of the verdict ("en", "ja"); by default the environment's.

    Raises
    ------
    AssertionError
        If sympy does not reduce the statement to 0, or reduces its mutant to 0, or the
        statement fails at a point of its domain, or holds at its point outside.

    Examples
    --------
    >>> from elliptic_pendulum.checks.identities import identity as named
    >>> print(identity(named("eq13")))
    ✔ (13) holds identically: sympy reduces the difference of its two sides to 0.
    >>> print(identity(named("eq13_root")))
    ✔ (13) holds for $- \pi < \theta < \pi$, not beyond: sympy reduces ... to 0 there.
    >>> print(identity(named("eq13"), language="ja"))
    ✔ (13) は恒等的に成り立つ。sympy は両辺の差を 0 に簡約する。
    """
    say = _say(language)
    _require(ident.check(), f"{ident.equation} ({ident.name}): sympy does not confirm it")
    kind = getattr(ident, "kind", "sympy identity")
    where = getattr(ident, "where", ())
    outside = getattr(ident, "outside", ())
    details = []
    if kind == "arithmetic":
        text = say("follows by arithmetic: sympy evaluates both sides to the same value")
    elif where:
        domain = say(getattr(ident, "domain_md", "")) or f"${ident.domain_latex()}$"  # type: ignore[attr-defined]
        at = ident.domain_residuals()  # type: ignore[attr-defined]
        _require(max(at) <= 1e-20, f"{ident.name}: fails at a point of its domain ({max(at):.3g})")
        if outside:
            text = say("holds for {domain}, not beyond: sympy reduces the difference of its two "
                       "sides to 0 there", domain=domain)
        else:
            text = say("holds for {domain}: sympy reduces the difference of its two sides to 0 "
                       "there", domain=domain)
        details.append(say(
            "Sympy splits square roots as if their radicands were positive, which is true for "
            "{domain} only; without that step the difference is below $10^{{-20}}$ at {count} "
            "points of it.", domain=domain, count=len(at)))
        if outside:
            off = ident.value_at(dict(outside))  # type: ignore[attr-defined]
            _require(off > 1e-6, f"{ident.name}: holds outside its domain too")
            point = ", ".join(f"${_tex(v)} = {_tex(x)}$" for v, x in outside)
            details.append(say("Beyond it the statement is false: at {point} the two sides "
                               "differ by {difference}.", point=point, difference=_fmt(off)))
    else:
        text = say("holds identically: sympy reduces the difference of its two sides to 0")
    mutant = getattr(ident, "mutant", None)
    if mutant is not None:
        wrong = ident.mutant_identity()  # type: ignore[attr-defined]
        _require(not wrong.check(), f"{ident.name}: the check cannot tell the mutant apart")
        label = say(getattr(ident, "mutant_label", "")) or f"${wrong.latex()}$"
        details.append(say("A wrong version, {label}, is rejected: sympy does not reduce it "
                           "to 0.", label=label))
    else:
        details.append(say("No wrong version is tried."))
    return Verdict(ident.equation, kind, text, ident.latex() if show else "",
                   say.sentences(details), say.language, _shown(say, ident.equation))


def _shown(say: Say, claim: str) -> str:
    """Return the claim in the reader's language, or "" when it reads the same."""
    shown = say(claim)
    return "" if shown == claim else shown


def _tex(x: Any) -> str:
    """LaTeX of a sympy object, without importing sympy here (it has its own printer)."""
    printer = getattr(x, "_repr_latex_", None)
    text = printer() if printer is not None else str(x)
    return text.strip("$").replace("\\displaystyle ", "").replace(r"{\left(t \right)}", "")


def numeric(
    claim: str,
    residual: Callable[[Any], float],
    formula: Any,
    mutant: Any = None,
    *,
    tol: float,
    over: str,
    mutant_label: str = "",
    measure: str = "max |residual|",
    values: Mapping[str, Any] | None = None,
    language: str | None = None,
) -> Verdict:
    r"""Assert ``residual(formula) <= tol < residual(mutant)``; return the verdict.

    Parameters
    ----------
    claim : str
        What is checked, a literal: ``"(26)"``, ``"Proposition 1.2"``.
    residual : callable
        Measures how far a candidate formula is from an *independent* computation (quadrature,
        an integrator, mpmath, an FFT); the same function judges the formula and its mutant.
    formula, mutant
        The formula as printed, and a mutant of it (None only where no mutant makes sense,
        which the verdict then says).
    tol : float
        The tolerance; it must separate the two.
    over : str
        Where it was measured: ``"20 swings, 3001 times each"``.
    mutant_label : str
        The mutant as the reader would write it, e.g. ``"$8K_1/\omega_0$"``.
    measure : str
        What the residual is, for the verdict line.
    values : dict, optional
        Makes ``over``, ``mutant_label`` and ``measure`` templates (``str.format``; a literal
        brace is ``{{``), filled with these values after translation, so that a catalog
        translates "{n} swings" once for every n: ``over="{n} swings", values={"n": 20}``.
    language : str, optional
        The language of the verdict ("en", "ja"); by default the environment's. ``over``,
        ``mutant_label`` and ``measure`` are looked up in the catalog of the environment (see
        the module's description); the default ``measure`` is the package's own.

    Examples
    --------
    The period of small swings, 2 pi / omega0, against the zeros of cos(omega0 t) found by
    bisection, and the mutant 4 pi / omega0:

    >>> import math
    >>> from scipy.optimize import brentq
    >>> w0 = 1.7
    >>> zeros = [brentq(lambda t: math.cos(w0 * t), a / w0, (a + 1) / w0) for a in (1, 7)]
    >>> def residual(T):
    ...     return abs(T(w0) - (zeros[1] - zeros[0]))
    >>> v = numeric("(8)", residual, lambda w: 2 * math.pi / w, lambda w: 4 * math.pi / w,
    ...             tol=1e-12, over="two zeros of cos", mutant_label="4 pi / omega0")
    >>> v.claim, v.kind
    ('(8)', 'numerical')
    >>> numeric("(8)", residual, lambda w: 4 * math.pi / w, tol=1e-12, over="two zeros")
    Traceback (most recent call last):
    ...
    AssertionError: (8): max |residual| 3.7 > tolerance 1e-12
    """
    say = _say(language)
    fill = dict(values or {})
    err = float(residual(formula))
    _require(err <= tol, f"{claim}: {measure} {err:.3g} > tolerance {tol:.1g}")
    measured = say(measure, **fill)
    text = say("holds: {measure} {error} over {over}", measure=measured, error=_fmt(err),
               over=say(over, **fill))
    details = [say("Measured against an independent computation; the tolerance is "
                   "{tolerance}.", tolerance=_fmt(tol))]
    if mutant is not None:
        bad = float(residual(mutant))
        _require(not bad <= tol, f"{claim}: the mutant passes too ({measure} {bad:.3g})")
        if mutant_label:
            details.append(say("A wrong version, {label}, is rejected: its {measure} is "
                               "{error}.", label=say(mutant_label, **fill), measure=measured,
                               error=_fmt(bad)))
        else:
            details.append(say("A wrong version, a changed formula, is rejected: its {measure} "
                               "is {error}.", measure=measured, error=_fmt(bad)))
    else:
        # Said, so that a reader sees the check is the weaker kind.
        details.append(say("No wrong version is tried."))
    return Verdict(claim, "numerical", text, details=say.sentences(details),
                   language=say.language, shown=_shown(say, claim))


def fact(claim: str, ok: bool, text: str, *, values: Mapping[str, Any] | None = None,
         language: str | None = None) -> Verdict:
    """Assert a numerical fact and return it as a verdict.

    ``text`` is written in ``language`` (by default the environment's) when the catalog of the
    environment has it (see the module's description), else as given. With ``values`` it is
    a template (``str.format``), filled after translation: ``fact("(30)", ok, "over {n}
    rotations", values={"n": n})`` needs one catalog entry for every n.

    Examples
    --------
    >>> fact("(14)", -1 <= 0.3 <= 1, "xi stays in [-1, 1]")
    ✔ (14) xi stays in [-1, 1].
    """
    say = _say(language)
    _require(ok, f"{claim}: not so: {text.format(**values) if values else text}")
    return Verdict(claim, "numerical fact", say(text, **(values or {})), language=say.language,
                   shown=_shown(say, claim))
