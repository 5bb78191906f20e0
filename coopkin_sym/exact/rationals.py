"""One place for converting exact rationals between the libraries the package uses.

The package meets four rational types: Python's :class:`fractions.Fraction` (plain
arithmetic, homogeneous coordinates), SymPy's ``Rational`` (expressions shown to
people), python-flint's ``fmpq`` and ``fmpz`` (polynomial coefficients), and ``int``.
Each function here takes any of them and returns its own type, exactly; none goes
through a float.

Example
-------
>>> import flint
>>> to_sympy(Fraction(-3, 4)), to_fraction(flint.fmpq(5, 6)), to_fmpq(sp.Rational(1, 3))
(-3/4, Fraction(5, 6), 1/3)
"""

from __future__ import annotations

from fractions import Fraction

import flint
import sympy as sp

from coopkin_sym.errors import ArgumentTypeError

__all__ = ["to_fmpq", "to_fraction", "to_sympy"]


def _parts(x) -> tuple[int, int]:
    """Numerator and denominator of an exact rational of any of the types the package
    meets (int, Fraction, flint, SymPy, and SymPy's pure-Python QQ elements)."""
    if isinstance(x, bool):
        raise ArgumentTypeError("a boolean is not a rational")
    if isinstance(x, int):
        return x, 1
    if isinstance(x, Fraction):
        return x.numerator, x.denominator
    if isinstance(x, flint.fmpz):
        return int(x), 1
    if isinstance(x, flint.fmpq):
        return int(x.p), int(x.q)
    if isinstance(x, sp.Basic) and x.is_Rational:
        return int(x.p), int(x.q)
    if type(x).__name__ == "PythonMPQ":   # SymPy's QQ under pure-Python ground types
        return int(x.numerator), int(x.denominator)
    raise ArgumentTypeError(f"not an exact rational: {x!r}")


def to_sympy(x) -> sp.Rational:
    """``x`` as a SymPy ``Rational``.

    Example
    -------
    >>> to_sympy(Fraction(6, 4))
    3/2
    """
    return sp.Rational(*_parts(x))


def to_fraction(x) -> Fraction:
    """``x`` as a :class:`fractions.Fraction`.

    Example
    -------
    >>> to_fraction(sp.Rational(-2, 6))
    Fraction(-1, 3)
    """
    return Fraction(*_parts(x))


def to_fmpq(x) -> flint.fmpq:
    """``x`` as a python-flint ``fmpq``.

    Example
    -------
    >>> to_fmpq(Fraction(2, 4))
    1/2
    """
    return flint.fmpq(*_parts(x))
