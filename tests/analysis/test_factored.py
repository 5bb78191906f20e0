"""The factored coordinated motions: ``[C12; K C12]`` lies in the nullspace of ``Q``
and spans what ``[C12; C22]`` spans, checked exactly at random rational points on
random systems; the JSON and text outputs give it when ``C22`` is over budget."""

from __future__ import annotations

import json
import random

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from strategies import random_systems
from support import same_span
from typer.testing import CliRunner

import coopkin_sym
from coopkin_sym.cli import app
from coopkin_sym.errors import ConfigurationError
from coopkin_sym.model.builders import planar_hand


def _points(symbols, count, seed):
    rng = random.Random(seed)
    for _ in range(count):
        yield {s: sp.Rational(rng.randint(-60, 60), rng.randint(1, 60)) for s in symbols}


def _check(a, seed: int, compare_c22: bool) -> int:
    f = a.coordinated_factored()
    checked = 0
    for point in _points(f.symbols, 12, seed):
        try:
            u, q = f.at(point)
        except ValueError:                        # a denominator factor vanishes here
            continue
        column = sp.Matrix.vstack(u, q)
        assert (a.Q.subs(point) * column).is_zero_matrix
        if compare_c22:
            theirs = sp.Matrix.vstack(a.C12, a.C22).subs(point)
            both = sp.Matrix.hstack(column, theirs)
            assert column.rank() == theirs.rank() == both.rank()
        if column.rank() == a.numbers.Nc - a.numbers.Ni:
            checked += 1
    return checked


@pytest.mark.slow  # campaign-style (random systems): run by .ci/run, not by the default command
@settings(max_examples=30, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(st.data())
def test_factored_motions_of_random_systems(data):
    spec = data.draw(random_systems(with_parameter=data.draw(st.booleans())))
    a = coopkin_sym.load(spec).analyze(generic=True)
    a.term_budget = None
    if a.numbers.Nc == a.numbers.Ni:
        assert a.coordinated_factored().twists.cols == 0
        return
    assert _check(a, data.draw(st.integers(0, 10**6)), compare_c22=True) > 0


@pytest.mark.slow
def test_factored_motions_of_a_hand():
    """planar_hand(4, 2): C22's entries run to 100,000 characters; the maps are small
    and name the finger singularities (t = 1, t = -1) once."""
    a = coopkin_sym.load(planar_hand(4, 2)).analyze(generic=True)
    f = a.coordinated_factored()
    assert max(len(str(e)) for k in f.maps().values() for e in k) < 400
    assert len(f.factors) == len({str(p) for _, p in f.factors})
    assert _check(a, 1, compare_c22=False) > 0


def test_factored_in_text_and_json():
    runner = CliRunner()
    out = runner.invoke(app, ["analyze", "dh-three-finger-hand", "--generic", "--json"])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout)
    assert data["blocks"]["C22"] is None
    factored = data["factored"]
    assert [arm["name"] for arm in factored["arms"]] == ["f1", "f2", "f3"]
    assert all(len(arm["map"]) == len(arm["joints"]) == 3 for arm in factored["arms"])
    assert all(len(row) == 6 for arm in factored["arms"] for row in arm["map"])
    names = {x["name"] for x in factored["factors"]}
    used = {n for arm in factored["arms"] for row in arm["map"] for e in row
            for n in names if n in e}
    assert used and used <= names
    assert data["certificate"]["exact"] is True
    text = runner.invoke(app, ["analyze", "dh-three-finger-hand", "--generic"])
    assert "C22 factored: the joint velocities of each arm are K_arm u" in text.stdout
    home = json.loads(runner.invoke(app, ["analyze", "paper-case1-hard", "--json"]).stdout)
    assert home["factored"] is None


def test_factored_latex_renders():
    """The LaTeX of the factored form names every arm and factor; its equations and
    factors (not the matrices, which mathtext does not typeset) are read by
    matplotlib's mathtext."""
    from matplotlib.mathtext import MathTextParser

    f = coopkin_sym.load("planar-two-fingers").analyze(generic=True).coordinated_factored()
    lines = f.latex().splitlines()
    assert len(lines) == 2 * len(f.arms) + len(f.factors)
    assert all(f"K_{{\\mathrm{{{arm.name}}}}}" in f.latex() for arm in f.arms)
    parser = MathTextParser("agg")
    for line in lines[0:2 * len(f.arms):2] + lines[2 * len(f.arms):]:
        parser.parse(f"${line}$")
    assert f._repr_latex_().startswith("$$")


def test_at_takes_at_text_names_and_symbols_and_spans_the_point_analysis():
    system = coopkin_sym.load("planar-two-fingers")
    f = system.analyze(generic=True).coordinated_factored()
    symbols = {str(x): x for x in f.symbols}
    for text in ("q1=2*atan(1/3),q2=2*atan(-2),q3=2*atan(1/5),q4=2*atan(2/7),L=2",
                 "q1=pi/2,q2=2*atan(1/2),q3=-pi/2,q4=2*atan(3),L=1"):
        u, qdot = f.at(text)
        a = system.analyze(text)
        assert same_span(sp.Matrix.vstack(u, qdot), sp.Matrix.vstack(a.C12, a.C22))
        values = dict(item.split("=") for item in text.split(","))
        assert f.at(values) == (u, qdot)                    # names as keys, text values
        point = system.configuration(text)
        by_symbol = {symbols[f"t_{j}"]: sp.Rational(a.num, a.den)
                     for j, a in point.revolute.items()}
        by_symbol[symbols["L"]] = point.parameters["L"]
        assert f.at(by_symbol) == (u, qdot)
    with pytest.raises(ConfigurationError, match="q = pi lies outside the t = tan"):
        f.at("q1=pi,L=1")
    with pytest.raises(ConfigurationError, match="unknown name 'q9'"):
        f.at("q9=0")
    with pytest.raises(ConfigurationError, match="expected an exact rational, got '0.5'"):
        f.at({symbols["t_q1"]: 0.5})
    with pytest.raises(ConfigurationError, match="no value for L"):
        f.at("q1=pi/2")
