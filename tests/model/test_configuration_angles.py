"""A configuration holds its revolute angles as the one exact-angle type
(:class:`~coopkin_sym.exact.angles.ExactAngle`), and writes them back as it read them."""

from __future__ import annotations

import pickle
from fractions import Fraction

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from coopkin_sym.errors import ConfigurationError
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.model.configuration import (
    Configuration,
    Point,
    assignments_text,
    split_assignments,
)
from coopkin_sym.model.model import load_model

MODEL = load_model("paper-case1-hard")          # revolute q1, q2; parameter L
tangents = st.fractions(min_value=-10**4, max_value=10**4, max_denominator=10**4)
angles = st.one_of(tangents.map(ExactAngle.from_tangent), st.just(ExactAngle(1, 0)))
ROUND_TRIP = settings(max_examples=150, deadline=None, derandomize=True)


@pytest.mark.parametrize(("text", "tangent"), [
    ("pi/2", Fraction(1)), ("-pi/2", Fraction(-1)), ("0", Fraction(0)),
    ("2*atan(1/3)", Fraction(1, 3)), ("2*atan(-7/2)", Fraction(-7, 2)),
    ("pi/2 + 2*atan(1/3)", Fraction(2)), ("-pi", None), ("pi", None), ("3*pi", None),
])
def test_a_parsed_angle_is_an_exact_angle_with_its_tangent(text, tangent):
    angle = Configuration.parse(MODEL, f"q1={text},L=1").revolute["q1"]
    assert isinstance(angle, ExactAngle) and angle.tangent == tangent


def test_q_at_pi():
    c = Configuration.parse(MODEL, "q1=pi,q2=-pi,L=2")
    assert c.revolute["q1"] == c.revolute["q2"] == ExactAngle(1, 0)
    assert c.revolute["q1"].cos_sin == (-1, 0)
    assert c.at_text() == "q1=pi,q2=pi,L=2"
    assert Configuration.parse(MODEL, c.at_text()) == c


def test_other_forms_of_an_angle_become_the_same_exact_angle():
    by_text = Configuration.parse(MODEL, "q1=2*atan(1/3)").revolute["q1"]
    by_pair = Configuration.parse(MODEL, {"q1": (sp.Rational(4, 5), sp.Rational(3, 5))})
    by_angle = Configuration.parse(MODEL, {"q1": ExactAngle(2, 6)})
    assert by_pair.revolute["q1"] == by_angle.revolute["q1"] == by_text == ExactAngle(1, 3)
    assert Configuration.parse(MODEL, {"q1": 0}).revolute["q1"] == ExactAngle(0, 1)


@pytest.mark.parametrize(("value", "match"), [
    ((sp.Rational(1, 2), sp.Rational(1, 2)), "not an exact point on the unit circle"),
    ((sp.sqrt(2) / 2, sp.sqrt(2) / 2), "not an exact rational number"),
    ("pi/3", "nearest exact angles"),
])
def test_an_inexact_angle_is_one_configuration_error(value, match):
    with pytest.raises(ConfigurationError, match=match):
        Configuration.parse(MODEL, {"q1": value})


def test_a_configuration_refuses_a_revolute_value_that_is_not_an_exact_angle():
    with pytest.raises(ConfigurationError, match="q1: a revolute value .* is an ExactAngle"):
        Configuration({"q1": (sp.Integer(0), sp.Integer(1))})


@given(angles, angles, st.integers(1, 50))
@ROUND_TRIP
def test_at_text_round_trips_through_parse(a1, a2, length):
    c = Configuration(revolute={"q1": a1, "q2": a2}, parameters={"L": sp.Integer(length)})
    again = Configuration.parse(MODEL, c.at_text())
    assert again == c
    assert again.revolute["q1"] == a1 and again.revolute["q2"] == a2
    assert again.at_text() == c.at_text() == f"q1={a1.text},q2={a2.text},L={length}"


@given(angles, angles)
@ROUND_TRIP
def test_a_point_reads_as_its_angle_texts_and_round_trips(a1, a2):
    p = Point.of({"q1": a1, "q2": a2}, parameters={"L": sp.Integer(1)})
    assert dict(p) == {"q1": a1.text, "q2": a2.text, "L": "1"}
    assert p == Point.of({"q1": a1.cos_sin, "q2": a2.cos_sin}, parameters={"L": 1})
    again = Configuration.parse(MODEL, p.at_text())
    assert again.revolute == p.revolute and again.parameters == p.parameters
    assert pickle.loads(pickle.dumps(p)) == p
    moved = p.moved("q2", a1)
    assert moved["q2"] == a1.text and moved.revolute["q2"] is a1 and p.revolute["q2"] == a2


def test_a_configuration_pickles_with_its_angles():
    c = Configuration.parse(MODEL, "q1=2*atan(1/3),q2=pi,L=2", free=())
    again = pickle.loads(pickle.dumps(c))
    assert again == c and again.revolute["q1"].cos_sin == (sp.Rational(4, 5), sp.Rational(3, 5))


def test_assignments_text_is_what_split_assignments_reads():
    values = {"q1": "2*atan(1/3)", "L": "Rational(1, 3)", "d2": "-1/2"}
    assert split_assignments(assignments_text(values), "--at") == list(values.items())
    assert assignments_text(list(values.items())) == assignments_text(values) == \
        "q1=2*atan(1/3),L=Rational(1, 3),d2=-1/2"
    assert assignments_text({}) == ""
