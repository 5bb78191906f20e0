"""Rational functions over Q: the package's one rational-function type, :class:`RatFunc`.

A :class:`RatFunc` holds its value in one of two forms:

* *reduced*: ``num / den`` with ``num`` and ``den`` coprime ``fmpz_mpoly`` of one
  context and ``den`` with a positive leading coefficient (a canonical form). The
  parser reads values in this form, the entries of a field of a few SymPy expressions
  are kept in it, and so are vectors whose entries come from different arms (keeping
  each entry in lowest terms avoids multiplying every arm's denominators into every
  entry);
* *over known factors*: the numerator ``num`` an ``fmpq_mpoly`` of a
  :class:`~coopkin_sym.exact.ring.Ring` and the denominator
  ``prod ring.den_factors[j] ** powers[j]`` (the factors ``1 + t_j**2`` of the
  kinematics), kept as the exponents ``powers``. Sums and products of two such values
  of one ring never take a polynomial gcd, which keeps the Jacobians fast.

Arithmetic of two values over the known factors of one ring stays in that form; every
other combination (two reduced values, mixed forms, a division by a non-constant) is
done on the reduced forms (:meth:`RatFunc.reduced`). Equality compares values, whatever
the forms.

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

from fractions import Fraction
from math import lcm
from typing import Any

import flint

Poly = flint.fmpz_mpoly


class RatFunc:
    """A rational function, reduced or over the known factors of a ring (see the module).

    Parameters
    ----------
    num
        The numerator: an ``fmpz_mpoly`` (reduced form) or an ``fmpq_mpoly`` of
        ``ring`` (over known factors).
    den
        The denominator of the reduced form (``num`` and ``den`` coprime, ``den`` with a
        positive leading coefficient; :meth:`make` reduces any pair); ``None`` over
        known factors.
    ring, powers
        Over known factors: the :class:`~coopkin_sym.exact.ring.Ring` and the exponent
        of each of its ``den_factors`` in the denominator (both ``None`` when reduced).

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("t",), "lex")
    >>> (t,) = ctx.gens()
    >>> f = RatFunc(t**2 - 1, t + 1)
    >>> f.num, f.den
    (t^2 - 1, t + 1)
    >>> from coopkin_sym.exact.ring import Ring
    >>> c = Ring(["t"], ["t"]).cos_of(0)           # (1 - t^2) / (1 + t^2)
    >>> c.num, c.powers, str(c.reduced().den)
    (-t^2 + 1, (1,), 't^2 + 1')
    """

    __slots__ = ("den", "num", "powers", "ring")

    def __init__(self, num, den: Poly | None = None, ring: Any = None,
                 powers: tuple[int, ...] | None = None):
        self.num = num
        self.den = den
        self.ring = ring
        self.powers = powers

    # --- constructing -------------------------------------------------------------
    @staticmethod
    def make(num: Poly, den: Poly) -> RatFunc:
        """``num / den`` (integer polynomials of one context) in lowest terms."""
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
        """The integer polynomial ``p`` as a reduced rational function."""
        return RatFunc(p, p.context().constant(1))

    @staticmethod
    def over(ring: Any, num: flint.fmpq_mpoly, powers: tuple[int, ...]) -> RatFunc:
        """``num / prod(ring.den_factors[j] ** powers[j])``, over the known factors."""
        return RatFunc(num, None, ring, powers)

    @property
    def known(self) -> bool:
        """Whether the value is held over the known factors of a ring."""
        return self.ring is not None

    def reduced(self) -> RatFunc:
        """The reduced form of the value (itself when it is reduced).

        Example
        -------
        >>> from coopkin_sym.exact.ring import Ring
        >>> ring = Ring(["t"], ["t"])
        >>> (t,) = ring.gens()
        >>> f = (t * t + 1) * ring.cos_of(0) * ring.ratfunc(Fraction(1, 2))
        >>> r = f.reduced()
        >>> str(r.num), str(r.den), r.powers
        ('-t^2 + 1', '2', None)
        """
        ring = self.ring
        if ring is None:
            return self
        terms = self.num.to_dict()
        d = lcm(*(int(c.q) for c in terms.values())) if terms else 1
        num = ring.zctx.from_dict({m: int(c.p) * (d // int(c.q)) for m, c in terms.items()})
        den = ring.zctx.constant(d) * ring.to_zpoly(ring.den_poly(self.powers))
        return RatFunc.make(num, den)

    def _lift(self, other) -> RatFunc:
        """A number (``int``, ``Fraction``, ``fmpq``) in the form of ``self``."""
        if isinstance(other, RatFunc):
            return other
        if self.ring is not None:
            return self.ring.ratfunc(other)
        x = Fraction(int(other.p), int(other.q)) if isinstance(other, flint.fmpq) else \
            Fraction(other)
        ctx = self.num.context()
        return RatFunc(ctx.constant(x.numerator), ctx.constant(x.denominator))

    def _same_ring(self, other: RatFunc) -> bool:
        a, b = self.ring, other.ring
        return a is not None and (a is b or a == b)

    # --- queries ------------------------------------------------------------------
    def is_zero(self) -> bool:
        return self.num.is_zero()

    def is_constant(self) -> bool:
        """Whether the value is a constant (a rational number)."""
        f = self
        if self.ring is not None:
            if self.num.is_constant():
                return self.num.is_zero() or not any(self.powers)
            f = self.reduced()
        return f.num.is_constant() and f.den.is_constant()

    def rational(self) -> Fraction:
        """The value of a constant (see :meth:`is_constant`).

        Example
        -------
        >>> import flint
        >>> ctx = flint.fmpz_mpoly_ctx.get(("t",), "lex")
        >>> RatFunc.make(ctx.constant(2), ctx.constant(-6)).rational()
        Fraction(-1, 3)
        """
        f = self.reduced()
        return Fraction(int(f.num.leading_coefficient()) if not f.num.is_zero()
                        else 0, int(f.den.leading_coefficient()))

    def terms(self) -> int:
        """Number of terms of numerator and denominator together (reduced form)."""
        f = self.reduced()
        return len(f.num) + len(f.den)

    # --- arithmetic ---------------------------------------------------------------
    def _common(self, other: RatFunc) -> tuple[flint.fmpq_mpoly, flint.fmpq_mpoly, tuple]:
        """Both numerators over the least common power product (known factors)."""
        if self.powers == other.powers:
            return self.num, other.num, self.powers
        top = tuple(max(a, b) for a, b in zip(self.powers, other.powers, strict=True))
        dp = self.ring.den_poly
        a = self.num * dp(tuple(t - e for t, e in zip(top, self.powers, strict=True)))
        b = other.num * dp(tuple(t - e for t, e in zip(top, other.powers, strict=True)))
        return a, b, top

    def __add__(self, other) -> RatFunc:
        other = self._lift(other)
        ring = self.ring
        if ring is not None and (other.ring is ring or other.ring == ring):
            if other.num.is_zero():
                return self
            if self.num.is_zero():
                return other
            a, b, powers = self._common(other)
            return RatFunc(a + b, None, ring, powers)
        x, y = self.reduced(), other.reduced()
        if y.num.is_zero():
            return x
        if x.num.is_zero():
            return y
        if x.den == y.den:
            return RatFunc.make(x.num + y.num, x.den)
        g = x.den.gcd(y.den)
        a, b = x.den / g, y.den / g
        return RatFunc.make(x.num * b + y.num * a, x.den * b)

    __radd__ = __add__

    def __neg__(self) -> RatFunc:
        return RatFunc(-self.num, self.den, self.ring, self.powers)

    def __sub__(self, other) -> RatFunc:
        return self + (-self._lift(other))

    def __rsub__(self, other) -> RatFunc:
        return self._lift(other) - self

    def __mul__(self, other) -> RatFunc:
        other = self._lift(other)
        ring = self.ring
        if ring is not None and (other.ring is ring or other.ring == ring):
            if self.num.is_zero() or other.num.is_zero():
                return ring.zero()
            powers = tuple(a + b for a, b in zip(self.powers, other.powers, strict=True))
            return RatFunc(self.num * other.num, None, ring, powers)
        x, y = self.reduced(), other.reduced()
        if x.num.is_zero() or y.num.is_zero():
            return RatFunc.poly(x.num.context().constant(0))
        g1 = x.num.gcd(y.den)
        g2 = y.num.gcd(x.den)
        num = (x.num / g1) * (y.num / g2)
        den = (x.den / g2) * (y.den / g1)
        if int(den.leading_coefficient()) < 0:
            num, den = -num, -den
        return RatFunc(num, den)

    __rmul__ = __mul__

    def __truediv__(self, other) -> RatFunc:
        other = self._lift(other)
        if other.num.is_zero():
            raise ZeroDivisionError("division by a zero rational function")
        if self._same_ring(other) and other.is_constant():
            c = other.rational()
            return RatFunc(self.num * flint.fmpq(c.denominator, c.numerator), None,
                           self.ring, self.powers)
        y = other.reduced()
        inverse = RatFunc(y.den, y.num) if int(y.num.leading_coefficient()) > 0 else \
            RatFunc(-y.den, -y.num)
        return self.reduced() * inverse

    def __rtruediv__(self, other) -> RatFunc:
        return self._lift(other) / self

    # --- comparing, pickling, printing ----------------------------------------------
    def __eq__(self, other: object) -> bool:
        if isinstance(other, int | Fraction | flint.fmpq):
            other = self._lift(other)
        if not isinstance(other, RatFunc):
            return NotImplemented
        if self._same_ring(other):
            a, b, _ = self._common(other)
            return a == b
        x, y = self.reduced(), other.reduced()
        return x.num == y.num and x.den == y.den

    __hash__ = None  # type: ignore[assignment]  # flint polynomials are unhashable

    def __reduce__(self):
        return RatFunc, (self.num, self.den, self.ring, self.powers)

    def __repr__(self) -> str:
        if self.ring is not None:
            return f"RatFunc.over(ring, {self.num!r}, {self.powers!r})"
        return f"RatFunc({self.num!r}, {self.den!r})"
