r"""The note's identities as sympy statements, each one checkable.

Every statement is an :class:`Identity`: the note's location, a left and a right side to display
(``sympy.latex``), and :meth:`Identity.check`, True iff ``sympy.simplify`` reduces the residual
to 0.
The book shows and checks a statement in one cell, and ``tests/checks/test_symbolic.py``
checks the very same objects. :func:`.identities` lists the correct statements in the
note's order, (1)-(46); :func:`.printed_errata` lists the places where the note prints
something else, with the printed statement as an Identity whose check fails.

Some steps hold only on a domain, where the radicands are positive: -1 < z < 1, 0 < alpha < 1,
-pi < theta < pi. There sympy cannot split sqrt(A B) into sqrt(A) sqrt(B) by itself; such statements
carry ``positive_radicands=True`` and their residual splits radicals as if every factor were
positive (``force=True``). That is sound on the stated domain only, so the tests also evaluate the
residuals numerically at random points of the domain, independently of ``simplify``.

This module imports sympy only, nothing numeric from the package.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import sympy as sp

__all__ = ["Identity", "G", "symbols"]

# The note's symbols. Positivity is what the note assumes (l, m, g, omega_0 > 0, 0 < alpha < 1).
t, u, v, x, z, s, phi = sp.symbols("t u v x z s phi", real=True)
ell, mass, g, omega0 = sp.symbols(r"\ell m g omega_0", positive=True)
alpha, gamma, beta = sp.symbols("alpha gamma beta", positive=True)
c1, c2, c3, c4, theta0, A, T = sp.symbols("c_1 c_2 c_3 c_{4} theta_0 A T", real=True)
K1 = sp.Symbol("K_1", positive=True)
theta = sp.Function("theta", real=True)(t)
Gs = sp.Symbol("G", real=True)  # G as a value, where (22) or (23) is read pointwise
n_int = sp.Symbol("m", integer=True)

dth, ddth = theta.diff(t), theta.diff(t, 2)


class G(sp.Function):
    r"""The note's G(u, k) (19), known to sympy through its derivative (22).

    .. math:: G_u(u, k) = \sqrt{(1 - G^2)(1 - k^2 G^2)}

    With (22) as ``fdiff`` the chain rule does the rest: (23), (25), (42) and (43) follow by
    differentiation, as in the note.
    """

    nargs = 2

    def fdiff(self, argindex=1):  # noqa: D102 - sympy's hook
        if argindex != 1:
            raise sp.ArgumentIndexError(self, argindex)
        k = self.args[1]
        return sp.sqrt((1 - self**2) * (1 - k**2 * self**2))

    def _eval_is_real(self):
        return True


def symbols() -> dict[str, sp.Basic]:
    """Return the note's symbols by name, for the book's cells.

    Examples
    --------
    >>> sorted(symbols())[:4]
    ['A', 'G', 'G_value', 'K1']
    """
    return {"t": t, "u": u, "z": z, "s": s, "phi": phi, "l": ell, "m": mass, "g": g,
            "omega0": omega0, "alpha": alpha, "beta": beta, "gamma": gamma, "c1": c1,
            "theta0": theta0, "theta": theta, "G": G, "G_value": Gs, "K1": K1, "A": A, "T": T}


@dataclass(frozen=True)
class Identity:
    r"""One statement of the note: lhs = rhs, with where it is and what it needs.

    Parameters
    ----------
    name : str
        Short ASCII key, e.g. ``"eq23"``.
    equation : str
        The note's location, e.g. ``"(23)"`` or ``"§4, after (23)"``.
    lhs, rhs : sympy.Expr
        The two sides, as displayed (derivatives and integrals may be unevaluated).
    given : tuple
        Pairs (old, new) of sympy expressions: substitutions that hold along the motion
        (e.g. theta'' -> -omega_0^2 sin theta), applied in order after ``doit()``.
    positive_radicands : bool
        Split radicals as if their factors were positive (true on the stated ``domain`` only).
    domain : str
        Where the statement is claimed.
    mutant : sympy.Expr or None
        A wrong right-hand side, the mistake a reader could make (a changed coefficient, sign,
        exponent or argument); a check worth its name must reject it
        (``elliptic_pendulum.checks.verify.identity`` asserts that it does).
    mutant_label : str
        How the verdict names the mutant (Markdown); by default its LaTeX.
    where : tuple
        The domain as intervals ``(variable, low, high)``, exact: a symbol, an applied
        function such as ``theta`` (its value), or the class :class:`G` (every value of G).
        Required with ``positive_radicands``: :meth:`domain_residuals` evaluates the
        residual *without* splitting radicals at points of it, so that what the splitting
        assumed is checked by arithmetic.
    outside : tuple
        Pairs ``(variable, value)``: a point beyond the domain where the statement fails, to
        show that the domain is part of the statement (:meth:`value_at`).
    kind : str
        ``"sympy identity"``, or ``"arithmetic"`` for a one-line evaluation or substitution
        (a value at an end point, a shift by 2 pi) that the registry does not count as an
        identity.
    samples : int
        How many points of ``where`` :meth:`domain_residuals` evaluates.
    domain_md : str
        The domain as the verdict states it (Markdown), when it is larger than the sampled
        ``where`` (all real t, say); by default :meth:`domain_latex`.
    change_of_variable : tuple
        ``(x, f(v), v)``: compare integrals after the substitution x = f(v) (sympy's
        ``Integral.transform``, limits included), by linearity over each range of v, instead of
        integrating in closed form; ``given`` is substituted first.

    Examples
    --------
    >>> e = Identity("demo", "(none)", sp.sin(x) ** 2 + sp.cos(x) ** 2, sp.Integer(1))
    >>> e.check(), e.latex()
    (True, '\\sin^{2}{\\left(x \\right)} + \\cos^{2}{\\left(x \\right)} = 1')
    """

    name: str
    equation: str
    lhs: sp.Expr
    rhs: sp.Expr
    given: tuple = ()
    positive_radicands: bool = False
    domain: str = ""
    mutant: sp.Expr | None = None
    mutant_label: str = ""
    change_of_variable: tuple = ()
    where: tuple = ()
    outside: tuple = ()
    kind: str = "sympy identity"
    samples: int = 6
    domain_md: str = ""

    def mutant_identity(self) -> Identity:
        """Return the same statement with the mutant as its right-hand side."""
        if self.mutant is None:
            raise ValueError(f"{self.name} has no mutant")
        return replace(self, name=self.name + "_mutant", rhs=self.mutant, mutant=None)

    def residual(self) -> sp.Expr:
        """Return lhs - rhs with derivatives and integrals done and the ``given`` substituted."""
        r = self.lhs - self.rhs
        if self.change_of_variable:
            return self._substituted(r)
        # Derivatives first and shallow: d/dz of an integral is its integrand (Leibniz), and a deep
        # doit() would first try, slowly and in vain, to integrate E1 in closed form.
        r = r.replace(lambda e: isinstance(e, sp.Derivative), lambda e: e.doit(deep=False)).doit()
        for old, new in self.given:
            r = r.subs(old, new).doit()
        if self.positive_radicands:
            r = r.replace(sp.Abs, lambda a: a)  # |a| = a on the domain, like the radicands
            r = sp.powdenest(sp.expand_power_base(r, force=True), force=True)
            r = sp.powsimp(r, force=True).doit().replace(sp.Abs, lambda a: a)
        return r

    def _substituted(self, r: sp.Expr) -> sp.Expr:
        old, new, var = self.change_of_variable
        for a, b in self.given:
            r = r.subs(a, b)
        r = r.replace(lambda e: isinstance(e, sp.Integral) and tuple(e.variables) == (old,),
                      lambda e: e.transform(old, (new, var)))
        # One integral per range: the integrands are compared, never integrated (E1 has no
        # elementary antiderivative, and sympy would spend seconds finding that out).
        rest: sp.Expr = sp.Integer(0)
        merged: dict[tuple, sp.Expr] = {}
        for term in sp.Add.make_args(sp.expand(r, deep=False)):
            coeff, part = term.as_independent(sp.Integral, as_Add=False)
            if isinstance(part, sp.Integral) and var not in coeff.free_symbols:
                merged[part.limits] = merged.get(part.limits, 0) + coeff * part.function
            else:
                rest += term
        for limits, integrand in merged.items():
            h = integrand
            if self.positive_radicands:  # factor each radicand's content, then split it
                h = h.replace(lambda e: e.is_Pow and e.exp.is_Rational and not e.exp.is_Integer,
                              lambda e: sp.Pow(sp.factor_terms(e.base), e.exp))
                h = sp.powdenest(sp.expand_power_base(h, force=True), force=True)
            h = sp.simplify(h)
            if h != 0:
                rest += sp.Integral(h, *limits)
        return rest

    def check(self) -> bool:
        """Return True iff ``sympy.simplify(self.residual()) == 0``."""
        return bool(sp.simplify(self.residual()) == 0)

    def domain_latex(self) -> str:
        r"""Return the domain ``where`` as LaTeX, e.g. ``-\pi < \theta < \pi``."""
        def name(var):
            return "G" if var is G else sp.latex(var).replace(r"{\left(t \right)}", "")
        return ", ".join(f"{sp.latex(lo)} < {name(v)} < {sp.latex(hi)}"
                         for v, lo, hi in self.where)

    def value_at(self, point: dict) -> float:
        """Return the absolute difference of the two sides at ``point``, at 30 digits.

        Radicals are principal roots here: nothing is split.

        ``point`` maps symbols, applied functions (``theta``), derivatives, or the class
        :class:`G` (every value of G) to exact numbers; anything left is given a value by
        ``_default``, inside the note's standing assumptions.
        """
        r = replace(self, positive_radicands=False).residual()
        for d in sorted(r.atoms(sp.Derivative), key=lambda d: -d.derivative_count):
            r = r.subs(d, point.get(d, sp.Rational(3, 10)))
        for f in r.atoms(sp.core.function.AppliedUndef) | r.atoms(G):
            value = point.get(f, point.get(type(f)))
            r = r.subs(f, value if value is not None else self._default(f))
        r = r.subs({v: point.get(v, self._default(v)) for v in r.free_symbols})
        return abs(complex(sp.N(r, 30)))

    @staticmethod
    def _default(v) -> sp.Expr:
        # A fixed value inside the standing assumptions: positive constants positive,
        # 0 < alpha, gamma < 1, beta > 1, |z|, |G| < 1, |theta| small enough for regime II.
        name = getattr(v, "name", type(v).__name__)
        if getattr(v, "is_integer", False):
            return sp.Integer(2)
        if name in {"alpha", "gamma"}:
            return sp.Rational(7, 10)
        if name == "beta":
            return sp.Rational(17, 10)
        if name in {"theta", "z", "s", "G"}:
            return sp.Rational(2, 10)
        return sp.Rational(13, 10) if getattr(v, "is_positive", False) else sp.Rational(-4, 10)

    def domain_residuals(self) -> list[float]:
        """Return :meth:`value_at` at ``samples`` points spread over ``where`` (none if empty).

        The k-th point puts variable i at the fraction (k + 1/2) * phi_i (mod 1) of its
        interval, phi_i the golden ratio's powers: spread, never at an end point.
        """
        golden = (1 + sp.sqrt(5)) / 2
        points = []
        for k in range(self.samples if self.where else 0):
            point = {}
            for i, (v, lo, hi) in enumerate(self.where):
                frac = sp.Rational(sp.N(((k + sp.Rational(1, 2)) * golden ** (i + 1)) % 1, 12))
                point[v] = lo + (hi - lo) * frac
            points.append(self.value_at(point))
        return points

    def latex(self) -> str:
        """Return the statement as LaTeX, lhs = rhs."""
        return f"{sp.latex(self.lhs)} = {sp.latex(self.rhs)}"

    def _repr_latex_(self) -> str:
        return f"$${self.latex()}$$"
