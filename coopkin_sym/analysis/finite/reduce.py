"""The constraint map reduced to the first-order motions (Lyapunov-Schmidt).

With ``J`` of rank ``r``, ``r`` independent rows of ``F`` are solved for the ``r``
coordinates of a pivot set as power series in the other ``n = N - r`` (the implicit
function theorem; by the chord iteration ``y <- y - A^-1 F_r(x, y)``, each step exact
to one more degree). Near the configuration the closed system is then, exactly, the
zero set of the other rows ``g(x) = F_rest(x, y(x))``, whose linear parts vanish: the
first-order motions are ``x``, and what ``g`` says at higher orders is what decides
which of them are finite motions.

Example
-------
>>> from coopkin_sym.model import load_model
>>> from coopkin_sym.model.configuration import Configuration
>>> from coopkin_sym.analysis.finite.constraints import ConstraintMap
>>> model = load_model("paper-case1-planar")
>>> cmap = ConstraintMap(model, Configuration.parse(model, "q1=pi/2,q2=pi/2,L=1"))
>>> red = reduce_map(cmap, 2)
>>> red.free, [str(g) for g in red.g]
(('u_q1', 'u_q2'), ['-4*u_q1*u_q2 + 4*u_q2^2'])
"""

from __future__ import annotations

from dataclasses import dataclass

import flint

from coopkin_sym.analysis.finite.constraints import ConstraintMap


@dataclass(frozen=True)
class Reduced:
    """``g(x)`` (series in :attr:`free`, exact to degree ``order``), with the rank ``r``
    of ``J``, the rows solved (``rows``) and the pivot coordinates (``pivots``).

    Example
    -------
    >>> Reduced((), ("x",), (), [], 3, 0, 2).n
    1
    """

    pivots: tuple[str, ...]
    free: tuple[str, ...]
    rows: tuple[int, ...]
    g: list
    order: int
    rank: int
    equations: int

    @property
    def n(self) -> int:
        """The dimension of the first-order motions."""
        return len(self.free)


def _pivots(matrix: list[list]) -> tuple[int, list[int]]:
    """The rank of an exact matrix and the pivot columns of its reduced echelon form."""
    if not matrix or not matrix[0]:
        return 0, []
    m = flint.fmpq_mat(len(matrix), len(matrix[0]), [x for row in matrix for x in row])
    rref, rank = m.rref()
    cols = []
    for i in range(rank):
        cols.append(next(j for j in range(m.ncols()) if rref[i, j] != 0))
    return rank, cols


def echelon(matrix: list[list]) -> tuple[int, list[int], list[list]]:
    """The rank, the pivot columns and the reduced echelon form of a matrix over a
    field whose elements have ``+ - * /`` and an exact zero test (as
    :class:`~coopkin_sym.exact.numberfield.Number`), by Gauss-Jordan elimination.

    Example
    -------
    >>> from fractions import Fraction
    >>> echelon([[Fraction(1), Fraction(2)], [Fraction(2), Fraction(4)]])[:2]
    (1, [0])
    """
    a = [list(row) for row in matrix]
    if not a or not a[0]:
        return 0, [], a
    rows, cols = len(a), len(a[0])
    r, pivots = 0, []
    for j in range(cols):
        k = next((i for i in range(r, rows) if a[i][j] != 0), None)
        if k is None:
            continue
        a[r], a[k] = a[k], a[r]
        inv = 1 / a[r][j]
        a[r] = [x * inv for x in a[r]]
        for i in range(rows):
            if i != r and a[i][j] != 0:
                c = a[i][j]
                a[i] = [x - c * y for x, y in zip(a[i], a[r], strict=True)]
        pivots.append(j)
        r += 1
        if r == rows:
            break
    return r, pivots, a


def inverse(a: list[list]) -> list[list]:
    """The inverse of an invertible square matrix (elements as in :func:`echelon`)."""
    n = len(a)
    one, zero = a[0][0] * 0 + 1, a[0][0] * 0
    wide = [list(row) + [one if i == j else zero for j in range(n)]
            for i, row in enumerate(a)]
    _, _, e = echelon(wide)
    return [row[n:] for row in e]


def reduce_map(cmap: ConstraintMap, order: int) -> Reduced:
    """``g`` of :mod:`this module <coopkin_sym.analysis.finite.reduce>` to ``order``."""
    names = cmap.names
    if cmap.point is None:
        jac = [[flint.fmpq(x) for x in row] for row in cmap.linear()]
        rank, pivot_cols = _pivots(jac)
        transposed = [list(col) for col in zip(*jac, strict=True)] if jac else []
        _, rows = _pivots(transposed)
    else:                       # over the number field of the configuration
        jac = cmap.linear()
        rank, pivot_cols, _ = echelon(jac)
        transposed = [list(col) for col in zip(*jac, strict=True)] if jac else []
        _, rows, _ = echelon(transposed)
    free = [k for k in range(len(names)) if k not in pivot_cols]
    field = cmap.series_field(tuple(names[k] for k in free), order)
    x = dict(zip(free, field.gens, strict=True))
    if rank and cmap.point is None:
        a = flint.fmpq_mat(rank, rank, [jac[i][j] for i in rows for j in pivot_cols])
        inv = a.inv()
        a_inv = [[inv[i, j] for j in range(rank)] for i in range(rank)]
    elif rank:
        a_inv = [[field.lift(c) for c in row] for row in
                 inverse([[jac[i][j] for j in pivot_cols] for i in rows])]
    y = {k: field.zero for k in pivot_cols}
    for _ in range(order):
        z = [x[k] if k in x else y[k] for k in range(len(names))]
        values = cmap.evaluate(field, z)
        solved = [values[i] for i in rows]
        for a_row, k in enumerate(pivot_cols):
            step = sum((a_inv[a_row][b] * solved[b] for b in range(rank)), field.zero)
            y[k] = field.red(y[k] - step)
        if all(v.is_zero() for v in solved):
            break
    z = [x[k] if k in x else y[k] for k in range(len(names))]
    values = cmap.evaluate(field, z)
    rest = [values[i] for i in range(len(values)) if i not in rows]
    return Reduced(tuple(names[k] for k in pivot_cols), field.names, tuple(rows),
                   [field.red(v) for v in rest], order, rank, len(values))
