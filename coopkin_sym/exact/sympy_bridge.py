"""Conversions between SymPy and python-flint: the one place where they meet.

SymPy is the front end (model numbers in, matrices out for display, LaTeX and
printing); python-flint does the algebra. Nothing else in the package converts.

Example
-------
>>> import sympy as sp
>>> from coopkin_sym.exact.ring import Ring
>>> ring = Ring(["L"])
>>> L = sp.Symbol("L", positive=True)
>>> p = poly_from_sympy(2 * L**2 + sp.Rational(1, 3), ring, {"L": L})
>>> poly_to_sympy(p, ring, {"L": L})
2*L**2 + 1/3
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from fractions import Fraction

import flint
import sympy as sp

from coopkin_sym.errors import ArgumentError
from coopkin_sym.exact.ratfunc import RatFunc
from coopkin_sym.exact.rationals import to_fmpq, to_sympy
from coopkin_sym.exact.ring import Ring


def rational_to_sympy(c) -> sp.Rational:
    """An ``fmpz``/``fmpq``/``int`` as a SymPy ``Rational``."""
    if isinstance(c, flint.fmpq):
        return sp.Rational(int(c.p), int(c.q))
    return sp.Integer(int(c))


def poly_to_sympy(p, ring: Ring, symbols: Mapping[str, sp.Symbol]) -> sp.Expr:
    """An ``fmpz_mpoly`` or ``fmpq_mpoly`` of ``ring`` as a SymPy expression.

    The terms are distinct monomials, so the expression is assembled in SymPy's
    canonical order directly (``Mul._from_args``, ``Add._from_args``) instead of being
    flattened and collected again: the same expression (equal, same hash and
    ``srepr``). The canonical order is SymPy's ``Basic.compare``, reproduced by a sort
    key (:func:`_canonical_key`): the factors of a term by one precomputed rank per
    symbol and kind (a symbol, or a power of it: two distinct symbols' powers compare
    by their bases), the terms by keys built once per distinct factor. Far faster on
    large entries than sorting with ``Basic.compare`` itself.

    Example
    -------
    >>> import flint
    >>> from coopkin_sym.exact.ring import Ring
    >>> ring = Ring(("t_q1", "L"), ("t_q1",))
    >>> t, L = ring.zctx.gens()
    >>> poly_to_sympy(3 * t**2 * L - L + 1, ring, {"t_q1": sp.Symbol("t_q1"),
    ...                                           "L": sp.Symbol("L", positive=True)})
    3*L*t_q1**2 - L + 1
    """
    syms = [symbols[n] for n in ring.names]
    powers: dict[tuple[int, int], tuple[sp.Expr, tuple]] = {}
    rank = _factor_ranks(tuple(syms))
    # every factor commutes (checked once, not for every term)
    commutative = True if all(x.is_commutative for x in syms) else None
    numbers, terms, keys = [], [], []
    for monom, c in p.to_dict().items():
        coeff = rational_to_sympy(c)
        factors = []
        for k, e in enumerate(monom):
            if e:
                hit = powers.get((k, e))
                if hit is None:
                    power = syms[k] if e == 1 else sp.Pow(syms[k], int(e))
                    hit = powers[(k, e)] = (power, _canonical_key(power))
                factors.append((rank[(k, e == 1)], hit))
        if not factors:
            numbers.append(coeff)
            continue
        factors.sort(key=_first)
        args = [f[1][0] for f in factors]
        if len(args) == 1 and coeff == 1:
            terms.append(args[0])
            keys.append(factors[0][1][1])
            continue
        if coeff != 1:
            args.insert(0, coeff)
            parts = (_canonical_key(coeff),) + tuple(f[1][1] for f in factors)
        else:
            parts = tuple(f[1][1] for f in factors)
        terms.append(sp.Mul._from_args(args, commutative))
        keys.append((_MUL_KEY, len(args), parts))
    if len(numbers) + len(terms) <= 1:
        return (numbers + terms)[0] if numbers or terms else sp.Integer(0)
    order = sorted(range(len(terms)), key=keys.__getitem__)
    return sp.Add._from_args(numbers + [terms[i] for i in order], commutative)


def _first(pair):
    return pair[0]


def _class_key(cls: type) -> tuple[int, str]:
    """The position of a class in SymPy's canonical order (``basic._cmp_name``): its
    index in ``ordering_of_classes``, the classes not listed after all of them by
    name."""
    from sympy.core import basic

    order = basic.ordering_of_classes
    name = cls.__name__
    if name in order:
        return order.index(name), ""
    return len(order) + 1, name


def _canonical_key(e) -> tuple:
    """A sort key whose order is SymPy's ``Basic.compare`` on ``e``: the class (as
    ``_cmp_name`` orders them), the length of the hashable content, then its items
    (each expression by its own key, other items as they compare in Python).
    Expressions whose contents hold sets (which ``compare`` turns into expressions)
    are not keyed here."""
    content = e._hashable_content()
    items = []
    for x in content:
        if isinstance(x, sp.Basic):
            items.append(_canonical_key(x))
        elif isinstance(x, frozenset | set):
            raise ArgumentError("no canonical key for a set")  # pragma: no cover
        else:
            items.append(x)
    return (_CLASS_KEYS(type(e)), len(content), tuple(items))


_CLASS_KEYS = functools.lru_cache(maxsize=None)(_class_key)
_MUL_KEY = _class_key(sp.Mul)


@functools.lru_cache(maxsize=64)
def _factor_ranks(syms: tuple[sp.Symbol, ...]) -> dict[tuple[int, bool], int]:
    """The place of ``syms[k]`` (``True``) and of any power of it (``False``) among the
    factors of a monomial, in SymPy's canonical order of a product's factors."""
    candidates = [((k, True), s) for k, s in enumerate(syms)]
    candidates += [((k, False), sp.Pow(s, 2)) for k, s in enumerate(syms)]
    candidates.sort(key=lambda kv: _canonical_key(kv[1]))
    return {key: i for i, (key, _) in enumerate(candidates)}


def ratfunc_to_sympy(f: RatFunc, symbols: Mapping[str, sp.Symbol],
                     ring: Ring | None = None) -> sp.Expr:
    """A :class:`~coopkin_sym.exact.ratfunc.RatFunc` as a SymPy expression
    ``num / den``: over known factors, the denominator as the product of its factors
    ``(1 + t**2)**e``; a reduced one in lowest terms (its variables those of ``ring``).

    Example
    -------
    >>> ring = Ring(("t_q1",), ("t_q1",))
    >>> syms = {"t_q1": sp.Symbol("t_q1")}
    >>> f = ring.cos_of(0) * ring.cos_of(0)
    >>> ratfunc_to_sympy(f, syms)
    (t_q1**4 - 2*t_q1**2 + 1)/(t_q1**2 + 1)**2
    >>> ratfunc_to_sympy(f.reduced(), syms, ring)
    (t_q1**4 - 2*t_q1**2 + 1)/(t_q1**4 + 2*t_q1**2 + 1)
    """
    if f.ring is None:
        if ring is None:
            raise ArgumentError("a reduced rational function needs its ring's names")
        return ratio_to_sympy(f.num, f.den, ring, symbols)
    num = poly_to_sympy(f.num, f.ring, symbols)
    if not any(f.powers):
        return num
    den = sp.Mul(*[(1 + symbols[n] ** 2) ** e
                   for n, e in zip(f.ring.den_names, f.powers, strict=True) if e])
    return num / den


def poly_from_sympy(expr, ring: Ring, symbols: Mapping[str, sp.Symbol]) -> flint.fmpq_mpoly:
    """A SymPy polynomial with rational coefficients in ``ring``'s variables (or an
    ``int``/``Fraction``), as an ``fmpq_mpoly``; raises ``ValueError`` if it is not
    one. Only the variables it uses are handed to SymPy, so a ring with many
    variables costs nothing more."""
    if isinstance(expr, int):
        expr = sp.Integer(expr)
    elif isinstance(expr, Fraction):
        expr = to_sympy(expr)
    if not isinstance(expr, sp.Expr):
        raise ArgumentError(f"a {type(expr).__name__} is not a number")
    if expr.is_Rational:
        return ring.qctx.constant(to_fmpq(expr))
    index = {symbols[n]: k for k, n in enumerate(ring.names)}
    used = sorted(expr.free_symbols, key=lambda s: index.get(s, -1))
    if not used or any(s not in index for s in used):
        raise ArgumentError(f"{sp.sstr(expr)[:80]} is not a polynomial in "
                         f"{', '.join(ring.names) or 'no variable'}")
    try:
        poly = sp.Poly(expr, *used, domain=sp.QQ)
    except (sp.PolynomialError, sp.CoercionFailed) as exc:
        raise ArgumentError(f"{sp.sstr(expr)[:80]} is not a polynomial in "
                         f"{', '.join(ring.names)}") from exc
    terms = {}
    for monom, c in poly.terms():
        full = [0] * len(ring.names)
        for s, e in zip(used, monom, strict=True):
            full[index[s]] = int(e)
        terms[tuple(full)] = flint.fmpq(int(sp.Rational(c).p), int(sp.Rational(c).q))
    return ring.qctx.from_dict(terms)


def ratio_to_sympy(num, den, ring: Ring, symbols: Mapping[str, sp.Symbol]) -> sp.Expr:
    """``num / den`` (integer polynomials) as a SymPy expression in lowest terms."""
    g = num.gcd(den) if not num.is_zero() else den
    num, den = num / g, den / g
    if int(den.leading_coefficient()) < 0:
        num, den = -num, -den
    n = poly_to_sympy(num, ring, symbols)
    return n if den.is_one() else n / poly_to_sympy(den, ring, symbols)


def matrix_to_sympy(rows, ring: Ring, symbols: Mapping[str, sp.Symbol],
                    shape: tuple[int, int] | None = None) -> sp.Matrix:
    """A list of rows of polynomials or
    :class:`~coopkin_sym.exact.ratfunc.RatFunc` as an immutable SymPy matrix."""
    def conv(e):
        return (ratfunc_to_sympy(e, symbols, ring) if isinstance(e, RatFunc)
                else poly_to_sympy(e, ring, symbols))
    if not rows:
        return sp.ImmutableMatrix(sp.zeros(*(shape or (0, 0))))
    return sp.ImmutableMatrix([[conv(e) for e in r] for r in rows])


def columns_to_sympy(columns, nrows: int, ring: Ring,
                     symbols: Mapping[str, sp.Symbol]) -> sp.Matrix:
    """Vectors (lists of polynomials) as the columns of a SymPy matrix
    (``nrows x 0`` when there are none)."""
    if not columns:
        return sp.ImmutableMatrix(sp.zeros(nrows, 0))
    return matrix_to_sympy(columns, ring, symbols).T
