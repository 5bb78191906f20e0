"""Model loading and validation (coopkin_sym.model.model, coopkin_sym.model.examples)."""

from __future__ import annotations

import copy
import dataclasses
import json
from fractions import Fraction
from pathlib import Path
from typing import Any

import pytest
import sympy as sp
import yaml
from hypothesis import HealthCheck, given, settings
from strategies import random_systems

from coopkin_sym.errors import ArgumentError
from coopkin_sym.model.examples import describe_example, example_path, list_examples
from coopkin_sym.model.model import Arm, Contact, Joint, Model, ModelError, load_model

L = sp.Symbol("L", positive=True)
R = sp.Rational

EXAMPLES = [
    "allegro-hand-sphere",
    "bennett-linkage",
    "bricard-linkage",
    "dh-three-finger-hand",
    "dh-two-puma560-box",
    "five-bar",
    "four-bar",
    "panda-two-arm-box",
    "paper-case1-complete-hard",
    "paper-case1-hard",
    "paper-case1-planar",
    "paper-case1-soft",
    "paper-case1-soft-hard",
    "paper-case2-complete",
    "paper-case2-hard",
    "parallel-cranks",
    "planar-two-fingers",
    "quadruped-standing",
    "seven-r-loop",
    "shaky-pinned-bars",
    "underactuated-finger",
    "urdf-two-fingers",
]

CASE1 = {
    "name": "two one-link arms",
    "parameters": ["L"],
    "arms": [
        {"name": "a1", "joints": [
            {"name": "q1", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]}]},
        {"name": "a2", "joints": [
            {"name": "q2", "type": "revolute", "axis": [0, 0, 1], "point": ["L", 0, 0]}]},
    ],
    "contacts": [
        {"name": "c1", "link": "a1/1", "point": [0, "L", 0], "normal": [1, 0, 0],
         "model": "hard"},
        {"name": "c2", "link": "a2/1", "point": ["L", "L", 0], "normal": [-1, 0, 0],
         "model": "hard"},
    ],
}


def case1() -> dict[str, Any]:
    return copy.deepcopy(CASE1)


def problems_of(source: Any) -> ModelError:
    """Load ``source``, which must fail; check the one-line-per-problem form."""
    with pytest.raises(ModelError) as info:
        load_model(source)
    err = info.value
    assert err.problems, "a ModelError lists at least one problem"
    for line in err.problems:
        assert "\n" not in line
    prefix = f"{err.source}: " if err.source else ""
    assert str(err).split("\n") == [prefix + p for p in err.problems]
    assert "Traceback" not in str(err) and "pydantic" not in str(err).lower()
    return err


def assert_problem(err: ModelError, path: str, fragment: str) -> None:
    """Some problem is about entry ``path`` and says ``fragment``."""
    hits = [p for p in err.problems if p.startswith(f"{path}: ") and fragment in p]
    assert hits, f"no problem '{path}: ...{fragment}...' in {err.problems}"


# ------------------------------------------------------------------------- examples


def test_list_examples():
    assert list_examples() == EXAMPLES


def test_example_path_and_unknown_example():
    path = example_path("paper-case1-hard")
    assert path.name == "paper-case1-hard.yaml" and path.is_file()
    with pytest.raises(ArgumentError, match="unknown example 'x'; shipped examples: "
                                         "allegro-hand-sphere, bennett-linkage, "
                                         "bricard-linkage, dh-three-finger-hand, "
                                         "dh-two-puma560-box, "
                                         "five-bar, four-bar, panda-two-arm-box, "
                                         "paper-case1-complete-hard, "):
        example_path("x")


@pytest.mark.parametrize("name", [e for e in EXAMPLES if e.startswith("paper-")])
def test_every_example_loads_with_paper_header(name):
    model = load_model(name)
    assert model.parameters == (L,)
    assert model.source == str(example_path(name))
    assert model == load_model(example_path(name))
    text = example_path(name).read_text(encoding="utf-8")
    assert "ICRA 1992" in text and "section" in text
    assert describe_example(name).startswith("Paper case study ")


@pytest.mark.parametrize("name", [e for e in EXAMPLES if e.startswith("dh-")]
                         + ["allegro-hand-sphere", "panda-two-arm-box"])
def test_every_dh_example_loads_and_says_where_it_comes_from(name):
    model = load_model(name)
    assert model == load_model(example_path(name))
    assert all(arm.frames is not None and len(arm.frames) == len(arm.joints) + 1
               for arm in model.arms)
    assert "DH table" in describe_example(name)


def test_case1_hard_exact_contents():
    m = load_model("paper-case1-hard")
    assert m.arms == (
        Arm("a1", (Joint("q1", "revolute", (0, 0, 1), (0, 0, 0)),)),
        Arm("a2", (Joint("q2", "revolute", (0, 0, 1), (L, 0, 0)),)),
    )
    assert m.contacts == (
        Contact("c1", 0, 1, (0, L, 0), (1, 0, 0), "hard"),
        Contact("c2", 1, 1, (L, L, 0), (-1, 0, 0), "hard"),
    )
    assert m.joint_names == ("q1", "q2")


@pytest.mark.parametrize(
    ("name", "models"),
    [
        ("paper-case1-hard", ("hard", "hard")),
        ("paper-case1-soft", ("soft", "soft")),
        ("paper-case1-soft-hard", ("soft", "hard")),
        ("paper-case1-complete-hard", ("complete", "hard")),
    ],
)
def test_case1_variants_differ_only_in_contact_models(name, models):
    m = load_model(name)
    reference = load_model("paper-case1-hard")
    assert m.arms == reference.arms
    assert tuple(c.model for c in m.contacts) == models
    assert [dataclasses.replace(c, model="hard") for c in m.contacts] == list(
        reference.contacts)


@pytest.mark.parametrize("name", ["paper-case2-complete", "paper-case2-hard"])
def test_case2_exact_contents(name):
    m = load_model(name)
    assert [a.name for a in m.arms] == ["s1", "s2"]
    assert m.joint_names == tuple(f"q{k}" for k in range(1, 9))
    types = [j.type for j in m.joints]
    assert types == ["revolute"] * 3 + ["prismatic", "prismatic"] + ["revolute"] * 3
    z, x = (0, 0, 1), (1, 0, 0)
    assert [j.axis for j in m.joints] == [z] * 4 + [x] * 4
    assert [j.point for j in m.joints] == [
        (0, 2 * L, 0), (L, 2 * L, 0), (L, L, 0), (L, L, 0),
        (4 * L, L, L), (4 * L, L, L), (4 * L, L, 2 * L), (4 * L, 0, 2 * L)]
    c1, c2 = m.contacts
    assert (c1.arm, c1.link, c1.point, c1.normal) == (0, 4, (L, L, L), (1, 0, 0))
    assert (c2.arm, c2.link, c2.point, c2.normal) == (1, 4, (3 * L, L, L), (-1, 0, 0))
    assert c2.point[0].free_symbols == {L}
    expected = "complete" if name.endswith("complete") else "hard"
    assert (c1.model, c2.model) == (expected, expected)
    assert m.joint_offset(1) == 4


# ------------------------------------------------------------------ valid variations


def test_dict_json_and_yaml_give_equal_models(tmp_path):
    from_dict = load_model(case1())
    json_file = tmp_path / "m.json"
    json_file.write_text(json.dumps(case1()), encoding="utf-8")
    yaml_file = tmp_path / "m.yaml"
    yaml_file.write_text(yaml.safe_dump(case1()), encoding="utf-8")
    from_json, from_yaml = load_model(json_file), load_model(str(yaml_file))
    assert from_dict.source is None
    assert from_json.source == str(json_file)
    assert dataclasses.replace(from_json, source=None) == from_dict
    assert dataclasses.replace(from_yaml, source=None) == from_dict


def test_yaml_decimal_is_exact(tmp_path):
    path = tmp_path / "dec.yaml"
    path.write_text(
        "arms:\n- name: a\n  joints:\n"
        "  - {name: q1, type: revolute, axis: [0, 0, 1], point: [0.1, 0, 0]}\n"
        "contacts:\n- {name: c, link: a/1, point: [1.5e3, -0.25, 1_000.5], model: hard}\n",
        encoding="utf-8")
    m = load_model(path)
    assert m.joints[0].point == (R(1, 10), 0, 0)
    assert isinstance(m.joints[0].point[0], sp.Rational)
    assert m.contacts[0].point == (1500, R(-1, 4), R(2001, 2))


def test_json_decimal_is_exact(tmp_path):
    tree = case1()
    tree["arms"][0]["joints"][0]["point"] = [0.1, 0, 0]
    path = tmp_path / "dec.json"
    path.write_text(json.dumps(tree), encoding="utf-8")
    assert load_model(path).joints[0].point == (R(1, 10), 0, 0)


def test_dict_numbers_of_every_exact_kind():
    tree = case1()
    tree["arms"][1]["joints"][0]["point"] = [Fraction(1, 3), 0.1, sp.Rational(2, 7)]
    tree["arms"][1]["joints"][0]["axis"] = ["3/5", "4/5", 0]
    tree["contacts"][0]["point"] = ["L/2 + 1", "2*L", sp.Symbol("L") ** 2]
    m = load_model(tree)
    assert m.joints[1].point == (R(1, 3), R(1, 10), R(2, 7))
    assert m.joints[1].axis == (R(3, 5), R(4, 5), 0)
    assert m.contacts[0].point == (L / 2 + 1, 2 * L, L**2)


def test_defaults_name_parameters_normal_and_prismatic_point(tmp_path):
    tree = {
        "arms": [{"name": "a", "joints": [
            {"name": "d1", "type": "prismatic", "axis": [0, 0, 2]}]}],
        "contacts": [
            {"name": "c1", "link": "a/1", "point": [0, 0, 1], "model": "hard"},
            {"name": "c2", "link": "base", "point": [1, 0, 0], "model": "complete"},
            {"name": "c3", "link": "a/0", "point": [1, 0, 0], "normal": [0, 1, 0],
             "model": "frictionless"},
        ],
    }
    m = load_model(tree)
    assert m.name == "unnamed" and m.parameters == ()
    assert m.joints[0] == Joint("d1", "prismatic", (0, 0, 2), None)
    assert m.contacts[0].normal is None
    assert (m.contacts[1].arm, m.contacts[1].link) == (None, 0)
    assert (m.contacts[2].arm, m.contacts[2].link) == (0, 0)
    path = tmp_path / "stem-name.yml"
    path.write_text(yaml.safe_dump(tree), encoding="utf-8")
    assert load_model(path).name == "stem-name"


def test_model_is_frozen():
    m = load_model(case1())
    assert isinstance(m, Model)
    with pytest.raises(dataclasses.FrozenInstanceError):
        m.name = "x"  # type: ignore[misc]


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(random_systems(with_parameter=True))
def test_random_valid_systems_load_and_survive_json(tree):
    m = load_model(tree)
    assert len(m.joints) == sum(len(a["joints"]) for a in tree["arms"])
    assert [c.name for c in m.contacts] == [c["name"] for c in tree["contacts"]]
    again = load_model(json.loads(json.dumps(tree)))
    assert again == m


# ------------------------------------------------------------ bad input, one by one


def test_unknown_key():
    tree = case1()
    tree["arms"][0]["joint"] = tree["arms"][0].pop("joints")
    err = problems_of(tree)
    assert_problem(err, "arms[0]", "unknown key 'joint' (did you mean 'joints'?)")
    assert_problem(err, "arms[0]", "missing key 'joints'")


def test_unknown_top_level_key():
    tree = case1()
    tree["contact"] = []
    assert_problem(problems_of(tree), "(top level)", "unknown key 'contact'")


def test_missing_key():
    tree = case1()
    del tree["contacts"][0]["point"]
    err = problems_of(tree)
    assert err.problems == ["contacts[0]: missing key 'point'"]


def test_unknown_link_arm():
    tree = case1()
    tree["contacts"][0]["link"] = "a3/1"
    err = problems_of(tree)
    assert err.problems == ["contacts[0].link: unknown arm 'a3' (arms: a1, a2)"]


def test_link_index_out_of_range():
    tree = case1()
    tree["contacts"][0]["link"] = "a1/2"
    err = problems_of(tree)
    assert err.problems == ["contacts[0].link: arm a1 has 1 joint, no link 2"]


def test_link_malformed():
    tree = case1()
    tree["contacts"][1]["link"] = "a2"
    assert_problem(problems_of(tree), "contacts[1].link", "expected ARM/K")


def test_non_unit_revolute_axis():
    tree = case1()
    tree["arms"][1]["joints"][0]["axis"] = [0, 3, 4]
    err = problems_of(tree)
    assert_problem(err, "arms[1].joints[0].axis", "not a unit vector")
    assert_problem(err, "arms[1].joints[0].axis", "did you mean [0, 3/5, 4/5]?")


def test_non_unit_normal():
    tree = case1()
    tree["contacts"][1]["normal"] = [1, 1, 0]
    err = problems_of(tree)
    assert err.problems == ["contacts[1].normal: not a unit vector (squared length 2)"]


def test_zero_prismatic_axis():
    tree = case1()
    tree["arms"][0]["joints"][0].update(type="prismatic", axis=[0, 0, 0])
    assert_problem(problems_of(tree), "arms[0].joints[0].axis", "zero vector")


def test_axis_with_parameter():
    tree = case1()
    tree["arms"][0]["joints"][0]["axis"] = [0, 0, "L"]
    assert_problem(problems_of(tree), "arms[0].joints[0].axis", "'L' uses a parameter")


def test_missing_point_for_revolute():
    tree = case1()
    del tree["arms"][0]["joints"][0]["point"]
    assert_problem(problems_of(tree), "arms[0].joints[0].point",
                   "required for a revolute joint")


def test_missing_normal_for_soft():
    tree = case1()
    tree["contacts"][0]["model"] = "soft"
    del tree["contacts"][0]["normal"]
    err = problems_of(tree)
    assert err.problems == ["contacts[0].normal: required for a soft contact"]


def test_missing_normal_for_frictionless():
    tree = case1()
    tree["contacts"][1]["model"] = "frictionless"
    tree["contacts"][1]["normal"] = None
    err = problems_of(tree)
    assert err.problems == ["contacts[1].normal: required for a frictionless contact"]


def test_unknown_contact_model():
    tree = case1()
    tree["contacts"][0]["model"] = "rigid"
    assert_problem(problems_of(tree), "contacts[0].model",
                   "unknown contact model 'rigid' (expected complete, soft, hard or "
                   "frictionless)")


def test_unknown_joint_type():
    tree = case1()
    tree["arms"][0]["joints"][0]["type"] = "rotary"
    err = problems_of(tree)
    assert err.problems == ["arms[0].joints[0].type: unknown joint type 'rotary' "
                            "(expected revolute or prismatic)"]


def test_duplicate_contact_name():
    tree = case1()
    tree["contacts"].append(dict(tree["contacts"][0]))
    err = problems_of(tree)
    assert_problem(err, "contacts[2].name", "duplicate name 'c1'")


def test_duplicate_arm_name():
    tree = case1()
    tree["arms"][1]["name"] = "a1"
    assert_problem(problems_of(tree), "arms[1].name", "duplicate name 'a1'")


def test_joint_named_like_parameter():
    tree = case1()
    tree["arms"][1]["joints"][0]["name"] = "L"
    err = problems_of(tree)
    assert_problem(err, "arms[1].joints[0].name", "duplicate name 'L' (already used at "
                                                  "parameters[0])")


def test_contact_named_like_arm():
    tree = case1()
    tree["contacts"][0]["name"] = "a2"
    assert_problem(problems_of(tree), "contacts[0].name", "duplicate name 'a2'")


def test_name_clashes_with_half_angle_variable():
    tree = case1()
    tree["arms"][1]["joints"][0]["name"] = "t_q1"
    err = problems_of(tree)
    assert_problem(err, "arms[1].joints[0].name", "clashes with the half-angle variable "
                                                  "t_q1 of joint q1")


def test_parameter_clashes_with_half_angle_variable():
    tree = case1()
    tree["parameters"] = ["L", "t_q2"]
    assert_problem(problems_of(tree), "parameters[1]", "half-angle variable t_q2")


def test_invalid_name():
    tree = case1()
    tree["arms"][0]["joints"][0]["name"] = "2q"
    assert_problem(problems_of(tree), "arms[0].joints[0].name", "not a valid name")


def test_reserved_parameter_name():
    tree = case1()
    tree["parameters"] = ["L", "pi"]
    assert_problem(problems_of(tree), "parameters[1]", "'pi' is reserved")


def test_undeclared_symbol():
    tree = case1()
    tree["arms"][0]["joints"][0]["point"] = ["M", 0, 0]
    err = problems_of(tree)
    assert err.problems == ["arms[0].joints[0].point: 'M' uses undeclared symbol M "
                            "(declared parameters: L)"]


def test_wrong_vector_length():
    tree = case1()
    tree["arms"][0]["joints"][0]["axis"] = [0, 1]
    err = problems_of(tree)
    assert err.problems == ["arms[0].joints[0].axis: expected 3 numbers, got 2"]


def test_vector_not_a_list():
    tree = case1()
    tree["contacts"][0]["point"] = "0 L 0"
    assert_problem(problems_of(tree), "contacts[0].point", "expected a list")


def test_empty_arms():
    tree = case1()
    tree["arms"] = []
    err = problems_of(tree)
    assert err.problems == ["arms: at least one arm with one joint is needed"]


def test_arm_without_joints():
    tree = case1()
    tree["arms"][1]["joints"] = []
    assert_problem(problems_of(tree), "arms[1].joints", "at least one joint is needed")


def test_empty_contacts():
    tree = case1()
    tree["contacts"] = []
    err = problems_of(tree)
    assert err.problems == ["contacts: at least one contact is needed"]


def test_missing_contacts():
    tree = case1()
    del tree["contacts"]
    assert problems_of(tree).problems == ["contacts: at least one contact is needed"]


def test_non_polynomial_number():
    tree = case1()
    tree["contacts"][0]["point"] = ["1/L", 0, 0]
    err = problems_of(tree)
    assert err.problems == ["contacts[0].point: '1/L' is not a polynomial in the "
                            "parameters"]


def test_irrational_number():
    tree = case1()
    tree["contacts"][1]["point"] = ["sqrt(2)", 0, 0]
    err = problems_of(tree)
    assert err.problems == ["contacts[1].point: 'sqrt(2)' is not an exact rational "
                            "number"]


def test_boolean_is_not_a_number():
    tree = case1()
    tree["contacts"][1]["point"] = [True, 0, 0]
    assert_problem(problems_of(tree), "contacts[1].point", "truth value")


def test_wrong_type_of_text_field():
    tree = case1()
    tree["contacts"][0]["name"] = 3
    assert_problem(problems_of(tree), "contacts[0].name", "expected text, got 3")


def test_entry_not_a_mapping():
    tree = case1()
    tree["arms"][0]["joints"] = ["q1"]
    assert_problem(problems_of(tree), "arms[0].joints[0]", "expected a mapping")


def test_several_problems_are_all_reported():
    tree = case1()
    tree["arms"][0]["joints"][0]["type"] = "rotary"
    tree["contacts"][0]["normal"] = [2, 0, 0]
    tree["contacts"][1]["link"] = "a9/1"
    err = problems_of(tree)
    assert len(err.problems) == 3
    assert_problem(err, "arms[0].joints[0].type", "unknown joint type")
    assert_problem(err, "contacts[0].normal", "not a unit vector")
    assert_problem(err, "contacts[1].link", "unknown arm 'a9'")


def test_invalid_yaml_syntax(tmp_path):
    path = tmp_path / "broken.yaml"
    path.write_text("name: x\narms:\n  - name: a1\n    joints: [\ncontacts: []\n",
                    encoding="utf-8")
    err = problems_of(path)
    assert err.source == str(path)
    assert str(err).startswith(f"{path}: line ")
    assert "not valid YAML" in err.problems[0]


def test_yaml_error_names_the_line(tmp_path):
    path = tmp_path / "flow.yaml"
    path.write_text("name: x\nparameters: [L]\narms: {a: [1, 2}\n", encoding="utf-8")
    err = problems_of(path)
    assert err.problems[0].startswith("line 3, column ")


def test_yaml_duplicate_key(tmp_path):
    path = tmp_path / "dup.yaml"
    path.write_text("name: x\nname: y\n", encoding="utf-8")
    err = problems_of(path)
    assert err.problems == ["line 2, column 1: not valid YAML: duplicate key 'name'"]


def test_yaml_infinity_is_rejected(tmp_path):
    tree = case1()
    tree["contacts"][0]["point"] = [0, ".inf", 0]
    path = tmp_path / "inf.yaml"
    path.write_text(yaml.safe_dump(tree).replace("'.inf'", ".inf"), encoding="utf-8")
    err = problems_of(path)
    assert err.problems == ["contacts[0].point: '.inf' is not a finite number"]


def test_invalid_json(tmp_path):
    path = tmp_path / "broken.json"
    path.write_text('{"arms": [1,\n', encoding="utf-8")
    err = problems_of(path)
    assert err.source == str(path)
    assert err.problems[0].startswith("line 2, column 1: not valid JSON")


def test_missing_file(tmp_path):
    path = tmp_path / "nope.yaml"
    err = problems_of(path)
    assert err.source == str(path)
    assert err.problems[0].startswith("no such file")


def test_unknown_example_name():
    err = problems_of("paper-case9")
    assert err.source == "paper-case9"
    assert "paper-case1-hard" in err.problems[0]


def test_a_misspelled_example_gets_the_closest_name():
    assert problems_of("paper-case1-hrd").problems[0].endswith(
        "; did you mean paper-case1-hard?")
    assert problems_of("planar-two-finger").problems[0].endswith(
        "; did you mean planar-two-fingers?")
    assert "did you mean" not in problems_of("zzzz").problems[0]


def test_file_problems_are_prefixed_with_the_file(tmp_path):
    tree = case1()
    tree["contacts"][1]["normal"] = [0, 0, 2]
    path = tmp_path / "m.yaml"
    path.write_text(yaml.safe_dump(tree), encoding="utf-8")
    err = problems_of(path)
    assert str(err) == (f"{path}: contacts[1].normal: not a unit vector (squared "
                        f"length 4); did you mean [0, 0, 1]?")


def test_empty_file(tmp_path):
    path = tmp_path / "empty.yaml"
    path.write_text("# nothing\n", encoding="utf-8")
    assert "empty" in problems_of(path).problems[0]


def test_top_level_not_a_mapping(tmp_path):
    path = Path(tmp_path / "list.yaml")
    path.write_text("- 1\n- 2\n", encoding="utf-8")
    assert_problem(problems_of(path), "(top level)", "expected a mapping")


# ------------------------------------------------------------------------- one error per problem

DH_ARM = {"name": "d", "dh": [{"name": "q3", "type": "revolute", "a": "L"},
                              {"name": "q4", "type": "revolute", "a": "L"}]}


def _with_arm(arm: dict, *links: str) -> dict[str, Any]:
    """Case 1 with ``arm`` added as arms[2], contacts on it at ``links`` (in its link
    frames), and a non-unit normal on contact c2 (of arm a2, a problem of its own)."""
    tree = case1()
    tree["arms"].append(arm)
    tree["contacts"][1]["normal"] = [0, 0, 2]
    tree["contacts"] += [{"name": f"c{3 + k}", "link": link, "point": [0, 0, 0],
                          "normal": [1, 0, 0], "model": "hard", "frame": "link"}
                         for k, link in enumerate(links)]
    return tree


NORMAL = "contacts[1].normal: not a unit vector (squared length 4); did you mean [0, 0, 1]?"


@pytest.mark.parametrize("change, problem", [
    ({"dh": [{"name": "q3", "type": "revolute", "alpha": "x"}]},
     "arms[2].dh[0].alpha: 'x' uses undeclared symbol x (declared parameters: none)"),
    ({"convention": "craig"},
     "arms[2].convention: expected standard (Denavit-Hartenberg) or modified (Craig), got "
     "'craig'"),
    ({"base": {"xyz": [0, 0]}}, "arms[2].base.xyz: expected 3 numbers, got 2"),
    ({"dh": "x"}, "arms[2].dh: expected a list, got 'x'"),
])
def test_a_failed_dh_arm_is_the_one_error_about_it(change, problem):
    err = problems_of(_with_arm({**DH_ARM, **change}, "d/1", "d/2", "d/b", "d/0"))
    assert err.problems == [problem, NORMAL]


@pytest.mark.parametrize("change, problem", [
    ({"joints": "x"}, "arms[2].joints: expected a list, got 'x'"),
    ({"urdf": 5}, "arms[2].urdf: expected text, got 5"),
    ({"name": "p q"},
     "arms[2].name: 'p q' is not a valid name (letters, digits and underscores, not "
     "starting with a digit)"),
])
def test_an_arm_that_cannot_be_read_is_the_one_error_about_it(change, problem):
    arm = {"name": "p", "joints": [{"name": "q3", "type": "revolute", "axis": [0, 0, 1],
                                    "point": [0, 0, 0]}], **change}
    name = arm["name"]
    err = problems_of(_with_arm(arm, f"{name}/1", f"{name}/b"))
    assert err.problems == [problem, NORMAL]


def test_a_plain_arm_with_a_bad_joint_still_has_its_links_checked():
    """The links of an arm given by its joints are known even when a joint is wrong:
    a contact on a link it does not have is a problem of its own."""
    arm = {"name": "p", "joints": [{"name": "q3", "type": "rotary", "axis": [0, 0, 1],
                                    "point": [0, 0, 0]}]}
    tree = _with_arm(arm)
    tree["contacts"].append({"name": "c3", "link": "p/2", "point": [0, 0, 0],
                             "model": "hard"})
    assert problems_of(tree).problems == [
        "arms[2].joints[0].type: unknown joint type 'rotary' (expected revolute or "
        "prismatic)", NORMAL, "contacts[2].link: arm p has 1 joint, no link 2"]


def test_an_arm_without_a_name_or_no_arms_is_the_one_error():
    tree = _with_arm({"joints": []}, "p/1", "p/b")
    assert problems_of(tree).problems == ["arms[2]: missing key 'name'", NORMAL]
    tree = _with_arm(DH_ARM, "p/1", "p/b")
    tree["arms"] = "a1"
    assert problems_of(tree).problems == ["arms: expected a list, got 'a1'", NORMAL]
    tree["arms"] = []
    assert problems_of(tree).problems == ["arms: at least one arm with one joint is "
                                          "needed", NORMAL]


def test_a_failed_dh_arm_is_one_line_on_the_command_line(tmp_path):
    from typer.testing import CliRunner

    from coopkin_sym.cli import app

    tree = _with_arm({**DH_ARM, "convention": "craig"}, "d/1", "d/b")
    tree["contacts"][1]["normal"] = [0, 0, 1]
    path = tmp_path / "m.json"
    path.write_text(json.dumps(tree), encoding="utf-8")
    result = CliRunner().invoke(app, ["analyze", str(path)])
    assert result.exit_code == 2
    assert result.stderr == (f"coopkin: error: {path}: arms[2].convention: expected "
                             f"standard (Denavit-Hartenberg) or modified (Craig), got "
                             f"'craig'\n")


@pytest.mark.parametrize("parameters, problem", [
    ("L", "parameters: expected a list, got 'L'"),
    (["L L"], "parameters[0]: 'L L' is not a valid name (letters, digits and underscores, "
              "not starting with a digit)"),
    (["pi"], "parameters[0]: 'pi' is reserved (it means something else in SymPy text); "
             "choose another name"),
    (["deg"], "parameters[0]: 'deg' is reserved (it means something else in SymPy text); "
              "choose another name"),
    ([5], "parameters[0]: expected a name, got 5"),
])
def test_a_parameter_list_that_cannot_be_read_is_the_one_error_about_it(parameters,
                                                                        problem):
    """The numbers that use L are not reported as using an undeclared symbol: which
    names the list meant is unknown; other problems still are."""
    tree = case1()
    tree["parameters"] = parameters
    tree["contacts"][1]["normal"] = [0, 0, 2]
    assert problems_of(tree).problems == [problem, NORMAL]


def test_a_symbol_missing_from_a_parameter_list_that_was_read_is_reported():
    tree = case1()
    tree["parameters"] = ["L", "L", "M"]
    tree["contacts"][0]["point"] = [0, "N", 0]
    assert problems_of(tree).problems == [
        "parameters[1]: duplicate name 'L' (already used at parameters[0])",
        "contacts[0].point: 'N' uses undeclared symbol N (declared parameters: L, M)"]
