"""Components come in a canonical order (depth first down the tree of parents,
siblings sorted by kind, equations): the report does not depend on the order the
search found them in."""

from __future__ import annotations

import copy
import random

import pytest
from support import texts

from coopkin_sym import load
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.locus.types import (
    Component,
    Locus,
    _renumbered,
    canonical_order,
    ended_at_bound,
)
from coopkin_sym.errors import TimeLimitReached
from coopkin_sym.present.report import render_json, render_markdown


def _shuffled(locus: Locus, seed: int) -> Locus:
    """The same locus with its components in a random order (parents and the indices
    in remarks renumbered to match)."""
    out = copy.deepcopy(locus)
    order = list(range(len(out.components)))
    random.Random(seed).shuffle(order)
    new = {old: i for i, old in enumerate(order)}
    out.components = [out.components[k] for k in order]
    for c in out.components:
        if c.parent is not None:
            c.parent = new[c.parent]
    for name in ("parameter_conditions", "dropped", "unexplored", "notes"):
        setattr(out, name, [_renumbered(r, new) for r in getattr(out, name)])
    return out


def _tree() -> Locus:
    generic = {"Nm": 2}
    comps = [Component(["t_q1"], {"Nm": 3}, None, True),
             Component(["t_q1", "t_q2"], {"Nm": 4}, None, True, kind="isolated", depth=1,
                       parent=0),
             Component(["t_q1", "t_q2 - 1"], {"Nm": 4}, None, True, kind="isolated",
                       depth=1, parent=0),
             Component(["t_q2**2 + 4*t_q2 + 1"], {"Nm": 3}, None, True),
             Component(["s_q1"], {"Nm": 3}, None, True, kind="chart")]
    notes = [Remark.of("deeper_not_explored", component=2, condition="", reason="max_depth",
                       bound=2), Remark.of("pi_chart")]
    return Locus("demo", ["t_q1", "t_q2"], "", generic, comps, unexplored=notes)


@pytest.mark.parametrize("name", ["paper-case1-hard", "paper-case1-soft-hard",
                                  "paper-case1-planar"])
def test_shuffled_components_give_the_same_report(name):
    locus = load(name).locus()
    assert canonical_order(locus) == list(range(len(locus.components)))  # already so
    expected = render_json(locus), render_markdown(locus)
    for seed in range(3):
        shuffled = _shuffled(locus, seed)
        canonical_order(shuffled)
        assert (render_json(shuffled), render_markdown(shuffled)) == expected


def test_the_order_of_a_tree_and_its_remarks():
    locus = _tree()
    assert canonical_order(locus) == [0, 1, 2, 3, 4]
    for seed in range(5):
        shuffled = _shuffled(_tree(), seed)
        canonical_order(shuffled)
        assert shuffled == locus
    shuffled = _shuffled(_tree(), 1)
    canonical_order(shuffled)
    assert shuffled.unexplored[0]["component"] == 2
    assert [texts(c.equations) for c in shuffled.components] == [
        ["t_q1"], ["t_q1", "t_q2"], ["t_q1", "t_q2 - 1"], ["t_q2**2 + 4*t_q2 + 1"], ["s_q1"]]
    assert [c.parent for c in shuffled.components] == [None, 0, 0, None, None]


def test_a_locus_cut_at_its_bound_comes_in_the_canonical_order_too():
    for seed in range(3):
        exc = TimeLimitReached(5.0, "a resultant", hard=True)
        exc.kept = _shuffled(_tree(), seed)
        cut = ended_at_bound(exc)
        assert [texts(c.equations) for c in cut.components] == [
            ["t_q1"], ["t_q1", "t_q2"], ["t_q1", "t_q2 - 1"], ["t_q2**2 + 4*t_q2 + 1"],
            ["s_q1"]]
        assert [c.parent for c in cut.components] == [None, 0, 0, None, None]
        assert [r.kind for r in cut.unexplored] == ["deeper_not_explored", "pi_chart",
                                                    "time_whole_run"]
