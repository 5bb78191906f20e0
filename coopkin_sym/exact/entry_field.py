"""One exact field for a handful of SymPy entries, so that sums, products and zero
tests are arithmetic instead of simplification.

The entries of twists, joint motions and points (exact SymPy numbers and expressions)
are read into the rational functions in their symbols over the rationals (python-flint
:class:`~coopkin_sym.exact.ratfunc.RatFunc`, :class:`FlintEntryField`) or over the
number field of their radicals (SymPy's ``QQ<sqrt(3)>(L)``, :class:`EntryField`).
Entries outside such a field (``cos(L)``, ``sqrt(L)``) keep the expression arithmetic
(:class:`ExprArithmetic`, zero tests by ``cancel``/``radsimp``). The three share one
interface: ``of(expr)``, ``is_zero``, ``div``, ``to_sympy`` and ``text`` (factored, as
``sp.factor`` writes it).

Example
-------
>>> import sympy as sp
>>> L = sp.Symbol("L")
>>> f = field_of([[sp.sqrt(3) * L, 3 * L**2]])
>>> f.is_zero(f.of(sp.sqrt(3) * L) * f.of(sp.sqrt(3) * L) - f.of(3 * L**2))
True
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from math import lcm

import flint
import sympy as sp
from sympy.core.mul import _keep_coeff
from sympy.polys.polyerrors import BasePolynomialError

from coopkin_sym.exact.factoring import factor
from coopkin_sym.exact.ratfunc import RatFunc


def is_zero_expr(e: sp.Expr) -> bool:
    """Whether an exact SymPy expression is zero (cancelled; radicals simplified).

    Example
    -------
    >>> is_zero_expr(sp.sqrt(2) * sp.sqrt(8) - 4), is_zero_expr(sp.Symbol("L"))
    (True, False)
    """
    e = sp.cancel(e)
    if e == 0:
        return True
    radicals = any(not p.exp.is_Integer for p in e.atoms(sp.Pow))
    return radicals and sp.radsimp(sp.expand(e)) == 0


class ExprArithmetic:
    """Arithmetic on SymPy expressions with simplification for zero tests: the way
    entries are compared when they do not all lie in one field of rational functions
    over the rationals or a number field.

    Example
    -------
    >>> L = sp.Symbol("L")
    >>> f = field_of([[sp.sqrt(L), L]])          # sqrt(L) is in no such field
    >>> f.is_zero(f.of(sp.sqrt(L))**2 - f.of(L)), type(f).__name__
    (True, 'ExprArithmetic')
    """

    def of(self, e: sp.Expr) -> sp.Expr:
        return e

    def is_zero(self, x: sp.Expr) -> bool:
        return is_zero_expr(x)

    def div(self, a: sp.Expr, b: sp.Expr) -> sp.Expr:
        return sp.radsimp(sp.cancel(a / b))

    def to_sympy(self, x: sp.Expr) -> sp.Expr:
        return x

    def text(self, x) -> str:
        return sp.sstr(sp.factor(self.to_sympy(x)))


class EntryField(ExprArithmetic):
    """The entries as elements of one exact field that SymPy builds for them (``QQ``,
    ``QQ<sqrt(3)>(L)``, ...): sums, products and zero tests are then polynomial
    arithmetic, not simplification of expressions. Without radicals the field is
    :class:`FlintEntryField` (the same, in python-flint).

    Example
    -------
    >>> L = sp.Symbol("L")
    >>> EntryField.of_entries([sp.sqrt(3) * L, 1 / (1 + L)]).domain
    QQ<sqrt(3)>(L)
    """

    def __init__(self, domain, exprs: Sequence[sp.Expr], elements: Sequence) -> None:
        self.domain = domain
        self._elements = dict(zip(exprs, elements, strict=True))

    @staticmethod
    def of_entries(exprs: Sequence[sp.Expr]) -> ExprArithmetic:
        """The field of ``exprs``: rational functions in their symbols over the
        rationals or over the number field of their radicals; the expression arithmetic
        when some entry does not lie in it."""
        if not all(isinstance(e, int | sp.Expr) for e in exprs):
            return ExprArithmetic()
        exprs = list(dict.fromkeys(sp.Integer(e) if isinstance(e, int) else e for e in exprs))
        symbols = sorted(set().union(*(e.free_symbols for e in exprs)), key=sp.default_sort_key)
        radicals = sorted({p for e in exprs for p in e.atoms(sp.Pow)
                           if p.base.is_Rational and p.exp.is_Rational and not p.exp.is_Integer},
                          key=sp.default_sort_key)
        try:
            if not radicals:
                return FlintEntryField(exprs, symbols)
            ground = sp.QQ.algebraic_field(*radicals)
            domain = ground.frac_field(*symbols) if symbols else ground
            elements = [domain.from_sympy(e) for e in exprs]
        except (BasePolynomialError, NotImplementedError, ValueError, TypeError):
            return ExprArithmetic()
        return EntryField(domain, exprs, elements)

    def of(self, e: sp.Expr):
        return self._elements[e]

    def is_zero(self, x) -> bool:
        return self.domain.is_zero(x)

    def div(self, a, b):
        return a / b

    def to_sympy(self, x) -> sp.Expr:
        return self.domain.to_sympy(x)


class FlintEntryField(EntryField):
    """Rational functions over the rationals as reduced pairs of python-flint integer
    polynomials (:class:`~coopkin_sym.exact.ratfunc.RatFunc`, lex order of the symbols
    as SymPy sorts them): fast products and gcds, and factored text through flint.

    Example
    -------
    >>> L, t = sp.symbols("L t")
    >>> f = FlintEntryField([L * t - L, 1 + t], [L, t])
    >>> f.text(f.of(L * t - L) / f.of(1 + t))
    'L*(t - 1)/(t + 1)'
    """

    def __init__(self, exprs: Sequence[sp.Expr], symbols: Sequence[sp.Symbol]) -> None:
        self.symbols = list(symbols) or [sp.Dummy("x")]
        self.ctx = flint.fmpz_mpoly_ctx.get(tuple(f"x{k}" for k in range(len(self.symbols))),
                                            "lex")
        self._index = {x: k for k, x in enumerate(self.symbols)}
        self._domain = sp.ZZ.frac_field(*self.symbols)
        self._elements = {e: self._element(e) for e in exprs}

    def _element(self, e: sp.Expr) -> RatFunc:
        num, den = sp.fraction(e)
        fast = [self._sum_of_monomials(num), self._sum_of_monomials(den)]
        if None not in fast:
            (n, dn), (d, dd) = fast
            return RatFunc.make(n * dd, d * dn)
        x = self._domain.from_sympy(e)
        return RatFunc.make(self._poly(x.numer), self._poly(x.denom))

    def _sum_of_monomials(self, p: sp.Expr) -> tuple[flint.fmpz_mpoly, int] | None:
        """``p`` as ``(P, d)`` with ``p = P / d`` when it is a sum of rational multiples
        of monomials (as the blocks are), read term by term; ``None`` otherwise."""
        terms: dict[tuple[int, ...], Fraction] = {}
        for term in sp.Add.make_args(p):
            coeff, mono = Fraction(1), [0] * len(self.symbols)
            for f in sp.Mul.make_args(term):
                base, exp = f.as_base_exp()
                if f.is_Rational:
                    coeff *= Fraction(int(f.p), int(f.q))
                elif base in self._index and exp.is_Integer and exp > 0:
                    mono[self._index[base]] += int(exp)
                else:
                    return None
            key = tuple(mono)
            terms[key] = terms.get(key, Fraction(0)) + coeff
        d = lcm(*(c.denominator for c in terms.values())) if terms else 1
        return self.ctx.from_dict({m: int(c * d) for m, c in terms.items() if c}), d

    def _poly(self, p) -> flint.fmpz_mpoly:
        return self.ctx.from_dict({m: int(c) for m, c in p.to_dict().items()})

    def _expr(self, p: flint.fmpz_mpoly) -> sp.Expr:
        return sp.Poly.from_dict({tuple(int(e) for e in m): int(c) for m, c in
                                  p.to_dict().items()}, *self.symbols, domain=sp.ZZ).as_expr()

    def is_zero(self, x: RatFunc) -> bool:
        return x.is_zero()

    def to_sympy(self, x: RatFunc) -> sp.Expr:
        return self._expr(x.num) / self._expr(x.den)

    def text(self, x: RatFunc) -> str:
        if x.is_zero():
            return "0"
        factors = []
        content = sp.Integer(1)
        for poly, power in ((x.num, 1), (x.den, -1)):
            c, fs = factor(poly)
            content *= sp.Integer(c) ** power
            factors += [self._expr(f) ** (m * power) for f, m in fs]
        return sp.sstr(_keep_coeff(content, sp.Mul(*factors)))  # as sp.factor writes it


def field_of(vectors: Sequence[Sequence[sp.Expr]],
             points: Sequence[Sequence[sp.Expr]] = ()) -> ExprArithmetic:
    """One field for the entries of ``vectors`` and of ``points`` (all exact SymPy
    numbers or expressions, or ``int``).

    Example
    -------
    >>> type(field_of([[1, sp.Rational(1, 2)]])).__name__
    'FlintEntryField'
    """
    return EntryField.of_entries([e for v in vectors for e in v]
                                 + [x for p in points for x in p])
