"""Exact numbers, angles and expressions from text: the one parser of the package.

Every text that becomes a number or an expression (model files, ``--at``, ``--grid``,
arguments of the API, equations and witnesses of a report read back) passes through
:func:`parse_expression`, and comes out exact. The parser is the package's own: a
small recursive-descent reader of decimal numbers, declared names, ``pi``, degrees
(``deg`` is ``pi/180``: ``90deg`` and ``90*deg`` are ``pi/2`` exactly), the
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
>>> parse_angle("90deg", "q1") == parse_angle("pi/2", "q1")
True
>>> from fractions import Fraction
>>> tangent_text(Fraction(1, 3))
'2*atan(1/3)'
"""

from __future__ import annotations

from coopkin_sym.errors import NumberError
from coopkin_sym.exact.parse.angle_reader import (
    algebraic_half_angle,
    parse_angle,
    tangent_text,
)
from coopkin_sym.exact.parse.expressions import FUNCTIONS, parse_expression, parse_polynomial
from coopkin_sym.exact.parse.messages import brief
from coopkin_sym.exact.parse.values import exact_expr, parse_number

__all__ = ["FUNCTIONS", "NumberError", "algebraic_half_angle", "brief",
           "exact_expr", "parse_angle", "parse_expression", "parse_number",
           "parse_polynomial", "tangent_text"]
