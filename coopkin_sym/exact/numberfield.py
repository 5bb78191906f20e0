"""Univariate polynomials over a number field ``Q(alpha) = Q[x]/(g)``, exact.

Elements of ``Q(alpha)`` are python-flint ``fmpq_poly`` in ``x`` of degree below
``deg g`` (``g`` irreducible); a polynomial in ``y`` over ``Q(alpha)`` is a list of such
coefficients, lowest degree first. This is what finding the ``y`` of a point whose
``x`` is a root of ``g`` needs: the gcd over ``Q(alpha)`` of the equations in ``y``.

Example
-------
>>> import flint
>>> g = flint.fmpq_poly([-2, 0, 1])                 # alpha = sqrt(2)
>>> field = NumberField(g)
>>> x = flint.fmpq_poly([0, 1])
>>> # y^2 - 2 and y - x have the common root y = alpha
>>> [str(c) for c in field.gcd([[-2, 0, 1], [-x, 1]])]    # y - alpha
['(-1)*x', '1']
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction

import flint

from coopkin_sym.errors import ArgumentError
from coopkin_sym.exact.deadline import check
from coopkin_sym.exact.numberfield_gcd import modular_gcd

Element = flint.fmpq_poly
KPoly = list[Element]


class NumberField:
    """``Q[x]/(g)`` for an irreducible ``g`` (``fmpq_poly``).

    Example
    -------
    >>> import flint
    >>> k = NumberField(flint.fmpq_poly([-2, 0, 1]))      # Q(sqrt(2))
    >>> k.inverse(k.element([0, 1]))                    # 1/sqrt(2) = sqrt(2)/2
    1/2*x
    """

    def __init__(self, g: flint.fmpq_poly):
        if g.degree() < 1:
            raise ArgumentError("a number field needs a polynomial of positive degree")
        self.g = g

    def element(self, a) -> Element:
        """``a`` (an integer, ``Fraction``, ``fmpq`` or polynomial in ``x``) reduced mod
        ``g``."""
        if isinstance(a, Fraction):
            a = flint.fmpq(a.numerator, a.denominator)
        return flint.fmpq_poly(a) % self.g if not isinstance(a, flint.fmpq_poly) \
            else a % self.g

    def inverse(self, a: Element) -> Element:
        """``1/a`` in the field (``a`` nonzero)."""
        a = self.element(a)
        if a.is_zero():
            raise ZeroDivisionError("zero has no inverse")
        d, s, _ = a.xgcd(self.g)
        if d.degree() != 0:
            raise ArgumentError(f"{self.g} is not irreducible (it shares {d} with {a})")
        return self.element(s / d)

    def _trim(self, p: Sequence) -> KPoly:
        out = [self.element(c) for c in p]
        while out and out[-1].is_zero():
            out.pop()
        return out

    def _divmod(self, a: KPoly, b: KPoly) -> tuple[KPoly, KPoly]:
        inv = self.inverse(b[-1])
        a = list(a)
        quotient = [flint.fmpq_poly(0)] * max(len(a) - len(b) + 1, 0)
        while len(a) >= len(b):
            check("a division over a number field")
            factor = self.element(a[-1] * inv)
            shift = len(a) - len(b)
            quotient[shift] = factor
            for i, c in enumerate(b):
                a[shift + i] = self.element(a[shift + i] - factor * c)
            a = self._trim(a)
        return quotient, a

    def _rem(self, a: KPoly, b: KPoly) -> KPoly:
        return self._divmod(a, b)[1]

    def squarefree(self, p: Sequence) -> KPoly:
        """``p`` without repeated factors (``p / gcd(p, p')``), monic.

        Example
        -------
        >>> import flint
        >>> field = NumberField(flint.fmpq_poly([1, 4, 1]))   # alpha^2 + 4 alpha + 1
        >>> x = flint.fmpq_poly([0, 1])
        >>> # y^2 + 2 alpha y - 4 alpha - 1 = (y + alpha)^2
        >>> [str(c) for c in field.squarefree([-4 * x - 1, 2 * x, 1])]
        ['x', '1']
        """
        p = self._trim(p)
        if len(p) <= 2:
            return self.gcd([p])
        derivative = [self.element(c * i) for i, c in enumerate(p)][1:]
        common = self.gcd([p, derivative])
        if len(common) > 1:
            p = self._divmod(p, common)[0]
        return self.gcd([p])

    def gcd(self, polys: Sequence[Sequence]) -> KPoly:
        """The monic gcd over the field of polynomials in ``y`` (coefficient lists,
        lowest degree first); ``[]`` when all are zero. Computed modulo primes and
        certified (:func:`~coopkin_sym.exact.numberfield_gcd.modular_gcd`), else by
        Euclid's algorithm over the field."""
        nonzero = [b for b in (self._trim(p) for p in polys) if b]
        if len(nonzero) > 1 and all(len(b) > 1 for b in nonzero):
            common = modular_gcd(self.g, nonzero)
            if common is not None:
                return common
        g: KPoly = []
        for p in polys:
            b = self._trim(p)
            while b:
                g, b = b, (self._rem(g, b) if g else [])
        if not g:
            return []
        inv = self.inverse(g[-1])
        return [self.element(c * inv) for c in g]


class RealNumberField(NumberField):
    """``Q(alpha)`` with ``alpha`` a chosen real root of ``g`` (a
    :class:`~coopkin_sym.exact.realroot.RealRoot`, the real embedding): the sign of an
    element is decided exactly, by evaluating it on rational isolating intervals of
    ``alpha``, refined until the enclosure excludes 0 (it does, the element being
    nonzero at a root of an irreducible ``g`` only when it is not a multiple of ``g``).

    Example
    -------
    >>> import flint
    >>> from coopkin_sym.exact.realroot import RealRoot
    >>> root = RealRoot.all_of([-3, 0, 1])[1]              # sqrt(3)
    >>> k = RealNumberField(flint.fmpq_poly([-3, 0, 1]), root)
    >>> k.sign(k.element([-17, 10])), k.sign(k.element([-18, 10]))   # 10 sqrt 3 - 17
    (1, -1)
    """

    def __init__(self, g: flint.fmpq_poly, root, expression=None):
        super().__init__(g)
        self.root = root
        #: ``alpha`` written exactly (a SymPy expression in radicals), when known:
        #: elements are written with it (else with ``root.expression()``).
        self.expression = expression

    def sign(self, a) -> int:
        """The sign of ``a`` at the real embedding: -1, 0 or 1, exactly."""
        from coopkin_sym.exact.realroot import _horner

        a = self.element(a)
        if a.is_zero():
            return 0
        coeffs = [Fraction(int(c.p), int(c.q)) for c in a.coeffs()]
        width = Fraction(1, 16)
        while True:
            lo, hi = self.root.refine(width)
            low, high = _horner(coeffs, lo, hi)
            if low > 0:
                return 1
            if high < 0:
                return -1
            width /= 2**20

    def number(self, a) -> Number:
        """``a`` as a :class:`Number` of this field."""
        return Number(self, self.element(a))


class Number:
    """An element of a :class:`RealNumberField`, with ``+ - * /``, equality and the
    order of the reals (exact signs), so that elimination written for fractions runs
    over ``Q(alpha)`` unchanged.

    Example
    -------
    >>> import flint
    >>> from coopkin_sym.exact.realroot import RealRoot
    >>> k = RealNumberField(flint.fmpq_poly([-2, 0, 1]), RealRoot.all_of([-2, 0, 1])[0])
    >>> a = k.number([0, 1])                                # -sqrt(2)
    >>> a * a == 2, a < 0, str(1 / a)
    (True, True, '1/2*x')
    """

    __slots__ = ("field", "value")

    def __init__(self, field: RealNumberField, value: Element):
        self.field = field
        self.value = value

    def _of(self, other) -> Element | None:
        if isinstance(other, Number):
            return other.value
        if isinstance(other, int | Fraction | flint.fmpq | flint.fmpz | flint.fmpq_poly):
            return self.field.element(other)
        return None

    def _make(self, value: Element) -> Number:
        return Number(self.field, self.field.element(value))

    def __add__(self, other):
        o = self._of(other)
        return NotImplemented if o is None else self._make(self.value + o)

    __radd__ = __add__

    def __sub__(self, other):
        o = self._of(other)
        return NotImplemented if o is None else self._make(self.value - o)

    def __rsub__(self, other):
        o = self._of(other)
        return NotImplemented if o is None else self._make(o - self.value)

    def __mul__(self, other):
        o = self._of(other)
        return NotImplemented if o is None else self._make(self.value * o)

    __rmul__ = __mul__

    def __truediv__(self, other):
        o = self._of(other)
        return NotImplemented if o is None else self._make(self.value *
                                                           self.field.inverse(o))

    def __rtruediv__(self, other):
        o = self._of(other)
        return NotImplemented if o is None else self._make(o * self.field.inverse(self.value))

    def __neg__(self):
        return Number(self.field, -self.value)

    def __eq__(self, other):
        o = self._of(other)
        return NotImplemented if o is None else (self.value - o) % self.field.g == 0

    def __hash__(self):
        return hash(str(self.value))

    def __bool__(self) -> bool:
        return not self.value.is_zero()

    def sign(self) -> int:
        return self.field.sign(self.value)

    def __lt__(self, other):
        return (self - other).sign() < 0

    def __gt__(self, other):
        return (self - other).sign() > 0

    def __le__(self, other):
        return (self - other).sign() <= 0

    def __ge__(self, other):
        return (self - other).sign() >= 0

    def __str__(self) -> str:
        return str(self.value)

    __repr__ = __str__


def change_generator(g: flint.fmpq_poly, t: Element, elements: Sequence[Element]
                     ) -> tuple[flint.fmpq_poly, list[Element]] | None:
    """``Q[x]/(g)`` generated by ``t`` instead of ``x``: the minimal polynomial of ``t``
    and each of ``elements`` as a polynomial in ``t`` (of degree below ``deg g``), or
    None when ``t`` does not generate the whole field (its minimal polynomial has a
    lower degree). ``g`` is irreducible; linear algebra over Q on the powers of ``t``.

    Example
    -------
    >>> import flint
    >>> g = flint.fmpq_poly([-2, 0, 1])                 # x = sqrt(2)
    >>> t = flint.fmpq_poly([1, 1])                     # t = 1 + sqrt(2)
    >>> change_generator(g, t, [flint.fmpq_poly([0, 1])])  # t^2 - 2t - 1; x = t - 1
    (x^2 + (-2)*x + (-1), [x + (-1)])
    >>> change_generator(g, flint.fmpq_poly([0, 0, 1]), []) is None   # t = 2
    True
    """
    d = g.degree()
    powers = [flint.fmpq_poly([1])]
    for _ in range(d):
        check("a change of generator of a number field")
        powers.append((powers[-1] * t) % g)
    columns = flint.fmpq_mat(d, d, [powers[j][i] for i in range(d) for j in range(d)])
    if columns.rank() < d:
        return None
    inverse = columns.inv()

    def in_t(e: Element) -> list:
        e = e % g
        return list((inverse * flint.fmpq_mat(d, 1, [e[i] for i in range(d)])).entries())

    top = in_t(powers[d])
    minimal = flint.fmpq_poly([-c for c in top] + [1])
    return minimal, [flint.fmpq_poly(in_t(e)) for e in elements]


__all__ = ["Number", "NumberField", "RealNumberField", "change_generator"]
