"""One first-order motion: the closure polynomials along the curve, to a Bezout bound.

Let ``g_1, ..., g_r`` be polynomials in ``N = r + 1`` variables, zero at the origin,
with independent linear parts there: near it they cut out a smooth curve ``M``, which
lies on exactly one irreducible component ``C`` of their zero set (a curve). Let ``f``
be another polynomial, zero at the origin. If ``f`` does not vanish on ``C``, the
curve meets the hypersurface ``f = 0`` in finitely many points, with multiplicities
adding up to at most ``deg C deg f <= deg g_1 ... deg g_r deg f`` (Bezout's inequality:
the degrees of the components of ``g_1 = ... = g_r = 0`` add up to at most the product
of the degrees). At the origin, a smooth point of ``C``, that multiplicity is the order
in ``t`` of ``f(gamma(t))``, ``gamma`` a parametrization of ``M``. So when
``f(gamma(t))`` vanishes to an order above ``deg g_1 ... deg g_r deg f``, ``f``
vanishes on ``C``, and on ``M`` near the origin: exactly, with no Gröbner basis.

``gamma`` is computed by Newton's method on power series (:mod:`coopkin_sym.exact.
powerseries`): one coordinate along the curve's tangent is ``t``, the others follow
from ``g = 0``, the precision doubling at every step; over a number field the series
have coefficients in it (the polynomials then hold ``alpha`` as a last variable).

Example
-------
>>> import flint
>>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "degrevlex")
>>> x, y = ctx.gens()
>>> # y = x^2 near 0 (y - x^2 = 0); (y - x^2) (y + 1) vanishes on it, x y does not
>>> vanishes_along_curve([y - x**2], [(y - x**2) * (y + 1)], 2)
True
>>> vanishes_along_curve([y - x**2], [x * y], 2)
False
"""

from __future__ import annotations

import time
from math import prod

import flint

from coopkin_sym.analysis.finite.reduce import echelon, inverse
from coopkin_sym.exact.powerseries import SeriesRing

#: The largest Bezout bound worked to (above it the test is not tried).
MAX_BOUND = 20_000


def _terms(p, n: int, field) -> list[tuple[tuple[int, ...], list]]:
    """``p`` as ``(exponents in the n variables, coefficient)``, the coefficient the
    list of rationals of its powers of ``alpha`` (reduced modulo its minimal
    polynomial over a number field)."""
    grouped: dict = {}
    for mono, c in p.to_dict().items():
        key = tuple(int(e) for e in mono[:n])
        power = int(mono[n]) if field is not None else 0
        grouped.setdefault(key, {})[power] = c
    out = []
    for key, parts in grouped.items():
        if field is None:
            out.append((key, [parts[0]]))
            continue
        value = flint.fmpq_poly([parts.get(j, 0) for j in range(max(parts) + 1)]) % field.g
        coeffs = [value[i] for i in range(field.g.degree())]
        if any(c != 0 for c in coeffs):
            out.append((key, coeffs))
    return out


class _Evaluator:
    """Polynomials evaluated at a vector of series, modulo ``t^prec``."""

    def __init__(self, ring: SeriesRing, gamma: list, prec: int, degree: int):
        self.ring, self.prec = ring, prec
        self.powers = []
        for s in gamma:
            row = [ring.constant([1])]
            for _ in range(degree):
                row.append(ring.mul(row[-1], s, prec))
            self.powers.append(row)

    def __call__(self, terms: list) -> tuple:
        ring, prec = self.ring, self.prec
        total = ring.zero()
        for exps, coeff in terms:
            value = ring.constant(coeff)
            for j, e in enumerate(exps):
                if e:
                    value = ring.mul(value, self.powers[j][e], prec)
            total = ring.add(total, value)
        return total


def _number(field, coeffs: list):
    """An element of the field (a rational over Q) from its coefficients in alpha."""
    if field is None:
        return coeffs[0]
    return field.number(flint.fmpq_poly(list(coeffs)))


def _coeffs(field, x) -> list:
    if field is None:
        return [flint.fmpq(x)]
    v = field.element(x.value)
    return [v[i] for i in range(field.g.degree())]


def _curve(ring, g_terms, jac_terms, free: int, pivots: list[int], n: int, prec: int,
           inv0: list[list], deadline: float) -> list | None:
    """The parametrization ``gamma`` (``gamma[free] = t``) of the curve ``g = 0``
    modulo ``t^prec``, by Newton's method (None past the deadline)."""
    r = len(pivots)
    gamma = [ring.zero() for _ in range(n)]
    gamma[free] = ring.variable()
    degree = max(sum(e) for terms in g_terms for e, _ in terms)
    x = [[ring.constant(c) for c in row] for row in inv0]        # J^-1, exact mod t
    p, px = 1, 1
    while p < prec:
        if time.monotonic() > deadline:
            return None
        p2 = min(2 * p, prec)
        if px < p:               # refine the inverse to t^p: X <- X + X (I - J X)
            ev = _Evaluator(ring, gamma, p, degree)
            jac = [[ev(t) for t in row] for row in jac_terms]
            jx = [[_dot(ring, jac[i], [x[k][j] for k in range(r)], p) for j in range(r)]
                  for i in range(r)]
            rest = [[ring.sub(ring.constant([int(i == j)]), jx[i][j]) for j in range(r)]
                    for i in range(r)]
            x = [[ring.truncate(ring.add(x[i][j], _dot(ring, x[i], [rest[k][j] for k in
                                                                     range(r)], p)), p)
                  for j in range(r)] for i in range(r)]
            px = p
        ev = _Evaluator(ring, gamma, p2, degree)
        values = [ev(t) for t in g_terms]
        for i, k in enumerate(pivots):
            gamma[k] = ring.truncate(ring.sub(gamma[k], _dot(ring, x[i], values, p2)), p2)
        p = p2
    return gamma


def _dot(ring, a: list, b: list, prec: int):
    total = ring.zero()
    for x, y in zip(a, b, strict=True):
        total = ring.add(total, ring.mul(x, y, prec))
    return total


def vanishes_along_curve(independent: list, dependent: list, n: int, field=None,
                         timeout: float = 10.0) -> bool | None:
    """Whether every polynomial of ``dependent`` vanishes on the curve that the
    polynomials ``independent`` (``n - 1`` of them, independent linear parts at the
    origin) cut out near the origin (see the module's text): True or False, exactly;
    None when the Bezout bound is over :data:`MAX_BOUND` or the time bound is reached.
    The polynomials are ``fmpq_mpoly`` in ``n`` variables, over a real number field
    ``field`` with ``alpha`` as one more, last variable."""
    verdicts = curve_verdicts(independent, dependent, n, field, timeout)
    return None if verdicts is None else all(verdicts)


def curve_verdicts(independent: list, dependent: list, n: int, field=None,
                   timeout: float = 10.0) -> list[bool] | None:
    """For each polynomial of ``dependent``, whether it vanishes on the curve (as
    :func:`vanishes_along_curve`), or None when not decided."""
    deadline = time.monotonic() + timeout
    if len(independent) != n - 1:
        return None
    if not dependent:
        return []
    degree = prod(_degree(g, n) for g in independent)
    bounds = [degree * _degree(f, n) for f in dependent]
    if max(bounds) > MAX_BOUND:
        return None
    jac = [[_linear_coefficient(g, n, k, field) for k in range(n)] for g in independent]
    rank, pivots, _ = echelon(jac)
    if rank != n - 1:
        return None
    (free,) = [k for k in range(n) if k not in pivots]
    inv0 = inverse([[jac[i][j] for j in pivots] for i in range(n - 1)])
    ring = SeriesRing(None if field is None else field.g)
    g_terms = [_terms(g, n, field) for g in independent]
    jac_terms = [[_terms(g.derivative(j), n, field) for j in pivots] for g in independent]
    gamma = _curve(ring, g_terms, jac_terms, free, pivots, n, max(bounds) + 1,
                   [[_coeffs(field, c) for c in row] for row in inv0], deadline)
    if gamma is None:
        return None
    top = max(_degree(f, n) for f in dependent)
    out = []
    for f, bound in zip(dependent, bounds, strict=True):
        if time.monotonic() > deadline:
            return None
        value = _Evaluator(ring, [ring.truncate(s, bound + 1) for s in gamma], bound + 1,
                           top)(_terms(f, n, field))
        out.append(ring.is_zero(value))
    return out


def _degree(p, n: int) -> int:
    """The total degree in the first ``n`` variables."""
    return max((sum(int(e) for e in mono[:n]) for mono in p.to_dict()), default=0)


def _linear_coefficient(p, n: int, k: int, field):
    """The coefficient of the ``k``-th variable in the linear part of ``p``, exactly
    (an ``fmpq``, or an element of the number field)."""
    parts = {}
    for mono, c in p.to_dict().items():
        head = tuple(int(e) for e in mono[:n])
        if sum(head) == 1 and head[k] == 1:
            parts[int(mono[n]) if field is not None else 0] = c
    if field is None:
        return parts.get(0, flint.fmpq(0))
    return _number(field, [parts.get(j, 0) for j in range(max(parts, default=0) + 1)])
