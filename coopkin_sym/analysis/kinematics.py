"""Contact kinematics: the matrices G, D, H and Q of the paper, exactly.

Link poses come from the product of exponentials of the home pose: joint ``k`` of an
arm moves everything outboard of it by a rotation about (or a translation along) its
home axis, and the pose of link ``K`` is ``M_1(q_1) ... M_K(q_K)``. A free revolute
angle enters through ``t = tan(q/2)``, so every entry is a rational function of the
ring variables whose denominator is a product of ``1 + t_j**2``; a fixed angle enters
through its exact cosine and sine (q = pi included).

Conventions: object twist ``u = (v, w)`` with the reference point
at the base origin; contact velocities stacked all linear blocks first, then all
angular; ``G^T`` maps ``u`` to the object's contact-frame velocities, ``D`` maps
``qdot`` to the links' ones, ``H`` keeps the components each contact model
constrains; ``Q = (H G^T | -H D)``.

A planar system (``planar: true``) keeps the in-plane components: object twist
``(v_x, v_y, w_z)``, contact velocities ``(v_x, v_y)`` of every contact then ``w_z``
of every contact; each contact model keeps the components of its entry in
:mod:`coopkin_sym.model.contacts` (a hard contact, point with friction, ``v_x, v_y``,
a frictionless one ``v.n``, a complete one also ``w_z``). With joints about z (or
sliding in the plane) and contacts in the plane the dropped components of the
spatial matrices are identically zero, so this is the spatial analysis restricted
to the plane.

Example
-------
>>> from coopkin_sym.model.model import load_model
>>> from coopkin_sym.model.configuration import Configuration
>>> m = load_model("paper-case1-hard")
>>> k = build(m, Configuration())
>>> len(k.Q), len(k.Q[0])          # 6 constrained components, 6 + 2 unknowns
(6, 8)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import sympy as sp

from coopkin_sym.exact.angles import tangent_name
from coopkin_sym.exact.deadline import check
from coopkin_sym.exact.parse import exact_expr
from coopkin_sym.exact.ratfunc import RatFunc
from coopkin_sym.exact.rationals import to_fmpq
from coopkin_sym.exact.ring import Ring
from coopkin_sym.exact.sympy_bridge import poly_from_sympy
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.contacts import contact_kind
from coopkin_sym.model.model import Model

Vec = list[RatFunc]
Mat = list[list[RatFunc]]

#: The columns of the spatial ``G^T`` a planar system keeps: ``v_x, v_y, w_z``.
PLANAR_COLUMNS = (0, 1, 5)


@dataclass(frozen=True)
class Kinematics:
    """The exact matrices of one system at one (possibly symbolic) configuration.

    Attributes
    ----------
    ring
        The polynomial ring of the analysis: free joint variables (``t_<joint>`` for
        revolute, the joint name for prismatic), then free parameters.
    symbols
        SymPy symbol of each ring variable (parameters are the model's symbols).
    GT, D, H, Q
        ``G^T`` (6n x 6), ``D`` (6n x r), ``H`` (m x 6n), ``Q`` (m x (6+r)), entries
        :class:`~coopkin_sym.exact.ratfunc.RatFunc` (3n, 3 and 3 + r for a planar system).
    row_labels
        What each row of ``H`` and ``Q`` constrains, e.g. ``"c1: v_x"``, ``"c2: w.n"``.
    row_contacts
        Index (in the model's contacts) of the contact each row of ``H`` and ``Q``
        belongs to.
    points, normals
        Current contact points and normals (normals ``None`` where not given).
    axes, origins
        Current joint axes and points on them (``None`` for a prismatic joint
        without a point).

    Example
    -------
    >>> from coopkin_sym.model import load_model
    >>> from coopkin_sym.model.configuration import Configuration
    >>> model = load_model("paper-case1-hard")
    >>> kin = build(model, Configuration.parse(model, "q1=pi/2,q2=pi/2,L=1"))
    >>> len(kin.Q), len(kin.Q[0]), kin.row_labels[0]
    (6, 8, 'c1: v_x')
    """

    ring: Ring
    symbols: dict[str, sp.Symbol]
    GT: Mat
    D: Mat
    H: Mat
    Q: Mat
    row_labels: list[str]
    row_contacts: list[int]
    points: list[Vec]
    normals: list[Vec | None]
    axes: list[Vec]
    origins: list[Vec | None]

    @property
    def object_dim(self) -> int:
        """Components of an object twist: the object columns of ``Q`` (6, or 3)."""
        return len(self.GT[0]) if self.GT else 6


def ring_for(model: Model, config: Configuration) -> tuple[Ring, dict[str, sp.Symbol]]:
    """The ring of the analysis: free joints in model order, then unset parameters."""
    names: list[str] = []
    den: list[str] = []
    symbols: dict[str, sp.Symbol] = {}
    for j in model.joints:
        if j.name in config.free:
            v = tangent_name(j.name) if j.type == "revolute" else j.name
            names.append(v)
            symbols[v] = sp.Symbol(v, real=True)
            if j.type == "revolute":
                den.append(v)
    for p in model.parameters:
        if p.name not in config.parameters:
            names.append(p.name)
            symbols[p.name] = p
    return Ring(names, den), symbols


class _Builder:
    def __init__(self, model: Model, config: Configuration):
        self.model = model
        self.config = config
        self.ring, self.symbols = ring_for(model, config)
        self.param_subs = {p: config.parameters[p.name] for p in model.parameters
                           if p.name in config.parameters}
        self._numbers: dict = {}   # each model number read once (it recurs in every pose)

    # exact numbers of the model, as rational functions of the ring
    def num(self, expr) -> RatFunc:
        if getattr(expr, "is_Rational", False) or type(expr) is int:
            return self.ring.ratfunc(to_fmpq(expr))     # a number: no polynomial to read
        value = self._numbers.get(expr)
        if value is None:
            e = exact_expr(expr, None, "value")
            e = e.subs(self.param_subs) if self.param_subs else e
            value = self._numbers[expr] = self.ring.ratfunc(
                poly_from_sympy(e, self.ring, self.symbols))
        return value

    def vec(self, v: Sequence) -> Vec:
        return [self.num(x) for x in v]

    def joint_motion(self, joint) -> tuple[Mat, Vec]:
        """Rotation and translation ``x -> R x + p`` of joint ``joint`` at its value."""
        ring = self.ring
        axis = self.vec(joint.axis)
        one, zero = ring.one(), ring.zero()
        ident = [[one if i == k else zero for k in range(3)] for i in range(3)]
        if joint.type == "prismatic":
            if joint.name in self.config.free:
                d = ring.ratfunc(ring.qvar(joint.name))
            else:
                d = self.num(self.config.prismatic.get(joint.name, 0))
            return ident, [d * a for a in axis]
        if joint.name in self.config.free:
            k = ring.den_names.index(tangent_name(joint.name))
            c, s = ring.cos_of(k), ring.sin_of(k)
        else:
            angle = self.config.revolute.get(joint.name)
            if angle is None:                                 # home: q = 0
                c, s = one, zero
            else:
                c, s = (self.num(x) for x in angle.cos_sin)
        sk = skew(axis)
        sk2 = matmul(sk, sk)
        one_minus_c = one - c
        rot = [[ident[i][k] + s * sk[i][k] + one_minus_c * sk2[i][k] for k in range(3)]
               for i in range(3)]
        o = self.vec(joint.point)
        ro = matvec(rot, o)
        return rot, [o[i] - ro[i] for i in range(3)]

    def build(self) -> Kinematics:
        model, ring = self.model, self.ring
        r = len(model.joints)
        # poses of every link of every arm; current joint axes and points
        poses: list[list[tuple[Mat, Vec]]] = []
        axes: list[Vec] = []
        origins: list[Vec | None] = []
        one, zero = ring.one(), ring.zero()
        ident = [[one if i == k else zero for k in range(3)] for i in range(3)]
        for arm in model.arms:
            pose = (ident, [zero, zero, zero])
            arm_poses = [pose]
            for joint in arm.joints:
                rot, trans = pose
                axes.append(matvec(rot, self.vec(joint.axis)))
                origins.append(apply(pose, self.vec(joint.point))
                               if joint.point is not None else None)
                pose = compose(pose, self.joint_motion(joint))
                arm_poses.append(pose)
            poses.append(arm_poses)
        points, normals = [], []
        for c in model.contacts:
            pose = (ident, [zero] * 3) if c.arm is None else poses[c.arm][c.link]
            points.append(apply(pose, self.vec(c.point)))
            normals.append(matvec(pose[0], self.vec(c.normal)) if c.normal is not None
                           else None)
        n = len(model.contacts)
        GT = [[zero] * 6 for _ in range(6 * n)]
        D = [[zero] * r for _ in range(6 * n)]
        for i, c in enumerate(model.contacts):
            lin, ang = 3 * i, 3 * n + 3 * i
            sc = skew(points[i])
            for a in range(3):
                GT[lin + a][a] = one
                GT[ang + a][3 + a] = one
                for b in range(3):
                    GT[lin + a][3 + b] = -sc[a][b]
            if c.arm is None:
                continue
            off = model.joint_offset(c.arm)
            for k, joint in enumerate(model.arms[c.arm].joints[: c.link]):
                col = off + k
                if joint.name in model.locked:
                    continue   # held still: its column stays zero
                s = axes[col]
                if joint.type == "prismatic":
                    for a in range(3):
                        D[lin + a][col] = s[a]
                else:
                    arm_vec = [points[i][a] - origins[col][a] for a in range(3)]
                    lv = cross(s, arm_vec)
                    for a in range(3):
                        D[lin + a][col] = lv[a]
                        D[ang + a][col] = s[a]
        if model.object_frame is not None:
            GT = self.in_object_frame(GT, points)
        if model.planar:
            keep = [k for i in range(n) for k in (3 * i, 3 * i + 1)] + [
                3 * n + 3 * i + 2 for i in range(n)]
            GT = [[GT[k][c] for c in PLANAR_COLUMNS] for k in keep]
            D = [D[k] for k in keep]
            selected, labels, row_contacts = self.planar_selection(normals)
        else:
            selected, labels, row_contacts = self.selection(normals)
        # Q = H [G^T  -D], row by row from the rows of G^T and D that H selects
        Q = [_row_times(h, GT, model.object_dim, zero)
             + [x if x.is_zero() else -x for x in _row_times(h, D, r, zero)]
             for h in selected]
        H = _dense(selected, len(GT), zero)
        return Kinematics(ring, self.symbols, GT, D, H, Q, labels, row_contacts, points,
                          normals, axes, origins)

    def in_object_frame(self, GT: Mat, points: list[Vec]) -> Mat:
        """``G^T`` for twists ``(v, w)`` with ``v`` at the object's reference point
        ``o`` and both in the object's axes ``R``: each contact's rows become
        ``[R, -[c - o]x R]`` (linear) and ``[0, R]`` (angular)."""
        rotation, origin = self.model.object_frame
        rot = [[self.num(rotation[i, k]) for k in range(3)] for i in range(3)]
        o = self.vec(origin)
        zero = self.ring.zero()
        n = len(points)
        out = [[zero] * 6 for _ in range(6 * n)]
        for i in range(n):
            lin, ang = 3 * i, 3 * n + 3 * i
            arm = skew([points[i][a] - o[a] for a in range(3)])
            moved = matmul(arm, rot)
            for a in range(3):
                for b in range(3):
                    out[lin + a][b] = rot[a][b]
                    out[lin + a][3 + b] = -moved[a][b]
                    out[ang + a][3 + b] = rot[a][b]
        return out

    def selection(self, normals: list[Vec | None]
                  ) -> tuple[list[SparseRow], list[str], list[int]]:
        """H: linear-block rows contact by contact, then angular-block rows (each row
        as its few non-zero entries); with the rows' labels and contacts. Each contact
        keeps the components its model transmits
        (:attr:`~coopkin_sym.model.contacts.ContactKind.spatial`)."""
        n = len(self.model.contacts)
        return self._select(normals, lambda i: (3 * i, 3 * n + 3 * i), 3, planar=False)

    def planar_selection(self, normals: list[Vec | None]
                         ) -> tuple[list[SparseRow], list[str], list[int]]:
        """H of a planar system over the components ``(v_x, v_y)`` of every contact,
        then ``w_z`` of every contact (each row as its few non-zero entries); with the
        rows' labels and contacts (the components of
        :attr:`~coopkin_sym.model.contacts.ContactKind.planar`)."""
        n = len(self.model.contacts)
        return self._select(normals, lambda i: (2 * i, 2 * n + i - 2), 2, planar=True)

    def _select(self, normals: list[Vec | None], starts, width: int, planar: bool
                ) -> tuple[list[SparseRow], list[str], list[int]]:
        """The rows of H: contact ``i``'s linear components start at column
        ``starts(i)[0]``, its angular ones at ``starts(i)[1]`` (``x`` there, ``z`` two
        further), a normal component spans ``width`` columns."""
        one = self.ring.one()
        lin_rows: list[SparseRow] = []
        ang_rows: list[SparseRow] = []
        labels: tuple[list[str], list[str]] = ([], [])
        owners: tuple[list[int], list[int]] = ([], [])
        for i, c in enumerate(self.model.contacts):
            lin, ang = starts(i)
            linear = {a: [(lin + k, one)] for k, a in enumerate("xyz"[:width])}
            angular = {a: [(ang + "xyz".index(a), one)] for a in ("z" if planar else "xyz")}
            normal = normals[i]

            def along(rows: list[SparseRow], normal=normal) -> SparseRow:
                return [(col, normal[a] * v) for a, row in enumerate(rows)
                        for col, v in row if not normal[a].is_zero()]
            comps = contact_kind(c.model).components(planar)  # type: ignore[union-attr]
            picked = pick_rows(comps, linear, angular, along)
            for block, (rows, out) in enumerate(zip(picked, (lin_rows, ang_rows),
                                                    strict=True)):
                out += rows
                labels[block].extend(f"{c.name}: {x}" for x in comps
                                     if (x[0] == "w") == bool(block))
                owners[block].extend([i] * len(rows))
        return lin_rows + ang_rows, labels[0] + labels[1], owners[0] + owners[1]


def pick_rows(components: Sequence[str], linear: dict, angular: dict, along
              ) -> tuple[list, list]:
    """The rows a contact transmits (its model's ``components``, see
    :mod:`coopkin_sym.model.contacts`), linear then angular: ``linear`` and
    ``angular`` map an axis letter to the row of that velocity component,
    ``along(rows)`` combines the rows of a block into the component along the normal.

    Example
    -------
    >>> pick_rows(("v_x", "v_y", "w.n"), {"x": "vx", "y": "vy"}, {"z": "wz"},
    ...           lambda rows: "+".join(rows))
    (['vx', 'vy'], ['wz'])
    """
    lin: list = []
    ang: list = []
    for comp in components:
        rows, out = (linear, lin) if comp[0] == "v" else (angular, ang)
        out.append(along(list(rows.values())) if comp.endswith(".n") else rows[comp[-1]])
    return lin, ang


#: A row of H as its non-zero entries: (column, value) pairs.
SparseRow = list[tuple[int, RatFunc]]


def _dense(rows: list[SparseRow], width: int, zero: RatFunc) -> Mat:
    out = []
    for entries in rows:
        row = [zero] * width
        for k, x in entries:
            row[k] = x
        out.append(row)
    return out


def _row_times(h: SparseRow, m: Mat, width: int, zero: RatFunc) -> list[RatFunc]:
    """The row ``h m`` (``m`` has ``width`` columns), over the few non-zero entries of
    ``h`` only: a row of H selects one to three rows of ``G^T -D``, so Q costs its size,
    not its size times the number of contacts."""
    check("the kinematics (Q)")
    support = [(hk, m[k]) for k, hk in h]
    out = []
    for j in range(width):
        acc = None
        for hk, row in support:
            x = row[j]
            if x.is_zero():
                continue
            term = hk * x
            acc = term if acc is None else acc + term
        out.append(acc if acc is not None else zero)
    return out


def build(model: Model, config: Configuration) -> Kinematics:
    """G, D, H and Q of ``model`` at ``config``, exactly."""
    return _Builder(model, config).build()


def q_at_pi(kin: Kinematics, joints: Sequence[str]
            ) -> tuple[Ring, dict[str, sp.Symbol], Mat] | None:
    """The ring, symbols and ``Q`` of ``kin`` with the free revolute ``joints`` at
    ``q = pi``, as the limits of its entries at ``t = tan(q/2) = oo`` (no pose is
    multiplied again); ``None`` when an entry has no such limit in its form
    (:meth:`Ring.at_infinity`). Every entry is a polynomial in ``cos q`` and
    ``sin q``, so its limit is its value at ``q = pi``: the ``Q`` of :func:`build` at
    the configuration with ``joints`` at pi.

    Example
    -------
    >>> from coopkin_sym.model.model import load_model
    >>> m = load_model("paper-case1-hard")
    >>> c = Configuration.parse(m, "L=1", free=["q1", "q2"])
    >>> ring, symbols, Q = q_at_pi(build(m, c), ["q1"])
    >>> ring.names, Q == build(m, Configuration.parse(m, "q1=pi,L=1", free=["q2"])).Q
    (('t_q2',), True)
    """
    names = [tangent_name(j) for j in joints]
    ring, limit = kin.ring.at_infinity(names)
    check("the kinematics at q = pi")
    Q = [[limit(f) for f in row] for row in kin.Q]
    if any(f is None for row in Q for f in row):
        return None
    return ring, {n: s for n, s in kin.symbols.items() if n not in names}, Q


# --- small exact 3-vector algebra on RatFunc ------------------------------------------
def skew(v: Vec) -> Mat:
    """Cross-product matrix ``S(v)`` with ``S(v) x = v x x``."""
    z = v[0].ring.zero()
    return [[z, -v[2], v[1]], [v[2], z, -v[0]], [-v[1], v[0], z]]


def cross(a: Vec, b: Vec) -> Vec:
    check("the kinematics (link velocities)")
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def matmul(a: Mat, b: Mat) -> Mat:
    check("the kinematics (link poses)")
    return [[sum((a[i][k] * b[k][j] for k in range(3)), a[0][0].ring.zero()) for j in range(3)]
            for i in range(3)]


def matvec(a: Mat, v: Vec) -> Vec:
    check("the kinematics (link poses)")
    return [sum((a[i][k] * v[k] for k in range(3)), v[0].ring.zero()) for i in range(3)]


def apply(pose: tuple[Mat, Vec], x: Vec) -> Vec:
    rot, trans = pose
    rx = matvec(rot, x)
    return [rx[i] + trans[i] for i in range(3)]


def compose(outer: tuple[Mat, Vec], inner: tuple[Mat, Vec]) -> tuple[Mat, Vec]:
    """``outer o inner``: apply ``inner`` first."""
    r1, p1 = outer
    r2, p2 = inner
    return matmul(r1, r2), apply(outer, p2)


def spatial_twist(u: Sequence) -> list:
    """An object twist as the six components ``(v, w)``: a planar one ``(v_x, v_y,
    w_z)`` is ``(v_x, v_y, 0, 0, 0, w_z)``; a spatial one is returned as it is.

    Example
    -------
    >>> spatial_twist([1, 2, 3])
    [1, 2, 0, 0, 0, 3]
    """
    if len(u) == len(PLANAR_COLUMNS):
        out = [sp.Integer(0)] * 6
        for value, c in zip(u, PLANAR_COLUMNS, strict=True):
            out[c] = value
        return out
    return list(u)


def twist_in_base(u: Sequence, frame) -> list[sp.Expr]:
    """An object twist written in an object frame (``v`` at its reference point, both
    parts in its axes), as ``(v, w)`` with ``v`` at the base origin in base axes:
    ``w = R w'``, ``v = R v' - w x o``. ``frame`` None is the base frame itself.

    Example
    -------
    >>> rotation = sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 1]])   # yaw pi/2
    >>> twist_in_base([0, 0, 0, 0, 0, 1], (rotation, (1, 0, 0)))   # spin about o
    [0, -1, 0, 0, 0, 1]
    >>> twist_in_base([0, 0, 1], (rotation, (1, 0, 0)))            # planar (v_x, v_y, w_z)
    [0, -1, 1]
    """
    if frame is None:
        return list(u)
    if len(u) == len(PLANAR_COLUMNS):
        spatial = twist_in_base(spatial_twist(u), frame)
        return [spatial[c] for c in PLANAR_COLUMNS]
    rotation, origin = frame
    r = sp.Matrix(rotation)
    v = r * sp.Matrix(list(u[:3]))
    w = r * sp.Matrix(list(u[3:]))
    v = v - w.cross(sp.Matrix(list(origin)))
    return [sp.expand(x) for x in (*v, *w)]
