"""The real roots of a polynomial over a real number field, as real algebraic numbers.

A polynomial ``p(x)`` with coefficients in ``Q(alpha)`` (``alpha`` a chosen real root
of an irreducible ``g``: a :class:`~coopkin_sym.exact.numberfield.RealNumberField`) has
real roots that are algebraic over Q. Each is given exactly as a
:class:`~coopkin_sym.exact.realroot.RealRoot`: its minimal polynomial over Q and an
isolating interval with rational ends. The minimal polynomials divide the norm
``N(x) = Res_a(p(x, a), g(a))`` (every root of ``p`` is a root of ``N``); which real
roots of ``N``'s irreducible factors are roots of ``p`` at the real embedding is decided
by rational interval arithmetic: ``p(x, alpha)`` is enclosed on ever smaller boxes
around each candidate and ``alpha`` until exactly as many candidates remain as ``p``
has distinct real roots (counted exactly by Sturm's theorem over the field). A
candidate that is not a root is excluded once its box is small enough, and a root
never is: nothing is decided in floating point.

Example
-------
>>> import flint
>>> from coopkin_sym.exact.numberfield import RealNumberField
>>> from coopkin_sym.exact.realroot import RealRoot
>>> k = RealNumberField(flint.fmpq_poly([-2, 0, 1]), RealRoot.all_of([-2, 0, 1])[1])
>>> # x^3 - sqrt(2): the real root 2^(1/6), of minimal polynomial x^6 - 2 over Q
>>> (r,) = real_roots(k, [k.element([0, -1]), 0, 0, 1])
>>> r.coeffs, r.lo < r.hi
((-2, 0, 0, 0, 0, 0, 1), True)
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction

import flint

from coopkin_sym.errors import NumberError
from coopkin_sym.exact.numberfield import RealNumberField
from coopkin_sym.exact.realroot import RealRoot, _horner

__all__ = ["real_root_count", "real_roots"]

#: Refinements of the boxes before giving up (never reached: see the module's text).
_MAX_ROUNDS = 200


def real_root_count(field: RealNumberField, p: Sequence) -> int:
    """The number of distinct real roots of ``p`` (coefficients in the real number
    field ``field``, lowest degree first, nonzero): Sturm's theorem, with the signs of
    the leading coefficients at the real embedding decided exactly.

    Example
    -------
    >>> import flint
    >>> k = RealNumberField(flint.fmpq_poly([-2, 0, 1]), RealRoot.all_of([-2, 0, 1])[1])
    >>> real_root_count(k, [k.element([0, -1]), 0, 1])        # x^2 - sqrt(2)
    2
    """
    p = field.gcd([p])                    # monic
    if len(p) <= 1:
        return 0
    seq = [p, [field.element(c * i) for i, c in enumerate(p)][1:]]
    while True:
        r = field._rem(seq[-2], seq[-1])
        if not r:
            break
        seq.append([field.element(-c) for c in r])
    plus = [field.sign(q[-1]) for q in seq]
    minus = [s if (len(q) - 1) % 2 == 0 else -s for s, q in zip(plus, seq, strict=True)]

    def changes(signs):
        signs = [s for s in signs if s]
        return sum(1 for a, b in zip(signs, signs[1:], strict=False) if a != b)
    return changes(minus) - changes(plus)


def _norm_factors(field: RealNumberField, p: list) -> list[tuple[int, ...]]:
    """The irreducible factors over Q (integer coefficients, lowest degree first) of
    the norm of ``p`` from ``Q(alpha)`` to Q."""
    ctx = flint.fmpq_mpoly_ctx.get(("x", "a"), "lex")
    x, a = ctx.gens()
    big = ctx.constant(0)
    for i, c in enumerate(p):
        for j, cj in enumerate(field.element(c).coeffs()):
            if cj != 0:
                big += cj * x ** i * a ** j
    g = ctx.constant(0)
    for j, cj in enumerate(field.g.coeffs()):
        g += cj * a ** j
    norm = big.resultant(g, "a")
    coeffs = [flint.fmpq(0)] * (norm.degrees()[0] + 1)
    for mono, c in norm.to_dict().items():
        coeffs[mono[0]] = c
    _, factors = flint.fmpq_poly(coeffs).factor()
    out = []
    for f, _e in factors:
        ints = f.numer()
        ints = ints if ints[ints.degree()] > 0 else -ints
        content = int(ints.content())
        out.append(tuple(int(c) // content for c in ints.coeffs()))
    return sorted(out, key=lambda f: (len(f), f))


def _enclosure(parts: list[list[Fraction]], alpha: tuple, x: tuple) -> tuple:
    """An enclosure of ``sum_i c_i(alpha) x^i`` for ``alpha`` and ``x`` in the given
    rational intervals (``parts[i]``: the coefficients of ``c_i`` in alpha)."""
    lo = hi = Fraction(0)
    for coeffs in reversed(parts):
        c_lo, c_hi = _horner(coeffs, *alpha) if coeffs else (Fraction(0), Fraction(0))
        products = (lo * x[0], lo * x[1], hi * x[0], hi * x[1])
        lo, hi = min(products) + c_lo, max(products) + c_hi
    return lo, hi


def real_roots(field: RealNumberField, p: Sequence) -> list[RealRoot]:
    """The distinct real roots of ``p`` (coefficients in ``field``, lowest degree first,
    nonzero) at the real embedding of the field, in increasing order, each as a
    :class:`~coopkin_sym.exact.realroot.RealRoot` over Q (minimal polynomial and an
    isolating interval); see the module's text.

    Example
    -------
    >>> import flint
    >>> k = RealNumberField(flint.fmpq_poly([-3, 0, 1]), RealRoot.all_of([-3, 0, 1])[1])
    >>> # (x - sqrt(3)) (x - 1): the roots 1 and sqrt(3)
    >>> [r.expression() for r in real_roots(k, [k.element([0, 1]), k.element([-1, -1]), 1])]
    [1, sqrt(3)]
    """
    p = field.squarefree(p)
    count = real_root_count(field, p) if len(p) > 1 else 0
    if not count:
        return []
    candidates = [r for f in _norm_factors(field, p) if len(f) > 1
                  for r in RealRoot.all_of(f)]
    parts = [[Fraction(int(c.p), int(c.q)) for c in field.element(c).coeffs()] for c in p]
    width = Fraction(1, 16)
    for _ in range(_MAX_ROUNDS):
        alpha = field.root.refine(width)
        candidates = [r for r in candidates
                      if _contains_zero(_enclosure(parts, alpha, r.refine(width)))]
        if len(candidates) == count:
            break
        width /= 2**8
    else:  # pragma: no cover - the enclosures of non-roots always exclude 0 in the end
        raise NumberError("the real roots over the number field were not separated")
    return _increasing(candidates, width)


def _increasing(roots: list[RealRoot], width: Fraction) -> list[RealRoot]:
    """Distinct real roots in increasing order: their intervals refined until no two
    meet."""
    while True:
        boxes = sorted(((r.refine(width), k) for k, r in enumerate(roots)),
                       key=lambda b: b[0])
        if all(a[0][1] < b[0][0] for a, b in zip(boxes, boxes[1:], strict=False)):
            return [roots[k] for _, k in boxes]
        width /= 2**8


def _contains_zero(box: tuple) -> bool:
    return box[0] <= 0 <= box[1]
