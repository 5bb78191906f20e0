"""Singularity locus: where, exactly, the mobility numbers change.

The numbers follow from three ranks: ``rank Gt^T`` (Ni), ``rank Dt`` (Nr) and
``rank Q`` (Nm); Nc = Nm - Nr. Each arm's joint variables appear only in its own
contacts' rows, so the rank of ``Q`` splits (at any point) as

    rank Q = sum_a rank Dt_a + rank A,    A = [Y_a Gt_a]_a  (and the ground rows),

with ``Y_a`` a left-nullspace basis of ``Dt_a``. A point where every ``Dt_a`` keeps its
generic rank, every ``Y_a`` keeps full rank and ``A`` and ``Gt^T`` keep theirs has the
generic numbers. Each of these matrices is small in one dimension (six object columns,
or one arm), so the set where it drops rank, the common zeros of its maximal minors,
is cut out by a few random combinations ``det(P M R)`` of them (Cauchy-Binet; random
integer ``P``, ``R``). Their gcd, factored over Z, gives the hypersurface components;
the rest is solved when few variables remain (isolated configurations).

Every candidate component is then decided exactly: when its polynomial is linear in a
variable it is parametrized and the numbers are computed over its function field
(and the search recurses inside it for deeper drops); otherwise at a rational point on
it. Every reported component has an exact witness checked by a direct analysis where
one with rational coordinates exists. ``q = pi`` (``t = oo``) is checked joint by
joint in the second chart.

Example
-------
>>> from coopkin_sym import load
>>> locus = compute_locus(load("paper-case1-hard"))
>>> sorted(c.condition for c in locus.components)  # doctest: +NORMALIZE_WHITESPACE
['q1 = -pi/2, q2 = -pi/2', 'q1 = -pi/2, q2 = pi/2', 'q1 = pi/2, q2 = -pi/2',
 'q1 = pi/2, q2 = pi/2']
"""

from __future__ import annotations

import itertools
import random
import time
from dataclasses import dataclass
from fractions import Fraction
from math import atan, pi, tan

import flint
import sympy as sp

from . import kinematics
from .configuration import Configuration
from .exact import elimination as el
from .exact.sympy_bridge import poly_to_sympy
from .exactnum import angle_text
from .locus_types import Component, FloatCheck, Locus
from .mobility import Numbers, analyze, decompose
from .model import Model
from .numeric import float_numbers

# values tried, in order, for the free coordinates of a witness
_NICE = [Fraction(1, 2), Fraction(2), Fraction(-1, 3), Fraction(3), Fraction(-2),
         Fraction(1, 3), Fraction(-1, 2), Fraction(2, 3), Fraction(5, 2), Fraction(-3, 4),
         Fraction(1), Fraction(-1), Fraction(0), Fraction(7, 5), Fraction(-5, 3)]
_FLOAT_DISTANCES = (1e-6, 1e-9, 1e-12)


class LocusError(ValueError):
    """A locus that cannot be computed for this input."""


@dataclass
class _Context:
    model: Model
    config: Configuration
    ring_names: tuple[str, ...]
    kinds: dict[str, tuple[str, str]]  # ring variable -> (kind, joint or parameter)
    row_contacts: list[int]
    symbols: dict
    ring: object
    generic: Numbers
    deadline: float | None
    max_depth: int
    locus: Locus
    rng: random.Random

    def expired(self) -> bool:
        return self.deadline is not None and time.monotonic() > self.deadline


def compute_locus(system, at=None, max_depth: int = 2, timeout: float | None = None,
                  progress: bool = False) -> Locus:
    """Every family of configurations where the numbers differ from the generic ones.

    Parameters
    ----------
    system
        A :class:`~coopkin_sym.system.System` (or anything with a ``model``).
    at
        Values fixing some joints or parameters (``--at`` syntax); the other joint
        variables are free. When the model has one length parameter and it is not
        set, it is set to 1 (uniform scaling changes no number) and a note says so.
    max_depth
        How deep to recurse inside components (0: only the generic locus).
    timeout
        Seconds after which no new component is explored (the report says what was
        left out).
    progress
        Show a progress bar on standard error.
    """
    started = time.monotonic()
    model: Model = system.model
    fixed = Configuration.parse(model, at)
    notes: list[str] = []
    params = dict(fixed.parameters)
    free_params = [p for p in model.parameters if p.name not in params]
    if len(free_params) == 1 and len(model.parameters) == 1:
        params[free_params[0].name] = sp.Integer(1)
        notes.append(f"Every length is a multiple of {free_params[0].name}: uniform scaling "
                     f"changes no number, so {free_params[0].name} = 1 (equations in "
                     f"prismatic displacements are in units of {free_params[0].name}).")
    free_joints = [j.name for j in model.joints
                   if j.name not in fixed.revolute and j.name not in fixed.prismatic]
    if not free_joints:
        raise LocusError("every joint has a value: a locus needs at least one free joint")
    config = Configuration(fixed.revolute, fixed.prismatic, params, frozenset(free_joints))
    kin = kinematics.build(model, config)
    ring = kin.ring
    q_rows = [ring.clear_row(row) for row in kin.Q]
    kinds: dict[str, tuple[str, str]] = {}
    for j in model.joints:
        if j.name in config.free:
            kinds[f"t_{j.name}" if j.type == "revolute" else j.name] = (j.type, j.name)
    for p in model.parameters:
        if p.name not in params:
            kinds[p.name] = ("parameter", p.name)
    generic = decompose(q_rows, model, kin.row_contacts, ring.zctx).numbers
    locus = Locus(system=model.name, variables=list(ring.names), fixed=config.at_text(),
                  generic=generic.as_dict(), notes=notes)
    locus.notes.append(
        "Candidate sets come from random combinations of minors (Cauchy-Binet); every "
        "component reported is then decided exactly, so a candidate can only be missed, "
        "never wrongly reported, and a miss has probability below degree/2^20 per step.")
    ctx = _Context(model, config, ring.names, kinds, kin.row_contacts, kin.symbols, ring,
                   generic, None if timeout is None else started + timeout, max_depth,
                   locus, random.Random(1992))
    reporter = _Progress(progress)
    with reporter:
        _explore(ctx, q_rows, [], {}, depth=0, parent=None, reporter=reporter)
        if not ctx.expired():
            _pi_chart(ctx, reporter)
        else:
            locus.unexplored.append("q = pi (second chart): not checked, time bound reached")
    locus.seconds = round(time.monotonic() - started, 3)
    return locus


# --- candidate polynomials -------------------------------------------------------------
def _candidates(ctx: _Context, q_rows) -> dict[str, list]:
    """For each matrix whose rank drop changes a number, random combinations of its
    maximal minors (a few polynomials whose common zeros are the drop set)."""
    model, zctx = ctx.model, ctx.ring.zctx
    owners = [model.contacts[c].arm for c in ctx.row_contacts]
    gt = [row[:6] for row in q_rows]
    mats: dict[str, list] = {"HG^T": gt}
    a_rows = [gt[i] for i, o in enumerate(owners) if o is None]
    for a, arm in enumerate(model.arms):
        rows = [i for i, o in enumerate(owners) if o == a]
        off = 6 + model.joint_offset(a)
        d = [[q_rows[i][off + k] for k in range(len(arm.joints))] for i in rows]
        if not rows:
            continue
        mats[f"HD:{arm.name}"] = d
        dt = [list(col) for col in zip(*d, strict=True)]
        y, _ = el.nullspace_rref(dt, len(rows), zctx)
        if y:
            mats[f"Y:{arm.name}"] = y
        for v in y:
            acc = [zctx.constant(0)] * 6
            for vi, i in zip(v, rows, strict=True):
                if not vi.is_zero():
                    acc = [x + vi * g for x, g in zip(acc, gt[i], strict=True)]
            a_rows.append(acc)
    if a_rows:
        mats["A"] = a_rows
    out = {}
    for name, rows in mats.items():
        polys = _minor_combinations(rows, ctx)
        if polys:
            out[name] = polys
    return out


def _reduce_constant_pivots(rows):
    """Eliminate with every nonzero constant pivot: the rank falls by the number of
    pivots and the set where it drops stays the same (a constant never vanishes)."""
    rows = [list(r) for r in rows]
    while rows and rows[0]:
        spot = next(((i, j) for i, r in enumerate(rows) for j, e in enumerate(r)
                     if not e.is_zero() and e.is_constant()), None)
        if spot is None:
            break
        i, j = spot
        prow = rows.pop(i)
        p = prow[j]
        rows = [[p * x - r[j] * y for x, y in zip(r, prow, strict=True)]
                if not r[j].is_zero() else r for r in rows]
        rows = [el.primitive(r[:j] + r[j + 1:]) for r in rows]
        rows = [r for r in rows if not all(e.is_zero() for e in r)]
    return rows


def _minor_combinations(rows, ctx: _Context) -> list:
    rows = [r for r in rows if not all(e.is_zero() for e in r)]
    rows = _reduce_constant_pivots(rows)
    if not rows or not rows[0]:
        return []
    ncols = len(rows[0])
    zctx = ctx.ring.zctx
    rank = ncols - len(el.nullspace_rref(rows, ncols, zctx)[0])
    if rank == 0:
        return []
    nvars = len({n for r in rows for e in r for n in _vars_of(ctx, e)})
    if nvars > 4 and not _common_factor_on_a_line(ctx, rows, rank):
        # no hypersurface part (the lower-dimensional part is solved only in up to two
        # variables, so nothing here needs the full determinants)
        ctx.locus.unexplored.append(
            f"rank drops of codimension 2 or more of a {len(rows)} x {ncols} block in "
            f"{nvars} variables: not solved (it has no real hypersurface part)")
        return []
    count = nvars + 1 if nvars <= 2 else 3
    polys = []
    for _ in range(count):
        if ctx.expired():
            break
        left = _random_matrix(ctx, rank, len(rows)) if rank < len(rows) else None
        right = _random_matrix(ctx, ncols, rank) if rank < ncols else None
        m = rows
        if left is not None:
            m = el.matmul(left, m, zctx)
        if right is not None:
            m = el.matmul(m, right, zctx)
        det = _determinant(m)
        if not det.is_zero():
            polys.append(det)
        if left is None and right is None:
            break
    return polys


def _common_factor_on_a_line(ctx: _Context, rows, rank: int, lines: int = 3) -> bool:
    """Whether two random combinations of the maximal minors may share a factor with
    real zeros.

    Restricted to a random real line ``x = a + b s``, a common factor of the two
    determinants stays a common factor of the univariate restrictions, and a real
    hypersurface meets almost every line through the region it crosses; factors
    without real points (``1 + t^2``) stay positive on every real line. So a gcd
    without real roots on a few lines through ``[-2, 2]^n`` shows, up to that choice,
    that the drop set has no real hypersurface part. The univariate work is cheap.
    """
    lctx = flint.fmpz_mpoly_ctx.get(("s",), "degrevlex")
    (svar,) = lctx.gens()
    for _ in range(lines):
        line = [lctx.constant(ctx.rng.randint(-2, 2)) + ctx.rng.randint(1, 9) * svar
                for _ in ctx.ring_names]
        restricted = [[e.compose(*line, ctx=lctx) if not e.is_constant() else
                       lctx.constant(int(e.leading_coefficient()) if not e.is_zero()
                                     else 0) for e in r] for r in rows]
        dets = []
        for _ in range(2):
            m = restricted
            if rank < len(rows):
                m = el.matmul(_random_matrix(ctx, rank, len(rows), lctx), m, lctx)
            if rank < len(rows[0]):
                m = el.matmul(m, _random_matrix(ctx, len(rows[0]), rank, lctx), lctx)
            dets.append(_determinant(m))
        g = dets[0].gcd(dets[1])
        if g.is_constant():
            continue
        coeffs = [0] * (g.total_degree() + 1)
        for (e,), c in g.to_dict().items():
            coeffs[int(e)] = int(c)
        if sp.Poly(coeffs[::-1], sp.Symbol("s")).count_roots() > 0:
            return True
    return False


def _random_matrix(ctx: _Context, n: int, m: int, zctx=None):
    c = (zctx or ctx.ring.zctx).constant
    return [[c(ctx.rng.randint(-3, 3)) for _ in range(m)] for _ in range(n)]


_determinant = el.determinant


# --- exploring --------------------------------------------------------------------------
def _explore(ctx: _Context, q_rows, equations: list[str], point_so_far: dict,
             depth: int, parent: int | None, reporter) -> None:
    """Find the components inside the current (parametrized) set and decide them."""
    if ctx.expired():
        ctx.locus.unexplored.append(
            f"depth {depth}{' inside ' + '; '.join(equations) if equations else ''}: not "
            "explored, time bound reached")
        return
    base = decompose(q_rows, ctx.model, ctx.row_contacts, ctx.ring.zctx).numbers
    cands = _candidates(ctx, q_rows)
    factors: dict[str, tuple] = {}
    rests: list[list] = []
    for name, polys in cands.items():
        g = polys[0]
        for p in polys[1:]:
            g = g.gcd(p)
        if not g.is_constant():
            _, fs = g.factor()
            for f, _e in fs:
                f = _normalize(f)
                key = str(f)
                drops = factors.get(key, (f, set()))[1]
                drops.add(name.split(":")[0])
                factors[key] = (f, drops)
        rest = [p / g for p in polys] if not g.is_constant() else polys
        if len(rest) > 1 or (rest and not rest[0].is_constant()):
            rests.append(rest)
    ordered = sorted(factors.values(), key=lambda fd: (fd[0].total_degree(), len(fd[0]),
                                                       str(fd[0])))
    reporter.add(len(ordered))
    for f, drops in ordered:
        reporter.step(f"depth {depth}: {f}")
        if ctx.expired():
            ctx.locus.unexplored.append(f"component {f} = 0 (depth {depth}): not decided, "
                                        "time bound reached")
            continue
        _decide_factor(ctx, q_rows, f, drops, equations, point_so_far, base, depth, parent,
                       reporter)
    if rests:
        _isolated(ctx, q_rows, rests, equations, point_so_far, base, depth, parent)


def _normalize(f):
    f = f if int(f.leading_coefficient()) > 0 else -f
    c = f.content()
    return f / f.context().constant(c) if c != 1 else f


def _vars_of(ctx: _Context, f) -> list[str]:
    return [n for n, d in zip(ctx.ring_names, f.degrees(), strict=True) if d > 0]


def _drops_text(drops: set[str]) -> list[str]:
    names = {"HG^T": "HG^T", "HD": "HD", "Y": "Q", "A": "Q", "Q": "Q"}
    return sorted({names[d] for d in drops})


def _decide_factor(ctx: _Context, q_rows, f, drops, equations, point_so_far, base, depth,
                   parent, reporter) -> None:
    names = _vars_of(ctx, f)
    f_text = sp.sstr(poly_to_sympy(f, ctx.ring, ctx.symbols))
    if all(ctx.kinds[n][0] == "parameter" for n in names):
        text = f"{f_text} = 0"
        if text not in ctx.locus.parameter_conditions:
            ctx.locus.parameter_conditions.append(text)
        return
    linear = next((n for n in names if f.degrees()[ctx.ring_names.index(n)] == 1
                   and ctx.kinds[n][0] != "parameter"), None)
    if linear is None:
        _nonlinear_factor(ctx, q_rows, f, f_text, drops, equations, point_so_far, base,
                          depth, parent)
        return
    sub_rows, f0, f1 = _substitute_linear(ctx, q_rows, f, linear)
    numbers = decompose(sub_rows, ctx.model, ctx.row_contacts, ctx.ring.zctx).numbers
    if numbers == base:
        return
    eqs = equations + [f_text]
    witness = _witness_linear(ctx, sub_rows, linear, f0, f1, point_so_far, numbers)
    comp = _component(ctx, eqs, numbers, witness, "hypersurface" if depth == 0 else
                      "subvariety", drops, depth, parent,
                      "exact over the component's function field")
    if comp is None:
        return
    index = len(ctx.locus.components) - 1
    if depth < ctx.max_depth and comp is not None:
        sub_point = dict(point_so_far)
        sub_point[linear] = (f0, f1)
        _explore(ctx, sub_rows, eqs, sub_point, depth + 1, index, reporter)
    elif comp is not None and depth >= ctx.max_depth:
        ctx.locus.unexplored.append(f"inside component {index} ({comp.condition}): deeper "
                                    f"drops not explored (max depth {ctx.max_depth})")


def _substitute_linear(ctx: _Context, q_rows, f, name: str):
    """Rows of Q on ``f = 0`` with ``name = -f0/f1`` (denominators cleared row by row)."""
    k = ctx.ring_names.index(name)
    f1, f0 = _split_linear(f, k)
    out = []
    for row in q_rows:
        deg = max((e.degrees()[k] for e in row if not e.is_zero()), default=0)
        new = [_substitute(e, k, f0, f1, deg) for e in row]
        out.append(el.primitive(new))
    return out, f0, f1


def _split_linear(f, k: int):
    zctx = f.context()
    parts: dict[int, dict] = {0: {}, 1: {}}
    for mon, c in f.to_dict().items():
        e = mon[k]
        rest = tuple(0 if i == k else x for i, x in enumerate(mon))
        parts[e][rest] = c
    return zctx.from_dict(parts[1]), zctx.from_dict(parts[0])


def _substitute(p, k: int, f0, f1, deg: int):
    """``p(x_k = -f0/f1) * f1^deg``."""
    if p.is_zero():
        return p
    zctx = p.context()
    by_power: dict[int, dict] = {}
    for mon, c in p.to_dict().items():
        e = mon[k]
        rest = tuple(0 if i == k else x for i, x in enumerate(mon))
        by_power.setdefault(e, {})[rest] = c
    acc = zctx.constant(0)
    for e, terms in by_power.items():
        acc = acc + zctx.from_dict(terms) * (-f0) ** e * f1 ** (deg - e)
    return acc


def _nonlinear_factor(ctx, q_rows, f, f_text, drops, equations, point_so_far, base, depth,
                      parent) -> None:
    """A factor linear in no variable: look for real and rational points on it."""
    names = _vars_of(ctx, f)
    real = _has_real_point(ctx, f, names)
    if real is False:
        text = f"{f_text} = 0 (no real points)"
        if text not in ctx.locus.dropped:
            ctx.locus.dropped.append(text)
        return
    point = _rational_point(ctx, f, names)
    if point is None:
        ctx.locus.unexplored.append(
            f"{f_text} = 0: no rational point found, numbers not decided (depth {depth})")
        return
    values = _complete_point(ctx, point_so_far, point)
    numbers = _numbers_at_values(ctx, values)
    if numbers is None or numbers == base:
        return
    witness = _to_at(ctx, values)
    _component(ctx, equations + [f_text], numbers, witness, "hypersurface" if depth == 0
               else "subvariety", drops, depth, parent,
               "exact at a rational point of the component (generic there with high "
               "probability)")
    ctx.locus.unexplored.append(
        f"inside {f_text} = 0: deeper drops not explored (no rational parametrization)")


def _has_real_point(ctx, f, names) -> bool | None:
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
    return None


def _rational_point(ctx, f, names) -> dict[str, Fraction] | None:
    expr = poly_to_sympy(f, ctx.ring, ctx.symbols)
    syms = [ctx.symbols[n] for n in names]
    for x_idx in range(len(syms)):
        x = syms[x_idx]
        others_syms = [s for i, s in enumerate(syms) if i != x_idx]
        for values in itertools.islice(itertools.product(_NICE, repeat=len(others_syms)),
                                       60):
            sub = {s: sp.Rational(v.numerator, v.denominator)
                   for s, v in zip(others_syms, values, strict=True)}
            uni = sp.Poly(expr.subs(sub), x)
            if uni.degree() <= 0:
                continue
            roots = [r for r in sp.roots(uni, filter="Q") if r.is_Rational]
            if roots:
                point = {str(s): Fraction(int(v.p), int(v.q)) for s, v in sub.items()}
                point[str(x)] = Fraction(int(roots[0].p), int(roots[0].q))
                return {_name_of(ctx, k): v for k, v in point.items()}
    return None


def _name_of(ctx, symbol_name: str) -> str:
    for n, s in ctx.symbols.items():
        if str(s) == symbol_name:
            return n
    return symbol_name


def _isolated(ctx, q_rows, rests, equations, point_so_far, base, depth, parent) -> None:
    """Common zeros of the remaining minor combinations (codimension 2 or more)."""
    free = [n for n in ctx.ring_names if n not in point_so_far]
    for polys in rests:
        names_used = sorted({n for p in polys for n in _vars_of(ctx, p)},
                            key=ctx.ring_names.index)
        if not names_used:
            continue
        if len(names_used) > 2:
            note = (f"depth {depth}: lower-dimensional drops in {len(names_used)} variables "
                    f"({', '.join(names_used)}) not solved (up to two are solved)")
            if note not in ctx.locus.unexplored:
                ctx.locus.unexplored.append(note)
            continue
        points, irrational = _solve_small(ctx, polys, names_used)
        for text in irrational:
            note = f"real points with irrational coordinates ({text}): numbers not decided"
            if note not in ctx.locus.unexplored:
                ctx.locus.unexplored.append(note)
        for point in points:
            values = _complete_point(ctx, point_so_far, point)
            if values is None:
                continue
            numbers = _numbers_at_values(ctx, values)
            if numbers is None or numbers == base:
                continue
            eqs = equations + [sp.sstr(v.denominator * ctx.symbols[n] - v.numerator)
                               for n, v in point.items()]
            if any(c.equations == eqs for c in ctx.locus.components):
                continue
            kind = "isolated" if len(point) == len(free) else "subvariety"
            _component(ctx, eqs, numbers, _to_at(ctx, values), kind, {"Q"}, depth, parent,
                       "exact at the point")


def _solve_small(ctx, polys, names: list[str]):
    """Common zeros of ``polys`` in one or two variables: rational points, and the
    real irrational ones described by their minimal polynomials. Resultants and
    factorization over Z (python-flint), all exact."""
    zctx = ctx.ring.zctx
    x = names[0]
    if len(names) == 1:
        g = polys[0]
        for p in polys[1:]:
            g = g.gcd(p)
        xs = _roots(ctx, g, x)
        return [{x: r} for r in xs[0]], xs[1]
    y = names[1]
    combo = polys[1] if len(polys) == 2 else sum(
        (p * zctx.constant(ctx.rng.randint(1, 9)) for p in polys[1:]), zctx.constant(0))
    g = polys[0].resultant(combo, y)
    for p in polys[1:]:
        if g.is_constant():
            break
        g = g.gcd(polys[0].resultant(p, y))
    points: list[dict] = []
    irrational: list[str] = []
    if g.is_zero() or g.is_constant():
        return points, irrational
    k = ctx.ring_names.index(x)
    xs, irr = _roots(ctx, g, x)
    irrational += irr
    for x0 in xs:
        f0, f1 = zctx.constant(-x0.numerator), zctx.constant(x0.denominator)
        uni = None
        for p in polys:
            deg = p.degrees()[k]
            q = _substitute(p, k, f0, f1, deg)
            uni = q if uni is None else uni.gcd(q)
        ys, irr_y = _roots(ctx, uni, y)
        points += [{x: x0, y: y0} for y0 in ys]
        irrational += [f"{x} = {x0}, {text}" for text in irr_y]
    return points, irrational


def _roots(ctx, g, name: str):
    """Rational roots of a univariate polynomial ``g`` (in ``name``), and its
    irreducible factors of higher degree that have real roots (as text)."""
    if g.is_zero() or g.is_constant():
        return [], []
    k = ctx.ring_names.index(name)
    _, factors = g.factor()
    roots, irrational = [], []
    for f, _e in factors:
        if f.degrees()[k] == 1 and sum(f.degrees()) == 1:
            f1, f0 = _split_linear(f, k)
            roots.append(Fraction(-int(f0.leading_coefficient()) if not f0.is_zero() else 0,
                                  int(f1.leading_coefficient())))
        else:
            expr = poly_to_sympy(f, ctx.ring, ctx.symbols)
            if sp.Poly(expr, ctx.symbols[name]).count_roots() > 0:
                irrational.append(f"{sp.sstr(expr)} = 0")
    return roots, irrational


# --- points and witnesses ---------------------------------------------------------------
def _complete_point(ctx, point_so_far: dict, point: dict[str, Fraction]):
    """A full point: the given coordinates, nice values for the others, then the
    parametrized coordinates of enclosing components (``x = -f0/f1``)."""
    values = dict(point)
    for n in ctx.ring_names:
        if n not in values and n not in point_so_far:
            values[n] = _NICE[len(values) % len(_NICE)]
    for n, (f0, f1) in reversed(list(point_so_far.items())):
        args = [values.get(k, Fraction(0)) for k in ctx.ring_names]
        den = _eval(f1, args)
        if den == 0:
            return None
        values[n] = -_eval(f0, args) / den
    return values


def _eval(p, args: list[Fraction]) -> Fraction:
    total = Fraction(0)
    for mon, c in p.to_dict().items():
        term = Fraction(int(c))
        for a, e in zip(args, mon, strict=True):
            if e:
                term *= a ** int(e)
        total += term
    return total


def _witness_linear(ctx, sub_rows, name, f0, f1, point_so_far, numbers):
    """A rational point of the component where the numbers are the component's."""
    others = [n for n in ctx.ring_names if n != name and n not in point_so_far]
    tries = itertools.islice(itertools.product(_NICE, repeat=len(others)), 200)
    for values in tries:
        point = dict(zip(others, values, strict=True))
        inner = dict(point_so_far)
        inner[name] = (f0, f1)
        full = _complete_point(ctx, inner, point)
        if full is None:
            continue
        if _numbers_at_values(ctx, full) == numbers:
            return _to_at(ctx, full)
    return None


def _numbers_at_values(ctx, values: dict[str, Fraction]) -> Numbers | None:
    at = _to_at(ctx, values)
    if at is None:
        return None
    return analyze(ctx.model, Configuration.parse(ctx.model, at)).numbers


def _to_at(ctx, values: dict[str, Fraction]) -> dict[str, str] | None:
    """A full point in ``--at`` syntax (joints set by the caller and fixed values
    included)."""
    out: dict[str, str] = {}
    config = ctx.config
    for j in ctx.model.joints:
        if j.name in config.revolute:
            out[j.name] = angle_text(*config.revolute[j.name])
        elif j.name in config.prismatic:
            out[j.name] = sp.sstr(config.prismatic[j.name])
    for n, (kind, name) in ctx.kinds.items():
        v = values.get(n)
        if v is None:
            return None
        if kind == "revolute":
            t = sp.Rational(v.numerator, v.denominator)
            out[name] = angle_text((1 - t**2) / (1 + t**2), 2 * t / (1 + t**2))
        else:
            out[name] = f"{v.numerator}" if v.denominator == 1 else f"{v.numerator}/" \
                f"{v.denominator}"
    for p, v in config.parameters.items():
        out[p] = sp.sstr(v)
    return out


# --- components -------------------------------------------------------------------------
def _component(ctx, equations, numbers: Numbers, witness, kind, drops, depth, parent,
               decided, condition: str | None = None) -> Component | None:
    if any(sorted(c.equations) == sorted(equations) for c in ctx.locus.components):
        return None
    generic = ctx.generic.as_dict()
    here = numbers.as_dict()
    changes = {k: (generic[k], here[k]) for k in generic if generic[k] != here[k]}
    comp = Component(equations=equations, numbers=here, witness=witness, real=True,
                     kind=kind, condition=condition or _condition(ctx, equations),
                     drops=_drops_text(
                         drops), changes=changes, decided=decided, depth=depth,
                     parent=parent)
    if witness is not None:
        analysis = analyze(ctx.model, Configuration.parse(ctx.model, witness))
        comp.witness_checked = analysis.numbers == numbers
        comp.meaning = _meaning(analysis, changes)
        comp.float_checks = _float_checks(ctx, witness, analysis)
    ctx.locus.components.append(comp)
    return comp


def _meaning(analysis, changes) -> list[str]:
    from .interpret import sentences

    keys = {k for k in changes}
    return [s for s in sentences(analysis) if s.split(" ")[0] in keys]


def _condition(ctx, equations: list[str]) -> str:
    parts = []
    for eq in equations:
        parts.append(_read_equation(ctx, eq))
    return ", ".join(parts)


def _read_equation(ctx, eq: str) -> str:
    syms = {str(s): s for s in ctx.symbols.values()}
    expr = sp.sympify(eq, locals=syms)
    free = sorted(expr.free_symbols, key=str)
    joint = {s: ctx.kinds[_name_of(ctx, str(s))] for s in free}
    rev = [s for s in free if joint[s][0] == "revolute"]
    if len(free) == 1 and rev:
        (s,) = rev
        poly = sp.Poly(expr, s)
        if poly.degree() == 1:
            t = -poly.coeff_monomial(1) / poly.coeff_monomial(s)
            return f"{joint[s][1]} = {angle_text((1 - t**2) / (1 + t**2), 2 * t / (1 + t**2))}"
    if len(free) == 2 and len(rev) == 2:
        a, b = rev
        na, nb = joint[a][1], joint[b][1]
        for candidate, text in ((a - b, f"{na} = {nb}"), (a + b, f"{na} = -{nb}"),
                                (a * b + 1, f"{na} = {nb} + pi (mod 2*pi)"),
                                (a * b - 1, f"{na} + {nb} = pi (mod 2*pi)")):
            if sp.expand(expr - candidate) == 0 or sp.expand(expr + candidate) == 0:
                return text
    if len(free) == 1 and joint[free[0]][0] == "prismatic":
        sol = sp.solve(expr, free[0])
        if len(sol) == 1 and sol[0].is_Rational:
            return f"{joint[free[0]][1]} = {sol[0]}"
    return f"{eq} = 0"


def _float_checks(ctx, witness: dict[str, str], analysis) -> list[FloatCheck]:
    """Float ranks at the witness, at points near it, and with lengths rescaled."""
    checks = []
    scale = ", ".join(f"{p}={v}" for p, v in ctx.config.parameters.items()) or "-"
    checks.append(FloatCheck(0.0, scale, witness, analysis.numbers.as_dict(),
                             float_numbers(analysis)))
    joint = next((name for kind, name in ctx.kinds.values() if kind == "revolute"), None)
    for distance in _FLOAT_DISTANCES:
        if joint is None:
            break
        point = dict(witness)
        point[joint] = _nudged_angle(point[joint], distance)
        near = analyze(ctx.model, Configuration.parse(ctx.model, point))
        checks.append(FloatCheck(distance, scale, point, near.numbers.as_dict(),
                                 float_numbers(near)))
    for p in ctx.model.parameters:
        for value in ("1/1000", "1000"):
            for distance in (0.0, *_FLOAT_DISTANCES):
                point = dict(witness)
                point[p.name] = value
                if distance and joint is not None:
                    point[joint] = _nudged_angle(point[joint], distance)
                elif distance:
                    continue
                a = analyze(ctx.model, Configuration.parse(ctx.model, point))
                checks.append(FloatCheck(distance, f"{p.name}={value}", point,
                                         a.numbers.as_dict(), float_numbers(a)))
    return checks


def _nudged_angle(text: str, distance: float) -> str:
    """An exact angle about ``distance`` radians above ``text`` (a rational tangent
    half-angle; the float only chooses it)."""
    from .exactnum import parse_angle

    c, s = parse_angle(text, "witness")
    q = float(sp.atan2(s, c)) + distance  # float-ok: choosing a nearby exact angle
    t = Fraction(tan(q / 2))  # float-ok: the binary float is itself an exact rational
    if abs(2 * atan(float(t)) - q) > pi:  # float-ok
        t = -t
    return f"2*atan({t.numerator}/{t.denominator})"


def _pi_chart(ctx: _Context, reporter) -> None:
    """Joints at q = pi, where t = tan(q/2) is infinite: decided in the second chart."""
    rev = [name for kind, name in ctx.kinds.values() if kind == "revolute"]
    base = ctx.generic
    for name in rev:
        if ctx.expired():
            ctx.locus.unexplored.append("q = pi for the remaining joints: time bound")
            return
        reporter.step(f"{name} = pi")
        revolute = dict(ctx.config.revolute)
        revolute[name] = (sp.Integer(-1), sp.Integer(0))
        free = ctx.config.free - {name}
        config = Configuration(revolute, ctx.config.prismatic, ctx.config.parameters, free)
        kin = kinematics.build(ctx.model, config)
        rows = [kin.ring.clear_row(r) for r in kin.Q]
        numbers = decompose(rows, ctx.model, kin.row_contacts, kin.ring.zctx).numbers
        if numbers == base:
            continue
        witness = None
        for values in itertools.islice(itertools.product(
                _NICE, repeat=len(ctx.ring_names) - 1), 100):
            names = [n for n in ctx.ring_names if n != f"t_{name}"]
            point = dict(zip(names, values, strict=True))
            at = _to_at(ctx, {**point, f"t_{name}": Fraction(0)})
            if at is None:
                continue
            at[name] = "pi"
            if analyze(ctx.model, Configuration.parse(ctx.model, at)).numbers == numbers:
                witness = at
                break
        _component(ctx, [f"s_{name}"], numbers, witness, "chart", {"Q"}, 0, None,
                   "exact over the function field of the other variables",
                   condition=f"{name} = pi")
        ctx.locus.notes.append(f"s_{name} = cot({name}/2): the component s_{name} = 0 is "
                               f"{name} = pi, outside the chart of t_{name}.")


class _Progress:
    """A rich progress bar on standard error, or nothing."""

    def __init__(self, enabled: bool):
        self.enabled = enabled
        self._progress = None
        self._task = None

    def __enter__(self):
        if self.enabled:
            from rich.progress import Progress

            self._progress = Progress(transient=True)
            self._progress.__enter__()
            self._task = self._progress.add_task("locus", total=0)
        return self

    def __exit__(self, *exc):
        if self._progress is not None:
            self._progress.__exit__(*exc)

    def add(self, n: int) -> None:
        if self._progress is not None:
            total = self._progress.tasks[0].total or 0
            self._progress.update(self._task, total=total + n)

    def step(self, text: str) -> None:
        if self._progress is not None:
            self._progress.update(self._task, advance=1, description=text[:60])


__all__ = ["LocusError", "compute_locus"]
