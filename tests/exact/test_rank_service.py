"""Contract test of the rank service: one test body over every domain of the facade.

:func:`~coopkin_sym.exact.matrix.rank` and :func:`~coopkin_sym.exact.matrix.rank_triple`
are checked against SymPy's exact rank (``DomainMatrix`` over the field the domain
stands for, as SymPy's own ``polys/matrices/tests/test_xxm.py`` runs one body over its
representations) on random small integer and polynomial matrices drawn by hypothesis,
many rank-deficient on purpose (products of thin factors, a row repeated as a multiple
of another). The rank triple is checked with and without arm blocks (block-diagonal
joint columns) and through the arm-by-arm elimination.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction

import flint
import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from sympy.polys.matrices import DomainMatrix

from coopkin_sym.exact.matrix import (
    POLYNOMIALS,
    RATIONALS,
    SYMPY,
    PrimeField,
    rank,
    rank_triple,
)
from coopkin_sym.exact.quotient import Quotient, Tower


@dataclass
class Domain:
    """A domain of the facade and the SymPy field its ranks are checked in."""

    name: str
    names: tuple[str, ...]       # polynomial variables ((): numbers)
    domain: object
    values: dict                 # variable -> SymPy value (the map to the field)
    prime: int | None = None     # reference over GF(prime)
    fraction: Callable | None = None   # rows of halves of this type (over Q)
    batch: bool = False          # a NumPy batch over GF(prime)
    sympy_entries: bool = False  # rows of SymPy expressions (the values substituted)


def _domains() -> list[Domain]:
    (x,) = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex").gens()
    x2, y2 = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex").gens()
    return [
        Domain("Z", (), RATIONALS, {}),
        Domain("QQ", (), RATIONALS, {}, fraction=Fraction),
        Domain("QQ (flint)", (), RATIONALS, {}, fraction=flint.fmpq),
        Domain("QQ (SymPy)", (), RATIONALS, {}, fraction=sp.Rational),
        Domain("GF(7)", (), PrimeField(7), {}, prime=7),
        Domain("GF(2^61-1)", (), PrimeField(2**61 - 1), {}, prime=2**61 - 1),
        Domain("GF(101) batch", (), PrimeField(101), {}, prime=101, batch=True),
        Domain("Q(x)", ("x",), POLYNOMIALS, {}),
        Domain("Q(x, y)", ("x", "y"), POLYNOMIALS, {}),
        Domain("Z[x]/(x^2 - 2)", ("x",), Quotient(x**2 - 2, 0), {"x": sp.sqrt(2)}),
        Domain("Z[x, y]/(xy - 1)", ("x", "y"), Quotient(x2 * y2 - 1, 1),
               {"y": 1 / sp.Symbol("x")}),
        Domain("Z[x, y]/(x^2 - 2, y^2 - 3)", ("x", "y"),
               Tower([Quotient(x2**2 - 2, 0), Quotient(y2**2 - 3, 1)]),
               {"x": sp.sqrt(2), "y": sp.sqrt(3)}),
        Domain("SymPy Q", (), SYMPY, {}, fraction=sp.Rational, sympy_entries=True),
        Domain("SymPy Q(x, y)", ("x", "y"), SYMPY, {}, sympy_entries=True),
        Domain("SymPy Q(x), y = 1/(1 + x)", ("x", "y"), SYMPY,
               {"y": 1 / (1 + sp.Symbol("x"))}, sympy_entries=True),
        Domain("SymPy Q(x, sqrt(2))", ("x", "y"), SYMPY, {"y": sp.sqrt(2)},
               sympy_entries=True),
    ]


DOMAINS = _domains()

#: An entry: ``{exponents: coefficient}`` (the number itself when there is no variable).
_COEFF = st.integers(-3, 3)


def _entries(nvars: int):
    monomial = st.tuples(*[st.integers(0, 2)] * nvars)
    return st.dictionaries(monomial, _COEFF, max_size=2) if nvars else _COEFF


@st.composite
def matrices(draw, nvars: int):
    """A small matrix of entries (see :data:`_COEFF`), full or of low rank, and the
    number of object columns ``dim`` with arm blocks on the other columns."""
    m, n = draw(st.integers(1, 4)), draw(st.integers(1, 5))
    entries = _entries(nvars)
    if draw(st.booleans()):
        cells = [[draw(entries) for _ in range(n)] for _ in range(m)]
    else:                                   # a product of thin factors: rank <= k
        k = draw(st.integers(0, min(m, n) - 1 if min(m, n) > 1 else 0))
        b = [[draw(entries) for _ in range(k)] for _ in range(m)]
        c = [[draw(entries) for _ in range(n)] for _ in range(k)]
        cells = [[("prod", [(b[r][j], c[j][s]) for j in range(k)]) for s in range(n)]
                 for r in range(m)]
    if m > 1 and draw(st.booleans()):       # one row a multiple of another
        factor = draw(entries)
        cells[-1] = [("prod", [(factor, e)]) for e in cells[0]]
    dim = draw(st.integers(0, n))
    cut = draw(st.integers(dim, n))         # two arms: joint columns dim:cut and cut:n
    split = draw(st.integers(0, m))         # rows :split on the first arm, the rest on
    arms = [(list(range(split)), dim, cut), (list(range(split, m)), cut, n)]
    blocked = [[cell if j < dim or (i < split) == (j < cut) else 0
                for j, cell in enumerate(row)] for i, row in enumerate(cells)]
    return cells, blocked, n, dim, arms


def _build(cell, make, one):
    if isinstance(cell, tuple):
        total = 0 * one
        for a, b in cell[1]:
            total = total + _build(a, make, one) * _build(b, make, one)
        return total
    if isinstance(cell, int):
        return cell * one
    return make(cell)


def _rows(case: Domain, cells):
    """The cells in the domain's own entries, and as SymPy expressions."""
    if case.names:
        ctx = flint.fmpz_mpoly_ctx.get(case.names, "degrevlex")
        syms = sp.symbols(case.names)

        def make(d):
            return ctx.from_dict(d) if d else ctx.constant(0)

        def make_sympy(d):
            return sp.Add(*[c * sp.Mul(*[s**e for s, e in zip(syms, mon, strict=True)])
                            for mon, c in d.items()])

        ours = [[_build(c, make, ctx.constant(1)) for c in r] for r in cells]
        theirs = [[_build(c, make_sympy, sp.Integer(1)) for c in r] for r in cells]
        if case.sympy_entries:
            values = {sp.Symbol(k): v for k, v in case.values.items()}
            ours = [[sp.sympify(e).subs(values) for e in r] for r in theirs]
        return ours, theirs
    ours = [[_build(c, int, 1) for c in r] for r in cells]
    if case.fraction is not None:
        ours = [[case.fraction(e, 2) for e in r] for r in ours]
    return ours, [[sp.Rational(int(e.numerator), int(e.denominator)) if case.fraction else
                   sp.Rational(e) for e in r] for r in ours]


def _reference(case: Domain, entries, ncols: int) -> int:
    if not entries or ncols == 0:
        return 0
    if case.prime is not None:
        return DomainMatrix([[sp.GF(case.prime)(int(e)) for e in r] for r in entries],
                            (len(entries), ncols), sp.GF(case.prime)).rank()
    values = {sp.Symbol(k): v for k, v in case.values.items()}
    exprs = [[sp.expand(sp.sympify(e).subs(values)) for e in r] for r in entries]
    return DomainMatrix.from_list_sympy(len(entries), ncols, exprs,
                                        extension=True).to_field().rank()


def _ours(case: Domain, rows, ncols: int) -> int:
    if case.batch:
        batch = np.array([rows, rows[::-1]], dtype=np.int64).reshape(2, len(rows), ncols)
        got = rank(batch, None, case.domain).tolist()
        assert got[0] == got[1]
        return got[0]
    return rank(rows, ncols, case.domain)


def _columns(entries, start: int, stop: int, rows=None):
    return [entries[i][start:stop] for i in (range(len(entries)) if rows is None else rows)]


@pytest.mark.parametrize("case", DOMAINS, ids=lambda d: d.name)
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_rank_and_rank_triple_agree_with_sympy(case, data):
    cells, blocked, n, dim, arms = data.draw(matrices(len(case.names)))
    rows, entries = _rows(case, cells)
    assert _ours(case, rows, n) == _reference(case, entries, n)
    if case.batch:
        return
    expected = (_reference(case, entries, n), _reference(case, _columns(entries, 0, dim), dim),
                _reference(case, _columns(entries, dim, n), n - dim))
    assert rank_triple(rows, n, dim, case.domain).triple == expected
    # block-diagonal joint columns: ranked arm by arm, and eliminated arm by arm
    rows, entries = _rows(case, blocked)
    per_arm = tuple(_reference(case, _columns(entries, c0, c1, block), c1 - c0)
                    for block, c0, c1 in arms)
    expected = (_reference(case, entries, n), _reference(case, _columns(entries, 0, dim), dim),
                sum(per_arm), per_arm)
    assert rank_triple(rows, n, dim, case.domain, arms) == expected
    if case.names:
        assert rank_triple(rows, n, dim, case.domain, arms, by_arms=True) == expected


def test_every_domain_of_the_facade_is_covered():
    kinds = {type(d.domain).__name__ for d in DOMAINS}
    assert kinds == {"Rationals", "PrimeField", "Polynomials", "Quotient", "Tower",
                     "SympyEntries"}
    assert any(d.batch for d in DOMAINS)


def test_empty_matrices_have_rank_zero():
    ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
    for domain in (RATIONALS, PrimeField(7), POLYNOMIALS, SYMPY):
        assert rank([], 3, domain) == 0
        assert rank_triple([], 3, 2, domain, [([], 2, 3)]) == (0, 0, 0, (0,))
    assert rank([[ctx.constant(0)] * 2], 0) == 0
    assert rank(np.zeros((3, 2, 2), dtype=np.int64), None, PrimeField(5)).tolist() == [0] * 3


_X, _Y = sp.symbols("x y")
_DENOMINATORS = st.sampled_from([1, 1 + _X, 2 - _X * _Y, 1 + _X**2, 3 + _Y, _X])


@st.composite
def rational_function_matrices(draw):
    """A product ``B C`` of matrices of rational functions in ``x, y`` (each entry of
    ``B`` and ``C`` with its own denominator): the denominators of the product vary
    from entry to entry, and its rank is at most the inner size."""
    m, n, k = draw(st.integers(1, 4)), draw(st.integers(1, 4)), draw(st.integers(1, 4))

    def entry():
        terms = draw(st.dictionaries(st.tuples(st.integers(0, 2), st.integers(0, 2)),
                                     _COEFF, max_size=2))
        num = sp.Add(*[c * _X**a * _Y**b for (a, b), c in terms.items()])
        return num / draw(_DENOMINATORS)

    b = sp.Matrix(m, k, lambda i, j: entry())
    c = sp.Matrix(k, n, lambda i, j: entry())
    return (b * c).tolist(), n


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=rational_function_matrices())
def test_sympy_rational_functions_are_ranked_with_their_denominators(case):
    rows, n = case
    expected = DomainMatrix.from_list_sympy(len(rows), n, rows).to_field().rank()
    assert rank(rows, n, SYMPY) == expected
    assert rank_triple(rows, n, 1, SYMPY).q == expected


@st.composite
def many_arm_matrices(draw):
    """``Q``-shaped integer matrices with many arm blocks: object columns, then each
    arm's joint columns, each arm's rows zero outside its own joint columns; some arms
    without rows, some without joints, some rows on no arm, blocks often rank-deficient
    (a row the sum of two others)."""
    dim = draw(st.integers(1, 6))
    arms, rows, col = [], [], dim
    count = draw(st.integers(1, 12))
    sizes = [(draw(st.integers(0, 4)), draw(st.integers(0, 4))) for _ in range(count)]
    n = dim + sum(j for _, j in sizes)
    for nrows, joints in sizes:
        block = []
        for _ in range(nrows):
            row = [0] * n
            for c in list(range(dim)) + list(range(col, col + joints)):
                row[c] = draw(st.integers(-5, 5))
            block.append(len(rows))
            rows.append(row)
        if nrows >= 3 and draw(st.booleans()):
            rows[block[-1]] = [a + b for a, b in zip(rows[block[0]], rows[block[1]],
                                                     strict=True)]
        arms.append((block, col, col + joints))
        col += joints
    for _ in range(draw(st.integers(0, 3))):           # rows of contacts on no arm
        rows.append([draw(st.integers(-5, 5)) for _ in range(dim)] + [0] * (n - dim))
    return rows, n, dim, arms


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=many_arm_matrices(), halves=st.booleans())
def test_arm_by_arm_ranks_over_fields_equal_the_whole_matrix_ranks(case, halves):
    """Over Q and GF(p) the rank triple with arm blocks is found arm by arm; it equals
    the ranks of the whole matrix (flint, one elimination) and of its blocks."""
    rows, n, dim, arms = case
    if not rows:
        return
    if halves:
        rows = [[Fraction(e, 2 + (i % 3)) for e in r] for i, r in enumerate(rows)]
    whole = flint.fmpq_mat([[flint.fmpq(e.numerator, e.denominator) if halves else e
                             for e in r] for r in rows])
    blocks = tuple(flint.fmpq_mat([[whole[i, c] for c in range(c0, c1)] for i in block]
                                  ).rank() if block and c1 > c0 else 0
                   for block, c0, c1 in arms)
    obj = flint.fmpq_mat([[whole[i, c] for c in range(dim)] for i in range(len(rows))])
    assert rank_triple(rows, n, dim, RATIONALS, arms) == (whole.rank(), obj.rank(),
                                                         sum(blocks), blocks)
    if not halves:
        p = 7
        mod = flint.nmod_mat(rows, p)
        blocks = tuple(flint.nmod_mat([[rows[i][c] for c in range(c0, c1)] for i in block],
                                      p).rank() if block and c1 > c0 else 0
                       for block, c0, c1 in arms)
        obj = flint.nmod_mat([r[:dim] for r in rows], p)
        assert rank_triple(rows, n, dim, PrimeField(p), arms) == (
            mod.rank(), obj.rank(), sum(blocks), blocks)
