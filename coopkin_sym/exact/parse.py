"""Exact numbers, angles and expressions from text: the one parser of the package.

Every text that becomes a number or an expression (model files, ``--at``, ``--grid``,
arguments of the API, equations and witnesses of a report read back) passes through
:func:`parse_expression`, and comes out exact. The parser is the package's own: a
small recursive-descent reader of decimal numbers, declared names, ``pi``, the
functions ``atan``, ``sqrt``, ``Rational`` and ``Integer``, ``+ - * / ** ^``
and parentheses. Nothing is handed to Python or to SymPy's parser, so no text can
run code. A decimal such as ``0.1`` is the exact decimal ``1/10``, never a binary
float. Polynomials are built with python-flint under the budgets of
:mod:`coopkin_sym.limits` (digits, exponents, degree, terms), checked before each
step, so that ``(L+M+N+1)**1000`` or ``10**1000**...`` is refused at once.

Angles are exact when their tangent half-angle ``t = tan(q/2)`` is rational (then
``cos q`` and ``sin q`` are rational) or when they are odd multiples of ``pi``; an
angle is decided exactly from its parts (rational multiples of ``pi`` and of
``atan(p/q)``), with bounded work.

Example
-------
>>> import sympy as sp
>>> L = sp.Symbol("L", positive=True)
>>> parse_number("L/2 + 0.1", {"L": L}, "x")
L/2 + 1/10
>>> parse_expression("t_q1**2 - 1", ["t_q1"], "equation")
t_q1**2 - 1
>>> parse_angle("2*atan(1/3)", "q1")
(4/5, 3/5)
>>> angle_text(sp.Rational(4, 5), sp.Rational(3, 5))
'2*atan(1/3)'
"""

from __future__ import annotations

import math
import numbers
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction

import flint
import mpmath
import sympy as sp

from coopkin_sym import limits
from coopkin_sym.errors import NumberError, UndeclaredSymbol
from coopkin_sym.exact.rationals import to_fraction, to_sympy

__all__ = ["FUNCTIONS", "NumberError", "algebraic_half_angle", "angle_text", "brief",
           "exact_expr", "parse_angle", "parse_expression", "parse_number",
           "parse_polynomial"]

#: Functions allowed in text, besides the declared names and ``pi``.
FUNCTIONS = ("atan", "sqrt", "Rational", "Integer")
_NOT_FINITE = {"inf", "+inf", "-inf", "infinity", "+infinity", "-infinity", "nan",
               ".inf", "+.inf", "-.inf", ".nan", "oo", "-oo", "zoo"}
_TOKEN = re.compile(
    r"\s*(?:(?P<num>(?:\d|\.\d)(?:[\w.]|(?<=[eE])[+-])*)"
    r"|(?P<name>[A-Za-z_]\w*)|(?P<op>\*\*|[-+*/^(),])|(?P<other>\S))", re.ASCII)
_DECIMAL = re.compile(r"(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?", re.ASCII)



def brief(value: object) -> str:
    """The value as the user wrote it, quoted and shortened (for error messages: one
    short line, never the repr of a whole large object).

    Example
    -------
    >>> brief("q1=" + "9" * 100)
    "'q1=999999999999999999999999999999999999999999999999999999...'"
    """
    return _show(value)


def _show(value: object) -> str:
    """The value as the user wrote it, quoted, shortened if long (never the repr of a
    large object: only its first characters are looked at)."""
    if isinstance(value, str):
        text = value[:200]
    elif isinstance(value, int | Fraction) and not isinstance(value, bool):
        text = _int_text(value)
    else:
        text = type(value).__name__ if isinstance(value, list | dict | tuple | set) else \
            _safe_str(value)
    text = " ".join(text.split())
    if len(text) > 60:
        text = text[:57] + "..."
    return f"'{text}'"


def _int_text(value: int | Fraction) -> str:
    if isinstance(value, Fraction):
        if value.denominator == 1:
            return _int_text(value.numerator)
        return f"{_int_text(value.numerator)}/{_int_text(value.denominator)}"
    if abs(value) >= limits.integer_bound():
        return f"{'-' if value < 0 else ''}<an integer of about {_digits(value)} digits>"
    return str(value)


def _digits(value: int) -> int:
    return max(1, math.floor(abs(value).bit_length() * math.log10(2)) + 1)


def _safe_str(value: object) -> str:
    try:
        if isinstance(value, sp.Basic):
            return _sympy_text(value)
        return str(value)[:200]
    except Exception:  # noqa: BLE001 - a value whose str() fails is shown by its type
        return type(value).__name__


def _sympy_text(expr: sp.Basic) -> str:
    """``sstr`` of a SymPy object, or a placeholder when it holds a huge integer."""
    for atom in expr.atoms(sp.Rational):
        if abs(atom.p) >= limits.integer_bound() or atom.q >= limits.integer_bound():
            return "<an expression with a number of more than "\
                   f"{limits.MAX_DIGITS} digits>"
    return sp.sstr(expr)[:200]


def _declared(names: Iterable[str]) -> str:
    names = list(names)
    return ", ".join(names) if names else "none"


# ------------------------------------------------------------------------ values
#
# While text is read, a value is either a rational function with rational
# coefficients in the declared names (``_RF``: integer polynomials ``num / den`` of one
# flint context, in lowest terms, ``den`` with a positive leading coefficient), or an
# expression holding an irrational constant (``_Sym``: SymPy, small).


@dataclass(frozen=True)
class _RF:
    num: flint.fmpz_mpoly
    den: flint.fmpz_mpoly

    def is_constant(self) -> bool:
        return self.num.is_constant() and self.den.is_constant()

    def rational(self) -> Fraction:
        """The value of a constant."""
        return Fraction(int(self.num.leading_coefficient()) if not self.num.is_zero()
                        else 0, int(self.den.leading_coefficient()))


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
    def constant(self, value: Fraction) -> _RF:
        self._check_int(value.numerator)
        self._check_int(value.denominator)
        return _RF(self.ctx.constant(value.numerator), self.ctx.constant(value.denominator))

    def symbol(self, name: str) -> _RF:
        if name not in self.symbols:
            raise self.undeclared(name)
        return _RF(self.ctx.gens()[self.names.index(name)], self.one)

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

    def _reduced(self, num: flint.fmpz_mpoly, den: flint.fmpz_mpoly) -> _RF:
        if den.is_zero():
            raise self.fail("is not a finite number (division by zero)")
        if num.is_zero():
            return _RF(num, self.one)
        if not den.is_one():
            g = num.gcd(den)
            if not g.is_one():
                num, den = num / g, den / g
            if int(den.leading_coefficient()) < 0:
                num, den = -num, -den
        self._check_poly(num)
        self._check_poly(den)
        return _RF(num, den)

    def add(self, a: _RF, b: _RF) -> _RF:
        if a.den == b.den:
            return self._reduced(a.num + b.num, a.den)
        return self._reduced(self._product(a.num, b.den) + self._product(b.num, a.den),
                             self._product(a.den, b.den))

    def mul(self, a: _RF, b: _RF) -> _RF:
        an, ad, bn, bd = a.num, a.den, b.num, b.den
        if not ad.is_one() and not bn.is_zero():
            g = bn.gcd(ad)
            bn, ad = bn / g, ad / g
        if not bd.is_one() and not an.is_zero():
            g = an.gcd(bd)
            an, bd = an / g, bd / g
        return self._reduced(self._product(an, bn), self._product(ad, bd))

    def inverse(self, a: _RF) -> _RF:
        if a.num.is_zero():
            raise self.fail("is not a finite number (division by zero)")
        return self._reduced(a.den, a.num)

    def power(self, a: _RF, n: int) -> _RF:
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
        result = _RF(self.one, self.one)
        base = a
        while n:
            if n & 1:
                result = self.mul(result, base)
            n >>= 1
            if n:
                base = self.mul(base, base)
        return result

    # --- SymPy side ---------------------------------------------------------------
    def to_sympy(self, a: _RF) -> sp.Expr:
        return _poly_expr(a.num, self.names, self.symbols) / _poly_expr(
            a.den, self.names, self.symbols)

    def sym(self, expr: sp.Expr) -> _RF | _Sym:
        """An expression built by SymPy: back to ``_RF`` when it holds no irrational
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

    def as_sympy(self, v: _RF | _Sym) -> sp.Expr:
        if isinstance(v, _Sym):
            return v.expr
        if len(v.num) + len(v.den) > limits.MAX_CONSTANT_NODES // 4:
            raise self.too_large("a long polynomial combined with pi, atan or sqrt")
        return self.to_sympy(v)

    def tree(self, expr: sp.Basic, strict: bool = True) -> _RF | None:
        """A SymPy expression made of rationals, declared symbols (matched by name),
        sums, products and integer powers, as ``_RF`` with every budget applied;
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
    def v_add(self, values: list) -> _RF | _Sym:
        exact = [v for v in values if isinstance(v, _RF)]
        other = [v for v in values if isinstance(v, _Sym)]
        total = self.balanced(exact, self.add) if exact else None
        if not other:
            return total
        parts = [v.expr for v in other] + ([self.as_sympy(total)] if total is not None
                                           else [])
        return self.sym(sp.Add(*parts))

    def v_neg(self, v):
        return _RF(-v.num, v.den) if isinstance(v, _RF) else self.sym(-v.expr)

    def v_mul(self, a, b):
        if isinstance(a, _RF) and isinstance(b, _RF):
            return self.mul(a, b)
        return self.sym(self.as_sympy(a) * self.as_sympy(b))

    def v_div(self, a, b):
        if isinstance(b, _RF):
            return self.v_mul(a, self.inverse(b))
        if b.expr.is_zero:
            raise self.fail("is not a finite number (division by zero)")
        return self.sym(self.as_sympy(a) / b.expr)

    def v_pow(self, a, n: int):
        if isinstance(a, _RF):
            return self.power(a, n)
        bits = max((max(abs(int(r.p)).bit_length(), int(r.q).bit_length())
                    for r in a.expr.atoms(sp.Rational)), default=1)
        if (bits - 1) * abs(n) > limits.max_bits():
            raise self.too_large(f"a number of more than {limits.MAX_DIGITS} digits")
        if n < 0 and a.expr.is_zero:
            raise self.fail("is not a finite number (division by zero)")
        return self.sym(a.expr ** n)

    # --- functions ------------------------------------------------------------------
    def call(self, name: str, args: list) -> _RF | _Sym:
        if name in ("Integer", "Rational"):
            return self._rational_call(name, args)
        if len(args) != 1:
            raise self.fail(f"cannot be parsed ({name} takes one argument)")
        (x,) = args
        if isinstance(x, _RF) and not x.is_constant():
            raise self.fail(f"cannot take {name} of an expression in the {self.kind} "
                            f"(only of numbers)")
        if name == "sqrt":
            if isinstance(x, _RF):
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

    def _rational_call(self, name: str, args: list) -> _RF:
        allowed = (1,) if name == "Integer" else (1, 2)
        if len(args) not in allowed:
            count = "one number" if name == "Integer" else "one or two numbers"
            raise self.fail(f"cannot be parsed ({name} takes {count})")
        values = []
        for x in args:
            if not isinstance(x, _RF) or not x.is_constant():
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


# ------------------------------------------------------------------------ the parser


def _tokens(text: str) -> list[tuple[str, str]]:
    out, pos = [], 0
    while pos < len(text):
        match = _TOKEN.match(text, pos)
        if match is None:        # only trailing white space is left
            break
        kind = match.lastgroup
        out.append((kind, match.group(kind)))
        pos = match.end()
    return out


def _decimal(token: str, reader: _Reader) -> Fraction:
    """The exact value of a decimal literal (``12``, ``0.5``, ``1e-3``)."""
    match = _DECIMAL.fullmatch(token)
    if match is None or not (match.group(1) or match.group(2)):
        hint = "write numbers in decimal, e.g. 3/5 or 0.6"
        head = re.match(r"[\d.]+", token)
        if head and re.fullmatch(r"[A-Za-z]\w*", token[head.end():], re.ASCII):
            hint = f"write {head.group()}*{token[head.end():]} for a product"
        raise reader.fail(f"cannot be parsed ({hint})")
    whole, frac, exp = match.group(1) or "", match.group(2) or "", match.group(3)
    if len(whole) > 1 and whole[0] == "0":
        raise reader.fail(f"has a number with a leading zero ({token}), which is "
                          f"ambiguous (octal in YAML 1.1 and C): write it without the "
                          f"zero")
    exponent = int(exp) if exp is not None and len(exp) <= 8 else None
    if exp is not None and (exponent is None or abs(exponent) > limits.MAX_EXPONENT):
        raise reader.too_large(f"a decimal exponent over {limits.MAX_EXPONENT}")
    digits = (whole + frac).lstrip("0")
    shift = (exponent or 0) - len(frac)
    if len(digits) + max(shift, 0) > limits.MAX_DIGITS or (
            digits and -shift > limits.MAX_DIGITS):
        raise reader.too_large(f"a number of more than {limits.MAX_DIGITS} digits")
    mantissa = int(digits) if digits else 0
    return Fraction(mantissa * 10**shift) if shift >= 0 else Fraction(mantissa,
                                                                      10**-shift)


class _Parser:
    """Recursive descent over the tokens, with Python's precedence (``-x**2`` is
    ``-(x**2)``); every value goes through the budgets of the reader."""

    def __init__(self, tokens: list[tuple[str, str]], reader: _Reader):
        self.tokens, self.reader, self.i = tokens, reader, 0

    def peek(self) -> str:
        return self.tokens[self.i][1] if self.i < len(self.tokens) else ""

    def take(self) -> tuple[str, str]:
        tok = self.tokens[self.i]
        self.i += 1
        return tok

    def syntax(self) -> NumberError:
        return self.reader.fail("cannot be parsed")

    def parse(self):
        value = self.sum()
        if self.i != len(self.tokens):
            raise self.syntax()
        return value

    def sum(self):
        values = [self.product()]
        while self.peek() in ("+", "-") and self.i < len(self.tokens):
            op = self.take()[1]
            value = self.product()
            values.append(self.reader.v_neg(value) if op == "-" else value)
        return values[0] if len(values) == 1 else self.reader.v_add(values)

    def product(self):
        value = self.unary()
        while self.peek() in ("*", "/") and self.i < len(self.tokens):
            op = self.take()[1]
            rhs = self.unary()
            value = (self.reader.v_mul(value, rhs) if op == "*"
                     else self.reader.v_div(value, rhs))
        return value

    def unary(self):
        negative = False
        while self.peek() in ("+", "-") and self.i < len(self.tokens):
            negative ^= self.take()[1] == "-"
        value = self.power()
        return self.reader.v_neg(value) if negative else value

    def power(self):
        base = self.atom()
        if self.peek() in ("**", "^") and self.i < len(self.tokens):
            self.take()
            n = self.exponent()
            if self.peek() in ("**", "^") and self.i < len(self.tokens):
                raise self.reader.fail("cannot be parsed: chained powers are not "
                                       "accepted (use parentheses)")
            base = self.reader.v_pow(base, n)
        return base

    def exponent(self) -> int:
        sign = 1
        if self.peek() in ("+", "-") and self.i < len(self.tokens):
            sign = -1 if self.take()[1] == "-" else 1
        if self.i >= len(self.tokens) or self.tokens[self.i][0] != "num" or \
                not self.tokens[self.i][1].isdigit():
            raise self.reader.fail("cannot be parsed: an exponent must be an integer "
                                   "literal (write sqrt(x) for a square root)")
        text = self.take()[1]
        if len(text) > 6 or int(text) > limits.MAX_EXPONENT:
            raise self.reader.too_large(f"an exponent over {limits.MAX_EXPONENT}")
        return sign * int(text)

    def atom(self):
        if self.i >= len(self.tokens):
            raise self.syntax()
        kind, text = self.take()
        if kind == "num":
            return self.reader.constant(_decimal(text, self.reader))
        if kind == "name":
            if text == "CRootOf":
                return self.root()
            if text in FUNCTIONS:
                return self.reader.call(text, self.arguments())
            if text == "pi":
                return _Sym(sp.pi)
            return self.reader.symbol(text)
        if text == "(":
            value = self.sum()
            if self.peek() != ")" or self.i >= len(self.tokens):
                raise self.syntax()
            self.take()
            return value
        raise self.syntax()

    def root(self) -> _Sym:
        """``CRootOf(p, k)``: the ``k``-th root of a polynomial ``p`` in one variable (as
        SymPy orders them: real roots first, increasing)."""
        span = _root_argument(self.tokens, self.i)
        if self.peek() != "(":
            raise self.syntax()
        names = {self.tokens[k][1] for k in span if self.tokens[k][0] == "name"
                 and self.tokens[k][1] not in self.reader.symbols
                 and self.tokens[k][1] not in FUNCTIONS
                 and self.tokens[k][1] not in ("pi", "CRootOf")}
        outer = self.reader
        variable = next(iter(names), "x")
        inner = _Reader({variable: sp.Symbol(variable)}, outer.where, outer.shown,
                        outer.kind)
        self.take()
        self.reader = inner
        try:
            poly = self.sum()
        finally:
            self.reader = outer
        if self.peek() != ",":
            raise outer.fail("cannot be parsed (CRootOf takes a polynomial and an index)")
        self.take()
        index = self.sum()
        if self.peek() != ")":
            raise self.syntax()
        self.take()
        if not isinstance(poly, _RF) or not poly.den.is_constant() or \
                poly.num.is_constant():
            raise outer.fail("cannot be parsed (CRootOf takes a polynomial with rational "
                             "coefficients)")
        degree = poly.num.total_degree()
        if degree > limits.MAX_ROOT_DEGREE:
            raise outer.too_large(f"a root of a polynomial of degree over "
                                  f"{limits.MAX_ROOT_DEGREE}")
        if max(_height(poly.num), _height(poly.den)) > 64 * degree + 256:
            raise outer.too_large("a root of a polynomial with very large coefficients")
        expr = inner.to_sympy(poly)
        real = sp.Poly(expr, inner.symbols[inner.names[0]]).count_roots()
        if not isinstance(index, _RF) or not index.is_constant() or \
                index.rational().denominator != 1 or \
                not 0 <= int(index.rational()) < real:
            raise outer.fail(f"cannot be parsed (CRootOf here names a real root: its index "
                             f"is an integer from 0 to {real - 1}, the polynomial having "
                             f"{real} real roots)")
        try:
            return _Sym(sp.CRootOf(expr, int(index.rational())))
        except (sp.PolynomialError, ValueError, IndexError) as exc:
            raise outer.fail(f"cannot be parsed ({exc})") from None

    def arguments(self) -> list:
        if self.peek() != "(":
            raise self.syntax()
        self.take()
        args = [self.sum()]
        while self.peek() == "," and self.i < len(self.tokens):
            self.take()
            args.append(self.sum())
        if self.peek() != ")" or self.i >= len(self.tokens):
            raise self.syntax()
        self.take()
        return args


def _check_tokens(tokens: list[tuple[str, str]], reader: _Reader) -> None:
    """Refuse, in reading order, anything outside the whitelist (before any value is
    built): unbalanced or too deep parentheses, unknown characters and names."""
    depth = 0
    for _, text in tokens:
        depth += text == "("
        depth -= text == ")"
        if depth < 0:
            raise reader.fail("cannot be parsed")
        if depth > limits.MAX_PARENTHESES:
            raise reader.too_large(f"parentheses nested more than "
                                   f"{limits.MAX_PARENTHESES} deep")
    if depth:
        raise reader.fail("cannot be parsed")
    bound = _bound_names(tokens, reader)
    for i, (kind, text) in enumerate(tokens):
        following = tokens[i + 1][1] if i + 1 < len(tokens) else ""
        if kind == "name":
            if i in bound:
                continue
            if text in FUNCTIONS or text == "CRootOf":
                if following != "(":
                    raise reader.fail(f"cannot be parsed ({text} is a function)")
            elif text in reader.symbols or text == "pi":
                continue
            elif following == "(":
                raise reader.fail(f"uses unknown function {text} (allowed: atan, sqrt)")
            else:
                raise reader.undeclared(text)
        elif kind == "other":
            raise reader.fail("cannot be parsed")


def _root_argument(tokens: list[tuple[str, str]], start: int) -> range:
    """Token positions of the first argument of ``CRootOf(`` opening at ``start``."""
    depth, i = 0, start
    while i < len(tokens):
        text = tokens[i][1]
        depth += text == "("
        depth -= text == ")"
        if depth == 1 and text == "," or depth == 0:
            break
        i += 1
    return range(start + 1, i)


def _bound_names(tokens: list[tuple[str, str]], reader: _Reader) -> set[int]:
    """Positions of the variable of each ``CRootOf(polynomial, k)``: one name, not a
    declared one, may be the polynomial's variable there."""
    out: set[int] = set()
    for i, (kind, text) in enumerate(tokens):
        if kind != "name" or text != "CRootOf" or i + 1 >= len(tokens) or \
                tokens[i + 1][1] != "(":
            continue
        span = _root_argument(tokens, i + 1)
        names = {tokens[k][1] for k in span if tokens[k][0] == "name"
                 and tokens[k][1] not in reader.symbols and tokens[k][1] not in FUNCTIONS
                 and tokens[k][1] not in ("pi", "CRootOf")}
        if len(names) > 1:
            raise reader.fail("cannot be parsed (CRootOf takes a polynomial in one "
                              "variable)")
        out.update(k for k in span if tokens[k][1] in names)
    return out


def _symbols(symbols: Mapping[str, sp.Symbol] | Iterable[str]) -> dict[str, sp.Symbol]:
    if isinstance(symbols, Mapping):
        return dict(symbols)
    return {n: sp.Symbol(n) for n in symbols}


def _read(text: str, symbols: Mapping[str, sp.Symbol], where: str, *,
          max_length: int, kind: str) -> tuple[_RF | _Sym, _Reader]:
    """Read ``text`` into a value (see :func:`parse_expression`)."""
    reader = _Reader(symbols, where, _show(text), kind)
    stripped = text.strip()
    if not stripped:
        raise NumberError(where, "empty text is not a number")
    if stripped.lower() in _NOT_FINITE:
        raise reader.fail("is not a finite number")
    if len(stripped) > max_length:
        raise reader.fail(f"is too long ({len(stripped):,} characters; at most "
                          f"{max_length:,})")
    if "\n" in stripped or "\r" in stripped:
        raise reader.fail("cannot be parsed (one line expected)")
    tokens = _tokens(stripped)
    _check_tokens(tokens, reader)
    try:
        return _Parser(tokens, reader).parse(), reader
    except RecursionError:
        raise reader.too_large("nested too deeply") from None


def parse_expression(text: str, symbols: Mapping[str, sp.Symbol] | Iterable[str],
                     where: str, *, max_length: int | None = None,
                     kind: str = "variables") -> sp.Expr:
    """Read an exact expression from text: the one parser of the package.

    Accepted: decimal numbers (``12``, ``0.5``, ``1e-3``, all exact), the names in
    ``symbols``, ``pi``, ``atan(x)``, ``sqrt(x)``, ``Rational(p, q)``,
    ``Integer(n)`` (exact: ``Integer(0.5)`` is an error), ``+ - * /``, ``**`` or
    ``^`` with an integer literal exponent, and parentheses. Nothing else is
    evaluated; no Python runs. Every step is checked against the budgets of
    :mod:`coopkin_sym.limits` before it is taken.

    Parameters
    ----------
    text : str
        The expression, one line.
    symbols : mapping of name to Symbol, or names
        The names the text may use (plain symbols are made for bare names).
    where : str
        The entry being read, for error messages.
    max_length : int, optional
        Longest text accepted (default :data:`~coopkin_sym.limits.MAX_EXPRESSION_TEXT`).
    kind : str
        What the names are, for error messages (``"parameters"``, ``"variables"``).

    Returns
    -------
    sympy.Expr
        A rational function with rational coefficients in the symbols, or an exact
        expression with irrational constants (``pi/3``, ``sqrt(2)``).

    Raises
    ------
    NumberError
        One line naming ``where`` and what is wrong.

    Example
    -------
    >>> parse_expression("(t_q1 + 1)**2 / 2", ["t_q1"], "equation")
    t_q1**2/2 + t_q1 + 1/2
    >>> parse_expression("exec(1)", [], "x")  # parse-ok: refused  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.NumberError: x: 'exec(1)' uses unknown function exec (allowed: ...)
    """
    if not isinstance(text, str):
        raise NumberError(where, f"{_show(text)} is not text (got {type(text).__name__})")
    value, reader = _read(text, _symbols(symbols), where, kind=kind,
                          max_length=max_length or limits.MAX_EXPRESSION_TEXT)
    return reader.as_sympy(value) if isinstance(value, _Sym) else reader.to_sympy(value)


def parse_polynomial(text: str, names: Iterable[str], where: str) -> flint.fmpq_mpoly:
    """Read a polynomial with rational coefficients in ``names`` from text, as
    :func:`parse_expression` does, but without building a SymPy expression: a
    polynomial of many terms (an equation of a report read back) is read in a
    fraction of the time.

    Returns
    -------
    flint.fmpq_mpoly
        In a context whose variables are ``names``, in order, each once
        (``p.context().names()``).

    Raises
    ------
    NumberError
        What :func:`parse_expression` refuses, and a text that is not a polynomial
        (it divides by an expression in the names, or has an irrational constant).

    Example
    -------
    >>> parse_polynomial("(t_q1 + 1)**2 / 2", ["t_q1", "L"], "equation")
    1/2*t_q1^2 + t_q1 + 1/2
    >>> parse_polynomial("1/t_q1", ["t_q1"], "equation")
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.NumberError: equation: '1/t_q1' is not a polynomial
    """
    if not isinstance(text, str):
        raise NumberError(where, f"{_show(text)} is not text (got {type(text).__name__})")
    value, reader = _read(text, _symbols(list(dict.fromkeys(names))), where, kind="variables",
                          max_length=limits.MAX_EXPRESSION_TEXT)
    if isinstance(value, _Sym) or not value.den.is_constant():
        raise reader.fail("is not a polynomial")
    d = int(value.den.leading_coefficient())
    ctx = flint.fmpq_mpoly_ctx.get(reader.names, "lex")
    return ctx.from_dict({m: flint.fmpq(int(c), d) for m, c in value.num.to_dict().items()})


def _value(value: object, parameters: Mapping[str, sp.Symbol], where: str,
           kind: str, max_length: int | None = None) -> tuple[object, _Reader]:
    """Any accepted input as a value of the reader (the common front of
    :func:`parse_number`, :func:`parse_angle` and :func:`exact_expr`)."""
    reader = _Reader(parameters, where, _show(value), kind)
    if isinstance(value, bool) or (type(value).__module__ == "numpy"
                                   and type(value).__name__ in ("bool", "bool_")):
        raise reader.fail("is a truth value, not a number")
    if isinstance(value, str):
        return _read(value, parameters, where, kind=kind,
                     max_length=max_length or limits.MAX_NUMBER_TEXT)
    if isinstance(value, sp.Basic):
        if not isinstance(value, sp.Expr):
            raise reader.fail("is not a number")
        rf = reader.tree(value, strict=False) if _small(value) else None
        return (rf if rf is not None else reader.sym(value)), reader
    if isinstance(value, numbers.Integral):
        return reader.constant(Fraction(int(value))), reader
    if isinstance(value, numbers.Rational):
        return reader.constant(Fraction(int(value.numerator), int(value.denominator))), \
            reader
    if isinstance(value, float):
        if not math.isfinite(value):  # float-ok: a finiteness test, not a decision
            raise reader.fail("is not a finite number")
        # float-ok: the float's shortest decimal text, read exactly (0.1 is 1/10)
        return reader.constant(Fraction(repr(float(value)))), reader  # float-ok
    if isinstance(value, Decimal):
        if not value.is_finite():
            raise reader.fail("is not a finite number")
        sign, digits, exponent = value.as_tuple()
        if abs(int(exponent)) > limits.MAX_EXPONENT:
            raise reader.too_large(f"a decimal exponent over {limits.MAX_EXPONENT}")
        if len(digits) > limits.MAX_DIGITS:
            raise reader.too_large(f"a number of more than {limits.MAX_DIGITS} digits")
        return reader.constant(Fraction(value)), reader
    module = type(value).__module__ or ""
    if module.startswith("numpy") and "float" in type(value).__name__:
        raise reader.fail(f"is a numpy {type(value).__name__}, which is not exact; write "
                          "the number as text (e.g. '0.1') or as a Python int or Fraction")
    raise reader.fail(f"is not a number (got {type(value).__name__})")


def _small(expr: sp.Basic) -> bool:
    """Whether a SymPy input is within the budget of parts (counted lazily)."""
    for k, _ in enumerate(sp.preorder_traversal(expr)):
        if k > limits.MAX_TERMS:
            return False
    return True


def exact_expr(value: object, symbols: Mapping[str, sp.Symbol] | Iterable[str] | None = None,
               where: str = "value") -> sp.Expr:
    """An exact SymPy value from a number, an exact SymPy expression or text.

    Text goes through :func:`parse_expression` (the names it may use: ``symbols``);
    a SymPy expression is kept as it is (with ``symbols`` given, its symbols are
    matched to them by name); ``int``, ``Fraction``, numpy integers and ``Decimal``
    are exact; a Python float is the decimal it prints as. Nothing is ever evaluated
    as code.

    Example
    -------
    >>> exact_expr("1/2"), exact_expr(3), exact_expr(0.25)
    (1/2, 3, 1/4)
    """
    syms = _symbols(symbols if symbols is not None else ())
    if isinstance(value, sp.Expr):
        if symbols is None:
            return value
        mapping = {}
        for s in value.free_symbols:
            if s.name not in syms:
                raise UndeclaredSymbol(where, f"{_show(value)} uses undeclared symbol "
                                              f"{s.name} (declared variables: "
                                              f"{_declared(syms)})")
            mapping[s] = syms[s.name]
        return value.xreplace(mapping) if mapping else value
    v, reader = _value(value, syms, where, "variables", limits.MAX_EXPRESSION_TEXT)
    return reader.as_sympy(v) if isinstance(v, _Sym) else reader.to_sympy(v)


#: integers as the general parser reads them (no leading zero), of at most 60 digits
_INT = r"(?:0|[1-9]\d{0,59})"
_SIMPLE_RATIONAL = re.compile(rf"\s*(-?{_INT})\s*(?:/\s*({_INT})\s*)?", re.ASCII)


def _simple_rational(value: object) -> sp.Rational | None:
    """The commonest exact numbers read without the general parser: the texts ``p``
    and ``p/q`` with integers of at most 60 digits, Python and SymPy integers and
    rationals; ``None`` for anything else."""
    if isinstance(value, str):
        match = _SIMPLE_RATIONAL.fullmatch(value)
        if match and (match.group(2) is None or int(match.group(2)) != 0):
            return sp.Rational(int(match.group(1)), int(match.group(2) or 1))
        return None
    if isinstance(value, int) and not isinstance(value, bool):
        return sp.Integer(value) if abs(value) < 10**60 else None
    if isinstance(value, sp.Rational):
        return value if value.q < 10**60 and abs(value.p) < 10**60 else None
    return None


def parse_number(value: object, parameters: Mapping[str, sp.Symbol],
                 where: str) -> sp.Expr:
    """Read one exact number: a rational, or a polynomial in the parameters.

    Parameters
    ----------
    value : int, Fraction, str, SymPy number or expression, or float
        Text (``"3/5"``, ``"2*L"``, ``"0.1"`` is exactly 1/10), read by
        :func:`parse_expression`. A Python float is read from its shortest decimal
        text (``0.1`` -> 1/10); numpy integers are exact; other numpy floats are
        refused.
    parameters : mapping of name to Symbol
        The declared parameters; no other symbol is accepted.
    where : str
        The entry being read, for error messages.

    Returns
    -------
    sympy.Expr
        A ``Rational``, or an expanded polynomial with rational coefficients.

    Raises
    ------
    NumberError
        If the value cannot be parsed, is not exact, uses an undeclared symbol,
        is not a polynomial in the parameters, or is over a budget.

    Example
    -------
    >>> import sympy as sp
    >>> L = sp.Symbol("L", positive=True)
    >>> parse_number("L/2 + 1", {"L": L}, "point")
    L/2 + 1
    """
    simple = _simple_rational(value)
    if simple is not None:
        return simple
    v, reader = _value(value, parameters, where, "parameters")
    if isinstance(v, _Sym):
        expr = v.expr
        if expr.is_real is False:
            raise reader.fail("is not a real number")
        if expr.free_symbols:
            irrational = [a for a in sp.Add.make_args(expr)
                          if not a.as_coeff_Mul()[0].is_Rational
                          or a.atoms(sp.NumberSymbol, sp.Function)
                          or any(not p.exp.is_Integer for p in a.atoms(sp.Pow))]
            what = _sympy_text(irrational[0])[:40] if irrational else _sympy_text(expr)[:40]
            raise reader.fail(f"has a coefficient that is not an exact rational number "
                              f"({what})")
        raise reader.fail("is not an exact rational number")
    if not v.den.is_constant():
        raise reader.fail("is not a polynomial in the parameters")
    return reader.to_sympy(v)


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


def _small_angle(parts: _AngleParts) -> bool:
    """Whether the part this module does not decide itself is small enough for SymPy's
    trigonometric simplification: one short term, such as ``2*atan(sqrt(2))``."""
    terms = len(parts.other) + len(parts.atans) + bool(parts.pi_coeff) + \
        bool(parts.radians)
    return terms == 1 and all(sp.count_ops(t) <= 20 and len(t.atoms(sp.atan)) <= 1
                              and not t.has(sp.CRootOf) for t in parts.other)


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
        if approx is None:
            cos, sin = sp.Integer(-1), sp.Integer(0)
        else:
            tr = to_sympy(approx)
            cos, sin = (1 - tr**2) / (1 + tr**2), 2 * tr / (1 + tr**2)
        text = angle_text(cos, sin)
        angle = math.atan2(float(sin), float(cos))  # float-ok: shown to the user
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


def angle_text(cos: object, sin: object) -> str:
    """The shortest exact text for the angle with rational ``(cos, sin)``.

    ``"0"``, ``"pi/2"``, ``"-pi/2"``, ``"pi"``, else ``"2*atan(p/q)"`` with
    ``p/q = sin/(1 + cos)``, in ``(-pi, pi]``. Inverse of :func:`parse_angle`.

    Raises
    ------
    NumberError
        If ``cos`` and ``sin`` are not rational or ``cos^2 + sin^2 != 1``.

    Example
    -------
    >>> import sympy as sp
    >>> angle_text(sp.Rational(4, 5), sp.Rational(-3, 5))
    '2*atan(-1/3)'
    """
    c = parse_number(cos, {}, "cos") if not isinstance(cos, float) else None
    s = parse_number(sin, {}, "sin") if not isinstance(sin, float) else None
    if c is None or s is None or not (c.is_Rational and s.is_Rational):
        raise NumberError("angle", f"cos = {cos}, sin = {sin} must be exact rationals")
    if c**2 + s**2 != 1:
        raise NumberError("angle", f"cos = {c}, sin = {s} is not a point on the unit "
                                   f"circle")
    return tangent_text(None if c == -1 else Fraction(int(s.p), int(s.q))
                        / Fraction(int((1 + c).p), int((1 + c).q)))


def tangent_text(t: Fraction | None) -> str:
    """The angle with ``tan(q/2) = t`` (None: ``q = pi``) as :func:`angle_text` writes
    it: ``"0"``, ``"pi/2"``, ``"-pi/2"``, ``"pi"``, else ``"2*atan(p/q)"``.

    Example
    -------
    >>> tangent_text(Fraction(-1, 3)), tangent_text(None)
    ('2*atan(-1/3)', 'pi')
    """
    if t is None:
        return "pi"
    return {0: "0", 1: "pi/2", -1: "-pi/2"}.get(t, f"2*atan({t})")
