"""``coopkin analyze --json`` has one documented shape on every path (at a rational
point, at home, generically, with some joints free, at irrational angles, with a block
over the term budget, with passive joints): the schema docs/analyze-json.schema.json,
checked with jsonschema when it is installed and by the structural rules below always."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from coopkin_sym.cli import app
from coopkin_sym.present.text import JSON_KEYS

runner = CliRunner()
SCHEMA = json.loads((Path(__file__).resolve().parents[1] / "docs" /
                     "analyze-json.schema.json").read_text())
BLOCKS = ("C11", "C12", "C22", "C23")

PATHS = {
    "home": ["paper-case1-hard"],
    "rational": ["paper-case1-hard", "--at", "q1=pi/2,q2=2*atan(1/3),L=1000"],
    "generic": ["paper-case2-hard", "--generic"],
    "free": ["paper-case1-hard", "--free", "q1", "--at", "q2=pi/2"],
    "planar": ["paper-case1-planar", "--at", "q1=pi/2"],
    "irrational": ["paper-case1-hard", "--at", "q1=-pi/6,q2=pi/6"],
    "irrational-quartic": ["paper-case2-hard", "--at", "q1=pi/3,q3=pi/4"],
    "over-budget": ["dh-three-finger-hand", "--generic"],
    "passive": ["five-bar", "--at", "q1=pi/2"],
    "passive-irrational": ["five-bar", "--at", "q1=pi/3"],
}


@pytest.fixture(scope="module")
def outputs() -> dict[str, dict]:
    out = {}
    for name, args in PATHS.items():
        result = runner.invoke(app, ["analyze", *args, "--json"])
        assert result.exit_code == 0, (name, result.output)
        out[name] = json.loads(result.stdout)
    return out


def structural_problems(data: dict) -> list[str]:
    """What breaks the documented rules, beyond the schema's types."""
    problems = []
    keys = list(data)
    want = list(JSON_KEYS) + (["passive"] if "passive" in data else [])
    if keys != want:
        problems.append(f"keys {keys} != {want}")
    n = data["numbers"]
    dim, r = len(data["twist"]), len(data["joints"])
    shapes = {"C11": [dim, n["Ni"]], "C12": [dim, n["Nc"] - n["Ni"]],
              "C22": [r, n["Nc"] - n["Ni"]], "C23": [r, n["Nr"]]}
    if data["shapes"] != shapes:
        problems.append(f"shapes {data['shapes']} != {shapes} (from the numbers)")
    for name in BLOCKS:
        block = data["blocks"][name]
        if block is None:
            if not data["omitted"].get(name):
                problems.append(f"{name} is null without a reason in omitted")
        else:
            if block and [len(block), len(block[0])] != shapes[name]:
                problems.append(f"{name} is not {shapes[name]}")
            if name in data["omitted"]:
                problems.append(f"{name} is given and omitted")
    if data["coordinated_form"] is None and "coordinated_form" not in data["omitted"]:
        problems.append("coordinated_form is null without a reason")
    if (data["point"] == "irrational") != (data["field"] is not None):
        problems.append("field is given exactly at irrational points")
    if len(data["meaning"]) < 7 or not all(s.startswith(k) for s, k in zip(
            data["meaning"], ("Nm", "Nc", "Ni", "Nr", "Ng", "Nd", "Nh"), strict=False)):
        problems.append("meaning: one sentence per number, in order")
    return problems


@pytest.mark.parametrize("name", list(PATHS))
def test_every_path_follows_the_documented_rules(outputs, name):
    assert structural_problems(outputs[name]) == []


def test_every_path_validates_against_the_schema(outputs):
    jsonschema = pytest.importorskip("jsonschema")
    validator = jsonschema.Draft202012Validator
    validator.check_schema(SCHEMA)
    for name, data in outputs.items():
        errors = [e.message for e in validator(SCHEMA).iter_errors(data)]
        assert errors == [], name


def test_the_schema_rejects_other_shapes(outputs):
    jsonschema = pytest.importorskip("jsonschema")
    validator = jsonschema.Draft202012Validator(SCHEMA)
    good = outputs["irrational"]
    assert not validator.is_valid({k: v for k, v in good.items() if k != "shapes"})
    assert not validator.is_valid({**good, "blocks": {}})                 # the old shape
    assert not validator.is_valid({**good, "field": None})
    assert not validator.is_valid({**good, "extra": 1})
    assert not validator.is_valid({**outputs["home"], "numbers": {"Nm": "2"}})


def test_the_paths_share_their_keys(outputs):
    keys = {name: [k for k in data if k != "passive"] for name, data in outputs.items()}
    assert all(k == list(JSON_KEYS) for k in keys.values())
    assert "passive" in outputs["passive"] and "passive" in outputs["passive-irrational"]
    assert "passive" not in outputs["home"]


def test_what_each_path_gives(outputs):
    assert [outputs[n]["point"] for n in ("home", "generic", "free", "irrational")] == [
        "rational", "symbolic", "symbolic", "irrational"]
    home = outputs["home"]
    assert home["omitted"] == {"finite": "not computed: ask for it with coopkin analyze "
                                         "--finite"} and home["field"] is None
    assert home["finite"] is None
    assert home["blocks"]["C11"] == [["0"], ["0"], ["L"], ["-1"], ["0"], ["0"]]
    irr = outputs["irrational"]
    assert irr["system"] == home["system"] and irr["joints"] == ["q1", "q2"]
    assert irr["configuration"] == "q1=-pi/6,q2=pi/6" and irr["variables"] == ["L"]
    assert irr["blocks"] == dict.fromkeys(BLOCKS) and irr["shapes"]["C11"] == [6, 3]
    assert set(irr["omitted"]) == {*BLOCKS, "coordinated_form", "finite"}
    assert irr["field"]["minimal_polynomial"] == "alpha**2 + 4*alpha + 1"
    over = outputs["over-budget"]
    assert over["blocks"]["C22"] is None and "budget" in over["omitted"]["C22"]
    assert over["shapes"]["C22"] == [9, over["numbers"]["Nc"] - over["numbers"]["Ni"]]
    assert over["coordinated_form"] is None
    passive = outputs["passive-irrational"]["passive"]
    assert passive["actuated"] == ["q1", "q3"] and passive["controlled"] is None
    assert "passive" in outputs["passive-irrational"]["omitted"]
    assert outputs["passive"]["passive"]["controlled"] is not None


def test_the_finite_mobility_is_in_the_document_when_asked():
    """``coopkin analyze --finite --json``: the ``finite`` entry, valid for the schema."""
    result = runner.invoke(app, ["analyze", "four-bar", "--at", "q1=-pi/2,q2=-pi/2",
                                 "--finite", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    jsonschema = pytest.importorskip("jsonschema")
    jsonschema.Draft202012Validator(SCHEMA).validate(data)
    finite = data["finite"]
    assert (finite["dimension"], finite["first_order"], finite["classification"]) == (
        1, 2, "bifurcation")
    assert [b["tangent"] for b in finite["branches"]] == [[["0", "2", "0", "2", "2"]],
                                                          [["0", "-2", "4/3", "-2/3", "2"]]]
    assert finite["orders"] == [{"order": 1, "dimension": 2}, {"order": 2, "dimension": 1}]
    assert "finite" not in data["omitted"]
