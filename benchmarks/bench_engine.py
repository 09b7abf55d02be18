"""The engine's ratios, from one run: many moduli, ensemble, scalar calls, memory.

* Many moduli (1e6 random elements, best of three, ratios to scipy.special on the same
  points): ``complete_integral(k)`` against ``ellipk(k**2)`` (goal <= 2), ``sn(u, k)`` with
  k in [0, 1) against ``ellipj(u, k**2)`` (goal <= 1), ``sn(u, 0.7)`` against
  ``ellipj(u, 0.49)``, ``period_ratio(theta0)`` against ``ellipk`` (goal <= 2); and the
  worst error of each in ulps against mpmath at 50 digits on 2000 of those points.

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


def _ulps(values, references):
    return max(abs(float(x) - float(r)) / np.spacing(abs(float(r))) if r != 0 else
               (0.0 if x == 0 else math.inf) for x, r in zip(values, references, strict=True))


def moduli(args, rng, n=1_000_000, sample=2000):
    """The table of many moduli: ratios to scipy.special, and accuracy against mpmath."""
    import mpmath

    from elliptic_pendulum.periods import period_ratio

    k = rng.uniform(0.0, 1.0, n)
    u = rng.uniform(-10.0, 10.0, n)
    theta0 = rng.uniform(0.0, 3.0, n)
    rows = [
        ("complete_integral(k), k in [0, 1)", lambda: ep.complete_integral(k),
         "ellipk(k**2)", lambda: special.ellipk(k**2), "<= 2"),
        ("sn(u, k), u in [-10, 10], k in [0, 1)", lambda: ep.sn(u, k),
         "ellipj(u, k**2)", lambda: special.ellipj(u, k**2), "<= 1.0"),
        ("sn(u, 0.7) (one modulus)", lambda: ep.sn(u, 0.7),
         "ellipj(u, 0.49)", lambda: special.ellipj(u, 0.49), "keep"),
        ("period_ratio(theta0), theta0 in [0, 3)", lambda: period_ratio(theta0),
         "ellipk(k**2)", lambda: special.ellipk(k**2), "<= 2"),
    ]
    print(f"many moduli, {n:.0e} random elements, best of {args.repeats}:")
    for name, ours, theirs_name, theirs, goal in rows:
        ratio = best_time(ours, args.repeats) / best_time(theirs, args.repeats)
        print(f"  {name:<42} / {theirs_name:<16} {ratio:6.2f}x  (goal {goal})")
    i = rng.choice(n, sample, replace=False)
    with mpmath.workdps(50):
        ref_k = [mpmath.ellipk(mpmath.mpf(x) ** 2) for x in k[i]]
        ref_sn = [mpmath.ellipfun("sn", mpmath.mpf(a), m=mpmath.mpf(b) ** 2)
                  for a, b in zip(u[i], k[i], strict=True)]
        ref_sn1 = [mpmath.ellipfun("sn", mpmath.mpf(a), m=mpmath.mpf(0.7) ** 2) for a in u[i]]
        ref_r = [2 / mpmath.pi * mpmath.ellipk(mpmath.sin(mpmath.mpf(t) / 2) ** 2)
                 for t in theta0[i]]
    print(f"  worst ulps against mpmath (50 digits) on {sample} of those points: "
          f"K {_ulps(ep.complete_integral(k[i]), ref_k):.2f}, "
          f"sn {_ulps(ep.sn(u[i], k[i]), ref_sn):.2f}, "
          f"sn(one modulus) {_ulps(ep.sn(u[i], 0.7), ref_sn1):.2f}, "
          f"period_ratio {_ulps(period_ratio(theta0[i]), ref_r):.2f}")


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
    moduli(argparse.Namespace(repeats=3), np.random.default_rng(20260101))
    ensemble(args, rng)
    scalars(args)
    memory(args)


if __name__ == "__main__":
    main()
