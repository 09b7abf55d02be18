"""Command line: ``python -m elliptic_pendulum table | period | crossing | solve``.

A thin layer over :mod:`~elliptic_pendulum.periods`, :mod:`~elliptic_pendulum.motion` and
:mod:`~elliptic_pendulum.mechanics`, speaking degrees as the note does. Every bad argument,
including a value the library refuses, ends as one line on stderr and exit status 2.
"""

from __future__ import annotations

import argparse
import math
import os
import re
import sys
from collections.abc import Sequence
from fractions import Fraction

import numpy as np

from .mechanics.rod import Pendulum
from .motion import solve
from .periods.period import crossing_angle, period, period_ratio, small_angle_period

__all__ = ["main"]

# Section 4 of the note: amplitude in degrees -> R to three decimals.
NOTE_TABLE = {30: 1.017, 45: 1.040, 60: 1.073, 90: 1.180, 120: 1.373, 135: 1.528, 150: 1.762}

EXAMPLES = """\
examples:
  python -m elliptic_pendulum table                      the note's table of R (section 4)
  python -m elliptic_pendulum period 120                 R of a 120 degree swing
  python -m elliptic_pendulum period 120 --length 1      ... and its period in seconds
  python -m elliptic_pendulum crossing 2 3 4             where R reaches 2, 3 and 4
  python -m elliptic_pendulum solve --theta0 170 --t 0 10 0.5
  python -m elliptic_pendulum solve --theta0 0 --dtheta0 400 --t 0 5 1 --length 2
"""


class _Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs) -> None:  # noqa: D107
        super().__init__(*args, **kwargs)
        # argparse takes "-4e-1" for an option (its pattern knows only -4 and -0.4), so that
        # "--dtheta0 -4e-1" failed with "expected one argument": teach it e-notation.
        self._negative_number_matcher = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")

    def error(self, message: str) -> None:  # type: ignore[override]
        # argparse would print the whole usage first; one line that says what is wrong (and
        # where the help is) is easier to read in a classroom terminal.
        self.exit(2, f"{self.prog}: error: {message} (try --help)\n")


def _frequency_options(parser: argparse.ArgumentParser) -> None:
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--omega0", type=float, help="angular frequency sqrt(g/l) in rad/s (6)")
    group.add_argument("--length", type=float, help="rod length l in metres")
    parser.add_argument("--g", type=float, default=None,
                        help="gravitational acceleration with --length (default 9.80665)")


def _prog() -> str:
    """Return the name the user typed: ``python -m elliptic_pendulum`` or the script's."""
    name = os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else ""
    if name in ("__main__.py", "-m", "-c", ""):
        return "python -m elliptic_pendulum"
    return name if name.startswith("elliptic") else "elliptic-pendulum"


def _build_parser() -> _Parser:
    from . import __version__

    parser = _Parser(prog=_prog(),
                     description="The exact simple pendulum via Jacobi elliptic functions.",
                     epilog=EXAMPLES, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    commands.add_parser("table", help="the note's table of R(theta0) = (2/pi) K(sin(theta0/2))",
                        description="R(theta0) to 6 decimals beside the note's 3 (section 4).")
    p = commands.add_parser("period", help="period ratio R and period (26) of a swing",
                            description="Period ratio R = (26)/(8) of swings of the given "
                                        "amplitudes in degrees, 0 <= amplitude < 180; the "
                                        "period itself with --omega0 or --length [--g].")
    p.add_argument("amplitude", type=float, nargs="+", help="amplitude theta0 in degrees")
    _frequency_options(p)
    c = commands.add_parser("crossing", help="amplitudes at which R reaches given values",
                            description="The amplitude (degrees) where R(theta0) = value, "
                                        "for each value >= 1; the note says 160, 176, 179.2 "
                                        "for 2, 3, 4.")
    c.add_argument("value", type=float, nargs="+", help="period ratio R >= 1")
    s = commands.add_parser("solve", help="tabulate theta(t), theta'(t) from an initial state",
                            description="Columns t, theta, theta' of the exact motion, in "
                                        "degrees and deg/s (radians with --rad).")
    s.add_argument("--theta0", type=float, required=True, help="initial angle (degrees)")
    s.add_argument("--dtheta0", type=float, default=0.0,
                   help="initial angular velocity (deg/s; default 0)")
    s.add_argument("--t", type=float, nargs=3, metavar=("START", "STOP", "STEP"),
                   default=[0.0, 10.0, 0.5], help="times START..STOP (inclusive) by STEP "
                                                  "(default 0 10 0.5)")
    s.add_argument("--rad", action="store_true", help="angles in radians, in and out")
    _frequency_options(s)
    return parser


def _omega0(parser: _Parser, args: argparse.Namespace) -> float | None:
    if args.g is not None and args.length is None:
        parser.error("--g needs --length (omega0 = sqrt(g/length))")
    if args.length is not None:
        g = 9.80665 if args.g is None else args.g
        return Pendulum(args.length, g=g).omega0
    return args.omega0


# The most rows `solve` prints (docs/cli.md): a table to read, not a data file; 200,001 rows took
# seconds to print. For more, the library: ep.solve(...).theta(t) on any array of times.
MAX_ROWS = 100_000


def _times(parser: _Parser, start: float, stop: float, step: float) -> np.ndarray:
    if not all(map(math.isfinite, (start, stop, step))):
        parser.error("--t START STOP STEP must be finite numbers")
    # Signs, not the product (stop - start) * step, which can underflow to -0.0 or overflow.
    if step == 0 or (stop != start and (stop > start) != (step > 0)):
        parser.error(f"--t: STEP must be nonzero and lead from START={start} to STOP={stop}")
    # STOP - START overflows for -1e308 1e308, and the quotient for 0 1e300 1e-300: a float
    # count that is inf (or beyond the cap) is refused before it meets math.floor.
    rows = (stop - start) / step
    if math.isinf(rows):
        rows = stop / step - start / step
    if not rows < MAX_ROWS:  # also refuses a count whose floor would be out of reach
        parser.error(f"--t START STOP STEP must give at most {MAX_ROWS:,} rows; "
                     f"got {_count(rows)}; use a larger STEP")
    count = math.floor(rows * (1 + 1e-12)) + 1  # STOP itself when on the grid
    if count > MAX_ROWS:
        parser.error(f"--t START STOP STEP must give at most {MAX_ROWS:,} rows; got {count:,}; "
                     "use a larger STEP")
    with np.errstate(over="ignore"):
        t = start + step * np.arange(count)
        if not np.all(np.isfinite(t)):  # step * k overflowed on the way to a finite time
            t = 2.0 * (0.5 * start + (0.5 * step) * np.arange(count))
    return t


# pi to 60 digits as an exact fraction. d pi / 180 is then rounded once (a Fraction converts to
# the nearest double), so that 360 degrees is the double nearest 2 pi (the bottom, like 0) and
# 180 n degrees the double nearest n pi for every n; math.radians rounds twice and misses the
# nearest double for about one angle in nine.
_PI = Fraction("3.14159265358979323846264338327950288419716939937510582097494")


def _radians(degrees: float) -> float:
    """Return the double nearest ``degrees`` * pi / 180; NaN and inf pass to the library."""
    if not math.isfinite(degrees):
        return degrees
    return float(Fraction(degrees) * _PI / 180)


def _count(rows: float) -> str:
    """Return a row count for a message: exact with separators when small, else 3 digits."""
    if rows < 1e15:
        return f"{math.floor(rows) + 1:,}"
    return f"about {rows:.3g}" if math.isfinite(rows) else "more than 1e308"


# Beyond this size a column's fixed decimals would print a number of up to 309 digits (a time
# of 1e308, a speed of 1e300 deg/s): there it is printed as repr, in scientific notation.
_FIXED_BELOW = 1e15


def _cell(x: float, decimals: int, width: int) -> str:
    """Return one value of the solve table: fixed decimals, or repr for a huge value."""
    if abs(x) >= _FIXED_BELOW:
        return f"{repr(float(x)):>{width}}"
    # round() first, + 0.0 then: a value like -1e-17 prints as 0, not as "-0.000...".
    return f"{round(float(x), decimals) + 0.0:>{width}.{decimals}f}"


def _number(x: float) -> str:
    """``x`` as the user typed it, to every digit that tells it apart from its neighbours.

    repr is the shortest string that reads back as the same double ('{:g}' printed 179.9999 as
    180, the amplitude the program refuses); '90' rather than '90.0', and 0 for -0.
    """
    text = repr(float(x) + 0.0)
    return text[:-2] if text.endswith(".0") else text


def _table() -> None:
    print(f"{'theta0/deg':>10}  {'R(theta0)':>10}  {'note':>6}")
    ratios = np.asarray(period_ratio(np.radians(list(NOTE_TABLE))))
    for (degrees, note), ratio in zip(NOTE_TABLE.items(), ratios, strict=True):
        print(f"{degrees:>10}  {ratio:>10.6f}  {note:>6.3f}")


def _period(parser: _Parser, args: argparse.Namespace) -> None:
    for degrees in args.amplitude:
        if not 0 <= degrees < 180:
            parser.error(f"amplitude must be in degrees with 0 <= amplitude < 180, got {degrees}")
    omega0 = _omega0(parser, args)
    lines = []  # all of them before any is printed: a refusal must not follow half an answer
    for degrees in args.amplitude:
        theta0 = _radians(degrees)
        line = f"R({_number(degrees)} deg) = {period_ratio(theta0):.6f}"
        if omega0 is not None:
            line += (f"   period = {period(theta0, omega0):.6g} s"
                     f"   small-angle period = {small_angle_period(omega0):.6g} s")
        lines.append(line)
    print("\n".join(lines))


def _crossing(args: argparse.Namespace) -> None:
    # One at a time, so an error names the offending value; all of them before anything is
    # printed, so that a bad value after good ones ends with the error alone.
    angles = [crossing_angle(value) for value in args.value]
    for value, angle in zip(args.value, angles, strict=True):
        print(f"R = {_number(value)} at theta0 = {math.degrees(angle):.9f} deg")


def _solve(parser: _Parser, args: argparse.Namespace) -> None:
    omega0 = _omega0(parser, args)
    t = _times(parser, *args.t)
    convert = (lambda x: x) if args.rad else _radians
    motion = solve(convert(args.theta0), convert(args.dtheta0),
                   omega0=1.0 if omega0 is None else omega0)
    theta, dtheta = motion.theta(t), motion.dtheta(t)
    if not args.rad:
        with np.errstate(under="ignore"):  # a subnormal angle prints as 0 all the same
            theta, dtheta = np.degrees(theta), np.degrees(dtheta)
    unit = "rad" if args.rad else "deg"
    kind = "time per revolution" if motion.regime.value == "IV" else "period"
    # Without --omega0 or --length, omega0 = 1: time is counted in units of sqrt(l/g).
    second = "s" if omega0 is not None else "sqrt(l/g)"
    if motion.regime.value == "III":
        when = "infinite"
    elif math.isinf(motion.period):  # a finite period beyond the doubles (omega0 ~ 1e-320)
        when = f"beyond the largest double (> {sys.float_info.max:.2g} {second})"
    else:
        when = f"{motion.period:.10g} {second}"
    print(f"# regime {motion.regime.value} ({motion.regime.name.lower()}), {kind} {when}")
    rate = unit + "/" + ("s" if omega0 is not None else "unit")
    print(f"{'t':>12}  {'theta/' + unit:>16}  {'theta_dot/' + rate:>18}")
    for t_k, theta_k, dtheta_k in zip(t, theta, dtheta, strict=True):
        print(f"{_cell(t_k, 6, 12)}  {_cell(theta_k, 9, 16)}  {_cell(dtheta_k, 9, 18)}")


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line with ``argv`` (default ``sys.argv[1:]``); return the exit status.

    Examples
    --------
    >>> main(["period", "90"])
    R(90 deg) = 1.180341
    0
    """
    parser = _build_parser()
    args = parser.parse_args(sys.argv[1:] if argv is None else list(argv))
    try:
        if args.command == "table":
            _table()
        elif args.command == "period":
            _period(parser, args)
        elif args.command == "crossing":
            _crossing(args)
        else:
            _solve(parser, args)
        sys.stdout.flush()
    except (ValueError, TypeError) as error:  # the library's domain errors, for the user
        parser.error(str(error))
    except BrokenPipeError:
        # The reader went away (``... | head``): not an error of ours. Point stdout at
        # devnull so that Python's own flush at exit does not raise again.
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 1
    return 0
