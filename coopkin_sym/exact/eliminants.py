"""Polynomials that vanish on the points of an ideal's zero set outside some
components: the generators with the hypersurface components' factors taken out,
resultants of two of them, and elements of lexicographic Gröbner bases (of the ideal,
and of the covering system of :func:`~coopkin_sym.exact.groebner.covers` with its
extra variables eliminated). When one of them has no real zero, no real point of the
zero set lies outside the components: the certificate's proof at real points.

Example
-------
>>> import flint
>>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
>>> x, y = ctx.gens()
>>> [str(g) for g in residual_eliminants([x * y, x * (x**2 + 1)], [[x]], timeout=30)][:2]
['y', 'x^2 + 1']
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence

import flint

from coopkin_sym.exact.groebner import (
    MAX_PRODUCT_TERMS,
    PolyDict,
    Verdict,
    _Clock,
    _ctx,
    _merge_hypersurfaces,
    _plain,
    _prepare_cover,
    _Worker,
    covering_system,
)
from coopkin_sym.exact.sizes import resultant_terms

#: The most estimated terms of a resultant taken by :func:`residual_eliminants`.
ELIMINANT_TERMS = 20_000


def residual_eliminants(ideal: Sequence, components: Sequence[Sequence], *,
                        timeout: float = 60.0, nvars: int | None = None,
                        allowed: Sequence[Sequence] = ()) -> Iterator:
    """Polynomials that vanish wherever ``ideal`` does outside every component and
    ``allowed`` set, in turn, within ``timeout`` seconds in all: so when one of them
    has no *real* zero, no real point of ``V(ideal)`` lies outside the components.

    First the generators of the ideal with the factors of the hypersurface components
    taken out (step 1 of :func:`covers`: the same points outside them), the
    resultants of two of them (up to :data:`ELIMINANT_TERMS` estimated terms) and
    their lexicographic Gröbner basis (flint, exact); then the elements free of ``z``
    (and ``w``) of the lexicographic basis of the covering system with one ``z``,
    ``z`` and ``w`` first: they generate the elimination ideal, whose zeros are the
    closure of ``V(ideal)`` minus the components. A nonzero constant when the
    components are found to cover. Flint polynomials in the context of ``ideal``
    (else ``nvars`` variables ``x0, x1, ...``).

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    >>> x, y = ctx.gens()
    >>> # x (x^2 + y^2 + 1) = 0, y = 0: outside x = 0 only complex points (x = +-i)
    >>> found = residual_eliminants([x**3 + x*y**2 + x, y], [[x]], timeout=30)
    >>> [str(g) for g in found][:3]     # the generators without x, then a resultant
    ['x^2 + y^2 + 1', 'y', 'x^2 + 1']
    """
    clock = _Clock(timeout)
    prepared = _prepare_cover(ideal, components, allowed, nvars, clock)
    ctx = next((p.context() for p in ideal if isinstance(p, flint.fmpz_mpoly)), None)
    if isinstance(prepared, Verdict):
        if prepared.holds:
            yield (ctx or _ctx(1)).constant(1)
        return
    polys, comps, gens_f, _, n = prepared
    ctx = ctx or _ctx(n)
    yield from (ctx.from_dict(g) for g in polys)
    # resultants of two generators lie in the ideal, in one variable fewer
    names = gens_f[0].context().names() if gens_f else ()
    for k in range(n):
        for i, a in enumerate(gens_f):
            for b in gens_f[i + 1:]:
                if (a.degrees()[k] > 0 and b.degrees()[k] > 0 and clock.left() > 0
                        and resultant_terms(a, b, k) <= ELIMINANT_TERMS):
                    r = a.resultant(b, names[k])
                    if not r.is_zero():
                        yield ctx.from_dict(_plain(r))

    def basis(system: list[PolyDict], total: int, seconds: float) -> list[PolyDict]:
        answer = _Worker.ask("_flint_lex_basis_child", system, total, max(seconds, 0.0))
        return [] if answer is None or isinstance(answer, str) else answer
    for g in basis(polys, n, clock.left() / 2):
        yield ctx.from_dict(g)
    made = covering_system(polys, _merge_hypersurfaces(comps, n), n,
                           max_terms=MAX_PRODUCT_TERMS)
    if made is None or clock.left() <= 0:
        return
    system, total = made
    extra = total - n
    order = list(range(n, total)) + list(range(n))     # z and w first: eliminated
    moved = [{tuple(k[i] for i in order): c for k, c in p.items()} for p in system]
    for g in basis(moved, total, clock.left()):
        if all(not any(k[:extra]) for k in g):
            yield ctx.from_dict({k[extra:]: c for k, c in g.items()})


__all__ = ["ELIMINANT_TERMS", "residual_eliminants"]
