"""The drop ideals of a locus certificate (:mod:`.certify`), at real points.

For a polynomial matrix of a chart and a target rank, the generators of the ideal whose
zeros are the real points where the rank falls below the target: rows and pivots
without real zeros handled first (:func:`_reduce`), factors without real zeros removed
(:class:`_RealZeros`), the minors listed or, past :data:`MAX_MINORS`, replaced by
random combinations ``det(A M B)`` (Cauchy-Binet), which lie in the ideal.

Example
-------
>>> ctx = flint.fmpz_mpoly_ctx.get(("t_q1",), "lex")
>>> (t,) = ctx.gens()
>>> _primitive(-2 * t - 4)
t_q1 + 2
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from math import comb

import flint
import sympy as sp

from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.exact import elimination as el
from coopkin_sym.exact.factoring import factor
from coopkin_sym.exact.matrix import PolyMatrix
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model

Poly = flint.fmpz_mpoly

#: Largest number of minors listed one by one; above it, random combinations.
MAX_MINORS = 400
#: Largest size (terms) a minor may reach by the product of its largest entries.
MAX_MINOR_TERMS = 2_000_000



# --- setting up ------------------------------------------------------------------------
@dataclass
class _Setup:
    model: Model
    config: Configuration
    revolute: list[str]
    full_names: tuple[str, ...]
    generic_ranks: dict[str, int]
    components: list[tuple[list[dict], dict[str, int]] | None]
    conditions: list[dict]
    parameters: set[str]


@dataclass
class _Chart:
    name: str
    pi_joints: tuple[str, ...]
    names: tuple[str, ...]
    zctx: flint.fmpz_mpoly_ctx
    units: list[Poly]
    matrices: dict[str, list]           # "HG^T", "HD[arm]", "Q" -> rows
    arm_blocks: list[tuple[str, list]]


def _primitive(p: Poly) -> Poly:
    c = p.content()
    p = p / p.context().constant(c) if c != 1 else p
    return p if int(p.leading_coefficient()) > 0 else -p


# --- drop ideals ---------------------------------------------------------------------------
class _Everywhere:
    """Marker: the rank is at least the target at every real point (no drop)."""


@dataclass
class _TooLarge:
    """The drop ideal is too large to write down; ``why`` says how large."""

    why: Remark


def _is_real_unit(p: Poly, units: list[Poly]) -> bool:
    """A nonzero constant times powers of ``1 + t_j^2``: no real zeros."""
    if p.is_zero():
        return False
    for u in units:
        while not p.is_constant():
            q, r = divmod(p, u)
            if not r.is_zero():
                break
            p = q
    return p.is_constant()


def _real_content(row: list[Poly], units: list[Poly]) -> list[Poly]:
    """The row divided by the part of its content that has no real zeros."""
    nonzero = [e for e in row if not e.is_zero()]
    if not nonzero:
        return row
    g = nonzero[0]
    for e in nonzero[1:]:
        g = g.gcd(e)
        if g.is_one():
            return row
    part = g.context().constant(g.content())
    for u in units:
        while not g.is_constant():
            q, r = divmod(g, u)
            if not r.is_zero():
                break
            g, part = q, part * u
    return row if part.is_one() else [e / part for e in row]


def _reduce(rows: list[list[Poly]], units: list[Poly]) -> tuple[list[list[Poly]], int]:
    """Eliminate with pivots that have no real zeros (nonzero constants times powers of
    ``1 + t^2``): at every real point the rank falls by exactly one per pivot."""
    rows = [_real_content(list(r), units) for r in rows if not all(e.is_zero() for e in r)]
    pivots = 0
    while rows and rows[0]:
        best = None
        for i, r in enumerate(rows):
            for j, e in enumerate(r):
                if e.is_zero() or (best is not None and (len(e), e.total_degree())
                                   >= best[0]):
                    continue
                if _is_real_unit(e, units):
                    best = ((len(e), e.total_degree()), i, j)
        if best is None:
            break
        _, i, j = best
        prow = rows.pop(i)
        p = prow[j]
        new = []
        for r in rows:
            if r[j].is_zero():
                nr = r[:j] + r[j + 1:]
            else:
                g = p.gcd(r[j])
                pg, ag = p / g, r[j] / g
                nr = [pg * x - ag * y for x, y in zip(r, prow, strict=True)]
                nr = nr[:j] + nr[j + 1:]
            nr = _real_content(nr, units)
            if not all(e.is_zero() for e in nr):
                new.append(nr)
        rows = new
        pivots += 1
    return rows, pivots


class _RealZeros:
    """Which irreducible factors have no real zeros (cached)."""

    def __init__(self, chart: _Chart, parameters: set[str]):
        self.units = {str(u) for u in chart.units}
        self.parameters = {chart.names.index(p) for p in parameters if p in chart.names}
        self.cache: dict[str, bool] = {}

    def strip(self, p: Poly) -> Poly:
        """The square-free part of ``p`` without factors that have no real zeros."""
        _, factors = factor(p)
        out = p.context().constant(1)
        for f, _e in factors:
            f = _primitive(f)
            if not self.none(f):
                out = out * f
        return out

    def none(self, f: Poly) -> bool:
        key = str(f)
        if key not in self.cache:
            self.cache[key] = self._decide(f)
        return self.cache[key]

    def _decide(self, f: Poly) -> bool:
        if str(f) in self.units:
            return True
        degrees = f.degrees()
        used = [i for i, d in enumerate(degrees) if d]
        items = [(tuple(int(e) for e in m), int(c)) for m, c in f.to_dict().items()]
        if len(used) == 1 and used[0] in self.parameters and len(items) == 1 \
                and f.total_degree() == 1:
            return True                        # a length parameter: positive
        if len({c > 0 for _, c in items}) == 1 and any(not any(m) for m, _ in items) \
                and all(e % 2 == 0 for m, _ in items for e in m):
            return True                        # even monomials of one sign, constant
        if len(used) == 1 and degrees[used[0]] % 2 == 0:
            k = used[0]
            x = sp.Symbol("x")
            poly = sp.Poly({(m[k],): c for m, c in items}, x, domain=sp.ZZ)
            return poly.count_roots() == 0     # Sturm's theorem: exact
        return False


def _drop_generators(rows, rho: int, chart: _Chart, real: _RealZeros, rng
                     ) -> list[Poly] | type[_Everywhere] | _TooLarge:
    """Generators of an ideal whose zeros contain the real points where
    ``rank(rows) < rho`` and no other real point: the ``rho``-minors after the
    real-unit reduction, stripped of factors without real zeros. ``[]`` when the rank
    is below ``rho`` everywhere; :class:`_Everywhere` when it never is at a real point."""
    reduced, pivots = _reduce(rows, chart.units)
    k = rho - pivots
    if k <= 0:
        return _Everywhere
    if not reduced or k > min(len(reduced), len(reduced[0])):
        return []
    nr, nc = len(reduced), len(reduced[0])
    sizes = sorted((len(e) for r in reduced for e in r), reverse=True)
    estimate = 1
    for size in sizes[:k]:
        estimate *= size
    if estimate > MAX_MINOR_TERMS:
        return _TooLarge(Remark.of("cert_minors_too_large", size=k, rows=nr, columns=nc,
                                   terms=estimate, largest=sizes[0]))
    dets = []
    if comb(nr, k) * comb(nc, k) <= MAX_MINORS:
        for rs in itertools.combinations(range(nr), k):
            for cs in itertools.combinations(range(nc), k):
                dets.append(PolyMatrix([[reduced[i][j] for j in cs] for i in rs], len(cs)).det())
    else:
        zctx = chart.zctx
        for _ in range(len(chart.names) + 3):
            m = reduced
            if k < nr:
                left = [[zctx.constant(rng.randint(-5, 5)) for _ in range(nr)]
                        for _ in range(k)]
                m = el.matmul(left, m, zctx)
            if k < nc:
                right = [[zctx.constant(rng.randint(-5, 5)) for _ in range(k)]
                         for _ in range(nc)]
                m = el.matmul(m, right, zctx)
            dets.append(PolyMatrix(m, len(m)).det())
    return _clean([d for d in dets if not d.is_zero()], real)


def _clean(polys: list[Poly], real: _RealZeros) -> list[Poly] | type[_Everywhere]:
    """Square-free parts without factors that have no real zeros; multiples of another
    generator dropped (the ideal is unchanged)."""
    seen: dict[str, Poly] = {}
    for p in polys:
        q = real.strip(p)
        if q.is_constant():
            return _Everywhere
        seen.setdefault(str(q), q)
    kept: list[Poly] = []
    for g in sorted(seen.values(), key=lambda p: (len(p), p.total_degree(), str(p))):
        if not any(divmod(g, h)[1].is_zero() for h in kept):
            kept.append(g)
    return kept


def _dt_generators(chart: _Chart, total: int, setup: _Setup, real: _RealZeros, rng,
                   cache: dict) -> list[Poly] | type[_Everywhere] | _TooLarge:
    """The points where the ranks of the arm blocks of ``Dt`` add up to less than
    ``total``: for every split ``k_1 + ... = total`` (each ``k_a`` at most the arm's
    generic rank) some arm has rank below ``k_a``; the ideal is the sum over splits of
    the products of the arms' ``I_(k_a)``."""
    per_arm = []
    for name, block in chart.arm_blocks:
        top = setup.generic_ranks[f"HD[{name}]"]
        per_arm.append([_cached(cache, (f"HD[{name}]", k), lambda b=block, k=k:
                                _Everywhere if k <= 0 else
                                _drop_generators(b, k, chart, real, rng))
                        for k in range(top + 1)])
    gens: list[Poly] = []
    one = chart.zctx.constant(1)
    for split in itertools.product(*[range(len(a)) for a in per_arm]):
        if sum(split) != total:
            continue
        parts = [per_arm[a][k] for a, k in enumerate(split)]
        too_large = next((p for p in parts if isinstance(p, _TooLarge)), None)
        if too_large is not None:
            return too_large
        lists = [p for p in parts if p is not _Everywhere]
        if not lists:
            return _Everywhere                 # these ranks hold at every real point
        if any(not p for p in lists):
            continue                           # an arm is below k_a everywhere
        for choice in itertools.product(*lists):
            prod = one
            for g in choice:
                prod = prod * g
            gens.append(prod)
    return _clean(gens, real) if gens else []


def _cached(cache: dict, key, make):
    if key not in cache:
        cache[key] = make()
    return cache[key]
