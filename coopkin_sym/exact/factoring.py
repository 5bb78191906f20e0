"""Factorization over Z that always answers.

python-flint's ``fmpz_mpoly.factor`` sorts its factors with a key that overflows a C
long on factors with very large coefficients or exponents (``OverflowError``). The
factorization itself is fine: this module asks FLINT first and, when the sort fails,
factors through SymPy's ``factor_list`` on the same exact polynomial.

Example
-------
>>> import flint
>>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "lex")
>>> x, y = ctx.gens()
>>> content, factors = factor((x**2 - y**2) * 6)
>>> content, sorted(str(f) for f, _ in factors)
(6, ['x + y', 'x - y'])
"""

from __future__ import annotations

import sympy as sp

#: Polynomials of at least this many terms have their factorization kept (a search
#: meets one minor again in several places; factoring it again costs seconds).
KEEP_TERMS = 1000

#: How many such factorizations are kept, the latest first.
KEPT = 16

_kept: list[tuple] = []


def factor(p) -> tuple[int, list]:
    """``(content, [(factor, multiplicity), ...])`` of an ``fmpz_mpoly`` over Z, the
    factors primitive and irreducible, their product times the content equal to ``p``
    (up to the signs the factors carry). The factorizations of the last few large
    polynomials are kept and given again for an equal polynomial."""
    big = len(p) >= KEEP_TERMS
    if big:
        for q, content, factors in _kept:
            if len(q) == len(p) and q.context() is p.context() and q == p:
                return content, list(factors)
    try:
        content, factors = p.factor()
        content, factors = int(content), list(factors)
    except OverflowError:
        content, factors = _factor_with_sympy(p)
    if big:
        _kept.insert(0, (p, content, tuple(factors)))
        del _kept[KEPT:]
    return content, factors


def _factor_with_sympy(p) -> tuple[int, list]:
    ctx = p.context()
    names = [sp.Symbol(n) for n in ctx.names()]
    terms = {tuple(int(e) for e in mon): int(c) for mon, c in p.to_dict().items()}
    poly = sp.Poly.from_dict(terms, *names, domain=sp.ZZ)
    content, factors = poly.factor_list()
    out = []
    for f, e in factors:
        fd = {tuple(int(x) for x in mon): int(c) for mon, c in f.as_dict().items()}
        out.append((ctx.from_dict(fd), int(e)))
    return int(content), out


__all__ = ["factor"]
