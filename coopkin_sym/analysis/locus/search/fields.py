"""Sets over number fields: a root of one variable joined with an algebraic point of
the others (one point per orbit of conjugate pairs, over the compositum of their
fields), and a set whose coordinates are irrational written as a family that the
search inside curved families takes (in a coordinate that generates their field, or
in two whose fields make it).
"""

from __future__ import annotations

import itertools
import math
from fractions import Fraction

import flint

from coopkin_sym.analysis.locus import algebra
from coopkin_sym.analysis.locus.algebra import (
    as_poly,
    normalize,
    poly_text,
    substitute_values,
    univariate,
)
from coopkin_sym.analysis.locus.context import Place, SearchContext
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.exact.numberfield import change_generator
from coopkin_sym.exact.realroot import real_root_count
from coopkin_sym.exact.subfields import compositum, minimal_polynomial, product_generators
from coopkin_sym.exact.substitution import substitute_rows


def joined_points(ctx: SearchContext, x: str, h, point: tuple, max_degree: int | None
                   ) -> list | None:
    """A root ``x`` of the univariate ``h`` together with an algebraic point of the
    other variables (``(y, g, values, equations, alpha)`` of :func:`solve_small`): the
    pairs, one point per orbit of conjugate pairs, over its field ``Q[theta]/(m)``
    (``theta = x + c alpha``, ``m`` a real-rooted irreducible factor of the minimal
    polynomial of ``theta`` in ``Q[x, alpha]/(h, g)``), in the form
    :func:`solve_small` gives (slot ``x``; its coordinate and the others polynomials in
    ``theta``), or a :class:`~.remarks.Remark` for an orbit of degree over
    ``max_degree``. None when the pairs are not solved this way."""
    y, g, values, eqs, alpha = point
    k = ctx.ring_names.index(x)
    if h.degrees()[k] * g.degrees()[ctx.ring_names.index(y)] > algebra.DISJOINT_DEGREE:
        return None
    coordinates = dict(values)
    if y not in coordinates:   # the root is the coordinate of its own slot
        coordinates[y] = flint.fmpq_poly([0, 1])
    irrational = [n for n, v in coordinates.items() if not isinstance(v, Fraction)]
    joined = compositum(univariate(ctx, h, x), univariate(ctx, g, y),
                        [coordinates[n] for n in irrational])
    if joined is None:
        return None
    c, minimal, root, expressed = joined
    inner = alpha if " " not in alpha else f"({alpha})"
    sign = "+" if c > 0 else "-"
    text = f"{x} {sign} {inner}" if abs(c) == 1 else f"{x} {sign} {abs(c)}*{inner}"
    orbits = [m for m, _e in minimal.factor()[1]]
    per_orbit = [dict(zip(irrational, (e % m for e in expressed), strict=True))
                 for m in orbits]
    apart = _orbit_equations(ctx, x, [root % m for m in orbits], orbits, per_orbit)
    if apart is None:
        return None
    out = []
    for m, here, orbit in zip(orbits, per_orbit, apart, strict=True):
        if real_root_count(m) == 0:
            continue   # no real pair in this orbit
        equations = [h, *eqs, *([orbit] if orbit is not None else [])]
        if max_degree is not None and m.degree() > max_degree:
            out.append(Remark.of("points_not_decided", degree=m.degree(), bound=max_degree,
                                 polynomial=" = 0, ".join(poly_text(ctx, e)
                                                          for e in equations)))
            continue
        here = {x: root % m, **coordinates, **here}   # the slot's own value first
        out.append((x, normalize(as_poly(ctx, m, x)[0]), here, equations, text))
    return out


def _orbit_equations(ctx: SearchContext, x: str, roots: list, orbits: list, values: list
                     ) -> list | None:
    """An equation that holds on each orbit of :func:`joined_points` and on no other:
    ``M_i(L) = 0``, ``M_i`` the minimal polynomial on orbit ``i`` of a linear form
    ``L = x + c u`` or ``x + c u + d v`` (``u, v`` other coordinates), the first that
    makes them pairwise distinct (so, irreducible, with no common root). ``[None]``
    for a single orbit; None when no such form is found."""
    if len(orbits) == 1:
        return [None]
    zctx = ctx.ring.zctx
    names = [n for n in values[0] if n != x]
    shapes = [((u,), (c,)) for u in names for c in (1, -1, 2, 3)]
    shapes += [((u, v), (c, d)) for u, v in itertools.combinations(names, 2)
               for c in (1, -1, 2) for d in (1, -1, 2)]
    for used, coefficients in shapes:
        forms = [minimal_polynomial(m, (r + sum(c * v[u] for u, c in zip(
                     used, coefficients, strict=True))) % m)
                 for m, r, v in zip(orbits, roots, values, strict=True)]
        if len(set(map(str, forms))) == len(forms):
            t = zctx.gens()[ctx.ring_names.index(x)] + sum(
                (c * zctx.gens()[ctx.ring_names.index(u)]
                 for u, c in zip(used, coefficients, strict=True)), zctx.constant(0))
            return [normalize(sum((int(a) * t**k for k, a in enumerate(form.numer().coeffs())
                                   if a), zctx.constant(0))) for form in forms]
    return None


def irrational_family(ctx: SearchContext, place: Place, values: dict, x: str, g,
                      equations: list[str]) -> tuple[Place, tuple] | None:
    """The set where the coordinates ``values`` are fixed (rationals, or polynomials
    over Q in a root ``x`` of ``g``; the other free variables generic) as a family
    ``h = 0`` that :func:`~.curved.inside_curved` searches inside: ``(place, (h, k))``,
    ``h`` the minimal polynomial of one of its irrational coordinates (variable ``k``),
    the others polynomials in it, substituted in the rows. The first coordinate that
    generates ``Q(x)`` is taken. When none does, two coordinates whose fields are
    linearly disjoint and make ``Q(x)`` (``t_1 = sqrt 2``, ``t_4 = sqrt 3``) give the
    family ``((h_1, h_2), (k_1, k_2))``: both stay in the rows, each a root of its
    univariate minimal polynomial, every conjugate pair being a point of the set. None
    when there is no such pair (the report then says there is no rational
    parametrization).

    ``x`` is the variable whose slot holds the root; its own coordinate may be one of
    ``values`` (a polynomial in the root, as when the root is ``3 t``): the family is
    then written in the coordinate, never in the root."""
    gq = univariate(ctx, g, x)
    irrational = {n: v for n, v in values.items() if not isinstance(v, Fraction)}
    rational = {n: v for n, v in values.items() if n not in irrational}
    if x not in values:
        return _family_in(ctx, place, equations, x, g, dict(values))
    order = sorted(irrational, key=lambda n: (n != x, ctx.ring_names.index(n)))
    for chosen in order:
        others = [n for n in irrational if n != chosen]
        changed = change_generator(gq, irrational[chosen], [irrational[n] for n in others])
        if changed is not None:
            minimal, expressed = changed
            h = normalize(as_poly(ctx, minimal, chosen)[0])
            return _family_in(ctx, place, equations, chosen, h,
                              {**rational, **dict(zip(others, expressed, strict=True))})
    # no coordinate generates the field: two whose fields are linearly disjoint
    names = sorted(irrational, key=ctx.ring_names.index)
    split = product_generators(gq, [irrational[n] for n in names])
    if split is None:
        return None
    i, j, m_i, m_j, rest = split
    a, b = names[i], names[j]
    zctx = ctx.ring.zctx
    ga, gb = zctx.gens()[ctx.ring_names.index(a)], zctx.gens()[ctx.ring_names.index(b)]
    fixed = {n: (zctx.constant(-v.numerator), zctx.constant(v.denominator))
             for n, v in rational.items()}
    for n, terms in zip([n for k, n in enumerate(names) if k not in (i, j)], rest,
                        strict=True):
        den = math.lcm(*(int(c.q) for c in terms.values()))
        fixed[n] = (-sum((zctx.constant(int(c * den)) * ga**p * gb**q
                          for (p, q), c in terms.items()), zctx.constant(0)),
                    zctx.constant(den))
    here = place.inside(rows=_substitute_chain(ctx, place.rows, fixed), equations=equations,
                        point={**place.point, **fixed},
                        charts=tuple(c for c in (_substitute_chain(ctx, [[c]], fixed)[0][0]
                                                 for c in place.charts)
                                     if not c.is_constant()))
    return here, ((normalize(as_poly(ctx, m_i, a)[0]), normalize(as_poly(ctx, m_j, b)[0])),
                  (ctx.ring_names.index(a), ctx.ring_names.index(b)))


def _substitute_chain(ctx: SearchContext, rows, values: dict):
    """``rows`` with each variable of ``values`` replaced by ``-f0/f1`` (``values`` maps
    it to ``(f0, f1)``, polynomials in variables not among ``values``), rows scaled by
    the cleared denominators."""
    for n, (f0, f1) in values.items():
        rows = substitute_rows(rows, ctx.ring_names.index(n), f0, f1)
    return rows


def _family_in(ctx: SearchContext, place: Place, equations: list[str], chosen: str, h,
               fixed: dict) -> tuple[Place, tuple]:
    """The place and family ``(h, k)`` of :func:`irrational_family`: ``h`` the
    family's polynomial, curved in ``chosen`` (variable ``k``), and ``fixed`` the
    coordinates put in (rationals, or polynomials in ``chosen``)."""
    rows = substitute_values(ctx, place.rows, fixed, chosen)
    point = dict(place.point)
    for n, v in fixed.items():
        num, den = as_poly(ctx, v, chosen)
        point[n] = (-num, ctx.ring.zctx.constant(den))
    charts = tuple(c for c in (substitute_values(ctx, [[c]], fixed, chosen)[0][0]
                               for c in place.charts) if not c.is_constant())
    return (place.inside(rows=rows, equations=equations, point=point, charts=charts),
            (h, ctx.ring_names.index(chosen)))
