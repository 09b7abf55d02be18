"""The edges of the modulus: k > 1, negative k, k and kc of different shapes.

References: mpmath's ellipfun and ellipk (which take the parameter m = k**2 and accept m > 1),
at 40 digits; DLMF 22.17 (reciprocal modulus), DLMF 19.2.8 (K even in k).
"""

import math

import mpmath
import numpy as np
import pytest

import elliptic_pendulum as ep
from tests import mpref


@pytest.mark.parametrize("k", [1.0000001, 1.1, 1.5, 3.0, 40.0])
def test_modulus_above_one_matches_mpmath(k):
    # DLMF 22.17.2-4: sn(u, k) = sn(k u, 1/k) / k, cn(u, k) = dn(k u, 1/k),
    # dn(u, k) = cn(k u, 1/k). mpmath evaluates m = k^2 > 1 directly.
    u = np.linspace(-30.0, 30.0, 41) / k + 0.123
    s, c, d = ep.jacobi(u, k)
    with mpmath.workdps(40):
        ref = mpref.jacobi(u, mpmath.mpf(k) ** 2, 40)  # mpmath takes m = k^2 > 1 directly
    for ours, exact in zip((s, c, d), ref, strict=True):
        np.testing.assert_allclose(ours, exact, rtol=0, atol=2e-15)
    # am(u, k) is bounded for k > 1, sin am = sn and cos am = cn
    a = ep.am(u, k)
    assert np.all(np.abs(a) <= math.pi / 2)
    np.testing.assert_allclose(np.sin(a), s, atol=1e-15)
    np.testing.assert_allclose(np.cos(a), c, atol=1e-15)
    # the mutant "sn(u, k) = sn(u, 1/k)" is off by far more than the tolerance
    assert np.max(np.abs(ep.sn(u, 1 / k) - np.array(ref[0]))) > 1e-9


def test_negative_modulus_is_the_positive_one():
    # K and the Jacobi functions depend on k through k^2 (DLMF 19.2.8, 22.2.4).
    for k in (0.3, 0.999, 1.0):
        assert ep.complete_integral(-k) == ep.complete_integral(k)
        assert ep.sn(1.3, -k) == ep.sn(1.3, k) and ep.am(2.0, -k) == ep.am(2.0, k)
    assert ep.incomplete_integral(0.4, -0.5) == ep.incomplete_integral(0.4, 0.5)
    with mpmath.workdps(40):
        exact = float(mpmath.ellipk(mpmath.mpf(-0.7) ** 2))
    assert abs(ep.complete_integral(-0.7) - exact) <= 2 * math.ulp(exact)


def test_mismatched_k_and_kc_shapes_are_refused():
    with pytest.raises(ValueError, match=r"\bk\b and \bkc\b"):
        ep.sn(0.3, np.array([0.5, 0.6]), kc=np.array([0.8, 0.7, 0.6]))
    # a single k beside an array kc is fine (kc is trusted over k)
    assert ep.sn(0.3, 1.0, kc=np.array([0.8, 0.6])).shape == (2,)
    assert ep.sn(0.3, np.array([0.6, 0.8]), kc=np.array([0.8, 0.6])).shape == (2,)


def test_complete_integral_refuses_k_above_one():
    with pytest.raises(ValueError, match=r"\bk\b.*complex"):
        ep.complete_integral(1.5)
