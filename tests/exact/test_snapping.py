"""Snapping floats to exact angles and exact unit axes: the bound always holds
(checked here with 120 digits beyond those of the angle, independently of the
package's intervals), the distance reported is the exact one to display precision,
and the value is the simplest one (checked by brute force over smaller
denominators)."""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from coopkin_sym.exact.angles import ExactAngle, simplest_between
from coopkin_sym.exact.axes import axis_angle, snap_axis

BOUNDS = st.one_of(st.sampled_from([Fraction(1, 10**k) for k in range(1, 16)]),
                   st.floats(min_value=1e-15, max_value=0.9).map(Fraction))


# the smallest positive double: a tiny distance is a subnormal float
TINY = mpmath.mpf(2) ** -1074


def _mpf(x: Fraction):
    return mpmath.mpf(x.numerator) / x.denominator


def angle_distance(angle: ExactAngle, q: Fraction):
    """|angle - q| up to whole turns, with 120 digits after those of ``q``."""
    digits = len(str(abs(q.numerator) // q.denominator)) + 120
    with mpmath.workdps(digits):
        d = 2 * mpmath.atan2(angle.num, angle.den) - _mpf(q)
        two_pi = 2 * mpmath.pi
        return abs(d - two_pi * mpmath.nint(d / two_pi))


def tangent_interval(q: Fraction, bound: Fraction):
    """The tangents of half the angles within ``bound`` of ``q`` (no wrap at pi)."""
    with mpmath.workdps(60):
        two_pi = 2 * mpmath.pi
        r = _mpf(q) - two_pi * mpmath.nint(_mpf(q) / two_pi)
        return mpmath.tan((r - _mpf(bound)) / 2), mpmath.tan((r + _mpf(bound)) / 2)


@given(st.one_of(st.floats(min_value=-1e6, max_value=1e6, allow_subnormal=False),
                 st.floats(min_value=-1e-6, max_value=1e-6),
                 st.floats(allow_nan=False, allow_infinity=False)),
       BOUNDS)
@settings(max_examples=300, deadline=None)
def test_a_snapped_angle_is_exact_within_the_bound_and_its_distance_is_exact(q, bound):
    q = Fraction(q)
    angle, error = ExactAngle.snap(q, bound)
    assert isinstance(angle.num, int) and isinstance(angle.den, int) and angle.den >= 0
    exact = angle_distance(angle, q)
    assert exact <= _mpf(bound)
    assert abs(mpmath.mpf(error) - exact) <= exact * mpmath.mpf(2) ** -50 + TINY


@given(st.floats(min_value=-3.1, max_value=3.1),
       st.sampled_from([Fraction(1, 10), Fraction(1, 100), Fraction(1, 1000),
                        Fraction(1, 10**4)]))
@settings(max_examples=200, deadline=None)
def test_a_snapped_angle_has_the_smallest_denominator_within_the_bound(q, bound):
    q = Fraction(q)
    angle, _ = ExactAngle.snap(q, bound)
    if abs(q) <= bound or angle.den == 0:
        # 0 is chosen whenever it is within the bound, pi whenever it is
        assert (angle.num == 0) == (abs(q) <= bound)
        return
    lo, hi = tangent_interval(q, bound)
    assert lo <= mpmath.mpf(angle.num) / angle.den <= hi
    for den in range(1, angle.den):   # no fraction with a smaller denominator fits
        assert mpmath.ceil(lo * den) > mpmath.floor(hi * den), den


def test_the_snapping_bound_is_honoured_far_below_double_precision():
    # 1.5707963 is 2.7e-8 from pi/2: within 1e-6 it is pi/2, within 1e-15 it is not
    angle, error = ExactAngle.snap(Fraction("1.5707963"), Fraction(1, 10**6))
    assert (angle.text, f"{error:.6g}") == ("pi/2", "2.67949e-08")
    angle, error = ExactAngle.snap(Fraction("1.5707963"), Fraction(1, 10**15))
    assert angle.text == "2*atan(37320538/37320539)"
    assert angle_distance(angle, Fraction("1.5707963")) <= mpmath.mpf(10) ** -15
    assert f"{error:.6g}" == f"{float(angle_distance(angle, Fraction('1.5707963'))):.6g}"


@pytest.mark.parametrize("q, bound, text", [
    (Fraction("1e300"), Fraction(1, 10**9), "2*atan(-44657/37682)"),
    (10**999 + Fraction(1, 3), Fraction(1, 10**15), "2*atan(57612941/1499062)"),
    (Fraction(-10**200, 7), Fraction(1, 10), "2*atan(-3/2)"),
])
def test_huge_angles_are_reduced_by_whole_turns_exactly(q, bound, text):
    # 1e300 rad was snapped to pi, 2.4e283 rad away, when the turns were counted in
    # doubles
    angle, error = ExactAngle.snap(q, bound)
    assert angle.text == text
    exact = angle_distance(angle, q)
    assert exact <= _mpf(bound)
    assert abs(mpmath.mpf(error) - exact) <= exact * mpmath.mpf(2) ** -50


def test_pi_and_zero_are_chosen_when_within_the_bound():
    assert ExactAngle.snap(Fraction("3.1415926"), Fraction(1, 10**6))[0].text == "pi"
    assert ExactAngle.snap(Fraction("-3.1415926"), Fraction(1, 10**6))[0].text == "pi"
    assert ExactAngle.snap(Fraction("6.2831853"), Fraction(1, 10**6))[0].text == "0"
    angle, error = ExactAngle.snap(Fraction(1, 10**9), Fraction(1, 10**9))
    assert (angle.text, error) == ("0", 1e-9)


@pytest.mark.parametrize("bound", [0, -1, Fraction(3, 2), 2])
def test_a_bound_out_of_range_is_refused(bound):
    with pytest.raises(ValueError, match="a snapping bound must be between 0 and 3/2 rad"):
        ExactAngle.snap(1.0, bound)


@given(st.fractions(min_value=-5, max_value=5, max_denominator=50),
       st.fractions(min_value=0, max_value=1, max_denominator=50))
@settings(max_examples=300, deadline=None)
def test_simplest_between_has_the_smallest_denominator_then_numerator(lo, width):
    hi = lo + width
    s = simplest_between(lo, hi)
    assert lo <= s <= hi
    for den in range(1, s.denominator):
        assert math.ceil(lo * den) > math.floor(hi * den)
    fits = [n for n in range(math.ceil(lo * s.denominator), math.floor(hi * s.denominator) + 1)]
    assert abs(s.numerator) == min(abs(n) for n in fits)


def test_simplest_between_refuses_an_empty_interval():
    with pytest.raises(ValueError, match=r"an empty interval \[1, 1/2\]"):
        simplest_between(Fraction(1), Fraction(1, 2))


def exact_axis_angle(v, w):
    with mpmath.workdps(150):
        v, w = [list(map(_mpf, x)) for x in (v, w)]
        cross = [v[1] * w[2] - v[2] * w[1], v[2] * w[0] - v[0] * w[2],
                 v[0] * w[1] - v[1] * w[0]]
        return mpmath.atan2(mpmath.sqrt(sum(x * x for x in cross)),
                            sum(a * b for a, b in zip(v, w, strict=True)))


COORDINATE = st.floats(min_value=-10, max_value=10).map(lambda x: Fraction(repr(x)))


@given(st.tuples(COORDINATE, COORDINATE, COORDINATE).filter(any), BOUNDS)
@settings(max_examples=300, deadline=None)
def test_a_snapped_axis_is_an_exact_unit_vector_within_the_bound(v, bound):
    w, error = snap_axis(v, bound)
    assert all(isinstance(x, Fraction) for x in w) and sum(x * x for x in w) == 1
    exact = exact_axis_angle(v, w)
    assert exact <= _mpf(bound)
    assert abs(mpmath.mpf(error) - exact) <= exact * mpmath.mpf(2) ** -50 + TINY


def test_the_axis_of_the_issue_is_snapped_within_1e_9_and_its_distance_said():
    v = (Fraction("0.7071068"), Fraction("0.7071068"), Fraction(0))
    w, error = snap_axis(v, Fraction(1, 10**9))
    assert w == (Fraction(927538921, 1311738121), Fraction(927538920, 1311738121), 0)
    assert f"{error:.4g}" == "5.391e-10" and exact_axis_angle(v, w) <= mpmath.mpf(1e-9)
    w, error = snap_axis(v, Fraction(1, 10**15))
    assert sum(x * x for x in w) == 1 and 0 < error <= 1e-15
    assert exact_axis_angle(v, w) <= mpmath.mpf(10) ** -15


def test_an_axis_of_rational_length_is_scaled_exactly():
    assert snap_axis((Fraction(0), Fraction(3), Fraction(4)), Fraction(1, 10**6)) == (
        (0, Fraction(3, 5), Fraction(4, 5)), 0.0)
    assert axis_angle((1, 0, 0), (-1, 0, 0)) == math.pi
