"""Snapping a direction to an exact rational unit vector within a bound.

A direction ``v`` (three rationals, as a robot file writes them) is replaced by a unit
vector ``w`` with rational entries whose angle to ``v`` is at most the bound: ``v``
itself, scaled, when its length is rational; else the inverse stereographic image of
rational points near ``v``'s stereographic coordinates (seen from the pole opposite
its largest entry): the simplest rationals (:func:`~coopkin_sym.exact.angles.
simplest_between`) within ``h`` of each coordinate, for ``h`` = bound, bound/2,
bound/4, ... until the exact angle is within the bound (at most three tries: a point
within ``bound/(2 sqrt 2)`` always is). The test is exact: ``v.w > 0`` and
``(v.w)^2 >= |v|^2 cos^2(bound)``, with ``cos^2(bound)`` enclosed in intervals refined
until the comparison is certain; the angle reported is computed in intervals too.

Example
-------
>>> w, error = snap_axis((Fraction(7071068, 10**7), Fraction(7071068, 10**7), Fraction(0)),
...                      Fraction(1, 10**9))
>>> w, f"{error:.3g}"
((Fraction(927538921, 1311738121), Fraction(927538920, 1311738121), Fraction(0, 1)), '5.39e-10')
"""

from __future__ import annotations

from fractions import Fraction
from math import isqrt

import mpmath
from mpmath.libmp import to_rational

from coopkin_sym.errors import ArgumentError, NumberError
from coopkin_sym.exact.angles import simplest_between

__all__ = ["axis_angle", "snap_axis"]

Vector = tuple[Fraction, Fraction, Fraction]

#: Tries of ever closer points (three always suffice: a point within bound/(2 sqrt 2)
#: of the stereographic coordinates is within the bound).
_MAX_TRIES = 8
#: The largest precision (bits) of the intervals that decide whether an axis is within
#: the bound (the comparison is with an irrational number: refining always ends).
_MAX_PREC = 1 << 16


def snap_axis(v: Vector, bound: Fraction) -> tuple[Vector, float]:  # float-ok
    """The exact unit vector ``v`` is snapped to (see the module) and its angle to
    ``v`` in radians (a float, for display).

    Example
    -------
    >>> snap_axis((Fraction(0), Fraction(0), Fraction(2)), Fraction(1, 10**6))
    ((Fraction(0, 1), Fraction(0, 1), Fraction(1, 1)), 0.0)
    """
    v = tuple(Fraction(x) for x in v)
    bound = Fraction(bound)
    if not 0 < bound < Fraction(3, 2):
        raise ArgumentError(f"a snapping bound must be between 0 and 3/2 rad, got {bound}")
    norm2 = sum(x * x for x in v)
    if norm2 == 0:
        raise ArgumentError("the zero vector has no direction")
    root = _rational_sqrt(norm2)
    if root is not None:
        return tuple(x / root for x in v), 0.0
    big = max(range(3), key=lambda i: abs(v[i]))
    others = [i for i in range(3) if i != big]
    sign = 1 if v[big] > 0 else -1
    h = bound
    for _ in range(_MAX_TRIES):
        plane = [_near(v[i], abs(v[big]), norm2, h) for i in others]
        a, c = plane
        s = 1 + a * a + c * c
        w = [Fraction(0)] * 3
        w[others[0]], w[others[1]] = 2 * a / s, 2 * c / s
        w[big] = sign * (1 - a * a - c * c) / s
        w = tuple(w)
        if _within(v, norm2, w, bound):
            return w, axis_angle(v, w)
        h /= 2
    raise NumberError("", f"cannot snap the axis {v} within {bound} rad")  # pragma: no cover


def axis_angle(v: Vector, w: Vector) -> float:  # float-ok: for display
    """The angle between two nonzero rational vectors (radians), computed in intervals
    to 60 significant bits at least.

    Example
    -------
    >>> f"{axis_angle((1, 0, 0), (1, 1, 0)):.6f}"
    '0.785398'
    """
    v, w = tuple(map(Fraction, v)), tuple(map(Fraction, w))
    cross = (v[1] * w[2] - v[2] * w[1], v[2] * w[0] - v[0] * w[2],
             v[0] * w[1] - v[1] * w[0])
    cross2 = sum(x * x for x in cross)
    dot = sum(x * y for x, y in zip(v, w, strict=True))
    if cross2 == 0:
        return 0.0 if dot > 0 else float(mpmath.pi)  # float-ok: for display
    iv = mpmath.iv
    saved = iv.prec
    prec = 64
    try:
        while True:
            iv.prec = prec
            angle = iv.atan2(iv.sqrt(_interval(cross2)), _interval(dot))
            if angle.delta <= angle.a * mpmath.mpf(2) ** -60 or prec > _MAX_PREC:
                return float((_end(angle.a) + _end(angle.b)) / 2)  # float-ok: for display
            prec *= 2
    finally:
        iv.prec = saved


def _rational_sqrt(x: Fraction) -> Fraction | None:
    """``sqrt(x)`` when it is rational, else None."""
    p, q = isqrt(x.numerator), isqrt(x.denominator)
    return Fraction(p, q) if p * p == x.numerator and q * q == x.denominator else None


def _interval(x: Fraction):
    """A certified enclosure of the rational ``x``."""
    return mpmath.iv.mpf(x.numerator) / x.denominator


def _end(x) -> Fraction:
    """The exact value of a (finite) end ``x.a`` or ``x.b`` of an interval."""
    return Fraction(*to_rational(x._mpi_[0]))


def _near(x: Fraction, big: Fraction, norm2: Fraction, h: Fraction) -> Fraction:
    """The simplest rational within ``h`` of the stereographic coordinate
    ``x / (|v| + big)`` (certified: the interval is shrunk by its enclosure)."""
    iv = mpmath.iv
    saved = iv.prec
    try:
        iv.prec = 64 + 2 * h.denominator.bit_length()
        y = _interval(x) / (iv.sqrt(_interval(norm2)) + _interval(big))
        lo = _end(y.b) - h
        hi = _end(y.a) + h
    finally:
        iv.prec = saved
    return simplest_between(lo, hi)


def _within(v: Vector, norm2: Fraction, w: Vector, bound: Fraction) -> bool:
    """Whether the angle between ``v`` and the unit vector ``w`` is at most ``bound``,
    decided exactly: ``v.w > 0`` and ``(v.w)^2 >= |v|^2 cos^2(bound)``."""
    dot = sum(x * y for x, y in zip(v, w, strict=True))
    if dot <= 0:
        return False
    lhs = dot * dot
    iv = mpmath.iv
    saved = iv.prec
    prec = 64 + 2 * bound.denominator.bit_length()
    try:
        while prec <= _MAX_PREC:
            iv.prec = prec
            cos2 = iv.cos(_interval(bound)) ** 2 * _interval(norm2)
            if lhs >= _end(cos2.b):
                return True
            if lhs < _end(cos2.a):
                return False
            prec *= 2
    finally:
        iv.prec = saved
    raise NumberError("", "cannot decide an axis snap")  # pragma: no cover - cos^2 irrational
