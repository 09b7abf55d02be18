"""Safe in threads: solving never reads or writes mpmath.mp.

Four threads solve near-separatrix states (and a few far ones, which use a private mpmath
context) while a fifth keeps setting mpmath.mp.dps = 15; every period and theta must be
bit for bit what a single thread computes, and mp.dps must be left as it was. The mutant
this rejects is the old classification under mpmath.workdps(50), which changed the shared
precision: 712 of 1,600 periods differed then.
"""

import threading

import mpmath
import numpy as np

import elliptic_pendulum as ep


def states():
    rng = np.random.default_rng(3)
    theta0 = rng.uniform(-3.0, 3.0, 400)
    dtheta0 = 2 * np.cos(theta0 / 2) * (1 + rng.uniform(-1e-12, 1e-12, 400))
    theta0[::50] = 1e7 + theta0[::50]   # far angles: the private-context path
    return theta0, dtheta0


def run(theta0, dtheta0):
    out = []
    for a, b in zip(theta0, dtheta0, strict=True):
        m = ep.solve(a, b)
        out.append((m.period, m.theta(3.7), m.regime))
    return out


def test_threads_give_single_threaded_results_and_leave_mp_alone():
    theta0, dtheta0 = states()
    expected = run(theta0, dtheta0)
    before = mpmath.mp.dps = 37
    results = [None] * 4
    stop = threading.Event()

    def meddle():
        while not stop.is_set():
            mpmath.mp.dps = 15
            mpmath.mp.dps = 37

    def work(i):
        results[i] = run(theta0, dtheta0)

    meddler = threading.Thread(target=meddle)
    workers = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    meddler.start()
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    stop.set()
    meddler.join()
    try:
        for result in results:
            assert result == expected
        # and the array call agrees with the single states
        m = ep.solve(theta0, dtheta0)
        np.testing.assert_array_equal(m.period, [e[0] for e in expected])
        # nothing in the library moved the shared precision
        assert mpmath.mp.dps == before
        ep.solve(1e9, 2.0), ep.solve(0.5, 1.0)
        assert mpmath.mp.dps == before
    finally:
        mpmath.mp.dps = 15
