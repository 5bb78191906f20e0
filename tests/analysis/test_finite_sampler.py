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
