"""Tests of the command line (cli.py), run in-process through main(argv).

Expectations come from the note (its table and crossing angles, section 4), from mpmath for
the six-decimal values, and from argparse's contract: exit status 2 and one line on stderr.
"""

import math
import subprocess
import sys

import mpmath
import pytest

import elliptic_pendulum as ep
from elliptic_pendulum.cli import main
from tests import mpref


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def fail(capsys, *argv):
    with pytest.raises(SystemExit) as info:
        main(list(argv))
    out, err = capsys.readouterr()
    assert info.value.code == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    return lines[0]




def test_table_has_the_notes_values_and_six_decimals(capsys):
    status, out, err = run(capsys, "table")
    assert status == 0 and err == ""
    rows = [line.split() for line in out.strip().splitlines()[1:]]
    note = {30: "1.017", 45: "1.040", 60: "1.073", 90: "1.180", 120: "1.373", 135: "1.528",
            150: "1.762"}  # section 4 of the note
    assert [int(r[0]) for r in rows] == list(note)
    for degrees, ratio, printed_note in rows:
        assert printed_note == note[int(degrees)]
        assert ratio == mpmath.nstr(mpref.ratio_degrees(int(degrees)), 7, strip_zeros=False)
        assert f"{float(ratio):.3f}" == printed_note


def test_period_ratio_and_period(capsys):
    status, out, _ = run(capsys, "period", "120")
    assert status == 0
    assert out.strip() == f"R(120 deg) = {float(mpref.ratio_degrees(120)):.6f}"
    _, out, _ = run(capsys, "period", "120", "--omega0", "2")
    expected = 4 * float(mpmath.ellipk(mpmath.sin(mpmath.radians(60)) ** 2)) / 2  # (26)
    assert f"period = {expected:.6g} s" in out
    _, out, _ = run(capsys, "period", "90", "--length", "1", "--g", "9.80665")
    expected = 4 * float(mpmath.ellipk(0.5)) * math.sqrt(1 / 9.80665)
    assert f"period = {expected:.6g} s" in out
    assert f"small-angle period = {2 * math.pi * math.sqrt(1 / 9.80665):.6g} s" in out
    _, out, _ = run(capsys, "period", "0", "30")
    assert len(out.strip().splitlines()) == 2


def test_crossing_angles(capsys):
    status, out, _ = run(capsys, "crossing", "2", "3", "4")
    assert status == 0
    angles = [float(line.split("=")[2].split()[0]) for line in out.strip().splitlines()]
    # The note: R exceeds 2, 3, 4 "at" 160, 176, 179.2 degrees (first grid angle past the root).
    for angle, note, step in zip(angles, [160, 176, 179.2], [1, 1, 0.1], strict=True):
        assert note - step < angle < note
    for value, angle in zip([2, 3, 4], angles, strict=True):  # mpmath checks the 9 printed decimals
        with mpmath.workdps(30):
            assert abs(mpref.ratio_degrees(mpmath.mpf(angle)) - value) < 1e-7


def test_solve_columns_in_degrees_and_radians(capsys):
    status, out, _ = run(capsys, "solve", "--theta0", "170", "--t", "0", "10", "0.5")
    assert status == 0
    lines = out.strip().splitlines()
    assert lines[0].startswith("# regime II")
    rows = [list(map(float, line.split())) for line in lines[2:]]
    assert len(rows) == 21 and rows[0] == [0.0, 170.0, 0.0] and rows[-1][0] == 10.0
    # Energy (9) in degrees: (theta')^2 - 2 cos(theta) stays at -2 cos(170 deg) with omega0 = 1.
    for _, theta, dtheta in rows:
        c1 = math.radians(dtheta) ** 2 - 2 * math.cos(math.radians(theta))
        assert c1 == pytest.approx(-2 * math.cos(math.radians(170)), abs=1e-7)
    _, out, _ = run(capsys, "solve", "--theta0", "1", "--rad", "--t", "0", "1", "0.25",
                    "--omega0", "3")
    rows = [list(map(float, line.split())) for line in out.strip().splitlines()[2:]]
    assert rows[0][1] == 1.0 and len(rows) == 5
    for _, theta, dtheta in rows:
        assert dtheta**2 - 18 * math.cos(theta) == pytest.approx(-18 * math.cos(1), abs=1e-7)


def test_solve_rotation_with_length(capsys):
    _, out, _ = run(capsys, "solve", "--theta0", "0", "--dtheta0", "400", "--t", "0", "3", "1",
                    "--length", "2")
    assert out.startswith("# regime IV")
    thetas = [float(line.split()[1]) for line in out.strip().splitlines()[2:]]
    assert all(b > a for a, b in zip(thetas, thetas[1:], strict=False))  # it keeps going round


@pytest.mark.parametrize("argv, word", [
    (["period", "180"], "amplitude"),
    (["period", "-5"], "amplitude"),
    (["period", "x"], "amplitude"),
    (["period", "120", "--g", "3"], "--length"),
    (["period", "120", "--length", "-1"], "length"),
    (["period", "120", "--length", "1", "--omega0", "2"], "not allowed"),
    (["period", "120", "--omega0", "0"], "omega0"),
    (["crossing", "0.5"], "value"),
    (["crossing", "nan"], "value"),
    (["solve", "--theta0", "nan"], "theta0"),
    (["solve", "--t", "0", "1", "1"], "--theta0"),
    (["solve", "--theta0", "10", "--t", "0", "10", "-1"], "STEP"),
    (["solve", "--theta0", "10", "--t", "0", "10", "0"], "STEP"),
    (["solve", "--theta0", "10", "--t", "0", "inf", "1"], "finite"),
    ([], "COMMAND"),
    (["dance"], "invalid choice"),
])
def test_bad_arguments_exit_2_with_one_line(capsys, argv, word):
    line = fail(capsys, *argv)
    assert "error" in line and word in line


def test_help_shows_examples(capsys):
    with pytest.raises(SystemExit) as info:
        main(["--help"])
    assert info.value.code == 0
    assert "crossing 2 3 4" in capsys.readouterr().out


def test_python_dash_m():
    result = subprocess.run([sys.executable, "-m", "elliptic_pendulum", "period", "90"],
                            capture_output=True, text=True, check=False)
    assert result.returncode == 0 and result.stdout.startswith("R(90 deg) = 1.180341")
    result = subprocess.run([sys.executable, "-m", "elliptic_pendulum", "crossing", "0"],
                            capture_output=True, text=True, check=False)
    assert result.returncode == 2 and len(result.stderr.strip().splitlines()) == 1


# --- hostile input: one line and status 2 --------------------------------------------------------

def test_negative_numbers_in_e_notation(capsys):
    # "--dtheta0 -4e-1" was taken for an option ("expected one argument").
    assert main(["solve", "--theta0", "10", "--dtheta0", "-4e-1", "--t", "0", "1", "1"]) == 0
    out = capsys.readouterr().out
    first = out.strip().splitlines()[2].split()
    assert float(first[2]) == pytest.approx(-0.4)
    assert main(["solve", "--theta0", "-1.5E+1", "--t", "0", "1", "1"]) == 0
    assert float(capsys.readouterr().out.strip().splitlines()[2].split()[1]) == -15.0


def test_version(capsys):
    with pytest.raises(SystemExit) as info:
        main(["--version"])
    assert info.value.code == 0
    assert ep.__version__ in capsys.readouterr().out


def test_broken_pipe_is_quiet():
    # "| head" closes the pipe early: no BrokenPipeError traceback on stderr.
    code = ("import sys\n"
            "from elliptic_pendulum.cli import main\n"
            "sys.argv[0] = 'elliptic-pendulum'\n"
            "raise SystemExit(main(['solve', '--theta0', '10', '--t', '0', '20000', '0.01']))")
    proc = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE)
    proc.stdout.read(100)
    proc.stdout.close()
    with proc.stderr:
        stderr = proc.stderr.read().decode()
    proc.wait(timeout=60)
    assert "Traceback" not in stderr and "BrokenPipe" not in stderr, stderr


def test_program_name_is_what_the_user_typed(monkeypatch, capsys):
    monkeypatch.setattr(sys, "argv", ["/usr/bin/elliptic-pendulum"])
    assert fail(capsys, "crossing", "0").startswith("elliptic-pendulum: error")
    monkeypatch.setattr(sys, "argv", ["/x/elliptic_pendulum/__main__.py"])
    assert fail(capsys, "crossing", "0").startswith("python -m elliptic_pendulum: error")
