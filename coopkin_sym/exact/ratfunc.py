"""Rational functions over Z: reduced ``num / den`` pairs of ``fmpz_mpoly``.

The package's one rational-function type: the values the parser reads (it does its
own arithmetic on them, under its budgets), the entries of a field of a few SymPy
expressions, and vectors whose entries come from different arms (keeping each entry
in lowest terms avoids multiplying every arm's denominators into every entry).

Example
-------
>>> import flint
>>> ctx = flint.fmpz_mpoly_ctx.get(("t", "L"), "degrevlex")
>>> t, L = ctx.gens()
>>> a = RatFunc.make(L * t, L * (1 + t))
>>> str(a.num), str(a.den)
('t', 't + 1')
>>> b = a + RatFunc.make(ctx.constant(1), 1 + t)
>>> str(b.num), str(b.den)
('1', '1')
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import flint

Poly = flint.fmpz_mpoly


@dataclass(frozen=True, slots=True)
class RatFunc:
    """``num / den`` in lowest terms, ``den`` with a positive leading coefficient.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("t",), "lex")
    >>> (t,) = ctx.gens()
    >>> f = RatFunc(t**2 - 1, t + 1)
    >>> f.num, f.den
    (t^2 - 1, t + 1)
    """

    num: Poly
    den: Poly

    @staticmethod
    def make(num: Poly, den: Poly) -> RatFunc:
        if den.is_zero():
            raise ZeroDivisionError("rational function with zero denominator")
        if num.is_zero():
            return RatFunc(num, den.context().constant(1))
        g = num.gcd(den)
        if not g.is_one():
            num, den = num / g, den / g
        if int(den.leading_coefficient()) < 0:
            num, den = -num, -den
        return RatFunc(num, den)

    @staticmethod
    def poly(p: Poly) -> RatFunc:
        return RatFunc(p, p.context().constant(1))

    def is_zero(self) -> bool:
        return self.num.is_zero()

    def is_constant(self) -> bool:
        """Whether both numerator and denominator are constants."""
        return self.num.is_constant() and self.den.is_constant()

    def rational(self) -> Fraction:
        """The value of a constant (see :meth:`is_constant`).

        Example
        -------
        >>> import flint
        >>> ctx = flint.fmpz_mpoly_ctx.get(("t",), "lex")
        >>> RatFunc.make(ctx.constant(2), ctx.constant(-6)).rational()
        Fraction(-1, 3)
        """
        return Fraction(int(self.num.leading_coefficient()) if not self.num.is_zero()
                        else 0, int(self.den.leading_coefficient()))

    def __add__(self, other: RatFunc) -> RatFunc:
        if other.num.is_zero():
            return self
        if self.num.is_zero():
            return other
        if self.den == other.den:
            return RatFunc.make(self.num + other.num, self.den)
        g = self.den.gcd(other.den)
        a, b = self.den / g, other.den / g
        return RatFunc.make(self.num * b + other.num * a, self.den * b)

    def __neg__(self) -> RatFunc:
        return RatFunc(-self.num, self.den)

    def __sub__(self, other: RatFunc) -> RatFunc:
        return self + (-other)

    def __mul__(self, other: RatFunc) -> RatFunc:
        if self.num.is_zero() or other.num.is_zero():
            return RatFunc.poly(self.num.context().constant(0))
        g1 = self.num.gcd(other.den)
        g2 = other.num.gcd(self.den)
        num = (self.num / g1) * (other.num / g2)
        den = (self.den / g2) * (other.den / g1)
        if int(den.leading_coefficient()) < 0:
            num, den = -num, -den
        return RatFunc(num, den)

    def __truediv__(self, other: RatFunc) -> RatFunc:
        if other.num.is_zero():
            raise ZeroDivisionError("division by a zero rational function")
        return self * RatFunc(other.den, other.num) if int(
            other.num.leading_coefficient()) > 0 else self * RatFunc(-other.den, -other.num)

    def terms(self) -> int:
        """Number of terms of numerator and denominator together."""
        return len(self.num) + len(self.den)
