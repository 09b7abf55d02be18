"""Input checks shared by the public functions.

Every public function turns its arguments into float arrays here, so that a
bad argument is reported once, in words a student can act on, and never
travels on as a silent NaN.

Masked arrays (``numpy.ma``) are refused with a TypeError naming the parameter:
``np.asarray`` would drop the mask and compute the masked entries as if they
were data, and what a mask should mean for a Motion or a tuple of results is not
numpy's to say. Pass ``x.filled(value)`` or ``x.compressed()`` instead.
"""

from __future__ import annotations

import math
import numbers
from typing import Any

import numpy as np
import numpy.typing as npt

from ._engine import landen as _landen

__all__ = ["FloatOrArray", "real_array", "real_scalar", "modulus_pair", "positive_array",
           "positive_scalar", "refuse_masked", "scalar_or_array"]

#: What a public function returns: a Python float for scalar input, else a float array of
#: the broadcast shape (see :func:`scalar_or_array`).
FloatOrArray = float | npt.NDArray[np.float64]


_BEYOND_DOUBLES = "must be finite (a number within the range of doubles)"


def _masked(value: Any) -> bool:
    """Tell whether value is a masked array, or a list or tuple holding one (or np.ma.masked)."""
    if isinstance(value, np.ma.MaskedArray):
        return True
    return isinstance(value, (list, tuple)) and any(_masked(item) for item in value)


def refuse_masked(value: Any, name: str) -> None:
    """Raise TypeError naming ``name`` if ``value`` is (or holds) a masked array."""
    if _masked(value):
        raise TypeError(f"{name} must not be a masked array (numpy.ma): its mask would be "
                        f"ignored; pass {name}.filled(value) or {name}.compressed() instead")


def real_array(value: Any, name: str) -> np.ndarray:
    """Return ``value`` as a finite float array, or raise naming ``name``.

    Booleans, strings, complex numbers and None are refused with TypeError
    (``True`` as a time or an angle is almost always a mistake); NaN and
    infinities with ValueError; masked arrays with TypeError (see the module).
    """
    refuse_masked(value, name)
    if isinstance(value, (bool, np.bool_, str, bytes)) or value is None:
        raise TypeError(f"{name} must be a real number or an array of real numbers, "
                        f"got {type(value).__name__}")
    try:
        arr = np.asarray(value)
    except OverflowError as exc:  # a Python int beyond the range of doubles
        raise ValueError(f"{name} {_BEYOND_DOUBLES}") from exc
    except Exception as exc:  # ragged sequences and the like
        raise TypeError(f"{name} must be a real number or an array of real numbers") from exc
    if arr.dtype.kind == "O":
        # Decimal, Fraction, mpmath.mpf: accept what converts to float.
        try:
            arr = arr.astype(float)
        except OverflowError as exc:
            raise ValueError(f"{name} {_BEYOND_DOUBLES}") from exc
        except (TypeError, ValueError) as exc:
            raise TypeError(f"{name} must be a real number or an array of real numbers, "
                            f"got {type(value).__name__}") from exc
    if arr.dtype.kind not in "iuf":
        raise TypeError(f"{name} must be a real number or an array of real numbers, "
                        f"got values of dtype {arr.dtype}")
    arr = arr.astype(float, copy=False)
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite (no NaN or infinity)")
    return arr


def real_scalar(value: Any, name: str) -> float:
    """Return ``value`` as one finite float; an array is refused with TypeError naming ``name``."""
    array = real_array(value, name)
    if array.ndim != 0:
        raise TypeError(f"{name} must be a single real number (one initial state), "
                        f"got an array of shape {array.shape}; call once per state")
    return float(array)


def modulus_pair(k: Any, kc: Any = None,
                 beyond_one: bool = False) -> tuple[np.ndarray, np.ndarray, Any]:
    """Return (|k|, kc, kc_lo) as arrays, k checked to lie in [-1, 1] and kc in [0, 1].

    Everything here is even in k (it enters through k**2), so a negative k is taken as
    |k|. With ``beyond_one`` (the Jacobi functions) |k| > 1 is let through, and its kc is
    0: the caller uses the reciprocal modulus (DLMF 22.17). When ``kc`` is given it is
    trusted over ``k``, and taken as exact (kc_lo = 0): near the separatrix k rounds to 1.0
    while kc = sqrt(1 - k^2) still holds every digit, so only kc drives the algorithms that
    are sensitive there. k and kc given as arrays must have one shape. From ``k`` alone, kc
    is formed as a double-double (hi, lo).
    """
    if kc is None:
        k = np.abs(real_array(k, "k"))
        if not beyond_one and np.any(k > 1):
            raise ValueError("k (the modulus) must lie in [-1, 1] here (the value is even in "
                             "k, so [0, 1] in effect): for |k| > 1 it is complex")
        kc_hi, kc_lo = _landen.complement(np.minimum(k, 1.0))
        return k, kc_hi, kc_lo
    kc = real_array(kc, "kc")
    if np.any((kc < 0) | (kc > 1)):
        raise ValueError("kc (the complementary modulus sqrt(1 - k**2)) must lie in [0, 1]")
    if k is None:
        k = np.sqrt((1.0 - kc) * (1.0 + kc))
    else:
        k = np.abs(real_array(k, "k"))
        if np.any(k > 1):
            raise ValueError("k (the modulus) must lie in [-1, 1] when kc is given "
                             "(kc = sqrt(1 - k**2) is real only there)")
        if k.ndim and kc.ndim and k.shape != kc.shape:
            raise ValueError(f"k and kc must have the same shape (or k be a single number, "
                             f"since kc is trusted over it); got {k.shape} and {kc.shape}")
    return k, kc, 0.0


def positive_scalar(value: Any, name: str) -> float:
    """Return ``value`` as a finite float > 0, or raise naming ``name``."""
    refuse_masked(value, name)
    if not isinstance(value, numbers.Real) or isinstance(value, bool):
        if not (isinstance(value, np.ndarray) and value.ndim == 0):
            raise TypeError(f"{name} must be a real number, got {type(value).__name__}")
    try:
        x = float(value)
    except OverflowError:
        x = math.inf
    if not np.isfinite(x) or x <= 0:
        raise ValueError(f"{name} must be a finite number > 0, got {x!r}")
    return x


def positive_array(value: Any, name: str) -> np.ndarray:
    """Return ``value`` as a float array of finite numbers > 0, or raise naming ``name``."""
    try:
        array = real_array(value, name)
    except ValueError:
        raise ValueError(f"{name} must be a finite number > 0, got {value!r}") from None
    if not np.all(array > 0):
        bad = array[~(array > 0)].ravel()[0] if array.ndim else float(array)
        raise ValueError(f"{name} must be a finite number > 0, got {float(bad)!r}")
    return array


def scalar_or_array(result: Any, *inputs: Any) -> Any:
    """Return a Python float when every input was a scalar, else the array.

    Python floats print as ``1.0`` under NumPy 2 (not ``np.float64(1.0)``),
    which keeps doctests and the book's glued numbers plain.
    """
    if all(np.ndim(x) == 0 for x in inputs):
        return float(result)
    return result
