"""The repository's build tools: not part of the installed package, run from the root.

* :mod:`tools.classroom` -- the book's pages as classroom notebooks (``python -m tools.classroom``);
* :mod:`tools.pdf` -- the book as PDF, printed by headless Chromium (``python -m tools.pdf``);
* :mod:`tools.figures` -- the README's figure, screenshots of notebooks.
"""
