"""Curved families: a candidate factor that is not linear in any variable, decided
modulo its polynomial (over its function field) and searched inside on the random
lines and points it holds.
"""

from __future__ import annotations

from coopkin_sym.analysis.locus.algebra import (
    has_real_point,
    rational_point,
    vars_of,
)
from coopkin_sym.analysis.locus.context import Place, SearchContext
from coopkin_sym.analysis.locus.remarks import Remark, add_once
from coopkin_sym.analysis.locus.search.components import (
    HIDDEN_DEPTH,
    _new_component,
    beyond_chart,
    note,
)
from coopkin_sym.analysis.locus.search.hypersurface import (
    arm_blocks,
    reduce_constant_pivots,
)
from coopkin_sym.analysis.locus.types import Component
from coopkin_sym.analysis.locus.witness import (
    algebraic_witness_on,
    attach_witness,
    complete_point,
    numbers_at_values,
    to_at,
)
from coopkin_sym.analysis.mobility import numbers_modulo
from coopkin_sym.analysis.numbers import Numbers
from coopkin_sym.exact.quotient import (
    Quotient,
)
from coopkin_sym.exact.substitution import split_linear, substitute_rows


def substitute_linear(ctx: SearchContext, q_rows, f, name: str):
    """Rows of Q on ``f = 0`` with ``name = -f0/f1`` (denominators cleared row by row)."""
    k = ctx.ring_names.index(name)
    f1, f0 = split_linear(f, k)
    return substitute_rows(q_rows, k, f0, f1), f0, f1


# the largest curved family whose numbers are decided modulo its polynomial
_MAX_CURVED_TERMS = 3000


def nonlinear_factor(ctx: SearchContext, place: Place, f, f_text, drops) -> None:
    """A factor linear in no variable: its numbers over its function field (rank modulo
    ``f``), a witness on it (rational, else a real algebraic point)."""
    names = vars_of(ctx, f)
    if len(f) > _MAX_CURVED_TERMS:
        note(ctx, "family_too_large", terms=len(f), degree=f.total_degree(),
             variables=names, equations=place.equations, bound=_MAX_CURVED_TERMS)
        return
    real = has_real_point(ctx, f, names)
    if real is False:
        add_once(ctx.locus.dropped, Remark.of("no_real_points", polynomial=f_text))
        return
    k = min((ctx.ring_names.index(n) for n in names if ctx.kinds[n][0] != "parameter"),
            key=lambda i: (f.degrees()[i], i))
    numbers = numbers_modulo(place.rows, ctx.model, ctx.row_contacts, Quotient(f, k))
    if numbers == place.base:
        if len([n for n in ctx.ring_names if n not in place.point]) <= 1:
            return
        on_f = place.inside(equations=place.equations + [f_text], charts=())
        if ctx.hidden >= HIDDEN_DEPTH or place.depth > 0 or ctx.expired():
            ctx.steps.inside_candidate(ctx, on_f.inside(rows=None, point=None))
        else:   # after the components of the enclosing level, like other candidates
            ctx.steps.after_enclosing(ctx, lambda: inside_curved(ctx, on_f, f, k, None))
        return
    comp = _new_component(ctx, place, place.equations + [f_text], numbers,
                          "hypersurface" if not beyond_chart(ctx, place.equations)
                          else "subvariety", drops,
                          Remark.of("decided_modulo_family"), real=real is True, within=place.point,
                          generic_point=(place.point, Quotient(f, k)))
    if comp is None:
        return
    point = rational_point(ctx, f, names)
    if point is not None:
        values = complete_point(ctx, place.point, point)
        if values is not None and numbers_at_values(ctx, values) == numbers:
            attach_witness(ctx, comp, to_at(ctx, values), numbers)
    if comp.witness is None:
        algebraic_witness_on(ctx, comp, f, k, place.point, numbers)
    if place.depth > 0 or place.depth >= ctx.max_depth or ctx.expired():
        ctx.steps.go_deeper(ctx, comp, place.inside(rows=None, point=None, charts=()),
                            "no_parametrization")
    else:
        inside_curved(ctx, place.inside(equations=place.equations + [f_text], charts=()),
                      f, k, comp)


def inside_curved(ctx: SearchContext, place: Place, f, k: int,
                  comp: Component | None) -> None:
    """Drops inside a family ``f = 0`` of the first level (depth 0) with no rational
    parametrization, where a divisor of the rows vanishes: each block (``H G^T``, and
    ``H D`` of each arm) is reduced modulo ``f`` (a row divisible by ``f`` is zero
    there), its pivots positive everywhere eliminated, and the zero set on ``f = 0`` of
    each divisor taken out of a row is solved like any set of codimension 2. Drops cut
    out there by minors alone are not searched, and the report says so. With ``comp``
    None, ``f = 0`` is a candidate with the enclosing numbers (``place.base``, in
    ``place.parent``), searched one such level deep."""
    names = ({n for row in place.rows for e in row if not e.is_constant()
              for n in vars_of(ctx, e)} | set(vars_of(ctx, f)))
    if comp is not None:
        index = ctx.locus.components.index(comp)
        where = dict(component=index, equations=())
        place = place.inside(base=Numbers(**comp.numbers), depth=place.depth + 1,
                             parent=index)
    else:
        where = dict(component=None, equations=place.equations)
    if len(names) > 4:
        # the sets cut out there are solved in up to four variables only
        note(ctx, "too_many_variables", variables=len(names), **where)
        return
    quotient = Quotient(f, k)
    dim = ctx.model.object_dim
    blocks = [[row[:dim] for row in place.rows]] + [
        d for _, _, d in arm_blocks(ctx, place.rows)]
    divisors: list = []
    for rows in blocks:
        rows = [quotient.reduce_row(r) for r in rows]
        contents: list = []
        reduce_constant_pivots([r for r in rows if any(not e.is_zero() for e in r)],
                               contents)
        divisors += [g for g in contents if not g.is_constant() and not quotient.is_zero(g)
                     and g not in divisors]
    note(ctx, "divisors_only", **where)
    if not divisors:
        return
    ctx.hidden += comp is None
    try:
        ctx.steps.isolated(ctx, place, [[f, g] for g in divisors])
    finally:
        ctx.hidden -= comp is None
