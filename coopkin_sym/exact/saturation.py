"""The saturation ``I : f^oo``: the ideal of the closure of ``V(I)`` minus ``V(f)``.

A locus component found through a parametrization is the set where its equations hold
and none of its ``outside`` polynomials (the parametrization's denominators) vanishes;
the zero set of the saturation is its closure, so a certificate can use the component
as a closed set. Computed by elimination: a Gröbner basis of ``I + (1 - z f)`` for the
lexicographic order with ``z`` first; its elements free of ``z`` generate ``I : f^oo``.
The basis is computed by python-flint in the package's worker process, killed at its
time bound (an undecided saturation is None, never a guess).

Example
-------
>>> import flint
>>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
>>> x, y = ctx.gens()
>>> I = [x * y, x * (y - 1)]                  # V(I) = {x = 0}; away from x = 0: nothing
>>> saturate(as_dicts(I)[0], as_dicts([y])[0][0], 2, timeout=30)
[{(1, 0): 1}]
"""

from __future__ import annotations

from collections.abc import Sequence

from coopkin_sym.exact.groebner import PolyDict, _one_minus, _Worker, as_dicts

__all__ = ["as_dicts", "saturate"]


def saturate(ideal: Sequence[PolyDict], f: PolyDict, nvars: int, *,
             timeout: float = 10.0) -> list[PolyDict] | None:
    """Generators of ``ideal : f^oo`` (plain integer polynomials in ``nvars``
    variables), or None when not computed within ``timeout`` seconds.

    Example
    -------
    >>> saturate([{(2,): 1, (1,): -1}], {(1,): 1}, 1, timeout=30)   # x^2 - x : x^oo
    [{(1,): 1, (0,): -1}]
    """
    if not ideal:
        return []
    if timeout <= 0:
        return None
    shifted = [{(0, *k): c for k, c in p.items()} for p in ideal]
    shifted.append(_one_minus(0, {(0, *k): c for k, c in f.items()}, nvars + 1))
    answer = _Worker.ask("_flint_lex_basis_child", shifted, nvars + 1, timeout)
    if answer is None or isinstance(answer, str):
        return None
    out = [{k[1:]: c for k, c in g.items()} for g in answer if all(k[0] == 0 for k in g)]
    return sorted(out, key=lambda g: (len(g), sorted(g.items())))
