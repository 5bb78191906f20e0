"""``Q`` at a point from the product of exponentials (analysis/sweep/chains.py) against
the kinematics (analysis/kinematics.py) entry by entry, and the compiled point numbers
against the first point analysis of a freshly loaded system, on the shipped examples,
random systems and long arms."""

from __future__ import annotations

import random
from fractions import Fraction

import flint
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from random_systems import random_system
from strategies import random_configurations, random_systems

import coopkin_sym
from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.generic import generic_numbers
from coopkin_sym.analysis.numbers import ranks_from_numbers
from coopkin_sym.analysis.sweep import chains
from coopkin_sym.analysis.sweep.compiled import POINT_PRIME, compile_system
from coopkin_sym.exact.sympy_bridge import matrix_to_sympy
from coopkin_sym.model import load_model
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import list_examples

SETTINGS = dict(deadline=None, max_examples=25,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


def _unit(rng: random.Random) -> list[str]:
    """An exact unit vector (inverse stereographic projection of a rational point)."""
    a = Fraction(rng.randint(-5, 5), rng.randint(1, 5))
    b = Fraction(rng.randint(-5, 5), rng.randint(1, 5))
    d = 1 + a * a + b * b
    return [str(x) for x in (2 * a / d, 2 * b / d, (a * a + b * b - 1) / d)]


def _point(rng: random.Random) -> list[str]:
    return [str(Fraction(rng.randint(-9, 9), rng.randint(1, 4))) for _ in range(3)]


def long_arm(joints: int, seed: int = 0, contact: str = "hard",
             prismatic: tuple[int, ...] = ()) -> dict:
    """One arm of ``joints`` joints with random exact axes and points, one contact on
    its last link."""
    rng = random.Random(seed)
    chain = [{"name": f"q{k + 1}", "type": "prismatic" if k in prismatic else "revolute",
              "axis": _unit(rng), "point": _point(rng)} for k in range(joints)]
    return {"name": f"arm of {joints}", "parameters": [],
            "arms": [{"name": "a", "joints": chain}],
            "contacts": [{"name": "c", "link": f"a/{joints}", "point": _point(rng),
                          "normal": _unit(rng), "model": contact}]}


def _pair(rng: random.Random, kind: str) -> tuple[int, int]:
    """A joint value as ``(a, b)``: ``tan(q/2) = a/b`` (``q = pi`` sometimes), or a
    displacement ``a/b``."""
    if kind == "revolute" and rng.random() < 0.2:
        return (1, 0)
    if rng.random() < 0.2:
        return (0, 1)
    return (rng.randint(-9, 9), rng.randint(1, 9))


def _config_of(model, pairs, parameters) -> Configuration:
    values = {}
    for joint, (a, b) in zip(model.joints, pairs, strict=True):
        if joint.type == "revolute":
            values[joint.name] = sp.pi if b == 0 else 2 * sp.atan(sp.Rational(a, b))
        else:
            values[joint.name] = sp.Rational(a, b)
    return Configuration.parse(model, {**values, **parameters})


def _kinematics_q(model, config) -> sp.Matrix:
    kin = kinematics.build(model, config)
    shape = (len(kin.Q), model.object_dim + len(model.joints))
    return matrix_to_sympy(kin.Q, kin.ring, kin.symbols, shape), kin


def _as_sympy(rows, model, symbols=()) -> sp.Matrix:
    def entry(x):
        if isinstance(x, flint.fmpq):
            return sp.Rational(int(x.p), int(x.q))
        return sp.Add(*[sp.Rational(int(c.p), int(c.q)) * sp.Mul(
            *[s ** int(e) for s, e in zip(symbols, exps, strict=True)])
            for exps, c in x.to_dict().items()])
    width = model.object_dim + len(model.joints)
    return sp.Matrix(len(rows), width, [entry(x) for row in rows for x in row])


def _check_rows(model, pairs, parameters) -> None:
    """The rows at the point equal the kinematics' ``Q`` exactly (every parameter
    set), and reduce to the modular rows."""
    chain = chains.ChainQ(chains.chain_data(model, Configuration.parse(model, parameters),
                                            model.joint_names))
    q, _ = _kinematics_q(model, _config_of(model, pairs, parameters))
    rows = chain.rows(chains.RationalField(), pairs)
    assert _as_sympy(rows, model) == q
    p = 1_000_003
    residues = chain.rows(chains.ModularField(p), pairs)
    assert residues == [[int(x.p) * pow(int(x.q), -1, p) % p for x in row] for row in rows]


def _check_symbolic_rows(model, pairs) -> None:
    """With the parameters symbolic the rows are the kinematics' polynomials in them,
    and the modular rows their values at the residues of the field."""
    names = [p.name for p in model.parameters]
    chain = chains.ChainQ(chains.chain_data(model, Configuration.parse(model, None),
                                            model.joint_names))
    q, kin = _kinematics_q(model, _config_of(model, pairs, {}))
    rows = chain.rows(chains.PolynomialField(names), pairs)
    assert (_as_sympy(rows, model, [kin.symbols[n] for n in names]) - q).expand() \
        == sp.zeros(*q.shape)
    p, values = 1_000_003, [5 + k for k in range(len(names))]
    residues = chain.rows(chains.ModularField(p, values), pairs)
    for row, res in zip(rows, residues, strict=True):
        for x, r in zip(row, res, strict=True):
            v = x(*[flint.fmpq(v) for v in values]) if names else x
            assert r == int(v.p) * pow(int(v.q), -1, p) % p


@pytest.mark.parametrize("name", list_examples())
def test_rows_equal_the_kinematics_on_every_example(name):
    model = load_model(name)
    rng = random.Random(name)
    for _ in range(4):
        pairs = [_pair(rng, j.type) for j in model.joints]
        parameters = {p.name: sp.Rational(rng.randint(1, 9), rng.randint(1, 4))
                      for p in model.parameters}
        _check_rows(model, pairs, parameters)
        if model.parameters:
            _check_symbolic_rows(model, pairs)


@settings(**SETTINGS)
@given(st.data(), st.booleans())
def test_rows_equal_the_kinematics_on_random_systems(data, with_parameter):
    raw = data.draw(random_systems(with_parameter=with_parameter))
    model = load_model(raw)
    at, _ = data.draw(random_configurations(raw))
    pairs = []
    for joint in model.joints:
        value = at[joint.name]
        if joint.type == "revolute":
            c, s = value
            pairs.append((1, 0) if c == -1 else (int((s / (1 + c)).p), int((s / (1 + c)).q)))
        else:
            pairs.append((int(value.p), int(value.q)))
    parameters = {p.name: at[p.name] for p in model.parameters}
    _check_rows(model, pairs, parameters)
    if with_parameter:
        _check_symbolic_rows(model, pairs)


@pytest.mark.parametrize("seed", range(16))
def test_rows_equal_the_kinematics_on_the_random_two_arm_systems(seed):
    model = load_model(random_system(seed))
    rng = random.Random(seed)
    for _ in range(3):
        _check_rows(model, [_pair(rng, j.type) for j in model.joints], {})


@pytest.mark.parametrize("contact, prismatic", [("hard", ()), ("soft", (2,)),
                                                ("frictionless", (0, 5)),
                                                ("complete", (6,))])
def test_rows_of_a_seven_joint_arm(contact, prismatic):
    model = load_model(long_arm(7, 3, contact, prismatic))
    rng = random.Random(contact)
    for _ in range(3):
        _check_rows(model, [_pair(rng, j.type) for j in model.joints], {})


def _text(model, pairs) -> str:
    parts = []
    for joint, (a, b) in zip(model.joints, pairs, strict=True):
        if joint.type == "prismatic":
            parts.append(f"{joint.name}={a}/{b}")
        else:
            parts.append(f"{joint.name}=" + ("pi" if b == 0 else f"2*atan({a}/{b})"))
    return ",".join(parts)


def _first_numbers(raw, at):
    """The numbers of the first analysis of a freshly loaded system (the kinematics
    and exact ranks, never the compiled path)."""
    return coopkin_sym.load(raw).analyze(at).numbers


@pytest.mark.parametrize("raw", [long_arm(7, 1), long_arm(7, 2, "soft", (3,)),
                                 long_arm(5, 4, "complete")], ids=["7R", "6R1P", "5R"])
def test_compiled_numbers_of_long_arms_equal_the_first_analysis(raw):
    system = coopkin_sym.load(raw)
    compiled = compile_system(system, system.joint_names)
    assert compiled.quick_generic_ranks is not None    # certified by the sizes
    rng = random.Random(11)
    points = [[_pair(rng, j.type) for j in system.model.joints] for _ in range(6)]
    points.append([(0, 1)] * len(system.model.joints))                  # home
    points.append([(1, 0) if j.type == "revolute" else (0, 1)            # all at pi
                   for j in system.model.joints])
    for pairs in points:
        text = _text(system.model, pairs)
        assert compiled.numbers(text) == _first_numbers(raw, text), text
        assert system.analyze(text).numbers == _first_numbers(raw, text), text


@pytest.mark.parametrize("name", ["paper-case1-hard", "paper-case2-hard", "paper-case1-soft",
                                  "five-bar"])
def test_compiled_numbers_with_symbolic_parameters_are_those_over_q_of_l(name):
    model = load_model(name)
    compiled = compile_system(model, model.joint_names)          # L symbolic
    rng = random.Random(name)
    for _ in range(5):
        pairs = [_pair(rng, j.type) for j in model.joints]
        text = _text(model, pairs)
        assert compiled.numbers(text) == _first_numbers(name, text), text


@pytest.mark.parametrize("name, certified", [("paper-case1-hard", True),
                                             ("paper-case2-hard", True),
                                             ("paper-case2-complete", False),
                                             ("paper-case1-soft", False),
                                             ("urdf-two-fingers", True), ("five-bar", True)])
def test_sampled_generic_ranks_agree_with_the_symbolic_ones(name, certified):
    """Where the bounds certify them, the generic ranks from modular ranks at random
    points are those of the elimination over ``Q(t, L)``; a hyperstatic grasp (rank of
    ``Q`` below its rows) is left to the elimination."""
    model = load_model(name)
    at = ",".join(f"{p.name}=1" for p in model.parameters) or None
    compiled = compile_system(model, model.joint_names, at)
    kin, rows = compiled._symbolic
    numbers, cert = generic_numbers(rows, model, kin.row_contacts, kin.ring.zctx, seed=0,
                                    certify_seconds=None)
    assert cert.exact
    symbolic = ranks_from_numbers(numbers, len(model.joints), dim=model.object_dim)
    assert compiled._sampled_generic() == (symbolic if certified else None)
    assert compiled.generic_ranks == symbolic


def test_the_sizes_certify_a_long_arm():
    assert compile_system(load_model(long_arm(7, 5)), [f"q{k}" for k in range(1, 8)]
                          )._sampled_generic() == (3, 3, 3)


@pytest.mark.parametrize("models, planar, bound", [
    (["hard"], False, 3), (["hard", "hard"], False, 5), (["hard"] * 3, False, 6),
    (["soft", "soft"], False, 6), (["frictionless"] * 5, False, 5),
    (["frictionless"] * 7, False, 6), (["complete"], False, 6), (["soft"], False, 4),
    (["hard"], True, 2), (["hard", "hard"], True, 3), (["frictionless"] * 2, True, 2),
    (["complete"], True, 3)])
def test_the_grasp_bound_is_the_rank_with_independent_points_and_normals(models, planar,
                                                                         bound):
    raw = long_arm(2, 7)
    if planar:
        raw["planar"] = True
        for joint in raw["arms"][0]["joints"]:
            joint["axis"], joint["point"][2] = [0, 0, 1], 0
    contact = raw["contacts"][0]
    raw["contacts"] = [{**contact, "name": f"c{i}", "model": kind,
                        "normal": [1, 0, 0] if planar else contact["normal"],
                        "point": [str(i), "1", "0" if planar else "2"]}
                       for i, kind in enumerate(models)]
    model = load_model(raw)
    assert compile_system(model, model.joint_names)._grasp_bound() == bound


def test_a_denominator_divisible_by_the_prime_falls_back_to_exact_ranks():
    raw = long_arm(4, 6)
    raw["contacts"][0]["point"] = [f"1/{POINT_PRIME}", "1", "2"]
    model = load_model(raw)
    chain = chains.ChainQ(chains.chain_data(model, Configuration(), model.joint_names))
    with pytest.raises(chains.Unlucky):
        chain.rows(chains.ModularField(POINT_PRIME), [(1, 2)] * 4)
    system = coopkin_sym.load(raw)
    rng = random.Random(6)
    for _ in range(4):
        text = _text(model, [_pair(rng, "revolute") for _ in range(4)])
        assert system.analyze(text).numbers == _first_numbers(raw, text)
