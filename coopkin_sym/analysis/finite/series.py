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

    def lift(self, x):
        """``x`` (a rational or a series) as a series."""
        return x if isinstance(x, flint.fmpq_mpoly) else self.ctx.constant(x)

    def coefficients(self, x) -> dict:
        """The coefficient (``fmpq``) of each monomial of ``x``."""
        return {tuple(int(e) for e in m): c for m, c in x.to_dict().items()}

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


class AlgebraicSeriesField(SeriesField):
    """Truncated power series over a real number field ``Q(alpha)``
    (:class:`~coopkin_sym.exact.numberfield.RealNumberField`): polynomials over Q in
    ``names`` and one more variable ``alpha``, whose degree is kept below that of its
    minimal polynomial ``g`` (``alpha^d`` rewritten by ``g(alpha) = 0``); the truncation
    counts the degree in ``names`` only. Coefficients come out as
    :class:`~coopkin_sym.exact.numberfield.Number` (:meth:`coefficients`).

    Example
    -------
    >>> import flint
    >>> from coopkin_sym.exact.numberfield import RealNumberField
    >>> from coopkin_sym.exact.realroot import RealRoot
    >>> k = RealNumberField(flint.fmpq_poly([-2, 0, 1]), RealRoot.all_of([-2, 0, 1])[1])
    >>> f = AlgebraicSeriesField(("u",), 2, k)
    >>> (u,) = f.gens
    >>> s = f.number(k.element([0, 1]))                  # sqrt(2)
    >>> str(f.red((s + u) ** 3))
    '3*u^2*alpha + 6*u + 2*alpha'
    """

    def __init__(self, names: Sequence[str], order: int, field):
        self.names = tuple(names)
        self.order = order
        self.numberfield = field
        self.ctx = flint.fmpq_mpoly_ctx.get(self.names + ("alpha",), "deglex")
        self.one, self.zero = self.ctx.constant(1), self.ctx.constant(0)
        gens = self.ctx.gens()
        self.gens = gens[: len(self.names)]
        self.alpha = gens[-1]
        d = field.g.degree()
        self._degree = d
        # alpha^k modulo g, for k < 2 d - 1 (products of two reduced elements)
        self._powers = [field.element(flint.fmpq_poly([0] * k + [1]))
                        for k in range(2 * d + 1)]

    def number(self, value):
        """An element of ``Q(alpha)`` (``fmpq_poly`` in alpha, or a
        :class:`~coopkin_sym.exact.numberfield.Number`) as a constant series."""
        value = getattr(value, "value", value)
        value = self.numberfield.element(value)
        n = len(self.names)
        return self.ctx.from_dict({(0,) * n + (i,): c for i, c in enumerate(value.coeffs())
                                   if c != 0})

    def lift(self, x):
        """``x`` (a rational, series or number) as a series."""
        if isinstance(x, flint.fmpq_mpoly):
            return x
        if hasattr(x, "field") or isinstance(x, flint.fmpq_poly):
            return self.number(x)
        return self.ctx.constant(x)

    def red(self, x):
        if not isinstance(x, flint.fmpq_mpoly):
            return self.lift(x)
        n, d = len(self.names), self._degree
        terms = x.to_dict()
        if all(m[n] < d and sum(m[:n]) <= self.order for m in terms):
            return x
        out: dict = {}
        for m, c in terms.items():
            if sum(m[:n]) > self.order:
                continue
            e = m[n]
            if e < d:
                out[m] = out.get(m, 0) + c
                continue
            power = self._powers[e] if e < len(self._powers) else self.numberfield.element(
                flint.fmpq_poly([0] * e + [1]))
            for i, a in enumerate(power.coeffs()):
                if a != 0:
                    key = tuple(m[:n]) + (i,)
                    out[key] = out.get(key, 0) + c * a
        return self.ctx.from_dict({m: c for m, c in out.items() if c != 0})

    def mul(self, a, b):
        return self.red(a * b)

    def coefficients(self, x) -> dict:
        """The coefficient of each monomial in ``names`` of ``x``, in ``Q(alpha)``
        (:class:`~coopkin_sym.exact.numberfield.Number`)."""
        n = len(self.names)
        grouped: dict = {}
        for m, c in x.to_dict().items():
            grouped.setdefault(tuple(int(e) for e in m[:n]), {})[int(m[n])] = c
        out = {}
        for m, parts in grouped.items():
            coeffs = [parts.get(i, 0) for i in range(max(parts) + 1)]
            v = self.numberfield.number(flint.fmpq_poly(coeffs))
            if v:
                out[m] = v
        return out

    def constant_term(self, x):
        """The value at the expansion point, in ``Q(alpha)``."""
        zero = self.numberfield.number(0)
        return self.coefficients(x).get((0,) * len(self.names), zero)

    def inverse(self, x):
        c = self.constant_term(x)
        if not c:
            raise FiniteMobilityError("no inverse: the constant term is zero")
        inv = self.number(1 / c)
        e = self.red(inv * x - self.one)
        out, power = self.one, self.one
        for _ in range(self.order):
            power = self.mul(power, -e)
            out = out + power
        return self.red(out * inv)

    def lowest(self, x) -> tuple[int, object]:
        terms = x.to_dict()
        n = len(self.names)
        if not terms:
            return self.order + 1, self.zero
        d = int(min(sum(int(e) for e in m[:n]) for m in terms))
        return d, self.ctx.from_dict({m: c for m, c in terms.items() if sum(m[:n]) == d})
