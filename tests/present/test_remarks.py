"""Remarks of a locus search: data in the analysis layer, one sentence each here."""

from __future__ import annotations

import json

import pytest

from coopkin_sym import load
from coopkin_sym.analysis.locus.remarks import REASONS, REMARK_KINDS, Remark, add_once
from coopkin_sym.analysis.locus.search import compute_locus
from coopkin_sym.errors import ArgumentError
from coopkin_sym.present import remarks as words
from coopkin_sym.present.remarks import remark_text, remark_texts
from coopkin_sym.present.report import locus_from_json, render_json

# a value of the right type for every fact any kind holds
SAMPLE = {"tries": 14, "polynomial": "t_q1**2 + 1", "equations": ("t_q1", "t_q2 - 1"), "depth": 2,
          "joints": ("q1", "q3"), "seconds": 5.0, "where": "the generic decomposition",
          "rows": 6, "columns": 9, "block": "HG^T", "variables": 3, "limit": "minors",
          "bound": 4, "reason": "max_depth", "terms": 3001, "degree": 7,
          "component": 1, "count": 2, "variable": "t_q2", "over": "t_q1", "first": 0,
          "second": 3, "condition": "q1 = q2", "deeper": True, "fields": 2,
          "minimal_polynomial": "alpha**2 + 4*alpha + 1", "parameter": "L",
          "given": (("Nm", 3), ("Nc", 2)), "exact": (("Nm", 2), ("Nc", 2)),
          "implied": (("Nm", 3), ("Nc", 3)), "left": 2, "hint": "pip install x",
          "error": "component #1, equation 1: 't_q1 +' is not a polynomial", "size": 3,
          "largest": 40, "modular": True, "backend": "msolve",
          "detail": "timed out after 2 s", "locus_system": "one", "model_system": "two",
          "undecided": False, "operation": "resultant"}
SAMPLE_FOR = {("family_too_large", "variables"): ("t_q1", "t_q2"),
              ("lower_dimensional_not_solved", "variables"): ("t_q1", "t_q2", "t_q3"),
              ("block_not_solved", "bound"): (6, 200),
              ("operation_too_large", "variables"): ("t_q1", "t_q2"),
              ("operation_too_slow", "variables"): ("t_q1", "t_q2"),
              ("operation_over_bound", "variables"): ("t_q1", "t_q2"),
              ("inside_not_searched", "limit"): "terms"}


def sample(kind: str) -> Remark:
    return Remark.of(kind, **{n: SAMPLE_FOR.get((kind, n), SAMPLE[n])
                              for n in REMARK_KINDS[kind]})


def test_every_kind_has_one_wording_and_nothing_else_does():
    assert set(words._WORDS) == set(REMARK_KINDS)


@pytest.mark.parametrize("kind", sorted(REMARK_KINDS))
def test_every_kind_is_worded_from_its_facts(kind):
    remark = sample(kind)
    text = remark_text(remark)
    assert text and text == text.strip() and "{" not in text and "None" not in text
    # the facts that locate it appear in the sentence
    for name in ("polynomial", "minimal_polynomial", "condition", "parameter"):
        if name in REMARK_KINDS[kind]:
            assert remark[name] in text
    # as data, a remark survives JSON
    assert json.loads(json.dumps(remark.to_json()))["kind"] == kind


@pytest.mark.parametrize("reason", REASONS)
def test_every_reason_is_worded(reason):
    text = remark_text(Remark.of("deeper_not_explored", component=0, condition="q1 = 0",
                                 reason=reason, bound=3))
    assert text.startswith("inside component #1 (q1 = 0): deeper drops not explored (")
    assert ("max depth 3" in text) == (reason == "max_depth")


def test_remarks_are_checked_values():
    with pytest.raises(ArgumentError, match="unknown remark kind 'nope'"):
        Remark.of("nope")
    with pytest.raises(ArgumentError, match="needs the facts polynomial"):
        Remark.of("no_real_points")
    with pytest.raises(ArgumentError, match="unknown reason 'tired'"):
        Remark.of("enclosing_not_searched", equations=(), reason="tired", bound=None)
    with pytest.raises(TypeError, match="remark_text"):
        "x" in Remark.of("pi_chart")  # noqa: B015 - a remark is not text to search
    a = Remark.of("time_depth", depth=1, equations=["t_q1"])
    assert a == Remark.of("time_depth", depth=1, equations=("t_q1",)) and hash(a)
    said: list = []
    add_once(said, a)
    add_once(said, Remark.of("time_depth", depth=1, equations=("t_q1",)))
    assert said == [a]


def test_long_component_conditions_are_cut_to_the_number():
    long = " or ".join(f"q1 = {k}*pi/7" for k in range(20))
    text = remark_text(Remark.of("deeper_not_explored", component=4, condition=long,
                                 reason="no_parametrization", bound=None))
    assert text == ("inside component #5: deeper drops not explored (no rational "
                    "parametrization)")


def test_a_computed_locus_holds_data_and_its_report_holds_sentences():
    locus = compute_locus(load("paper-case1-hard"))
    listed = [*locus.dropped, *locus.notes, *(c.decided for c in locus.components)]
    assert listed and all(isinstance(r, Remark) for r in listed)
    data = json.loads(render_json(locus))
    assert data["dropped"] == remark_texts(locus.dropped)
    assert "t_q1**2 + 1 = 0 (no real points)" in data["dropped"]
    assert [c["decided"] for c in data["components"]] == [
        remark_text(c.decided) for c in locus.components]
    assert all(isinstance(c["decided"], str) and c["decided"].startswith("exact ")
               for c in data["components"])
    # read back, the sentences stay sentences, and write the same report
    again = locus_from_json(data)
    assert again.dropped == data["dropped"]
    assert render_json(again) == render_json(locus)
