"""Exact rank modulo an irreducible polynomial: numbers on a curved component.

For an irreducible integer polynomial ``f`` of degree ``d > 0`` in the variable
``x_k``, the ring ``Z[x]/(f)`` is a domain and its fraction field is the function field
of the hypersurface ``f = 0`` (the number field ``Q(alpha)``, ``f(alpha) = 0``, when
``f`` is univariate). A polynomial is zero there exactly when ``f`` divides it, which
the pseudo-remainder by ``f`` in ``x_k`` decides. Fraction-free elimination with that
zero test gives the rank of a polynomial matrix at the generic point of the component,
or, for a univariate ``f``, at every root of ``f`` at once (the roots are conjugate, so
the rank is the same at each).

Example
-------
>>> import flint
>>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
>>> x, y = ctx.gens()
>>> circle = Quotient(x**2 + y**2 - 1, 0)         # reduce in x
>>> circle.is_zero(x**4 - (1 - y**2)**2)
True
>>> rows = [[x, y], [1 - y, x]]    # det = x^2 + y^2 - y = 1 - y on the circle
>>> rank_modulo(rows, 2, circle)
2
>>> rank_modulo(rows, 2, Quotient(x**2 + y**2 - y, 0))   # det vanishes on this one
1
"""

from __future__ import annotations

from collections.abc import Sequence

import flint

from coopkin_sym.errors import ArgumentError, BlockTooLarge
from coopkin_sym.exact.deadline import check
from coopkin_sym.exact.elimination import CONTENT_GCD_TERMS, combine, gcd_fits, primitive
from coopkin_sym.exact.substitution import coefficients_in

Poly = flint.fmpz_mpoly


class Quotient:
    """``Z[x]/(f)`` with ``f`` irreducible of positive degree in variable ``k``.

    Elements are kept reduced (degree below ``deg_k f`` in ``x_k``) by pseudo-division;
    a reduced element is zero in the quotient exactly when it is the zero polynomial.
    Pseudo-division multiplies by powers of the leading coefficient of ``f`` in
    ``x_k``, which is not divisible by ``f``; a row is reduced with one power for all
    its entries, so it is the same row times a nonzero factor, which a rank never
    notices.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "lex")
    >>> x, y = ctx.gens()
    >>> qr = Quotient(x**2 - 2, 0)                        # Z[x, y]/(x^2 - 2)
    >>> qr.reduce(x**3 + y)
    2*x + y
    """

    def __init__(self, f: Poly, k: int):
        degree = f.degrees()[k]
        if degree < 1:
            raise ArgumentError(f"{f} does not involve variable {k}")
        self.f, self.k, self.degree = f, k, degree
        self.zctx = f.context()
        self.lead = _coefficient(f, k, degree)
        self._x = f.context().gens()[k]
        self._coeffs: list[Poly] | None = None   # of f in x_k, when first needed

    def _reduce_counted(self, p: Poly) -> tuple[Poly, int]:
        """``lead^n p`` reduced, and ``n``: each step is ``lead p - c x^(e - d) f`` for
        the coefficient ``c`` of the top power ``x^e`` of ``p`` (``d = deg f``), done on
        the coefficients of ``p`` in ``x`` (split once)."""
        if p.is_zero() or p.degrees()[self.k] < self.degree:
            return p, 0
        if self._coeffs is None:
            self._coeffs = coefficients_in(self.f, self.k)
        c = coefficients_in(p, self.k)
        f, d, n = self._coeffs, self.degree, 0
        while len(c) > d:
            check("a reduction modulo a polynomial")
            top = c.pop()
            shift = len(c) - d
            c = [self.lead * e for e in c]
            for i in range(d):
                if not f[i].is_zero():
                    c[shift + i] = c[shift + i] - top * f[i]
            n += 1
            while c and c[-1].is_zero():
                c.pop()
        return _join(c, self._x), n

    def reduce(self, p: Poly) -> Poly:
        """``lead^n p`` (for some ``n``) of degree below ``deg_k f``: the same element up
        to a nonzero factor, enough for a zero test. Rows go through
        :meth:`reduce_row`, which uses one factor for the whole row."""
        return self._reduce_counted(p)[0]

    def reduce_row(self, row: Sequence[Poly]) -> list[Poly]:
        """Every entry reduced with the same multiplier ``lead^n`` (a row times a
        nonzero element: its span, hence every rank, is unchanged)."""
        done = [self._reduce_counted(e) for e in row]
        top = max((n for _, n in done), default=0)
        return [r if n == top or r.is_zero() else r * self.lead ** (top - n)
                for r, n in done]

    def is_zero(self, p: Poly) -> bool:
        """Whether ``f`` divides ``p``."""
        return self.reduce(p).is_zero()


class Tower:
    """``Z[x]/(g_1, ..., g_n)`` for univariate polynomials ``g_i`` in distinct
    variables, each with a constant leading coefficient, whose roots generate linearly
    disjoint fields (the caller checks it: then the quotient by all of them is a field,
    ``Q(alpha_1, ..., alpha_n)`` over the other variables, and reduction by each in turn
    gives a unique normal form). Same interface as :class:`Quotient` for ranks.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    >>> x, y = ctx.gens()
    >>> t = Tower([Quotient(x**2 - 2, 0), Quotient(y**2 - 3, 1)])     # sqrt 2, sqrt 3
    >>> t.is_zero((x * y)**2 - 6), t.is_zero(x * y - 6)
    (True, False)
    """

    def __init__(self, moduli: Sequence[Quotient]):
        for q in moduli:
            if not q.lead.is_constant() or any(
                    d and i != q.k for i, d in enumerate(q.f.degrees())):
                raise ArgumentError(f"{q.f} is not univariate with a constant leading "
                                 "coefficient")
        self.moduli = list(moduli)
        self.zctx = self.moduli[0].zctx

    def reduce_row(self, row: Sequence[Poly]) -> list[Poly]:
        row = list(row)
        for q in self.moduli:
            row = q.reduce_row(row)
        return row

    def reduce(self, p: Poly) -> Poly:
        return self.reduce_row([p])[0]

    def is_zero(self, p: Poly) -> bool:
        return self.reduce(p).is_zero()


def _coefficient(p: Poly, k: int, e: int) -> Poly:
    """The coefficient of ``x_k^e`` in ``p`` (a polynomial free of ``x_k``)."""
    terms = {m[:k] + (0,) + m[k + 1:]: c for m, c in p.to_dict().items() if m[k] == e}
    return p.context().from_dict(terms)


def _join(coeffs: Sequence[Poly], x: Poly) -> Poly:
    """``sum_e coeffs[e] x^e``."""
    out = x.context().constant(0)
    power = x.context().constant(1)
    for e, c in enumerate(coeffs):
        if e:
            power = power * x
        if not c.is_zero():
            out = out + c * power
    return out


def _size(p: Poly) -> tuple[int, int]:
    return (p.total_degree(), len(p))


def eliminate_modulo(rows: Sequence[Sequence[Poly]], columns: Sequence[int],
                     quotient: Quotient) -> tuple[int, list[list[Poly]]]:
    """Fraction-free elimination over the fraction field of ``quotient`` on the given
    columns: the number of pivots found there, and the rows left over (zero in those
    columns), reduced, and primitive unless that needs a gcd of two polynomials over
    :data:`~coopkin_sym.exact.elimination.CONTENT_GCD_TERMS` terms (flint cannot
    interrupt it; the row then keeps its factor, which no rank notices).

    Dividing a row by the gcd of its reduced entries is safe: that gcd has degree in
    ``x_k`` below ``deg_k f``, so ``f`` does not divide it.
    """
    bound = CONTENT_GCD_TERMS   # only ranks are asked: a row may keep a large factor
    left = [quotient.reduce_row(row) for row in rows]
    left = [primitive(r, bound) for r in left if any(not e.is_zero() for e in r)]
    pivots = 0
    for col in columns:
        candidates = [i for i, r in enumerate(left) if not r[col].is_zero()]
        if not candidates:
            continue
        best = min(candidates, key=lambda i: _size(left[i][col]))
        prow = left.pop(best)
        pivots += 1
        out = []
        for r in left:
            check("an elimination modulo a polynomial")
            if not r[col].is_zero():
                r = combine(r, prow, col, quotient.reduce_row, bound)
                if all(e.is_zero() for e in r):
                    continue
            out.append(r)
        left = out
    return pivots, left


def nullspace_modulo(rows: Sequence[Sequence[Poly]], ncols: int,
                     quotient: Quotient) -> list[list[Poly]]:
    """A basis of the right nullspace over the fraction field of ``quotient``: one
    primitive vector per free column (reduced echelon form, fraction free).

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
    >>> (x,) = ctx.gens()
    >>> q = Quotient(x**2 - 2, 0)                  # x = sqrt(2)
    >>> one = ctx.constant(1)
    >>> (v,) = nullspace_modulo([[x, 2 * one]], 2, q)
    >>> [str(e) for e in v], q.is_zero(x * v[0] + 2 * v[1])     # (2, -sqrt 2)
    (['2', '-x'], True)
    """
    pivots: list[tuple[int, list[Poly]]] = []
    left = [quotient.reduce_row(list(r)) for r in rows]
    left = [primitive(r) for r in left if any(not e.is_zero() for e in r)]
    for col in range(ncols):
        candidates = [i for i, r in enumerate(left) if not r[col].is_zero()]
        if not candidates:
            continue
        prow = left.pop(min(candidates, key=lambda i: _size(left[i][col])))
        left = [r for r in (_clear(r, prow, col, quotient) for r in left)
                if any(not e.is_zero() for e in r)]
        pivots = [(c, _clear(r, prow, col, quotient)) for c, r in pivots]
        pivots.append((col, prow))
    pivot_cols = {c for c, _ in pivots}
    zctx = quotient.zctx
    basis = []
    for free in (j for j in range(ncols) if j not in pivot_cols):
        v = [zctx.constant(0)] * ncols
        product = zctx.constant(1)
        for c, r in pivots:
            product = product * r[c]
        v[free] = product
        for c, r in pivots:
            others = zctx.constant(1)
            for c2, r2 in pivots:
                if c2 != c:
                    others = others * r2[c2]
            v[c] = -r[free] * others
        v = quotient.reduce_row(v)
        basis.append(primitive(v))
    return basis


def _clear(r: list[Poly], prow: list[Poly], col: int, quotient: Quotient) -> list[Poly]:
    """``r`` with its entry in ``col`` eliminated by the pivot row ``prow``."""
    check("an elimination modulo a polynomial")
    return combine(r, prow, col, quotient.reduce_row) if not r[col].is_zero() else r


def rank_modulo(rows: Sequence[Sequence[Poly]], ncols: int, quotient: Quotient) -> int:
    """The rank of ``rows`` over the fraction field of ``quotient``."""
    if not rows:
        return 0
    pivots, _ = eliminate_modulo(rows, range(ncols), quotient)
    return pivots


def gcd_modulo(polys: Sequence[Sequence[Poly]], quotient: Quotient,
               max_terms: int | None = None) -> list[Poly]:
    """The gcd, over the fraction field of ``quotient``, of polynomials in a further
    variable given by their coefficient lists (lowest degree first), up to a nonzero
    factor; ``[]`` when all are zero. With ``max_terms``:
    :class:`~coopkin_sym.errors.BlockTooLarge` (its ``terms`` said) as soon as a
    remainder has more terms than that (the gcd of its coefficients, which flint
    cannot interrupt, is not started).

    Euclid's algorithm with pseudo-remainders; the coefficients are reduced modulo
    ``f`` (one multiplier for the whole list) and made primitive after every step.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "p", "y"), "degrevlex")
    >>> x, p, y = ctx.gens()
    >>> q = Quotient(x**2 - p, 0)                  # x = sqrt(p)
    >>> a = coefficients_in((y - x) * (y + 1), 2)  # (y - x)(y + 1)
    >>> b = coefficients_in(y**2 - p, 2)           # (y - x)(y + x)
    >>> g = gcd_modulo([a, b], q)                   # c0 + c1 y, up to a factor
    >>> len(g), q.is_zero(g[0] + g[1] * x)            # degree 1, root y = x
    (2, True)
    """
    def trim(c: list[Poly]) -> list[Poly]:
        check("a gcd modulo a polynomial")
        c = quotient.reduce_row(c)
        while c and c[-1].is_zero():
            c.pop()
        terms = sum(len(e) for e in c)
        if max_terms is not None and terms > max_terms:
            too_large = BlockTooLarge(f"a gcd modulo a polynomial: a remainder of {terms} "
                                      f"terms (more than {max_terms})")
            too_large.terms = terms
            raise too_large
        if c and quotient.degree == 2 and c[-1].degrees()[quotient.k] > 0:
            # times the conjugate of the leading coefficient, which makes it free of x_k:
            # the coefficients stay as small as the element allows
            c = quotient.reduce_row([e * _conjugate(c[-1], quotient) for e in c])
        return primitive(c) if c else c

    return _euclid(polys, trim)


def _euclid(polys: Sequence[Sequence[Poly]], trim) -> list[Poly]:
    """Euclid's algorithm with pseudo-remainders, each made smaller by ``trim``."""
    g: list[Poly] = []
    for p in polys:
        b = trim(list(p))
        while b:
            if not g:
                g, b = b, []
                break
            a = g
            while len(a) >= len(b) and a:
                shift = len(a) - len(b)
                lead_a, lead_b = a[-1], b[-1]
                new = [lead_b * c for c in a]
                for i, c in enumerate(b):
                    new[shift + i] = new[shift + i] - lead_a * c
                a = trim(new)
            g, b = b, a
    return g


def _conjugate(e: Poly, quotient: Quotient) -> Poly:
    """For ``f = a x^2 + b x + c`` and a reduced ``e = u + v x``: the element ``e'`` with
    ``e e' = a u^2 - b u v + c v^2 - v^2 f``, free of ``x`` modulo ``f``."""
    k = quotient.k
    a, b = _coefficient(quotient.f, k, 2), _coefficient(quotient.f, k, 1)
    v, u = _coefficient(e, k, 1), _coefficient(e, k, 0)
    return (a * u - b * v) - a * v * quotient._x


def smallest_fraction(num: Poly, den: Poly, quotient: Quotient) -> tuple[Poly, Poly]:
    """The element ``num/den`` of the fraction field of ``quotient`` written with a
    denominator free of ``x_k`` and no common factor: ``(a, b)`` with ``a/b = num/den``
    there, ``a`` reduced, ``b`` free of ``x_k``, ``gcd(coefficients of a, b) = 1``.
    Unique up to sign, hence as small as the element allows (a root found by a gcd over
    the quotient can carry thousands of spurious terms). Done for ``f`` of degree 2 in
    ``x_k``, where ``den`` times its conjugate is free of ``x_k``; for higher degrees the
    content is removed only. A common factor whose gcd would be too large to take
    (:func:`~coopkin_sym.exact.elimination.primitive`'s bound) stays.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "p"), "degrevlex")
    >>> x, p = ctx.gens()
    >>> q = Quotient(x**2 - p, 0)                     # x = sqrt(p)
    >>> a, b = smallest_fraction((p + 1) * (1 + x), (p + 1) * (x - 1), q)
    >>> str(a), str(b)                  # (1 + x)/(x - 1) = (1 + x)^2/(p - 1)
    ('2*x + p + 1', 'p - 1')
    """
    k = quotient.k
    # reduced forms carry powers of the leading coefficient (free of x_k): balance them
    (num, n_num), (den, n_den) = quotient._reduce_counted(num), quotient._reduce_counted(den)
    num, den = num * quotient.lead ** n_den, den * quotient.lead ** n_num
    if quotient.degree == 2 and den.degrees()[k] > 0:
        (num, den), = [quotient.reduce_row([e * _conjugate(den, quotient) for e in (num, den)])]
    parts = [c for c in coefficients_in(num, k) if not c.is_zero()] + [den]
    g = None
    for c in sorted(parts, key=len):   # the gcd only shrinks: small sides first
        if g is not None and not gcd_fits(g, c, CONTENT_GCD_TERMS):
            g = num.context().constant(1)   # too large to shrink: the same element
            break
        g = c if g is None else g.gcd(c)
        if g.is_one():
            break
    if den.leading_coefficient() < 0:
        g = -g
    return num / g, den / g


__all__ = ["Quotient", "Tower", "eliminate_modulo", "gcd_modulo",
           "nullspace_modulo", "rank_modulo", "smallest_fraction"]
