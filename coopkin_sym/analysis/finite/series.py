"""Power series over Q truncated at a total degree: the arithmetic of a local expansion.

A :class:`SeriesField` is a :class:`~coopkin_sym.analysis.sweep.chains.Field` whose
elements are polynomials over Q (flint ``fmpq_mpoly``) in the local coordinates at a
configuration, cut after the terms of total degree ``order``: every product is
truncated, so the terms up to that degree are exact and nothing above it is kept.
Elements with a nonzero constant term are invertible (:meth:`SeriesField.inverse`).

Example
-------
>>> field = SeriesField(("u",), 4)
>>> (u,) = field.gens
>>> str(field.inverse(field.one + u * u))
'u^4 - u^2 + 1'
"""

from __future__ import annotations

from collections.abc import Sequence

import flint

from coopkin_sym.analysis.sweep.chains import Field, Terms
from coopkin_sym.errors import FiniteMobilityError


class SeriesField(Field):
    """Truncated power series over Q in ``names``, exact up to total degree ``order``.

    Example
    -------
    >>> field = SeriesField(("x", "y"), 2)
    >>> x, y = field.gens
    >>> str(field.red((field.one + x + y) ** 3))
    '3*x^2 + 6*x*y + 3*y^2 + 3*x + 3*y + 1'
    """

    def __init__(self, names: Sequence[str], order: int):
        self.names = tuple(names)
        self.order = order
        self.ctx = flint.fmpq_mpoly_ctx.get(self.names or ("_",), "deglex")
        self.one, self.zero = self.ctx.constant(1), self.ctx.constant(0)
        self.gens = self.ctx.gens()[: len(self.names)]

    def red(self, x):
        """``x`` without its terms of total degree above :attr:`order`."""
        if not isinstance(x, flint.fmpq_mpoly):
            return self.ctx.constant(x)
        if x.total_degree() <= self.order:
            return x
        return self.ctx.from_dict({m: c for m, c in x.to_dict().items()
                                   if sum(m) <= self.order})

    def mul(self, a, b):
        """The truncated product."""
        return self.red(a * b)

    def ratio(self, a: int, b: int):
        return self.ctx.constant(flint.fmpq(a, b))

    def const(self, terms: Terms):
        if any(any(exps) for exps, _, _ in terms):
            raise FiniteMobilityError("a local expansion needs a value for every parameter")
        return self.ctx.constant(sum((flint.fmpq(n, d) for _, n, d in terms),
                                     flint.fmpq(0)))

    def constant_term(self, x) -> flint.fmpq:
        """The value at the expansion point."""
        return x.to_dict().get((0,) * len(self.ctx.gens()), flint.fmpq(0))

    def inverse(self, x):
        """``1 / x`` for an element with a nonzero constant term."""
        c = self.constant_term(x)
        if c == 0:
            raise FiniteMobilityError("no inverse: the constant term is zero")
        e = self.red(x / c - self.one)          # 1/x = (1/c) * sum (-e)^k
        out, power = self.one, self.one
        for _ in range(self.order):
            power = self.mul(power, -e)
            out = out + power
        return self.red(out / c)

    def lowest(self, x) -> tuple[int, object]:
        """The order of ``x`` (the lowest total degree of its terms) and its initial
        form (those terms), or ``(order + 1, 0)`` when ``x`` vanishes to the truncation."""
        terms = x.to_dict()
        if not terms:
            return self.order + 1, self.zero
        d = int(min(sum(int(e) for e in m) for m in terms))
        return d, self.ctx.from_dict({m: c for m, c in terms.items() if sum(m) == d})
