"""Witnesses of locus components, and what floats say there (see
:mod:`coopkin_sym.analysis.locus.search`).

A witness is an exact point of a component where a direct analysis gives the
component's numbers: rational coordinates where they exist (completed from nice values
and the parametrization of enclosing components), else a real point with algebraic
coordinates, handled in ``Q(alpha)`` and written in radicals or ``CRootOf``. Each
witness also gets the motions that change there, in words, and float rank tests at,
near (1e-6, 1e-9, 1e-12 rad) and with lengths rescaled.

Example
-------
>>> ExactAngle.parse("pi/2", "q1").nudged(1e-6).text.startswith("2*atan(")
True
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from fractions import Fraction

import flint
import mpmath
import numpy as np
import sympy as sp

from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.floatcheck import float_numbers
from coopkin_sym.analysis.irrational import point_motions
from coopkin_sym.analysis.locus.algebra import NICE, roots, substitute_values, univariate, vars_of
from coopkin_sym.analysis.locus.conditions import Condition, Value
from coopkin_sym.analysis.locus.context import SearchContext
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.locus.types import Component, FloatCheck, WitnessMotions
from coopkin_sym.analysis.mobility import Analysis, numbers_modulo
from coopkin_sym.analysis.numbers import Numbers, numbers_from_ranks
from coopkin_sym.analysis.sweep.chains import ChainQ, RationalField, chain_data, row_contacts
from coopkin_sym.analysis.sweep.compiled import _arm_blocks
from coopkin_sym.exact import matrix
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.numberfield import NumberField
from coopkin_sym.exact.polynomial import NamedPolynomial
from coopkin_sym.exact.quotient import Quotient, Tower
from coopkin_sym.exact.rationals import to_fraction
from coopkin_sym.exact.realroot import RealRoot, element_expression
from coopkin_sym.exact.substitution import substitute
from coopkin_sym.exact.sympy_bridge import poly_to_sympy
from coopkin_sym.model.configuration import Configuration, Point

FLOAT_DISTANCES = (1e-6, 1e-9, 1e-12)
#: The float rank tests at witnesses are run when ``Q`` has at most this many entries
#: (a float SVD costs the cube of its size: about 8 s CPU for 1,200 x 1,206); beyond
#: it they are left out and the locus says so (see :func:`floats_left_out`).
FLOAT_CHECK_ENTRIES = 40_000


def complete_point(ctx: SearchContext, point_so_far: dict, point: dict[str, Fraction],
                   offset: int = 0):
    """A full point: the given coordinates, nice values for the others, then the
    parametrized coordinates of enclosing components (``x = -f0/f1``)."""
    values = dict(point)
    for n in ctx.ring_names:
        if n not in values and n not in point_so_far:
            values[n] = nice_value(ctx, n, len(values) + offset)
    for n, (f0, f1) in reversed(list(point_so_far.items())):
        args = [values.get(k, Fraction(0)) for k in ctx.ring_names]
        den = eval_at(f1, args)
        if den == 0:
            return None
        values[n] = -eval_at(f0, args) / den
    return values


def nice_value(ctx: SearchContext, name: str, k: int) -> Fraction:
    """The ``k``-th nice value for variable ``name``: parameters are lengths, so they
    get positive ones."""
    v = NICE[k % len(NICE)]
    if ctx.kinds.get(name, ("",))[0] == "parameter":
        return abs(v) or Fraction(1)
    return v


def eval_at(p, args: list[Fraction]) -> Fraction:
    total = Fraction(0)
    for mon, c in p.to_dict().items():
        term = Fraction(int(c))
        for a, e in zip(args, mon, strict=True):
            if e:
                term *= a ** int(e)
        total += term
    return total


def witness_linear(ctx: SearchContext, sub_rows, name, f0, f1, point_so_far, numbers):
    """A rational point of the component where the numbers are the component's."""
    others = [n for n in ctx.ring_names if n != name and n not in point_so_far]
    tries = itertools.islice(itertools.product(NICE, repeat=len(others)), 200)
    for values in tries:
        point = dict(zip(others, values, strict=True))
        inner = dict(point_so_far)
        inner[name] = (f0, f1)
        full = complete_point(ctx, inner, point)
        if full is None:
            continue
        if numbers_at_values(ctx, full) == numbers:
            return to_at(ctx, full)
    return None


def numbers_at_values(ctx: SearchContext, values: dict[str, Fraction]) -> Numbers | None:
    """The numbers at a full point (see :func:`to_at`) by a direct exact analysis;
    None when the values are no point (a length not positive)."""
    point = to_at(ctx, values)
    return None if point is None else analysis_at(ctx, point).numbers


def analysis_at(ctx: SearchContext, point: Point) -> Analysis:
    """The exact analysis at ``point``, made once per point in a search."""
    key = point.at_text()
    if key not in ctx.analyses:
        ctx.analyses[key] = Analysis(ctx.model, point)
    return ctx.analyses[key]


def to_at(ctx: SearchContext, values: dict[str, Fraction]) -> Point | None:
    """A full exact point (joints set by the caller and fixed values included), named
    in the order of ``--at``: the fixed joints, the free variables, the fixed
    parameters; None when a length is not positive."""
    config = ctx.config
    order = [j.name for j in ctx.model.joints
             if j.name in config.revolute or j.name in config.prismatic]
    revolute, prismatic = dict(config.revolute), dict(config.prismatic)
    parameters = {}
    for n, (kind, name) in ctx.kinds.items():
        v = values.get(n)
        if v is None or (kind == "parameter" and v <= 0):
            return None
        order.append(name)
        if kind == "revolute":
            revolute[name] = ExactAngle.from_tangent(v)
        elif kind == "parameter":
            parameters[name] = sp.Rational(v.numerator, v.denominator)
        else:
            prismatic[name] = sp.Rational(v.numerator, v.denominator)
    order += list(config.parameters)
    parameters.update(config.parameters)
    return Point.of(revolute, prismatic, parameters, order)


def complete_algebraic(ctx: SearchContext, point_so_far: dict, x: str, field: NumberField,
                       values: dict, offset: int = 0) -> dict | None:
    """A full point over ``Q(alpha)``: every variable but ``x`` as an element (a
    polynomial in ``x`` of degree below ``deg g``); nice rationals for the free ones."""
    full = {n: field.element(v if not isinstance(v, Fraction) else
                             flint.fmpq(v.numerator, v.denominator))
            for n, v in values.items()}
    for n in ctx.ring_names:
        if n != x and n not in full and n not in point_so_far:
            v = nice_value(ctx, n, len(full) + offset)
            full[n] = field.element(flint.fmpq(v.numerator, v.denominator))
    for n, (f0, f1) in reversed(list(point_so_far.items())):
        den = eval_in(ctx, f1, full, x, field)
        if den.is_zero():
            return None
        full[n] = field.element(-eval_in(ctx, f0, full, x, field) * field.inverse(den))
    return full


def eval_in(ctx: SearchContext, p, values: dict, x: str, field: NumberField):
    """``p`` at a point over ``Q(alpha)`` (``x`` is alpha itself)."""
    args = [flint.fmpq_poly([0, 1]) if n == x and n not in values else
            values.get(n, flint.fmpq_poly(0))
            for n in ctx.ring_names]
    total = flint.fmpq_poly(0)
    for mon, c in p.to_dict().items():
        term = flint.fmpq_poly(int(c))
        for a, e in zip(args, mon, strict=True):
            if e:
                term = field.element(term * a ** int(e))
        total += term
    return field.element(total)


def numbers_at_algebraic(ctx: SearchContext, x: str, g, full: dict) -> Numbers:
    """The numbers at a point over ``Q(alpha)``, by a direct exact analysis: the rows of
    ``Q`` with every free variable (nothing from the locus search) evaluated there."""
    rows = substitute_values(ctx, ctx.rows0, full, x)
    return numbers_modulo(rows, ctx.model, ctx.row_contacts,
                          Quotient(g, ctx.ring_names.index(x)))


def value_expr(v, root: sp.Expr) -> sp.Expr:
    """An element of ``Q(alpha)`` (polynomial in alpha) at the real root ``root``."""
    return element_expression(v, root)


def value_near(v, a: Fraction) -> Fraction:
    if isinstance(v, Fraction):
        return v
    return sum((to_fraction(c) * a**i for i, c in enumerate(v.coeffs())),
               Fraction(0))


def algebraic_point_values(ctx: SearchContext, values: dict, root: RealRoot, x: str,
                            only: set[str] | None = None) -> dict[str, sp.Expr]:
    """The point (at one real root), exact SymPy numbers (radicals, or CRootOf) named
    as in ``--at``; an angle is a rational multiple of pi when it is one (decided by
    arithmetic in ``Q(alpha)``, :meth:`~coopkin_sym.exact.realroot.RealRoot.angle_at`)."""
    expr = root.expression()
    out: dict[str, sp.Expr] = {}
    for n, (kind, name) in ctx.kinds.items():
        if only is not None and n not in only:
            continue
        v = _GENERATOR if n == x and n not in values else values[n]
        out[name] = root.angle_at(v) if kind == "revolute" else element_expression(v, expr)
    return out


def algebraic_point_text(ctx: SearchContext, values: dict, root: RealRoot, x: str,
                         only: set[str] | None = None) -> dict[str, str]:
    """:func:`algebraic_point_values` in ``--at`` syntax."""
    return {k: sp.sstr(v) for k, v in algebraic_point_values(ctx, values, root, x,
                                                               only).items()}


#: alpha itself, as an element of ``Q(alpha)``.
_GENERATOR = flint.fmpq_poly([0, 1])


def algebraic_condition(ctx: SearchContext, x: str, g, values: dict) -> Condition:
    """The real points of an algebraic component, one alternative per real root."""
    names = {x, *values}
    roots = RealRoot.all_of(univariate(ctx, g, x).coeffs())
    kinds = {name: kind for kind, name in ctx.kinds.values()}
    return Condition.either(
        Condition.of(*(Value(k, v, kinds[k]) for k, v in
                       algebraic_point_values(ctx, values, root, x, only=names).items()))
        for root in roots)


def attach_algebraic_witness(ctx: SearchContext, comp: Component, x: str, g, values: dict,
                              point_so_far: dict, numbers: Numbers,
                              alpha: str | None = None) -> None:
    """A witness at a real root of ``g``: exact coordinates (radicals or ``CRootOf``),
    its numbers from a direct analysis over ``Q(alpha)``, and float checks on its float
    image."""
    field = NumberField(univariate(ctx, g, x))
    roots = RealRoot.all_of(field.g.coeffs())
    if not roots:
        return
    for offset in range(6):
        full = complete_algebraic(ctx, point_so_far, x, field, values, offset)
        if full is None:
            continue
        direct = numbers_at_algebraic(ctx, x, g, full)
        if direct != numbers:
            continue
        root = roots[0]
        point = algebraic_point_text(ctx, full, root, x)
        given = {**fixed_at(ctx), **point}
        order = [j.name for j in ctx.model.joints] + [p.name for p in ctx.model.parameters]
        at = {k: given[k] for k in order if k in given}
        a = root.approximation()
        near = {n: (a if n == x and n not in full else value_near(full[n], a))
                for n in ctx.ring_names}
        approx_at = to_at(ctx, near)
        comp.algebraic_witness = {
            "point": at,
            "alpha": alpha or x,
            "root_of": sp.sstr(poly_to_sympy(g, ctx.ring, ctx.symbols).subs(
                ctx.symbols[x], sp.Symbol("alpha"))),
            "root": sp.sstr(root.expression()),
            "interval": [str(root.lo), str(root.hi)],
            "approx": _approximations(ctx, point, near),
        }
        comp.witness_checked = True
        comp.shown = algebraic_motions(ctx, full, x, g, root, numbers, comp.changes)
        if approx_at is not None:
            comp.float_checks = float_image_checks(ctx, approx_at, analysis_at(ctx, approx_at),
                                                   numbers, comp.equations)
        return


def _approximations(ctx: SearchContext, point: dict[str, str], near: dict[str, Fraction]
                    ) -> dict[str, str]:
    """The coordinates of ``point`` to 12 digits, from ``near`` (each variable's value
    within 1e-40 of the exact one: an angle is ``2 atan`` of its tangent), for
    display."""
    kinds = {name: (kind, n) for n, (kind, name) in ctx.kinds.items()}
    out = {}
    with mpmath.workdps(30):
        for k in point:
            kind, n = kinds[k]
            v = mpmath.mpf(near[n].numerator) / near[n].denominator
            out[k] = f"{float(2 * mpmath.atan(v) if kind == 'revolute' else v):.12g}"  # float-ok
    return out


def algebraic_witness_on(ctx: SearchContext, comp: Component, f, k: int, point_so_far: dict,
                         numbers: Numbers) -> None:
    """A witness on the hypersurface ``f = 0``: nice rationals for the other variables,
    ``x_k`` a root of what is left (see :func:`family_witness`)."""
    family_witness(ctx, comp, f, ctx.ring_names[k], point_so_far, numbers)


def fixed_at(ctx: SearchContext) -> dict[str, str]:
    """The joints and parameters the locus was asked to hold fixed, in ``--at`` syntax."""
    out: dict[str, str] = {}
    config = ctx.config
    for j in ctx.model.joints:
        if j.name in config.revolute:
            out[j.name] = config.revolute[j.name].text
        elif j.name in config.prismatic:
            out[j.name] = sp.sstr(config.prismatic[j.name])
    for p, v in config.parameters.items():
        out[p] = sp.sstr(v)
    return out


def algebraic_motions(ctx: SearchContext, full: dict, x: str, g, root: RealRoot, numbers: Numbers,
                      changes) -> WitnessMotions:
    """What an irrational witness shows: the exact motions behind the changed ``Ni`` and
    ``Nr`` for a quadratic field (the counts alone otherwise)."""
    rows = substitute_values(ctx, ctx.rows0, full, x)
    alpha = root.expression()
    values = {ctx.symbols[n]: (alpha if n == x and n not in full else
                               value_expr(full[n], alpha)) for n in ctx.ring_names}
    if ctx.kin is None:        # a slice at q = pi: built once, where a witness needs it
        ctx.kin = kinematics.build(ctx.model, ctx.config)
    kin = ctx.kin
    motions = point_motions(ctx.model, numbers, rows, Quotient(g, ctx.ring_names.index(x)),
                            kin, values, root.degree, changed=set(changes))
    return WitnessMotions(numbers, ctx.model.joint_names, frozenset(changes),
                          motions=motions, object_dim=ctx.model.object_dim)


def float_image_checks(ctx: SearchContext, approx_at: Point, analysis, numbers: Numbers,
                        comp_equations: Sequence[NamedPolynomial]):
    """Float checks at the float image of an irrational witness (a rational point
    within 1e-40 of it stands in for it; its float64 image is the same), where the
    exact numbers are the witness's own."""
    checks = float_checks(ctx, approx_at, analysis, comp_equations)
    uniform = len(ctx.model.parameters) <= 1
    out = []
    for c in checks:
        if c.distance == 0:
            if c.scale != checks[0].scale and not uniform:
                continue
            c.exact = numbers.as_dict()
        out.append(c)
    return out


def attach_witness(ctx: SearchContext, comp: Component, witness: Point,
                   numbers: Numbers) -> None:
    """A rational witness, checked by a direct exact analysis, with its float checks."""
    analysis = analysis_at(ctx, witness)
    comp.witness = witness
    comp.witness_checked = analysis.numbers == numbers
    comp.shown = WitnessMotions(numbers, ctx.model.joint_names, frozenset(comp.changes),
                                analysis=analysis, object_dim=ctx.model.object_dim)
    comp.float_checks = float_checks(ctx, witness, analysis, comp.equations)


def float_checks(ctx: SearchContext, witness: Point, analysis,
                  equations: Sequence[NamedPolynomial] = ()) -> list[FloatCheck]:
    """Float ranks at the witness, at points near it, and with lengths rescaled. The
    nearby points move a revolute joint of the component's last equation (so they leave
    the component, and stay in its parent)."""
    if floats_left_out(ctx) is not None:
        return []
    checks = []
    scale = ", ".join(f"{p}={v}" for p, v in ctx.config.parameters.items()) or "-"
    probe = _FloatProbe.of(ctx, witness)
    checks.append(FloatCheck(0.0, scale, witness, analysis.numbers.as_dict(),
                             float_numbers(analysis) if probe is None else
                             probe.numbers(witness)[1]))
    used = [set(eq.variables) for eq in reversed(equations)]
    revolute = [(n, name) for n, (kind, name) in ctx.kinds.items() if kind == "revolute"]
    joint = next((name for names in used for n, name in revolute if n in names),
                 revolute[0][1] if revolute else None)
    for distance in FLOAT_DISTANCES:
        if joint is None:
            break
        point = witness.moved(joint, _nudged(witness, joint, distance))
        checks.append(FloatCheck(distance, scale, point, *_both(ctx, probe, point)))
    for p in ctx.model.parameters:
        for value in ("1/1000", "1000"):
            for distance in (0.0, *FLOAT_DISTANCES):
                point = witness.moved(p.name, sp.Rational(value))
                if distance and joint is not None:
                    point = point.moved(joint, _nudged(witness, joint, distance))
                elif distance:
                    continue
                checks.append(FloatCheck(distance, f"{p.name}={value}", point,
                                         *_both(ctx, _FloatProbe.of(ctx, point), point)))
    return checks


def floats_left_out(ctx: SearchContext) -> Remark | None:
    """The note that the float rank tests were left out (``Q`` over
    :data:`FLOAT_CHECK_ENTRIES` entries), or None when they are run."""
    rows, columns = len(ctx.rows0), ctx.model.object_dim + len(ctx.model.joints)
    if rows * columns <= FLOAT_CHECK_ENTRIES:
        return None
    return Remark.of("float_checks_left_out", rows=rows, columns=columns,
                     bound=FLOAT_CHECK_ENTRIES)


def _both(ctx: SearchContext, probe: _FloatProbe | None, point: Point
          ) -> tuple[dict[str, int], dict[str, int]]:
    """The exact and the float numbers at ``point``: from ``Q`` there (the compiled
    chains), else from an analysis."""
    if probe is not None:
        return probe.numbers(point)
    a = Analysis(ctx.model, point)
    return a.numbers.as_dict(), float_numbers(a)


class _FloatProbe:
    """``Q`` at exact points with given parameter values, from the compiled chains
    (:mod:`coopkin_sym.analysis.sweep.chains`): the exact numbers there (exact ranks)
    and what a float pipeline says (ranks of its float64 image by numpy, as
    :func:`~coopkin_sym.analysis.floatcheck.float_numbers`). One per parameter values
    in a search."""

    def __init__(self, model, parameters):
        self.model = model
        self.joints = [j for j in model.joints]
        base = Configuration(parameters=dict(parameters))
        self.chain = ChainQ(chain_data(model, base, [j.name for j in self.joints]))
        self.field = RationalField()
        self.arms = _arm_blocks(model, row_contacts(model), model.object_dim)

    @classmethod
    def of(cls, ctx: SearchContext, point: Point) -> _FloatProbe | None:
        """The probe for the parameter values of ``point``; None when one is missing
        (a parameter left symbolic)."""
        if any(p.name not in point.parameters for p in ctx.model.parameters):
            return None
        key = ("probe", *sorted((k, str(v)) for k, v in point.parameters.items()))
        if key not in ctx.analyses:
            ctx.analyses[key] = cls(ctx.model, point.parameters)
        return ctx.analyses[key]

    def numbers(self, point: Point) -> tuple[dict[str, int], dict[str, int]]:
        values = []
        for j in self.joints:
            if j.type == "revolute":
                angle = point.revolute.get(j.name, ExactAngle(0, 1))
                values.append((angle.num, angle.den))
            else:
                v = sp.Rational(point.prismatic.get(j.name, 0))
                values.append((int(v.p), int(v.q)))
        rows = self.chain.rows(self.field, values)
        d, n = self.model.object_dim, self.chain.n
        m, r = len(rows), len(self.joints)

        q = np.array([[int(x.p) / int(x.q) for x in row] for row in rows],  # float-ok
                     dtype=float).reshape(m, n)

        def rank(a: np.ndarray) -> int:
            return int(np.linalg.matrix_rank(a)) if a.size else 0  # float-ok

        exact = matrix.rank_triple(rows, n, d, matrix.RATIONALS, self.arms)  # arm by arm
        exact_numbers = numbers_from_ranks(m, r, *exact.triple, dim=d)
        float_ranks = numbers_from_ranks(m, r, rank(q), rank(q[:, :d]), rank(q[:, d:]),
                                         dim=d)
        return exact_numbers.as_dict(), float_ranks.as_dict()


def _nudged(point: Point, joint: str, distance: float):  # float-ok: chooses a point
    """An exact angle about ``distance`` above the joint's."""
    return point.revolute[joint].nudged(distance)


def family_witness(ctx: SearchContext, comp: Component, f, x: str, inner: dict,
                   numbers: Numbers) -> None:
    """A witness on a family ``f(x, params) = 0`` (the other coordinates given by
    ``inner``): nice values for the parameters, then a rational root of what is left
    in ``x`` if there is one, else a real algebraic one."""
    k = ctx.ring_names.index(x)
    params = [n for n in vars_of(ctx, f) if n != x]
    zctx = ctx.ring.zctx
    for values in itertools.islice(itertools.product(NICE, repeat=len(params)), 12):
        point = dict(zip(params, values, strict=True))
        g = f
        for n, v in point.items():
            j = ctx.ring_names.index(n)
            g = substitute(g, j, zctx.constant(-v.numerator), zctx.constant(v.denominator),
                            g.degrees()[j])
        if g.is_zero() or g.degrees()[k] == 0:
            continue
        rational, curved = roots(ctx, g, x)
        for x0 in rational:
            full = complete_point(ctx, inner, {**point, x: x0})
            if full is not None and numbers_at_values(ctx, full) == numbers:
                attach_witness(ctx, comp, to_at(ctx, full), numbers)
                return
        for g1 in curved:
            attach_algebraic_witness(ctx, comp, x, g1, point, inner, numbers)
            if comp.algebraic_witness is not None:
                return


def attach_two_root_witness(ctx: SearchContext, comp: Component, first: tuple, second: tuple,
                            numbers: Numbers) -> None:
    """A witness of the intersection of two families with irrational coordinates in
    disjoint variables: ``first`` and ``second`` are ``(x, g, values)`` (values
    polynomials in the root ``x`` of ``g``, or rationals). The other variables get nice
    values; the numbers there come from a direct analysis over ``Q(alpha, beta)``."""
    (x1, g1, v1), (x2, g2, v2) = first, second
    field1 = NumberField(univariate(ctx, g1, x1))
    roots1 = RealRoot.all_of(field1.g.coeffs())
    roots2 = RealRoot.all_of(univariate(ctx, g2, x2).coeffs())
    if not roots1 or not roots2:
        return
    dims2 = {x2, *v2}
    for offset in range(6):
        full1 = complete_algebraic(ctx, {}, x1, field1, v1, offset)
        if full1 is None:
            continue
        part1 = {n: v for n, v in full1.items() if n not in dims2}
        rows = substitute_values(ctx, ctx.rows0, part1, x1)
        rows = substitute_values(ctx, rows, v2, x2)
        tower = Tower([Quotient(g1, ctx.ring_names.index(x1)),
                       Quotient(g2, ctx.ring_names.index(x2))])
        if numbers_modulo(rows, ctx.model, ctx.row_contacts, tower) != numbers:
            continue
        root1, root2 = roots1[0], roots2[0]
        point = {**algebraic_point_text(ctx, part1, root1, x1,
                                        only=set(ctx.ring_names) - dims2),
                 **algebraic_point_text(ctx, v2, root2, x2, only=dims2)}
        given = {**fixed_at(ctx), **point}
        order = [j.name for j in ctx.model.joints] + [p.name for p in ctx.model.parameters]
        a1, a2 = root1.approximation(), root2.approximation()
        near = {n: (a1 if n == x1 else a2 if n == x2 else
                    value_near(part1[n], a1) if n in part1 else value_near(v2[n], a2))
                for n in ctx.ring_names}
        comp.algebraic_witness = {
            "point": {k: given[k] for k in order if k in given},
            "alpha": f"{x1}, {x2}",
            "root_of": "; ".join(sp.sstr(poly_to_sympy(g, ctx.ring, ctx.symbols))
                                 for g in (g1, g2)),
            "root": f"{sp.sstr(root1.expression())}; {sp.sstr(root2.expression())}",
            "interval": [f"{root1.lo}; {root2.lo}", f"{root1.hi}; {root2.hi}"],
            "approx": _approximations(ctx, point, near),
        }
        comp.witness_checked = True
        comp.shown = WitnessMotions(numbers, ctx.model.joint_names, frozenset(comp.changes),
                                    object_dim=ctx.model.object_dim)
        approx_at = to_at(ctx, near)
        if approx_at is not None:
            comp.float_checks = float_image_checks(ctx, approx_at, analysis_at(ctx, approx_at),
                                                   numbers, comp.equations)
        return
