"""Sweeps evaluated point by point from the product of exponentials (more swept joints
on one chain than the expansion affords) against the expanded batch evaluation and
the first analysis of a freshly loaded system."""

from __future__ import annotations

import random
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest
from test_chains import _pair, _text, long_arm

import coopkin_sym
from coopkin_sym.analysis.sweep import compile_system, grid
from coopkin_sym.analysis.sweep import compiled as compiled_module

CASE2 = coopkin_sym.load("paper-case2-hard")


def test_a_long_chain_is_swept_point_by_point_and_agrees_with_the_first_analysis():
    raw = long_arm(7, 8, "soft", (4,))
    system = coopkin_sym.load(raw)
    rng = random.Random(3)
    points = [_text(system.model, [_pair(rng, j.type) for j in system.model.joints])
              for _ in range(12)]
    points.append(_text(system.model, [(1, 0), (1, 0), (1, 0), (1, 0), (0, 1), (1, 0),
                                       (1, 0)]))
    result = system.sweep(points)
    assert compile_system(system, system.joint_names).plan["pointwise"] is True
    for i, text in enumerate(points):
        first = coopkin_sym.load(raw).analyze(text).numbers
        assert result.numbers[i].tolist() == list(first.as_dict().values()), text


@pytest.mark.parametrize("at", ["L=1", None])
def test_point_by_point_and_expanded_sweeps_agree(monkeypatch, at):
    g = grid(CASE2, "q1=-pi..pi:3,q2=-pi/2..pi/2:3,q3=0..pi:3,q4=-1..1:3")
    expanded = CASE2.sweep(g, at=at)
    compiled_module._COMPILED.clear()
    compiled_module._EXACT_CACHE.clear()
    monkeypatch.setattr(compiled_module, "EXPANDED_JOINTS", 1)
    pointwise = CASE2.sweep(g, at=at)
    assert compile_system(CASE2, g.joints, at).plan["pointwise"] is True
    assert np.array_equal(pointwise.numbers, expanded.numbers)
    assert pointwise.rechecked.sum() > 0            # the grid holds singular points
    assert not pointwise.rechecked.all()
    compiled_module._COMPILED.clear()
    compiled_module._EXACT_CACHE.clear()


def test_a_pointwise_sweep_on_an_executor_is_the_serial_one():
    system = coopkin_sym.load(long_arm(6, 9))
    g = grid(system, ",".join(f"q{k}=-pi/2..pi:{2 if k > 2 else 3}" for k in range(1, 7)))
    serial = system.sweep(g)
    with ThreadPoolExecutor(2) as pool:
        spread = system.sweep(g, executor=pool, chunk=10)
    assert np.array_equal(serial.numbers, spread.numbers)
    assert np.array_equal(serial.rechecked, spread.rechecked)
