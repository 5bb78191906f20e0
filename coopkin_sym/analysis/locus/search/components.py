"""The components the search reports: building one from its equations and numbers (its
witness, angle condition, denominators, the wider component it may extend), and the
small steps every seam of the search shares (notes, the step's name, realness).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from coopkin_sym.analysis.locus.algebra import (
    bounded_factor,
    has_real_point,
    normalize,
    poly_text,
    vars_of,
)
from coopkin_sym.analysis.locus.conditions import Condition, Vanishes
from coopkin_sym.analysis.locus.context import Place, SearchContext
from coopkin_sym.analysis.locus.implied import without_implied
from coopkin_sym.analysis.locus.remarks import Remark, add_once
from coopkin_sym.analysis.locus.types import Component
from coopkin_sym.analysis.locus.witness import (
    attach_witness,
)
from coopkin_sym.analysis.numbers import Numbers
from coopkin_sym.exact.angles import COTANGENT_PREFIX, cotangent_name, joint_of
from coopkin_sym.exact.polynomial import NamedPolynomial
from coopkin_sym.exact.substitution import substitute


@dataclass(frozen=True)
class Steps:
    """The recursive steps of the search, for the seams that call back into them: a
    curved family or a codimension-2 family searched inside, a point decided there,
    the slices at q = pi explored. They are defined above those seams
    (:mod:`.recursion`, :mod:`.codimension`), which reach them through
    ``ctx.steps`` so that no module imports one above it.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.search.recursion import STEPS
    >>> STEPS.explore.__name__, STEPS.isolated.__module__.rsplit(".", 1)[1]
    ('explore', 'codimension')
    """

    explore: Callable[..., None]
    go_deeper: Callable[..., None]
    inside_candidate: Callable[..., None]
    after_enclosing: Callable[..., None]
    isolated: Callable[..., None]


def step_name(ctx: SearchContext) -> str:
    """The slice at q = pi the search is in, for the progress bar ("" in the t chart)."""
    return "".join(f"{n} = pi, " for n in sorted(ctx.pi))


def note(ctx: SearchContext, kind: str, **facts) -> None:
    """Say once in the report what was not explored (a :class:`Remark` of ``kind``)."""
    add_once(ctx.locus.unexplored, Remark.of(kind, **facts))


def drops_text(drops: set[str]) -> list[str]:
    names = {"HG^T": "HG^T", "HD": "HD", "Y": "Q", "A": "Q", "Q": "Q"}
    return sorted({names[d] for d in drops})


# how many candidate sets with the enclosing numbers are searched inside one another
HIDDEN_DEPTH = 2


def variable_to_solve(ctx: SearchContext, f, exclude=()) -> str:
    """A variable of ``f`` to solve it for: the first in which it is linear, else the
    first of lowest degree (variables in ``exclude`` last)."""
    degrees = f.degrees()
    names = [n for n in vars_of(ctx, f)]
    names.sort(key=lambda n: (n in exclude, degrees[ctx.ring_names.index(n)] != 1,
                              degrees[ctx.ring_names.index(n)], ctx.ring_names.index(n)))
    return names[0]


def no_real_points(ctx: SearchContext, f) -> bool:
    """Whether ``f = 0`` has no real points (then it is listed as dropped)."""
    if has_real_point(ctx, f, vars_of(ctx, f)) is not False:
        return False
    add_once(ctx.locus.dropped, Remark.of("no_real_points", polynomial=poly_text(ctx, f)))
    return True


def off_charts(charts, substitute, quotient=None) -> bool:
    """Whether an enclosing chart denominator vanishes on the new family."""
    for c in charts:
        c_here = substitute(c)
        if c_here.is_zero() or (quotient is not None and quotient.is_zero(c_here)):
            return True
    return False


# --- components -------------------------------------------------------------------------
def _equation_set(ctx: SearchContext, c: Component) -> frozenset:
    """``set(c.equations)``, built once while its equations stay the same objects."""
    kept = ctx.equation_sets.get(id(c))
    if kept is not None and len(kept[0]) == len(c.equations) and all(
            a is b for a, b in zip(kept[0], c.equations, strict=True)):
        return kept[1]
    eqs = tuple(c.equations)
    out = frozenset(eqs)
    ctx.equation_sets[id(c)] = (eqs, out)
    return out


def _new_component(ctx: SearchContext, place: Place, equations: list[str], numbers: Numbers,
                   kind: str, drops, decided: Remark, *, witness: dict | None = None,
                   condition: Condition | Callable[[], Condition] | None = None,
                   real: bool = True, chain: dict | None = None,
                   within: dict | None = None,
                   generic_point: tuple | None = None,
                   held_searched: bool = False) -> Component | None:
    """Record a component found at ``place`` (its depth and parent; None when the same
    set is already recorded); used by every seam of the search. ``chain`` is its
    parametrization by successive linear substitutions (variable -> ``(f0, f1)``,
    the variable equals ``-f0/f1``), used to recognize the same set found twice;
    ``within``, when there is no chain, the parametrization of the set it was found
    in. Their denominators become the component's ``outside``. ``generic_point``,
    ``(parametrization, quotient or None)``, describes its generic point: a component of
    the same chart with the same numbers whose equations vanish there contains it, and
    it is not recorded. ``condition`` may be given as a function, called only for a
    component that is recorded (a costly one is then not built for the others).
    ``held_searched``: the caller searches inside a set held by a component of another
    chart here (:func:`recorded_elsewhere`), so that is not said to be left out."""
    polys = [_named(ctx, text) for text in equations]
    mine = frozenset(polys)
    if any(_equation_set(ctx, c) == mine for c in ctx.locus.components):
        return None
    here = numbers.as_dict()
    holder = next((c for c in ctx.locus.components if c.numbers == here and c.equations
                   and _equation_set(ctx, c) < mine), None)
    if holder is not None:
        _held_elsewhere(ctx, holder, kind, held_searched)
        return None  # inside a recorded component, with its numbers: nothing new
    if chain is not None and any(_within(ctx, chain, c, numbers)
                                 for c in ctx.locus.components):
        return None
    holder = None if generic_point is None else next(
        (c for c in ctx.locus.components
         if c.numbers == here and _vanish_at(ctx, c, *generic_point)), None)
    if holder is not None:
        _held_elsewhere(ctx, holder, kind, held_searched)
        return None
    generic = ctx.generic.as_dict()
    here = numbers.as_dict()
    changes = {k: (generic[k], here[k]) for k in generic if generic[k] != here[k]}
    outside = _denominators(ctx, chain if chain is not None else within, equations)
    if callable(condition):
        condition = condition()
    comp = Component(equations=polys, numbers=here, witness=None, real=real,
                     kind=kind, condition=without_implied(
                         condition or angle_condition(ctx, equations), ctx.kinds),
                     drops=drops_text(drops), changes=changes, decided=decided,
                     depth=place.depth, parent=place.parent,
                     outside=[_named(ctx, text) for text in outside],
                     chart=tuple(ctx.pi))
    if witness is not None:
        attach_witness(ctx, comp, witness, numbers)
    ctx.locus.components.append(comp)
    if ctx.owners is not None:
        ctx.owners[id(comp)] = ctx
    if chain is not None:
        ctx.chains[id(comp)] = (ctx, dict(chain))
    return comp


def _named(ctx: SearchContext, text: str) -> NamedPolynomial:
    """The exact polynomial behind an equation text of this chart: kept when the text
    was written (:func:`~coopkin_sym.analysis.locus.algebra.poly_text`), or the
    variable ``s_<joint>`` of a chart at q = pi."""
    p = ctx.polys.get(text)
    if p is not None:
        return NamedPolynomial.from_flint(p, ctx.ring_names)
    if text.startswith(COTANGENT_PREFIX) and joint_of(text) in ctx.pi:
        return NamedPolynomial.variable(text)
    # not expected: every equation is written from a polynomial of this chart; its text
    # then reads back exactly through the one parser
    names = [*ctx.ring_names, *(cotangent_name(j) for j in sorted(ctx.pi))]
    return NamedPolynomial.parse(text, names, "equation")


def _held_elsewhere(ctx: SearchContext, holder: Component, kind: str,
                    searched: bool) -> None:
    """A set found inside ``holder`` (with its numbers) is not recorded again; when
    ``holder`` was found in a chart with other joints at pi, the drops inside the set
    here are not reached by the search inside ``holder`` in its own chart: said, unless
    the caller searches inside the set here (``searched``) or it is a point."""
    beyond = sorted(ctx.pi - set(holder.chart))
    if beyond and not searched and kind != "isolated":
        add_once(ctx.locus.unexplored, Remark.of(
            "pi_inside_not_searched", component=ctx.locus.components.index(holder),
            joints=tuple(beyond)))


def _vanish_at(ctx: SearchContext, comp: Component, point: dict, quotient) -> bool:
    """Whether ``comp`` holds at the generic point given by the parametrization
    ``point`` and, when not None, the ``quotient`` by an irreducible polynomial: every
    equation of ``comp`` vanishes there and no polynomial of its ``outside`` does.
    ``comp`` is recorded in this chart or, inside a family with no rational
    parametrization (``ctx.inside``), in one whose joints at pi are at pi here too and
    whose equations are polynomials of this chart (they hold here as they are)."""
    other = ctx.owners.get(id(comp)) if ctx.owners is not None else None
    if other is None or (other is not ctx and not (ctx.inside and other.pi <= ctx.pi)):
        return False
    at_pi = {cotangent_name(n) for n in other.pi}

    def here(text: str):
        p = other.polys.get(text)
        if p is not None and other is not ctx:
            p = _transfer(p, other, ctx)
        return None if p is None else _on_chain(p, ctx, point)

    def zero(p) -> bool:
        return p.is_zero() or (quotient is not None and quotient.is_zero(p))

    for eq in comp.equations:
        if eq.text in at_pi:
            continue
        p = here(eq.text)
        if p is None or not zero(p):
            return False
    for out in comp.outside:   # where a denominator of its parametrization vanishes,
        p = here(out.text)     # the component does not hold
        if p is None or zero(p):
            return False
    return True


def beyond_chart(ctx: SearchContext, equations: list[str]) -> list[str]:
    """The equations other than those of the chart (``s_<joint>`` for the joints at
    q = pi here)."""
    chart = {cotangent_name(n) for n in ctx.pi}
    return [e for e in equations if e not in chart]


def _denominators(ctx: SearchContext, chain: dict | None, equations: list[str]) -> list[str]:
    """The irreducible factors of the denominators of a linear parametrization: its
    image is the set where the equations hold and none of them vanishes (where one
    does, the equations may hold on a wider set, searched apart by
    :func:`~.codimension.where_parametrization_fails`). None for one irreducible
    equation (in a chart): its zero set is the closure of that image."""
    if len(beyond_chart(ctx, equations)) <= 1:
        return []
    out: list[str] = []
    for _f0, f1 in (chain or {}).values():
        if f1.is_constant():
            continue
        factored = bounded_factor(ctx, f1)      # too large: f1 itself, the same zeros
        for g, _e in (factored[1] if factored is not None else [(f1, 1)]):
            g = normalize(g)
            if g.is_constant() or no_real_points(ctx, g):
                continue
            text = poly_text(ctx, g)
            if text not in out:
                out.append(text)
    return out


def _on_chain(p, ctx, chain: dict):
    """``p`` on the set parametrized by ``chain`` (denominators cleared): zero exactly
    when ``p`` vanishes on that set."""
    for name, (f0, f1) in chain.items():
        k = ctx.ring_names.index(name)
        if p.degrees()[k]:
            p = substitute(p, k, f0, f1, p.degrees()[k])
    return p


def _contained(ctx: SearchContext, inner: dict, outer: dict) -> bool:
    """Whether the set of chain ``inner`` lies in the set of chain ``outer`` (both in
    the variables of ``ctx``): every relation ``f1 x + f0`` of ``outer`` vanishes on
    ``inner``, and no denominator ``f1`` of ``outer`` does."""
    gens = ctx.ring.zctx.gens()
    for name, (f0, f1) in outer.items():
        relation = f1 * gens[ctx.ring_names.index(name)] + f0
        if not _on_chain(relation, ctx, inner).is_zero():
            return False
        if not f1.is_constant() and _on_chain(f1, ctx, inner).is_zero():
            return False
    return True


def wider_component(ctx: SearchContext, chain: dict, numbers: Numbers) -> Component | None:
    """A component with the same numbers, recorded in a chart with fewer joints at pi,
    that contains the set of ``chain`` (in a chart with joints at pi) because its
    equations do not involve the joints at pi here (so they hold there as they are);
    None when there is none."""
    if not ctx.pi:
        return None
    here = numbers.as_dict()
    for comp in ctx.locus.components:
        known = ctx.chains.get(id(comp))
        if known is None or comp.numbers != here:
            continue
        other, other_chain = known
        if other is ctx or not other.pi < ctx.pi:
            continue
        relations = []
        for name, (f0, f1) in other_chain.items():
            x = other.ring.zctx.gens()[other.ring_names.index(name)]
            relations.append((f1 * x + f0, f1))
        moved = [(_transfer(r, other, ctx), _transfer(d, other, ctx)) for r, d in relations]
        if any(r is None or d is None for r, d in moved):
            continue
        if all(_on_chain(r, ctx, chain).is_zero() and
               (d.is_constant() or not _on_chain(d, ctx, chain).is_zero())
               for r, d in moved):
            return comp
    return None


def recorded_elsewhere(ctx: SearchContext, equations: list[str], numbers: Numbers,
                       point: dict, quotient) -> Component | None:
    """The component, recorded in another chart with the same numbers, that holds the
    set of ``equations`` (its equations are among them) or its generic point (the
    parametrization ``point`` and the ``quotient``, as in :func:`_new_component`);
    None when there is none. The set is then not recorded again, but what lies inside
    it in this chart (at the joints at pi here) is searched here."""
    if quotient is None and (wider := wider_component(ctx, point, numbers)) is not None:
        return wider
    if ctx.owners is None:
        return None
    here = numbers.as_dict()
    mine = frozenset(_named(ctx, text) for text in equations)
    for comp in ctx.locus.components:
        if comp.numbers != here or ctx.owners.get(id(comp)) in (None, ctx):
            continue
        if (comp.equations and _equation_set(ctx, comp) <= mine) or _vanish_at(
                ctx, comp, point, quotient):
            return comp
    return None


def _transfer(p, source, target):
    """``p`` from the ring of context ``source`` to that of ``target`` by variable
    names (None when it uses a variable ``target`` does not have)."""
    index = {n: i for i, n in enumerate(target.ring_names)}
    terms = {}
    for mon, c in p.to_dict().items():
        new = [0] * len(target.ring_names)
        for name, e in zip(source.ring_names, mon, strict=True):
            if e:
                if name not in index:
                    return None
                new[index[name]] = int(e)
        terms[tuple(new)] = int(c)
    return target.ring.zctx.from_dict(terms)


def _within(ctx: SearchContext, chain: dict, other: Component, numbers: Numbers) -> bool:
    """Whether the set of ``chain`` lies in component ``other`` of the same chart with
    the same numbers (then it adds nothing: drops deeper inside it are deeper inside
    ``other`` and searched there)."""
    known = ctx.chains.get(id(other))
    if known is None or known[0] is not ctx or other.numbers != numbers.as_dict():
        return False
    return _contained(ctx, chain, known[1])


def angle_condition(ctx: SearchContext, equations: list[str]) -> Condition:
    """The equations in angles where they read simply (see
    :func:`~coopkin_sym.analysis.locus.algebra.read_poly`)."""
    return Condition.of(*(ctx.readings.get(eq) or Vanishes(_named(ctx, eq))
                          for eq in equations))


def settle_realness(ctx: SearchContext) -> None:
    """A component is called real only with a real witness (rational, or algebraic in
    an isolating interval); one without is marked as undecided, never as real (those
    proved to have no real points were dropped when found)."""
    for c in ctx.locus.components:
        c.real = c.witness is not None or c.algebraic_witness is not None
        c.real_points = "witness" if c.real else "undecided"
