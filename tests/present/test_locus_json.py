"""One JSON serializer for the locus: what is written reads back equal (on the exact
data), in both forms (the report of ``render_json``, the data of ``Locus.to_json``),
and both follow the schema docs/locus.schema.json."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from coopkin_sym import load
from coopkin_sym.analysis.locus.certify import certify_locus
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.locus.types import Certificate, Check, Component, FloatCheck, Locus
from coopkin_sym.analysis.numbers import NUMBER_NAMES
from coopkin_sym.cli import app
from coopkin_sym.model.configuration import Point
from coopkin_sym.present.certificate import certificate_json
from coopkin_sym.present.report import locus_from_json, render_json
from tests.strategies import exact_angles, small_rationals

SCHEMA = json.loads((Path(__file__).parents[2] / "docs" / "locus.schema.json").read_text())
SMALL = ("paper-case1-hard", "paper-case1-soft-hard", "paper-case1-planar",
         "paper-case1-complete-hard")


def _schema_check(tree: dict) -> None:
    jsonschema = pytest.importorskip("jsonschema")
    jsonschema.Draft202012Validator.check_schema(SCHEMA)
    jsonschema.validate(tree, SCHEMA, cls=jsonschema.Draft202012Validator)


def _round_trip(locus: Locus) -> None:
    data = json.loads(json.dumps(locus.to_json()))
    _schema_check(data)
    assert locus_from_json(data) == locus
    assert locus_from_json(json.dumps(data)).to_json() == data
    report = render_json(locus)
    _schema_check(json.loads(report))
    assert render_json(locus_from_json(report)) == report


@pytest.fixture(scope="module")
def shipped() -> dict[str, tuple]:
    out = {}
    for name in SMALL:
        system = load(name)
        out[name] = system, system.locus()
    return out


@pytest.mark.parametrize("name", SMALL)
def test_shipped_loci_read_back_equal(shipped, name):
    _round_trip(shipped[name][1])


def test_a_certified_locus_reads_back_with_its_certificate(shipped):
    system, locus = shipped["paper-case1-hard"]
    locus.certificate = certify_locus(system, locus, timeout=60)
    try:
        _round_trip(locus)
        back = locus_from_json(locus.to_json())
        assert isinstance(back.certificate, Certificate) and back.certified
        assert back.certificate.checks == locus.certificate.checks
        assert certificate_json(back.certificate) == certificate_json(locus.certificate)
    finally:
        locus.certificate = None


def test_the_data_form_is_accepted_by_coopkin_verify(shipped, tmp_path):
    _, locus = shipped["paper-case1-hard"]
    path = tmp_path / "case1.json"
    path.write_text(json.dumps(locus.to_json()))
    result = CliRunner().invoke(app, ["verify", "paper-case1-hard", str(path)])
    assert result.exit_code == 0, result.output
    assert "Verification: passed (0 uncovered points, 0 unsound components)" in result.output


def test_the_data_form_refuses_unknown_remarks(shipped):
    _, locus = shipped["paper-case1-hard"]
    data = locus.to_json()
    data["notes"] = [{"kind": "no_such_kind"}]
    with pytest.raises(ValueError, match=r"notes\[0\]: unknown remark kind 'no_such_kind'"):
        locus_from_json(data)
    data["notes"] = [{"kind": "no_real_points"}]
    with pytest.raises(ValueError, match=r"notes\[0\]: remark 'no_real_points' needs"):
        locus_from_json(data)
    data = locus.to_json()
    data["certificate"] = Certificate("demo", checks=[Check("t chart", 0, 9, "Q", "drops")]
                                      ).to_json()
    with pytest.raises(ValueError, match=r"certificate.checks\[0\].inside: no component"):
        locus_from_json(data)


# ------------------------------------------------------------------ random loci

VARIABLES = ["t_q1", "t_q2", "d3"]


@st.composite
def _numbers(draw) -> dict[str, int]:
    return {k: draw(st.integers(0, 6)) for k in NUMBER_NAMES}


@st.composite
def _points(draw) -> Point:
    (c1, s1), _ = draw(exact_angles())
    (c2, s2), _ = draw(exact_angles())
    d3 = draw(small_rationals())
    return Point.of({"q1": (c1, s1), "q2": (c2, s2)}, {"d3": d3}, {"L": sp.Integer(1)},
                    ["q1", "q2", "d3", "L"])


@st.composite
def _equations(draw) -> list[str]:
    t1, t2, d3 = sp.symbols(VARIABLES)
    out = []
    for _ in range(draw(st.integers(1, 2))):
        a, b, c = (draw(st.integers(-3, 3)) for _ in range(3))
        f = sp.expand(a * t1**2 + b * t2 * d3 + c * t1 + 1)
        out.append(sp.sstr(f))
    return out


REMARKS = st.sampled_from([Remark.of("pi_chart"),
                           Remark.of("no_real_points", polynomial="t_q1**2 + 1"),
                           Remark.of("time_depth", depth=2, equations=["t_q1", "t_q2"]),
                           "a sentence read back"])


@st.composite
def _components(draw, count: int) -> list[Component]:
    comps = []
    for k in range(count):
        witness = draw(st.none() | _points())
        checks = [] if witness is None else [
            FloatCheck(draw(st.sampled_from([0.0, 1e-6])), "L=1", witness, draw(_numbers()),
                       draw(_numbers()))]
        comps.append(Component(
            draw(_equations()), draw(_numbers()), witness, witness is not None,
            kind=draw(st.sampled_from(["hypersurface", "subvariety", "isolated", "chart"])),
            condition=draw(st.sampled_from(["", "q1 = pi/2", "q1 = -q2 or q2 = 0"])),
            drops=draw(st.lists(st.sampled_from(["Q", "HG^T", "HD"]), max_size=2)),
            changes={"Nm": (draw(st.integers(0, 4)), draw(st.integers(0, 4)))},
            decided=draw(st.sampled_from([Remark.of("decided_at_point"), "",
                                          "a sentence"])),
            witness_checked=draw(st.booleans()), float_checks=checks,
            depth=0 if k == 0 else draw(st.integers(0, 2)),
            parent=None if k == 0 else draw(st.none() | st.integers(0, k - 1)),
            real_points=draw(st.sampled_from(["", "witness", "undecided"])),
            outside=draw(st.sampled_from([[], ["t_q1 + 1"]]))))
    return comps


@st.composite
def random_loci(draw) -> Locus:
    count = draw(st.integers(0, 3))
    comps = draw(_components(count))
    certificate = None
    if draw(st.booleans()):
        checks = [Check("t chart", 0, draw(st.none() | st.integers(0, max(count - 1, 0)))
                        if count else None, "Q", "drops", draw(st.booleans()),
                        draw(st.none() | st.just(Remark.of("cert_never_drops"))), "flint",
                        0.5)]
        certificate = Certificate(
            "demo", all(c.certified for c in checks), None,
            {0: {"certified": checks[0].certified,
                 "why": None if checks[0].certified else checks[0], "tests": 1,
                 "failed": 0 if checks[0].certified else 1}},
            {"t chart": {"certified": True, "why": None, "tests": 1, "failed": 0}},
            checks, draw(st.lists(REMARKS, max_size=1)), draw(st.none() | st.just(1)), 1.25)
        certificate.certified = not certificate.failures()
    return Locus("random", VARIABLES, "L=1", draw(_numbers()), comps,
                 draw(st.lists(REMARKS, max_size=2)), draw(st.lists(REMARKS, max_size=1)),
                 draw(st.lists(REMARKS, max_size=2)), draw(st.lists(REMARKS, max_size=2)),
                 seconds=draw(st.sampled_from([0.0, 1.5, 3])), certificate=certificate)


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(random_loci())
def test_random_loci_read_back_equal(locus):
    data = json.loads(json.dumps(locus.to_json()))
    _schema_check(data)
    assert locus_from_json(data) == locus
    report = render_json(locus)
    _schema_check(json.loads(report))
    assert render_json(locus_from_json(report)) == report
