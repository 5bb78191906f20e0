"""The values of one reading and their budgeted arithmetic.

While text is read, a value is either a rational function with rational coefficients
in the declared names, or an expression holding an irrational constant (``_Sym``:
SymPy, small). Every product, power and reduction is checked against the budgets of
:mod:`coopkin_sym.limits` before it is taken.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from fractions import Fraction

import flint
import sympy as sp

from coopkin_sym import limits
from coopkin_sym.errors import NumberError, UndeclaredSymbol
from coopkin_sym.exact.parse.messages import _declared, _digits, _int_text
from coopkin_sym.exact.ratfunc import RatFunc
from coopkin_sym.exact.rationals import to_fraction, to_sympy

# ------------------------------------------------------------------------ values
#
# While text is read, a value is either a rational function with rational
# coefficients in the declared names (a :class:`~coopkin_sym.exact.ratfunc.RatFunc`:
# integer polynomials ``num / den`` of one flint context, in lowest terms, ``den`` with
# a positive leading coefficient), or an
# expression holding an irrational constant (``_Sym``: SymPy, small).


@dataclass(frozen=True)
class _Sym:
    expr: sp.Expr


def _height(p: flint.fmpz_mpoly) -> int:
    """Bits of the largest coefficient of ``p``."""
    return max((abs(int(c)).bit_length() for c in p.coeffs()), default=0)


class _Reader:
    """The arithmetic of one reading: budgets, the flint context, error messages."""

    def __init__(self, names: Mapping[str, sp.Symbol], where: str, shown: str,
                 kind: str):
        self.symbols = dict(names)
        self.names = tuple(self.symbols)
        self.ctx = flint.fmpz_mpoly_ctx.get(self.names, "lex")
        self.where, self.shown, self.kind = where, shown, kind
        self.one = self.ctx.constant(1)

    # --- errors -------------------------------------------------------------------
    def fail(self, message: str) -> NumberError:
        return NumberError(self.where, f"{self.shown} {message}")

    def undeclared(self, name: str) -> UndeclaredSymbol:
        return UndeclaredSymbol(self.where, f"{self.shown} uses undeclared symbol {name} "
                                            f"(declared {self.kind}: "
                                            f"{_declared(self.names)})")

    def too_large(self, what: str) -> NumberError:
        return self.fail(f"is too large: {what}")

    # --- building -----------------------------------------------------------------
    def constant(self, value: Fraction) -> RatFunc:
        self._check_int(value.numerator)
        self._check_int(value.denominator)
        return RatFunc(self.ctx.constant(value.numerator), self.ctx.constant(value.denominator))

    def symbol(self, name: str) -> RatFunc:
        if name not in self.symbols:
            raise self.undeclared(name)
        return RatFunc(self.ctx.gens()[self.names.index(name)], self.one)

    def _check_int(self, value: int) -> None:
        if abs(value) >= limits.integer_bound():
            raise self.too_large(f"a number of more than {limits.MAX_DIGITS} digits")

    def _check_poly(self, p: flint.fmpz_mpoly) -> None:
        if len(p) > limits.MAX_TERMS:
            raise self.too_large(f"more than {limits.MAX_TERMS:,} terms")
        if p.total_degree() > limits.MAX_DEGREE:
            raise self.too_large(f"degree over {limits.MAX_DEGREE}")
        for c in p.coeffs():
            if abs(int(c)) >= limits.integer_bound():
                raise self.too_large(f"a number of more than {limits.MAX_DIGITS} digits")

    def _product(self, a: flint.fmpz_mpoly, b: flint.fmpz_mpoly) -> flint.fmpz_mpoly:
        """``a * b`` after checking what it would cost and how large it would be."""
        if a.is_constant() and b.is_constant():
            bits = _height(a) + _height(b)
            if bits > 4 * limits.max_bits():
                raise self.too_large(f"a number of more than {limits.MAX_DIGITS} digits")
            return a * b
        if len(a) * len(b) > limits.MAX_PRODUCT:
            raise self.too_large(f"a product of {len(a):,} by {len(b):,} terms")
        if max(a.total_degree(), 0) + max(b.total_degree(), 0) > limits.MAX_DEGREE:
            raise self.too_large(f"degree over {limits.MAX_DEGREE}")
        bits = _height(a) + _height(b) + min(len(a), len(b)).bit_length()
        if bits > 2 * limits.max_bits():
            raise self.too_large(f"a number of more than {limits.MAX_DIGITS} digits")
        return a * b

    def _reduced(self, num: flint.fmpz_mpoly, den: flint.fmpz_mpoly) -> RatFunc:
        if den.is_zero():
            raise self.fail("is not a finite number (division by zero)")
        if num.is_zero():
            return RatFunc(num, self.one)
        if not den.is_one():
            g = num.gcd(den)
            if not g.is_one():
                num, den = num / g, den / g
            if int(den.leading_coefficient()) < 0:
                num, den = -num, -den
        self._check_poly(num)
        self._check_poly(den)
        return RatFunc(num, den)

    def add(self, a: RatFunc, b: RatFunc) -> RatFunc:
        if a.den == b.den:
            return self._reduced(a.num + b.num, a.den)
        return self._reduced(self._product(a.num, b.den) + self._product(b.num, a.den),
                             self._product(a.den, b.den))

    def mul(self, a: RatFunc, b: RatFunc) -> RatFunc:
        an, ad, bn, bd = a.num, a.den, b.num, b.den
        if not ad.is_one() and not bn.is_zero():
            g = bn.gcd(ad)
            bn, ad = bn / g, ad / g
        if not bd.is_one() and not an.is_zero():
            g = an.gcd(bd)
            an, bd = an / g, bd / g
        return self._reduced(self._product(an, bn), self._product(ad, bd))

    def inverse(self, a: RatFunc) -> RatFunc:
        if a.num.is_zero():
            raise self.fail("is not a finite number (division by zero)")
        return self._reduced(a.den, a.num)

    def power(self, a: RatFunc, n: int) -> RatFunc:
        if n < 0:
            return self.power(self.inverse(a), -n)
        if a.is_constant():
            bits = max(_height(a.num), _height(a.den))
            if (bits - 1) * n > limits.max_bits():
                raise self.too_large(f"a number of more than {limits.MAX_DIGITS} digits")
        degree = max(a.num.total_degree(), a.den.total_degree(), 0)
        if degree * n > limits.MAX_DEGREE:
            raise self.too_large(f"degree over {limits.MAX_DEGREE}")
        if len(a.num) == 1 and a.den.is_one():   # a monomial: one power, no squarings
            if (_height(a.num) - 1) * n > limits.max_bits():
                raise self.too_large(f"a number of more than {limits.MAX_DIGITS} digits")
            return self._reduced(a.num ** n, self.one)
        result = RatFunc(self.one, self.one)
        base = a
        while n:
            if n & 1:
                result = self.mul(result, base)
            n >>= 1
            if n:
                base = self.mul(base, base)
        return result

    # --- SymPy side ---------------------------------------------------------------
    def to_sympy(self, a: RatFunc) -> sp.Expr:
        return _poly_expr(a.num, self.names, self.symbols) / _poly_expr(
            a.den, self.names, self.symbols)

    def sym(self, expr: sp.Expr) -> RatFunc | _Sym:
        """An expression built by SymPy: back to ``RatFunc`` when it holds no irrational
        constant, else checked for size."""
        if not isinstance(expr, sp.Expr):
            raise self.fail("is not a number")
        if expr.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
            raise self.fail("is not a finite number")
        nodes = 0
        for node in sp.preorder_traversal(expr):
            nodes += 1
            if nodes > limits.MAX_CONSTANT_NODES:
                raise self.too_large("an irrational expression of more than "
                                     f"{limits.MAX_CONSTANT_NODES} parts")
            if isinstance(node, sp.Rational):
                self._check_int(int(node.p))
                self._check_int(int(node.q))
        rf = self.tree(expr, strict=False)
        return rf if rf is not None else _Sym(expr)

    def as_sympy(self, v: RatFunc | _Sym) -> sp.Expr:
        if isinstance(v, _Sym):
            return v.expr
        if len(v.num) + len(v.den) > limits.MAX_CONSTANT_NODES // 4:
            raise self.too_large("a long polynomial combined with pi, atan or sqrt")
        return self.to_sympy(v)

    def tree(self, expr: sp.Basic, strict: bool = True) -> RatFunc | None:
        """A SymPy expression made of rationals, declared symbols (matched by name),
        sums, products and integer powers, as ``RatFunc`` with every budget applied;
        ``None`` (or, with ``strict``, an error) for anything else."""
        if isinstance(expr, sp.Rational):
            return self.constant(to_fraction(expr))
        if isinstance(expr, sp.Symbol):
            if expr.name in self.symbols:
                return self.symbol(expr.name)
            raise self.undeclared(expr.name)
        if isinstance(expr, sp.Add | sp.Mul):
            parts = []
            for arg in expr.args:
                part = self.tree(arg, strict)
                if part is None:
                    return None
                parts.append(part)
            if isinstance(expr, sp.Add):
                return self.balanced(parts, self.add)
            return self.balanced(parts, self.mul)
        if isinstance(expr, sp.Pow) and isinstance(expr.exp, sp.Integer):
            n = int(expr.exp)
            if abs(n) > limits.MAX_EXPONENT:
                raise self.too_large(f"an exponent over {limits.MAX_EXPONENT}")
            base = self.tree(expr.base, strict)
            return None if base is None else self.power(base, n)
        if strict:
            raise self.fail("is not a rational function with rational coefficients")
        return None

    @staticmethod
    def balanced(parts: list, op):
        """``op`` folded over ``parts`` as a balanced tree (sums of many terms stay
        cheap)."""
        while len(parts) > 1:
            parts = [op(parts[i], parts[i + 1]) if i + 1 < len(parts) else parts[i]
                     for i in range(0, len(parts), 2)]
        return parts[0]

    # --- mixed arithmetic ----------------------------------------------------------
    def v_add(self, values: list) -> RatFunc | _Sym:
        exact = [v for v in values if isinstance(v, RatFunc)]
        other = [v for v in values if isinstance(v, _Sym)]
        total = self.balanced(exact, self.add) if exact else None
        if not other:
            return total
        parts = [v.expr for v in other] + ([self.as_sympy(total)] if total is not None
                                           else [])
        return self.sym(sp.Add(*parts))

    def v_neg(self, v):
        return RatFunc(-v.num, v.den) if isinstance(v, RatFunc) else self.sym(-v.expr)

    def v_mul(self, a, b):
        if isinstance(a, RatFunc) and isinstance(b, RatFunc):
            return self.mul(a, b)
        return self.sym(self.as_sympy(a) * self.as_sympy(b))

    def v_div(self, a, b):
        if isinstance(b, RatFunc):
            return self.v_mul(a, self.inverse(b))
        if b.expr.is_zero:
            raise self.fail("is not a finite number (division by zero)")
        return self.sym(self.as_sympy(a) / b.expr)

    def v_pow(self, a, n: int):
        if isinstance(a, RatFunc):
            return self.power(a, n)
        bits = max((max(abs(int(r.p)).bit_length(), int(r.q).bit_length())
                    for r in a.expr.atoms(sp.Rational)), default=1)
        if (bits - 1) * abs(n) > limits.max_bits():
            raise self.too_large(f"a number of more than {limits.MAX_DIGITS} digits")
        if n < 0 and a.expr.is_zero:
            raise self.fail("is not a finite number (division by zero)")
        return self.sym(a.expr ** n)

    # --- functions ------------------------------------------------------------------
    def call(self, name: str, args: list) -> RatFunc | _Sym:
        if name in ("Integer", "Rational"):
            return self._rational_call(name, args)
        if len(args) != 1:
            raise self.fail(f"cannot be parsed ({name} takes one argument)")
        (x,) = args
        if isinstance(x, RatFunc) and not x.is_constant():
            raise self.fail(f"cannot take {name} of an expression in the {self.kind} "
                            f"(only of numbers)")
        if name == "sqrt":
            if isinstance(x, RatFunc):
                r = x.rational()
                if r >= 0:
                    p, q = math.isqrt(r.numerator), math.isqrt(r.denominator)
                    if p * p == r.numerator and q * q == r.denominator:
                        return self.constant(Fraction(p, q))
                value = to_sympy(r)
                if max(_digits(r.numerator), _digits(r.denominator)) > 50:
                    return _Sym(sp.Pow(value, sp.Rational(1, 2), evaluate=False))
                return self.sym(sp.sqrt(value))
            return self.sym(sp.sqrt(x.expr))
        return self.sym(sp.atan(self.as_sympy(x)))

    def _rational_call(self, name: str, args: list) -> RatFunc:
        allowed = (1,) if name == "Integer" else (1, 2)
        if len(args) not in allowed:
            count = "one number" if name == "Integer" else "one or two numbers"
            raise self.fail(f"cannot be parsed ({name} takes {count})")
        values = []
        for x in args:
            if not isinstance(x, RatFunc) or not x.is_constant():
                raise self.fail(f"cannot be parsed ({name} takes rational numbers)")
            values.append(x.rational())
        if name == "Integer":
            if values[0].denominator != 1:
                raise self.fail(f"is not exact: Integer of {_int_text(values[0])}, which "
                                "is not an integer")
            return self.constant(values[0])
        if len(values) == 2 and values[1] == 0:
            raise self.fail("is not a finite number (division by zero)")
        return self.constant(values[0] / values[1] if len(values) == 2 else values[0])


def _poly_expr(p: flint.fmpz_mpoly, names: tuple[str, ...],
               symbols: Mapping[str, sp.Symbol]) -> sp.Expr:
    """An ``fmpz_mpoly`` as a SymPy expression in ``symbols``."""
    syms = [symbols[n] for n in names]
    terms = []
    for monom, c in zip(p.monoms(), p.coeffs(), strict=True):
        factors = [sp.Integer(int(c))]
        factors += [s ** int(e) for s, e in zip(syms, monom, strict=True) if e]
        terms.append(sp.Mul(*factors))
    return sp.Add(*terms)


