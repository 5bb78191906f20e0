"""Polynomials over named variables, independent of any ring: how a locus keeps its
equations exactly.

A :class:`NamedPolynomial` is a polynomial with rational coefficients in variables
given by name (``t_q1``, ``q4``, ``L``, ``s_q2``). It does not belong to a python-flint
context, so components found in different charts of a search (whose rings differ)
share one form, it pickles and compares as plain data, and it converts to a flint
polynomial over any list of names that holds its variables, or to SymPy. Text becomes
one only through the package's one parser (:meth:`NamedPolynomial.parse`).

Example
-------
>>> p = NamedPolynomial.parse("t_q1**2 + 4*t_q1 + 1", ["t_q1", "t_q2"], "equation")
>>> p.variables, p.exponents(("t_q2", "t_q1"))
(('t_q1',), {(0, 0): Fraction(1, 1), (0, 1): Fraction(4, 1), (0, 2): Fraction(1, 1)})
>>> p.text
't_q1**2 + 4*t_q1 + 1'
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property

import sympy as sp

from coopkin_sym.errors import NumberError
from coopkin_sym.exact.parse import brief, parse_polynomial
from coopkin_sym.exact.rationals import to_fraction, to_sympy

__all__ = ["NamedPolynomial", "integer_text"]

_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_RESERVED = frozenset({"pi", "E", "I", "oo", "sqrt", "sin", "cos", "tan", "atan", "asin",
                       "acos", "exp", "log"})


@dataclass(frozen=True)
class NamedPolynomial:
    """``sum c * prod(names[i] ** e[i])`` over the terms ``(e, c)``, exactly.

    ``variables`` are the names it uses (sorted); ``terms`` maps exponent tuples over
    ``variables`` to nonzero rational coefficients, sorted: equal polynomials are
    equal (and hash alike) however they were built.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    >>> x, y = ctx.gens()
    >>> p = NamedPolynomial.from_flint(3 * y**2 - 1, ("x", "y"))
    >>> p.variables, p.text, NamedPolynomial.variable("s_q1").text
    (('y',), '3*y**2 - 1', 's_q1')
    """

    variables: tuple[str, ...]
    terms: tuple[tuple[tuple[int, ...], Fraction], ...]

    @classmethod
    def _build(cls, names: Sequence[str], terms: Mapping[tuple[int, ...], object]
               ) -> NamedPolynomial:
        # the variables it uses, by name: equal polynomials are equal objects
        used = sorted((k for k in range(len(names)) if any(e[k] for e in terms)),
                      key=lambda k: names[k])
        out: dict[tuple[int, ...], Fraction] = {}
        for exps, c in terms.items():
            c = to_fraction(c)
            if c:
                key = tuple(exps[k] for k in used)
                out[key] = out.get(key, Fraction(0)) + c
        return cls(tuple(names[k] for k in used),
                   tuple(sorted((e, c) for e, c in out.items() if c)))

    @classmethod
    def from_flint(cls, p, names: Sequence[str]) -> NamedPolynomial:
        """A python-flint polynomial (``fmpz_mpoly`` or ``fmpq_mpoly``) whose context's
        variables are ``names``."""
        return cls._build(tuple(names), {tuple(int(e) for e in m): c
                                         for m, c in p.to_dict().items()})

    @classmethod
    def variable(cls, name: str) -> NamedPolynomial:
        """The polynomial ``name`` itself."""
        return cls((name,), (((1,), Fraction(1)),))

    @classmethod
    def from_sympy(cls, expr: sp.Expr, where: str = "polynomial") -> NamedPolynomial:
        """A SymPy polynomial expression with rational coefficients."""
        symbols = sorted(expr.free_symbols, key=lambda s: s.name)
        try:
            poly = sp.Poly(expr, *symbols, domain=sp.QQ) if symbols else None
        except (sp.PolynomialError, sp.CoercionFailed):
            poly = None
        if poly is None:
            if symbols or not expr.is_Rational:
                raise NumberError(where, f"{brief(sp.sstr(expr))} is not a polynomial with "
                                         "rational coefficients")
            return cls._build((), {(): to_sympy(expr)} if expr != 0 else {})
        return cls._build(tuple(s.name for s in symbols),
                          {tuple(m): to_sympy(c) for m, c in poly.terms()})

    @classmethod
    def parse(cls, text: str, names: Sequence[str], where: str) -> NamedPolynomial:
        """A polynomial from text, through the package's one parser (only ``names``
        may appear); read by the parser's own arithmetic, without SymPy."""
        read = parse_polynomial(text, list(names), where)
        return cls.from_flint(read, read.context().names())

    def exponents(self, names: Sequence[str]) -> dict[tuple[int, ...], Fraction]:
        """The terms as exponent tuples over ``names`` (which must hold every
        variable)."""
        missing = [v for v in self.variables if v not in names]
        if missing:
            raise NumberError("polynomial", f"{self.text} uses {', '.join(missing)}, "
                                            f"not among {', '.join(names) or 'no names'}")
        index = [list(names).index(v) for v in self.variables]
        out = {}
        for exps, c in self.terms:
            full = [0] * len(names)
            for k, e in zip(index, exps, strict=True):
                full[k] = e
            out[tuple(full)] = c
        return out

    def to_sympy(self, symbols: Mapping[str, sp.Symbol] | None = None) -> sp.Expr:
        """The polynomial as a SymPy expression (symbols by name, created when not
        given)."""
        if not symbols or not any(v in symbols for v in self.variables):
            return self._expression
        return self._build_sympy(symbols)

    def _build_sympy(self, symbols: Mapping[str, sp.Symbol] | None) -> sp.Expr:
        syms = [symbols[v] if symbols and v in symbols else sp.Symbol(v)
                for v in self.variables]
        return sp.Add(*[to_sympy(c) * sp.Mul(*[s**e for s, e in zip(syms, exps,
                                                                    strict=True)])
                        for exps, c in self.terms])

    @cached_property
    def _expression(self) -> sp.Expr:
        """The SymPy expression with plain symbols, built once (it is immutable)."""
        return self._build_sympy(None)

    @cached_property
    def text(self) -> str:
        """The polynomial as text (SymPy's printing), printed once."""
        if all(c.denominator == 1 for _, c in self.terms):
            return integer_text(self.variables,
                                ((e, c.numerator) for e, c in self.terms))
        return sp.sstr(self._expression)

    def is_zero(self) -> bool:
        return not self.terms

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        return f"NamedPolynomial({self.text!r})"

    def sort_key(self) -> tuple[int, str]:
        """Shortest text first, then by text: the order of equations in reports."""
        return (len(self.text), self.text)

    @classmethod
    def read(cls, text: str, where: str) -> NamedPolynomial:
        """A polynomial from text whose variables are the names it uses (through the
        one parser; for polynomials written by hand, where no list of names is known).

        Example
        -------
        >>> NamedPolynomial.read("t_q1 - 2*L", "equation").variables
        ('L', 't_q1')
        """
        names = [n for n in dict.fromkeys(_NAME.findall(str(text))) if n not in _RESERVED]
        return cls.parse(text, names, where)


def integer_text(names: Sequence[str], terms) -> str:
    """The text SymPy prints (``sstr``) for the polynomial with integer coefficients
    ``sum c * prod(names[i] ** e[i])`` over ``terms`` (pairs ``(exponents, c)``, distinct
    exponents), written directly: the terms by decreasing lex order of their exponents
    over the names sorted, each as its coefficient and its powers in that order.

    Example
    -------
    >>> integer_text(("y", "x"), [((0, 0), 5), ((1, 2), -3), ((2, 0), 1)])
    '-3*x**2*y + y**2 + 5'
    """
    order = sorted(range(len(names)), key=lambda k: names[k])
    keyed = []
    for exps, c in terms:
        c = int(c)
        if c:
            keyed.append((tuple(int(exps[k]) for k in order), c))
    if not keyed:
        return "0"
    keyed.sort(reverse=True)
    if (len(keyed) == 2 and keyed[1][1] > 0 and not any(keyed[1][0]) and keyed[0][1] < 0
            and sum(1 for e in keyed[0][0] if e) == 1):
        keyed.reverse()  # SymPy's one exception: a positive number, then -c*x**e
    out: list[str] = []
    for exps, c in keyed:
        powers = [names[k] if e == 1 else f"{names[k]}**{e}"
                  for k, e in zip(order, exps, strict=True) if e]
        body = "*".join(([str(abs(c))] if abs(c) != 1 or not powers else []) + powers)
        out.append(("-" if c < 0 else "+") + body)
    text = out[0][1:] if out[0][0] == "+" else out[0]
    return " ".join([text] + [f"{t[0]} {t[1:]}" for t in out[1:]])
