"""Substituting a variable by a quotient of polynomials, denominators cleared.

On a component ``f1 x_k + f0 = 0`` (or at a point) a matrix of integer polynomials is
replaced by the same matrix with ``x_k = -f0/f1``, each row multiplied by the power of
``f1`` that keeps it polynomial. ``f0`` may involve ``x_k`` itself (a polynomial in
the same variable): the substitution is then a composition.

Example
-------
>>> import flint
>>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
>>> x, y = ctx.gens()
>>> str(substitute(x**2 + y, 0, -y, 2 * ctx.constant(1), 2))     # (y/2)^2 + y, times 4
'y^2 + 4*y'
"""

from __future__ import annotations

from math import gcd

from coopkin_sym.exact.deadline import check


def substitute_rows(rows, k: int, f0, f1):
    """``rows`` with ``x_k = -f0/f1``, each row times the power of ``f1`` that clears
    it, then divided by the part of its content that divides that power (never by a
    factor that could vanish where ``f1`` does not: the rank stays right at every point
    with ``f1 != 0``)."""
    out = []
    powers = Powers(f0, f1)
    for row in rows:
        # zero entries (most of a row of a system with many arms) are kept as they are
        places = [i for i, e in enumerate(row) if not e.is_zero()]
        deg = max((row[i].degrees()[k] for i in places), default=0)
        new = list(row)
        for i in places:
            new[i] = substitute(row[i], k, f0, f1, deg, powers)
        nonzero = [new[i] for i in places if not new[i].is_zero()]
        if not nonzero:
            out.append(new)
            continue
        common = common_part(nonzero, f1, deg)
        if not common.is_one():
            for i in places:
                new[i] = new[i] / common
        out.append(new)
    return out


def common_part(entries: list, f1, deg: int):
    """The part of the content of ``entries`` (nonzero) that divides ``f1^deg``: its
    integer content when ``f1`` is a constant. Taken one gcd with ``f1`` at a time,
    each against the entries one by one, so that every gcd has ``f1`` (or a factor of
    it) on one side: never one of two large entries, nor ``f1^deg`` itself (a flint gcd
    cannot be interrupted).

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    >>> x, y = ctx.gens()
    >>> str(common_part([(x + 1)**2 * y, (x + 1)**3], x + 1, 2))
    'x^2 + 2*x + 1'
    """
    ctx = entries[0].context()
    if f1.is_constant():
        g = 0
        for e in entries:
            g = gcd(g, int(e.content()))
        return ctx.constant(g)
    common = ctx.constant(1)
    for _ in range(deg):
        g = f1
        for e in entries:
            check("a substitution")
            g = g.gcd(e)
            if g.is_one():
                return common
        common, entries = common * g, [e / g for e in entries]
    return common



def split_linear(f, k: int):
    """``(f1, f0)`` with ``f = f1 x_k + f0`` for ``f`` of degree one in ``x_k``."""
    zctx = f.context()
    parts: dict[int, dict] = {0: {}, 1: {}}
    for mon, c in f.to_dict().items():
        e = mon[k]
        rest = tuple(0 if i == k else x for i, x in enumerate(mon))
        parts[e][rest] = c
    return zctx.from_dict(parts[1]), zctx.from_dict(parts[0])


class Powers:
    """The products ``(-f0)^e f1^(d - e)`` of one substitution, each computed once
    (a matrix substituted entry by entry asks for the same ones again and again).

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    >>> x, y = ctx.gens()
    >>> str(Powers(y, 2 * ctx.constant(1)).term(1, 2))         # (-y)^1 * 2^1
    '-2*y'
    """

    def __init__(self, f0, f1):
        self._a, self._b = [f0.context().constant(1), -f0], [f0.context().constant(1), f1]
        self._unit = f1.is_one()
        self._terms: dict[tuple[int, int], object] = {}

    @staticmethod
    def _power(table: list, e: int):
        while len(table) <= e:
            check("a substitution")
            table.append(table[-1] * table[1])
        return table[e]

    def term(self, e: int, deg: int):
        """``(-f0)^e f1^(deg - e)``."""
        key = (e, deg)
        got = self._terms.get(key)
        if got is None:
            got = self._power(self._a, e)
            if not self._unit and deg > e:
                got = got * self._power(self._b, deg - e)
            self._terms[key] = got
        return got


def substitute(p, k: int, f0, f1, deg: int, powers: Powers | None = None):
    """``p(x_k = -f0/f1) * f1^deg`` (``powers``: the :class:`Powers` of ``f0, f1``
    when several polynomials are substituted alike)."""
    if p.is_zero():
        return p
    zctx = p.context()
    powers = powers if powers is not None else Powers(f0, f1)
    acc = zctx.constant(0)
    for e, c in enumerate(coefficients_in(p, k)):
        check("a substitution")
        if not c.is_zero():
            acc = acc + c * powers.term(e, deg)
    return acc


def coefficients_in(p, k: int) -> list:
    """The coefficients of ``p`` in ``x_k`` (free of it), lowest degree first: each is
    the remainder of a division by the monomial ``x_k``, the quotient going on (flint's
    own operations, no pass over the terms in Python).

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    >>> x, y = ctx.gens()
    >>> [str(c) for c in coefficients_in(3 * x**2 * y + x + y, 0)]
    ['y', '1', '3*y']
    """
    top = p.degrees()[k]
    x = p.context().gens()[k]
    out = []
    for _ in range(top + 1):
        p, rest = divmod(p, x)
        out.append(rest)
    return out


__all__ = ["Powers", "coefficients_in", "common_part", "split_linear", "substitute",
           "substitute_rows"]
