"""Small matrices of rational functions, computed with python-flint.

SymPy's ``DomainMatrix`` over a fraction field ``ZZ(x, y, ...)`` does its arithmetic
with SymPy's own polynomials, whose gcds are slow once entries have a few dozen terms
(an inverse of a 3 x 3 matrix of such entries took minutes). A :class:`FieldMatrix`
holds the same entries as :class:`~coopkin_sym.exact.ratfunc.RatFunc` (python-flint
numerators and denominators, in lowest terms), does the products, inverses and
determinants there, and gives a ``DomainMatrix`` over the same field back: the entries
come back exactly as SymPy writes them. With a budget ``max_terms``, an entry (its
numerator and denominator) of more terms, read or made by a product, an inverse or a
determinant, stops the computation at once: a
:class:`~coopkin_sym.errors.BlockTooLarge` that says how large it grew.

Example
-------
>>> import sympy as sp
>>> from sympy.polys.matrices import DomainMatrix
>>> x, y = sp.symbols("x y")
>>> dm = DomainMatrix.from_Matrix(sp.Matrix([[x, 1], [1, y]])).to_field()
>>> m = FieldMatrix.of(dm)
>>> (m * m.inv()).to_domain_matrix().to_Matrix()
Matrix([
[1, 0],
[0, 1]])
>>> m.field.to_sympy(m.det_element())
x*y - 1
"""

from __future__ import annotations

from math import lcm

import flint
from sympy.polys.matrices import DomainMatrix

from coopkin_sym.errors import BlockTooLarge, NumberError
from coopkin_sym.exact.ratfunc import RatFunc
from coopkin_sym.exact.rationals import to_fraction

__all__ = ["FieldMatrix"]


class FieldMatrix:
    """A matrix of :class:`RatFunc` entries of one flint context, read from a
    ``DomainMatrix`` over a SymPy fraction field ``field`` (whose symbols are the
    context's variables).

    Example
    -------
    >>> import sympy as sp
    >>> from sympy.polys.matrices import DomainMatrix
    >>> t = sp.Symbol("t")
    >>> m = FieldMatrix.of(DomainMatrix.from_Matrix(sp.Matrix([[1 / (1 + t)]])).to_field())
    >>> m.inv().to_domain_matrix().to_Matrix()
    Matrix([[t + 1]])
    >>> FieldMatrix.of(DomainMatrix.from_Matrix(sp.Matrix([[1 + t + t**2]])).to_field(),
    ...                max_terms=3)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.BlockTooLarge: an entry of 4 terms, over the budget of 3
    """

    def __init__(self, rows: list[list[RatFunc]], shape: tuple[int, int], field, ctx,
                 max_terms: int | None = None):
        self.rows, self.shape, self.field, self.ctx = rows, shape, field, ctx
        self.max_terms = max_terms

    @classmethod
    def of(cls, dm: DomainMatrix, max_terms: int | None = None) -> FieldMatrix:
        """The matrix ``dm`` (over a fraction field of polynomials); ``max_terms``: the
        budget of terms of an entry (numerator and denominator), None for none."""
        field = dm.domain
        names = tuple(str(s) for s in field.symbols)
        ctx = flint.fmpz_mpoly_ctx.get(names, "degrevlex")
        rows = [[_from_element(e, ctx) for e in row] for row in dm.to_list()]
        out = cls(rows, dm.shape, field, ctx, max_terms)
        for row in rows:
            for e in row:
                out._check(e)
        return out

    def _check(self, e: RatFunc) -> RatFunc:
        """``e``, when within the budget of terms."""
        if self.max_terms is not None:
            terms = len(e.num) + len(e.den)
            if terms > self.max_terms:
                raise BlockTooLarge(f"an entry of {terms:,} terms, over the budget of "
                                    f"{self.max_terms:,}")
        return e

    def _budget(self, other: FieldMatrix | None = None) -> int | None:
        budgets = [b for b in (self.max_terms, getattr(other, "max_terms", None))
                   if b is not None]
        return min(budgets) if budgets else None

    def _new(self, rows: list[list[RatFunc]]) -> FieldMatrix:
        return FieldMatrix(rows, (len(rows), len(rows[0]) if rows else self.shape[1]),
                           self.field, self.ctx, self.max_terms)

    def _zero(self) -> RatFunc:
        return RatFunc.poly(self.ctx.constant(0))

    def transpose(self) -> FieldMatrix:
        if not self.rows:
            return FieldMatrix([], (self.shape[1], 0), self.field, self.ctx, self.max_terms)
        return self._new([list(col) for col in zip(*self.rows, strict=True)])

    def __mul__(self, other: FieldMatrix) -> FieldMatrix:
        cols = list(zip(*other.rows, strict=True)) if other.rows else []
        product = FieldMatrix([], (self.shape[0], other.shape[1]), self.field, self.ctx,
                              self._budget(other))
        for row in self.rows:
            line = []
            for col in cols:
                acc = self._zero()
                for a, b in zip(row, col, strict=True):
                    if not (a.is_zero() or b.is_zero()):
                        acc = acc + a * b
                line.append(product._check(acc))
            product.rows.append(line)
        return product

    def __sub__(self, other: FieldMatrix) -> FieldMatrix:
        out = self._new([[a - b for a, b in zip(r, s, strict=True)]
                         for r, s in zip(self.rows, other.rows, strict=True)])
        out.max_terms = self._budget(other)
        for row in out.rows:
            for e in row:
                out._check(e)
        return out

    def inv(self) -> FieldMatrix:
        """The inverse (Gauss-Jordan; every entry kept in lowest terms); a
        :class:`~coopkin_sym.errors.NumberError` when there is none."""
        n = self.shape[0]
        one, zero = RatFunc.poly(self.ctx.constant(1)), self._zero()
        work = [list(row) + [one if i == j else zero for j in range(n)]
                for i, row in enumerate(self.rows)]
        for c in range(n):
            p = next((r for r in range(c, n) if not work[r][c].is_zero()), None)
            if p is None:
                raise NumberError("matrix", "not invertible (its determinant is 0)")
            work[c], work[p] = work[p], work[c]
            pivot = work[c][c]
            work[c] = [self._check(e / pivot) for e in work[c]]
            for r in range(n):
                if r != c and not work[r][c].is_zero():
                    f = work[r][c]
                    work[r] = [self._check(a - f * b)
                               for a, b in zip(work[r], work[c], strict=True)]
        return self._new([row[n:] for row in work])

    def det_element(self):
        """The determinant, an element of :attr:`field` (fraction-free elimination)."""
        n = self.shape[0]
        work = [list(row) for row in self.rows]
        det = RatFunc.poly(self.ctx.constant(1))
        for c in range(n):
            p = next((r for r in range(c, n) if not work[r][c].is_zero()), None)
            if p is None:
                return self.field.zero
            if p != c:
                work[c], work[p] = work[p], work[c]
                det = -det
            pivot = work[c][c]
            det = self._check(det * pivot)
            for r in range(c + 1, n):
                if not work[r][c].is_zero():
                    f = work[r][c] / pivot
                    work[r] = [self._check(a - f * b)
                               for a, b in zip(work[r], work[c], strict=True)]
        return _to_element(det, self.field)

    def to_domain_matrix(self) -> DomainMatrix:
        """The matrix over :attr:`field`, each entry as SymPy writes it."""
        rows = [[_to_element(e, self.field) for e in row] for row in self.rows]
        return DomainMatrix(rows, self.shape, self.field)


def _from_element(e, ctx) -> RatFunc:
    num = {k: to_fraction(c) for k, c in e.numer.to_dict().items()}
    den = {k: to_fraction(c) for k, c in e.denom.to_dict().items()}
    scale = lcm(*(c.denominator for c in (*num.values(), *den.values())))

    def poly(d):
        return ctx.from_dict({k: int(c * scale) for k, c in d.items()}) if d \
            else ctx.constant(0)
    return RatFunc.make(poly(num), poly(den))


def _to_element(f: RatFunc, field):
    f = f.reduced()
    frac = field.field                       # SymPy's FracField behind the domain
    ring = frac.ring
    num = ring.from_dict({tuple(int(x) for x in k): int(c)
                          for k, c in f.num.to_dict().items()})
    den = ring.from_dict({tuple(int(x) for x in k): int(c)
                          for k, c in f.den.to_dict().items()})
    return frac.new(num, den)
