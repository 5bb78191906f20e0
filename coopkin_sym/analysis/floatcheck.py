"""Floating-point comparisons: what a float rank test would say (never used to decide).

Everything here is deliberately *not* exact: it reproduces the usual float pipeline
(the matrices rounded to float64, ranks by ``numpy.linalg.matrix_rank`` with its
default tolerance) so that reports can show where it disagrees with the exact engine.

Example
-------
>>> from coopkin_sym import load
>>> a = load("paper-case1-hard").analyze("q1=-pi/2,q2=-pi/2,L=1")
>>> float_numbers(a) == a.numbers.as_dict()
True
"""

from __future__ import annotations

import numpy as np

from coopkin_sym.analysis.mobility import Analysis
from coopkin_sym.analysis.numbers import numbers_from_ranks
from coopkin_sym.errors import ArgumentError


def float_matrix(m) -> np.ndarray:
    """A SymPy matrix with numeric entries, rounded to float64."""
    return np.array([[float(e) for e in m.row(i)] for i in range(m.rows)],  # float-ok
                    dtype=float).reshape(m.shape)


def float_numbers(analysis: Analysis) -> dict[str, int]:
    """The seven numbers as a float pipeline computes them at a numeric configuration:
    ranks of ``Q``, ``H G^T`` and ``H D`` by ``numpy.linalg.matrix_rank``
    (default tolerance) on the float64 image of the exact matrices."""
    if analysis.variables:
        raise ArgumentError("float_numbers needs a configuration with every joint and "
                         f"parameter set (free: {', '.join(map(str, analysis.variables))})")
    q = float_matrix(analysis.Q)
    r, m = analysis.r, analysis.m

    def rank(a: np.ndarray) -> int:
        return int(np.linalg.matrix_rank(a)) if a.size else 0  # float-ok

    d = analysis.model.object_dim
    return numbers_from_ranks(m, r, rank(q), rank(q[:, :d]), rank(q[:, d:]),
                              dim=d).as_dict()
