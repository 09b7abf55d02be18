r"""The note's correct statements, (1)-(46), each with a mutant: the list behind ``identities()``.

Each :class:`.Identity` is displayed as it is checked: a left side that
sympy would evaluate on construction (a derivative, a substitution, a sum) is kept unevaluated
(``sp.Derivative``, ``sp.Subs``, ``evaluate=False``), so that no display reads "X = X". Each
``mutant`` is a wrong right-hand side, the slip a reader could make: a sign, a factor 2, a
squared modulus, the wrong branch; ``tests/checks/test_symbolic.py`` asserts that sympy
rejects it and that it is far from the truth at random points of the domain.

Imports sympy and :mod:`elliptic_pendulum.checks.symbolic` only.
"""

from __future__ import annotations

import sympy as sp

from .symbolic import (
    K1,
    A,
    G,
    Gs,
    Identity,
    T,
    alpha,
    beta,
    c1,
    c2,
    c3,
    c4,
    ddth,
    dth,
    ell,
    g,
    gamma,
    mass,
    n_int,
    omega0,
    phi,
    s,
    t,
    theta,
    theta0,
    u,
    x,
    z,
)

__all__ = ["identities", "identity", "note_identities"]


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


def _unevaluated_sum(*terms):
    """Return the sum as written: -(1 + a^2) + 2 a^2 must not collapse before it is shown."""
    return sp.Add(*terms, evaluate=False)


def note_identities() -> list[Identity]:  # noqa: PLR0915 - one statement per line, by design
    """Return the note's correct statements in the note's order (see ``symbolic.identities``)."""
    A_sol, T_sol = _solve_12()
    w2 = omega0**2
    xi = sp.sin(theta / 2) / alpha
    X = (1 - Gs**2) * (1 - alpha**2 * Gs**2)
    Ga, Gg = G(u, alpha), G(u, gamma)
    Xu = (1 - Ga**2) * (1 - alpha**2 * Ga**2)
    C1, C2 = sp.symbols("C_1 C_2", real=True)
    c7 = C1 * sp.sin(omega0 * t) + C2 * sp.cos(omega0 * t)
    th25 = 2 * sp.asin(alpha * G(omega0 * t + c2, alpha))
    th35 = 2 * sp.asin(G(omega0 * t / gamma + c4, gamma))
    tanh = sp.tanh(omega0 * t - c3)
    sqrt30 = sp.sqrt(2 * sp.cos(theta) + 2 * beta)
    beta_of_gamma = 2 / gamma**2 - 1
    dth30 = 2 * omega0 / gamma * sp.sqrt(1 - gamma**2 * sp.sin(theta / 2) ** 2)
    I_ = sp.asin(Gg)
    integrand = 1 / sp.sqrt((1 - s**2) * (1 - alpha**2 * s**2))
    f_z = integrand.subs(s, z)
    P_II, P_l, tau_ = sp.symbols(r"P_{II} P_\ell tau", positive=True)
    In = sp.Function("I")
    th_v = sp.Symbol("theta", real=True)  # a variable of integration named like the angle
    th0_p = sp.Symbol("theta_0", positive=True)
    c41 = sp.Symbol("c_{4,1}", real=True)
    H = lambda lo: sp.Integral(1 / sp.sqrt(1 - gamma**2 * sp.sin(phi / 2) ** 2),  # noqa: E731
                               (phi, lo, theta))
    dom_z = "-1 < z < 1, 0 < alpha < 1"
    where_z = ((z, -1, 1), (alpha, 0, 1))
    where_zg = ((z, -1, 1), (gamma, 0, 1))
    where_G = ((G, -1, 1), (alpha, 0, 1))
    where_Gg = ((G, -1, 1), (gamma, 0, 1))
    D = sp.Derivative
    return [
        Identity("xpp", r"§2, $x''$", D(ell * sp.sin(theta), (t, 2)),
                 ell * ddth * sp.cos(theta) - ell * dth**2 * sp.sin(theta),
                 mutant=ell * ddth * sp.cos(theta) + ell * dth**2 * sp.sin(theta)),
        Identity("ypp", r"§2, $y''$", D(-ell * sp.cos(theta), (t, 2)),
                 ell * ddth * sp.sin(theta) + ell * dth**2 * sp.cos(theta),
                 mutant=ell * ddth * sp.sin(theta) - ell * dth**2 * sp.cos(theta)),
        Identity("eq3", "(3)", ddth, -g / ell * sp.sin(theta), given=((ddth, A_sol),),
                 domain="theta'' from (1)-(2), T eliminated", mutant=g / ell * sp.sin(theta)),
        Identity("eq4", "(4)", dth**2, T / (ell * mass) - g / ell * sp.cos(theta),
                 given=((T, T_sol),), domain="T from (1)-(2), theta'' eliminated",
                 mutant=T / (ell * mass) + g / ell * sp.cos(theta)),
        Identity("eq7", "(7)", D(c7, (t, 2)), -g / ell * c7,
                 given=((omega0, sp.sqrt(g / ell)),), mutant=-ell / g * c7),
        # The period as four quarter swings of (7), theta = theta_0 sin(omega_0 t), along which
        # theta' = omega_0 sqrt(theta_0^2 - theta^2): a statement that a period twice as long
        # (4 pi / omega_0, also a period of (7)) fails.
        Identity("eq8", "(8)", 4 * sp.Integral(1 / (omega0 * sp.sqrt(th0_p**2 - th_v**2)),
                                               (th_v, 0, th0_p)),
                 2 * sp.pi / omega0, domain="four quarter swings of (7)",
                 mutant=4 * sp.pi / omega0, mutant_label=r"$4\pi/\omega_0$"),
        Identity("eq8_value", "(8)", 2 * sp.pi / omega0,
                 2 * sp.pi * sp.Pow(ell / g, sp.Rational(1, 2), evaluate=False),
                 given=((omega0, sp.sqrt(g / ell)),),
                 mutant=2 * sp.pi * sp.Pow(g / ell, sp.Rational(1, 2), evaluate=False)),
        Identity("eq9", "(9)", D(dth**2, t), D(2 * w2 * sp.cos(theta), t),
                 given=((ddth, -w2 * sp.sin(theta)),), mutant=D(-2 * w2 * sp.cos(theta), t)),
        Identity("eq10", "(10)", D(ell * sp.sin(theta), t) ** 2 + D(-ell * sp.cos(theta), t) ** 2,
                 ell**2 * dth**2, mutant=ell * dth**2),
        Identity("energy", "§3, after (10)",
                 mass / 2 * ell**2 * dth**2 - mass * g * ell * sp.cos(theta),
                 mass / 2 * ell**2 * c1, given=((c1, dth**2 - 2 * w2 * sp.cos(theta)),
                                                (g, w2 * ell)), mutant=mass * ell**2 * c1),
        Identity("regime_I", "§3, case I", 2 * w2 * sp.cos(theta) - 2 * w2,
                 -4 * w2 * sp.sin(theta / 2) ** 2, mutant=-2 * w2 * sp.sin(theta / 2) ** 2),
        Identity("eq12", "(12)", 2 * w2 * sp.cos(theta) + c1,
                 2 * w2 * (sp.cos(theta) - sp.cos(theta0)),
                 given=((c1, -2 * w2 * sp.cos(theta0)),),
                 mutant=2 * w2 * (sp.cos(theta) + sp.cos(theta0))),
        Identity("phase_clockwise", "§3, case II, direction",
                 D(sp.atan(dth / theta), t),
                 (-w2 * theta * sp.sin(theta) - dth**2) / (theta**2 + dth**2),
                 given=((ddth, -w2 * sp.sin(theta)),),
                 mutant=(w2 * theta * sp.sin(theta) + dth**2) / (theta**2 + dth**2),
                 mutant_label="the opposite sense of rotation"),
        Identity("eq13", "(13)", 2 * w2 * (sp.cos(theta) + 1), 4 * w2 * sp.cos(theta / 2) ** 2,
                 mutant=4 * w2 * sp.sin(theta / 2) ** 2),
        Identity("eq13_root", "(13)", sp.sqrt(4 * w2 * sp.cos(theta / 2) ** 2),
                 2 * omega0 * sp.cos(theta / 2), positive_radicands=True,
                 domain="-pi < theta < pi", where=((theta, -sp.pi, sp.pi),),
                 outside=((theta, 2 * sp.pi + sp.Rational(1, 2)), (omega0, 1)),
                 mutant=-2 * omega0 * sp.cos(theta / 2),
                 mutant_label=r"the other branch, $-2\omega_0\cos\frac{\theta}{2}$"),
        Identity("eq12_half_angle", "§4, before (14)", 2 * w2 * (sp.cos(theta) - sp.cos(theta0)),
                 4 * w2 * (sp.sin(theta0 / 2) ** 2 - sp.sin(theta / 2) ** 2),
                 mutant=4 * w2 * (sp.sin(theta / 2) ** 2 - sp.sin(theta0 / 2) ** 2)),
        Identity("eq15", "(15)", D(xi, t) ** 2, w2 * (1 - xi**2) * (1 - alpha**2 * xi**2),
                 given=((dth, 2 * omega0 * sp.sqrt(alpha**2 - sp.sin(theta / 2) ** 2)),),
                 mutant=w2 * (1 - xi**2) * (1 + alpha**2 * xi**2)),
        # (16) for z(s) = xi(s / omega_0), with theta' from (12): dz/ds = xi' / omega_0. Not
        # for z = G, which sympy knows through (22), itself derived from (16): that would be
        # circular.
        Identity("eq16", "(16)", D(xi, t) ** 2 / w2, (1 - xi**2) * (1 - alpha**2 * xi**2),
                 given=((dth, 2 * omega0 * sp.sqrt(alpha**2 - sp.sin(theta / 2) ** 2)),),
                 domain="z(s) = xi(s / omega_0), theta' from (12)",
                 mutant=(1 - xi**2) * (1 - alpha * xi**2)),
        Identity("prop1_2", "Proposition 1.2", D(integrand, s),
                 ((1 - s**2) * (1 - alpha**2 * s**2)) ** sp.Rational(-3, 2)
                 * s * (1 + alpha**2 - 2 * alpha**2 * s**2),
                 mutant=((1 - s**2) * (1 - alpha**2 * s**2)) ** sp.Rational(-1, 2)
                 * s * (1 + alpha**2 - 2 * alpha**2 * s**2)),
        Identity("prop1_2_sign", "Proposition 1.2", 1 + alpha**2 - 2 * alpha**2 * s**2,
                 (1 - alpha**2) + 2 * alpha**2 * (1 - s**2),
                 mutant=(1 - alpha**2) + alpha**2 * (1 - s**2)),
        Identity("prop1_3_E1", "Proposition 1.3", _E1(z).subs(alpha, 0), sp.asin(z),
                 mutant=sp.atan(z)),
        Identity("prop1_3_K1", "Proposition 1.3", _E1(1).subs(alpha, 0), sp.pi / 2,
                 mutant=sp.Integer(1)),
        Identity("eq17_sympy", "(17)", D(sp.elliptic_f(sp.asin(z), alpha**2), z), f_z,
                 positive_radicands=True, domain=dom_z, where=where_z,
                 mutant=1 / sp.sqrt((1 - z**2) * (1 - alpha * z**2)),
                 mutant_label=r"the modulus for the parameter, $1/\sqrt{(1-z^2)(1-\alpha z^2)}$"),
        Identity("eq22", "(22)", 1 / D(_E1(Gs), Gs), sp.sqrt(X), mutant=1 / sp.sqrt(X),
                 mutant_label=r"$(E_1)_z$ itself, $1/\sqrt{(1-G^2)(1-\alpha^2G^2)}$"),
        Identity("eq22_at_K1", r"§4, $G_u(K_1 - 0) = 0$", sp.Subs(sp.sqrt(X), Gs, 1), sp.Integer(0),
                 kind="arithmetic", mutant=sp.sqrt(1 - alpha**2)),
        Identity("eq23_middle", "(23)", (-2 * Ga - 2 * alpha**2 * Ga + 4 * alpha**2 * Ga**3)
                 * D(Ga, u) / (2 * sp.sqrt(Xu)),
                 -(1 + alpha**2) * Ga + 2 * alpha**2 * Ga**3,
                 mutant=-(1 + alpha**2) * Ga - 2 * alpha**2 * Ga**3),
        Identity("eq23", "(23)", D(Xu, u) / (2 * D(Ga, u)),
                 -(1 + alpha**2) * Ga + 2 * alpha**2 * Ga**3,
                 mutant=-(1 + alpha**2) * Ga + 2 * alpha**2 * Ga**2),
        Identity("eq23_direct", "(23)", D(Ga, (u, 2)),
                 -(1 + alpha**2) * Ga + 2 * alpha**2 * Ga**3,
                 mutant=-((1 + alpha) ** 2) * Ga + 2 * alpha**2 * Ga**3),
        # The expression the note misprints as -(1 + alpha)^2 + 2 alpha^2, shown as written.
        Identity("eq23_at_K1", r"§4, $G_{uu}(K_1 - 0)$",
                 _unevaluated_sum(sp.Mul(-1, 1 + alpha**2, evaluate=False), 2 * alpha**2),
                 alpha**2 - 1, kind="arithmetic", mutant=alpha**2 - 2 * alpha - 1,
                 mutant_label=r"$\alpha^2 - 2\alpha - 1$, the value of the printed "
                              r"$-(1+\alpha)^2 + 2\alpha^2$"),
        Identity("eq25_solves_eq3", "(25)", D(th25, (t, 2)), -w2 * sp.sin(th25),
                 positive_radicands=True, domain="|G| < 1", where=where_G,
                 mutant=-omega0 * sp.sin(th25)),
        # The period as four quarter swings: dt = d(theta) / theta' from (12), and the
        # substitution sin(theta/2) = alpha s turns the quarter into E1(1, alpha) = K1.
        Identity("eq26", "(26)",
                 4 * sp.Integral(1 / (2 * omega0 * sp.sqrt(sp.sin(theta0 / 2) ** 2
                                                         - sp.sin(phi / 2) ** 2)),
                                 (phi, 0, theta0)),
                 4 * K1 / omega0, given=((theta0, 2 * sp.asin(alpha)), (K1, _E1(1))),
                 change_of_variable=(phi, 2 * sp.asin(alpha * s), s), positive_radicands=True,
                 where=((alpha, 0, 1),), samples=1,
                 domain="four quarter swings, 0 < alpha = sin(theta_0/2) < 1",
                 mutant=8 * K1 / omega0, mutant_label=r"$8K_1/\omega_0$"),
        Identity("eq26_value", "(26)", 4 * K1 / omega0, 4 * K1 * sp.sqrt(ell / g),
                 given=((omega0, sp.sqrt(g / ell)),), mutant=4 * K1 * sp.sqrt(g / ell)),
        Identity("ratio_R", r"§4, $R(\theta_0)$", P_II / P_l, 2 * K1 / sp.pi,
                 given=((P_II, 4 * K1 / omega0), (P_l, 2 * sp.pi / omega0)),
                 mutant=sp.pi * K1 / 2),
        Identity("K1_at_0", r"§4, $K_1(+0)$", sp.elliptic_k(0, evaluate=False), sp.pi / 2,
                 mutant=sp.pi),
        Identity("partial_fractions", "§5", 1 / (1 - z**2),
                 (1 / (1 - z) + 1 / (1 + z)) / 2, mutant=(1 / (1 - z) - 1 / (1 + z)) / 2,
                 mutant_label="the note's printed difference"),
        Identity("log_antiderivative", "§5", D(sp.log((1 + z) / (1 - z)) / 2, z),
                 1 / (1 - z**2), mutant=2 / (1 - z**2)),
        Identity("eq27", "(27)", D(tanh, t), omega0 * (1 - tanh**2),
                 mutant=omega0 * (1 + tanh**2)),
        Identity("eq27_exp", "(27)", (sp.exp(2 * x) - 1) / (sp.exp(2 * x) + 1), sp.tanh(x),
                 given=((sp.tanh(x), (sp.exp(x) - sp.exp(-x)) / (sp.exp(x) + sp.exp(-x))),),
                 mutant=sp.tanh(2 * x)),
        Identity("eq13_to_27", "§5", dth / 2 * sp.cos(theta / 2),
                 omega0 * (1 - sp.sin(theta / 2) ** 2),
                 given=((dth, 2 * omega0 * sp.cos(theta / 2)),),
                 mutant=omega0 * (1 + sp.sin(theta / 2) ** 2)),
        Identity("eq28", "(28)", D(2 * sp.asin(tanh), t), 2 * omega0 * sp.cos(sp.asin(tanh)),
                 mutant=-2 * omega0 * sp.cos(sp.asin(tanh)),
                 mutant_label="the minus branch of (13)"),
        Identity("eq28_solves_eq3", "(28)", D(2 * sp.asin(tanh), (t, 2)),
                 -w2 * sp.sin(2 * sp.asin(tanh)), positive_radicands=True, domain="all t",
                 where=((t, -5, 5),), domain_md="all real $t$",
                 mutant=w2 * sp.sin(2 * sp.asin(tanh))),
        Identity("eq29", "(29)", 2 * w2 * sp.cos(theta) + c1, 2 * w2 * (sp.cos(theta) + beta),
                 given=((c1, 2 * w2 * beta),), mutant=2 * w2 * (sp.cos(theta) - beta)),
        Identity("eq30_half_angle", r"§6, $\gamma$", 2 * sp.cos(theta) + 2 * beta,
                 2 * beta + 2 - 4 * sp.sin(theta / 2) ** 2,
                 mutant=2 * beta + 2 - 2 * sp.sin(theta / 2) ** 2),
        Identity("eq30_gamma", r"§6, $\gamma$", sp.sqrt(2 * beta + 2 - 4 * sp.sin(theta / 2) ** 2),
                 2 / gamma * sp.sqrt(1 - gamma**2 * sp.sin(theta / 2) ** 2),
                 given=((beta, beta_of_gamma),), positive_radicands=True, domain="beta > 1",
                 where=((gamma, 0, 1), (theta, -sp.pi, sp.pi)),
                 mutant=2 * gamma * sp.sqrt(1 - gamma**2 * sp.sin(theta / 2) ** 2)),
        Identity("eq32", "(32)", D(H(0), t), D(2 * (omega0 * t / gamma + c4), t),
                 given=((dth, dth30),), mutant=D(omega0 * t / gamma + c4, t)),
        Identity("eq33", "(33)", (1 / sp.sqrt(1 - gamma**2 * sp.sin(phi / 2) ** 2)).subs(
                     phi, 2 * sp.asin(z)) * D(2 * sp.asin(z), z),
                 2 / sp.sqrt((1 - z**2) * (1 - gamma**2 * z**2)),
                 positive_radicands=True, domain="z = sin(phi/2), -pi < phi < pi", where=where_zg,
                 mutant=1 / sp.sqrt((1 - z**2) * (1 - gamma**2 * z**2))),
        Identity("eq34", "(34)", D(_E1(sp.sin(theta / 2), gamma), t), omega0 / gamma,
                 given=((dth, dth30), (sp.cos(theta / 2), sp.sqrt(1 - sp.sin(theta / 2) ** 2))),
                 positive_radicands=True, domain="-pi < theta < pi, cos(theta/2) > 0",
                 where=((theta, -sp.pi, sp.pi), (gamma, 0, 1)),
                 mutant=2 * omega0 / gamma),
        Identity("eq37", "(37)", D(H(2 * sp.pi), t), D(2 * (omega0 * t / gamma + c41), t),
                 given=((dth, dth30),), mutant=D(omega0 * t / gamma + c41, t)),
        Identity("eq38", "(38)", sp.sin(sp.Mul(sp.Rational(1, 2), theta - 2 * sp.pi,
                                               evaluate=False)),
                 -sp.sin(theta / 2), kind="arithmetic", mutant=sp.sin(theta / 2)),
        Identity("E1_odd", "(38)", D(_E1(z) + _E1(-z), z), sp.Integer(0),
                 mutant=2 * f_z, mutant_label=r"$2(E_1)_z$, as if $E_1$ were even"),
        Identity("eq35_solves_eq30", "(35), (41)", D(th35, t),
                 omega0 * sqrt30.subs(theta, th35), given=((beta, beta_of_gamma),),
                 positive_radicands=True, domain="|G| < 1, 0 < gamma < 1", where=where_Gg,
                 mutant=-omega0 * sqrt30.subs(theta, th35), mutant_label="the minus branch"),
        Identity("eq42", "(42)", D(I_, u), sp.sqrt(1 - gamma**2 * Gg**2),
                 positive_radicands=True, domain="|G| < 1", where=where_Gg,
                 mutant=1 / sp.sqrt(1 - gamma**2 * Gg**2)),
        Identity("eq42_at_K1", "(42)", sp.Subs(sp.sqrt(1 - gamma**2 * Gs**2), Gs, 1),
                 sp.sqrt(1 - gamma**2), kind="arithmetic", mutant=sp.Integer(0)),
        Identity("I_uu", r"§6, $I_{uu}$", D(sp.sqrt(1 - gamma**2 * Gg**2), u),
                 -gamma**2 * Gg * sp.sqrt(1 - Gg**2), positive_radicands=True, domain="|G| < 1",
                 where=where_Gg,
                 mutant=-gamma * Gg * sp.sqrt(1 - Gg**2)),
        Identity("I_uu_at_K1", r"§6, $I_{uu}(K_1 - 0) = 0$",
                 sp.Subs(-gamma**2 * Gs * sp.sqrt(1 - Gs**2), Gs, 1), sp.Integer(0),
                 kind="arithmetic", mutant=-gamma**2),
        Identity("eq43", "(43)",
                 D(sp.asin(G(u - 2 * n_int * K1, gamma)) + n_int * sp.pi, u),
                 sp.sqrt(1 - gamma**2 * ((-1) ** n_int * G(u - 2 * n_int * K1, gamma)) ** 2),
                 positive_radicands=True, domain="|G| < 1", where=where_Gg,
                 mutant=sp.sqrt(1 - gamma * G(u - 2 * n_int * K1, gamma) ** 2)),
        Identity("eq45", "(45)", In(u + 2 * K1) - tau_ * (u + 2 * K1), In(u) - tau_ * u,
                 given=((In(u + 2 * K1), In(u) + sp.pi), (tau_, sp.pi / (2 * K1))),
                 kind="arithmetic", mutant=In(u) - tau_ * u + sp.pi,
                 mutant_label=r"$\hat I(u) - \tau u + \pi$ (no period)"),
        Identity("tau_integrand", r"§6, $\tau$",
                 sp.sqrt(1 - gamma**2 * z**2) / sp.sqrt((1 - z**2) * (1 - gamma**2 * z**2)),
                 1 / sp.sqrt(1 - z**2), positive_radicands=True, domain=dom_z, where=where_zg,
                 mutant=1 / sp.sqrt(1 - gamma**2 * z**2)),
        Identity("tau", r"§6, $\tau$", sp.Integral(1 / sp.sqrt(1 - z**2), (z, 0, 1)) / K1,
                 sp.pi / (2 * K1), mutant=sp.pi / K1),
    ]


def identities() -> list[Identity]:
    r"""Return the note's correct statements, in the note's order, each with its mutant.

    Examples
    --------
    >>> ids = {e.name: e for e in identities()}
    >>> ids["eq23"].check(), ids["eq3"].check(), ids["tau"].check()
    (True, True, True)
    >>> ids["eq26"].mutant_identity().check()  # 8 K_1 / omega_0 is not the period
    False
    """
    return note_identities()


def identity(name: str) -> Identity:
    """Return the correct statement called ``name`` (see :func:`.identities` for the names).

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
