"""Speed and accuracy of the closed-form theta(t) against scipy's ellipj, solve_ivp and mpmath.

Prints one table per motion (a libration of 170 degrees and a rotation). Times are the best of
several repeats with time.perf_counter, and every speed is a ratio to a run made in the same
process, so the numbers compare across machines. The target is a ratio to one bare
scipy.special.ellipj call of at most 1.5 (goal 1.0).

    python benchmarks/bench_theta.py [--points 1000000] [--repeats 5]

It first prints the engine's ratios (bench_engine.py: many moduli against scipy.special
and mpmath, an ensemble of 1e5 states,
one call on one number, the memory of theta(t)), so that `make bench` gives them all in one run.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import mpmath
import numpy as np
from scipy import integrate, special

import elliptic_pendulum as ep

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_engine  # noqa: E402  (its sibling script)

MP_DPS = 40  # reference precision: far beyond double, so its own error is out of the picture


def best_time(function, repeats):
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - start)
    return best


class Case:
    """A motion with omega0 = 1, its closed form by mpmath, and the bare ellipj call for it."""

    def __init__(self, name, theta0, dtheta0):
        self.name, self.theta0, self.dtheta0 = name, theta0, dtheta0
        self.motion = ep.solve(theta0, dtheta0)
        with mpmath.workdps(MP_DPS):
            if dtheta0 == 0:  # libration released at rest: theta = 2 asin(k sn(t + K, k))
                self.k = mpmath.sin(mpmath.mpf(theta0) / 2)
                self.speed = mpmath.mpf(1)
            else:  # rotation from theta = 0: theta = 2 am(t / gamma, gamma), gamma = 2 / theta'
                self.k = 2 / mpmath.mpf(dtheta0)
                self.speed = 1 / self.k
            self.m = self.k**2
            self.quarter = mpmath.ellipk(self.m)
        self.m_double = float(self.m)
        self.speed_double = float(self.speed)
        self.shift = float(self.quarter) if dtheta0 == 0 else 0.0

    def bare_ellipj(self, t):
        # What any closed-form evaluation has to do at least: one Jacobi call on the points.
        return special.ellipj(self.speed_double * t + self.shift, self.m_double)

    def mp_theta(self, t):
        with mpmath.workdps(MP_DPS):
            u = self.speed * mpmath.mpf(float(t))
            if self.dtheta0 == 0:
                sn = mpmath.ellipfun("sn", u + self.quarter, m=self.m)
                return 2 * mpmath.asin(self.k * sn)
            n = mpmath.nint(u / (2 * self.quarter))  # am(u) = n pi + am(u - 2 n K)
            reduced = u - 2 * n * self.quarter
            sn = mpmath.ellipfun("sn", reduced, m=self.m)
            cn = mpmath.ellipfun("cn", reduced, m=self.m)
            return 2 * (n * mpmath.pi + mpmath.atan2(sn, cn))

    def ode(self, t_end, t_eval=None, dense=False):
        def rhs(_, y):
            return [y[1], -math.sin(y[0])]

        return integrate.solve_ivp(rhs, (0.0, t_end), [self.theta0, self.dtheta0],
                                   method="DOP853", rtol=1e-10, atol=1e-12, t_eval=t_eval,
                                   dense_output=dense)


def report(case, points, repeats, rng):
    period = case.motion.period
    t = np.linspace(0.0, 100 * period, points)
    print(f"\n== {case.name}: regime {case.motion.regime.value}, period {period:.6f}, "
          f"{points:.0e} points over 100 periods ==")

    ours = best_time(lambda: case.motion.theta(t), repeats)
    bare = best_time(lambda: case.bare_ellipj(t), repeats)
    ivp = best_time(lambda: case.ode(t[-1], dense=True).sol(t), max(1, repeats // 2))
    print(f"{'ours  m.theta(t)':<40}{ours:10.4f} s")
    print(f"{'one bare scipy.special.ellipj(u, m)':<40}{bare:10.4f} s   ratio ours/ellipj "
          f"{ours / bare:6.2f}  (target: <= 1.5, goal <= 1.0)")
    print(f"{'solve_ivp DOP853 rtol 1e-10, dense':<40}{ivp:10.4f} s   ratio ours/solve_ivp "
          f"{ours / ivp:6.3f}")

    # The solver's drift, measured against the closed form on a grid; mpmath then decides who
    # is right at the worst grid time (not at a turning point, where a phase error hides).
    ends = np.array([100 * period, 1000 * period])
    grid = np.linspace(0.0, ends[-1], 20001)
    numeric = case.ode(ends[-1], t_eval=grid).y[0]
    closed = case.motion.theta(grid)
    for end in ends:
        inside = grid <= end * (1 + 1e-12)
        errors = np.abs(numeric[inside] - closed[inside])
        worst = grid[inside][errors.argmax()]
        exact = float(case.mp_theta(worst))
        print(f"solve_ivp max |error| up to {end / period:5.0f} periods: {errors.max():.2e} rad"
              f"   (at its worst t = {worst:.1f} vs mpmath: solve_ivp "
              f"{abs(numeric[inside][errors.argmax()] - exact):.2e}, "
              f"ours {abs(float(case.motion.theta(worst)) - exact):.2e})")

    sample = np.sort(rng.uniform(0.0, 100 * period, 200))
    start = time.perf_counter()
    reference = np.array([float(case.mp_theta(s)) for s in sample])
    per_point = (time.perf_counter() - start) / sample.size
    ours_per_point = ours / points
    print(f"mpmath (dps {MP_DPS}) per point: {per_point * 1e6:9.1f} us   "
          f"(ours {ours_per_point * 1e9:.1f} ns: {per_point / ours_per_point:,.0f} times faster)")
    error = np.abs(case.motion.theta(sample) - reference)
    # The input t itself is only known to half an ulp, which moves theta by |theta'| ulp(t)/2:
    # the error in units of that unavoidable spread (plus one ulp of theta) says how much the
    # algorithm adds.
    spread = np.abs(case.motion.dtheta(sample)) * np.spacing(sample) / 2 + np.spacing(reference)
    print(f"ours vs mpmath on {sample.size} points: max |error| {error.max():.2e} rad, "
          f"{(error / spread).max():.2f} times the spread of theta over t +- ulp(t)/2")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    rng = np.random.default_rng(20241206)
    print(f"numpy {np.__version__}, scipy {__import__('scipy').__version__}, "
          f"mpmath {mpmath.__version__}")
    engine = argparse.Namespace(states=100_000, times=10, points=10_000_000,
                                repeats=args.repeats)
    print("\n== the engine ==")
    bench_engine.moduli(argparse.Namespace(repeats=3), np.random.default_rng(20260101))
    bench_engine.ensemble(engine, np.random.default_rng(20261201))
    bench_engine.scalars(engine)
    bench_engine.memory(engine)
    for case in (Case("libration of 170 degrees", math.radians(170), 0.0),
                 Case("rotation, theta'(0) = 2.5 omega0", 0.0, 2.5)):
        report(case, args.points, args.repeats, rng)


if __name__ == "__main__":
    main()
