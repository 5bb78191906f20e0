"""Passive joints (``actuated: false``): the numbers and subspaces of
:mod:`coopkin_sym.analysis.passive`, checked against an independent computation (the
Jacobians of ``tests/independent.py``, ranks and nullspaces by SymPy over Q), on
random systems, the shipped five-bar, and where the locus says they change."""

from __future__ import annotations

import copy
import json
import random
from fractions import Fraction

import pytest
import sympy as sp

import coopkin_sym
from coopkin_sym.analysis.locus.verify import verify_locus
from coopkin_sym.errors import ModelError
from coopkin_sym.present.report import locus_from_json, render_json
from tests.independent import at_from_text, reference_jacobians
from tests.random_systems import random_system


def _span_rank(vectors: list[sp.Matrix], n: int) -> int:
    return sp.Matrix.hstack(*vectors).rank() if vectors else 0


def independent_passive(raw: dict, at: str) -> dict:
    """The passive-joint numbers and subspaces from the reference Jacobians, by the
    definitions: with ``Q = [HG^T | -HD]`` split into object, motor and passive
    columns."""
    jac = reference_jacobians(raw, at_from_text(raw, at))
    gt, hd = jac["HGt"], jac["HD"]
    if raw.get("planar"):
        # the spatial reference restricted to the plane: hard contacts keep v_x, v_y
        # (rows 3i, 3i + 1), twists (v_x, v_y, w_z)
        assert all(c["model"] == "hard" for c in raw["contacts"])
        keep = [3 * i + k for i in range(len(raw["contacts"])) for k in (0, 1)]
        gt = gt.extract(keep, [0, 1, 5])
        hd = hd.extract(keep, list(range(hd.cols)))
    d = gt.cols
    joints = [j for arm in raw["arms"] for j in arm["joints"]]
    act = [k for k, j in enumerate(joints) if j.get("actuated", True)]
    pas = [k for k, j in enumerate(joints) if not j.get("actuated", True)]
    q = gt.row_join(-hd)
    q_lock = gt.row_join(-hd.extract(list(range(hd.rows)), pas)) if pas else gt
    nq = q.nullspace()
    nlock = q_lock.nullspace()
    nd = hd.nullspace()
    u_all = [v[:d, :] for v in nq]
    u_free = [v[:d, :] for v in nlock]
    nc, nuo = _span_rank(u_all, d), _span_rank(u_free, d)
    npi = len(pas) - (hd.extract(list(range(hd.rows)), pas).rank() if pas else 0)
    nr = len(nd)
    motors_of_nd = [v.extract(act, [0]) for v in nd]
    motors_of_nq = [v.extract([d + k for k in act], [0]) for v in nq]
    return {"numbers": {"Na": len(act), "Np": len(pas), "Nco": nc - nuo, "Nuo": nuo,
                        "Npi": npi, "Nar": nr - npi, "Nam": _span_rank(motors_of_nq,
                                                                       len(act))},
            "u_all": u_all, "u_free": u_free, "act": act, "pas": pas, "hd": hd,
            "motors_of_nd": motors_of_nd, "nar": _span_rank(motors_of_nd, len(act))}


def _with_passive(raw: dict, rng: random.Random) -> dict:
    raw = copy.deepcopy(raw)
    joints = [j for arm in raw["arms"] for j in arm["joints"]]
    for j in joints:
        if rng.random() < 0.4:
            j["actuated"] = False
    if all(j.get("actuated", True) for j in joints):
        rng.choice(joints)["actuated"] = False
    return raw


def _at(raw: dict, rng: random.Random, special: bool) -> str:
    parts = []
    for arm in raw["arms"]:
        for j in arm["joints"]:
            v = rng.choice([Fraction(0), Fraction(1), Fraction(-1)]) if special else \
                Fraction(rng.randint(-9, 9), rng.randint(1, 5))
            parts.append(f"{j['name']}=2*atan({v})" if j["type"] == "revolute"
                         else f"{j['name']}={v}")
    return ",".join(parts)


def _same_span(a: sp.Matrix, vectors: list[sp.Matrix]) -> bool:
    n = a.rows
    r = _span_rank(vectors, n)
    return a.rank() == a.cols == r and (a.row_join(sp.Matrix.hstack(*vectors))
                                        if vectors else a).rank() == r


@pytest.mark.parametrize("seed", range(30))
def test_random_passive_systems_against_independent_definitions(seed):
    rng = random.Random(7000 + seed)
    raw = _with_passive(random_system(seed), rng)
    system = coopkin_sym.load(raw)
    assert system.model.passive_joints
    for special in (False, True, True):
        at = _at(raw, rng, special)
        a = system.analyze(at)
        p = a.passive
        ref = independent_passive(raw, at)
        assert p.numbers.as_dict() == ref["numbers"], (seed, at)
        n = p.numbers
        # the identities of the module text
        assert n.Nco + n.Nuo == a.numbers.Nc and n.Nar + n.Npi == a.numbers.Nr
        assert n.Nam == n.Nco + n.Nar and n.Nuo >= a.numbers.Ni
        # the subspaces, against the independent nullspaces
        assert _same_span(p.uncontrolled, ref["u_free"]) or (not ref["u_free"]
                                                              and p.uncontrolled.cols == 0)
        both = sp.Matrix.hstack(p.controlled, p.uncontrolled)
        assert both.rank() == both.cols == _span_rank(ref["u_all"], a.dim)
        assert both.row_join(sp.Matrix.hstack(*ref["u_all"])).rank() == both.cols \
            if ref["u_all"] else both.cols == 0
        hd = ref["hd"]
        assert (hd * p.internal).is_zero_matrix and p.internal.rank() == n.Npi
        assert all(p.internal[k, c] == 0 for k in ref["act"] for c in range(n.Npi))
        assert p.actuated_redundant.rank() == n.Nar == ref["nar"]
        if ref["motors_of_nd"]:
            assert p.actuated_redundant.row_join(
                sp.Matrix.hstack(*ref["motors_of_nd"])).rank() == n.Nar


@pytest.mark.parametrize("seed", range(8))
def test_generic_passive_numbers_match_a_random_point(seed):
    rng = random.Random(9100 + seed)
    raw = _with_passive(random_system(seed), rng)
    system = coopkin_sym.load(raw)
    generic = system.analyze(free=list(system.joint_names)).passive.numbers.as_dict()
    far = ",".join(f"{j['name']}=2*atan({rng.randint(50, 900)}/{rng.randint(901, 2000)})"
                   if j["type"] == "revolute" else f"{j['name']}={rng.randint(50, 900)}/7"
                   for arm in raw["arms"] for j in arm["joints"])
    assert generic == independent_passive(raw, far)["numbers"]


def test_every_joint_actuated_gives_the_papers_numbers():
    a = coopkin_sym.load("paper-case2-hard").analyze("L=1")
    n, p = a.numbers, a.passive.numbers
    assert p.as_dict() == {"Na": 8, "Np": 0, "Nco": n.Nc - n.Ni, "Nuo": n.Ni, "Npi": 0,
                           "Nar": n.Nr, "Nam": n.Nm - n.Ni}
    assert p.Nuo == 1 and p.Nco == 5       # Nc = 6: the spin about the line stays free


def test_five_bar_at_home_by_hand():
    """Each leg's pin velocity is ``A_k (qa, qp)`` with ``A_k`` invertible at home, so
    the pin is driven by both motors: the spin about the pin is the only free motion."""
    a = coopkin_sym.load("five-bar").analyze("L=1")
    p = a.passive
    assert p.actuated == ("q1", "q3") and p.passive == ("q2", "q4")
    assert p.numbers.as_dict() == {"Na": 2, "Np": 2, "Nco": 2, "Nuo": 1, "Npi": 0,
                                   "Nar": 0, "Nam": 2}
    assert p.uncontrolled == sp.Matrix([2, 0, 1])      # the spin about (0, 2)
    # the pin's manipulability: |qa|^2 = (vx + vy)^2 + (vx - vy)^2 = 2 |v|^2
    m = a.manipulability(["v_x", "v_y"], point=[0, 2, 0])
    assert m.shape == sp.eye(2) / 2 and m.rank == 2 and m.index == sp.Rational(1, 4)


def test_all_passive_joints_leave_everything_free():
    raw = _planar_two_fingers()
    for arm in raw["arms"]:
        for j in arm["joints"]:
            j["actuated"] = False
    a = coopkin_sym.load(raw).analyze("L=1")
    p = a.passive.numbers
    assert p.Na == 0 and p.Nco == 0 and p.Nam == 0 and p.Nuo == a.numbers.Nc
    assert p.Npi == a.numbers.Nr
    m = a.manipulability()
    assert m.rank == 0 and m.shape.is_zero_matrix


def _planar_two_fingers() -> dict:
    return {"name": "two fingers", "planar": True, "parameters": ["L"], "arms": [
        {"name": "left", "joints": [
            {"name": "q1", "type": "revolute", "axis": [0, 0, 1], "point": ["-2*L", 0, 0]},
            {"name": "q2", "type": "revolute", "axis": [0, 0, 1], "point": ["-2*L", "L", 0],
             "actuated": False}]},
        {"name": "right", "joints": [
            {"name": "q3", "type": "revolute", "axis": [0, 0, 1], "point": ["2*L", 0, 0]},
            {"name": "q4", "type": "revolute", "axis": [0, 0, 1], "point": ["2*L", "L", 0],
             "actuated": False}]}],
        "contacts": [
            {"name": "tip1", "link": "left/2", "point": ["-L", "L", 0], "normal": [1, 0, 0],
             "model": "hard"},
            {"name": "tip2", "link": "right/2", "point": ["L", "L", 0], "normal": [-1, 0, 0],
             "model": "hard"}]}


def _paper_case1_q2_passive() -> dict:
    return {"name": "case 1, q2 passive", "parameters": ["L"], "arms": [
        {"name": "a1", "joints": [{"name": "q1", "type": "revolute", "axis": [0, 0, 1],
                                   "point": [0, 0, 0]}]},
        {"name": "a2", "joints": [{"name": "q2", "type": "revolute", "axis": [0, 0, 1],
                                   "point": ["L", 0, 0], "actuated": False}]}],
        "contacts": [
            {"name": "c1", "link": "a1/1", "point": [0, "L", 0], "normal": [1, 0, 0],
             "model": "hard"},
            {"name": "c2", "link": "a2/1", "point": ["L", "L", 0], "normal": [-1, 0, 0],
             "model": "hard"}]}


SYSTEMS = {
    "five-bar slice": ("five-bar", "q4=0"),
    "two fingers, passive distal joints": (_planar_two_fingers(), None),
    "paper case 1, q2 passive": (_paper_case1_q2_passive(), None),
}


@pytest.mark.parametrize("name", [
    pytest.param(n, marks=[pytest.mark.slow] if n.startswith("two fingers") else [])
    for n in SYSTEMS])
def test_passive_numbers_change_exactly_on_the_locked_locus(name):
    """The locus of the locked system is verified independently (grid with q = pi,
    random lines), and at each of its witnesses the passive numbers are those its
    numbers predict, checked against the independent definitions."""
    source, at = SYSTEMS[name]
    system = coopkin_sym.load(source)
    raw = source if isinstance(source, dict) else _raw_of(source)
    locus = system.locus(at)
    locked = locus.locked
    assert locked is not None and locked.locked_joints == [
        j for j in system.joint_names if j not in system.model.passive_joints]
    check = verify_locus(system.model.with_actuators_locked(), locked, max_points=2000,
                         lines=6)
    assert not check.unsound, (name, check)
    na = len(locked.locked_joints)
    # every point where the locked system's numbers change lies on a component with
    # those numbers; where the search missed one (the five-bar slice: a point where two
    # components meet and both drops add up), it lies on a component with the same Nc
    # and Nr, so Nuo and Npi there are still those of the locus
    assert len(check.uncovered) == check.uncovered_total <= 1, (name, check)
    for point in check.uncovered:
        assert any(locked.components[i].numbers["Nc"] == point.numbers["Nc"]
                   and locked.components[i].numbers["Nr"] == point.numbers["Nr"]
                   for i in point.on), (name, point)
    generic_uo = locked.generic["Nc"]
    seen_change = False
    for c in locked.components:
        if not c.witness:
            continue
        text = ",".join(f"{k}={v}" for k, v in c.witness.items())
        got = system.analyze(text).passive.numbers
        assert got.Nuo == c.numbers["Nc"] and got.Npi == c.numbers["Nr"] - na, (name, c)
        if "L" not in c.witness and "L" in (raw.get("parameters") or []):
            text += ",L=1"
        assert got.as_dict() == independent_passive(raw, text)["numbers"], (name, text)
        seen_change |= got.Nuo != generic_uo
    assert seen_change, name
    # read back from the report, the locked locus comes along
    back = locus_from_json(render_json(locus))
    assert back.locked is not None and back.locked.generic == locked.generic
    assert json.loads(render_json(locus))["locked"]["locked_joints"] == locked.locked_joints


def _raw_of(example: str) -> dict:
    from coopkin_sym.model.examples import example_path
    from coopkin_sym.model.trees import read_text

    path = example_path(example)
    return read_text(path.read_text(), path.suffix)


def test_loader_reads_actuated_and_refuses_bad_values():
    raw = _planar_two_fingers()
    model = coopkin_sym.load(raw).model
    assert model.passive_joints == ("q2", "q4")
    bad = copy.deepcopy(raw)
    bad["arms"][0]["joints"][1]["actuated"] = "no"
    with pytest.raises(ModelError, match=r"arms\[0\]\.joints\[1\]\.actuated"):
        coopkin_sym.load(bad)
    bad = copy.deepcopy(raw)
    bad["arms"][0]["passive"] = ["q2"]
    with pytest.raises(ModelError, match=r"arms\[0\]\.passive: only an arm read from a URDF"):
        coopkin_sym.load(bad)


def test_dh_rows_take_actuated():
    raw = {"name": "dh", "parameters": [], "arms": [{"name": "a", "dh": [
        {"name": "q1", "type": "revolute", "a": 1},
        {"name": "q2", "type": "revolute", "a": 1, "actuated": False}]}],
        "contacts": [{"name": "c", "link": "a/2", "point": [0, 0, 0], "model": "hard"}]}
    assert coopkin_sym.load(raw).model.passive_joints == ("q2",)


def test_cli_analyze_prints_and_writes_the_passive_numbers():
    from typer.testing import CliRunner

    from coopkin_sym.cli import app

    runner = CliRunner()
    done = runner.invoke(app, ["analyze", "five-bar", "--at", "L=1"])
    assert done.exit_code == 0, done.output
    assert "Passive joints: q2, q4 (actuated: q1, q3)" in done.output
    assert "Na = 2  Np = 2  Nco = 2  Nuo = 1  Npi = 0  Nar = 0  Nam = 2" in done.output
    done = runner.invoke(app, ["analyze", "five-bar", "--at", "L=1", "--json"])
    data = json.loads(done.output)
    assert data["passive"]["numbers"]["Nco"] == 2
    assert data["passive"]["uncontrolled"] == [["2"], ["0"], ["1"]]
    # at an irrational angle the pins part: with the motors still, the platform and
    # the two distal links form a four-bar linkage (one free motion, Nuo = 1)
    done = runner.invoke(app, ["analyze", "five-bar", "--at", "q1=pi/6,L=1", "--json"])
    data = json.loads(done.output)
    numbers = data["passive"]["numbers"]
    assert numbers == {"Na": 2, "Np": 2, "Nco": data["numbers"]["Nc"] - 1, "Nuo": 1,
                       "Npi": 0, "Nar": data["numbers"]["Nr"],
                       "Nam": data["numbers"]["Nc"] - 1 + data["numbers"]["Nr"]}
    done = runner.invoke(app, ["analyze", "five-bar", "--at", "q1=pi/6,L=1"])
    assert "Passive-joint numbers: Na = 2  Np = 2" in done.output
