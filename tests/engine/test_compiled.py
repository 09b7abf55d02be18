"""The compiled loops (numba) give the bits of the NumPy passes and of the scalar twins.

Once a call on ``agm.LOAD_FROM`` elements has loaded them, every piece of at least
``agm.COMPILED_FROM`` elements takes the compiled AGM, reduction, product and Landen
recurrence of ``_engine/compiled.py``; a smaller one NumPy's passes, and one number the
Python-float twins. The library promises that a value never depends on the
other elements of its array, so an element must come out to the bit the same alone, in a
small array and in a large one. The expectations here are the library's other two paths,
which share no loop with the compiled one: NumPy's ufuncs (``agm._levels``,
``landen._recurrence``) and Python's float arithmetic (``agm._constants_float``). Their
accuracy, in turn, is held against mpmath elsewhere (tests/test_elliptic_tables.py,
tests/engine/test_zero_crossings.py); so a compiled loop that reassociated, fused a
multiply-add, or took another branch would fail here by at least one bit.
"""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest

import elliptic_pendulum as ep
from elliptic_pendulum._engine import agm, landen
from tests.strict import quietly

BIG = agm.COMPILED_FROM + 905  # compiled once loaded, and not a multiple of anything


@pytest.fixture(autouse=True)
def spy(monkeypatch):
    """Load the compiled loops (as a large call does), and count the calls of each."""
    agm.load_compiled(agm.LOAD_FROM)
    compiled = agm.compiled_for(agm.COMPILED_FROM)
    calls: dict[str, int] = {}

    def counted(name):
        original = getattr(compiled, name)

        def wrapper(*args, **kwargs):
            calls[name] = calls.get(name, 0) + 1
            return original(*args, **kwargs)
        return wrapper

    for name in ("agm", "recurrence", "reduce", "two_prod"):
        monkeypatch.setattr(compiled, name, counted(name))
    return calls


def _bits(x):
    return np.asarray(x, dtype=float).view(np.uint64)


def _same(a, b):
    np.testing.assert_array_equal(_bits(a), _bits(b))


def _moduli(rng):
    """Complementary moduli kc (+ low parts) from every corner the AGM meets."""
    k = np.concatenate([
        rng.uniform(0.0, 1.0, BIG - 200),
        1.0 - rng.uniform(0.0, 1e-6, 40),             # beside the separatrix
        1.0 - 2.0 ** -rng.integers(20, 53, 40),       # within a few ulp of k = 1
        rng.uniform(0.0, 1e-8, 40),                   # kc rounds to 1, with a low part
        np.sqrt(1.0 - (1.0 / 16.0) ** 2) + rng.uniform(-1e-9, 1e-9, 40),  # kc = 1/16
        [0.0, 0.5, 0.998, np.nextafter(1.0, 0.0)] * 10,
    ])
    kc, kc_lo = agm.complement(k)
    tiny = np.array([1e-300, 5e-324, 2.0 ** -60, 2.0 ** -1000, 1e-160, 0.0])  # 0: the top
    return (np.concatenate([kc, tiny]), np.concatenate([kc_lo, np.zeros(tiny.size)]))


def test_the_compiled_agm_gives_the_bits_of_numpy_and_of_the_float_twin(spy):
    rng = np.random.default_rng(20261204)
    kc, kc_lo = _moduli(rng)
    assert kc.size >= agm.COMPILED_FROM
    big = agm.constants(kc, kc_lo)                      # compiled
    assert spy == {"agm": 1}
    levels = len(big.mu)
    for start in range(0, kc.size, 1000):               # NumPy's passes, 1000 at a time
        part = slice(start, start + 1000)
        small = agm.constants(kc[part], kc_lo[part])
        for field in range(agm.SCALARS):
            _same(big[field][part], small[field])
        small_mu, small_rho = agm.pad(small.mu, levels), agm.pad(small.rho, levels)
        for j in range(levels):
            _same(big.mu[j][part], small_mu[j])
            _same(big.rho[j][part], small_rho[j])
    for i in rng.choice(np.nonzero(kc > 0)[0], 300, replace=False):  # the Python floats
        one = agm.constants_float(float(kc[i]), float(kc_lo[i]))
        assert [float(big[f][i]) for f in range(1, agm.SCALARS)] == list(one[1:agm.SCALARS])
        mu = agm.pad(one.mu, levels)
        rho = agm.pad(one.rho, levels)
        assert [float(x[i]) for x in big.mu] == list(mu)
        assert [float(x[i]) for x in big.rho] == list(rho)


@pytest.mark.parametrize("function", [ep.sn, ep.cn, ep.dn, ep.am])
def test_jacobi_functions_of_many_moduli_do_not_depend_on_the_array(function, spy):
    rng = np.random.default_rng(7)
    k = np.concatenate([rng.uniform(0.0, 1.0, BIG), 1.0 - rng.uniform(0.0, 1e-9, 50),
                        rng.uniform(1.0, 30.0, 50), [0.0, 1.0, 0.998, 0.0625]])
    u = np.concatenate([rng.uniform(-10.0, 10.0, k.size - 100),
                        rng.uniform(-1e4, 1e4, 100)])
    whole = quietly(function, u, k)
    assert {"agm", "recurrence", "reduce"} <= set(spy)
    pieces = np.concatenate([function(u[i:i + 700], k[i:i + 700])
                             for i in range(0, k.size, 700)])
    _same(whole, pieces)
    for i in rng.choice(k.size, 50, replace=False):
        _same(whole[i], function(float(u[i]), float(k[i])))
    # one modulus for all: the constants broadcast against u in the compiled loops
    _same(function(u, 0.7), np.concatenate([function(u[i:i + 700], 0.7)
                                            for i in range(0, u.size, 700)]))


@pytest.mark.parametrize("times_shape", [(1, 7), (7,)], ids=["states-by-times", "one-time"])
def test_an_ensemble_does_not_depend_on_its_companions(times_shape, spy):
    """States (N, 1) at times (1, T): the levels broadcast; and N states at one time each."""
    rng = np.random.default_rng(11)
    n = BIG
    theta0 = np.concatenate([rng.uniform(-np.pi, np.pi, n - 40), [-2.9, 3.1, 0.0, -0.1] * 10])
    dtheta0 = np.concatenate([rng.uniform(-3.0, 3.0, n - 40), [-0.05, 0.001, 2.0, -1.0] * 10])
    near = rng.random(n) < 0.02  # beside the separatrix, as the benchmark's ensemble
    dtheta0[near] = (2.0 * np.cos(theta0 / 2.0) * (1.0 + 1e-12 * rng.uniform(-1, 1, n)))[near]
    if times_shape == (1, 7):
        theta0, dtheta0 = theta0[:, None], dtheta0[:, None]
        t = np.linspace(-50.0, 300.0, 7)[None, :]
    else:
        t = rng.uniform(-100.0, 100.0, n)
    motion = quietly(ep.solve, theta0, dtheta0)
    theta = quietly(motion.theta, t)
    dtheta = motion.dtheta(t)
    assert theta.size >= agm.COMPILED_FROM
    assert {"agm", "recurrence", "reduce", "two_prod"} <= set(spy)
    for i in rng.choice(n, 40, replace=False):
        one = ep.solve(float(np.ravel(theta0)[i]), float(np.ravel(dtheta0)[i]))
        t_i = t[0] if times_shape == (1, 7) else t[i]
        _same(theta[i], one.theta(t_i))
        _same(dtheta[i], one.dtheta(t_i))
    # the same states in arrays too small for the compiled loops
    part = slice(0, 500)
    small = ep.solve(theta0[part], dtheta0[part])
    t_part = t if times_shape == (1, 7) else t[part]
    _same(theta[part], small.theta(t_part))


def test_one_state_at_many_times_is_the_same_in_pieces(spy):
    motion = ep.solve(2.9, 0.1)
    t = np.linspace(-1e4, 1e4, 3 * agm.COMPILED_FROM)
    theta = motion.theta(t)
    assert spy["recurrence"] >= 1 and spy["two_prod"] >= 1
    _same(theta, np.concatenate([motion.theta(t[i:i + 1000])
                                           for i in range(0, t.size, 1000)]))


def test_the_recurrence_lays_out_levels_of_any_shape():
    """Levels that vary along a trailing axis, or along none, take the general layout."""
    rng = np.random.default_rng(3)
    kc, kc_lo = agm.complement(rng.uniform(0.0, 0.99, 64))
    c = agm.constants(kc[None, :], kc_lo[None, :])          # shape (1, 64)
    t = np.tan(rng.uniform(-0.7, 0.7, (50, 64)))
    cc = c.mu[-1] * t
    cc_numpy = cc.copy()
    d_numpy = landen._recurrence(cc_numpy, c.mu, c.rho, np.empty(cc.shape), np.empty(cc.shape))
    from elliptic_pendulum._engine import compiled

    cc_compiled, d_compiled = compiled.recurrence(cc, c.mu, c.rho)
    _same(cc_compiled, cc_numpy)
    _same(d_compiled, d_numpy)


_LOADS = """
import sys, numpy as np, elliptic_pendulum as ep
def loaded():
    print('numba' in sys.modules)
ep.sn(np.linspace(0, 1, 100), np.linspace(0, 0.9, 100))
ep.solve(1.0, 0.2).theta(3.0)
loaded()
n = {lesson}  # a lesson's grid: many moduli, many states, one state at many times
ep.sn(np.linspace(0, 1, n), np.linspace(0, 0.9, n))
ep.solve(np.linspace(0, 3, n), 0.5).theta(1.0)
ep.solve(2.0, 0.5).theta(np.linspace(0, 5, n))
ep.complete_integral(np.linspace(0, 0.99, n))
loaded()
{large}
loaded()
"""


@pytest.mark.parametrize("large", [
    "ep.sn(np.linspace(0, 1, {n}), np.linspace(0, 0.9, {n}))",
    "ep.solve(np.linspace(0, 3, {n}), 0.5)",
    "ep.solve(2.0, 0.5).theta(np.linspace(0, 5, {n}))",
], ids=["many-moduli", "many-states", "many-times"])
def test_numba_is_loaded_only_by_a_large_call(large):
    """A scalar call, the CLI's path, or a lesson's arrays do not pay for numba's import
    (agm.LOAD_FROM); each kind of large call loads it."""
    code = _LOADS.format(lesson=20001, large=large.format(n=agm.LOAD_FROM))
    out = subprocess.run([sys.executable, "-W", "error", "-c", code], capture_output=True,
                         text=True, check=True).stdout.split()
    assert out == ["False", "False", "True"]


_RACE = f"""
import threading, numpy as np, elliptic_pendulum as ep
rng = np.random.default_rng(9)
u, k = rng.uniform(-5, 5, 4096), rng.uniform(0, 1, 4096)
before = ep.sn(u, k)
done = threading.Event()
def load():
    ep.sn(rng.uniform(-5, 5, {agm.LOAD_FROM}), 0.5)
    done.set()
loader = threading.Thread(target=load)
loader.start()
calls = 0
while not done.is_set():
    assert ep.sn(u, k).tobytes() == before.tobytes()
    calls += 1
loader.join()
assert ep.sn(u, k).tobytes() == before.tobytes()
print(calls)
"""


def test_a_thread_runs_while_another_loads_the_compiled_loops():
    """numba's module is in sys.modules from the first line of its import: a piece in
    another thread must not take it before its loops exist (it then ran NumPy's passes)."""
    out = subprocess.run([sys.executable, "-W", "error", "-c", _RACE], capture_output=True,
                         text=True)
    assert out.returncode == 0, out.stderr[-3000:]
    assert int(out.stdout) > 0  # the other thread did run during the load


_RUN = f"""
import hashlib, numpy as np, elliptic_pendulum as ep
rng = np.random.default_rng(5)
theta0, dtheta0 = rng.uniform(-3, 3, ({agm.LOAD_FROM}, 1)), rng.uniform(-2, 2, ({agm.LOAD_FROM}, 1))
theta = ep.solve(theta0, dtheta0).theta(np.linspace(0, 10, 7)[None, :])
sn = ep.sn(rng.uniform(-5, 5, 5000), rng.uniform(0, 1, 5000))
print(hashlib.sha256(theta.tobytes() + sn.tobytes()).hexdigest())
"""


@pytest.mark.slow
def test_processes_that_compile_at_once_leave_a_cache_the_next_ones_load(tmp_path):
    """Three processes compile into one empty numba cache at once; two more load it.

    Without the lock of compiled._one_at_a_time, numba's cache written by processes at once
    crashed a later process (a segmentation fault) in about one trial of three here; with
    it, every process finishes and all agree with one another to the bit.
    """
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)}
    command = [sys.executable, "-W", "error", "-c", _RUN]
    together = [subprocess.Popen(command, env=env, stdout=subprocess.PIPE, text=True)
                for _ in range(3)]
    outs = [p.communicate()[0] for p in together]
    assert [p.returncode for p in together] == [0, 0, 0]
    assert any(tmp_path.rglob("*.nbc"))  # the cache was written where we said
    for _ in range(2):
        outs.append(subprocess.run(command, env=env, capture_output=True, text=True,
                                   check=True).stdout)
    assert len(set(outs)) == 1
