"""Exact algebraic layer: ranks modulo an irreducible polynomial, polynomials over a
number field, real algebraic roots and their angles, each against an independent exact
computation (SymPy over ``QQ<alpha>`` or a rational parametrization, Sturm counts,
sign changes with Fractions)."""

from __future__ import annotations

from fractions import Fraction

import flint
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.polys.matrices import DomainMatrix

from coopkin_sym.exact.angles import algebraic_angle as angle_of
from coopkin_sym.exact.numberfield import NumberField
from coopkin_sym.exact.quotient import (
    Quotient,
    eliminate_modulo,
    rank_modulo,
    smallest_fraction,
)
from coopkin_sym.exact.realroot import RealRoot

CTX = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
X, Y = CTX.gens()
ONE = CTX.constant(1)
SX, SY, ST = sp.symbols("x y t")

# a real root of each univariate f (all roots are conjugate, so any one will do)
SQRT2 = sp.sqrt(2)
ROOT_QUADRATIC = -2 + sp.sqrt(3)  # x**2 + 4*x + 1
ROOT_CUBIC = sp.CRootOf(SX**3 - 3 * SX + 1, 0)  # x**3 - 3*x + 1
UNIVARIATE = {
    "x**2 - 2": (X**2 - 2, SQRT2),
    "x**2 + 4*x + 1": (X**2 + 4 * X + 1, ROOT_QUADRATIC),
    "x**3 - 3*x + 1": (X**3 - 3 * X + 1, ROOT_CUBIC),
}
# the circle x^2 + y^2 = 1 is rational: its function field is Q(t)
CIRCLE = X**2 + Y**2 - 1
CIRCLE_POINT = {SX: (1 - ST**2) / (1 + ST**2), SY: 2 * ST / (1 + ST**2)}


# --------------------------------------------------------------------------- helpers


def to_flint(expr) -> flint.fmpz_mpoly:
    """An integer polynomial in x, y (SymPy) as an ``fmpz_mpoly`` of CTX."""
    terms = sp.Poly(sp.expand(expr), SX, SY).as_dict()
    return CTX.from_dict({k: int(v) for k, v in terms.items() if v != 0})


def to_sympy(p: flint.fmpz_mpoly) -> sp.Expr:
    # int(): SymPy with python ground types would read flint's fmpz exponents as floats
    return sp.Add(*[int(c) * SX ** int(i) * SY ** int(j) for (i, j), c in p.to_dict().items()])


def flint_rows(matrix) -> list[list[flint.fmpz_mpoly]]:
    return [[to_flint(e) for e in row] for row in matrix]


def reference_rank(matrix, point: dict) -> int:
    """SymPy's exact rank of ``matrix`` (SymPy expressions) with ``point`` substituted,
    over the algebraic number field (or rational function field) it generates."""
    m = sp.Matrix(matrix).subs(point).applyfunc(sp.cancel)
    # from_Matrix can store an entry that is zero only in QQ<alpha> (a CRootOf
    # polynomial) as a sparse nonzero; the dense form pivots on true zeros correctly
    return DomainMatrix.from_Matrix(m, extension=True).to_dense().rank()


def sign(p: list[int], v: Fraction) -> int:
    """The sign of the polynomial ``p`` (lowest degree first) at ``v``, exactly."""
    value = sum(Fraction(c) * v**i for i, c in enumerate(p))
    return (value > 0) - (value < 0)


def q_rational(q: flint.fmpq) -> sp.Rational:
    return sp.Rational(int(q.p), int(q.q))


def element_at(c: flint.fmpq_poly, alpha: sp.Expr) -> sp.Expr:
    return sp.Add(*[q_rational(a) * alpha**i for i, a in enumerate(c.coeffs())])


def kpoly_at(p, alpha: sp.Expr) -> sp.Expr:
    """A polynomial in y over Q(alpha) (list of ``fmpq_poly`` in x) at x = alpha."""
    return sp.expand(sp.Add(*[element_at(c, alpha) * SY**i for i, c in enumerate(p)]))


def kmul(field: NumberField, a, b):
    """The product of two polynomials in y over ``field`` (coefficient lists)."""
    out = [flint.fmpq_poly(0)] * (len(a) + len(b) - 1)
    for i, u in enumerate(a):
        for j, v in enumerate(b):
            out[i + j] = field.element(out[i + j] + flint.fmpq_poly(u) * flint.fmpq_poly(v))
    return out


XQ = flint.fmpq_poly([0, 1])  # x, the generator alpha of Q[x]/(g)


# ------------------------------------------------------------------ Quotient basics


def test_reduce_and_is_zero_in_a_number_field():
    q = Quotient(X**2 - 2, 0)
    assert q.degree == 2
    assert q.reduce(X**2) == CTX.constant(2)
    assert q.reduce(X**3 + X**2 + 1) == 2 * X + 3
    assert q.reduce(X) == X
    assert q.is_zero(X**3 - 2 * X)
    assert q.is_zero((X**2 - 2) * (X**5 + Y + 7))
    assert not q.is_zero(X)
    assert not q.is_zero(X**2 - 3)
    assert not q.is_zero(Y * (X**2 - 1))


def test_reduce_and_is_zero_on_the_circle():
    q = Quotient(CIRCLE, 0)
    assert q.reduce(X**2) == 1 - Y**2
    assert q.is_zero(X**4 - (1 - Y**2) ** 2)
    assert q.is_zero((X + Y) * CIRCLE)
    assert not q.is_zero(X**2 + Y**2)
    assert not q.is_zero(X * Y)


def test_quotient_needs_the_variable():
    with pytest.raises(ValueError):
        Quotient(Y**2 - 2, 0)


def test_rank_of_no_rows_is_zero():
    assert rank_modulo([], 3, Quotient(X**2 - 2, 0)) == 0


# ------------------------------------------------- hand-built singular matrices


# each matrix has determinant exactly the named f (or a multiple of it)
SINGULAR = {
    "x**2 - 2": [[SX, 2], [1, SX]],
    "x**2 + 4*x + 1": [[SX + 4, -1], [1, SX]],
    # x I - (companion matrix of t^3 - 3 t + 1)
    "x**3 - 3*x + 1": [[SX, 0, 1], [-1, SX, -3], [0, -1, SX]],
}
SINGULAR_3X3 = {
    "x**2 - 2": [[SX, 1, 0], [2, SX, 1], [0, 0, SX + 1]],
    "x**2 + 4*x + 1": [[SX + 4, -1, SX], [1, SX, 3], [0, 0, SX**2 - 5]],
}


@pytest.mark.parametrize("name", sorted(SINGULAR))
def test_matrix_singular_modulo_its_determinant(name):
    f, alpha = UNIVARIATE[name]
    matrix = SINGULAR[name]
    n = len(matrix)
    # the construction: det is f itself
    assert sp.expand(sp.Matrix(matrix).det() - to_sympy(f)) == 0
    rows = flint_rows(matrix)
    assert rank_modulo(rows, n, Quotient(f, 0)) == n - 1
    assert reference_rank(matrix, {SX: alpha}) == n - 1
    for other, (g, beta) in UNIVARIATE.items():
        if other != name:
            assert rank_modulo(rows, n, Quotient(g, 0)) == n
            assert reference_rank(matrix, {SX: beta}) == n


@pytest.mark.parametrize("name", sorted(SINGULAR_3X3))
def test_3x3_with_determinant_a_multiple_of_f(name):
    f, alpha = UNIVARIATE[name]
    matrix = SINGULAR_3X3[name]
    det = sp.Matrix(matrix).det()
    assert sp.rem(sp.expand(det), to_sympy(f), SX) == 0
    assert sp.expand(det) != 0
    rows = flint_rows(matrix)
    assert rank_modulo(rows, 3, Quotient(f, 0)) == reference_rank(matrix, {SX: alpha}) == 2
    for other, (g, beta) in UNIVARIATE.items():
        if other != name:
            assert rank_modulo(rows, 3, Quotient(g, 0)) == 3
            assert reference_rank(matrix, {SX: beta}) == 3


def test_rank_sees_entries_that_are_multiples_of_f():
    f, alpha = UNIVARIATE["x**3 - 3*x + 1"]
    matrix = [[SX**3 - 3 * SX + 1, 0, (SX + 2) * (SX**3 - 3 * SX + 1)],
              [SX**4 - 3 * SX**2 + SX, 0, 0],      # x * f
              [1, SX, SX**2]]
    rows = flint_rows(matrix)
    assert rank_modulo(rows, 3, Quotient(f, 0)) == reference_rank(matrix, {SX: alpha}) == 1
    assert rank_modulo(rows, 3, Quotient(X**2 - 2, 0)) == 3


def test_rank_of_wide_and_tall_matrices():
    f, alpha = UNIVARIATE["x**2 - 2"]
    # second row = x * first row at x = sqrt(2) (x^2 = 2), third = first + second
    wide = [[1, SX, 2, SX + 1], [SX, 2, 2 * SX, 2 + SX],
            [1 + SX, SX + 2, 2 + 2 * SX, SX + 3 + SX]]
    rows = flint_rows(wide)
    assert rank_modulo(rows, 4, Quotient(f, 0)) == reference_rank(wide, {SX: alpha}) == 1
    assert rank_modulo(rows, 4, Quotient(X**2 + 4 * X + 1, 0)) == 2
    tall = [list(r) for r in zip(*wide, strict=True)]
    assert rank_modulo(flint_rows(tall), 3, Quotient(f, 0)) == 1


# ------------------------------------ non-monic f: one multiplier for a whole row


def test_rank_modulo_non_monic_univariate():
    # alpha = 1/sqrt(2): [[1/2, 1], [1, 1]] has determinant -1/2, rank 2
    matrix = [[SX**2, 1], [1, 1]]
    assert reference_rank(matrix, {SX: 1 / sp.sqrt(2)}) == 2
    assert rank_modulo(flint_rows(matrix), 2, Quotient(2 * X**2 - 1, 0)) == 2


def test_rank_modulo_non_monic_singular():
    # alpha = 1/sqrt(2): [[1/2, 1], [1, 2]] has determinant 0, rank 1
    matrix = [[SX**2, 1], [1, 2]]
    assert reference_rank(matrix, {SX: 1 / sp.sqrt(2)}) == 1
    assert rank_modulo(flint_rows(matrix), 2, Quotient(2 * X**2 - 1, 0)) == 1


def test_rank_modulo_non_monic_bivariate():
    # on y x^2 = 1 (x^2 = 1/y): [[1/y, 1], [1, 1]] has determinant 1/y - 1, rank 2
    matrix = [[SX**2, 1], [1, 1]]
    assert reference_rank(matrix, {SX: 1 / sp.sqrt(SY)}) == 2
    assert rank_modulo(flint_rows(matrix), 2, Quotient(Y * X**2 - 1, 0)) == 2


# ------------------------------------------------------------------ random matrices


def _poly_x(coeffs) -> sp.Expr:
    return sp.Add(*[c * SX**i for i, c in enumerate(coeffs)])


_x_polys = st.lists(st.integers(-3, 3), min_size=1, max_size=3).map(_poly_x)


@st.composite
def x_matrices(draw, f: sp.Expr):
    """Small integer-polynomial matrices in x: plain, low rank (a product through r
    columns) and/or with multiples of ``f`` added to entries."""
    n, m = draw(st.integers(1, 4)), draw(st.integers(1, 4))
    if draw(st.booleans()):
        r = draw(st.integers(1, min(n, m)))
        a = sp.Matrix(draw(st.lists(st.lists(_x_polys, min_size=r, max_size=r),
                                    min_size=n, max_size=n)))
        b = sp.Matrix(draw(st.lists(st.lists(_x_polys, min_size=m, max_size=m),
                                    min_size=r, max_size=r)))
        matrix = (a * b).applyfunc(sp.expand)
    else:
        matrix = sp.Matrix(draw(st.lists(st.lists(_x_polys, min_size=m, max_size=m),
                                         min_size=n, max_size=n)))
    if draw(st.booleans()):
        shift = sp.Matrix(draw(st.lists(st.lists(_x_polys, min_size=m, max_size=m),
                                        min_size=n, max_size=n)))
        matrix = (matrix + f * shift).applyfunc(sp.expand)
    return matrix.tolist()


@settings(max_examples=40, deadline=None)
@given(x_matrices(SX**2 - 2))
def test_random_rank_modulo_x2_minus_2_matches_sympy(matrix):
    ncols = len(matrix[0])
    got = rank_modulo(flint_rows(matrix), ncols, Quotient(X**2 - 2, 0))
    assert got == reference_rank(matrix, {SX: SQRT2})


@settings(max_examples=40, deadline=None)
@given(x_matrices(2 * SX**2 - 1))
def test_random_rank_modulo_non_monic_matches_sympy(matrix):
    # f = 2 x^2 - 1: pseudo-division multiplies by 2, once per row for every entry
    ncols = len(matrix[0])
    got = rank_modulo(flint_rows(matrix), ncols, Quotient(2 * X**2 - 1, 0))
    assert got == reference_rank(matrix, {SX: 1 / SQRT2})


def _poly_xy(coeffs) -> sp.Expr:
    monomials = [1, SX, SY, SX**2, SX * SY, SY**2]
    return sp.Add(*[c * mono for c, mono in zip(coeffs, monomials, strict=False)])


_xy_polys = st.lists(st.integers(-2, 2), min_size=1, max_size=6).map(_poly_xy)


@st.composite
def xy_matrices(draw):
    n, m = draw(st.integers(1, 3)), draw(st.integers(1, 3))
    if draw(st.booleans()):
        a = sp.Matrix(draw(st.lists(st.lists(_xy_polys, min_size=1, max_size=1),
                                    min_size=n, max_size=n)))
        b = sp.Matrix(draw(st.lists(st.lists(_xy_polys, min_size=m, max_size=m),
                                    min_size=1, max_size=1)))
        matrix = (a * b).applyfunc(sp.expand)
    else:
        matrix = sp.Matrix(draw(st.lists(st.lists(_xy_polys, min_size=m, max_size=m),
                                         min_size=n, max_size=n)))
    if draw(st.booleans()):
        shift = sp.Matrix(draw(st.lists(st.lists(_xy_polys, min_size=m, max_size=m),
                                        min_size=n, max_size=n)))
        matrix = (matrix + (SX**2 + SY**2 - 1) * shift).applyfunc(sp.expand)
    return matrix.tolist()


@settings(max_examples=30, deadline=None)
@given(xy_matrices())
def test_random_rank_on_the_circle_matches_rational_parametrization(matrix):
    ncols = len(matrix[0])
    got = rank_modulo(flint_rows(matrix), ncols, Quotient(CIRCLE, 0))
    assert got == reference_rank(matrix, CIRCLE_POINT)


@settings(max_examples=30, deadline=None)
@given(xy_matrices())
def test_rows_that_keep_their_content_give_the_same_ranks(matrix):
    # no gcd at all (both sides always over the bound): the rows keep every factor,
    # the ranks do not change
    from coopkin_sym.exact import quotient

    ncols = len(matrix[0])
    before = quotient.CONTENT_GCD_TERMS
    quotient.CONTENT_GCD_TERMS = 0
    try:
        got = rank_modulo(flint_rows(matrix), ncols, Quotient(CIRCLE, 0))
    finally:
        quotient.CONTENT_GCD_TERMS = before
    assert got == reference_rank(matrix, CIRCLE_POINT)


def test_a_content_gcd_that_would_outlast_the_time_left_is_not_taken(monkeypatch):
    from coopkin_sym.exact import deadline, elimination

    row = [(X + Y) * (X**2 + 3), (X + Y) * (Y**3 - 2)]
    assert elimination.primitive(row, 10) == [X**2 + 3, Y**3 - 2]
    monkeypatch.setattr(elimination, "WEIGHED_TERMS", 0)
    monkeypatch.setattr(elimination, "CONTENT_GCD_RATE", 0.01)   # every gcd takes ages
    assert elimination.primitive(row, 10) == [X**2 + 3, Y**3 - 2]     # no bound: taken
    with deadline.time_limit(60):
        assert elimination.primitive(row, 10) == row                  # the factor kept
        assert elimination.primitive(row) == [X**2 + 3, Y**3 - 2]     # not weighed
        kept = elimination.combine([X * (X + 1), ONE, Y], [X * (X + 2), ONE, 0 * ONE], 0,
                                   max_terms=10)
    # x (x + 2) row1 - x (x + 1) row2: neither gcd (x, then the row's x) taken
    assert kept == [0 * ONE, X, X * (X + 2) * Y]
    assert elimination.combine([X * (X + 1), ONE, Y], [X * (X + 2), ONE, 0 * ONE], 0,
                               max_terms=10) == [0 * ONE, ONE, (X + 2) * Y]


# ------------------------------------------------------------------ the circle


def test_circle_rotation_matrix_has_full_rank():
    matrix = [[SX, SY], [-SY, SX]]  # det = x^2 + y^2 = 1 on the circle
    assert rank_modulo(flint_rows(matrix), 2, Quotient(CIRCLE, 0)) == 2
    assert reference_rank(matrix, CIRCLE_POINT) == 2


def test_circle_singular_matrix_has_rank_one():
    matrix = [[SX, 1 - SY], [1 + SY, SX]]  # det = x^2 + y^2 - 1
    rows = flint_rows(matrix)
    assert rank_modulo(rows, 2, Quotient(CIRCLE, 0)) == 1
    assert reference_rank(matrix, CIRCLE_POINT) == 1
    # on another curve the determinant does not vanish
    assert rank_modulo(rows, 2, Quotient(X**2 + Y**2 - 2, 0)) == 2
    # reduced in y instead of x: the same function field
    assert rank_modulo(rows, 2, Quotient(CIRCLE, 1)) == 1


def test_circle_doctest_matrices():
    rows = [[X, Y], [1 - Y, X]]
    assert rank_modulo(rows, 2, Quotient(CIRCLE, 0)) == 2
    assert rank_modulo(rows, 2, Quotient(X**2 + Y**2 - Y, 0)) == 1


def _is_unit_gcd(row) -> bool:
    g = None
    for e in row:
        if not e.is_zero():
            g = e if g is None else g.gcd(e)
    return g is not None and (g == 1 or g == -1)


def test_eliminate_modulo_on_the_circle_singular_matrix():
    q = Quotient(CIRCLE, 0)
    pivots, left = eliminate_modulo([[X, 1 - Y], [1 + Y, X]], [0], q)
    assert pivots == 1
    assert left == []  # the second row is (1 + y)/x times the first on the circle
    pivots, left = eliminate_modulo([[X, 1 - Y], [1 + Y, X]], [0, 1], q)
    assert (pivots, left) == (1, [])


def test_eliminate_modulo_on_the_circle_leftover():
    q = Quotient(CIRCLE, 0)
    matrix = [[SX, 1 - SY, SY], [1 + SY, SX, SX * SY]]
    pivots, left = eliminate_modulo(flint_rows(matrix), [0], q)
    assert pivots == 1
    assert len(left) == 1
    (row,) = left
    assert row[0].is_zero()
    # the columns 0, 1 are dependent on the circle, so the leftover is zero there too;
    # the last column is -(y^3 + y^2) / gcd: a unit
    assert row[1].is_zero()
    assert row[2] == 1 or row[2] == -1
    # the leftover lies in the row space: adding it does not raise the rank
    total = reference_rank(matrix, CIRCLE_POINT)
    assert total == 2
    assert pivots + reference_rank([[to_sympy(e) for e in r] for r in left],
                                   CIRCLE_POINT) == total
    assert reference_rank(matrix + [[to_sympy(e) for e in row]], CIRCLE_POINT) == total


def test_eliminate_modulo_leftover_rows_are_reduced_primitive_and_in_row_space():
    q = Quotient(CIRCLE, 0)
    matrix = [[SX, SY, 1, SX**3], [SY, -SX, SX * SY, 2], [SX + SY, SY - SX, 1 + SX * SY, 3],
              [SX**2, SY**2, 1, SX]]
    rows = flint_rows(matrix)
    pivots, left = eliminate_modulo(rows, [0], q)
    assert pivots == 1
    assert len(left) == 3
    for row in left:
        assert row[0].is_zero()
        assert all(e.degrees()[0] < 2 for e in row if not e.is_zero())
        assert _is_unit_gcd(row)
    total = reference_rank(matrix, CIRCLE_POINT)
    left_sym = [[to_sympy(e) for e in r] for r in left]
    assert pivots + reference_rank(left_sym, CIRCLE_POINT) == total
    assert reference_rank(matrix + left_sym, CIRCLE_POINT) == total
    assert rank_modulo(rows, 4, q) == total


def test_eliminate_modulo_skips_columns_zero_modulo_f():
    q = Quotient(CIRCLE, 0)
    pivots, left = eliminate_modulo([[CIRCLE, X], [(X + 1) * CIRCLE, Y]], [0], q)
    assert pivots == 0
    assert len(left) == 2
    assert all(r[0].is_zero() for r in left)
    # the rows are reduced and primitive: [0, x] and [0, y] become [0, +-1]
    assert all(r[1] == 1 or r[1] == -1 for r in left)


# ------------------------------------------------------------------ NumberField

FIELDS = {
    "sqrt2": (flint.fmpq_poly([-2, 0, 1]), SQRT2),
    "quadratic": (flint.fmpq_poly([1, 4, 1]), ROOT_QUADRATIC),
    "cubic": (flint.fmpq_poly([1, -3, 0, 1]), sp.CRootOf(ST**3 - 3 * ST + 1, 2)),
}
ELEMENTS = [
    flint.fmpq_poly([1]),
    flint.fmpq_poly([0, 1]),
    flint.fmpq_poly([3, 1]),
    flint.fmpq_poly([flint.fmpq(-1, 2), 0, 5]),
    flint.fmpq_poly([7, flint.fmpq(2, 3), 1, 4]),  # degree 3: reduced first
    flint.fmpq_poly([2, 0, 1]),  # x^2 + 2, which is 4 in Q(sqrt 2)
]


@pytest.mark.parametrize("name", sorted(FIELDS))
def test_inverse_times_element_is_one(name):
    g, _ = FIELDS[name]
    field = NumberField(g)
    gx = sp.Poly(list(reversed([q_rational(c) for c in g.coeffs()])), SX)
    for a in ELEMENTS:
        if field.element(a).is_zero():
            continue
        inv = field.inverse(a)
        assert inv.degree() < g.degree()
        assert field.element(inv * a) == 1
        assert (inv * a - 1) % g == 0
        # independent: SymPy's inverse modulo g
        ax = sp.Poly(list(reversed([q_rational(c) for c in a.coeffs()])), SX)
        expected = sp.invert(ax.as_expr(), gx.as_expr(), SX)
        assert sp.expand(element_at(inv, SX) - expected) == 0


def test_inverse_of_integers_and_rationals():
    field = NumberField(flint.fmpq_poly([-2, 0, 1]))
    assert field.inverse(4) == flint.fmpq_poly([flint.fmpq(1, 4)])
    assert field.inverse(flint.fmpq(-2, 3)) == flint.fmpq_poly([flint.fmpq(-3, 2)])
    # 1/sqrt(2) = sqrt(2)/2; 1/(1 + sqrt(2)) = sqrt(2) - 1
    assert field.inverse(XQ) == flint.fmpq_poly([0, flint.fmpq(1, 2)])
    assert field.inverse(XQ + 1) == flint.fmpq_poly([-1, 1])


def test_inverse_of_zero_raises():
    field = NumberField(flint.fmpq_poly([1, 4, 1]))
    with pytest.raises(ZeroDivisionError):
        field.inverse(0)
    with pytest.raises(ZeroDivisionError):
        field.inverse(flint.fmpq_poly(0))
    with pytest.raises(ZeroDivisionError):
        field.inverse(flint.fmpq_poly([1, 4, 1]))  # g itself is zero in the field
    with pytest.raises(ZeroDivisionError):
        field.inverse(XQ**2 + 4 * XQ + 1)


def test_number_field_needs_positive_degree():
    with pytest.raises(ValueError):
        NumberField(flint.fmpq_poly([3]))


def test_element_reduces_modulo_g():
    field = NumberField(flint.fmpq_poly([-2, 0, 1]))
    assert field.element(XQ**2) == 2
    assert field.element(XQ**3 + XQ) == 3 * XQ
    assert field.element(5) == 5
    assert field.element(flint.fmpq(1, 3)) == flint.fmpq_poly([flint.fmpq(1, 3)])


def test_gcd_y_squared_minus_two_and_y_minus_sqrt2():
    field = NumberField(flint.fmpq_poly([-2, 0, 1]))
    got = field.gcd([[-2, 0, 1], [-XQ, 1]])
    assert got == [-XQ, flint.fmpq_poly(1)]
    # and the other root
    assert field.gcd([[-2, 0, 1], [XQ, 1]]) == [XQ, flint.fmpq_poly(1)]


def test_gcd_of_coprime_polynomials_is_one():
    field = NumberField(flint.fmpq_poly([-2, 0, 1]))
    assert field.gcd([[-2, 0, 1], [-3, 1]]) == [flint.fmpq_poly(1)]
    assert field.gcd([[1, 0, 1], [-XQ, 1]]) == [flint.fmpq_poly(1)]
    assert field.gcd([[-XQ, 1], [XQ, 1]]) == [flint.fmpq_poly(1)]
    assert field.gcd([[5]]) == [flint.fmpq_poly(1)]


def test_gcd_of_zero_polynomials_is_empty():
    field = NumberField(flint.fmpq_poly([-2, 0, 1]))
    assert field.gcd([]) == []
    assert field.gcd([[], [0, 0]]) == []
    assert field.gcd([[0], [-XQ, 1]]) == [-XQ, flint.fmpq_poly(1)]


@pytest.mark.parametrize("name", sorted(FIELDS))
def test_gcd_of_non_monic_products_matches_sympy(name):
    g, alpha = FIELDS[name]
    field = NumberField(g)
    common = [-XQ, 1]  # y - alpha
    p = kmul(field, kmul(field, common, [1, 1]), [3])  # 3 (y - alpha)(y + 1)
    q = kmul(field, kmul(field, common, [-5, XQ + 2]), [flint.fmpq(2, 7)])
    got = field.gcd([p, q])
    assert got == [-XQ, flint.fmpq_poly(1)]
    # independent: SymPy's gcd over QQ<alpha>
    expected = sp.Poly(sp.gcd(kpoly_at(p, alpha), kpoly_at(q, alpha), extension=True),
                       SY, extension=True).monic()
    assert sp.simplify(kpoly_at(got, alpha) - expected.as_expr()) == 0


def test_squarefree_of_a_square():
    field = NumberField(flint.fmpq_poly([1, 4, 1]))  # alpha^2 + 4 alpha + 1 = 0
    # (y + alpha)^2 = y^2 + 2 alpha y + alpha^2 = y^2 + 2 alpha y - 4 alpha - 1
    square = kmul(field, [XQ, 1], [XQ, 1])
    assert square == [-4 * XQ - 1, 2 * XQ, flint.fmpq_poly(1)]
    assert field.squarefree(square) == [XQ, flint.fmpq_poly(1)]
    assert field.squarefree([flint.fmpq(3, 2) * c for c in square]) == [XQ, flint.fmpq_poly(1)]


def test_squarefree_of_a_cube_times_a_simple_factor():
    field = NumberField(flint.fmpq_poly([-2, 0, 1]))
    cube = kmul(field, kmul(field, [-XQ, 1], [-XQ, 1]), [-XQ, 1])
    p = kmul(field, kmul(field, cube, [1, 1]), [-4])  # -4 (y - a)^3 (y + 1)
    assert field.squarefree(p) == kmul(field, [-XQ, 1], [1, 1])
    # already squarefree: just made monic
    assert field.squarefree([-2, 0, 3]) == [flint.fmpq_poly(flint.fmpq(-2, 3)), 0, 1]
    assert field.squarefree([2 * XQ, 4]) == [flint.fmpq_poly([0, flint.fmpq(1, 2)]), 1]


# ------------------------------------------------------------------ RealRoot


def _check_isolating(roots: list[RealRoot], coeffs: list[int]) -> None:
    poly = sp.Poly(list(reversed(coeffs)), ST)
    for r in roots:
        assert isinstance(r.lo, Fraction) and isinstance(r.hi, Fraction)
        assert r.lo < r.hi
        assert sign(coeffs, r.lo) * sign(coeffs, r.hi) == -1
        assert poly.count_roots(sp.Rational(r.lo.numerator, r.lo.denominator),
                                sp.Rational(r.hi.numerator, r.hi.denominator)) == 1
    for a, b in zip(roots, roots[1:], strict=False):
        assert a.hi <= b.lo  # the intervals (lo, hi] are disjoint and increasing
    assert [r.index for r in roots] == list(range(len(roots)))
    assert len(roots) == poly.count_roots()


def test_roots_of_t2_plus_4t_plus_1():
    roots = RealRoot.all_of([1, 4, 1])
    _check_isolating(roots, [1, 4, 1])
    assert [r.expression() for r in roots] == [-2 - sp.sqrt(3), -2 + sp.sqrt(3)]
    assert [r.angle_text() for r in roots] == ["-5*pi/6", "-pi/6"]
    assert [r.angle() for r in roots] == [-5 * sp.pi / 6, -sp.pi / 6]
    assert [r.degree for r in roots] == [2, 2]
    assert roots[0].coeffs == (1, 4, 1)
    assert roots[0].polynomial_text("x") == "x**2 + 4*x + 1"
    # independent: tan of half the angle is the root
    for r in roots:
        assert sp.simplify(sp.tan(r.angle() / 2) - r.expression()) == 0


def test_roots_of_t2_minus_2_are_not_rational_angles():
    roots = RealRoot.all_of([-2, 0, 1])
    _check_isolating(roots, [-2, 0, 1])
    assert [r.expression() for r in roots] == [-sp.sqrt(2), sp.sqrt(2)]
    assert [r.angle() for r in roots] == [-2 * sp.atan(sp.sqrt(2)), 2 * sp.atan(sp.sqrt(2))]
    assert [r.angle_text() for r in roots] == ["-2*atan(sqrt(2))", "2*atan(sqrt(2))"]
    for r in roots:
        assert not (r.angle() / sp.pi).is_Rational


def test_roots_of_cubic_are_crootof_with_isolating_intervals():
    coeffs = [1, -3, 0, 1]
    roots = RealRoot.all_of(coeffs)
    assert len(roots) == 3
    _check_isolating(roots, coeffs)
    for i, r in enumerate(roots):
        e = r.expression()
        assert isinstance(e, sp.CRootOf)
        assert e == sp.CRootOf(ST**3 - 3 * ST + 1, i)
        assert e.is_real
    # the intervals are SymPy's own isolating intervals, in CRootOf's order
    expected = sp.Poly(ST**3 - 3 * ST + 1, ST).intervals()
    assert [(sp.Rational(r.lo.numerator, r.lo.denominator),
             sp.Rational(r.hi.numerator, r.hi.denominator)) for r in roots] == \
        [iv for iv, _ in expected]


def test_root_of_t2_plus_2t_minus_1_is_tan_pi_over_8():
    roots = RealRoot.all_of([-1, 2, 1])
    _check_isolating(roots, [-1, 2, 1])
    assert [r.expression() for r in roots] == [-1 - sp.sqrt(2), -1 + sp.sqrt(2)]
    assert roots[1].angle() == sp.pi / 4
    assert roots[1].angle_text() == "pi/4"
    assert roots[0].angle() == -3 * sp.pi / 4


def test_no_real_roots():
    assert RealRoot.all_of([1, 0, 1]) == []


def test_linear_root_is_rational():
    (root,) = RealRoot.all_of([-3, 2])
    assert root.expression() == sp.Rational(3, 2)
    assert root.lo <= Fraction(3, 2) <= root.hi
    assert root.angle() == 2 * sp.atan(sp.Rational(3, 2))


@pytest.mark.parametrize("coeffs", [[-2, 0, 1], [1, -3, 0, 1], [1, 4, 1]])
def test_refine_to_1e_minus_30(coeffs):
    width = Fraction(1, 10**30)
    for r in RealRoot.all_of(coeffs):
        lo, hi = r.refine(width)
        assert isinstance(lo, Fraction) and isinstance(hi, Fraction)
        assert 0 < hi - lo <= width
        assert r.lo <= lo < hi <= r.hi
        assert sign(coeffs, lo) * sign(coeffs, hi) == -1
        # a wide enough width leaves the interval alone
        assert r.refine(r.hi - r.lo) == (r.lo, r.hi)


def test_approximation_of_sqrt2_is_within_width():
    width = Fraction(1, 10**30)
    root = RealRoot.all_of([-2, 0, 1])[1]
    a = root.approximation(width)
    assert isinstance(a, Fraction)
    assert 0 < a - width
    assert (a - width) ** 2 < 2 < (a + width) ** 2
    neg = RealRoot.all_of([-2, 0, 1])[0].approximation(width)
    assert neg + width < 0
    assert (neg + width) ** 2 < 2 < (neg - width) ** 2


# ------------------------------------------------------------------ angle_of


def test_angle_of_recognises_rational_multiples_of_pi():
    assert angle_of(sp.sqrt(2) - 1) == sp.pi / 4
    assert angle_of(2 - sp.sqrt(3)) == sp.pi / 6
    assert angle_of(-sp.sqrt(3)) == -2 * sp.pi / 3
    assert angle_of(sp.Integer(1)) == sp.pi / 2
    assert angle_of(sp.Integer(0)) == 0


def test_angle_of_leaves_other_tangents_alone():
    assert angle_of(sp.sqrt(2)) == 2 * sp.atan(sp.sqrt(2))
    assert angle_of(sp.Rational(1, 2)) == 2 * sp.atan(sp.Rational(1, 2))
    t = sp.CRootOf(ST**3 - 3 * ST + 1, 1)
    assert angle_of(t) == 2 * sp.atan(t)


# ------------------------------------------------------------------ towers


_xy_small = st.lists(st.integers(-2, 2), min_size=1, max_size=4).map(
    lambda c: sp.Add(*[k * m for k, m in zip(c, [1, SX, SY, SX * SY], strict=False)]))


@settings(max_examples=30, deadline=None)
@given(st.integers(1, 3), st.integers(1, 3), st.data())
def test_random_rank_over_q_sqrt2_sqrt3_matches_sympy(n, m, data):
    from coopkin_sym.exact.quotient import Tower

    matrix = data.draw(st.lists(st.lists(_xy_small, min_size=m, max_size=m),
                                min_size=n, max_size=n))
    if data.draw(st.booleans()):           # a low-rank product, singular on purpose
        a = sp.Matrix(data.draw(st.lists(st.lists(_xy_small, min_size=1, max_size=1),
                                         min_size=n, max_size=n)))
        b = sp.Matrix(data.draw(st.lists(st.lists(_xy_small, min_size=m, max_size=m),
                                         min_size=1, max_size=1)))
        matrix = (a * b).applyfunc(sp.expand).tolist()
    tower = Tower([Quotient(X**2 - 2, 0), Quotient(Y**2 - 3, 1)])
    got = rank_modulo(flint_rows(matrix), m, tower)
    assert got == reference_rank(matrix, {SX: sp.sqrt(2), SY: sp.sqrt(3)})


def test_tower_refuses_moduli_that_are_not_univariate():
    from coopkin_sym.exact.quotient import Tower

    with pytest.raises(ValueError, match="univariate"):
        Tower([Quotient(X**2 + Y**2 - 1, 0)])


# --- gcd over the function field of a quadratic hypersurface, in lowest terms ----------
_XPY = flint.fmpz_mpoly_ctx.get(("x", "p", "y"), "degrevlex")
_small = st.integers(-4, 4)
_element = st.tuples(_small, _small, _small, _small)   # c0 + c1 p + c2 x + c3 x p


def _poly(c):
    x, p, _ = _XPY.gens()
    return c[0] + c[1] * p + c[2] * x + c[3] * x * p


@settings(max_examples=60, deadline=None)
@given(num=_element, den=_element, a=st.integers(1, 3), b=_small, c=st.integers(1, 5))
def test_smallest_fraction_is_the_same_element_with_a_denominator_free_of_x(num, den, a,
                                                                            b, c):
    x, p, _ = _XPY.gens()
    f = a * x**2 + b * x - c * (p**2 + 1)            # irreducible: -c(p^2+1) not a square
    q = Quotient(f, 0)
    n, d = _poly(num), _poly(den)
    if q.is_zero(d):
        return
    top, bottom = smallest_fraction(n, d, q)
    assert bottom.degrees()[0] == 0 and not bottom.is_zero()
    assert top.degrees()[0] < 2
    assert q.is_zero(top * d - bottom * n)            # the same element
    # no common factor left: the content over Z[p] of (top, bottom) is 1
    parts = [bottom] + [e for e in _coefficients_in_x(top) if not e.is_zero()]
    g = parts[0]
    for e in parts[1:]:
        g = g.gcd(e)
    assert g.is_constant()


def test_smallest_fraction_keeps_a_factor_too_large_to_take_and_stays_the_element(
        monkeypatch):
    import coopkin_sym.exact.quotient as quotient_module
    x, p, _ = _XPY.gens()
    q = Quotient(x**2 - p, 0)                          # x = sqrt(p)
    num, den = (p + 1) * (1 + x), (p + 1) * (x - 1)
    assert [str(e) for e in smallest_fraction(num, den, q)] == ["2*x + p + 1", "p - 1"]
    monkeypatch.setattr(quotient_module, "CONTENT_GCD_TERMS", 1)   # no gcd is taken
    top, bottom = smallest_fraction(num, den, q)
    assert bottom.degrees()[0] == 0 and int(bottom.leading_coefficient()) > 0
    assert q.is_zero(top * den - bottom * num)        # the same element
    assert divmod(bottom, p + 1)[1] == 0 and bottom != p - 1   # it kept p + 1


def _coefficients_in_x(e):
    from coopkin_sym.exact.substitution import coefficients_in
    return coefficients_in(e, 0)


@settings(max_examples=40, deadline=None)
@given(num=_element, den=_element, other=_element, b=_small, c=st.integers(1, 5))
def test_gcd_modulo_finds_a_planted_root_in_lowest_terms(num, den, other, b, c):
    from coopkin_sym.exact.quotient import gcd_modulo
    from coopkin_sym.exact.substitution import coefficients_in
    x, p, y = _XPY.gens()
    q = Quotient(x**2 + b * x - c * (p**2 + 1), 0)
    n, d, o = _poly(num), _poly(den), _poly(other)
    if q.is_zero(d) or q.is_zero(n) or q.is_zero((n + 1)**2 + o * d**2):
        return                                        # (the other factors share a root)
    root = d * y - n                                   # y = n/d
    f1 = root * (y**2 + o)
    f2 = root * (d * y + n + 1)
    common = gcd_modulo([coefficients_in(f1, 2), coefficients_in(f2, 2)], q)
    assert len(common) == 2                           # degree 1: y = -c0/c1
    c0, c1 = smallest_fraction(*common, q)
    assert c1.degrees()[0] == 0
    assert q.is_zero(c0 * d + c1 * n)                 # -c0/c1 = n/d
