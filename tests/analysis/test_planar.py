"""Planar systems (``planar: true``): object twists ``(v_x, v_y, w_z)`` and planar
contact models, checked against two independent computations:

* a planar re-implementation written here with SymPy alone (link poses as 2-D
  rotations about the joint points, the velocity of a point as ``w_z`` times its
  perpendicular), ranked over the rationals;
* the spatial analysis of the same system (``planar`` off) restricted to the plane:
  the rows of the in-plane constraints and the columns ``v_x, v_y, w_z``.

Random planar systems (revolute joints about +z or -z, prismatic joints in the plane,
hard, frictionless and complete contacts on links and on the ground) at random exact
configurations give the same seven numbers all three ways, and the same subspaces.
"""

from __future__ import annotations

import random
from fractions import Fraction

import pytest
import sympy as sp

import coopkin_sym
from coopkin_sym.errors import InfeasibleMotion, ModelError
from coopkin_sym.model import load_model
from coopkin_sym.model.examples import example_path
from coopkin_sym.model.trees import read_file

#: unit vectors of the plane with rational components
UNITS = [(1, 0), (0, 1), (-1, 0), (0, -1), (Fraction(3, 5), Fraction(4, 5)),
         (Fraction(-4, 5), Fraction(3, 5)), (Fraction(5, 13), Fraction(-12, 13)),
         (Fraction(-8, 17), Fraction(-15, 17))]


def _q(x) -> str:
    return str(Fraction(x))


def random_planar_system(seed: int) -> dict:
    """A random planar model (as a dict) with exact data. Odd seeds give fingers: chains
    of revolute joints standing up (+y) at integer points, touching with their tips,
    so that the numbers change at quarter turns (a finger stretched or folded)."""
    rng = random.Random(seed)
    if seed % 2:
        return _random_fingers(rng, seed)
    arms, contacts, joint_no = [], [], 0

    def coordinate() -> str:
        return _q(Fraction(rng.randint(-6, 6), rng.randint(1, 3)))

    for a in range(rng.randint(1, 3)):
        joints = []
        for _ in range(rng.randint(1, 3)):
            joint_no += 1
            if rng.random() < 0.75:
                joints.append({"name": f"q{joint_no}", "type": "revolute",
                               "axis": [0, 0, rng.choice([1, -1])],
                               "point": [coordinate(), coordinate(), 0]})
            else:
                ux, uy = rng.choice(UNITS)
                joints.append({"name": f"d{joint_no}", "type": "prismatic",
                               "axis": [_q(ux), _q(uy), 0]})
        arms.append({"name": f"a{a}", "joints": joints})
    for k in range(rng.randint(1, 4)):
        if rng.random() < 0.15:
            link = "base"
        else:
            arm = rng.randrange(len(arms))
            link = f"a{arm}/{rng.randint(1, len(arms[arm]['joints']))}"
        nx, ny = rng.choice(UNITS)
        contacts.append({"name": f"c{k}", "link": link, "model": _contact_model(rng),
                         "point": [coordinate(), coordinate(), 0],
                         "normal": [_q(nx), _q(ny), 0]})
    return {"name": f"random planar {seed}", "planar": True, "arms": arms,
            "contacts": contacts}


def _contact_model(rng: random.Random) -> str:
    return rng.choice(["hard", "hard", "frictionless", "complete"])


def _random_fingers(rng: random.Random, seed: int) -> dict:
    arms, contacts, joint_no = [], [], 0
    for a in range(rng.randint(1, 3)):
        x = rng.randint(-3, 3)
        joints = []
        for k in range(rng.randint(1, 3)):
            joint_no += 1
            joints.append({"name": f"q{joint_no}", "type": "revolute",
                           "axis": [0, 0, rng.choice([1, -1])], "point": [x, k, 0]})
        arms.append({"name": f"a{a}", "joints": joints})
        tip = len(joints)
        for c in range(rng.randint(1, 2)):
            link = rng.randint(1, tip)
            contacts.append({"name": f"c{a}_{c}", "link": f"a{a}/{link}",
                             "model": _contact_model(rng),
                             "point": [x, rng.randint(link, tip + 1) - 1 if c else tip, 0],
                             "normal": [rng.choice([1, -1]), 0, 0]})
    return {"name": f"random fingers {seed}", "planar": True, "arms": arms,
            "contacts": contacts}


def random_point(raw: dict, rng: random.Random, special: bool = False
                 ) -> dict[str, Fraction]:
    """Random exact joint values: ``tan(q/2)`` for revolute joints, displacements for
    prismatic ones; ``special`` draws from 0, 1 and -1 (q = 0, pi/2, -pi/2),
    where arms line up and numbers change."""
    out = {}
    for arm in raw["arms"]:
        for j in arm["joints"]:
            value = Fraction(rng.randint(-9, 9), rng.randint(1, 5))
            out[j["name"]] = rng.choice([Fraction(0), Fraction(1), Fraction(-1)]) \
                if special else value
    return out


def at_text(raw: dict, values: dict[str, Fraction]) -> str:
    kinds = {j["name"]: j["type"] for arm in raw["arms"] for j in arm["joints"]}
    return ",".join(f"{n}=2*atan({v})" if kinds[n] == "revolute" else f"{n}={v}"
                    for n, v in values.items())


# --- the independent planar re-implementation ---------------------------------------
def _perp(x: sp.Matrix) -> sp.Matrix:
    return sp.Matrix([-x[1], x[0]])


def planar_q(raw: dict, values: dict[str, Fraction]) -> sp.Matrix:
    """``Q`` of a planar system at ``values``: for each contact, the object's velocity
    at the contact minus the link's, its in-plane constrained components, as a row
    over ``(v_x, v_y, w_z, qdot)``."""
    names = [j["name"] for arm in raw["arms"] for j in arm["joints"]]
    r = len(names)
    # per arm, per link k: (rotation, translation) of the link, and the joint
    # velocity columns of a point: list of (kind, column, sign, current point/axis)
    links = {}
    for a, arm in enumerate(raw["arms"]):
        rot, trans = sp.eye(2), sp.zeros(2, 1)
        chain = []
        links[(a, 0)] = (rot, trans, [])
        for k, j in enumerate(arm["joints"], start=1):
            col = names.index(j["name"])
            if j["type"] == "revolute":
                home = sp.Matrix([sp.Rational(j["point"][0]), sp.Rational(j["point"][1])])
                sign = j["axis"][2]
                t = sp.Rational(values[j["name"]])
                c, s = (1 - t**2) / (1 + t**2), sign * 2 * t / (1 + t**2)
                step = sp.Matrix([[c, -s], [s, c]])
                chain.append(("revolute", col, sign, rot * home + trans))
                # the link moves by x -> step (x - home) + home, then by the links inboard
                rot, trans = rot * step, rot * (home - step * home) + trans
            else:
                d = rot * sp.Matrix([sp.Rational(j["axis"][0]), sp.Rational(j["axis"][1])])
                chain.append(("prismatic", col, 1, d))
                trans = trans + d * sp.Rational(values[j["name"]])
            links[(a, k)] = (rot, trans, list(chain))
    rows = []
    for contact in raw["contacts"]:
        home = sp.Matrix([sp.Rational(contact["point"][0]), sp.Rational(contact["point"][1])])
        normal = sp.Matrix([sp.Rational(contact["normal"][0]),
                            sp.Rational(contact["normal"][1])])
        if contact["link"] == "base":
            rot, trans, chain = sp.eye(2), sp.zeros(2, 1), []
        else:
            arm, k = contact["link"].split("/")
            rot, trans, chain = links[(int(arm[1:]), int(k))]
        x = rot * home + trans
        n = rot * normal
        lin = sp.zeros(2, 3 + r)
        ang = sp.zeros(1, 3 + r)
        lin[:, 0], lin[:, 1], lin[:, 2] = sp.Matrix([1, 0]), sp.Matrix([0, 1]), _perp(x)
        ang[0, 2] = 1
        for kind, col, sign, where in chain:
            if kind == "revolute":
                lin[:, 3 + col] = -sign * _perp(x - where)
                ang[0, 3 + col] = -sign
            else:
                lin[:, 3 + col] = -where
        if contact["model"] == "frictionless":
            rows.append(n.T * lin)
        else:
            rows += [lin[0, :], lin[1, :]]
        if contact["model"] == "complete":
            rows.append(ang)
    return sp.Matrix.vstack(*rows)


def numbers_from(q: sp.Matrix, dim: int) -> dict[str, int]:
    """The seven numbers from the ranks of ``Q`` and its two column blocks (the
    paper's definitions, written out here)."""
    m, n = q.shape
    r = n - dim
    rq, rg, rd = q.rank(), q[:, :dim].rank(), q[:, dim:].rank() if r else 0
    nm, nr = n - rq, r - rd
    return {"Nm": nm, "Nc": nm - nr, "Ni": dim - rg, "Nr": nr, "Ng": m - rg,
            "Nd": m - rd, "Nh": m - rq}


def spatial_restricted(raw: dict, at: str) -> dict[str, int]:
    """The numbers of the spatial analysis of the same system, restricted to the
    plane: in-plane constraint rows, columns ``v_x, v_y, w_z`` and the joints."""
    spatial = coopkin_sym.load({**raw, "planar": False}).analyze(at)
    labels = spatial.kinematics.row_labels
    keep = [i for i, lab in enumerate(labels)
            if lab.split(": ")[1] in ("v_x", "v_y", "v.n", "w_z")]
    cols = [0, 1, 5] + list(range(6, 6 + spatial.r))
    return numbers_from(spatial.Q.extract(keep, cols), 3)


SEEDS = list(range(40))


@pytest.mark.parametrize("seed", SEEDS)
def test_random_planar_systems_three_ways(seed):
    raw = random_planar_system(seed)
    system = coopkin_sym.load(raw)
    rng = random.Random(1000 + seed)
    for special in (False, True, True, True):
        values = random_point(raw, rng, special)
        at = at_text(raw, values)
        a = system.analyze(at)
        q = planar_q(raw, values)
        assert a.Q.shape == q.shape == (q.rows, 3 + len(values))
        independent = numbers_from(q, 3)
        assert a.numbers.as_dict() == independent, (at, raw)
        assert spatial_restricted(raw, at) == independent
        # the subspaces: C11 spans the kernel of H G^T, C23 that of H D, Q C = 0
        assert a.check()
        assert (q[:, :3] * a.C11).is_zero_matrix and a.C11.rank() == a.numbers.Ni
        assert (q[:, 3:] * a.C23).is_zero_matrix and a.C23.rank() == a.numbers.Nr
        assert sp.Matrix.hstack(a.C11, a.C12).rank() == a.numbers.Nc


@pytest.mark.parametrize("seed", SEEDS[:12])
def test_random_planar_systems_generic_numbers(seed):
    """The symbolic (generic) analysis gives the numbers of a random point."""
    raw = random_planar_system(seed)
    system = coopkin_sym.load(raw)
    generic = system.analyze(free=list(system.joint_names)).numbers.as_dict()
    values = random_point(raw, random.Random(seed))
    big = {n: v * 7919 + Fraction(1, 101) for n, v in values.items()}
    assert generic == numbers_from(planar_q(raw, big), 3)


# --- the shipped planar examples -------------------------------------------------------
def test_paper_case1_planar_numbers_and_blocks():
    a = coopkin_sym.load("paper-case1-planar").analyze()
    assert a.numbers.as_dict() == {"Nm": 1, "Nc": 1, "Ni": 0, "Nr": 0, "Ng": 1, "Nd": 2,
                                   "Nh": 0}
    L = sp.Symbol("L", positive=True)
    assert a.C12 == sp.Matrix([L, 0, 0]) and a.C22 == sp.Matrix([-1, -1])
    assert a.G.shape == (3, 6) and a.H.shape == (4, 6) and a.Q.shape == (4, 5)
    # the spatial system has one more motion: the indeterminate spin about the line
    # of the contacts, out of the plane
    spatial = coopkin_sym.load("paper-case1-hard").analyze()
    assert (spatial.numbers.Nm, spatial.numbers.Ni) == (2, 1)
    assert list(spatial.C11.col(0)[:2]) + [spatial.C11[5, 0]] == [0, 0, 0]


@pytest.mark.parametrize("at, numbers", [
    (None, (3, 3, 0, 0, 1, 0, 0)),
    ("q2=pi/2", (3, 2, 0, 1, 1, 1, 0)),
    ("q2=-pi/2,q4=pi/2", (3, 1, 0, 2, 1, 2, 0)),
    ("q1=pi/2,q2=pi/2,q3=-pi/2,q4=-pi/2", (4, 2, 0, 2, 1, 2, 1)),
])
def test_planar_two_fingers_numbers(at, numbers):
    a = coopkin_sym.load("planar-two-fingers").analyze(at)
    assert tuple(a.numbers.as_dict().values()) == numbers


def test_planar_maps_take_three_components():
    a = coopkin_sym.load("planar-two-fingers").analyze("L=1")
    u = [1, 0, 0]
    qdot = a.joint_velocities(u).particular
    assert a.object_velocities(list(qdot)).particular == sp.Matrix(u)
    with pytest.raises(InfeasibleMotion, match="expected 3 components, got 6"):
        a.joint_velocities([1, 0, 0, 0, 0, 0])


def test_planar_json_and_text_name_the_twist():
    a = coopkin_sym.load("paper-case1-planar").analyze()
    data = a.as_json()
    assert data["twist"] == ["v_x", "v_y", "w_z"] and data["shapes"]["C12"] == [3, 1]
    from coopkin_sym.present.text import analysis_text
    text = analysis_text(a)
    assert "Object twist (v_x, v_y, w_z), planar" in text and "  w_z | 0" in text


def test_planar_object_frame_changes_blocks_not_numbers():
    raw = read_file(example_path("planar-two-fingers"))
    framed = coopkin_sym.load({**raw, "object": {"point": [0, 1, 0], "rpy": [0, 0, "pi/2"]}})
    plain = coopkin_sym.load(raw)
    at = "q1=2*atan(1/3),q2=-2*atan(1/2),q3=2*atan(1/5),q4=2*atan(2),L=2"
    a, b = framed.analyze(at), plain.analyze(at)
    assert a.numbers == b.numbers
    moved = sp.Matrix.hstack(*[sp.Matrix(a.twist_in_base(a.C12.col(k)))
                               for k in range(a.C12.cols)])
    assert moved.rank() == b.C12.rank() == sp.Matrix.hstack(moved, b.C12).rank() == 3
    # a spin about the object point, written in the object frame, is a spin about
    # (0, 1) plus the velocity of the base origin
    assert a.twist_in_base([0, 0, 1]) == [1, 0, 1]


def test_planar_sweep_agrees_with_point_analyses():
    from coopkin_sym.analysis.sweep import grid
    system = coopkin_sym.load("planar-two-fingers")
    res = system.sweep(grid(system, "q2=-pi..pi:9,q4=-pi..pi:9"), at="q1=2*atan(1/3),L=1")
    assert res.generic.as_dict()["Nc"] == 3
    assert len(res) == 81
    singular = [i for i in range(len(res)) if res.numbers_at(i) != res.generic]
    assert singular and len(singular) < 81
    for i in list(range(0, 81, 8)) + singular[:6]:
        at = res.at_text(i)
        assert res.numbers_at(i) == system.analyze(at).numbers, at


def test_planar_dh_and_urdf_arms():
    # a planar DH finger: alpha = 0, the joints turn about z
    dh = {"name": "dh planar", "planar": True, "parameters": ["L"],
          "arms": [{"name": "f", "dh": [
              {"name": "q1", "type": "revolute", "a": "L"},
              {"name": "q2", "type": "revolute", "a": "L"}]}],
          "contacts": [{"name": "c", "link": "f/2", "frame": "link", "point": [0, 0, 0],
                        "normal": [1, 0, 0], "model": "hard"}]}
    by_joints = {"name": "joints", "planar": True, "parameters": ["L"],
                 "arms": [{"name": "f", "joints": [
                     {"name": "q1", "type": "revolute", "axis": [0, 0, 1],
                      "point": [0, 0, 0]},
                     {"name": "q2", "type": "revolute", "axis": [0, 0, 1],
                      "point": ["L", 0, 0]}]}],
                 "contacts": [{"name": "c", "link": "f/2", "point": ["2*L", 0, 0],
                               "normal": [1, 0, 0], "model": "hard"}]}
    at = "q1=2*atan(1/2),q2=2*atan(-3)"
    a, b = coopkin_sym.load(dh).analyze(at), coopkin_sym.load(by_joints).analyze(at)
    assert a.numbers == b.numbers and a.Q == b.Q
    # the URDF fingers turn about z (the second flipped: about -z): planar too
    raw = read_file(example_path("urdf-two-fingers"))
    raw["arms"] = [{**arm, "urdf": str(example_path("urdf-two-fingers").parent / arm["urdf"])}
                   for arm in raw["arms"]]
    planar = coopkin_sym.load({**raw, "planar": True})
    spatial = coopkin_sym.load(raw)
    at = "l_mcp=2*atan(1/3),l_pip=2*atan(1/2),r_mcp=2*atan(-1/4),r_pip=2*atan(2)"
    numbers = planar.analyze(at).numbers.as_dict()
    assert numbers == spatial_restricted(raw, at) == {"Nm": 3, "Nc": 3, "Ni": 0, "Nr": 0,
                                                      "Ng": 1, "Nd": 0, "Nh": 0}
    # in space the object also spins about the line of the two tips
    assert spatial.analyze(at).numbers.Ni == 1


def test_planar_locus_is_certified_and_verified():
    from coopkin_sym.analysis.locus.certify import certify_locus
    from coopkin_sym.analysis.locus.verify import verify_locus
    system = coopkin_sym.load("paper-case1-planar")
    locus = system.locus()
    assert locus.generic == {"Nm": 1, "Nc": 1, "Ni": 0, "Nr": 0, "Ng": 1, "Nd": 2, "Nh": 0}
    conditions = [c.condition.text for c in locus.components]
    assert "q1 = pi/2, q2 = pi/2" in conditions
    v = verify_locus(system, locus)
    assert v.uncovered_total == 0 and v.unsound == []
    cert = certify_locus(system, locus)
    assert cert.certified_by() is not None and not cert.failures()


def test_planar_system_is_drawn_from_above(tmp_path):
    fig = coopkin_sym.load("planar-two-fingers").draw(
        "q1=2*atan(1/4),q2=-2*atan(1/2),q3=-2*atan(1/4),q4=2*atan(1/2)",
        motion="coordinated:1")
    ax = fig.axes[0]
    assert (ax.elev, ax.azim) == (90, -90)
    out = tmp_path / "planar.png"
    fig.savefig(out)
    assert out.stat().st_size > 10_000


# --- what a planar model refuses -------------------------------------------------------
PLANAR_CASE1 = read_file(example_path("paper-case1-planar"))


def _with(change) -> dict:
    import copy
    raw = copy.deepcopy(PLANAR_CASE1)
    change(raw)
    return raw


@pytest.mark.parametrize("change, path, fragment", [
    (lambda m: m["arms"][0]["joints"][0].update(axis=[1, 0, 0]),
     "arms[0].joints[0].axis", "a revolute axis along z"),
    (lambda m: m["arms"][0]["joints"][0].update(point=[0, 0, 1]),
     "arms[0].joints[0].point", "joint points in the xy-plane"),
    (lambda m: m["arms"][0]["joints"].append(
        {"name": "d", "type": "prismatic", "axis": [0, 0, 1]}),
     "arms[0].joints[1].axis", "a prismatic axis in the xy-plane"),
    (lambda m: m["contacts"][0].update(model="soft"),
     "contacts[0].model", "a soft contact has no planar model"),
    (lambda m: m["contacts"][1].update(point=["L", "L", 1]),
     "contacts[1].point", "contact points in the xy-plane"),
    (lambda m: m["contacts"][1].update(normal=[0, 0, 1]),
     "contacts[1].normal", "normals in the xy-plane"),
    (lambda m: m.update(object={"point": [0, 0, 0], "rpy": ["pi/2", 0, 0]}),
     "object", "turned about z only"),
    (lambda m: m.update(planar="yes"), "planar", "bool"),
])
def test_planar_refuses_what_leaves_the_plane(change, path, fragment):
    with pytest.raises(ModelError) as info:
        load_model(_with(change))
    hits = [p for p in info.value.problems if p.startswith(f"{path}: ") and fragment in p]
    assert hits, info.value.problems


@pytest.mark.parametrize("seed", [s for s in range(1, 60, 2)
                                  if sum(len(a["joints"]) for a in
                                         random_planar_system(s)["arms"]) <= 4])
def test_random_planar_fingers_locus_verifies(seed):
    """The locus of random planar fingers, checked by the independent verifier (exact
    numbers on a rational grid with q = pi and on random lines)."""
    from coopkin_sym.analysis.locus.verify import verify_locus
    from coopkin_sym.present.verification import summary_lines
    system = coopkin_sym.load(random_planar_system(seed))
    locus = system.locus()
    v = verify_locus(system, locus, lines=10)
    assert v.uncovered_total == 0 and v.unsound == [], summary_lines(v)
