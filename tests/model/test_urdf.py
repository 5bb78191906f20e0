"""Arms read from URDF files, checked against forward kinematics written here from the
exact values the files were made from (4 x 4 homogeneous matrices, independent of the
package): random chains with revolute, continuous, prismatic and fixed joints, floats
as robot files write them, and one test per refused file."""

from __future__ import annotations

import contextlib
import json
import math
import os
import random
import time
from pathlib import Path

import pytest
import sympy as sp
from bounded_run import run_coopkin, run_python
from independent import reference_analysis

import coopkin_sym
from coopkin_sym import limits
from coopkin_sym.analysis.kinematics import build
from coopkin_sym.errors import ModelError, UrdfError
from coopkin_sym.exact.sympy_bridge import ratfunc_to_sympy
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.examples import example_path
from coopkin_sym.model.urdf import read_urdf_text
from coopkin_sym.present.remarks import remark_texts
from coopkin_sym.present.text import analysis_text

# exact angles: (text in --at syntax, cos, sin, radians)
ANGLES = [("0", 1, 0), ("pi/2", 0, 1), ("-pi/2", 0, -1), ("pi", -1, 0),
          ("2*atan(1/2)", sp.Rational(3, 5), sp.Rational(4, 5)),
          ("2*atan(-1/3)", sp.Rational(4, 5), sp.Rational(-3, 5)),
          ("2*atan(3/2)", sp.Rational(-5, 13), sp.Rational(12, 13))]
# exact unit axes and a float text of each
AXES = [((0, 0, 1), "0 0 1"), ((1, 0, 0), "1 0 0"), ((0, -1, 0), "0 -1 0"),
        ((sp.Rational(3, 5), sp.Rational(4, 5), 0), "0.6 0.8 0"),
        ((0, sp.Rational(-5, 13), sp.Rational(12, 13)),
         "0 -0.38461538461538464 0.9230769230769231")]


def _radians(text: str) -> float:
    c, s = next((c, s) for t, c, s in ANGLES if t == text)
    return math.atan2(float(s), float(c))


def _rot(axis, c, s) -> sp.Matrix:
    m = sp.eye(4)
    i, j = {"x": (1, 2), "y": (2, 0), "z": (0, 1)}[axis]
    m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
    return m


def _about(axis, c, s) -> sp.Matrix:
    """Rotation about a unit axis (Rodrigues), 4 x 4."""
    k = sp.Matrix(axis)
    kx = sp.Matrix([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    m = sp.eye(4)
    m[:3, :3] = sp.eye(3) + s * kx + (1 - c) * kx * kx
    return m


def _move(v) -> sp.Matrix:
    m = sp.eye(4)
    m[:3, 3] = sp.Matrix(v)
    return m


def random_chain(rng: random.Random, robot: str) -> tuple[str, list[dict]]:
    """A URDF chain as text, and its exact description."""
    joints = []
    n = rng.randint(1, 4)
    for k in range(n):
        kind = rng.choice(["revolute", "continuous", "prismatic", "fixed", "revolute"])
        xyz = [sp.Rational(rng.randint(-5, 5), rng.choice([1, 2, 4, 10])) for _ in range(3)]
        rpy = [rng.choice(ANGLES)[0] for _ in range(3)]
        axis, axis_text = rng.choice(AXES)
        joints.append({"name": f"j{k}", "type": kind, "xyz": xyz, "rpy": rpy, "axis": axis,
                       "axis_text": axis_text})
    links = "".join(f'<link name="l{k}"/>' for k in range(n + 1))
    body = ""
    for k, j in enumerate(joints):
        xyz = " ".join(str(float(x)) for x in j["xyz"])
        rpy = " ".join(repr(_radians(a)) for a in j["rpy"])
        body += (f'<joint name="{j["name"]}" type="{j["type"]}"><parent link="l{k}"/>'
                 f'<child link="l{k + 1}"/><origin xyz="{xyz}" rpy="{rpy}"/>'
                 f'<axis xyz="{j["axis_text"]}"/>'
                 f'<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>')
    return f'<?xml version="1.0"?>\n<robot name="{robot}">{links}{body}</robot>', joints


def exact_frames(joints: list[dict], values: dict, base=None) -> list[sp.Matrix]:
    """Every link's pose (4 x 4) from the exact description, joints at ``values``."""
    frames = [base if base is not None else sp.eye(4)]
    for j in joints:
        r, p, y = (next((c, s) for t, c, s in ANGLES if t == a) for a in j["rpy"])
        t = frames[-1] * _move(j["xyz"]) * _rot("z", *y) * _rot("y", *p) * _rot("x", *r)
        if j["type"] in ("revolute", "continuous"):
            t = t * _about(j["axis"], *values.get(j["name"], (1, 0)))
        elif j["type"] == "prismatic":
            t = t * _move([values.get(j["name"], 0) * a for a in j["axis"]])
        frames.append(t)
    return frames


def _write(tmp: Path, name: str, text: str) -> Path:
    path = tmp / name
    path.write_text(text, encoding="utf-8")
    return path


def _contacts_points(system, at: str) -> list:
    kin = build(system.model, Configuration.parse(system.model, at))
    return [(tuple(ratfunc_to_sympy(x, kin.symbols) for x in p),
             tuple(ratfunc_to_sympy(x, kin.symbols) for x in n))
            for p, n in zip(kin.points, kin.normals, strict=True)]


@pytest.mark.parametrize("seed", range(25))
def test_random_urdf_chains_move_their_links_as_urdf_kinematics_says(seed, tmp_path):
    rng = random.Random(seed)
    text, joints = random_chain(rng, f"r{seed}")
    _write(tmp_path, "arm.urdf", text)
    moving = [j for j in joints if j["type"] != "fixed"]
    if not moving:   # an arm needs a moving joint: the first one turns
        joints[0]["type"] = "revolute"
        _write(tmp_path, "arm.urdf", text.replace('type="fixed"', 'type="revolute"', 1))
        moving = [joints[0]]
    tip = f"l{len(joints)}"
    point, normal = [1, 0, "1/2"], [0, sp.Rational(3, 5), sp.Rational(4, 5)]
    model = {"name": "urdf", "arms": [{"name": "a", "urdf": str(tmp_path / "arm.urdf"),
                                       "snap": "1e-9"}],
             "contacts": [{"name": "c", "link": f"a/{tip}", "frame": "link",
                           "point": point, "normal": [str(x) for x in normal],
                           "model": "soft"}]}
    system = coopkin_sym.load(model)
    assert [j.name for j in system.model.joints] == [j["name"] for j in moving]
    for _ in range(3):
        values, at = {}, []
        for j in moving:
            if j["type"] == "prismatic":
                values[j["name"]] = sp.Rational(rng.randint(-3, 3), 2)
                at.append(f"{j['name']}={values[j['name']]}")
            else:
                text_angle, c, s = rng.choice(ANGLES)
                values[j["name"]] = (c, s)
                at.append(f"{j['name']}={text_angle}")
        t = exact_frames(joints, values)[-1]
        want_p = t * sp.Matrix([sp.Rational(1), 0, sp.Rational(1, 2), 1])
        want_n = t[:3, :3] * sp.Matrix(normal)
        (p, n), = _contacts_points(system, ",".join(at))
        assert [sp.simplify(a - b) for a, b in zip(p, want_p[:3], strict=True)] == [0, 0, 0]
        assert [sp.simplify(a - b) for a, b in zip(n, want_n, strict=True)] == [0, 0, 0]


def fingers_by_hand() -> dict:
    """The shipped urdf-two-fingers, written joint by joint."""
    return {"name": "two URDF fingers", "arms": [
        {"name": "left", "joints": [
            {"name": "l_mcp", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]},
            {"name": "l_pip", "type": "revolute", "axis": [0, 0, 1],
             "point": ["1/10", 0, 0]}]},
        {"name": "right", "joints": [
            {"name": "r_mcp", "type": "revolute", "axis": [0, 0, -1],
             "point": ["3/10", 0, 0]},
            {"name": "r_pip", "type": "revolute", "axis": [0, 0, -1],
             "point": ["1/5", 0, 0]}]}],
        "contacts": [
            {"name": "c1", "link": "left/2", "point": ["1/10", "1/10", 0],
             "normal": [1, 0, 0], "model": "hard"},
            {"name": "c2", "link": "right/2", "point": ["1/5", "1/10", 0],
             "normal": [-1, 0, 0], "model": "hard"}]}


def test_two_urdf_arms_have_the_numbers_of_the_same_system_written_by_hand():
    system = coopkin_sym.load("urdf-two-fingers")
    assert [j.name for j in system.model.joints] == ["l_mcp", "l_pip", "r_mcp", "r_pip"]
    by_hand = fingers_by_hand()
    assert system.model.contacts == coopkin_sym.load(by_hand).model.contacts
    for at, values in [("", {}), ("l_mcp=pi/2,r_pip=2*atan(1/2)",
                                  {"l_mcp": (0, 1), "r_pip": ANGLES[4][1:]})]:
        reference = reference_analysis(by_hand, values)
        ours = system.analyze(at or None).numbers.as_dict()
        assert ours == {k: reference[k] for k in ours}
    assert system.analyze(generic=True).numbers.as_dict() == {
        "Nm": 4, "Nc": 4, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 2, "Nh": 0}


def test_snapped_floats_are_stated():
    system = coopkin_sym.load("urdf-two-fingers")
    assert [(s.given, s.exact) for s in system.model.snapped] == [("1.5708", "pi/2")] * 2
    assert all(0 < s.error < 1e-5 for s in system.model.snapped)
    text = analysis_text(system.analyze())
    assert "Snapped: 2 floats of URDF files replaced by exact values" in text
    assert "joint 'pip' origin rpy[2]: 1.5708 -> pi/2 (3.7e-06 rad away)" in text
    assert any("replaced by exact values" in n for n in remark_texts(system.locus().notes))


def test_a_bound_too_tight_for_a_float_is_said():
    text = ('<robot name="r"><link name="a"/><link name="b"/><joint name="j" '
            'type="revolute"><parent link="a"/><child link="b"/>'
            '<origin rpy="0 0 1.5708"/><axis xyz="0 0 1"/></joint></robot>')
    arm = read_urdf_text(text, "r.urdf", bound=1e-9)
    # 1.5708 is not pi/2 within 1e-9: the nearest exact angle within the bound is taken
    assert arm.snapped[0].exact != "pi/2" and arm.snapped[0].error <= 1e-9


def _robot(body: str, links: str = '<link name="a"/><link name="b"/>') -> str:
    return f'<robot name="r">{links}{body}</robot>'


JOINT = ('<joint name="j" type="{type}"><parent link="a"/><child link="b"/>{extra}'
         '</joint>')


@pytest.mark.parametrize("text, message", [
    (_robot(JOINT.format(type="floating", extra="")),
     r"^r\.urdf: joint 'j': type 'floating' is not supported on the arm's chain "
     r"\(revolute, continuous, prismatic and fixed joints make an arm\)$"),
    (_robot(JOINT.format(type="planar", extra="")),
     r"^r\.urdf: joint 'j': type 'planar' is not supported on the arm's chain "),
    (_robot(JOINT.format(type="revolute", extra='<mimic joint="k"/>')),
     r"^r\.urdf: joint 'j': mimics 'k'; a mimic \(coupled\) joint on the arm's chain is "
     r"not supported \(each joint is a variable of its own\): make it fixed in a copy of "
     r"the file, or choose a tip whose chain has none$"),
    (_robot(JOINT.format(type="revolute", extra="")
            + '<joint name="k" type="revolute"><parent link="a"/><child link="b"/></joint>'),
     r"joint 'k': link 'b' already has the parent joint 'j': a closed loop is not "
     r"supported"),
    (_robot('<joint name="j" type="fixed"><parent link="b"/><child link="b"/></joint>'),
     r"^r\.urdf: a closed loop: joint 'j' leads from link 'b' back to 'b' \(a link "
     r"cannot be its own ancestor\)$"),
    (_robot('<joint name="j" type="fixed"><parent link="b"/><child link="c"/></joint>'
            '<joint name="k" type="fixed"><parent link="c"/><child link="b"/></joint>',
            '<link name="a"/><link name="b"/><link name="c"/>'),
     r"^r\.urdf: a closed loop: joints 'k', 'j' lead from link 'c' through 'b' back to "
     r"'c' \(a link cannot be its own ancestor\)$"),
    (_robot('<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>'
            '<joint name="k" type="fixed"><parent link="b"/><child link="c"/></joint>'
            '<joint name="m" type="fixed"><parent link="c"/><child link="a"/></joint>',
            '<link name="a"/><link name="b"/><link name="c"/>'),
     r"^r\.urdf: a closed loop: joints 'k', 'm', 'j' lead from link 'b' through 'c', 'a' "
     r"back to 'b' \(a link cannot be its own ancestor\)$"),
    (_robot("", '<link name="a"/><link name="b"/><link name="a"/>'),
     r"^r\.urdf: two links are named 'a'$"),
    (_robot("", "".join(f'<link name="l{i}"/>' for i in range(10))),
     r"^r\.urdf: expected one root link, found 'l0', 'l1', 'l2', 'l3', 'l4', 'l5', \.\.\. "
     r"\(10 in all\)$"),
    (_robot('<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>'
            '<joint name="k" type="fixed"><parent link="a"/><child link="c"/></joint>',
            '<link name="a"/><link name="b"/><link name="c"/>'),
     r"the robot branches at link 'a' \(joints 'j', 'k'\): name the arm's last link"),
    (_robot(JOINT.format(type="revolute", extra='<origin xyz="0 0"/>')),
     r"joint 'j': origin xyz '0 0': expected 3 numbers"),
    (_robot(JOINT.format(type="revolute", extra='<origin rpy="0 0 x"/>')),
     r"joint 'j' origin rpy\[2\]: 'x' is not a number"),
    (_robot(JOINT.format(type="revolute", extra='<origin rpy="0 0 inf"/>')),
     r"'inf' is not a finite number"),
    (_robot(JOINT.format(type="revolute", extra='<axis xyz="0 0 0"/>')),
     r"axis xyz '0 0 0' is the zero vector"),
    (_robot(JOINT.format(type="revolute", extra="").replace('link="b"', 'link="z"')),
     r"joint 'j': unknown link 'z'"),
    ("<robot name='r'><link/></robot>", r"every <link> needs a name"),
    ("<model/>", r"the root element is <model>, expected <robot>"),
    ("<robot", r"not a URDF file"),
    ('<!DOCTYPE r [<!ENTITY a "aaaa">]><robot name="r"><link name="&a;"/></robot>',
     r"not a URDF file \(DTDForbidden: a DTD, entity or external reference is forbidden"),
])
def test_bad_urdf_gets_one_clear_error(text, message):
    with pytest.raises(UrdfError, match=message):
        read_urdf_text(text, "r.urdf")


def _loop_beside_the_chain(tmp: Path) -> Path:
    """A model whose URDF arm ends at a tip on a closed loop that the root does not
    reach (walking from that tip towards the root never ended)."""
    _write(tmp, "loop.urdf", _robot(
        '<joint name="j0" type="revolute"><parent link="a"/><child link="x"/>'
        '<axis xyz="0 0 1"/></joint>'
        '<joint name="j1" type="revolute"><parent link="b"/><child link="c"/>'
        '<axis xyz="0 0 1"/></joint>'
        '<joint name="j2" type="revolute"><parent link="c"/><child link="b"/>'
        '<axis xyz="0 0 1"/></joint>',
        '<link name="a"/><link name="x"/><link name="b"/><link name="c"/>'))
    return _write(tmp, "m.json", json.dumps(
        {"arms": [{"name": "f", "urdf": "loop.urdf", "tip": "c"}],
         "contacts": [{"name": "k", "link": "f/c", "point": [1, 0, 0], "model": "hard"}]}))


def test_a_tip_on_a_closed_loop_is_one_error_at_once(tmp_path):
    model = _loop_beside_the_chain(tmp_path)
    done = run_coopkin("analyze", str(model), timeout=30)
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr == (f"coopkin: error: {model}: arms[0].urdf: loop.urdf: a closed "
                           f"loop: joints 'j2', 'j1' lead from link 'c' through 'b' back "
                           f"to 'c' (a link cannot be its own ancestor)\n")


def _chain_text(joints: int, *, links_first: bool = True, body: str = "",
                short: bool = False) -> str:
    """A chain of revolute joints l0 -> l1 -> ... (``short``: fixed joints with nothing
    but their links)."""
    links = "".join(f'<link name="l{i}"/>' for i in range(joints + 1))
    inside = "" if short else \
        '<origin xyz="0 0 0.1" rpy="0 0 0.3"/><axis xyz="0 0 1"/>' + body
    chain = "".join(f'<joint name="j{i}" type="{"fixed" if short else "revolute"}">'
                    f'<parent link="l{i}"/><child link="l{i + 1}"/>{inside}</joint>'
                    for i in range(joints))
    return f'<robot name="r">{links + chain if links_first else chain + links}</robot>'


# a URDF file of 5,000 or 70,000 joints, timed in a fresh interpreter
_TIMED = """
import json, sys, time
from coopkin_sym.errors import UrdfError
from coopkin_sym.model.urdf import read_urdf
start = time.monotonic()
try:
    read_urdf(sys.argv[1])
    message = None
except UrdfError as exc:
    message = str(exc)
print(json.dumps([message, time.monotonic() - start]))
"""


@pytest.mark.parametrize("joints, links_first, what", [
    (5000, True, "links"), (5000, False, "joints"), (70_000, True, "links"),
    (70_000, False, "joints")])
def test_urdf_files_of_thousands_of_joints_are_refused_at_once(tmp_path, joints,
                                                               links_first, what):
    path = _write(tmp_path, "big.urdf", _chain_text(joints, links_first=links_first,
                                                    short=joints > 5000))
    assert path.stat().st_size < 8 * 1024 * 1024
    done = run_python(_TIMED.replace("sys.argv[1]", repr(str(path))), timeout=60)
    message, seconds = json.loads(done.stdout)
    assert message == f"big.urdf: more than 4,000 {what} (the limit for a URDF file)"
    assert seconds < 0.5


def test_a_large_urdf_file_is_one_line_on_the_command_line(tmp_path):
    _write(tmp_path, "big.urdf", _chain_text(5000))
    model = _write(tmp_path, "m.json", json.dumps(
        {"arms": [{"name": "f", "urdf": "big.urdf"}],
         "contacts": [{"name": "k", "link": "f/1", "point": [1, 0, 0], "model": "hard"}]}))
    done = run_coopkin("analyze", str(model), timeout=60)
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr == (f"coopkin: error: {model}: arms[0].urdf: big.urdf: more than "
                           f"4,000 links (the limit for a URDF file)\n")


@pytest.mark.parametrize("limit, value, text, message", [
    ("MAX_URDF_LINKS", 3, _chain_text(2), None),
    ("MAX_URDF_LINKS", 2, _chain_text(2), "more than 2 links (the limit for a URDF file)"),
    ("MAX_URDF_JOINTS", 2, _chain_text(2), None),
    ("MAX_URDF_JOINTS", 1, _chain_text(2), "more than 1 joints (the limit for a URDF "
                                           "file)"),
    ("MAX_URDF_ELEMENTS", 14, _chain_text(2), None),   # robot, 3 links, 2 x 5 in joints
    ("MAX_URDF_ELEMENTS", 13, _chain_text(2), "more than 13 XML elements (the limit for "
                                              "a URDF file)"),
    ("MAX_DEPTH", 4, _chain_text(2, body="<a><b/></a>"), None),
    ("MAX_DEPTH", 3, _chain_text(2, body="<a><b/></a>"), "XML elements nested more than "
                                                         "3 deep (the limit for a URDF "
                                                         "file)"),
    ("MAX_URDF_CHAIN", 2, _chain_text(2), None),
    ("MAX_URDF_CHAIN", 1, _chain_text(2), "the chain from link 'l0' has more than 1 "
                                          "joints (the limit for one arm)"),
])
def test_urdf_budgets(monkeypatch, limit, value, text, message):
    monkeypatch.setattr(limits, limit, value)
    for tip in (None, "l2"):
        if message is None:
            assert len(read_urdf_text(text, "r.urdf", tip=tip).joints) == 2
        else:
            with pytest.raises(UrdfError) as info:
                read_urdf_text(text, "r.urdf", tip=tip)
            assert str(info.value) == f"r.urdf: {message}"


def test_a_urdf_text_handed_over_is_bounded_like_a_file(monkeypatch):
    monkeypatch.setattr(limits, "MAX_FILE_BYTES", len(FINGER))
    assert len(read_urdf_text(FINGER, "f.urdf").joints) == 1
    with pytest.raises(UrdfError, match=rf"^f\.urdf: the text is longer than "
                                        rf"{len(FINGER)} bytes \(the limit for a URDF "
                                        rf"file\)$"):
        read_urdf_text(FINGER + " ", "f.urdf")


def test_a_flood_of_elements_or_of_nesting_stops_the_parse(tmp_path):
    for body, message in (("<a/>" * 2_000_000, "more than 100,000 XML elements"),
                          ("<a>" * 1_000_000 + "</a>" * 1_000_000,
                           "XML elements nested more than 32 deep")):
        text = f'<robot name="r"><link name="l"/>{body}</robot>'
        assert len(text) < 8 * 1024 * 1024
        start = time.monotonic()
        with pytest.raises(UrdfError, match=f"^r.urdf: {message} \\(the limit for a URDF "
                                            f"file\\)$"):
            read_urdf_text(text, "r.urdf")
        assert time.monotonic() - start < 2


def test_tip_chooses_a_chain_of_a_branching_robot():
    text = _robot('<joint name="j" type="revolute"><parent link="a"/><child link="b"/>'
                  '<axis xyz="0 0 1"/></joint>'
                  '<joint name="k" type="prismatic"><parent link="a"/><child link="c"/>'
                  '<axis xyz="1 0 0"/></joint>',
                  '<link name="a"/><link name="b"/><link name="c"/>')
    assert [j.name for j in read_urdf_text(text, "r.urdf", tip="c").joints] == ["k"]
    with pytest.raises(UrdfError, match=r"tip: no link 'd'"):
        read_urdf_text(text, "r.urdf", tip="d")


FINGER = ('<robot name="f"><link name="a"/><link name="b"/><joint name="q" '
          'type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>'
          '</joint></robot>')


def _arm_model(tmp: Path, arm: dict, contact: dict | None = None) -> dict:
    _write(tmp, "f.urdf", FINGER)
    return {"arms": [{"name": "f", "urdf": str(tmp / "f.urdf"), **arm}],
            "contacts": [contact or {"name": "c", "link": "f/b", "point": [1, 0, 0],
                                     "normal": [1, 0, 0], "model": "hard"}]}


@pytest.mark.parametrize("arm, contact, message", [
    ({"joints": []}, None, r"arms\[0\]\.joints: an arm read from a URDF file has no joints"),
    ({"snap": 2}, None, r"arms\[0\]\.snap: expected a bound between 0 and 1"),
    ({"urdf": "missing.urdf"}, None, r"arms\[0\]\.urdf: .*missing\.urdf: no such file"),
    ({"prefix": "1"}, None, r"^arms\[0\]\.prefix: '1' is not a valid start of a name "
                            r"\(letters, digits and underscores, not starting with a "
                            r"digit\)$"),
    ({}, {"name": "c", "link": "f/z", "point": [0, 0, 0], "model": "hard"},
     r"contacts\[0\]\.link: arm f has no link 'z' on its chain \(links: a, b\)"),
])
def test_bad_urdf_arms_get_one_clear_error(tmp_path, arm, contact, message):
    with pytest.raises(ModelError, match=message):
        coopkin_sym.load(_arm_model(tmp_path, arm, contact))


def _file_arm_model(urdf: Path | str) -> dict:
    return {"arms": [{"name": "f", "urdf": str(urdf)}],
            "contacts": [{"name": "c", "link": "f/1", "point": [1, 0, 0], "model": "hard"}]}


def test_a_urdf_path_naming_a_pipe_is_refused_before_it_is_read(tmp_path):
    pipe = tmp_path / "f.urdf"
    os.mkfifo(pipe)
    _write(tmp_path, "m.json", json.dumps(_file_arm_model("f.urdf")))
    try:
        done = run_coopkin("analyze", str(tmp_path / "m.json"), timeout=30)
    finally:   # a reader blocked on it (a regression) gets an end of file
        with contextlib.suppress(OSError):
            os.close(os.open(pipe, os.O_WRONLY | os.O_NONBLOCK))
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr == (f"coopkin: error: {tmp_path / 'm.json'}: arms[0].urdf: {pipe}: "
                           f"is a named pipe (FIFO), not a regular file\n")


def test_a_urdf_path_naming_a_device_or_a_directory_is_refused(tmp_path):
    _write(tmp_path, "m.json", json.dumps(_file_arm_model("/dev/zero")))
    done = run_coopkin("analyze", str(tmp_path / "m.json"), timeout=30)
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr == (f"coopkin: error: {tmp_path / 'm.json'}: arms[0].urdf: "
                           f"/dev/zero: is a character device, not a regular file\n")
    with pytest.raises(ModelError) as info:
        coopkin_sym.load(_file_arm_model("/"))
    assert info.value.problems == ["arms[0].urdf: /: is a directory, not a file"]


FLOATING = _robot(JOINT.format(type="floating", extra=""))
BRANCHING = _robot('<joint name="j" type="revolute"><parent link="a"/><child link="b"/>'
                   '<axis xyz="0 0 1"/></joint>'
                   '<joint name="k" type="prismatic"><parent link="a"/><child link="c"/>'
                   '<axis xyz="1 0 0"/></joint>',
                   '<link name="a"/><link name="b"/><link name="c"/>')


def _refused_arm_model(tmp: Path, text: str, **arm) -> dict:
    """Arm f read from ``text`` with contacts on its links by name, by number and in
    a link's frame; arm g is fine, but its contact has a normal that is not a unit
    vector (a problem of its own)."""
    _write(tmp, "f.urdf", text)
    on = [("f/b", "base"), ("f/b", "link"), ("f/1", "base"), ("f/0", "link")]
    return {"arms": [{"name": "f", "urdf": str(tmp / "f.urdf"), **arm},
                     {"name": "g", "joints": [{"name": "p", "type": "revolute",
                                               "axis": [0, 0, 1], "point": [0, 0, 0]}]}],
            "contacts": [{"name": "g1", "link": "g/1", "point": [1, 0, 0],
                          "normal": [0, 3, 0], "model": "hard"}]
            + [{"name": f"f{k}", "link": link, "frame": frame, "point": [1, 0, 0],
                "normal": [1, 0, 0], "model": "hard"} for k, (link, frame) in enumerate(on)]}


@pytest.mark.parametrize("text, arm, problem", [
    (FLOATING, {}, "arms[0].urdf: f.urdf: joint 'j': type 'floating' is not supported "
                   "on the arm's chain (revolute, continuous, prismatic and fixed joints "
                   "make an arm)"),
    (BRANCHING, {"tip": 7}, "arms[0].tip: expected text, got 7"),
    (BRANCHING, {"tip": "b", "prefix": ["l_"]}, "arms[0].prefix: expected text, got "
                                                "['l_']"),
    (FINGER, {"base": {"rpy": [0, 0, "x"]}},
     "arms[0].base.rpy[2]: 'x' uses undeclared symbol x (declared parameters: none)"),
])
def test_a_refused_urdf_arm_is_the_one_error_about_it(tmp_path, text, arm, problem):
    with pytest.raises(ModelError) as info:
        coopkin_sym.load(_refused_arm_model(tmp_path, text, **arm))
    assert info.value.problems == [problem, "contacts[0].normal: not a unit vector "
                                            "(squared length 9); did you mean [0, 1, 0]?"]


def test_a_refused_urdf_arm_is_one_line_on_the_command_line(tmp_path):
    model = _refused_arm_model(tmp_path, FLOATING)
    model["contacts"][0]["normal"] = [0, 1, 0]
    path = _write(tmp_path, "m.json", json.dumps(model))
    done = run_coopkin("analyze", str(path), timeout=30)
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr == (f"coopkin: error: {path}: arms[0].urdf: f.urdf: joint 'j': "
                           f"type 'floating' is not supported on the arm's chain "
                           f"(revolute, continuous, prismatic and fixed joints make an "
                           f"arm)\n")


def test_two_arms_from_one_file_need_prefixes(tmp_path):
    model = _arm_model(tmp_path, {})
    model["arms"].append({"name": "g", "urdf": str(tmp_path / "f.urdf")})
    with pytest.raises(ModelError, match=r"arms\[1\]\.urdf: joint 1 \('q'\): duplicate "
                                         r"name 'q'"):
        coopkin_sym.load(model)
    model["arms"][1]["prefix"] = "g_"
    assert coopkin_sym.load(model).model.joint_names == ("q", "g_q")


def test_urdf_keys_belong_to_urdf_arms():
    with pytest.raises(ModelError, match=r"arms\[0\]\.tip: only an arm read from a URDF"):
        coopkin_sym.load({"arms": [{"name": "a", "tip": "x", "joints": [
            {"name": "q", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]}]}],
            "contacts": [{"name": "c", "link": "a/1", "point": [1, 0, 0],
                          "model": "hard"}]})


def test_a_relative_urdf_path_is_read_beside_the_model_file(tmp_path):
    _write(tmp_path, "f.urdf", FINGER)
    _write(tmp_path, "m.yaml", "arms:\n  - {name: f, urdf: f.urdf}\ncontacts:\n"
                               "  - {name: c, link: f/b, point: [1, 0, 0], model: hard}\n")
    assert coopkin_sym.load(str(tmp_path / "m.yaml")).model.joint_names == ("q",)


def test_loading_a_urdf_file_alone_says_how_to_use_it():
    urdf = example_path("urdf-two-fingers").with_name("planar-2r-finger.urdf")
    with pytest.raises(ModelError, match=r"a URDF file describes one robot, not a "
                                         r"cooperating system: write a model file with an "
                                         r"arm 'urdf: planar-2r-finger.urdf'"):
        coopkin_sym.load(str(urdf))
