"""The manipulability ellipsoid, checked against an independent computation from the
nullspace of ``Q`` alone (SymPy, over the rationals): with ``(u, qdot) = K z`` every
motion that keeps the contacts, the driven object motions modulo the indeterminate
ones are ``P W K_u z`` and the ellipsoid of those with ``|K_q z| <= 1`` has the shape
``M (K_q^T K_q)^+ M^T``, ``M = S P W K_u``."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from test_planar import at_text, random_planar_system, random_point

import coopkin_sym
from coopkin_sym.errors import ManipulabilityError


def shape_from_kernel(a, controlled, length) -> sp.Matrix:
    names = a.model.twist_names
    d = a.model.object_dim
    kernel = a.Q.nullspace()
    if not kernel:
        return sp.zeros(len(controlled), len(controlled))
    k = sp.Matrix.hstack(*kernel)
    ku, kq = k[:d, :], k[d:, :]
    w = sp.diag(*[1 if n.startswith("v") else sp.sympify(length) for n in names])
    # the indeterminate motions: u with (u, 0) in N(Q)
    free = [v[:d, 0] for v in a.Q[:, :d].nullspace()]
    p = sp.eye(d)
    if free:
        f = w * sp.Matrix.hstack(*free)
        p = sp.eye(d) - f * (f.T * f).inv() * f.T
    rows = [names.index(c) for c in controlled]
    m = (p * w * ku).extract(rows, list(range(ku.cols)))
    return (m * (kq.T * kq).pinv() * m.T).applyfunc(sp.nsimplify)


@pytest.mark.parametrize("seed", range(1, 30, 2))
def test_planar_random_systems_against_the_kernel(seed):
    raw = random_planar_system(seed)
    system = coopkin_sym.load(raw)
    rng = random.Random(seed)
    for special in (False, True):
        a = system.analyze(at_text(raw, random_point(raw, rng, special)))
        for controlled, length in ((None, 1), (("v_x", "w_z"), "3/2"), (("v_y",), 2)):
            m = a.manipulability(controlled, length)
            names = controlled or a.model.twist_names
            assert m.shape == shape_from_kernel(a, names, length)
            assert m.rank == m.shape.rank()
            assert m.index == m.shape.det()


@pytest.mark.parametrize("name, at", [
    ("paper-case1-hard", "L=1"), ("paper-case1-soft", "L=2"),
    ("paper-case2-hard", "L=1"), ("paper-case2-complete", "L=1"),
    ("dh-two-puma560-box", "p1_2=2*atan(1/3),p2_3=2*atan(1/2)"),
])
def test_spatial_examples_against_the_kernel(name, at):
    a = coopkin_sym.load(name).analyze(at)
    for controlled in (None, ("v_x", "v_y", "v_z"), ("w_x", "w_y", "w_z")):
        names = controlled or a.model.twist_names
        assert a.manipulability(controlled, 2).shape == shape_from_kernel(a, names, 2)


def test_least_joint_speed_of_each_coordinated_motion():
    a = coopkin_sym.load("paper-case2-hard").analyze("L=1")
    m = a.manipulability()
    for k in range(a.C12.cols):
        x = sp.Matrix([1 if i == k else 0 for i in range(a.C12.cols)])
        qdot = a.C22 * x
        if a.C23.cols:   # remove the redundant part: the least-norm joint rates
            y = -(a.C23.T * a.C23).inv() * a.C23.T * qdot
            qdot = qdot + a.C23 * y
        assert (x.T * m.form * x)[0] == (qdot.T * qdot)[0]


def test_paper_case1_ellipsoid_is_a_segment():
    m = coopkin_sym.load("paper-case1-hard").analyze().manipulability(["v_x", "v_y"])
    L = sp.Symbol("L", positive=True)
    # one driven motion: translation along x, L/sqrt(2) at unit joint speed
    assert m.shape == sp.Matrix([[L**2 / 2, 0], [0, 0]]) and m.rank == 1 and m.index == 0


def test_degeneracy_locus_is_where_a_finger_lines_up():
    m = coopkin_sym.load("planar-two-fingers").analyze(free=["q2"]).manipulability(
        length="L")
    t = sp.Symbol("t_q2", real=True)
    assert set(m.degeneracy) == {t - 1, t + 1}          # q2 = pi/2, q2 = -pi/2
    assert m.rank == 3
    at_singular = coopkin_sym.load("planar-two-fingers").analyze("q2=pi/2,L=1")
    assert at_singular.manipulability(length=1).rank == 2


@pytest.mark.parametrize("controlled, length, fragment", [
    (["v_w"], 1, "unknown object motion 'v_w'"),
    (["v_x", "v_x"], 1, "named twice"),
    ([], 1, "non-empty list"),
    ("v_x", 1, "non-empty list"),
    (None, -1, "positive length"),
    (None, "L**2 - 5", "positive length"),
    (None, "__import__('os')", "length"),
])
def test_bad_requests_are_refused(controlled, length, fragment):
    a = coopkin_sym.load("paper-case1-hard").analyze("L=1")
    with pytest.raises(ManipulabilityError, match=fragment.replace("(", r"\(")):
        a.manipulability(controlled, length)


def _shifted(a, point) -> sp.Matrix:
    """Q with its object columns written for (velocity of ``point``, w)."""
    d = a.model.object_dim
    px, py, pz = point
    if d == 3:   # u = (v_p - w x p, w): v_x = v_px + w_z p_y, v_y = v_py - w_z p_x
        back = sp.Matrix([[1, 0, py], [0, 1, -px], [0, 0, 1]])
    else:
        p = sp.Matrix(point)
        skew = sp.Matrix([[0, -p[2], p[1]], [p[2], 0, -p[0]], [-p[1], p[0], 0]])
        back = sp.Matrix(sp.BlockMatrix([[sp.eye(3), skew], [sp.zeros(3), sp.eye(3)]]))
    q = sp.Matrix(a.Q)
    q[:, :d] = a.Q[:, :d] * back
    return q


@pytest.mark.parametrize("name, at, point", [
    ("planar-two-fingers", "q1=2*atan(1/4),q2=-2*atan(1/2),q3=-2*atan(1/4),q4=2*atan(1/2),L=1",
     ("1/3", "1/2", 0)),
    ("paper-case2-hard", "L=1", (2, 1, 1)),
])
def test_velocity_of_an_object_point(name, at, point):
    a = coopkin_sym.load(name).analyze(at)

    class Shifted:   # the same analysis with twists written at ``point``
        model = a.model
        Q = _shifted(a, [sp.Rational(x) for x in point])

    names = tuple(n for n in a.model.twist_names if n.startswith("v"))
    expected = shape_from_kernel(Shifted, names, 1)
    assert a.manipulability(names, point=point).shape == expected
    assert a.manipulability(names).shape != expected


def test_ellipsoid_is_drawn_with_its_scale(tmp_path):
    from coopkin_sym.present.draw import draw_system
    fig = draw_system(coopkin_sym.load("paper-case2-hard"), ellipsoid=True)
    title = fig.axes[0].get_title()
    assert "manipulability ellipsoid: velocity of the contacts' centre" in title
    assert "(rank 3)" in title and "drawn x" in title
    flat = draw_system(coopkin_sym.load("planar-two-fingers"), ellipsoid=True)
    assert "manipulability ellipse:" in flat.axes[0].get_title()
    out = tmp_path / "e.png"
    fig.savefig(out)
    assert out.stat().st_size > 10_000


# --- the budget of terms ---------------------------------------------------------------
@pytest.mark.parametrize("name, kwargs", [
    ("paper-case1-soft", {"generic": True}),
    ("paper-case1-hard", {"generic": True}),
    ("planar-two-fingers", {"free": ["q2"]}),
    ("five-bar", {"at": "q1=2*atan(1/3)"}),
])
def test_the_budget_leaves_small_results_unchanged(name, kwargs):
    from coopkin_sym.analysis.manipulability import MAX_TERMS

    a = coopkin_sym.load(name).analyze(**kwargs)
    unbounded = a.manipulability(length="L", max_terms=None)
    assert MAX_TERMS == 10_000
    for m in (a.manipulability(length="L"), a.manipulability(length="L", max_terms=2000)):
        assert (m.shape, m.form, m.index, m.rank, m.degeneracy) == (
            unbounded.shape, unbounded.form, unbounded.index, unbounded.rank,
            unbounded.degeneracy)


def test_an_entry_over_the_budget_stops_the_ellipsoid_naming_the_step():
    from coopkin_sym.errors import BlockTooLarge

    a = coopkin_sym.load("planar-two-fingers").analyze(free=["q2"])
    with pytest.raises(BlockTooLarge) as info:
        a.manipulability(length="L", max_terms=3)
    message = str(info.value)
    assert message.startswith("manipulability: the ")
    assert "over the budget of 3 (terms of its numerator and denominator; max_terms= or " \
           "--max-terms N raises it); the ellipsoid is not computed" in message


def test_the_generic_two_fingers_stop_quickly_at_a_small_budget():
    import time

    from coopkin_sym.errors import BlockTooLarge

    a = coopkin_sym.load("planar-two-fingers").analyze(generic=True)
    start = time.monotonic()
    with pytest.raises(BlockTooLarge, match=r"^manipulability: the inverse of A: an entry "
                                            r"of [\d,]+ terms, over the budget of 2,000 "):
        a.manipulability(length="L", max_terms=2000)
    assert time.monotonic() - start < 5


@pytest.mark.parametrize("budget", [0, -3, 2.5, True, "100"])
def test_a_bad_budget_is_refused(budget):
    a = coopkin_sym.load("paper-case1-hard").analyze("L=1")
    with pytest.raises(ManipulabilityError, match="max_terms: expected a positive integer"):
        a.manipulability(max_terms=budget)
