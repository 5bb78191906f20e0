"""The paper's case studies reproduced: numbers, subspaces, maps (exact)."""

from __future__ import annotations

import pytest
import sympy as sp
from support import rank, same_span

import coopkin_sym
from coopkin_sym import InfeasibleMotion

L = sp.Symbol("L", positive=True)


def is_zero(m: sp.Matrix) -> bool:
    return m.applyfunc(sp.cancel) == sp.zeros(*m.shape)


PAPER_NUMBERS = {
    # paper section 4.1 and 4.2: (Nm, Nc, Ni, Nr)
    "paper-case1-hard": (2, 2, 1, 0),
    "paper-case1-soft": (1, 1, 0, 0),
    "paper-case1-soft-hard": (1, 1, 0, 0),
    "paper-case1-complete-hard": (0, 0, 0, 0),
    "paper-case2-complete": (3, 3, 0, 0),
    "paper-case2-hard": (8, 6, 1, 2),
}


@pytest.mark.parametrize("name", sorted(PAPER_NUMBERS))
@pytest.mark.parametrize("at", [None, "L=1", "L=1000", "L=3/7"])
def test_paper_numbers(name, at):
    a = coopkin_sym.load(name).analyze(at)
    n = a.numbers
    assert (n.Nm, n.Nc, n.Ni, n.Nr) == PAPER_NUMBERS[name]
    assert n.Nm == n.Nc + n.Nr
    assert n.Nm - n.Nh == 6 + a.r - a.m
    assert a.check()
    assert is_zero(a.Q * a.C)


def test_case1_hard_subspaces():
    a = coopkin_sym.load("paper-case1-hard").analyze()
    # indeterminate: rotation about the line through c1 and c2 (x axis at y = L)
    assert same_span(a.C11, sp.Matrix([0, 0, -L, 1, 0, 0]))
    # coordinated: translation along x with both joints at equal speed
    coordinated = a.C12.col_join(a.C22)
    assert same_span(coordinated, sp.Matrix([-L, 0, 0, 0, 0, 0, 1, 1]))
    assert a.C23.shape == (2, 0)
    # canonical bases: primitive, positive pivot
    assert a.C11 == sp.Matrix([0, 0, L, -1, 0, 0])
    assert a.C12 == sp.Matrix([L, 0, 0, 0, 0, 0]) and a.C22 == sp.Matrix([-1, -1])


@pytest.mark.parametrize("name", ["paper-case1-soft", "paper-case1-soft-hard"])
def test_case1_soft_only_the_coordinated_translation(name):
    a = coopkin_sym.load(name).analyze()
    assert a.C11.shape == (6, 0)
    assert same_span(a.C12.col_join(a.C22), sp.Matrix([-L, 0, 0, 0, 0, 0, 1, 1]))


def test_case1_matrices_as_in_section_2_1():
    a = coopkin_sym.load("paper-case1-soft").analyze()
    assert a.G.shape == (6, 12) and a.D.shape == (12, 2) and a.H.shape == (8, 12)
    # c1 = (0, L, 0), c2 = (L, L, 0): G = [[I, I, 0, 0], [S(c1), S(c2), I, I]]
    assert a.G[3:, 0:3] == sp.Matrix([[0, 0, L], [0, 0, 0], [-L, 0, 0]])
    assert a.G[3:, 3:6] == sp.Matrix([[0, 0, L], [0, 0, -L], [-L, L, 0]])
    # D: q1 moves c1 by z x c1 = (-L, 0, 0), and spins it about z
    assert a.D[:, 0].T == sp.Matrix([[-L, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0]])
    assert a.D[:, 1].T == sp.Matrix([[0, 0, 0, -L, 0, 0, 0, 0, 0, 0, 0, 1]])
    # soft/soft H: the last two rows are n1^T and n2^T on the angular block
    assert a.H[6, 6:] == sp.Matrix([[1, 0, 0, 0, 0, 0]])
    assert a.H[7, 6:] == sp.Matrix([[0, 0, 0, -1, 0, 0]])
    assert a.H[:6, :6] == sp.eye(6)


def test_case2_complete_blocks_are_the_papers():
    a = coopkin_sym.load("paper-case2-complete").analyze()
    c12 = sp.Matrix([[L, 0, 0], [0, L, 0], [0, 0, L], [0, 0, 0], [0, 0, 0], [0, 0, 0]])
    c22 = sp.Matrix([[0, 1, 0], [1, -1, 0], [-1, 0, 0], [0, 0, L], [L, 0, 0],
                     [0, -1, 0], [0, 1, -1], [0, 0, 1]])
    assert a.C12 == c12 and a.C22 == c22
    assert a.C11.shape == (6, 0) and a.C23.shape == (8, 0)


def test_case2_hard_subspaces():
    a = coopkin_sym.load("paper-case2-hard").analyze()
    # rotation about the line through c1 = (L, L, L) and c2 = (3L, L, L)
    assert same_span(a.C11, sp.Matrix([0, L, -L, 1, 0, 0]))
    # redundancy: the third and sixth joints alone (SCARA axes)
    e3, e6 = sp.zeros(8, 1), sp.zeros(8, 1)
    e3[2] = e6[5] = 1
    assert same_span(a.C23, e3.row_join(e6))
    # full connectivity: [C11 C12] spans every twist
    assert rank(a.C11.row_join(a.C12)) == 6


def test_generic_case2_all_eight_joints():
    a = coopkin_sym.load("paper-case2-hard").analyze(generic=True)
    assert a.numbers.as_dict() == {"Nm": 8, "Nc": 6, "Ni": 1, "Nr": 2,
                                   "Ng": 1, "Nd": 0, "Nh": 0}
    assert a.check()
    assert [str(v) for v in a.variables] == [
        "t_q1", "t_q2", "t_q3", "q4", "q5", "t_q6", "t_q7", "t_q8", "L"]


def test_generic_numbers_match_a_random_rational_configuration():
    # Schwartz-Zippel: generic ranks equal the ranks at a random point (w.h.p.)
    system = coopkin_sym.load("paper-case2-hard")
    generic = system.analyze(generic=True).numbers
    at = "q1=2*atan(3/7),q2=2*atan(-5/11),q3=2*atan(2/9),q4=3/13,q5=-4/17,"
    at += "q6=2*atan(7/3),q7=2*atan(1/19),q8=2*atan(-8/5),L=29/31"
    assert system.analyze(at).numbers == generic


def test_joint_velocities_paper_eq_11():
    a = coopkin_sym.load("paper-case2-hard").analyze("L=2")
    u = a.C12[:, 0] + 3 * a.C12[:, 1]
    motion = a.joint_velocities(list(u))
    assert motion.particular == a.C22[:, 0] + 3 * a.C22[:, 1]
    assert motion.free == a.C23
    # every solution keeps the contacts: Q (u, qdot) = 0
    y = motion.particular + 5 * motion.free[:, 0] - motion.free[:, 1]
    assert is_zero(a.Q * u.col_join(y))


def test_object_velocities_paper_eq_12_with_indeterminacy():
    a = coopkin_sym.load("paper-case1-hard").analyze()
    motion = a.object_velocities([1, 1])
    assert motion.particular == sp.Matrix([-L, 0, 0, 0, 0, 0])
    assert motion.free == a.C11


def test_infeasible_requests_raise():
    a = coopkin_sym.load("paper-case1-soft").analyze()
    with pytest.raises(InfeasibleMotion, match="not feasible"):
        a.joint_velocities([0, 1, 0, 0, 0, 0])
    with pytest.raises(InfeasibleMotion, match="not feasible"):
        a.object_velocities([1, 0])
    with pytest.raises(InfeasibleMotion, match="expected 6 components"):
        a.joint_velocities([1, 0])


def test_one_to_one_map_eq_10_symbolic_configuration():
    # with q1 free the coordinated motion depends on the angle; the map stays exact
    a = coopkin_sym.load("paper-case1-soft").analyze(free=["q1", "q2"])
    assert a.numbers.Ni == a.numbers.Nr == 0
    for k in range(a.C12.cols):
        motion = a.joint_velocities(list(a.C12[:, k]))
        assert is_zero(motion.particular - a.C22[:, k])


def test_pi_is_exact():
    # q = pi is the one angle t = tan(q/2) misses: it goes through cos, sin directly
    a = coopkin_sym.load("paper-case1-hard").analyze("q1=pi,q2=pi")
    assert (a.numbers.Nm, a.numbers.Nc, a.numbers.Ni) == (2, 2, 1)
    # both links now point down: c1 = (0, -L, 0), c2 = (L, -L, 0)
    assert a.C11 == sp.Matrix([0, 0, L, 1, 0, 0]) or same_span(
        a.C11, sp.Matrix([0, 0, L, 1, 0, 0]))


def test_singular_configuration_found_exactly():
    # both links along the contact line (q1 = q2 = -pi/2): the rank of Q drops
    system = coopkin_sym.load("paper-case1-hard")
    generic = system.analyze(generic=True).numbers
    assert (generic.Nm, generic.Nc, generic.Ni, generic.Nr) == (2, 2, 1, 0)
    # c1 = (L, 0, 0), c2 = (2L, 0, 0): each joint now moves its contact along y alone,
    # so the object gains a rotation about z: Nm = Nc = 3 (by hand, see the docstring)
    special = system.analyze("q1=-pi/2,q2=-pi/2").numbers
    assert (special.Nm, special.Nc, special.Ni, special.Nr) == (3, 3, 1, 0)


def test_blocks_in_angles_span_the_same_columns():
    a = coopkin_sym.load("paper-case2-hard").analyze(free=["q1", "q2", "q7"])
    t = {str(v): v for v in a.variables}
    q = {n: sp.Symbol(n, real=True) for n in ("q1", "q2", "q7")}
    point = {"q1": sp.Rational(1, 3), "q2": sp.Rational(-2, 5), "q7": sp.Rational(3, 7)}
    for block in (a.C11, a.C12, a.C23):
        angles = a.in_angles(block)
        assert not any(s.name.startswith("t_") for s in angles.free_symbols)
        for k in range(block.cols):
            x = block.col(k).subs({t[f"t_{n}"]: v for n, v in point.items()})
            # t = tan(q/2) = v  <=>  cos q = (1-v^2)/(1+v^2), sin q = 2v/(1+v^2)
            trig = {}
            for n, v in point.items():
                trig[sp.cos(q[n])] = (1 - v**2) / (1 + v**2)
                trig[sp.sin(q[n])] = 2 * v / (1 + v**2)
            y = angles.col(k).subs(trig)
            assert rank(x.row_join(y)) == 1


def test_term_budget_leaves_out_huge_blocks_and_says_so():
    a = coopkin_sym.load("paper-case2-hard").analyze(generic=True)
    a.term_budget = 10
    with pytest.raises(coopkin_sym.BlockTooLarge, match="over the budget of 10"):
        _ = a.C22
    data = a.as_json()
    assert data["blocks"]["C22"] is None and "C22" in data["omitted"]
    assert data["blocks"]["C23"] is not None
    assert data["numbers"]["Nm"] == 8


def test_the_term_budget_holds_on_every_block_before_it_is_written():
    """Each block's largest entry is known before the block is written out (exactly
    for C11, C23 and the twists of C12, a bound for C22): a block over the budget is
    refused with the size it would have had, every other block is kept as it was."""
    full = coopkin_sym.load("paper-case2-hard").analyze(generic=True).blocks()
    a = coopkin_sym.load("paper-case2-hard").analyze(generic=True)
    assert a.block_terms() == {"C11": 276, "C12": 60, "C22": 60, "C23": 7}
    a.term_budget = 100
    blocks, omitted = a.available_blocks()
    assert omitted == {"C11": "C11: the indeterminate object motions would have entries "
                              "of 276 terms, over the budget of 100; keep fewer joints "
                              "symbolic (free=[...] / --free) or set analysis.term_budget "
                              "= None"}
    assert blocks["C11"] is None and blocks["C23"] == full["C23"]
    assert blocks["C12"].shape == full["C12"].shape == (6, 5)
    assert blocks["C22"].shape == full["C22"].shape == (8, 5)
    at_size = coopkin_sym.load("paper-case2-hard").analyze(generic=True)
    at_size.term_budget = 276
    blocks, omitted = at_size.available_blocks()
    assert omitted == {} and blocks["C11"] == full["C11"] and blocks["C23"] == full["C23"]
    b = coopkin_sym.load("paper-case2-hard").analyze(generic=True)
    b.term_budget = 6
    blocks, omitted = b.available_blocks()
    assert sorted(omitted) == ["C11", "C22", "C23"]
    assert "entries of 7 terms, over the budget of 6" in omitted["C23"]
    assert blocks["C12"] == b.C12 and b.coordinated_form == "rational"
