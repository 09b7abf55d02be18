"""The mpmath references the tests share, written once (as scipy keeps its ``_mptestutils``).

Each reference works in mpmath at a stated precision, in a ``workdps`` block (which restores
mpmath's precision on exit), from the exact double it is given: nothing here calls the
library under test. mpmath takes the parameter m = k**2, the library the modulus k.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np


def ratio(theta0, dps: int = 50):
    """R(theta0) = (2/pi) K(m), m = sin^2(theta0/2), as an mpf, from the exact double theta0.

    (8) and (26) of the note: the period over the small-angle period 2 pi / omega0.
    """
    with mpmath.workdps(dps):
        m = mpmath.sin(mpmath.mpf(theta0) / 2) ** 2
        return 2 / mpmath.pi * mpmath.ellipk(m)


def ratio_degrees(degrees, dps: int = 30):
    """R at an amplitude given in degrees (an int, a float or an mpf), as an mpf."""
    with mpmath.workdps(dps):
        return 2 / mpmath.pi * mpmath.ellipk(mpmath.sin(mpmath.radians(degrees) / 2) ** 2)


def motion(theta0, dtheta0, omega0, ts, dps: int = 40):
    """theta(t), theta'(t) and the amplitude (pi for a rotation) from the note's formulas.

    Regime II by (25): theta = 2 asin(k sn(omega0 t + c2, k)); regime IV by (46):
    theta = 2 am(omega0 t / gamma + c4, gamma), with the winding of theta0 added back.
    """
    with mpmath.workdps(dps):
        th, w0 = mpmath.mpf(theta0), mpmath.mpf(omega0)
        winding = mpmath.nint(th / (2 * mpmath.pi))
        r = th - 2 * mpmath.pi * winding
        s, w = mpmath.sin(r / 2), mpmath.mpf(dtheta0) / (2 * w0)
        k2 = s**2 + w**2
        k = mpmath.sqrt(k2)
        thetas, dthetas = [], []
        if k2 < 1:  # II, (25)
            c2 = mpmath.ellipf(mpmath.atan2(s, w), k2)
            for t in ts:
                u = w0 * mpmath.mpf(float(t)) + c2
                thetas.append(2 * mpmath.pi * winding
                              + 2 * mpmath.asin(k * mpmath.ellipfun("sn", u, m=k2)))
                dthetas.append(2 * w0 * k * mpmath.ellipfun("cn", u, m=k2))
            amplitude = 2 * mpmath.asin(k)
        else:  # IV, (46) with gamma = 1/k
            g2 = 1 / k2
            d = 1 if dtheta0 > 0 else -1
            c4 = mpmath.ellipf(d * r / 2, g2)
            K = mpmath.pi / (2 * mpmath.agm(1, mpmath.sqrt(1 - g2)))
            for t in ts:
                u = k * w0 * mpmath.mpf(float(t)) + c4
                n = mpmath.nint(u / (2 * K))
                am = n * mpmath.pi + mpmath.asin(mpmath.ellipfun("sn", u - 2 * n * K, m=g2))
                thetas.append(2 * mpmath.pi * winding + d * 2 * am)
                dthetas.append(d * 2 * k * w0 * mpmath.ellipfun("dn", u, m=g2))
            amplitude = mpmath.pi
        return (np.array([float(x) for x in thetas]), np.array([float(x) for x in dthetas]),
                float(amplitude))


def jacobi(us, m, dps: int = 40):
    """sn, cn, dn at each u of ``us`` for the parameter m (an mpf: 1 - kc**2, or k**2 > 1).

    mpmath answers m > 1 with a complex number whose imaginary part is rounding: the real
    part is kept. Evaluated at ``dps`` digits from the exact doubles u.
    """
    with mpmath.workdps(dps):
        out = np.array([[float(mpmath.re(mpmath.ellipfun(f, mpmath.mpf(float(u)), m=m)))
                         for f in ("sn", "cn", "dn")] for u in us])
    return out[:, 0], out[:, 1], out[:, 2]


def period(theta0, omega0, dps: int = 50):
    """The period (26), 4 K(sin^2(theta0/2)) / omega0, as an mpf (it may exceed any double)."""
    with mpmath.workdps(dps):
        return 4 * mpmath.ellipk(mpmath.sin(mpmath.mpf(theta0) / 2) ** 2) / mpmath.mpf(omega0)


# --- any double initial state, at a precision sized for it (tests/engine/test_extreme_search) --

#: The library's documented convention (docs/conventions.md): the double nearest a multiple n pi
#: of pi means n pi itself (odd n: balanced at the top; even n: at the bottom) for
#: |theta0| < 2**50, where doubles are at most 1/4 apart; beyond 2**50 every double is taken
#: as it is.
CONVENTION_LIMIT = 2.0**50


def _digits(x) -> int:
    """The decimal exponent of a nonzero mpf (log10 |x|, rounded up), without overflow."""
    return int(mpmath.ceil(mpmath.log10(abs(x))))


def reduce_angle(theta0, dps: int = 40):
    """(winding m, s, c, exact) with theta0 = 2 pi m + r, |r| <= pi, s = sin(r/2), c = cos(r/2).

    s and c are mpfs correct to ``dps`` digits (the reduction is carried out at as many digits
    as theta0 and its distance to the nearest multiple of 2 pi need). Where theta0 is the
    double nearest a multiple n pi (|theta0| < CONVENTION_LIMIT), r is 0 or +-pi exactly
    (the sign of theta0 for odd n) and ``exact`` is True: then s, c are 0, 1 or +-1, 0.
    """
    th = mpmath.mpf(theta0)
    if theta0 == 0:
        return 0, mpmath.mpf(0), mpmath.mpf(1), True
    work = dps + 20 + max(0, int(math.log10(abs(theta0))) + 1)
    with mpmath.workdps(work):
        n = int(mpmath.nint(th / mpmath.pi))
        if abs(theta0) < CONVENTION_LIMIT and float(n * mpmath.pi) == theta0:
            if n % 2 == 0:
                return n // 2, mpmath.mpf(0), mpmath.mpf(1), True
            up = 1 if theta0 > 0 else -1
            return (n - up) // 2, mpmath.mpf(up), mpmath.mpf(0), True
        m = int(mpmath.nint(th / (2 * mpmath.pi)))
        r = th - 2 * m * mpmath.pi
        if r != 0 and _digits(r) < -10:  # close to a multiple of 2 pi: digits for r itself
            with mpmath.workdps(work - _digits(r) + 10):
                r = th - 2 * m * mpmath.pi
        with mpmath.workdps(dps + 10):
            return m, +mpmath.sin(r / 2), +mpmath.cos(r / 2), False


def _jacobi(v, m):
    """sn, cn, dn of v for the parameter m, sn to the working digits relative to itself.

    mpmath's ellipfun (theta functions) is accurate to the working digits absolutely: near
    v = 0, where sn is tiny, it is evaluated again with as many more digits as sn is small.
    """
    if v == 0:
        return mpmath.mpf(0), mpmath.mpf(1), mpmath.mpf(1)
    sn = mpmath.ellipfun("sn", v, m=m)
    if sn == 0 or _digits(sn) < -3:
        extra = (mpmath.mp.dps - 3 if sn == 0 else -_digits(sn)) + 10
        with mpmath.workdps(mpmath.mp.dps + extra):
            sn = mpmath.ellipfun("sn", v, m=m)
    return sn, mpmath.ellipfun("cn", v, m=m), mpmath.ellipfun("dn", v, m=m)


class Exact:
    """The exact motion from the double state (theta0, theta0', omega0), as mpmath gives it.

    Attributes: ``regime`` ('I', 'II', 'III', 'IV'), ``still`` (I, or III at rest at the
    top: theta = theta0 forever), ``size`` (the amplitude of II, pi for III and IV, 0 for I
    and the balanced top), ``speed`` (max |theta'| = 2 omega0 k, k^2 = s^2 + w^2),
    ``mod_c`` (alpha_c in II, gamma_c in IV, else 0) and ``quarter`` (the time of a quarter
    period, K / w0 in II and K / (w0 k) in IV, else inf), as floats; ``kc2`` = 1 - k^2 as an
    mpf. ``at(ts)`` gives (theta, theta') at the exact doubles ``ts`` as float arrays (each
    correctly rounded from ~30 digits).

    Regime II by (25), theta/2 = atan2(k sn u, dn u) (= asin(k sn u)), u = w0 t + F(atan2(s,
    w) | k^2); IV by (46), theta = 2 pi m + d 2 am(k w0 t + F(d r/2 | 1/k^2), 1/k); III by
    (28) from any point of it, theta = 2 pi m + 2 gd(sigma w0 t + gd^-1(r/2)). The elliptic
    argument is reduced by 2K at enough digits for the largest time asked. Precision: ``dps``
    digits plus those that 1 - k^2 cancels (found by raising the precision until 1 - k^2 is
    known to ``dps`` digits of its own), plus the digits of the reduction of theta0.
    """

    def __init__(self, theta0, dtheta0=0.0, omega0=1.0, dps: int = 30):
        self.theta0, self.dtheta0, self.omega0 = float(theta0), float(dtheta0), float(omega0)
        self.dps = dps
        work = dps + 10
        while True:
            m, s, c, exact = reduce_angle(self.theta0, work + 10)
            with mpmath.workdps(work):
                w = mpmath.mpf(self.dtheta0) / (2 * mpmath.mpf(self.omega0))
                k2 = s * s + w * w
                kc2 = (c - abs(w)) * (c + abs(w))
            # kc2 is exact zero only on the exact separatrix (r = 0 and |w| = 1, or the top
            # at rest), where c and w are exact; otherwise it must carry dps digits of its own
            # against 1 (mpmath's K and sn form 1 - m themselves).
            on = exact and (c == 0 and w == 0 or c == 1 and abs(w) == 1)
            if on or kc2 != 0 and _digits(kc2) - _digits(k2 + 1) > -(work - dps - 5):
                break
            work *= 2
            if work > 20000:
                raise RuntimeError("1 - k^2 cancels beyond 20000 digits")
        self.winding, self.s, self.c, self.w, self.k2 = m, s, c, w, k2
        self.kc2 = mpmath.mpf(0) if on else kc2
        self.work = work  # digits that keep 1 - k^2 to dps digits
        with mpmath.workdps(work):
            k = mpmath.sqrt(k2)
            self.k = k
            self.speed = float(2 * mpmath.mpf(self.omega0) * k)
            if s == 0 and w == 0:
                self.regime, self.still, self.size = "I", True, 0.0
            elif self.kc2 == 0:
                self.regime, self.still = "III", w == 0
                self.size = 0.0 if self.still else math.pi
            elif self.kc2 > 0:
                self.regime, self.still = "II", False
                self.size = float(2 * mpmath.atan2(k, mpmath.sqrt(self.kc2)))
            else:
                self.regime, self.still, self.size = "IV", False, math.pi
            # The elliptic modulus' complement (alpha_c in II, gamma_c = |kc|/k in IV) and the
            # time of a quarter period K / rate (rate w0 in II, w0 k in IV); inf elsewhere.
            if self.regime == "II":
                self.mod_c = float(mpmath.sqrt(self.kc2))
                self.quarter = float(mpmath.ellipk(k2) / mpmath.mpf(self.omega0))
            elif self.regime == "IV":
                self.mod_c = float(mpmath.sqrt(-self.kc2) / k)
                self.quarter = float(mpmath.ellipk(1 / k2) / (k * mpmath.mpf(self.omega0)))
            else:
                self.mod_c, self.quarter = 0.0, math.inf

    def at(self, ts):
        """(theta, theta') at the exact doubles ``ts``, as float arrays."""
        ts = [float(t) for t in np.ravel(ts)]
        if self.still:
            return np.full(len(ts), self.theta0), np.zeros(len(ts))
        top = max([abs(t) for t in ts] + [1.0])
        grow = max(0, int(math.log10(top * max(self.speed, self.omega0) + 1.0)))
        base = self.work + grow + 10
        wind = max(0, int(math.log10(abs(self.winding) + 1))) + self.dps + 10
        out_th, out_dth = [], []
        with mpmath.workdps(base):
            s, c, w, k, k2 = self.s, self.c, self.w, self.k, self.k2
            w0 = mpmath.mpf(self.omega0)
            if self.regime == "III":
                sigma = 1 if w > 0 else -1
                x0 = mpmath.asinh(s / c)  # gd^-1(r/2) = asinh(tan(r/2))
                for t in ts:
                    y = sigma * w0 * mpmath.mpf(t) + x0
                    if abs(y) > 4000:  # sech y < 1e-1700: theta/2 = +-pi/2 in any double
                        half, dth = mpmath.sign(y) * mpmath.pi / 2, mpmath.mpf(0)
                    else:
                        half = mpmath.atan(mpmath.sinh(y))
                        dth = sigma * 2 * w0 * mpmath.sech(y)
                    out_th.append(half)
                    out_dth.append(dth)
            elif self.regime == "II":
                K = mpmath.ellipk(k2)
                # c2 = F(atan2(s, w)) = q 2K + rem: for w < 0, F(+-pi - psi) = +-2K - F(psi)
                # with psi = atan2(s, -w), so that v = u - 2nK keeps its digits near t = 0
                if w < 0:
                    q, rem = (1 if s >= 0 else -1), -mpmath.ellipf(mpmath.atan2(s, -w), k2)
                else:
                    q, rem = 0, mpmath.ellipf(mpmath.atan2(s, w), k2)
                for t in ts:
                    x = w0 * mpmath.mpf(t) + rem
                    n = int(mpmath.nint((x + 2 * q * K) / (2 * K)))
                    v = x + 2 * (q - n) * K
                    sign = -1 if n % 2 else 1
                    sn, cn, dn = _jacobi(v, k2)
                    sn, cn = sign * sn, sign * cn
                    out_th.append(mpmath.atan2(k * sn, dn))
                    out_dth.append(2 * w0 * k * cn)
            else:  # IV
                g2 = 1 / k2
                d = 1 if w > 0 else -1
                # r/2 = atan2(s, c), exact at the top (s = +-1, c = 0)
                c4 = mpmath.ellipf(d * mpmath.atan2(s, c), g2)
                K = mpmath.ellipk(g2)
                for t in ts:
                    u = k * w0 * mpmath.mpf(t) + c4
                    n = int(mpmath.nint(u / (2 * K)))
                    v = u - 2 * n * K
                    sn, cn, dn = _jacobi(v, g2)
                    out_th.append(d * (n * mpmath.pi + mpmath.atan2(sn, cn)))
                    out_dth.append(d * 2 * k * w0 * dn)
        with mpmath.workdps(wind):
            turns = 2 * self.winding * mpmath.pi
            theta = np.array([float(turns + 2 * h) for h in out_th])
        return theta, np.array([float(x) for x in out_dth])
