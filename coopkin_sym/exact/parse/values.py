"""Exact numbers from any accepted input (text, Python and SymPy numbers, floats by
their shortest decimal text): :func:`parse_number` and :func:`exact_expr`."""

from __future__ import annotations

import math
import numbers
import re
from collections.abc import Iterable, Mapping
from decimal import Decimal
from fractions import Fraction

import sympy as sp

from coopkin_sym import limits
from coopkin_sym.errors import UndeclaredSymbol
from coopkin_sym.exact.parse.expressions import _read, _symbols
from coopkin_sym.exact.parse.messages import _declared, _show, _sympy_text
from coopkin_sym.exact.parse.reader import _Reader, _Sym


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


