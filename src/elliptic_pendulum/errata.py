"""Where the note prints something other than what it means, each with the check that finds it.

Every :class:`Erratum` pairs the statement as printed (an
:class:`~elliptic_pendulum.symbolic.Identity` whose check fails, when the printed text is an
equation) with the corrected one (whose check holds).
The book's page "Notes on the original" and ``tests/test_symbolic.py`` iterate over the same list.
Like :mod:`elliptic_pendulum.symbolic`, this module imports sympy only.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from .symbolic import Identity, alpha, c1, dth, omega0, t, theta, theta0, z

__all__ = ["Erratum", "printed_errata"]


@dataclass(frozen=True)
class Erratum:
    """A place where the note prints something other than what it means.

    ``printed`` is the statement as printed (its check fails) or None when the printed text is
    not an equation; ``corrected`` is the statement that holds (its check succeeds).
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

    Each erratum's ``printed`` statement (when the printed text is an equation) fails its check and
    its ``corrected`` statement passes. ``kind`` says how serious it is: "error" (wrong mathematics
    that the note does not use further), "typo" (a wrong symbol), "notation", "statement" (a remark
    that is true of a different equation) and "transcription" (an artefact of the text copy).

    Examples
    --------
    >>> errata = printed_errata()
    >>> [e.printed.check() for e in errata if e.printed is not None]
    [False, False, False, False]
    >>> all(e.corrected.check() for e in errata if e.corrected is not None)
    True
    """
    w2 = omega0**2
    omega, w_0 = sp.symbols("omega w_0", positive=True)  # the printed, undefined symbols
    th_p = 2 * omega0 * sp.cos(theta / 2)  # (13), plus branch
    const = sp.Derivative(theta0, t)
    return [
        Erratum(
            "§3, case III, before (13)", "typo",
            r"(\theta')^2 = 2\omega^2(\cos\theta + 1) = 4\omega^2\cos^2\frac{\theta}{2}",
            r"(\theta')^2 = 2\omega_0^2(\cos\theta + 1) = 4\omega_0^2\cos^2\frac{\theta}{2}",
            Identity("case_III_printed", "§3, case III", 2 * w2 * sp.cos(theta) + c1,
                     2 * omega**2 * (sp.cos(theta) + 1), given=((c1, 2 * w2),)),
            Identity("case_III", "§3, case III", 2 * w2 * sp.cos(theta) + c1,
                     2 * w2 * (sp.cos(theta) + 1), given=((c1, 2 * w2),)),
            "omega for omega_0; (13) itself is right.",
        ),
        Erratum(
            "§4, after (23)", "error",
            r"G_{uu}(K_1(\alpha) - 0, \alpha) = -(1 + \alpha)^2 + 2\alpha^2 = \alpha^2 - 1",
            r"G_{uu}(K_1(\alpha) - 0, \alpha) = -(1 + \alpha^2) + 2\alpha^2 = \alpha^2 - 1",
            Identity("eq23_at_K1_printed", "§4, after (23)", -((1 + alpha) ** 2) + 2 * alpha**2,
                     alpha**2 - 1),
            Identity("eq23_at_K1", "§4, after (23)", -(1 + alpha**2) + 2 * alpha**2, alpha**2 - 1),
            "The square is misplaced: -(1 + alpha)^2 + 2 alpha^2 = alpha^2 - 2 alpha - 1. Setting "
            "G = 1 in (23) gives -(1 + alpha^2) + 2 alpha^2; the final value alpha^2 - 1 is right.",
        ),
        Erratum(
            "§4, after (23)", "notation",
            r"G(u, \alpha) \text{ is } C^2", r"\bar G(u, \alpha) \text{ is } C^2", None, None,
            "Lemma 2.2 makes the extension G-bar C^2; G lives on [-K_1, K_1] only.",
        ),
        Erratum(
            "§4, after (25)", "statement",
            r"\xi = \pm 1 \text{ is not a solution, so (25) is the general solution of (12)}",
            r"\theta \equiv \pm\theta_0 \text{ solves (12) but not (3): (25) is the general "
            r"solution of (3)}",
            None,
            Identity("theta0_solves_eq12", "§4, after (25)", const**2,
                     2 * w2 * (sp.cos(theta0) - sp.cos(theta0))),
            "The constants theta = +-theta_0 (xi = +-1) satisfy the first-order (12), where the "
            "right side has a simple zero (and (12) then has non-unique solutions that rest at "
            "theta_0 for a while); they do not satisfy (3), since sin(theta_0) != 0.",
        ),
        Erratum(
            "(26)", "notation", r"4K\left(\sin\frac{\theta_0}{2}\right)\sqrt{\ell/g}",
            r"4K_1\left(\sin\frac{\theta_0}{2}\right)\sqrt{\ell/g}", None, None,
            "K for the note's K_1 (the usual name elsewhere).",
        ),
        Erratum(
            "§4, after (26)", "transcription", r"\theta_0 \div 0", r"\theta_0 \fallingdotseq 0",
            None, None, "The text copy renders the Japanese 'approximately equal' sign as a "
            "division sign (likewise the small-angle sign before (5)).",
        ),
        Erratum(
            "§5, before (27)", "typo",
            r"z' = \frac{\theta'}{2}\cos\frac{\theta}{2} = w_0\cos^2\frac{\theta}{2}",
            r"z' = \frac{\theta'}{2}\cos\frac{\theta}{2} = \omega_0\cos^2\frac{\theta}{2}",
            Identity("eq13_to_27_printed", "§5", dth / 2 * sp.cos(theta / 2),
                     w_0 * sp.cos(theta / 2) ** 2, given=((dth, th_p),)),
            Identity("eq13_to_27_middle", "§5", dth / 2 * sp.cos(theta / 2),
                     omega0 * sp.cos(theta / 2) ** 2, given=((dth, th_p),)),
            "w_0 for omega_0.",
        ),
        Erratum(
            "§5, between (13) and (27)", "error",
            r"\frac{1}{1 - z^2} = \frac{1}{2}\left(\frac{1}{1 - z} - \frac{1}{1 + z}\right)",
            r"\frac{1}{1 - z^2} = \frac{1}{2}\left(\frac{1}{1 - z} + \frac{1}{1 + z}\right)",
            Identity("partial_fractions_printed", "§5", 1 / (1 - z**2),
                     (1 / (1 - z) - 1 / (1 + z)) / 2),
            Identity("partial_fractions", "§5", 1 / (1 - z**2), (1 / (1 - z) + 1 / (1 + z)) / 2),
            "The printed right side is z/(1 - z^2). The antiderivative the note writes next, "
            "(1/2) log|(1 + z)/(1 - z)|, is that of the corrected sum, so (27) is right.",
        ),
        Erratum(
            "(41)", "notation",
            r"\theta(t) = 2\hat I\left(\frac{\omega_0 t}{\gamma} + c_{4,1}, \gamma\right)",
            r"\theta(t) = 2\hat I\left(\frac{\omega_0 t}{\gamma} + c_{4,0}, \gamma\right)",
            None, None,
            "Joining (35) and (39) into one motion forces c_{4,1} = c_{4,0} - 2 K_1(gamma); since "
            "I-hat(u - 2 K_1) = I-hat(u) - pi, the printed constant gives the same motion lowered "
            "by 2 pi, which is also a solution of (3).",
        ),
    ]
