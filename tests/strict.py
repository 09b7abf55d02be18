"""Run a call as strictly as the library promises to behave: silent under any caller's settings.

Every floating-point event (``np.errstate(all="raise")``) and every warning (``-W error``) is
an error inside :func:`quietly`; both settings are restored on the way out.
"""

from __future__ import annotations

import warnings

import numpy as np


def quietly(f, *args, **kwargs):
    """Call ``f(*args, **kwargs)`` with every floating-point trap and every warning an error."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with np.errstate(all="raise"):
            return f(*args, **kwargs)
