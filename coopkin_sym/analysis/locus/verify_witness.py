"""The witnesses of a locus verification: each component's witness (rational, or
algebraic over a number field) read, placed on the component and analysed exactly.
"""

from __future__ import annotations

from collections.abc import Mapping
from fractions import Fraction

import flint
import sympy as sp
from sympy.polys.numberfields.subfield import primitive_element

from coopkin_sym.analysis.locus.verify_checker import _Checker, _on_curve, _State
from coopkin_sym.analysis.locus.verify_exact import _fmpq, _frac, _Line
from coopkin_sym.analysis.locus.verify_lines import _line_ranks, _line_rows, _to_mpoly
from coopkin_sym.analysis.mobility import analyze
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.parse import (
    NumberError,
    algebraic_half_angle,
    parse_expression,
    parse_number,
)
from coopkin_sym.exact.quotient import Quotient
from coopkin_sym.model.configuration import (
    Configuration,
    ConfigurationError,
)


def _check_witnesses(checker: _Checker, state: _State) -> None:
    for i, comp in enumerate(checker.locus.components):
        witness = comp.witness
        if not witness and comp.algebraic_witness:
            witness = comp.algebraic_witness.get("point")
        if not witness:
            continue
        try:
            point, curve, modulus = _read_witness(checker, witness)
        except _Unreadable as exc:
            state.result.unread_witnesses[i] = str(exc)
            continue
        except _Conflict as exc:
            state.issue(i, "witness-off", {str(k): str(x) for k, x in witness.items()},
                        None, str(exc))
            continue
        state.witnessed.add(i)
        if point is not None:
            at = checker.at_text(point)
            numbers = analyze(checker.model, Configuration.parse(checker.model, at)) \
                .numbers.as_dict()
            inside = checker.contains(i, point)
        else:
            at = {**dict(checker.fixed_items), **{str(k): str(x) for k, x in witness.items()}}
            rows = [[_to_mpoly(p) for p in row] for row in _line_rows(checker, curve)]
            modulus_z = _to_mpoly(modulus * int(modulus.denom()))
            numbers = checker.numbers(_line_ranks(rows, Quotient(modulus_z, 0), checker.r,
                                                  checker.dim))
            inside = _on_curve(checker, i, curve, modulus)
        if not inside:
            state.issue(i, "witness-off", at, numbers)
        if numbers != checker.claims[i]:
            state.issue(i, "witness-numbers", at, numbers)


class _Unreadable(Exception):
    """A witness this check cannot read (a ``CRootOf`` value, say)."""


class _Conflict(Exception):
    """A witness that contradicts the locus's fixed values."""


def _read_witness(checker: _Checker, witness: Mapping):
    """``(point, None, None)`` for a rational witness; ``(None, curve, g)`` for one with
    irrational algebraic values: every free variable a polynomial in ``alpha``, a
    primitive element of their field with minimal polynomial ``g``."""

    model = checker.model
    fixed = dict(checker.fixed_items)
    given = {str(k): str(x) for k, x in witness.items()}
    free_names = {v.source for v in checker.free}
    for k, x in given.items():
        if k in free_names:
            continue
        if k not in fixed:
            raise _Unreadable(f"{k} is neither free nor fixed in the locus")
        try:
            same = (Configuration.parse(model, {k: x}) == Configuration.parse(model, {k: fixed[k]}))
        except ConfigurationError as exc:
            raise _Unreadable(str(exc)) from None
        if not same:
            raise _Conflict(f"the witness sets {k}={x}, the locus fixes {k}={fixed[k]}")
    symbols = {p.name: p for p in model.parameters}
    values: list = []
    irrational: dict[int, sp.Expr] = {}
    for i, v in enumerate(checker.free):
        text = given.get(v.source)
        where = f"witness {v.source}"
        if text is None:
            if v.kind == "parameter":
                raise _Unreadable(f"no value for {v.source}")
            values.append(Fraction(0))
            continue
        try:
            if v.kind == "revolute":
                try:
                    values.append(ExactAngle.parse(text, where).tangent)
                except NumberError:
                    irrational[i] = algebraic_half_angle(text, where)
                    values.append(None)
                continue
            try:
                x = parse_number(text, symbols, where)
                x = x.subs({symbols[n]: sp.Rational(given.get(n, fixed.get(n, "0")))
                            for n in map(str, x.free_symbols) if n in symbols})
            except NumberError:
                x = parse_expression(text, {}, where)
                sp.minimal_polynomial(x, sp.Symbol("t"))
            if x.free_symbols or x.is_real is False:
                raise _Unreadable(f"{where}: {text} is not a real number")
            if x.is_Rational:
                values.append(_frac(x))
            else:
                irrational[i] = sp.radsimp(x)
                values.append(None)
        except (NumberError, ValueError, TypeError, NotImplementedError,
                sp.polys.polyerrors.NotAlgebraic) as exc:
            raise _Unreadable(str(exc)) from None
    if not irrational:
        return values, None, None
    alpha = sp.Symbol("alpha")
    order = list(irrational)
    minimal, _, reps = primitive_element([irrational[i] for i in order], alpha, ex=True)
    g = flint.fmpq_poly([_fmpq(c) for c in reversed(sp.Poly(minimal, alpha).all_coeffs())])
    rep = {i: flint.fmpq_poly([_fmpq(c) for c in reversed(list(r))])
           for i, r in zip(order, reps, strict=True)}
    coords = []
    for i, (v, x) in enumerate(zip(checker.free, values, strict=True)):
        chart = "t" if v.kind == "revolute" else "x"
        if i in rep:
            coords.append((chart, rep[i]))
        elif v.kind == "revolute" and x is None:
            coords.append(("s", flint.fmpq_poly([0])))
        else:
            coords.append((chart, flint.fmpq_poly([_fmpq(x)])))
    return None, _Line(coords, (None, None)), g
