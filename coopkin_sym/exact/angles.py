"""Exact angles: how the package names, reads, writes, snaps and moves an angle.

A revolute joint ``q`` enters every polynomial through its tangent half-angle
``t = tan(q/2)``, the ring variable ``t_<joint>`` (:func:`tangent_name`); at
``q = pi``, where ``t`` is infinite, through ``s = cot(q/2)``, the variable
``s_<joint>`` (:func:`cotangent_name`). An :class:`ExactAngle` is an angle whose
tangent half-angle is rational or infinite, held as homogeneous integers
``tan(q/2) = num/den`` (``(1, 0)`` is ``q = pi``): it is read from text by the package's
one parser (:func:`~coopkin_sym.exact.parse.parse_angle`), written back in ``--at``
syntax, snapped from a float (or an exact rational) to the simplest exact angle within
a stated bound (decided exactly: the bound always holds), and
nudged by a small distance (for float checks near a witness). An angle with an
irrational but algebraic tangent half-angle is written by :func:`algebraic_angle`.

Example
-------
>>> a = ExactAngle.parse("2*atan(1/3)", "q1")
>>> a.tangent, a.text, a.cos_sin
(Fraction(1, 3), '2*atan(1/3)', (4/5, 3/5))
>>> ExactAngle.parse("pi", "q2").tangent is None, tangent_name("q2"), joint_of("s_q2")
(True, 't_q2', 'q2')
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from fractions import Fraction

import flint
import mpmath
import sympy as sp
from mpmath.libmp import to_rational
from sympy.polys.polyerrors import NotAlgebraic

from coopkin_sym.errors import ArgumentError, NumberError
from coopkin_sym.exact.parse import parse_angle, parse_number, tangent_text
from coopkin_sym.exact.rationals import to_fraction, to_sympy
from coopkin_sym.exact.realroot import RealRoot

__all__ = ["COTANGENT_PREFIX", "TANGENT_PREFIX", "ExactAngle", "algebraic_angle",
           "cotangent_name", "joint_of", "simplest_between", "tangent_name"]

#: The ring variable of a revolute joint is ``t_<joint>`` = tan(q/2) ...
TANGENT_PREFIX = "t_"
#: ... and, at q = pi, ``s_<joint>`` = cot(q/2).
COTANGENT_PREFIX = "s_"


def tangent_name(joint: str) -> str:
    """The variable ``t_<joint>`` = tan(q/2) of a revolute joint.

    Example
    -------
    >>> tangent_name("q1")
    't_q1'
    """
    return TANGENT_PREFIX + joint


def cotangent_name(joint: str) -> str:
    """The variable ``s_<joint>`` = cot(q/2) of a revolute joint (its chart at pi).

    Example
    -------
    >>> cotangent_name("q1")
    's_q1'
    """
    return COTANGENT_PREFIX + joint


def joint_of(variable: str) -> str | None:
    """The joint of a ``t_<joint>`` or ``s_<joint>`` variable, else None.

    Example
    -------
    >>> joint_of("t_elbow"), joint_of("L")
    ('elbow', None)
    """
    for prefix in (TANGENT_PREFIX, COTANGENT_PREFIX):
        if variable.startswith(prefix) and len(variable) > len(prefix):
            return variable[len(prefix):]
    return None


@dataclass(frozen=True)
class ExactAngle:
    """An angle with a rational (or infinite) tangent half-angle ``num/den``.

    The pair is kept in lowest terms with ``den >= 0``, and ``q = pi`` is ``(1, 0)``,
    so that equal angles are equal (and hash alike). This is the one type of an exact
    joint angle: ``--at`` values, sweeps, witnesses and pictures all hold it.

    Example
    -------
    >>> ExactAngle.from_tangent(Fraction(-1)).text
    '-pi/2'
    >>> ExactAngle.from_cos_sin(-1, 0).text, ExactAngle.from_tangent(None).den
    ('pi', 0)
    >>> ExactAngle(2, -6) == ExactAngle(-1, 3), ExactAngle(-5, 0)
    (True, ExactAngle(num=1, den=0))
    """

    num: int
    den: int

    def __post_init__(self) -> None:
        num, den = self.num, self.den
        if not (isinstance(num, int) and isinstance(den, int)) \
                or isinstance(num, bool) or isinstance(den, bool):
            raise ArgumentError(f"an exact angle is a pair of integers num/den = tan(q/2), "
                                f"got {num!r}, {den!r}")
        if den == 0:
            if num == 0:
                raise ArgumentError("an exact angle cannot be 0/0 (tan(q/2) = num/den)")
            num = 1
        else:
            g = math.gcd(num, den) * (1 if den > 0 else -1)
            num, den = int(num // g), int(den // g)
        if (num, den) != (self.num, self.den) or type(self.num) is not int \
                or type(self.den) is not int:
            object.__setattr__(self, "num", num)
            object.__setattr__(self, "den", den)

    @classmethod
    def from_tangent(cls, t: Fraction | int | None) -> ExactAngle:
        """The angle with ``tan(q/2) = t`` (None: ``q = pi``)."""
        if t is None:
            return cls(1, 0)
        t = Fraction(t)
        return cls(t.numerator, t.denominator)

    @classmethod
    def from_cos_sin(cls, cos: object, sin: object) -> ExactAngle:
        """The angle with exact rational ``(cos q, sin q)``.

        Raises
        ------
        NumberError
            If ``cos`` or ``sin`` is not an exact rational (a float is refused), or
            ``cos^2 + sin^2 != 1``.

        Example
        -------
        >>> import sympy as sp
        >>> ExactAngle.from_cos_sin(sp.Rational(4, 5), sp.Rational(-3, 5)).text
        '2*atan(-1/3)'
        """
        c = parse_number(cos, {}, "cos") if not isinstance(cos, float) else None
        s = parse_number(sin, {}, "sin") if not isinstance(sin, float) else None
        if c is None or s is None or not (c.is_Rational and s.is_Rational):
            raise NumberError("angle", f"cos = {cos}, sin = {sin} must be exact rationals")
        if c**2 + s**2 != 1:
            raise NumberError("angle", f"cos = {c}, sin = {s} is not a point on the unit "
                                       f"circle")
        return cls._on_circle(c, s)

    @classmethod
    def _on_circle(cls, c: sp.Rational, s: sp.Rational) -> ExactAngle:
        """The angle of a rational point ``(c, s)`` known to be on the unit circle."""
        if c == -1:
            return cls(1, 0)
        # tan(q/2) = sin / (1 + cos)
        return cls(int(s.p) * int((1 + c).q), int(s.q) * int((1 + c).p))

    @classmethod
    def parse(cls, text: object, where: str) -> ExactAngle:
        """An angle from ``--at`` text (``pi/2``, ``2*atan(1/3)``), through the one
        parser; an angle without a rational tangent half-angle is refused there, with
        the nearest exact ones named."""
        return cls._on_circle(*parse_angle(text, where))

    @classmethod
    def snap(cls, q: float | Fraction, bound: float | Fraction  # float-ok
             ) -> tuple[ExactAngle, float]:  # float-ok: the distance, for display
        """The simplest exact angle within ``bound`` of ``q`` (radians; a float is its
        exact binary value, a :class:`~fractions.Fraction` is exact): ``0`` or ``pi``
        when one is within the bound, else the angle whose ``tan(q/2)`` is the rational
        with the smallest denominator in the interval of tangents within the bound
        (:func:`simplest_between`); and its distance to ``q``. The decisions are exact
        (interval arithmetic, refined until certain), so the distance never exceeds
        the bound; the distance returned is rounded to a float for display.

        Example
        -------
        >>> angle, error = ExactAngle.snap(Fraction("1.5707963"), Fraction(1, 10**6))
        >>> angle.text, f"{error:.3g}"
        ('pi/2', '2.68e-08')
        >>> ExactAngle.snap(math.pi / 3, 1e-3)[0].text
        '2*atan(15/26)'
        """
        q, bound = Fraction(q), Fraction(bound)
        if not 0 < bound < Fraction(3, 2):
            raise ArgumentError(f"a snapping bound must be between 0 and 3/2 rad, got {bound}")
        if q == 0:
            return cls(0, 1), 0.0
        prec = 64 + abs(q.numerator // q.denominator).bit_length() + bound.denominator.bit_length()
        while prec <= _MAX_SNAP_PREC:
            angle = _snap_at(q, bound, prec)
            if angle is not None:
                return angle, _distance(angle, q, prec)
            prec *= 2
        raise NumberError("", f"cannot snap the angle {q} within {bound} rad")  # pragma: no cover

    @property
    def tangent(self) -> Fraction | None:
        """``tan(q/2)``, None at ``q = pi``."""
        return None if self.den == 0 else Fraction(self.num, self.den)

    @functools.cached_property
    def cos_sin(self) -> tuple[sp.Rational, sp.Rational]:
        """``(cos q, sin q)``, exact rationals (computed once per angle)."""
        if self.den == 0:
            return sp.Integer(-1), sp.Integer(0)
        n2, d2 = self.num * self.num, self.den * self.den
        return sp.Rational(d2 - n2, d2 + n2), sp.Rational(2 * self.num * self.den, d2 + n2)

    @functools.cached_property
    def text(self) -> str:
        """The angle in ``--at`` syntax, the way the package writes an exact angle
        (:func:`~coopkin_sym.exact.parse.tangent_text`): ``0``, ``pi/2``, ``-pi/2``,
        ``pi``, else ``2*atan(p/q)`` with ``p/q = tan(q/2)``, in ``(-pi, pi]``;
        :meth:`parse` reads it back.

        Example
        -------
        >>> [ExactAngle(n, d).text for n, d in ((0, 1), (1, 1), (-1, 1), (1, 0), (-1, 3))]
        ['0', 'pi/2', '-pi/2', 'pi', '2*atan(-1/3)']
        """
        return tangent_text(self.tangent)

    @property
    def value(self) -> sp.Expr:
        """The angle as an exact SymPy number, in ``(-pi, pi]``, written as
        :attr:`text` is (``pi/2``, ``2*atan(1/3)``).

        Example
        -------
        >>> ExactAngle(1, 3).value, ExactAngle(1, 0).value
        (2*atan(1/3), pi)
        """
        t = self.tangent
        if t is None:
            return sp.pi
        return {0: sp.Integer(0), 1: sp.pi / 2, -1: -sp.pi / 2}.get(
            t, 2 * sp.atan(sp.Rational(t.numerator, t.denominator)))

    def radians(self) -> float:  # float-ok: for choosing and for pictures only
        """The angle in radians, in ``(-pi, pi]`` (a float)."""
        return 2 * math.atan2(self.num, self.den)  # float-ok

    def nudged(self, distance: float) -> ExactAngle:  # float-ok
        """An exact angle about ``distance`` radians above this one (the float only
        chooses it: its tangent half-angle is the binary float's exact value).

        Example
        -------
        >>> moved = ExactAngle.parse("pi/2", "q1").nudged(1e-6)
        >>> 0 < moved.radians() - math.pi / 2 < 2e-6
        True
        """
        cos, sin = self.cos_sin
        q = float(sp.atan2(sin, cos)) + distance  # float-ok: correctly rounded, then moved
        # 2 atan(tan(q/2)) is q up to a whole turn, on either side of pi
        return ExactAngle.from_tangent(Fraction(math.tan(q / 2)))  # float-ok: exact value


#: The largest precision (bits) of the intervals that decide a snap; an undecided snap
#: past it is impossible (the ends of the interval are irrational) but would be an error.
_MAX_SNAP_PREC = 1 << 16


def simplest_between(lo: Fraction, hi: Fraction) -> Fraction:
    """The simplest rational in the closed interval ``[lo, hi]``: the one with the
    smallest denominator (it has the smallest absolute numerator too: the first
    one met going down the Stern-Brocot tree), ``0`` when the interval holds it.

    Example
    -------
    >>> simplest_between(Fraction(3, 10), Fraction(7, 20)), simplest_between(Fraction(-5, 2), 1)
    (Fraction(1, 3), Fraction(0, 1))
    """
    lo, hi = Fraction(lo), Fraction(hi)
    if lo > hi:
        raise ArgumentError(f"an empty interval [{lo}, {hi}]")
    if lo <= 0 <= hi:
        return Fraction(0)
    if hi < 0:
        return -simplest_between(-hi, -lo)
    terms = []
    while True:
        whole = lo.numerator // lo.denominator
        if whole == lo or whole + 1 <= hi:
            value = Fraction(whole if whole == lo else whole + 1)
            break
        terms.append(whole)                  # lo, hi in (whole, whole + 1)
        lo, hi = 1 / (hi - whole), 1 / (lo - whole)
    for whole in reversed(terms):
        value = whole + 1 / value
    return value


def _interval(x: Fraction):
    """A certified enclosure of the rational ``x`` (at the current interval precision)."""
    return mpmath.iv.mpf(x.numerator) / x.denominator


def _exact(x) -> Fraction:
    """The exact value of a (finite) end ``x.a`` or ``x.b`` of an interval."""
    return Fraction(*to_rational(x._mpi_[0]))


def _nearest_integer(x) -> int:
    """The integer nearest the middle of the interval ``x`` (computed exactly)."""
    middle = (_exact(x.a) + _exact(x.b)) / 2
    return math.floor(middle + Fraction(1, 2))


def _snap_at(q: Fraction, bound: Fraction, prec: int) -> ExactAngle | None:
    """:meth:`ExactAngle.snap` decided with intervals of ``prec`` bits, or None when
    they are too wide to decide."""
    iv = mpmath.iv
    saved = iv.prec
    try:
        iv.prec = prec
        pi, qi, b = iv.pi, _interval(q), _interval(bound)
        turns = _nearest_integer(qi / (2 * pi))
        r = qi - 2 * pi * turns           # q - 2 pi turns, about in [-pi, pi]
        if r.delta > 1 or abs(_exact(r.a)) > 4 or abs(_exact(r.b)) > 4:
            return None                   # too wide to tell the turn
        for beyond in (r + b - pi, -r + b - pi):     # is pi (or -pi) within the bound?
            if beyond.a >= 0:
                return ExactAngle(1, 0)
            if beyond.b >= 0:
                return None
        if turns == 0:                    # r = q exactly: is 0 within the bound?
            if abs(q) <= bound:
                return ExactAngle(0, 1)
        else:
            low, high = r - b, r + b
            if low.b <= 0 <= high.a:
                return ExactAngle(0, 1)
            if low.a <= 0 <= high.b:
                return None
        low, high = iv.tan((r - b) / 2), iv.tan((r + b) / 2)
        if _exact(low.b) > _exact(high.a):
            return None
        t = simplest_between(_exact(low.a), _exact(high.b))
        if not _exact(low.b) <= t <= _exact(high.a):
            return None
        return ExactAngle(t.numerator, t.denominator)
    finally:
        iv.prec = saved


def _distance(angle: ExactAngle, q: Fraction, prec: int) -> float:  # float-ok
    """``|angle - q|`` up to whole turns, to 60 bits at least (for display)."""
    iv = mpmath.iv
    saved = iv.prec
    try:
        while True:
            iv.prec = prec
            two_pi = 2 * iv.pi
            d = 2 * iv.atan2(iv.mpf(angle.num), iv.mpf(angle.den)) - _interval(q)
            d = d - two_pi * _nearest_integer(d / two_pi)
            if d.b < 0:
                d = -d
            if (d.a > 0 and d.b < 4 and d.delta <= d.a * mpmath.mpf(2) ** -60) \
                    or prec > _MAX_SNAP_PREC:
                return float((_exact(d.a) + _exact(d.b)) / 2)  # float-ok: for display
            prec *= 2
    finally:
        iv.prec = saved


_T = sp.Symbol("t")


def algebraic_angle(tangent: sp.Expr) -> sp.Expr:
    """``2 atan(tangent)`` for a real algebraic ``tangent`` (a SymPy expression), as a
    rational multiple of pi when it is one (decided exactly, by
    :meth:`~coopkin_sym.exact.realroot.RealRoot.pi_multiple` on the real root of its
    minimal polynomial that it is), else left as ``2*atan(tangent)``.

    Example
    -------
    >>> algebraic_angle(sp.sqrt(2) - 1), algebraic_angle(sp.sqrt(2))
    (pi/4, 2*atan(sqrt(2)))
    """
    plain = 2 * sp.atan(tangent)
    try:
        minimal = sp.Poly(sp.minimal_polynomial(tangent, _T), _T)
        coeffs = [int(c) for c in reversed(minimal.all_coeffs())]
        roots = [r for r in RealRoot.all_of(coeffs) if r.contains(tangent)]
    except (TypeError, ValueError, NotImplementedError, NotAlgebraic, sp.PolynomialError):
        return plain
    if len(roots) != 1:
        return plain
    ratio = roots[0].pi_multiple(to_fraction(tangent) if tangent.is_Rational
                                 else flint.fmpq_poly([0, 1]))
    return plain if ratio is None else sp.pi * to_sympy(ratio)
