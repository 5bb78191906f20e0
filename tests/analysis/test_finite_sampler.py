"""Finite mobility checked against an independent numerical sampler of the closure
(:mod:`finite_sampler`): the same local dimension, and every sampled motion along one
of the branches found, each branch met."""

from __future__ import annotations

import random
import sys
from pathlib import Path

import mpmath as mp
import pytest
import sympy as sp

import coopkin_sym
from coopkin_sym import load
from coopkin_sym.analysis.finite import finite_mobility

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from finite_sampler import Sampler  # noqa: E402
from random_systems import random_system  # noqa: E402


def _angle(text: str):
    """The radians of an exact angle of the tests (``pi/2``, ``2*atan(1/3)``)."""
    value = sp.sympify(text)
    return mp.mpf(str(sp.N(value, 70)))


def _check(system, at: dict, samples: int = 10) -> None:
    text = ",".join(f"{k}={v}" for k, v in at.items())
    fm = finite_mobility(system.model, text)
    assert fm.dimension is not None, fm
    sampler = Sampler(system.model, {k: _angle(v) for k, v in at.items()}, {
        p.name: 1 for p in system.model.parameters})
    assert sampler.dimension(samples) == fm.dimension
    if fm.dimension == 0:
        return
    spans = [mp.matrix([[mp.mpf(str(sp.N(x, 70))) for x in v] for v in b.tangent]).T
             for b in fm.branches]
    met = [False] * len(spans)
    for d in sampler.directions(samples):
        v = mp.matrix(d)
        off = []
        for s in spans:        # the distance of d from the span of s
            coef = mp.lu_solve(s.T * s, s.T * v)
            off.append(mp.norm(v - s * coef))
        k = min(range(len(off)), key=lambda i: off[i])
        assert off[k] < mp.mpf(10) ** -2, (d, off)
        met[k] = True
    assert all(met)


def test_the_sampler_sees_the_folded_four_bar_bifurcate():
    _check(load("four-bar"), {"q1": "-pi/2", "q2": "-pi/2"}, samples=6)


@pytest.mark.slow
@pytest.mark.parametrize(("name", "at"), [
    ("paper-case1-planar", {"q1": "pi/2", "q2": "pi/2"}),
    ("paper-case1-planar", {"q1": "2*atan(1/3)", "q2": "2*atan(-2/5)"}),
    ("paper-case1-hard", {"q1": "pi/2", "q2": "pi/2"}),
    ("paper-case1-hard", {"q1": "2*atan(1/3)", "q2": "pi"}),
    ("paper-case1-hard", {"q1": "pi/2", "q2": "-pi/2"}),
    ("paper-case1-complete-hard", {"q1": "2*atan(1/3)", "q2": "2*atan(1/2)"}),
    ("four-bar", {"q1": "2*atan(1/2)", "q2": "2*atan(1/2)"}),
    ("shaky-pinned-bars", {"q1": "0", "q2": "0"}),
])
def test_the_sampler_sees_the_same_motions(name, at):
    _check(load(name), at)


@pytest.mark.slow
def test_random_systems_move_as_the_sampler_sees():
    """Random two-arm systems with hard and welded contacts, at random rational
    configurations and at the witnesses of their loci: every decided finite mobility
    is the sampler's."""
    rng = random.Random(29)
    seeds = [s for s in range(64) if {c["model"] for c in random_system(s)["contacts"]}
             <= {"hard", "complete"}]
    checked = 0
    for seed in seeds[:8]:
        system = coopkin_sym.load(random_system(seed))
        joints = system.model.joints
        for _ in range(2):
            at = {j.name: f"2*atan({rng.randint(-4, 4)}/{rng.randint(1, 5)})"
                  if j.type == "revolute" else f"{rng.randint(-4, 4)}/{rng.randint(1, 5)}"
                  for j in joints}
            fm = finite_mobility(system.model, ",".join(f"{k}={v}" for k, v in at.items()))
            if fm.dimension is not None:
                _check(system, at, samples=6)
                checked += 1
    assert checked >= 8


@pytest.mark.slow
@pytest.mark.parametrize("name", ["bennett-linkage", "bricard-linkage"])
def test_the_sampler_sees_the_overconstrained_loops_move_once(name):
    """The closure saturation's finite mobility 1, and its branch tangent, are the
    sampler's (Grübler-Kutzbach counts -2 and 0)."""
    system = load(name)
    _check(system, {j.name: "0" for j in system.model.joints}, samples=6)


@pytest.mark.slow
@pytest.mark.parametrize("seed", [26, 42])
def test_the_closure_decisions_on_random_loci_are_the_samplers(seed):
    """Random two-arm systems with point contacts at the witnesses of their loci,
    where the loop closure's saturation decides (the expansion stays undecided there,
    every reduced constraint vanishing): the sampler finds the same local dimension."""
    system = coopkin_sym.load(random_system(seed))
    joints = {j.name for j in system.model.joints}
    checked = 0
    for component in system.locus().components:
        if component.witness is None or checked == 2:
            continue
        fm = finite_mobility(system.model, component.witness)
        if fm.reason not in ("closure_saturation", "closure_bezout"):
            continue
        values = {k: _angle(v) for k, v in dict(component.witness).items() if k in joints}
        assert Sampler(system.model, values, {}).dimension(6) == fm.dimension
        checked += 1
    assert checked == 2


PINNED_TIP = """\
name: four-bar with a pin joint at the rocker's tip
planar: true
arms:
  - name: crank
    joints:
      - {name: q1, type: revolute, axis: [0, 0, 1], point: [0, 0, 0]}
  - name: rocker
    joints:
      - {name: q2, type: revolute, axis: [0, 0, 1], point: [2, 0, 0]}
      - {name: q3, type: revolute, axis: [0, 0, 1], point: [2, 1, 0]}
contacts:
  - {name: c1, link: crank/1, point: [0, 1, 0], normal: [0, 1, 0], model: hard}
  - {name: c2, link: rocker/2, point: [2, 1, 0], normal: [0, 1, 0], model: hard}
"""


def test_a_rank_two_cone_in_three_motions_is_not_counted_as_two_branches(tmp_path):
    """The folded four-bar with one more joint about the rocker's pin (a motion that
    enters no constraint): three first-order motions, a tangent cone of two planes.
    Its dimension, 2, is proved and the sampler's; its branches are not counted (a
    cone xy + z^3 = 0 has the same tangent cone and is one sheet)."""
    path = tmp_path / "pinned-tip.yaml"
    path.write_text(PINNED_TIP)
    system = load(str(path))
    fm = finite_mobility(system.model, "q1=-pi/2,q2=-pi/2")
    assert (fm.dimension, fm.first_order, fm.classification) == (2, 3, "cone")
    assert [b.dimension for b in fm.branches] == [2] and fm.branches[0].tangent is None
    assert sp.factor(fm.branches[0].cone) == sp.factor(
        sp.sympify("(3*x1 + x2)*(x1 - x2)"))
    sampler = Sampler(system.model, {"q1": -mp.pi / 2, "q2": -mp.pi / 2, "q3": 0}, {})
    assert sampler.dimension(8) == 2


@pytest.mark.slow
def test_the_sampler_sees_the_group_orbit_at_a_drop_of_case_1():
    """Paper case 1 at q1 = -5pi/6, q2 = 5pi/6 (Nm 2 -> 3): the rotations about the
    contact line are all the first-order motions, and all finite."""
    _check(load("paper-case1-hard"), {"q1": "-5*pi/6", "q2": "5*pi/6"})


#: The expansion's decisions (not the rank of Q, not the loop closure's).
_EXPANSION = {"cone_regular_points", "binary_form_roots", "real_cone_origin",
              "group_orbit"}


@pytest.mark.slow
@pytest.mark.parametrize("seed", [0, 32, 42])
def test_the_expansions_decisions_on_random_loci_are_the_samplers(seed):
    """Random two-arm systems with point and welded contacts, at the witnesses of
    their loci where the expansion decides (bifurcations, shaky points, cones): the
    sampler finds the same local dimension, and no sampled motion leaves along a
    column of the blocks said to fail."""
    system = coopkin_sym.load(random_system(seed))
    joints = {j.name for j in system.model.joints}
    checked = 0
    for component in system.locus().components:
        if component.witness is None:
            continue
        analysis = system.analyze(component.witness)
        fm = analysis.finite_mobility()
        if fm.reason not in _EXPANSION:
            continue
        values = {k: _angle(v) for k, v in dict(component.witness).items() if k in joints}
        sampler = Sampler(system.model, values, {})
        assert sampler.dimension(6) == fm.dimension, component.condition.text
        blocks = analysis.blocks()
        failing = [list(blocks["C12"][:, c.index - 1]) + list(blocks["C22"][:, c.index - 1])
                   for c in fm.columns if c.verdict == "fails" and c.block == "C12"]
        for d in sampler.directions(6) if failing else ():
            v = mp.matrix(d)
            for column in failing:
                s = mp.matrix([mp.mpf(str(sp.N(x, 70))) for x in column])
                s = s / mp.norm(s)
                off = min(mp.norm(v - s), mp.norm(v + s))
                assert off > mp.mpf(10) ** -2, (component.condition.text, d, column)
        checked += 1
    assert checked >= 2


@pytest.mark.slow
def test_a_frictionless_contact_moves_as_the_sampler_sees():
    """The underactuated finger, whose thumb pad slides on the object's face: at a
    regular configuration the finite mobility is the sampler's, and where the tip is
    folded back onto the inner contact (undecided there, the closure's saturation
    inconclusive) the bounds proved hold the sampler's dimension."""
    system = load("underactuated-finger")
    assert system.model.contacts[2].model == "frictionless"
    regular = {"q1": "2*atan(1/3)", "q2": "2*atan(1/2)", "q3": "2*atan(1/3)"}
    _check(system, regular, samples=6)
    folded = {"q1": "2*atan(1/3)", "q2": "-pi/2", "q3": "2*atan(1/3)"}
    fm = finite_mobility(system.model, ",".join(f"{k}={v}" for k, v in folded.items()))
    seen = Sampler(system.model, {k: _angle(v) for k, v in folded.items()},
                   {"L": 1}).dimension(6)
    assert fm.bounds[0] <= seen <= fm.bounds[1], (fm.bounds, seen)
    assert (fm.dimension, seen) == (None, 2)
