"""Double-double arithmetic: a number as an unevaluated sum hi + lo of two doubles.

Dekker's and Knuth's error-free transformations and the operations built on them: two_sum
and two_prod are exact; add, mul and sqrt are within 2**-104 (4.9e-32) relative and div
within 8e-32 (measured against exact fractions: 2.0e-32, 3.6e-32, 3.3e-32 and 7.3e-32 at
worst over random operands, add under heavy cancellation). Every function is plain
arithmetic on its arguments, so the same code serves Python floats (the fast scalar path)
and NumPy arrays (elementwise, each element on its own: nothing here looks at the other
elements of an array). No global state is read or written, unlike an mpmath precision, so
all of it is safe in threads.

Range: the products split their factors with 2**27 + 1, which overflows beyond about 1e300;
callers keep magnitudes within 2**±400 (and route the rest elsewhere).

Also here: pi to about 160 bits in three parts, and sin and cos of a double-double angle in
[0, pi/4] (a table of sin(j/32), cos(j/32) plus a short Taylor series), which the
classification of an initial state needs to form the energy without rounding it away:
within 6e-32 relative (measured 5.3e-32 for sin, 2.8e-32 for cos, against mpmath).
"""

from __future__ import annotations

import mpmath

# pi = PI_HI + PI_LO + PI_LO2 to about 2**-160.
PI_HI = 3.141592653589793
PI_LO = 1.2246467991473532e-16
PI_LO2 = -2.9947698097183397e-33
SPLIT = 134217729.0  # 2**27 + 1, Dekker's splitter


def two_sum(a, b):
    """Return (s, e) with s = fl(a + b) and a + b = s + e exactly (Knuth)."""
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def fast_two_sum(a, b):
    """Return (s, e) with a + b = s + e exactly, for |a| >= |b| (Dekker)."""
    s = a + b
    return s, b - (s - a)


def split(a):
    """Return (hi, lo) = a with hi holding the top 26 bits: hi * hi' is exact."""
    t = SPLIT * a
    hi = t - (t - a)
    return hi, a - hi


def two_prod(a, b):
    """Return (p, e) with p = fl(a b) and a b = p + e exactly (Dekker), |a|, |b| < 1e300."""
    p = a * b
    ah, al = split(a)
    bh, bl = split(b)
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def add(ah, al, bh, bl):
    """(ah + al) + (bh + bl), accurate to about 2**-104 relative even under cancellation."""
    s, e = two_sum(ah, bh)
    t, f = two_sum(al, bl)
    s, e = fast_two_sum(s, e + t)
    return fast_two_sum(s, e + f)


def mul(ah, al, bh, bl):
    """(ah + al) (bh + bl)."""
    p, e = two_prod(ah, bh)
    return fast_two_sum(p, e + (ah * bl + al * bh))


def mul_d(ah, al, b):
    """(ah + al) b for a double b."""
    p, e = two_prod(ah, b)
    return fast_two_sum(p, e + al * b)


def div(ah, al, bh, bl):
    """(ah + al) / (bh + bl), bh != 0."""
    q = ah / bh
    p, e = mul(q, 0.0 * q, bh, bl)
    s, f = two_sum(ah, -p)
    r = s + (f - e + al)
    return fast_two_sum(q, r / bh)


def sqrt(ah, al, root):
    """Square root of ah + al > 0; ``root`` is math.sqrt or np.sqrt, for the type at hand."""
    x = root(ah)
    p, e = two_prod(x, x)
    r = ((ah - p) - e) + al
    return fast_two_sum(x, r / (2.0 * x))


def _tables():
    # sin(j/32) and cos(j/32), j = 0..26, and 1/n! as double-doubles; computed once in a
    # private mpmath context (never mpmath.mp, whose precision is the whole process's).
    ctx = mpmath.MPContext()
    ctx.prec = 200

    def pair(v):
        hi = float(v)
        return hi, float(v - hi)

    rows = [pair(ctx.sin(ctx.mpf(j) / 32)) + pair(ctx.cos(ctx.mpf(j) / 32)) for j in range(27)]
    inverse = {n: pair(1 / ctx.factorial(n)) for n in range(2, 8)}
    return tuple(zip(*rows, strict=True)), inverse


(SIN_HI, SIN_LO, COS_HI, COS_LO), _INV = _tables()


def _series(zh, zl):
    """Sin z and cos z for a double-double |z| <= 1/64 + tiny.

    The series is truncated below 1e-36; what is left is the rounding of the double-double
    operations, measured at 3.4e-32 (sin) and 5.5e-33 (cos) relative.
    """
    z2h, z2l = mul(zh, zl, zh, zl)
    # Beyond z^7/7! (3e-15 z) the terms fit in a double: z^8/8! <= 1e-19, z^9/9! <= 1e-20 z,
    # so the tail's rounding (and that of 1/n!) costs below 1e-35. It must run to z^12/12!
    # (4.4e-31 at |z| = 1/64) in cos and z^13/13! (3.4e-32 z) in sin to reach 1e-32; the next
    # terms, z^14/14! <= 6e-37 and z^15/15! <= 4e-38 z, are below the double-double rounding.
    z2 = z2h
    tail_s = z2 * (1.0 / 362880.0 - z2 * (1.0 / 39916800.0 - z2 / 6227020800.0))
    #        (z^9/9! - z^11/11! + z^13/13!) / z^7
    tail_c = z2 * (1.0 / 40320.0 - z2 * (1.0 / 3628800.0 - z2 / 479001600.0))
    #        (z^8/8! - z^10/10! + z^12/12!) / z^6
    # sin z / z = 1 - z^2/3! + z^4/5! - z^6/7! + ...
    ph, pl = add(-_INV[7][0], -_INV[7][1], tail_s, 0.0)
    ph, pl = mul(ph, pl, z2h, z2l)
    ph, pl = add(ph, pl, *_INV[5])
    ph, pl = mul(ph, pl, z2h, z2l)
    ph, pl = add(ph, pl, -_INV[3][0], -_INV[3][1])
    ph, pl = mul(ph, pl, z2h, z2l)
    ph, pl = add(ph, pl, 1.0, 0.0)
    sh, sl = mul(ph, pl, zh, zl)
    # cos z = 1 - z^2/2 + z^4/4! - z^6/6! + ...
    ph, pl = add(-_INV[6][0], -_INV[6][1], tail_c, 0.0)
    ph, pl = mul(ph, pl, z2h, z2l)
    ph, pl = add(ph, pl, *_INV[4])
    ph, pl = mul(ph, pl, z2h, z2l)
    ph, pl = add(ph, pl, -0.5, 0.0)
    ph, pl = mul(ph, pl, z2h, z2l)
    ch, cl = add(ph, pl, 1.0, 0.0)
    return sh, sl, ch, cl


def sincos(yh, yl, rint, take, tables=None):
    """Sin y and cos y, each a double-double, for a double-double 0 <= y <= pi/4 (+ an ulp).

    y = j/32 + z with |z| <= 1/64: the table gives sin and cos of j/32, the series those of z,
    and the addition theorem joins them without cancellation (cos >= 0.7 here, and sin(j/32)
    dominates z where j > 0). ``rint`` rounds to an integer and ``take(table, j)`` looks the
    table up, for the type at hand (floats or arrays), in ``tables`` (the four tables as
    that type wants them).

    Within 6e-32 relative (measured against mpmath: 5.3e-32 for sin, 2.8e-32 for cos; the
    sine is worst near y = 1/64, where the addition theorem halves sin(1/32)).
    """
    j = rint(yh * 32.0)
    zh, zl = two_sum(yh - j / 32.0, yl)  # yh - j/32 is exact (Sterbenz)
    s_h, s_l, c_h, c_l = _series(zh, zl)
    ash, asl, ach, acl = (take(t, j) for t in (tables or (SIN_HI, SIN_LO, COS_HI, COS_LO)))
    p = mul(ash, asl, c_h, c_l)
    q = mul(ach, acl, s_h, s_l)
    sin_h, sin_l = add(*p, *q)
    p = mul(ach, acl, c_h, c_l)
    q = mul(ash, asl, s_h, s_l)
    cos_h, cos_l = add(*p, -q[0], -q[1])
    return sin_h, sin_l, cos_h, cos_l
