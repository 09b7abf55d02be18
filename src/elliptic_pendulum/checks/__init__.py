"""The book's checks: the note's statements in sympy, its errata, and the registry of claims.

* :mod:`.symbolic` -- the note's symbols and :class:`~.symbolic.Identity`, a checkable statement;
* :mod:`.identities` -- the note's correct statements (1)-(46), each with its mutant;
* :mod:`.errata` -- where the print says something other than what it means;
* :mod:`.verify` -- the three kinds of check a page runs (identity, numeric, fact) and verdicts;
* :mod:`.registry` -- which claim of the note each check backs.

Nothing here imports the numerical part of the package (a contract in pyproject.toml): a
check compares the library with something independent of it, never with itself.
"""
