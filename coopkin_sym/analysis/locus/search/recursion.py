"""The recursion of the search: explore a place (its candidates, then each factor),
decide a factor, and go deeper inside a component. :data:`STEPS` hands these steps
to the seams below that call back into them (through ``ctx.steps``).
"""

from __future__ import annotations

from coopkin_sym.analysis.decomposition import attains
from coopkin_sym.analysis.locus.algebra import (
    bounded_factor,
    bounded_gcd,
    normalize,
    poly_text,
    vars_of,
)
from coopkin_sym.analysis.locus.context import Place, SearchContext
from coopkin_sym.analysis.locus.remarks import Remark, add_once
from coopkin_sym.analysis.locus.search.codimension import isolated, where_parametrization_fails
from coopkin_sym.analysis.locus.search.components import (
    HIDDEN_DEPTH,
    Steps,
    _new_component,
    note,
    recorded_elsewhere,
    step_name,
    wider_component,
)
from coopkin_sym.analysis.locus.search.curved import (
    inside_curved,
    nonlinear_factor,
    substitute_linear,
)
from coopkin_sym.analysis.locus.search.hypersurface import MAX_SPLITS, candidates
from coopkin_sym.analysis.locus.types import Component
from coopkin_sym.analysis.locus.witness import (
    witness_linear,
)
from coopkin_sym.analysis.mobility import decompose
from coopkin_sym.analysis.numbers import Numbers
from coopkin_sym.errors import WorkLimitReached
from coopkin_sym.exact import deadline
from coopkin_sym.exact.substitution import substitute


# --- exploring --------------------------------------------------------------------------
def explore(ctx: SearchContext, place: Place) -> None:
    """Find the components inside the current (parametrized) set and decide them.

    ``place.point`` maps each parametrized variable to ``(f0, f1)`` (it equals
    ``-f0/f1``); ``place.charts`` are the denominators ``f1``, in the current variables:
    the rows are valid only where none of them vanishes."""
    if ctx.expired():
        ctx.locus.unexplored.append(Remark.of("time_depth", depth=place.depth,
                                              equations=place.equations))
        return
    # the enclosing numbers bound the ranks here: reaching them at a point proves them
    if place.base is None or not attains(place.rows, ctx.model, place.base):
        place = place.inside(base=decompose(place.rows, ctx.model, ctx.row_contacts,
                                            ctx.ring.zctx).numbers)
    ctx.deferred.append([])
    cands = candidates(ctx, place.rows)
    factors: dict[str, tuple] = {}
    splitting: set[str] = set()  # factors of single minors (see splitting_minor)
    rests: list[list] = []
    def add_factors(g, matrix: str, split: bool = False) -> None:
        factored = bounded_factor(ctx, g)
        if factored is None:
            return                # not searched, and the report says why
        for f, _e in factored[1]:
            f = normalize(f)
            key = str(f)
            drops = factors.get(key, (f, set()))[1]
            drops.add(matrix)
            factors[key] = (f, drops)
            if split:
                splitting.add(key)

    for name, polys in cands.items():
        if name.startswith(("content:", "split:")):
            for c in polys:
                add_factors(c, name.split(":")[1], name.startswith("split:"))
            continue
        g = polys[0]
        for p in sorted(polys[1:], key=len):
            g = bounded_gcd(ctx, g, p)
            if g is None:
                break
        if g is None:
            continue              # this block's drops not searched, said in the report
        if not g.is_constant():
            add_factors(g, name.split(":")[0])
        rest = [p / g for p in polys] if not g.is_constant() else polys
        if f"split:{name}" in cands and len({n for p in rest for n in vars_of(ctx, p)}) > 4:
            continue  # inside the factors of its splitting minor, searched one by one
        if len(rest) > 1 or (rest and not rest[0].is_constant()):
            rests.append(rest)
    ordered = sorted(factors.values(), key=lambda fd: (fd[0].total_degree(), len(fd[0]),
                                                       str(fd[0])))
    # one part of the progress per factor, one for the isolated points and the
    # searches deferred to the end of this level
    with ctx.reporter.parts(len(ordered) + 1):
        for f, drops in ordered:
            ctx.reporter.step(f"{step_name(ctx)}depth {place.depth}: {f}")
            if ctx.expired():
                ctx.locus.unexplored.append(Remark.of("time_component", polynomial=str(f),
                                                      depth=place.depth))
                continue
            if any(not c.gcd(f).is_constant() for c in place.charts):
                # the image of f = 0 lies where a parametrization's denominator
                # vanishes: those points are searched from the enclosing variables
                # (where_parametrization_fails)
                continue
            split = str(f) in splitting
            _decide_factor(ctx, place, f, drops, split=split)
        ctx.reporter.step(f"{step_name(ctx)}depth {place.depth}: isolated points")
        if rests:
            isolated(ctx, place, rests)
        for search in ctx.deferred.pop():
            search()


def _decide_factor(ctx: SearchContext, place: Place, f, drops, split: bool = False) -> None:
    """Decide the candidate ``f = 0``: a component when its numbers differ from
    ``place.base``, else searched inside (``split``: a factor of a single minor, whose zero
    set holds a drop set of codimension 2 or more)."""
    names = vars_of(ctx, f)
    f_text = poly_text(ctx, f)
    if all(ctx.kinds[n][0] == "parameter" for n in names):
        add_once(ctx.locus.parameter_conditions,
                 Remark.of("parameter_condition", polynomial=f_text))
        return
    linear = next((n for n in names if f.degrees()[ctx.ring_names.index(n)] == 1
                   and ctx.kinds[n][0] != "parameter"), None)
    if linear is None:
        nonlinear_factor(ctx, place, f, f_text, drops)
        return
    sub_rows, f0, f1 = substitute_linear(ctx, place.rows, f, linear)
    k = ctx.ring_names.index(linear)
    sub_charts = [substitute(c, k, f0, f1, c.degrees()[k]) for c in place.charts]
    if any(c.is_zero() for c in sub_charts):
        ctx.locus.unexplored.append(Remark.of("outside_parametrization", polynomial=f_text,
                                              equations=place.equations))
        return
    sub_charts = tuple(c for c in [*sub_charts, f1] if not c.is_constant())
    eqs = place.equations + [f_text]
    where_parametrization_fails(ctx, place.inside(equations=eqs), [], f0, f1)
    # f = 0 lies in the place: its ranks are at most the place's, and reaching them at
    # a point of it proves its numbers are the place's
    numbers = place.base if attains(sub_rows, ctx.model, place.base) else decompose(
        sub_rows, ctx.model, ctx.row_contacts, ctx.ring.zctx).numbers
    sub_point = dict(place.point)
    sub_point[linear] = (f0, f1)
    inside = place.inside(rows=sub_rows, equations=eqs, point=sub_point, charts=sub_charts)
    if numbers == place.base:
        inside_candidate(ctx, inside, split=split)
        return
    wider = wider_component(ctx, sub_point, numbers)
    if wider is not None:  # already found, in a chart with fewer joints at pi
        inside_candidate(ctx, inside.inside(depth=wider.depth + 1,
                                            parent=ctx.locus.components.index(wider)))
        return
    witness = witness_linear(ctx, sub_rows, linear, f0, f1, place.point, numbers)
    left = [n for n in ctx.ring_names if n not in sub_point]
    kind = ("isolated" if not left else "hypersurface" if len(eqs) == 1 else "subvariety")
    comp = _new_component(ctx, place, eqs, numbers, kind, drops,
                          Remark.of("decided_function_field"), witness=witness,
                          chain=sub_point, held_searched=True)
    if comp is not None:
        go_deeper(ctx, comp, inside)
    else:   # recorded in another chart: searched inside at its joints at pi
        go_deeper(ctx, recorded_elsewhere(ctx, eqs, numbers, sub_point, None), inside,
                  held=True)


def inside_candidate(ctx: SearchContext, place: Place, split: bool = False,
                     family: tuple | None = None) -> None:
    """A candidate set whose numbers are the enclosing ones. Some candidates come from
    conditions that are sufficient, not necessary (a left nullspace basis losing rank, a
    row divisor), or hold a drop set of higher codimension (``split``: a factor of a
    single minor): the enclosing search does not see drops deeper inside them, so they
    are searched too, without being reported. ``family = (f, k)``: the set is ``f = 0``
    inside the rows of ``place`` (``f`` curved in variable ``k``), searched by
    :func:`~.curved.inside_curved`."""
    if ctx.expired():
        return
    if place.point is not None and all(n in place.point for n in ctx.ring_names):
        return  # a point: nothing lies deeper inside it
    reason, bound = None, None
    if split:
        if place.rows is not None and ctx.splits >= MAX_SPLITS:
            reason, bound = "nested_splits", MAX_SPLITS
    elif place.rows is not None and ctx.hidden >= HIDDEN_DEPTH:
        reason, bound = "hidden_depth", HIDDEN_DEPTH
    if reason is None and place.depth > ctx.max_depth:
        reason, bound = "max_depth", ctx.max_depth
    if reason is not None or place.rows is None:
        note(ctx, "enclosing_not_searched", equations=place.equations,
             reason=reason or "no_parametrization", bound=bound)
        return
    if family is not None:   # the same family, found again from another block
        key = frozenset(place.equations)
        if key in ctx.searched:
            return
        ctx.searched.add(key)

    def search() -> None:
        if split:
            ctx.splits += 1
        else:
            ctx.hidden += 1
        try:
            if family is None:
                explore(ctx, place)
            else:
                inside_curved(ctx, place, *family)
        finally:
            if split:
                ctx.splits -= 1
            else:
                ctx.hidden -= 1

    after_enclosing(ctx, search)


def after_enclosing(ctx: SearchContext, search) -> None:
    """Run ``search`` after the components of the enclosing level are found, or now when
    that level is already done (a search started by a deferred one)."""
    if ctx.deferred:
        ctx.deferred[-1].append(search)
    else:
        search()


#: The work budget, in steps of :func:`~coopkin_sym.exact.deadline.check`, that the
#: searches inside the sets of one chart at q = pi held by a component of another
#: chart share (deterministic: the same cut on any machine); past it, each such set
#: is said not searched inside.
HELD_STEPS = 50_000
#: The owner of that budget (see :func:`~coopkin_sym.exact.deadline.active`).
HELD_OWNER = "the search inside sets held in another chart"


def go_deeper(ctx: SearchContext, comp: Component | None, place: Place,
              why_not: str | None = None, family: tuple | None = None,
              held: bool = False) -> None:
    """Search inside a new component for deeper drops, or say why it was not done
    (``why_not``: a reason of :data:`~.remarks.REASONS`). ``family = (f, k)``: the
    component is ``f = 0`` inside the rows of ``place`` (``f`` curved in variable
    ``k``), searched by :func:`~.curved.inside_curved`. ``held``: ``place`` is a set
    of this chart inside ``comp``, a component recorded in another chart (searched
    under the chart's budget :data:`HELD_STEPS`)."""
    if comp is None or comp.kind == "isolated":
        return
    if held:
        _search_held(ctx, comp, place, why_not, family)
        return
    index = ctx.locus.components.index(comp)
    # a set held by a component of another chart, found again from another minor with
    # the same parametrization's denominators: searched inside once
    key = ("inside", index, frozenset(place.equations),
           tuple(sorted(str(c) for c in place.charts)),
           None if family is None else str(family[0]))
    if key in ctx.searched:
        return
    ctx.searched.add(key)
    if place.depth >= ctx.max_depth:
        why_not = "max_depth"
    elif place.rows is None and why_not is None:
        why_not = "no_parametrization"
    if why_not is not None:
        ctx.locus.unexplored.append(Remark.of(
            "deeper_not_explored", component=index, condition=comp.condition.text,
            reason=why_not, bound=ctx.max_depth if why_not == "max_depth" else None))
    elif family is None:
        explore(ctx, place.inside(depth=place.depth + 1, parent=index))
    else:
        inside_curved(ctx, place.inside(depth=place.depth + 1, parent=index,
                                        base=Numbers(**comp.numbers)), *family)


def _search_held(ctx: SearchContext, comp: Component, place: Place, why_not: str | None,
                 family: tuple | None) -> None:
    """:func:`go_deeper` inside a set held by ``comp`` from another chart, under what
    is left of the chart's budget; said when the budget is used up."""
    said = Remark.of("pi_inside_not_searched", component=ctx.locus.components.index(comp),
                     joints=tuple(sorted(ctx.pi - set(comp.chart))))
    left = HELD_STEPS if ctx.held_left is None else ctx.held_left
    if left <= 0:
        add_once(ctx.locus.unexplored, said)
        return
    levels = len(ctx.deferred)
    with deadline.work_limit(left, HELD_OWNER) as bound:
        start = bound.budget[0]   # less than left inside a smaller enclosing budget
        try:
            go_deeper(ctx, comp, place, why_not, family)
        except WorkLimitReached:
            if bound.budget[0] >= 0:
                raise   # an enclosing budget, used up here
            del ctx.deferred[levels:]   # what it left to search later is cut too
            add_once(ctx.locus.unexplored, said)
    ctx.held_left = max(left - (start - bound.budget[0]), 0)


#: The steps the seams below call back into (see :class:`.components.Steps`).
STEPS = Steps(explore=explore, go_deeper=go_deeper, inside_candidate=inside_candidate,
              after_enclosing=after_enclosing, isolated=isolated)
