"""Batched evaluation and Gaussian elimination modulo a word-size prime, on numpy.

A polynomial matrix with integer coefficients is given as a list of terms (exponent
vector, coefficient, flat entry index). :func:`evaluate` reduces it modulo a prime
``p`` at a whole batch of integer points at once, and :func:`rank_profile` eliminates
a batch of matrices modulo ``p`` column by column, fraction-free (no inverses), all in
``int64``: every residue is below ``p < 2**31``, so a product of two fits.

Reduction modulo ``p`` is a ring homomorphism, so the rank of a matrix modulo ``p``
never exceeds its rank over the rationals: a batch element whose modular rank reaches
a known upper bound (the generic rank) has that rank over Q, certified.

Example
-------
>>> import numpy as np
>>> a = np.array([[[1, 2], [2, 4]], [[1, 2], [3, 4]]]).transpose(1, 2, 0)  # (m, n, B)
>>> rank_profile(a, PRIME)[0].tolist()
[1, 2]
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

#: The default prime: 2**31 - 1 (a Mersenne prime, 3 mod 4, so -1 is not a square).
PRIME = 2**31 - 1


def evaluate(exponents: np.ndarray, coefficients: np.ndarray, entries: np.ndarray,
             size: int, values: np.ndarray, p: int = PRIME) -> np.ndarray:
    """Evaluate a polynomial matrix modulo ``p`` at a batch of points.

    Parameters
    ----------
    exponents
        ``(T, V)`` non-negative exponents of the ``T`` terms in ``V`` variables.
    coefficients
        ``(T,)`` coefficients already reduced modulo ``p`` (``int64``).
    entries
        ``(T,)`` flat index of the matrix entry each term belongs to.
    size
        Number of matrix entries (``rows * cols``).
    values
        ``(V, B)`` residues of the variables at the ``B`` points.

    Returns
    -------
    numpy.ndarray
        ``(size, B)`` residues in ``[0, p)``.

    Example
    -------
    >>> import numpy as np
    >>> e = np.array([[2, 0], [0, 1]]); c = np.array([1, 3]); k = np.array([0, 1])
    >>> evaluate(e, c, k, 2, np.array([[2, 5], [7, 1]]), 11).tolist()   # x^2, 3y
    [[4, 3], [10, 3]]
    """
    batch = values.shape[1]
    out = np.zeros((size, batch), dtype=np.int64)
    powers: dict[tuple[int, int], np.ndarray] = {}

    def power(v: int, e: int) -> np.ndarray:
        key = (v, e)
        if key not in powers:
            if e == 1:
                powers[key] = values[v] % p
            else:
                half = power(v, e // 2)
                sq = half * half % p
                powers[key] = sq if e % 2 == 0 else sq * power(v, 1) % p
        return powers[key]

    monomials: dict[tuple[int, ...], np.ndarray | None] = {}
    for exps, coef, entry in zip(exponents.tolist(), coefficients.tolist(),
                                 entries.tolist(), strict=True):
        key = tuple(exps)
        if key not in monomials:
            mono = None
            for v, e in enumerate(exps):
                if e:
                    mono = power(v, e) if mono is None else mono * power(v, e) % p
            monomials[key] = mono
        mono = monomials[key]
        if mono is None:
            out[entry] += coef
            out[entry] %= p
        else:
            out[entry] += mono * coef
            out[entry] %= p
    return out


def rank_profile(matrices: np.ndarray, p: int = PRIME,
                 prefix: int | None = None) -> tuple[np.ndarray, np.ndarray | None]:
    """Ranks modulo ``p`` of a batch of matrices, fraction-free Gaussian elimination.

    Parameters
    ----------
    matrices
        ``(m, n, B)`` residues in ``[0, p)`` (``int64``); overwritten.
    prefix
        Also count the pivots in the first ``prefix`` columns: the rank of those
        columns alone.

    Returns
    -------
    (ranks, prefix ranks)
        ``(B,)`` arrays (the second ``None`` without ``prefix``).

    Example
    -------
    >>> import numpy as np
    >>> a = np.array([[[0, 1], [1, 1]], [[1, 2], [2, 4]]]).transpose(1, 2, 0)
    >>> r, r1 = rank_profile(a, 7, prefix=1)
    >>> r.tolist(), r1.tolist()
    ([2, 1], [1, 1])
    """
    m, n, batch = matrices.shape
    rank = np.zeros(batch, dtype=np.int64)
    first = None
    cols = np.arange(batch)
    for c in range(n):
        if prefix is not None and c == prefix:
            first = rank.copy()
        col = matrices[:, c, :]
        nonzero = col != 0
        has = nonzero.any(axis=0)
        if not has.any():
            continue
        rank += has
        if c == n - 1:
            break
        pivot = nonzero.argmax(axis=0)
        rest = matrices[:, c + 1:, :]
        prow = rest[pivot, :, cols].T                # (n - c - 1, B)
        scale = np.where(has, col[pivot, cols], 1)    # nonzero pivot (or 1: no pivot)
        # every row becomes pivot * row - row[c] * pivot_row; the pivot row becomes 0
        rest *= scale
        rest -= col[:, None, :] * prow[None, :, :]
        np.remainder(rest, p, out=rest)
    if prefix is not None and first is None:
        first = rank.copy()
    return rank, first


def residues(numbers: Sequence[int], p: int = PRIME) -> np.ndarray:
    """Python integers (any size) reduced modulo ``p``, as ``int64``.

    Example
    -------
    >>> residues([-1, 2**70], 7).tolist()
    [6, 2]
    """
    return np.array([int(x) % p for x in numbers], dtype=np.int64)
