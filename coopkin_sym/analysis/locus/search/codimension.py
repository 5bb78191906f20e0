"""Codimension two and points: isolated configurations, the intersections of two
components, and families of codimension 2 solved for two variables over the field of
the others (linear or curved in the first), each decided exactly at its point or
over its field.
"""

from __future__ import annotations

import itertools

import sympy as sp

from coopkin_sym.analysis.locus import algebra
from coopkin_sym.analysis.locus.algebra import (
    as_poly,
    bounded_factor,
    bounded_gcd,
    bounded_gcd_modulo,
    bounded_resultant,
    linear_equation,
    linearly_disjoint,
    normalize,
    poly_text,
    roots,
    solve_small,
    substitute_values,
    univariate,
    value_equation,
    vars_of,
)
from coopkin_sym.analysis.locus.conditions import Condition
from coopkin_sym.analysis.locus.context import Place, SearchContext
from coopkin_sym.analysis.locus.remarks import Remark, add_once
from coopkin_sym.analysis.locus.search.components import (
    HIDDEN_DEPTH,
    _new_component,
    angle_condition,
    no_real_points,
    note,
    off_charts,
    recorded_elsewhere,
    variable_to_solve,
)
from coopkin_sym.analysis.locus.search.fields import irrational_family, joined_points
from coopkin_sym.analysis.locus.search.modular import (
    enclosing_numbers_at_a_point,
    numbers_on,
    reaches_at_values,
)
from coopkin_sym.analysis.locus.witness import (
    algebraic_condition,
    attach_algebraic_witness,
    attach_two_root_witness,
    attach_witness,
    complete_point,
    family_witness,
    numbers_at_values,
    to_at,
)
from coopkin_sym.analysis.mobility import decompose, numbers_modulo
from coopkin_sym.exact.numberfield import NumberField
from coopkin_sym.exact.quotient import (
    Quotient,
    Tower,
    smallest_fraction,
)
from coopkin_sym.exact.realroot import real_root_count
from coopkin_sym.exact.sizes import resultant_terms
from coopkin_sym.exact.substitution import split_linear, substitute, substitute_rows
from coopkin_sym.exact.sympy_bridge import poly_to_sympy


def isolated(ctx: SearchContext, place: Place, rests, max_degree: int | None = None) -> None:
    """Common zeros of the remaining minor combinations (codimension 2 or more); points
    of degree above ``max_degree`` over Q are not decided (and the report says so)."""
    free = [n for n in ctx.ring_names if n not in place.point]
    rational_points: list[dict] = []
    algebraic_points: list[tuple] = []
    for polys in rests:
        names_used = sorted({n for p in polys for n in vars_of(ctx, p)},
                            key=ctx.ring_names.index)
        if not names_used:
            continue
        if len(names_used) > 2 and _no_real_common_zero(ctx, polys):
            continue
        if len(names_used) > 2:
            # roots in one variable times points in the others, families of
            # codimension 2, then finitely many points (each None when it does not apply)
            found = _product_points(ctx, polys, names_used, max_degree, place.depth)
            if found is None and len(names_used) <= 4 and _solve_with_parameters(
                    ctx, place, polys, names_used):
                continue
            if found is None:
                found = _eliminated_points(ctx, polys, names_used, max_degree, place.depth)
            if found is None:
                note(ctx, "lower_dimensional_not_solved", depth=place.depth,
                     variables=names_used, bound=_PARAMETER_SOLVE_TERMS)
                continue
            points, algebraic, unresolved = found
        else:
            points, algebraic, unresolved = solve_small(ctx, polys, names_used, max_degree)
        for remark in unresolved:
            add_once(ctx.locus.unexplored, remark)
        rational_points += points
        algebraic_points += algebraic
    created = []
    for point in rational_points:
        created.append(_decide_point(ctx, place, point, None, free))
    for x, g, values, eqs, alpha in algebraic_points:
        created.append(_decide_point(ctx, place, values, (x, g, eqs, alpha), free))
    _intersections(ctx, place, [c for c in created if c is not None], free)


def _product_points(ctx: SearchContext, polys, names: list[str], max_degree: int | None,
                    depth: int):
    """The common zeros of ``polys`` when some of them are in one variable ``x`` alone
    and the others are free of ``x`` in at most two variables: the roots of the first
    (their gcd) times the points of the others, as :func:`solve_small` gives points
    (a root of degree 2 or more with rational other coordinates, or a rational root
    with an algebraic point). ``None`` when the system is not of this form; a root and
    a point both irrational are said not decided (two fields at once)."""
    for x in names:
        k = ctx.ring_names.index(x)
        alone = [p for p in polys if vars_of(ctx, p) == [x]]
        rest = [p for p in polys if p.degrees()[k] == 0]
        others = [n for n in names if n != x]
        if not alone or len(alone) + len(rest) != len(polys) or not 1 <= len(others) <= 2:
            continue
        g = alone[0]
        for p in alone[1:]:
            g = g.gcd(p)
        rational_x, curved_x = roots(ctx, g, x)
        points, algebraic, unresolved = solve_small(ctx, rest, others, max_degree)
        out_points = [{**pt, x: x0} for x0 in rational_x for pt in points]
        out_algebraic = [(y, h, {**values, x: x0}, [*eqs, linear_equation(ctx, x, x0)], alpha)
                         for x0 in rational_x for y, h, values, eqs, alpha in algebraic]
        for h in curved_x:
            if max_degree is not None and h.degrees()[k] > max_degree:
                unresolved.append(Remark.of("points_not_decided", polynomial=poly_text(ctx, h),
                                            degree=int(h.degrees()[k]), bound=max_degree))
                continue
            out_algebraic += [(x, h, dict(pt), [h, *(linear_equation(ctx, n, v)
                                                     for n, v in pt.items())], x)
                              for pt in points]
            for point in algebraic:
                joined = joined_points(ctx, x, h, point, max_degree)
                if joined is None:
                    unresolved.append(Remark.of("lower_dimensional_not_solved", depth=depth,
                                                variables=names,
                                                bound=_PARAMETER_SOLVE_TERMS))
                    continue
                for one in joined:
                    (unresolved if isinstance(one, Remark) else out_algebraic).append(one)
        return out_points, out_algebraic, unresolved
    return None


def _eliminated_points(ctx: SearchContext, polys, names: list[str], max_degree: int | None,
                       depth: int):
    """The common zeros of ``polys`` in three or four variables when the others take
    finitely many values on them: a variable ``v`` is eliminated (resultants in ``v``
    with the smallest equation in it; every common zero projects into their zeros), the
    points of the result in the others solved (in two by :func:`solve_small`: finitely
    many exactly when its equations have no common factor; in three by this function),
    and ``v`` at each point from the gcd of all the equations there (``v`` stays free
    where they all vanish, at the outermost level only). ``None`` when no variable
    leaves finitely many points, an equation has more than
    :data:`_PARAMETER_SOLVE_TERMS` terms, or a resultant is over its bound."""
    if not 3 <= len(names) <= 4 or any(len(p) > _PARAMETER_SOLVE_TERMS for p in polys):
        return None
    first = None
    for v in names:          # the first order that leaves nothing undecided
        found = _eliminating(ctx, polys, names, v, max_degree, depth)
        if found == "too large":
            return None       # not solved, and the report says why
        if found is not None and not found[2]:
            return found
        first = first or found
    return first


def _eliminating(ctx: SearchContext, polys, names: list[str], v: str,
                 max_degree: int | None, depth: int):
    """:func:`_eliminated_points` with ``v`` eliminated first: its result, ``None``
    when that leaves infinitely many points, ``"too large"`` when a resultant is over
    its bound."""
    kv = ctx.ring_names.index(v)
    with_v = sorted((p for p in polys if p.degrees()[kv] > 0), key=len)
    if not with_v:
        return None
    if any(resultant_terms(with_v[0], p, kv) > _ELIMINATION_TERMS for p in with_v[1:]):
        return None           # a resultant that could be large and slow: not this way
    system = [p for p in polys if p.degrees()[kv] == 0]
    for p in with_v[1:]:
        r = bounded_resultant(ctx, with_v[0], p, v)
        if r is None:
            return "too large"
        system.append(r)
    system = [p for p in system if not p.is_zero()]
    if not system or any(p.is_constant() for p in system):
        return ([], [], []) if system else None     # no common zero at all, or v alone
    others = [n for n in names if n != v]
    if len(others) == 2:
        g = system[0]
        for p in system[1:]:
            g = g.gcd(p)
        if not g.is_constant():
            return None                                 # a curve: not finitely many
        points, algebraic, unresolved = solve_small(ctx, system, others, max_degree)
        if unresolved:       # the other variable first may determine every point
            again = solve_small(ctx, system, others[::-1], max_degree)
            if not again[2]:
                points, algebraic, unresolved = again
    else:
        inner = _eliminated_points(ctx, system, others, max_degree, depth)
        if inner is None:
            return None
        points, algebraic, unresolved = inner
        if any(set(p) != set(others) for p in points) or any(
                set(values) | {x} != set(others) for x, _h, values, _e, _a in algebraic):
            return None                         # an inner coordinate free: a curve
    unresolved = list(unresolved)
    out_points, out_algebraic = [], []
    for point in points:
        at = _values_substituted(ctx, polys, point, None)
        rational, curved = _lifted_roots(ctx, at, v)
        if rational is None:
            out_points.append(point)                    # v free there
            continue
        out_points += [{**point, v: r} for r in rational]
        for f in curved:
            if max_degree is not None and f.degrees()[kv] > max_degree:
                unresolved.append(Remark.of(
                    "points_not_decided", polynomial=poly_text(ctx, f),
                    degree=int(f.degrees()[kv]), bound=max_degree))
                continue
            out_algebraic.append((v, f, dict(point), [f, *(linear_equation(ctx, n, c)
                                                       for n, c in point.items())], v))
    for x, h, values, eqs, alpha in algebraic:
        how, lifted = _lifted_value(ctx, polys, x, h, values, v)
        if how == "one":
            out_algebraic.append((x, h, {**values, v: lifted},
                                  [*eqs, value_equation(ctx, v, lifted, x)], alpha))
        elif how == "free":
            out_algebraic.append((x, h, values, eqs, alpha))
        elif how == "several":
            unresolved.append(Remark.of("shared_values_undecided",
                                        polynomial=poly_text(ctx, h), count=lifted,
                                        variable=v, over=x))
        elif how == "sheared":
            unresolved.append(Remark.of("lower_dimensional_not_solved", depth=depth,
                                        variables=names, bound=_PARAMETER_SOLVE_TERMS))
    return out_points, out_algebraic, unresolved


def _values_substituted(ctx: SearchContext, polys, values: dict, x: str | None) -> list:
    """``polys`` with each variable of ``values`` replaced by its value (a rational, or
    a polynomial over Q in the root ``x``), denominators cleared."""
    out = []
    for p in polys:
        for name, value in values.items():
            k = ctx.ring_names.index(name)
            if p.degrees()[k] == 0:
                continue
            num, den = as_poly(ctx, value, x)
            p = substitute(p, k, -num, ctx.ring.zctx.constant(den), p.degrees()[k])
        out.append(p)
    return out


def _lifted_roots(ctx: SearchContext, polys, v: str):
    """The real roots of the gcd of univariate ``polys`` in ``v`` (``roots``), or
    ``(None, None)`` when they all vanish (``v`` free)."""
    g = None
    for p in polys:
        if not p.is_zero():
            g = p if g is None else g.gcd(p)
    if g is None:
        return None, None
    return roots(ctx, g, v)


def _lifted_value(ctx: SearchContext, polys, x: str, h, values: dict, v: str):
    """The value of ``v`` at a point whose coordinates are polynomials over Q in a root
    ``x`` of ``h``, as ``(how, value)``: ``("one", P)`` when the equations there have
    one common root in ``v``, a polynomial in that root; ``("free", None)`` when they
    all vanish; ``("none", None)`` when they have no common root; ``("several", n)``
    when they share ``n`` (not decided here); ``("sheared", None)`` for a point in
    sheared coordinates (``x`` among the values: not lifted here)."""
    if x in values:
        return "sheared", None
    at = _values_substituted(ctx, polys, values, x)
    nonzero = [p for p in at if not p.is_zero()]
    if not nonzero:
        return "free", None
    field = NumberField(univariate(ctx, h, x))
    kx, kv = ctx.ring_names.index(x), ctx.ring_names.index(v)
    common = field.squarefree(field.gcd([algebra.coefficients_in(ctx, p, kx, kv)
                                         for p in nonzero]))
    if len(common) == 2:
        return "one", field.element(-common[0])
    return ("none", None) if len(common) < 2 else ("several", len(common) - 1)


def _no_real_common_zero(ctx: SearchContext, polys) -> bool:
    """Whether the polynomials of ``polys`` in one same variable alone have no common
    real root (then ``polys`` have no common real zero, whatever the others are)."""
    by_name: dict = {}
    for p in polys:
        names = vars_of(ctx, p)
        if len(names) == 1:
            g = by_name.get(names[0])
            by_name[names[0]] = p if g is None else g.gcd(p)
    return any(g.is_constant() or real_root_count(univariate(ctx, g, n)) == 0
               for n, g in by_name.items())


def _intersections(ctx: SearchContext, place: Place, created, free) -> None:
    """Intersections of two families found together, in disjoint variables (two
    fingers stretched at once): the numbers where both hold, exactly (over the compositum
    of their fields when both are irrational and their fields are linearly disjoint)."""
    families = [c for c in created if c[0].kind == "subvariety"]
    for (ci, vi, ai), (cj, vj, aj) in itertools.combinations(families, 2):
        dims_i = set(vi) | ({ai[0]} if ai else set())
        dims_j = set(vj) | ({aj[0]} if aj else set())
        if dims_i & dims_j or ctx.expired():
            continue
        if ai and aj and not linearly_disjoint(ctx, ai[1], ai[0], aj[1], aj[0]):
            ctx.locus.unexplored.append(Remark.of(
                "fields_not_disjoint", first=ctx.locus.components.index(ci),
                second=ctx.locus.components.index(cj)))
            continue
        if place.depth >= ctx.max_depth:
            continue
        moduli = [Quotient(a[1], ctx.ring_names.index(a[0])) for a in (ai, aj) if a]
        reducer = (moduli[0] if len(moduli) == 1 else Tower(moduli)) if moduli else None

        def here(rows, vi=vi, ai=ai, vj=vj, aj=aj):
            rows = substitute_values(ctx, rows, vi, ai[0] if ai else None)
            return substitute_values(ctx, rows, vj, aj[0] if aj else None)

        if any(c.is_zero() or (reducer is not None and reducer.is_zero(c))
               for c in (here([[c]])[0][0] for c in place.charts)):
            continue  # outside the enclosing parametrization
        rows = here(place.rows)
        if reducer is None:
            numbers = decompose(rows, ctx.model, ctx.row_contacts, ctx.ring.zctx).numbers
        else:
            numbers = numbers_modulo(rows, ctx.model, ctx.row_contacts, reducer)
        if numbers.as_dict() in (ci.numbers, cj.numbers):
            continue
        eqs = [e.text for e in ci.equations]
        eqs += [e.text for e in cj.equations if e not in ci.equations]
        kind = "isolated" if len(dims_i | dims_j) == len(free) else "subvariety"
        comp = _new_component(ctx, place.inside(depth=place.depth + 1,
                                                parent=ctx.locus.components.index(ci)),
                              eqs, numbers, kind, {"Q"},
                              Remark.of("decided_joined_fields", fields=len(moduli)),
                              condition=ci.condition & cj.condition,
                              within=place.point)
        if comp is None:
            continue
        values = {**vi, **vj}
        if not moduli:
            full = complete_point(ctx, place.point, values)
            if full is not None and numbers_at_values(ctx, full) == numbers:
                attach_witness(ctx, comp, to_at(ctx, full), numbers)
        elif len(moduli) == 1:
            (x, g) = (ai or aj)[:2]
            attach_algebraic_witness(ctx, comp, x, g, values, place.point, numbers)
        elif not place.point:
            attach_two_root_witness(ctx, comp, (ai[0], ai[1], vi), (aj[0], aj[1], vj),
                                    numbers)


# the largest minor combination (in terms) solved with parameters
_PARAMETER_SOLVE_TERMS = 400
# the largest resultant (a bound from degrees, in terms) that points are eliminated with
_ELIMINATION_TERMS = 2_000


def _solve_with_parameters(ctx: SearchContext, place: Place, polys, names: list[str]) -> bool:
    """Codimension-2 families in three or four variables, decided exactly.

    Two variables ``x, y`` are solved over the field of the others (the parameters):
    the resultant in ``y`` is factored over Z; for each factor ``h`` involving ``x``,
    ``x`` is substituted when ``h`` is linear in it (then ``y`` comes from the gcd of
    the equations, substituted too or kept as a curve ``k(y, ...) = 0``), and otherwise
    ``y = -c0/c1`` comes from their gcd over the function field of ``h``, whose ranks
    are computed modulo ``h``. Returns whether the system was solved.
    """
    if any(len(p) > _PARAMETER_SOLVE_TERMS for p in polys):
        return False
    by_y: dict = {}   # the resultants in y do not depend on x: each computed once
    for x, y in itertools.permutations(names, 2):
        kx, ky = ctx.ring_names.index(x), ctx.ring_names.index(y)
        if any(p.degrees()[ky] == 0 for p in polys):
            continue
        if y not in by_y:
            res = None
            for p in polys[1:]:
                r = bounded_resultant(ctx, polys[0], p, y)
                if r is None:
                    return True   # not solved, and the report says why
                if res is None:
                    res = r
                    continue
                # either resultant's zeros hold the projection: over the gcd's size
                # the smaller one is kept (its factors are checked on all of polys)
                common = bounded_gcd(ctx, res, r, report=False)
                res = common if common is not None else min(res, r, key=len)
            by_y[y] = res
        res = by_y[y]
        if res is None or res.is_zero() or res.is_constant() or res.degrees()[kx] == 0:
            continue
        factored = bounded_factor(ctx, res)
        if factored is None:
            return True
        _, factors = factored
        for h, _e in sorted(factors, key=lambda fe: (fe[0].total_degree(), str(fe[0]))):
            h = normalize(h)
            if no_real_points(ctx, h):
                continue
            hx = x if h.degrees()[kx] else variable_to_solve(ctx, h, exclude=(y,))
            if h.degrees()[ctx.ring_names.index(hx)] == 1:
                _solve_linear_x(ctx, place, polys, h, hx, y)
            else:
                _solve_curved_x(ctx, place, polys, h, hx, y)
        return True
    return False


def _solve_linear_x(ctx: SearchContext, place: Place, polys, h, x, y) -> None:
    kx, ky_first = ctx.ring_names.index(x), ctx.ring_names.index(y)
    y_first = y
    h1, h0 = split_linear(h, kx)
    moved = [substitute(p, kx, h0, h1, p.degrees()[kx]) for p in polys]
    common = None
    for p in moved:
        if not p.is_zero():
            common = p if common is None else bounded_gcd(ctx, common, p)
            if common is None:
                return            # not solved, and the report says why
    if common is None or common.is_constant():
        return
    rows_x = substitute_rows(place.rows, kx, h0, h1)
    inner = dict(place.point)
    inner[x] = (h0, h1)
    where_parametrization_fails(ctx, place, [*polys, h], h0, h1)
    factored = bounded_factor(ctx, common)
    if factored is None:
        return
    _, factors = factored
    for k, _e in sorted(factors, key=lambda fe: (fe[0].total_degree(), str(fe[0]))):
        if k.is_constant():
            continue
        # the family's second equation, solved for y, or for another of its variables
        # when y stays free along it
        y = y_first if k.degrees()[ky_first] else variable_to_solve(ctx, k)
        k = normalize(k)
        if not no_real_points(ctx, k):
            _linear_x_family(ctx, place, h, (kx, h0, h1), rows_x, inner, k, y)


def where_parametrization_fails(ctx: SearchContext, place: Place, polys, f0, f1) -> None:
    """The part of a set ``polys = 0`` (a hypersurface ``f1 v + f0 = 0``: no ``polys``)
    that its parametrization ``v = -f0/f1`` does not reach: where ``f0 = f1 = 0`` too
    (``v`` free there), searched as a set of its own (its numbers decided, and inside
    it) when ``f1`` is not constant; each such system once per parametrization."""
    if f1.is_constant():
        return
    system = [*polys, f0, f1]
    key = ("denominator", frozenset(str(p) for p in system), frozenset(place.point or ()))
    if key in ctx.searched:
        return
    ctx.searched.add(key)
    ctx.steps.isolated(ctx, place, [system])


def _charts_after(charts, at, denominator) -> tuple:
    """The denominators of a parametrization once a variable is put in: each of
    ``charts`` through ``at`` (the substitution), and the new ``denominator``, those
    that are not constants."""
    return tuple(c for c in (*(at(c) for c in charts), denominator) if not c.is_constant())


def _linear_x_family(ctx: SearchContext, place: Place, h, at: tuple, rows_x, inner: dict,
                     k, y: str) -> None:
    """One family ``h = 0, k = 0`` of :func:`_solve_linear_x`, ``x`` (index ``at[0]``)
    being ``-h0/h1`` there (``at = (kx, h0, h1)``) and ``y`` the variable ``k`` is solved
    for: decided, then searched inside."""
    kx, h0, h1 = at
    ky = ctx.ring_names.index(y)

    def at_x(c):
        return substitute(c, kx, h0, h1, c.degrees()[kx])

    if k.degrees()[ky] == 1:
        k1, k0 = split_linear(k, ky)

        def at_xy(c, k0=k0, k1=k1, ky=ky):
            c = at_x(c)
            return substitute(c, ky, k0, k1, c.degrees()[ky])

        if off_charts([*place.charts, h1], at_xy):
            return
        where_parametrization_fails(ctx, place, [h, k], k0, k1)
        rows = substitute_rows(rows_x, ky, k0, k1)
        numbers = decompose(rows, ctx.model, ctx.row_contacts, ctx.ring.zctx).numbers
        decided = Remark.of("decided_two_substitutions")
        if numbers == place.base:
            sub_point = dict(inner)
            sub_point[y] = (k0, k1)
            sub_charts = _charts_after([*place.charts, h1], at_xy, k1)
            ctx.steps.inside_candidate(ctx, place.inside(
                rows=rows, equations=place.equations + [poly_text(ctx, h),
                                                        poly_text(ctx, k)],
                point=sub_point, charts=sub_charts))
            return
    else:
        quotient = Quotient(k, ky)
        if off_charts([*place.charts, h1], at_x, quotient):
            return
        numbers = numbers_on(ctx, rows_x, quotient, place.base)
        decided = Remark.of("decided_substitution_modulo")
    eqs = place.equations + [poly_text(ctx, h), poly_text(ctx, k)]
    on_x = place.inside(rows=rows_x, equations=eqs, point=inner,
                        charts=_charts_after(place.charts, at_x, h1))
    if numbers == place.base:
        ctx.steps.inside_candidate(ctx, on_x, family=(k, ky))
        return
    chain = None
    if k.degrees()[ky] == 1:
        chain = dict(inner)
        chain[y] = (k0, k1)
    comp = _new_component(ctx, place, eqs, numbers, "subvariety", {"Q"}, decided,
                          chain=chain, within=inner,
                          generic_point=None if chain is not None else (inner, quotient),
                          held_searched=True)
    held = comp is None
    if held:   # recorded in another chart: searched inside at its joints at pi
        comp = recorded_elsewhere(ctx, eqs, numbers, *((chain, None) if chain is not None
                                                        else (inner, quotient)))
        if comp is None:
            return
    else:
        family_witness(ctx, comp, k, y, inner, numbers)
    if k.degrees()[ky] == 1:
        sub_point = dict(inner)
        sub_point[y] = (k0, k1)
        sub_charts = _charts_after([*place.charts, h1], at_xy, k1)
        ctx.steps.go_deeper(ctx, comp, place.inside(rows=rows, equations=eqs, point=sub_point,
                                                    charts=sub_charts), held=held)
    else:
        ctx.steps.go_deeper(ctx, comp, on_x, family=(k, ky), held=held)


def _solve_curved_x(ctx: SearchContext, place: Place, polys, h, x, y,
                    swapped: bool = False) -> None:
    kx, ky = ctx.ring_names.index(x), ctx.ring_names.index(y)
    if ((ctx.hidden >= HIDDEN_DEPTH or place.depth > ctx.max_depth or ctx.expired())
            and enclosing_numbers_at_a_point(ctx, place, polys, h, x, y)):
        # its numbers are the enclosing ones, and it would not be searched inside
        note(ctx, "common_root_not_searched",
             equations=place.equations + [poly_text(ctx, h)], variable=y)
        return
    quotient = Quotient(h, kx)
    common = bounded_gcd_modulo(ctx, polys, quotient, y)
    if common is None:
        return
    if len(common) > 2 and not swapped:
        # several values of y over each point of h = 0 (angles that differ by pi): the
        # family projects onto the hypersurfaces N = 0 in y and the parameters, N a
        # factor of the norm res_x(h, g); over each, x is solved from h and g instead
        g = sum((c * ctx.ring.zctx.gens()[ky] ** i for i, c in enumerate(common)),
                ctx.ring.zctx.constant(0))
        norm = bounded_resultant(ctx, h, g, x)
        factored = None if norm is None else bounded_factor(ctx, norm)
        if factored is None:
            return
        _, factors = factored
        for n, _e in sorted(factors, key=lambda fe: (fe[0].total_degree(), str(fe[0]))):
            if n.degrees()[ky] == 0:
                continue  # where the leading coefficients vanish: part of a wider set
            n = normalize(n)
            if no_real_points(ctx, n):
                continue
            if n.degrees()[ky] == 1:
                _solve_linear_x(ctx, place, [*polys, h], n, y, x)
            else:
                _solve_curved_x(ctx, place, [*polys, h], n, y, x, swapped=True)
        return
    if len(common) > 2:
        note(ctx, "shared_values_not_solved", depth=place.depth,
             polynomial=poly_text(ctx, h), count=len(common) - 1, variable=y)
        return
    if len(common) < 2:
        return
    c0, c1 = smallest_fraction(*common, quotient)  # y = -c0/c1, c1 free of x
    if off_charts([*place.charts, c1], lambda c: substitute(c, ky, c0, c1, c.degrees()[ky]),
                  quotient):
        return
    where_parametrization_fails(ctx, place, [*polys, h], c0, c1)
    rows = substitute_rows(place.rows, ky, c0, c1)
    numbers = numbers_on(ctx, rows, quotient, place.base)
    y_eq = c1 * ctx.ring.zctx.gens()[ky] + c0
    eqs = place.equations + [poly_text(ctx, h), poly_text(ctx, y_eq)]
    inner = dict(place.point)
    inner[y] = (c0, c1)
    on_h = place.inside(rows=rows, equations=eqs, point=inner, charts=_charts_after(
        place.charts, lambda c: substitute(c, ky, c0, c1, c.degrees()[ky]), c1))
    if numbers == place.base:
        ctx.steps.inside_candidate(ctx, on_h, family=(h, kx))
        return
    comp = _new_component(ctx, place, eqs, numbers, "subvariety", {"Q"},
                          Remark.of("decided_family_modulo"), within=inner,
                          generic_point=(inner, quotient), held_searched=True)
    held = comp is None
    if held:   # recorded in another chart: searched inside at its joints at pi
        comp = recorded_elsewhere(ctx, eqs, numbers, inner, quotient)
        if comp is None:
            return
    else:
        family_witness(ctx, comp, h, x, inner, numbers)
    ctx.steps.go_deeper(ctx, comp, on_h, family=(h, kx), held=held)


def _decide_point(ctx: SearchContext, place: Place, values: dict, algebraic,
                  free) -> tuple | None:
    """The numbers on the set where some coordinates are fixed (rationals, or
    polynomials over Q in a root ``x`` of ``g`` when ``algebraic = (x, g, equations,
    alpha)``, ``alpha`` naming what ``x`` stands for), every
    other free variable staying generic, decided exactly."""
    quotient = None
    if algebraic is not None:
        x, g, _, _ = algebraic
        quotient = Quotient(g, ctx.ring_names.index(x))
    x = algebraic[0] if algebraic is not None else None
    charts = []   # the denominators of the parametrization, the values put in
    for c in place.charts:
        c_here = substitute_values(ctx, [[c]], values, x)[0][0]
        if c_here.is_zero() or (quotient is not None and quotient.is_zero(c_here)):
            return None  # outside the enclosing parametrization
        if not c_here.is_constant():
            charts.append(c_here)
    rows = None
    if quotient is not None and reaches_at_values(ctx, place.rows, values, x,
                                                  algebraic[1], place.base):
        numbers = place.base   # shown modulo a prime: no substitution over Q[x]/(g)
    else:
        rows = substitute_values(ctx, place.rows, values, x)
        numbers = (decompose(rows, ctx.model, ctx.row_contacts, ctx.ring.zctx).numbers
                   if quotient is None else
                   numbers_modulo(rows, ctx.model, ctx.row_contacts, quotient))
    eqs = list(place.equations)
    if algebraic is not None:
        new = [poly_text(ctx, e) for e in algebraic[2]]
    else:
        new = [poly_text(ctx, linear_equation(ctx, n, v)) for n, v in values.items()]
    eqs += [e for e in dict.fromkeys(new) if e not in eqs]   # an equation once
    dims = set(values) | ({x} if x is not None else set())
    kind = "isolated" if len(dims) == len(free) else "subvariety"
    if numbers == place.base:
        if kind == "subvariety" and algebraic is None:
            ctx.steps.inside_candidate(ctx, place.inside(
                rows=rows, equations=eqs, point=_with_values(ctx, place.point, values),
                charts=tuple(charts)))
        elif kind == "subvariety":
            family = irrational_family(ctx, place, values, x, algebraic[1], eqs)
            if family is None:   # said in the report: no rational parametrization
                ctx.steps.inside_candidate(ctx, place.inside(rows=None, equations=eqs,
                                                             point=dict(place.point)))
            else:
                ctx.steps.inside_candidate(ctx, family[0], family=family[1])
        return None
    if algebraic is not None:
        return _algebraic_point(ctx, place, values, algebraic, quotient, rows, eqs, numbers,
                                kind)
    chain = _with_values(ctx, place.point, values)
    comp = _new_component(ctx, place, eqs, numbers, kind, {"Q"},
                          Remark.of("decided_at_point" if kind == "isolated" else
                                    "decided_free_variables"),
                          chain=chain,
                          generic_point=(chain, None) if ctx.inside else None,
                          held_searched=True)
    if comp is None:
        holder = (recorded_elsewhere(ctx, eqs, numbers, chain, None) if kind == "subvariety"
                  else None)
        if holder is not None:   # recorded in another chart: searched inside here
            ctx.steps.go_deeper(ctx, holder, place.inside(rows=rows, equations=eqs,
                                                          point=chain, charts=tuple(charts)),
                                held=True)
        return None
    for offset in range(6):
        full = complete_point(ctx, place.point, values, offset)
        if full is not None and numbers_at_values(ctx, full) == numbers:
            attach_witness(ctx, comp, to_at(ctx, full), numbers)
            break
    ctx.steps.go_deeper(ctx, comp, place.inside(rows=rows, equations=eqs,
                                                point=_with_values(ctx, place.point, values),
                                                charts=tuple(charts)))
    return comp, values, None


def _with_values(ctx: SearchContext, point: dict, values: dict) -> dict:
    """``point`` with each variable of ``values`` set to its rational value (as the
    pair ``(-numerator, denominator)`` of a linear factor)."""
    out = dict(point)
    for n, v in values.items():
        out[n] = (ctx.ring.zctx.constant(-v.numerator), ctx.ring.zctx.constant(v.denominator))
    return out


def _algebraic_point(ctx: SearchContext, place: Place, values: dict, algebraic, quotient,
                     rows, eqs, numbers, kind: str) -> tuple | None:
    """The component of :func:`_decide_point` at a point whose coordinates are
    polynomials over Q in a root ``x`` of ``g`` (``algebraic = (x, g, equations,
    alpha)``), its numbers ``numbers`` (over ``Q[x]/(g)``, ``quotient``)."""
    x, g, _eq_polys, alpha = algebraic

    def condition() -> Condition:
        here = algebraic_condition(ctx, x, g, values)
        return angle_condition(ctx, place.equations) & here if place.equations else here

    m = sp.sstr(poly_to_sympy(g, ctx.ring, ctx.symbols).subs(ctx.symbols[x],
                                                             sp.Symbol("alpha")))
    at_point = dict(place.point)
    for n, v in values.items():   # n = num(x)/den, x a root of g
        num, den = as_poly(ctx, v, x)
        at_point[n] = (-num, ctx.ring.zctx.constant(den))
    comp = _new_component(ctx, place, eqs, numbers, kind, {"Q"},
                          Remark.of("decided_algebraic", variable=alpha, minimal_polynomial=m),
                          condition=condition, within=place.point,
                          generic_point=(at_point, quotient) if ctx.inside else None,
                          held_searched=True)
    held = comp is None
    if held:   # recorded in another chart (or here): searched inside at its joints at pi
        comp = (recorded_elsewhere(ctx, eqs, numbers, at_point, quotient)
                if kind == "subvariety" else None)
        if comp is None:
            return None
    else:
        attach_algebraic_witness(ctx, comp, x, g, values, place.point, numbers, alpha)
    family = (irrational_family(ctx, place, values, x, g, eqs) if kind == "subvariety"
              else None)
    if family is None:
        ctx.steps.go_deeper(ctx, comp, place.inside(rows=rows, equations=eqs, point=None),
                            "irrational_family", held=held)
    else:
        ctx.steps.go_deeper(ctx, comp, family[0], family=family[1], held=held)
    return None if held else (comp, values, (x, g))
