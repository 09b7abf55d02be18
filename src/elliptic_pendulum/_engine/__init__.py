"""The engine: initial states to the motion theta(t), in double and double-double arithmetic.

Private: nothing here is public API, and nothing here imports from the rest of the package
(an import-linter contract in pyproject.toml keeps it so). NumPy and scipy.special only, and
mpmath, in a private context, for the rare states beyond the double-double range.

Modules, from the bottom up (the design note of the reference site gives the invariants):

* :mod:`.dd` -- double-double arithmetic (error-free sums and products, sqrt, sin/cos);
* :mod:`.levels` -- one level of that AGM, on floats and in place on arrays;
* :mod:`.ends` -- its two ends on arrays, in place: kc from k, and K from M;
* :mod:`.agm` -- the AGM / descending Landen constants (K in double-double, the levels);
* :mod:`.landen` -- the Jacobi kernel on them;
* :mod:`.careful` -- that kernel in double-double arithmetic, for kc below 1/16;
* :mod:`.quarter` -- K alone, in double precision, for many moduli at once;
* :mod:`.jacobi` -- the edges of the Jacobi functions (k = 0, kc = 0, k > 1);
* :mod:`.codes` -- the integer code of each regime;
* :mod:`.classify` and :mod:`.farstates` -- initial states to regime, modulus and phase;
* :mod:`.remainder` -- the phase's remainder in double-double, where theta crosses 0;
* :mod:`.params` -- what the evaluation keeps per state;
* :mod:`.flow` -- theta(t) and theta'(t) from those parameters, in chunks;
* :mod:`.redo` -- theta near 0 evaluated again from the argument itself;
* :mod:`.states` -- arrays of states, in chunks, to the parameters a Motion keeps.

Each kernel has a twin on Python floats, ``<name>_float``, right below it in its module: the
same operations in the same order, for one number at a time, to the bit (a NumPy call on one
number costs a microsecond of dispatch).
"""
