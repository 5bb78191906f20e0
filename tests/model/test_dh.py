"""Arms given as DH tables, checked against DH forward kinematics written here with
SymPy (4 x 4 homogeneous matrices, the textbook products), independently of the
package: contact points and normals at random exact configurations, joint axes at
home, and the numbers against the independent analysis of the same system."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from independent import angle_from_text, reference_analysis
from support import texts

import coopkin_sym
from coopkin_sym.analysis.kinematics import build
from coopkin_sym.errors import ModelError
from coopkin_sym.exact.sympy_bridge import ratfunc_to_sympy
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.examples import example_path
from coopkin_sym.model.trees import read_file

# exact angles with their cosine and sine
ANGLES = {"0": (1, 0), "pi/2": (0, 1), "-pi/2": (0, -1), "pi": (-1, 0),
          "2*atan(1/2)": (sp.Rational(3, 5), sp.Rational(4, 5)),
          "2*atan(-1/3)": (sp.Rational(4, 5), sp.Rational(-3, 5)),
          "2*atan(2)": (sp.Rational(-3, 5), sp.Rational(4, 5)),
          "2*atan(1/5)": (sp.Rational(12, 13), sp.Rational(5, 13))}
NORMALS = [(1, 0, 0), (0, -1, 0), (0, 0, 1), (0, sp.Rational(3, 5), sp.Rational(4, 5)),
           (sp.Rational(-12, 13), 0, sp.Rational(5, 13))]


def _rot(axis: str, c, s) -> sp.Matrix:
    m = sp.eye(4)
    i, j = {"x": (1, 2), "y": (2, 0), "z": (0, 1)}[axis]
    m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
    return m


def _move(x, y, z) -> sp.Matrix:
    m = sp.eye(4)
    m[0, 3], m[1, 3], m[2, 3] = x, y, z
    return m


def _cs(text):
    """cos and sin of an exact angle: from the table, else by the independent module."""
    return ANGLES[str(text)] if str(text) in ANGLES else angle_from_text(str(text))


def _plus(a, b):
    """cos and sin of a sum."""
    (c1, s1), (c2, s2) = a, b
    return c1 * c2 - s1 * s2, s1 * c2 + c1 * s2


def _num(value, params):
    """A length: a rational, or an expression in the parameters (given values)."""
    if isinstance(value, str):
        return sp.sympify(value, locals={k: sp.Symbol(k) for k in params}, rational=True).subs(
            {sp.Symbol(k): v for k, v in params.items()})
    return sp.Rational(value)


def dh_frames(arm: dict, at: dict, params: dict) -> list[sp.Matrix]:
    """``T_0 .. T_n`` of one DH arm (4 x 4), the joint values ``at`` (cos, sin) pairs
    for revolute joints and rationals for prismatic ones; missing joints at 0."""
    base = arm.get("base", {})
    x, y, z = (_num(v, params) for v in base.get("xyz", [0, 0, 0]))
    roll, pitch, yaw = (_cs(v) for v in base.get("rpy", [0, 0, 0]))
    frames = [_move(x, y, z) * _rot("z", *yaw) * _rot("y", *pitch) * _rot("x", *roll)]
    modified = arm.get("convention") == "modified"
    for row in arm["dh"]:
        theta = _cs(row.get("theta", 0))
        d = _num(row.get("d", 0), params)
        if row["type"] == "revolute":
            theta = _plus(theta, at.get(row["name"], (1, 0)))
        else:
            d = d + at.get(row["name"], 0)
        a, alpha = _num(row.get("a", 0), params), _cs(row.get("alpha", 0))
        if modified:
            step = _rot("x", *alpha) * _move(a, 0, 0) * _rot("z", *theta) * _move(0, 0, d)
        else:
            step = _rot("z", *theta) * _move(0, 0, d) * _move(a, 0, 0) * _rot("x", *alpha)
        frames.append(frames[-1] * step)
    return frames


def dh_contacts(model: dict, at: dict, params: dict) -> dict:
    """Each contact's point and normal in the base frame, by DH forward kinematics."""
    arms = {arm["name"]: dh_frames(arm, at, params) for arm in model["arms"]}
    out = {}
    for c in model["contacts"]:
        name, k = c["link"].split("/")
        t = arms[name][int(k)]
        p = t * sp.Matrix([*(_num(v, params) for v in c["point"]), 1])
        n = t[:3, :3] * sp.Matrix([sp.Rational(v) for v in c["normal"]]) \
            if "normal" in c else None
        out[c["name"]] = (sp.expand(p[:3, 0]), n)
    return out


def as_joints(model: dict) -> dict:
    """The same system in the joints form (axes and points at home), from the DH
    frames at home: for the independent analysis."""
    arms = []
    for arm in model["arms"]:
        frames = dh_frames(arm, {}, {})
        modified = arm.get("convention") == "modified"
        joints = []
        for i, row in enumerate(arm["dh"]):
            if modified:   # z of frame i, before the slide d_i
                t = frames[i + 1] * _move(0, 0, -_num(row.get("d", 0), {}))
            else:
                t = frames[i]
            joints.append({"name": row["name"], "type": row["type"],
                           "axis": [str(x) for x in t[:3, 2]],
                           "point": [str(x) for x in t[:3, 3]]})
        arms.append({"name": arm["name"], "joints": joints})
    home = dh_contacts(model, {}, {})
    contacts = [{"name": c["name"], "link": c["link"], "model": c["model"],
                 "point": [str(x) for x in home[c["name"]][0]],
                 **({"normal": [str(x) for x in home[c["name"]][1]]} if "normal" in c
                    else {})}
                for c in model["contacts"]]
    return {"name": model.get("name", "dh"), "arms": arms, "contacts": contacts}


def random_dh_model(rng: random.Random) -> dict:
    arms = []
    for k in range(rng.randint(1, 2)):
        rows = []
        for i in range(rng.randint(1, 3)):
            rows.append({"name": f"j{k}{i}", "type": rng.choice(["revolute"] * 3
                                                                 + ["prismatic"]),
                         "theta": rng.choice(list(ANGLES)), "d": rng.choice([0, 1, "1/2"]),
                         "a": rng.choice([0, 1, "2/3", -1]),
                         "alpha": rng.choice(list(ANGLES))})
        arms.append({"name": f"a{k}", "convention": rng.choice(["standard", "modified"]),
                     "base": {"xyz": [rng.randint(-2, 2) for _ in range(3)],
                              "rpy": [rng.choice(list(ANGLES)) for _ in range(3)]},
                     "dh": rows})
    contacts = []
    for k, arm in enumerate(arms):
        for j in range(rng.randint(1, 2)):
            contacts.append({"name": f"c{k}{j}", "link": f"a{k}/{rng.randint(0, len(arm['dh']))}",
                             "frame": "link", "point": [rng.randint(-1, 1) for _ in range(3)],
                             "normal": list(rng.choice(NORMALS)),
                             "model": rng.choice(["hard", "soft", "frictionless"])})
    return {"name": "random DH", "arms": arms, "contacts": contacts}


def random_at(model: dict, rng: random.Random) -> tuple[str, dict]:
    text, values = [], {}
    for arm in model["arms"]:
        for row in arm["dh"]:
            if row["type"] == "revolute":
                angle = rng.choice(list(ANGLES))
                text.append(f"{row['name']}={angle}")
                values[row["name"]] = ANGLES[angle]
            else:
                d = sp.Rational(rng.randint(-4, 4), rng.randint(1, 3))
                text.append(f"{row['name']}={d}")
                values[row["name"]] = d
    return ",".join(text), values


def engine_contacts(system, at: str) -> list:
    model = system.model
    kin = build(model, Configuration.parse(model, at))
    return [(tuple(ratfunc_to_sympy(x, kin.symbols) for x in p),
             None if n is None else tuple(ratfunc_to_sympy(x, kin.symbols) for x in n))
            for p, n in zip(kin.points, kin.normals, strict=True)]


def _same(engine, direct) -> bool:
    return all(sp.simplify(a - b) == 0 for a, b in zip(engine, direct, strict=True))


@pytest.mark.parametrize("seed", range(40))
def test_random_dh_arms_move_their_contacts_as_dh_kinematics_says(seed):
    rng = random.Random(seed)
    raw = random_dh_model(rng)
    system = coopkin_sym.load(raw)
    for _ in range(2):
        at, values = random_at(raw, rng)
        direct = dh_contacts(raw, values, {})
        for (p, n), c in zip(engine_contacts(system, at), raw["contacts"], strict=True):
            dp, dn = direct[c["name"]]
            assert _same(p, dp), (seed, at, c["name"])
            assert _same(n, dn), (seed, at, c["name"])
        # the numbers, against the independent analysis of the same system
        reference = reference_analysis(as_joints(raw), values)
        ours = system.analyze(at).numbers.as_dict()
        assert ours == {k: reference[k] for k in ours}, (seed, at)


@pytest.mark.parametrize("name", ["dh-three-finger-hand", "dh-two-puma560-box"])
def test_shipped_dh_examples_follow_dh_kinematics(name):
    raw = read_file(example_path(name))
    system = coopkin_sym.load(name)
    params = {p.name: sp.Rational(k + 2, 3) for k, p in enumerate(system.model.parameters)}
    rng = random.Random(7)
    for _ in range(3):
        at, values = random_at(raw, rng)
        at += "".join(f",{k}={v}" for k, v in params.items())
        direct = dh_contacts(raw, values, params)
        for (p, n), c in zip(engine_contacts(system, at), raw["contacts"], strict=True):
            assert _same(p, direct[c["name"]][0]) and _same(n or (), direct[c["name"]][1]
                                                             or ()), (at, c["name"])


def test_two_pumas_holding_a_box_have_the_numbers_of_a_rigid_closed_chain():
    system = coopkin_sym.load("dh-two-puma560-box")
    # 12 joints, 6 object twist components, 2 x 6 constraints: 6 motions, each object
    # twist reached by exactly one joint motion (both arms regular)
    generic = system.analyze(generic=True).numbers.as_dict()
    assert generic == {"Nm": 6, "Nc": 6, "Ni": 0, "Nr": 0, "Ng": 6, "Nd": 0, "Nh": 0}
    # at home both wrists are straight (q5 = 0): each arm gains a self-motion
    # (joints 4 and 6 turn against each other), and the box loses one coordinated motion
    home = system.analyze().numbers.as_dict()
    assert home == {"Nm": 7, "Nc": 5, "Ni": 0, "Nr": 2, "Ng": 6, "Nd": 2, "Nh": 1}
    raw = read_file(example_path("dh-two-puma560-box"))
    reference = reference_analysis(as_joints(raw), {})
    assert {k: reference[k] for k in home} == home


def test_three_finger_hand_numbers():
    system = coopkin_sym.load("dh-three-finger-hand")
    # 9 joints, 3 soft fingers (4 constraints each): 9 + 6 - 12 = 3 motions of the
    # object, all coordinated, none redundant
    generic = system.analyze(generic=True).numbers.as_dict()
    assert generic == {"Nm": 3, "Nc": 3, "Ni": 0, "Nr": 0, "Ng": 6, "Nd": 3, "Nh": 0}
    raw = read_file(example_path("dh-three-finger-hand"))
    at = "f1_2=2*atan(1/2),f2_2=2*atan(-1/3),f3_2=2*atan(1/5),f1_3=pi/2,R=1,L1=2,L2=1"
    values = {"f1_2": ANGLES["2*atan(1/2)"], "f2_2": ANGLES["2*atan(-1/3)"],
              "f3_2": ANGLES["2*atan(1/5)"], "f1_3": ANGLES["pi/2"]}
    joints = as_joints({**raw, "arms": raw["arms"]})
    ours = system.analyze(at).numbers.as_dict()
    reference = reference_analysis(
        {**joints, "parameters": ["R", "L1", "L2"]},
        {**values, "R": sp.Integer(1), "L1": sp.Integer(2), "L2": sp.Integer(1)})
    assert ours == {k: reference[k] for k in ours}


def test_the_case1_arms_as_dh_tables_are_case1():
    raw = {"name": "case 1 by DH", "parameters": ["L"], "arms": [
        {"name": "a1", "dh": [{"name": "q1", "type": "revolute", "theta": "pi/2",
                               "a": "L"}]},
        {"name": "a2", "base": {"xyz": ["L", 0, 0]},
         "dh": [{"name": "q2", "type": "revolute", "theta": "pi/2", "a": "L"}]}],
        "contacts": [
            {"name": "c1", "link": "a1/1", "frame": "link", "point": [0, 0, 0],
             "normal": [0, -1, 0], "model": "hard"},
            {"name": "c2", "link": "a2/1", "frame": "link", "point": [0, 0, 0],
             "normal": [0, 1, 0], "model": "hard"}]}
    ours, paper = coopkin_sym.load(raw), coopkin_sym.load("paper-case1-hard")
    assert ours.model.contacts == paper.model.contacts
    assert [(j.axis, j.point) for j in ours.model.joints] == [
        (j.axis, j.point) for j in paper.model.joints]
    assert [texts(c.equations) for c in ours.locus().components] == [
        texts(c.equations) for c in paper.locus().components]


ROW = {"name": "q1", "type": "revolute", "theta": 0, "d": 0, "a": 1, "alpha": 0}
CONTACT = {"name": "c", "link": "a/1", "point": [0, 0, 0], "normal": [1, 0, 0],
           "model": "hard"}


def _model(arm: dict, contact: dict | None = None) -> dict:
    return {"arms": [{"name": "a", **arm}], "contacts": [contact or CONTACT]}


@pytest.mark.parametrize("arm, contact, message", [
    ({"dh": [dict(ROW, alpha="pi/3")]}, None,
     r"arms\[0\]\.dh\[0\]\.alpha: .*nearest exact"),
    ({"dh": [dict(ROW, theta="1.2")]}, None, r"arms\[0\]\.dh\[0\]\.theta"),
    ({"dh": [dict(ROW, a="M")]}, None, r"arms\[0\]\.dh\[0\]\.a: .*'M'"),
    ({"dh": [dict(ROW, type="spherical")]}, None,
     r"arms\[0\]\.dh\[0\]\.type: unknown joint type 'spherical'"),
    ({"dh": [dict(ROW, offset=1)]}, None, r"arms\[0\]\.dh\[0\]: unknown key 'offset'"),
    ({"dh": [ROW], "convention": "craig"}, None,
     r"arms\[0\]\.convention: expected standard .* or modified .*, got 'craig'"),
    ({"dh": [ROW], "joints": []}, None, r"arms\[0\]: give either joints or dh"),
    ({"dh": []}, None, r"arms\[0\]\.dh: at least one row"),
    ({"dh": [ROW], "base": {"rpy": [0, 0]}}, None,
     r"arms\[0\]\.base\.rpy: expected 3 angles"),
    ({"dh": [ROW], "base": {"xyz": [0, 0, 0], "yaw": 1}}, None,
     r"arms\[0\]\.base: unknown key 'yaw'"),
    ({"dh": [ROW], "base": {"rpy": [0, 0, "pi/6"]}}, None,
     r"arms\[0\]\.base\.rpy\[2\]: .*nearest exact"),
    ({"joints": [{"name": "q1", "type": "revolute", "axis": [0, 0, 1],
                  "point": [0, 0, 0]}], "convention": "standard"}, None,
     r"arms\[0\]\.convention: only an arm given by a DH table"),
    ({"joints": [{"name": "q1", "type": "revolute", "axis": [0, 0, 1],
                  "point": [0, 0, 0]}]}, dict(CONTACT, frame="link"),
     r"contacts\[0\]\.frame: link frames exist only for an arm given by a DH table"),
    ({"dh": [ROW]}, dict(CONTACT, frame="tool"),
     r"contacts\[0\]\.frame: expected base .* or link .*, got 'tool'"),
    ({"name": "a"}, None, r"arms\[0\]: missing key 'joints' \(or 'dh'"),
])
def test_bad_dh_input_gets_one_clear_error(arm, contact, message):
    with pytest.raises(ModelError, match=message):
        coopkin_sym.load(_model(arm, contact))


def test_dh_joint_names_share_the_one_namespace():
    raw = _model({"dh": [ROW, dict(ROW)]})
    with pytest.raises(ModelError, match=r"arms\[0\]\.dh\[1\]\.name: .*'q1'"):
        coopkin_sym.load(raw)


def test_a_table_whose_frames_outgrow_the_digit_budget_is_refused_at_the_row():
    # each rotation by 2*atan(123456789/987654321) multiplies the frames' denominators
    # by up to 10**36 (theta and alpha both turn): at dh[31] a frame has more than
    # 1000 digits; the table used to be accepted, taking minutes for 1000 rows
    angle = "2*atan(123456789/987654321)"
    rows = [dict(ROW, name=f"q{k}", theta=angle, alpha=angle) for k in range(120)]
    with pytest.raises(ModelError) as caught:
        coopkin_sym.load(_model({"dh": rows}, dict(CONTACT, link="a/120")))
    assert caught.value.problems == [
        "arms[0].dh[31] (joint 'q31'): the link frame at home has a number of more than "
        "1000 digits (the rotations of the rows up to here multiply their denominators); "
        "use angles whose tan(q/2) have fewer digits"]


def test_a_long_table_of_small_angles_is_within_the_digit_budget():
    rows = [dict(ROW, name=f"q{k}", alpha="2*atan(1/2)") for k in range(200)]
    model = coopkin_sym.load(_model({"dh": rows}, dict(CONTACT, link="a/200"))).model
    # joint 200 turns about z of frame 199, turned about x by 199 * alpha (numbers of
    # 140 digits): (0, -sin, cos) of that angle
    turn = sp.expand((sp.Rational(3, 5) + sp.I * sp.Rational(4, 5)) ** 199)
    assert model.arms[0].joints[-1].axis == (0, -sp.im(turn), sp.re(turn))
