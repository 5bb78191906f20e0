"""The example families of :mod:`coopkin_sym.model.builders` against the independent reference,
against hand derivations, and generic numbers against random rational points."""

from __future__ import annotations

import random
from fractions import Fraction

import pytest
import sympy as sp
from independent import reference_analysis

import coopkin_sym
from coopkin_sym.errors import ArgumentError
from coopkin_sym.model.builders import arm_cell, circle_point, planar_hand, spatial_hand

NUMBER_KEYS = ("Nm", "Nc", "Ni", "Nr", "Ng", "Nd", "Nh")
MIXED5 = ["hard", "soft", "hard", "soft", "hard"]

# (builder, args, kwargs): every family, several sizes, every option
MODELS = [
    (planar_hand, (1, 1), {}),
    (planar_hand, (2, 2), {}),
    (planar_hand, (2, 2), {"tips": "soft"}),
    (planar_hand, (3, 3), {"tips": ["hard", "soft", "frictionless"]}),
    (planar_hand, (4, 2), {"palm": True}),
    (planar_hand, (3, 2), {"inner": "frictionless", "palm": "soft"}),
    (planar_hand, (6, 3), {"tips": "complete", "inner": True}),
    (spatial_hand, (1, 1), {}),
    (spatial_hand, (2, 3), {}),
    (spatial_hand, (3, 3), {"tips": ["hard", "soft", "hard"]}),
    (spatial_hand, (4, 4), {"tips": "soft", "palm": "frictionless"}),
    (spatial_hand, (5, 4), {"tips": MIXED5}),
    (arm_cell, (2, 6), {}),
    (arm_cell, (3, 6), {"contact": "hard"}),
    (arm_cell, (2, 8), {}),
    (arm_cell, (4, 5), {"contact": ["complete", "soft", "hard", "frictionless"]}),
    (arm_cell, (1, 1), {"contact": "soft"}),
]
IDS = [f"{f.__name__}{args}{''.join(f'-{k}={v}' for k, v in kw.items())}"
       for f, args, kw in MODELS]


def build(case) -> dict:
    f, args, kwargs = case
    return f(*args, **kwargs)


def random_configuration(model: dict, rng: random.Random, size: int = 9) -> dict:
    """Every joint at q = 2 atan(p/q) (exact cos, sin), ``L`` a random positive rational."""
    at: dict = {}
    for arm in model["arms"]:
        for joint in arm["joints"]:
            t = sp.Rational(rng.randint(-size, size), rng.randint(1, size))
            at[joint["name"]] = ((1 - t**2) / (1 + t**2), 2 * t / (1 + t**2))
    at["L"] = sp.Rational(rng.randint(1, size), rng.randint(1, size))
    return at


def r_of(model: dict) -> int:
    return sum(len(arm["joints"]) for arm in model["arms"])


# --------------------------------------------------------------------- loading, exactness


@pytest.mark.parametrize("case", MODELS, ids=IDS)
def test_every_model_loads_with_exact_numbers(case):
    model = build(case)
    system = coopkin_sym.load(model)
    f, (count, joints), _ = case
    assert len(system.model.arms) == count
    assert len(system.model.joints) == count * joints
    assert [str(p) for p in system.model.parameters] == ["L"]
    for arm in model["arms"]:
        for joint in arm["joints"]:
            assert all(isinstance(x, int | str) for x in joint["axis"] + joint["point"])
    for c in system.model.contacts:
        if c.normal is not None:
            assert sum(x**2 for x in c.normal) == 1


def test_circle_points_are_rational_unit_and_distinct():
    points = [circle_point(k) for k in range(24)]
    assert all(c * c + s * s == 1 for c, s in points)
    assert len(set(points)) == 24


@pytest.mark.parametrize("bad, message", [
    (lambda: planar_hand(2, 2, tips=["hard"]), "expected 2 contact models"),
    (lambda: spatial_hand(2, 2, tips="sticky"), "unknown contact model 'sticky'"),
    (lambda: arm_cell(2, 9), "at most 8 joints"),
    (lambda: planar_hand(25, 1), "at most 24"),
    (lambda: planar_hand(0, 2), "at least one"),
])
def test_bad_sizes_and_models_are_refused(bad, message):
    with pytest.raises(ArgumentError, match=message):
        bad()


# ---------------------------------------------------------------- against the reference


@pytest.mark.parametrize("case", MODELS, ids=IDS)
def test_random_rational_configuration_matches_reference(case):
    model = build(case)
    rng = random.Random(IDS[MODELS.index(case)])
    at = random_configuration(model, rng)
    ref = reference_analysis(model, at)
    a = coopkin_sym.load(model).analyze(at)
    assert a.numbers.as_dict() == {k: ref[k] for k in NUMBER_KEYS}
    assert a.Q == ref["Q"]
    assert a.check()
    n = a.numbers
    assert n.Nm == n.Nc + n.Nr
    assert n.Nm - n.Nh == 6 + r_of(model) - a.m


@pytest.mark.parametrize("case", MODELS, ids=IDS)
def test_home_has_the_numbers_of_a_random_point(case):
    # Home is not singular by accident. (Small half-angle tangents are not random
    # enough: with t = -1/2 a spatial finger of 3 joints is stretched straight, since
    # its home bend is 2 atan(1/2); so the point here takes p/q with |p|, q <= 97.)
    model = build(case)
    rng = random.Random("home " + IDS[MODELS.index(case)])
    at = random_configuration(model, rng, size=97)
    ref = reference_analysis(model, at)
    system = coopkin_sym.load(model)
    numbers = system.analyze(at).numbers
    assert numbers.as_dict() == {k: ref[k] for k in NUMBER_KEYS}
    assert system.analyze().numbers == numbers


@pytest.mark.parametrize("case", MODELS, ids=IDS)
def test_home_matches_reference_and_identities_hold(case):
    model = build(case)
    ref = reference_analysis(model, {"L": sp.Rational(3, 2)})
    a = coopkin_sym.load(model).analyze("L=3/2")
    n = a.numbers
    assert n.as_dict() == {k: ref[k] for k in NUMBER_KEYS}
    assert n.Nm == n.Nc + n.Nr
    assert n.Nm - n.Nh == 6 + r_of(model) - a.m
    assert a.m == ref["m"]


# ------------------------------------------------------------------------ hand checked


def test_planar_two_fingers_two_joints_hard_by_hand():
    # Two planar 2R fingers (axes along z, in the plane z = 0), hard tips at c1, c2 in
    # that plane: r = 4, m = 6, Q is 6 x 10.
    # * Out of the plane the fingers cannot move: v_z + (w x c_i)_z = 0 at both tips,
    #   two independent equations on (v_z, w_x, w_y); what is left is the rotation
    #   about the line c1 c2. So Ni = 1 (joints locked, in-plane motion is stopped by
    #   two fixed points).
    # * In the plane: (v_x, v_y, w_z) and 4 joint rates, 4 equations
    #   v + w_z e_z x c_i = J_i qdot_i with each 2x2 finger Jacobian J_i invertible
    #   (bent fingers): rank 4, 7 - 4 = 3 coordinated motions, no redundancy (Nr = 0).
    # Nm = 1 + 3 = 4, Nc = 4; rank Q = 10 - 4 = 6 = m, so Nh = 0;
    # Ng = m - rank(HG^T) = 6 - 5 = 1; Nd = m - rank(HD) = 6 - 4 = 2.
    a = coopkin_sym.load(planar_hand(2, 2)).analyze()
    assert a.numbers.as_dict() == {"Nm": 4, "Nc": 4, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 2,
                                   "Nh": 0}
    # C11 is the rotation about the line through the two contact points
    tips = [c.point for c in a.model.contacts]
    axis = sp.Matrix(tips[1]) - sp.Matrix(tips[0])
    w = a.C11[3:, 0]
    v = a.C11[:3, 0]
    assert w.cross(axis) == sp.zeros(3, 1)
    assert sp.simplify(v + w.cross(sp.Matrix(tips[0]))) == sp.zeros(3, 1)


def test_planar_two_fingers_two_joints_soft_by_hand():
    # Soft tips add n_i . w = 0 with in-plane inward normals n_i = -u_i (the finger's
    # angular velocity is along z, so it drops out). The rotation about c1 c2 has
    # w parallel to u2 - u1, and u1 . (u2 - u1) = u1 . u2 - 1 != 0: it is stopped.
    # Nm = 0 + 3 = 3 = Nc, Ni = Nr = 0; m = 8, rank Q = 10 - 3 = 7, Nh = 1;
    # rank(HG^T) = 6, Ng = 2; rank(HD) = 4, Nd = 4.  (Like the paper's case study 1.)
    a = coopkin_sym.load(planar_hand(2, 2, tips="soft")).analyze()
    assert a.numbers.as_dict() == {"Nm": 3, "Nc": 3, "Ni": 0, "Nr": 0, "Ng": 2, "Nd": 4,
                                   "Nh": 1}


def test_planar_three_fingers_three_joints_hard_by_hand():
    # Three hard tips at non-collinear points of the plane stop (v_z, w_x, w_y);
    # in the plane each 3R finger has 2 equations and one self-motion: Nr = 3,
    # coordinated = 3 + 9 - 6 = 6 - 3 = 3 (the planar object motions), Nm = 6.
    a = coopkin_sym.load(planar_hand(3, 3)).analyze()
    assert a.numbers.as_dict() == {"Nm": 6, "Nc": 3, "Ni": 0, "Nr": 3, "Ng": 3, "Nd": 3,
                                   "Nh": 0}


# ------------------------------------------------------------- generic (Schwartz-Zippel)

GENERIC = [
    (planar_hand, (2, 2), {}),
    (planar_hand, (2, 2), {"tips": "soft"}),
    (planar_hand, (3, 3), {}),
    (planar_hand, (3, 2), {"palm": True}),
    (spatial_hand, (2, 2), {}),
    (spatial_hand, (3, 3), {"tips": ["hard", "soft", "hard"]}),
    (arm_cell, (2, 3), {"contact": "soft"}),
]
GENERIC_IDS = [f"{f.__name__}{args}{''.join(f'-{k}={v}' for k, v in kw.items())}"
               for f, args, kw in GENERIC]


@pytest.mark.parametrize("case", GENERIC, ids=GENERIC_IDS)
def test_generic_numbers_equal_a_random_point_and_home(case):
    # A rank over Q(t, L) is attained at every point off a proper algebraic set: a
    # random rational point attains it with high probability (Schwartz-Zippel), and
    # the geometry of the builders makes home a generic point too.
    model = build(case)
    system = coopkin_sym.load(model)
    generic = system.analyze(generic=True)
    rng = random.Random(GENERIC_IDS[GENERIC.index(case)])
    at = random_configuration(model, rng, size=97)
    assert system.analyze(at).numbers == generic.numbers
    assert system.analyze().numbers == generic.numbers


@pytest.mark.parametrize("arms", [25, 48, 49, 200, 1000])
def test_a_cell_of_more_than_24_arms_gives_each_arm_its_own_direction(arms):
    """Beyond the 24 directions of the table, rings of turned directions: every arm
    stands and touches the object at its own exact point, its axes exact unit vectors."""
    model = arm_cell(arms, 2, "hard")
    assert len(model["arms"]) == len(model["contacts"]) == arms
    assert len({tuple(c["point"]) for c in model["contacts"]}) == arms
    assert len({tuple(a["joints"][0]["point"]) for a in model["arms"]}) == arms
    assert model["arms"][:24] == arm_cell(24, 2, "hard")["arms"]     # the first ring
    for c in model["contacts"]:
        assert sum(Fraction(x) ** 2 for x in c["normal"]) == 1


def test_a_cell_of_200_arms_has_the_numbers_of_200_arms_holding_one_object():
    """200 six-joint arms, each welded to the object: 1,200 joints, 1,200 constraints;
    rigid (each arm exactly constrained), generic numbers certified by the sizes."""
    a = coopkin_sym.load(arm_cell(200, 6)).analyze(generic=True)
    assert a.numbers.as_dict() == {"Nm": 6, "Nc": 6, "Ni": 0, "Nr": 0, "Ng": 1194,
                                   "Nd": 0, "Nh": 0}
    assert a.certificate.exact
