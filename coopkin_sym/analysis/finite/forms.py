"""Exact facts about the initial forms of the reduced equations: a quadratic form's
diagonal form over Q (its signature and rank), and the real directions of binary forms.

Example
-------
>>> ds, forms = diagonal_form([[0, 1], [1, 0]])     # 2 x y = (x + y)^2 / 2 - (x - y)^2 / 2
>>> [str(d) for d in ds], [[str(c) for c in f] for f in forms]
(['2', '-1/2'], [['1/2', '1/2'], ['1', '-1']])
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction

import flint

from coopkin_sym.exact.realroot import RealRoot


def diagonal_form(matrix: Sequence[Sequence]) -> tuple[list[Fraction], list[list[Fraction]]]:
    """``h(x) = x^T A x`` as ``sum d_i l_i(x)^2``: the nonzero ``d_i`` and the
    coefficient rows of the linear forms ``l_i`` (independent), by symmetric
    elimination over Q. The signature is the signs of the ``d_i``, the rank their count.

    Example
    -------
    >>> ds, forms = diagonal_form([[1, 0], [0, 1]])
    >>> [str(d) for d in ds], [[str(c) for c in f] for f in forms]
    (['1', '1'], [['1', '0'], ['0', '1']])
    """
    n = len(matrix)
    a = [[Fraction(x) for x in row] for row in matrix]
    ds: list[Fraction] = []
    rows: list[list[Fraction]] = []
    while True:
        # v with v^T A v = d != 0: a unit vector on a nonzero diagonal entry, else the
        # sum of two with a nonzero entry between them; then A -> A - (A v)(A v)^T / d
        k = next((i for i in range(n) if a[i][i] != 0), None)
        if k is not None:
            v = [Fraction(int(i == k)) for i in range(n)]
        else:
            pair = next(((i, j) for i in range(n) for j in range(i + 1, n) if a[i][j] != 0),
                        None)
            if pair is None:
                return ds, rows
            v = [Fraction(int(i in pair)) for i in range(n)]
        w = [sum((a[i][j] * v[j] for j in range(n)), Fraction(0)) for i in range(n)]
        d = sum((v[i] * w[i] for i in range(n)), Fraction(0))
        ds.append(d)
        rows.append([x / d for x in w])
        for i in range(n):
            for j in range(n):
                a[i][j] -= w[i] * w[j] / d


def quadratic_matrix(h, n: int) -> list[list[Fraction]]:
    """The symmetric matrix of a quadratic form (flint polynomial in ``n`` variables)."""
    a = [[Fraction(0)] * n for _ in range(n)]
    for mono, c in h.to_dict().items():
        idx = [i for i, e in enumerate(mono[:n]) for _ in range(e)]
        c = Fraction(int(c.p), int(c.q))
        if idx[0] == idx[1]:
            a[idx[0]][idx[0]] += c
        else:
            a[idx[0]][idx[1]] += c / 2
            a[idx[1]][idx[0]] += c / 2
    return a


def real_directions(forms: Sequence, n: int) -> list[tuple[object, int]] | None:
    """The common real zeros on the projective line of binary forms (``n == 2``), as
    ``(direction, multiplicity in the first form)``: a direction is ``(1, 0)``, a
    rational ``(x, 1)``, or ``(root, 1)`` with a :class:`RealRoot`. None for ``n != 2``.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "deglex")
    >>> x, y = ctx.gens()
    >>> [(str(d[0]), m) for d, m in real_directions([x * y * (x - 2 * y)], 2)]
    [('1', 1), ('0', 1), ('2', 1)]
    """
    if n != 2:
        return None
    ctx = forms[0].context()
    g = forms[0]
    for h in forms[1:]:
        g = g.gcd(h)
    if g.is_constant():
        return []
    x, y = ctx.gens()[:2]
    out: list[tuple[object, int]] = []
    _, factors = g.factor()
    first = dict((str(f), e) for f, e in forms[0].factor()[1])
    for f, _e in factors:
        mult = first.get(str(f), 1)
        if f.degrees()[0] == 0:                        # a power of y: the direction x
            out.append(((1, 0), mult))
            continue
        coeffs = [0] * (f.degrees()[0] + 1)
        for mono, c in f.to_dict().items():
            coeffs[mono[0]] += c
        if len(coeffs) == 2:
            out.append(((-coeffs[0] / coeffs[1], 1), mult))
            continue
        den = 1
        for c in coeffs:
            den = den * int(flint.fmpq(c).q) // _gcd(den, int(flint.fmpq(c).q))
        ints = [int(flint.fmpq(c) * den) for c in coeffs]
        for root in RealRoot.all_of(ints):
            out.append(((root, 1), mult))
    return out


def _gcd(a: int, b: int) -> int:
    while b:
        a, b = b, a % b
    return a
