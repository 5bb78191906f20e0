"""A component of the locus cut by a picture's plane: the other variables put in at
exact values, the curve (the gcd of the equations there) and the isolated points, with
flint when every value is rational and with SymPy otherwise (algebraic values, a joint
at ``q = pi``). Floats only for the plotted coordinates of points.

Example
-------
>>> ax, ay = _Axis("q1", "t_q1", "t"), _Axis("q2", "t_q2", "t")
>>> ax.angle(sp.Integer(1))  # doctest: +ELLIPSIS
1.5707963...
"""

from __future__ import annotations

import functools
import itertools
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import flint
import sympy as sp

from coopkin_sym.analysis.locus.types import Component
from coopkin_sym.errors import PlotError
from coopkin_sym.exact.parse import NumberError
from coopkin_sym.exact.polynomial import NamedPolynomial

INFINITY = "oo"  # a revolute joint at q = pi: t = tan(q/2) is infinite


def _equations(c: Component, names: tuple[str, ...]) -> list[sp.Expr]:
    """The component's equations, exactly, as SymPy expressions to draw."""
    try:
        return [p.to_sympy() for p in c.equation_polynomials(names)]
    except NumberError as exc:
        raise PlotError(str(exc)) from None


def _substitute(f: sp.Expr, values: Mapping[str, Any]) -> sp.Expr:
    """``f`` with exact values put in; a variable at INFINITY keeps the top
    coefficient (what ``f cos(q/2)^deg`` tends to at q = pi)."""
    for name, v in values.items():
        s = sp.Symbol(name)
        if s not in f.free_symbols:
            continue
        if isinstance(v, str):  # INFINITY
            f = sp.Poly(f, s).LC()
        else:
            f = f.xreplace({s: v})
    return sp.expand(f)


@dataclass
class _Axis:
    """One axis of the plane: its joint, the variable the component uses and its
    chart (``t``, ``s`` or ``d``)."""

    joint: str
    variable: str
    chart: str

    @property
    def symbol(self) -> sp.Symbol:
        return sp.Symbol(self.variable)

    def angle(self, z: Any) -> float | None:  # float-ok: plotting
        """The plotted coordinate of a real value of the variable (None if complex)."""
        w = complex(sp.N(z, 30))  # float-ok
        if abs(w.imag) > 1e-9 * max(1.0, abs(w.real)):  # float-ok: complex, not drawn
            return None
        if self.chart == "t":
            return 2 * math.atan(w.real)  # float-ok
        if self.chart == "s":
            return math.remainder(2 * math.atan2(1.0, w.real), 2 * math.pi)  # float-ok
        return w.real  # float-ok

    @property
    def at_infinity(self) -> float | None:  # float-ok
        return {"t": math.pi, "s": 0.0}.get(self.chart)  # float-ok


@dataclass
class _Drawn:
    """What one component becomes in the plane: a curve (or none) and points."""

    curve: sp.Poly | None = None
    points: list[tuple[float, float]] = field(default_factory=list)   # float-ok
    whole: bool = False


#: Bits of the balls in which :func:`_real_common_zeros` finds the coordinates of a
#: point (for a picture: far more than a pixel needs).
POINT_BITS = 200


def _real_roots(u, k: int) -> list[Any] | None:
    """Balls around the real roots of ``u``, a flint polynomial in variable ``k``
    alone (None when ``u`` is zero)."""
    if u.is_zero():
        return None
    terms = {e[k]: c for e, c in u.to_dict().items()}
    den = math.lcm(*(int(c.q) for c in terms.values()))
    f = flint.fmpz_poly([int(terms.get(d, 0) * den) for d in range(max(terms) + 1)])
    if f.degree() < 1:
        return []
    return [z.real for z, _ in f.complex_roots() if z.imag.is_zero()]


def _real_common_zeros(polys: list[Any], ix: int, iy: int
                       ) -> list[tuple[float, float]] | None:  # float-ok: plotting
    """The real common zeros of flint polynomials in the variables ``ix``, ``iy`` alone
    (finitely many), approximately, for a picture: each coordinate a real root of the
    resultants eliminating the other variable (computed exactly, roots in balls of
    :data:`POINT_BITS` bits), a pair kept where every polynomial's ball holds 0. None
    when the resultants vanish (a common factor of two of them)."""
    names = polys[0].context().names()
    with flint.ctx.workprec(POINT_BITS):
        coordinates = []
        for keep, drop in ((ix, iy), (iy, ix)):
            # a polynomial free of the other variable is an equation in this one;
            # two that have it give their resultant
            free = [p for p in polys if p.degrees()[drop] == 0]
            pairs = [(a, b) for i, a in enumerate(polys) for b in polys[i + 1:]
                     if a.degrees()[drop] > 0 and b.degrees()[drop] > 0]
            found = None
            for r in itertools.chain(free, (a.resultant(b, names[drop]) for a, b in pairs)):
                if not r.is_zero():
                    found = r if found is None else found.gcd(r)
            roots = None if found is None else _real_roots(found, keep)
            if roots is None:
                return None
            coordinates.append(roots)
        terms = [[(flint.arb(c), e[ix], e[iy]) for e, c in p.to_dict().items()]
                 for p in polys]
        out = []
        for x in coordinates[0]:
            for y in coordinates[1]:
                if all(sum((c * x**i * y**j for c, i, j in t), flint.arb(0)).contains(0)
                       for t in terms):
                    out.append((float(x.mid()), float(y.mid())))  # float-ok: plotting
    return out


def _points(polys: list[sp.Expr], ax: _Axis, ay: _Axis,
            tops: Callable[[int, tuple[str, ...]], sp.Expr] | None = None,
            finite: list[tuple[float, float]] | None = None  # float-ok: plotting
            ) -> list[tuple[float, float]]:  # float-ok: plotting
    """Real common zeros of ``polys`` (gcd 1, so finitely many), in the plane's
    coordinates, including the ones where a variable is infinite. ``tops(k, names)``:
    the top coefficient of ``polys[k]`` in the variables ``names`` (in turn), when the
    caller has it cheaper than SymPy; ``finite``: the finite zeros (values of the two
    variables), when the caller has them (:func:`_real_common_zeros`)."""
    out = []
    x, y = ax.symbol, ay.symbol
    nonzero = [k for k, p in enumerate(polys) if p != 0]

    def top(k: int, names: tuple[str, ...]) -> sp.Expr:   # k among the nonzero ones
        if tops is not None:
            return tops(nonzero[k], names)
        return _substitute(polys[nonzero[k]], dict.fromkeys(names, INFINITY))
    polys = [polys[k] for k in nonzero]
    if not polys or any(p.is_number for p in polys):
        return out
    if finite is not None:
        solutions = finite
    else:
        try:
            solutions = sp.solve_poly_system(polys, x, y) or []
        except (NotImplementedError, sp.PolificationFailed):  # pragma: no cover
            solutions = []
    for sx, sy in solutions:
        a, b = ax.angle(sx), ay.angle(sy)
        if a is not None and b is not None:
            out.append((a, b))
    # one variable infinite: the top coefficients in it, solved for the other
    for inf, other, swap in ((ax, ay, False), (ay, ax, True)):
        if inf.at_infinity is None:
            continue
        lead = [top(k, (inf.variable,)) for k in range(len(polys))]
        lead = [t for t in lead if t != 0]
        if lead and any(t.is_number for t in lead):
            continue
        g = functools.reduce(sp.gcd, lead) if lead else sp.Integer(0)
        if g == 0:
            continue
        g = sp.Poly(g, other.symbol)
        for r in (g.real_roots() if g.degree() > 0 else []):
            value = other.angle(r)
            if value is not None:
                out.append((value, inf.at_infinity) if swap else (inf.at_infinity, value))
    if ax.at_infinity is not None and ay.at_infinity is not None:
        both = [top(k, (ax.variable, ay.variable)) for k in range(len(polys))]
        if all(b == 0 for b in both):
            out.append((ax.at_infinity, ay.at_infinity))
    return out


def _in_plane_rational(c: Component, values: Mapping[str, Any], ax: _Axis, ay: _Axis,
                       names: tuple[str, ...]) -> _Drawn | None:
    """What :func:`_in_plane` draws, computed with flint when every value put in is
    rational (``None`` otherwise, or when a used variable has no value): the same
    curve and points as the SymPy way (its polynomials up to constant factors)."""
    if any(isinstance(v, str) or not getattr(v, "is_Rational", False)
           for v in values.values()):
        return None
    try:
        equations = c.equation_polynomials(names)
    except NumberError as exc:
        raise PlotError(str(exc)) from None
    plane = (ax.variable, ay.variable)
    used = sorted({v for p in equations for v in p.variables} | set(plane))
    if set(used) - set(values) - set(plane):
        return None
    ctx = flint.fmpq_mpoly_ctx.get(tuple(used), "lex")
    at = {n: flint.fmpq(int(values[n].p), int(values[n].q))
          for n in used if n not in plane}
    polys = []
    for p in equations:
        f = ctx.from_dict({e: flint.fmpq(k.numerator, k.denominator)
                           for e, k in p.exponents(used).items()})
        f = f.subs(at) if at else f
        if not f.is_zero():
            polys.append(f)
    drawn = _Drawn()
    if not polys:
        drawn.whole = True
        return drawn
    if any(f.is_constant() for f in polys):
        return drawn            # does not meet the plane at these values
    g = functools.reduce(lambda a, b: a.gcd(b), polys)
    symbols = {n: sp.Symbol(n) for n in used}

    def back(f) -> sp.Expr:
        return NamedPolynomial.from_flint(f, used).to_sympy(symbols)

    if not g.is_constant():
        drawn.curve = sp.Poly(back(g), ax.symbol, ay.symbol)
    if len(polys) > 1:
        rest = [f / g for f in polys]

        def tops(k: int, variables: tuple[str, ...]) -> sp.Expr:
            f = rest[k]
            for v in variables:
                f = _top_coefficient(f, used.index(v))
            return back(f)
        finite = _real_common_zeros(rest, used.index(ax.variable), used.index(ay.variable))
        drawn.points = _points([back(f) for f in rest], ax, ay, tops, finite)
    return drawn


def _top_coefficient(f, k: int):
    """The coefficient of the highest power of variable ``k`` in the flint polynomial
    ``f`` (free of it): what ``f`` over that power tends to at infinity."""
    if f.is_zero():
        return f
    d = f.degrees()[k]
    return f.context().from_dict({e[:k] + (0,) + e[k + 1:]: c
                                  for e, c in f.to_dict().items() if e[k] == d})


def _in_plane(c: Component, values: Mapping[str, Any], ax: _Axis, ay: _Axis,
              names: tuple[str, ...]) -> _Drawn:
    fast = _in_plane_rational(c, values, ax, ay, names)
    return fast if fast is not None else _in_plane_sympy(c, values, ax, ay, names)


def _in_plane_sympy(c: Component, values: Mapping[str, Any], ax: _Axis, ay: _Axis,
                    names: tuple[str, ...]) -> _Drawn:
    """What :func:`_in_plane` draws, with SymPy (any exact values, ``INFINITY``)."""
    drawn = _Drawn()
    x, y = ax.symbol, ay.symbol
    polys = [_substitute(f, values) for f in _equations(c, names)]
    polys = [p for p in polys if p != 0]
    if not polys:
        drawn.whole = True
        return drawn
    if any(p.is_number for p in polys):
        return drawn            # does not meet the plane at these values
    if set().union(*(p.free_symbols for p in polys)) - {x, y}:
        return drawn            # pragma: no cover - every other variable has a value
    g = functools.reduce(sp.gcd, polys)
    if not g.is_number:
        drawn.curve = sp.Poly(g, x, y)
    rest = [sp.cancel(p / g) for p in polys]
    if len(rest) > 1:
        drawn.points = _points(rest, ax, ay)
    return drawn
