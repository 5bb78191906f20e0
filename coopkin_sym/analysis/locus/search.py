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
(and the search recurses inside it for deeper drops); otherwise by ranks modulo its
irreducible polynomial (:mod:`coopkin_sym.exact.quotient`: over the function field of a
curved hypersurface, or over a number field ``Q(alpha)`` for points with irrational
coordinates, every conjugate point at once). Points of two variables come from
resultants, a gcd over ``Q(alpha)`` and, when one coordinate does not separate them,
the coordinate ``y + c x``; families of codimension 2 in three or four variables are
solved for two of them over the field of the others. Every reported component gets
an exact witness checked by a direct analysis: rational where one exists, else a real
algebraic point (radicals or ``CRootOf``). ``q = pi`` (``t = oo``) is checked joint
by joint in the second chart.

This module runs the search and decides the components; the polynomial systems are
solved in :mod:`coopkin_sym.analysis.locus.algebra`, witnesses and float checks are made in
:mod:`coopkin_sym.analysis.locus.witness`, and the results are the plain data of
:mod:`coopkin_sym.analysis.locus.types`.

Example
-------
>>> from coopkin_sym import load
>>> locus = compute_locus(load("paper-case1-hard"))
>>> for c in locus.components:
...     print(c.condition)
q1 = -pi/2, q2 = -pi/2
q1 = -pi/2, q2 = pi/2
q1 = pi/2, q2 = -pi/2
q1 = pi/2, q2 = pi/2
q1 = -5*pi/6, q2 = 5*pi/6 or q1 = -pi/6, q2 = pi/6
"""

from __future__ import annotations

import dataclasses
import itertools
import random
import time
from fractions import Fraction
from math import comb

import flint
import sympy as sp

from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.locus.algebra import (
    has_real_point,
    linear_equation,
    linearly_disjoint,
    normalize,
    poly_text,
    rational_point,
    solve_small,
    substitute_values,
    vars_of,
)
from coopkin_sym.analysis.locus.context import Place, Progress, SearchContext
from coopkin_sym.analysis.locus.remarks import Remark, add_once
from coopkin_sym.analysis.locus.types import Component, Locus, canonical_order, cut_short
from coopkin_sym.analysis.locus.witness import (
    algebraic_condition,
    algebraic_witness_on,
    attach_algebraic_witness,
    attach_two_root_witness,
    attach_witness,
    complete_point,
    family_witness,
    numbers_at_values,
    to_at,
    witness_linear,
)
from coopkin_sym.analysis.mobility import decompose, numbers_modulo
from coopkin_sym.analysis.numbers import Numbers
from coopkin_sym.errors import LocusError, TimeLimitReached
from coopkin_sym.exact import deadline
from coopkin_sym.exact import elimination as el
from coopkin_sym.exact.angles import COTANGENT_PREFIX, cotangent_name, joint_of, tangent_name
from coopkin_sym.exact.factoring import factor
from coopkin_sym.exact.matrix import PolyMatrix
from coopkin_sym.exact.polynomial import NamedPolynomial
from coopkin_sym.exact.quotient import (
    Quotient,
    Tower,
    coefficients_in,
    gcd_modulo,
    smallest_fraction,
)
from coopkin_sym.exact.substitution import split_linear, substitute, substitute_rows
from coopkin_sym.exact.sympy_bridge import poly_to_sympy
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model, model_of


def compute_locus(system, at=None, max_depth: int = 2, timeout: float | None = None,
                  progress: bool = False, free=None, pi_size: int | None = None) -> Locus:
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
        Report the steps of the search and the share done (see
        :func:`coopkin_sym.exact.bounded.report`; the caller's display shows them, as
        ``System.locus(progress=True)`` and ``coopkin locus`` do).
    free
        The joints to keep free (names); the others not set in ``at`` stay at home
        (q = 0, d = 0). Default: every joint not set in ``at``.
    pi_size
        Sets of joints at q = pi (outside the t chart) are searched inside up to this
        many joints at once; larger sets get their numbers decided and a note. Default:
        every set for up to four free revolute joints, two for up to six, one for up
        to eight, else none (the numbers of every set are always decided).
    """
    if timeout is not None and not deadline.active("locus"):  # checked inside eliminations
        with deadline.time_limit(timeout, "locus") as bound:
            try:
                return compute_locus(system, at, max_depth, timeout, progress, free, pi_size)
            except TimeLimitReached as exc:
                return cut_short(bound, exc)
    started = time.monotonic()
    model: Model = model_of(system).in_base_frame()  # numbers only
    fixed = Configuration.parse(model, at)
    notes: list[Remark | str] = []
    params = dict(fixed.parameters)
    free_params = [p for p in model.parameters if p.name not in params]
    if len(free_params) == 1 and len(model.parameters) == 1:
        params[free_params[0].name] = sp.Integer(1)
        notes.append(Remark.of("uniform_scaling", parameter=free_params[0].name))
    free_joints = [j.name for j in model.joints
                   if j.name not in fixed.revolute and j.name not in fixed.prismatic]
    if free is not None:
        chosen = Configuration.parse(model, None, free).free
        free_joints = [j for j in free_joints if j in chosen]
    revolute, prismatic = dict(fixed.revolute), dict(fixed.prismatic)
    for j in model.joints:  # joints neither set nor free stay at home
        if j.name not in free_joints and j.name not in revolute | prismatic:
            if j.type == "revolute":
                revolute[j.name] = (sp.Integer(1), sp.Integer(0))
            else:
                prismatic[j.name] = sp.Integer(0)
    if not free_joints:
        raise LocusError("every joint has a value: a locus needs at least one free joint")
    config = Configuration(revolute, prismatic, params, frozenset(free_joints))
    locus = Locus(system=model.name, variables=[], fixed=config.at_text(), generic={},
                  notes=notes, locked_joints=[j for j in model.joint_names
                                              if j in model.locked])
    chart, q_rows = _chart(model, config)
    generic = decompose(q_rows, model, chart["row_contacts"], chart["ring"].zctx).numbers
    ctx = SearchContext(model=model, generic=generic, max_depth=max_depth, locus=locus,
                        rng=random.Random(1992), readings={}, chains={}, owners={},
                        deadline=None if timeout is None else started + timeout,
                        reporter=Progress(progress), **chart)
    locus.variables = list(ctx.ring_names)
    locus.generic = ctx.generic.as_dict()
    deadline.keep(locus)  # from here on, a time bound returns what was found
    if model.snapped:
        locus.notes.append(Remark.of("snapped_model", count=len(model.snapped),
                                     largest=max(x.error for x in model.snapped)))
    locus.notes.append(Remark.of("candidates_probabilistic"))
    size = pi_size if pi_size is not None else _default_pi_size(ctx)
    with ctx.reporter, ctx.reporter.parts(2):
        # the progress: half for the t chart, half for the slices at q = pi (shared
        # by the slices searched inside; the others only get their numbers decided)
        ctx.reporter.step("depth 0: the numbers and their candidates")
        _explore(ctx, Place(rows=q_rows, equations=[], point={}, depth=0))
        ctx.reporter.step("q = pi")
        # a slice searched inside weighs more than one whose numbers alone are decided
        weights = [PI_SEARCH_WEIGHT if size is None or len(s) <= size else 1
                   for s in _pi_subsets(_revolute(ctx))]
        with ctx.reporter.parts(len(weights), weights):
            _pi_slices(ctx, size)
        _settle_realness(ctx)
        canonical_order(locus)
    if any(c.algebraic_witness for c in locus.components):
        locus.notes.append(Remark.of("irrational_witness_floats"))
    if model.passive_joints and not model.locked:
        # where the passive-joint numbers change: the locus of the locked system
        left = None if timeout is None else max(0.0, timeout - (time.monotonic() - started))
        try:
            locus.locked = compute_locus(model.with_actuators_locked(), at, max_depth,
                                         left, progress, free, pi_size)
        finally:  # cut inside it: what is kept is this locus, not the locked one
            deadline.keep(locus)
    locus.seconds = round(time.monotonic() - started, 3)
    return locus


#: The share of the progress bar a slice at q = pi searched inside gets, against 1 for
#: a slice whose numbers alone are decided.
PI_SEARCH_WEIGHT = 20


def _chart(model: Model, config: Configuration) -> tuple[dict, list]:
    """The fields of a :class:`SearchContext` that belong to the chart of ``config``
    (its free joints and parameters are the variables), and the cleared rows of Q
    there."""
    kin = kinematics.build(model, config)
    ring = kin.ring
    q_rows = [ring.clear_row(row) for row in kin.Q]
    kinds: dict[str, tuple[str, str]] = {}
    for j in model.joints:
        if j.name in config.free:
            kinds[tangent_name(j.name) if j.type == "revolute" else j.name] = (j.type, j.name)
    for p in model.parameters:
        if p.name not in config.parameters:
            kinds[p.name] = ("parameter", p.name)
    chart = {"config": config, "ring_names": ring.names, "kinds": kinds,
             "row_contacts": kin.row_contacts, "symbols": kin.symbols, "ring": ring,
             "rows0": q_rows, "kin": kin}
    return chart, q_rows


# --- candidate polynomials -------------------------------------------------------------
def _candidates(ctx: SearchContext, q_rows) -> dict[str, list]:
    """For each matrix whose rank drop changes a number, random combinations of its
    maximal minors (a few polynomials whose common zeros are the drop set); under
    ``content:<matrix>`` the polynomials rows were divided by (each one's zero set is a
    candidate on its own)."""
    zctx = ctx.ring.zctx
    owners = [ctx.model.contacts[c].arm for c in ctx.row_contacts]
    dim = ctx.model.object_dim
    gt = [row[:dim] for row in q_rows]
    mats: dict[str, list] = {"HG^T": gt}
    a_rows = [gt[i] for i, o in enumerate(owners) if o is None]
    for arm, rows, d in _arm_blocks(ctx, q_rows):
        mats[f"HD:{arm.name}"] = d
        dt = [list(col) for col in zip(*d, strict=True)]
        y, _ = PolyMatrix(dt, len(rows), context=zctx).nullspace_rref()
        if y:
            mats[f"Y:{arm.name}"] = y
        for v in y:
            acc = [zctx.constant(0)] * dim
            for vi, i in zip(v, rows, strict=True):
                if not vi.is_zero():
                    acc = [x + vi * g for x, g in zip(acc, gt[i], strict=True)]
            a_rows.append(acc)
    if a_rows:
        mats["A"] = a_rows
    out = {}
    for name, rows in mats.items():
        contents: list = []
        deep: list = []
        polys = _minor_combinations(rows, ctx, contents, deep, name)
        if contents:
            out[f"content:{name}"] = contents
        if deep:
            out[f"split:{name}"] = deep
        if polys:
            out[name] = polys
    return out


def _arm_blocks(ctx: SearchContext, q_rows):
    """For each arm with contact rows: the arm, the indices of its rows of ``Q`` and
    its block ``H D`` (those rows, its joint columns)."""
    model = ctx.model
    owners = [model.contacts[c].arm for c in ctx.row_contacts]
    for a, arm in enumerate(model.arms):
        rows = [i for i, o in enumerate(owners) if o == a]
        if rows:
            off = model.object_dim + model.joint_offset(a)
            yield arm, rows, [q_rows[i][off:off + len(arm.joints)] for i in rows]


def _positive(e) -> bool:
    """Whether ``e`` is positive at every real point because every monomial has even
    exponents and a positive coefficient, and one is constant (``1 + t^2``, the
    denominators of the kinematics and their products)."""
    terms = e.to_dict()
    return (not e.is_zero() and any(not any(m) for m in terms)
            and all(c > 0 and all(x % 2 == 0 for x in m) for m, c in terms.items()))


def _reduce_constant_pivots(rows, contents: list):
    """Eliminate with every pivot that vanishes at no real point (a nonzero constant,
    or a polynomial that :func:`_positive` shows positive): the rank falls by the
    number of pivots at every real point and the set where it drops stays the same.

    Each row is then divided by the gcd of its entries; where that gcd vanishes the
    rank may drop, so every such non-constant gcd is appended to ``contents``: its
    zero set is a candidate to decide like the others."""
    rows = [list(r) for r in rows]
    while rows and rows[0]:
        spot = next(((i, j) for i, r in enumerate(rows) for j, e in enumerate(r)
                     if not e.is_zero() and e.is_constant()), None)
        if spot is None:
            spots = [(len(e), i, j) for i, r in enumerate(rows) for j, e in enumerate(r)
                     if not e.is_zero() and _positive(e)]
            spot = min(spots)[1:] if spots else None
        if spot is None:
            break
        i, j = spot
        prow = rows.pop(i)
        p = prow[j]
        rows = [[p * x - r[j] * y for x, y in zip(r, prow, strict=True)]
                if not r[j].is_zero() else r for r in rows]
        rows = [_without_content(r[:j] + r[j + 1:], contents) for r in rows]
        rows = [r for r in rows if not all(e.is_zero() for e in r)]
    return rows


def _without_content(row, contents: list):
    """``row`` divided by the gcd of its entries; a non-constant gcd goes to
    ``contents`` (dividing by it must not hide the rank drop at its zeros)."""
    g = None
    for e in row:
        if not e.is_zero():
            g = e if g is None else g.gcd(e)
            if g.is_constant():
                return row
    if g is None:
        return row
    if not _positive(g):        # a positive divisor hides no real drop
        contents.append(g)
    return [e / g for e in row]


def _minor_combinations(rows, ctx: SearchContext, contents: list, deep: list | None = None,
                        name: str = "") -> list:
    """Random combinations of the maximal minors of ``rows`` (their common zeros are the
    set where the rank drops), after a reduction whose divisors go to ``contents``.

    When the drop set has no hypersurface part and more than four variables, no
    combination is returned; one maximal minor goes to ``deep`` instead (see
    :func:`_splitting_minor`)."""
    rows = [r for r in rows if not all(e.is_zero() for e in r)]
    rows = _reduce_constant_pivots(rows, contents)
    if not rows or not rows[0]:
        return []
    ncols = len(rows[0])
    zctx = ctx.ring.zctx
    rank = ncols - len(PolyMatrix(rows, ncols, context=zctx).nullspace_rref()[0])
    if rank == 0:
        return []
    nvars = len({n for r in rows for e in r for n in vars_of(ctx, e)})
    if nvars > 4:
        # the part of codimension 2 or more is solved here only in up to four variables;
        # it lies in the zero set of any one maximal minor, whose factors are then
        # searched inside one by one
        minor = None
        if deep is not None and ctx.splits < _MAX_SPLITS:
            minor = _splitting_minor(rows, rank, zctx)
            if minor is not None:
                deep.append(minor)
        if not _common_factor_on_a_line(ctx, rows, rank):
            if minor is None:
                splits = ctx.splits >= _MAX_SPLITS
                _note(ctx, "block_not_solved", rows=len(rows), columns=ncols, block=name,
                      variables=nvars, limit="splits" if splits else "minors",
                      bound=_MAX_SPLITS if splits else (_MAX_SPLIT_RANK, _MAX_SPLIT_MINORS))
            return []
    count = nvars + 1 if nvars <= 2 else 3
    polys: list = []
    tries = 0
    while len(polys) < count and tries < count + _REDRAWS:
        # a zero combination is bad luck (the rank says some maximal minor is nonzero):
        # draw again
        tries += 1
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
    if not polys and not ctx.expired():
        _note(ctx, "combinations_vanish", block=name, tries=tries)
    return polys


# how many more random combinations are drawn when some vanish identically
_REDRAWS = 12


# how many zero sets of single minors are searched inside one another
_MAX_SPLITS = 4
# the most maximal minors listed to choose a splitting one, and their largest size
_MAX_SPLIT_MINORS = 60
_MAX_SPLIT_RANK = 3


def _splitting_minor(rows, rank: int, zctx):
    """A nonzero maximal minor of ``rows`` (rank ``rank``) whose zero set is simplest:
    fewest factors linear in no variable, then lowest degree of its square-free part
    (factors positive at every real point left out). Its real zero set contains the
    whole real drop set. None when there are too many minors."""
    nrows, ncols = len(rows), len(rows[0])
    if rank > _MAX_SPLIT_RANK or comb(nrows, rank) * comb(ncols, rank) > _MAX_SPLIT_MINORS:
        return None
    best, best_key = None, None
    for ri in itertools.combinations(range(nrows), rank):
        for ci in itertools.combinations(range(ncols), rank):
            det = _determinant([[rows[i][j] for j in ci] for i in ri])
            if det.is_zero():
                continue
            _, fs = factor(det)
            square_free = zctx.constant(1)
            curved = 0
            for f, _e in fs:
                if _positive(f):        # no real zeros: no part of the drop set
                    continue
                square_free *= f
                if not any(d == 1 for d in f.degrees()):
                    curved += 1
            key = (curved, square_free.total_degree(), len(fs), str(square_free))
            if best_key is None or key < best_key:
                best, best_key = square_free, key
    return best


def _common_factor_on_a_line(ctx: SearchContext, rows, rank: int, lines: int = 3) -> bool:
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


def _random_matrix(ctx: SearchContext, n: int, m: int, zctx=None):
    """An ``n x m`` matrix of small random integers (small, so that the combinations
    of minors stay cheap to factor; one that vanishes identically is drawn again)."""
    c = (zctx or ctx.ring.zctx).constant
    return [[c(ctx.rng.randint(-3, 3)) for _ in range(m)] for _ in range(n)]


_determinant = el.determinant


# --- exploring --------------------------------------------------------------------------
def _explore(ctx: SearchContext, place: Place) -> None:
    """Find the components inside the current (parametrized) set and decide them.

    ``place.point`` maps each parametrized variable to ``(f0, f1)`` (it equals
    ``-f0/f1``); ``place.charts`` are the denominators ``f1``, in the current variables:
    the rows are valid only where none of them vanishes."""
    if ctx.expired():
        ctx.locus.unexplored.append(Remark.of("time_depth", depth=place.depth,
                                              equations=place.equations))
        return
    place = place.inside(base=decompose(place.rows, ctx.model, ctx.row_contacts,
                                        ctx.ring.zctx).numbers)
    ctx.deferred.append([])
    cands = _candidates(ctx, place.rows)
    factors: dict[str, tuple] = {}
    splitting: set[str] = set()  # factors of single minors (see _splitting_minor)
    rests: list[list] = []
    def add_factors(g, matrix: str, split: bool = False) -> None:
        _, fs = factor(g)
        for f, _e in fs:
            f = normalize(f)
            key = str(f)
            drops = factors.get(key, (f, set()))[1]
            drops.add(matrix)
            factors[key] = (f, drops)
            if split:
                splitting.add(key)

    for name, polys in cands.items():
        if name.startswith(("content:", "split:")):
            for c in polys:
                add_factors(c, name.split(":")[1], name.startswith("split:"))
            continue
        g = polys[0]
        for p in polys[1:]:
            g = g.gcd(p)
        if not g.is_constant():
            add_factors(g, name.split(":")[0])
        rest = [p / g for p in polys] if not g.is_constant() else polys
        if f"split:{name}" in cands and len({n for p in rest for n in vars_of(ctx, p)}) > 4:
            continue  # inside the factors of its splitting minor, searched one by one
        if len(rest) > 1 or (rest and not rest[0].is_constant()):
            rests.append(rest)
    ordered = sorted(factors.values(), key=lambda fd: (fd[0].total_degree(), len(fd[0]),
                                                       str(fd[0])))
    # one part of the progress per factor, one for the isolated points and the
    # searches deferred to the end of this level
    with ctx.reporter.parts(len(ordered) + 1):
        for f, drops in ordered:
            ctx.reporter.step(f"{_where(ctx)}depth {place.depth}: {f}")
            if ctx.expired():
                ctx.locus.unexplored.append(Remark.of("time_component", polynomial=str(f),
                                                      depth=place.depth))
                continue
            if any(not c.gcd(f).is_constant() for c in place.charts):
                # the image of f = 0 lies where a parametrization's denominator
                # vanishes: those points are searched from the enclosing variables
                # (_chart_points)
                continue
            split = str(f) in splitting
            _decide_factor(ctx, place, f, drops, split=split)
        ctx.reporter.step(f"{_where(ctx)}depth {place.depth}: isolated points")
        if rests:
            _isolated(ctx, place, rests)
        for search in ctx.deferred.pop():
            search()


def _where(ctx: SearchContext) -> str:
    """The slice at q = pi the search is in, for the progress bar ("" in the t chart)."""
    return "".join(f"{n} = pi, " for n in sorted(ctx.pi))


def _note(ctx: SearchContext, kind: str, **facts) -> None:
    """Say once in the report what was not explored (a :class:`Remark` of ``kind``)."""
    add_once(ctx.locus.unexplored, Remark.of(kind, **facts))


def _drops_text(drops: set[str]) -> list[str]:
    names = {"HG^T": "HG^T", "HD": "HD", "Y": "Q", "A": "Q", "Q": "Q"}
    return sorted({names[d] for d in drops})


def _decide_factor(ctx: SearchContext, place: Place, f, drops, split: bool = False) -> None:
    """Decide the candidate ``f = 0``: a component when its numbers differ from
    ``place.base``, else searched inside (``split``: a factor of a single minor, whose zero
    set holds a drop set of codimension 2 or more)."""
    names = vars_of(ctx, f)
    f_text = poly_text(ctx, f)
    if all(ctx.kinds[n][0] == "parameter" for n in names):
        add_once(ctx.locus.parameter_conditions,
                 Remark.of("parameter_condition", polynomial=f_text))
        return
    linear = next((n for n in names if f.degrees()[ctx.ring_names.index(n)] == 1
                   and ctx.kinds[n][0] != "parameter"), None)
    if linear is None:
        _nonlinear_factor(ctx, place, f, f_text, drops)
        return
    sub_rows, f0, f1 = _substitute_linear(ctx, place.rows, f, linear)
    k = ctx.ring_names.index(linear)
    sub_charts = [substitute(c, k, f0, f1, c.degrees()[k]) for c in place.charts]
    if any(c.is_zero() for c in sub_charts):
        ctx.locus.unexplored.append(Remark.of("outside_parametrization", polynomial=f_text,
                                              equations=place.equations))
        return
    sub_charts = tuple(c for c in [*sub_charts, f1] if not c.is_constant())
    eqs = place.equations + [f_text]
    _chart_points(ctx, place.inside(equations=eqs), f0, f1)
    numbers = decompose(sub_rows, ctx.model, ctx.row_contacts, ctx.ring.zctx).numbers
    sub_point = dict(place.point)
    sub_point[linear] = (f0, f1)
    inside = place.inside(rows=sub_rows, equations=eqs, point=sub_point, charts=sub_charts)
    if numbers == place.base:
        _inside_candidate(ctx, inside, split=split)
        return
    wider = _wider_component(ctx, sub_point, numbers)
    if wider is not None:  # already found, in a chart with fewer joints at pi
        _inside_candidate(ctx, inside.inside(depth=wider.depth + 1,
                                             parent=ctx.locus.components.index(wider)))
        return
    witness = witness_linear(ctx, sub_rows, linear, f0, f1, place.point, numbers)
    left = [n for n in ctx.ring_names if n not in sub_point]
    kind = ("isolated" if not left else "hypersurface" if len(eqs) == 1 else "subvariety")
    comp = _component(ctx, place, eqs, numbers, kind, drops,
                      Remark.of("decided_function_field"), witness=witness,
                      chain=sub_point)
    _go_deeper(ctx, comp, inside)


def _chart_points(ctx: SearchContext, place: Place, f0, f1) -> None:
    """The part of ``f1 x + f0 = 0`` that ``x = -f0/f1`` does not reach: ``f0 = f1 = 0``
    (codimension 2 when ``f1`` is not constant), searched as a set of its own."""
    if f1.is_constant():
        return
    _isolated(ctx, place, [[f0, f1]])


def _inside_candidate(ctx: SearchContext, place: Place, split: bool = False) -> None:
    """A candidate set whose numbers are the enclosing ones. Some candidates come from
    conditions that are sufficient, not necessary (a left nullspace basis losing rank, a
    row divisor), or hold a drop set of higher codimension (``split``: a factor of a
    single minor): the enclosing search does not see drops deeper inside them, so they
    are searched too, without being reported."""
    if ctx.expired():
        return
    if place.point is not None and all(n in place.point for n in ctx.ring_names):
        return  # a point: nothing lies deeper inside it
    reason, bound = None, None
    if split:
        if place.rows is not None and ctx.splits >= _MAX_SPLITS:
            reason, bound = "nested_splits", _MAX_SPLITS
    elif place.rows is not None and ctx.hidden >= _HIDDEN_DEPTH:
        reason, bound = "hidden_depth", _HIDDEN_DEPTH
    if reason is None and place.depth > ctx.max_depth:
        reason, bound = "max_depth", ctx.max_depth
    if reason is not None or place.rows is None:
        _note(ctx, "enclosing_not_searched", equations=place.equations,
              reason=reason or "no_parametrization", bound=bound)
        return
    def search() -> None:
        if split:
            ctx.splits += 1
        else:
            ctx.hidden += 1
        try:
            _explore(ctx, place)
        finally:
            if split:
                ctx.splits -= 1
            else:
                ctx.hidden -= 1

    _after_enclosing(ctx, search)


def _after_enclosing(ctx: SearchContext, search) -> None:
    """Run ``search`` after the components of the enclosing level are found, or now when
    that level is already done (a search started by a deferred one)."""
    if ctx.deferred:
        ctx.deferred[-1].append(search)
    else:
        search()


# how many candidate sets with the enclosing numbers are searched inside one another
_HIDDEN_DEPTH = 2


def _substitute_linear(ctx: SearchContext, q_rows, f, name: str):
    """Rows of Q on ``f = 0`` with ``name = -f0/f1`` (denominators cleared row by row)."""
    k = ctx.ring_names.index(name)
    f1, f0 = split_linear(f, k)
    return substitute_rows(q_rows, k, f0, f1), f0, f1


# the largest curved family whose numbers are decided modulo its polynomial
_MAX_CURVED_TERMS = 3000


def _nonlinear_factor(ctx: SearchContext, place: Place, f, f_text, drops) -> None:
    """A factor linear in no variable: its numbers over its function field (rank modulo
    ``f``), a witness on it (rational, else a real algebraic point)."""
    names = vars_of(ctx, f)
    if len(f) > _MAX_CURVED_TERMS:
        _note(ctx, "family_too_large", terms=len(f), degree=f.total_degree(),
              variables=names, equations=place.equations, bound=_MAX_CURVED_TERMS)
        return
    real = has_real_point(ctx, f, names)
    if real is False:
        add_once(ctx.locus.dropped, Remark.of("no_real_points", polynomial=f_text))
        return
    k = min((ctx.ring_names.index(n) for n in names if ctx.kinds[n][0] != "parameter"),
            key=lambda i: (f.degrees()[i], i))
    numbers = numbers_modulo(place.rows, ctx.model, ctx.row_contacts, Quotient(f, k))
    if numbers == place.base:
        if len([n for n in ctx.ring_names if n not in place.point]) <= 1:
            return
        on_f = place.inside(equations=place.equations + [f_text], charts=())
        if ctx.hidden >= _HIDDEN_DEPTH or place.depth > 0 or ctx.expired():
            _inside_candidate(ctx, on_f.inside(rows=None, point=None))
        else:   # after the components of the enclosing level, like other candidates
            _after_enclosing(ctx, lambda: _inside_curved(ctx, on_f, f, k, None))
        return
    comp = _component(ctx, place, place.equations + [f_text], numbers,
                      "hypersurface" if not _beyond_chart(ctx, place.equations)
                      else "subvariety", drops,
                      Remark.of("decided_modulo_family"), real=real is True, within=place.point,
                      generic_point=(place.point, Quotient(f, k)))
    if comp is None:
        return
    point = rational_point(ctx, f, names)
    if point is not None:
        values = complete_point(ctx, place.point, point)
        if values is not None and numbers_at_values(ctx, values) == numbers:
            attach_witness(ctx, comp, to_at(ctx, values), numbers)
    if comp.witness is None:
        algebraic_witness_on(ctx, comp, f, k, place.point, numbers)
    if place.depth > 0 or place.depth >= ctx.max_depth or ctx.expired():
        _go_deeper(ctx, comp, place.inside(rows=None, point=None, charts=()),
                   "no_parametrization")
    else:
        _inside_curved(ctx, place.inside(equations=place.equations + [f_text], charts=()),
                       f, k, comp)


def _inside_curved(ctx: SearchContext, place: Place, f, k: int,
                   comp: Component | None) -> None:
    """Drops inside a family ``f = 0`` of the first level (depth 0) with no rational
    parametrization, where a divisor of the rows vanishes: each block (``H G^T``, and
    ``H D`` of each arm) is reduced modulo ``f`` (a row divisible by ``f`` is zero
    there), its pivots positive everywhere eliminated, and the zero set on ``f = 0`` of
    each divisor taken out of a row is solved like any set of codimension 2. Drops cut
    out there by minors alone are not searched, and the report says so. With ``comp``
    None, ``f = 0`` is a candidate with the enclosing numbers (``place.base``, in
    ``place.parent``), searched one such level deep."""
    names = ({n for row in place.rows for e in row for n in vars_of(ctx, e)}
             | set(vars_of(ctx, f)))
    if comp is not None:
        index = ctx.locus.components.index(comp)
        where = dict(component=index, equations=())
        place = place.inside(base=Numbers(**comp.numbers), depth=place.depth + 1,
                             parent=index)
    else:
        where = dict(component=None, equations=place.equations)
    if len(names) > 4:
        # the sets cut out there are solved in up to four variables only
        _note(ctx, "too_many_variables", variables=len(names), **where)
        return
    quotient = Quotient(f, k)
    dim = ctx.model.object_dim
    blocks = [[row[:dim] for row in place.rows]] + [
        d for _, _, d in _arm_blocks(ctx, place.rows)]
    divisors: list = []
    for rows in blocks:
        rows = [quotient.reduce_row(r) for r in rows]
        contents: list = []
        _reduce_constant_pivots([r for r in rows if any(not e.is_zero() for e in r)],
                                contents)
        divisors += [g for g in contents if not g.is_constant() and not quotient.is_zero(g)
                     and g not in divisors]
    _note(ctx, "divisors_only", **where)
    if not divisors:
        return
    ctx.hidden += comp is None
    try:
        _isolated(ctx, place, [[f, g] for g in divisors])
    finally:
        ctx.hidden -= comp is None


def _isolated(ctx: SearchContext, place: Place, rests) -> None:
    """Common zeros of the remaining minor combinations (codimension 2 or more)."""
    free = [n for n in ctx.ring_names if n not in place.point]
    rational_points: list[dict] = []
    algebraic_points: list[tuple] = []
    for polys in rests:
        names_used = sorted({n for p in polys for n in vars_of(ctx, p)},
                            key=ctx.ring_names.index)
        if not names_used:
            continue
        if len(names_used) > 2:
            if len(names_used) <= 4 and _solve_with_parameters(ctx, place, polys, names_used):
                continue
            _note(ctx, "lower_dimensional_not_solved", depth=place.depth,
                  variables=names_used, bound=_PARAMETER_SOLVE_TERMS)
            continue
        points, algebraic, unresolved = solve_small(ctx, polys, names_used)
        for remark in unresolved:
            add_once(ctx.locus.unexplored, remark)
        rational_points += points
        algebraic_points += algebraic
    created = []
    for point in rational_points:
        created.append(_decide_point(ctx, place, point, None, free))
    for x, g, values, eqs, alpha in algebraic_points:
        created.append(_decide_point(ctx, place, values, (x, g, eqs, alpha), free))
    _intersections(ctx, place, [c for c in created if c is not None], free)


def _intersections(ctx: SearchContext, place: Place, created, free) -> None:
    """Intersections of two families found together, in disjoint variables (two
    fingers stretched at once): the numbers where both hold, exactly (over the compositum
    of their fields when both are irrational and their fields are linearly disjoint)."""
    families = [c for c in created if c[0].kind == "subvariety"]
    for (ci, vi, ai), (cj, vj, aj) in itertools.combinations(families, 2):
        dims_i = set(vi) | ({ai[0]} if ai else set())
        dims_j = set(vj) | ({aj[0]} if aj else set())
        if dims_i & dims_j or ctx.expired():
            continue
        if ai and aj and not linearly_disjoint(ctx, ai[1], ai[0], aj[1], aj[0]):
            ctx.locus.unexplored.append(Remark.of(
                "fields_not_disjoint", first=ctx.locus.components.index(ci),
                second=ctx.locus.components.index(cj)))
            continue
        if place.depth >= ctx.max_depth:
            continue
        moduli = [Quotient(a[1], ctx.ring_names.index(a[0])) for a in (ai, aj) if a]
        reducer = (moduli[0] if len(moduli) == 1 else Tower(moduli)) if moduli else None

        def here(rows, vi=vi, ai=ai, vj=vj, aj=aj):
            rows = substitute_values(ctx, rows, vi, ai[0] if ai else None)
            return substitute_values(ctx, rows, vj, aj[0] if aj else None)

        if any(c.is_zero() or (reducer is not None and reducer.is_zero(c))
               for c in (here([[c]])[0][0] for c in place.charts)):
            continue  # outside the enclosing parametrization
        rows = here(place.rows)
        if reducer is None:
            numbers = decompose(rows, ctx.model, ctx.row_contacts, ctx.ring.zctx).numbers
        else:
            numbers = numbers_modulo(rows, ctx.model, ctx.row_contacts, reducer)
        if numbers.as_dict() in (ci.numbers, cj.numbers):
            continue
        eqs = ci.equations + [e for e in cj.equations if e not in ci.equations]
        kind = "isolated" if len(dims_i | dims_j) == len(free) else "subvariety"
        comp = _component(ctx, place.inside(depth=place.depth + 1,
                                            parent=ctx.locus.components.index(ci)),
                          eqs, numbers, kind, {"Q"},
                          Remark.of("decided_joined_fields", fields=len(moduli)),
                          condition=f"{ci.condition}; and {cj.condition}",
                          within=place.point)
        if comp is None:
            continue
        values = {**vi, **vj}
        if not moduli:
            full = complete_point(ctx, place.point, values)
            if full is not None and numbers_at_values(ctx, full) == numbers:
                attach_witness(ctx, comp, to_at(ctx, full), numbers)
        elif len(moduli) == 1:
            (x, g) = (ai or aj)[:2]
            attach_algebraic_witness(ctx, comp, x, g, values, place.point, numbers)
        elif not place.point:
            attach_two_root_witness(ctx, comp, (ai[0], ai[1], vi), (aj[0], aj[1], vj),
                                    numbers)


def _go_deeper(ctx: SearchContext, comp: Component | None, place: Place,
               why_not: str | None = None) -> None:
    """Search inside a new component for deeper drops, or say why it was not done
    (``why_not``: a reason of :data:`~.remarks.REASONS`)."""
    if comp is None or comp.kind == "isolated":
        return
    index = ctx.locus.components.index(comp)
    if place.depth >= ctx.max_depth:
        why_not = "max_depth"
    if why_not is not None:
        ctx.locus.unexplored.append(Remark.of(
            "deeper_not_explored", component=index, condition=comp.condition,
            reason=why_not, bound=ctx.max_depth if why_not == "max_depth" else None))
    else:
        _explore(ctx, place.inside(depth=place.depth + 1, parent=index))


# the largest minor combination (in terms) solved with parameters
_PARAMETER_SOLVE_TERMS = 400


def _solve_with_parameters(ctx: SearchContext, place: Place, polys, names: list[str]) -> bool:
    """Codimension-2 families in three or four variables, decided exactly.

    Two variables ``x, y`` are solved over the field of the others (the parameters):
    the resultant in ``y`` is factored over Z; for each factor ``h`` involving ``x``,
    ``x`` is substituted when ``h`` is linear in it (then ``y`` comes from the gcd of
    the equations, substituted too or kept as a curve ``k(y, ...) = 0``), and otherwise
    ``y = -c0/c1`` comes from their gcd over the function field of ``h``, whose ranks
    are computed modulo ``h``. Returns whether the system was solved.
    """
    if any(len(p) > _PARAMETER_SOLVE_TERMS for p in polys):
        return False
    for x, y in itertools.permutations(names, 2):
        kx, ky = ctx.ring_names.index(x), ctx.ring_names.index(y)
        if any(p.degrees()[ky] == 0 for p in polys):
            continue
        res = None
        for p in polys[1:]:
            r = polys[0].resultant(p, y)
            res = r if res is None else res.gcd(r)
        if res is None or res.is_zero() or res.is_constant() or res.degrees()[kx] == 0:
            continue
        _, factors = factor(res)
        for h, _e in sorted(factors, key=lambda fe: (fe[0].total_degree(), str(fe[0]))):
            h = normalize(h)
            if _no_real_points(ctx, h):
                continue
            hx = x if h.degrees()[kx] else _variable_to_solve(ctx, h, exclude=(y,))
            if h.degrees()[ctx.ring_names.index(hx)] == 1:
                _solve_linear_x(ctx, place, polys, h, hx, y)
            else:
                _solve_curved_x(ctx, place, polys, h, hx, y)
        return True
    return False


def _variable_to_solve(ctx: SearchContext, f, exclude=()) -> str:
    """A variable of ``f`` to solve it for: the first in which it is linear, else the
    first of lowest degree (variables in ``exclude`` last)."""
    degrees = f.degrees()
    names = [n for n in vars_of(ctx, f)]
    names.sort(key=lambda n: (n in exclude, degrees[ctx.ring_names.index(n)] != 1,
                              degrees[ctx.ring_names.index(n)], ctx.ring_names.index(n)))
    return names[0]


def _no_real_points(ctx: SearchContext, f) -> bool:
    """Whether ``f = 0`` has no real points (then it is listed as dropped)."""
    if has_real_point(ctx, f, vars_of(ctx, f)) is not False:
        return False
    add_once(ctx.locus.dropped, Remark.of("no_real_points", polynomial=poly_text(ctx, f)))
    return True


def _off_charts(charts, substitute, quotient=None) -> bool:
    """Whether an enclosing chart denominator vanishes on the new family."""
    for c in charts:
        c_here = substitute(c)
        if c_here.is_zero() or (quotient is not None and quotient.is_zero(c_here)):
            return True
    return False


def _solve_linear_x(ctx: SearchContext, place: Place, polys, h, x, y) -> None:
    kx, ky_first = ctx.ring_names.index(x), ctx.ring_names.index(y)
    y_first = y
    h1, h0 = split_linear(h, kx)
    moved = [substitute(p, kx, h0, h1, p.degrees()[kx]) for p in polys]
    common = None
    for p in moved:
        if not p.is_zero():
            common = p if common is None else common.gcd(p)
    if common is None or common.is_constant():
        return
    rows_x = substitute_rows(place.rows, kx, h0, h1)
    inner = dict(place.point)
    inner[x] = (h0, h1)
    _, factors = factor(common)
    for k, _e in sorted(factors, key=lambda fe: (fe[0].total_degree(), str(fe[0]))):
        if k.is_constant():
            continue
        # the family's second equation, solved for y, or for another of its variables
        # when y stays free along it
        y = y_first if k.degrees()[ky_first] else _variable_to_solve(ctx, k)
        ky = ctx.ring_names.index(y)
        k = normalize(k)
        if _no_real_points(ctx, k):
            continue

        def at_x(c):
            return substitute(c, kx, h0, h1, c.degrees()[kx])

        if k.degrees()[ky] == 1:
            k1, k0 = split_linear(k, ky)

            def at_xy(c, k0=k0, k1=k1, ky=ky):
                c = at_x(c)
                return substitute(c, ky, k0, k1, c.degrees()[ky])

            if _off_charts([*place.charts, h1], at_xy):
                continue
            rows = substitute_rows(rows_x, ky, k0, k1)
            numbers = decompose(rows, ctx.model, ctx.row_contacts, ctx.ring.zctx).numbers
            decided = Remark.of("decided_two_substitutions")
            if numbers == place.base:
                sub_point = dict(inner)
                sub_point[y] = (k0, k1)
                sub_charts = tuple(c for c in (at_xy(c) for c in [*place.charts, h1]) if
                                   not c.is_constant()) + ((k1,) if not k1.is_constant()
                                                           else ())
                _inside_candidate(ctx, place.inside(
                    rows=rows, equations=place.equations + [poly_text(ctx, h),
                                                            poly_text(ctx, k)],
                    point=sub_point, charts=sub_charts))
                continue
        else:
            quotient = Quotient(k, ky)
            if _off_charts([*place.charts, h1], at_x, quotient):
                continue
            numbers = numbers_modulo(rows_x, ctx.model, ctx.row_contacts, quotient)
            decided = Remark.of("decided_substitution_modulo")
        eqs = place.equations + [poly_text(ctx, h), poly_text(ctx, k)]
        if numbers == place.base:
            _inside_candidate(ctx, place.inside(rows=None, equations=eqs, point=None,
                                                charts=()))
            continue
        chain = None
        if k.degrees()[ky] == 1:
            chain = dict(inner)
            chain[y] = (k0, k1)
        comp = _component(ctx, place, eqs, numbers, "subvariety", {"Q"}, decided,
                          chain=chain, within=inner,
                          generic_point=None if chain is not None else (inner, quotient))
        if comp is None:
            continue
        family_witness(ctx, comp, k, y, inner, numbers)
        if k.degrees()[ky] == 1:
            sub_point = dict(inner)
            sub_point[y] = (k0, k1)
            sub_charts = tuple(c for c in (at_xy(c) for c in [*place.charts, h1]) if
                               not c.is_constant()) + ((k1,) if not k1.is_constant() else ())
            _go_deeper(ctx, comp, place.inside(rows=rows, equations=eqs, point=sub_point,
                                               charts=sub_charts))
        elif place.depth > 0 or place.depth >= ctx.max_depth or ctx.expired():
            _go_deeper(ctx, comp, place.inside(rows=None, equations=eqs, point=None),
                       "no_parametrization")
        else:
            _inside_curved(ctx, place.inside(
                rows=rows_x, equations=eqs, point=inner,
                charts=(*place.charts, h1) if not h1.is_constant() else place.charts),
                k, ky, comp)


def _solve_curved_x(ctx: SearchContext, place: Place, polys, h, x, y,
                    swapped: bool = False) -> None:
    kx, ky = ctx.ring_names.index(x), ctx.ring_names.index(y)
    if _enclosing_numbers_at_a_point(ctx, place, polys, h, x, y):
        _note(ctx, "common_root_not_searched",
              equations=place.equations + [poly_text(ctx, h)], variable=y)
        return
    quotient = Quotient(h, kx)
    common = gcd_modulo([coefficients_in(p, ky) for p in polys], quotient)
    if len(common) > 2 and not swapped:
        # several values of y over each point of h = 0 (angles that differ by pi): the
        # family projects onto the hypersurfaces N = 0 in y and the parameters, N a
        # factor of the norm res_x(h, g); over each, x is solved from h and g instead
        g = sum((c * ctx.ring.zctx.gens()[ky] ** i for i, c in enumerate(common)),
                ctx.ring.zctx.constant(0))
        _, factors = factor(h.resultant(g, x))
        for n, _e in sorted(factors, key=lambda fe: (fe[0].total_degree(), str(fe[0]))):
            if n.degrees()[ky] == 0:
                continue  # where the leading coefficients vanish: part of a wider set
            n = normalize(n)
            if _no_real_points(ctx, n):
                continue
            if n.degrees()[ky] == 1:
                _solve_linear_x(ctx, place, [*polys, h], n, y, x)
            else:
                _solve_curved_x(ctx, place, [*polys, h], n, y, x, swapped=True)
        return
    if len(common) > 2:
        _note(ctx, "shared_values_not_solved", depth=place.depth,
              polynomial=poly_text(ctx, h), count=len(common) - 1, variable=y)
        return
    if len(common) < 2:
        return
    c0, c1 = smallest_fraction(*common, quotient)  # y = -c0/c1, c1 free of x
    if _off_charts([*place.charts, c1], lambda c: substitute(c, ky, c0, c1, c.degrees()[ky]),
                   quotient):
        return
    rows = substitute_rows(place.rows, ky, c0, c1)
    numbers = numbers_modulo(rows, ctx.model, ctx.row_contacts, quotient)
    y_eq = c1 * ctx.ring.zctx.gens()[ky] + c0
    eqs = place.equations + [poly_text(ctx, h), poly_text(ctx, y_eq)]
    if numbers == place.base:
        _inside_candidate(ctx, place.inside(rows=None, equations=eqs, point=None, charts=()))
        return
    inner = dict(place.point)
    inner[y] = (c0, c1)
    comp = _component(ctx, place, eqs, numbers, "subvariety", {"Q"},
                      Remark.of("decided_family_modulo"), within=inner,
                      generic_point=(inner, quotient))
    if comp is None:
        return
    family_witness(ctx, comp, h, x, inner, numbers)
    if place.depth > 0 or place.depth >= ctx.max_depth or ctx.expired():
        _go_deeper(ctx, comp, place.inside(rows=None, point=None),
                   "no_parametrization")
    else:
        _inside_curved(ctx, place.inside(
            rows=rows, equations=comp.equations, point=inner,
            charts=(*place.charts, c1) if not c1.is_constant() else place.charts),
            h, kx, comp)


# parameters of a family set to random integers of at most this size
_SPECIALIZE_BOUND = 1 << 16


def _enclosing_numbers_at_a_point(ctx: SearchContext, place: Place, polys, h, x, y) -> bool:
    """Whether the family ``h = 0`` (``x`` curved), ``y`` a common root of ``polys``,
    has the enclosing numbers, shown at one point of it: the other variables set to
    random integers, ``x`` a root of a factor of ``h`` there, ``y`` from the gcd over
    ``Q(x)``. Ranks never rise at a special point and never exceed the enclosing ones, so
    equal ranks there are the family's own. ``False`` means not shown (the family is then
    decided over its function field). The point lies on the family unless the random
    values hit a proper subset of it (Schwartz-Zippel)."""
    kx, ky = ctx.ring_names.index(x), ctx.ring_names.index(y)
    values = {n: Fraction(ctx.rng.randint(-_SPECIALIZE_BOUND, _SPECIALIZE_BOUND))
              for n in ctx.ring_names if n not in (x, y)}
    (h_here, *polys_here), = substitute_values(ctx, [[h, *polys]], values)
    if h_here.degrees()[kx] < h.degrees()[kx] or any(
            p.degrees()[ky] < q.degrees()[ky] for p, q in zip(polys_here, polys, strict=True)):
        return False
    _, factors = factor(h_here)
    curved = [f for f, _e in factors if f.degrees()[kx] > 0]
    if not curved:
        return False
    quotient = Quotient(min(curved, key=lambda f: (f.degrees()[kx], len(f))), kx)
    common = gcd_modulo([coefficients_in(p, ky) for p in polys_here], quotient)
    if len(common) != 2:
        return False
    rows = substitute_rows(substitute_values(ctx, place.rows, values), ky, *common)
    return numbers_modulo(rows, ctx.model, ctx.row_contacts, quotient) == place.base


def _decide_point(ctx: SearchContext, place: Place, values: dict, algebraic,
                  free) -> tuple | None:
    """The numbers on the set where some coordinates are fixed (rationals, or
    polynomials over Q in a root ``x`` of ``g`` when ``algebraic = (x, g, equations,
    alpha)``, ``alpha`` naming what ``x`` stands for), every
    other free variable staying generic, decided exactly."""
    quotient = None
    if algebraic is not None:
        x, g, _, _ = algebraic
        quotient = Quotient(g, ctx.ring_names.index(x))
    x = algebraic[0] if algebraic is not None else None
    for c in place.charts:
        c_here = substitute_values(ctx, [[c]], values, x)[0][0]
        if c_here.is_zero() or (quotient is not None and quotient.is_zero(c_here)):
            return None  # outside the enclosing parametrization
    rows = substitute_values(ctx, place.rows, values, x)
    if quotient is None:
        numbers = decompose(rows, ctx.model, ctx.row_contacts, ctx.ring.zctx).numbers
    else:
        numbers = numbers_modulo(rows, ctx.model, ctx.row_contacts, quotient)
    eqs = list(place.equations)
    if algebraic is not None:
        eqs += [poly_text(ctx, e) for e in algebraic[2]]
    else:
        eqs += [poly_text(ctx, linear_equation(ctx, n, v)) for n, v in values.items()]
    dims = set(values) | ({x} if x is not None else set())
    kind = "isolated" if len(dims) == len(free) else "subvariety"
    if numbers == place.base:
        if kind == "subvariety":
            sub_point = dict(place.point)
            zctx = ctx.ring.zctx
            if algebraic is None:
                for n, v in values.items():
                    sub_point[n] = (zctx.constant(-v.numerator), zctx.constant(v.denominator))
            _inside_candidate(ctx, place.inside(rows=rows if algebraic is None else None,
                                                equations=eqs, point=sub_point))
        return None
    if algebraic is None:
        chain = dict(place.point)
        for n, v in values.items():
            chain[n] = (ctx.ring.zctx.constant(-v.numerator),
                        ctx.ring.zctx.constant(v.denominator))
        comp = _component(ctx, place, eqs, numbers, kind, {"Q"},
                          Remark.of("decided_at_point" if kind == "isolated" else
                                    "decided_free_variables"),
                          chain=chain)
        if comp is None:
            return None
        for offset in range(6):
            full = complete_point(ctx, place.point, values, offset)
            if full is not None and numbers_at_values(ctx, full) == numbers:
                attach_witness(ctx, comp, to_at(ctx, full), numbers)
                break
        sub_point = dict(place.point)
        zctx = ctx.ring.zctx
        for n, v in values.items():
            sub_point[n] = (zctx.constant(-v.numerator), zctx.constant(v.denominator))
        _go_deeper(ctx, comp, place.inside(rows=rows, equations=eqs, point=sub_point))
        return comp, values, None
    x, g, eq_polys, alpha = algebraic
    condition = algebraic_condition(ctx, x, g, values)
    if place.equations:
        inside = _condition(ctx, place.equations)
        condition = " or ".join(f"{inside}, {part}" for part in condition.split(" or "))
    m = sp.sstr(poly_to_sympy(g, ctx.ring, ctx.symbols).subs(ctx.symbols[x],
                                                                sp.Symbol("alpha")))
    comp = _component(ctx, place, eqs, numbers, kind, {"Q"},
                      Remark.of("decided_algebraic", variable=alpha, minimal_polynomial=m),
                      condition=condition, within=place.point)
    if comp is None:
        return None
    attach_algebraic_witness(ctx, comp, x, g, values, place.point, numbers, alpha)
    _go_deeper(ctx, comp, place.inside(rows=rows, equations=eqs, point=None),
               "irrational_family")
    return comp, values, (x, g)


# --- components -------------------------------------------------------------------------
def _component(ctx: SearchContext, place: Place, equations: list[str], numbers: Numbers,
               kind: str, drops, decided: Remark, *, witness: dict | None = None,
               condition: str | None = None, real: bool = True, chain: dict | None = None,
               within: dict | None = None,
               generic_point: tuple | None = None) -> Component | None:
    """Record a component found at ``place`` (its depth and parent; None when the same
    set is already recorded). ``chain`` is
    its parametrization by successive linear substitutions (variable -> ``(f0, f1)``,
    the variable equals ``-f0/f1``), used to recognize the same set found twice;
    ``within``, when there is no chain, the parametrization of the set it was found
    in. Their denominators become the component's ``outside``. ``generic_point``,
    ``(parametrization, quotient or None)``, describes its generic point: a component of
    the same chart with the same numbers whose equations vanish there contains it, and
    it is not recorded."""
    if any(sorted(c.equations) == sorted(equations) for c in ctx.locus.components):
        return None
    here = numbers.as_dict()
    if any(c.numbers == here and c.equations and set(c.equations) < set(equations)
           for c in ctx.locus.components):
        return None  # inside a recorded component, with its numbers: nothing new
    if chain is not None and any(_within(ctx, chain, c, numbers)
                                 for c in ctx.locus.components):
        return None
    if generic_point is not None and any(_vanish_at(ctx, c, *generic_point)
                                         for c in ctx.locus.components
                                         if c.numbers == here):
        return None
    generic = ctx.generic.as_dict()
    here = numbers.as_dict()
    changes = {k: (generic[k], here[k]) for k in generic if generic[k] != here[k]}
    comp = Component(equations=equations, numbers=here, witness=None, real=real,
                     kind=kind, condition=condition or _condition(ctx, equations),
                     drops=_drops_text(
                         drops), changes=changes, decided=decided, depth=place.depth,
                     parent=place.parent,
                     outside=_denominators(ctx, chain if chain is not None else within,
                                           equations))
    comp.polynomials = [_named(ctx, text) for text in comp.equations]
    comp.outside_polynomials = [_named(ctx, text) for text in comp.outside]
    if witness is not None:
        attach_witness(ctx, comp, witness, numbers)
    ctx.locus.components.append(comp)
    if ctx.owners is not None:
        ctx.owners[id(comp)] = ctx
    if chain is not None:
        ctx.chains[id(comp)] = (ctx, dict(chain))
    return comp


def _named(ctx: SearchContext, text: str) -> NamedPolynomial:
    """The exact polynomial behind an equation text of this chart: kept when the text
    was written (:func:`~coopkin_sym.analysis.locus.algebra.poly_text`), or the
    variable ``s_<joint>`` of a chart at q = pi."""
    p = ctx.polys.get(text)
    if p is not None:
        return NamedPolynomial.from_flint(p, ctx.ring_names)
    if text.startswith(COTANGENT_PREFIX) and joint_of(text) in ctx.pi:
        return NamedPolynomial.variable(text)
    # not expected: every equation is written from a polynomial of this chart; its text
    # then reads back exactly through the one parser
    names = [*ctx.ring_names, *(cotangent_name(j) for j in sorted(ctx.pi))]
    return NamedPolynomial.parse(text, names, "equation")


def _vanish_at(ctx: SearchContext, comp: Component, point: dict, quotient) -> bool:
    """Whether every equation of ``comp`` (recorded in this chart) vanishes at the
    generic point given by the parametrization ``point`` and, when not None, the
    ``quotient`` by an irreducible polynomial."""
    if ctx.owners is None or ctx.owners.get(id(comp)) is not ctx:
        return False
    for text in comp.equations:
        p = ctx.polys.get(text)
        if p is None:
            return False
        p = _on_chain(p, ctx, point)
        if not (p.is_zero() or (quotient is not None and quotient.is_zero(p))):
            return False
    return True


def _beyond_chart(ctx: SearchContext, equations: list[str]) -> list[str]:
    """The equations other than those of the chart (``s_<joint>`` for the joints at
    q = pi here)."""
    chart = {cotangent_name(n) for n in ctx.pi}
    return [e for e in equations if e not in chart]


def _denominators(ctx: SearchContext, chain: dict | None, equations: list[str]) -> list[str]:
    """The irreducible factors of the denominators of a linear parametrization: its
    image is the set where the equations hold and none of them vanishes (where one
    does, the equations may hold on a wider set, searched apart by
    :func:`_chart_points`). None for one irreducible equation (in a chart): its zero
    set is the closure of that image."""
    if len(_beyond_chart(ctx, equations)) <= 1:
        return []
    out: list[str] = []
    for _f0, f1 in (chain or {}).values():
        if f1.is_constant():
            continue
        for g, _e in factor(f1)[1]:
            g = normalize(g)
            if g.is_constant() or _no_real_points(ctx, g):
                continue
            text = poly_text(ctx, g)
            if text not in out:
                out.append(text)
    return out


def _on_chain(p, ctx, chain: dict):
    """``p`` on the set parametrized by ``chain`` (denominators cleared): zero exactly
    when ``p`` vanishes on that set."""
    for name, (f0, f1) in chain.items():
        k = ctx.ring_names.index(name)
        if p.degrees()[k]:
            p = substitute(p, k, f0, f1, p.degrees()[k])
    return p


def _contained(ctx: SearchContext, inner: dict, outer: dict) -> bool:
    """Whether the set of chain ``inner`` lies in the set of chain ``outer`` (both in
    the variables of ``ctx``): every relation ``f1 x + f0`` of ``outer`` vanishes on
    ``inner``, and no denominator ``f1`` of ``outer`` does."""
    gens = ctx.ring.zctx.gens()
    for name, (f0, f1) in outer.items():
        relation = f1 * gens[ctx.ring_names.index(name)] + f0
        if not _on_chain(relation, ctx, inner).is_zero():
            return False
        if not f1.is_constant() and _on_chain(f1, ctx, inner).is_zero():
            return False
    return True


def _wider_component(ctx: SearchContext, chain: dict, numbers: Numbers) -> Component | None:
    """A component with the same numbers, recorded in a chart with fewer joints at pi,
    that contains the set of ``chain`` (in a chart with joints at pi) because its
    equations do not involve the joints at pi here (so they hold there as they are);
    None when there is none."""
    if not ctx.pi:
        return None
    here = numbers.as_dict()
    for comp in ctx.locus.components:
        known = ctx.chains.get(id(comp))
        if known is None or comp.numbers != here:
            continue
        other, other_chain = known
        if other is ctx or not other.pi < ctx.pi:
            continue
        relations = []
        for name, (f0, f1) in other_chain.items():
            x = other.ring.zctx.gens()[other.ring_names.index(name)]
            relations.append((f1 * x + f0, f1))
        moved = [(_transfer(r, other, ctx), _transfer(d, other, ctx)) for r, d in relations]
        if any(r is None or d is None for r, d in moved):
            continue
        if all(_on_chain(r, ctx, chain).is_zero() and
               (d.is_constant() or not _on_chain(d, ctx, chain).is_zero())
               for r, d in moved):
            return comp
    return None


def _transfer(p, source, target):
    """``p`` from the ring of context ``source`` to that of ``target`` by variable
    names (None when it uses a variable ``target`` does not have)."""
    index = {n: i for i, n in enumerate(target.ring_names)}
    terms = {}
    for mon, c in p.to_dict().items():
        new = [0] * len(target.ring_names)
        for name, e in zip(source.ring_names, mon, strict=True):
            if e:
                if name not in index:
                    return None
                new[index[name]] = int(e)
        terms[tuple(new)] = int(c)
    return target.ring.zctx.from_dict(terms)


def _within(ctx: SearchContext, chain: dict, other: Component, numbers: Numbers) -> bool:
    """Whether the set of ``chain`` lies in component ``other`` of the same chart with
    the same numbers (then it adds nothing: drops deeper inside it are deeper inside
    ``other`` and searched there)."""
    known = ctx.chains.get(id(other))
    if known is None or known[0] is not ctx or other.numbers != numbers.as_dict():
        return False
    return _contained(ctx, chain, known[1])


def _condition(ctx: SearchContext, equations: list[str]) -> str:
    """The equations in angles where they read simply (see
    :func:`~coopkin_sym.analysis.locus.algebra.read_poly`)."""
    return ", ".join(ctx.readings.get(eq, f"{eq} = 0") for eq in equations)


def _pi_slices(ctx: SearchContext, pi_size: int | None = None) -> None:
    """Every subset of the free revolute joints at q = pi, where t = tan(q/2) is
    infinite: each slice is a system in the other variables, searched like the t chart
    (its generic numbers, and every drop inside it, at every depth). A component there
    has the equations ``s_<joint>`` (``s = cot(q/2) = 0``) for the joints at pi.
    ``pi_size``: the largest set of joints at pi searched inside (None: all); larger
    sets get their own numbers decided and a note."""
    rev = _revolute(ctx)
    subsets = _pi_subsets(rev)
    for subset in subsets:
        where = ", ".join(f"{n} = pi" for n in subset)
        ctx.reporter.step(where)
        if ctx.expired():
            ctx.locus.unexplored.append(Remark.of("time_pi_set", joints=subset))
            continue
        revolute = dict(ctx.config.revolute)
        for n in subset:
            revolute[n] = (sp.Integer(-1), sp.Integer(0))
        config = Configuration(revolute, ctx.config.prismatic, ctx.config.parameters,
                               ctx.config.free - set(subset))
        chart, rows = _chart(ctx.model, config)
        sub = dataclasses.replace(ctx, **chart, pi=frozenset(subset), hidden=0, splits=0,
                                  deferred=[], polys={})
        equations = [cotangent_name(n) for n in subset]
        for n in subset:
            ctx.readings[cotangent_name(n)] = f"{n} = pi"
        numbers = decompose(rows, ctx.model, sub.row_contacts, sub.ring.zctx).numbers
        parent, depth = None, 0
        wider = _wider_component(sub, {}, numbers)
        if wider is not None:  # the slice lies in a component of a wider chart
            parent, depth = ctx.locus.components.index(wider), 1
        elif numbers != ctx.generic:
            kind = "chart" if sub.ring_names else "isolated"
            comp = _component(sub, Place(rows=rows, equations=[], point={}, depth=0),
                              equations, numbers, kind, {"Q"},
                              Remark.of("decided_other_variables" if sub.ring_names
                                        else "decided_at_point"),
                              condition=where)
            for offset in range(6):
                values = complete_point(sub, {}, {}, offset)
                if values is not None and numbers_at_values(sub, values) == numbers:
                    attach_witness(sub, comp, to_at(sub, values), numbers)
                    break
            ctx.chains[id(comp)] = (sub, {})
            parent, depth = ctx.locus.components.index(comp), 1
        if not sub.ring_names:
            continue
        if depth > ctx.max_depth:
            ctx.locus.unexplored.append(Remark.of("pi_deeper_not_explored", joints=subset,
                                                  bound=ctx.max_depth))
            continue
        if pi_size is not None and len(subset) > pi_size:
            ctx.locus.unexplored.append(Remark.of(
                "pi_set_not_searched", joints=subset, deeper=parent is not None,
                bound=pi_size))
            continue
        _explore(sub, Place(rows=rows, equations=equations, point={}, depth=depth,
                            parent=parent))
    if rev:
        ctx.locus.notes.append(Remark.of("pi_chart"))


def _revolute(ctx: SearchContext) -> list[str]:
    """The free revolute joints of the chart."""
    return [name for kind, name in ctx.kinds.values() if kind == "revolute"]


def _pi_subsets(rev: list[str]) -> list[tuple[str, ...]]:
    """Every non-empty set of the joints ``rev`` (the slices at q = pi), smallest first."""
    return [s for size in range(1, len(rev) + 1) for s in itertools.combinations(rev, size)]


def _default_pi_size(ctx: SearchContext) -> int | None:
    """How many joints at pi at once are searched inside by default: every set for up
    to four free revolute joints, then fewer as the number of sets grows (2^r - 1)."""
    rev = sum(1 for kind, _ in ctx.kinds.values() if kind == "revolute")
    return None if rev <= 4 else 2 if rev <= 6 else 1 if rev <= 8 else 0


def _settle_realness(ctx: SearchContext) -> None:
    """A component is called real only with a real witness (rational, or algebraic in
    an isolating interval); one without is marked as undecided, never as real (those
    proved to have no real points were dropped when found)."""
    for c in ctx.locus.components:
        c.real = c.witness is not None or c.algebraic_witness is not None
        c.real_points = "witness" if c.real else "undecided"


__all__ = ["LocusError", "compute_locus"]
