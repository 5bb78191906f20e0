"""The real branches of a plane curve along a multiple tangent, by Newton's polygon.

One reduced constraint ``g(x, y)`` in two first-order motions, exact to total degree
``K``, whose lowest form has a real root of multiplicity ``m > 1`` (a tangent met by
several branches, or by a cusp): in coordinates along that tangent (``t``) and across
it (``w``), every real branch tangent to it is ``w = c |t|^e + ...`` for ``t > 0`` or
``t < 0``, ``e = p/q > 1`` the slope of an edge of the Newton polygon of ``g(t, w)``
and ``c`` a nonzero real root of the edge's polynomial ``E(c) = sum a_ik c^k`` over
the edge's terms ``a_ik t^i w^k``. A simple real root gives exactly one real
half-branch (the implicit function theorem after the weighted blow-up
``w = |t|^e (c + v)``); a multiple one is not decided here. The polygon's edges of
slope above 1 are fixed by the terms of degree at most ``K`` once a pure power of
``t`` of degree ``J <= K`` is met: every unknown term lies to the right of them.

Half-branches on both sides of one analytic branch (``e`` an integer) make one smooth
branch; for ``e = p/q`` with ``q`` even two half-branches on one side make one cusp
(``w^2 = t^3``), with ``q`` odd one half on each side make one singular branch
(``w^3 = t^4``).

Example
-------
>>> import flint
>>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "deglex")
>>> x, y = ctx.gens()
>>> along_tangent(y**2 - x**3, (1, 0), 3)
Tangent(smooth=0, singular=1, half_branches=(2, 0))
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from math import gcd

import flint

from coopkin_sym.exact.realroot import RealRoot


@dataclass(frozen=True)
class Tangent:
    """The real branches along one tangent: ``smooth`` (analytic) ones and
    ``singular`` ones (cusps and other branches with a fractional exponent), and the
    real half-branches found for ``t > 0`` and ``t < 0``.

    Example
    -------
    >>> Tangent(2, 0, (2, 2)).branches
    2
    """

    smooth: int
    singular: int
    half_branches: tuple[int, int]

    @property
    def branches(self) -> int:
        """How many real branches have this tangent."""
        return self.smooth + self.singular


def _along(g, direction):
    """``g`` in the coordinates ``(t, w)``: ``(x, y) = t (a, b) + w (across)``."""
    ctx = g.context()
    x, y = ctx.gens()[:2]
    if direction == (1, 0):                  # along x: t = x, w = y
        return g
    a = Fraction(str(direction[0]))          # along (s, 1): x = s t + w, y = t
    s = flint.fmpq(a.numerator, a.denominator)
    return g.compose(s * y + x, y)           # in (w, t) stored as (x, y) -> swap below


def _points(g, direction, order: int) -> dict[tuple[int, int], flint.fmpq]:
    """The terms ``(i, k) -> a`` of ``g(t, w) = sum a t^i w^k`` of degree at most
    ``order``."""
    h = _along(g, direction)
    out = {}
    for mono, c in h.to_dict().items():
        i, k = (int(mono[0]), int(mono[1]))
        if direction != (1, 0):              # (x, y) stood for (w, t)
            i, k = k, i
        if i + k <= order and c != 0:
            out[(i, k)] = flint.fmpq(c)
    return out


def _edges(points: dict, top: tuple[int, int]):
    """The edges of the lower hull from ``top`` down to the lowest pure power of
    ``t``: ``(slope as Fraction, [(i, k) on the edge])``."""
    edges = []
    here = top
    while here[1] > 0:
        below = [(i, k) for (i, k) in points if k < here[1]]
        slope = min(Fraction(i - here[0], here[1] - k) for i, k in below)
        on = [here] + sorted((p for p in below
                              if Fraction(p[0] - here[0], here[1] - p[1]) == slope),
                             key=lambda p: -p[1])
        edges.append((slope, on))
        here = on[-1]
    return edges


def _real_simple_roots(coeffs: list) -> int | None:
    """How many nonzero real roots the polynomial ``sum coeffs[k] c^k`` has, or None
    when one of them is multiple."""
    den = 1
    for c in coeffs:
        den = den * int(flint.fmpq(c).q) // gcd(den, int(flint.fmpq(c).q))
    ints = [int(flint.fmpq(c) * den) for c in coeffs]
    while ints and ints[0] == 0:             # the root c = 0 is not a branch
        ints = ints[1:]
    if len(ints) <= 1:
        return 0
    count = 0
    for f, e in flint.fmpz_poly(ints).factor()[1]:
        real = len(RealRoot.all_of([int(x) for x in f.coeffs()])) if f.degree() > 0 else 0
        if e > 1 and real:
            return None
        count += real
    return count


def _side(points: dict, top) -> tuple[list[tuple[Fraction, int]], bool]:
    """The real half-branches for ``t > 0``: ``(exponent, count)`` per edge, and
    whether every real root was simple."""
    found, simple = [], True
    for slope, on in _edges(points, top):
        low = on[-1][1]
        coeffs = [flint.fmpq(0)] * (on[0][1] - low + 1)
        for i, k in on:
            coeffs[k - low] += points[(i, k)]
        count = _real_simple_roots(coeffs)
        if count is None:
            simple = False
            continue
        found.append((slope, count))
    return found, simple


def along_tangent(g, direction, order: int) -> Tangent | None:
    """The real branches of ``g = 0`` (two variables, exact to total degree
    ``order``) tangent to ``direction`` (``(1, 0)`` or a rational ``(s, 1)``, a
    multiple root of the lowest form), or None when this cannot decide them: no pure
    power of ``t`` up to ``order``, or a multiple real root of an edge's polynomial.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "deglex")
    >>> x, y = ctx.gens()
    >>> along_tangent(y**2 - x**4, (1, 0), 4).smooth, along_tangent(y**2 + x**4, (1, 0), 4)
    (2, Tangent(smooth=0, singular=0, half_branches=(0, 0)))
    """
    plus = _points(g, direction, order)
    if not any(k == 0 for (_, k) in plus):
        return None                          # no pure power of t: the polygon is open
    low = min(i + k for i, k in plus)
    m = min(k for i, k in plus if i + k == low)      # the multiplicity of the tangent
    top = (low - m, m)
    if m == 0:
        return None
    minus = {(i, k): a * (-1) ** i for (i, k), a in plus.items()}
    right, ok_right = _side(plus, top)
    left, ok_left = _side(minus, top)
    if not (ok_right and ok_left):
        return None
    smooth = sum(n for e, n in right if e.denominator == 1)
    if smooth != sum(n for e, n in left if e.denominator == 1):
        return None                        # analytic branches are met on both sides
    fractional = (sum(n for e, n in right if e.denominator != 1)
                  + sum(n for e, n in left if e.denominator != 1))
    if fractional % 2:
        return None
    halves = (sum(n for _, n in right), sum(n for _, n in left))
    return Tangent(smooth, fractional // 2, halves)
