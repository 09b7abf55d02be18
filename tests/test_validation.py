"""Bad input, broadcasting and return types of the public functions.

Out-of-domain input is refused naming the parameter and its range; array-likes broadcast.

Out-of-domain input raises ValueError naming the parameter and its range; a non-number raises
TypeError naming the parameter. Scalars in give Python floats out; arrays broadcast.
"""

import math

import numpy as np
import pytest

import elliptic_pendulum as ep
from elliptic_pendulum import am, cn, dn, jacobi, sn

JACOBI = [sn, cn, dn, am, jacobi]
NON_FINITE = [math.nan, math.inf, -math.inf, np.float64("nan")]
NON_REAL = ["1.0", b"1", None, True, False, np.bool_(True), 1 + 2j, np.complex128(1.0),
            object(), [1.0, "a"]]


@pytest.mark.parametrize("f", JACOBI)
@pytest.mark.parametrize("bad", NON_FINITE)
def test_jacobi_non_finite_u(f, bad):
    with pytest.raises(ValueError, match=r"\bu\b.*finite"):
        f(bad, 0.5)
    with pytest.raises(ValueError, match=r"\bu\b"):
        f([0.0, bad], 0.5)


@pytest.mark.parametrize("f", JACOBI)
@pytest.mark.parametrize("bad", NON_FINITE)
def test_jacobi_non_finite_modulus(f, bad):
    with pytest.raises(ValueError, match=r"\bk\b"):
        f(0.3, bad)
    with pytest.raises(ValueError, match=r"\bkc\b"):
        f(0.3, 1.0, kc=bad)


@pytest.mark.parametrize("f", JACOBI)
@pytest.mark.parametrize("bad", NON_REAL)
def test_jacobi_non_real_arguments(f, bad):
    with pytest.raises(TypeError, match=r"\bu\b"):
        f(bad, 0.5)
    with pytest.raises(TypeError, match=r"\bk\b"):
        f(0.5, bad)
    if bad is not None:  # kc=None is the documented default: "use k"
        with pytest.raises(TypeError, match=r"\bkc\b"):
            f(0.5, 1.0, kc=bad)


@pytest.mark.parametrize("f", JACOBI + [ep.complete_integral])
@pytest.mark.parametrize("bad", [-1e-300, -0.5, 1.0000000000000002, 2.0, [0.5, 1.5]])
def test_modulus_out_of_range_names_k_and_its_range(f, bad):
    # kc must lie in [0, 1]. k itself: everything is even in k, so a negative k
    # is |k|; the Jacobi functions take |k| > 1 by the reciprocal modulus (test_edges.py);
    # K1 refuses |k| > 1 (complex there), naming k and its range.
    args = () if f is ep.complete_integral else (0.3,)
    if f is ep.complete_integral and np.any(np.abs(bad) > 1):
        with pytest.raises(ValueError, match=r"\bk\b.*\[-1, 1\]"):
            f(*args, bad)
    with pytest.raises(ValueError, match=r"\bkc\b.*\[0, 1\]"):
        f(*args, 1.0, kc=bad)


def test_incomplete_integral_outside_unit_interval():
    with pytest.raises(ValueError, match=r"\bz\b.*\[-1, 1\]"):
        ep.incomplete_integral(1.0000000000000002, 0.5)
    with pytest.raises(ValueError, match=r"\bz\b.*\[-1, 1\]"):
        ep.incomplete_integral([0.0, -2.0], 0.5)
    with pytest.raises(ValueError, match=r"\bz\b"):
        ep.incomplete_integral(math.nan, 0.5)
    with pytest.raises(TypeError, match=r"\bz\b"):
        ep.incomplete_integral("0.5", 0.5)


def test_inverse_integral_outside_its_interval():
    K = ep.complete_integral(0.5)
    with pytest.raises(ValueError, match=r"\bu\b.*K1"):
        ep.inverse_integral(np.nextafter(K, 10.0), 0.5)
    with pytest.raises(ValueError, match=r"\bu\b.*K1"):
        ep.inverse_integral(-1.01 * K, 0.5)
    assert ep.inverse_integral(K, 0.5) == 1.0


@pytest.mark.parametrize("name", ["theta0", "dtheta0"])
def test_solve_bad_initial_state(name):
    for bad in NON_FINITE:
        with pytest.raises(ValueError, match=name):
            ep.solve(**{"theta0": 0.1, name: bad})
    for bad in ["0.1", None, True, 1j]:
        with pytest.raises(TypeError, match=name):
            ep.solve(**{"theta0": 0.1, name: bad})
    # Arrays of states broadcast; a bad element is named like a bad scalar.
    for bad in NON_FINITE:
        with pytest.raises(ValueError, match=name):
            ep.solve(**{"theta0": [0.1, 0.2], name: [0.1, bad]})
    other = "dtheta0" if name == "theta0" else "theta0"
    with pytest.raises(ValueError, match="broadcast"):
        ep.solve(**{other: [0.1, 0.2, 0.3], name: [0.1, 0.2]})


@pytest.mark.parametrize("bad", [0.0, -0.0, -1.0, math.nan, math.inf, -math.inf])
def test_solve_omega0_must_be_positive_and_finite(bad):
    with pytest.raises(ValueError, match=r"omega0.*> 0"):
        ep.solve(0.1, 0.0, bad)


@pytest.mark.parametrize("bad", ["1", None, True, 1j, ["1.0"]])
def test_solve_omega0_type(bad):
    with pytest.raises(TypeError, match="omega0"):
        ep.solve(0.1, 0.0, bad)


@pytest.mark.parametrize("state", [(0.5, 0.0), (0.0, 2.0), (0.0, 3.0), (0.0, 0.0), (math.pi, 0.0)])
def test_motion_rejects_bad_times(state):
    m = ep.solve(*state)
    for method in (m.theta, m.dtheta):
        with pytest.raises(ValueError, match=r"\bt\b.*finite"):
            method(math.nan)
        with pytest.raises(ValueError, match=r"\bt\b"):
            method(np.array([0.0, math.inf]))
        with pytest.raises(TypeError, match=r"\bt\b"):
            method("1.0")
        with pytest.raises(TypeError, match=r"\bt\b"):
            method(None)


# --- return types and broadcasting ------------------------------------------------------

@pytest.mark.parametrize("f", [sn, cn, dn, am, ep.incomplete_integral, ep.inverse_integral])
def test_scalar_in_python_float_out(f):
    for u in (0.3, 1, np.float64(0.3), np.float32(0.3), np.int64(0), np.array(0.3)):
        out = f(u, 0.5)
        assert type(out) is float
    assert type(f(0.3, 0.5, kc=0.8)) is float
    assert type(ep.complete_integral(0.5)) is float
    s, c, d = jacobi(0.3, 0.5)
    assert type(s) is float and type(c) is float and type(d) is float


@pytest.mark.parametrize("f", [sn, cn, dn, am])
def test_array_in_same_shape_out(f):
    for shape in [(0,), (1,), (5,), (2, 3), (2, 1, 4)]:
        u = np.linspace(-3, 3, int(np.prod(shape))).reshape(shape)
        out = f(u, 0.7)
        assert isinstance(out, np.ndarray) and out.shape == shape and out.dtype == float
    assert f([0.1, 0.2], 0.7).shape == (2,)


def test_modulus_array_broadcasts_with_u():
    u = np.linspace(0.1, 2.0, 4)[:, None]
    k = np.array([0.0, 0.5, 0.9])
    s, c, d = jacobi(u, k)
    assert s.shape == c.shape == d.shape == (4, 3)
    for j, kj in enumerate(k):
        np.testing.assert_array_equal(s[:, j], sn(u[:, 0], kj))
    # a scalar u with an array modulus gives an array, k by keyword kc too
    assert sn(0.4, k).shape == (3,)
    kc = np.array([1.0, 1e-10, 0.0])
    assert dn(u, 1.0, kc=kc).shape == (4, 3)
    np.testing.assert_array_equal(dn(0.4, 1.0, kc=kc)[2], 1 / np.cosh(0.4))
    assert ep.complete_integral(k).shape == (3,)


def test_motion_return_types():
    for state in [(0.5, 0.0), (0.0, 2.0), (0.0, 3.0), (0.0, 0.0), (math.pi, 0.0)]:
        m = ep.solve(*state)
        assert type(m.theta(1.0)) is float and type(m.dtheta(1)) is float
        t = np.zeros((2, 3))
        assert m.theta(t).shape == (2, 3) and m.dtheta(t).shape == (2, 3)
        assert m.theta([0.0, 1.0]).shape == (2,)
        assert isinstance(m.period, float) and isinstance(m.energy_constant, float)


def test_solve_accepts_numpy_and_integer_scalars():
    a = ep.solve(np.float64(0.5), np.int64(0), np.float32(2.0))
    b = ep.solve(0.5, 0.0, float(np.float32(2.0)))
    assert a.theta(1.3) == b.theta(1.3)
    assert ep.solve(1, 0, 1).regime is ep.Regime.LIBRATION


# --- from the second review: inputs past the range of doubles, arguments past exact reduction --

@pytest.mark.parametrize("call", [
    lambda: ep.sn(10**400, 0.5), lambda: ep.sn([10**400], 0.5),
    lambda: ep.solve(10**400), lambda: ep.solve(0.0, 10**400)])
def test_python_ints_beyond_doubles_raise_valueerror(call):
    # float(10**400) raises OverflowError; the library reports a ValueError naming the parameter.
    with pytest.raises(ValueError, match="finite"):
        call()


@pytest.mark.parametrize(("call", "name"), [
    (lambda: ep.sn(1e12, 0.5), "u"), (lambda: ep.jacobi(1e19, 1.0, kc=1e-300), "u"),
    (lambda: ep.solve(1.0).theta(1e12), "t"),
    (lambda: ep.solve(0.5, 0.0, 1e-300).theta(6e300), "t")])
def test_arguments_past_exact_reduction_raise(call, name):
    # Beyond 2**26 quarter periods n K1 is no longer exact: an error, not digits that are not there.
    with pytest.raises(ValueError, match=f"^{name} is too large"):
        call()
