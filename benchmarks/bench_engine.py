"""The engine's ratios, from one run: ensemble, scalar calls, memory.

* Ensemble: 1e5 mixed initial states (1% of them within 1e-12 of the separatrix), each at
  10 times, ``solve`` plus ``theta``, against one bare ``scipy.special.ellipj`` call on the
  same 1e6 points (target: <= 1.5, goal <= 1.0).
* One call on one number, in units of one scalar ``ellipj`` call: ``m.theta(t)`` (<= 10),
  ``solve`` (<= 25), ``ep.sn`` (<= 10).
* Memory: the peak that ``tracemalloc`` sees during ``theta(t)`` on 1e7 points, over the
  size of its result (<= 4).

    python benchmarks/bench_engine.py [--states 100000] [--times 10] [--repeats 5]
"""

from __future__ import annotations

import argparse
import math
import time
import tracemalloc

import numpy as np
from scipy import special

import elliptic_pendulum as ep


def best_time(function, repeats):
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - start)
    return best


def ensemble_states(n, rng):
    """n states: 99% uniform in (theta, theta') over [-pi, pi] x [-3, 3], 1% within 1e-12 of
    the separatrix (theta' = +-2 cos(theta/2) (1 +- 1e-12 u), u uniform in (0, 1))."""
    theta0 = rng.uniform(-math.pi, math.pi, n)
    dtheta0 = rng.uniform(-3.0, 3.0, n)
    near = rng.random(n) < 0.01
    sign = rng.choice([-1.0, 1.0], n)
    eps = rng.uniform(-1e-12, 1e-12, n)
    dtheta0[near] = (sign * 2 * np.cos(theta0 / 2) * (1 + eps))[near]
    return theta0, dtheta0


def ensemble(args, rng):
    theta0, dtheta0 = ensemble_states(args.states, rng)
    t = np.linspace(0.0, 20.0, args.times)
    m_param = rng.uniform(0.0, 1.0, args.states)
    u = theta0[:, None] + t[None, :]  # the same 1e6 points, an elliptic parameter per state
    m_points = np.broadcast_to(m_param[:, None], u.shape)

    def ours():
        return ep.solve(theta0[:, None], dtheta0[:, None]).theta(t[None, :])

    def bare():
        return special.ellipj(u, m_points)

    ours_s, bare_s = best_time(ours, args.repeats), best_time(bare, args.repeats)
    solve_s = best_time(lambda: ep.solve(theta0[:, None], dtheta0[:, None]), args.repeats)
    print(f"ensemble {args.states:.0e} states x {args.times} times: solve + theta "
          f"{ours_s:.3f} s (solve alone {solve_s:.3f} s), one bare ellipj {bare_s:.3f} s: "
          f"ratio {ours_s / bare_s:.2f}  (target: <= 1.5, goal <= 1.0)")


def scalars(args):
    one = best_time(lambda: special.ellipj(0.3, 0.7), 2000)
    m = ep.solve(0.9, 0.4)
    figures = {
        "m.theta(t)": (best_time(lambda: m.theta(1.7), 2000), 10),
        "solve(theta0, dtheta0)": (best_time(lambda: ep.solve(0.9, 0.4), 500), 25),
        "ep.sn(u, k)": (best_time(lambda: ep.sn(1.7, 0.6), 2000), 10),
    }
    print(f"one scalar ellipj call: {one * 1e6:.2f} us")
    for name, (seconds, limit) in figures.items():
        print(f"  {name:<24} {seconds * 1e6:7.2f} us = {seconds / one:5.1f} ellipj calls"
              f"  (target: <= {limit})")


def memory(args):
    m = ep.solve(2.0, 0.3)
    t = np.linspace(0.0, 1e3, args.points)
    tracemalloc.start()
    tracemalloc.reset_peak()
    result = m.theta(t)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    print(f"memory: theta(t) on {args.points:.0e} points peaks at {peak / 2**20:.0f} MiB, "
          f"{peak / result.nbytes:.2f} times its {result.nbytes / 2**20:.0f} MiB result "
          f"(target: <= 4)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--states", type=int, default=100_000)
    parser.add_argument("--times", type=int, default=10)
    parser.add_argument("--points", type=int, default=10_000_000)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    rng = np.random.default_rng(20261201)
    ensemble(args, rng)
    scalars(args)
    memory(args)


if __name__ == "__main__":
    main()
