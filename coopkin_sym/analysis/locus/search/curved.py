"""Curved families: a candidate factor that is not linear in any variable, decided
modulo its polynomial (over its function field), and the search inside any family
with no rational parametrization (the minors of each block over its function field,
their common zeros with its polynomial solved like any set of codimension 2).
"""

from __future__ import annotations

from coopkin_sym.analysis.locus.algebra import (
    bounded_factor,
    has_real_point,
    normalize,
    rational_point,
    vars_of,
)
from coopkin_sym.analysis.locus.context import Place, SearchContext
from coopkin_sym.analysis.locus.remarks import Remark, add_once
from coopkin_sym.analysis.locus.search.components import (
    _new_component,
    beyond_chart,
    no_real_points,
    note,
    recorded_elsewhere,
)
from coopkin_sym.analysis.locus.search.hypersurface import candidates
from coopkin_sym.analysis.locus.search.modular import numbers_on
from coopkin_sym.analysis.locus.witness import (
    algebraic_witness_on,
    attach_witness,
    complete_point,
    numbers_at_values,
    to_at,
)
from coopkin_sym.errors import WorkLimitReached
from coopkin_sym.exact import deadline
from coopkin_sym.exact.quotient import Quotient, Tower
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
    ``f``), a witness on it (rational, else a real algebraic point), and the search
    inside it (:func:`inside_curved`)."""
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
    numbers = numbers_on(ctx, place.rows, Quotient(f, k), place.base)
    on_f = place.inside(equations=place.equations + [f_text])
    if numbers == place.base:
        if len([n for n in ctx.ring_names if n not in place.point]) > 1:
            ctx.steps.inside_candidate(ctx, on_f, family=(f, k))
        return
    comp = _new_component(ctx, place, place.equations + [f_text], numbers,
                          "hypersurface" if not beyond_chart(ctx, place.equations)
                          else "subvariety", drops,
                          Remark.of("decided_modulo_family"), real=real is True, within=place.point,
                          generic_point=(place.point, Quotient(f, k)), held_searched=True)
    if comp is None:
        # recorded in another chart: what lies inside it at the joints at pi here
        holder = recorded_elsewhere(ctx, place.equations + [f_text], numbers, place.point,
                                    Quotient(f, k))
        if holder is not None:
            ctx.steps.go_deeper(ctx, holder, on_f, family=(f, k), held=True)
        return
    point = rational_point(ctx, f, names)
    if point is not None:
        values = complete_point(ctx, place.point, point)
        if values is not None and numbers_at_values(ctx, values) == numbers:
            attach_witness(ctx, comp, to_at(ctx, values), numbers)
    if comp.witness is None:
        algebraic_witness_on(ctx, comp, f, k, place.point, numbers)
    ctx.steps.go_deeper(ctx, comp, on_f, family=(f, k))


def inside_curved(ctx: SearchContext, place: Place, f, k) -> None:
    """Drops inside a family ``f = 0`` (``f`` irreducible, linear in no variable; ``k``
    a variable it is curved in) with no rational parametrization, whose numbers are
    ``place.base``. ``place.rows`` are the rows of the set ``f`` was found in (they hold
    on ``f = 0``, outside the zeros of ``place.charts``). ``f`` and ``k`` may also be
    tuples: univariate polynomials in distinct variables whose roots generate linearly
    disjoint fields (the family is where all of them vanish, over their compositum).

    For each block whose rank drop changes a number (``H G^T``, ``H D`` of each arm,
    the left nullspace of each ``H D`` and the object rows it leaves) the rank over the
    function field of ``f`` is taken, and the set where it drops there is cut out by
    ``f`` and random combinations of the minors of that size, reduced modulo ``f``
    (Cauchy-Binet over ``Z[x]/(f)``); where a divisor taken out of a row vanishes on
    ``f = 0`` is a set of its own. Each is solved like any set of codimension 2 (its
    families decided over their own fields, the points exactly) and what has the
    numbers of ``f = 0`` is searched in turn, within the bounds of the search. Where
    two families meet, each is searched inside the other: their intersection is found
    as a drop set of one of them.

    A family larger than :data:`INSIDE_TERMS` (its polynomial, or an entry of its
    rows) is not searched, a search past its work budget :data:`INSIDE_STEPS` is
    cut (what it found by then is kept, and the searches it deferred still run),
    and points of degree above :data:`INSIDE_DEGREE` are not decided; the report
    says so each time."""
    moduli = family_moduli(f, k)
    names = ({n for row in place.rows for e in row if not e.is_constant()
              for n in vars_of(ctx, e)} | {n for g, _ in moduli for n in vars_of(ctx, g)})
    where = (dict(component=place.parent, equations=()) if place.parent is not None
             and place.depth > 0 and _is_component(ctx, place) else
             dict(component=None, equations=place.equations))
    if len(names) > 4:
        # the sets cut out there are solved in up to four variables only
        note(ctx, "too_many_variables", variables=len(names), **where)
        return
    if len(names) < 2:
        return   # points: nothing lies deeper inside them
    size = max(*(len(g) for g, _ in moduli), max(len(e) for row in place.rows for e in row))
    if size > INSIDE_TERMS:
        note(ctx, "inside_not_searched", limit="terms", size=size, bound=INSIDE_TERMS,
             **where)
        return
    levels = len(ctx.deferred)
    with deadline.work_limit(INSIDE_STEPS, INSIDE_OWNER) as bound:
        ctx.inside += 1
        try:
            _search_inside(ctx, place, moduli)
        except WorkLimitReached:
            if bound.budget[0] >= 0:
                raise   # an enclosing family's budget, used up here
            note(ctx, "inside_not_searched", limit="steps", size=None,
                 bound=INSIDE_STEPS, **where)
        except BaseException:
            del ctx.deferred[levels:]   # the whole search is ending
            raise
        finally:
            ctx.inside -= 1
    _keep_deferred(ctx, levels)


def _keep_deferred(ctx: SearchContext, levels: int) -> None:
    """The searches deferred by levels the cut search left open (``ctx.deferred``
    beyond ``levels``) go to the enclosing level, run now when there is none: a cut
    in one family drops no search of another."""
    orphans = [search for level in ctx.deferred[levels:] for search in level]
    del ctx.deferred[levels:]
    if ctx.deferred:
        ctx.deferred[-1].extend(orphans)
    else:
        for search in orphans:
            search()


#: The largest family searched inside: terms of its polynomial and of an entry of its
#: rows (the minors and resultants grow fast with them).
INSIDE_TERMS = 150
#: The work budget of the search inside one family, in steps of
#: :func:`~coopkin_sym.exact.deadline.check` (deterministic: the same cut on any
#: machine and under any load).
INSIDE_STEPS = 10**9
#: The highest degree over Q of a point decided inside such a family.
INSIDE_DEGREE = 8
#: The owner of the time bound of one such search (see :func:`.deadline.active`).
INSIDE_OWNER = "the search inside a family"
#: The order the blocks are searched in: those that change the most numbers first.
BLOCK_ORDER = ("HG^T", "HD", "A", "Y")


def family_moduli(f, k) -> list[tuple]:
    """The polynomials of a family ``(f, k)`` of :func:`inside_curved` with their
    variables: ``[(f, k)]``, or one pair per polynomial when they are tuples."""
    return list(zip(f, k, strict=True)) if isinstance(f, tuple) else [(f, k)]


def family_quotient(moduli) -> Quotient | Tower:
    """The quotient ranks are taken in on a family of :func:`family_moduli`."""
    if len(moduli) == 1:
        return Quotient(*moduli[0])
    return Tower([Quotient(g, k) for g, k in moduli])


def _search_inside(ctx: SearchContext, place: Place, moduli) -> None:
    """The drop sets of :func:`inside_curved`, block by block (:data:`BLOCK_ORDER`,
    the divisors taken out of the rows of every block before the minors)."""
    cands = candidates(ctx, place.rows, family_quotient(moduli))
    f = [g for g, _ in moduli]

    def order(name: str) -> tuple:
        block = name.split(":")[1] if name.startswith("content:") else name.split(":")[0]
        return (not name.startswith("content:"), BLOCK_ORDER.index(block), name)

    for name in sorted(cands, key=order):
        polys = cands[name]
        if name.startswith("content:"):
            systems = [s for g in polys if not g.is_constant()
                       for s in _split_system(ctx, f, [g])]
        else:
            systems = _split_system(ctx, f, polys) if polys else []
        if systems:
            ctx.steps.isolated(ctx, place, systems, INSIDE_DEGREE)


def _split_system(ctx: SearchContext, f: list, polys) -> list[list]:
    """``f = 0`` (the family's polynomials) and ``polys = 0`` as a union of smaller
    systems when ``polys`` are one polynomial ``g`` (up to constants): one system
    ``[*f, h]`` per factor ``h`` of ``g`` with real points (factors without are listed
    as dropped). A minor such as ``(1 + t_3^2)^2 (t_4^2 - 2 t_4 - 1)`` then gives a set
    in two variables (``f`` in ``t_2``, ``h`` in ``t_4``), not one in three. Otherwise
    ``[[*f, *polys]]``."""
    g = polys[0]
    if g.is_constant() or not all(_proportional(p, g) for p in polys[1:]):
        return [[*f, *polys]]
    factored = bounded_factor(ctx, g)
    if factored is None:
        return [[*f, *polys]]
    return [[*f, h] for h in (normalize(h) for h, _e in factored[1])
            if not no_real_points(ctx, h)]


def _proportional(p, g) -> bool:
    """Whether ``p`` is a constant multiple of ``g`` (``p lc(g) = g lc(p)``)."""
    return len(p) == len(g) and p * g.leading_coefficient() == g * p.leading_coefficient()


def _is_component(ctx: SearchContext, place: Place) -> bool:
    """Whether ``place`` is the inside of a recorded component (its equations are
    those of its parent)."""
    comp = ctx.locus.components[place.parent]
    return [e.text for e in comp.equations] == list(place.equations)
