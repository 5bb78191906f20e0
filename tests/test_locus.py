"""Singularity loci, exactly: paper case 1 and a constructed codimension-2 example."""

from __future__ import annotations

import json

import pytest

import coopkin_sym
from coopkin_sym.locus import LocusError, compute_locus

CASE1_GENERIC = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
# both links on the contact line: the object gains a rotation about z (checked by
# hand in tests/test_mobility.py::test_singular_configuration_found_exactly)
CASE1_ON_LINE = {"Nm": 3, "Nc": 3, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 1}


@pytest.fixture(scope="module")
def case1():
    return compute_locus(coopkin_sym.load("paper-case1-hard"))


def test_case1_finds_exactly_the_four_isolated_configurations(case1):
    assert case1.generic == CASE1_GENERIC
    found = {tuple(sorted(c.equations)): c for c in case1.components}
    expected = {("t_q1 - 1", "t_q2 - 1"), ("t_q1 - 1", "t_q2 + 1"),
                ("t_q1 + 1", "t_q2 - 1"), ("t_q1 + 1", "t_q2 + 1")}
    assert set(found) == expected
    for c in case1.components:
        assert c.kind == "isolated" and c.real
        assert c.numbers == CASE1_ON_LINE
        assert c.changes == {"Nm": (2, 3), "Nc": (2, 3), "Nh": (0, 1)}
        assert c.witness_checked


def test_case1_witnesses_are_exact_and_confirmed_by_a_direct_analysis(case1):
    system = coopkin_sym.load("paper-case1-hard")
    conditions = set()
    for c in case1.components:
        assert set(c.witness) == {"q1", "q2", "L"}
        assert c.witness["q1"] in ("pi/2", "-pi/2") and c.witness["q2"] in ("pi/2", "-pi/2")
        direct = system.analyze(",".join(f"{k}={v}" for k, v in c.witness.items()))
        assert direct.numbers.as_dict() == c.numbers
        conditions.add(c.condition)
    assert "q1 = -pi/2, q2 = -pi/2" in conditions


def test_case1_drops_non_real_factors_and_states_its_limits(case1):
    assert "t_q1**2 + 1 = 0 (no real points)" in case1.dropped
    # the configurations where c1 and c2 coincide have irrational coordinates
    assert "real points with irrational coordinates (t_q1**2 + 4*t_q1 + 1 = 0): numbers " \
        "not decided" in case1.unexplored
    assert any("L = 1" in n for n in case1.notes)


def test_float_rank_tests_fail_near_the_locus_with_rescaled_lengths(case1):
    summary = case1.float_summary()
    assert summary["false_singular"] > 0
    bad = [f for c in case1.components for f in c.float_checks if not f.agree]
    # every disagreement is 1e-12 rad from a singular configuration, lengths rescaled:
    # numpy calls a regular configuration singular
    assert bad and all(f.distance == 1e-12 and f.scale in ("L=1/1000", "L=1000")
                       for f in bad)
    assert all(f.exact == CASE1_GENERIC and f.float["Nm"] == 3 for f in bad)
    # at the singular configurations themselves floats agree
    assert all(f.agree for c in case1.components for f in c.float_checks if f.distance == 0)


def test_json_contract(case1):
    data = json.loads(json.dumps(case1.to_json()))
    assert data["generic"] == CASE1_GENERIC
    for comp in data["components"]:
        assert {"equations", "numbers", "witness", "real"} <= set(comp)
        assert isinstance(comp["equations"], list) and comp["real"] is True


TWO_FINGERS = {
    "name": "two planar 2R fingers", "parameters": ["L"],
    "arms": [
        {"name": "f1", "joints": [
            {"name": "a1", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]},
            {"name": "a2", "type": "revolute", "axis": [0, 0, 1], "point": [0, "L", 0]}]},
        {"name": "f2", "joints": [
            {"name": "b1", "type": "revolute", "axis": [0, 0, 1], "point": ["3*L", 0, 0]},
            {"name": "b2", "type": "revolute", "axis": [0, 0, 1],
             "point": ["3*L", "L", 0]}]}],
    "contacts": [
        {"name": "c1", "link": "f1/2", "point": [0, "2*L", 0], "normal": [1, 0, 0],
         "model": "hard"},
        {"name": "c2", "link": "f2/2", "point": ["3*L", "2*L", 0], "normal": [-1, 0, 0],
         "model": "hard"}]}


def test_recursion_finds_the_codimension_two_drop():
    locus = compute_locus(coopkin_sym.load(TWO_FINGERS), max_depth=2)
    by_eqs = {tuple(c.equations): c for c in locus.components}
    # one finger stretched straight: it can no longer move its tip along itself
    a2 = by_eqs[("t_a2",)]
    assert a2.kind == "hypersurface" and a2.condition == "a2 = 0"
    assert a2.changes == {"Nc": (4, 3), "Nr": (0, 1), "Nd": (2, 3)}
    # both stretched: found inside the first component (depth 1, codimension 2)
    both = by_eqs[("t_a2", "t_b2")]
    assert both.depth == 1 and both.parent == locus.components.index(a2)
    assert both.changes == {"Nc": (4, 2), "Nr": (0, 2), "Nd": (2, 4)}
    # and deeper still: both stretched along the contact line (isolated, depth 2)
    deepest = [c for c in locus.components if c.depth == 2]
    assert len(deepest) == 4 and all(c.numbers["Nm"] == 5 for c in deepest)
    # q = pi, outside the t chart: the finger folded back is singular too
    assert {c.condition for c in locus.components if c.kind == "chart"} == {
        "a2 = pi", "b2 = pi"}
    assert all(c.witness_checked for c in locus.components)


def test_max_depth_bounds_the_search_and_says_so():
    locus = compute_locus(coopkin_sym.load(TWO_FINGERS), max_depth=0)
    assert all(c.depth == 0 for c in locus.components)
    assert any("max depth 0" in u for u in locus.unexplored)


def test_a_locus_needs_a_free_joint():
    with pytest.raises(LocusError, match="free joint"):
        compute_locus(coopkin_sym.load("paper-case1-hard"), at="q1=0,q2=0")
