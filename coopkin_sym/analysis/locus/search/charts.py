"""Charts: the ring and rows of ``Q`` for a configuration's free joints, and the slices
at ``q = pi`` (``t = oo``, outside the t chart) searched joint set by joint set.
"""

from __future__ import annotations

import dataclasses
import itertools
from collections.abc import Iterator, Sequence

import sympy as sp

from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.decomposition import attains
from coopkin_sym.analysis.locus.conditions import Condition, Value
from coopkin_sym.analysis.locus.context import Place, SearchContext
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.locus.search.components import _new_component, wider_component
from coopkin_sym.analysis.locus.witness import (
    attach_witness,
    complete_point,
    numbers_at_values,
    to_at,
)
from coopkin_sym.analysis.mobility import decompose
from coopkin_sym.exact.angles import ExactAngle, cotangent_name, tangent_name
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model

#: The share of the progress bar a slice at q = pi searched inside gets, against 1 for
#: a slice whose numbers alone are decided.
PI_SEARCH_WEIGHT = 20


def chart_of(model: Model, config: Configuration) -> tuple[dict, list]:
    """The fields of a :class:`SearchContext` that belong to the chart of ``config``
    (its free joints and parameters are the variables), and the cleared rows of Q
    there."""
    kin = kinematics.build(model, config)
    ring = kin.ring
    q_rows = [ring.clear_row(row) for row in kin.Q]
    kinds: dict[str, tuple[str, str]] = {}
    for j in model.joints:
        if j.name in config.free:
            kinds[tangent_name(j.name) if j.type == "revolute" else j.name] = (j.type, j.name)
    for p in model.parameters:
        if p.name not in config.parameters:
            kinds[p.name] = ("parameter", p.name)
    chart = {"config": config, "ring_names": ring.names, "kinds": kinds,
             "row_contacts": kin.row_contacts, "symbols": kin.symbols, "ring": ring,
             "rows0": q_rows, "kin": kin}
    return chart, q_rows


def slice_chart(ctx: SearchContext, config: Configuration, joints: Sequence[str]
                ) -> tuple[dict, list]:
    """:func:`chart_of` for the slice ``config`` of the chart of ``ctx`` with ``joints``
    at pi: its ``Q`` is the limit of the chart's (:func:`kinematics.q_at_pi`), and its
    kinematics (``kin``) is built only where a witness needs it."""
    at = kinematics.q_at_pi(ctx.kin, joints) if ctx.kin is not None else None
    if at is None:
        return chart_of(ctx.model, config)
    ring, symbols, Q = at
    q_rows = [ring.clear_row(row) for row in Q]
    chart = {"config": config, "ring_names": ring.names,
             "kinds": {v: k for v, k in ctx.kinds.items() if v in ring.names},
             "row_contacts": ctx.row_contacts, "symbols": symbols, "ring": ring,
             "rows0": q_rows, "kin": None}
    return chart, q_rows


def pi_slices(ctx: SearchContext, pi_size: int | None = None) -> None:
    """Every subset of the free revolute joints at q = pi, where t = tan(q/2) is
    infinite: each slice is a system in the other variables, searched like the t chart
    (its generic numbers, and every drop inside it, at every depth). A component there
    has the equations ``s_<joint>`` (``s = cot(q/2) = 0``) for the joints at pi.
    ``pi_size``: the largest set of joints at pi searched inside (None: all); larger
    sets get their own numbers decided and a note."""
    rev = revolute_joints(ctx)
    total = 2 ** len(rev) - 1
    for k, subset in enumerate(pi_subsets(rev)):
        where = ", ".join(f"{n} = pi" for n in subset)
        ctx.reporter.step(where)
        if ctx.expired():   # one remark for this set and the ones after it
            left = total - k - 1
            ctx.locus.unexplored.append(
                Remark.of("time_pi_sets_left", joints=subset, left=left) if left else
                Remark.of("time_pi_set", joints=subset))
            break
        revolute = dict(ctx.config.revolute)
        for n in subset:
            revolute[n] = ExactAngle(1, 0)
        config = Configuration(revolute, ctx.config.prismatic, ctx.config.parameters,
                               ctx.config.free - set(subset))
        chart, rows = slice_chart(ctx, config, subset)
        sub = dataclasses.replace(ctx, **chart, pi=frozenset(subset), hidden=0, splits=0,
                                  deferred=[], polys={}, searched=set(), inside=0)
        equations = [cotangent_name(n) for n in subset]
        for n in subset:
            ctx.readings[cotangent_name(n)] = Value(n, sp.pi, "revolute")
        # the slice's ranks are at most the chart's: reaching them at a point proves them
        numbers = ctx.generic if attains(rows, ctx.model, ctx.generic) else decompose(
            rows, ctx.model, sub.row_contacts, sub.ring.zctx).numbers
        parent, depth = None, 0
        wider = wider_component(sub, {}, numbers)
        if wider is not None:  # the slice lies in a component of a wider chart
            parent, depth = ctx.locus.components.index(wider), 1
        elif numbers != ctx.generic:
            kind = "chart" if sub.ring_names else "isolated"
            comp = _new_component(sub, Place(rows=rows, equations=[], point={}, depth=0),
                                  equations, numbers, kind, {"Q"},
                                  Remark.of("decided_other_variables" if sub.ring_names
                                            else "decided_at_point"),
                                  condition=Condition.of(*(Value(n, sp.pi, "revolute")
                                                           for n in subset)))
            for offset in range(6):
                values = complete_point(sub, {}, {}, offset)
                if values is not None and numbers_at_values(sub, values) == numbers:
                    attach_witness(sub, comp, to_at(sub, values), numbers)
                    break
            ctx.chains[id(comp)] = (sub, {})
            parent, depth = ctx.locus.components.index(comp), 1
        if not sub.ring_names:
            continue
        if depth > ctx.max_depth:
            ctx.locus.unexplored.append(Remark.of("pi_deeper_not_explored", joints=subset,
                                                  bound=ctx.max_depth))
            continue
        if pi_size is not None and len(subset) > pi_size:
            ctx.locus.unexplored.append(Remark.of(
                "pi_set_not_searched", joints=subset, deeper=parent is not None,
                bound=pi_size))
            continue
        ctx.steps.explore(sub, Place(rows=rows, equations=equations, point={}, depth=depth,
                                     parent=parent, base=numbers))
    if rev:
        ctx.locus.notes.append(Remark.of("pi_chart"))


def revolute_joints(ctx: SearchContext) -> list[str]:
    """The free revolute joints of the chart."""
    return [name for kind, name in ctx.kinds.values() if kind == "revolute"]


def pi_subsets(rev: list[str]) -> Iterator[tuple[str, ...]]:
    """Every non-empty set of the joints ``rev`` (the slices at q = pi), smallest first,
    one at a time (there are ``2^r - 1``)."""
    for size in range(1, len(rev) + 1):
        yield from itertools.combinations(rev, size)


def default_pi_size(ctx: SearchContext) -> int | None:
    """How many joints at pi at once are searched inside by default: every set for up
    to four free revolute joints, then fewer as the number of sets grows (2^r - 1)."""
    rev = sum(1 for kind, _ in ctx.kinds.values() if kind == "revolute")
    return None if rev <= 4 else 2 if rev <= 6 else 1 if rev <= 8 else 0
