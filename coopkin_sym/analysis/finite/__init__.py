"""Finite mobility: the local dimension of the closed system's configuration space.

The seven numbers are first-order. With holonomic contacts (hard, complete, and
frictionless ones read as a point on a flat face of the object) arms and object form
a linkage whose configurations ``V`` are the zeros of a constraint map ``F``
(:mod:`.constraints`); its expansion at a configuration, exact to a stated order and
reduced to the first-order motions (:mod:`.reduce`), says whether they are finite:

* ``rank J`` equal to the number of rows (a submersion), or to the generic rank of
  ``Q`` with hard and complete contacts only (the rank of ``DF`` is that of ``Q`` at
  every nearby point, so it is constant): ``V`` is smooth there, of dimension
  ``n = dim ker J``, by the constant rank theorem;
* otherwise the reduced equations ``g`` decide: the real zeros of their initial forms
  hold the real tangent cone, so none but the origin means an isolated configuration
  (dimension 0: shaky when first-order motions exist); one equation whose initial form
  has real zeros where its gradient does not vanish gives, by the implicit function
  theorem after a blow-up, real branches of dimension ``n - 1`` tangent to them (two
  hyperplanes: a bifurcation; an irreducible quadratic cone: a cone point); binary
  forms give one branch per simple real root. Anything else is undecided at the order
  reached, with the bounds that are proved;
* at a joint angle with an irrational ``tan(q/2)`` (``pi/3``), all of this runs over
  the number field of the configuration, every sign decided exactly
  (:mod:`.algebraic`), but for the closure saturation below;
* with complete contacts only (a welded loop), when the expansion stays undecided:
  the closure conditions dependent here are proved, by exact saturations, to vanish on
  the smooth set cut out by independent ones (:mod:`.closure`): the loop is
  overconstrained, and ``V`` is smooth of dimension ``n`` (Bennett's and Bricard's
  linkages).

Example
-------
>>> from coopkin_sym import load
>>> fm = finite_mobility(load("paper-case1-planar").model, "q1=pi/2,q2=pi/2")
>>> fm.dimension, fm.first_order, fm.classification, len(fm.branches)
(1, 2, 'bifurcation', 2)
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field, replace
from fractions import Fraction

import flint
import sympy as sp

from coopkin_sym.analysis.finite.algebraic import AlgebraicPoint, algebraic_point
from coopkin_sym.analysis.finite.closure import closure_dimension
from coopkin_sym.analysis.finite.closure_map import ClosureMap, closure_map
from coopkin_sym.analysis.finite.constraints import ConstraintMap
from coopkin_sym.analysis.finite.forms import (
    algebraic_directions,
    diagonal_form,
    field_directions,
    quadratic_matrix,
    real_directions,
)
from coopkin_sym.analysis.finite.puiseux import along_tangent
from coopkin_sym.analysis.finite.reduce import Reduced, echelon, reduce_map
from coopkin_sym.analysis.finite.reduce import inverse as _field_inverse
from coopkin_sym.errors import FiniteMobilityError
from coopkin_sym.exact.matrix import RATIONALS, rank
from coopkin_sym.exact.realroot import RealRoot, element_expression
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.contacts import contact_kind
from coopkin_sym.model.model import Model

#: The highest order tried when none is given.
DEFAULT_ORDER = 4

CLASSES = ("regular", "kinematic_singularity", "bifurcation", "cusp", "cone", "shaky",
           "undecided")


@dataclass(frozen=True)
class RootDirection:
    """An irrational branch tangent, exactly: in the two first-order motions ``free``
    (coordinates of the expansion) the branch leaves along ``(s, 1)``, ``s`` the real
    algebraic number ``root`` (its minimal polynomial over Q and an isolating interval
    with rational ends, :class:`~coopkin_sym.exact.realroot.RealRoot`); ``tangent`` is
    the branch's velocity ``(u, qdot)`` with ``s`` kept as the symbol ``s`` (each entry
    linear in it, with coefficients in the field of the configuration).

    Example
    -------
    >>> r = RealRoot.all_of([-2, 0, 0, 1])[0]              # 2^(1/3)
    >>> RootDirection(r, ("u_q1", "u_q2"), (sp.Symbol("s"), sp.Integer(1))).polynomial
    s**3 - 2
    """

    root: RealRoot
    free: tuple[str, ...]
    tangent: tuple[sp.Expr, ...]

    @property
    def polynomial(self) -> sp.Expr:
        """The minimal polynomial of ``s`` over Q (integer coefficients)."""
        return sp.Poly(list(reversed(self.root.coeffs)), sp.Symbol("s")).as_expr()

    @property
    def interval(self) -> tuple[Fraction, Fraction]:
        """The isolating interval ``(lo, hi]`` of ``s``, rational ends."""
        return self.root.lo, self.root.hi


@dataclass(frozen=True)
class Branch:
    """One branch of the closed system's motions through the configuration: its
    ``dimension``, and its tangent space as exact velocity vectors ``(u, qdot)`` (the
    columns of ``Q``: ``Q v = 0``), or, for a cone, the quadratic form whose zeros
    (velocities ``v``) it is (``cone``, a SymPy expression in ``v1, v2, ...``). A
    tangent leaving along an irrational root of a binary form (degree three or more:
    ``CRootOf`` in :attr:`tangent`) also has it as its minimal polynomial and an
    isolating interval (``direction``, :class:`RootDirection`).

    Example
    -------
    >>> Branch(1, ((0, 0, 1),)).dimension
    1
    """

    dimension: int
    tangent: tuple[tuple, ...] | None = None
    cone: sp.Expr | None = None
    direction: RootDirection | None = None


@dataclass(frozen=True)
class FiniteMobility:
    """The local dimension of the configuration space at one configuration.

    Attributes
    ----------
    dimension
        The finite mobility (None when undecided).
    bounds
        ``(lower, upper)`` proved (equal when decided).
    first_order
        The dimension of the first-order motions (``dim ker Q`` without the joints
        held still).
    classification
        One of :data:`CLASSES`.
    reason
        How it was decided (``"submersion"``, ``"constant_rank"``, ``"real_cone_origin"``,
        ``"cone_regular_points"``, ``"binary_form_roots"``, ``"closure_saturation"``), or
        why not.
    branches
        The motion branches through the point (when decided).
    orders
        ``(i, m_i)``: the dimension of the first-order motions that extend to order
        ``i`` (for the orders decided).
    order
        The order of the expansion used.
    assumptions
        What the model was read as (``"frictionless_flat_face"``, ``"unit_length"``).
    equations
        The reduced constraints (texts, to :attr:`order`) when they were needed.
    group_motions
        Object rotations that keep every contact with the joints still (a group acting
        on the configuration space, :func:`stabilizer`): split off before the
        expansion, counted in :attr:`dimension` and in every branch.

    Example
    -------
    >>> from coopkin_sym import load
    >>> finite_mobility(load("paper-case1-planar").model, "q1=2*atan(1/2),q2=0").reason
    'submersion'
    """

    dimension: int | None
    bounds: tuple[int, int]
    first_order: int
    classification: str
    reason: str
    branches: tuple[Branch, ...] = ()
    orders: tuple[tuple[int, int], ...] = ()
    order: int = 1
    assumptions: tuple[str, ...] = ()
    equations: tuple[str, ...] = field(default=(), compare=False)
    group_motions: tuple[tuple, ...] = ()
    #: The number field of a configuration with an irrational ``tan(q/2)``
    #: (``alpha``, ``minimal_polynomial``, ``tangents``), None at a rational one.
    field: dict | None = None
    #: Which columns of the paper's blocks are finite motions' velocities
    #: (:class:`~coopkin_sym.analysis.finite.columns.ColumnVerdict`; asked of an
    #: analysis, which has the blocks), empty otherwise.
    columns: tuple = dataclasses.field(default=(), compare=False)


def _sym(x) -> sp.Expr:
    """An exact number (``fmpq``, ``Fraction``, a number-field element) in SymPy."""
    if hasattr(x, "field") and hasattr(x, "value"):
        root = x.field.expression if x.field.expression is not None else x.field.root
        return element_expression(x.value, root)
    if isinstance(x, sp.Basic):
        return x
    return sp.Rational(str(x))


def stabilizer(cmap: ConstraintMap) -> tuple[list[list], list[tuple]]:
    """The object motions that keep every contact with the joints still, when they
    form a group acting on the configuration space: with hard contacts only, the
    rotations about the line through all contact points (collinear ones), or about the
    one point (all at one place). Returns the slice (linear forms in the coordinates,
    transversal to its orbits: the rotation coordinates along the group's axes) and the
    group's velocities ``(u, qdot)``; both empty when there is no such group.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.model.configuration import Configuration
    >>> m = load("paper-case1-hard").model
    >>> cmap = ConstraintMap(m, Configuration.parse(m, "q1=0,q2=0,L=1"))
    >>> stabilizer(cmap)
    ([[0, 0, 0, 1, 0, 0, 0, 0]], [(0, 0, -1, 1, 0, 0, 0, 0)])
    """
    points = cmap.contact_points()
    if not points or any(contact_kind(m).position != "point" for _, m in points):
        return [], []
    algebraic = cmap.point is not None
    base = [x if algebraic else sp.Rational(str(x)) for x in points[0][0]]
    spread = [[(x if algebraic else sp.Rational(str(x))) - b
               for x, b in zip(pt, base, strict=True)] for pt, _ in points[1:]]
    span = echelon(spread)[0] if algebraic else rank(spread, 3, RATIONALS)
    if cmap.planar:
        axes = [(0, 0, 1)] if span == 0 else []
    elif span == 0:
        axes = [(1, 0, 0), (0, 1, 0), (0, 0, 1)]
    elif span == 1:
        d = next(row for row in spread if any(row))
        axes = [tuple(d)]
    else:
        axes = []
    nobj = 3 if cmap.planar else 6
    njoints = len(cmap.joint_names)
    rows, motions = [], []
    for a in axes:
        row = [0] * len(cmap.names)
        if cmap.planar:
            row[2] = 1
        else:
            for k in range(3):
                row[3 + k] = a[k]
        rows.append(row)
        omega = sp.Matrix([_sym(x) for x in a])
        v = sp.Matrix([_sym(x) for x in base]).cross(omega)
        v = v.applyfunc(sp.radsimp) if algebraic else v          # velocity of the origin: c x a
        twist = [v[0], v[1], omega[2]] if cmap.planar else list(v) + list(omega)
        motions.append(tuple(twist) + (0,) * njoints)
    del nobj
    return rows, motions


def _generic_rank(model: Model, config: Configuration,
                  point: AlgebraicPoint | None = None) -> tuple[int | None, bool]:
    """The rank of ``Q`` over the joint variables (None unless it is certified: an
    uncertified one could be too low, and a smooth point would not be proved), and
    whether the seven numbers at ``config`` differ from the generic ones (over the
    number field of ``point`` for the joints it holds)."""
    from coopkin_sym.analysis import kinematics
    from coopkin_sym.analysis.decomposition import decompose
    from coopkin_sym.analysis.generic import generic_numbers

    if point is None:
        kin = kinematics.build(model, config)
        here = decompose([kin.ring.clear_row(r) for r in kin.Q], model, kin.row_contacts,
                         kin.ring.zctx).numbers
    else:
        from coopkin_sym.analysis.field_rows import field_rows, numbers_at

        here = numbers_at(field_rows(model, point.at))
    everywhere = Configuration({}, {}, dict(config.parameters),
                               frozenset(j.name for j in model.joints))
    gkin = kinematics.build(model, everywhere)
    numbers, certificate = generic_numbers([gkin.ring.clear_row(r) for r in gkin.Q], model,
                                           gkin.row_contacts, gkin.ring.zctx)
    rows = len(gkin.row_contacts)
    rank = rows - numbers.Nh if certificate.exact else None
    return rank, here.as_dict() != numbers.as_dict()


def _configuration(model: Model, at) -> tuple[Configuration, tuple[str, ...],
                                               AlgebraicPoint | None]:
    found = algebraic_point(model, at)
    point = None
    if found is not None:
        config, point = found
    else:
        config = at if isinstance(at, Configuration) else Configuration.parse(model, at)
    left = sorted(config.free - set(point.cos_sin if point is not None else ()))
    if left:
        raise FiniteMobilityError(
            f"finite mobility is asked at one configuration, but joint"
            f"{'s' if len(left) > 1 else ''} {', '.join(left)} "
            f"{'are' if len(left) > 1 else 'is'} left free (a generic or free= "
            f"analysis): give every joint a value")
    notes: tuple[str, ...] = ()
    unset = [p for p in model.parameters if p.name not in config.parameters]
    if len(unset) == 1 and len(model.parameters) == 1:
        params = dict(config.parameters)
        params[unset[0].name] = sp.Integer(1)
        config = Configuration(config.revolute, config.prismatic, params, config.free)
        notes = ("unit_length",)
        if point is not None:
            point = point.with_parameter(unset[0].name, "1")
    return config, notes, point


def _velocity(cmap: ConstraintMap, red: Reduced, x: list) -> tuple:
    """The velocity ``(u, qdot)`` (columns of ``Q``) of the first-order motion with
    free coordinates ``x``: the pivots follow by ``J z = 0``, and ``v = S z`` with the
    joints held still at 0."""
    names = cmap.names
    jac = cmap.linear()
    z = {name: sp.Rational(0) for name in names}
    for name, value in zip(red.free, x, strict=True):
        z[name] = sp.nsimplify(value) if not isinstance(value, sp.Basic) else value
    if red.pivots and cmap.point is not None:
        # y = -(A^-1 B) x with A^-1 B computed over the number field, then written
        # in radicals once (x may hold a square root outside the field)
        piv = [names.index(p) for p in red.pivots]
        rows = list(red.rows)
        frees = [names.index(f) for f in red.free]
        inv = _field_inverse([[jac[i][j] for j in piv] for i in rows])
        for k, p in enumerate(red.pivots):
            coeffs = [sum((inv[k][r] * jac[i][j] for r, i in enumerate(rows)),
                          cmap.point.field.number(0)) for j in frees]
            z[p] = -sum((_sym(c) * z[f] for c, f in zip(coeffs, red.free, strict=True)
                         if c), sp.Integer(0))
    elif red.pivots:
        piv = [names.index(p) for p in red.pivots]
        rows = list(red.rows)
        a = sp.Matrix([[_sym(jac[i][j]) for j in piv] for i in rows])
        b = sp.Matrix([sum((_sym(jac[i][names.index(f)]) * z[f]
                            for f in red.free), sp.Rational(0)) for i in rows])
        y = -a.LUsolve(b)
        for k, p in enumerate(red.pivots):
            z[p] = sp.simplify(y[k]) if cmap.point is None else sp.radsimp(y[k])
    if isinstance(cmap, ClosureMap):        # the object's coordinates, left out there
        z, cmap = cmap.extend(z), cmap.base
        names = cmap.names
    scale = cmap.scale
    velocity = [scale[k] * z[name] for k, name in enumerate(names)]
    velocity = [sp.radsimp(sp.expand(v)) if isinstance(v, sp.Basic) and not v.is_Rational
                else v for v in velocity]          # radicals written out simply
    nobj = 3 if cmap.planar else 6
    out = velocity[:nobj]
    moving = iter(velocity[nobj:])
    for k in range(len(cmap.joint_names)):
        out.append(next(moving) if k in cmap.moving else sp.Integer(0))
    return tuple(out)


def _kernel(cmap: ConstraintMap, red: Reduced, basis: list[list]) -> tuple[tuple, ...]:
    return tuple(_velocity(cmap, red, x) for x in basis)


def _unit(n: int, k: int) -> list:
    return [sp.Integer(int(i == k)) for i in range(n)]


def _hyperplane(form: list) -> list[list]:
    """A basis of the zeros of the linear form with coefficients ``form``."""
    n = len(form)
    k = next(i for i in range(n) if form[i] != 0)
    basis = []
    for j in range(n):
        if j == k:
            continue
        v = _unit(n, j)
        v[k] = -form[j] / form[k]
        basis.append(v)
    return basis


def _decide_singular(cmap: ConstraintMap, red: Reduced) -> dict:
    """What the reduced equations prove at a rank drop (see the module's text)."""
    n = red.n
    field = cmap.series_field(red.free, red.order)
    algebraic = cmap.point is not None
    lows = [field.lowest(g) for g in red.g]
    forms = [(d, h) for d, h in lows if d <= red.order]
    vanishing = len(lows) - len(forms)
    upper = n - 1 if forms else n
    out = {"bounds": (0, upper), "classification": "undecided", "dimension": None,
           "reason": f"undecided_at_order_{red.order}", "branches": (),
           "orders": tuple((i, n) for i in range(1, min([d for d, _ in forms] +
                                                         [red.order + 1])))}
    if n == 0:
        return dict(out, bounds=(0, 0), dimension=0, classification="regular",
                    reason="no_first_order_motion")
    isolated = _only_origin([h for _, h in forms], n, field if algebraic else None)
    if isolated:
        lowest = min(d for d, _ in forms)
        return dict(out, bounds=(0, 0), dimension=0, classification="shaky",
                    reason="real_cone_origin", orders=out["orders"] + ((lowest, 0),))
    if vanishing or len(forms) != 1:
        return out
    d, h = forms[0]
    if d == 2:
        ds, lins = diagonal_form(quadratic_matrix(h, n, field.coefficients(h)
                                                  if algebraic else None))
        pos, neg = sum(1 for x in ds if x > 0), sum(1 for x in ds if x < 0)
        if not (pos and neg):                 # semidefinite: in two motions, a
            out = dict(out, bounds=(0, n - len(ds)))    # double tangent, or undecided
            return _binary_branches(cmap, red, h, d, out) if n == 2 else out
        out = dict(out, bounds=(n - 1, n - 1), dimension=n - 1,
                   reason="cone_regular_points", orders=((1, n), (2, n - 1)))
        if len(ds) == 2 and n == 2:
            a, b = (ds[0], ds[1]) if ds[0] > 0 else (ds[1], ds[0])
            lin_a, lin_b = (lins[0], lins[1]) if ds[0] > 0 else (lins[1], lins[0])
            if algebraic:
                root = sp.sqrt(sp.radsimp(_sym(-b / a)))
            else:
                root = sp.sqrt(sp.Rational(-b.numerator, b.denominator)
                               / sp.Rational(a.numerator, a.denominator))
            planes = []
            for sign in (1, -1):
                form = [_sym(x) for x in lin_a]
                other = [_sym(x) for x in lin_b]
                planes.append([(sp.radsimp if algebraic else sp.nsimplify)(
                    form[i] - sign * root * other[i] / 1) for i in range(n)])
            branches = tuple(Branch(n - 1, _kernel(cmap, red, _hyperplane(p)))
                             for p in planes)
            return dict(out, classification="bifurcation", branches=branches)
        cone = sp.expand(sum(_sym(x) * sum(_sym(c) * sp.Symbol(f"x{i + 1}")
                                           for i, c in enumerate(lin)) ** 2
                             for x, lin in zip(ds, lins, strict=True)))
        return dict(out, classification="cone", branches=(Branch(n - 1, None, cone),))
    if n == 2:
        return _binary_branches(cmap, red, h, d, out)
    return out


def _binary_branches(cmap: ConstraintMap, red: Reduced, h, d: int, out: dict) -> dict:
    """In two first-order motions, one branch per simple real root of the lowest form
    ``h`` (of degree ``d``), each with its exact tangent (:class:`RootDirection` when
    irrational); ``out`` (undecided) when a real root is multiple."""
    if cmap.point is not None:
        field = cmap.series_field(red.free, red.order)
        directions, multiple = field_directions(field.coefficients(h), cmap.point.field)
    else:
        directions = real_directions([h], 2)
        multiple = any(m > 1 for _, m in directions)
    if multiple and cmap.point is None and len(red.g) == 1:
        return _multiple_tangents(cmap, red, directions, d, out)
    if multiple or not directions:
        return out
    along = _velocity(cmap, red, [sp.Integer(1), sp.Integer(0)])      # x = (1, 0)
    across = _velocity(cmap, red, [sp.Integer(0), sp.Integer(1)])     # x = (0, 1)
    s = sp.Symbol("s")
    branches = []
    for (a, _b), _m in directions:
        if (a, _b) == (1, 0):
            branches.append(Branch(1, (along,)))
            continue
        root = a if isinstance(a, RealRoot) else RealRoot.all_of(
            [-int(flint.fmpq(a).p), int(flint.fmpq(a).q)])[0]
        if root.degree > 1:                 # an interval that reads: width 1/1000 at most
            root = replace(root, **dict(zip(("lo", "hi"), root.refine(Fraction(1, 1000)),
                                            strict=True)))
        tangent = tuple(sp.expand(s * x + y) for x, y in zip(along, across, strict=True))
        value = root.expression()
        exact = tuple(sp.expand(t.subs(s, value)) for t in tangent)
        if cmap.point is not None:
            exact = tuple(sp.radsimp(x) for x in exact)
        branches.append(Branch(1, (exact,), direction=None if root.degree == 1 else
                               RootDirection(root, tuple(red.free), tangent)))
    kind = "bifurcation" if len(branches) > 1 else "kinematic_singularity"
    return dict(out, bounds=(1, 1), dimension=1, classification=kind,
                reason="binary_form_roots", branches=tuple(branches),
                orders=tuple((i, 2) for i in range(1, d)) + ((d, 1),))


def _multiple_tangents(cmap: ConstraintMap, red: Reduced, directions: list, d: int,
                       out: dict) -> dict:
    """Two first-order motions, one reduced constraint whose lowest form (degree
    ``d``) has a multiple real root: the real branches along every real tangent by
    Newton's polygon (:mod:`.puiseux`; simple tangents make one smooth branch each),
    or ``out`` (undecided) where that does not decide them."""
    branches, singular = [], 0
    along = _velocity(cmap, red, [sp.Integer(1), sp.Integer(0)])      # x = (1, 0)
    across = _velocity(cmap, red, [sp.Integer(0), sp.Integer(1)])     # x = (0, 1)
    for (a, b), m in directions:
        if isinstance(a, RealRoot):
            return out                       # an irrational tangent: not done here
        direction = (a, b)
        if (a, b) == (1, 0):
            tangent = along
        else:
            s = sp.Rational(str(flint.fmpq(a)))
            tangent = tuple(sp.expand(s * x + y) for x, y in zip(along, across, strict=True))
        count = 1
        if m > 1:
            found = along_tangent(red.g[0], direction, red.order)
            if found is None:
                return out
            count, singular = found.branches, singular + found.singular
        branches += [Branch(1, (tangent,))] * count
    orders = tuple((i, 2) for i in range(1, d)) + ((d, 1 if branches else 0),)
    if not branches:
        return dict(out, bounds=(0, 0), dimension=0, classification="shaky",
                    reason="newton_polygon", orders=orders)
    kind = ("cusp" if singular and len(branches) == 1 else
            "bifurcation" if len(branches) > 1 else "kinematic_singularity")
    return dict(out, bounds=(1, 1), dimension=1, classification=kind,
                reason="newton_polygon", branches=tuple(branches), orders=orders)


def _closure_expansion(cmap: ConstraintMap, orders: list[int], notes: tuple,
                       where: dict | None) -> FiniteMobility | None:
    """The finite mobility decided by expanding the loop closure's polynomials instead
    of the constraint map (:mod:`.closure_map`: without the conditions that hold
    identically or are proved redundant), or None when that does not decide either."""
    closed = closure_map(cmap)
    if closed is None or len(closed.polys) >= len(cmap.linear()):
        return None
    for k in orders:
        red = reduce_map(closed, k)
        if red.n != reduce_map(cmap, 1).n:          # not the same first-order motions
            return None
        found = _decide_singular(closed, red)
        if found["dimension"] is not None:
            return FiniteMobility(found["dimension"], found["bounds"], red.n,
                                  found["classification"], found["reason"],
                                  found["branches"], found["orders"], k,
                                  notes + ("closure_expansion",),
                                  tuple(str(g) for g in red.g), (), where)
    return None


def _only_origin(forms: list, n: int, field=None) -> bool:
    """Whether the common real zeros of homogeneous forms in ``n`` variables are the
    origin alone (proved: one variable and a nonzero form; two variables and no common
    real root; or a definite quadratic form); ``field``: the series over a number
    field the forms are in (None: over Q)."""
    if not forms:
        return False
    if n == 1:
        return True
    if n == 2 and field is not None:
        return algebraic_directions([field.coefficients(h) for h in forms],
                                    field.numberfield)[0] == 0
    if n == 2:
        return real_directions(forms, 2) == []
    for h in forms:
        degree = (max(sum(m) for m in field.coefficients(h)) if field is not None
                  else h.total_degree())
        if degree == 2:
            ds, _ = diagonal_form(quadratic_matrix(
                h, n, None if field is None else field.coefficients(h)))
            if len(ds) == n and (all(x > 0 for x in ds) or all(x < 0 for x in ds)):
                return True
    return False


def _group_orbit(found: dict, extra: int, numbers_change: bool) -> tuple[str, str]:
    """The classification and reason of ``found`` (the slice's), where every
    first-order motion may be the group's: then its orbit, smooth, is all there is."""
    if found["reason"] == "no_first_order_motion" and extra:
        return ("kinematic_singularity" if numbers_change else "regular"), "group_orbit"
    return found["classification"], found["reason"]


def finite_mobility(model: Model, at=None, order: int | None = None,
                    generic_rank: int | None = None,
                    numbers_change: bool | None = None) -> FiniteMobility:
    """The finite mobility of ``model`` at the configuration ``at`` (``--at`` syntax or
    a :class:`~coopkin_sym.model.configuration.Configuration`; every joint at a
    rational ``tan(q/2)``, ``q = pi`` included, or an algebraic one such as ``pi/3``
    given as text, computed then over its number field (:mod:`.algebraic`), and every
    parameter set, a single length set to 1 when left free), exact to ``order``
    (default: 2, 3, ... up to
    :data:`DEFAULT_ORDER`, until decided). ``generic_rank`` is the rank of ``Q`` over
    the joint variables (computed when not given); ``numbers_change`` whether the
    seven numbers here differ from the generic ones (for the words "regular" and
    "kinematic singularity").

    Example
    -------
    >>> from coopkin_sym import load
    >>> fm = finite_mobility(load("paper-case1-hard").model, "q1=pi/2,q2=pi/2")
    >>> fm.dimension, fm.first_order, fm.classification
    (2, 3, 'bifurcation')
    """
    config, notes, point = _configuration(model, at)
    cmap = ConstraintMap(model, config, point=point)
    where = None if point is None else point.as_json()
    if cmap.frictionless:
        notes = notes + ("frictionless_flat_face",)
    if generic_rank is None or numbers_change is None:
        known_rank, changed = _generic_rank(model, config, point)
        generic_rank = known_rank if generic_rank is None else generic_rank
        numbers_change = changed if numbers_change is None else numbers_change
    first = reduce_map(cmap, 1)
    n, rank, rows = first.n, first.rank, first.equations
    smooth = ("submersion" if rank == rows else "constant_rank"
              if rank == generic_rank and not cmap.frictionless else None)
    if smooth is not None:
        basis = [_unit(n, k) for k in range(n)]
        return FiniteMobility(n, (n, n), n, "kinematic_singularity" if numbers_change
                              else "regular", smooth,
                              (Branch(n, _kernel(cmap, first, basis)),),
                              tuple((i, n) for i in (1,)), 1, notes, field=where)
    orders = [order] if order is not None else list(range(2, DEFAULT_ORDER + 1))
    rows_g, motions = stabilizer(cmap)
    work = ConstraintMap(model, config, rows_g, point=point) if rows_g else cmap
    extra = len(rows_g)
    for k in orders:
        red = reduce_map(work, k)
        found = _decide_singular(work, red)
        if (found["dimension"] is None and k == orders[-1]
                and found["bounds"][1] + extra == n):      # every constraint vanishes
            proved = closure_dimension(cmap, n)
            if proved is not None:
                basis = [_unit(n, i) for i in range(n)]
                return FiniteMobility(n, (n, n), n, "kinematic_singularity"
                                      if numbers_change else "regular", proved[1],
                                      (Branch(n, _kernel(cmap, first, basis)),),
                                      ((1, n),), 1, notes, field=where)
            notes = notes + ("closure_saturation_inconclusive",)
        if (found["dimension"] is None and k == orders[-1] and not extra
                and any(g.is_zero() for g in red.g)):   # rows that vanish: the closure's
            closed = _closure_expansion(cmap, orders, notes, where)
            if closed is not None:
                return closed
        if found["dimension"] is not None or k == orders[-1]:
            lower, upper = found["bounds"]
            branches = tuple(Branch(b.dimension + extra, None if b.tangent is None else
                                    b.tangent + tuple(motions), b.cone, b.direction)
                             for b in found["branches"])
            if found["dimension"] == 0 and extra:        # the group's orbit alone
                branches = (Branch(extra, tuple(motions)),)
            dim = None if found["dimension"] is None else found["dimension"] + extra
            kind, reason = _group_orbit(found, extra, numbers_change)
            return FiniteMobility(dim, (lower + extra, upper + extra), n,
                                  kind, reason, branches,
                                  tuple((i, m + extra) for i, m in found["orders"]), k,
                                  notes, tuple(str(g) for g in red.g), tuple(motions),
                                  where)
    raise AssertionError("unreachable")  # pragma: no cover
