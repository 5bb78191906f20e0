"""Bennett's and Bricard's linkages: overconstrained loops that move.

Grübler-Kutzbach says they cannot (-2 and 0 motions); the package's exact finite
mobility says 1, and an independent numerical projection onto the loop closure,
written here from the published geometry alone (mpmath, 50 digits), finds a
one-dimensional set of closed configurations around the shipped one.
"""

from __future__ import annotations

import random
import time

import mpmath as mp
import pytest
import sympy as sp

from coopkin_sym import load
from coopkin_sym.analysis.finite.closure import closure_polynomials
from coopkin_sym.analysis.finite.constraints import ConstraintMap
from coopkin_sym.model.configuration import Configuration

# --- the geometry, typed from the files' comments ------------------------------------
A1, A2 = 4, 3
ALPHA1, ALPHA2 = 2 * sp.atan(sp.Rational(1, 2)), 2 * sp.atan(sp.Rational(1, 3))
THETA = [sp.pi / 2, 2 * sp.atan(-5), -sp.pi / 2, 2 * sp.atan(5)]       # theta1..theta4
BRICARD = [((2, 0, 0), (0, sp.Rational(3, 5), sp.Rational(4, 5))),
           ((1, 2, 1), (sp.Rational(2, 3), sp.Rational(1, 3), sp.Rational(2, 3))),
           ((-1, 1, 3), (sp.Rational(2, 7), sp.Rational(-3, 7), sp.Rational(6, 7)))]
BRICARD += [((-p[0], -p[1], p[2]), (-d[0], -d[1], d[2])) for p, d in BRICARD]


def _dh(theta, a, alpha, lib=sp):
    c, s, ca, sa = lib.cos(theta), lib.sin(theta), lib.cos(alpha), lib.sin(alpha)
    return lib.matrix([[c, -s * ca, s * sa, a * c], [s, c * ca, -c * sa, a * s],
                       [0, sa, ca, 0], [0, 0, 0, 1]]) if lib is mp else sp.Matrix(
        [[c, -s * ca, s * sa, a * c], [s, c * ca, -c * sa, a * s], [0, sa, ca, 0],
         [0, 0, 0, 1]])


def _bennett_loop(thetas, lib=sp):
    links = [(A1, ALPHA1), (A2, ALPHA2), (A1, ALPHA1), (A2, ALPHA2)]
    out = sp.eye(4) if lib is sp else mp.eye(4)
    for th, (a, al) in zip(thetas, links, strict=True):
        out = out * _dh(th, a, mp.mpf(sp.N(al, 60)) if lib is mp else al, lib)
    return out


def _screw(point, axis, angle):
    """The rotation by ``angle`` about the line (``point``, unit ``axis``), 4 x 4, mpmath."""
    k = mp.matrix([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    r = mp.eye(3) + mp.sin(angle) * k + (1 - mp.cos(angle)) * k * k
    p = mp.matrix(point)
    t = p - r * p
    out = mp.eye(4)
    for i in range(3):
        for j in range(3):
            out[i, j] = r[i, j]
        out[i, 3] = t[i]
    return out


def _bricard_loop(dq):
    """The motion of the loop q1..q6 turned by ``dq`` about the lines at home (the
    product of the six screws in loop order is the identity exactly when it closes)."""
    out = mp.eye(4)
    for (point, axis), angle in zip(BRICARD, dq, strict=True):
        out = out * _screw([mp.mpf(sp.Rational(x).p) / sp.Rational(x).q for x in point],
                           [mp.mpf(sp.Rational(x).p) / sp.Rational(x).q for x in axis],
                           angle)
    return out


def _residual(loop, x):
    m = loop(x)
    return mp.matrix([m[i, j] - (1 if i == j else 0) for i in range(3) for j in range(4)])


def _jacobian(loop, x):
    h = mp.mpf(10) ** -30
    f0 = _residual(loop, x)
    cols = []
    for k in range(len(x)):
        y = list(x)
        y[k] += h
        cols.append((_residual(loop, y) - f0) / h)
    return mp.matrix([[cols[k][i] for k in range(len(x))] for i in range(len(f0))])


def _project(loop, x):
    """Gauss-Newton with the pseudo-inverse onto the closure ``loop(x) = I``."""
    for _ in range(60):
        f = _residual(loop, x)
        if mp.norm(f) < mp.mpf(10) ** -40:
            return x
        u, s, v = mp.svd_r(_jacobian(loop, x))
        step = [mp.mpf(0)] * len(x)
        for k in range(len(s)):
            if s[k] > mp.mpf(10) ** -20 * s[0]:
                coef = sum(u[i, k] * f[i] for i in range(len(f))) / s[k]
                for j in range(len(x)):
                    step[j] += coef * v[k, j]
        x = [a - b for a, b in zip(x, step, strict=True)]
    raise AssertionError("no convergence")


def _spread_rank(loop, x0, samples=8):
    """The numerical rank of the displacements of projected random perturbations, and
    the corank of the closure's Jacobian at them (both are the local dimension at
    smooth points)."""
    rng = random.Random(1903)
    radius = mp.mpf(10) ** -4
    points = []
    for _ in range(samples):
        x = [a + radius * mp.mpf(rng.uniform(-1, 1)) for a in x0]
        points.append(_project(loop, x))
    d = mp.matrix([[p[j] - x0[j] for j in range(len(x0))] for p in points])
    s = mp.svd_r(d, compute_uv=False)
    spread = sum(1 for x in s if x > mp.mpf(10) ** -2 * s[0])
    sj = mp.svd_r(_jacobian(loop, points[0]), compute_uv=False)
    corank = len(x0) - sum(1 for x in sj if x > mp.mpf(10) ** -15 * sj[0])
    return spread, corank, max(max(abs(a - b) for a, b in zip(p, x0, strict=True))
                               for p in points)


@pytest.fixture(autouse=True)
def _digits():
    old = mp.mp.dps
    mp.mp.dps = 50
    yield
    mp.mp.dps = old


# --- the tests -------------------------------------------------------------------------
def test_the_bennett_geometry_closes_exactly_and_obeys_bennetts_conditions():
    assert sp.simplify(_bennett_loop(THETA)) == sp.eye(4)
    def exact(x):
        return sp.radsimp(sp.simplify(sp.expand_trig(x)))
    assert exact(sp.sin(ALPHA1)) == sp.Rational(4, 5)
    assert exact(sp.sin(ALPHA2)) == sp.Rational(3, 5)
    assert A1 / exact(sp.sin(ALPHA1)) == A2 / exact(sp.sin(ALPHA2)) == 5
    ratio = sp.sin((ALPHA2 + ALPHA1) / 2) / sp.sin((ALPHA2 - ALPHA1) / 2)
    assert exact(ratio) == -5
    assert exact(sp.tan(THETA[0] / 2) * sp.tan(THETA[1] / 2)) == -5
    model = load("bennett-linkage").model
    points = ConstraintMap(model, Configuration.parse(model, None)).contact_points()
    assert points[0] == points[1]


def test_the_bricard_axes_are_line_symmetric_and_meet_the_file():
    model = load("bricard-linkage").model
    order = ["q1", "q2", "q3", "q4", "q5", "q6"]
    joints = {j.name: j for j in model.joints}
    for name, (point, axis) in zip(order, BRICARD, strict=True):
        assert tuple(joints[name].axis) == tuple(sp.Rational(x) for x in axis)
        assert tuple(joints[name].point) == tuple(sp.Rational(x) for x in point)
    assert _residual(_bricard_loop, [mp.mpf(0)] * 6) == mp.matrix(12, 1)


@pytest.mark.parametrize(("name", "numbers", "rank_q", "gruebler"), [
    ("bennett-linkage", dict(Nm=1, Nc=1, Ni=0, Nr=0, Ng=6, Nd=8, Nh=3), 9, -2),
    ("bricard-linkage", dict(Nm=1, Nc=1, Ni=0, Nr=0, Ng=6, Nd=6, Nh=1), 11, 0)])
def test_the_overconstrained_loops_move_once(name, numbers, rank_q, gruebler):
    system = load(name)
    joints = len(system.model.joints)
    # the loop: the ground, the object and the arms' inner links, one joint between each
    assert 6 * (joints - 1) - 5 * joints == gruebler
    a = system.analyze()
    assert a.numbers.as_dict() == numbers
    assert a.Q.rank() == rank_q and a.Q.rows == 12 and a.Q.cols == 6 + joints
    start = time.perf_counter()
    fm = system.finite_mobility()
    assert time.perf_counter() - start < 10
    assert (fm.dimension, fm.bounds, fm.first_order) == (1, (1, 1), 1)
    assert (fm.classification, fm.reason) == ("kinematic_singularity", "closure_bezout")
    (branch,) = fm.branches
    (v,) = branch.tangent
    assert a.Q * sp.Matrix(v) == sp.zeros(12, 1) and any(x != 0 for x in v)
    assert fm.dimension > gruebler


def test_the_bennett_tangent_is_exact():
    fm = load("bennett-linkage").finite_mobility()
    R = sp.Rational
    assert fm.branches[0].tangent == ((R(24, 13), 0, R(-32, 13), R(8, 13), 0, R(32, 13),
                                       2, R(10, 13), R(10, 13), 2),)


def test_closure_polynomials_vanish_at_the_configuration_only_to_first_order():
    model = load("bricard-linkage").model
    polys, names = closure_polynomials(ConstraintMap(model, Configuration.parse(model, None)))
    assert names == ("v_q1", "v_q2", "v_q3", "v_q6", "v_q5", "v_q4")
    assert all(p.to_dict().get((0,) * 6, 0) == 0 for p in polys) and len(polys) == 7


def test_the_expansion_alone_stays_undecided_there():
    """What the saturation adds: to order 4 every first-order motion extends."""
    from coopkin_sym.analysis.finite import _decide_singular
    from coopkin_sym.analysis.finite.reduce import reduce_map

    for name in ("bennett-linkage", "bricard-linkage"):
        model = load(name).model
        cmap = ConstraintMap(model, Configuration.parse(model, None))
        red = reduce_map(cmap, 4)
        assert all(g.is_zero() for g in red.g)
        assert _decide_singular(cmap, red)["reason"] == "undecided_at_order_4"


@pytest.mark.parametrize("name", ["bennett-linkage", "bricard-linkage"])
def test_a_numerical_projection_finds_a_curve_of_closed_configurations(name):
    """Independent of the package: random perturbations of the joint angles projected
    onto the closure spread along one direction, and the closure's Jacobian at them has
    corank 1 (Grübler's count would give none)."""
    if name == "bennett-linkage":
        x0 = [mp.mpf(sp.N(t, 60)) for t in THETA]
        loop = _bennett_loop_mp
    else:
        x0 = [mp.mpf(0)] * 6
        loop = _bricard_loop
    spread, corank, moved = _spread_rank(loop, x0)
    assert spread == 1 and corank == 1
    assert moved > mp.mpf(10) ** -5           # the points left the configuration


def _bennett_loop_mp(x):
    return _bennett_loop(x, mp)


def test_the_germ_proof_is_local_and_refuses_what_does_not_vanish():
    """``y (y - 1) = 0`` is the line ``y = 0`` near the origin (and ``y = 1`` away):
    ``x y`` vanishes on the germ though not on all of it, ``x^3`` does not, and a
    dependent polynomial ``(y - x^2) (y - 1)`` of ``y - x^2`` does."""
    import flint

    from coopkin_sym.analysis.finite.closure import _germ_dimension

    ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "degrevlex")
    x, y = ctx.gens()
    assert _germ_dimension([y * (y - 1), x * y], 2, 10) == (1, "closure_bezout")
    assert _germ_dimension([y * (y - 1), x ** 3], 2, 10) is None
    assert _germ_dimension([y - x ** 2, (y - x ** 2) * (y - 1)], 2, 10) == (1,
                                                                            "closure_bezout")
    assert _germ_dimension([y - x ** 2, x * y], 2, 10) is None


def test_the_germ_proof_by_saturation_on_a_surface():
    """Two free directions (no Bezout bound for curves): ``z (z - 1) = 0`` is the plane
    ``z = 0`` near the origin; ``x z`` vanishes there (an exact saturation finds
    ``z - 1``, nonzero at the origin), ``x^2 - y z`` does not."""
    import flint

    from coopkin_sym.analysis.finite.closure import _germ_dimension

    ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "z"), "degrevlex")
    x, y, z = ctx.gens()
    assert _germ_dimension([z * (z - 1), x * z], 3, 30) == (2, "closure_saturation")
    assert _germ_dimension([z * (z - 1), x * x - y * z], 3, 30) is None


def test_the_command_words_the_proof():
    from typer.testing import CliRunner

    from coopkin_sym.cli import app

    out = CliRunner().invoke(app, ["analyze", "bennett-linkage", "--finite"])
    assert out.exit_code == 0, out.output
    assert ("  Proof: the loop is overconstrained: the closure conditions that are "
            "independent here cut out a smooth curve, and each dependent one vanishes along "
            "it to an order above Bezout's bound (the product of the degrees), so on all of "
            "it; the configuration space is that curve here (exact power series).\n"
            ) in out.stdout
    data = CliRunner().invoke(app, ["analyze", "bricard-linkage", "--finite", "--json"])
    assert '"reason": "closure_bezout"' in data.stdout
