"""Size estimates for the polynomial operations flint cannot interrupt.

A resultant, a factorization or a gcd of python-flint runs in C until it is done: a
wall-clock bound (:mod:`coopkin_sym.exact.deadline`) is checked only between such
calls. Before one on large inputs the callers estimate the size of what it makes
(from degrees and term counts, without computing it) and skip it over a budget, saying
so. The estimates are upper bounds of the number of terms, from degree bounds:

* a resultant in ``x_k`` of ``p`` (degree ``m`` in ``x_k``) and ``q`` (degree ``n``)
  has degree at most ``n deg_i p + m deg_i q`` in each other variable ``x_i`` and total
  degree at most ``n deg p + m deg q``;
* an ``r x r`` determinant has degree at most the sum over its rows of the largest
  degree of an entry there, in each variable and in total.

The number of terms of a polynomial in ``v`` variables with degrees at most ``d_i``
and total degree at most ``D`` is at most ``min(prod (d_i + 1), C(D + v, v))``.

Example
-------
>>> import flint
>>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
>>> x, y = ctx.gens()
>>> resultant_terms(x**2 + y**2 - 1, x - y, 0)   # res = 2 y^2 - 1: degree 4 at most
5
>>> determinant_terms([[x, y], [y, x]])              # x^2 - y^2: degree 2, 3 terms at most
6
"""

from __future__ import annotations

from collections.abc import Sequence
from math import comb, prod

import flint

Poly = flint.fmpz_mpoly

__all__ = ["coefficient_bits", "determinant_terms", "resultant_terms", "resultant_work",
           "terms_bound"]


def terms_bound(degrees: Sequence[int], total: int) -> int:
    """Most terms of a polynomial with these degrees in its variables (those of
    positive degree count) and this total degree."""
    used = [int(d) for d in degrees if d > 0]
    total = int(total)
    if not used or total <= 0:
        return 1
    return min(prod(d + 1 for d in used), comb(total + len(used), len(used)))


def resultant_terms(p: Poly, q: Poly, k: int) -> int:
    """An upper bound of the terms of the resultant of ``p`` and ``q`` in ``x_k``."""
    dp, dq = [int(d) for d in p.degrees()], [int(d) for d in q.degrees()]
    m, n = dp[k], dq[k]
    if m <= 0 or n <= 0:
        return max(len(p), len(q))
    degrees = [n * a + m * b for i, (a, b) in enumerate(zip(dp, dq, strict=True)) if i != k]
    return terms_bound(degrees, n * int(p.total_degree()) + m * int(q.total_degree()))


def coefficient_bits(p: Poly) -> int:
    """Bits of the largest coefficient of ``p`` (0 for the zero polynomial)."""
    coeffs = p.coeffs()
    if not coeffs:
        return 0
    return max(int(max(coeffs)), -int(min(coeffs))).bit_length()


def resultant_work(p: Poly, q: Poly, k: int) -> int:
    """A measure of the work of the resultant of ``p`` and ``q`` in ``x_k``: the
    degrees ``m``, ``n`` in ``x_k`` times the terms of the result
    (:func:`resultant_terms`) times a bound of the bits of its coefficients
    (``n bits(p) + m bits(q) + (m + n) log2(terms)``, from Hadamard's bound on the
    Sylvester matrix). Term counts alone miss the cost of large coefficients: a
    resultant of two polynomials in two variables can run for minutes with a result of
    a few hundred terms of thousands of bits.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    >>> x, y = ctx.gens()
    >>> resultant_work(x**2 + y**2 - 1, x - y, 0)     # 2 * 1 * 5 terms * 9 bits
    90
    """
    m, n = int(p.degrees()[k]), int(q.degrees()[k])
    if m <= 0 or n <= 0:
        return max(len(p), len(q))
    bits = (n * coefficient_bits(p) + m * coefficient_bits(q)
            + (m + n) * max(len(p), len(q)).bit_length())
    return m * n * resultant_terms(p, q, k) * bits


def determinant_terms(rows: Sequence[Sequence[Poly]]) -> int:
    """An upper bound of the terms of the determinant of a square matrix."""
    nvars = None
    degrees: list[int] = []
    total = 0
    for row in rows:
        entries = [e for e in row if not e.is_zero()]
        if not entries:
            return 0
        if nvars is None:
            nvars = len(entries[0].degrees())
            degrees = [0] * nvars
        for i in range(nvars):
            degrees[i] += max(int(e.degrees()[i]) for e in entries)
        total += max(int(e.total_degree()) for e in entries)
    return terms_bound(degrees, total)
