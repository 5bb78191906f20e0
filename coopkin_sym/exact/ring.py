"""Polynomial rings of one analysis, and rows of rational functions cleared of their
denominators.

Every quantity of the kinematics is a rational function of the analysis variables
(tangent half-angles ``t_<joint>``, free prismatic displacements, free parameters)
whose denominator is a product of the factors ``1 + t_j**2``, one per free revolute
joint. A :class:`Ring` makes them as :class:`~coopkin_sym.exact.ratfunc.RatFunc` over
those known factors (numerator a python-flint ``fmpq_mpoly``, denominator the
exponents of the factors), so sums and products never need a polynomial gcd, and a
row is cleared of denominators by multiplying with the highest power of each factor.

Example
-------
>>> ring = Ring(["t_q1", "L"], denominator_variables=["t_q1"])
>>> t, L = ring.gens()
>>> c = ring.cos_of(0)                       # (1 - t^2) / (1 + t^2)
>>> (c * L + L).powers                       # denominators are exponents of 1 + t^2
(1,)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from fractions import Fraction
from math import factorial, lcm

import flint

from coopkin_sym.exact import pickling  # noqa: F401 - flint polynomials pickle (copyreg)
from coopkin_sym.exact.ratfunc import RatFunc

ORDERING = "degrevlex"


class Ring:
    """The polynomial ring ``Q[x_1..x_n]`` (and ``Z[...]``) of one analysis.

    Parameters
    ----------
    names
        Variable names, in order.
    denominator_variables
        Names ``t`` whose factor ``1 + t**2`` may appear in denominators.

    Example
    -------
    >>> ring = Ring(["t_q1", "L"], ["t_q1"])
    >>> ring.names, ring.zctx.nvars()
    (('t_q1', 'L'), 2)
    """

    def __init__(self, names: Sequence[str], denominator_variables: Sequence[str] = ()):
        self.names: tuple[str, ...] = tuple(names)
        self.qctx = flint.fmpq_mpoly_ctx.get(self.names, ORDERING)
        self.zctx = flint.fmpz_mpoly_ctx.get(self.names, ORDERING)
        self.den_names: tuple[str, ...] = tuple(denominator_variables)
        one = self.qctx.constant(1)
        self.den_factors: tuple[flint.fmpq_mpoly, ...] = tuple(
            one + self.qvar(n) ** 2 for n in self.den_names
        )
        self._no_den = (0,) * len(self.den_names)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Ring) and (other.names, other.den_names) == (
            self.names, self.den_names)

    def __hash__(self) -> int:
        return hash((self.names, self.den_names))

    @property
    def nvars(self) -> int:
        return len(self.names)

    def qvar(self, name: str) -> flint.fmpq_mpoly:
        """The variable ``name`` as an ``fmpq_mpoly``."""
        return self.qctx.gens()[self.names.index(name)]

    def gens(self) -> list[RatFunc]:
        """All variables as :class:`~coopkin_sym.exact.ratfunc.RatFunc`."""
        return [self.ratfunc(g) for g in self.qctx.gens()]

    # --- constructing rational functions -------------------------------------------
    def ratfunc(self, num, powers: tuple[int, ...] | None = None) -> RatFunc:
        """``num / prod(den_factors[j] ** powers[j])`` (no denominator without
        ``powers``), over the known factors; ``num`` an fmpq_mpoly, int, Fraction or
        fmpq."""
        if not isinstance(num, flint.fmpq_mpoly):
            num = self.qctx.constant(_to_fmpq(num))
        return RatFunc(num, None, self, self._no_den if powers is None else powers)

    def zero(self) -> RatFunc:
        return self.ratfunc(0)

    def one(self) -> RatFunc:
        return self.ratfunc(1)

    def _den_of(self, name: str) -> tuple[int, ...]:
        k = self.den_names.index(name)
        return tuple(1 if i == k else 0 for i in range(len(self.den_names)))

    def cos_of(self, k: int) -> RatFunc:
        """``cos q = (1 - t^2)/(1 + t^2)`` for the ``k``-th denominator variable."""
        t = self.qvar(self.den_names[k])
        return RatFunc(1 - t**2, None, self, self._den_of(self.den_names[k]))

    def sin_of(self, k: int) -> RatFunc:
        """``sin q = 2 t/(1 + t^2)`` for the ``k``-th denominator variable."""
        t = self.qvar(self.den_names[k])
        return RatFunc(2 * t, None, self, self._den_of(self.den_names[k]))

    def den_poly(self, den: tuple[int, ...]) -> flint.fmpq_mpoly:
        """The denominator ``prod (1 + t_j^2)^e_j`` as a polynomial."""
        p = self.qctx.constant(1)
        for f, e in zip(self.den_factors, den, strict=True):
            if e:
                p = p * f**e
        return p

    # --- values at t = oo -----------------------------------------------------------
    def at_infinity(self, names: Sequence[str]) -> tuple[Ring, Callable[[RatFunc],
                                                                     RatFunc | None]]:
        """The ring without the denominator variables ``names``, and the map taking a
        value over this ring's known factors to its value at ``t = oo`` for every ``t``
        in ``names`` (``q = pi`` for ``t = tan(q/2)``). The map gives ``None`` for a
        value without a finite limit there or in reduced form with a variable of
        ``names``.

        A value ``num / prod (1 + t_j^2)^e_j`` has the finite limit
        ``[t^(2e)] num`` (its coefficient, a polynomial in the other variables, over the
        other factors) when no term of ``num`` has a higher power of ``t``.

        Example
        -------
        >>> ring = Ring(["t_q1", "L"], ["t_q1"])
        >>> t, L = ring.gens()
        >>> smaller, limit = ring.at_infinity(["t_q1"])
        >>> c = limit(ring.cos_of(0) * L)               # cos(pi) L
        >>> smaller.names, str(c.num), c.powers
        (('L',), '-L', ())
        """
        drop = [self.names.index(n) for n in names]
        den_at = [self.den_names.index(n) for n in names]
        keep_den = [k for k in range(len(self.den_names)) if k not in den_at]
        smaller = Ring([n for n in self.names if n not in names],
                       [self.den_names[k] for k in keep_den])
        qctx, zctx = smaller.qctx, smaller.zctx

        zero = qctx.constant(0)

        def limit(f: RatFunc) -> RatFunc | None:
            num = f.num
            if f.ring is not None and num.is_zero():
                return RatFunc(zero, None, smaller, tuple(f.powers[k] for k in keep_den))
            degrees = num.degrees()
            if f.ring is None:
                if any(degrees[i] or f.den.degrees()[i] for i in drop):
                    return None
                return RatFunc(num.project_to_context(zctx), f.den.project_to_context(zctx))
            powers = tuple(f.powers[k] for k in keep_den)
            for i, k in zip(drop, den_at, strict=True):
                top = 2 * f.powers[k]
                if degrees[i] > top:
                    return None
                if degrees[i] < top:               # the value tends to zero
                    return smaller.ratfunc(0, powers)
                if top:                            # [t^top] num: differentiate top times
                    for _ in range(top):
                        num = num.derivative(i)
                    num = num / factorial(top)
            return RatFunc(num.project_to_context(qctx), None, smaller, powers)
        return smaller, limit

    # --- integer polynomials ------------------------------------------------------
    def to_zpoly(self, p: flint.fmpq_mpoly) -> flint.fmpz_mpoly:
        """``p`` times the least common denominator of its coefficients, over Z."""
        terms = p.to_dict()
        d = lcm(*(int(c.q) for c in terms.values())) if terms else 1
        return self.zctx.from_dict({m: int(c.p) * (d // int(c.q)) for m, c in terms.items()})

    def clear_row(self, row: Sequence[RatFunc]) -> list[flint.fmpz_mpoly]:
        """A row of fractions times one nonzero polynomial, as integer polynomials.

        Scaling a row of a matrix by a nonzero polynomial keeps its nullspace and rank,
        so this is how a matrix of rational functions enters the fraction-free
        elimination of :mod:`coopkin_sym.exact.elimination`.
        """
        if not row:
            return []
        # zero entries (most of a row of a system with many arms) stay zero: only the
        # others are scaled and converted
        nonzero = [k for k, f in enumerate(row) if not f.num.is_zero()]
        zero = self.zctx.constant(0)           # one zero for the row (never changed)
        if not nonzero:
            return [zero] * len(row)
        top = tuple(max(es) for es in zip(*(row[k].powers for k in nonzero), strict=True))
        factors: dict[tuple[int, ...], flint.fmpq_mpoly] = {}
        nums = {}
        for k in nonzero:
            f = row[k]
            missing = tuple(a - b for a, b in zip(top, f.powers, strict=True))
            if any(missing):
                if missing not in factors:
                    factors[missing] = self.den_poly(missing)
                nums[k] = f.num * factors[missing]
            else:
                nums[k] = f.num
        d = 1
        for p in nums.values():
            for c in p.coeffs():
                if c.q != 1:
                    d = lcm(d, int(c.q))
        out = []
        for k in range(len(row)):
            p = nums.get(k)
            if p is None:
                out.append(zero)
                continue
            if d != 1:
                p = p * d                                  # integer coefficients now
            out.append(self.zctx.from_dict(dict(zip(p.monoms(), [int(c.p) for c in p.coeffs()],
                                                    strict=True))))
        return out


class ClearedRows(Sequence):
    """The rows of a matrix of :class:`~coopkin_sym.exact.ratfunc.RatFunc` (over the
    known factors of ``ring``), each cleared to integer polynomials
    (:meth:`Ring.clear_row`) when first used; :meth:`values_at` gives the rows' values
    at an integer point (each row scaled to integers) without clearing any.

    Example
    -------
    >>> ring = Ring(["t_q1"], ["t_q1"])
    >>> rows = ClearedRows(ring, [[ring.cos_of(0), ring.sin_of(0)]])
    >>> rows.values_at([2])                  # (cos, sin) at t = 2 is (-3/5, 4/5)
    [[-3, 4]]
    >>> [str(e) for e in rows[0]]
    ['-t_q1^2 + 1', '2*t_q1']
    """

    def __init__(self, ring: Ring, rows: Sequence[Sequence[RatFunc]]) -> None:
        self.ring = ring
        self.entries = rows
        self._cleared: dict[int, list[flint.fmpz_mpoly]] = {}

    def __len__(self) -> int:
        return len(self.entries)

    def __getitem__(self, i):
        if isinstance(i, slice):
            return [self[k] for k in range(*i.indices(len(self)))]
        if i < 0:
            i += len(self)
        if i not in self._cleared:
            self._cleared[i] = self.ring.clear_row(self.entries[i])
        return self._cleared[i]

    def block(self, rows: Sequence[int], cols: Sequence[int]) -> list[list[flint.fmpz_mpoly]]:
        """The block ``rows x cols``, each of its rows cleared on its own (the block's
        rank and nullspace, not the whole rows', are kept)."""
        return [self.ring.clear_row([self.entries[i][c] for c in cols]) for i in rows]

    def values_at(self, point: Sequence[int]) -> list[list[int]]:
        """The rows at ``point`` (integers; the denominators ``1 + t^2`` never vanish
        there), each row times one positive integer so that its values are integers:
        the same rank as the matrix at the point, in any set of rows and columns."""
        out = []
        factor_values = [int(f(*point)) for f in self.ring.den_factors]
        for row in self.entries:
            values = []
            for f in row:
                if f.num.is_zero():
                    values.append(flint.fmpq(0))
                    continue
                den = 1
                for v, e in zip(factor_values, f.powers, strict=True):
                    if e:
                        den *= v**e
                values.append(f.num(*point) / den)
            d = 1
            for v in values:
                if v.q != 1:
                    d = lcm(d, int(v.q))
            out.append([int(v.p) * (d // int(v.q)) for v in values])
        return out


def _to_fmpq(x) -> flint.fmpq:
    if isinstance(x, flint.fmpq):
        return x
    if isinstance(x, int):
        return flint.fmpq(x)
    f = Fraction(x)
    return flint.fmpq(f.numerator, f.denominator)
