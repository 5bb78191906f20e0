"""Exact angles: how the package names, reads, writes, snaps and moves an angle.

A revolute joint ``q`` enters every polynomial through its tangent half-angle
``t = tan(q/2)``, the ring variable ``t_<joint>`` (:func:`tangent_name`); at
``q = pi``, where ``t`` is infinite, through ``s = cot(q/2)``, the variable
``s_<joint>`` (:func:`cotangent_name`). An :class:`ExactAngle` is an angle whose
tangent half-angle is rational or infinite, held as homogeneous integers
``tan(q/2) = num/den`` (``(1, 0)`` is ``q = pi``): it is read from text by the package's
one parser (:func:`~coopkin_sym.exact.parse.parse_angle`), written back in ``--at``
syntax, snapped from a float within a stated bound (the float only chooses), and
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

import math
from dataclasses import dataclass
from fractions import Fraction

import flint
import sympy as sp
from sympy.polys.polyerrors import NotAlgebraic

from coopkin_sym.errors import NumberError
from coopkin_sym.exact.parse import parse_angle, tangent_text
from coopkin_sym.exact.rationals import to_fraction, to_sympy
from coopkin_sym.exact.realroot import RealRoot

__all__ = ["COTANGENT_PREFIX", "TANGENT_PREFIX", "ExactAngle", "algebraic_angle",
           "cotangent_name", "joint_of", "tangent_name"]

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

    Example
    -------
    >>> ExactAngle.from_tangent(Fraction(-1)).text
    '-pi/2'
    >>> ExactAngle.from_cos_sin(-1, 0).text, ExactAngle.from_tangent(None).den
    ('pi', 0)
    """

    num: int
    den: int

    @classmethod
    def from_tangent(cls, t: Fraction | int | None) -> ExactAngle:
        """The angle with ``tan(q/2) = t`` (None: ``q = pi``)."""
        if t is None:
            return cls(1, 0)
        t = Fraction(t)
        return cls(t.numerator, t.denominator)

    @classmethod
    def from_cos_sin(cls, cos, sin) -> ExactAngle:
        """The angle with exact rational ``(cos q, sin q)``."""
        c, s = Fraction(str(cos)), Fraction(str(sin))
        return cls.from_tangent(None if c == -1 else s / (1 + c))

    @classmethod
    def parse(cls, text: object, where: str) -> ExactAngle:
        """An angle from ``--at`` text (``pi/2``, ``2*atan(1/3)``), through the one
        parser; an angle without a rational tangent half-angle is refused there, with
        the nearest exact ones named."""
        return cls.from_cos_sin(*parse_angle(text, where))

    @classmethod
    def snap(cls, q: float, bound: float) -> tuple[ExactAngle, float]:  # float-ok
        """The angle near ``q`` (radians) with the smallest rational tangent
        half-angle within ``bound``: the first continued-fraction convergent of
        ``tan(q/2)`` (of ``cot(q/2)`` beyond 1) that meets it; and its distance to
        ``q``. The float only chooses: the angle returned is exact.

        Example
        -------
        >>> angle, error = ExactAngle.snap(math.pi / 3, 1e-3)
        >>> angle.text, error < 1e-3
        ('2*atan(15/26)', True)
        """
        q = math.remainder(q, 2 * math.pi)  # float-ok: choosing only
        t = math.tan(q / 2)  # float-ok
        inverse = abs(t) > 1  # float-ok
        for f in _convergents(Fraction(1 / t if inverse else t)):  # float-ok
            if inverse:
                a, b = (1, 0) if f == 0 else (f.denominator * (1 if f > 0 else -1),
                                              abs(f.numerator))
            else:
                a, b = f.numerator, f.denominator
            err = abs(math.remainder(2 * math.atan2(a, b) - q, 2 * math.pi))  # float-ok
            if err <= bound:  # float-ok
                return cls(a, b), err
        raise NumberError("", f"cannot snap the angle {q!r} within {bound} rad")  # pragma: no cover

    @property
    def tangent(self) -> Fraction | None:
        """``tan(q/2)``, None at ``q = pi``."""
        return None if self.den == 0 else Fraction(self.num, self.den)

    @property
    def cos_sin(self) -> tuple[sp.Rational, sp.Rational]:
        """``(cos q, sin q)``, exact rationals."""
        if self.den == 0:
            return sp.Integer(-1), sp.Integer(0)
        t = sp.Rational(self.num, self.den)
        return (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)

    @property
    def text(self) -> str:
        """The angle in ``--at`` syntax (``0``, ``pi/2``, ``-pi/2``, ``pi``,
        ``2*atan(p/q)``), as :func:`~coopkin_sym.exact.parse.angle_text` writes it."""
        return tangent_text(self.tangent)

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


def _convergents(x: Fraction):
    """The continued fraction convergents of ``x``, in order (the last is ``x``)."""
    p, q = x.numerator, x.denominator
    h0, h1, k0, k1 = 0, 1, 1, 0
    while q:
        a, r = divmod(p, q)
        h0, h1 = h1, a * h1 + h0
        k0, k1 = k1, a * k1 + k0
        yield Fraction(h1, k1)
        p, q = q, r


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
