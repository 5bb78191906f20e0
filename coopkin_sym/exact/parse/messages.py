"""How the parser shows what it read: the user's text quoted and shortened, never
the repr of a large object (one short line per error message)."""

from __future__ import annotations

import math
from collections.abc import Iterable
from fractions import Fraction

import sympy as sp

from coopkin_sym import limits


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


