"""The shipped underactuated finger (``underactuated-finger``: a two-phalanx finger
with a passive distal joint, touching the object with both phalanges, and a one-link
thumb with a frictionless pad): its numbers at home and where the distal phalanx lines
up with the proximal one, and its passive-joint numbers and subspaces against a
computation from ``Q`` alone (SymPy ranks and nullspaces of its column blocks)."""

from __future__ import annotations

import random
from fractions import Fraction

import pytest
import sympy as sp

import coopkin_sym

HOME = {"Nm": 1, "Nc": 1, "Ni": 0, "Nr": 0, "Ng": 2, "Nd": 2, "Nh": 0}
HOME_PASSIVE = {"Na": 2, "Np": 1, "Nco": 1, "Nuo": 0, "Npi": 0, "Nar": 0, "Nam": 1}
#: the distal phalanx in line with the proximal one: the triangle (inner contact,
#: distal joint, tip) is flat and the object may also turn about the inner contact
LINED_UP = {"Nm": 2, "Nc": 2, "Ni": 0, "Nr": 0, "Ng": 2, "Nd": 2, "Nh": 1}


@pytest.fixture(scope="module")
def finger():
    return coopkin_sym.load("underactuated-finger")


def from_q(a) -> dict:
    """The passive-joint numbers from ``Q = [object | joints]`` alone: ``Nuo`` the
    object part of ``N([Q_object | Q_passive])``, ``Npi = dim N(Q_passive)``,
    ``Nco = Nc - Nuo``, ``Nar = Nr - Npi``; ``Nam`` both as ``Nco + Nar`` and as the
    rank of the motor part of ``N(Q)``."""
    q = sp.Matrix(a.Q)
    d = q.cols - len(a.model.joints)
    rows = list(range(q.rows))
    act = [d + k for k, j in enumerate(a.model.joints) if j.actuated]
    pas = [d + k for k, j in enumerate(a.model.joints) if not j.actuated]

    def rank(cols):
        return q.extract(rows, cols).rank() if cols else 0

    def span(vectors, part):
        return sp.Matrix.hstack(*[v.extract(part, [0]) for v in vectors]).rank() \
            if vectors else 0

    r = len(act) + len(pas)
    nm = d + r - q.rank()
    nr = r - rank(act + pas)
    nc = nm - nr
    nuo = span(q.extract(rows, list(range(d)) + pas).nullspace(), list(range(d)))
    npi = len(pas) - rank(pas)
    nam = span(q.nullspace(), act)
    assert nam == nc - nuo + nr - npi
    return {"Na": len(act), "Np": len(pas), "Nco": nc - nuo, "Nuo": nuo, "Npi": npi,
            "Nar": nr - npi, "Nam": nam}


def test_home_by_hand(finger):
    """The object turns with the proximal phalanx about the base, the thumb at the same
    rate (its pad slides): ``u = (0, 0, 1)``, ``qdot = (1, 0, 1)``."""
    a = finger.analyze()
    assert a.numbers.as_dict() == HOME
    assert a.C.rank() == 1 and (a.Q * sp.Matrix([0, 0, 1, 1, 0, 1])).is_zero_matrix
    p = a.passive
    assert p.actuated == ("q1", "q3") and p.passive == ("q2",)
    assert p.numbers.as_dict() == HOME_PASSIVE
    assert p.controlled == sp.Matrix([0, 0, 1]) and p.uncontrolled.shape == (3, 0)
    assert p.internal.shape == (3, 0) and p.actuated_redundant.shape == (2, 0)
    generic = finger.analyze(generic=True)
    assert generic.numbers.as_dict() == HOME
    assert generic.passive.numbers.as_dict() == HOME_PASSIVE


def test_straight_finger_frees_a_turn_about_the_inner_contact(finger):
    """At q2 = pi/2 (finger straight) with the thumb's pad normal through the inner
    contact (0, L): with the motors still the object turns about (0, L), the distal
    joint at twice its rate, and the pad slides along its face."""
    a = finger.analyze("q2=pi/2")
    assert a.numbers.as_dict() == LINED_UP
    p = a.passive
    assert p.numbers.as_dict() == {"Na": 2, "Np": 1, "Nco": 1, "Nuo": 1, "Npi": 0,
                                   "Nar": 0, "Nam": 1}
    L = a.model.parameters[0]
    assert p.uncontrolled == sp.Matrix([L, 0, 1])          # the spin about (0, L)
    # the spin about the inner contact with q2' = 2, the motors still, keeps Q = 0
    assert (a.Q * sp.Matrix([L, 0, 1, 0, 2, 0])).is_zero_matrix


def test_straight_finger_elsewhere_both_motions_controlled(finger):
    a = finger.analyze("q1=2*atan(1/2),q2=pi/2,L=1")
    assert a.numbers.as_dict() == LINED_UP
    assert a.passive.numbers.as_dict() == {"Na": 2, "Np": 1, "Nco": 2, "Nuo": 0,
                                           "Npi": 0, "Nar": 0, "Nam": 2}


def test_folded_finger_tip_on_the_inner_contact(finger):
    a = finger.analyze("q2=-pi/2,L=1")
    assert a.numbers.as_dict() == dict(LINED_UP, Ni=1, Ng=3)
    assert a.passive.numbers.as_dict() == {"Na": 2, "Np": 1, "Nco": 1, "Nuo": 1,
                                           "Npi": 0, "Nar": 0, "Nam": 1}


def _angle(t: Fraction) -> str:
    return f"2*atan({t})"


def _points():
    rng = random.Random(20240611)

    def t():
        return Fraction(rng.randint(-9, 9), rng.randint(1, 6))

    for _ in range(6):
        yield f"q1={_angle(t())},q2={_angle(t())},q3={_angle(t())},L={rng.randint(1, 5)}"
    for q2 in ("pi/2", "-pi/2"):
        yield f"q1=0,q2={q2},q3=0"
        for _ in range(2):
            yield f"q1={_angle(t())},q2={q2},q3={_angle(t())},L={t() ** 2 + 1}"
        # the pad's normal through the inner contact: 2 t1^2 t3 - t1^2 + 2 t1 t3 - t3^2
        # + 2 t3 = 0 (from the locus), e.g. t1 = -3/4, t3 = 1/2
        yield f"q1=2*atan(-3/4),q2={q2},q3=2*atan(1/2),L=3"


@pytest.mark.parametrize("at", list(_points()))
def test_passive_numbers_against_q(finger, at):
    a = finger.analyze(at)
    p = a.passive
    assert p.numbers.as_dict() == from_q(a), at
    n = a.numbers
    assert p.numbers.Nco + p.numbers.Nuo == n.Nc and p.numbers.Npi + p.numbers.Nar == n.Nr
    # the uncontrolled twists: exactly the object part of N([Q_object | Q_passive])
    q = sp.Matrix(a.Q)
    pas = [3 + k for k, j in enumerate(a.model.joints) if not j.actuated]
    lock = q.extract(list(range(q.rows)), [0, 1, 2] + pas).nullspace()
    free = [v[:3, :] for v in lock]
    if p.uncontrolled.cols:
        both = p.uncontrolled.row_join(sp.Matrix.hstack(*free))
        assert both.rank() == p.uncontrolled.rank() == p.uncontrolled.cols
    # controlled and uncontrolled together: every object motion the contacts allow
    moving = sp.Matrix.hstack(*[v[:3, :] for v in q.nullspace()])
    both = p.controlled.row_join(p.uncontrolled)
    assert both.rank() == both.cols == n.Nc == both.row_join(moving).rank()


def test_lined_up_families_on_the_locus(finger):
    """With the thumb at home and the two finger joints free, the numbers change on
    q2 = +-pi/2 only, and with the motors held still (the locked locus) only at
    q1 = 0 there, where Nuo = Nc of the locked system goes from 0 to 1."""
    locus = finger.locus(free=["q1", "q2"])
    assert locus.generic == HOME
    conditions = [c.condition.text for c in locus.components]
    assert "q2 = pi/2" in conditions and "q2 = -pi/2" in conditions
    for c in locus.components:
        assert c.numbers["Nm"] == 2
    assert locus.locked is not None and locus.locked.generic["Nc"] == 0
    locked = {c.condition.text: c.numbers for c in locus.locked.components}
    assert set(locked) == {"q1 = 0, q2 = -pi/2", "q1 = 0, q2 = pi/2"}
    assert all(n["Nc"] == 1 for n in locked.values())
