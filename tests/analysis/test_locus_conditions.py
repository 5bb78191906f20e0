"""Conditions of locus components are exact data: written as text and LaTeX from the
data, read back equal (from the text and from the JSON), on the shipped loci and on
random conditions."""

from __future__ import annotations

import json

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from support import shipped_locus

from coopkin_sym.analysis.locus.conditions import (
    Condition,
    Related,
    Value,
    Vanishes,
    chains,
)
from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.exact.angles import ExactAngle, joint_of
from coopkin_sym.exact.polynomial import NamedPolynomial
from coopkin_sym.present.conditions import condition_text, short_condition
from coopkin_sym.present.report import locus_from_json, render_json

GENERIC = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
SHIPPED = ["paper-case1-hard", "paper-case1-soft-hard", "paper-case1-planar",
           "paper-case1-complete-hard"]


@pytest.mark.parametrize("name", SHIPPED)
def test_shipped_conditions_are_data_that_read_back_equal(name):
    locus = shipped_locus(name)
    kinds = {joint_of(v): "revolute" for v in locus.variables if joint_of(v)}
    assert locus.components
    for c in locus.components:
        assert isinstance(c.condition, Condition) and c.condition
        assert all(isinstance(e, NamedPolynomial) for e in c.equations)
        # the text is the exact notation: read back, the same data
        assert Condition.parse(c.condition.text, kinds) == c.condition
        # every clause is written in LaTeX as mathematics, never as typed text
        assert "texttt" not in short_condition(c).tex
    back = locus_from_json(render_json(locus))
    assert [c.condition for c in back.components] == [c.condition for c in locus.components]


def test_case1_algebraic_family_is_two_alternatives_of_exact_angles():
    locus = shipped_locus("paper-case1-hard")
    (c,) = [c for c in locus.components
            if c.condition.text == "q1 = -5*pi/6, q2 = 5*pi/6 or q1 = -pi/6, q2 = pi/6"]
    first, second = c.condition.alternatives
    assert first == (Value("q1", -5 * sp.pi / 6, "revolute"),
                     Value("q2", 5 * sp.pi / 6, "revolute"))
    assert second == (Value("q1", -sp.pi / 6, "revolute"), Value("q2", sp.pi / 6, "revolute"))


def test_the_four_relations_of_two_angles_in_text_and_latex():
    comp = Component(["t_a - t_b"], {}, None, True)
    shown = []
    for sign in (1, -1):
        for plus_pi in (False, True):
            comp.condition = Condition.of(Related("a", "b", sign, plus_pi))
            shown.append((condition_text(comp), condition_text(comp).tex))
    assert shown == [("a = b", "$a = b$"),
                     ("a = b + pi (mod 2*pi)", r"$a = b + \pi \pmod{2\pi}$"),
                     ("a = -b", "$a = -b$"),
                     ("a + b = pi (mod 2*pi)", r"$a + b = \pi \pmod{2\pi}$")]


def test_long_values_are_rounded_for_people_and_kept_exact_in_the_data():
    root = sp.CRootOf(sp.Poly([1, 0, -3, 1], sp.Symbol("x")), 1)
    comp = Component(["t_q1**3 - 3*t_q1 + 1"], {}, None, True, condition=Condition.of(
        Value("q1", 2 * sp.atan(root), "revolute"), Value("d4", root, "prismatic")))
    degrees = float(2 * sp.atan(root)) * 180 / 3.141592653589793  # float-ok: the check
    assert condition_text(comp) == f"q1 \u2248 {degrees:.4g}\u00b0, d4 \u2248 {float(root):.4g}"
    assert "CRootOf" in comp.condition.text
    assert comp.condition.clauses()[0].value == 2 * sp.atan(root)


def test_long_polynomials_are_named_in_titles_and_written_out_in_full():
    long = "3*t_a1**2*t_b1**2 + 8*t_a1*t_b1 + 3*t_a1**2 - 7*t_b1 + 1"
    comp = Component(["t_a2", long], {}, None, True,
                     condition=f"a2 = 0, {long} = 0")
    assert short_condition(comp) == "a2 = 0, P2(t_a1, t_b1) = 0"
    assert short_condition(comp).tex == "$a_{2} = 0$, $P_{2}(t_{a1}, t_{b1}) = 0$"
    # in full, the polynomial as the package prints it
    assert condition_text(comp) == ("a2 = 0, 3*t_a1**2*t_b1**2 + 3*t_a1**2 + 8*t_a1*t_b1 "
                                    "- 7*t_b1 + 1 = 0")
    assert [type(k) for k in comp.condition.clauses()] == [Value, Vanishes]


def test_more_than_two_alternatives_are_shortened_in_titles_only():
    comp = Component(["t_q1**4 - 1"], {}, None, True,
                     condition="q1 = 0 or q1 = pi/2 or q1 = -pi/2")
    assert short_condition(comp) == "q1 = 0 or ..."
    assert condition_text(comp) == "q1 = 0 or q1 = pi/2 or q1 = -pi/2"


def test_and_distributes_over_alternatives_and_chains_are_written_in_one_piece():
    a = Condition.parse("q1 = 0 or q1 = pi")
    b = Condition.parse("q2 = q3 = pi/2")
    assert (a & b).text == "q1 = 0, q2 = q3 = pi/2 or q1 = pi, q2 = q3 = pi/2"
    assert [len(c) for c in chains((a & b).alternatives[0])] == [1, 2]
    assert (Condition() & a) == a and bool(Condition()) is False


# --- random conditions ---------------------------------------------------------------
_JOINTS = ["q1", "q2", "q3"]
_tangents = st.fractions(min_value=-20, max_value=20, max_denominator=30)
_values = st.builds(lambda j, t: Value(j, ExactAngle.from_tangent(t).value, "revolute"),
                    st.sampled_from(_JOINTS), st.one_of(_tangents, st.none()))
_related = st.builds(Related, st.sampled_from(_JOINTS), st.sampled_from(_JOINTS),
                     st.sampled_from([1, -1]), st.booleans()).filter(
                         lambda r: r.left != r.right)
_terms = st.dictionaries(st.tuples(*(st.integers(0, 3),) * 3),
                         st.integers(-9, 9).filter(bool), min_size=2, max_size=5)
_vanishes = _terms.map(lambda t: Vanishes(NamedPolynomial._build(
    ("t_q1", "t_q2", "t_q3"), t))).filter(lambda v: len(v.polynomial.variables) > 0)
_conditions = st.lists(st.lists(st.one_of(_values, _related, _vanishes), min_size=1,
                                max_size=4), min_size=1, max_size=3).map(
    lambda alts: Condition(tuple(tuple(dict.fromkeys(a)) for a in alts)))


@settings(max_examples=60, deadline=None, derandomize=True)
@given(_conditions)
def test_random_conditions_read_back_equal(condition):
    kinds = dict.fromkeys(_JOINTS, "revolute")
    # the text reads back to the same data (a chain is read as it was written)
    assert Condition.parse(condition.text, kinds) == condition
    # and so does the JSON, through the report reader
    comp = Component(["t_q1"], dict(GENERIC, Nm=3), None, True, kind="isolated",
                     condition=condition)
    locus = Locus("random", ["t_q1", "t_q2", "t_q3"], "L=1", GENERIC, [comp])
    data = json.loads(render_json(locus))
    assert locus_from_json(data).components[0].condition == condition
