"""Extract the Boost.Math and GSL test arguments and recompute their references with mpmath.

    python tests/data/make_elliptic_tables.py                      # references only
    python tests/data/make_elliptic_tables.py --boost DIR --gsl DIR  # arguments too

The arguments (u, k) come from the public test data of Boost.Math (test/jacobi_elliptic*.ipp,
jacobi_near_1.ipp, jacobi_large_phi.ipp, the spot values of test/test_jacobi.hpp, and
test/ellint_k_data.ipp with the spot values of test/test_ellint_1.hpp) and from the
gsl_sf_elljac_e calls of GSL's specfunc/test_sf.c. Only the arguments are kept: every
reference value is recomputed here by mpmath at 50 significant digits from the exact double
arguments (the library's input), and written with 20 digits, enough to count ulps to 1e-3.
With --boost the script also compares those references with Boost's own printed values,
a check of the reference (they agree to about 1e-40 where Boost's arguments are doubles).

mpmath takes the parameter m = k**2, formed exactly from the double k. For k > 1 the
reference goes through the reciprocal modulus, sn(u, k) = sn(k u, 1/k) / k,
cn(u, k) = dn(k u, 1/k) and dn(u, k) = cn(k u, 1/k) (DLMF 22.17.2-4), exact identities
evaluated at the working precision. The amplitude am(u, k) is n pi + atan2(sn v, cn v) with
v = u - 2 n K in [-K, K] (DLMF 22.16.1-2) for k < 1, and atan2(sn u, cn u) for k > 1 (the
library's bounded amplitude there).
"""

from __future__ import annotations

import argparse
import csv
import math
import re
import subprocess
from pathlib import Path

import mpmath

HERE = Path(__file__).resolve().parent
JACOBI = HERE / "jacobi_boost_gsl.csv"
QUARTER = HERE / "complete_integral_boost.csv"
DPS = 50
DIGITS = 20

HEADER_JACOBI = """\
# Arguments of Jacobi's sn, cn, dn from the public test data of Boost.Math and GSL, and their
# values recomputed by mpmath at 50 digits (tests/data/make_elliptic_tables.py).
# Boost.Math (github.com/boostorg/math, test/): jacobi_elliptic.ipp, jacobi_elliptic_small.ipp,
#   jacobi_near_1.ipp, jacobi_large_phi.ipp and the spot values of test_jacobi.hpp;
#   Copyright John Maddock 2006-2012, Paul A. Bristow 2007, 2009; distributed under the Boost
#   Software License, Version 1.0 (http://www.boost.org/LICENSE_1_0.txt).
# GSL (specfunc/test_sf.c, the gsl_sf_elljac_e calls): only the argument pairs (u, m) are taken,
#   with k = sqrt(m) rounded to a double; GSL is GPL-3.0-or-later, Copyright (C) 1996-2004
#   Gerard Jungman, (C) 2007 Brian Gough.
# Columns: source (Boost's table jacobi_<source>.ipp; "spots" for test_jacobi.hpp's data1;
# "gsl"), u and k as exact doubles (repr), then sn, cn, dn and am at those doubles.
"""

HEADER_QUARTER = """\
# Moduli k of the complete elliptic integral K(k) from the public test data of Boost.Math
# (github.com/boostorg/math, test/ellint_k_data.ipp and the spot values of test_ellint_1.hpp;
# Copyright John Maddock 2006-7, Boost Software License, Version 1.0,
# http://www.boost.org/LICENSE_1_0.txt), and K recomputed by mpmath at 50 digits
# (tests/data/make_elliptic_tables.py). Columns: source (the table ellint_k_data.ipp, or
# "spots": test_ellint_1.hpp's data2), k as an exact double (repr), K(k).
"""

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def _value(text: str) -> mpmath.mpf:
    """One C++ table entry: SC_(x), ldexp(T(1), -n), 1 - ldexp(T(1), -n)."""
    with mpmath.workdps(120):
        return _parse(text.strip())


def _parse(text: str) -> mpmath.mpf:
    m = re.fullmatch(r"SC_\((" + _NUMBER + r")\)", text)
    if m:
        return mpmath.mpf(m.group(1))
    m = re.fullmatch(r"(-?)ldexp\(T\(1\), *(-?\d+)\)", text)
    if m:
        return (-1 if m.group(1) else 1) * mpmath.ldexp(1, int(m.group(2)))
    m = re.fullmatch(r"1 - ldexp\(T\(1\), *(-?\d+)\)", text)
    if m:
        return 1 - mpmath.ldexp(1, int(m.group(1)))
    raise ValueError(f"unknown table entry {text!r}")


def _rows(text: str, name: str) -> list[list[mpmath.mpf]]:
    """The rows {{ a, b, ... }} of the C++ array called ``name``."""
    start = text.index(name)
    body = text[text.index("{{", start) + 2:]  # past the array's own opening brace
    body = body[:body.index("}};")]
    rows = []
    for row in re.findall(r"\{\{(.*?)\}\}", body, flags=re.S):
        row = re.sub(r"/\*.*?\*/", "", row)
        rows.append([_value(x) for x in _split(row)])
    return rows


def _split(row: str) -> list[str]:
    """Split a row at the commas outside parentheses."""
    parts, depth, current = [], 0, ""
    for ch in row:
        if ch == "," and depth == 0:
            parts.append(current)
            current = ""
            continue
        depth += (ch == "(") - (ch == ")")
        current += ch
    return [p for p in (*parts, current) if p.strip()]


def _git_show(repo: Path, path: str) -> str:
    """A file of a checkout or of a bare git directory."""
    if (repo / path).exists():
        return (repo / path).read_text()
    return subprocess.run(["git", f"--git-dir={repo}", "show", f"HEAD:{path}"], check=True,
                          capture_output=True, text=True).stdout


def _exact(x: mpmath.mpf, where: str) -> float:
    with mpmath.workdps(120):
        d = float(x)
        if mpmath.mpf(d) != x:
            print(f"  note: {where} argument {mpmath.nstr(x, 30)} is not a double; "
                  f"the double {d!r} is used")
    return d


def boost_jacobi(repo: Path) -> list[tuple[str, float, float, list]]:
    out = []
    spots = _rows(_git_show(repo, "test/test_jacobi.hpp"), "data1")
    tables = [("spots", spots)]
    for name in ("jacobi_elliptic", "jacobi_elliptic_small", "jacobi_near_1",
                 "jacobi_large_phi"):
        text = _git_show(repo, f"test/{name}.ipp")
        tables.append((name.removeprefix("jacobi_"), _rows(text, f" {name} =")))
    for source, rows in tables:
        for row in rows:
            u, k = (_exact(x, source) for x in row[:2])
            out.append((source, u, k, row[2:5]))
    return out


def boost_quarter(repo: Path) -> list[tuple[str, float, list]]:
    spots = _rows(_git_show(repo, "test/test_ellint_1.hpp"), "data2")
    table = _rows(_git_show(repo, "test/ellint_k_data.ipp"), "ellint_k_data =")
    return [(source, _exact(row[0], source), row[1:2])
            for source, rows in (("spots", spots), ("ellint_k_data", table)) for row in rows]


def gsl_jacobi() -> list[tuple[str, float, float, list]]:
    """The arguments of the gsl_sf_elljac_e calls in specfunc/test_sf.c, as C forms them."""
    pairs = [(0.5, 0.5), (1.0, 0.3), (1.0, 0.6), (3.0, 0.6), (2.0, 0.999999),
             (1.69695970624443, 0.270378013104138)]
    m = 0.1
    K = (math.pi / 2) / 0.9741726903999478375938128316  # the test's K, as C rounds it
    eps = 1e-10
    us = [0.0, -eps, eps, 1e-30, K / 2.0 - eps, K / 2.0, K / 2.0 + eps, K - eps, K, K + eps,
          3.0 * K / 2.0, 2.0 * K - eps, 2.0 * K, 2.0 * K + eps, 5.0 * K / 2.0, 3.0 * K - eps,
          3.0 * K, 3.0 * K + eps, 7.0 * K / 2.0, 4.0 * K - eps, 4.0 * K, 9.0 * K / 2.0,
          -K / 2.0, -K, -3.0 * K / 2.0, -2.0 * K, -5.0 * K / 2.0, -3.0 * K, -7.0 * K / 2.0,
          -4.0 * K]
    pairs += [(u, m) for u in us]
    return [("gsl", u, math.sqrt(m), []) for u, m in pairs]


def reference_jacobi(u: float, k: float) -> list[mpmath.mpf]:
    """sn, cn, dn, am at the exact doubles u, k, at DPS digits (see the module's docstring)."""
    if u == 0:  # exact; mpmath's theta series leaves a 1e-78 there
        return [mpmath.mpf(0), mpmath.mpf(1), mpmath.mpf(1), mpmath.mpf(0)]
    with mpmath.workdps(DPS + 20):
        u_, k_ = mpmath.mpf(u), mpmath.mpf(k)
        if k_ > 1:
            mu = 1 / k_
            s, c, d = (mpmath.ellipfun(f, k_ * u_, m=mu**2) for f in ("sn", "cn", "dn"))
            s, c, d = s / k_, d, c
            return [s, c, d, mpmath.atan2(s, c)]
        m = k_**2
        s, c, d = (mpmath.ellipfun(f, u_, m=m) for f in ("sn", "cn", "dn"))
        if k_ == 1:
            return [s, c, d, 2 * mpmath.atan(mpmath.exp(u_)) - mpmath.pi / 2]
        quarter = mpmath.ellipk(m)
        n = mpmath.nint(u_ / (2 * quarter))
        sign = -1 if n % 2 else 1
        return [s, c, d, n * mpmath.pi + mpmath.atan2(sign * s, sign * c)]


def reference_quarter(k: float) -> mpmath.mpf:
    with mpmath.workdps(DPS + 20):
        kc = mpmath.sqrt(1 - mpmath.mpf(k) ** 2)
        return mpmath.pi / (2 * mpmath.agm(1, kc))


def _text(x: mpmath.mpf) -> str:
    return mpmath.nstr(x, DIGITS, min_fixed=1, max_fixed=0) if x != 0 else "0"


def _compare(label: str, ours: list, theirs: list) -> None:
    """Print the largest relative difference between our references and Boost's values."""
    worst = mpmath.mpf(0)
    with mpmath.workdps(DPS + 20):
        for a, b in zip(ours, theirs, strict=False):
            # Boost's rows hold 60 to 100 digits; a zero is compared absolutely
            worst = max(worst, abs(a - b) / (abs(b) if b else 1))
    print(f"  {label}: largest relative difference from Boost's own values "
          f"{mpmath.nstr(worst, 3)}")


def read_arguments() -> tuple[list, list]:
    """The committed arguments (source, u, k) and (source, k)."""
    with JACOBI.open() as f:
        jac = [(r[0], float(r[1]), float(r[2]), []) for r in csv.reader(_data(f))]
    with QUARTER.open() as f:
        quarter = [(r[0], float(r[1]), []) for r in csv.reader(_data(f))]
    return jac, quarter


def _data(f):
    return (line for line in f if line.strip() and not line.startswith(("#", "source")))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--boost", type=Path, help="a Boost.Math checkout or bare git dir")
    parser.add_argument("--gsl", type=Path, help="a GSL checkout or bare git dir (unused: "
                        "its arguments are written out in gsl_jacobi)")
    args = parser.parse_args()
    if args.boost:
        jac = boost_jacobi(args.boost) + gsl_jacobi()
        quarter = boost_quarter(args.boost)
    else:
        jac, quarter = read_arguments()
    rows, by_source, theirs = [], {}, {}
    for source, u, k, given in jac:
        ref = reference_jacobi(u, k)
        rows.append([source, repr(u), repr(k), *(_text(x) for x in ref)])
        if given:
            by_source.setdefault(source, []).extend(ref[:3])
            theirs.setdefault(source, []).extend(given)
    for source in by_source:
        _compare(source, by_source[source], theirs[source])
    with JACOBI.open("w", newline="") as f:
        f.write(HEADER_JACOBI)
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(["source", "u", "k", "sn", "cn", "dn", "am"])
        writer.writerows(rows)
    rows, ours_k, theirs_k = [], [], []
    for source, k, given in quarter:
        ref = reference_quarter(k)
        rows.append([source, repr(k), _text(ref)])
        ours_k += [ref]
        theirs_k += given
    if theirs_k:
        _compare("K", ours_k, theirs_k)
    with QUARTER.open("w", newline="") as f:
        f.write(HEADER_QUARTER)
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(["source", "k", "K"])
        writer.writerows(rows)
    print(f"wrote {JACOBI.name} ({len(jac)} rows) and {QUARTER.name} ({len(quarter)} rows)")


if __name__ == "__main__":
    main()
