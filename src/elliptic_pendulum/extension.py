"""Lemma 2 of the note as code: extending an odd function from [-a, a] to the real line.

The odd periodic extension (20) turns the restricted inverse G of E1 into sn; the odd staircase
extension (21) turns I = arcsin G into the amplitude am. The lemma's hypotheses
(f'(a-0) = 0 for (20), f''(a-0) = 0 for (21)) are what make the extensions smooth;
:func:`one_sided_derivatives` shows numerically what happens when they fail.

Both extensions reduce x to r = x - 2na with ``|r| <= a``. The reduction is exact for the given
float a (an error-free product, then a Sterbenz subtraction), so for ``|x|`` up to 1e4 a the
extension is as accurate as f itself; what remains is the error of a: n times the difference
between the float a and the true one. Pass ``a`` as a pair ``(hi, lo)`` with a = hi + lo to
remove that too.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ._engine.landen import _two_prod as _two_product  # Dekker's error-free product
from ._validation import refuse_masked

__all__ = ["periodic_extension", "staircase_extension", "one_sided_derivatives", "derivative_jump"]

def _validate(f, a):
    if not callable(f):
        raise TypeError(f"f must be a callable (a vectorized odd function on [-a, a]), got {f!r}")
    try:
        hi, lo = (float(a[0]), float(a[1])) if isinstance(a, tuple) else (float(a), 0.0)
    except (TypeError, ValueError, IndexError):
        raise TypeError(f"a must be a real number (or a pair (hi, lo)), got {a!r}") from None
    if not (np.isfinite(hi) and np.isfinite(lo) and hi > 0.0 and abs(lo) <= 1e-8 * hi):
        raise ValueError(f"a must be a finite number > 0 (or a pair (hi, lo) with hi > 0 and "
                         f"|lo| <= 1e-8 hi), got a = {a!r}")
    return hi, lo


def _reduce(x, hi, lo):
    """Split x = 2 n a + r with n integer and |r| <= a; return (n, r, finite mask)."""
    refuse_masked(x, "x")
    x = np.asarray(x, dtype=float)
    finite = np.isfinite(x)
    xs = np.where(finite, x, 0.0)  # f never sees inf or nan; those give nan below
    n = np.rint(xs / (2.0 * hi))
    p, e = _two_product(n, 2.0 * hi)
    # x - p is exact (Sterbenz: x, p within a factor 2 when n != 0); e is the product's error.
    r = ((xs - p) - e) - n * (2.0 * lo)
    # Rounding at a half-integer x/(2a) may leave r an ulp outside [-a, a], where f is undefined.
    return n, np.clip(r, -hi, hi), finite


def periodic_extension(f: Callable, a) -> Callable:
    r"""Extend an odd function on [-a, a] to an odd function of period 4a, the note's (20).

    .. math::

        \bar f(x) = \begin{cases} f(x) & -a \le x \le a \\ -f(x - 2a) & a \le x \le 3a
        \end{cases}, \qquad \bar f(x + 4a) = \bar f(x).

    Lemma 2.2: if f is C^2 on (-a, a) with f'(a-0) = 0 and f''(a-0) finite, then f-bar is C^2.
    Applied to G = E1^{-1} on [-K1, K1] it gives sn (the note's G-bar).

    Parameters
    ----------
    f : callable
        Vectorized odd function, called only with arguments in [-a, a].
    a : float or (float, float)
        Half-width a > 0, or a pair (hi, lo) with a = hi + lo for an exact reduction.

    Returns
    -------
    callable
        f-bar, vectorized: x array-like of any shape, nan where x is not finite.

    Raises
    ------
    TypeError
        If f is not callable.
    ValueError
        If a is not finite and > 0.

    Examples
    --------
    The extension of sin from [-pi/2, pi/2] is sin, and that of the identity is the triangle wave:

    >>> import numpy as np
    >>> x = np.linspace(-50.0, 50.0, 1001)
    >>> bool(np.allclose(periodic_extension(np.sin, np.pi / 2)(x), np.sin(x), atol=1e-13))
    True
    >>> tri = periodic_extension(lambda x: x, np.pi / 2)
    >>> bool(np.allclose(tri(x), np.arcsin(np.sin(x)), atol=1e-12))
    True
    """
    hi, lo = _validate(f, a)

    def fbar(x):
        n, r, finite = _reduce(x, hi, lo)
        # n odd: x lies in [a, 3a] modulo 4a, where (20) flips the sign.
        sign = np.where(np.remainder(n, 2.0) == 1.0, -1.0, 1.0)
        return np.where(finite, sign * np.asarray(f(r), dtype=float), np.nan)[()]

    return fbar


def staircase_extension(f: Callable, a) -> Callable:
    r"""Extend an odd function on [-a, a] by odd steps of height 2 f(a), the note's (21).

    .. math::

        \hat f(x) = f(x - 2ma) + 2m f(a) \qquad ((2m-1)a \le x \le (2m+1)a,\ m \in \mathbb Z).

    Lemma 2.3: if f is C^2 on (-a, a) with f'(a-0) finite and f''(a-0) = 0, then f-hat is C^2.
    Applied to I = arcsin G on [-K1, K1] it gives the amplitude am (the note's I-hat, (40)-(41)).

    Parameters
    ----------
    f : callable
        Vectorized odd function, called only with arguments in [-a, a].
    a : float or (float, float)
        Half-width a > 0, or a pair (hi, lo) with a = hi + lo.

    Returns
    -------
    callable
        f-hat, vectorized: nan where x is not finite.

    Raises
    ------
    TypeError
        If f is not callable.
    ValueError
        If a is not finite and > 0.

    Examples
    --------
    A straight line plus an odd 2a-periodic function is its own staircase extension:

    >>> import numpy as np
    >>> x = np.linspace(-40.0, 40.0, 801)
    >>> g = staircase_extension(lambda x: x + np.sin(x), np.pi)
    >>> bool(np.allclose(g(x), x + np.sin(x), atol=1e-12))
    True

    The extension is odd, as Lemma 2.3 claims:

    >>> h = staircase_extension(np.arctan, 1.0)
    >>> bool(np.allclose(h(-x), -h(x), atol=1e-13))
    True
    """
    hi, lo = _validate(f, a)
    # f(a) once, at the float a: the steps 2 m f(a) are then exactly consistent with f(r) at r = a.
    step = 2.0 * float(np.asarray(f(np.float64(hi))))

    def fhat(x):
        n, r, finite = _reduce(x, hi, lo)
        return np.where(finite, np.asarray(f(r), dtype=float) + n * step, np.nan)[()]

    return fhat


def one_sided_derivatives(g: Callable, x: float, order: int = 1, h: float | None = None):
    r"""Left and right one-sided difference quotients of g at x, of order 1 or 2.

    .. math::

        g'(x \mp 0) &\approx \pm\frac{3g(x) - 4g(x \mp h) + g(x \mp 2h)}{2h}, \\
        g''(x \mp 0) &\approx \frac{2g(x) - 5g(x \mp h) + 4g(x \mp 2h) - g(x \mp 3h)}{h^2}.

    Both are second-order accurate, and use values on one side of x only, so they see a kink (or a
    jump of g'') at x that a central quotient would average away. Lemma 2.1 says g is differentiable
    at x when the two one-sided limits agree.

    Parameters
    ----------
    g : callable
        Vectorized function of one real variable.
    x : float
        The point, e.g. a in the note's Lemma 2.
    order : {1, 2}
        Which derivative.
    h : float, optional
        Step; default eps**(1/3) (order 1) or eps**(1/4) (order 2), times ``max(1, |x|)``.

    Returns
    -------
    (float, float)
        The left and right quotients.

    Examples
    --------
    The periodic extension (20) of sin on [-1, 1] violates f'(a-0) = 0: it is continuous but has a
    corner at x = 1, where the slope jumps from cos 1 to -cos 1.

    >>> import numpy as np
    >>> left, right = one_sided_derivatives(periodic_extension(np.sin, 1.0), 1.0)
    >>> round(left, 6), round(right, 6), round(float(np.cos(1.0)), 6)
    (0.540302, -0.540302, 0.540302)
    """
    if order not in (1, 2):
        raise ValueError(f"order must be 1 or 2, got {order!r}")
    x = float(x)
    if h is None:
        h = np.finfo(float).eps ** (1.0 / 3.0 if order == 1 else 0.25) * max(1.0, abs(x))
    if not (np.isfinite(h) and h > 0.0):
        raise ValueError(f"h must be a finite number > 0, got h = {h!r}")
    out = []
    for s in (-1.0, 1.0):
        v = np.asarray(g(x + s * h * np.arange(4.0)), dtype=float)
        if order == 1:
            out.append(float(s * (-3.0 * v[0] + 4.0 * v[1] - v[2]) / (2.0 * h)))
        else:
            out.append(float((2.0 * v[0] - 5.0 * v[1] + 4.0 * v[2] - v[3]) / h**2))
    return out[0], out[1]


def derivative_jump(g: Callable, x: float, order: int = 1, h: float | None = None) -> float:
    r"""Return g^{(order)}(x+0) - g^{(order)}(x-0), estimated by :func:`one_sided_derivatives`.

    .. math:: J = g^{(k)}(x + 0) - g^{(k)}(x - 0)

    Examples
    --------
    The staircase extension (21) of x + sin x on [-pi/2, pi/2] violates f''(a-0) = 0 (it is
    -sin(pi/2) = -1): it is C^1, but f-hat'' jumps by 2 at a = pi/2.

    >>> import numpy as np
    >>> g = staircase_extension(lambda x: x + np.sin(x), np.pi / 2)
    >>> abs(derivative_jump(g, np.pi / 2)) < 1e-8
    True
    >>> round(derivative_jump(g, np.pi / 2, order=2), 5)
    2.0
    """
    left, right = one_sided_derivatives(g, x, order=order, h=h)
    return right - left
