"""Polynomial systems of the singularity locus, exactly (see :mod:`.search`).

Helpers on the polynomials of a locus search (``fmpz_mpoly`` in the ring of the free
variables, held by the search context ``ctx``): normal forms and texts, real and
rational points of a hypersurface, substitution of values (rationals, or elements of
``Q(alpha)`` written as polynomials in the variable that carries ``alpha``), and the
common zeros of a few polynomials in one or two variables (resultants, factorization
over Z, a gcd over ``Q(alpha)``, sheared coordinates when one variable does not
separate the points).

Example
-------
>>> NICE[:3]
[Fraction(1, 2), Fraction(2, 1), Fraction(-1, 3)]
"""

from __future__ import annotations

import itertools
import math
from fractions import Fraction

import flint
import sympy as sp

from coopkin_sym.analysis.locus.conditions import Clause, Related, Value, Vanishes
from coopkin_sym.analysis.locus.context import SearchContext
from coopkin_sym.analysis.locus.remarks import Remark, add_once
from coopkin_sym.errors import BlockTooLarge
from coopkin_sym.exact import deadline
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.factoring import factor
from coopkin_sym.exact.numberfield import NumberField
from coopkin_sym.exact.polynomial import NamedPolynomial, integer_text
from coopkin_sym.exact.quotient import Quotient, gcd_modulo
from coopkin_sym.exact.rationals import to_fraction, to_sympy
from coopkin_sym.exact.realroot import RealRoot, real_root_count
from coopkin_sym.exact.sizes import resultant_terms, resultant_work
from coopkin_sym.exact.substitution import coefficients_in as coefficients_of
from coopkin_sym.exact.substitution import split_linear, substitute, substitute_rows
from coopkin_sym.exact.sympy_bridge import poly_to_sympy

# values tried, in order, for the free coordinates of a witness
NICE = [Fraction(1, 2), Fraction(2), Fraction(-1, 3), Fraction(3), Fraction(-2),
        Fraction(1, 3), Fraction(-1, 2), Fraction(2, 3), Fraction(5, 2), Fraction(-3, 4),
        Fraction(1), Fraction(-1), Fraction(0), Fraction(7, 5), Fraction(-5, 3)]


#: Budgets of the flint operations that run to their end once started (a time bound
#: is checked only between them): the estimated terms of a resultant
#: (:func:`~coopkin_sym.exact.sizes.resultant_terms`) and the terms of a polynomial to
#: factor. Over one, the operation is not run and the report says so.
RESULTANT_TERMS = 200_000
FACTOR_TERMS = 100_000
#: Under a time bound, a resultant of about ``RESULTANT_RATE * sqrt(s)`` terms takes
#: some ``s`` seconds here (measured on dense ones): the largest started is the one the
#: time left allows.
RESULTANT_RATE = 25_000
#: Under a time bound, a resultant of :func:`~coopkin_sym.exact.sizes.resultant_work`
#: ``w`` is taken to need ``w / RESULTANT_WORK_RATE`` seconds (the slowest rate measured
#: here, on resultants in two variables with coefficients of up to 120 bits): one that
#: would not end in the time left is not started.
RESULTANT_WORK_RATE = 40_000_000
#: The longest a single resultant may be estimated to take (``work /
#: RESULTANT_WORK_RATE`` seconds), with or without a time bound: flint cannot interrupt
#: it, so a longer one is not started (deterministic: decided from the sizes alone).
RESULTANT_SECONDS = 10


def bounded_resultant(ctx: SearchContext, p, q, name: str):
    """The resultant of ``p`` and ``q`` in the variable ``name``, or None when its
    estimated size is over :data:`RESULTANT_TERMS`, its estimated time over
    :data:`RESULTANT_SECONDS`, or over what the time left allows under a time bound
    (then a remark says so)."""
    size = resultant_terms(p, q, ctx.ring_names.index(name))
    bound = RESULTANT_TERMS
    left = deadline.remaining()
    if left is not None:
        bound = min(bound, int(RESULTANT_RATE * max(left, 0.0) ** 0.5))  # float-ok: time
    if size > bound:
        _too_large(ctx, "resultant", size, bound, [p, q])
        return None
    seconds = resultant_work(p, q, ctx.ring_names.index(name)) / RESULTANT_WORK_RATE
    names = [n for n in ctx.ring_names if n in vars_of(ctx, p) + vars_of(ctx, q)]
    if left is not None and seconds > max(left, 0.0):
        add_once(ctx.locus.unexplored, Remark.of(
            "operation_too_slow", operation="resultant", variables=names,
            seconds=max(1, round(seconds)), left=max(0, round(left))))
        return None
    if seconds > RESULTANT_SECONDS:
        add_once(ctx.locus.unexplored, Remark.of(
            "operation_over_bound", operation="resultant", variables=names,
            seconds=round(seconds), bound=RESULTANT_SECONDS))
        return None
    deadline.spend(size, "a resultant")   # under a work budget: one step per term
    return p.resultant(q, name)


#: The most terms of a remainder in :func:`bounded_gcd_modulo` (the gcd of its
#: coefficients, which flint cannot interrupt, takes about a second at 50,000 terms
#: here and grows faster than the terms).
GCD_MODULO_TERMS = 30_000


def bounded_gcd_modulo(ctx: SearchContext, polys, quotient: Quotient, name: str):
    """:func:`~coopkin_sym.exact.quotient.gcd_modulo` of the polynomials ``polys`` in
    the variable ``name`` over the fraction field of ``quotient``, or None when a
    remainder grows over :data:`GCD_MODULO_TERMS` terms (then a remark says so)."""
    k = ctx.ring_names.index(name)
    try:
        return gcd_modulo([coefficients_of(p, k) for p in polys], quotient,
                          max_terms=GCD_MODULO_TERMS)
    except BlockTooLarge as exc:
        _too_large(ctx, "gcd modulo a polynomial", exc.terms, GCD_MODULO_TERMS,
                   [*polys, quotient.f])
        return None


#: The most terms of the smaller side of a multivariate gcd (flint runs it to its
#: end once started: with both sides this large it can take minutes).
GCD_TERMS = 20_000
#: The most estimated terms of a discriminant (a resultant of a polynomial and its
#: derivative) taken to prove that a polynomial has no real zeros.
DISCRIMINANT_TERMS = 50_000


def bounded_gcd(ctx: SearchContext, a, b, report: bool = True):
    """``gcd(a, b)``, or None when both have more than :data:`GCD_TERMS` terms (then
    a remark says so, unless ``report`` is False: for a caller that has a safe way
    around it)."""
    size = min(len(a), len(b))
    if size > GCD_TERMS:
        if report:
            _too_large(ctx, "gcd", size, GCD_TERMS, [a, b])
        return None
    deadline.spend(len(a) + len(b), "a gcd")
    return a.gcd(b)


def bounded_factor(ctx: SearchContext, p):
    """``factor(p)`` (content and factors), or None when ``p`` has more than
    :data:`FACTOR_TERMS` terms (then a remark says so)."""
    if len(p) > FACTOR_TERMS:
        _too_large(ctx, "factorization", len(p), FACTOR_TERMS, [p])
        return None
    return factor(p)


def _too_large(ctx: SearchContext, operation: str, size: int, bound: int, polys) -> None:
    names = sorted({n for p in polys for n in vars_of(ctx, p)}, key=ctx.ring_names.index)
    add_once(ctx.locus.unexplored, Remark.of("operation_too_large", operation=operation,
                                             variables=names, size=size, bound=bound))


def normalize(f):
    f = f if int(f.leading_coefficient()) > 0 else -f
    c = f.content()
    return f / f.context().constant(c) if c != 1 else f


def vars_of(ctx: SearchContext, f) -> list[str]:
    return [n for n, d in zip(ctx.ring_names, f.degrees(), strict=True) if d > 0]


def poly_text(ctx: SearchContext, f) -> str:
    """``f`` as text; its reading in angles is kept in ``ctx.readings`` (when the
    context has one) so that conditions never parse text back."""
    if isinstance(f, flint.fmpz_mpoly):  # SymPy's printing, written directly
        text = integer_text(ctx.ring.names, f.to_dict().items())
    else:
        text = sp.sstr(poly_to_sympy(f, ctx.ring, ctx.symbols))
    readings = getattr(ctx, "readings", None)
    if readings is not None and text not in readings:
        readings[text] = read_poly(ctx, f, text)
    polys = getattr(ctx, "polys", None)
    if polys is not None:
        polys.setdefault(text, f)
    return text


def read_poly(ctx: SearchContext, f, text: str) -> Clause:
    """The condition ``f = 0`` in angles where it reads simply (``q2 = pi/2``,
    ``q1 = -q2``, ``q1 + q2 = pi (mod 2*pi)``, ``d4 = 1/2``: a
    :class:`~.conditions.Value` or :class:`~.conditions.Related`), else
    ``f = 0`` (:class:`~.conditions.Vanishes`).

    Works on the polynomial itself (no text is parsed)."""
    names = vars_of(ctx, f)
    kinds = [ctx.kinds[n] for n in names]
    zctx = ctx.ring.zctx
    if len(names) == 1:
        k = ctx.ring_names.index(names[0])
        if f.degrees()[k] == 1:
            terms = f.to_dict()
            one = tuple(1 if i == k else 0 for i in range(len(ctx.ring_names)))
            zero = tuple(0 for _ in ctx.ring_names)
            value = sp.Rational(-int(terms.get(zero, 0)), int(terms[one]))
            kind, joint = kinds[0]
            if kind == "revolute":
                return Value(joint, angle_value(value), kind)
            if kind == "prismatic":
                return Value(joint, value, kind)
    if len(names) == 2 and all(k[0] == "revolute" for k in kinds):
        a, b = (zctx.gens()[ctx.ring_names.index(n)] for n in names)
        na, nb = kinds[0][1], kinds[1][1]
        for candidate, reading in ((a - b, Related(na, nb, 1)), (a + b, Related(na, nb, -1)),
                                   (a * b + 1, Related(na, nb, 1, True)),
                                   (a * b - 1, Related(na, nb, -1, True))):
            if f == candidate or f == -candidate:
                return reading
    return Vanishes(NamedPolynomial.from_flint(f, ctx.ring_names))


def angle_value(t: sp.Rational) -> sp.Expr:
    """The angle (in radians, in (-pi, pi)) whose tangent half-angle is ``t``, as
    :class:`~coopkin_sym.exact.angles.ExactAngle` writes it (``pi/2``,
    ``2*atan(1/3)``).

    Example
    -------
    >>> angle_value(sp.Integer(-1)), angle_value(sp.Rational(1, 3))
    (-pi/2, 2*atan(1/3))
    """
    return ExactAngle.from_tangent(Fraction(int(t.p), int(t.q))).value


def has_real_point(ctx: SearchContext, f, names) -> bool | None:
    """True when a real point of ``f = 0`` is found (a real root of a restriction to
    rational values of the other variables), False when ``f`` is proved to have no real
    zero (:func:`no_real_zeros`), None when undecided."""
    index = [ctx.ring_names.index(n) for n in names]
    if not isinstance(f, flint.fmpz_mpoly) or set(vars_of(ctx, f)) - set(names):
        return _has_real_point_sympy(ctx, f, names)
    terms = [(tuple(int(e) for e in m), int(c)) for m, c in f.to_dict().items()]
    for _ in range(12):
        others = [Fraction(ctx.rng.randint(-9, 9), ctx.rng.randint(1, 5))
                  for _ in names[1:]]
        uni = _restriction(terms, index, others)
        if uni.degree() > 0 and real_root_count(uni) > 0:
            return True
        if len(names) == 1:
            return False
    return False if no_real_zeros(f) else None


def _restriction(terms, index: list[int], values: list[Fraction]) -> flint.fmpq_poly:
    """The polynomial with ``terms`` in the variable ``index[0]`` once the variables
    ``index[1:]`` take ``values``."""
    xs = [flint.fmpq(v.numerator, v.denominator) for v in values]
    powers: dict[tuple[int, int], flint.fmpq] = {}
    coeffs: dict[int, flint.fmpq] = {}
    for mon, c in terms:
        v = flint.fmpq(c)
        for j, k in enumerate(index[1:]):
            e = mon[k]
            if e:
                power = powers.get((j, e))
                if power is None:
                    power = powers[(j, e)] = xs[j] ** e
                v *= power
        e = mon[index[0]]
        coeffs[e] = coeffs[e] + v if e in coeffs else v
    top = max(coeffs, default=0)
    return flint.fmpq_poly([coeffs.get(e, flint.fmpq(0)) for e in range(top + 1)])


def _has_real_point_sympy(ctx: SearchContext, f, names) -> bool | None:
    expr = poly_to_sympy(f, ctx.ring, ctx.symbols)
    syms = [ctx.symbols[n] for n in names]
    for _ in range(12):
        others = {s: sp.Rational(ctx.rng.randint(-9, 9), ctx.rng.randint(1, 5))
                  for s in syms[1:]}
        uni = sp.Poly(expr.subs(others), syms[0])
        if uni.degree() > 0 and uni.count_roots() > 0:
            return True
        if len(syms) == 1:
            return False
    return False if no_real_zeros(f) else None


def no_real_zeros(f, depth: int = 0) -> bool:
    """Whether ``f`` (an integer polynomial) is proved to vanish nowhere on R^n.

    For the last variable ``y`` of ``f``: when neither the leading coefficient nor the
    discriminant in ``y`` has a real zero (recursively), the number of real roots of
    ``f(x, y)`` in ``y`` is the same for every real ``x`` (R^(n-1) is connected), so it
    is counted at one rational point. False means "not proved", not "has zeros".

    Example
    -------
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "lex")
    >>> x, y = ctx.gens()
    >>> no_real_zeros(x**2 + y**2 + 1), no_real_zeros(x**2 + y**2 - 1)
    (True, False)
    """
    if f.is_zero():
        return False
    if f.is_constant():
        return True
    if depth > 4:
        return False
    degrees = f.degrees()
    used = [k for k, d in enumerate(degrees) if d > 0]
    k = max(used, key=lambda i: (degrees[i] > 0, i))
    zctx = f.context()
    if len(used) == 1:
        return _real_root_count(f, k) == 0
    by_power: dict[int, dict] = {}
    for mon, c in f.to_dict().items():
        rest = tuple(0 if i == k else int(e) for i, e in enumerate(mon))
        by_power.setdefault(int(mon[k]), {})[rest] = int(c)
    lead = zctx.from_dict(by_power[degrees[k]])
    if not no_real_zeros(lead, depth + 1):
        return False
    if degrees[k] % 2 == 1:
        return False  # odd degree in y: a real root for every x
    name = zctx.names()[k]
    if resultant_terms(f, f.derivative(name), k) > DISCRIMINANT_TERMS:
        return False      # not proved (a discriminant this large is not taken)
    disc = f.discriminant(name)
    if not disc.is_zero() and not no_real_zeros(disc, depth + 1):
        return False
    if disc.is_zero():
        return False
    uni = f.subs({zctx.names()[i]: 0 for i in used if i != k})
    return _real_root_count(uni, k) == 0


def _real_root_count(f, k: int) -> int:
    """The number of distinct real roots of ``f``, a polynomial in variable ``k`` only."""
    coeffs = [0] * (f.degrees()[k] + 1)
    for mon, c in f.to_dict().items():
        coeffs[int(mon[k])] = int(c)
    return real_root_count(flint.fmpq_poly(coeffs))


def _specialized(terms, k: int, others: list[int], degrees, values) -> flint.fmpz_poly:
    """``f`` (its ``terms``) with variable ``others[i]`` set to ``values[i]``, as an
    integer polynomial in variable ``k`` (a nonzero multiple of it: each value ``p/q``
    enters as ``p^e q^(d - e)``, ``d`` the degree of ``f`` in that variable)."""
    coeffs = [0] * (degrees[k] + 1)
    for mon, c in terms:
        c = int(c)
        for i, v in zip(others, values, strict=True):
            e = int(mon[i])
            c *= v.numerator ** e * v.denominator ** (degrees[i] - e)
        coeffs[int(mon[k])] += c
    return flint.fmpz_poly(coeffs)


def _has_rational_root(uni: flint.fmpz_poly) -> bool:
    """Whether a nonconstant integer polynomial has a rational root (a factor of
    degree 1 over Z)."""
    if uni[0] == 0:
        return True
    _, factors = uni.factor()
    return any(g.degree() == 1 for g, _e in factors)


def rational_point(ctx: SearchContext, f, names) -> dict[str, Fraction] | None:
    expr = None
    syms = [ctx.symbols[n] for n in names]
    terms = list(f.to_dict().items())
    degrees = f.degrees()
    indices = [ctx.ring_names.index(n) for n in names]
    for x_idx in range(len(syms)):
        x = syms[x_idx]
        others_syms = [s for i, s in enumerate(syms) if i != x_idx]
        others = [k for i, k in enumerate(indices) if i != x_idx]
        for values in itertools.islice(itertools.product(NICE, repeat=len(others_syms)),
                                       60):
            # decided over Z first: no rational root there (the common case) is exact;
            # otherwise SymPy picks the root, as it always did
            uni = _specialized(terms, indices[x_idx], others, degrees, values)
            if uni.degree() <= 0 or not _has_rational_root(uni):
                continue
            if expr is None:
                expr = poly_to_sympy(f, ctx.ring, ctx.symbols)
            sub = {s: to_sympy(v)
                   for s, v in zip(others_syms, values, strict=True)}
            uni = sp.Poly(expr.subs(sub), x)
            if uni.degree() <= 0:
                continue
            roots = [r for r in sp.roots(uni, filter="Q") if r.is_Rational]
            if roots:
                point = {str(s): to_fraction(v) for s, v in sub.items()}
                point[str(x)] = Fraction(int(roots[0].p), int(roots[0].q))
                return {name_of(ctx, k): v for k, v in point.items()}
    return None


def name_of(ctx: SearchContext, symbol_name: str) -> str:
    for n, s in ctx.symbols.items():
        if str(s) == symbol_name:
            return n
    return symbol_name


def as_poly(ctx: SearchContext, v, x: str | None):
    """A coordinate value (``Fraction``, or ``fmpq_poly`` in ``x``) as ``(P, c)``:
    an integer polynomial in the ring and a positive integer with ``v = P/c``."""
    zctx = ctx.ring.zctx
    if isinstance(v, Fraction):
        return zctx.constant(v.numerator), v.denominator
    k = ctx.ring_names.index(x)
    num, den = v.numer(), int(v.denom())
    terms = {}
    for e, c in enumerate(num.coeffs()):
        if c:
            mon = [0] * len(ctx.ring_names)
            mon[k] = e
            terms[tuple(mon)] = int(c)
    return zctx.from_dict(terms), den


def substitute_values(ctx: SearchContext, rows, values: dict, x: str | None = None):
    """``rows`` with each variable in ``values`` replaced (rationals, or polynomials in
    the algebraic variable ``x``), rows scaled by the cleared denominators. A value for
    ``x`` itself (a polynomial in its own slot) goes first, so the others' values,
    which are polynomials in ``x``, are not substituted again."""
    ordered = sorted(values.items(), key=lambda nv: nv[0] != x)
    for n, v in ordered:
        num, den = as_poly(ctx, v, x)
        rows = substitute_rows(rows, ctx.ring_names.index(n), -num,
                                ctx.ring.zctx.constant(den))
    return rows


def solve_small(ctx: SearchContext, polys, names: list[str], max_degree: int | None = None):
    """Common zeros of ``polys`` in one or two variables, exactly: the rational points,
    the real algebraic ones as ``(x, g, {y: r(x)}, equations, alpha)`` (``g``
    irreducible over Q, ``y`` a polynomial in its root, from a gcd over ``Q[x]/(g)``),
    and descriptions of what could not be resolved. Resultants and factorization over
    Z (python-flint). Points whose coordinate ``x`` has degree above ``max_degree``
    over Q are left unresolved (said among the descriptions). A system met before in
    the same ring is not solved again."""
    key = (ctx.ring_names, tuple(str(p) for p in polys), tuple(names), max_degree)
    if key not in ctx.solved:
        ctx.solved[key] = _solve_small(ctx, polys, names, max_degree)
    points, algebraic, unresolved = ctx.solved[key]
    return [dict(p) for p in points], list(algebraic), list(unresolved)


def _solve_small(ctx: SearchContext, polys, names: list[str], max_degree: int | None):
    x = names[0]
    if len(names) == 1:
        g = polys[0]
        for p in polys[1:]:
            g = g.gcd(p)
        rational, curved = roots(ctx, g, x)
        unresolved = [_too_high(ctx, f, x, max_degree) for f in curved
                      if _over(f, ctx.ring_names.index(x), max_degree)]
        return ([{x: r} for r in rational],
                [(x, f, {}, [f], x) for f in curved
                 if not _over(f, ctx.ring_names.index(x), max_degree)], unresolved)
    return solve_two(ctx, polys, names, max_degree)


def _over(f, k: int, max_degree: int | None) -> bool:
    return max_degree is not None and f.degrees()[k] > max_degree


def _too_high(ctx: SearchContext, f, x: str, max_degree: int | None) -> Remark:
    return Remark.of("points_not_decided", polynomial=poly_text(ctx, f),
                     degree=int(f.degrees()[ctx.ring_names.index(x)]), bound=max_degree)


def solve_two(ctx: SearchContext, polys, names: list[str], max_degree: int | None = None):
    """:func:`solve_small` for two variables, eliminating the second: ``x`` must
    generate each point's field (else the point is left unresolved)."""
    zctx = ctx.ring.zctx
    x, y = names
    combo = polys[1] if len(polys) == 2 else sum(
        (p * zctx.constant(ctx.rng.randint(1, 9)) for p in polys[1:]), zctx.constant(0))
    points: list[dict] = []
    algebraic: list[tuple] = []
    unresolved: list[Remark] = []
    g = bounded_resultant(ctx, polys[0], combo, y)
    for p in (polys[1:] if len(polys) > 2 else []):   # with two, combo is polys[1]
        if g is None or g.is_constant():
            break
        r = bounded_resultant(ctx, polys[0], p, y)
        g = None if r is None else g.gcd(r)
    if g is None or g.is_zero() or g.is_constant():
        return points, algebraic, unresolved
    k = ctx.ring_names.index(x)
    rational, curved = roots(ctx, g, x)
    for x0 in rational:
        f0, f1 = zctx.constant(-x0.numerator), zctx.constant(x0.denominator)
        uni = None
        for p in polys:
            q = substitute(p, k, f0, f1, p.degrees()[k])
            uni = q if uni is None else uni.gcd(q)
        ys, curved_y = roots(ctx, uni, y)
        points += [{x: x0, y: y0} for y0 in ys]
        ky = ctx.ring_names.index(y)
        unresolved += [_too_high(ctx, h, y, max_degree) for h in curved_y
                       if _over(h, ky, max_degree)]
        algebraic += [(y, h, {x: x0}, [h, linear_equation(ctx, x, x0)], y)
                      for h in curved_y if not _over(h, ky, max_degree)]
    for h in curved:
        if _over(h, k, max_degree):
            unresolved.append(_too_high(ctx, h, x, max_degree))
            continue
        field = NumberField(univariate(ctx, h, x))
        ky = ctx.ring_names.index(y)
        common = field.squarefree(field.gcd([coefficients_in(ctx, p, k, ky)
                                             for p in polys]))
        if len(common) == 2:
            value = field.element(-common[0])
            algebraic.append((x, h, {y: value}, [h, value_equation(ctx, y, value, x)], x))
        elif len(common) > 2:
            # the points are the common zeros of h(x) and of the shared factor, lifted
            sheared = solve_sheared(ctx, [h, _lifted(ctx, common, x, y)], x, y)
            if sheared is not None:     # solved (none when no point is real)
                algebraic += sheared
            else:
                unresolved.append(Remark.of(
                    "shared_values_undecided", polynomial=poly_text(ctx, h),
                    count=len(common) - 1, variable=y, over=x))
    return points, algebraic, unresolved


def _lifted(ctx: SearchContext, coefficients, x: str, y: str):
    """The polynomial in ``y`` with coefficients in ``Q[x]/(h)`` (``fmpq_poly`` in
    ``x``, lowest power of ``y`` first) as an integer polynomial in ``x`` and ``y``
    (a positive multiple: denominators cleared)."""
    zctx = ctx.ring.zctx
    kx, ky = ctx.ring_names.index(x), ctx.ring_names.index(y)
    den = math.lcm(*(int(c.denom()) for c in coefficients))
    terms = {}
    for j, c in enumerate(coefficients):
        for e, a in enumerate(c.coeffs()):
            if a:
                mon = [0] * len(ctx.ring_names)
                mon[kx], mon[ky] = e, j
                terms[tuple(mon)] = int(a * den)
    return zctx.from_dict(terms)


def solve_sheared(ctx: SearchContext, polys, x: str, y: str, tries=(1, -1, 2, 3)
                  ) -> list[tuple] | None:
    """Points whose ``x`` does not determine ``y``: in the coordinate ``z = y + c x``
    (slot of ``y``), for a small ``c`` that separates them, ``z`` generates each
    point's field (``polys[0]`` free of ``y``, best: each resultant is then a norm
    from ``Q[x]/(polys[0])``). Returns the real ones as ``(y, m(z), {y: z - c r(z), x: r(z)},
    equations)`` with the equations in the original coordinates (``m(y + c x)``,
    ``x - r(y + c x)``): an empty list when none is real (``z`` is real at a real
    point, and no factor ``m`` has a real root); None when they are not separated or a
    resultant or a factorization is over its bound."""
    zctx = ctx.ring.zctx
    kx, ky = ctx.ring_names.index(x), ctx.ring_names.index(y)
    gx, gy = zctx.gens()[kx], zctx.gens()[ky]
    for c in tries:
        moved = [substitute(p, ky, c * gx - gy, zctx.constant(1), p.degrees()[ky])
                 for p in polys]
        elim = None
        for p in moved[1:]:
            r = bounded_resultant(ctx, moved[0], p, x) if moved[0].degrees()[kx] else moved[0]
            if r is None:
                return None
            elim = r if elim is None else elim.gcd(r)
        if elim is None or elim.is_zero() or elim.is_constant():
            continue
        factored = bounded_factor(ctx, elim)
        if factored is None:
            return None
        _, factors = factored
        out, separated = [], True
        for m, _e in factors:
            if m.degrees()[kx] or m.is_constant():
                continue
            if not RealRoot.all_of(univariate(ctx, m, y).coeffs()):
                continue
            field = NumberField(univariate(ctx, m, y))
            common = field.squarefree(field.gcd([coefficients_in(ctx, p, ky, kx)
                                                 for p in moved]))
            if len(common) == 1:
                continue
            if len(common) > 2:
                separated = False
                break
            r = field.element(-common[0])
            z = flint.fmpq_poly([0, 1])
            values = {y: field.element(z - c * r), x: r}
            back = gy + c * gx
            m_back = substitute(normalize(m), ky, -back, zctx.constant(1), m.degrees()[ky])
            num, den = as_poly(ctx, r, y)
            x_eq = zctx.constant(den) * gx - substitute(num, ky, -back, zctx.constant(1),
                                                         num.degrees()[ky])
            out.append((y, normalize(m), values, [normalize(m_back), x_eq],
                        f"{y} {'+' if c > 0 else '-'} {abs(c) if abs(c) != 1 else ''}"
                        f"{'*' if abs(c) != 1 else ''}{x}"))
        if separated:
            return out
    return None


def linear_equation(ctx: SearchContext, name: str, value: Fraction):
    zctx = ctx.ring.zctx
    return zctx.constant(value.denominator) * zctx.gens()[ctx.ring_names.index(name)] - \
        zctx.constant(value.numerator)


def value_equation(ctx: SearchContext, name: str, value, x: str):
    """``den * name - P(x)`` for ``name = P(x)/den``."""
    zctx = ctx.ring.zctx
    num, den = as_poly(ctx, value, x)
    return zctx.constant(den) * zctx.gens()[ctx.ring_names.index(name)] - num


def univariate(ctx: SearchContext, g, x: str) -> flint.fmpq_poly:
    k = ctx.ring_names.index(x)
    coeffs = [0] * (g.degrees()[k] + 1)
    for mon, c in g.to_dict().items():
        coeffs[mon[k]] = int(c)
    return flint.fmpq_poly(coeffs)


def coefficients_in(ctx: SearchContext, p, kx: int, ky: int) -> list:
    """``p(x, y)`` as a list of polynomials in ``x`` (``fmpq_poly``), by power of y."""
    by_y: dict[int, dict[int, int]] = {}
    for mon, c in p.to_dict().items():
        by_y.setdefault(mon[ky], {})[mon[kx]] = int(c)
    out = []
    for e in range(max(by_y) + 1):
        terms = by_y.get(e, {})
        coeffs = [0] * (max(terms, default=0) + 1)
        for d, c in terms.items():
            coeffs[d] = c
        out.append(flint.fmpq_poly(coeffs))
    return out


def roots(ctx: SearchContext, g, name: str):
    """Rational roots of a univariate polynomial ``g`` (in ``name``), and its
    irreducible factors of higher degree that have real roots (those without are
    listed as dropped)."""
    if g.is_zero() or g.is_constant():
        return [], []
    k = ctx.ring_names.index(name)
    factored = bounded_factor(ctx, g)
    if factored is None:
        return [], []
    _, factors = factored
    roots, curved = [], []
    for f, _e in sorted(factors, key=lambda fe: (fe[0].degrees()[k], str(fe[0]))):
        if f.degrees()[k] == 1 and sum(f.degrees()) == 1:
            f1, f0 = split_linear(f, k)
            roots.append(Fraction(-int(f0.leading_coefficient()) if not f0.is_zero() else 0,
                                  int(f1.leading_coefficient())))
        elif sum(f.degrees()) == f.degrees()[k]:
            if RealRoot.all_of(univariate(ctx, f, name).coeffs()):
                curved.append(normalize(f))
            else:
                add_once(ctx.locus.dropped,
                         Remark.of("no_real_points", polynomial=poly_text(ctx, f)))
    return roots, curved


#: The largest degree ``deg g1 * deg g2`` of a compositum tried by
#: :func:`linearly_disjoint` (a resultant of that degree, then factored).
DISJOINT_DEGREE = 64


def linearly_disjoint(ctx: SearchContext, g1, x1: str, g2, x2: str) -> bool:
    """Whether the roots of the irreducible univariate ``g1`` (in ``x1``) and ``g2`` (in
    ``x2``) generate linearly disjoint fields: some ``alpha + c beta`` (small ``c``)
    has degree ``deg g1 * deg g2`` over Q (its minimal polynomial, a resultant, is
    irreducible)."""
    d1 = g1.degrees()[ctx.ring_names.index(x1)]
    d2 = g2.degrees()[ctx.ring_names.index(x2)]
    if d1 * d2 > DISJOINT_DEGREE:
        return False          # not proved (a resultant and factorization this large)
    zy = flint.fmpz_mpoly_ctx.get(("z", "y"), "degrevlex")
    z, y = zy.gens()
    p1 = univariate(ctx, g1, x1)
    p2 = univariate(ctx, g2, x2)
    den1, den2 = int(p1.denom()), int(p2.denom())
    c1 = [int(c * den1) for c in p1.coeffs()]
    c2 = [int(c * den2) for c in p2.coeffs()]
    second = sum((c * y**i for i, c in enumerate(c2)), zy.constant(0))
    for c in (1, 2, 3):
        shifted = z - c * y
        first = sum((k * shifted**i for i, k in enumerate(c1)), zy.constant(0))
        res = first.resultant(second, "y")
        if res.is_zero():
            continue
        _, factors = factor(res)
        if len(factors) == 1 and factors[0][1] == 1 and res.total_degree() == d1 * d2:
            return True
    return False
