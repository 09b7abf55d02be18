"""Where the note prints something other than what it means, each with the check that finds it.

Every :class:`Erratum` pairs the statement as printed (an
:class:`~elliptic_pendulum.checks.symbolic.Identity` whose check fails, when the printed text is an
equation) with the corrected one (whose check holds).
The book's page "Notes on the original" and ``tests/checks/test_symbolic.py`` iterate over
the same list.
Like :mod:`elliptic_pendulum.checks.symbolic`, this module imports sympy only.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from .identities import identity
from .symbolic import Identity, alpha, c1, dth, omega0, t, theta, theta0, z

__all__ = ["Erratum", "printed_errata"]


@dataclass(frozen=True)
class Erratum:
    """A place where the note prints something other than what it means.

    ``printed`` is the statement as printed (its check fails) or None when the printed text is
    not an equation sympy can refute; ``corrected`` is the statement that holds (its check
    succeeds, and it carries a mutant that fails).
    """

    location: str
    kind: str  # "error" (wrong mathematics), "typo" (wrong symbol), "notation", "statement"
    printed_text: str
    corrected_text: str
    printed: Identity | None
    corrected: Identity | None
    comment: str = ""


def printed_errata() -> list[Erratum]:
    r"""Return the places where the note prints something other than what it means.

    Each erratum's ``printed`` statement (when the printed text is an equation that can be
    refuted) fails its check and its ``corrected`` statement passes, and rejects its mutant.
    ``kind`` says how serious it is: "error" (wrong mathematics that the note does not use
    further), "typo" (a wrong symbol), "notation", "statement" (a remark that is true of a
    different equation) and "transcription" (an artefact of the text copy).

    We read the note in a text copy of the PDF. Its slips of a symbol or a square (omega, w_0,
    (1 + alpha)^2) may be the copy's rather than the author's; the comments say so.

    Examples
    --------
    >>> errata = printed_errata()
    >>> [e.printed.check() for e in errata if e.printed is not None]
    [False, False]
    >>> all(e.corrected.check() for e in errata if e.corrected is not None)
    True
    """
    w2 = omega0**2
    th_p = 2 * omega0 * sp.cos(theta / 2)  # (13), plus branch
    maybe_copy = " The text copy may have introduced it; the PDF would tell."
    # A symbol such as omega, which the note never defines, cannot be refuted: an undefined
    # symbol is not wrong, only unexplained. Those entries carry the corrected statement only.
    return [
        Erratum(
            "§2, (1)", "statement",
            r"\mathbf{T} \text{ the rod's pull}, \quad T = |\mathbf{T}|",
            r"\mathbf{T} = T\,(-\sin\theta, \cos\theta), \quad T \text{ the signed component}",
            None, None,
            "A magnitude is never negative, yet a rod also pushes, and the note, like the book, "
            "finds T < 0 for large swings. (1) itself, (4) and everything after use T as the "
            "signed component along the unit vector towards the pivot, so no result changes.",
        ),
        Erratum(
            "§3, case III, before (13)", "typo",
            r"(\theta')^2 = 2\omega^2(\cos\theta + 1) = 4\omega^2\cos^2\frac{\theta}{2}",
            r"(\theta')^2 = 2\omega_0^2(\cos\theta + 1) = 4\omega_0^2\cos^2\frac{\theta}{2}",
            None,
            Identity("case_III", "§3, case III", 2 * w2 * sp.cos(theta) + c1,
                     2 * w2 * (sp.cos(theta) + 1), given=((c1, 2 * w2),),
                     mutant=2 * w2 * (sp.cos(theta) - 1),
                     mutant_label=r"case I's $2\omega_0^2(\cos\theta - 1)$"),
            "omega for omega_0, a symbol the note does not define; (13) itself is right."
            + maybe_copy,
        ),
        Erratum(
            "Lemma 2, parts 2 and 3", "statement",
            r"f \text{ odd on } [-a, a],\ C^2 \text{ on } (-a, a),\ f'(a - 0) = 0,\ "
            r"f''(a - 0) = B \;\Rightarrow\; \bar f \in C^2",
            r"f \text{ odd and continuous on the closed } [-a, a],\ C^2 \text{ on } (-a, a),"
            r"\ \ldots \;\Rightarrow\; \bar f \in C^2",
            None, None,
            "Without continuity at the end points the lemma is false: f = sin(pi x / (2a)) on "
            "(-a, a) with f(+-a) = +-5 is odd, C^2 inside, f'(a - 0) = 0, yet its extension "
            "(20) jumps at x = a; likewise for (21). Part 1 of the lemma needs f continuous at "
            "a. The note applies the lemma to G, which is continuous on [-K_1, K_1], so its "
            "results stand.",
        ),
        Erratum(
            "§4, after (23)", "error",
            r"G_{uu}(K_1(\alpha) - 0, \alpha) = -(1 + \alpha)^2 + 2\alpha^2 = \alpha^2 - 1",
            r"G_{uu}(K_1(\alpha) - 0, \alpha) = -(1 + \alpha^2) + 2\alpha^2 = \alpha^2 - 1",
            Identity("eq23_at_K1_printed", "§4, after (23)", -((1 + alpha) ** 2) + 2 * alpha**2,
                     alpha**2 - 1),
            identity("eq23_at_K1"),
            "The square is misplaced: -(1 + alpha)^2 + 2 alpha^2 = alpha^2 - 2 alpha - 1. Setting "
            "G = 1 in (23) gives -(1 + alpha^2) + 2 alpha^2; the final value alpha^2 - 1 is right."
            + maybe_copy,
        ),
        Erratum(
            "§4, after (23)", "notation",
            r"G(u, \alpha) \text{ is } C^2", r"\bar G(u, \alpha) \text{ is } C^2", None, None,
            "Lemma 2.2 makes the extension G-bar C^2; G lives on [-K_1, K_1] only.",
        ),
        Erratum(
            "§4, after (25)", "statement",
            r"\xi = \pm 1 \text{ is not a solution, so (25) is the general solution of (12)}",
            r"\text{(3) has unique solutions: every solution of (3) with this energy is (25)} "
            r"+ 2n\pi",
            None,
            Identity("theta0_solves_eq12", "§4, after (25)", sp.Derivative(theta0, t) ** 2,
                     2 * w2 * sp.Add(sp.cos(theta0), -sp.cos(theta0), evaluate=False),
                     mutant=2 * w2 * (1 - sp.cos(theta0)),
                     mutant_label=r"(12) at $\theta = 0$, $2\omega_0^2(1 - \cos\theta_0)$"),
            "The constants theta = +-theta_0 (xi = +-1) satisfy the first-order (12), whose right "
            "side has a simple zero there, and so do swings that rest at theta_0 for a while "
            "and then fall back: (12) has solutions that are not (25). None of them satisfies "
            "(3), since theta'' = 0 at rest while sin(theta_0) != 0. (3) has a Lipschitz right "
            "side, so its solutions are unique, and those with energy c_1 are the (25) and "
            "their translates by 2 n pi. The note gives (14) as the reason; it is (3).",
        ),
        Erratum(
            "§6", "statement",
            r"\hat I \text{ is smooth}",
            r"\hat I \text{ is } C^2 \text{ (Lemma 2.3); analytic, by the theory of sn}",
            None, None,
            "§4 hedges ('smooth, at least C^2') and Lemma 2 proves C^2; §6 drops the hedge and "
            "calls I-hat smooth, which is true (it is analytic, a property of sn the note "
            "quotes) but is not what Lemma 2.3 shows.",
        ),
        Erratum(
            "(26)", "notation", r"4K\left(\sin\frac{\theta_0}{2}\right)\sqrt{\ell/g}",
            r"4K_1\left(\sin\frac{\theta_0}{2}\right)\sqrt{\ell/g}", None, None,
            "K for the note's K_1 (the usual name elsewhere).",
        ),
        Erratum(
            "§4, after (26)", "transcription", r"\theta_0 \div 0", r"\theta_0 \fallingdotseq 0",
            None, None, "The text copy renders the Japanese 'approximately equal' sign as a "
            "division sign here; before (5) it shows the approximate-equality sign itself.",
        ),
        Erratum(
            "§5, before (27)", "typo",
            r"z' = \frac{\theta'}{2}\cos\frac{\theta}{2} = w_0\cos^2\frac{\theta}{2}",
            r"z' = \frac{\theta'}{2}\cos\frac{\theta}{2} = \omega_0\cos^2\frac{\theta}{2}",
            None,
            Identity("eq13_to_27_middle", "§5", dth / 2 * sp.cos(theta / 2),
                     omega0 * sp.cos(theta / 2) ** 2, given=((dth, th_p),),
                     mutant=omega0 * sp.cos(theta / 2),
                     mutant_label=r"$\omega_0\cos\frac{\theta}{2}$"),
            "w_0 for omega_0, a symbol the note does not define." + maybe_copy,
        ),
        Erratum(
            "§5, before (27)", "statement",
            r"z = \pm 1 \text{ are singular solutions; the general solution is the rest}",
            r"z = \pm 1 \text{ are singular, and are motions: the equilibrium } \theta = \pi "
            r"\text{ (mod } 2\pi\text{) belongs to regime III}",
            None, None,
            "Under the usual definition (a solution outside the general solution) z = +-1 are "
            "singular solutions, as the note says. What matters is what discarding them drops: "
            "they are the equilibrium upside down, a motion of (3) of energy 2 omega_0^2 like "
            "the separatrix, so regime III is (28) and its translates by 2 n pi together with "
            "theta = pi (mod 2 pi)."
        ),
        Erratum(
            "§5, between (13) and (27)", "error",
            r"\frac{1}{1 - z^2} = \frac{1}{2}\left(\frac{1}{1 - z} - \frac{1}{1 + z}\right)",
            r"\frac{1}{1 - z^2} = \frac{1}{2}\left(\frac{1}{1 - z} + \frac{1}{1 + z}\right)",
            Identity("partial_fractions_printed", "§5", 1 / (1 - z**2),
                     (1 / (1 - z) - 1 / (1 + z)) / 2),
            identity("partial_fractions"),
            "The printed right side is z/(1 - z^2). The antiderivative the note writes next, "
            "(1/2) log|(1 + z)/(1 - z)|, is that of the corrected sum, so (27) is right.",
        ),
    ]
