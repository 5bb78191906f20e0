"""The exact layer: fraction-free elimination over Z and Z[x], against SymPy."""

from __future__ import annotations

import flint
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from coopkin_sym.exact import elimination as el
from coopkin_sym.exact.ring import Ring
from coopkin_sym.exact.sympy_bridge import matrix_to_sympy, poly_from_sympy

T, L = sp.symbols("t L")
SYMS = {"t": T, "L": L}


def poly_matrix(ring: Ring, mat: sp.Matrix):
    return [[ring.to_zpoly(poly_from_sympy(e, ring, SYMS)) for e in mat.row(i)]
            for i in range(mat.rows)]


def test_nullspace_of_polynomial_matrix_is_exact_and_primitive():
    ring = Ring(["t", "L"])
    m = sp.Matrix([[T, L, 1 + T**2], [2 * T, 2 * L, 2 + 2 * T**2], [0, 1, T]])
    rows = poly_matrix(ring, m)
    basis = el.nullspace(rows)
    assert len(basis) == 3 - m.rank() == 1
    v = matrix_to_sympy([basis[0]], ring, SYMS).T
    assert (m * v).expand() == sp.zeros(3, 1)
    # primitive: the gcd of the entries is 1
    g = 0
    for e in basis[0]:
        g = e if g == 0 else g.gcd(e)
    assert g.is_one()


def test_nullspace_without_the_minors_route_is_the_same_basis(monkeypatch):
    ring = Ring(["t", "L"])
    m = sp.Matrix([[T, L, 1 + T**2, 1], [2 * T, 2 * L, 2 + L * T**2, T], [0, 1, T, L]])
    rows = poly_matrix(ring, m)
    zctx = rows[0][0].context()
    used = []
    minors = el._minors_nullspace
    monkeypatch.setattr(el, "_minors_nullspace",
                        lambda *a: used.append(minors(*a)) or used[-1])
    by_minors = el.nullspace_rref(rows, 4, zctx)
    assert used and used[-1] is not None               # the minors route answered
    monkeypatch.setattr(el, "MINORS_TERMS", 0)     # every minor counts as too large
    by_elimination = el.nullspace_rref(rows, 4, zctx)
    assert used[-1] is None                            # ... and now it declined
    assert [[str(e) for e in v] for v in by_elimination[0]] == \
        [[str(e) for e in v] for v in by_minors[0]]
    assert by_elimination[1] == by_minors[1]
    v = matrix_to_sympy([by_minors[0][0]], ring, SYMS).T
    assert (m * v).expand() == sp.zeros(3, 1)


def test_rank_drops_only_where_the_determinant_vanishes():
    ring = Ring(["t"])
    m = sp.Matrix([[T, 1], [1, T]])
    assert el.rank(poly_matrix(ring, m)) == 2
    ring0 = Ring([])
    assert el.rank(poly_matrix(ring0, m.subs(T, 1))) == 1
    assert el.rank(poly_matrix(ring0, m.subs(T, 2))) == 2


def test_canonical_form_is_the_same_for_equal_row_spaces():
    ring = Ring(["t", "L"])
    a = sp.Matrix([[1, T, L, 0], [0, 1, T, L]])
    change = sp.Matrix([[T + 1, 2], [L, 3]])  # invertible over Q(t, L)
    b = change * a
    ra, pa = el.gauss_jordan(poly_matrix(ring, a), 4)
    rb, pb = el.gauss_jordan(poly_matrix(ring, b), 4)
    assert pa == pb == [0, 1]
    assert [[str(e) for e in r] for r in ra] == [[str(e) for e in r] for r in rb]
    # each reduced row is proportional to sympy's rref row
    rref, _ = a.rref()
    got = matrix_to_sympy(ra, ring, SYMS)
    for i in range(2):
        ratio = sp.cancel(got[i, i] / rref[i, i])
        assert (got.row(i) - ratio * rref.row(i)).applyfunc(sp.cancel) == sp.zeros(1, 4)


def test_column_order_gives_the_echelon_form_of_the_permuted_matrix():
    ring = Ring([])
    m = sp.Matrix([[1, 2, 3], [2, 4, 7]])
    rows, pivots = el.gauss_jordan(poly_matrix(ring, m), 3, column_order=[2, 1, 0])
    assert pivots == [2, 1]
    got = matrix_to_sympy(rows, ring, {})
    # reduced rows are primitive multiples of the echelon rows of m[:, [2, 1, 0]]
    assert got == sp.Matrix([[0, 0, 1], [1, 2, 0]])


def test_empty_and_zero_matrices():
    ring = Ring(["t"])
    zero = ring.zctx.constant(0)
    assert el.rank([[zero, zero]]) == 0
    assert el.nullspace([], 2, ring.zctx) == [[ring.zctx.constant(1), zero],
                                              [zero, ring.zctx.constant(1)]]
    assert el.gauss_jordan([[zero, zero]], 2) == ([], [])


small = st.integers(-4, 4)


@pytest.mark.slow  # campaign-style (random matrices): run by .ci/run, not by the default command
@settings(max_examples=60, deadline=None)
@given(st.integers(1, 4), st.integers(1, 5), st.data())
def test_integer_and_polynomial_paths_agree_with_sympy(nrows, ncols, data):
    # entries a + b*t: the polynomial path; then at t = 2 the integer path
    ring = Ring(["t"])
    m = sp.Matrix(nrows, ncols, lambda i, j: data.draw(small) + data.draw(small) * T)
    rows = poly_matrix(ring, m)
    assert el.rank(rows) == m.rank()
    basis = el.nullspace(rows)
    assert len(basis) == ncols - m.rank()
    for v in basis:
        vs = matrix_to_sympy([v], ring, {"t": T}).T
        assert (m * vs).expand() == sp.zeros(nrows, 1)
    ring0 = Ring([])
    m2 = m.subs(T, 2)
    rows2 = poly_matrix(ring0, m2)
    assert el.rank(rows2) == m2.rank()
    reduced, pivots = el.gauss_jordan(rows2, ncols)
    rref, piv = m2.rref()
    assert tuple(pivots) == piv
    got = matrix_to_sympy(reduced, ring0, {})
    for i in range(len(pivots)):
        assert got.row(i) / got[i, pivots[i]] == rref.row(i)


def test_fmpz_context_without_variables_uses_integers():
    ctx = flint.fmpz_mpoly_ctx.get((), "degrevlex")
    rows = [[ctx.constant(2), ctx.constant(4)], [ctx.constant(3), ctx.constant(6)]]
    reduced, pivots = el.gauss_jordan(rows, 2)
    assert pivots == [0] and [int(e.coeffs()[0]) for e in reduced[0]] == [1, 2]


def test_primitive_makes_the_first_entry_positive_even_when_it_is_alone():
    ctx = flint.fmpz_mpoly_ctx.get(("y",), "degrevlex")
    (y,) = ctx.gens()
    zero = ctx.constant(0)
    assert [str(e) for e in el.primitive([-y, zero])] == ["1", "0"]
    assert [str(e) for e in el.primitive([-2 * y, 4 * y**2])] == ["1", "-2*y"]
    assert [str(e) for e in el.primitive([zero, -3 * y, ctx.constant(6)])] == ["0", "y", "-2"]


def test_a_gcd_of_a_nullspace_vector_that_would_outlast_the_time_left_is_not_started(
        monkeypatch):
    """The lcm of the pivots of a nullspace vector takes gcds flint cannot interrupt:
    under a time bound, one estimated to outlast the time left is not started (the
    bound is reported reached there); without a bound it is taken."""
    from coopkin_sym.errors import TimeLimitReached
    from coopkin_sym.exact import deadline, elimination
    ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    x, y = ctx.gens()
    p = sum((x**i * y**(i % 7) * (i + 1) for i in range(600)), ctx.constant(1))
    q = sum((y**i * x**(i % 5) * (i + 2) for i in range(600)), ctx.constant(3))
    zero = ctx.constant(0)
    reduced = [[p, zero, x + 1], [zero, q, y - 2]]
    vector = elimination._kernel_vector(reduced, [0, 1], 2, 3, ctx)
    assert all((row[0] * vector[0] + row[1] * vector[1] + row[2] * vector[2]).is_zero()
               for row in reduced)
    monkeypatch.setattr(elimination, "CONTENT_GCD_RATE", 1)   # every large gcd is slow
    with deadline.time_limit(60, "a test"):
        with pytest.raises(TimeLimitReached, match="a nullspace vector"):
            elimination._kernel_vector(reduced, [0, 1], 2, 3, ctx)
