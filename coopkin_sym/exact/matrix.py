"""One exact-matrix type over every domain the package computes in.

A :class:`PolyMatrix` is a matrix of integer polynomials (python-flint ``fmpz_mpoly``,
one context) read over a *domain*:

* :data:`POLYNOMIALS`: the fraction field ``Q(x)`` of the polynomial ring (with no
  variables, the rationals: the work then goes to flint's ``fmpz_mat``);
* a :class:`~coopkin_sym.exact.quotient.Quotient` ``Z[x]/(f)``: the function field of
  the hypersurface ``f = 0`` (a number field for a univariate ``f``);
* a :class:`~coopkin_sym.exact.quotient.Tower` ``Z[x]/(g_1, ..., g_n)``: several
  algebraic numbers at once.

Every method means the same thing on every domain (rank, nullspace, determinant over
that field) and is checked against SymPy in ``tests/exact/test_exact_matrix.py``, one test
body for every domain. The kernels behind it are
:mod:`~coopkin_sym.exact.elimination` (over ``Q(x)``) and
:mod:`~coopkin_sym.exact.quotient` (modulo ``f``); both clear entries with the one
row update :func:`~coopkin_sym.exact.elimination.combine`. Batches of integer matrices
at many points are ranked modulo a word-size prime by :func:`batch_ranks`
(:mod:`~coopkin_sym.exact.modular`): a rank modulo ``p`` never exceeds the rank over
``Q``.

Example
-------
>>> import flint
>>> from coopkin_sym.exact.quotient import Quotient
>>> ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
>>> (x,) = ctx.gens()
>>> one = ctx.constant(1)
>>> m = PolyMatrix([[x, 2 * one], [2 * one, x]], 2)
>>> m.rank(), str(m.det())
(2, 'x^2 - 4')
>>> m.over(Quotient(x**2 - 4, 0)).rank()       # at x = 2 and x = -2 the rank drops
1
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from math import lcm
from typing import TYPE_CHECKING, Protocol

import flint

from coopkin_sym.errors import ArgumentError
from coopkin_sym.exact import elimination as el
from coopkin_sym.exact.quotient import eliminate_modulo, nullspace_modulo, rank_modulo

if TYPE_CHECKING:  # pragma: no cover
    import numpy as np

Poly = flint.fmpz_mpoly
Row = list[Poly]

__all__ = ["POLYNOMIALS", "RATIONALS", "SYMPY", "ArmBlock", "Domain", "PolyMatrix",
           "Polynomials", "PrimeField", "Ranks", "Rationals", "SympyEntries", "arm_elimination",
           "batch_rank_profile", "batch_ranks", "eliminate_arm", "rank", "rank_triple"]


class Domain(Protocol):
    """What a domain gives the matrix: rows reduced to a normal form, and a zero test
    (``Quotient`` and ``Tower`` have both).

    Example
    -------
    >>> import flint
    >>> from coopkin_sym.exact.quotient import Quotient
    >>> (x,) = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex").gens()
    >>> domain: Domain = Quotient(x**2 - 2, 0)
    >>> domain.is_zero(x**4 - 4), domain.is_zero(x)
    (True, False)
    """

    def reduce_row(self, row: Sequence[Poly]) -> list[Poly]: ...

    def is_zero(self, p: Poly) -> bool: ...


class Polynomials:
    """The fraction field ``Q(x)`` of the integer polynomials themselves: no reduction.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
    >>> POLYNOMIALS.is_zero(ctx.constant(0)), repr(POLYNOMIALS)
    (True, 'Q(x)')
    """

    def reduce_row(self, row: Sequence[Poly]) -> list[Poly]:
        return list(row)

    def is_zero(self, p: Poly) -> bool:
        return p.is_zero()

    def __repr__(self) -> str:
        return "Q(x)"


#: The default domain: polynomials read over their fraction field.
POLYNOMIALS = Polynomials()


class PolyMatrix:
    """An ``m x ncols`` matrix of integer polynomials, read over ``domain``.

    Parameters
    ----------
    rows
        The rows, lists of ``fmpz_mpoly`` of one context.
    ncols
        The number of columns (needed when there is no row).
    domain
        :data:`POLYNOMIALS` (default), a ``Quotient`` or a ``Tower``.
    context
        The polynomial context, needed only when there is no row.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("L",), "degrevlex")
    >>> (L,) = ctx.gens()
    >>> m = PolyMatrix([[L, 2 * L, ctx.constant(0)]], 3)
    >>> m.rank(), [[str(e) for e in v] for v in m.nullspace()]
    (1, [['2', '-1', '0'], ['0', '0', '1']])
    """

    __slots__ = ("rows", "ncols", "domain", "context", "_integers")

    def __init__(self, rows: Sequence[Sequence[Poly]], ncols: int,
                 domain: Domain = POLYNOMIALS, context=None):
        self.rows = [list(r) for r in rows]
        self.ncols = ncols
        self.domain = domain
        if context is None and self.rows and self.rows[0]:
            context = self.rows[0][0].context()
        self.context = context
        self._integers: flint.fmpz_mat | None = None
        if any(len(r) != ncols for r in self.rows):
            raise ArgumentError(f"every row must have {ncols} entries")

    @classmethod
    def from_integers(cls, nrows: int, ncols: int, entries: Sequence[int]) -> PolyMatrix:
        """An integer matrix (row-major ``entries``), kept as flint's ``fmpz_mat``: the
        rationals' path, with no polynomial built (the sweep's exact rechecks).

        Example
        -------
        >>> m = PolyMatrix.from_integers(2, 3, [1, 2, 3, 2, 4, 6])
        >>> m.rank(), m.columns(2).rank(), m.shape
        (1, 1, (2, 3))
        """
        out = object.__new__(cls)          # no polynomial rows: nothing to check
        out.rows, out.ncols, out.domain, out.context = [], ncols, POLYNOMIALS, None
        out._integers = flint.fmpz_mat(nrows, ncols, entries)
        return out

    def _integer_columns(self, start: int, stop: int) -> PolyMatrix:
        out = PolyMatrix([], stop - start)
        out._integers = self._integers * _selection(self.ncols, start, stop)
        return out

    @property
    def shape(self) -> tuple[int, int]:
        if self._integers is not None:
            return self._integers.nrows(), self.ncols
        return len(self.rows), self.ncols

    def over(self, domain: Domain) -> PolyMatrix:
        """The same entries read over another domain."""
        self._require_rows("over")
        return PolyMatrix(self.rows, self.ncols, domain, self.context)

    def columns(self, start: int, stop: int | None = None) -> PolyMatrix:
        """The block of columns ``start:stop``."""
        stop = self.ncols if stop is None else stop
        if self._integers is not None:
            return self._integer_columns(start, stop)
        return PolyMatrix([r[start:stop] for r in self.rows], stop - start, self.domain,
                          self.context)

    def split_ranks(self, split: int) -> tuple[int, int, int]:
        """The ranks of the whole matrix, of its first ``split`` columns and of the
        others (one call: the sweep asks this at every point).

        Example
        -------
        >>> PolyMatrix.from_integers(2, 3, [1, 0, 0, 0, 0, 1]).split_ranks(2)
        (2, 1, 1)
        """
        if self._integers is not None:
            m = self._integers
            n = self.ncols
            rest = (m * _selection(n, split, n)).rank() if n > split else 0
            return m.rank(), (m * _selection(n, 0, split)).rank(), rest
        return rank_triple(self.rows, self.ncols, split, self.domain).triple

    def _is_polynomials(self) -> bool:
        return isinstance(self.domain, Polynomials)

    def rank(self) -> int:
        """The rank over the domain's field."""
        if self._integers is not None:
            return self._integers.rank() if self.ncols else 0
        if not self.rows or self.ncols == 0:
            return 0
        if self._is_polynomials():
            return el.rank(self.rows, self.ncols)
        return rank_modulo(self.rows, self.ncols, self.domain)

    def _triple(self, dim: int, arms: Sequence[ArmBlock] | None, by_arms: bool) -> Ranks:
        """:func:`rank_triple` over this matrix's polynomial domain."""
        if by_arms and arms is not None:
            pivots, leftover = arm_elimination(self.rows, dim, arms, self.domain)
            q = sum(pivots) + rank(leftover, dim, self.domain, self.context)
            gt = rank([r[:dim] for r in self.rows], dim, self.domain, self.context)
            return Ranks(q, gt, sum(pivots), tuple(pivots))
        return _direct_triple(self.rows, self.ncols, dim, self.domain, arms, self.context)

    def nullspace(self) -> list[Row]:
        """A basis of the right nullspace over the domain's field: primitive polynomial
        vectors, one per free column."""
        self._require_rows("nullspace")
        if self._is_polynomials():
            return el.nullspace(self.rows, self.ncols, self.context)
        return nullspace_modulo(self.rows, self.ncols, self.domain)

    def nullspace_rref(self, column_order: Sequence[int] | None = None
                       ) -> tuple[list[Row], list[int]]:
        """The reduced echelon basis of the right nullspace (unique for the subspace)
        and its pivot columns, over ``Q(x)``."""
        self._require_rows("nullspace_rref")
        self._require_polynomials("a reduced echelon nullspace")
        return el.nullspace_rref(self.rows, self.ncols, self.context, column_order)

    def rref(self, column_order: Sequence[int] | None = None, canonical: bool = True
             ) -> tuple[list[Row], list[int]]:
        """The reduced rows (primitive multiples of the reduced row echelon form) and
        the pivot columns, over ``Q(x)`` (see
        :func:`~coopkin_sym.exact.elimination.gauss_jordan`)."""
        self._require_rows("rref")
        self._require_polynomials("a reduced row echelon form")
        return el.gauss_jordan(self.rows, self.ncols, column_order, canonical=canonical)

    def eliminate(self, columns: Sequence[int]) -> tuple[int, list[Row]]:
        """Eliminate on ``columns`` only: the number of pivots found there and the
        rows left over (zero in those columns), reduced and primitive."""
        self._require_rows("eliminate")
        return eliminate_modulo(self.rows, columns, self.domain)

    def det(self) -> Poly:
        """The determinant (square matrices), reduced in the domain."""
        self._require_rows("det")
        if len(self.rows) != self.ncols:
            raise ArgumentError(f"a determinant needs a square matrix, not {self.shape}")
        if not self.rows:
            return self.context.constant(1)
        d = el.determinant(self.rows)
        return d if self._is_polynomials() else self.domain.reduce_row([d])[0]

    def is_zero_vector(self, v: Sequence[Poly]) -> bool:
        """Whether ``M v = 0`` in the domain."""
        self._require_rows("is_zero_vector")
        return all(self.domain.is_zero(_dot(r, v)) for r in self.rows)

    def _require_rows(self, what: str) -> None:
        if self._integers is not None:
            raise ArgumentError(f"{what}: a matrix built from_integers gives its rank and "
                             "column blocks only")

    def _require_polynomials(self, what: str) -> None:
        if not self._is_polynomials():
            raise ArgumentError(f"{what} is computed over Q(x) only, not over {self.domain!r}")

    def __repr__(self) -> str:
        m, n = self.shape
        return f"PolyMatrix({m} x {n} over {self.domain!r})"


@functools.lru_cache(maxsize=64)
def _selection(n: int, start: int, stop: int) -> flint.fmpz_mat:
    """The ``n x (stop - start)`` matrix that picks columns ``start:stop``."""
    return flint.fmpz_mat(n, stop - start, [int(i == j + start) for i in range(n)
                                             for j in range(stop - start)])


def _dot(a: Sequence[Poly], b: Sequence[Poly]):
    total = None
    for x, y in zip(a, b, strict=True):
        total = x * y if total is None else total + x * y
    return total


def batch_ranks(matrices: np.ndarray, p: int | None = None) -> np.ndarray:
    """The ranks modulo ``p`` of a batch of integer matrices, shape ``(batch, m, n)``
    (any integers; reduced modulo ``p`` here): each a lower bound on the rank over
    ``Q``, equal to it for all but finitely many primes (``p`` by default
    :data:`~coopkin_sym.exact.modular.PRIME`; NumPy is imported on first use).

    Example
    -------
    >>> import numpy as np
    >>> batch = np.array([[[1, 2], [2, 4]], [[1, 0], [0, 1]]], dtype=np.int64)
    >>> batch_ranks(batch).tolist()
    [1, 2]
    """
    import numpy as np

    from coopkin_sym.exact import modular
    p = modular.PRIME if p is None else p
    work = np.remainder(np.asarray(matrices, dtype=np.int64), p).transpose(1, 2, 0).copy()
    return modular.rank_profile(work, p)[0]


def batch_rank_profile(matrices: np.ndarray, p: int | None = None,
                       prefix: int | None = None) -> tuple[np.ndarray, np.ndarray | None]:
    """Ranks modulo ``p`` of a batch in the sweep's own layout, ``(m, n, batch)``
    residues (overwritten), and with ``prefix`` the ranks of the first ``prefix``
    columns too (see :func:`~coopkin_sym.exact.modular.rank_profile`).

    Example
    -------
    >>> import numpy as np
    >>> a = np.array([[[0, 1], [1, 1]], [[1, 2], [2, 4]]]).transpose(1, 2, 0)
    >>> [r.tolist() for r in batch_rank_profile(a, 7, prefix=1)]
    [[2, 1], [1, 1]]
    """
    from coopkin_sym.exact import modular
    return modular.rank_profile(matrices, modular.PRIME if p is None else p, prefix)


# --- the rank service ------------------------------------------------------------------
class Rationals:
    """The field ``Q`` read on rows of Python or flint integers and rationals (flint's
    ``fmpz_mat``, or ``fmpq_mat`` when an entry is not an integer).

    Example
    -------
    >>> from fractions import Fraction
    >>> rank([[1, 2], [2, 4]], 2, RATIONALS), rank([[Fraction(1, 2), 1], [1, 2]], 2, RATIONALS)
    (1, 1)
    """

    def __repr__(self) -> str:
        return "Q"


#: Integer and rational matrices, ranked over ``Q``.
RATIONALS = Rationals()


class PrimeField:
    """The field ``GF(p)`` of a prime ``p``, on rows of integers (any integers, reduced
    modulo ``p``; flint's ``nmod_mat``) or on a NumPy batch of shape ``(batch, m, n)``
    (:mod:`~coopkin_sym.exact.modular`). A rank modulo ``p`` never exceeds the rank
    over ``Q``.

    Example
    -------
    >>> rank([[1, 2], [3, 4]], 2, PrimeField(2)), rank([[1, 2], [3, 4]], 2, RATIONALS)
    (1, 2)
    """

    __slots__ = ("p",)

    def __init__(self, p: int):
        self.p = p

    def __eq__(self, other: object) -> bool:
        return isinstance(other, PrimeField) and other.p == self.p

    def __hash__(self) -> int:
        return hash(("GF", self.p))

    def __repr__(self) -> str:
        return f"GF({self.p})"


class SympyEntries:
    """The field of a matrix of SymPy expressions (rows of expressions, or a SymPy
    ``DomainMatrix``): rational functions over ``Q`` in the symbols (and other
    generators, ``cos(x)`` as a variable) are ranked by flint over :data:`POLYNOMIALS`,
    each row cleared of its denominators; entries of any other SymPy domain (radicals:
    ``EX``) by SymPy's ``DomainMatrix`` over the field of that domain.

    Example
    -------
    >>> import sympy as sp
    >>> t = sp.Symbol("t")
    >>> rank([[t / (1 + t), 1], [t**2 / (1 + t), t]], 2, SYMPY), rank([[t, sp.sqrt(2)]], 2, SYMPY)
    (1, 1)
    """

    def __repr__(self) -> str:
        return "SymPy"


#: SymPy expressions, ranked over the field they generate.
SYMPY = SympyEntries()


def _sympy_rank(rows, ncols: int | None) -> int:
    """:func:`rank` over :data:`SYMPY`."""
    from sympy.polys.matrices import DomainMatrix

    if not isinstance(rows, DomainMatrix):
        if not rows or not ncols:
            return 0
        rows = DomainMatrix.from_list_sympy(len(rows), ncols, [list(r) for r in rows])
    if 0 in rows.shape:
        return 0
    field = rows.domain if rows.domain.is_Field else rows.domain.get_field()
    matrix = rows.convert_to(field)
    if field.is_QQ:
        return rank(matrix.to_list(), matrix.shape[1], RATIONALS)
    if not (getattr(field, "is_FractionField", False)
            and (field.domain.is_ZZ or field.domain.is_QQ)):
        return matrix.rank()
    ctx = flint.fmpz_mpoly_ctx.get(tuple(f"x{i}" for i in range(len(field.symbols))),
                                   "degrevlex")
    return rank([_cleared_row(row, ctx) for row in matrix.to_list()], matrix.shape[1],
                POLYNOMIALS, ctx)


def _cleared_row(row, ctx) -> Row:
    """A row of SymPy rational functions times one nonzero polynomial, over Z."""
    nums, dens = [], []
    scale = 1
    for e in row:
        for part, out in ((e.numer, nums), (e.denom, dens)):
            terms = {m: _rational(c) for m, c in part.terms()}
            d = functools.reduce(lcm, (int(c.q) for c in terms.values()), 1)
            out.append((ctx.from_dict({m: int((c * d).p) for m, c in terms.items()}), d))
    common = ctx.constant(1)
    for den, _ in dens:
        common = common * (den / common.gcd(den))
    out = []
    for (num, a), (den, b) in zip(nums, dens, strict=True):
        # e = (num / a) / (den / b) = b num / (a den)
        out.append((num * (common / den), flint.fmpq(b, a)))
        scale = lcm(scale, a)
    return [p * int((c * scale).p) for p, c in out]


#: An arm block of ``Q``: the rows of the arm's contacts and its joint columns
#: ``start:stop`` (the arm's rows are zero in every other joint column).
ArmBlock = tuple[Sequence[int], int, int]


class Ranks(tuple):
    """The rank triple of ``Q = [H G^T | H D]``: ``q = rank Q``, ``gt = rank H G^T``
    (the object columns), ``dt = rank H D`` (the joint columns), and with arm blocks
    the rank of each arm's block of ``H D`` (their sum is ``dt``).

    Example
    -------
    >>> r = rank_triple([[1, 0, 0], [0, 0, 1]], 3, 2, RATIONALS, [([1], 2, 3)])
    >>> r.triple, r.arms
    ((2, 1, 1), (1,))
    """

    __slots__ = ()

    def __new__(cls, q: int, gt: int, dt: int, arms: tuple[int, ...] = ()) -> Ranks:
        return super().__new__(cls, (q, gt, dt, tuple(arms)))

    q = property(lambda self: self[0], doc="``rank Q``")
    gt = property(lambda self: self[1], doc="``rank H G^T``")
    dt = property(lambda self: self[2], doc="``rank H D``")
    arms = property(lambda self: self[3], doc="the rank of each arm block of ``H D``")

    @property
    def triple(self) -> tuple[int, int, int]:
        """``(rank Q, rank H G^T, rank H D)``, the ranks the numbers come from."""
        return self[0], self[1], self[2]


def rank(rows, ncols: int | None, domain: object = POLYNOMIALS, context=None):
    """The rank of a matrix over ``domain``: the one entry point for every domain.

    Parameters
    ----------
    rows
        The rows: integers or rationals over :data:`RATIONALS` or a
        :class:`PrimeField`; ``fmpz_mpoly`` of one context over :data:`POLYNOMIALS`
        (``Q(x)``), a :class:`~coopkin_sym.exact.quotient.Quotient` (``Z[x]/(f)``)
        or a :class:`~coopkin_sym.exact.quotient.Tower`. Over a :class:`PrimeField`, a
        NumPy array of shape ``(batch, m, n)`` is a batch: its ranks come back as an
        array.
    ncols
        The number of columns (needed when there is no row; ignored for a batch).
    domain, context
        The domain, and the polynomial context (only for a polynomial matrix with
        no row).

    Example
    -------
    >>> import flint
    >>> from coopkin_sym.exact.quotient import Quotient
    >>> (x,) = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex").gens()
    >>> rows = [[x, 2 + 0 * x], [2 + 0 * x, x]]
    >>> rank(rows, 2), rank(rows, 2, Quotient(x**2 - 4, 0)), rank([[2, 4]], 2, PrimeField(2))
    (2, 1, 0)
    """
    if isinstance(domain, PrimeField) and getattr(rows, "ndim", 0) == 3:
        return batch_ranks(rows, domain.p)
    if isinstance(domain, SympyEntries):
        return _sympy_rank(rows, ncols)
    if ncols == 0 or len(rows) == 0:
        return 0
    if isinstance(domain, Rationals):
        if all(isinstance(e, int | flint.fmpz) for r in rows for e in r):
            return flint.fmpz_mat(rows).rank()
        return flint.fmpq_mat([[_rational(e) for e in r] for r in rows]).rank()
    if isinstance(domain, PrimeField):
        return flint.nmod_mat(rows, domain.p).rank()
    return PolyMatrix(rows, ncols, domain, context).rank()


def _rational(e) -> flint.fmpq:
    if isinstance(e, flint.fmpq):
        return e
    if isinstance(e, int | flint.fmpz):
        return flint.fmpq(e)
    return flint.fmpq(e.numerator, e.denominator)


def rank_triple(rows, ncols: int, dim: int, domain: object = POLYNOMIALS,
                arms: Sequence[ArmBlock] | None = None, *, by_arms: bool = False,
                context=None) -> Ranks:
    """The rank triple of ``Q``: the ranks of ``Q``, of its first ``dim`` columns
    (``H G^T``) and of the others (``H D``), over ``domain`` (as for :func:`rank`).

    With ``arms`` (the blocks of ``H D``, see :data:`ArmBlock`), ``rank H D`` is the sum
    of the blocks' ranks, each given in :attr:`Ranks.arms`. With ``by_arms`` too, over a
    polynomial domain, ``rank Q`` is found arm by arm (:func:`arm_elimination`): each
    arm's joint columns eliminated from its own rows, then the object rows left over
    from every arm ranked together (the same rank, on smaller eliminations).

    Example
    -------
    >>> rows = [[1, 0, 2, 0], [0, 1, 0, 0], [1, 1, 2, 0]]
    >>> rank_triple(rows, 4, 2, RATIONALS).triple
    (2, 2, 1)
    >>> rank_triple(rows, 4, 2, PrimeField(7), [([0, 2], 2, 3), ([1], 3, 4)])
    (2, 2, 1, (1, 0))
    """
    if isinstance(domain, Rationals | PrimeField | SympyEntries):
        return _direct_triple(rows, ncols, dim, domain, arms, context)
    if not rows:
        return Ranks(0, 0, 0, tuple(0 for _ in arms or ()))
    return PolyMatrix(rows, ncols, domain, context)._triple(dim, arms, by_arms)


def _direct_triple(rows, ncols: int, dim: int, domain, arms, context) -> Ranks:
    gt = rank([r[:dim] for r in rows], dim, domain, context)
    if arms is None:
        q = rank(rows, ncols, domain, context)
        return Ranks(q, gt, rank([r[dim:] for r in rows], ncols - dim, domain, context))
    if isinstance(domain, Rationals | PrimeField):
        blocks, q = _field_arm_ranks(rows, dim, arms, domain)
        return Ranks(q, gt, sum(blocks), blocks)
    q = rank(rows, ncols, domain, context)
    blocks = tuple(rank([rows[i][c0:c1] for i in block], c1 - c0, domain, context)
                   for block, c0, c1 in arms)
    return Ranks(q, gt, sum(blocks), blocks)


def _field_arm_ranks(rows, dim: int, arms: Sequence[ArmBlock], domain
                     ) -> tuple[tuple[int, ...], int]:
    """The rank of each arm block of ``H D`` and ``rank Q``, arm by arm, over ``Q``
    (:data:`RATIONALS`) or a :class:`PrimeField`.

    Each arm's rows (zero in every other arm's joint columns), its joint columns first,
    are brought to reduced echelon form on their own (flint: fraction-free over the
    integers, or modulo ``p``): the pivots in the joint columns are the block's rank,
    the rows left have a zero joint part, and their object parts, with the rows of no
    arm, are ranked together. Row operations within one arm's rows keep the rank, so
    ``rank Q`` is the sum of the pivots and that rank: small eliminations, linear in
    the number of arms, instead of one elimination of the whole matrix (over ``Q`` its
    entries grow with its size).
    """
    in_arm: set[int] = set()
    leftover: list[list] = []
    blocks = []
    for block, c0, c1 in arms:
        in_arm.update(block)
        width = c1 - c0
        if not block:
            blocks.append(0)
            continue
        reduced, found = _reduced([rows[i][c0:c1] + rows[i][:dim] for i in block], domain)
        pivots = 0
        for k in range(found):
            row = [reduced[k, j] for j in range(width + dim)]
            if any(row[:width]):
                pivots += 1
            else:
                leftover.append([int(x) for x in row[width:]])
        blocks.append(pivots)
    leftover += [rows[i][:dim] for i in range(len(rows)) if i not in in_arm]
    return tuple(blocks), sum(blocks) + rank(leftover, dim, domain)


def _reduced(rows, domain) -> tuple:
    """The reduced echelon form of a small matrix over ``Q`` (as integers: each row
    times the least common multiple of its denominators, the same row space) or
    modulo ``p``, and its rank."""
    if isinstance(domain, PrimeField):
        return flint.nmod_mat(rows, domain.p).rref()
    out = []
    for r in rows:
        if all(isinstance(e, int | flint.fmpz) for e in r):
            out.append(list(r))
            continue
        values = [_rational(e) for e in r]
        scale = lcm(*(int(v.q) for v in values))
        out.append([int(v.p) * (scale // int(v.q)) for v in values])
    reduced, _, found = flint.fmpz_mat(out).rref()
    return reduced, found


def arm_elimination(rows, dim: int, arms: Sequence[ArmBlock], domain: object = POLYNOMIALS
                    ) -> tuple[list[int], list[Row]]:
    """Each arm's joint columns eliminated from its own rows (over a polynomial
    domain): the number of pivots of each arm (the rank of its block of ``H D``) and
    the object rows left over, from every arm and from the rows of no arm, whose rank
    added to the pivots is ``rank Q``.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
    >>> (x,) = ctx.gens()
    >>> z, one = ctx.constant(0), ctx.constant(1)
    >>> pivots, left = arm_elimination([[one, z, x], [z, one, x]], 2, [([0, 1], 2, 3)])
    >>> pivots, [[str(e) for e in r] for r in left]
    ([1], [['1', '-1']])
    """
    in_arm = {i for block, _, _ in arms for i in block}
    leftover = [rows[i][:dim] for i in range(len(rows)) if i not in in_arm]
    pivots = []
    for arm in arms:
        found, left = eliminate_arm(rows, dim, arm, domain)
        pivots.append(found)
        leftover += left
    return pivots, leftover


def eliminate_arm(rows, dim: int, arm: ArmBlock, domain: object = POLYNOMIALS
                  ) -> tuple[int, list[Row]]:
    """One arm of :func:`arm_elimination`: the rank of the arm's block of ``H D`` and
    the object parts of its rows left over once its joint columns are eliminated.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
    >>> (x,) = ctx.gens()
    >>> eliminate_arm([[x, ctx.constant(1)]], 1, ([0], 1, 2))
    (1, [])
    """
    block, c0, c1 = arm
    matrix = [rows[i][c0:c1] + rows[i][:dim] for i in block]
    if not matrix:
        return 0, []
    found, left = PolyMatrix(matrix, c1 - c0 + dim, domain).eliminate(range(c1 - c0))
    return found, [r[c1 - c0:] for r in left]
