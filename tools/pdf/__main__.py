"""``python -m tools.pdf book book/_build``: both editions of the book as PDF."""

import sys

from .build import main

sys.exit(main())
