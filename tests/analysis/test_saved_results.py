"""Sweep and manipulability results written as JSON and read back: the package's
output validates against the documented schemas (docs/sweep.schema.json,
docs/manipulability.schema.json, and docs/analyze-json.schema.json for
``Analysis.as_json``), reading it back gives an equal result, and a bad entry is one
package error naming it."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from random_systems import random_system
from strategies import random_systems

import coopkin_sym
from coopkin_sym.analysis.manipulability import Manipulability
from coopkin_sym.analysis.sweep import SweepResult, grid
from coopkin_sym.errors import ManipulabilityError, ModelError, SweepError

jsonschema = pytest.importorskip("jsonschema")
DOCS = Path(__file__).resolve().parents[2] / "docs"


def schema(name: str):
    data = json.loads((DOCS / name).read_text())
    jsonschema.Draft202012Validator.check_schema(data)
    return jsonschema.Draft202012Validator(data)


SWEEP, MANIPULABILITY = schema("sweep.schema.json"), schema("manipulability.schema.json")
QUICK = ["paper-case1-hard", "paper-case1-soft", "paper-case1-planar", "five-bar",
         "planar-two-fingers", "paper-case2-hard"]


def errors(validator, data) -> list[str]:
    return [e.message for e in validator.iter_errors(data)]


def round_trip_sweep(result: SweepResult) -> None:
    assert errors(SWEEP, result.to_json()) == []
    assert errors(SWEEP, json.loads(result.json_text())) == []
    back = SweepResult.from_json(result.json_text())
    assert back == result
    assert back.to_json() == result.to_json()
    assert back.to_csv() == result.to_csv()
    assert SweepResult.from_json(result.to_json()) == result


def round_trip_manipulability(m: Manipulability) -> None:
    data = m.to_json()
    assert errors(MANIPULABILITY, data) == []
    back = Manipulability.from_json(json.dumps(data))
    assert back == m
    assert back.to_json() == data


@pytest.mark.parametrize("name", QUICK)
def test_shipped_examples_round_trip(name, tmp_path):
    system = coopkin_sym.load(name)
    first = system.model.joints[0].name
    spec = ",".join(f"{j}=-pi..pi:5" for j in system.joint_names[:2])
    result = system.sweep(grid(system, spec))
    round_trip_sweep(result)
    result.write(tmp_path / "sweep.json")
    assert SweepResult.read(tmp_path / "sweep.json") == result
    points = system.sweep([f"{first}=pi/2", f"{first}=2*atan(1/3)", f"{first}=pi"])
    round_trip_sweep(points)
    m = system.analyze().manipulability()
    round_trip_manipulability(m)
    m.write(tmp_path / "m.json")
    assert Manipulability.read(tmp_path / "m.json") == m


def test_a_snapped_grid_keeps_its_requested_angles():
    system = coopkin_sym.load("paper-case1-hard")
    result = system.sweep(grid(system, "q1=-pi..pi:7,q2=-pi/3..pi:4"))
    assert result.summary()["snapped_values"] == 7
    back = SweepResult.from_json(result.json_text())
    assert back == result and back.snapped == result.snapped


def test_symbolic_and_parametric_ellipsoids_round_trip():
    for name, kwargs in [("paper-case1-soft", {"generic": True}),
                         ("paper-case1-hard", {"free": ["q1"]})]:
        a = coopkin_sym.load(name).analyze(**kwargs)
        m = a.manipulability(length="L")
        assert m.to_json()["symbols"]["L"] == "positive"
        round_trip_manipulability(m)


@settings(max_examples=15, deadline=None, derandomize=True,
          suppress_health_check=list(HealthCheck))
@given(random_systems(max_arms=2, max_joints=2, max_contacts=2), st.integers(2, 4))
def test_random_systems_round_trip(model, count):
    """Random systems (the same ones at every run), their manipulability at home with
    every length 1: a symbolic ellipsoid of a random system can need more memory than
    the machine has (the symbolic round trip has its own test above)."""
    try:
        system = coopkin_sym.load(model)
    except ModelError:
        return
    spec = ",".join(f"{j}=-pi..pi:{count}" if system.model.joints[k].type == "revolute"
                    else f"{j}=-1..1:{count}"
                    for k, j in enumerate(system.joint_names[:2]))
    round_trip_sweep(system.sweep(grid(system, spec)))
    lengths = ",".join(f"{p.name}=1" for p in system.model.parameters) or None
    round_trip_manipulability(system.analyze(lengths).manipulability())


@pytest.mark.parametrize("seed", range(4))
def test_seeded_random_systems_round_trip(seed):
    system = coopkin_sym.load(random_system(seed))
    spec = ",".join(f"{j.name}=-pi..pi:3" for j in system.model.joints[:2]
                    if j.type == "revolute") or None
    if spec:
        round_trip_sweep(system.sweep(grid(system, spec)))
    round_trip_manipulability(system.analyze().manipulability())


@pytest.fixture(scope="module")
def sweep_json() -> dict:
    return coopkin_sym.load("paper-case1-hard").sweep(
        ["q1=pi/2,q2=pi/2", "q1=0,q2=pi"]).to_json()


def bad(data: dict, path: tuple, value) -> dict:
    data = json.loads(json.dumps(data))
    node = data
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    return data


@pytest.mark.parametrize("path, value, message", [
    (("points", 1, "q2"), "pi/3", "not a sweep result: points[1].q2: angle 'pi/3' is "
                                  "not exact"),
    (("points", 0, "q1"), "__import__('os')", "not a sweep result: points[0].q1: "),
    (("points", 0, "Nm"), "3", "not a sweep result: points[0].Nm: expected an integer, "
                               "got '3'"),
    (("points", 0, "Nm"), -1, "not a sweep result: points[0].Nm: expected a count"),
    (("points", 0, "exact_recheck"), 1, "not a sweep result: points[0].exact_recheck: "
                                        "expected true or false, got 1"),
    (("points", 0, "extra"), "x", "not a sweep result: points[0].extra: unknown entry"),
    (("header", "prime"), 2**40, "not a sweep result: header.prime: expected a prime"),
    (("header", "counts", "points"), 3, "not a sweep result: header.counts.points: 3 "
                                        "does not match the points (2)"),
    (("header", "joints"), ["q1", "q1"], "not a sweep result: header.joints: a joint is "
                                         "named twice"),
    (("header", "float_columns"), {"q1_x": "", "q2_rad": ""},
     "not a sweep result: header.float_columns.q1_x: expected q1_rad or q1_float"),
])
def test_a_bad_sweep_entry_is_one_error_naming_it(sweep_json, path, value, message):
    with pytest.raises(SweepError) as info:
        SweepResult.from_json(bad(sweep_json, path, value))
    assert str(info.value).startswith(message)
    assert "\n" not in str(info.value)


def test_bad_sweep_texts_and_files(tmp_path):
    with pytest.raises(SweepError, match="^not a sweep result: line 1, column 2: not "
                                         "valid JSON"):
        SweepResult.from_json("{x")
    with pytest.raises(SweepError, match="^not a sweep result: expected a JSON object"):
        SweepResult.from_json("[1]")
    with pytest.raises(SweepError, match="^/dev/null: is a character device"):
        SweepResult.read("/dev/null")
    (tmp_path / "s.json").write_text('{"header": {}, "points": [], "header": 1}')
    with pytest.raises(SweepError, match="duplicate key 'header'"):
        SweepResult.read(tmp_path / "s.json")


@pytest.mark.parametrize("key, value, message", [
    ("shape", [["1/2", "0"]], "not a manipulability result: shape: expected a square "
                              "matrix of 2 rows"),
    ("index", "exec(1)", "not a manipulability result: index: 'exec(1)' uses unknown "
                         "function exec"),
    ("index", "t_q9", "not a manipulability result: index: "),
    ("rank", 3, "not a manipulability result: rank: expected 0 to 2, got 3"),
    ("rank", True, "not a manipulability result: rank: expected an integer, got true"),
    ("symbols", {"L": "imaginary"}, "not a manipulability result: symbols.L: expected "
                                    "one of positive, real, none"),
    ("extra", 1, "not a manipulability result: extra: unknown entry"),
])
def test_a_bad_manipulability_entry_is_one_error_naming_it(key, value, message):
    good = coopkin_sym.load("five-bar").analyze("L=1").manipulability(
        ["v_x", "v_y"], point=[0, 2, 0]).to_json()
    with pytest.raises(ManipulabilityError) as info:
        Manipulability.from_json({**good, key: value})
    assert str(info.value).startswith(message)


def test_analysis_as_json_validates_against_the_analyze_schema():
    """``as_json`` is the document of ``coopkin analyze --json`` without the words the
    presentation layer adds: the schema's ``$defs/data``."""
    from referencing import Registry, Resource

    root = json.loads((DOCS / "analyze-json.schema.json").read_text())
    registry = Registry().with_resource("urn:analyze", Resource.from_contents(root))
    data = jsonschema.Draft202012Validator({"$ref": "urn:analyze#/$defs/data"},
                                           registry=registry)
    cases = [("paper-case1-hard", None), ("paper-case1-hard", "q1=-pi/6,q2=pi/6"),
             ("paper-case2-hard", "q1=pi/3,q3=pi/4"), ("five-bar", "q1=pi/2"),
             ("five-bar", "q1=pi/3"), ("paper-case1-planar", "q1=pi/2")]
    for name, at in cases:
        out = coopkin_sym.load(name).analyze(at).as_json()
        assert errors(data, out) == [], (name, at)
    generic = coopkin_sym.load("paper-case2-hard").analyze(generic=True).as_json()
    assert errors(data, generic) == []
    assert not data.is_valid({k: v for k, v in generic.items() if k != "certificate"})
