"""Univariate polynomials over a number field ``Q(alpha) = Q[x]/(g)``, exact.

Elements of ``Q(alpha)`` are python-flint ``fmpq_poly`` in ``x`` of degree below
``deg g`` (``g`` irreducible); a polynomial in ``y`` over ``Q(alpha)`` is a list of such
coefficients, lowest degree first. This is what finding the ``y`` of a point whose
``x`` is a root of ``g`` needs: the gcd over ``Q(alpha)`` of the equations in ``y``.

Example
-------
>>> import flint
>>> g = flint.fmpq_poly([-2, 0, 1])                 # alpha = sqrt(2)
>>> field = NumberField(g)
>>> x = flint.fmpq_poly([0, 1])
>>> # y^2 - 2 and y - x have the common root y = alpha
>>> [str(c) for c in field.gcd([[-2, 0, 1], [-x, 1]])]    # y - alpha
['(-1)*x', '1']
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction

import flint

from coopkin_sym.errors import ArgumentError

Element = flint.fmpq_poly
KPoly = list[Element]


class NumberField:
    """``Q[x]/(g)`` for an irreducible ``g`` (``fmpq_poly``).

    Example
    -------
    >>> import flint
    >>> k = NumberField(flint.fmpq_poly([-2, 0, 1]))      # Q(sqrt(2))
    >>> k.inverse(k.element([0, 1]))                    # 1/sqrt(2) = sqrt(2)/2
    1/2*x
    """

    def __init__(self, g: flint.fmpq_poly):
        if g.degree() < 1:
            raise ArgumentError("a number field needs a polynomial of positive degree")
        self.g = g

    def element(self, a) -> Element:
        """``a`` (an integer, ``Fraction``, ``fmpq`` or polynomial in ``x``) reduced mod
        ``g``."""
        if isinstance(a, Fraction):
            a = flint.fmpq(a.numerator, a.denominator)
        return flint.fmpq_poly(a) % self.g if not isinstance(a, flint.fmpq_poly) \
            else a % self.g

    def inverse(self, a: Element) -> Element:
        """``1/a`` in the field (``a`` nonzero)."""
        a = self.element(a)
        if a.is_zero():
            raise ZeroDivisionError("zero has no inverse")
        d, s, _ = a.xgcd(self.g)
        if d.degree() != 0:
            raise ArgumentError(f"{self.g} is not irreducible (it shares {d} with {a})")
        return self.element(s / d)

    def _trim(self, p: Sequence) -> KPoly:
        out = [self.element(c) for c in p]
        while out and out[-1].is_zero():
            out.pop()
        return out

    def _divmod(self, a: KPoly, b: KPoly) -> tuple[KPoly, KPoly]:
        inv = self.inverse(b[-1])
        a = list(a)
        quotient = [flint.fmpq_poly(0)] * max(len(a) - len(b) + 1, 0)
        while len(a) >= len(b):
            factor = self.element(a[-1] * inv)
            shift = len(a) - len(b)
            quotient[shift] = factor
            for i, c in enumerate(b):
                a[shift + i] = self.element(a[shift + i] - factor * c)
            a = self._trim(a)
        return quotient, a

    def _rem(self, a: KPoly, b: KPoly) -> KPoly:
        return self._divmod(a, b)[1]

    def squarefree(self, p: Sequence) -> KPoly:
        """``p`` without repeated factors (``p / gcd(p, p')``), monic.

        Example
        -------
        >>> import flint
        >>> field = NumberField(flint.fmpq_poly([1, 4, 1]))   # alpha^2 + 4 alpha + 1
        >>> x = flint.fmpq_poly([0, 1])
        >>> # y^2 + 2 alpha y - 4 alpha - 1 = (y + alpha)^2
        >>> [str(c) for c in field.squarefree([-4 * x - 1, 2 * x, 1])]
        ['x', '1']
        """
        p = self._trim(p)
        if len(p) <= 2:
            return self.gcd([p])
        derivative = [self.element(c * i) for i, c in enumerate(p)][1:]
        common = self.gcd([p, derivative])
        if len(common) > 1:
            p = self._divmod(p, common)[0]
        return self.gcd([p])

    def gcd(self, polys: Sequence[Sequence]) -> KPoly:
        """The monic gcd over the field of polynomials in ``y`` (coefficient lists,
        lowest degree first); ``[]`` when all are zero."""
        g: KPoly = []
        for p in polys:
            b = self._trim(p)
            while b:
                g, b = b, (self._rem(g, b) if g else [])
        if not g:
            return []
        inv = self.inverse(g[-1])
        return [self.element(c * inv) for c in g]


__all__ = ["NumberField"]
