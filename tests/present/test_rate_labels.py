"""Joint-rate labels on pictures of a system: ratios to the fastest joint as small
exact fractions, never long integers, one label for joints at one point."""

from __future__ import annotations

import re

import pytest
import sympy as sp

pytest.importorskip("matplotlib")

from coopkin_sym import load  # noqa: E402
from coopkin_sym.present.draw import (  # noqa: E402
    draw_system,
    rate_labels,
    rate_ratios,
    ratio_text,
)


def labels(fig) -> list[str]:
    return sorted(t.get_text() for t in fig.axes[0].texts
                  if (t.get_gid() or "").startswith("rate-label:"))


def test_ratios_to_the_fastest_joint():
    assert rate_ratios([sp.Integer(137020), sp.Integer(-68510)]) == [1, sp.Rational(-1, 2)]
    assert rate_ratios([sp.Integer(-3), sp.Integer(1)]) == [-1, sp.Rational(1, 3)]
    assert rate_ratios([sp.Integer(0), sp.Integer(0)]) == [0, 0]
    assert ratio_text(sp.Rational(-25, 29)) == "-25/29"
    assert ratio_text(sp.Rational(203, 4521)) == "~0.0449"
    assert ratio_text(sp.Integer(1)) == "1"


def test_joints_at_one_place_share_one_label():
    got = rate_labels(["q1", "q2", "q3"], [sp.Integer(4), sp.Integer(-2), sp.Integer(1)],
                      [(0, 0), (1, 0), (1, 0)])
    assert got == [(0, "q1: 1"), (1, "q2: -1/2, q3: 1/4")]


def test_case1_labels_are_exact_ratios():
    fig = draw_system(load("paper-case1-hard"), motion="coordinated:1")
    assert labels(fig) == ["q1: -1", "q2: -1"]
    # at an odd configuration the rates are large integers; the labels are their ratio
    fig = draw_system(load("paper-case1-hard"), at="q1=2*atan(1/7),q2=2*atan(3/11)",
                      motion="coordinated:1")
    assert labels(fig) == ["q1: -25/29", "q2: -1"]


def test_planar_two_fingers_labels():
    fig = draw_system(load("planar-two-fingers"), motion="coordinated:3")
    assert labels(fig) == ["q1: 1/2", "q2: -1", "q3: 1/2", "q4: -1"]


def test_coincident_joints_one_label_and_no_long_integers():
    fig = draw_system(load("dh-two-puma560-box"), motion="coordinated:2")
    got = labels(fig)
    # the wrist joints p1_5, p1_6 lie at one point: one label names both
    assert any(t.startswith("p1_5: ") and ", p1_6: -1" in t for t in got)
    assert len(got) == 6
    title = fig.axes[0].get_title()
    assert not any(re.search(r"(?<![\d.])\d{5,}", t) for t in [*got, title])   # integers
