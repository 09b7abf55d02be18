"""The claims of the note that the registry tracks, and those whose status is not a computation.

Data for :mod:`.registry` (which re-exports it): each entry of :data:`STATUS`
is a definition or a claim proved in the text only, with a one-line justification.
"""

from __future__ import annotations

__all__ = ["CLAIMS", "KINDS", "STATUS"]

#: The claims a reader of the note can point at: its 46 numbered equations, the parts of
#: Proposition 1 and Lemma 2, the table of R(theta_0) and the three crossing angles.
CLAIMS: tuple[str, ...] = (
    *(f"({n})" for n in range(1, 47)),
    *(f"Proposition 1.{i}" for i in (1, 2, 3)),
    *(f"Lemma 2.{i}" for i in (1, 2, 3)),
    "R table",
    "crossing angles",
)

KINDS = ("sympy identity", "independent numerical check", "numerical fact",
         "proof in the text only", "definition")

#: Claims whose status is not a computation, with why (kind, justification).
STATUS: dict[str, tuple[str, str]] = {
    "(1)": ("definition", "the bob's position and the rod's pull, read off the figure"),
    "(2)": ("definition", "Newton's second law for the bob: the model itself"),
    "(5)": ("definition", "the small-angle model sin(theta) ~ theta, an approximation of (3)"),
    "(6)": ("definition", "names omega_0 = sqrt(g / l)"),
    "(11)": ("definition", "names theta_0 by cos(theta_0) = -c_1 / (2 omega_0^2)"),
    "(14)": ("definition", "names xi = sin(theta/2) / alpha"),
    "(17)": ("definition", "names E_1, the incomplete elliptic integral"),
    "(18)": ("definition", "names K_1 = E_1(1)"),
    "(19)": ("definition", "names G, the inverse of E_1"),
    "(20)": ("definition", "the periodic extension f-bar of Lemma 2.2"),
    "(21)": ("definition", "the staircase extension f-hat of Lemma 2.3"),
    "(24)": ("proof in the text only",
             "that every solution of (3) with this energy is (25), so its xi is (24): "
             "uniqueness for (3); the constants xi = +-1 solve (15) but not (3)"),
    "(31)": ("definition", "names H_0, an integral"),
    "(36)": ("definition", "names H_1, an integral"),
    "(40)": ("definition", "names I = arcsin G"),
    "(46)": ("proof in the text only",
             "that every rotation is +-2 I-hat(omega_0 t / gamma + c_4): uniqueness for (3)"),
    "Lemma 2.1": ("proof in the text only", "the mean value theorem; a statement about all f"),
}
