r"""The note's elliptic integrals and Jacobi's elliptic functions.

Conventions
-----------
**Modulus k, not parameter m.** Like the note (whose alpha and gamma are
moduli), DLMF chapters 19 and 22 and Boost, every function here takes the
modulus ``k``; scipy and mpmath take the parameter ``m = k**2``. Every function
also accepts the complementary modulus ``kc = sqrt(1 - k**2)`` by keyword and
trusts it over ``k``: near the separatrix k rounds to 1.0 while kc still holds
every digit of the energy.

========================  =========================  ==================================
note                      here                       scipy / mpmath
========================  =========================  ==================================
E1(z, alpha)   (17)       ``incomplete_integral``    ``ellipkinc(arcsin(z), m)``
K1(alpha)      (18)       ``complete_integral``      ``ellipk(m)``
G(u, alpha)    (19)       ``inverse_integral``       sn restricted to [-K, K]
G-bar(u, alpha)           ``sn``                     ``ellipj(u, m)[0]``
I-hat(u, gamma)           ``am``                     ``ellipj(u, m)[3]``
========================  =========================  ==================================

Method
------
sn, cn and dn use the descending Landen (Gauss) transformation in the form of
GSL's ``gsl_sf_elljac_e``, seeded with kc, after an exact reduction of u by
multiples of the quarter period K (K from a double-double AGM, split in three
parts). The recurrence is free of cancellation, so sn, cn and dn carry small
relative errors for every kc in [0, 1]; scipy's ``ellipj`` (Cephes) is not
usable for 1 - m <= 1e-10 (scipy issue 8480). The limits k = 0 (sin, cos, 1)
and kc = 0 (tanh, sech, sech) are handled first, explicitly. E1 uses Carlson's
R_F (DLMF 19.25.5) with 1 - k^2 z^2 written as (1 - z)(1 + z) + kc^2 z^2.
"""

from __future__ import annotations

# The integrals and the Jacobi functions are two subjects, each in a private module of its
# own; this module is their one public import path and the page that documents them
# (docs/api.md: autodoc follows __all__ here).
from ._integrals import complete_integral, incomplete_integral, inverse_integral
from ._jacobi_functions import am, cn, dn, jacobi, sn

__all__ = ["complete_integral", "incomplete_integral", "inverse_integral",
           "jacobi", "sn", "cn", "dn", "am"]
