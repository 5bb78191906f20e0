"""Fraction-free Gauss-Jordan elimination on matrices of integer polynomials.

Matrices are lists of rows of python-flint ``fmpz_mpoly`` (one context). The
elimination is "primitive": a row is updated only when it has a nonzero entry in the
pivot column, as ``(p/g) row_i - (a/g) row_r`` with ``g = gcd(p, a)``, and every row
is then divided by the gcd of its entries. Coefficients and degrees stay small, and
everything is exact: this is elimination over the fraction field ``Q(x)`` done inside
``Z[x]``.

With no variables (a rational configuration) the work goes to flint's ``fmpz_mat``.

A *reduced row* here is the primitive integer-polynomial multiple of a row of the
reduced row echelon form over the fraction field, with a positive leading coefficient
in its pivot entry: unique for a given row space, so equal subspaces give equal
matrices.

Example
-------
>>> import flint
>>> ctx = flint.fmpz_mpoly_ctx.get(("L",), "degrevlex")
>>> (L,) = ctx.gens()
>>> rows = [[L, 2 * L, ctx.constant(0)], [ctx.constant(1), ctx.constant(2), L]]
>>> rank(rows)
2
>>> [[str(e) for e in v] for v in nullspace(rows)]
[['2', '-1', '0']]
"""

from __future__ import annotations

import random
from collections.abc import Callable, Sequence

import flint

from coopkin_sym.errors import ArgumentError
from coopkin_sym.exact.deadline import check, give_up, remaining
from coopkin_sym.exact.sizes import coefficient_bits, determinant_terms

Poly = flint.fmpz_mpoly
Row = list[Poly]


def _cheaper(p: Poly, best: list) -> bool:
    """Whether ``p`` is a cheaper pivot than ``best[0]``: by total degree, then terms,
    then coefficient bits (``best[1]`` keeps the bits of ``best[0]`` once counted: they
    are counted only to break a tie)."""
    q = best[0]
    key, best_key = (p.total_degree(), len(p)), (q.total_degree(), len(q))
    if key != best_key:
        return key < best_key
    if best[1] is None:
        best[1] = coefficient_bits(q)
    return coefficient_bits(p) < best[1]


#: The most terms of both sides of a gcd taken only to shrink a row (its content, or the
#: common part of two entries in :func:`combine`) when a caller bounds it: flint cannot
#: interrupt a gcd, and one between two such polynomials can take minutes. Above it the
#: row keeps its factor (the same span: every rank stays right).
CONTENT_GCD_TERMS = 20_000

#: Under a time bound, such a gcd of two polynomials of ``w`` term-bits each (terms
#: times coefficient bits, the smaller side) is taken to need about
#: ``(w / CONTENT_GCD_RATE)^2`` seconds (measured here: 9,800 terms of 6,700 bits in
#: two variables, 3 s); one that would not end in the time left is not taken.
CONTENT_GCD_RATE = 20_000_000

#: The most terms (a bound from degrees) of the minors of a nullspace by Cramer's rule;
#: above it elimination, which checks the time bound between its steps, decides.
MINORS_TERMS = 100_000

#: Polynomials with fewer terms are never weighed (their gcds take milliseconds).
WEIGHED_TERMS = 500


def gcd_fits(a: Poly, b: Poly, max_terms: int | None) -> bool:
    """Whether a gcd of ``a`` and ``b`` taken only to shrink a row is taken: always
    without ``max_terms``; else unless both sides have more terms, or it would outlast
    the time left under a bound."""
    if max_terms is None:
        return True
    if min(len(a), len(b)) > max_terms:
        return False
    return not _outlasts(a, b)


def _outlasts(a: Poly, b: Poly) -> bool:
    """Whether a gcd of ``a`` and ``b`` would outlast the time left under a bound (see
    :data:`CONTENT_GCD_RATE`; small ones never do)."""
    if min(len(a), len(b)) < WEIGHED_TERMS:
        return False
    left = remaining()
    if left is None:
        return False
    # the smaller side is weighed first: when it fits, the larger need not be weighed
    return all((len(p) * coefficient_bits(p) / CONTENT_GCD_RATE) ** 2 > max(left, 0.0)
               for p in sorted((a, b), key=len))


def primitive(row: Sequence[Poly], max_terms: int | None = None) -> Row:
    """``row`` divided by the gcd of its entries, its first nonzero entry made to have
    a positive leading coefficient; a zero row is returned unchanged. With
    ``max_terms``: a gcd whose two sides both have more terms, or that would outlast
    the time left under a bound (:data:`CONTENT_GCD_RATE`), is not taken, and the row
    is returned as it is (a multiple of its primitive part).

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
    >>> (x,) = ctx.gens()
    >>> [str(e) for e in primitive([-2 * x, 4 * x**2])]
    ['1', '-2*x']
    >>> [str(e) for e in primitive([2 * x + 2, 2 * x**2 + 2], max_terms=1)]
    ['2*x + 2', '2*x^2 + 2']
    """
    g = None
    # the smallest entries first: the gcd only shrinks, so each later gcd has a small
    # polynomial on one side (and a constant one ends it)
    for e in sorted((e for e in row if not e.is_zero()), key=len):
        if g is not None and not gcd_fits(g, e, max_terms):
            return list(row)
        g = e if g is None else g.gcd(e)
        if g.is_one():
            break
    if g is None:
        return list(row)
    first = next(e for e in row if not e.is_zero())
    if (int(first.leading_coefficient()) < 0) != (int(g.leading_coefficient()) < 0):
        g = -g
    if g.is_one():
        return list(row)
    return [e / g for e in row]


def _is_zero_row(row: Sequence[Poly]) -> bool:
    return all(e.is_zero() for e in row)


def combine(target: Sequence[Poly], pivot_row: Sequence[Poly], col: int,
            reduce_row: Callable[[list[Poly]], list[Poly]] | None = None,
            max_terms: int | None = None) -> Row:
    """The one row update of every elimination of the package: ``target`` with its
    entry in ``col`` cleared by ``pivot_row``, as ``(p/g) target - (a/g) pivot_row``
    with ``p``, ``a`` the two entries and ``g = gcd(p, a)``, reduced by ``reduce_row``
    (in a quotient ring) and made primitive. The entry ``a`` must be nonzero. With
    ``max_terms``: no gcd between two polynomials both over that many terms
    (``g = 1``, and see :func:`primitive`).

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("t",), "degrevlex")
    >>> (t,) = ctx.gens()
    >>> one = ctx.constant(1)
    >>> [str(e) for e in combine([t, 2 * one], [t**2, t], 0)]
    ['0', '1']
    """
    a, p = target[col], pivot_row[col]
    if not gcd_fits(p, a, max_terms):
        pg, ag = p, a
    else:
        g = p.gcd(a)
        pg, ag = p / g, a / g
    if max_terms is None:
        out = [pg * x - ag * y for x, y in zip(target, pivot_row, strict=True)]
    else:       # under a bound: between two products of large entries, the bound is read
        out = []
        for x, y in zip(target, pivot_row, strict=True):
            check("an elimination modulo a polynomial")
            out.append(pg * x - ag * y)
    return primitive(reduce_row(out) if reduce_row is not None else out, max_terms)


def _eliminate_checked(target: Row, pivot_row: Row, col: int) -> Row:
    check("an exact elimination")
    return combine(target, pivot_row, col)


def gauss_jordan(
    rows: Sequence[Sequence[Poly]],
    ncols: int,
    column_order: Sequence[int] | None = None,
    canonical: bool = True,
    reduce: bool = True,
) -> tuple[list[Row], list[int]]:
    """Fraction-free Gauss-Jordan elimination.

    Parameters
    ----------
    rows
        The matrix, a list of rows of ``fmpz_mpoly``.
    ncols
        Number of columns (needed when ``rows`` is empty).
    column_order
        With ``canonical``, the order in which columns are taken as pivots; the result
        is then the reduced row echelon form for the columns permuted into that order
        (as reduced rows, see the module docstring). Default: natural order.
    canonical
        If false, any nonzero entry may be the pivot (the cheapest is taken): same row
        space and rank, pivot columns not canonical. Faster on big symbolic matrices.
    reduce
        If false, only rows below the pivots are eliminated (enough for a rank).

    Returns
    -------
    (reduced rows, pivot columns), zero rows dropped, in pivot order.
    """
    order = list(range(ncols)) if column_order is None else list(column_order)
    work = [primitive(r) for r in rows if not _is_zero_row(r)]
    if not work:
        return [], []
    nvars = work[0][0].context().nvars()
    if nvars == 0 and canonical:
        return _integer_rref(work, ncols, order)
    done: list[tuple[Row, int]] = []
    while work:
        check("an exact elimination")
        best = None
        cols = order if canonical else range(ncols)
        for c in cols:
            for i, r in enumerate(work):
                e = r[c]
                if not e.is_zero() and (best is None or _cheaper(e, best)):
                    best = [e, None, i, c]
            if canonical and best is not None:
                break
        if best is None:
            break
        _, _, i, c = best
        prow = work.pop(i)
        work = [_eliminate_checked(r, prow, c) if not r[c].is_zero() else r for r in work]
        work = [r for r in work if not _is_zero_row(r)]
        if reduce:
            done = [(_eliminate_checked(r, prow, c) if not r[c].is_zero() else r, pc)
                    for r, pc in done]
        done.append((prow, c))
    if canonical:
        rank_of = {c: k for k, c in enumerate(order)}
        done.sort(key=lambda rc: rank_of[rc[1]])
    return [_pivot_positive(primitive(r), c) for r, c in done], [c for _, c in done]


def _pivot_positive(row: Row, pivot: int) -> Row:
    """``row`` or ``-row``, whichever has a positive leading coefficient at ``pivot``."""
    if int(row[pivot].leading_coefficient()) < 0:
        return [-e for e in row]
    return row


def _integer_rref(rows: list[Row], ncols: int, order: list[int]) -> tuple[list[Row], list[int]]:
    ctx = rows[0][0].context()
    m = flint.fmpz_mat([[int(r[c].coeffs()[0]) if not r[c].is_zero() else 0 for c in order]
                        for r in rows])
    reduced, _den, rk = m.rref()
    out_rows, pivots = [], []
    for i in range(rk):
        vals = [int(reduced[i, j]) for j in range(ncols)]
        row = [ctx.constant(0)] * ncols
        for j, c in enumerate(order):
            row[c] = ctx.constant(vals[j])
        pivots.append(order[next(j for j, v in enumerate(vals) if v)])
        out_rows.append(_pivot_positive(primitive(row), pivots[-1]))
    return out_rows, pivots


def rank(rows: Sequence[Sequence[Poly]], ncols: int | None = None) -> int:
    """Rank over the fraction field.

    Examples
    --------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("t",), "degrevlex")
    >>> (t,) = ctx.gens()
    >>> rank([[t, t**2], [ctx.constant(1), t]])
    1
    """
    if not rows:
        return 0
    n = len(rows[0]) if ncols is None else ncols
    return len(gauss_jordan(rows, n, canonical=False, reduce=False)[1])


def nullspace(rows: Sequence[Sequence[Poly]], ncols: int | None = None,
              zctx=None) -> list[Row]:
    """A basis of the right nullspace over the fraction field, as primitive
    polynomial vectors (one per free column).

    ``ncols`` and the context ``zctx`` are needed when ``rows`` is empty.
    """
    if rows:
        ncols = len(rows[0]) if ncols is None else ncols
        zctx = rows[0][0].context() if zctx is None else zctx
    if ncols is None or zctx is None:
        raise ArgumentError("nullspace of an empty matrix needs ncols and zctx")
    reduced, pivots = gauss_jordan(rows, ncols, canonical=False, reduce=True)
    pivot_set = set(pivots)
    out = []
    for f in range(ncols):
        if f not in pivot_set:
            check("a nullspace")
            out.append(primitive(_kernel_vector(reduced, pivots, f, ncols, zctx)))
    return out


def _kernel_vector(reduced: list[Row], pivots: list[int], free: int, ncols: int,
                   zctx) -> Row:
    """The nullspace vector of a Gauss-Jordan form for the free column ``free``:
    ``free`` set to the lcm of the pivots involved, pivot coordinates solved."""
    involved = [(r, c) for r, c in zip(reduced, pivots, strict=True) if not r[free].is_zero()]
    scale = zctx.constant(1)
    for r, c in involved:
        check("a nullspace vector")
        if _outlasts(scale, r[c]):   # flint cannot interrupt the gcd: not started
            give_up("a nullspace vector (a gcd that would outlast the time left)")
        scale = scale * r[c] / scale.gcd(r[c])
    v = [zctx.constant(0)] * ncols
    v[free] = scale
    for r, c in involved:
        v[c] = -(r[free] * (scale / r[c]))
    return v


# a prime for choosing pivot rows at a random point (choice only: results are verified)
_PRIME = 2**61 - 1
_rng = random.Random(20260522)


def independent_rows(rows: Sequence[Sequence[Poly]], ncols: int) -> list[int]:
    """Indices of rows independent at a random integer point, modulo a prime.

    Cheaper rows (by entry size) are preferred. The count is a certified lower bound
    on the rank over the fraction field (a rank modulo p at a point never exceeds the
    generic rank); the choice itself is only a guess that callers verify.
    """
    if not rows:
        return []
    nvars = rows[0][0].context().nvars()
    point = [_rng.randrange(1, 2**20) for _ in range(nvars)]
    cost = [sum(len(e) for e in r) for r in rows]
    order = sorted(range(len(rows)), key=lambda i: cost[i])
    values = [[int(e(*point)) % _PRIME if not e.is_zero() else 0 for e in rows[i]]
              for i in order]
    # pivot columns of the transposed matrix's echelon form = independent rows
    reduced, rk = flint.nmod_mat(values, _PRIME).transpose().rref()
    chosen, col = [], 0
    for i in range(rk):
        while int(reduced[i, col]) == 0:
            col += 1
        chosen.append(order[col])
    return sorted(chosen)


def ranks_at_random_point(rows: Sequence[Sequence[Poly]],
                          blocks: Sequence[Sequence[int]]) -> list[int]:
    """The rank of each block of columns of ``rows`` at one random integer point,
    modulo a prime: each a certified lower bound on the block's rank over the fraction
    field (a rank at a point, modulo p, never exceeds the generic rank).

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
    >>> (x,) = ctx.gens()
    >>> ranks_at_random_point([[x, x], [x, x + 1]], [[0, 1], [0]])
    [2, 1]
    """
    if not rows:
        return [0] * len(blocks)
    nvars = rows[0][0].context().nvars()
    point = [_rng.randrange(1, 2**20) for _ in range(nvars)]
    values = [[int(e(*point)) % _PRIME if not e.is_zero() else 0 for e in row]
              for row in rows]
    return [flint.nmod_mat([[row[c] for c in cols] for row in values], _PRIME).rank()
            if cols else 0 for cols in blocks]


def nullspace_rref(rows: Sequence[Sequence[Poly]], ncols: int, zctx,
                   column_order: Sequence[int] | None = None) -> tuple[list[Row], list[int]]:
    """The reduced echelon basis of the right nullspace (as reduced rows, see the
    module docstring), and its pivot columns, for the columns taken in
    ``column_order``.

    The reduced echelon basis of ``N(M)`` comes straight from the elimination of
    ``M`` with the columns in reverse order: its free columns are the basis's pivots.
    Only rows independent at a random point are eliminated; the others are then
    checked exactly against the basis (and everything is redone on all rows in the
    rare case a check fails), so the result is exact.

    Examples
    --------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("L",), "degrevlex")
    >>> (L,) = ctx.gens()
    >>> basis, pivots = nullspace_rref([[ctx.constant(0), L, L]], 3, ctx)
    >>> [[str(e) for e in v] for v in basis], pivots
    ([['1', '0', '0'], ['0', '1', '-1']], [0, 1])
    """
    order = list(range(ncols)) if column_order is None else list(column_order)
    rows = [list(r) for r in rows if not _is_zero_row(r)]
    chosen = independent_rows(rows, ncols)
    if len(chosen) == ncols:
        return [], []
    subset = [rows[i] for i in chosen]
    basis, pivots = _canonical_nullspace(subset, ncols, zctx, order)
    others = [r for i, r in enumerate(rows) if i not in set(chosen)]
    if not all(_dot(r, v).is_zero() for r in others for v in basis):
        basis, pivots = _canonical_nullspace(rows, ncols, zctx, order)
    return basis, pivots


def determinant(m: Sequence[Sequence[Poly]]) -> Poly:
    """Fraction-free (Bareiss) determinant of a square polynomial matrix.

    Examples
    --------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("t",), "degrevlex")
    >>> (t,) = ctx.gens()
    >>> str(determinant([[t, ctx.constant(1)], [ctx.constant(1), t]]))
    't^2 - 1'
    """
    a = [list(r) for r in m]
    n = len(a)
    zctx = a[0][0].context()
    prev = zctx.constant(1)
    sign = 1
    for k in range(n - 1):
        check("a determinant")
        if a[k][k].is_zero():
            swap = next((i for i in range(k + 1, n) if not a[i][k].is_zero()), None)
            if swap is None:
                return zctx.constant(0)
            a[k], a[swap] = a[swap], a[k]
            sign = -sign
        for i in range(k + 1, n):
            check("a determinant")
            for j in range(k + 1, n):
                a[i][j] = (a[i][j] * a[k][k] - a[i][k] * a[k][j]) / prev
        prev = a[k][k]
    return a[n - 1][n - 1] if sign > 0 else -a[n - 1][n - 1]


def _minors_nullspace(rows: list[Row], ncols: int, zctx, order: list[int]):
    """The reduced echelon nullspace basis of a few independent rows from maximal
    minors (Cramer's rule), or None when this route does not apply.

    The pivot columns ``P`` are chosen at a random point modulo a prime (greedily in
    reversed column order); a nonzero minor there proves ``det(R_P) != 0``. Each free
    column ``f`` gives ``det(R_P) e_f - sum_c det(R_P[c <- f]) e_c``. The result is
    kept only if it is exactly in reduced echelon form for ``order`` (then it is the
    unique reduced echelon basis); no entry ever holds a fraction.
    """
    k = len(rows)
    if k == 0 or k > 4 or rows[0][0].context().nvars() == 0:
        return None
    nvars = rows[0][0].context().nvars()
    point = [_rng.randrange(1, 2**20) for _ in range(nvars)]
    rev = order[::-1]
    values = [[int(r[c](*point)) % _PRIME if not r[c].is_zero() else 0 for c in rev]
              for r in rows]
    reduced, rk = flint.nmod_mat(values, _PRIME).rref()
    if rk < k:
        return None
    pivots, col = [], 0
    for i in range(rk):
        while int(reduced[i, col]) == 0:
            col += 1
        pivots.append(rev[col])
    if determinant_terms([[r[c] for c in pivots] for r in rows]) > MINORS_TERMS:
        return None   # the minors could be too large to compute uninterrupted
    d = determinant([[r[c] for c in pivots] for r in rows])
    position = {c: i for i, c in enumerate(order)}
    basis, free = [], []
    for f in order:
        if f in pivots:
            continue
        check("a nullspace")
        v = [zctx.constant(0)] * ncols
        v[f] = d
        for i, c in enumerate(pivots):
            cols = [f if j == i else pc for j, pc in enumerate(pivots)]
            v[c] = -determinant([[r[cc] for cc in cols] for r in rows])
        if any(not v[c].is_zero() and position[c] < position[f] for c in pivots):
            return None  # not the reduced echelon form: let elimination decide
        basis.append(_pivot_positive(primitive(v), f))
        free.append(f)
    return basis, free


def _canonical_nullspace(rows: list[Row], ncols: int, zctx, order: list[int]):
    """The reduced echelon nullspace basis by the cheapest exact route: maximal minors
    for a few rows, the elimination of ``rows`` in reversed column order (few rows),
    or any nullspace basis brought to reduced echelon form (few basis vectors)."""
    by_minors = _minors_nullspace(rows, ncols, zctx, order)
    if by_minors is not None:
        return by_minors
    if len(rows) <= ncols - len(rows):
        return _nullspace_from(rows, ncols, zctx, order)
    basis = nullspace(rows, ncols, zctx)
    if not basis:
        return [], []
    return gauss_jordan(basis, ncols, column_order=order)


def _dot(a: Sequence[Poly], b: Sequence[Poly]) -> Poly:
    acc = None
    for x, y in zip(a, b, strict=True):
        if not x.is_zero() and not y.is_zero():
            acc = x * y if acc is None else acc + x * y
    return acc if acc is not None else a[0].context().constant(0)


def _nullspace_from(rows: list[Row], ncols: int, zctx, order: list[int]):
    reduced, pivots = gauss_jordan(rows, ncols, column_order=order[::-1]) if rows else (
        [], [])
    pivot_set = set(pivots)
    free = [f for f in order if f not in pivot_set]
    basis = [_pivot_positive(primitive(_kernel_vector(reduced, pivots, f, ncols, zctx)), f)
             for f in free]
    return basis, free


def matmul(a: Sequence[Sequence[Poly]], b: Sequence[Sequence[Poly]], zctx) -> list[Row]:
    """Product of two polynomial matrices given as row lists."""
    if not a:
        return []
    inner = len(b)
    ncols = len(b[0]) if b else 0
    out = []
    for row in a:
        check("a matrix product")
        new = []
        for j in range(ncols):
            s = zctx.constant(0)
            for k in range(inner):
                if not row[k].is_zero() and not b[k][j].is_zero():
                    s = s + row[k] * b[k][j]
            new.append(s)
        out.append(new)
    return out
