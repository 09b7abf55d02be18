r"""The note's identities as sympy statements, each one checkable.

Every statement is an :class:`Identity`: the note's location, a left and a right side to display
(``sympy.latex``), and :meth:`Identity.check`, True iff ``sympy.simplify`` reduces the residual
to 0.
The book shows and checks a statement in one cell, and ``tests/test_symbolic.py`` checks the very
same objects. :func:`identities` lists the correct statements in the note's order, (1)-(46);
:func:`elliptic_pendulum.errata.printed_errata` lists the places where the note prints something
else, with the printed statement as an Identity whose check fails.

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

__all__ = ["Identity", "G", "identities", "identity", "symbols"]

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
        (:func:`elliptic_pendulum.verify.identity` asserts that it does).
    mutant_label : str
        How the verdict names the mutant (Markdown); by default its LaTeX.

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

    def mutant_identity(self) -> Identity:
        """Return the same statement with the mutant as its right-hand side."""
        if self.mutant is None:
            raise ValueError(f"{self.name} has no mutant")
        return replace(self, name=self.name + "_mutant", rhs=self.mutant, mutant=None)

    def residual(self) -> sp.Expr:
        """Return lhs - rhs with derivatives and integrals done and the ``given`` substituted."""
        r = self.lhs - self.rhs
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

    def check(self) -> bool:
        """Return True iff ``sympy.simplify(self.residual()) == 0``."""
        return bool(sp.simplify(self.residual()) == 0)

    def latex(self) -> str:
        """Return the statement as LaTeX, lhs = rhs."""
        return f"{sp.latex(self.lhs)} = {sp.latex(self.rhs)}"

    def _repr_latex_(self) -> str:
        return f"$${self.latex()}$$"


def _E1(upper, k=alpha):
    """Return the note's E1 (17) as an unevaluated integral."""
    return sp.Integral(1 / sp.sqrt((1 - s**2) * (1 - k**2 * s**2)), (s, 0, upper))


def _solve_12():
    """Solve the note's 2x2 linear system from (1)-(2) for theta'' (as A) and T."""
    xx, yy = ell * sp.sin(theta), -ell * sp.cos(theta)
    eqs = [sp.Eq(mass * xx.diff(t, 2), -T * sp.sin(theta)),
           sp.Eq(mass * yy.diff(t, 2), T * sp.cos(theta) - mass * g)]
    eqs = [e.subs(ddth, A) for e in eqs]
    sol = sp.solve(eqs, [A, T], dict=True)[0]
    return sp.simplify(sol[A]), sp.simplify(sol[T])


def identities() -> list[Identity]:
    r"""Return the note's correct statements, in the note's order.

    Examples
    --------
    >>> ids = {e.name: e for e in identities()}
    >>> ids["eq23"].check(), ids["eq3"].check(), ids["tau"].check()
    (True, True, True)
    """
    A_sol, T_sol = _solve_12()
    w2 = omega0**2
    xi = sp.sin(theta / 2) / alpha
    X = (1 - Gs**2) * (1 - alpha**2 * Gs**2)
    Ga, Gg = G(u, alpha), G(u, gamma)
    Xu = (1 - Ga**2) * (1 - alpha**2 * Ga**2)
    c7 = sp.Symbol("C_1") * sp.sin(omega0 * t) + sp.Symbol("C_2") * sp.cos(omega0 * t)
    th25 = 2 * sp.asin(alpha * G(omega0 * t + c2, alpha))
    th35 = 2 * sp.asin(G(omega0 * t / gamma + c4, gamma))
    tanh = sp.tanh(omega0 * t - c3)
    sqrt30 = sp.sqrt(2 * sp.cos(theta) + 2 * beta)
    beta_of_gamma = 2 / gamma**2 - 1
    I_ = sp.asin(Gg)
    integrand = 1 / sp.sqrt((1 - s**2) * (1 - alpha**2 * s**2))
    P = sp.Symbol("P_II")
    In = sp.Function("I")
    dom_z = "-1 < z < 1, 0 < alpha < 1"
    return [
        Identity("xpp", "§2, x''", (ell * sp.sin(theta)).diff(t, 2),
                 ell * ddth * sp.cos(theta) - ell * dth**2 * sp.sin(theta)),
        Identity("ypp", "§2, y''", (-ell * sp.cos(theta)).diff(t, 2),
                 ell * ddth * sp.sin(theta) + ell * dth**2 * sp.cos(theta)),
        Identity("eq3", "(3)", A_sol, -g / ell * sp.sin(theta)),
        Identity("eq4", "(4)", dth**2, T_sol / (ell * mass) - g / ell * sp.cos(theta)),
        Identity("eq7", "(5)-(7)", c7.diff(t, 2), -g / ell * c7,
                 given=((omega0, sp.sqrt(g / ell)),)),
        Identity("eq8", "(8)", c7.subs(t, t + 2 * sp.pi / omega0), c7),
        Identity("eq8_value", "(8)", 2 * sp.pi / sp.sqrt(g / ell), 2 * sp.pi * sp.sqrt(ell / g)),
        Identity("eq9", "(9)", sp.Derivative(dth**2 - 2 * w2 * sp.cos(theta), t), sp.Integer(0),
                 given=((ddth, -w2 * sp.sin(theta)),)),
        Identity("eq10", "(10)", (ell * sp.sin(theta)).diff(t) ** 2
                 + (-ell * sp.cos(theta)).diff(t) ** 2, ell**2 * dth**2),
        Identity("energy", "§3, after (10)",
                 mass / 2 * ell**2 * dth**2 - mass * g * ell * sp.cos(theta),
                 mass / 2 * ell**2 * c1, given=((c1, dth**2 - 2 * w2 * sp.cos(theta)),
                                                (g, w2 * ell))),
        Identity("regime_I", "§3, case I", 2 * w2 * sp.cos(theta) - 2 * w2,
                 -4 * w2 * sp.sin(theta / 2) ** 2),
        Identity("eq12", "(11)-(12)", 2 * w2 * sp.cos(theta) + c1,
                 2 * w2 * (sp.cos(theta) - sp.cos(theta0)),
                 given=((c1, -2 * w2 * sp.cos(theta0)),)),
        Identity("phase_clockwise", "§3, case II, direction",
                 sp.Derivative(sp.atan(dth / theta), t),
                 (-w2 * theta * sp.sin(theta) - dth**2) / (theta**2 + dth**2),
                 given=((ddth, -w2 * sp.sin(theta)),)),
        Identity("eq13", "(13)", 2 * w2 * (sp.cos(theta) + 1), 4 * w2 * sp.cos(theta / 2) ** 2),
        Identity("eq13_root", "(13)", sp.sqrt(4 * w2 * sp.cos(theta / 2) ** 2),
                 2 * omega0 * sp.cos(theta / 2), positive_radicands=True,
                 domain="-pi < theta < pi"),
        Identity("eq12_half_angle", "§4, before (14)", 2 * w2 * (sp.cos(theta) - sp.cos(theta0)),
                 4 * w2 * (sp.sin(theta0 / 2) ** 2 - sp.sin(theta / 2) ** 2)),
        Identity("eq15", "(14)-(15)", xi.diff(t) ** 2, w2 * (1 - xi**2) * (1 - alpha**2 * xi**2),
                 given=((dth, 2 * omega0 * sp.sqrt(alpha**2 - sp.sin(theta / 2) ** 2)),)),
        Identity("prop1_2", "Proposition 1.2", integrand.diff(s),
                 ((1 - s**2) * (1 - alpha**2 * s**2)) ** sp.Rational(-3, 2)
                 * s * (1 + alpha**2 - 2 * alpha**2 * s**2)),
        Identity("prop1_2_sign", "Proposition 1.2", 1 + alpha**2 - 2 * alpha**2 * s**2,
                 (1 - alpha**2) + 2 * alpha**2 * (1 - s**2)),
        Identity("prop1_3_E1", "Proposition 1.3", _E1(z).subs(alpha, 0), sp.asin(z)),
        Identity("prop1_3_K1", "Proposition 1.3", _E1(1).subs(alpha, 0), sp.pi / 2),
        Identity("eq17_sympy", "(17)", sp.Derivative(sp.elliptic_f(sp.asin(z), alpha**2), z),
                 integrand.subs(s, z), positive_radicands=True, domain=dom_z),
        Identity("eq22", "(22)", 1 / _E1(Gs).diff(Gs), sp.sqrt(X)),
        Identity("eq22_at_K1", "§4, G_u(K1 - 0) = 0", sp.sqrt(X).subs(Gs, 1), sp.Integer(0)),
        Identity("eq23_middle", "(23)", (-2 * Ga - 2 * alpha**2 * Ga + 4 * alpha**2 * Ga**3)
                 * sp.Derivative(Ga, u) / (2 * sp.sqrt(Xu)),
                 -(1 + alpha**2) * Ga + 2 * alpha**2 * Ga**3),
        Identity("eq23", "(23)", sp.Derivative(Xu, u) / (2 * sp.Derivative(Ga, u)),
                 -(1 + alpha**2) * Ga + 2 * alpha**2 * Ga**3),
        Identity("eq23_direct", "(23)", sp.Derivative(Ga, (u, 2)),
                 -(1 + alpha**2) * Ga + 2 * alpha**2 * Ga**3),
        Identity("eq23_at_K1", "§4, G_uu(K1 - 0)", -(1 + alpha**2) + 2 * alpha**2, alpha**2 - 1),
        Identity("eq25_solves_eq3", "(25)", sp.Derivative(th25, (t, 2)), -w2 * sp.sin(th25),
                 positive_radicands=True, domain="|G| < 1"),
        Identity("eq26", "(26)", 4 * K1 / omega0, 4 * K1 * sp.sqrt(ell / g),
                 given=((omega0, sp.sqrt(g / ell)),)),
        Identity("ratio_R", "§4, R(theta_0)", (4 * K1 / omega0) / (2 * sp.pi / omega0),
                 2 * K1 / sp.pi),
        Identity("K1_at_0", "§4, K1(+0)", sp.elliptic_k(0), sp.pi / 2),
        Identity("partial_fractions", "§5", 1 / (1 - z**2),
                 (1 / (1 - z) + 1 / (1 + z)) / 2),
        Identity("log_antiderivative", "§5", sp.Derivative(sp.log((1 + z) / (1 - z)) / 2, z),
                 1 / (1 - z**2)),
        Identity("eq27", "(27)", tanh.diff(t), omega0 * (1 - tanh**2)),
        Identity("eq27_exp", "(27)", (sp.exp(2 * x) - 1) / (sp.exp(2 * x) + 1), sp.tanh(x),
                 given=((sp.tanh(x), (sp.exp(x) - sp.exp(-x)) / (sp.exp(x) + sp.exp(-x))),)),
        Identity("eq13_to_27", "§5", dth / 2 * sp.cos(theta / 2),
                 omega0 * (1 - sp.sin(theta / 2) ** 2),
                 given=((dth, 2 * omega0 * sp.cos(theta / 2)),)),
        Identity("eq28", "(28)", (2 * sp.asin(tanh)).diff(t), 2 * omega0 * sp.cos(sp.asin(tanh))),
        Identity("eq28_solves_eq3", "(28)", (2 * sp.asin(tanh)).diff(t, 2),
                 -w2 * sp.sin(2 * sp.asin(tanh)), positive_radicands=True, domain="all t"),
        Identity("eq29", "(29)", 2 * w2 * sp.cos(theta) + c1, 2 * w2 * (sp.cos(theta) + beta),
                 given=((c1, 2 * w2 * beta),)),
        Identity("eq30_half_angle", "§6, gamma", 2 * sp.cos(theta) + 2 * beta,
                 2 * beta + 2 - 4 * sp.sin(theta / 2) ** 2),
        Identity("eq30_gamma", "§6, gamma", sp.sqrt(2 * beta + 2 - 4 * sp.sin(theta / 2) ** 2),
                 2 / gamma * sp.sqrt(1 - gamma**2 * sp.sin(theta / 2) ** 2),
                 given=((beta, beta_of_gamma),), positive_radicands=True, domain="beta > 1"),
        Identity("eq32", "(31)-(32)",
                 sp.Derivative(sp.Integral(1 / sp.sqrt(1 - gamma**2 * sp.sin(phi / 2) ** 2),
                                           (phi, 0, theta)), t),
                 sp.Derivative(2 * (omega0 * t / gamma + c4), t),
                 given=((dth, 2 * omega0 / gamma
                         * sp.sqrt(1 - gamma**2 * sp.sin(theta / 2) ** 2)),)),
        Identity("eq33", "(33)", (1 / sp.sqrt(1 - gamma**2 * sp.sin(phi / 2) ** 2)).subs(
                     phi, 2 * sp.asin(z)) * sp.Derivative(2 * sp.asin(z), z),
                 2 / sp.sqrt((1 - z**2) * (1 - gamma**2 * z**2)),
                 positive_radicands=True, domain="z = sin(phi/2), -pi < phi < pi"),
        Identity("eq38", "(38)", sp.sin((theta - 2 * sp.pi) / 2), -sp.sin(theta / 2)),
        Identity("E1_odd", "(38)", sp.Derivative(_E1(z) + _E1(-z), z), sp.Integer(0)),
        Identity("eq35_solves_eq30", "(35), (41)", sp.Derivative(th35, t),
                 omega0 * sqrt30.subs(theta, th35), given=((beta, beta_of_gamma),),
                 positive_radicands=True, domain="|G| < 1, 0 < gamma < 1"),
        Identity("eq42", "(42)", sp.Derivative(I_, u), sp.sqrt(1 - gamma**2 * Gg**2),
                 positive_radicands=True, domain="|G| < 1"),
        Identity("eq42_at_K1", "(42)", sp.sqrt(1 - gamma**2 * Gs**2).subs(Gs, 1),
                 sp.sqrt(1 - gamma**2)),
        Identity("I_uu", "§6, I_uu", sp.Derivative(sp.sqrt(1 - gamma**2 * Gg**2), u),
                 -gamma**2 * Gg * sp.sqrt(1 - Gg**2), positive_radicands=True, domain="|G| < 1"),
        Identity("I_uu_at_K1", "§6, I_uu(K1 - 0) = 0",
                 (-gamma**2 * Gs * sp.sqrt(1 - Gs**2)).subs(Gs, 1),
                 sp.Integer(0)),
        Identity("eq43", "(43)",
                 sp.Derivative(sp.asin(G(u - 2 * n_int * K1, gamma)) + n_int * sp.pi, u),
                 sp.sqrt(1 - gamma**2 * ((-1) ** n_int * G(u - 2 * n_int * K1, gamma)) ** 2),
                 positive_radicands=True, domain="|G| < 1"),
        Identity("eq45", "(45)", In(u + 2 * K1) - P * (u + 2 * K1), In(u) - P * u,
                 given=((In(u + 2 * K1), In(u) + sp.pi), (P, sp.pi / (2 * K1)))),
        Identity("tau_integrand", "§6, tau",
                 sp.sqrt(1 - gamma**2 * z**2) / sp.sqrt((1 - z**2) * (1 - gamma**2 * z**2)),
                 1 / sp.sqrt(1 - z**2), positive_radicands=True, domain=dom_z),
        Identity("tau", "§6, tau", sp.Integral(1 / sp.sqrt(1 - z**2), (z, 0, 1)) / K1,
                 sp.pi / (2 * K1)),
    ]


def identity(name: str) -> Identity:
    """Return the correct statement called ``name`` (see :func:`identities` for the names).

    Examples
    --------
    >>> e = identity("eq27")
    >>> e.equation, e.check()
    ('(27)', True)
    """
    found = {e.name: e for e in identities()}
    if name not in found:
        raise ValueError(f"name must be one of {sorted(found)}, got {name!r}")
    return found[name]
