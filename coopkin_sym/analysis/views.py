"""Exact views of results for scripts and notebooks: whether two blocks span the same
subspace, the contact points of an analysis.

Example
-------
>>> import sympy as sp
>>> same_span(sp.Matrix([[1, 0], [0, 1]]), sp.Matrix([[1, 1], [1, -1]]))
True
"""

from __future__ import annotations

import sympy as sp
from sympy.polys.matrices import DomainMatrix

from coopkin_sym.exact.matrix import SYMPY, rank


def exact_rank(matrix: sp.Matrix) -> int:
    """The rank of ``matrix`` (rational or rational-function entries), exactly: over
    the field its entries live in, by the rank service
    (:data:`~coopkin_sym.exact.matrix.SYMPY`).

    Example
    -------
    >>> t = sp.Symbol("t")
    >>> exact_rank(sp.Matrix([[t, 1], [t**2, t]])), exact_rank(sp.zeros(2, 0))
    (1, 0)
    """
    if 0 in matrix.shape:
        return 0
    return rank(DomainMatrix.from_Matrix(sp.Matrix(matrix)), None, SYMPY)


def same_span(a: sp.Matrix, b: sp.Matrix) -> bool:
    """Whether the columns of ``a`` and ``b`` span the same space (exact ranks).

    Example
    -------
    >>> same_span(sp.Matrix([1, 2]), sp.Matrix([2, 5]))
    False
    """
    if a.rows != b.rows:
        return False
    ra, rb = exact_rank(a), exact_rank(b)
    return ra == rb == exact_rank(sp.Matrix.hstack(a, b))


def contact_points(analysis) -> list[tuple[sp.Expr, ...]]:
    """The contact points of an analysis (base coordinates), exact SymPy values in its
    variables, one per contact in the model's order.

    Example
    -------
    >>> from coopkin_sym import load
    >>> contact_points(load("five-bar").analyze("L=1"))
    [(0, 2, 0), (0, 2, 0)]
    """
    from coopkin_sym.exact.sympy_bridge import ratfunc_to_sympy

    kin = analysis.kinematics
    return [tuple(ratfunc_to_sympy(x, kin.symbols) for x in point) for point in kin.points]


__all__ = ["contact_points", "exact_rank", "same_span"]
