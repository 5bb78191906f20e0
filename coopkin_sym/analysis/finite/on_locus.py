"""The finite mobility at the witnesses of a locus: which singular families are
bifurcations, which are shaky, and which only change the first-order numbers; and,
where cheap, along the whole component.

Each component with an exact rational witness gets, as plain data in
:attr:`~coopkin_sym.analysis.locus.types.Component.finite`, the finite mobility there
(:func:`~coopkin_sym.analysis.finite.finite_mobility`): its dimension (None when
undecided), the bounds proved, the first-order motions, the classification, how it was
decided, the order of the expansion and the dimensions of the branches. A component
with only an algebraic witness gets it there, over the number field of the witness
(:mod:`coopkin_sym.analysis.finite.algebraic`), with that field under ``"field"``; a
component with no witness keeps None.

Along the component (``"along"``, where cheap, said as what it is):

* ``"constant_rank"``, a proof: when the witness was decided by the rank of ``Q``
  alone (independent constraints, or the generic rank with hard and complete
  contacts) and its seven numbers are the component's, the same holds at every point
  of the component where its numbers hold (the rank of ``Q`` is the same there), so
  the finite mobility and its classification are those of the witness there;
* ``"second_point"``, evidence only: otherwise, when the component's equations solve
  one variable at a time for a variable they hold linearly with a constant
  coefficient (a rational parametrization), the finite mobility at a second rational
  point of it with the component's numbers.

Example
-------
>>> from coopkin_sym import load
>>> system = load("four-bar")
>>> locus = system.locus()
>>> finite_at_witnesses(locus, system.model)
4
>>> [c.finite["classification"] for c in locus.components]
['bifurcation', 'shaky', 'shaky', 'bifurcation']
"""

from __future__ import annotations

from fractions import Fraction
from itertools import product

import sympy as sp

from coopkin_sym.analysis.finite import FiniteMobility, finite_mobility
from coopkin_sym.analysis.finite.constraints import check_holonomic
from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.errors import CoopkinError
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.model.configuration import Configuration, Point
from coopkin_sym.model.model import Model

#: Values tried for the free variables of a second point (small, varied).
_VALUES = (Fraction(1, 2), Fraction(-1, 3), Fraction(2), Fraction(1, 3), Fraction(-2),
           Fraction(3, 2))


def finite_data(fm: FiniteMobility) -> dict:
    """The plain data a component keeps of a finite mobility.

    Example
    -------
    >>> from coopkin_sym import load
    >>> finite_data(load("shaky-pinned-bars").finite_mobility())["classification"]
    'shaky'
    """
    out = {"dimension": fm.dimension, "bounds": list(fm.bounds),
           "first_order": fm.first_order, "classification": fm.classification,
           "reason": fm.reason, "order": fm.order,
           "branches": [b.dimension for b in fm.branches],
           "assumptions": list(fm.assumptions)}
    if fm.field is not None:
        out["field"] = dict(fm.field)
    return out


def finite_at_witnesses(locus: Locus, model: Model, order: int | None = None) -> int:
    """The finite mobility at every witness of ``locus`` (a locus of ``model``):
    rational ones, and algebraic ones where a component has no rational witness; kept
    in each component's ``finite``; how many were computed. Raises
    :class:`~coopkin_sym.errors.FiniteMobilityError` for a contact that is not
    holonomic, before computing any."""
    check_holonomic(model)                       # refuses soft contacts at once
    done = 0
    for component in locus.components:
        point = component.witness
        if not isinstance(point, Configuration):
            point = (component.algebraic_witness or {}).get("point")
            if not point:
                continue
            try:
                found = finite_mobility(model, dict(point), order)
            except CoopkinError:
                # a witness whose values this expansion cannot take (an angle in a
                # root of a quintic, a field over the degree limit): not computed
                continue
            component.finite = finite_data(found)
            done += 1
            continue
        found = finite_mobility(model, point, order)
        component.finite = finite_data(found)
        along = along_component(component, model, found, order)
        if along is not None:
            component.finite["along"] = along
        done += 1
    return done


def along_component(component: Component, model: Model, found: FiniteMobility,
                    order: int | None = None) -> dict | None:
    """The finite mobility along ``component`` beyond its rational witness (``found``
    there), where cheap (see the module's text), as plain data, or None.

    Example
    -------
    >>> from coopkin_sym import load
    >>> system = load("parallel-cranks")
    >>> locus = system.locus()
    >>> (motion,) = [c for c in locus.components
    ...              if [e.text for e in c.equations] == ["t_q1 - t_q2", "t_q2 - t_q3"]]
    >>> along = along_component(motion, system.model, system.finite_mobility(motion.witness))
    >>> along["how"], along["point"]["q1"], along["point"]["q3"], along["dimension"]
    ('second_point', '2*atan(-1/3)', '2*atan(-1/3)', 1)
    """
    if found.reason in ("submersion", "constant_rank"):
        if not component.witness_checked:
            return None
        return {"how": "constant_rank", "dimension": found.dimension,
                "classification": found.classification}
    point = second_point(component, model)
    if point is None:
        return None
    from coopkin_sym.analysis.mobility import analyze

    numbers = component.numbers
    numbers = numbers.as_dict() if hasattr(numbers, "as_dict") else dict(numbers)
    if analyze(model, point).numbers.as_dict() != numbers:
        return None
    there = finite_mobility(model, point, order)
    return {"how": "second_point", "point": dict(point), "dimension": there.dimension,
            "bounds": list(there.bounds), "classification": there.classification,
            "reason": there.reason}


def _solved(equations: list[sp.Expr]) -> dict | None:
    """The equations solved one variable at a time, each for a variable it holds
    linearly with a constant coefficient: variable -> expression in the others; None
    when that is not possible."""
    solved: dict = {}
    pending = list(equations)
    while pending:
        rest = []
        for e in pending:
            e = sp.expand(e.subs(solved))
            if e == 0:
                continue
            for x in sorted(e.free_symbols, key=lambda v: v.name):
                poly = sp.Poly(e, x)
                lead = poly.coeff_monomial(x)
                if poly.degree() == 1 and lead.is_number and lead != 0:
                    value = -poly.coeff_monomial(1) / lead
                    solved = {k: sp.expand(v.subs(x, value)) for k, v in solved.items()}
                    solved[x] = value
                    break
            else:
                rest.append(e)
        if len(rest) == len(pending):
            return None
        pending = rest
    return solved


def _moved(point: Point, name: str, value: Fraction) -> Point:
    """``point`` with the variable ``name`` (``t_<joint>``, ``s_<joint>``, a prismatic
    joint) at ``value``."""
    if name.startswith("t_"):
        return point.moved(name[2:], ExactAngle.from_tangent(value))
    if name.startswith("s_"):
        return point.moved(name[2:], ExactAngle.from_tangent(None if value == 0 else
                                                             1 / value))
    return point.moved(name, sp.Rational(value.numerator, value.denominator))


def second_point(component: Component, model: Model) -> Point | None:
    """A rational point of ``component`` other than its witness, where its equations
    solve one variable at a time (see :func:`_solved`), the free variables at small
    values; None otherwise (or for a point: no free variable)."""
    witness = component.witness
    params = {p.name: sp.Rational(witness.parameters[p.name]) for p in model.parameters
              if p.name in witness.parameters}
    equations = [e.to_sympy().subs({sp.Symbol(k): v for k, v in params.items()})
                 for e in component.equations]
    solved = _solved(equations)
    if solved is None:
        return None
    used = {v for e in equations for v in e.free_symbols}
    joints = {sp.Symbol(f"s_{j.name}") if sp.Symbol(f"s_{j.name}") in used else
              sp.Symbol(f"t_{j.name}" if j.type == "revolute" else j.name)
              for j in model.joints}
    if not used <= joints | set(solved):
        return None
    names = sorted(joints - set(solved), key=lambda v: v.name)
    if not names:
        return None
    outside = [e.to_sympy().subs({sp.Symbol(k): v for k, v in params.items()})
               for e in component.outside]
    for values in product(_VALUES, repeat=len(names)):
        free = dict(zip(names, (sp.Rational(v.numerator, v.denominator) for v in values),
                        strict=True))
        full = {**free, **{x: e.subs(free) for x, e in solved.items()}}
        if any(e.subs(full) != 0 for e in equations) or \
                any(e.subs(full) == 0 for e in outside):
            continue
        point = witness
        for x, v in full.items():
            point = _moved(point, x.name, Fraction(int(v.p), int(v.q)))
        if point != witness:
            return point
    return None
