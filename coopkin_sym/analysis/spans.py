"""Exact comparisons of the subspaces a result gives as matrix columns.

Example
-------
>>> import sympy as sp
>>> same_span(sp.Matrix([[1, 0], [0, 1]]), sp.Matrix([[1, 1], [1, -1]]))
True
"""

from __future__ import annotations

import sympy as sp
from sympy.polys.matrices import DomainMatrix


def exact_rank(matrix: sp.Matrix) -> int:
    """The rank of ``matrix`` (rational or rational-function entries), exactly: by
    elimination over the field its entries live in.

    Example
    -------
    >>> t = sp.Symbol("t")
    >>> exact_rank(sp.Matrix([[t, 1], [t**2, t]])), exact_rank(sp.zeros(2, 0))
    (1, 0)
    """
    if 0 in matrix.shape:
        return 0
    dm = DomainMatrix.from_Matrix(sp.Matrix(matrix))
    return dm.convert_to(dm.domain.get_field()).rank()


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


__all__ = ["exact_rank", "same_span"]
