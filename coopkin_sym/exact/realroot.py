"""Real algebraic numbers: a root of an irreducible integer polynomial, exactly.

A :class:`RealRoot` is the irreducible polynomial and an isolating interval with
rational ends, so it can be compared, refined to any precision and written out
exactly: in radicals for degree two (``-2 + sqrt(3)``), as a SymPy ``CRootOf``
otherwise. As a tangent half-angle it reads as an angle, recognized exactly when it is
a rational multiple of pi (``-2 + sqrt(3)`` is ``tan(-pi/12)``), and so does any
element of the field ``Q(root)`` (:meth:`RealRoot.angle_at`): by arithmetic, not by
simplification. With ``t = tan(q/2)``, ``q = 2 pi j/d`` exactly when
``2 cos q = 2 (1 - t^2)/(1 + t^2)`` has the minimal polynomial of ``2 cos(2 pi/d)``
(FLINT's ``cos_minpoly``); which of its conjugates it is (which ``j``), and the sign of
``q``, are read off rational isolating intervals, refined until they decide.

Example
-------
>>> roots = RealRoot.all_of([1, 4, 1])           # t^2 + 4 t + 1
>>> [str(r.expression()) for r in roots]
['-2 - sqrt(3)', '-2 + sqrt(3)']
>>> [r.angle_text() for r in roots]
['-5*pi/6', '-pi/6']
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from functools import cache, cached_property
from math import gcd

import flint
import sympy as sp

from coopkin_sym.exact.rationals import to_fraction, to_sympy
from coopkin_sym.exact.subfields import minimal_polynomial

_T = sp.Symbol("t")

#: The largest denominator of ``q/pi`` recognized in an algebraic angle ``q``.
PI_DENOMINATOR = 120

#: An element of ``Q(root)``: a rational, or a polynomial in the root (``fmpq_poly``).
Element = Fraction | flint.fmpq_poly


@dataclass(frozen=True)
class RealRoot:
    """The root in ``(lo, hi]`` of the irreducible polynomial with integer
    coefficients ``coeffs`` (lowest degree first); ``index`` is its rank among the real
    roots, smallest first.

    Example
    -------
    >>> r = RealRoot.all_of([-2, 0, 1])[1]                # the positive root of x^2 - 2
    >>> r.expression(), r.lo < r.hi
    (sqrt(2), True)
    """

    coeffs: tuple[int, ...]
    lo: Fraction
    hi: Fraction
    index: int

    @classmethod
    def all_of(cls, coeffs) -> list[RealRoot]:
        """Every real root of the irreducible polynomial ``coeffs``, in increasing
        order."""
        poly = cls._poly_of(coeffs)
        out = []
        for i, ((lo, hi), _m) in enumerate(poly.intervals()):
            out.append(cls(tuple(int(c) for c in coeffs), to_fraction(lo),
                           to_fraction(hi), i))
        return out

    @staticmethod
    def _poly_of(coeffs) -> sp.Poly:
        return sp.Poly([int(c) for c in reversed(list(coeffs))], _T)

    @property
    def degree(self) -> int:
        return len(self.coeffs) - 1

    def polynomial_text(self, name: str) -> str:
        """The polynomial in the variable ``name``."""
        return sp.sstr(self._poly_of(self.coeffs).as_expr().subs(_T, sp.Symbol(name)))

    def refine(self, width: Fraction) -> tuple[Fraction, Fraction]:
        """An isolating interval of at most ``width``."""
        if self.lo == self.hi or self.hi - self.lo <= width:
            return self.lo, self.hi
        lo, hi = self._poly_of(self.coeffs).refine_root(
            to_sympy(self.lo),
            to_sympy(self.hi),
            eps=to_sympy(width))
        return to_fraction(lo), to_fraction(hi)

    def approximation(self, width: Fraction = Fraction(1, 10**40)) -> Fraction:
        """A rational within ``width`` of the root."""
        lo, hi = self.refine(width)
        return (lo + hi) / 2

    def __float__(self) -> float:
        return float(self.approximation(Fraction(1, 10**20)))  # float-ok: display only

    def expression(self) -> sp.Expr:
        """The root as an exact SymPy expression (radicals up to degree two)."""
        return self._expression

    @cached_property
    def _expression(self) -> sp.Expr:
        poly = self._poly_of(self.coeffs)
        if self.degree == 1:
            return sp.Rational(-self.coeffs[0], self.coeffs[1])
        if self.degree == 2:
            for r in sorted(sp.roots(poly, _T), key=lambda e: float(e)):  # float-ok: order
                if self.contains(r):
                    return r
        return sp.CRootOf(poly.as_expr(), self.index)

    def contains(self, expr: sp.Expr) -> bool:
        """Whether the real number ``expr`` lies in the isolating interval (then, for
        a root of the same polynomial, it is this root); a rational root's interval is
        the point itself."""
        lo = to_sympy(self.lo)
        hi = to_sympy(self.hi)
        if self.lo == self.hi:
            return bool(sp.Eq(expr, lo))
        return bool(expr > lo) and bool(expr <= hi)

    def in_subfield(self, value: flint.fmpq_poly) -> RealRoot | None:
        """``value`` (a polynomial in this root) as a root of its own minimal
        polynomial when that has degree at most two and below this root's: which of
        its roots it is is decided by enclosing ``value`` on isolating intervals of
        this root, refined until the enclosure falls on one side of a rational strictly
        between the two.
        None otherwise (or when no refinement up to ``1e-200`` decides).

        Example
        -------
        >>> import flint
        >>> r = RealRoot.all_of([1, 0, -10, 0, 1])[-1]             # sqrt 2 + sqrt 3
        >>> r.in_subfield(flint.fmpq_poly([0, -9, 0, 1]) / 2).expression()   # sqrt 2
        sqrt(2)
        """
        g = flint.fmpq_poly(list(self.coeffs))
        m = minimal_polynomial(g, value % g)
        if m.degree() > 2 or m.degree() >= self.degree:
            return None
        own = RealRoot.all_of(m.numer().coeffs())
        if len(own) == 1:
            return own[0]
        low, high = own
        width = (high.lo - low.lo) / 4 if high.lo > low.lo else Fraction(1)
        while low.refine(width)[1] >= high.refine(width)[0]:
            width /= 16
        split = (low.refine(width)[1] + high.refine(width)[0]) / 2   # strictly between
        for k in range(1, 21):
            a, b = _interval_value(value % g, *self.refine(Fraction(1, 10 ** (10 * k))))
            if b < split:
                return low
            if a > split:
                return high
        return None   # pragma: no cover

    def angle(self) -> sp.Expr:
        """The angle ``q = 2 atan(root)`` in ``(-pi, pi)``, a rational multiple of pi
        when it is one (see :meth:`angle_at`)."""
        return self.angle_at(flint.fmpq_poly([0, 1]))

    def angle_at(self, value: Element) -> sp.Expr:
        """The angle ``q = 2 atan(t)`` for ``t = value`` in ``Q(root)`` (a rational, or
        a polynomial in the root): ``k*pi/n`` when it is one with ``n`` up to
        :data:`PI_DENOMINATOR` (decided exactly, :meth:`pi_multiple`), else
        ``2*atan(t)`` with ``t`` written exactly (:func:`element_expression`).

        Example
        -------
        >>> import flint
        >>> (r,) = [r for r in RealRoot.all_of([-3, 0, 1]) if r.lo > 0]    # sqrt(3)
        >>> r.angle_at(flint.fmpq_poly([0, 1])), r.angle_at(flint.fmpq_poly([0, -1, 1]))
        (2*pi/3, 2*atan(3 - sqrt(3)))
        >>> r.angle_at(flint.fmpq_poly([0, flint.fmpq(1, 3)]))     # tan(pi/6) = sqrt(3)/3
        pi/3
        """
        ratio = self.pi_multiple(value)
        if ratio is not None:
            return sp.pi * to_sympy(ratio)
        return _two_atan(element_expression(value, self))

    def pi_multiple(self, value: Element) -> Fraction | None:
        """``q/pi`` for ``q = 2 atan(value)`` when it is rational with denominator at
        most :data:`PI_DENOMINATOR`, else None; exact (no float decides).

        A rational ``tan(q/2)`` gives a rational multiple of pi only at 0 and +-1. Else
        ``y = 2 cos q`` is an element of ``Q(root)``; its minimal polynomial (from the
        characteristic polynomial of multiplication by ``y``) is looked up among the
        minimal polynomials of ``2 cos(2 pi/d)``; the conjugate ``2 cos(2 pi j/d)``
        equal to ``y``, and the sign of ``t``, are found on rational intervals.

        Example
        -------
        >>> import flint
        >>> r = RealRoot.all_of([1, 4, 1])[1]                       # -2 + sqrt(3)
        >>> r.pi_multiple(flint.fmpq_poly([0, 1])), r.pi_multiple(Fraction(1, 2))
        (Fraction(-1, 6), None)
        """
        v = self._reduced(value)
        if v.degree() <= 0:
            t = to_fraction(v[0])
            return {0: Fraction(0), 1: Fraction(1, 2), -1: Fraction(-1, 2)}.get(t)
        g = self._field_polynomial()
        num = (1 - v * v) % g
        den = (1 + v * v) % g
        y = (2 * num * _inverse(den, g)) % g
        d = _cos_minpoly_table().get(_minimal_polynomial(y, g))
        if d is None:
            return None
        found = self._conjugate(v, d)
        if found is None:  # pragma: no cover - the refinement always separates them
            return None
        j, sign = found
        return Fraction(2 * j * sign, d)

    def _field_polynomial(self) -> flint.fmpq_poly:
        return flint.fmpq_poly(list(self.coeffs))

    def _reduced(self, value: Element) -> flint.fmpq_poly:
        if isinstance(value, flint.fmpq_poly):
            return value % self._field_polynomial()
        value = to_fraction(value)
        return flint.fmpq_poly([flint.fmpq(value.numerator, value.denominator)])

    def _conjugate(self, v: flint.fmpq_poly, d: int) -> tuple[int, int] | None:
        """``(j, sign)`` with ``2 (1 - t^2)/(1 + t^2) = 2 cos(2 pi j/d)`` and ``sign``
        the sign of ``t = v(root)`` (nonzero), for ``y`` known to be a root of
        ``cos_minpoly(d)``: rational intervals for ``t`` and ``y`` are narrowed (the
        root refined) until ``y``'s meets one isolating interval of that polynomial."""
        js = _conjugate_indices(d)               # j of the roots, smallest root first
        poly, intervals = _cos_minpoly_roots(d)
        coeffs = [to_fraction(c) for c in v.coeffs()]
        width = Fraction(1, 2**16)
        for _ in range(24):
            lo, hi = self.refine(width) if self.degree > 1 else (self.lo, self.hi)
            t_lo, t_hi = _horner(coeffs, lo, hi)
            s_lo = Fraction(0) if t_lo <= 0 <= t_hi else min(t_lo**2, t_hi**2)
            s_hi = max(t_lo**2, t_hi**2)
            y_lo, y_hi = 2 * (1 - s_hi) / (1 + s_hi), 2 * (1 - s_lo) / (1 + s_lo)
            hits = [k for k, (a, b) in enumerate(intervals) if a <= y_hi and y_lo <= b]
            if len(hits) == 1 and (t_lo > 0 or t_hi < 0):
                return js[hits[0]], (1 if t_lo > 0 else -1)
            width /= 2**16
            intervals = [_refine_root(poly, a, b, width) if k in hits else (a, b)
                         for k, (a, b) in enumerate(intervals)]
        return None  # pragma: no cover

    def angle_text(self) -> str:
        """:meth:`angle` in ``--at`` syntax."""
        return sp.sstr(self.angle())


def element_expression(value: Element, root: RealRoot | sp.Expr) -> sp.Expr:
    """An element of ``Q(root)`` (a rational, or a polynomial in the root) as an exact
    SymPy expression (the root in radicals up to degree two, else ``CRootOf``).

    Example
    -------
    >>> import flint
    >>> (r,) = [r for r in RealRoot.all_of([-2, 0, 1]) if r.lo > 0]
    >>> element_expression(flint.fmpq_poly([1, flint.fmpq(1, 2)]), r)
    sqrt(2)/2 + 1
    """
    if isinstance(value, Fraction):
        return to_sympy(value)
    if isinstance(root, RealRoot) and root.degree > 2:
        own = root.in_subfield(value)
        if own is not None:   # in a quadratic subfield: its own radicals
            return own.expression()
    expr = root.expression() if isinstance(root, RealRoot) else root
    coeffs = [sp.Rational(int(c.p), int(c.q)) for c in value.coeffs()]
    if coeffs == [0, 1]:
        return expr
    return radical_normal(sum(c * expr**i for i, c in enumerate(coeffs)))


def _interval_value(p: flint.fmpq_poly, lo: Fraction, hi: Fraction
                    ) -> tuple[Fraction, Fraction]:
    """An interval holding ``p(x)`` for every ``x`` in ``[lo, hi]`` (Horner's rule in
    exact interval arithmetic)."""
    coeffs = [Fraction(int(c.p), int(c.q)) for c in p.coeffs()] or [Fraction(0)]
    a = b = coeffs[-1]
    for c in reversed(coeffs[:-1]):
        products = (a * lo, a * hi, b * lo, b * hi)
        a, b = min(products) + c, max(products) + c
    return a, b


def _plain_radical(term: sp.Expr) -> bool:
    """Whether ``term`` is a rational, a square root of an integer, or their product."""
    def plain(f: sp.Expr) -> bool:
        return f.is_Rational or (f.is_Pow and f.base.is_Integer and f.exp == sp.S.Half)
    return plain(term) or (term.is_Mul and all(plain(f) for f in term.args))


def radical_normal(expr: sp.Expr) -> sp.Expr:
    """``radsimp(expand(expr))``, without the cost of ``radsimp`` when the expanded
    form is already a sum of rationals times square roots of integers (no radical left
    in a denominator: ``radsimp`` returns such a sum unchanged).

    Example
    -------
    >>> radical_normal((1 + sp.sqrt(2))**2)
    2*sqrt(2) + 3
    >>> radical_normal(1 / (1 + sp.sqrt(2)))
    -1 + sqrt(2)
    """
    expanded = sp.expand(expr)
    if all(_plain_radical(t) for t in sp.Add.make_args(expanded)):
        return expanded
    return sp.radsimp(expanded)


def _two_atan(t: sp.Expr) -> sp.Expr:
    """``2*atan(t)`` for a real algebraic ``t`` known not to be the tangent of a rational
    multiple of pi, as SymPy writes it (a minus sign taken out) but without SymPy's
    search of its tables and assumptions (slow on large radicals and ``CRootOf``):
    ``-2*atan(sqrt(2))``, ``2*atan(1 - sqrt(5))``."""
    if t.could_extract_minus_sign():
        return -2 * sp.atan(-t, evaluate=False)
    return 2 * sp.atan(t, evaluate=False)


def _inverse(a: flint.fmpq_poly, g: flint.fmpq_poly) -> flint.fmpq_poly:
    """``1/a`` modulo the irreducible ``g`` (``a`` not a multiple of ``g``)."""
    d, s, _ = a.xgcd(g)
    return (s / d[0]) % g


def _minimal_polynomial(y: flint.fmpq_poly, g: flint.fmpq_poly) -> tuple[int, ...]:
    """The minimal polynomial over Q of ``y`` in ``Q[x]/(g)``, primitive with a positive
    leading coefficient, integer coefficients lowest degree first: the squarefree part
    of the characteristic polynomial of multiplication by ``y`` (a power of it)."""
    n = g.degree()
    columns = []
    power = flint.fmpq_poly([1])
    for _ in range(n):
        column = (y * power) % g
        columns.append([column[i] for i in range(n)])
        power = power * flint.fmpq_poly([0, 1])
    matrix = flint.fmpq_mat(n, n, [columns[c][r] for r in range(n) for c in range(n)])
    char = matrix.charpoly()
    squarefree = char / char.gcd(char.derivative()) if char.degree() > 1 else char
    integer = squarefree.numer()
    content = int(integer.content()) * (1 if integer[integer.degree()] > 0 else -1)
    return tuple(int(c) // content for c in integer.coeffs())


@cache
def _cos_minpoly_table() -> dict[tuple[int, ...], int]:
    """``d`` by the minimal polynomial of ``2 cos(2 pi/d)``, for every ``d`` whose
    angles ``2 pi j/d`` have ``q/pi`` with denominator at most :data:`PI_DENOMINATOR`
    (``d`` odd up to it, ``d`` even up to twice it)."""
    out = {}
    for d in range(1, 2 * PI_DENOMINATOR + 1):
        if d % 2 and d > PI_DENOMINATOR:
            continue
        out[tuple(int(c) for c in flint.fmpz_poly.cos_minpoly(d).coeffs())] = d
    return out


@cache
def _conjugate_indices(d: int) -> tuple[int, ...]:
    """The ``j`` in ``[0, d/2]`` prime to ``d`` (the conjugates ``2 cos(2 pi j/d)``),
    in the order of increasing ``2 cos(2 pi j/d)``."""
    return tuple(sorted((j for j in range(d // 2 + 1) if gcd(j, d) == 1), reverse=True))


@cache
def _cos_minpoly_roots(d: int) -> tuple[sp.Poly, list[tuple[Fraction, Fraction]]]:
    """``cos_minpoly(d)`` as a SymPy polynomial and rational isolating intervals of its
    (real, simple) roots, increasing."""
    poly = sp.Poly([int(c) for c in reversed(flint.fmpz_poly.cos_minpoly(d).coeffs())], _T)
    return poly, [(to_fraction(a), to_fraction(b)) for (a, b), _m in poly.intervals()]


def _refine_root(poly: sp.Poly, lo: Fraction, hi: Fraction,
                 width: Fraction) -> tuple[Fraction, Fraction]:
    if lo == hi:
        return lo, hi
    a, b = poly.refine_root(to_sympy(lo), to_sympy(hi), eps=to_sympy(width))
    return to_fraction(a), to_fraction(b)


def _horner(coeffs: list[Fraction], lo: Fraction, hi: Fraction) -> tuple[Fraction, Fraction]:
    """An enclosure of the polynomial ``coeffs`` (lowest degree first) on
    ``[lo, hi]``, by interval arithmetic on rationals."""
    a = b = coeffs[-1]
    for c in reversed(coeffs[:-1]):
        products = (a * lo, a * hi, b * lo, b * hi)
        a, b = min(products) + c, max(products) + c
    return a, b


__all__ = ["PI_DENOMINATOR", "RealRoot", "element_expression", "radical_normal",
           "real_root_count",
           "sturm_real_root_count"]


#: Up to this degree the real roots are counted by Sturm's theorem; above it by flint's
#: certified isolation of the complex roots (a Sturm sequence over Q grows too fast:
#: degree 200 with 100-bit coefficients, minutes against 0.2 s).
STURM_DEGREE = 4


def real_root_count(p: flint.fmpq_poly) -> int:
    """The number of distinct real roots of a nonzero ``fmpq_poly``, exactly: by
    Sturm's theorem (the sign changes of its Sturm sequence at -oo minus those at +oo)
    up to degree :data:`STURM_DEGREE`, above it by flint's isolation of the complex
    roots in balls (real roots come with an exactly zero imaginary part: each is
    certified real, each other ball excludes the real line).

    Example
    -------
    >>> real_root_count(flint.fmpq_poly([-2, 0, 1])), real_root_count(flint.fmpq_poly([1, 0, 1]))
    (2, 0)
    """
    if p.degree() < 1:
        return 0
    if p.degree() > STURM_DEGREE:
        return _isolated_real_root_count(p)
    return sturm_real_root_count(p)


def _isolated_real_root_count(p: flint.fmpq_poly) -> int:
    roots = p.numer().complex_roots()     # distinct roots, with their multiplicities
    real = sum(1 for z, _m in roots if z.imag == 0)
    if any(not z.imag == 0 and z.imag.contains(0) for z, _m in roots):
        return sturm_real_root_count(p)   # never seen: flint isolates until decided
    return real


def sturm_real_root_count(p: flint.fmpq_poly) -> int:
    """:func:`real_root_count` by Sturm's theorem at any degree.

    Example
    -------
    >>> sturm_real_root_count(flint.fmpq_poly([0, -1, 0, 1]))       # t^3 - t
    3
    """
    if p.degree() < 1:
        return 0
    chain = [p, p.derivative()]
    while chain[-1].degree() > 0:
        r = chain[-2] % chain[-1]
        if r == 0:
            break
        chain.append(-r)
    plus = [1 if q.coeffs()[-1] > 0 else -1 for q in chain]
    minus = [s if q.degree() % 2 == 0 else -s for s, q in zip(plus, chain, strict=True)]
    return _changes(minus) - _changes(plus)


def _changes(signs: list[int]) -> int:
    return sum(1 for a, b in zip(signs, signs[1:], strict=False) if a != b)
