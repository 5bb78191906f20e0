"""The random rational lines of a locus verification: the matrix ``Q`` restricted to a
line (univariate polynomials in ``lam``), the polynomials whose roots are the rank drops,
and the exact decision at each of their real roots.
"""

from __future__ import annotations

import math
import random
from fractions import Fraction

import flint
import sympy as sp

from coopkin_sym.analysis.locus.verify_checker import _Checker, _on_curve, _State
from coopkin_sym.analysis.locus.verify_exact import _fmpq, _Line, _poly_text
from coopkin_sym.analysis.locus.verify_results import DropPoint
from coopkin_sym.analysis.numbers import ranks_of_q
from coopkin_sym.exact.factoring import factor
from coopkin_sym.exact.matrix import POLYNOMIALS, PolyMatrix
from coopkin_sym.exact.quotient import Quotient
from coopkin_sym.exact.rationals import to_fraction, to_sympy


def _random_rational(rng: random.Random, nonzero: bool = False, positive: bool = False):
    while True:
        num = rng.randint(1 if positive else -6, 6)
        if num or not nonzero:
            return Fraction(num, rng.randint(1, 4))


def _make_line(checker: _Checker, sets: list[list], rng: random.Random, k: int) -> _Line:
    """Line ``k``, in turn: a general line; one holding some variables at grid values;
    one inside a component that fixes variables at rational values (to look for drops
    inside it; else like the previous kind); one holding some revolute joints at
    q = pi (the ends of families in the other chart)."""
    free = checker.free
    n = len(free)
    held: dict[int, object] = {}
    revolute = [i for i, v in enumerate(free) if v.kind == "revolute"]
    kind = k % 4
    if kind == 2 and checker.flats and n > 1:
        held = dict(checker.flats[(k // 4) % len(checker.flats)])
    elif kind == 3 and revolute and n > 1:
        for i in rng.sample(revolute, rng.randint(1, min(len(revolute), n - 1))):
            held[i] = None
    elif kind and n > 1:
        for i in rng.sample(range(n), rng.randint(1, n - 1)):
            held[i] = rng.choice(sets[i])
    coords = []
    lo: Fraction | None = None
    hi: Fraction | None = None
    for i, v in enumerate(free):
        if i in held:
            x = held[i]
            if v.kind == "revolute" and x is None:
                coords.append(("s", flint.fmpq_poly([0])))
            else:
                coords.append(("t" if v.kind == "revolute" else "x",
                               flint.fmpq_poly([_fmpq(x)])))
            continue
        chart = rng.choice("ts") if v.kind == "revolute" else "x"
        a = _random_rational(rng, positive=v.kind == "parameter")
        b = _random_rational(rng, nonzero=True)
        coords.append((chart, flint.fmpq_poly([_fmpq(a), _fmpq(b)])))
        if v.kind == "parameter":           # a + b lam > 0
            edge = -a / b
            if b > 0:
                lo = edge if lo is None else max(lo, edge)
            else:
                hi = edge if hi is None else min(hi, edge)
    return _Line(coords, (lo, hi))


def _line_rows(checker: _Checker, line: _Line) -> list[list[flint.fmpq_poly]]:
    """The rows of Q on the line, each times ``prod (1 + t_j^2)^k`` (no real zero), as
    polynomials in ``lam`` with integer coefficients."""
    kin = checker.kin
    ring = kin.ring
    den_index = {name: k for k, name in enumerate(ring.den_names)}
    coords = line.coords
    one = flint.fmpq_poly([1])
    weights = []
    for (_, c), v in zip(coords, checker.free, strict=True):
        weights.append(one + c * c if v.kind == "revolute" else one)
    powers: dict[tuple[int, int], flint.fmpq_poly] = {}

    def power(i: int, e: int) -> flint.fmpq_poly:
        key = (i, e)
        if key not in powers:
            powers[key] = coords[i][1] ** e if e else one
        return powers[key]

    wpowers: dict[tuple[int, int], flint.fmpq_poly] = {}

    def wpower(i: int, e: int) -> flint.fmpq_poly:
        key = (i, e)
        if key not in wpowers:
            wpowers[key] = weights[i] ** e if e else one
        return wpowers[key]

    var_den = [den_index.get(name) for name in ring.names]
    out = []
    for row in kin.Q:
        top = [max(es) for es in zip(*(f.powers for f in row), strict=True)] if ring.den_names \
            else []
        new_row = []
        for f in row:
            if f.num.is_zero():
                new_row.append(flint.fmpq_poly([0]))
                continue
            acc = flint.fmpq_poly([0])
            for monom, coef in f.num.to_dict().items():
                term = flint.fmpq_poly([coef])
                for i, e in enumerate(monom):
                    d = var_den[i]
                    if d is not None and coords[i][0] == "s":
                        top_e = 2 * f.powers[d]
                        if e > top_e:  # pragma: no cover - entries of Q are bounded
                            raise AssertionError("an entry of Q unbounded at q = pi")
                        term *= power(i, top_e - e)
                    elif e:
                        term *= power(i, e)
                acc += term
            for i, d in enumerate(var_den):
                if d is not None and top[d] - f.powers[d]:
                    acc *= wpower(i, top[d] - f.powers[d])
            new_row.append(acc)
        denominators = [int(p.denom()) for p in new_row if not p.is_zero()]
        scale = math.lcm(*denominators) if denominators else 1
        out.append([p * scale for p in new_row])
    return out


_LAM = flint.fmpz_mpoly_ctx.get(("lam",), "degrevlex")


def _to_mpoly(p: flint.fmpq_poly) -> flint.fmpz_mpoly:
    coeffs = p.coeffs()
    return _LAM.from_dict({(i,): int(c.p) for i, c in enumerate(coeffs) if c != 0})


def _from_mpoly(p: flint.fmpz_mpoly) -> flint.fmpq_poly:
    d = p.to_dict()
    top = max((m[0] for m in d), default=0)
    coeffs = [0] * (top + 1)
    for m, c in d.items():
        coeffs[m[0]] = int(c)
    return flint.fmpq_poly(coeffs)


def _drop_polynomial(rows: list[list[flint.fmpz_mpoly]], ncols: int, rank: int,
                     rng: random.Random) -> flint.fmpz_mpoly | None:
    """A multiple of the gcd of the ``rank`` x ``rank`` minors: the gcd of two random
    combinations ``det(A M B)`` (Cauchy-Binet). None when the rank is 0."""
    if rank == 0:
        return None
    m = len(rows)
    zero = _LAM.constant(0)
    g = zero
    tries = 0
    while tries < 8:
        tries += 1
        a = [[rng.randint(-50, 50) for _ in range(m)] for _ in range(rank)]
        b = [[rng.randint(-50, 50) for _ in range(rank)] for _ in range(ncols)]
        am = []
        for arow in a:
            acc = [zero] * ncols
            for coef, row in zip(arow, rows, strict=True):
                if coef:
                    acc = [x + coef * y for x, y in zip(acc, row, strict=True)]
            am.append(acc)
        amb = [[sum((row[j] * b[j][c] for j in range(ncols) if b[j][c]), zero)
                for c in range(rank)] for row in am]
        det = PolyMatrix(amb, len(amb)).det()
        if det.is_zero():
            continue
        g = det if g.is_zero() else g.gcd(det)
        if tries >= 2 and not g.is_zero():
            break
        if g.is_constant():
            break
    if g.is_zero():   # pragma: no cover - a rank-`rank` matrix has a nonzero minor
        raise AssertionError("no nonzero combination of minors found")
    return g


def _line_ranks(rows, quotient: Quotient | None, r: int,
                dim: int) -> tuple[int, int, int]:
    n = dim + r
    if not rows:
        return (0, 0, 0)
    return ranks_of_q(PolyMatrix(rows, n, quotient or POLYNOMIALS), dim=dim)


def _real_roots_in(f: flint.fmpq_poly, domain) -> list[tuple[Fraction, Fraction]]:
    """Isolating intervals (rational ends) of the real roots of the irreducible ``f``
    (degree >= 2) inside the open interval ``domain``."""
    x = sp.Symbol("lam")
    poly = sp.Poly([sp.Rational(int(c.p), int(c.q)) for c in reversed(f.coeffs())], x)
    lo, hi = domain
    kwargs = {}
    if lo is not None:
        kwargs["inf"] = to_sympy(lo)
    if hi is not None:
        kwargs["sup"] = to_sympy(hi)
    out = []
    for (a, b), _ in poly.intervals(**kwargs):
        out.append((Fraction(int(sp.Rational(a).p), int(sp.Rational(a).q)),
                    Fraction(int(sp.Rational(b).p), int(sp.Rational(b).q))))
    return out


def _approximate(checker: _Checker, line: _Line, f: flint.fmpq_poly,
                 interval: tuple[Fraction, Fraction]) -> dict[str, str]:
    """Approximate coordinates of the root in ``interval`` (for reading only)."""
    x = sp.Symbol("lam")
    poly = sp.Poly([sp.Rational(int(c.p), int(c.q)) for c in reversed(f.coeffs())], x)
    a, b = poly.refine_root(sp.Rational(interval[0].numerator, interval[0].denominator),
                            sp.Rational(interval[1].numerator, interval[1].denominator),
                            eps=sp.Rational(1, 10**15))
    mid = (Fraction(int(sp.Rational(a).p), int(sp.Rational(a).q))
           + Fraction(int(sp.Rational(b).p), int(sp.Rational(b).q))) / 2
    out = {}
    for v, value in zip(checker.free, line.point(mid), strict=True):
        if v.kind == "revolute":
            angle = math.pi if value is None else 2 * math.atan(float(value))  # float-ok
            out[v.source] = f"{angle:.12g}"                                     # float-ok
        else:
            out[v.source] = f"{float(value):.12g}"                              # float-ok
    for k, x_ in checker.fixed_items:
        out.setdefault(k, x_)
    return out


def _check_line(checker: _Checker, state: _State, sets: list[list], rng: random.Random,
                k: int) -> None:
    line = _make_line(checker, sets, rng, k)
    source = f"line {k + 1}"
    rows_q = _line_rows(checker, line)
    rows = [[_to_mpoly(p) for p in row] for row in rows_q]
    r = checker.r
    dim = checker.dim
    ranks = _line_ranks(rows, None, r, dim)
    numbers = checker.numbers(ranks)
    result = state.result
    text = line.text(checker.free)
    # the generic point of the line
    inside = {c: m for c in range(len(checker.components))
              if (m := _on_curve(checker, c, line, None))}
    if numbers != checker.generic:
        result.singular_lines += 1
    state.judge(ranks, numbers, inside, DropPoint(source, dict(text), numbers, "line"))
    # candidate points: drops of the three ranks, zeros of the chart variables
    factors: list[flint.fmpz_mpoly] = []
    n = dim + r
    pieces = [(rows, n, ranks[0]), ([x[:dim] for x in rows], dim, ranks[1])]
    if r:
        pieces.append(([x[dim:] for x in rows], r, ranks[2]))
    for mat, ncols, rank in pieces:
        g = _drop_polynomial(mat, ncols, rank, rng) if mat else None
        if g is not None and not g.is_constant():
            factors += [f for f, _ in factor(g)[1]]
    for (_, c), v in zip(line.coords, checker.free, strict=True):
        if v.kind == "revolute" and c.degree() == 1:
            factors.append(_to_mpoly(c * int(c.denom())))
    distinct: dict[str, flint.fmpz_mpoly] = {}
    for f in factors:
        f = _primitive_positive(f)
        distinct.setdefault(str(f), f)
    for f in sorted(distinct.values(), key=lambda p: (p.total_degree(), str(p))):
        fq = _from_mpoly(f)
        if fq.degree() == 1:
            c0, c1 = fq.coeffs()
            lam = -to_fraction(c0) / to_fraction(c1)
            lo, hi = line.domain
            if (lo is not None and lam <= lo) or (hi is not None and lam >= hi):
                continue
            point = line.point(lam)
            result.line_points += 1
            pranks = checker.point_ranks(point)
            pnumbers = checker.numbers(pranks)
            inside = {c: m for c in range(len(checker.components))
                      if (m := checker.contains(c, point))}
            if state.judge(pranks, pnumbers, inside,
                           DropPoint(source, checker.at_text(point), pnumbers)):
                result.line_drops += 1
            continue
        roots = _real_roots_in(fq, line.domain)
        if not roots:
            continue
        result.line_points += 1
        quotient = Quotient(f, 0)
        pranks = _line_ranks(rows, quotient, r, checker.dim)
        pnumbers = checker.numbers(pranks)
        inside = {c: m for c in range(len(checker.components))
                  if (m := _on_curve(checker, c, line, fq))}
        if pnumbers == checker.generic and not inside:
            continue
        point = _approximate(checker, line, fq, roots[0])
        algebraic = {"line": text, "root_of": _poly_text(fq),
                     "interval": [str(roots[0][0]), str(roots[0][1])]}
        if state.judge(pranks, pnumbers, inside,
                       DropPoint(source, point, pnumbers, "root", algebraic)):
            result.line_drops += 1


def _primitive_positive(f: flint.fmpz_mpoly) -> flint.fmpz_mpoly:
    coeffs = [int(c) for c in f.to_dict().values()]
    g = math.gcd(*coeffs) or 1
    f = f / g if g != 1 else f
    top = max(f.to_dict().items(), key=lambda t: t[0])
    return -f if int(top[1]) < 0 else f
