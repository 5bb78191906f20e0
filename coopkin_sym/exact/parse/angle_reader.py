"""Exact angles from text, decided exactly from their parts (rational multiples of
``pi`` and of ``atan(p/q)``) with bounded work: :func:`parse_angle`,
:func:`algebraic_half_angle`, and the text written back (:func:`tangent_text`, the
one writer of an exact angle, which :attr:`~coopkin_sym.exact.angles.ExactAngle.text`
uses)."""

from __future__ import annotations

import math
import numbers
import re
from dataclasses import dataclass
from fractions import Fraction

import mpmath
import sympy as sp

from coopkin_sym import limits
from coopkin_sym.errors import NumberError
from coopkin_sym.exact.parse.messages import _show, _sympy_text
from coopkin_sym.exact.parse.reader import _Sym
from coopkin_sym.exact.parse.values import _INT, _value
from coopkin_sym.exact.rationals import to_fraction, to_sympy

# ------------------------------------------------------------------------ angles


@dataclass
class _AngleParts:
    """``q = pi_coeff * pi + sum(b * atan(r)) + radians + other``."""

    pi_coeff: Fraction
    atans: dict[Fraction, Fraction]
    radians: Fraction
    other: list[sp.Expr]


def _angle_parts(q: sp.Expr) -> _AngleParts:
    parts = _AngleParts(Fraction(0), {}, Fraction(0), [])
    for term in sp.Add.make_args(q):
        coeff, rest = term.as_coeff_Mul()
        if not coeff.is_Rational:
            parts.other.append(term)
            continue
        k = to_fraction(coeff)
        if rest == 1:
            parts.radians += k
        elif rest is sp.pi:
            parts.pi_coeff += k
        elif isinstance(rest, sp.atan) and rest.args[0].is_Rational:
            r = Fraction(int(rest.args[0].p), int(rest.args[0].q))
            parts.atans[r] = parts.atans.get(r, Fraction(0)) + k
        else:
            parts.other.append(term)
    parts.atans = {r: b for r, b in parts.atans.items() if b}
    return parts


class _Gauss:
    """``(x + i y) / z``: a point of Q(i), integers with ``z > 0``."""

    def __init__(self, x: int, y: int, z: int):
        g = math.gcd(math.gcd(x, y), z)
        self.x, self.y, self.z = x // g, y // g, z // g

    def __mul__(self, other: _Gauss) -> _Gauss:
        return _Gauss(self.x * other.x - self.y * other.y,
                      self.x * other.y + self.y * other.x, self.z * other.z)

    def conj(self) -> _Gauss:
        return _Gauss(self.x, -self.y, self.z)

    def __pow__(self, n: int) -> _Gauss:
        base = self if n >= 0 else self.conj()     # unit modulus: inverse = conjugate
        n = abs(n)
        out = _Gauss(1, 0, 1)
        while n:
            if n & 1:
                out = out * base
            n >>= 1
            if n:
                base = base * base
        return out


def _rotation(r: Fraction) -> _Gauss:
    """``exp(2 i atan r) = (1 + i r)^2 / (1 + r^2)``."""
    a, b = r.denominator, r.numerator           # (a + i b) / a = 1 + i r
    return _Gauss(a * a - b * b, 2 * a * b, a * a + b * b)


class _Undecided(Exception):
    """An angle this module does not decide within its budgets (message inside)."""


def _angle_point(parts: _AngleParts, where: str, shown: str) -> tuple[Fraction, Fraction] | None:
    """``(cos q, sin q)`` when both are rational, ``None`` when ``exp(i q)`` is not a
    rational point of the circle; :class:`_Undecided` when the parts are out of
    reach. Decided exactly: ``exp(i n q)`` is computed in Q(i) for the smallest ``n``
    making it rational, its ``n``-th root is located with interval arithmetic and
    confirmed exactly."""
    if parts.other:
        raise _Undecided("only rational multiples of pi and of atan(p/q) are decided")
    if parts.radians:
        return None                             # tan of a nonzero rational: irrational
    if len(parts.atans) + bool(parts.pi_coeff) > limits.MAX_ANGLE_TERMS:
        raise _Undecided(f"more than {limits.MAX_ANGLE_TERMS} terms")
    a = parts.pi_coeff
    if not parts.atans:
        if (2 * a).denominator != 1:
            return None                         # Niven: tan(a pi/2) is irrational
        return [(Fraction(1), Fraction(0)), (Fraction(0), Fraction(1)),
                (Fraction(-1), Fraction(0)), (Fraction(0), Fraction(-1))][int(2 * a) % 4]
    # exp(i q) = i^(2a) * prod w_r^(b/2), w_r = exp(2 i atan r) in Q(i)
    n = math.lcm((2 * a).denominator, *((b / 2).denominator for b in parts.atans.values()))
    if n > limits.MAX_ANGLE_ORDER:
        raise _Undecided(f"deciding it needs an {n}-th root (at most "
                         f"{limits.MAX_ANGLE_ORDER})")
    cost = sum(abs(b / 2 * n) * _rotation(r).z.bit_length() for r, b in parts.atans.items())
    if cost > 4 * limits.max_bits():
        raise _Undecided("its exact rotation has too many digits")
    w = [_Gauss(1, 0, 1), _Gauss(0, 1, 1), _Gauss(-1, 0, 1), _Gauss(0, -1, 1)][
        int(2 * a * n) % 4]
    for r, b in parts.atans.items():
        w = w * _rotation(r) ** int(b / 2 * n)
    if n == 1:
        return Fraction(w.x, w.z), Fraction(w.y, w.z)
    d = _iroot(w.z, n)
    if d is None:
        return None
    x, y = _nearest_point(parts, d, n)
    if x is None or x * x + y * y != d * d:
        return None
    z = _Gauss(x, y, d) ** n
    if (z.x, z.y, z.z) != (w.x, w.y, w.z):
        return None
    return Fraction(x, d), Fraction(y, d)


def _iroot(value: int, n: int) -> int | None:
    """The integer ``n``-th root of ``value`` when it is exact."""
    root = round(value ** (1.0 / n)) if value.bit_length() < 1000 else None  # float-ok
    if root is None or root ** n != value:
        lo, hi = 0, 1 << (value.bit_length() // n + 1)
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if mid ** n <= value:
                lo = mid
            else:
                hi = mid - 1
        root = lo
    return root if root ** n == value else None


def _nearest_point(parts: _AngleParts, d: int, n: int) -> tuple[int | None, int | None]:
    """Integers ``x, y`` inside certified enclosures of ``d cos q`` and ``d sin q``
    (mpmath interval arithmetic), when the enclosures are narrow enough to tell the
    ``n`` roots apart; otherwise ``(None, None)``."""
    iv = mpmath.iv
    saved = iv.prec
    try:
        iv.prec = d.bit_length() + 2 * n.bit_length() + 80
        q = iv.pi * iv.mpf(parts.pi_coeff.numerator) / parts.pi_coeff.denominator
        for r, b in parts.atans.items():
            angle = iv.atan2(iv.mpf(r.numerator) / r.denominator, iv.mpf(1))
            q = q + angle * iv.mpf(b.numerator) / b.denominator
        xs, ys = iv.cos(q) * d, iv.sin(q) * d
        if (xs.delta + ys.delta) * n >= d:      # cannot separate the n roots
            return None, None
        x, y = int(mpmath.nint(xs.mid)), int(mpmath.nint(ys.mid))
        if x in xs and y in ys:
            return x, y
        return None, None
    finally:
        iv.prec = saved


def _angle_value(text: object, where: str) -> tuple[sp.Expr, str]:
    """The angle as an exact SymPy constant, and how to show it."""
    if isinstance(text, bool):
        raise NumberError(where, f"{_show(text)} is a truth value, not an angle")
    if not isinstance(text, str | numbers.Rational | sp.Expr):
        raise NumberError(where, f"{_show(text)} is not an angle (write it as text, "
                                 f"e.g. 'pi/2' or '2*atan(1/3)')")
    v, reader = _value(text, {}, where, "parameters")
    q = v.expr if isinstance(v, _Sym) else reader.to_sympy(v)
    if q.free_symbols:
        raise reader.fail("is not a number")
    if q.is_real is False or q.has(sp.I):
        raise reader.fail("is not a real angle")
    return q, reader.shown


def parse_angle(text: object, where: str) -> tuple[sp.Rational, sp.Rational]:
    """Read an exact angle and return its exact ``(cos q, sin q)``.

    An angle is exact when ``tan(q/2)`` is rational (``0``, ``pi/2``, ``-pi/2``,
    ``2*atan(1/3)``, ``atan(3/4)``, ``3*pi/2``) or when it is an odd multiple of
    ``pi``. Decided exactly from the angle's parts (rational multiples of ``pi`` and
    of ``atan(p/q)``), never by floats, with bounded work.

    Parameters
    ----------
    text : str (or an exact SymPy number)
        The angle in radians.
    where : str
        The entry being read, for error messages (e.g. ``"q1=pi/3"``).

    Returns
    -------
    tuple of sympy.Rational
        ``(cos q, sin q)``.

    Raises
    ------
    NumberError
        If the text cannot be parsed or the angle is not exact; the message names
        the nearest exact angles.

    Example
    -------
    >>> parse_angle("pi/2", "q1")
    (0, 1)
    >>> parse_angle("atan(3/4)", "q1")
    (4/5, 3/5)
    """
    simple = _simple_angle(text)
    if simple is not None:
        return simple
    q, shown = _angle_value(text, where)
    parts = _angle_parts(q)
    direct = _direct_tangent(parts)
    try:
        if direct is not None:
            point, tangent = _tangent_point(direct)
        else:
            point = _angle_point(parts, where, shown)
            tangent = _tangent_text(q, parts)
    except _Undecided as exc:
        if not _small_angle(parts):
            raise NumberError(where, f"angle {shown} cannot be decided: {exc} (write "
                                     "angles as sums of multiples of pi/2 and "
                                     "2*atan(p/q))") from None
        point, tangent = _sympy_point(q)
    if point is not None:
        c, s = point
        return to_sympy(c), sp.Rational(s.numerator,
                                                                      s.denominator)
    value = "its tan(q/2)" if tangent == _LONG_TANGENT else f"tan(q/2) = {tangent}"
    message = (f"angle {shown} is not exact: {value} is irrational; exact angles have a "
               f"rational tan(q/2)")
    near = _nearest_angles(q)
    if near:
        message += "; nearest exact angles: " + ", ".join(near)
    raise NumberError(where, message)


_SIMPLE_ATAN = re.compile(rf"\s*(-?)\s*2\s*\*\s*atan\(\s*(-?)\s*({_INT})\s*"
                          rf"(?:/\s*({_INT})\s*)?\)\s*", re.ASCII)
_SIMPLE_PI = re.compile(r"\s*(-?)\s*(?:([1-9]\d{0,5})\s*\*\s*)?pi\s*(?:/\s*([1-9]\d{0,5})\s*)?",
                        re.ASCII)
_ONE, _ZERO = sp.Integer(1), sp.Integer(0)
#: ``(cos, sin)`` of ``k pi / 2`` for ``k`` modulo 4
_QUARTER_POINTS = ((_ONE, _ZERO), (_ZERO, _ONE), (-_ONE, _ZERO), (_ZERO, -_ONE))


def _circle_point(p: int, q: int) -> tuple[sp.Rational, sp.Rational]:
    """``(cos q, sin q)`` of the angle with ``tan(q/2) = p/q`` (``q > 0``)."""
    w = p * p + q * q
    return sp.Rational(q * q - p * p, w), sp.Rational(2 * p * q, w)


def _simple_angle(value: object) -> tuple[sp.Rational, sp.Rational] | None:
    """``(cos q, sin q)`` of the commonest exact angles, read without the general
    parser: the texts ``2*atan(p/q)``, ``k*pi/2`` and ``0`` (and the same SymPy
    objects); ``None`` for anything else (the general parser then decides).

    Example
    -------
    >>> _simple_angle("-2*atan(1/3)"), _simple_angle("3*pi/2"), _simple_angle("pi/3")
    ((4/5, -3/5), (0, -1), None)
    >>> _simple_angle("2*atan(1/0)") is None
    True
    """
    if isinstance(value, str):
        if value.strip() == "0":
            return _QUARTER_POINTS[0]
        match = _SIMPLE_ATAN.fullmatch(value)
        if match:
            outer, inner, num, den = match.groups()
            q = int(den or 1)
            if q == 0:
                return None
            p = int(num)
            return _circle_point(-p if (outer == "-") != (inner == "-") else p, q)
        match = _SIMPLE_PI.fullmatch(value)
        if match:
            sign, k, d = match.groups()
            ratio = Fraction(int(k or 1), int(d or 1)) * (-1 if sign else 1) * 2
            if ratio.denominator == 1:                # a multiple of pi/2
                return _QUARTER_POINTS[int(ratio) % 4]
        return None
    if isinstance(value, sp.Basic):
        if value.is_Integer and value == 0:
            return _QUARTER_POINTS[0]
        if isinstance(value, sp.Mul) and len(value.args) == 2:
            k, f = value.args
            if k.is_Integer and abs(int(k)) == 2 and isinstance(f, sp.atan) and \
                    f.args[0].is_Rational:
                t = f.args[0]
                p, q = int(t.p), int(t.q)
                return _circle_point(p if int(k) > 0 else -p, q)
            if k.is_Rational and f is sp.pi:
                ratio = to_fraction(k) * 2
                if ratio.denominator == 1:
                    return _QUARTER_POINTS[int(ratio) % 4]
        if value is sp.pi:
            return _QUARTER_POINTS[2]
    return None


#: The largest integer factor of a term that SymPy's trigonometric simplification is
#: given: ``tan(n x)`` expands into a polynomial of degree ``n`` (``256/pi**4`` took a
#: minute).
SMALL_MULTIPLE = 24


def _small_angle(parts: _AngleParts) -> bool:
    """Whether the part this module does not decide itself is small enough for SymPy's
    trigonometric simplification: one short term, such as ``2*atan(sqrt(2))``, with no
    integer factor over :data:`SMALL_MULTIPLE`."""
    terms = len(parts.other) + len(parts.atans) + bool(parts.pi_coeff) + \
        bool(parts.radians)
    return terms == 1 and all(sp.count_ops(t) <= 20 and len(t.atoms(sp.atan)) <= 1
                              and not t.has(sp.CRootOf)
                              and abs(t.as_coeff_Mul()[0].p) <= SMALL_MULTIPLE
                              for t in parts.other)


def _direct_tangent(parts: _AngleParts) -> sp.Expr | None:
    """``x`` when the angle is ``2*atan(x)`` alone (``-x`` for ``-2*atan(x)``), for an
    ``x`` this module does not split further (``sqrt(2)``, a ``CRootOf``): then
    ``tan(q/2)`` is ``x`` itself, with no simplification to do."""
    if len(parts.other) != 1 or parts.atans or parts.pi_coeff or parts.radians:
        return None
    coeff, rest = parts.other[0].as_coeff_Mul()
    if isinstance(rest, sp.atan) and coeff in (2, -2):
        return rest.args[0] if coeff == 2 else -rest.args[0]
    return None


def _tangent_point(t: sp.Expr) -> tuple[tuple[Fraction, Fraction] | None, str]:
    """The exact point of the angle with ``tan(q/2) = t``, when ``t`` is rational."""
    if t is sp.zoo:
        return (Fraction(-1), Fraction(0)), "zoo"
    if not t.is_Rational:
        return None, _sympy_text(t)[:80]
    r = to_fraction(t)
    return ((1 - r * r) / (1 + r * r), 2 * r / (1 + r * r)), sp.sstr(t)


def _sympy_point(q: sp.Expr) -> tuple[tuple[Fraction, Fraction] | None, str]:
    """The exact point and ``tan(q/2)`` as text, by SymPy (small angles only)."""
    return _tangent_point(_half_angle_tangent(q))


def _tangent_text(q: sp.Expr, parts: _AngleParts) -> str:
    """``tan(q/2)`` for a message: simplified by SymPy only when that is cheap."""
    if not parts.atans and not parts.other and not parts.radians and \
            parts.pi_coeff.denominator <= 24:
        return sp.sstr(sp.tan(q / 2))
    return f"tan({sp.sstr(q / 2)})" if len(sp.sstr(q)) < 80 else _LONG_TANGENT


#: :func:`_tangent_text` of an angle too long to write in a message.
_LONG_TANGENT = "tan(q/2)"


def _half_angle_tangent(q: sp.Expr) -> sp.Expr:
    """``tan(q/2)`` simplified exactly by SymPy (``zoo`` when q is an odd multiple of
    pi); used only for small angles (see :func:`_small_angle`)."""
    t = sp.tan(q / 2)
    if t.is_Rational or t is sp.zoo:
        return t
    t = sp.expand_trig(t)
    if t.is_Rational or t is sp.zoo:
        return t
    return sp.simplify(t)


def _nearest_angles(q: sp.Expr) -> list[str]:
    """A few exact angles near ``q`` (floats used only to suggest candidates). ``q``
    is reduced modulo ``2 pi`` with as many digits as its integer part has, plus 30:
    a large angle (``10**80 + 1/3``) gets the angles near it, not near a float's
    remainder."""
    try:
        size = abs(sp.N(q, 15))
        digits = 30 + (int(sp.floor(sp.log(size, 10))) if size > 1 else 0)
        # float-ok: only to suggest nearby exact angles
        value = float(sp.N(sp.Mod(q, 2 * sp.pi), digits))  # float-ok
    except (TypeError, ValueError, OverflowError):
        return []
    if not math.isfinite(value):  # float-ok
        return []
    value = math.remainder(value, 2 * math.pi)  # float-ok: reduce to [-pi, pi]
    t = math.tan(value / 2)  # float-ok
    out: list[str] = []
    for limit in (10, 100, 1000):
        if abs(t) <= 1:  # float-ok
            approx = Fraction(t).limit_denominator(limit)  # float-ok
        else:
            inverse = Fraction(1 / t).limit_denominator(limit)  # float-ok
            approx = None if inverse == 0 else 1 / inverse
        text = tangent_text(approx)
        angle = math.pi if approx is None else 2 * math.atan(approx)  # float-ok: shown
        entry = f"{text} ({angle:.6f})"
        if entry not in out:
            out.append(entry)
    return out


def _degree_bound(parts: _AngleParts) -> int | None:
    """An upper bound on the degree over Q of ``tan(q/2)`` (``None``: unknown)."""
    if parts.other or parts.radians:
        return None
    half = parts.pi_coeff / 2
    if not parts.atans:
        m = half.denominator
        return int(sp.totient(m)) if m <= limits.MAX_ANGLE_ORDER else m
    n = math.lcm((2 * parts.pi_coeff).denominator,
                 *((b / 2).denominator for b in parts.atans.values()))
    # exp(i q) is a root of z^n = w in Q(i): degree at most 2n over Q
    return 2 * n


def algebraic_half_angle(text: str, where: str) -> sp.Expr:
    """``tan(q/2)`` of an angle whose tangent half-angle is a real algebraic number
    (``-pi/6``: ``-2 + sqrt(3)``), exactly; rational ones are returned too.

    The degree such an angle brings is bounded (:data:`~coopkin_sym.limits.
    MAX_ANGLE_DEGREE`): ``pi/99991`` is refused at once.

    Raises
    ------
    NumberError
        If the text is not an angle, is ``pi`` (infinite tangent), ``tan(q/2)`` is not
        algebraic (``q = 1``), its degree is over the budget, or it cannot be written
        in radicals.

    Example
    -------
    >>> algebraic_half_angle("-pi/6", "q1")
    -2 + sqrt(3)
    """
    q, shown = _angle_value(text, where)
    parts = _angle_parts(q)
    if parts.radians:
        raise NumberError(where, f"angle {shown}: tan(q/2) is not an algebraic number "
                                 "(a nonzero rational number of radians)")
    direct = _direct_tangent(parts)
    try:
        point = "direct" if direct is not None else _angle_point(parts, where, shown)
    except _Undecided as exc:
        if not _small_angle(parts):
            raise NumberError(where, f"angle {shown} cannot be decided: {exc}") from None
        point = "sympy"
    if point is not None and point not in ("sympy", "direct"):
        c, s = point
        if c == -1:
            raise NumberError(where, f"{shown}: tan(q/2) is infinite")
        t = s / (1 + c)
        return to_sympy(t)
    bound = _degree_bound(parts)
    if bound is not None and bound > limits.MAX_ANGLE_DEGREE:
        raise NumberError(where, f"angle {shown}: tan(q/2) may have degree up to {bound} "
                                 f"over the rationals, over the limit of "
                                 f"{limits.MAX_ANGLE_DEGREE}")
    if len(parts.atans) > 3:
        raise NumberError(where, f"angle {shown}: more than 3 atan terms in an angle with "
                                 "an irrational tan(q/2)")
    t = direct if direct is not None else _half_angle_tangent(q)
    if t is sp.zoo or t.has(sp.zoo, sp.oo, sp.nan):
        raise NumberError(where, f"{shown}: tan(q/2) is infinite")
    try:
        polynomial = sp.minimal_polynomial(t, sp.Symbol("t"))
    except (sp.polys.polyerrors.NotAlgebraic, NotImplementedError, ValueError,
            TypeError):
        if bound is not None:
            tangent = _tangent_text(q, parts)
        value = "its tan(q/2)" if tangent == _LONG_TANGENT else f"tan(q/2) = {tangent}"
        raise NumberError(where, f"angle {shown}: {value} is algebraic but could not "
                                 "be written in radicals") from None
        raise NumberError(where, f"angle {shown}: tan(q/2) = {t} is not an "
                                 "algebraic number") from None
    if sp.degree(polynomial, sp.Symbol("t")) > limits.MAX_ANGLE_DEGREE:
        raise NumberError(where, f"angle {shown}: tan(q/2) has degree "
                                 f"{sp.degree(polynomial, sp.Symbol('t'))} over the "
                                 f"rationals, over the limit of {limits.MAX_ANGLE_DEGREE}")
    return sp.radsimp(t)


def tangent_text(t: Fraction | None) -> str:
    """The angle with ``tan(q/2) = t`` (None: ``q = pi``) in ``--at`` syntax, in
    ``(-pi, pi]``: ``"0"``, ``"pi/2"``, ``"-pi/2"``, ``"pi"``, else ``"2*atan(p/q)"``.
    The one writer of an exact angle (:func:`parse_angle` reads it back); elsewhere
    an angle is written by :attr:`~coopkin_sym.exact.angles.ExactAngle.text`.

    Example
    -------
    >>> tangent_text(Fraction(-1, 3)), tangent_text(None)
    ('2*atan(-1/3)', 'pi')
    """
    if t is None:
        return "pi"
    return {0: "0", 1: "pi/2", -1: "-pi/2"}.get(t, f"2*atan({t})")
