"""The finite mobility along a locus component beyond its witness: proved at every
point with the component's numbers when the witness was decided by the rank of Q
alone, else at a second rational point where the component's equations solve
linearly (evidence, said as such); in the report, its JSON (valid for the schema)
and read back."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp

from coopkin_sym import load
from coopkin_sym.analysis.finite import finite_mobility
from coopkin_sym.analysis.finite.on_locus import _solved, along_component, second_point
from coopkin_sym.analysis.mobility import analyze
from coopkin_sym.present.finite import finite_summary
from coopkin_sym.present.report import locus_from_json, render_json, render_markdown

SCHEMA = json.loads((Path(__file__).resolve().parents[2] / "docs" /
                     "locus.schema.json").read_text())


def _component(locus, texts):
    (found,) = [c for c in locus.components if [e.text for e in c.equations] == texts]
    return found


def test_a_component_decided_by_the_rank_of_q_is_so_everywhere_on_it():
    """planar-two-fingers, q2 = -pi/2: independent constraints at the witness and the
    component's numbers there, so at every point of it with those numbers."""
    system = load("planar-two-fingers")
    locus = system.locus()
    system.finite_locus(locus)
    c = _component(locus, ["t_q2 + 1"])
    assert c.witness_checked
    assert (c.finite["reason"], c.finite["dimension"]) == ("submersion", 3)
    assert c.finite["along"] == {"how": "constant_rank", "dimension": 3,
                                 "classification": "kinematic_singularity"}
    assert finite_summary(c.finite).endswith(
        "; the same at every point of the component where its numbers hold (the rank of Q "
        "is the same there)")
    # and indeed at another point of it (q1, q3, q4 elsewhere)
    fm = system.finite_mobility("q1=2*atan(3),q2=-pi/2,q3=-pi/3,q4=2*atan(-1/5)")
    assert (fm.dimension, fm.reason) == (3, "submersion")


def test_the_parallel_cranks_motion_is_checked_at_a_second_point():
    system = load("parallel-cranks")
    locus = system.locus()
    c = _component(locus, ["t_q1 - t_q2", "t_q2 - t_q3"])
    found = system.finite_mobility(c.witness)
    assert found.reason == "closure_bezout"
    point = second_point(c, system.model)
    assert dict(point) == {"q1": "2*atan(-1/3)", "q2": "2*atan(-1/3)", "q3": "2*atan(-1/3)"}
    assert analyze(system.model, point).numbers.as_dict() == dict(c.numbers)
    assert along_component(c, system.model, found) == {
        "how": "second_point", "point": dict(point), "dimension": 1, "bounds": [1, 1],
        "classification": "kinematic_singularity", "reason": "closure_bezout"}
    assert finite_mobility(system.model, point).dimension == 1


def test_second_points_solve_linearly_and_avoid_what_they_cannot():
    t1, t2, t3 = sp.symbols("t_q1 t_q2 t_q3")
    assert _solved([t1 - t2, t2 + 2 * t3 - 1]) == {t1: 1 - 2 * t3, t2: 1 - 2 * t3}
    assert _solved([t1**2 - 2]) is None                 # no linear variable
    assert _solved([t1 * t2 - 1]) is None               # not with a constant coefficient
    system = load("four-bar")                           # isolated points: no second one
    locus = system.locus()
    assert all(second_point(c, system.model) is None for c in locus.components)


def test_the_report_says_what_is_known_along_and_reads_it_back():
    jsonschema = pytest.importorskip("jsonschema")
    system = load("parallel-cranks")
    locus = system.locus()
    system.finite_locus(locus)
    text = render_json(locus)
    jsonschema.Draft202012Validator(SCHEMA).validate(json.loads(text))
    back = locus_from_json(text)
    assert [c.finite for c in back.components] == [c.finite for c in locus.components]
    alongs = [c.finite.get("along") for c in locus.components if c.finite]
    assert sum(1 for a in alongs if a and a["how"] == "second_point") == 9
    assert ("at a second point of the component, q1=2\\*atan(-1/3),q2=2\\*atan(-1/3),"
            "q3=2\\*atan(-1/3): 1, a kinematic singularity at a smooth point of the "
            "configuration space (one more point, not a proof for the whole component)"
            ) in render_markdown(locus)
