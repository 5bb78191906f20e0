"""URDF files as robots ship them: joints off the arm's chain that an arm cannot have
are ignored and said, names that are not identifiers get safe names (shown, and usable
in --at and contacts), mimic joints on the chain and xacro files are refused with the
reason, and snapped axes state their exact distance. The files are small texts written
here in the shape of real ones (a Panda-like arm with a mimic finger, an Allegro-like
finger with dotted joint names)."""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

import pytest
from bounded_run import run_coopkin

import coopkin_sym
from coopkin_sym.errors import ConfigurationError, ModelError, UrdfError
from coopkin_sym.model.urdf import IgnoredJoint, Renamed, read_urdf_text
from coopkin_sym.present.text import analysis_document, analysis_text, urdf_note_lines


def _joint(name: str, kind: str, parent: str, child: str, extra: str = "",
           xyz: str = "0 0 0.1", axis: str = "0 0 1") -> str:
    return (f'<joint name="{name}" type="{kind}"><parent link="{parent}"/>'
            f'<child link="{child}"/><origin xyz="{xyz}" rpy="0 0 0"/>'
            f'<axis xyz="{axis}"/>{extra}</joint>')


# a Panda-like arm: two revolute joints, a fixed hand, two prismatic fingers, the
# second mimicking the first, and a floating camera beside the arm
PANDA = ('<robot name="panda">'
         + "".join(f'<link name="{n}"/>' for n in ("panda_link0", "panda_link1",
                                                   "panda_link2", "panda_hand",
                                                   "panda_leftfinger",
                                                   "panda_rightfinger", "camera"))
         + _joint("panda_joint1", "revolute", "panda_link0", "panda_link1")
         + _joint("panda_joint2", "revolute", "panda_link1", "panda_link2",
                  axis="0 1 0")
         + _joint("panda_hand_joint", "fixed", "panda_link2", "panda_hand")
         + _joint("panda_finger_joint1", "prismatic", "panda_hand", "panda_leftfinger",
                  axis="0 1 0")
         + _joint("panda_finger_joint2", "prismatic", "panda_hand", "panda_rightfinger",
                  '<mimic joint="panda_finger_joint1"/>', axis="0 -1 0")
         + _joint("camera_joint", "floating", "panda_link0", "camera")
         + "</robot>")

# an Allegro-like finger: dotted joint names, a joint named like a Python keyword, a
# link name with a space and one of digits only
ALLEGRO = ('<robot name="allegro">'
           + "".join(f'<link name="{n}"/>' for n in ("palm", "link_0.0", "link 1", "2"))
           + _joint("joint_0.0", "revolute", "palm", "link_0.0")
           + _joint("joint_1.0", "revolute", "link_0.0", "link 1", axis="0 1 0")
           + _joint("lambda", "revolute", "link 1", "2", axis="0 1 0")
           + "</robot>")


def _write(tmp: Path, name: str, text: str) -> Path:
    path = tmp / name
    path.write_text(text, encoding="utf-8")
    return path


def _model(tmp: Path, name: str, text: str, link: str, **arm) -> dict:
    _write(tmp, name, text)
    return {"name": "one arm", "arms": [{"name": "h", "urdf": str(tmp / name), **arm}],
            "contacts": [{"name": "c", "link": f"h/{link}", "frame": "link",
                          "point": [0, 0, 0], "model": "hard"}]}


def test_joints_off_the_chain_are_ignored_and_said(tmp_path):
    arm = read_urdf_text(PANDA, "panda.urdf", tip="panda_hand")
    assert [j.name for j in arm.joints] == ["panda_joint1", "panda_joint2"]
    assert arm.ignored == (
        IgnoredJoint("panda.urdf", "panda_finger_joint2", "prismatic",
                     "panda_finger_joint1"),
        IgnoredJoint("panda.urdf", "camera_joint", "floating", None))
    system = coopkin_sym.load(_model(tmp_path, "panda.urdf", PANDA, "panda_hand",
                                     tip="panda_hand"))
    assert system.model.ignored == (
        IgnoredJoint("arms[0] (panda.urdf)", "panda_finger_joint2", "prismatic",
                     "panda_finger_joint1"),
        IgnoredJoint("arms[0] (panda.urdf)", "camera_joint", "floating", None))
    lines = analysis_text(system.analyze()).splitlines()
    start = lines.index("Ignored: 2 joints of URDF files off the arms' chains, left out "
                        "(an arm cannot have them: mimic, floating, planar or of an "
                        "unknown type):")
    assert lines[start + 1:start + 3] == [
        "  arms[0] (panda.urdf): joint 'panda_finger_joint2' ('prismatic', mimics "
        "'panda_finger_joint1')",
        "  arms[0] (panda.urdf): joint 'camera_joint' ('floating')"]


def test_a_chain_without_unusual_joints_says_nothing_about_them():
    arm = read_urdf_text(PANDA, "panda.urdf", tip="panda_leftfinger")
    assert [j.name for j in arm.joints] == ["panda_joint1", "panda_joint2",
                                            "panda_finger_joint1"]
    assert [j.joint for j in arm.ignored] == ["panda_finger_joint2", "camera_joint"]
    plain = read_urdf_text(PANDA.replace('<mimic joint="panda_finger_joint1"/>', "")
                           .replace('"floating"', '"fixed"'), "p.urdf", tip="panda_hand")
    assert plain.ignored == ()


@pytest.mark.parametrize("tip, message", [
    ("panda_rightfinger",
     "panda.urdf: joint 'panda_finger_joint2': mimics 'panda_finger_joint1'; a mimic "
     "(coupled) joint on the arm's chain is not supported (each joint is a variable of "
     "its own): make it fixed in a copy of the file, or choose a tip whose chain has "
     "none"),
    ("camera",
     "panda.urdf: joint 'camera_joint': type 'floating' is not supported on the arm's "
     "chain (revolute, continuous, prismatic and fixed joints make an arm)"),
])
def test_a_mimic_or_floating_joint_on_the_chain_is_refused_with_the_reason(tip, message):
    with pytest.raises(UrdfError) as info:
        read_urdf_text(PANDA, "panda.urdf", tip=tip)
    assert str(info.value) == message


def test_a_robot_that_branches_still_needs_a_tip():
    with pytest.raises(UrdfError) as info:
        read_urdf_text(PANDA, "panda.urdf")
    assert str(info.value) == ("panda.urdf: the robot branches at link 'panda_link0' "
                               "(joints 'panda_joint1', 'camera_joint'): name the arm's "
                               "last link with tip")


def test_names_that_are_not_identifiers_get_safe_names_shown_and_usable(tmp_path):
    system = coopkin_sym.load(_model(tmp_path, "allegro.urdf", ALLEGRO, "link_1"))
    model = system.model
    assert model.joint_names == ("joint_0_0", "joint_1_0", "lambda_")
    assert model.renamed == (
        Renamed("arms[0] (allegro.urdf)", "joint", "joint_0.0", "joint_0_0"),
        Renamed("arms[0] (allegro.urdf)", "joint", "joint_1.0", "joint_1_0"),
        Renamed("arms[0] (allegro.urdf)", "joint", "lambda", "lambda_"),
        Renamed("arms[0] (allegro.urdf)", "link", "link 1", "link_1"),
        Renamed("arms[0] (allegro.urdf)", "link", "2", "link_2"))
    assert [name for name, _, _ in model.arms[0].links] == ["palm", "link_0.0", "link_1",
                                                           "link_2"]
    text = analysis_text(system.analyze("joint_0_0=pi/2,lambda_=2*atan(1/2)"))
    lines = text.splitlines()
    assert lines[1] == "Configuration: joint_0_0=pi/2,lambda_=2*atan(1/2)"
    start = lines.index("Renamed: 5 names of URDF files that are not usable names (write "
                        "the new name, e.g. in --at or link: ARM/LINK):")
    assert lines[start + 1:start + 6] == [
        "  arms[0] (allegro.urdf): joint 'joint_0.0' is joint_0_0",
        "  arms[0] (allegro.urdf): joint 'joint_1.0' is joint_1_0",
        "  arms[0] (allegro.urdf): joint 'lambda' is lambda_",
        "  arms[0] (allegro.urdf): link 'link 1' is link_1",
        "  arms[0] (allegro.urdf): link '2' is link_2"]


def test_safe_names_follow_the_prefix_and_avoid_names_in_the_file(tmp_path):
    text = ALLEGRO.replace('name="lambda"', 'name="joint_0_0"')
    model = coopkin_sym.load(_model(tmp_path, "a.urdf", text, "link_0.0",
                                    prefix="r_")).model
    assert model.joint_names == ("r_joint_0_0_2", "r_joint_1_0", "r_joint_0_0")
    model = coopkin_sym.load(_model(tmp_path, "a.urdf", text, "link_0.0")).model
    assert model.joint_names == ("joint_0_0_2", "joint_1_0", "joint_0_0")


def test_a_joint_named_like_a_parameter_is_renamed(tmp_path):
    model = _model(tmp_path, "a.urdf", ALLEGRO.replace('name="joint_1.0"', 'name="L"'),
                   "link_0.0")
    model["parameters"] = ["L"]
    loaded = coopkin_sym.load(model).model
    assert loaded.joint_names == ("joint_0_0", "L_", "lambda_")
    assert Renamed("arms[0] (a.urdf)", "joint", "L", "L_") in loaded.renamed


def test_passive_joints_are_named_as_in_the_file_or_by_their_safe_name(tmp_path):
    for passive in (["joint_1.0"], ["joint_1_0"]):
        model = coopkin_sym.load(_model(tmp_path, "a.urdf", ALLEGRO, "link_0.0",
                                        passive=passive)).model
        assert model.passive_joints == ("joint_1_0",)


def test_a_renamed_joint_is_set_with_its_safe_name_on_the_command_line(tmp_path):
    model = _model(tmp_path, "allegro.urdf", ALLEGRO, "link_2")
    path = _write(tmp_path, "m.json", json.dumps(model))
    done = run_coopkin("analyze", str(path), "--at", "joint_1_0=pi/2", "--json",
                       timeout=60)
    assert (done.returncode, done.stderr) == (0, "")
    data = json.loads(done.stdout)
    assert (data["joints"], data["configuration"]) == (
        ["joint_0_0", "joint_1_0", "lambda_"], "joint_1_0=pi/2")
    bad = run_coopkin("analyze", str(path), "--at", "joint_1.0=pi/2", timeout=60)
    assert (bad.returncode, bad.stdout) == (2, "")
    assert bad.stderr == ("coopkin: error: --at joint_1.0: 'joint_1.0' is called "
                          "joint_1_0 here (a name of a URDF file that is not a variable "
                          "name gets a safe one)\n")


XACRO = ('<?xml version="1.0"?>\n<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
         '<xacro:property name="l" value="${2*pi}"/><link name="a"/></robot>')


@pytest.mark.parametrize("name, text, message", [
    ("arm.urdf.xacro", XACRO,
     "arm.urdf.xacro: a xacro file (it has xmlns:xacro and <xacro:) is not read: "
     "expanding it runs the expressions it contains; write the plain URDF first with "
     "ROS's xacro command (xacro arm.urdf.xacro > arm.urdf) and read that file"),
    ("arm.xacro", '<robot name="r"><link name="a"/></robot>',
     "arm.xacro: a xacro file (its name ends in .xacro) is not read: expanding it runs "
     "the expressions it contains; write the plain URDF first with ROS's xacro command "
     "(xacro arm.xacro > arm.urdf) and read that file"),
    ("arm.urdf", '<robot name="r"><xacro:include filename="x.xacro"/></robot>',
     "arm.urdf: a xacro file (it has <xacro:) is not read: expanding it runs the "
     "expressions it contains; write the plain URDF first with ROS's xacro command "
     "(xacro arm.urdf > arm.expanded.urdf) and read that file"),
])
def test_a_xacro_file_is_refused_with_a_pointer(tmp_path, name, text, message):
    with pytest.raises(UrdfError) as info:
        read_urdf_text(text, name)
    assert str(info.value) == message
    with pytest.raises(ModelError) as info:
        coopkin_sym.load(_model(tmp_path, name, text, "a"))
    assert info.value.problems == [f"arms[0].urdf: {message}"]


def test_the_output_of_xacro_is_read_though_it_declares_the_namespace():
    """ROS's xacro command keeps ``xmlns:xacro`` on the URDF it writes (as the Panda
    of example-robot-data has it): with nothing left to expand, the file is read; with
    a ``${...}`` left in it, it is refused."""
    text = ('<?xml version="1.0"?>\n<robot name="r" xmlns:xacro="http://www.ros.org/wiki/'
            'xacro"><link name="a"/><link name="b"/><joint name="q" type="revolute">'
            '<parent link="a"/><child link="b"/><origin xyz="0 0 0.333"/>'
            '<axis xyz="0 0 1"/></joint></robot>')
    arm = read_urdf_text(text, "arm.urdf")
    assert [(j.name, j.point) for j in arm.joints] == [("q", (0, 0, Fraction(333, 1000)))]
    with pytest.raises(UrdfError, match="a xacro file \\(it has xmlns:xacro\\)"):
        read_urdf_text(text.replace('"0 0 0.333"', '"0 0 ${l}"'), "arm.urdf")


AXIS = ('<robot name="r"><link name="a"/><link name="b"/><joint name="q" '
        'type="revolute"><parent link="a"/><child link="b"/>'
        '<axis xyz="0.7071068 0.7071068 0"/></joint></robot>')


def test_a_snapped_axis_honours_a_tight_bound_and_states_its_distance(tmp_path):
    system = coopkin_sym.load(_model(tmp_path, "r.urdf", AXIS, "b", snap="1e-9"))
    (snap,) = system.model.snapped
    assert (snap.where, snap.given, snap.exact) == (
        "arms[0] (r.urdf): joint 'q' axis", "0.7071068 0.7071068 0",
        "(927538921/1311738121, 927538920/1311738121, 0)")
    assert f"{snap.error:.3g}" == "5.39e-10"
    assert ("  arms[0] (r.urdf): joint 'q' axis: 0.7071068 0.7071068 0 -> "
            "(927538921/1311738121, 927538920/1311738121, 0) (5.4e-10 rad away)"
            in analysis_text(system.analyze()).splitlines())


def test_off_chain_joints_of_unknown_or_no_type_are_ignored_and_said():
    text = PANDA.replace('"floating"', '"spherical"').replace(
        '<joint name="panda_finger_joint1" type="prismatic"',
        '<joint name="panda_finger_joint1"')
    arm = read_urdf_text(text, "p.urdf", tip="panda_hand")
    assert arm.ignored == (
        IgnoredJoint("p.urdf", "panda_finger_joint1", None, None),
        IgnoredJoint("p.urdf", "panda_finger_joint2", "prismatic", "panda_finger_joint1"),
        IgnoredJoint("p.urdf", "camera_joint", "spherical", None))
    assert urdf_note_lines((), arm.ignored)[1:] == [
        "  p.urdf: joint 'panda_finger_joint1' (no type)",
        "  p.urdf: joint 'panda_finger_joint2' ('prismatic', mimics 'panda_finger_joint1')",
        "  p.urdf: joint 'camera_joint' ('spherical')"]


def test_renamed_and_ignored_are_in_the_analysis_json_and_fit_the_schema(tmp_path):
    import jsonschema

    schema = json.loads((Path(__file__).resolve().parents[2] / "docs"
                         / "analyze-json.schema.json").read_text())
    panda = coopkin_sym.load(_model(tmp_path, "panda.urdf", PANDA, "panda_hand",
                                    tip="panda_hand"))
    allegro = coopkin_sym.load(_model(tmp_path, "allegro.urdf", ALLEGRO, "link_1"))
    for system in (panda, allegro):
        for result in (system.analyze(), system.analyze(generic=True)):
            jsonschema.validate(analysis_document(result), schema)
    data = analysis_document(panda.analyze())
    assert data["renamed"] == []
    assert data["ignored"] == [
        {"where": "arms[0] (panda.urdf)", "joint": "panda_finger_joint2",
         "type": "prismatic", "mimics": "panda_finger_joint1"},
        {"where": "arms[0] (panda.urdf)", "joint": "camera_joint", "type": "floating",
         "mimics": None}]
    renamed = analysis_document(allegro.analyze())["renamed"]
    assert renamed[0] == {"where": "arms[0] (allegro.urdf)", "what": "joint",
                          "given": "joint_0.0", "name": "joint_0_0"}
    assert [r["name"] for r in renamed] == ["joint_0_0", "joint_1_0", "lambda_", "link_1",
                                            "link_2"]


def test_a_name_from_the_file_on_the_command_line_points_to_its_safe_name(tmp_path):
    system = coopkin_sym.load(_model(tmp_path, "allegro.urdf", ALLEGRO, "link_1"))
    with pytest.raises(ConfigurationError) as info:
        system.analyze("joint_0.0=pi/2")
    assert str(info.value) == ("--at joint_0.0: 'joint_0.0' is called joint_0_0 here (a "
                               "name of a URDF file that is not a variable name gets a "
                               "safe one)")
