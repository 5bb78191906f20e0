"""Arms given as DH tables or URDF files go through every analysis exactly as the same
arms written joint by joint: the locus, the sweep and the pictures do not depend on
how a model was written."""

from __future__ import annotations

import pytest
from support import texts
from test_dh import as_joints
from test_urdf import fingers_by_hand

import coopkin_sym
from coopkin_sym.analysis.sweep import grid
from coopkin_sym.model.examples import example_path
from coopkin_sym.model.trees import read_file

HAND_SLICE = ("R=1,L1=2,L2=1,f1_1=0,f2_1=0,f3_1=0,f2_2=0,f3_2=0,f2_3=0,f3_3=0")


def _hand_joints() -> dict:
    raw = read_file(example_path("dh-three-finger-hand"))
    return {**as_joints(raw), "name": raw["name"], "parameters": raw["parameters"]}


def _locus_key(locus) -> list:
    return [(texts(c.equations), c.numbers, c.witness, c.kind, c.depth) for c in locus.components]


@pytest.mark.parametrize("name, written, at", [
    ("urdf-two-fingers", fingers_by_hand, None),
    pytest.param("dh-three-finger-hand", _hand_joints, HAND_SLICE,
                 marks=pytest.mark.slow),  # 10 to 20 s: run by .ci/run
])
def test_the_locus_does_not_depend_on_how_arms_are_written(name, written, at):
    ours, theirs = coopkin_sym.load(name), coopkin_sym.load(written())
    a, b = ours.locus(at), theirs.locus(at)
    assert a.components and _locus_key(a) == _locus_key(b)
    assert a.generic == b.generic


@pytest.mark.parametrize("name, written, at, axes", [
    ("urdf-two-fingers", fingers_by_hand, None, "l_mcp=-pi..pi:9,r_pip=-pi..pi:9"),
    ("dh-three-finger-hand", _hand_joints, "R=1,L1=2,L2=1",
     "f1_2=-pi..pi:7,f2_3=-pi..pi:7"),
])
def test_the_sweep_does_not_depend_on_how_arms_are_written(name, written, at, axes):
    systems = coopkin_sym.load(name), coopkin_sym.load(written())
    ours, theirs = (s.sweep(grid(s, axes), at=at) for s in systems)
    assert ours.summary() == theirs.summary() and len(ours.summary()) >= 1
    assert (ours.numbers == theirs.numbers).all()


@pytest.mark.parametrize("name, at", [
    ("urdf-two-fingers", "l_mcp=2*atan(1/3)"),
    ("dh-two-puma560-box", "p1_2=2*atan(1/3),p2_3=2*atan(1/2)"),
    ("quadruped-standing", None),
])
def test_models_of_every_format_are_drawn(name, at, tmp_path):
    out = tmp_path / f"{name}.png"
    coopkin_sym.load(name).draw(at).savefig(out)
    assert out.stat().st_size > 10_000
