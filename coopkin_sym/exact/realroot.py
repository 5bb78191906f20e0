"""Real algebraic numbers: a root of an irreducible integer polynomial, exactly.

A :class:`RealRoot` is the irreducible polynomial and an isolating interval with
rational ends, so it can be compared, refined to any precision and written out
exactly: in radicals for degree two (``-2 + sqrt(3)``), as a SymPy ``CRootOf``
otherwise. As a tangent half-angle it reads as an angle, recognized exactly when it is
a rational multiple of pi (``-2 + sqrt(3)`` is ``tan(-pi/12)``).

Example
-------
>>> roots = RealRoot.all_of([1, 4, 1])           # t^2 + 4 t + 1
>>> [str(r.expression()) for r in roots]
['-2 - sqrt(3)', '-2 + sqrt(3)']
>>> [r.angle_text() for r in roots]
['-5*pi/6', '-pi/6']
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import sympy as sp

from coopkin_sym.exact.angles import algebraic_angle
from coopkin_sym.exact.rationals import to_fraction, to_sympy

_T = sp.Symbol("t")


@dataclass(frozen=True)
class RealRoot:
    """The root in ``(lo, hi]`` of the irreducible polynomial with integer
    coefficients ``coeffs`` (lowest degree first); ``index`` is its rank among the real
    roots, smallest first.

    Example
    -------
    >>> r = RealRoot.all_of([-2, 0, 1])[1]                # the positive root of x^2 - 2
    >>> r.expression(), r.lo < r.hi
    (sqrt(2), True)
    """

    coeffs: tuple[int, ...]
    lo: Fraction
    hi: Fraction
    index: int

    @classmethod
    def all_of(cls, coeffs) -> list[RealRoot]:
        """Every real root of the irreducible polynomial ``coeffs``, in increasing
        order."""
        poly = cls._poly_of(coeffs)
        out = []
        for i, ((lo, hi), _m) in enumerate(poly.intervals()):
            out.append(cls(tuple(int(c) for c in coeffs), to_fraction(lo),
                           to_fraction(hi), i))
        return out

    @staticmethod
    def _poly_of(coeffs) -> sp.Poly:
        return sp.Poly([int(c) for c in reversed(list(coeffs))], _T)

    @property
    def degree(self) -> int:
        return len(self.coeffs) - 1

    def polynomial_text(self, name: str) -> str:
        """The polynomial in the variable ``name``."""
        return sp.sstr(self._poly_of(self.coeffs).as_expr().subs(_T, sp.Symbol(name)))

    def refine(self, width: Fraction) -> tuple[Fraction, Fraction]:
        """An isolating interval of at most ``width``."""
        if self.lo == self.hi or self.hi - self.lo <= width:
            return self.lo, self.hi
        lo, hi = self._poly_of(self.coeffs).refine_root(
            to_sympy(self.lo),
            to_sympy(self.hi),
            eps=to_sympy(width))
        return to_fraction(lo), to_fraction(hi)

    def approximation(self, width: Fraction = Fraction(1, 10**40)) -> Fraction:
        """A rational within ``width`` of the root."""
        lo, hi = self.refine(width)
        return (lo + hi) / 2

    def __float__(self) -> float:
        return float(self.approximation(Fraction(1, 10**20)))  # float-ok: display only

    def expression(self) -> sp.Expr:
        """The root as an exact SymPy expression (radicals up to degree two)."""
        poly = self._poly_of(self.coeffs)
        if self.degree == 1:
            return sp.Rational(-self.coeffs[0], self.coeffs[1])
        if self.degree == 2:
            for r in sorted(sp.roots(poly, _T), key=lambda e: float(e)):  # float-ok: order
                if self._contains(r):
                    return r
        return sp.CRootOf(poly.as_expr(), self.index)

    def _contains(self, expr: sp.Expr) -> bool:
        lo = to_sympy(self.lo)
        hi = to_sympy(self.hi)
        return bool(expr > lo) and bool(expr <= hi)

    def angle(self) -> sp.Expr:
        """The angle ``q = 2 atan(root)`` in ``(-pi, pi)``: see
        :func:`~coopkin_sym.exact.angles.algebraic_angle`."""
        return algebraic_angle(self.expression())

    def angle_text(self) -> str:
        """:meth:`angle` in ``--at`` syntax."""
        return sp.sstr(self.angle())


__all__ = ["RealRoot"]
