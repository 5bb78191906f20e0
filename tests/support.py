"""Helpers shared by the tests: exact ranks and subspace equality, and the loci of
the shipped examples, computed once per test process.

Example
-------
>>> import sympy as sp
>>> same_span(sp.Matrix([[1], [2]]), sp.Matrix([[-2], [-4]]))
True
>>> same_span([sp.Matrix([1, 0])], [sp.Matrix([0, 1])])
False
"""

from __future__ import annotations

import copy
import functools

import sympy as sp
from sympy.polys.matrices import DomainMatrix

import coopkin_sym
from coopkin_sym.analysis.locus.search import compute_locus
from coopkin_sym.analysis.locus.types import Locus


def texts(polynomials) -> list[str]:
    """The texts of exact polynomials (a component's equations or outside)."""
    return [p.text for p in polynomials]


def rank(m: sp.Matrix) -> int:
    """The exact rank of ``m`` over the field of its entries (DomainMatrix: no
    simplification heuristics); 0 for an empty matrix."""
    if 0 in m.shape:
        return 0
    return DomainMatrix.from_Matrix(sp.Matrix(m)).to_field().rank()


def same_span(a: sp.Matrix | list[sp.Matrix], b: sp.Matrix | list[sp.Matrix]) -> bool:
    """Whether the columns of ``a`` and ``b`` span the same space (exactly); a list
    of column vectors is read as the matrix they make."""
    a = sp.Matrix.hstack(*a) if isinstance(a, list) else a
    b = sp.Matrix.hstack(*b) if isinstance(b, list) else b
    if a.cols == 0 or b.cols == 0:
        return rank(a) == rank(b) == 0
    return rank(a) == rank(b) == rank(a.row_join(b))


@functools.cache
def _shipped_locus(name: str) -> Locus:
    return compute_locus(coopkin_sym.load(name))


def shipped_locus(name: str) -> Locus:
    """The locus of the shipped example ``name`` (all joints free, the defaults of
    ``compute_locus``), computed once per process; each call returns a copy, so a test
    may change it."""
    return copy.deepcopy(_shipped_locus(name))
