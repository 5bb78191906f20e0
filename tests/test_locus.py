"""Singularity loci, exactly: paper case 1 and a constructed codimension-2 example."""

from __future__ import annotations

import json

import pytest
import sympy as sp
import yaml
from independent import at_from_text, reference_analysis
from sympy.polys.matrices import DomainMatrix

import coopkin_sym
import coopkin_sym.examples
from coopkin_sym.locus import LocusError, compute_locus

CASE1_GENERIC = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
# both links on the contact line: the object gains a rotation about z (checked by
# hand in tests/test_mobility.py::test_singular_configuration_found_exactly)
CASE1_ON_LINE = {"Nm": 3, "Nc": 3, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 1}
# c1 and c2 at the same point: two point contacts make a spherical joint, so with the
# joints locked the object can still turn about that point (Ni = 3)
CASE1_COINCIDENT = {"Nm": 3, "Nc": 3, "Ni": 3, "Nr": 0, "Ng": 3, "Nd": 4, "Nh": 1}
ON_LINE = {("t_q1 - 1", "t_q2 - 1"), ("t_q1 - 1", "t_q2 + 1"), ("t_q1 + 1", "t_q2 - 1"),
           ("t_q1 + 1", "t_q2 + 1")}
COINCIDENT = ("t_q1 + t_q2", "t_q1**2 + 4*t_q1 + 1")


@pytest.fixture(scope="module")
def case1():
    return compute_locus(coopkin_sym.load("paper-case1-hard"))


def test_case1_finds_exactly_the_five_isolated_families(case1):
    # hand check: c1 = L(-sin q1, cos q1), c2 = L(1 - sin q2, cos q2).
    # * both links along the contact line x: q1, q2 = +-pi/2 (four points);
    # * c1 = c2: cos q1 = cos q2 and sin q2 - sin q1 = 1, so q2 = -q1 and
    #   sin q1 = -1/2: q1 = -pi/6 or -5pi/6, i.e. t1 = tan(q1/2) = -2 +- sqrt(3), the
    #   roots of t^2 + 4t + 1, with t2 = -t1. No rational point: decided over Q(sqrt 3).
    assert case1.generic == CASE1_GENERIC
    found = {tuple(sorted(c.equations)): c for c in case1.components}
    assert set(found) == ON_LINE | {COINCIDENT}
    for key, c in found.items():
        assert c.kind == "isolated" and c.real and c.witness_checked
        if key in ON_LINE:
            assert c.numbers == CASE1_ON_LINE
            assert c.changes == {"Nm": (2, 3), "Nc": (2, 3), "Nh": (0, 1)}
    c = found[COINCIDENT]
    assert c.numbers == CASE1_COINCIDENT
    assert c.condition == "q1 = -5*pi/6, q2 = 5*pi/6 or q1 = -pi/6, q2 = pi/6"
    assert c.decided.startswith("exact over Q(alpha), alpha = t_q1 a root of "
                                "alpha**2 + 4*alpha + 1")
    assert c.witness is None  # no rational point (DESIGN: witness only when rational)
    w = c.algebraic_witness
    assert w["point"] == {"L": "1", "q1": "-5*pi/6", "q2": "5*pi/6"}
    assert w["root"] == "-2 - sqrt(3)" and w["root_of"] == "alpha**2 + 4*alpha + 1"
    assert c.meaning[2].startswith("Ni = 3")


def _ranks_over_the_algebraic_numbers(q: sp.Matrix) -> tuple[int, int, int]:
    """Ranks of Q, H G^T and H D in the smallest number field holding the entries."""
    def rank(m):
        return DomainMatrix.from_Matrix(m, extension=True).rank()
    return rank(q), rank(q[:, :6]), rank(q[:, 6:])


def test_case1_witnesses_are_confirmed_by_an_independent_analysis(case1):
    model = yaml.safe_load(coopkin_sym.examples.example_path(
        "paper-case1-hard").read_text())
    conditions = set()
    for c in case1.components:
        if c.witness is not None:
            assert set(c.witness) == {"q1", "q2", "L"}
            assert c.witness["q1"] in ("pi/2", "-pi/2")
            assert c.witness["q2"] in ("pi/2", "-pi/2")
            ref = reference_analysis(model, at_from_text(model, ",".join(
                f"{k}={v}" for k, v in c.witness.items())))
            assert {k: ref[k] for k in c.numbers} == c.numbers
            conditions.add(c.condition)
            continue
        # the irrational witness, and the other real point of the family, in radicals
        for q1, q2 in ((-5 * sp.pi / 6, 5 * sp.pi / 6), (-sp.pi / 6, sp.pi / 6)):
            ref = reference_analysis(model, {"q1": (sp.cos(q1), sp.sin(q1)),
                                             "q2": (sp.cos(q2), sp.sin(q2)), "L": 1})
            rq, rg, rd = _ranks_over_the_algebraic_numbers(ref["Q"])
            assert (rq, rg, rd) == (5, 3, 2)          # Nm = 8 - 5, Ni = 6 - 3, Nr = 0
            assert c.numbers["Nm"] == 8 - rq and c.numbers["Ni"] == 6 - rg
    assert "q1 = -pi/2, q2 = -pi/2" in conditions


def test_case1_drops_non_real_factors_and_leaves_nothing_unexplored(case1):
    assert "t_q1**2 + 1 = 0 (no real points)" in case1.dropped
    assert case1.unexplored == []
    assert any("L = 1" in n for n in case1.notes)


def test_float_rank_tests_fail_near_the_locus_with_rescaled_lengths(case1):
    summary = case1.float_summary()
    assert summary["false_singular"] > 0
    bad = [(c, f) for c in case1.components for f in c.float_checks if not f.agree]
    # every disagreement is 1e-12 rad from a singular configuration, lengths rescaled:
    # numpy calls a regular configuration singular, with the numbers of the component
    assert bad and all(f.distance == 1e-12 and f.scale in ("L=1/1000", "L=1000")
                       for _, f in bad)
    # floats see motions that are not there (larger Nm or Ni), mostly the component's
    assert all(f.exact == CASE1_GENERIC for _, f in bad)
    assert all(f.float["Nm"] > 2 or f.float["Ni"] > 1 for _, f in bad)
    assert sum(f.float == c.numbers for c, f in bad) >= len(bad) - 1
    assert len(bad) == summary["false_singular"] == 10
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
