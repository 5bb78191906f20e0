"""Shipped examples from the literature: their numbers, and the same numbers from the
independent analysis (tests/independent.py) at the same configurations."""

from __future__ import annotations

import pytest
import sympy as sp
from independent import reference_analysis

import coopkin_sym
from coopkin_sym.model.examples import example_path
from coopkin_sym.model.trees import read_file

STRAIGHT = (sp.Rational(7, 25), sp.Rational(-24, 25))   # cos, sin of 2*atan(-3/4)


@pytest.mark.parametrize("at, values, numbers", [
    # standing: the body moves in 6 independent ways, each by one joint motion; the
    # feet can push against one another through the ground in 6 independent ways
    ("", {}, {"Nm": 6, "Nc": 6, "Ni": 0, "Nr": 0, "Ng": 6, "Nd": 0, "Nh": 0}),
    # one straight leg: it gains a self-motion and the body loses a driven motion
    ("fl_knee=2*atan(-3/4)", {"fl_knee": STRAIGHT},
     {"Nm": 6, "Nc": 5, "Ni": 0, "Nr": 1, "Ng": 6, "Nd": 1, "Nh": 0}),
    ("fl_knee=2*atan(-3/4),fr_knee=2*atan(-3/4)",
     {"fl_knee": STRAIGHT, "fr_knee": STRAIGHT},
     {"Nm": 6, "Nc": 4, "Ni": 0, "Nr": 2, "Ng": 6, "Nd": 2, "Nh": 0}),
])
def test_quadruped_standing(at, values, numbers):
    system = coopkin_sym.load("quadruped-standing")
    assert system.analyze(at or None).numbers.as_dict() == numbers
    reference = reference_analysis(read_file(example_path("quadruped-standing")), values)
    assert {k: reference[k] for k in numbers} == numbers


def test_quadruped_generic_numbers_are_the_standing_ones():
    system = coopkin_sym.load("quadruped-standing")
    assert system.analyze(generic=True).numbers.as_dict() == {
        "Nm": 6, "Nc": 6, "Ni": 0, "Nr": 0, "Ng": 6, "Nd": 0, "Nh": 0}
