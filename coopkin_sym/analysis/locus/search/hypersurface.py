"""Candidate polynomials: for each matrix whose rank drop changes a number, random
combinations of its maximal minors (Cauchy-Binet), with constant pivots and contents
reduced, and the single minors that split a drop set into smaller ones.
"""

from __future__ import annotations

import itertools
from math import comb

import flint
import sympy as sp

from coopkin_sym.analysis.locus.algebra import (
    FACTOR_TERMS,
    vars_of,
)
from coopkin_sym.analysis.locus.context import SearchContext
from coopkin_sym.analysis.locus.search.components import note
from coopkin_sym.exact import elimination as el
from coopkin_sym.exact import matrix as exact_matrix
from coopkin_sym.exact.factoring import factor
from coopkin_sym.exact.matrix import POLYNOMIALS, PolyMatrix
from coopkin_sym.exact.quotient import Quotient
from coopkin_sym.exact.sizes import determinant_terms


# --- candidate polynomials -------------------------------------------------------------
def candidates(ctx: SearchContext, q_rows, quotient: Quotient | None = None
               ) -> dict[str, list]:
    """For each matrix whose rank drop changes a number, random combinations of its
    maximal minors (a few polynomials whose common zeros are the drop set); under
    ``content:<matrix>`` the polynomials rows were divided by (each one's zero set is a
    candidate on its own).

    With a ``quotient`` (``Z[x]/(f)``, ``f`` irreducible), the same on the family
    ``f = 0``: ranks over its function field, the minors at those ranks, every
    polynomial reduced modulo ``f`` (their common zeros with ``f`` are the drop set
    there)."""
    zctx = ctx.ring.zctx
    owners = [ctx.model.contacts[c].arm for c in ctx.row_contacts]
    dim = ctx.model.object_dim
    if quotient is not None:
        q_rows = [quotient.reduce_row(r) for r in q_rows]
    gt = [row[:dim] for row in q_rows]
    mats: dict[str, list] = {"HG^T": gt}
    a_rows = [gt[i] for i, o in enumerate(owners) if o is None]
    for arm, rows, d in arm_blocks(ctx, q_rows):
        mats[f"HD:{arm.name}"] = d
        dt = [list(col) for col in zip(*d, strict=True)]
        if quotient is None:
            y, _ = PolyMatrix(dt, len(rows), context=zctx).nullspace_rref()
        else:
            y = PolyMatrix(dt, len(rows), quotient, zctx).nullspace()
        if y:
            mats[f"Y:{arm.name}"] = y
        for v in y:
            acc = [zctx.constant(0)] * dim
            for vi, i in zip(v, rows, strict=True):
                if not vi.is_zero():
                    acc = [x + vi * g for x, g in zip(acc, gt[i], strict=True)]
            a_rows.append(acc)
    if a_rows:
        mats["A"] = a_rows
    out = {}
    for name, rows in mats.items():
        contents: list = []
        deep: list = []
        if quotient is not None:
            rows = [quotient.reduce_row(r) for r in rows]
        polys = _minor_combinations(rows, ctx, contents, deep, name, quotient)
        if quotient is not None:
            contents = [g for g in contents if not quotient.is_zero(g)]
        if contents:
            out[f"content:{name}"] = contents
        if deep:
            out[f"split:{name}"] = deep
        if polys:
            out[name] = polys
    return out


def arm_blocks(ctx: SearchContext, q_rows):
    """For each arm with contact rows: the arm, the indices of its rows of ``Q`` and
    its block ``H D`` (those rows, its joint columns)."""
    model = ctx.model
    owners = [model.contacts[c].arm for c in ctx.row_contacts]
    for a, arm in enumerate(model.arms):
        rows = [i for i, o in enumerate(owners) if o == a]
        if rows:
            off = model.object_dim + model.joint_offset(a)
            yield arm, rows, [q_rows[i][off:off + len(arm.joints)] for i in rows]


def _positive(e) -> bool:
    """Whether ``e`` is positive at every real point because every monomial has even
    exponents and a positive coefficient, and one is constant (``1 + t^2``, the
    denominators of the kinematics and their products)."""
    terms = e.to_dict()
    return (not e.is_zero() and any(not any(m) for m in terms)
            and all(c > 0 and all(x % 2 == 0 for x in m) for m, c in terms.items()))


def reduce_constant_pivots(rows, contents: list, quotient: Quotient | None = None):
    """Eliminate with every pivot that vanishes at no real point (a nonzero constant,
    or a polynomial that :func:`_positive` shows positive): the rank falls by the
    number of pivots at every real point and the set where it drops stays the same.

    Each row is then divided by the gcd of its entries; where that gcd vanishes the
    rank may drop, so every such non-constant gcd is appended to ``contents``: its
    zero set is a candidate to decide like the others. With a ``quotient``, every row
    is reduced modulo its polynomial first (a row zero there is dropped)."""
    rows = [list(r) for r in rows]
    if quotient is not None:
        rows = [r for r in (quotient.reduce_row(r) for r in rows)
                if not all(e.is_zero() for e in r)]
    while rows and rows[0]:
        spot = next(((i, j) for i, r in enumerate(rows) for j, e in enumerate(r)
                     if not e.is_zero() and e.is_constant()), None)
        if spot is None:
            spots = [(len(e), i, j) for i, r in enumerate(rows) for j, e in enumerate(r)
                     if not e.is_zero() and _positive(e)]
            spot = min(spots)[1:] if spots else None
        if spot is None:
            break
        i, j = spot
        prow = rows.pop(i)
        p = prow[j]
        rows = [[p * x - r[j] * y for x, y in zip(r, prow, strict=True)]
                if not r[j].is_zero() else r for r in rows]
        if quotient is not None:
            rows = [quotient.reduce_row(r) for r in rows]
        rows = [_without_content(r[:j] + r[j + 1:], contents) for r in rows]
        rows = [r for r in rows if not all(e.is_zero() for e in r)]
    return rows


def _without_content(row, contents: list):
    """``row`` divided by the gcd of its entries; a non-constant gcd goes to
    ``contents`` (dividing by it must not hide the rank drop at its zeros)."""
    g = None
    # smallest first: the gcd only shrinks, so each later gcd has a small side
    for e in sorted((e for e in row if not e.is_zero()), key=len):
        g = e if g is None else g.gcd(e)
        if g.is_constant():
            return row
    if g is None:
        return row
    if not _positive(g):        # a positive divisor hides no real drop
        contents.append(g)
    return [e / g for e in row]


def _minor_combinations(rows, ctx: SearchContext, contents: list, deep: list | None = None,
                        name: str = "", quotient: Quotient | None = None) -> list:
    """Random combinations of the maximal minors of ``rows`` (their common zeros are the
    set where the rank drops), after a reduction whose divisors go to ``contents``.

    When the drop set has no hypersurface part and more than four variables, no
    combination is returned; one maximal minor goes to ``deep`` instead (see
    :func:`splitting_minor`). With a ``quotient``, the rank is the one over its
    function field and each combination is reduced modulo its polynomial (one that is
    zero there is drawn again)."""
    rows = [r for r in rows if not all(e.is_zero() for e in r)]
    rows = reduce_constant_pivots(rows, contents, quotient)
    if not rows or not rows[0]:
        return []
    ncols = len(rows[0])
    zctx = ctx.ring.zctx
    rank = exact_matrix.rank(rows, ncols, quotient or POLYNOMIALS, zctx)
    if rank == 0:
        return []
    nvars = len({n for r in rows for e in r for n in vars_of(ctx, e)})
    if nvars > 4 and quotient is None:
        # the part of codimension 2 or more is solved here only in up to four variables;
        # it lies in the zero set of any one maximal minor, whose factors are then
        # searched inside one by one
        minor = None
        if deep is not None and ctx.splits < MAX_SPLITS:
            minor = splitting_minor(rows, rank, zctx)
            if minor is not None:
                deep.append(minor)
        if not _common_factor_on_a_line(ctx, rows, rank):
            if minor is None:
                splits = ctx.splits >= MAX_SPLITS
                note(ctx, "block_not_solved", rows=len(rows), columns=ncols, block=name,
                     variables=nvars, limit="splits" if splits else "minors",
                     bound=MAX_SPLITS if splits else (_MAX_SPLIT_RANK, _MAX_SPLIT_MINORS))
            return []
    count = nvars + 1 if nvars <= 2 else 3
    polys: list = []
    tries = 0
    while len(polys) < count and tries < count + _REDRAWS:
        # a zero combination is bad luck (the rank says some maximal minor is nonzero):
        # draw again
        tries += 1
        if ctx.expired():
            break
        left = _random_matrix(ctx, rank, len(rows)) if rank < len(rows) else None
        right = _random_matrix(ctx, ncols, rank) if rank < ncols else None
        m = rows
        if left is not None:
            m = el.matmul(left, m, zctx)
        if right is not None:
            m = el.matmul(m, right, zctx)
        size = determinant_terms(m)
        if size > DETERMINANT_TERMS:
            note(ctx, "operation_too_large", operation="determinant",
                 variables=sorted({n for r in m for e in r for n in vars_of(ctx, e)},
                                  key=ctx.ring_names.index),
                 size=size, bound=DETERMINANT_TERMS)
            return []
        det = _determinant(m)
        if quotient is not None:
            det = quotient.reduce(det)
        if not det.is_zero():
            polys.append(det)
        if left is None and right is None:
            break
    if not polys and not ctx.expired():
        note(ctx, "combinations_vanish", block=name, tries=tries)
    return polys


# how many more random combinations are drawn when some vanish identically
_REDRAWS = 12
#: The largest combination of minors computed: its estimated terms (see
#: :func:`~coopkin_sym.exact.sizes.determinant_terms`; the products of a fraction-free
#: determinant run to their end once started).
DETERMINANT_TERMS = 200_000


# how many zero sets of single minors are searched inside one another
MAX_SPLITS = 4
# the most maximal minors listed to choose a splitting one, and their largest size
_MAX_SPLIT_MINORS = 60
_MAX_SPLIT_RANK = 3


def splitting_minor(rows, rank: int, zctx):
    """A nonzero maximal minor of ``rows`` (rank ``rank``) whose zero set is simplest:
    fewest factors linear in no variable, then lowest degree of its square-free part
    (factors positive at every real point left out). Its real zero set contains the
    whole real drop set. None when there are too many minors."""
    nrows, ncols = len(rows), len(rows[0])
    if rank > _MAX_SPLIT_RANK or comb(nrows, rank) * comb(ncols, rank) > _MAX_SPLIT_MINORS:
        return None
    best, best_key = None, None
    for ri in itertools.combinations(range(nrows), rank):
        for ci in itertools.combinations(range(ncols), rank):
            sub = [[rows[i][j] for j in ci] for i in ri]
            if determinant_terms(sub) > DETERMINANT_TERMS:
                continue      # another minor may do; none at all: the caller says so
            det = _determinant(sub)
            if det.is_zero() or len(det) > FACTOR_TERMS:
                continue
            _, fs = factor(det)
            square_free = zctx.constant(1)
            curved = 0
            for f, _e in fs:
                if _positive(f):        # no real zeros: no part of the drop set
                    continue
                square_free *= f
                if not any(d == 1 for d in f.degrees()):
                    curved += 1
            key = (curved, square_free.total_degree(), len(fs), str(square_free))
            if best_key is None or key < best_key:
                best, best_key = square_free, key
    return best


def _common_factor_on_a_line(ctx: SearchContext, rows, rank: int, lines: int = 3) -> bool:
    """Whether two random combinations of the maximal minors may share a factor with
    real zeros.

    Restricted to a random real line ``x = a + b s``, a common factor of the two
    determinants stays a common factor of the univariate restrictions, and a real
    hypersurface meets almost every line through the region it crosses; factors
    without real points (``1 + t^2``) stay positive on every real line. So a gcd
    without real roots on a few lines through ``[-2, 2]^n`` shows, up to that choice,
    that the drop set has no real hypersurface part. The univariate work is cheap.
    """
    lctx = flint.fmpz_mpoly_ctx.get(("s",), "degrevlex")
    (svar,) = lctx.gens()
    for _ in range(lines):
        line = [lctx.constant(ctx.rng.randint(-2, 2)) + ctx.rng.randint(1, 9) * svar
                for _ in ctx.ring_names]
        restricted = [[e.compose(*line, ctx=lctx) if not e.is_constant() else
                       lctx.constant(int(e.leading_coefficient()) if not e.is_zero()
                                     else 0) for e in r] for r in rows]
        dets = []
        for _ in range(2):
            m = restricted
            if rank < len(rows):
                m = el.matmul(_random_matrix(ctx, rank, len(rows), lctx), m, lctx)
            if rank < len(rows[0]):
                m = el.matmul(m, _random_matrix(ctx, len(rows[0]), rank, lctx), lctx)
            dets.append(_determinant(m))
        g = dets[0].gcd(dets[1])
        if g.is_constant():
            continue
        coeffs = [0] * (g.total_degree() + 1)
        for (e,), c in g.to_dict().items():
            coeffs[int(e)] = int(c)
        if sp.Poly(coeffs[::-1], sp.Symbol("s")).count_roots() > 0:
            return True
    return False


def _random_matrix(ctx: SearchContext, n: int, m: int, zctx=None):
    """An ``n x m`` matrix of small random integers (small, so that the combinations
    of minors stay cheap to factor; one that vanishes identically is drawn again)."""
    c = (zctx or ctx.ring.zctx).constant
    return [[c(ctx.rng.randint(-3, 3)) for _ in range(m)] for _ in range(n)]


_determinant = el.determinant
