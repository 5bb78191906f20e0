"""Certificate tests proved at the real points only.

A covering test of :mod:`~coopkin_sym.analysis.locus.certify` is decided over the
complex numbers; only real configurations matter. When it fails, the points outside
the components may all be complex: a polynomial that vanishes on them
(:func:`~coopkin_sym.exact.eliminants.residual_eliminants`) whose irreducible factors
have no real zero (:func:`~coopkin_sym.analysis.locus.algebra.no_real_zeros`:
discriminants down to one variable, then Sturm's theorem) proves the test at the real
points, within :data:`REAL_SHARE` of the test's bound. The same proof with no
component at all shows that a component without a real witness has no real point on
a chart (its tests there are then not needed).

Example
-------
>>> import flint
>>> from coopkin_sym.exact.groebner import Verdict, covers
>>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
>>> x, y = ctx.gens()
>>> failed = Verdict(False, True, "flint", 0.0)     # V(x (x^2 + 1), y) is not in x = 0
>>> over_reals(failed, [x**3 + x, y], [[x]], [], 2, 30.0).proved      # at real points
True
"""

from __future__ import annotations

import time

from coopkin_sym.analysis.locus.algebra import no_real_zeros
from coopkin_sym.exact.eliminants import residual_eliminants
from coopkin_sym.exact.factoring import factor
from coopkin_sym.exact.groebner import Verdict, covers

#: How a test proved only at the real points says so.
REAL_DETAIL = "at real points: a polynomial vanishing outside the components has no real zero"
#: The share of a test's time bound that the proof at real points may take (measured
#: on planar-two-fingers: those that succeed take milliseconds).
REAL_SHARE = 0.2
#: Eliminants up to this many terms are tried for real zeros (larger ones are not:
#: their factorization and discriminants cannot be interrupted).
REAL_FACTOR_TERMS = 5_000


def no_real_zero(g) -> bool:
    """Whether the integer polynomial ``g`` is proved to have no real zero: each
    irreducible factor by :func:`no_real_zeros` (a factor like ``(1 + t^2)^3`` keeps it
    from a proof of the product). False for ``g`` over :data:`REAL_FACTOR_TERMS`
    terms.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    >>> x, y = ctx.gens()
    >>> no_real_zero((x**2 + 1)**3 * (x**2 + y**2 + 2)), no_real_zero(x * (x**2 + 1))
    (True, False)
    """
    if g.is_constant():
        return not g.is_zero()
    if len(g) > REAL_FACTOR_TERMS:
        return False
    return all(no_real_zeros(f) for f, _ in factor(g)[1])


def over_reals(verdict: Verdict, ideal: list, pieces: list, allowed: list, nvars: int,
               seconds: float, slopes_backend: str | None = None) -> Verdict:
    """``verdict`` of the test that ``V(ideal)`` lies in the ``pieces`` and ``allowed``
    sets, proved at the real points (detail :data:`REAL_DETAIL`) when it failed over C
    and a polynomial vanishing on the points outside has no real zero, or (with a
    ``slopes_backend``) by :func:`where_slopes_vanish`; else ``verdict`` unchanged.
    The proof takes at most :data:`REAL_SHARE` of ``seconds``, and no more than what
    the test left of them."""
    left = min(seconds - verdict.seconds, seconds * REAL_SHARE)
    if verdict.holds is not False or left <= 0:
        return verdict
    started = time.monotonic()
    if not no_real_point_outside(ideal, pieces, allowed, nvars, left):
        if slopes_backend is None:
            return verdict
        return where_slopes_vanish(verdict, ideal, pieces, allowed, nvars, seconds,
                                   slopes_backend)
    return Verdict(True, True, "flint", verdict.seconds + time.monotonic() - started,
                   REAL_DETAIL)


def nonreal_slopes(polys: list) -> list:
    """The coefficients ``c`` of polynomials ``c x + c0`` of ``polys`` linear in a
    variable ``x`` (``c`` free of it, not constant) that are proved to have no real
    zero: where ``c`` vanishes, the polynomials' parametrization ``x = -c0 / c`` fails,
    and no point there is real.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y", "z"), "degrevlex")
    >>> x, y, z = ctx.gens()
    >>> [str(c) for c in nonreal_slopes([(y**2 + 1) * x + z, (y - 1) * z + x**2])]
    ['y^2 + 1']
    """
    out = []
    for p in polys:
        for k, d in enumerate(p.degrees()):
            if d != 1:
                continue
            terms = {e[:k] + (0,) + e[k + 1:]: c for e, c in p.to_dict().items() if e[k]}
            slope = p.context().from_dict(terms)
            if not slope.is_constant() and slope not in out and no_real_zero(slope):
                out.append(slope)
    return out


def where_slopes_vanish(verdict: Verdict, ideal: list, pieces: list, allowed: list,
                        nvars: int, seconds: float, backend: str = "auto") -> Verdict:
    """``verdict`` of the test that ``V(ideal)`` lies in the ``pieces`` and ``allowed``
    sets, proved at the real points (detail :data:`REAL_DETAIL`) when it failed over C
    and holds once the zeros of the :func:`nonreal_slopes` of ``ideal`` are allowed
    too (they hold no real point); else ``verdict`` unchanged. Within
    :data:`REAL_SHARE` of ``seconds``.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    >>> x, y = ctx.gens()
    >>> failed = Verdict(False, True, "flint", 0.0)   # V((y^2 + 1) x) is not in x = 0
    >>> where_slopes_vanish(failed, [(y**2 + 1) * x], [[x]], [], 2, 30.0).proved
    True
    """
    if verdict.holds is not False:
        return verdict
    slopes = nonreal_slopes(ideal)
    if not slopes:
        return verdict
    again = covers(ideal, pieces, timeout=seconds * REAL_SHARE, backend=backend,
                   nvars=nvars, allowed=[*allowed, *([c] for c in slopes)])
    if not again.proved:
        return verdict
    return Verdict(True, True, again.backend, verdict.seconds + again.seconds, REAL_DETAIL)


def no_real_point_outside(ideal: list, pieces: list, allowed: list, nvars: int,
                          seconds: float) -> bool:
    """Whether ``V(ideal)`` is proved to have no real point outside the ``pieces`` and
    ``allowed`` sets (with no pieces: no real point at all), within ``seconds``: a
    polynomial vanishing there without a real zero (:func:`no_real_zero`)."""
    return any(no_real_zero(g) for g in residual_eliminants(
        ideal, pieces, timeout=seconds, nvars=nvars, allowed=allowed))


__all__ = ["REAL_DETAIL", "REAL_FACTOR_TERMS", "REAL_SHARE", "no_real_point_outside",
           "no_real_zero", "nonreal_slopes", "over_reals", "where_slopes_vanish"]
