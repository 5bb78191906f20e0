"""Conditions read in angles first: in each alternative of a
:class:`~coopkin_sym.analysis.locus.conditions.Condition`, a polynomial clause that
its values and relations already imply is left out, one that fixes one more joint
(linear in it, once the others are put in) becomes that joint's value, and a lone
quadratic in one angle becomes the alternatives of its real roots.

Every step is exact: a clause is left out only when putting the values in gives 0
exactly (SymPy's exact arithmetic of radicals; a value it cannot reduce keeps its
clause), and the values are the exact roots. The set the condition describes stays
the same; only the way it is written changes.

Example
-------
>>> import sympy as sp
>>> from coopkin_sym.analysis.locus.conditions import Condition, Related, Value, Vanishes
>>> from coopkin_sym.exact.polynomial import NamedPolynomial
>>> names = ["t_q1", "t_q4"]
>>> p = NamedPolynomial.parse("t_q4**2 + 2*t_q4 - 1", names, "p")
>>> c = Condition.of(Vanishes(p), Related("q1", "q4", -1),
...                  Value("q4", sp.pi / 4, "revolute"))
>>> variables = {"t_q1": ("revolute", "q1"), "t_q4": ("revolute", "q4")}
>>> without_implied(c, variables).text
'q1 = -q4, q4 = pi/4'
>>> without_implied(Condition.of(Vanishes(p)), variables).text
'q4 = -3*pi/4 or q4 = pi/4'
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy as sp

from coopkin_sym.analysis.locus.algebra import angle_value
from coopkin_sym.analysis.locus.conditions import Clause, Condition, Related, Value, Vanishes

__all__ = ["without_implied"]

#: Values longer than this (SymPy operations) are not put into clauses: a clause they
#: would leave out stays (reducing them could take long).
MAX_VALUE_SIZE = 60
#: A value written in place of a polynomial clause is at most this long as text
#: (``2*atan(2 + sqrt(5))``, ``3*pi/4``); a longer one (a radical with large numbers)
#: reads worse than the polynomial, which then stays.
MAX_VALUE_TEXT = 32


def without_implied(condition: Condition, variables: Mapping[str, tuple[str, str]]
                    ) -> Condition:
    """``condition`` written more simply (the same set of points): see the module.
    ``variables`` maps each polynomial variable to ``(kind, joint or parameter)``
    (``"t_q1": ("revolute", "q1")``, the variable of a revolute joint being
    ``tan(q/2)``).

    Example
    -------
    >>> from coopkin_sym.analysis.locus.conditions import Value
    >>> c = Condition.of(Value("d4", sp.Rational(1, 2), "prismatic"))
    >>> without_implied(c, {}) == c
    True
    """
    if not any(isinstance(c, Vanishes) for c in condition.clauses()):
        return condition
    alternatives = []
    for alt in condition.alternatives:
        alternatives.extend(_alternative(alt, variables))
    return Condition(tuple(alternatives)) if alternatives else condition


def _alternative(clauses: tuple[Clause, ...], variables: Mapping[str, tuple[str, str]]
                 ) -> list[tuple[Clause, ...]]:
    """One alternative written more simply: one or more alternatives (several when a
    lone quadratic is split into its roots)."""
    clauses = list(clauses)
    changed = True
    while changed:
        changed = False
        values = _known_values(clauses)
        for k, clause in enumerate(clauses):
            if not isinstance(clause, Vanishes):
                continue
            reduced = _put_in(clause, values, variables)
            if reduced is None:
                continue
            if reduced == 0:
                del clauses[k]
                changed = True
                break
            fixed = _fixed_by(reduced, variables, values)
            if fixed is not None:
                clauses[k] = fixed
                changed = True
                break
    split = _split_quadratic(tuple(clauses), variables)
    if len(split) == 1:
        return split
    return [out for alt in split for out in _alternative(alt, variables)]


def _known_values(clauses: list[Clause]) -> dict[str, sp.Expr]:
    """The joints and parameters an alternative fixes: its values, and through its
    relations the values of the joints related to one with a value."""
    values = {c.name: c.value for c in clauses if isinstance(c, Value)}
    related = [c for c in clauses if isinstance(c, Related)]
    grown = True
    while grown:
        grown = False
        for r in related:
            shift = sp.pi if r.plus_pi else sp.Integer(0)
            if r.right in values and r.left not in values:
                values[r.left] = r.sign * values[r.right] + shift
                grown = True
            elif r.left in values and r.right not in values:
                values[r.right] = r.sign * (values[r.left] - shift)
                grown = True
    return values


def _variable_value(kind: str, value: sp.Expr) -> sp.Expr | None:
    """The value of a polynomial variable: ``tan(q/2)`` for a revolute joint, the
    value itself otherwise; None where it is not put in: infinite (``q = pi``), a root
    of a polynomial of degree above 4 (``CRootOf``: its clauses would not reduce, at
    length) or too large."""
    half = sp.tan(value / 2) if kind == "revolute" else value
    if half.has(sp.zoo, sp.oo, sp.nan, sp.CRootOf) or sp.count_ops(half) > MAX_VALUE_SIZE:
        return None
    return half


def _put_in(clause: Vanishes, values: Mapping[str, sp.Expr],
            variables: Mapping[str, tuple[str, str]]) -> sp.Expr | None:
    """The clause's polynomial with the known values put in, expanded; None when no
    value is put in (nothing to reduce) or a value is too large to put in."""
    p = clause.polynomial
    at = {}
    for v in p.variables:
        kind, name = variables.get(v, ("", ""))
        if name in values:
            value = _variable_value(kind, values[name])
            if value is None:
                return None
            at[sp.Symbol(v)] = value
    if not at:
        return None
    return _exactly_reduced(p.to_sympy().xreplace(at))


def _exactly_reduced(e: sp.Expr) -> sp.Expr:
    """``e`` expanded, with its radicals taken out of denominators: 0 exactly when it
    reduces to 0 (a number it cannot reduce stays as it is, never wrongly 0)."""
    e = sp.expand(e)
    if e != 0 and e.is_number and not e.has(sp.CRootOf):
        e = sp.expand(sp.radsimp(e))
    return e


def _fixed_by(reduced: sp.Expr, variables: Mapping[str, tuple[str, str]],
              values: Mapping[str, sp.Expr]) -> Value | None:
    """The value of the one joint or parameter ``reduced = 0`` fixes, when it is
    linear in one variable (and that variable's joint has no value yet)."""
    free = reduced.free_symbols
    if len(free) != 1:
        return None
    (symbol,) = free
    kind, name = variables.get(symbol.name, ("", ""))
    if not name or name in values:
        return None
    by_power: dict = {}
    for term in sp.Add.make_args(reduced):
        coefficient, power = term.as_coeff_exponent(symbol)
        by_power[power] = by_power.get(power, 0) + coefficient
    slope = _exactly_reduced(by_power.get(1, 0))
    if set(by_power) - {0, 1} or slope == 0:
        return None
    root = _exactly_reduced(-by_power.get(0, 0) / slope)
    if not root.is_real or sp.count_ops(root) > MAX_VALUE_SIZE:
        return None
    angle = angle_value(root) if root.is_Rational else 2 * sp.atan(root)
    value = Value(name, angle if kind == "revolute" else root, kind)
    return value if _short(value) else None


def _short(value: Value) -> bool:
    return len(value.value_text) <= MAX_VALUE_TEXT


def _split_quadratic(clauses: tuple[Clause, ...], variables: Mapping[str, tuple[str, str]]
                     ) -> list[tuple[Clause, ...]]:
    """``clauses``, or, when one of them is a quadratic in one angle without a value
    with two real roots, one alternative per root (its value in place of the
    clause)."""
    values = _known_values(list(clauses))
    for k, clause in enumerate(clauses):
        if not isinstance(clause, Vanishes) or len(clause.polynomial.variables) != 1:
            continue
        (v,) = clause.polynomial.variables
        kind, name = variables.get(v, ("", ""))
        if kind != "revolute" or name in values:
            continue
        poly = sp.Poly(clause.polynomial.to_sympy(), sp.Symbol(v))
        if poly.degree() != 2 or sp.discriminant(poly) <= 0:
            continue
        values = [Value(name, 2 * sp.atan(r), kind) for r in poly.real_roots()]
        if not all(_short(v) for v in values):
            continue
        return [clauses[:k] + (v,) + clauses[k + 1:] for v in values]
    return [clauses]
