"""The loop closure as exact polynomials beyond welded loops at rational points: over
the number field of an irrational configuration (Bennett's linkage on its motion),
through hard contacts (three parallel cranks pinned to a coupler: Gruebler 0,
mobility 1) and frictionless ones; checked by hand, along exact motions and by the
independent mpmath sampler."""

from __future__ import annotations

import sys
from pathlib import Path

import flint
import mpmath as mp
import pytest
import sympy as sp

from coopkin_sym import load
from coopkin_sym.analysis.finite import _configuration, _sym
from coopkin_sym.analysis.finite.closure import (
    _germ_dimension,
    _on_pairs,
    closure_dimension,
    closure_polynomials,
)
from coopkin_sym.analysis.finite.constraints import ConstraintMap
from coopkin_sym.analysis.finite.loops import contact_polynomials
from coopkin_sym.exact.numberfield import RealNumberField
from coopkin_sym.exact.realroot import RealRoot
from coopkin_sym.model.configuration import Configuration

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
sys.path.insert(0, str(Path(__file__).resolve().parent))
from finite_sampler import Sampler  # noqa: E402

# Bennett's relation tan(theta1/2) tan(theta2/2) = -5 (the file's header) at
# theta1 = pi/2 + pi/6: tan(theta2/2) = -5/sqrt(3), so q2 = theta2 - 2 atan(-5) has
# tan(q2/2) = (65 sqrt(3) - 70)/311; arm b2 turns as arm b1 (q3 = q1, q4 = q2).
X = "2*atan((65*sqrt(3)-70)/311)"
ON_CURVE = f"q1=pi/6,q2={X},q3=pi/6,q4={X}"

FACE = {"name": "cranks and a face", "planar": True,
        "arms": [{"name": f"a{i}", "joints": [{"name": f"q{i}", "type": "revolute",
                                               "axis": [0, 0, 1], "point": [x, 0, 0]}]}
                 for i, x in ((1, 0), (2, 1), (3, 3))],
        "contacts": [{"name": f"c{i}", "link": f"a{i}/1", "point": [x, 1, 0],
                      "normal": [0, 1, 0], "model": m}
                     for i, x, m in ((1, 0, "hard"), (2, 1, "hard"),
                                     (3, 3, "frictionless"))]}


def _cmap(name, at):
    model = load(name).model
    config, _, point = _configuration(model, at)
    return ConstraintMap(model, config, point=point)


def test_the_bennett_configuration_is_on_its_motion_exactly():
    t1 = sp.tan(sp.pi / 3)                                   # theta1 / 2 = pi/3
    t_q2 = (65 * sp.sqrt(3) - 70) / 311
    t2 = sp.radsimp((t_q2 + -5) / (1 - t_q2 * -5))          # tan((q2 + theta2_0)/2)
    assert sp.radsimp(t1 * t2) == -5


def test_bennett_at_an_irrational_configuration_moves_once_over_q_sqrt3():
    """Before, over a number field the closure was not tried (undecided, 0 to 1)."""
    system = load("bennett-linkage")
    fm = system.finite_mobility(ON_CURVE)
    assert (fm.dimension, fm.bounds, fm.first_order) == (1, (1, 1), 1)
    assert (fm.classification, fm.reason) == ("kinematic_singularity", "closure_bezout")
    assert fm.field["minimal_polynomial"] == "alpha**2 - 4*alpha + 1"
    assert fm.assumptions == ()
    assert system.analyze(ON_CURVE).numbers.as_dict() == system.analyze().numbers.as_dict()
    cmap = _cmap("bennett-linkage", ON_CURVE)
    jac = sp.Matrix([[_sym(x) for x in row] for row in cmap.linear()])
    (v,) = fm.branches[0].tangent
    z = sp.Matrix([x / s for x, s in zip(v, cmap.scale, strict=True)])
    assert [sp.radsimp(e) for e in jac * z] == [0] * 12 and any(x != 0 for x in v)
    s3 = sp.sqrt(3)
    assert [sp.radsimp(a - b) for a, b in zip(v, (12 * s3 / 7, sp.Rational(12, 7),
                                                  sp.Rational(-32, 7), 4 * s3 / 7,
                                                  sp.Rational(4, 7), sp.Rational(20, 7),
                                                  2, sp.Rational(10, 7),
                                                  sp.Rational(10, 7), 2),
                                              strict=True)] == [0] * 10


def test_both_welded_proofs_run_over_the_field():
    """The proof on the paired joints and the one in the whole joint space, each
    with alpha as a variable and its minimal polynomial in the ideal."""
    cmap = _cmap("bennett-linkage", ON_CURVE)
    polys, names = closure_polynomials(cmap)
    field = cmap.point.field
    assert polys[0].context().names() == names + ("alpha",)
    assert _on_pairs(polys, names, 10, field) == (1, "closure_bezout")
    assert _germ_dimension(polys, len(names), 10, field) == (1, "closure_bezout")


def test_a_saturation_over_a_number_field_is_local_at_its_real_point():
    """In Q(sqrt 2): ``z (z - alpha) = 0`` is the plane z = 0 near the origin; ``x z``
    vanishes on it (the saturation holds z - alpha, -sqrt 2 at the origin), and
    ``x^2 - y z`` does not."""
    g = [-2, 0, 1]
    field = RealNumberField(flint.fmpq_poly(g), RealRoot.all_of(g)[1])
    ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "z", "alpha"), "degrevlex")
    x, y, z, a = ctx.gens()
    assert _germ_dimension([z * (z - a), x * z], 3, 30, field) == (2, "closure_saturation")
    assert _germ_dimension([z * (z - a), x * x - y * z], 3, 30, field) is None


def test_parallel_cranks_move_once_though_gruebler_says_they_cannot():
    system = load("parallel-cranks")
    links, pins = 5, 6
    assert 3 * (links - 1) - 2 * pins == 0
    a = system.analyze()
    assert a.numbers.as_dict() == dict(Nm=1, Nc=1, Ni=0, Nr=0, Ng=3, Nd=3, Nh=1)
    assert a.Q.rank() == 5 and system.analyze(generic=True).numbers.Nh == 0
    fm = system.finite_mobility()
    assert (fm.dimension, fm.bounds, fm.first_order) == (1, (1, 1), 1)
    assert (fm.classification, fm.reason) == ("kinematic_singularity", "closure_bezout")
    assert fm.branches[0].tangent == ((-2, 0, 0, 2, 2, 2),)   # the coupler translates
    assert a.Q * sp.Matrix(fm.branches[0].tangent[0]) == sp.zeros(6, 1)
    turned = system.finite_mobility("q1=pi/3,q2=pi/3,q3=pi/3")      # over Q(sqrt 3)
    assert (turned.dimension, turned.reason) == (1, "closure_bezout")
    assert [sp.radsimp(x - y) for x, y in zip(turned.branches[0].tangent[0],
                                              (-1, -sp.sqrt(3), 0, 2, 2, 2),
                                              strict=True)] == [0] * 6


def test_the_expansion_alone_cannot_decide_the_cranks():
    from coopkin_sym.analysis.finite import _decide_singular
    from coopkin_sym.analysis.finite.reduce import reduce_map

    cmap = _cmap("parallel-cranks", None)
    red = reduce_map(cmap, 4)
    assert all(g.is_zero() for g in red.g)
    assert _decide_singular(cmap, red)["reason"] == "undecided_at_order_4"


def _curve_residual(name, q_of_t, obj_of_t, q0=None):
    """The largest closure residual of the independent sampler (world frame, mpmath)
    at points of an exact motion from ``q0`` (radians)."""
    model = load(name).model
    sampler = Sampler(model, q0 or {}, {p.name: 1 for p in model.parameters})
    worst = mp.mpf(0)
    for t in (mp.mpf(1) / 7, mp.mpf(-2) / 5):
        x = obj_of_t(t) + q_of_t(t)
        worst = max(worst, max(abs(r) for r in sampler.closure(x)))
    return worst


def test_the_motions_proved_are_motions_of_the_independent_closure():
    """Along the motions the closure proofs claim (the cranks turning together, the
    object translating with their tips; case 1's object turning about the pin on
    joint 1's axis), the sampler's closure residuals vanish to 50 digits, and they do
    not along a motion that is not one (the first crank alone)."""
    def tip(t):                     # the crank tip's displacement for a turn t
        return [-mp.sin(t), mp.cos(t) - 1, 0]
    assert _curve_residual("parallel-cranks", lambda t: [t, t, t],
                           lambda t: tip(t)) < mp.mpf(10) ** -50
    assert _curve_residual("parallel-cranks", lambda t: [t, 0, 0],
                           lambda t: tip(t)) > mp.mpf(10) ** -3
    assert _curve_residual("paper-case1-complete-hard", lambda t: [t, 0],
                           lambda t: [0, 0, 0, 0, 0, t],
                           {"q1": 0, "q2": mp.pi / 2}) < mp.mpf(10) ** -50


def test_contact_polynomials_vanish_along_exact_motions_for_each_contact_model():
    """Exactly, in t = tan(dq/2): the hard cranks (p eliminated through the first pin:
    variables w3 and the joints), the frictionless face (crank 3's tip on the coupler's
    flat face: it moves with the parallelogram, or mirrored), the welded Bennett loop
    (the closure polynomials of its two arms)."""
    tctx = flint.fmpq_mpoly_ctx.get(("t",), "degrevlex")
    (t,) = tctx.gens()
    zero = tctx.constant(0)

    def along(polys, values):
        return [p.compose(*values, ctx=tctx) for p in polys]
    polys, names = contact_polynomials(_cmap("parallel-cranks", None))
    assert names == ("w3", "u_q1", "u_q2", "u_q3") and len(polys) == 4
    assert all(p.is_zero() for p in along(polys, [zero, t, t, t]))
    assert not all(p.is_zero() for p in along(polys, [zero, t, zero, zero]))
    face = load(FACE)
    polys, names = contact_polynomials(ConstraintMap(face.model, Configuration.parse(
        face.model, None)))
    assert names == ("w3", "u_q1", "u_q2", "u_q3") and len(polys) == 3
    for mirror in (t, -t):
        assert all(p.is_zero() for p in along(polys, [zero, t, t, mirror]))
    assert not all(p.is_zero() for p in along(polys, [zero, t, t, 2 * t]))
    assert face.finite_mobility().classification == "bifurcation"
    polys, names = closure_polynomials(_cmap("bennett-linkage", None))
    assert len(polys) == 7 and len(names) == 4


def test_the_closure_needs_its_dimension_to_be_the_first_order_one():
    """At a shaky configuration the closure proves nothing (its manifold of the
    independent conditions has the first-order dimension, the system does not)."""
    cmap = _cmap("shaky-pinned-bars", None)
    assert closure_dimension(cmap, 1) is None


@pytest.mark.slow
@pytest.mark.parametrize(("name", "at", "samples"), [
    ("bennett-linkage", {"q1": "pi/6", "q2": X, "q3": "pi/6", "q4": X}, 6),
    ("parallel-cranks", {"q1": "0", "q2": "0", "q3": "0"}, 6),
])
def test_the_sampler_sees_one_motion(name, at, samples):
    system = load(name)
    q0 = {k: mp.mpf(str(sp.N(sp.sympify(v), 70))) for k, v in at.items()}
    sampler = Sampler(system.model, q0, {})
    assert sampler.dimension(samples) == 1
    assert system.finite_mobility(",".join(f"{k}={v}" for k, v in at.items())).dimension == 1


def test_with_faces_only_the_object_stays_and_the_rows_are_those_of_q():
    """Frictionless contacts only: nothing carries the object's motion, so the
    polynomials keep p and w, and their linear parts span the rows of J = -Q S."""
    faces = dict(FACE, contacts=[dict(c, model="frictionless") for c in FACE["contacts"]])
    model = load(faces).model
    cmap = ConstraintMap(model, Configuration.parse(model, "q1=2*atan(1/2)"))
    polys, names = contact_polynomials(cmap)
    assert names == cmap.names == ("p1", "p2", "w3", "u_q1", "u_q2", "u_q3")
    n = len(names)
    linear = [[p.to_dict().get(tuple(int(i == k) for i in range(n)), 0) for k in range(n)]
              for p in polys]
    jac = [[flint.fmpq(x) for x in row] for row in cmap.linear()]
    both = flint.fmpq_mat(len(linear) + len(jac), n, [x for r in linear + jac for x in r])
    assert flint.fmpq_mat(3, n, [x for r in linear for x in r]).rank() == 3 == both.rank()


def _random(seed):
    from random_systems import random_system

    return load(random_system(seed))


# two planar arms welded to one object, seen in space: at these points of their loci
# the out-of-plane rows of the constraint map vanish to every order (they hold
# identically), which blocked the expansion before (undecided, 0 to 1)
PLANAR_IN_SPACE = [(0, "q1=-11/5,q2=2*atan(-1/3),q3=2*atan(2),q4=3"),
                   (32, "q1=2,q2=2*atan(-1/3),q3=pi/2,q4=2*atan(3)")]


@pytest.mark.parametrize(("seed", "at"), PLANAR_IN_SPACE)
def test_the_closure_expansion_leaves_out_what_holds_identically(seed, at):
    system = _random(seed)
    fm = system.finite_mobility(at)
    assert (fm.dimension, fm.bounds, fm.first_order) == (1, (1, 1), 2)
    assert (fm.classification, fm.reason) == ("bifurcation", "cone_regular_points")
    assert "closure_expansion" in fm.assumptions and len(fm.equations) == 1
    q = system.analyze(at).Q
    spans = []
    for branch in fm.branches:
        (v,) = branch.tangent
        assert [sp.radsimp(sp.expand(e)) for e in q * sp.Matrix(v)] == [0] * q.rows
        spans.append(v)
    assert sp.Matrix(spans).rank(simplify=True) == 2          # two distinct branches


def test_the_closure_map_expands_like_the_constraint_map_where_both_decide():
    """The folded four-bar through the closure's polynomials: the same bifurcation,
    with the same exact tangents once written back as velocities (u, qdot)."""
    from coopkin_sym.analysis.finite import _decide_singular
    from coopkin_sym.analysis.finite.closure_map import closure_map
    from coopkin_sym.analysis.finite.reduce import reduce_map

    cmap = _cmap("four-bar", "q1=-pi/2,q2=-pi/2")
    closed = closure_map(cmap)
    assert closed.names == ("w3", "u_q1", "u_q2")
    found = _decide_singular(closed, reduce_map(closed, 2))
    assert (found["dimension"], found["classification"]) == (1, "bifurcation")
    assert {b.tangent for b in found["branches"]} == {
        ((0, 2, 0, 2, 2),), ((0, -2, sp.Rational(4, 3), sp.Rational(-2, 3), 2),)}


@pytest.mark.slow
@pytest.mark.parametrize(("seed", "at"), PLANAR_IN_SPACE)
def test_the_sampler_sees_the_closure_expansions_branches(seed, at):
    """60-digit mpmath: the same local dimension, and started a small step along
    each branch's exact tangent, the projection onto the closure stays along it."""
    system = _random(seed)
    values = dict(item.split("=") for item in at.split(","))
    q0 = {k: mp.mpf(str(sp.N(sp.sympify(v), 70))) for k, v in values.items()}
    sampler = Sampler(system.model, q0, {})
    fm = system.finite_mobility(at)
    assert sampler.dimension(6) == fm.dimension == 1
    units = []
    for branch in fm.branches:
        v = [mp.mpf(str(sp.N(x, 70))) for x in branch.tangent[0]]
        norm = mp.sqrt(sum(c * c for c in v))
        units.append([c / norm for c in v])
    for k, u in enumerate(units):
        point = sampler.project([mp.mpf(10) ** -4 * c for c in u])
        size = mp.sqrt(sum(c * c for c in point))
        along = [c / size for c in point]
        off = [min(mp.sqrt(sum((a - b) ** 2 for a, b in zip(along, w, strict=True))),
                   mp.sqrt(sum((a + b) ** 2 for a, b in zip(along, w, strict=True))))
               for w in units]
        assert off[k] < mp.mpf(10) ** -3 and all(o > mp.mpf(10) ** -2 for i, o in
                                                  enumerate(off) if i != k), off
