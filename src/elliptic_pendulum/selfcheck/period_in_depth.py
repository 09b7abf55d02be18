"""Self-checks of the exercises of the chapter on the period in depth (book/period_in_depth.md)."""

from __future__ import annotations

import math
from functools import cache

from ._core import Exercise, Hint, Value, register


def terms() -> dict[str, float | int]:
    # The Maclaurin coefficients of R in theta0 composed here, at 30 digits, from the series
    # of R in k^2 = sin^2(theta0/2) (squared central binomials) and that of sin^2(theta0/2);
    # the AGM written out here; R by mpmath's quadrature of its integral. The exercise asks
    # for the library's ep.period_series, ep.agm_ratio and ep.period_ratio.
    import mpmath

    with mpmath.workdps(30):
        x0 = mpmath.radians(120)
        k2 = mpmath.sin(x0 / 2) ** 2
        R = 2 / mpmath.pi * mpmath.quad(
            lambda p: 1 / mpmath.sqrt(1 - k2 * mpmath.sin(p) ** 2), [0, mpmath.pi / 2])
        degree = 40  # in x = theta0^2: far beyond the count
        # sin^2(theta/2) = (1 - cos theta)/2 = sum_{j>=1} (-1)^(j+1) x^j / (2 (2j)!)
        s = [mpmath.mpf(0)] + [(-1) ** (j + 1) / (2 * mpmath.factorial(2 * j))
                               for j in range(1, degree + 1)]
        coeffs = [mpmath.mpf(0)] * (degree + 1)
        power = [mpmath.mpf(1)] + [mpmath.mpf(0)] * degree  # s^n, truncated
        for n in range(degree + 1):
            c = (mpmath.binomial(2 * n, n) / mpmath.mpf(4) ** n) ** 2
            for j in range(degree + 1):
                coeffs[j] += c * power[j]
            power = [sum(power[i] * s[j - i] for i in range(j + 1)) for j in range(degree + 1)]
        x = x0**2
        partial, n_terms = mpmath.mpf(0), None
        for n in range(1, degree + 1):
            partial += coeffs[n - 1] * x ** (n - 1)
            if abs(partial / R - 1) < mpmath.mpf("1e-6"):
                n_terms = n
                break
        a, b, n_steps, r1 = mpmath.mpf(1), mpmath.cos(x0 / 2), None, None
        for n in range(1, 10):
            a, b = (a + b) / 2, mpmath.sqrt(a * b)
            if n == 1:
                r1 = abs(1 / a / R - 1)
            if abs(1 / a / R - 1) < mpmath.mpf("1e-6"):
                n_steps = n
                break
        assert n_terms is not None and n_steps is not None and r1 is not None
        return {"n_terms": int(n_terms), "n_steps": int(n_steps), "r1": float(r1)}


def bracket() -> dict[str, float | bool]:
    # R by scipy's quadrature of its integral (not the AGM), the two one-step values from
    # their formulas 2/(1 + c) and 1/sqrt(c), c = cos(theta0/2); the exercise asks for the
    # library's ep.agm_ratio and ep.kidd_fogg_ratio.
    import math

    from scipy.integrate import quad

    def sides(degrees):
        x = math.radians(degrees)
        k2, c = math.sin(x / 2) ** 2, math.cos(x / 2)
        R = 2 / math.pi * quad(lambda p: 1 / math.sqrt(1 - k2 * math.sin(p) ** 2),
                               0, math.pi / 2, epsabs=0, epsrel=1e-13, limit=200)[0]
        return 2 / (1 + c), R, 1 / math.sqrt(c)

    inside = True
    for degrees in range(1, 180):
        low, R, high = sides(degrees)
        inside = inside and low < R < high
    low, R, high = sides(90)
    return {"bracket": bool(inside), "mean90": abs((low + high) / 2 / R - 1)}


def odd() -> dict[str, float]:
    # The fundamental from the nome, b_0 = 8 sqrt(q) / (1 + q) (mpmath's qfrom), where the
    # exercise takes an FFT of an integrated swing; an exact swing has no cosines and no even
    # sines at all.
    import mpmath

    with mpmath.workdps(30):
        q = mpmath.qfrom(m=mpmath.sin(mpmath.radians(150) / 2) ** 2)
        return {"cosines": 0.0, "even_sines": 0.0, "b1": float(8 * mpmath.sqrt(q) / (1 + q))}


@cache
def _wrong_mean90(mistake: str) -> float:
    # The error at 90 degrees as the expected mistakes give it.
    from scipy.special import ellipk

    half = math.radians(45) if mistake != "degrees" else 45.0
    c = math.cos(half)
    R = 2 / math.pi * ellipk(math.sin(math.radians(45)) ** 2)
    low, high = 2 / (1 + c), 1 / math.sqrt(c)
    if mistake == "one side":
        return abs(low / R - 1)
    if mistake == "absolute":
        return abs((low + high) / 2 - R)
    return abs((low + high) / 2 / R - 1)


@cache
def _r1_other(mistake: str) -> float:
    # r1 as the expected mistakes give it.
    from scipy.special import ellipk

    c = math.cos(math.radians(60))
    R = 2 / math.pi * ellipk(math.sin(math.radians(60)) ** 2)
    if mistake == "kidd fogg":
        return abs(1 / math.sqrt(c) / R - 1)
    return abs(2 / (1 + c) - R)

register(
    Exercise(
        "ex-period-terms",
        values=(
            Value("n_terms", "the number of terms of `ep.period_series` that give $R$ to a "
                  "relative $10^{-6}$ at 120 degrees", kind=int,
                  hints=(Hint(lambda a, e: a == e - 1,
                              "Count every term, the leading term (the small-angle ratio) "
                              "too: `ep.period_series(x, n)` sums `n` terms.",
                              lambda e: e - 1),
                         Hint(lambda a, e: a > e,
                              "Too many: stop at the first count whose relative error "
                              "is below the target.",
                              lambda e: e + 2))),
            Value("n_steps", "the number of AGM steps (`ep.agm_ratio`) that give $R$ to a "
                  "relative $10^{-6}$ at 120 degrees", kind=int,
                  hints=(Hint(lambda a, e: a == e + 1,
                              "`ep.agm_ratio(x, 0)` is the small-angle ratio, before any "
                              "step: did you count it as a step?",
                              lambda e: e + 1),
                         Hint(lambda a, e: a < e,
                              "Too few: is your error relative, $|R_n/R - 1|$, and is $R$ "
                              "the exact ratio at 120 degrees, in radians?",
                              lambda e: e - 1))),
            Value("r1", "the relative error $|R_1/R - 1|$ of one AGM step at 120 degrees",
                  rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: abs(a - _r1_other("kidd fogg")) < 1e-6 * e,
                              "That is the error of $1/b_1$ (Kidd and Fogg's); one AGM "
                              "step gives $R_1 = 1/a_1$.",
                              lambda e: _r1_other("kidd fogg")),
                         Hint(lambda a, e: abs(a - _r1_other("absolute")) < 1e-6 * e,
                              "Give the relative error: divide the difference by $R$.",
                              lambda e: _r1_other("absolute")))),
        ),
        reference=terms,
        written="Start from the error $r_1$ of one step and apply $r_{n+1} \\approx r_n^2/4$ "
                "until it falls below $10^{-6}$; the number of applications plus one is the "
                "predicted count.",
    ),
    Exercise(
        "ex-period-bracket",
        values=(
            Value("bracket", "whether $1/a_1 < R < 1/b_1$ at every amplitude you checked "
                  "(True or False)", kind=bool,
                  hints=(Hint(lambda a, e: a != e,
                              "Look again at the exact $R = (2/\\pi)K_1(\\sin(\\theta_0/2))$: "
                              "`scipy.special.ellipk` and `mpmath.ellipk` take $m = k^2$, "
                              "not $k$; and the amplitudes must be in radians, below $\\pi$.",
                              lambda e: not e),)),
            Value("mean90", "the relative error $|\\bar R/R - 1|$ of the mean $\\bar R$ of the "
                  "two one-step values at 90 degrees", rtol=1e-6, hidden_rtol=1e-9,
                  hints=(Hint(lambda a, e: abs(a - _wrong_mean90("one side")) < 1e-4 * a,
                              "That is the error of one AGM step alone; average it with "
                              "Kidd and Fogg's value first.",
                              lambda e: _wrong_mean90("one side")),
                         Hint(lambda a, e: abs(a - _wrong_mean90("absolute")) < 1e-6 * a,
                              "Give the relative error: divide the difference by $R$.",
                              lambda e: _wrong_mean90("absolute")),
                         Hint(lambda a, e: abs(a - _wrong_mean90("degrees")) < 1e-4 * a,
                              "Did you give the cosine an angle in degrees? `math.cos` and "
                              "`numpy.cos` take radians.",
                              lambda e: _wrong_mean90("degrees")))),
        ),
        reference=bracket,
        written="For 1, do one step of the AGM by hand from $(1, \\cos(\\theta_0/2))$. For 2, "
                "the inequality of the arithmetic and geometric means shows that each interval "
                "$[b_n, a_n]$ contains the next; where is their common limit? For 3, expand "
                "both one-step values and $R$ in powers of $\\theta_0$ and look at the first "
                "term of the difference that does not cancel.",
    ),
    Exercise(
        "ex-period-odd",
        values=(
            Value("cosines", "the largest cosine coefficient $|a_n|$ of your FFT of the swing "
                  "of 150 degrees", rtol=0.0, atol=1e-6, hidden_rtol=0.0,
                  hints=(Hint(lambda a, e: abs(a) > 1e-2,
                              "Start the swing at the bottom on the way up, "
                              "$\\theta(0) = 0$, $\\theta'(0) > 0$ (from a turning point "
                              "$\\theta$ is even: all cosines), and sample exactly one period, "
                              "at $kP_{II}/N$ for $k = 0, \\ldots, N - 1$ (not $P_{II}$ itself).",
                              lambda e: 0.5),
                         Hint(lambda a, e: 1e-6 < abs(a) <= 1e-2,
                              "Coefficients this small but not tiny are the integrator's "
                              "error: tighten its tolerances (`rtol`, `atol`), or use "
                              "`ep.integrate`.",
                              lambda e: 1e-4))),
            Value("even_sines", "the largest sine coefficient $|b_n|$ of an even harmonic $n$ "
                  "in your FFT", rtol=0.0, atol=1e-6, hidden_rtol=0.0,
                  hints=(Hint(lambda a, e: abs(a) > 1e-2,
                              "Sample exactly one period, at $kP_{II}/N$ for "
                              "$k = 0, \\ldots, N - 1$ (not $P_{II}$ itself), with $P_{II}$ "
                              "the period of this amplitude, not $2\\pi/\\omega_0$; and take "
                              "the even "
                              "harmonics $n = 2, 4, \\ldots$ (index $n$ of `rfft`).",
                              lambda e: 0.2),
                         Hint(lambda a, e: 1e-6 < abs(a) <= 1e-2,
                              "Coefficients this small but not tiny are the integrator's "
                              "error: tighten its tolerances (`rtol`, `atol`), or use "
                              "`ep.integrate`.",
                              lambda e: 1e-4))),
            Value("b1", "the sine coefficient $b_1$ of the fundamental, from your FFT",
                  rtol=1e-6, hidden_rtol=1e-8,
                  hints=(Hint(lambda a, e: abs(a + e) < 1e-6 * e,
                              "`numpy.fft.rfft` turns $b\\sin(2\\pi kn/N)$ into "
                              "$-ibN/2$: the sine coefficient is minus the imaginary part.",
                              lambda e: -e),
                         Hint(lambda a, e: abs(a / e - 0.5) < 1e-5
                              or (a / e > 4 and abs(math.log2(a / e) - round(math.log2(a / e)))
                                  < 1e-5),
                              "Normalise the FFT: divide `rfft` by $N/2$ for the "
                              "coefficients of $\\sin$ and $\\cos$ (by $N$ gives half of them).",
                              lambda e: e / 2),
                         Hint(lambda a, e: abs(a - math.radians(150)) < 1e-4,
                              "That is the amplitude $\\theta_0$, the fundamental of a small "
                              "swing; a wide swing is not a sine: take its FFT.",
                              lambda e: math.radians(150)))),
        ),
        reference=odd,
        written="For 1, write down the equation that $-\\theta(-t)$ satisfies, and its state "
                "at $t = 0$; do the same for $-\\theta(t + T/2)$, using the energy to get its "
                "speed at $t = 0$. For 2, split the integral of a Fourier coefficient over "
                "the two halves of the period and substitute $t \\to t + T/2$ in the second.",
    ),
)

