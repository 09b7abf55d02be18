"""The command line under hostile input: one line on stderr and status 2, never a traceback.

The contract is docs/cli.md's "Errors and exit status"; values are compared with mpmath or
with the library's own documented output. Calls are in-process (cli.main), under every
floating-point trap and warning turned into an error."""

import math

import pytest

from elliptic_pendulum.cli import main
from tests import mpref
from tests.strict import quietly as _silently


def _cli_fails(capsys, *argv):
    """Run the CLI in-process; docs/cli.md promises exit status 2, nothing on stdout and one
    line on stderr for a bad argument. Returns that line."""
    with pytest.raises(SystemExit) as info:
        _silently(main, list(argv))
    out, err = capsys.readouterr()
    assert info.value.code == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "error:" in lines[0]
    return lines[0]


def _cli_runs(capsys, *argv):
    status = _silently(main, list(argv))
    out, err = capsys.readouterr()
    assert status == 0 and err == ""
    return out.splitlines()


@pytest.mark.parametrize("times", [("0", "1e300", "1e-300"), ("-1e308", "1e308", "1e307"),
                                   ("0", "1", "1e-320"), ("0", "1e-10", "-1e-320")])
def test_cli_times_that_overflow_fail_in_one_line(capsys, times):
    # These raised OverflowError (math.floor of inf) or an overflow in step * k: a traceback
    # and status 1.
    _cli_fails(capsys, "solve", "--theta0", "170", "--t", *times)


@pytest.mark.parametrize("argv", [("crossing", "1", "1e-3"), ("crossing", "2", "3", "nan"),
                                  ("period", "0", "170", "--omega0", "3.6e-308")])
def test_cli_checks_every_value_before_printing_any(capsys, argv):
    # The last value is refused by the library (R < 1; NaN; a period of 170 degrees beyond
    # the doubles at this omega0, while that of 0 degrees, 2 pi / 3.6e-308, is not); the
    # answers for the good ones used to be printed first, then the error.
    line = _cli_fails(capsys, *argv)
    assert "value" in line or "omega0" in line


@pytest.mark.parametrize("typed", ["179.9999", "179.99999999999997", "90", "1e-05", "0.1",
                                   "33.333333333333336"])
def test_cli_period_label_reads_back_as_the_amplitude(capsys, typed):
    # The label must name the amplitude that was computed: read back, it is the same double
    # ('{:g}' printed 179.9999 as "R(180 deg)", the one amplitude the command refuses).
    import re

    (line,) = _cli_runs(capsys, "period", typed)
    label = re.fullmatch(r"R\((\S+) deg\) = \d+\.\d{6}", line).group(1)
    assert float(label) == float(typed)


@pytest.mark.parametrize("typed", ["3.0000000000000004", "2.123456789", "23.6"])
def test_cli_crossing_label_reads_back_as_the_value(capsys, typed):
    import re

    (line,) = _cli_runs(capsys, "crossing", typed)
    label = re.fullmatch(r"R = (\S+) at theta0 = \d+\.\d{9} deg", line).group(1)
    assert float(label) == float(typed)


def test_cli_degrees_are_converted_to_the_nearest_double():
    # Reference: mpmath at 60 digits, rounded once to a double. math.radians rounds twice
    # (pi / 180, then the product) and misses the nearest double for about one angle in nine,
    # among them multiples of 180 degrees (3960 = 11 turns).
    import random

    import mpmath

    from elliptic_pendulum import cli

    ctx = mpmath.MPContext()
    ctx.dps = 60
    rng = random.Random(20240611)
    angles = [180.0 * n for n in range(-50, 200)] + [rng.uniform(-1e4, 1e4) for _ in range(500)]
    angles += [1e-320, 5e-324, 1e308, -1e308, 179.9999, 33.333333333333336]
    for degrees in angles:
        assert cli._radians(degrees) == float(ctx.mpf(degrees) * ctx.pi / 180), degrees
    assert cli._radians(360.0) == 2 * math.pi  # 2 * (the double nearest pi) is exact


@pytest.mark.parametrize("degrees", ["180", "540", "-180"])
def test_cli_odd_multiples_of_180_degrees_are_the_top(capsys, degrees):
    # Released at rest upside down: the separatrix (regime III), as docs/cli.md shows for 180.
    lines = _cli_runs(capsys, "solve", "--theta0", degrees, "--t", "0", "1", "1")
    assert lines[0] == "# regime III (separatrix), period infinite"


@pytest.mark.parametrize("degrees", ["360", "720", "1080", "-360"])
def test_cli_even_multiples_of_180_degrees_are_the_bottom(capsys, degrees):
    # Released at rest hanging straight down, as for 0 degrees: regime I (rest), whatever the
    # number of turns the angle counts.
    lines = _cli_runs(capsys, "solve", "--theta0", degrees, "--t", "0", "1", "1")
    assert lines[0] == _cli_runs(capsys, "solve", "--theta0", "0", "--t", "0", "1", "1")[0]
    assert lines[0].startswith("# regime I (rest)")


def test_cli_swing_whose_period_overflows_is_not_called_infinite(capsys):
    # At omega0 = 1e-320 the period 4 K(sin 15 deg) / omega0 (mpmath) is finite, 6.4e320, but
    # beyond the doubles; "infinite" is what docs/cli.md reserves for the separatrix.
    assert math.isfinite(float(mpref.period(math.radians(30), 1e-320) / 1e300))
    lines = _cli_runs(capsys, "solve", "--theta0", "30", "--omega0", "1e-320", "--t", "0", "1", "1")
    assert lines[0].startswith("# regime II (libration), period ")
    assert "infinite" not in lines[0] and "largest double" in lines[0]


def test_cli_a_subnormal_push_fails_in_one_line(capsys):
    # 1e-320 deg/s is a subnormal rad/s: w = dtheta0 / (2 omega0) has no normal double, and
    # solve() refuses it (naming dtheta0 and omega0) rather than lose theta'.
    assert "dtheta0" in _cli_fails(capsys, "solve", "--theta0", "30", "--dtheta0", "1e-320")


@pytest.mark.parametrize("argv", [("--theta0", "1e-320"), ("--theta0", "30", "--dtheta0", "1e-305"),
                                  ("--theta0", "30", "--length", "1", "--g", "1e-320"),
                                  ("--theta0", "30", "--t", "1e-320", "1", "1")])
def test_cli_tiny_angles_and_rates_print_quietly(capsys, argv):
    # Subnormal angles or rates converted to degrees underflow; they print as 0.000000000
    # (rounded to nine decimals) all the same, so no FloatingPointError under errstate(raise).
    lines = _cli_runs(capsys, "solve", *argv)
    assert lines[0].startswith("# regime")


def test_cli_refuses_a_grid_of_more_than_the_documented_rows(capsys):
    # -1e308..1e308 by 1e303 is 200,001 rows: printed (in seconds) before; docs/cli.md says
    # at most 100,000. One line naming --t, status 2, no traceback.
    line = _cli_fails(capsys, "solve", "--theta0", "0", "--dtheta0", "114.59155902616465",
                      "--t", "-1e308", "1e308", "1e303")
    assert "--t" in line and "at most 100,000 rows" in line and "200,001" in line
    _cli_fails(capsys, "solve", "--theta0", "30", "--t", "0", "100000", "1")  # 100,001 rows
    assert len(_cli_runs(capsys, "solve", "--theta0", "30", "--t", "0", "99999", "1")) == 100_002


@pytest.mark.parametrize("argv, column, expected", [
    # Times of 1e308 printed as 309-digit integers; the grid -1e308 + k 1e306 is the exact
    # double sum (the times the library evaluates), read back from the printed text.
    (("--theta0", "0", "--dtheta0", "114.59155902616465", "--t", "-1e308", "1e308", "1e306"),
     0, [-1e308 + k * 1e306 for k in range(201)]),
    # A push of 1e150 deg/s printed as a 151-digit number: at t = 0, theta' is the push.
    (("--theta0", "0", "--dtheta0", "1e150", "--t", "0", "0", "1"), 2, [1e150]),
])
def test_cli_huge_values_print_in_scientific_notation(capsys, argv, column, expected):
    rows = [line.split() for line in _cli_runs(capsys, "solve", *argv)[2:]]
    assert all(len(line) < 80 for line in map(" ".join, rows))
    got = [float(row[column]) for row in rows]
    assert len(got) == len(expected)
    assert all(abs(g - e) <= 4 * math.ulp(e) for g, e in zip(got, expected, strict=True))
    assert all("e+" in row[column] for row in rows if abs(float(row[column])) >= 1e15)
