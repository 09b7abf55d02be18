"""A search over extreme initial states (hypothesis) against mpmath at the digits each needs.

Reference: :class:`tests.mpref.Exact`, the note's (25), (28) and (46) in mpmath from the exact
doubles of the state, with the library's one convention (the double nearest a multiple of pi,
below 2**50, means that multiple: odd at the top, even at the bottom) and
at as many digits as the state needs (the reduction of a far angle, the cancellation in
1 - k^2 near the separatrix, the reduction of the elliptic argument at large t).

Strategies (all log-uniform in magnitude, both signs):

* far and tiny angles: |theta0| from 5e-324 (subnormal) to 1e300, and 0;
* omega0 from 1e-150 to 1e150 (and 1);
* pushes |theta0'| from 1e-300 to 1e150, and 0;
* times from 1e-300 of a quarter period up to the documented limit, 2**26 quarter periods
  (Motion.theta), and |omega0 t| < 1e290;
* the top and the bottom: k * math.pi and the double nearest k pi, odd and even k up to 2**52,
  and their neighbours one ulp away;
* the separatrix: theta0' = 2 omega0 cos(theta0/2) (1 + eps), eps = 0 or |eps| from 1e-17 to
  0.1; and states that a continued fraction puts within ~1e-32 of it (theta0' / (2 omega0)
  the best rational approximation of cos(theta0/2) with 53-bit numerator and denominator);
* mixed batches of all of these in one array call.

Properties: (1) theta within C_SIZE ulp of max(size, |theta|) (size = the amplitude, pi for
III and IV) and within C_POINT ulp of itself (where |theta| >= 1e-3 size; nearer 0 in II and
III too);
theta' within C_SPEED ulp of its maximum 2 omega0 k (on the separatrix also of itself, up to
the conditioning 2 + omega0 |t|); rest and the balanced top exactly; the regime exactly;
(2) no floating-point event or warning (tests.strict.quietly); (3) outside the documented
domain a ValueError that names the parameter, never a NaN or an infinity; (4) each state of a
batch gives the bits of the same state alone, and of the scalar path (the sign of zero too).

The docstrings promise no number of ulp for theta(t): the bounds are "a few ulp" (see
C_SIZE). Run time: about 100 s of mpmath when every property holds (a few seconds while the
search still stops at its first failures); the worst errors found are printed by the last test.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

import elliptic_pendulum as ep
from tests.mpref import Exact
from tests.strict import quietly

pytestmark = pytest.mark.slow

# theta within C_SIZE ulp of max(size, |theta|), and within C_POINT ulp of |theta| itself where
# |theta| >= 1e-3 size (between size/64 and size the error is a few ulp of the size, up to 64
# ulp of |theta|); below, in II and III too (redo.direct evaluates theta near 0 again, for
# full relative accuracy, in II; (28) is relatively accurate), but only recorded in IV (after
# a turn, theta near 0 is N pi + 2 am, which cancels); theta' within C_SPEED ulp of 2 omega0 k,
# and on the separatrix (where it decays like exp(-omega0 |t|)) within C_SPEED (2 + omega0 |t|)
# ulp of itself. The docstrings promise no number of ulp: "a few". Measured over the search on
# the states that pass (2026): theta 3 ulp of the size, 66 ulp of itself, theta' 6 ulp.
C_SIZE = 4.0
C_POINT = 256.0
C_SPEED = 8.0
# The quarter periods of the documented limit of t (Motion.theta: 2**26), with a margin of a
# few quarters for the phase at t = 0 on either side.
QUARTERS = 2.0**26
# The documented limit of the double-double classification (docs/design.md, "Never lose the
# energy"; classify.classify): c - |w| carries an absolute error of up to GAP_ERROR (measured
# 2.3e-32 against mpmath), so kc^2 = (c - |w|)(c + |w|) the relative error
# cond = GAP_ERROR / |c - |w||, the modulus' complement half of it, K an absolute error of
# about cond / 2 and the phase at t = 0 (up to 2 quarter periods and a remainder) up to about
# 3 cond. After N quarter periods the elliptic argument u is off by up to cond (N + 3); theta
# moves by at most 2k |du| (speed / omega0 |du|) and theta' by at most speed |du|. Where
# cond >= 1 (c and |w| within GAP_ERROR) not even the regime is determined. cond is computed
# from the oracle's exact c - |w| = kc^2 / (c + |w|); off the separatrix it is ~3e-32 and adds
# nothing that a few ulp do not cover.
GAP_ERROR = 3e-32
WORST: dict[str, float] = {}


def conditioning(ex):
    """cond = GAP_ERROR / |c - |w|| of the oracle's state (0 on the exact separatrix)."""
    if ex.kc2 == 0:
        return 0.0  # r = 0 and |w| = 1, or the top at rest: exact doubles, exact arithmetic
    with mpmath.workdps(ex.work + 10):
        return float(GAP_ERROR * (ex.c + abs(ex.w)) / abs(ex.kc2))


def search(n):
    # No shrinking: a failing batch of mpmath references can shrink for minutes; the failures
    # found, shrunk by hand, are the cases of test_found_by_the_search below. The seed is the
    # profile's (tests/conftest.py): derandomized by default, fresh draws with
    # HYPOTHESIS_PROFILE=explore (derandomize=True here overrode the profile, so "explore"
    # drew the very examples of the default run).
    return settings(max_examples=n, deadline=None,
                    phases=(Phase.explicit, Phase.generate),
                    suppress_health_check=list(HealthCheck))


def log_uniform(lo, hi):
    """10**x for x uniform in [lo, hi] (hypothesis shrinks x)."""
    return st.floats(lo, hi).map(lambda x: 10.0**x)


def signed(strategy):
    return st.tuples(st.sampled_from([1.0, -1.0]), strategy).map(lambda p: p[0] * p[1])


tiny_or_far = signed(st.one_of(log_uniform(-300, 300), st.just(5e-324),
                               st.floats(5e-324, 1e-300)))
angles = st.one_of(st.just(0.0), st.just(-0.0), tiny_or_far, st.floats(-10.0, 10.0))
omegas = st.one_of(st.just(1.0), log_uniform(-150, 150))
pushes = st.one_of(st.just(0.0), signed(log_uniform(-300, 150)))


@st.composite
def multiples_of_pi(draw):
    """k * math.pi, or the double nearest k pi, or either's neighbour one ulp away."""
    k = draw(st.one_of(st.integers(-8, 8), st.integers(-2**52, 2**52),
                       st.integers(0, 52).map(lambda e: 2**e + 1)))
    how = draw(st.sampled_from(["float", "nearest"]))
    if how == "float":
        x = k * math.pi
    else:
        with mpmath.workdps(40):
            x = float(k * mpmath.pi)
    step = draw(st.sampled_from([0, 0, 1, -1]))
    for _ in range(abs(step)):
        x = math.nextafter(x, step * math.inf)
    return x


@st.composite
def separatrix_states(draw):
    """(theta0, theta0', omega0) with theta0' = +-2 omega0 cos(theta0/2) (1 + eps)."""
    theta0 = draw(st.one_of(angles, multiples_of_pi()))
    omega0 = draw(omegas)
    eps = draw(st.one_of(st.just(0.0), signed(log_uniform(-17, -1))))
    sign = draw(st.sampled_from([1.0, -1.0]))
    return theta0, sign * 2.0 * omega0 * math.cos(theta0 / 2) * (1.0 + eps), omega0


@st.composite
def continued_fraction_states(draw):
    """theta0' / (2 omega0) = p / q, a convergent of cos(theta0/2) with p, q < 2**53.

    1 - k^2 = (c - |w|)(c + |w|) is then ~ 1/q^2, about 1e-32: at the edge of double-double.
    """
    theta0 = draw(signed(st.one_of(st.floats(0.01, 10.0), log_uniform(0, 300))))
    with mpmath.workdps(60 + max(0, int(math.log10(abs(theta0) + 1)))):
        x = mpmath.mpf(theta0)
        c = abs(mpmath.cos(x / 2))
        if c == 0:
            c = mpmath.mpf(1)
        mant, exp = mpmath.frexp(c)  # c = mant 2**exp, mant in [1/2, 1)
        convergents, a, (p0, q0, p1, q1) = [], mant, (0, 1, 1, 0)
        for _ in range(60):
            n = int(mpmath.floor(a))
            p0, q0, p1, q1 = p1, q1, n * p1 + p0, n * q1 + q0
            if max(p1, q1) >= 2**53:
                break
            convergents.append((p1, q1))
            if a == n:
                break
            a = 1 / (a - n)
    p, q = convergents[-draw(st.integers(1, min(3, len(convergents))))]
    scale = draw(st.integers(-400, 400))
    omega0 = math.ldexp(float(q), scale - 53)
    dtheta0 = draw(st.sampled_from([1.0, -1.0])) * 2.0 * math.ldexp(float(p), scale - 53 + exp)
    if not (1e-150 <= omega0 <= 1e150) or dtheta0 == 0 or not math.isfinite(dtheta0):
        omega0 = math.ldexp(float(q), -53)
        dtheta0 = math.copysign(2.0 * math.ldexp(float(p), exp - 53), dtheta0)
    return theta0, dtheta0, omega0


# A time as (kind, x): "quarters": x quarter periods of the motion (|x| up to 2**26); "rate":
# x / max(omega0, 2 omega0 k) (the time scale of the motion); "zero"; "t": x itself.
times = st.lists(st.one_of(
    st.tuples(st.just("quarters"), signed(log_uniform(-20, math.log10(QUARTERS) - 1e-3))),
    st.tuples(st.just("rate"), signed(log_uniform(-300, 3))),
    st.tuples(st.just("zero"), st.just(0.0))), min_size=1, max_size=3)


def time_of(ex, kind, x):
    if kind == "zero":
        return 0.0
    if kind == "t":
        return x
    if kind == "quarters" and math.isfinite(ex.quarter):
        # stay below the limit: 2**26 quarters less the few of the phase at t = 0
        x = math.copysign(min(abs(x), QUARTERS - 4.0), x)
        t = x * ex.quarter
    else:
        t = x / max(ex.omega0, ex.speed)
    rate = ex.omega0 if ex.regime == "II" else ex.speed / 2.0
    if ex.regime in ("II", "IV"):  # |t| and |rate t| below 1e290 (Motion.theta's ValueError)
        t = math.copysign(min(abs(t), 1e289, 1e289 / rate), t)
    return t


def push_too_small(ex):
    """Near the top a push so small that the modulus' complement is below 1e-300.

    states._chunk refuses it with a ValueError naming dtheta0 ("use dtheta0 = 0 or
    |dtheta0| >= 2e-300 * omega0"), as solve()'s Raises documents.
    """
    return ex.regime in ("II", "IV") and ex.mod_c < 2e-300


def no_double_w(dtheta0, omega0):
    """A push whose w = theta0' / (2 omega0) has no normal double (motion.solve refuses it).

    states._chunk raises a ValueError naming dtheta0 and omega0: |dtheta0 / (2 omega0)|
    must be 0 or at least 2**-1022 (w would underflow to 0, or lose its digits).
    """
    two = 2.0 * omega0
    return dtheta0 != 0 and math.isfinite(two) and abs(dtheta0 / two) < 2.0**-1022


def no_double_k(ex):
    """A swing whose modulus k = sin(theta0/2) has no double (theta0 = +-5e-324 at rest).

    states._chunk raises a ValueError naming theta0: |theta0| must be 0 or at least 1e-323.
    """
    return ex.regime in ("II", "IV") and float(ex.k) == 0.0


def refused(ex):
    return push_too_small(ex) or no_double_w(ex.dtheta0, ex.omega0) or no_double_k(ex)


def record(key, value):
    if value > WORST.get(key, -1.0):
        WORST[key] = value


def ulp(x):
    """The spacing of doubles at |x| (5e-324 at 0: a speed 2 omega0 k that underflows)."""
    return math.ulp(abs(x))


def same_bits(a, b):
    return np.float64(a).tobytes() == np.float64(b).tobytes()


def check(theta0, dtheta0, omega0, spec):
    """Every property for one state: accuracy, silence, the scalar path's bits, errors."""
    ex = Exact(theta0, dtheta0, omega0)
    try:
        m = quietly(ep.solve, theta0, dtheta0, omega0)
    except ValueError as error:
        if no_double_w(dtheta0, omega0):
            assert "dtheta0" in str(error) and "omega0" in str(error), (theta0, error)
        elif no_double_k(ex):
            assert "theta0" in str(error), (theta0, error)
        else:
            assert push_too_small(ex) and "dtheta0" in str(error), (theta0, dtheta0, omega0,
                                                                    error)
        return
    assert not no_double_w(dtheta0, omega0), (theta0, dtheta0, omega0)
    state = (theta0, dtheta0, omega0)
    cond = conditioning(ex)
    determined = m.regime.value == ex.regime
    # within GAP_ERROR of the separatrix the regime may be either neighbour (documented)
    assert determined or (cond >= 1 and {m.regime.value, ex.regime} <= {"II", "III", "IV"}), (
        state, m.regime, ex.regime, cond)
    if not determined:
        record("1 / cond where the regime differs (<= 1)", 1.0 / cond)
    if determined and ex.regime in ("II", "IV") and cond > 0:
        # the modulus' complement to half the relative error of kc^2, the period to cond
        mod_err = abs(m.complementary_modulus - ex.mod_c) / ex.mod_c
        assert mod_err <= 4 * 2.0**-53 + cond / 2, (state, mod_err, cond)
        factor = 4.0 if ex.regime == "II" else 2.0
        per_err = abs(m.period - factor * ex.quarter) / (factor * ex.quarter)
        assert per_err <= 8 * 2.0**-53 + cond, (state, per_err, cond)
        if per_err > 8 * 2.0**-53:
            record("period's rel. error beyond 8 ulp / cond", per_err / cond)
    ts = [time_of(ex, kind, x) for kind, x in spec]
    th_ref, dth_ref = ex.at(ts)
    th, dth = quietly(m.state, np.array(ts))
    assert np.all(np.isfinite(th)) and np.all(np.isfinite(dth)), (state, ts, th, dth)
    for t, a, b, da, db in zip(ts, th, th_ref, dth, dth_ref, strict=True):
        where = (state, t, float(a), float(b), float(da), float(db), cond)
        if ex.still:
            assert a == b and da == 0, where
            continue
        if not determined:  # another motion of the same doubles: only finite, same bits
            continue
        a, b, da, db = float(a), float(b), float(da), float(db)
        # the drift of the elliptic argument that the conditioning allows (GAP_ERROR above)
        quarters = abs(t) / ex.quarter if math.isfinite(ex.quarter) else 0.0
        du = cond * (quarters + 3.0)
        slack_th, slack_dth = ex.speed / ex.omega0 * du, ex.speed * du
        err = abs(a - b) / ulp(max(ex.size, abs(b)))
        assert err <= C_SIZE + slack_th / ulp(max(ex.size, abs(b))), (where, err)
        if du > 1e-20 and abs(a - b) > C_SIZE * ulp(max(ex.size, abs(b))):
            record("theta's error beyond C_SIZE ulp / the drift allowed", abs(a - b) / slack_th)
        else:
            record(f"theta, ulp of max(size, |theta|), {ex.regime}", err)
        if b != 0:  # pointwise, relative: wherever |theta| >= 1e-3 size; nearer 0 in II, III
            point = abs(a - b) / ulp(b)
            near = abs(b) < 1e-3 * ex.size
            if not near or ex.regime in ("II", "III"):
                assert point <= C_POINT + slack_th / ulp(b), (where, point)
            if du <= 1e-20 or abs(a - b) <= C_POINT * ulp(b):
                band = "|theta| < 1e-3 size" if near else "|theta| >= 1e-3 size"
                record(f"theta, ulp of |theta| ({band}), {ex.regime}", point)
        speed_err = abs(da - db) / ulp(ex.speed)
        assert speed_err <= C_SPEED + slack_dth / ulp(ex.speed), (where, speed_err)
        if du > 1e-20 and abs(da - db) > C_SPEED * ulp(ex.speed):
            record("theta''s error beyond C_SPEED ulp / the drift allowed",
                   abs(da - db) / slack_dth)
        else:
            record(f"theta', ulp of 2 omega0 k, {ex.regime}", speed_err)
        if ex.regime == "III":
            # theta' = 2 w0 sech(w0 t + x0) decays: relative to itself, up to the conditioning
            # of sech in its argument, |w0 t| + 2 (test_motion.test_separatrix_is_the_notes_28)
            tail = abs(da - db) / ulp(db) / (2.0 + abs(omega0 * t))
            assert tail <= C_SPEED, (where, tail)
            record("theta', ulp of |theta'| / (2 + |omega0 t|), III", tail)
    # the scalar path (Python floats in, one float time): the array path's bits
    for t, a, da in zip(ts, th, dth, strict=True):
        one = quietly(m.state, float(t))
        assert same_bits(one[0], a) and same_bits(one[1], da), (state, t, one, (a, da))
        assert same_bits(quietly(m.theta, float(t)), a), (state, t)
        assert same_bits(quietly(m.dtheta, float(t)), da), (state, t)
    # beyond the documented limit of t (2**26 of the motion's own quarter periods, which near
    # the separatrix differ from the oracle's by up to cond): a ValueError naming t
    if determined and ex.regime in ("II", "IV") and math.isfinite(ex.quarter):
        quarter = m.period / (4.0 if ex.regime == "II" else 2.0)
        beyond = 1.01 * QUARTERS * quarter + 8 * quarter
        if math.isfinite(beyond):
            with pytest.raises(ValueError, match=r"\bt\b"):
                quietly(m.theta, beyond)
            with pytest.raises(ValueError, match=r"\bt\b"):
                quietly(m.state, np.array([0.0, -beyond]))


@search(2000)
@given(angles, pushes, omegas, times)
def test_far_and_tiny_states_match_mpmath(theta0, dtheta0, omega0, spec):
    check(theta0, dtheta0, omega0, spec)


@search(1000)
@given(multiples_of_pi(), st.one_of(st.just(0.0), st.just(-0.0), pushes), omegas, times)
def test_top_and_bottom_match_mpmath(theta0, dtheta0, omega0, spec):
    check(theta0, dtheta0, omega0, spec)


@search(600)
@given(separatrix_states(), times)
def test_near_the_separatrix_matches_mpmath(state, spec):
    check(*state, spec)


@search(400)
@given(continued_fraction_states(), times)
def test_within_1e_32_of_the_separatrix_matches_mpmath(state, spec):
    check(*state, spec)


# --- batches ---------------------------------------------------------------------------------

any_state = st.one_of(
    st.tuples(angles, pushes, omegas),
    st.tuples(multiples_of_pi(), st.one_of(st.just(0.0), pushes), omegas),
    separatrix_states(),
    st.tuples(st.floats(-10.0, 10.0), st.floats(-5.0, 5.0), st.just(1.0)))

PUBLIC = ("energy_constant", "modulus", "complementary_modulus", "amplitude", "phase",
          "direction", "period", "theta0", "dtheta0", "omega0")


@search(500)
@given(st.lists(st.tuples(any_state, signed(log_uniform(-300, 2))), min_size=2, max_size=12))
def test_a_mixed_batch_gives_each_state_its_bits_alone(rows):
    # ONE array call on states of every family (each at its own time, x / max(omega0,
    # 2 omega0 k) so that it stays within the limit); each element has the bits of the same
    # state alone (0-d arrays: the array path) and of the scalar path (Python floats),
    # the sign of zero included; the caller's arrays may change afterwards.
    states, ts = [], []
    for (theta0, dtheta0, omega0), x in rows:
        ex = Exact(theta0, dtheta0, omega0, dps=20)
        if refused(ex):  # refused alone (ValueError, dtheta0): not in a batch
            continue
        states.append((theta0, dtheta0, omega0))
        ts.append(time_of(ex, "rate", x))
    if not states:
        return
    th0, v0, w0 = (np.array(column) for column in zip(*states, strict=True))
    t = np.array(ts)
    many = quietly(ep.solve, th0, v0, w0)
    theta, dtheta = quietly(many.state, t)
    for i, (state, time) in enumerate(zip(states, ts, strict=True)):
        alone = quietly(ep.solve, *(np.float64(x) for x in state))
        a_th, a_dth = quietly(alone.state, np.float64(time))
        one = quietly(ep.solve, *(float(x) for x in state))
        s_th, s_dth = quietly(one.state, float(time))
        where = (state, time, float(theta[i]), float(a_th), s_th)
        assert same_bits(theta[i], a_th) and same_bits(dtheta[i], a_dth), where
        assert same_bits(theta[i], s_th) and same_bits(dtheta[i], s_dth), where
        row = many[i]
        assert row.regime is alone.regime is one.regime, where
        for name in PUBLIC:
            b, a, s = (getattr(x, name) for x in (row, alone, one))
            assert same_bits(b, a) and same_bits(b, s), (where, name, b, a, s)
    kept = [x.copy() for x in (th0, v0, w0, t)]
    for x in (th0, v0, w0, t):  # the Motion must not alias its caller's arrays
        x[...] = 0.25
    again = quietly(many.state, kept[3])
    np.testing.assert_array_equal(again[0], theta)
    np.testing.assert_array_equal(again[1], dtheta)
    for x, name in zip(kept[:3], ("theta0", "dtheta0", "omega0"), strict=True):
        np.testing.assert_array_equal(getattr(many, name), x, err_msg=name)


# --- outside the documented domain -----------------------------------------------------------

bad_numbers = st.sampled_from([math.nan, math.inf, -math.inf])


@search(400)
@given(st.data())
def test_outside_the_domain_a_value_error_names_the_parameter(data):
    # solve(): NaN and infinities (each parameter), omega0 <= 0, and an energy constant beyond
    # the doubles (|theta0'| >= 1.4e154 or omega0 >= 9.5e153); Motion.theta: t NaN, infinite or
    # beyond 2**26 quarter periods (or |omega0 t| >= 1e290). Each a ValueError naming the
    # parameter, in the scalar and the array path alike.
    theta0, dtheta0, omega0 = data.draw(angles), data.draw(pushes), data.draw(omegas)
    which = data.draw(st.sampled_from(["theta0", "dtheta0", "omega0", "omega0<=0",
                                       "energy dtheta0", "energy omega0", "t"]))
    if which in ("theta0", "dtheta0", "omega0"):
        bad = data.draw(bad_numbers)
        state = {"theta0": theta0, "dtheta0": dtheta0, "omega0": omega0} | {which: bad}
        name = which
    elif which == "omega0<=0":
        state = {"theta0": theta0, "dtheta0": dtheta0,
                 "omega0": data.draw(st.one_of(st.just(0.0), st.just(-0.0),
                                               signed(log_uniform(-300, 300)).map(
                                                   lambda x: -abs(x))))}
        name = "omega0"
    elif which == "energy dtheta0":
        state = {"theta0": theta0, "dtheta0": data.draw(signed(log_uniform(154.2, 308))),
                 "omega0": data.draw(log_uniform(-150, 150))}
        name = "dtheta0"
    elif which == "energy omega0":
        state = {"theta0": theta0, "dtheta0": data.draw(st.one_of(st.just(0.0),
                                                                   signed(log_uniform(-300, 0)))),
                 "omega0": data.draw(log_uniform(154.0, 308))}
        name = "omega0"
    else:
        state, name = {"theta0": theta0, "dtheta0": dtheta0, "omega0": omega0}, "t"
    for convert in (float, np.array):
        args = {key: convert(value) for key, value in state.items()}
        if name != "t":
            with pytest.raises(ValueError, match=rf"\b{name}\b"):
                quietly(ep.solve, **args)
            continue
        ex = Exact(theta0, dtheta0, omega0, dps=20)
        if refused(ex):
            return
        m = quietly(ep.solve, **args)
        t = data.draw(st.one_of(bad_numbers, st.just(1e300) if ex.regime in ("II", "IV")
                                else bad_numbers))
        with pytest.raises(ValueError, match=r"\bt\b"):
            quietly(m.theta, convert(t))
        with pytest.raises(ValueError, match=r"\bt\b"):
            quietly(m.state, convert(t))


# --- the failures found by the search, one by one ----------------------------------------------
# Each of these failed when the search was written (the first six are known and being fixed
# on another branch; the rest are new); once fixed, each passes as it stands.

with mpmath.workdps(40):
    _NEAREST_2_52_PLUS_1_PI = float((2**52 + 1) * mpmath.pi)
    # the largest odd multiple of pi below 2**50: still the top (docs/conventions.md)
    _NEAREST_BELOW_2_50 = float((2 * int(2**50 / mpmath.pi / 2) - 1) * mpmath.pi)


@pytest.mark.parametrize(("theta0", "dtheta0", "omega0", "t"), [
    # known, being fixed elsewhere
    pytest.param(math.pi, 1e-200, 1.0, 500.0, id="top-tiny-push"),
    pytest.param(2 * math.pi, 0.0, 1.0, 1.0, id="even-multiple-bottom"),
    pytest.param(-12.566370614359172, -3.98741195992232e-13, 1.0, -1.5707963267948966,
                 id="even-multiple-push"),
    pytest.param(0.0, 2.0, 1.0, 1e-20, id="separatrix-near-0"),
    pytest.param(0.0, 2.0, 1.0, 400.0, id="separatrix-large-t"),
    pytest.param(1e-310, 0.0, 1.0, 1.0, id="subnormal-angle"),
    # new
    pytest.param(-13 * math.pi, 0.0, 1.0, 50.0, id="odd-multiple-13"),
    pytest.param(-34.55751918948773, 0.0, 1.0, 50.0, id="odd-multiple-11"),
    # beyond 2**50 every double is itself (the documented convention; the oracle had 2**54)
    pytest.param(_NEAREST_2_52_PLUS_1_PI, 0.0, 1.0, 1.0, id="odd-multiple-beyond-2**50"),
    pytest.param(_NEAREST_BELOW_2_50, 0.0, 1.0, 1.0, id="odd-multiple-below-2**50"),
    pytest.param(1e-200, 2.0, 1.0, 1000.0, id="tiny-angle-beside-separatrix"),
    pytest.param(8.892898100017254e-42, 2.1800754380841732e-106, 1.0900377190420866e-106, 1.0,
                 id="small-angle-beside-separatrix"),
    pytest.param(0.0, 1e-250, 1e100, 0.0, id="tiny-push-huge-omega0"),
    pytest.param(0.0, 1e-300, 1e10, 0.0, id="subnormal-w"),
    pytest.param(-0.0, 0.0, 1.0, 1.0, id="rest-at-minus-zero"),
    pytest.param(53.40707511102648, -0.0, 1.0, 0.0, id="top-minus-zero-push"),
    pytest.param(5.2572380368982775e-05, -5.3249354027958094e-294, 1.1041687988883575e+40, 0.0,
                 id="minus-zero-speed"),
    pytest.param(-1.0, 2 * math.cos(0.5), 1.0, 421589.5148433658, id="one-ulp-from-separatrix"),
    pytest.param(7.682718547527642, 73689520.13397965, 48163556.37363873, 20.019202626361906,
                 id="near-separatrix-5e7-quarters"),
    pytest.param(109883.48624461019, -7.477336706619348e-12, 1.0, -45.76551800471442,
                 id="near-top-far-angle"),
    pytest.param(-3.815802432347169, -1.9981310347920427e-46, 3.020548539929703e-46, 1.0,
                 id="1e-33-from-separatrix-regime"),
    pytest.param(3.208060089907315, 3323332.8074038737, 50008618.197319925,
                 -7.919827275620904e-05, id="1e-34-from-separatrix-phase"),
    # a subnormal theta0 / 2 had lost bits before omega0 multiplied it (test_tiny_states)
    pytest.param(-2.2e-313, 0.0, 6.186400751363438e+32, -1.616448788545759e-33,
                 id="subnormal-half-angle-huge-omega0"),
    # k^2 underflowed: the phase's branch took a tiny swing for one at its turning point
    pytest.param(1e-200, 2e-170, 1.0, -5.025e-31, id="tiny-swing-beside-zero"),
])
def test_found_by_the_search(theta0, dtheta0, omega0, t):
    check(theta0, dtheta0, omega0, [("t", t)])


@pytest.mark.parametrize(("theta0", "dtheta0", "omega0"), [
    pytest.param([1e-310, 0.0], [0.0, 3.0], [1.0, 1.0], id="tiny-swing-beside-rotation"),
    pytest.param([-0.0, 0.5], [0.0, 0.0], [1.0, 1.0], id="rest-at-minus-zero"),
])
def test_batches_found_by_the_search(theta0, dtheta0, omega0):
    rows = [((a, b, c), 1.0) for a, b, c in zip(theta0, dtheta0, omega0, strict=True)]
    test_a_mixed_batch_gives_each_state_its_bits_alone.hypothesis.inner_test(rows)


def test_a_motion_does_not_alias_its_callers_arrays():
    theta0, dtheta0 = np.array([1.0, 2.0]), np.array([0.5, 0.0])
    m = ep.solve(theta0, dtheta0)
    before = m.state(np.array([1.0, 1.0]))
    theta0[...], dtheta0[...] = 0.25, 3.0
    np.testing.assert_array_equal(m.theta0, [1.0, 2.0])
    np.testing.assert_array_equal(m.dtheta0, [0.5, 0.0])
    np.testing.assert_array_equal(m.state(np.array([1.0, 1.0])), before)


def test_zz_report_worst_errors(capsys):
    with capsys.disabled():
        for name, value in sorted(WORST.items()):
            print(f"\n  worst {name}: {value:.3g}", end="")
