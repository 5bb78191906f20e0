"""The numbers that come first: compiled exact ranks at a point and generic numbers
from exact ranks at random points, checked against the arm-by-arm decomposition
(the blocks' own numbers) and against the independent reference on random systems."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from independent import reference_numbers_algebraic
from large_systems import many_arms
from strategies import random_configurations, random_systems

import coopkin_sym
from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.generic import NumbersCertificate, chain_numbers, generic_numbers
from coopkin_sym.analysis.mobility import decompose
from coopkin_sym.analysis.points import point_ranks
from coopkin_sym.exact.ring import ClearedRows
from coopkin_sym.model.builders import planar_hand, spatial_hand
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.examples import list_examples

SETTINGS = dict(deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                       HealthCheck.data_too_large])


def _decomposed(model, config):
    kin = kinematics.build(model, config)
    rows = [kin.ring.clear_row(r) for r in kin.Q]
    return rows, kin, decompose(rows, model, kin.row_contacts, kin.ring.zctx).numbers


@settings(max_examples=60, **SETTINGS)
@given(st.data())
@pytest.mark.slow
def test_point_numbers_compiled_agree_with_reference(data):
    """Every joint given: the compiled path (second and later points of a model) gives
    the reference's numbers, at generic-looking and special configurations."""
    spec = data.draw(random_systems(with_parameter=data.draw(st.booleans())))
    system = coopkin_sym.load(spec)
    for _ in range(3):
        at, text = data.draw(random_configurations(spec))
        config = system.configuration(text)
        a = system.analyze(config)
        expected = reference_numbers_algebraic(spec, at)
        assert a.numbers.as_dict() == expected, text
        assert a.certificate.exact
        # the same configuration again: now certainly on the compiled path
        assert point_ranks(system.model, config) is not None
        assert system.analyze(text).numbers.as_dict() == expected


@settings(max_examples=40, **SETTINGS)
@given(st.data())
def test_generic_numbers_agree_with_elimination(data):
    """Generic (every joint symbolic, L symbolic or given): the numbers from random
    points equal the decomposition's, whatever the certificate's time budget (none:
    every rank certified; zero: the certificate states the error bound)."""
    spec = data.draw(random_systems(with_parameter=data.draw(st.booleans())))
    model = coopkin_sym.load(spec).model
    config = Configuration.parse(model, None, "all")
    rows, kin, exact = _decomposed(model, config)
    seed = data.draw(st.integers(0, 2**32))
    certified, cert = generic_numbers(rows, model, kin.row_contacts, kin.ring.zctx,
                                      seed=seed, certify_seconds=None)
    assert certified == exact
    assert cert.exact and cert.error_bits is None
    assert all(r.how in {"size", "contacts", "elimination"} for r in cert.ranks)
    # rows cleared only where used, values at the points from the fractions
    lazy = ClearedRows(kin.ring, kin.Q)
    fast, cert_fast = generic_numbers(lazy, model, kin.row_contacts, kin.ring.zctx,
                                      seed=seed, certify_seconds=None)
    assert fast == exact and cert_fast.exact and cert_fast.error_bits is None
    sampled, cert0 = generic_numbers(rows, model, kin.row_contacts, kin.ring.zctx,
                                     seed=seed, certify_seconds=0)
    assert sampled == exact
    if not cert0.exact:
        assert cert0.error_bits >= 100
        assert any(r.how == "sampled" for r in cert0.ranks)


@settings(max_examples=40, **SETTINGS)
@given(st.data())
def test_numbers_from_the_chains_are_those_of_the_elimination_or_none(data):
    """Ranks modulo a prime at random points, ``Q`` evaluated from the product of
    exponentials: where they reach the size bounds, the numbers (every rank "size")
    are the decomposition's; otherwise nothing is claimed. Every joint symbolic, or
    some of them (the others at exact values), ``L`` symbolic or given."""
    spec = data.draw(random_systems(with_parameter=data.draw(st.booleans())))
    model = coopkin_sym.load(spec).model
    names = list(model.joint_names)
    free = data.draw(st.lists(st.sampled_from(names), min_size=1, unique=True))
    at = ",".join(f"{j}=2*atan({data.draw(st.integers(-3, 3))}/2)" for j in names
                  if j not in free and next(x for x in model.joints if x.name == j).type
                  == "revolute")
    config = Configuration.parse(model, at or None, free)
    _, _, exact = _decomposed(model, config)
    found = chain_numbers(model, config, seed=data.draw(st.integers(0, 2**32)))
    if found is not None:
        numbers, cert = found
        assert numbers == exact
        assert cert.exact and {r.how for r in cert.ranks} <= {"size", "contacts"}


@pytest.mark.parametrize("name", list_examples())
def test_numbers_from_the_chains_of_the_shipped_examples(name):
    """Every shipped example: the numbers from the chains, where the sizes certify
    them, are those of the symbolic ``Q``; they do for the real robots' arms."""
    model = coopkin_sym.load(name).model
    config = Configuration.parse(model, None, "all")
    kin = kinematics.build(model, config)
    expected, _ = generic_numbers(ClearedRows(kin.ring, kin.Q), model, kin.row_contacts,
                                  kin.ring.zctx, seed=3, certify_seconds=None)
    found = chain_numbers(model, config, seed=3)
    if name in ("panda-two-arm-box", "dh-two-puma560-box", "quadruped-standing"):
        assert found is not None
    assert found is None or found[0] == expected


@pytest.mark.parametrize("contact, numbers", [
    ("hard", {"Nm": 606, "Nc": 6, "Ni": 0, "Nr": 600, "Ng": 594, "Nd": 0, "Nh": 0}),
    pytest.param("complete",
                 {"Nm": 6, "Nc": 6, "Ni": 0, "Nr": 0, "Ng": 1194, "Nd": 0, "Nh": 0},
                 marks=pytest.mark.slow),
])
def test_generic_numbers_of_200_arms_come_from_the_chains(contact, numbers):
    """A cell of 200 six-joint arms (1,200 joints): its generic numbers are certified
    by the sizes from ranks at points modulo a prime, without the symbolic ``Q`` (whose
    kinematics alone costs about a minute); at a random exact point (ranked arm by arm
    over Q) the numbers are the same."""
    system = coopkin_sym.load(many_arms(200, 6, contact))
    a = system.analyze(generic=True)
    assert a.numbers.as_dict() == numbers
    assert a.certificate.exact and {r.how for r in a.certificate.ranks} == {"size"}
    assert "kinematics" not in a.__dict__
    at = ",".join(f"{j}=2*atan({(7 * k) % 11 - 5}/{k % 4 + 1})"
                  for k, j in enumerate(system.joint_names)) + ",L=1"
    assert system.analyze(at).numbers.as_dict() == numbers


@settings(max_examples=30, **SETTINGS)
@given(st.data())
def test_values_at_a_point_are_the_cleared_rows_scaled(data):
    """Each row of ``ClearedRows.values_at`` is a positive multiple of the cleared
    row's values at the point, and cleared blocks are the blocks of the rows scaled."""
    spec = data.draw(random_systems(with_parameter=data.draw(st.booleans())))
    model = coopkin_sym.load(spec).model
    kin = kinematics.build(model, Configuration.parse(model, None, "all"))
    lazy = ClearedRows(kin.ring, kin.Q)
    nvars = kin.ring.zctx.nvars()
    point = data.draw(st.lists(st.integers(-2**62, 2**62), min_size=nvars, max_size=nvars))
    for row, values in zip((kin.ring.clear_row(r) for r in kin.Q), lazy.values_at(point),
                           strict=True):
        exact = [0 if p.is_zero() else int(p(*point)) for p in row]
        # values = c * exact with c > 0: every 2x2 "minor" vanishes, signs agree
        assert all(a * y == b * x for a, x in zip(values, exact, strict=True)
                   for b, y in zip(values, exact, strict=True))
        assert all((a > 0) == (x > 0) and (a < 0) == (x < 0)
                   for a, x in zip(values, exact, strict=True))
    cols = data.draw(st.lists(st.integers(0, len(kin.Q[0]) - 1), min_size=1, unique=True))
    for i, row in enumerate(lazy.block(range(len(kin.Q)), cols)):
        full = kin.ring.clear_row(kin.Q[i])
        picked = [full[c] for c in cols]
        assert all((a * y - b * x).is_zero() for a, x in zip(row, picked, strict=True)
                   for b, y in zip(row, picked, strict=True))


@pytest.mark.parametrize("spec", ["paper-case1-hard", "paper-case2-hard",
                                  "paper-case2-complete", "planar-two-fingers",
                                  "five-bar", "underactuated-finger"])
def test_generic_analysis_numbers_before_blocks(spec):
    """``analyze(generic=True).numbers`` comes before any block and equals the blocks'
    numbers; once the blocks are built the certificate is the elimination's."""
    system = coopkin_sym.load(spec)
    a = system.analyze(generic=True)
    first, cert = a.numbers, a.certificate
    assert "_decomposition" not in a.__dict__
    assert cert.exact
    a.C11  # noqa: B018  (builds the decomposition)
    assert "_decomposition" in a.__dict__
    assert a.numbers == first
    assert a.certificate == NumbersCertificate.by_elimination()


@pytest.mark.parametrize("build, expected", [
    (lambda: spatial_hand(5, 2), {"Nm": 1, "Nc": 1, "Ni": 0, "Nr": 0}),
    (lambda: planar_hand(4, 3), {"Nm": 7, "Nc": 3, "Ni": 0, "Nr": 4}),
])
def test_generic_numbers_of_hands_are_certified(build, expected):
    a = coopkin_sym.load(build()).analyze(generic=True)
    assert {k: a.numbers.as_dict()[k] for k in expected} == expected
    assert a.certificate.exact


#: The generic numbers of the four-finger hand, every joint free: the exact elimination
#: of its Q (about 40 s: checked in the slow test below) gives them.
HAND_GENERIC = {"Nm": 6, "Nc": 3, "Ni": 0, "Nr": 3, "Ng": 10, "Nd": 3, "Nh": 0}


@pytest.mark.slow
def test_the_hands_generic_numbers_are_those_of_the_exact_elimination():
    model = coopkin_sym.load("allegro-hand-sphere").model
    _, _, exact = _decomposed(model, Configuration.parse(model, None, "all"))
    assert exact.as_dict() == HAND_GENERIC


def test_probabilistic_numbers_say_so():
    """With no time for a certificate, ranks the sizes do not bound are sampled, and
    the certificate gives the error exponent from the degrees and the points."""
    model = coopkin_sym.load("allegro-hand-sphere").model
    config = Configuration.parse(model, None, "all")
    kin = kinematics.build(model, config)
    rows = [kin.ring.clear_row(r) for r in kin.Q]
    numbers, cert = generic_numbers(rows, model, kin.row_contacts, kin.ring.zctx,
                                    seed=7, certify_seconds=0)
    assert numbers.as_dict() == HAND_GENERIC
    assert not cert.exact
    hows = {r.matrix: r.how for r in cert.ranks}
    assert hows["Dt[index]"] == "sampled"     # 4 rows, 4 joints, rank 3: no size bound
    assert hows["Dt[thumb]"] == "size"        # 4 rows, rank 4
    # two points, coordinates from 2**63 + 1 integers, minors of degree below 2**7
    assert 100 <= cert.error_bits <= 2 * 63
    assert cert.as_dict()["error_bits"] == cert.error_bits


def test_the_rank_of_gt_is_certified_by_free_contact_points():
    """Two hard contacts: rank H G^T is 5 (the object turns about the line through
    them), below the sizes' 6; it equals the rank with every contact point and normal
    free, a certified bound, so no elimination is needed (nor time for it)."""
    from coopkin_sym.analysis.generic import grasp_rank_bound

    model = coopkin_sym.load("paper-case2-hard").model
    assert grasp_rank_bound(model) == 5
    assert grasp_rank_bound(coopkin_sym.load("paper-case2-complete").model) == 6
    config = Configuration.parse(model, None, "all")
    rows, kin, exact = _decomposed(model, config)
    numbers, cert = generic_numbers(rows, model, kin.row_contacts, kin.ring.zctx,
                                    seed=7, certify_seconds=0)
    assert numbers == exact and cert.exact
    assert {r.matrix: r.how for r in cert.ranks}["Gt"] == "contacts"
    chained, cert = chain_numbers(model, config, seed=7)
    assert chained == exact and cert.exact
    a = coopkin_sym.load(spatial_hand(2, 4)).analyze(generic=True)
    assert a.certificate.exact and "kinematics" not in a.__dict__
    assert a.numbers.as_dict() == {"Nm": 8, "Nc": 6, "Ni": 1, "Nr": 2, "Ng": 1, "Nd": 0,
                                   "Nh": 0}


def test_point_analysis_blocks_after_numbers():
    """At a point, the blocks built after the compiled numbers agree with them."""
    system = coopkin_sym.load("paper-case2-hard")
    at = "q1=pi/2,q2=2*atan(1/3),q3=-pi/2,q4=1/2,q5=3,q6=pi,q7=2*atan(-2),q8=0,L=2"
    first = system.analyze(at)
    assert first.numbers.Nm == 8                 # the first point: no compiling
    second = system.analyze(at)
    numbers = second.numbers                     # compiled now
    assert point_ranks(system.model, second.configuration) is not None
    assert second.C.shape[1] == numbers.Nm
    assert second.numbers == numbers == first.numbers


@pytest.mark.parametrize("spec, joints", [("paper-case1-hard", ["q1", "q2"]),
                                          ("paper-case2-hard", ["q2", "q3"])])
def test_modular_shortcut_agrees_with_integer_ranks(spec, joints):
    """The point ranks taken modulo a prime when they reach the generic ranks equal the
    ranks over the integers on a grid of tangents that hits the singular values."""
    from coopkin_sym.analysis.sweep.compiled import _exact_for, compile_system

    system = coopkin_sym.load(spec)
    compiled = compile_system(system, system.joint_names, "L=1")
    generic = compiled.quick_generic_ranks
    assert generic == compiled.generic_ranks
    exact = _exact_for(compiled._plan)
    tangents = [(0, 1), (1, 0), (1, 1), (-1, 1), (1, 3), (-2, 1), (3, 4)]
    index = [system.joint_names.index(j) for j in joints]
    differ = 0
    for a in tangents:
        for b in tangents:
            pairs = [(1, 5)] * len(system.joint_names)
            pairs[index[0]], pairs[index[1]] = a, b
            fast, slow = exact.ranks(pairs, generic), exact.ranks(pairs)
            assert fast == slow
            differ += slow != generic
    assert differ > 0                          # the grid holds singular points
