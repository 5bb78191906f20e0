"""The seams of the locus search, each on its own: charts, candidate hypersurfaces,
curved families, codimension two and points, and the recursion that joins them.

Each test starts from :func:`search_context` (the state a search starts from) and runs
one seam, then checks its exact output against the whole search's."""

from __future__ import annotations

import pytest
from support import texts

from coopkin_sym import load
from coopkin_sym.analysis.locus.algebra import normalize
from coopkin_sym.analysis.locus.context import Place
from coopkin_sym.analysis.locus.search import compute_locus, search_context
from coopkin_sym.analysis.locus.search.charts import (
    chart_of,
    default_pi_size,
    pi_subsets,
    revolute_joints,
)
from coopkin_sym.analysis.locus.search.codimension import isolated
from coopkin_sym.analysis.locus.search.curved import nonlinear_factor
from coopkin_sym.analysis.locus.search.hypersurface import candidates
from coopkin_sym.analysis.locus.search.recursion import STEPS, explore
from coopkin_sym.exact.factoring import factor

CASE1_POINTS = [["t_q1 + 1", "t_q2 + 1"], ["t_q1 + 1", "t_q2 - 1"],
                ["t_q1 - 1", "t_q2 + 1"], ["t_q1 - 1", "t_q2 - 1"],
                ["t_q1**2 + 4*t_q1 + 1", "t_q1 + t_q2"]]


def _start(name: str, max_depth: int = 0):
    ctx, rows = search_context(load(name), max_depth=max_depth)
    return ctx, rows, Place(rows=rows, equations=[], point={}, depth=0)


def test_charts_list_every_joint_set_at_pi_and_the_rows_of_q():
    ctx, rows, _ = _start("paper-case1-hard")
    assert revolute_joints(ctx) == ["q1", "q2"]
    assert list(pi_subsets(revolute_joints(ctx))) == [("q1",), ("q2",), ("q1", "q2")]
    assert default_pi_size(ctx) is None          # two joints: every set searched inside
    chart, again = chart_of(ctx.model, ctx.config)
    assert chart["ring_names"] == ("t_q1", "t_q2") == ctx.ring_names
    assert [[str(e) for e in row] for row in again] == [[str(e) for e in row] for row in rows]
    assert len(rows) == 6


def test_candidate_hypersurfaces_are_the_hypersurface_components():
    """The common factors of each block's minor combinations (and the contents taken
    out) are exactly the hypersurface components the search reports."""
    ctx, rows, _ = _start("paper-case1-complete-hard")
    cands = candidates(ctx, rows)
    assert set(cands) == {"HD:a2", "Y:a2", "content:A"}
    factors = set()
    for polys in cands.values():
        g = polys[0]
        for p in polys[1:]:
            g = g.gcd(p)
        factors |= {str(normalize(f)) for f, _ in factor(g)[1] if not f.is_constant()}
    assert factors == {"t_q2 + 1", "t_q2 - 1"}
    found = compute_locus(load("paper-case1-complete-hard"), max_depth=0)
    assert sorted(texts(c.equations)[0] for c in found.components
                  if c.kind == "hypersurface") == ["t_q2 + 1", "t_q2 - 1"]


def test_codimension_two_finds_the_isolated_points_of_case_1():
    """The points where both links of paper case 1 lie on the contact line, found
    from the minor combinations alone (no hypersurface there)."""
    ctx, rows, place = _start("paper-case1-hard")
    place = place.inside(base=ctx.generic)
    rests = [polys for polys in candidates(ctx, rows).values()]
    isolated(ctx, place, rests)
    assert sorted(texts(c.equations) for c in ctx.locus.components) == sorted(CASE1_POINTS)
    assert {c.kind for c in ctx.locus.components} == {"isolated"}
    assert all(c.changes["Nm"] == (2, 3) for c in ctx.locus.components)


def test_a_curved_family_is_decided_modulo_its_polynomial():
    """The five-bar's elbow family t_q2^2 + 2 t_q2 - 1 = 0 is linear in no variable:
    its numbers come from ranks modulo it, equal to the whole search's."""
    ctx, rows, place = _start("five-bar")
    place = place.inside(base=ctx.generic)
    f = ctx.ring.zctx.gens()[ctx.ring_names.index("t_q2")]
    family = f ** 2 + 2 * f - 1
    nonlinear_factor(ctx, place, family, "t_q2**2 + 2*t_q2 - 1", {"HD"})
    (comp,) = ctx.locus.components
    assert texts(comp.equations) == ["t_q2**2 + 2*t_q2 - 1"] and comp.kind == "hypersurface"
    assert comp.decided.kind == "decided_modulo_family"
    assert comp.numbers == {"Nm": 3, "Nc": 2, "Ni": 0, "Nr": 1, "Ng": 1, "Nd": 1, "Nh": 0}
    assert ctx.generic.as_dict()["Nr"] == 0


@pytest.mark.parametrize("name", ["paper-case1-hard", "paper-case1-complete-hard"])
def test_the_recursion_joins_the_seams_into_the_t_chart_locus(name):
    """Exploring depth 0 gives the whole search's components in the t chart."""
    ctx, rows, place = _start(name)
    explore(ctx, place)
    whole = compute_locus(load(name), max_depth=0)
    assert [texts(c.equations) for c in ctx.locus.components] == [
        texts(c.equations) for c in whole.components if c.kind != "chart"]
    assert ctx.steps is STEPS


def test_the_slices_at_pi_are_counted_not_listed():
    """Thirty free revolute joints have 2^30 - 1 slices at q = pi: the progress weights
    stop at a cap and the slices come one at a time (a list of them would not fit in
    memory)."""
    from coopkin_sym.analysis.locus.search import MAX_PI_PARTS, _pi_weights

    assert _pi_weights(2, None) == [20, 20, 20]
    assert _pi_weights(3, 1) == [20, 20, 20, 1, 1, 1, 1]
    assert len(_pi_weights(30, 2)) == MAX_PI_PARTS
    subsets = pi_subsets([f"q{k}" for k in range(30)])
    assert next(subsets) == ("q0",) and next(subsets) == ("q1",)
