"""``python -m tools.classroom book notebooks [--execute | --glue-from DIR]``."""

import sys

from .export import main

sys.exit(main())
