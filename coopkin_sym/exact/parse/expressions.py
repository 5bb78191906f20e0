"""The tokenizer and the recursive-descent reader of expressions: the whitelist
(decimal numbers, declared names, ``pi``, degrees (``deg``, ``90deg``), ``atan``,
``sqrt``, ``Rational``, ``Integer``, ``+ - * / ** ^`` and parentheses), :func:`parse_expression` and
:func:`parse_polynomial`. No text is handed to Python or to SymPy's parser."""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from fractions import Fraction

import flint
import sympy as sp

from coopkin_sym import limits
from coopkin_sym.errors import NumberError
from coopkin_sym.exact.parse.messages import _show
from coopkin_sym.exact.parse.reader import _height, _Reader, _Sym
from coopkin_sym.exact.ratfunc import RatFunc

#: Functions allowed in text, besides the declared names and ``pi``.
FUNCTIONS = ("atan", "sqrt", "Rational", "Integer")
_NOT_FINITE = {"inf", "+inf", "-inf", "infinity", "+infinity", "-infinity", "nan",
               ".inf", "+.inf", "-.inf", ".nan", "oo", "-oo", "zoo"}
_TOKEN = re.compile(
    r"\s*(?:(?P<num>(?:\d|\.\d)(?:[\w.]|(?<=[eE])[+-])*)"
    r"|(?P<name>[A-Za-z_]\w*)|(?P<op>\*\*|[-+*/^(),])|(?P<other>\S))", re.ASCII)
_DECIMAL = re.compile(r"(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?", re.ASCII)



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


#: The name of a degree, ``pi/180`` (``90*deg``; also written after a number, ``90deg``).
DEGREE = "deg"


def _number(token: str, reader: _Reader):
    """The exact value of a number token: a decimal literal, or a decimal followed by
    ``deg`` (``90deg``: ``90*pi/180``, exactly ``pi/2``)."""
    if token.endswith(DEGREE) and _is_decimal(token[:-len(DEGREE)]):
        return reader.v_mul(reader.constant(_decimal(token[:-len(DEGREE)], reader)),
                            _Sym(sp.pi / 180))
    return reader.constant(_decimal(token, reader))


def _is_decimal(token: str) -> bool:
    match = _DECIMAL.fullmatch(token)
    return match is not None and bool(match.group(1) or match.group(2))


def _decimal(token: str, reader: _Reader) -> Fraction:
    """The exact value of a decimal literal (``12``, ``0.5``, ``1e-3``)."""
    match = _DECIMAL.fullmatch(token)
    if match is None or not (match.group(1) or match.group(2)):
        raise reader.fail(f"cannot be parsed ({_number_hint(token, reader)})")
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


def _number_hint(token: str, reader: _Reader) -> str:
    """How to write a token that starts with a digit but is no number: a product
    (``2*L``) when what follows the digits is a name that can be read, else decimals."""
    head = re.match(r"[\d.]+", token)
    tail = token[head.end():] if head else ""
    if head and tail.startswith(DEGREE) and tail != DEGREE:
        return f"an angle in degrees is written {head.group()}deg or {head.group()}*deg"
    if head and (tail in reader.symbols or tail in ("pi", DEGREE)):
        return f"write {head.group()}*{tail} for a product"
    return "write numbers in decimal, e.g. 3/5 or 0.6"


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
            return _number(text, self.reader)
        if kind == "name":
            if text == "CRootOf":
                return self.root()
            if text in FUNCTIONS:
                return self.reader.call(text, self.arguments())
            if text == "pi":
                return _Sym(sp.pi)
            if text == DEGREE and text not in self.reader.symbols:
                return _Sym(sp.pi / 180)
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
                 and self.tokens[k][1] not in ("pi", DEGREE, "CRootOf")}
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
        if not isinstance(poly, RatFunc) or not poly.den.is_constant() or \
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
        if not isinstance(index, RatFunc) or not index.is_constant() or \
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
            elif text in reader.symbols or text in ("pi", DEGREE):
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
                 and tokens[k][1] not in ("pi", DEGREE, "CRootOf")}
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
          max_length: int, kind: str) -> tuple[RatFunc | _Sym, _Reader]:
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
    ``symbols``, ``pi``, ``deg`` (a degree, ``pi/180``: ``90deg`` and ``90*deg`` are
    ``pi/2`` exactly; a declared name ``deg`` is that name), ``atan(x)``, ``sqrt(x)``,
    ``Rational(p, q)``, ``Integer(n)`` (exact: ``Integer(0.5)`` is an error),
    ``+ - * /``, ``**`` or
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
    >>> parse_expression("90deg", [], "q1"), parse_expression("-45*deg", [], "q1")
    (pi/2, -pi/4)
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


