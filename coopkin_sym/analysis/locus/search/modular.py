"""The numbers on a curved set, shown to be the enclosing ones cheaply: modulo a prime,
or at one random point of it.

On the zeros of an irreducible ``f`` inside a place, each rank of ``Q`` (over the
function field of ``f = 0``) is at most the place's: ``f = 0`` is a specialization of
the place. It is also at least the rank at any point of ``f = 0`` modulo a prime ``p``
(a minor that is a multiple of a primitive ``f`` vanishes at every such point). When
the ranks at one random point of ``f = 0`` over ``GF(p)`` reach the place's, the numbers
are the place's, exactly, with no elimination modulo ``f``; otherwise they are found
modulo ``f`` as before (:func:`~coopkin_sym.analysis.mobility.numbers_modulo`).
"""

from __future__ import annotations

from fractions import Fraction

import flint

from coopkin_sym.analysis.locus.algebra import GCD_MODULO_TERMS, substitute_values
from coopkin_sym.analysis.locus.context import Place, SearchContext
from coopkin_sym.analysis.mobility import numbers_modulo
from coopkin_sym.analysis.numbers import Numbers, ranks_from_numbers
from coopkin_sym.errors import BlockTooLarge
from coopkin_sym.exact.factoring import factor
from coopkin_sym.exact.matrix import PrimeField, rank_triple
from coopkin_sym.exact.quotient import Quotient, gcd_modulo
from coopkin_sym.exact.substitution import coefficients_in, substitute_rows

#: How many primes are tried: ``f = 0`` may have no point over ``GF(p)`` with the
#: residues drawn (a univariate ``f`` of degree ``n`` has a root modulo at least about
#: one prime in ``n``).
TRIES = 24


def _primes(count: int) -> list[int]:
    """The ``count`` largest primes below ``2**61`` (``nmod`` arithmetic)."""
    out, n = [], 2**61 - 1
    while len(out) < count:
        if flint.fmpz(n).is_prime():
            out.append(n)
        n -= 2
    return out


#: The primes tried, one after another.
PRIMES = tuple(_primes(TRIES))


def numbers_on(ctx: SearchContext, rows, quotient: Quotient, base: Numbers | None) -> Numbers:
    """The numbers of ``rows`` over the function field of ``quotient`` (as
    :func:`~coopkin_sym.analysis.mobility.numbers_modulo`): ``base``, the numbers of the
    place the zeros of ``quotient.f`` lie in, when the ranks at a point of them modulo
    a prime reach those of ``base``."""
    if base is not None and _reaches(ctx, rows, base,
                                     lambda p: _point_modulo(ctx, quotient, p)):
        return base
    return numbers_modulo(rows, ctx.model, ctx.row_contacts, quotient)


def reaches_at_values(ctx: SearchContext, rows, values: dict, x: str, g,
                      base: Numbers | None) -> bool:
    """Whether the numbers of ``rows`` with the variables of ``values`` set (rationals,
    or ``fmpq_poly`` in a root ``x`` of the irreducible ``g``; the other variables
    generic) are ``base``, the numbers of ``rows`` themselves, shown by the ranks
    modulo a prime at a root of ``g`` there (no substitution over ``Q[x]/(g)``).
    False when not shown (they may still be ``base``)."""
    return base is not None and _reaches(ctx, rows, base,
                                         lambda p: _values_modulo(ctx, values, x, g, p))


def _reaches(ctx: SearchContext, rows, base: Numbers, point_modulo) -> bool:
    """Whether the ranks of ``rows`` at the point ``point_modulo(p)`` (residues of the
    ring's variables, or None when it has none there) modulo some prime ``p`` are those
    of ``base`` (False also when no prime gave a point)."""
    dim, r = ctx.model.object_dim, len(ctx.model.joints)
    target = ranks_from_numbers(base, r, dim=dim)
    ncols = dim + r
    for p in PRIMES:
        point = point_modulo(p)
        if point is None:
            continue
        values = [[int(e(*point)) % p for e in row] for row in rows]
        ranks = rank_triple(values, ncols, dim, PrimeField(p))
        return (ranks.q, ranks.gt, ranks.dt) == target
    return False


def _point_modulo(ctx: SearchContext, quotient: Quotient, p: int) -> list[int] | None:
    """A point of ``f = 0`` over ``GF(p)``: random residues for every variable but
    ``x_k``, and a root of what is left in ``x_k``; None when that has no root."""
    f, k = quotient.f, quotient.k
    names = ctx.ring_names
    point = [ctx.rng.randrange(p) for _ in names]
    left = f.subs({n: point[i] for i, n in enumerate(names) if i != k})
    root = _root_modulo(left, k, p)
    if root is None:
        return None
    point[k] = root
    return point


def _values_modulo(ctx: SearchContext, values: dict, x: str, g, p: int) -> list[int] | None:
    """The residues of ``values`` (as in :func:`reaches_at_values`) at a root of ``g``
    modulo ``p``, random residues for the other variables; None when ``g`` has no root
    there or a denominator is divisible by ``p``."""
    names = ctx.ring_names
    k = names.index(x)
    root = _root_modulo(g, k, p)
    if root is None:
        return None
    point = [ctx.rng.randrange(p) for _ in names]
    point[k] = root
    for name, v in values.items():
        if isinstance(v, Fraction):
            num, den = v.numerator, v.denominator
        else:
            num, den = int(v.numer()(root)), int(v.denom())
        if den % p == 0:
            return None
        point[names.index(name)] = num * pow(den, -1, p) % p
    return point


def _root_modulo(f, k: int, p: int) -> int | None:
    """A root modulo ``p`` of ``f`` (in the variable ``x_k`` alone, integer
    coefficients), made primitive first; None when it has none (or is constant there)."""
    content = f.content()
    if content != 1:
        f = f / content
    coeffs = [0] * (f.degrees()[k] + 1)
    for mon, c in f.to_dict().items():
        coeffs[mon[k]] = int(c) % p
    uni = flint.nmod_poly(coeffs, p)
    if uni.degree() < 1:
        return None
    roots = uni.roots()
    return int(roots[0][0]) if roots else None


# parameters of a family set to random integers of at most this size
_SPECIALIZE_BOUND = 1 << 16


def enclosing_numbers_at_a_point(ctx: SearchContext, place: Place, polys, h, x, y) -> bool:
    """Whether the family ``h = 0`` (``x`` curved), ``y`` a common root of ``polys``,
    has the enclosing numbers, shown at one point of it: the other variables set to
    random integers, ``x`` a root of a factor of ``h`` there, ``y`` from the gcd over
    ``Q(x)``. Ranks never rise at a special point and never exceed the enclosing ones, so
    equal ranks there are the family's own. ``False`` means not shown (the family is then
    decided over its function field). The point lies on the family unless the random
    values hit a proper subset of it (Schwartz-Zippel)."""
    kx, ky = ctx.ring_names.index(x), ctx.ring_names.index(y)
    values = {n: Fraction(ctx.rng.randint(-_SPECIALIZE_BOUND, _SPECIALIZE_BOUND))
              for n in ctx.ring_names if n not in (x, y)}
    (h_here, *polys_here), = substitute_values(ctx, [[h, *polys]], values)
    if h_here.degrees()[kx] < h.degrees()[kx] or any(
            p.degrees()[ky] < q.degrees()[ky] for p, q in zip(polys_here, polys, strict=True)):
        return False
    _, factors = factor(h_here)
    curved = [f for f, _e in factors if f.degrees()[kx] > 0]
    if not curved:
        return False
    quotient = Quotient(min(curved, key=lambda f: (f.degrees()[kx], len(f))), kx)
    try:   # a cheap test only: too large, the family is decided the other way
        common = gcd_modulo([coefficients_in(p, ky) for p in polys_here], quotient,
                            max_terms=GCD_MODULO_TERMS)
    except BlockTooLarge:
        return False
    if len(common) != 2:
        return False
    rows = substitute_rows(substitute_values(ctx, place.rows, values), ky, *common)
    return numbers_on(ctx, rows, quotient, place.base) == place.base


__all__ = ["enclosing_numbers_at_a_point", "numbers_on", "reaches_at_values"]
