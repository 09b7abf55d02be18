"""Edge cases of the flow (theta(t), theta'(t)) found by an adversarial run against mpmath.

Every expectation comes from outside the library: the initial state itself, closed forms
evaluated by mpmath at 50 digits or more in a private context (never ``mpmath.mp``), or
exact algebra.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

import elliptic_pendulum as ep


def _ctx(dps=60):
    ctx = mpmath.mp.clone()
    ctx.dps = dps
    return ctx


def test_small_states_come_back_at_t0_and_circular_dn_is_one():
    # Near the bottom (|theta0| ~ 1e-9, |theta0'| ~ 1e-7) the modulus is so small that the
    # AGM of kc had stopped before its first step, and cn = dn = kc at v = 0: theta(0) came
    # back up to 8 ulp from theta0 (the promise is 4). The reference is the initial state.
    rng = np.random.default_rng(5)
    n = 20_000
    theta0 = rng.uniform(-1, 1, n) * 10.0 ** rng.uniform(-10, -8, n)
    dtheta0 = rng.uniform(-1, 1, n) * 10.0 ** rng.uniform(-8, -6, n)
    omega0 = 10.0 ** rng.uniform(-1, 1, n)
    theta, dtheta = ep.solve(theta0, dtheta0, omega0).state(0.0)
    assert np.max(np.abs(theta - theta0) / np.spacing(np.abs(theta0))) <= 1
    assert np.max(np.abs(dtheta - dtheta0) / np.spacing(np.abs(dtheta0))) <= 1
    for i in range(0, n, 400):  # the scalar path, the same bits
        one = ep.solve(float(theta0[i]), float(dtheta0[i]), float(omega0[i]))
        assert one.state(0.0) == (theta[i], dtheta[i])
    # cn(0) = dn(0) = 1 exactly (DLMF 22.5.1), for a modulus whose kc is 4 ulp below 1.
    for k in (3e-8, -2e-8, 1e-9):
        assert ep.cn(0.0, k) == ep.dn(0.0, k) == 1.0
        assert ep.cn(np.zeros(2), k).tolist() == ep.dn(np.zeros(2), k).tolist() == [1.0, 1.0]
    # and dn elsewhere to 2 ulp of 1, its size (it was 2.5: the factor kc).
    ctx = _ctx(50)
    u = rng.uniform(-3, 3, 200)
    k = 10.0 ** rng.uniform(-9, -7.5, 200)
    ref = np.array([float(ctx.ellipfun("dn", ctx.mpf(a), m=ctx.mpf(b) ** 2))
                    for a, b in zip(u, k, strict=True)])
    assert np.max(np.abs(ep.dn(u, k) - ref)) <= 2.0 ** -51
