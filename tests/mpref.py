"""The mpmath references the tests share, written once (as scipy keeps its ``_mptestutils``).

Each reference works in mpmath at a stated precision, in a ``workdps`` block (which restores
mpmath's precision on exit), from the exact double it is given: nothing here calls the
library under test. mpmath takes the parameter m = k**2, the library the modulus k.
"""

from __future__ import annotations

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
