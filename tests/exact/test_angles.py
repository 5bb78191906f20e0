"""Exact angles: written, read back, snapped and nudged, exactly (the floats only choose)."""

from __future__ import annotations

import math
import pickle
from fractions import Fraction

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from coopkin_sym.errors import ArgumentError, NumberError
from coopkin_sym.exact.angles import (
    ExactAngle,
    algebraic_angle,
    cotangent_name,
    joint_of,
    tangent_name,
)
from coopkin_sym.exact.parse import parse_angle

tangents = st.fractions(min_value=-10**6, max_value=10**6, max_denominator=10**6)


@given(tangents)
@settings(max_examples=200, deadline=None)
def test_text_reads_back_to_the_same_angle(t):
    angle = ExactAngle.from_tangent(t)
    again = ExactAngle.parse(angle.text, "q1")
    assert again.tangent == t
    c, s = angle.cos_sin
    assert c**2 + s**2 == 1                     # exactly on the circle


@given(tangents)
@settings(max_examples=200, deadline=None)
def test_cos_sin_and_text_agree_with_the_parser(t):
    angle = ExactAngle.from_tangent(t)
    assert parse_angle(angle.text, "q1") == angle.cos_sin
    assert ExactAngle.from_cos_sin(*angle.cos_sin) == angle
    T = sp.Rational(t.numerator, t.denominator)
    assert angle.cos_sin == ((1 - T**2) / (1 + T**2), 2 * T / (1 + T**2))


R = sp.Rational


@pytest.mark.parametrize(
    ("cos", "sin", "text"),
    [
        (1, 0, "0"),
        (0, 1, "pi/2"),
        (0, -1, "-pi/2"),
        (-1, 0, "pi"),
        (R(4, 5), R(3, 5), "2*atan(1/3)"),
        (R(4, 5), R(-3, 5), "2*atan(-1/3)"),
        (R(-3, 5), R(4, 5), "2*atan(2)"),
    ],
)
def test_the_text_of_an_angle_given_by_cos_and_sin(cos, sin, text):
    assert ExactAngle.from_cos_sin(R(cos), R(sin)).text == text


def test_an_angle_off_the_circle_is_refused():
    with pytest.raises(NumberError, match="not a point on the unit circle"):
        ExactAngle.from_cos_sin(R(1, 2), R(1, 2))


def test_an_angle_of_floats_is_refused():
    with pytest.raises(NumberError, match="exact rationals"):
        ExactAngle.from_cos_sin(0.6, 0.8)


def test_an_angle_is_held_in_lowest_terms():
    assert ExactAngle(2, -6) == ExactAngle(-1, 3) == ExactAngle.from_tangent(Fraction(-1, 3))
    assert (ExactAngle(2, -6).num, ExactAngle(2, -6).den) == (-1, 3)
    assert ExactAngle(-7, 0) == ExactAngle(1, 0) and ExactAngle(-7, 0).num == 1
    assert ExactAngle(0, -5) == ExactAngle(0, 1)
    assert hash(ExactAngle(3, 6)) == hash(ExactAngle(1, 2))
    assert len({ExactAngle(1, 0), ExactAngle(-1, 0), ExactAngle(2, 2), ExactAngle(1, 1)}) == 2


@pytest.mark.parametrize("pair", [(0, 0), (1.0, 2), (1, "2"), (True, 1), (sp.Integer(1), 2)])
def test_an_angle_of_anything_but_two_integers_is_refused(pair):
    with pytest.raises(ArgumentError, match="exact angle"):
        ExactAngle(*pair)


def test_cos_sin_is_computed_once_and_survives_pickling():
    angle = ExactAngle(1, 3)
    assert angle.cos_sin is angle.cos_sin and angle.text is angle.text
    again = pickle.loads(pickle.dumps(angle))
    assert again == angle and again.cos_sin == (R(4, 5), R(3, 5))
    assert pickle.loads(pickle.dumps(ExactAngle(1, 0))).cos_sin == (-1, 0)


def test_pi_and_the_named_angles():
    assert ExactAngle.parse("pi", "q").tangent is None
    assert ExactAngle.parse("-pi", "q").tangent is None
    assert [ExactAngle.from_tangent(t).text for t in (0, 1, -1)] == ["0", "pi/2", "-pi/2"]
    assert ExactAngle.from_tangent(None).cos_sin == (-1, 0)


def test_an_angle_without_a_rational_tangent_is_refused_with_its_neighbours():
    with pytest.raises(NumberError, match="nearest exact angles"):
        ExactAngle.parse("1", "q1")


@given(st.floats(min_value=-7.0, max_value=7.0), st.sampled_from([1e-3, 1e-6, 1e-9]))
@settings(max_examples=200, deadline=None)
def test_snapped_angles_lie_within_the_bound(q, bound):
    angle, error = ExactAngle.snap(q, bound)
    assert error <= bound
    distance = abs(math.remainder(angle.radians() - q, 2 * math.pi))
    assert distance <= bound + 1e-12
    assert ExactAngle.parse(angle.text, "q").tangent == angle.tangent


@given(tangents, st.sampled_from([1e-9, 1e-6, 1e-3]))
@settings(max_examples=100, deadline=None)
def test_nudged_angles_move_by_about_the_distance(t, distance):
    angle = ExactAngle.from_tangent(t)
    moved = angle.nudged(distance)
    step = math.remainder(moved.radians() - angle.radians(), 2 * math.pi)
    assert abs(step - distance) <= 1e-9 + 1e-6 * distance
    assert isinstance(moved.tangent, Fraction)


def test_variable_names():
    assert tangent_name("elbow") == "t_elbow" and cotangent_name("elbow") == "s_elbow"
    assert joint_of("t_elbow") == joint_of("s_elbow") == "elbow"
    assert joint_of("L") is None and joint_of("t_") is None


def test_algebraic_angles_in_multiples_of_pi_only_when_exact():
    import sympy as sp

    assert algebraic_angle(2 - sp.sqrt(3)) == sp.pi / 6
    assert algebraic_angle(sp.sqrt(3)) == 2 * sp.pi / 3
    assert algebraic_angle(sp.sqrt(3) + sp.Rational(1, 10**9)) == \
        2 * sp.atan(sp.sqrt(3) + sp.Rational(1, 10**9))
