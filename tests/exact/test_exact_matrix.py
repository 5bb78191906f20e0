"""Contract tests of the exact-matrix facade: one test body over every domain.

Each domain is a ring of integer polynomials and a map to a field SymPy computes in:
``Q`` (no variables), ``Q(x)``, ``Q(x, y)``, ``Q(sqrt 2)`` (``Z[x]/(x^2 - 2)``), the
function field of the hyperbola ``x y = 1`` (``Z[x, y]/(x y - 1)``, read as ``y = 1/x``
over ``Q(x)``) and ``Q(sqrt 2, sqrt 3)`` (a tower). Ranks, nullspaces and determinants
of seeded random matrices, many of them rank-deficient on purpose (products of thin
factors, rows multiplied by the modulus), are checked against SymPy's
``DomainMatrix`` over that field; nullspace vectors satisfy ``M v = 0`` in the domain.
The batched modular ranks are checked against SymPy over ``GF(p)``.
"""

from __future__ import annotations

import random
from dataclasses import dataclass

import flint
import numpy as np
import pytest
import sympy as sp
from sympy.polys.matrices import DomainMatrix

from coopkin_sym.errors import ArgumentError
from coopkin_sym.exact.matrix import POLYNOMIALS, PolyMatrix, batch_ranks
from coopkin_sym.exact.quotient import Quotient, Tower
from coopkin_sym.exact.sympy_bridge import poly_to_sympy


@dataclass
class Case:
    name: str
    names: tuple[str, ...]
    domain: object
    values: dict            # symbol name -> SymPy value: the map to the reference field
    modulus: str | None     # a polynomial that is zero in the domain (text for SymPy)
    exact_det: bool         # reduction keeps the determinant itself (monic modulus)


def _cases() -> list[Case]:
    out = [Case("Q", (), None, {}, None, True),
           Case("Q(x)", ("x",), None, {}, None, True),
           Case("Q(x, y)", ("x", "y"), None, {}, None, True)]
    ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
    (x,) = ctx.gens()
    out.append(Case("Q(sqrt 2)", ("x",), Quotient(x**2 - 2, 0),
                    {"x": sp.sqrt(2)}, "x**2 - 2", True))
    ctx2 = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    x2, y2 = ctx2.gens()
    out.append(Case("Q(x)[y]/(xy - 1)", ("x", "y"), Quotient(x2 * y2 - 1, 1),
                    {"y": 1 / sp.Symbol("x")}, "x*y - 1", False))
    out.append(Case("Q(sqrt 2, sqrt 3)", ("x", "y"),
                    Tower([Quotient(x2**2 - 2, 0), Quotient(y2**2 - 3, 1)]),
                    {"x": sp.sqrt(2), "y": sp.sqrt(3)}, "x**2 - 2", True))
    return out


CASES = _cases()


def _context(case: Case):
    return flint.fmpz_mpoly_ctx.get(case.names, "degrevlex")


def _random_poly(ctx, rng: random.Random, terms: int = 2, degree: int = 2):
    n = ctx.nvars()
    out = ctx.constant(rng.randint(-3, 3))
    for _ in range(terms if n else 0):
        mon = tuple(rng.randint(0, degree) for _ in range(n))
        out += ctx.from_dict({mon: rng.randint(-3, 3)})
    return out


def _matrices(case: Case, count: int = 12):
    """Seeded random matrices: full ones, products of thin factors (rank at most k),
    and, in a quotient, rows with a multiple of the modulus added (rank drops there
    only)."""
    ctx = _context(case)
    rng = random.Random(sum(map(ord, case.name)))
    for i in range(count):
        m, n = rng.randint(1, 4), rng.randint(1, 4)
        if i % 3 == 0:
            rows = [[_random_poly(ctx, rng) for _ in range(n)] for _ in range(m)]
        else:
            k = rng.randint(0, min(m, n))
            b = [[_random_poly(ctx, rng, 1, 1) for _ in range(k)] for _ in range(m)]
            c = [[_random_poly(ctx, rng, 1, 1) for _ in range(n)] for _ in range(k)]
            rows = [[sum((b[r][j] * c[j][s] for j in range(k)), ctx.constant(0))
                     for s in range(n)] for r in range(m)]
        if case.modulus is not None and i % 2 == 1 and m > 1:
            f = ctx.from_dict({mon: int(c) for mon, c in sp.Poly(
                sp.sympify(case.modulus), *sp.symbols(case.names)).as_dict().items()})
            rows[-1] = [e + f * _random_poly(ctx, rng, 1, 1) for e in rows[0]]
        yield rows, n


def _reference(case: Case, rows, n) -> DomainMatrix:
    syms = sp.symbols(case.names) if case.names else ()
    ring_syms = {s.name: s for s in syms}
    values = {ring_syms[k]: v for k, v in case.values.items()}
    entries = [[sp.expand(poly_to_sympy_plain(e, syms).subs(values)) for e in r]
               for r in rows]
    return DomainMatrix.from_list_sympy(len(rows), n, entries, extension=True).to_field()


def poly_to_sympy_plain(p, syms):
    if not syms:
        return sp.Integer(int(p.coeffs()[0])) if not p.is_zero() else sp.Integer(0)
    return sp.Add(*[sp.Integer(int(c)) * sp.Mul(*[s**int(e) for s, e in zip(syms, mon,
                                                                                strict=True)])
                    for mon, c in p.to_dict().items()])


def _matrix(case: Case, rows, n) -> PolyMatrix:
    return PolyMatrix(rows, n, case.domain or POLYNOMIALS, _context(case))


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_rank_agrees_with_sympy(case):
    seen = set()
    for rows, n in _matrices(case):
        ours = _matrix(case, rows, n).rank()
        assert ours == _reference(case, rows, n).rank()
        seen.add(ours < min(len(rows), n))
    assert seen == {True, False}          # both full and deficient ranks were met


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_nullspace_is_a_basis_of_the_kernel(case):
    for rows, n in _matrices(case):
        m = _matrix(case, rows, n)
        basis = m.nullspace()
        assert len(basis) == n - _reference(case, rows, n).rank()
        assert all(m.is_zero_vector(v) for v in basis)
        if basis:                          # independent over the field (SymPy's rank)
            assert _reference(case, basis, n).rank() == len(basis)


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_determinant_agrees_with_sympy(case):
    for rows, n in _matrices(case, 16):
        if len(rows) != n:
            continue
        ours = _matrix(case, rows, n).det()
        ref = _as_sympy(_reference(case, rows, n).det(), case, rows, n)
        got = _value(case, ours)
        assert (got == 0) == (ref == 0)
        if case.exact_det:
            assert sp.simplify(got - ref) == 0


def _as_sympy(element, case, rows, n):
    return sp.simplify(_reference(case, rows, n).domain.to_sympy(element))


def _value(case: Case, p) -> sp.Expr:
    """A polynomial of the domain mapped to the reference field, simplified."""
    syms = sp.symbols(case.names) if case.names else ()
    values = {s: case.values[s.name] for s in syms if s.name in case.values}
    return sp.simplify(sp.expand(poly_to_sympy_plain(p, syms).subs(values)))


def test_the_domains_differ_where_they_should():
    """The same matrix has rank 2 over Q(x) and rank 1 modulo x^2 - 2."""
    ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
    (x,) = ctx.gens()
    m = PolyMatrix([[x, ctx.constant(2)], [ctx.constant(1), x]], 2)
    assert m.rank() == 2
    assert m.over(Quotient(x**2 - 2, 0)).rank() == 1
    (v,) = m.over(Quotient(x**2 - 2, 0)).nullspace()
    assert m.over(Quotient(x**2 - 2, 0)).is_zero_vector(v)     # (x, -1) up to a factor
    assert not m.is_zero_vector(v)                              # not a kernel over Q(x)


def test_rref_and_echelon_nullspace_only_over_polynomials():
    ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
    (x,) = ctx.gens()
    m = PolyMatrix([[x, 2 * x, ctx.constant(0)]], 3)
    assert m.rref()[1] == [0]
    basis, pivots = m.nullspace_rref()
    assert pivots == [0, 2] and len(basis) == 2
    with pytest.raises(ArgumentError, match="over Q\\(x\\) only"):
        m.over(Quotient(x**2 - 2, 0)).rref()


def test_empty_and_ragged_matrices():
    ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
    empty = PolyMatrix([], 3, context=ctx)
    assert empty.rank() == 0 and len(empty.nullspace()) == 3
    assert str(PolyMatrix([], 0, context=ctx).det()) == "1"
    with pytest.raises(ArgumentError, match="3 entries"):
        PolyMatrix([[ctx.constant(1)]], 3)


@pytest.mark.parametrize("p", [7, 101, 2**31 - 1])
def test_batch_ranks_agree_with_sympy_over_gf_p(p):
    from sympy.polys.domains import GF

    rng = np.random.default_rng(p)
    for _ in range(10):
        batch, m, n = 6, int(rng.integers(1, 5)), int(rng.integers(1, 5))
        k = int(rng.integers(0, min(m, n) + 1))
        mats = rng.integers(-50, 50, (batch, m, k)) @ rng.integers(-50, 50, (batch, k, n))
        ours = batch_ranks(mats.astype(np.int64), p)
        for b in range(batch):
            ref = DomainMatrix([[GF(p)(int(v)) for v in row] for row in mats[b]],
                               (m, n), GF(p)).rank()
            assert ours[b] == ref
        assert all(r <= k for r in ours)


def test_reference_helper_matches_the_bridge():
    """The test's own conversion agrees with the package's SymPy bridge."""
    ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    x, y = ctx.gens()
    p = 3 * x**2 * y - y + 5
    syms = sp.symbols("x y")
    assert sp.expand(poly_to_sympy_plain(p, syms) - poly_to_sympy(
        p, _ring(("x", "y")), dict(zip(("x", "y"), syms, strict=True)))) == 0


def _ring(names):
    from coopkin_sym.exact.ring import Ring

    return Ring(list(names))


def test_poly_to_sympy_builds_the_canonical_expression():
    """The direct assembly gives exactly what SymPy's own Add/Mul give (equal, same
    hash, same srepr) on random polynomials over Z and Q: coefficients 1, -1, 1/2,
    -1/2 (SymPy's own classes), huge ones, symbols with and without assumptions, up to
    300 terms."""
    import random

    import flint
    import sympy as sp

    from coopkin_sym.exact.ring import Ring
    from coopkin_sym.exact.sympy_bridge import poly_to_sympy, rational_to_sympy

    names = ("L", "t_q1", "t_q2", "d3", "t_q10", "a", "B", "t_f1_2", "t_f10_2", "x_1")
    ring = Ring(names, ("t_q1", "t_q2", "t_q10", "t_f1_2", "t_f10_2"))
    symbols = {n: sp.Symbol(n, positive=True) if n in ("L", "a") else
               sp.Symbol(n, real=True) if n.startswith("t_") else sp.Symbol(n)
               for n in names}
    rng = random.Random(5)
    for trial in range(515):
        ctx = ring.zctx if trial % 2 else ring.qctx
        terms = {}
        used = rng.sample(range(len(names)), rng.randint(1, len(names)))
        for _ in range(rng.randint(0, 7 if trial < 510 else 300)):
            monom = tuple(rng.choice([0, 0, 1, 2, 5]) if k in used else 0
                          for k in range(len(names)))
            terms[monom] = (rng.choice([1, -1, 2, -3, 12, 2**70, -(3**50)]) if trial % 2
                            else flint.fmpq(rng.choice([1, -1, rng.randint(-9, 9)]),
                                            rng.choice([1, 2, rng.randint(1, 6)])))
        p = ctx.from_dict({k: v for k, v in terms.items() if v != 0})
        slow = sp.Add(*[sp.Mul(rational_to_sympy(c), *[symbols[n] ** int(e) for n, e
                                                       in zip(names, m, strict=True) if e])
                        for m, c in p.to_dict().items()])
        fast = poly_to_sympy(p, ring, symbols)
        assert fast == slow and hash(fast) == hash(slow)
        assert sp.srepr(fast) == sp.srepr(slow)
