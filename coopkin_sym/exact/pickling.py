"""Pickling for python-flint polynomials and their contexts.

python-flint's multivariate polynomials and contexts do not pickle on their own, so
an analysis could not come back from a worker process. Importing this module (the
exact layer does) registers reducers with :mod:`copyreg`: a context pickles as its
variable names and ordering (contexts are unique per names and ordering, so the same
one comes back), a polynomial as its context and its exponent/coefficient map, as
plain integers. Exact: nothing is rounded.

Example
-------
>>> import pickle
>>> import flint
>>> ctx = flint.fmpz_mpoly_ctx.get(("t", "L"), "degrevlex")
>>> t, L = ctx.gens()
>>> p = pickle.loads(pickle.dumps(3 * t**2 - L))
>>> p == 3 * t**2 - L, p.context() is ctx
(True, True)
"""

from __future__ import annotations

import copyreg

import flint


def _zctx(names: tuple[str, ...], ordering) -> flint.fmpz_mpoly_ctx:
    return flint.fmpz_mpoly_ctx.get(names, ordering)


def _qctx(names: tuple[str, ...], ordering) -> flint.fmpq_mpoly_ctx:
    return flint.fmpq_mpoly_ctx.get(names, ordering)


def _zpoly(ctx: flint.fmpz_mpoly_ctx, terms: dict) -> flint.fmpz_mpoly:
    return ctx.from_dict(terms)


def _qpoly(ctx: flint.fmpq_mpoly_ctx, terms: dict) -> flint.fmpq_mpoly:
    return ctx.from_dict({m: flint.fmpq(p, q) for m, (p, q) in terms.items()})


def _reduce_zctx(ctx):
    return _zctx, (tuple(ctx.names()), ctx.ordering())


def _reduce_qctx(ctx):
    return _qctx, (tuple(ctx.names()), ctx.ordering())


def _reduce_zpoly(p):
    return _zpoly, (p.context(), {m: int(c) for m, c in p.to_dict().items()})


def _reduce_qpoly(p):
    return _qpoly, (p.context(), {m: (int(c.p), int(c.q)) for m, c in p.to_dict().items()})


copyreg.pickle(flint.fmpz_mpoly_ctx, _reduce_zctx)
copyreg.pickle(flint.fmpq_mpoly_ctx, _reduce_qctx)
copyreg.pickle(flint.fmpz_mpoly, _reduce_zpoly)
copyreg.pickle(flint.fmpq_mpoly, _reduce_qpoly)
