"""The object frame: where object twists are referenced and in which axes. The numbers
never change; the blocks are the same subspaces written in the new coordinates."""

from __future__ import annotations

import json
import random

import pytest
import sympy as sp
from random_systems import random_system

import coopkin_sym
from coopkin_sym.analysis.kinematics import twist_in_base
from coopkin_sym.errors import ModelError
from coopkin_sym.model.examples import example_path
from coopkin_sym.model.trees import read_file
from coopkin_sym.present.text import analysis_json, analysis_text

ANGLES = ["0", "pi/2", "-pi/2", "pi", "2*atan(1/2)", "2*atan(-3)"]


def _with_frame(raw: dict, rng: random.Random) -> dict:
    return {**raw, "object": {"point": [rng.choice([0, 1, "1/2", -2]) for _ in range(3)],
                              "rpy": [rng.choice(ANGLES) for _ in range(3)]}}


def _span(columns: list[list[sp.Expr]]) -> sp.Matrix:
    return sp.Matrix.hstack(*[sp.Matrix(c) for c in columns]) if columns else sp.zeros(0, 0)


def _same_span(a: list, b: list) -> bool:
    if not a or not b:
        return not a and not b
    ma, mb = _span(a), _span(b)
    rank = ma.rank(simplify=True)
    return rank == mb.rank(simplify=True) == ma.row_join(mb).rank(simplify=True)


def _motions(analysis) -> list[list[sp.Expr]]:
    """Every column of C (C11, C12 over C22, C23), object part in base coordinates."""
    n, r = analysis.numbers, analysis.r
    cols = [analysis.twist_in_base(analysis.C11.col(k)) + [0] * r for k in range(n.Ni)]
    cols += [analysis.twist_in_base(analysis.C12.col(k)) + list(analysis.C22.col(k))
             for k in range(analysis.C12.cols)]
    cols += [[0] * 6 + list(analysis.C23.col(k)) for k in range(n.Nr)]
    return cols


@pytest.mark.parametrize("seed", range(12))
def test_numbers_stay_and_the_motions_are_the_same_subspace(seed):
    rng = random.Random(seed)
    raw = random_system(seed)
    system = coopkin_sym.load(raw)
    at = ",".join(f"{j.name}={rng.choice(ANGLES) if j.type == 'revolute' else '1/2'}"
                  for j in system.model.joints)
    plain = system.analyze(at)
    framed = coopkin_sym.load(_with_frame(raw, rng)).analyze(at)
    assert framed.numbers == plain.numbers
    assert _same_span(_motions(framed), _motions(plain))
    # the free object motions alone too
    assert _same_span([framed.twist_in_base(framed.C11.col(k))
                       for k in range(framed.numbers.Ni)],
                      [list(plain.C11.col(k)) for k in range(plain.numbers.Ni)])


def test_case1_spin_is_a_pure_rotation_about_the_object_point():
    raw = read_file(example_path("paper-case1-hard"))
    raw["object"] = {"point": ["L/2", "L", 0], "rpy": [0, 0, "pi/2"]}
    a = coopkin_sym.load(raw).analyze()
    L = sp.Symbol("L", positive=True)
    # the free spin about the line through c1 and c2 (base x), seen from the point
    # between them and in axes turned by pi/2: no velocity there, about -y'
    assert list(a.C11.col(0)) in ([0, 0, 0, 0, 1, 0], [0, 0, 0, 0, -1, 0])
    u, q = a.twist_in_base(a.C12.col(0)), list(a.C22.col(0))
    assert u == [-L * q[0], 0, 0, 0, 0, 0] and q[0] == q[1]
    text = analysis_text(a)
    assert ("Object twist (v, w): v at the object point (L/2, L, 0), in the object axes, "
            "x' = (0, 1, 0), y' = (-1, 0, 0), z' = (0, 0, 1)") in text
    assert "rotate about the line through c1 and c2" in text
    data = json.loads(analysis_json(a))
    assert data["object_frame"] == {"point": ["L/2", "L", "0"], "axes": {
        "x": ["0", "1", "0"], "y": ["-1", "0", "0"], "z": ["0", "0", "1"]}}
    plain = json.loads(analysis_json(coopkin_sym.load("paper-case1-hard").analyze()))
    assert plain["object_frame"] is None
    assert "v at the base origin, in base axes" in analysis_text(
        coopkin_sym.load("paper-case1-hard").analyze())


def test_twist_in_base_moves_the_reference_point_and_turns_the_axes():
    yaw = sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 1]])
    # a spin about z' through o = (1, 0, 0): at the base origin, v = -w x o
    assert twist_in_base([0, 0, 0, 0, 0, 1], (yaw, (1, 0, 0))) == [0, -1, 0, 0, 0, 1]
    # a translation along x' is one along base y
    assert twist_in_base([1, 0, 0, 0, 0, 0], (yaw, (5, 5, 5))) == [0, 1, 0, 0, 0, 0]
    assert twist_in_base([1, 2, 3, 4, 5, 6], None) == [1, 2, 3, 4, 5, 6]


def test_irrational_points_describe_their_motions_in_base_terms():
    raw = read_file(example_path("paper-case1-hard"))
    plain = coopkin_sym.load("paper-case1-hard").analyze("q1=-pi/6,q2=pi/6")
    framed = coopkin_sym.load({**raw, "object": {"point": [1, 2, 3]}}).analyze(
        "q1=-pi/6,q2=pi/6")
    assert framed.numbers == plain.numbers
    assert _same_span(framed.motions.twists_in_base(), plain.motions.twists_in_base())


@pytest.mark.parametrize("entry, message", [
    ({"point": [0, 0]}, r"object\.point: expected 3 numbers, got 2"),
    ({"rpy": [0, 0, "pi/3"]}, r"object\.rpy\[2\]: angle 'pi/3' is not exact"),
    ({"origin": [0, 0, 0]}, r"object: unknown key 'origin'"),
    ({"point": [0, 0, "M"]}, r"object\.point: .*'M'"),
    ([0, 0, 0], r"object: expected a mapping"),
])
def test_bad_object_frames_get_one_clear_error(entry, message):
    raw = {**read_file(example_path("paper-case1-hard")), "object": entry}
    with pytest.raises(ModelError, match=message):
        coopkin_sym.load(raw)
