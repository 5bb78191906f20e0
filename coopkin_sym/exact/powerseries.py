"""Truncated power series in one variable ``t`` over Q or a number field ``Q(alpha)``.

An element is a tuple of ``d`` python-flint ``fmpq_poly`` in ``t`` (``d`` the degree of
the field; 1 over Q): the series is ``sum_i c_i(t) alpha^i``. Products multiply the
parts with ``mul_low`` (exact to the precision asked) and rewrite ``alpha^k``,
``k >= d``, by the minimal polynomial of ``alpha``. This is what Newton's method on a
polynomial system along a curve needs (:mod:`coopkin_sym.analysis.finite.curve`):
thousands of exact terms in milliseconds.

Example
-------
>>> import flint
>>> ring = SeriesRing(flint.fmpq_poly([-2, 0, 1]))            # Q(sqrt 2)
>>> s = ring.constant([0, 1])                               # sqrt(2)
>>> t = ring.variable()
>>> x = ring.add(s, t)                                      # sqrt(2) + t
>>> [ring.coefficient(ring.mul(x, x, 3), k) for k in range(3)]  # 2 + 2 sqrt(2) t + t^2
[[2, 0], [0, 2], [1, 0]]
"""

from __future__ import annotations

from collections.abc import Sequence

import flint

__all__ = ["SeriesRing"]

Series = tuple  # of fmpq_poly, one per power of alpha


class SeriesRing:
    """Truncated power series in ``t`` over ``Q[alpha]/(g)`` (``g`` irreducible) or over
    Q (``g`` None).

    Example
    -------
    >>> ring = SeriesRing()
    >>> t = ring.variable()
    >>> one_minus = ring.sub(ring.constant([1]), t)
    >>> ring.coefficient(ring.inverse(one_minus, 5), 4)         # 1/(1 - t) = sum t^k
    [1]
    """

    def __init__(self, g: flint.fmpq_poly | None = None):
        self.d = 1 if g is None else g.degree()
        self.g = g
        # alpha^k as a combination of 1, alpha, ..., alpha^(d-1), for k < 2 d - 1
        self._powers = []
        if g is not None:
            for k in range(2 * self.d - 1):
                r = flint.fmpq_poly([0] * k + [1]) % g
                self._powers.append([r[i] for i in range(self.d)])

    def zero(self) -> Series:
        return tuple(flint.fmpq_poly() for _ in range(self.d))

    def constant(self, coeffs: Sequence) -> Series:
        """The element ``sum_i coeffs[i] alpha^i`` (rationals) as a constant series."""
        out = [flint.fmpq_poly([c]) if c != 0 else flint.fmpq_poly() for c in coeffs]
        return tuple(out + [flint.fmpq_poly()] * (self.d - len(out)))

    def variable(self) -> Series:
        """The series ``t``."""
        return (flint.fmpq_poly([0, 1]),) + tuple(flint.fmpq_poly()
                                                  for _ in range(self.d - 1))

    def add(self, a: Series, b: Series) -> Series:
        return tuple(x + y for x, y in zip(a, b, strict=True))

    def sub(self, a: Series, b: Series) -> Series:
        return tuple(x - y for x, y in zip(a, b, strict=True))

    def truncate(self, a: Series, n: int) -> Series:
        return tuple(x.truncate(n) for x in a)

    def mul(self, a: Series, b: Series, n: int) -> Series:
        """``a b`` modulo ``t^n``."""
        if self.d == 1:
            return (a[0].mul_low(b[0], n),)
        parts = [flint.fmpq_poly() for _ in range(2 * self.d - 1)]
        for i, x in enumerate(a):
            if x.is_zero():
                continue
            for j, y in enumerate(b):
                if not y.is_zero():
                    parts[i + j] += x.mul_low(y, n)
        out = parts[: self.d]
        for k in range(self.d, 2 * self.d - 1):
            if parts[k].is_zero():
                continue
            for i, c in enumerate(self._powers[k]):
                if c != 0:
                    out[i] += parts[k] * c
        return tuple(out)

    def coefficient(self, a: Series, k: int) -> list:
        """The coefficient of ``t^k`` (rationals, one per power of alpha)."""
        return [x[k] if k <= x.degree() else flint.fmpq(0) for x in a]

    def is_zero(self, a: Series) -> bool:
        return all(x.is_zero() for x in a)

    def inverse(self, a: Series, n: int) -> Series:
        """``1 / a`` modulo ``t^n`` (the constant term of ``a`` nonzero), by Newton's
        iteration ``x <- x (2 - a x)`` from the inverse of the constant term."""
        c = self.coefficient(a, 0)
        inv = self._field_inverse(c)
        x = self.constant(inv)
        p = 1
        two = self.constant([2])
        while p < n:
            p = min(2 * p, n)
            x = self.mul(x, self.sub(two, self.mul(a, x, p)), p)
        return x

    def _field_inverse(self, c: list) -> list:
        if self.g is None:
            return [1 / c[0]]
        value = flint.fmpq_poly(list(c))
        d, s, _ = value.xgcd(self.g)
        inv = (s / d[0]) % self.g
        return [inv[i] for i in range(self.d)]
