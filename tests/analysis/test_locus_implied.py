"""Conditions read in angles first: a polynomial clause the values of its alternative
imply is left out, one that fixes one more joint becomes its value, a lone quadratic in
one angle becomes its two roots; the set described never changes (checked exactly at
the values, on random rational points, and on random system 408)."""

from __future__ import annotations

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from coopkin_sym.analysis.locus.conditions import Condition, Related, Value, Vanishes
from coopkin_sym.analysis.locus.implied import without_implied
from coopkin_sym.exact.polynomial import NamedPolynomial

NAMES = ["t_q1", "t_q2", "t_q3", "d4"]
VARIABLES = {"t_q1": ("revolute", "q1"), "t_q2": ("revolute", "q2"),
             "t_q3": ("revolute", "q3"), "d4": ("prismatic", "d4")}


def _p(text: str) -> NamedPolynomial:
    return NamedPolynomial.parse(text, NAMES, "test")


def test_clauses_implied_by_values_and_relations_are_left_out():
    # t_q1 = 1 + sqrt(2) (q1 = 3 pi/4) through q1 = -q2, q2 = -3 pi/4
    c = Condition.of(Vanishes(_p("t_q2**2 + 2*t_q2 - 1")),
                     Vanishes(_p("t_q1**2 - 2*t_q1 - 1")),
                     Related("q1", "q2", -1), Value("q2", -3 * sp.pi / 4, "revolute"))
    assert without_implied(c, VARIABLES).text == "q1 = -q2, q2 = -3*pi/4"


def test_a_clause_linear_in_one_more_joint_becomes_its_value():
    c = Condition.of(Vanishes(_p("t_q1 - t_q2 - 2")), Value("q2", sp.pi / 4, "revolute"),
                     Vanishes(_p("d4 - t_q2")))
    assert without_implied(c, VARIABLES).text == (
        "q1 = 3*pi/4, q2 = pi/4, d4 = -1 + sqrt(2)")


def test_a_lone_quadratic_becomes_its_two_real_roots_and_other_clauses_stay():
    c = Condition.of(Vanishes(_p("t_q1**2 + 2*t_q1 - 1")), Vanishes(_p("t_q2*t_q3 - 3")))
    assert without_implied(c, VARIABLES).text == (
        "q1 = -3*pi/4, t_q2*t_q3 - 3 = 0 or q1 = pi/4, t_q2*t_q3 - 3 = 0")
    # no real root, or a joint at q = pi (its tangent infinite): written as it was
    none = Condition.of(Vanishes(_p("t_q1**2 + 1")))
    assert without_implied(none, VARIABLES) == none
    long = Condition.of(Vanishes(_p("38500*t_q1**2 - 152717*t_q1 - 38500")))
    assert without_implied(long, VARIABLES) == long     # its roots read worse
    at_pi = Condition.of(Vanishes(_p("t_q1*t_q2 - 1")), Value("q1", sp.pi, "revolute"))
    assert without_implied(at_pi, VARIABLES) == at_pi


def test_a_clause_the_values_do_not_make_vanish_stays():
    c = Condition.of(Vanishes(_p("t_q1**2 - 3")), Value("q1", sp.pi / 4, "revolute"))
    assert without_implied(c, VARIABLES) == c
    # linear in q2 once q1 is put in, but q2's value is a long radical: kept
    c = Condition.of(Vanishes(_p("77000*t_q2 - 17*t_q1 - 152717")),
                     Value("q1", 2 * sp.atan(sp.sqrt(101216201)), "revolute"))
    assert without_implied(c, VARIABLES) == c


_TANGENTS = st.fractions(min_value=-5, max_value=5, max_denominator=6)


@settings(max_examples=60, deadline=None)
@given(t=st.tuples(_TANGENTS, _TANGENTS, _TANGENTS), d=_TANGENTS,
       known=st.sets(st.sampled_from(["q1", "q2", "q3", "d4"]), min_size=1),
       coefficients=st.lists(st.integers(-3, 3), min_size=8, max_size=8))
def test_on_random_points_what_is_left_out_vanishes_there_and_values_are_exact(
        t, d, known, coefficients):
    """Clauses vanishing at a rational point, some coordinates given as values: every
    clause left out vanishes at the point, every value in the result is the point's,
    and the values given stay."""
    point = {"t_q1": sp.Rational(t[0]), "t_q2": sp.Rational(t[1]),
             "t_q3": sp.Rational(t[2]), "d4": sp.Rational(d)}
    x = {n: sp.Symbol(n) for n in NAMES}
    a = coefficients
    # each vanishes at the point: products and sums of (x - value) factors
    f = [(x[n] - point[n]) for n in NAMES]
    polys = [a[0] * f[0] + a[1] * f[1] * f[2], (a[2] * x["t_q2"] + a[3]) * f[1] + f[0] * f[3],
             f[2] + a[4] * f[0] * f[1], a[5] * f[3] + a[6] * f[2]**2 + a[7] * f[0]]
    clauses = [Vanishes(NamedPolynomial.from_sympy(sp.expand(p))) for p in polys
               if sp.expand(p) != 0]
    names = {"q1": "t_q1", "q2": "t_q2", "q3": "t_q3", "d4": "d4"}
    values = [Value(n, 2 * sp.atan(point[names[n]]) if n != "d4" else point["d4"],
                    "revolute" if n != "d4" else "prismatic") for n in sorted(known)]
    given_condition = Condition.of(*clauses, *values)
    out = without_implied(given_condition, VARIABLES)
    (alt,) = out.alternatives
    for v in values:
        assert v in alt
    for c in alt:
        if isinstance(c, Value):
            tangent = sp.tan(c.value / 2) if c.kind == "revolute" else c.value
            assert sp.simplify(tangent - point[names[c.name]]) == 0
    at = {sp.Symbol(n): v for n, v in point.items()}
    for c in clauses:
        if c not in alt:
            assert sp.expand(c.polynomial.to_sympy().xreplace(at)) == 0
