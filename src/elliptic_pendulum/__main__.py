"""``python -m elliptic_pendulum``: see :mod:`elliptic_pendulum.cli`."""

from .cli import main

raise SystemExit(main())
