"""Exact numbers and exact angles from text.

Every number a user writes (model files, ``--at`` values) passes through this module
and comes out exact: a SymPy ``Rational``, or a polynomial with rational coefficients
in the declared parameters. Text is parsed by SymPy's ``parse_expr`` after a token
whitelist (numbers, the declared parameters, ``pi``, ``atan``, ``sqrt``, ``Rational``,
``Integer`` and arithmetic operators), so no other Python can run. A decimal such as
``0.1`` is the exact decimal ``1/10``, never a binary float.

Angles are exact when their tangent half-angle ``t = tan(q/2)`` is rational (then
``cos q`` and ``sin q`` are rational) or when they are odd multiples of ``pi``.

Example
-------
>>> import sympy as sp
>>> L = sp.Symbol("L", positive=True)
>>> parse_number("L/2 + 0.1", {"L": L}, "x")
L/2 + 1/10
>>> parse_angle("2*atan(1/3)", "q1")
(4/5, 3/5)
>>> angle_text(sp.Rational(4, 5), sp.Rational(3, 5))
'2*atan(1/3)'
"""

from __future__ import annotations

import io
import math
import numbers
import re
import tokenize
from collections.abc import Mapping
from decimal import Decimal
from fractions import Fraction

import sympy as sp
from sympy.parsing.sympy_parser import auto_number, convert_xor, parse_expr, rationalize

__all__ = ["NumberError", "angle_text", "parse_angle", "parse_number", "parse_polynomial"]

#: Functions and constants allowed in number text besides the declared parameters.
ALLOWED_NAMES: dict[str, object] = {
    "pi": sp.pi,
    "atan": sp.atan,
    "sqrt": sp.sqrt,
    "Rational": sp.Rational,
    "Integer": sp.Integer,
}
_FUNCTIONS = ("atan", "sqrt", "Rational", "Integer")
_OPERATORS = {"+", "-", "*", "/", "**", "^", "(", ")", ","}
_DECIMAL = re.compile(r"(?:\d+(?:\.\d*)?|\.\d+)(?:[eE]([+-]?\d+))?")
_NOT_FINITE = {"inf", "+inf", "-inf", "infinity", "+infinity", "-infinity", "nan",
               ".inf", "+.inf", "-.inf", ".nan"}
_MAX_TEXT = 1000          # characters in one number
_MAX_EXPONENT = 1000      # largest exponent literal (and decimal exponent)
_MAX_POWER_PRODUCT = 10_000  # product of all exponent literals: no towers
_TRANSFORMATIONS = (auto_number, convert_xor, rationalize)


class NumberError(ValueError):
    """A number or angle that is not exact or cannot be read.

    ``where`` names the entry (``arms[0].joints[0].point``, ``q1``); ``message`` says
    what is wrong; ``str(error)`` is ``"where: message"``.

    Example
    -------
    >>> str(NumberError("q1", "'x' cannot be parsed"))
    "q1: 'x' cannot be parsed"
    """

    def __init__(self, where: str, message: str):
        self.where = where
        self.message = message
        super().__init__(f"{where}: {message}" if where else message)


def _show(value: object) -> str:
    """The value as the user wrote it, quoted, shortened if long."""
    text = value if isinstance(value, str) else str(value)
    text = " ".join(text.split())
    if len(text) > 60:
        text = text[:57] + "..."
    return f"'{text}'"


def _declared(parameters: Mapping[str, sp.Symbol]) -> str:
    return ", ".join(parameters) if parameters else "none"


def _check_tokens(text: str, parameters: Mapping[str, sp.Symbol], where: str) -> None:
    """Reject any token outside the whitelist before SymPy sees the text."""
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(text).readline))
    except (tokenize.TokenError, SyntaxError, IndentationError) as exc:
        raise NumberError(where, f"{_show(text)} cannot be parsed") from exc
    skip = {tokenize.NEWLINE, tokenize.NL, tokenize.ENDMARKER, tokenize.INDENT,
            tokenize.DEDENT}
    significant = [tok for tok in tokens if tok.type not in skip]
    power_product = 1
    for i, tok in enumerate(significant):
        following = significant[i + 1].string if i + 1 < len(significant) else ""
        if tok.type == tokenize.NUMBER:
            match = _DECIMAL.fullmatch(tok.string)
            if match is None:
                raise NumberError(where, f"{_show(text)} cannot be parsed "
                                         f"(write numbers in decimal, e.g. 3/5 or 0.6)")
            if match.group(1) and abs(int(match.group(1))) > _MAX_EXPONENT:
                raise NumberError(where, f"{_show(text)} has a decimal exponent that is "
                                         f"too large")
        elif tok.type == tokenize.NAME:
            if tok.string in _FUNCTIONS:
                if following != "(":
                    raise NumberError(where, f"{_show(text)} cannot be parsed "
                                             f"({tok.string} is a function)")
            elif tok.string in parameters or tok.string == "pi":
                pass
            elif following == "(":
                raise NumberError(where, f"{_show(text)} uses unknown function "
                                         f"{tok.string} (allowed: atan, sqrt)")
            else:
                raise NumberError(where, f"{_show(text)} uses undeclared symbol "
                                         f"{tok.string} (declared parameters: "
                                         f"{_declared(parameters)})")
        elif tok.type == tokenize.OP and tok.string in _OPERATORS:
            if tok.string in ("**", "^"):
                power_product *= _exponent_literal(significant, i + 1, text, where)
                if power_product > _MAX_POWER_PRODUCT:
                    raise NumberError(where, f"{_show(text)} has exponents that are "
                                             f"too large")
        else:
            raise NumberError(where, f"{_show(text)} cannot be parsed")


def _exponent_literal(tokens: list[tokenize.TokenInfo], i: int, text: str,
                      where: str) -> int:
    """Size of the integer literal exponent starting at ``tokens[i]``."""
    if i < len(tokens) and tokens[i].string in ("+", "-"):
        i += 1
    if (i >= len(tokens) or tokens[i].type != tokenize.NUMBER
            or not tokens[i].string.isdigit()):
        raise NumberError(where, f"{_show(text)}: an exponent must be an integer literal "
                                 f"(write sqrt(x) for a square root)")
    value = int(tokens[i].string)
    if i + 1 < len(tokens) and tokens[i + 1].string in ("**", "^"):
        raise NumberError(where, f"{_show(text)}: chained powers are not accepted "
                                 f"(use parentheses)")
    if value > _MAX_EXPONENT:
        raise NumberError(where, f"{_show(text)} has an exponent that is too large")
    return max(value, 1)


def _parse_text(text: str, parameters: Mapping[str, sp.Symbol], where: str) -> sp.Expr:
    """Parse whitelisted text into a SymPy expression (not yet checked for exactness)."""
    stripped = text.strip()
    if not stripped:
        raise NumberError(where, "empty text is not a number")
    if stripped.lower() in _NOT_FINITE:
        raise NumberError(where, f"{_show(text)} is not a finite number")
    if len(stripped) > _MAX_TEXT:
        raise NumberError(where, f"{_show(text)} is too long ({len(stripped)} characters)")
    if "\n" in stripped or "\r" in stripped:
        raise NumberError(where, f"{_show(text)} cannot be parsed (one line expected)")
    _check_tokens(stripped, parameters, where)
    namespace: dict[str, object] = {"__builtins__": {}, **ALLOWED_NAMES}
    namespace.update(parameters)
    try:
        expr = parse_expr(stripped, local_dict={}, global_dict=namespace,
                          transformations=_TRANSFORMATIONS)
    except Exception as exc:  # SyntaxError, TypeError, ZeroDivisionError, ...
        raise NumberError(where, f"{_show(text)} cannot be parsed") from exc
    if not isinstance(expr, sp.Expr):
        raise NumberError(where, f"{_show(text)} is not a number")
    if expr.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
        raise NumberError(where, f"{_show(text)} is not a finite number")
    return expr


def _from_sympy(value: sp.Basic, parameters: Mapping[str, sp.Symbol],
                where: str) -> sp.Expr:
    """A SymPy input: map its symbols to the declared ones by name."""
    if not isinstance(value, sp.Expr):
        raise NumberError(where, f"{_show(value)} is not a number")
    mapping = {}
    for sym in value.free_symbols:
        if sym.name not in parameters:
            raise NumberError(where, f"{_show(value)} uses undeclared symbol {sym.name} "
                                     f"(declared parameters: {_declared(parameters)})")
        mapping[sym] = parameters[sym.name]
    return value.xreplace(mapping) if mapping else value


def _exact_polynomial(expr: sp.Expr, shown: str, parameters: Mapping[str, sp.Symbol],
                      where: str) -> sp.Expr:
    """Check that ``expr`` is a polynomial with rational coefficients; return it expanded."""
    if expr.is_Rational:
        return expr
    used = sorted(expr.free_symbols, key=lambda s: s.name)
    if not used:
        raise NumberError(where, f"{shown} is not an exact rational number")
    if not expr.is_polynomial(*used):
        cancelled = sp.cancel(expr)
        if not cancelled.is_polynomial(*used):
            raise NumberError(where, f"{shown} is not a polynomial in the parameters")
        expr = cancelled
    poly = sp.Poly(expr, *used)
    bad = [c for c in poly.coeffs() if not c.is_Rational]
    if bad:
        raise NumberError(where, f"{shown} has a coefficient that is not an exact "
                                 f"rational number ({bad[0]})")
    return poly.as_expr()


def parse_number(value: object, parameters: Mapping[str, sp.Symbol],
                 where: str) -> sp.Expr:
    """Read one exact number: a rational, or a polynomial in the parameters.

    Parameters
    ----------
    value : int, Fraction, str, SymPy number or expression, or float
        Text in SymPy syntax (``"3/5"``, ``"2*L"``, ``"0.1"`` is exactly 1/10).
        A Python float is read from its shortest decimal text (``0.1`` -> 1/10).
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
        or is not a polynomial in the parameters.

    Example
    -------
    >>> import sympy as sp
    >>> L = sp.Symbol("L", positive=True)
    >>> parse_number("L/2 + 1", {"L": L}, "point")
    L/2 + 1
    """
    if isinstance(value, bool):
        raise NumberError(where, f"{_show(value)} is a truth value, not a number")
    if isinstance(value, sp.Basic):
        expr = _from_sympy(value, parameters, where)
    elif isinstance(value, numbers.Integral):
        return sp.Integer(int(value))
    elif isinstance(value, numbers.Rational):
        return sp.Rational(int(value.numerator), int(value.denominator))
    elif isinstance(value, float | Decimal):
        finite = value.is_finite() if isinstance(value, Decimal) else math.isfinite(value)
        if not finite:
            raise NumberError(where, f"{_show(value)} is not a finite number")
        exact = Fraction(repr(value) if isinstance(value, float) else str(value))
        return sp.Rational(exact.numerator, exact.denominator)
    elif isinstance(value, str):
        expr = _parse_text(value, parameters, where)
    else:
        raise NumberError(where, f"{_show(value)} is not a number "
                                 f"(got {type(value).__name__})")
    return _exact_polynomial(expr, _show(value), parameters, where)


def _half_angle_tangent(q: sp.Expr) -> sp.Expr:
    """``tan(q/2)`` simplified exactly (``zoo`` when q is an odd multiple of pi)."""
    t = sp.tan(q / 2)
    if t.is_Rational or t is sp.zoo:
        return t
    t = sp.expand_trig(t)
    if t.is_Rational or t is sp.zoo:
        return t
    return sp.simplify(t)


def _nearest_angles(q: sp.Expr) -> list[str]:
    """A few exact angles near ``q`` (floats used only to suggest candidates)."""
    try:
        value = float(sp.N(q, 30))  # float-ok: only to suggest nearby exact angles
    except (TypeError, ValueError):
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
            tr = sp.Rational(approx.numerator, approx.denominator)
            cos, sin = (1 - tr**2) / (1 + tr**2), 2 * tr / (1 + tr**2)
        text = angle_text(cos, sin)
        angle = math.atan2(float(sin), float(cos))  # float-ok: shown to the user
        entry = f"{text} ({angle:.6f})"
        if entry not in out:
            out.append(entry)
    return out


def algebraic_half_angle(text: str, where: str) -> sp.Expr:
    """``tan(q/2)`` of an angle whose tangent half-angle is a real algebraic number
    (``-pi/6``: ``-2 + sqrt(3)``), exactly; rational ones are returned too.

    Raises
    ------
    NumberError
        If the text is not an angle, is ``pi`` (infinite tangent), or ``tan(q/2)`` is not
        algebraic (``q = 1``).

    Example
    -------
    >>> algebraic_half_angle("-pi/6", "q1")
    -2 + sqrt(3)
    """
    q = _parse_text(text, {}, where)
    if q.free_symbols or q.is_real is False:
        raise NumberError(where, f"{_show(text)} is not a real angle")
    t = _half_angle_tangent(q)
    if t is sp.zoo or t.has(sp.zoo, sp.oo, sp.nan):
        raise NumberError(where, f"{_show(text)}: tan(q/2) is infinite")
    try:
        sp.minimal_polynomial(t, sp.Symbol("t"))
    except (sp.polys.polyerrors.NotAlgebraic, NotImplementedError, ValueError,
            TypeError):
        raise NumberError(where, f"angle {_show(text)}: tan(q/2) = {t} is not an "
                                 "algebraic number") from None
    return sp.radsimp(t)


def parse_angle(text: object, where: str) -> tuple[sp.Rational, sp.Rational]:
    """Read an exact angle and return its exact ``(cos q, sin q)``.

    An angle is exact when ``tan(q/2)`` is rational (``0``, ``pi/2``, ``-pi/2``,
    ``2*atan(1/3)``, ``3*pi/2``) or when it is an odd multiple of ``pi``. Decided by
    exact SymPy evaluation, never by floats.

    Parameters
    ----------
    text : str (or an exact SymPy number)
        The angle in radians, SymPy syntax.
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
    """
    if isinstance(text, bool):
        raise NumberError(where, f"{_show(text)} is a truth value, not an angle")
    if isinstance(text, str):
        q = _parse_text(text, {}, where)
    elif isinstance(text, numbers.Rational | sp.Expr):
        q = sp.sympify(text)
        if q.free_symbols:
            raise NumberError(where, f"{_show(text)} is not a number")
    else:
        raise NumberError(where, f"{_show(text)} is not an angle (write it as text, "
                                 f"e.g. 'pi/2' or '2*atan(1/3)')")
    if q.is_real is False:
        raise NumberError(where, f"{_show(text)} is not a real angle")
    ratio = q / sp.pi
    if ratio.is_Integer:
        return (sp.Integer(-1), sp.Integer(0)) if ratio % 2 else (sp.Integer(1),
                                                                  sp.Integer(0))
    t = _half_angle_tangent(q)
    if t is sp.zoo:
        return sp.Integer(-1), sp.Integer(0)
    if not t.is_Rational:
        kind = "irrational" if t.is_rational is False else "not a rational number"
        message = (f"angle {_show(text)} is not exact: tan(q/2) = {t} is {kind}; "
                   f"exact angles have a rational tan(q/2)")
        near = _nearest_angles(q)
        if near:
            message += "; nearest exact angles: " + ", ".join(near)
        raise NumberError(where, message)
    return (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)


def angle_text(cos: object, sin: object) -> str:
    """The shortest exact SymPy text for the angle with rational ``(cos, sin)``.

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
    named = {(1, 0): "0", (0, 1): "pi/2", (0, -1): "-pi/2", (-1, 0): "pi"}
    if (c, s) in named:
        return named[(c, s)]
    return f"2*atan({s / (1 + c)})"


# --- polynomial equations (locus components) -----------------------------------------
_POLY_TOKEN = re.compile(r"\s*(?:(\d+)|([A-Za-z_][A-Za-z_0-9]*)|(\*\*|\^|[-+*/()]))")
_MAX_POLY_TEXT = 200_000   # characters in one equation
_MAX_NESTING = 100
_MAX_POLY_DEGREE = 10_000  # total degree of a power
_MAX_POLY_TERMS = 200_000  # terms a product or power may reach


def parse_polynomial(text: str, names: list[str] | tuple[str, ...],
                     where: str) -> dict[tuple[int, ...], Fraction]:
    """Read a polynomial with rational coefficients in the variables ``names``.

    The grammar is small and read by hand (integers, the given names, ``+ - * /``,
    ``**`` or ``^`` with an integer exponent, parentheses; division only by a nonzero
    constant), so no code runs and no other name is accepted.

    Returns
    -------
    dict
        Exponent tuples (in the order of ``names``) to nonzero ``Fraction`` coefficients.

    Raises
    ------
    NumberError
        On anything else, naming ``where``.

    Example
    -------
    >>> parse_polynomial("t_q1**2 + 4*t_q1 + 1/2", ["t_q1", "t_q2"], "eq")
    {(2, 0): Fraction(1, 1), (1, 0): Fraction(4, 1), (0, 0): Fraction(1, 2)}
    """
    import flint

    if not isinstance(text, str):
        raise NumberError(where, f"{_show(text)} is not a polynomial (text expected)")
    if len(text) > _MAX_POLY_TEXT:
        raise NumberError(where, f"{_show(text)} is too long ({len(text)} characters)")
    tokens: list[tuple[str, str]] = []
    pos, stripped = 0, text.rstrip()
    while pos < len(stripped):
        match = _POLY_TOKEN.match(stripped, pos)
        if match is None or match.end() == pos:
            raise NumberError(where, f"{_show(text)} cannot be parsed as a polynomial")
        number, name, op = match.groups()
        if name is not None and name not in names:
            raise NumberError(where, f"{_show(text)} uses unknown variable {name} "
                                     f"(known: {', '.join(names)})")
        tokens.append(("n", number) if number else ("v", name) if name else ("o", op))
        pos = match.end()
    ctx = flint.fmpq_mpoly_ctx.get(tuple(names) or ("_",), "lex")
    index = 0

    def peek() -> tuple[str, str] | None:
        return tokens[index] if index < len(tokens) else None

    def take() -> tuple[str, str]:
        nonlocal index
        if index >= len(tokens):
            raise NumberError(where, f"{_show(text)} ends too early")
        index += 1
        return tokens[index - 1]

    def expression(depth: int):
        if depth > _MAX_NESTING:
            raise NumberError(where, f"{_show(text)} is nested too deeply")
        acc = None
        sign = 1
        while peek() in (("o", "+"), ("o", "-")):
            sign = -sign if take()[1] == "-" else sign
        acc = sign * term(depth)
        while peek() in (("o", "+"), ("o", "-")):
            op = take()[1]
            value = term(depth)
            acc = acc + value if op == "+" else acc - value
        return acc

    def term(depth: int):
        acc = power(depth)
        while peek() in (("o", "*"), ("o", "/")):
            op = take()[1]
            if peek() in (("o", "+"), ("o", "-")):
                sign = -1 if take()[1] == "-" else 1
                value = sign * power(depth)
            else:
                value = power(depth)
            if op == "*":
                _check_product_size(acc, value, names, text, where)
                acc = acc * value
            else:
                if not value.is_constant() or value.is_zero():
                    raise NumberError(where, f"{_show(text)}: division by a nonconstant "
                                             f"or zero")
                acc = acc * (1 / value.leading_coefficient())
        return acc

    def power(depth: int):
        base = atom(depth)
        if peek() in (("o", "**"), ("o", "^")):
            take()
            kind, value = take()
            if kind != "n":
                raise NumberError(where, f"{_show(text)}: an exponent must be an integer "
                                         f"literal")
            e = int(value)
            if e > _MAX_EXPONENT:
                raise NumberError(where, f"{_show(text)} has an exponent that is too "
                                         f"large")
            if peek() in (("o", "**"), ("o", "^")):
                raise NumberError(where, f"{_show(text)}: chained powers are not accepted")
            degree = base.total_degree() * e if not base.is_zero() else 0
            _check_size(len(base) ** e if len(base) > 1 else 1, degree, names, text, where)
            return base ** e
        return base

    def atom(depth: int):
        kind, value = take()
        if kind == "n":
            return ctx.constant(int(value))
        if kind == "v":
            return ctx.gens()[list(names).index(value)]
        if value == "(":
            inner = expression(depth + 1)
            if take() != ("o", ")"):
                raise NumberError(where, f"{_show(text)}: unbalanced parentheses")
            return inner
        if value in ("+", "-"):
            inner = atom(depth)
            return -inner if value == "-" else inner
        raise NumberError(where, f"{_show(text)} cannot be parsed as a polynomial")

    if not tokens:
        raise NumberError(where, "empty text is not a polynomial")
    poly = expression(0)
    if index != len(tokens):
        raise NumberError(where, f"{_show(text)} cannot be parsed as a polynomial")
    out = {}
    for monom, c in poly.to_dict().items():
        key = tuple(int(e) for e in monom)[: len(names)]
        out[key] = Fraction(int(c.p), int(c.q))
    return out


def _check_size(terms_bound: int, degree: int, names, text: str, where: str) -> None:
    """Refuse a product or power whose result may exceed the size limits."""
    if degree > _MAX_POLY_DEGREE or min(terms_bound, math.comb(
            degree + len(names), len(names))) > _MAX_POLY_TERMS:
        raise NumberError(where, f"{_show(text)} expands to a polynomial that is too large")


def _check_product_size(a, b, names, text: str, where: str) -> None:
    if a.is_zero() or b.is_zero():
        return
    _check_size(len(a) * len(b), a.total_degree() + b.total_degree(), names, text, where)
