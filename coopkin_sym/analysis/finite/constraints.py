"""The closed system's constraint map near a configuration, as truncated power series.

With ``hard`` contacts (the contact point fixed on both bodies), ``complete`` ones (the
link welded to the object) and ``frictionless`` ones (the link's point kept on a flat
face of the object, an assumption stated in the result), arms and object form a
linkage whose configurations are the zeros of ``F(z)``, written in the object's frame
so that its Jacobian has, at *every* nearby point, the rank of ``Q`` there:

* hard: ``R(w)^T (c(z) - p) - c0`` (3 rows, 2 planar), ``c(z)`` the contact point of
  the link, ``c0`` its place at the configuration;
* complete: also ``vee(skew(R(w)^T R_link(z) R_link0^T))`` (3 rows, 1 planar);
* frictionless: ``n0 . (R(w)^T (c(z) - p) - c0)``.

The local coordinates ``z`` are the object's displacement ``p`` and Cayley rotation
vector ``w`` (``R(w) = I + 2 (W + W^2) / (1 + w.w)``), then ``u_k = tan(dq_k/2)`` for
each revolute joint (``q_k = q0_k + dq_k``: any angle, ``q = pi`` included) and the
displacement change of each prismatic one; joints held still have none. Their order is
that of the columns of ``Q``, and the rows that of its rows, so the linear part is
``J = -Q S``: ``S`` is 2 on the rotation and revolute columns, 1 elsewhere.

Example
-------
>>> from coopkin_sym.model import load_model
>>> from coopkin_sym.model.configuration import Configuration
>>> model = load_model("paper-case1-hard")
>>> cmap = ConstraintMap(model, Configuration.parse(model, "q1=pi/2,q2=pi/2,L=1"))
>>> cmap.names
('p1', 'p2', 'p3', 'w1', 'w2', 'w3', 'u_q1', 'u_q2')
>>> [str(x) for x in cmap.linear()[0]]
['-1', '0', '0', '0', '0', '0', '0', '0']
"""

from __future__ import annotations

from collections.abc import Sequence

import flint
import sympy as sp

from coopkin_sym.analysis.finite.series import AlgebraicSeriesField, SeriesField
from coopkin_sym.analysis.sweep.chains import ChainQ, RationalField, chain_data
from coopkin_sym.errors import FiniteMobilityError
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.contacts import REGISTRY, contact_kind, listed
from coopkin_sym.model.model import Model


def holonomic_models() -> tuple[str, ...]:
    """The registered contact models that put a condition on positions.

    Example
    -------
    >>> holonomic_models()
    ('complete', 'hard', 'frictionless')
    """
    return tuple(k.name for k in REGISTRY.values() if k.position)


def _cross(a, b, f: SeriesField):
    return [f.red(a[1] * b[2] - a[2] * b[1]), f.red(a[2] * b[0] - a[0] * b[2]),
            f.red(a[0] * b[1] - a[1] * b[0])]


def _apply(m, v, f: SeriesField):
    return [f.red(sum((m[i][j] * v[j] for j in range(3)), f.zero)) for i in range(3)]


def _matmul(a, b, f: SeriesField):
    return [[f.red(sum((a[i][k] * b[k][j] for k in range(3)), f.zero)) for j in range(3)]
            for i in range(3)]


def cayley(w: Sequence, f: SeriesField) -> list[list]:
    """``R(w) = I + 2 (W + W^2) / (1 + w.w)``, ``W`` the cross-product matrix of ``w``.

    Example
    -------
    >>> f = SeriesField(("a",), 3)
    >>> (a,) = f.gens
    >>> [str(x) for x in cayley([f.zero, f.zero, a], f)[0]]
    ['-2*a^2 + 1', '2*a^3 - 2*a', '0']
    """
    z = f.zero
    big_w = [[z, -w[2], w[1]], [w[2], z, -w[0]], [-w[1], w[0], z]]
    w2 = _matmul(big_w, big_w, f)
    scale = f.red(2 * f.inverse(f.one + f.red(w[0] ** 2 + w[1] ** 2 + w[2] ** 2)))
    return [[f.red((f.one if i == j else z) + scale * (big_w[i][j] + w2[i][j]))
             for j in range(3)] for i in range(3)]


def check_holonomic(model: Model) -> None:
    """Nothing when every contact of ``model`` constrains positions (finite mobility is
    defined), else the :class:`~coopkin_sym.errors.FiniteMobilityError` naming the
    first contact that does not.

    Example
    -------
    >>> from coopkin_sym.model import load_model
    >>> check_holonomic(load_model("paper-case1-soft"))
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.FiniteMobilityError: contact 1 is soft: ...
    """
    for i, contact in enumerate(model.contacts):
        kind = contact_kind(contact.model)
        if not kind.position:
            raise FiniteMobilityError(
                f"contact {i + 1} is {contact.model}: {kind.not_holonomic}, so the "
                f"system has no configuration space to expand; finite mobility is "
                f"defined for {listed(holonomic_models(), 'and')} contacts")


class ConstraintMap:
    """``F(z)`` of the closed system at ``config`` (every joint and parameter set),
    evaluated for coordinates given as series (:meth:`evaluate`).

    Raises :class:`~coopkin_sym.errors.FiniteMobilityError` for a soft contact or a
    parameter left symbolic.

    Example
    -------
    >>> from coopkin_sym.model import load_model
    >>> model = load_model("paper-case1-planar")
    >>> cmap = ConstraintMap(model, Configuration.parse(model, "q1=0,q2=0,L=1"))
    >>> cmap.names, cmap.scale
    (('p1', 'p2', 'w3', 'u_q1', 'u_q2'), [1, 1, 2, 2, 2])
    """

    def __init__(self, model: Model, config: Configuration,
                 slice_rows: Sequence[Sequence] = (), point=None):
        check_holonomic(model)
        unset = [p.name for p in model.parameters if p.name not in config.parameters]
        if unset:
            raise FiniteMobilityError(f"finite mobility needs a value for {', '.join(unset)}"
                                      " (give it with at=)")
        self.model = model
        self.config = config
        self.chain = ChainQ(chain_data(model, config, ()))
        self.planar = model.planar
        joints = self.chain.data["joints"]
        self.joint_names = [j.name for arm in model.arms for j in arm.joints]
        self.moving = [k for k, j in enumerate(joints) if not j["locked"]]
        obj = ("p1", "p2", "w3") if self.planar else ("p1", "p2", "p3", "w1", "w2", "w3")
        self.names = obj + tuple(
            ("u_" if joints[k]["kind"] == "revolute" else "d_") + self.joint_names[k]
            for k in self.moving)
        self.positions = [contact_kind(c.model).position for c in model.contacts]
        self.frictionless = "face" in self.positions
        #: The configuration over a number field (an :class:`AlgebraicPoint`: the joints
        #: with an irrational ``tan(q/2)``, left free in ``config``), or None.
        self.point = point
        self._algebraic = {} if point is None else {
            k: point.cos_sin[name] for k, name in enumerate(self.joint_names)
            if name in point.cos_sin}
        #: Linear forms in the coordinates appended as rows (a slice: see
        #: :func:`stabilizer`).
        self.slice_rows = [[c if hasattr(c, "field") else
                            flint.fmpq(int(sp.Rational(c).p), int(sp.Rational(c).q))
                            for c in row] for row in slice_rows]
        exact = RationalField() if point is None else self.series_field((), 0)
        self._home_poses, _, _ = self.chain.poses(
            exact, lambda col, spec, fixed: self._fixed(exact, col, fixed))

    def series_field(self, names: Sequence[str], order: int) -> SeriesField:
        """The truncated power series in ``names`` over the field of the configuration
        (Q, or the number field of :attr:`point`)."""
        if self.point is None:
            return SeriesField(names, order)
        return AlgebraicSeriesField(names, order, self.point.field)

    def _fixed(self, f, col: int, fixed):
        """The value of joint ``col`` at the configuration in ``f``."""
        if col in self._algebraic:
            c, s = self._algebraic[col]
            return f.lift(c), f.lift(s)
        return fixed

    @property
    def scale(self) -> list[int]:
        """``S``: the linear part is ``-Q S`` (see the module's text)."""
        obj = [1, 1, 2] if self.planar else [1, 1, 1, 2, 2, 2]
        joints = self.chain.data["joints"]
        return obj + [2 if joints[k]["kind"] == "revolute" else 1 for k in self.moving]

    def evaluate(self, f: SeriesField, z: Sequence) -> list:
        """The rows of ``F`` at the coordinates ``z`` (series in ``f``, in the order of
        :attr:`names`)."""
        planar = self.planar
        zero = f.zero
        nobj = 3 if planar else 6
        if planar:
            p, w = [z[0], z[1], zero], [zero, zero, z[2]]
        else:
            p, w = list(z[0:3]), list(z[3:6])
        rt = cayley([-x for x in w], f)            # R(w)^T = R(-w)
        values = {k: z[nobj + i] for i, k in enumerate(self.moving)}

        def value(col, spec, fixed):
            fixed = self._fixed(f, col, fixed)
            if col not in values:           # held still (fixed is in the field already)
                return fixed
            u = values[col]
            if spec["kind"] == "prismatic":
                return f.red(fixed + u)
            c0, s0 = fixed
            inv = f.inverse(f.one + f.red(u * u))
            one_minus = f.red(f.one - u * u)
            return (f.red((c0 * one_minus - 2 * s0 * u) * inv),
                    f.red((s0 * one_minus + 2 * c0 * u) * inv))

        poses, _, _ = self.chain.poses(f, value)
        home = self._home(f)
        lin_rows, ang_rows = [], []
        keep = (0, 1) if planar else (0, 1, 2)
        for (arm, link, _, _, _), (home_pt, home_nm), position in zip(
                self.chain.data["contacts"], self.chain._bound(RationalField())[1],
                self.positions, strict=True):
            if arm is None:
                c = [f.ctx.constant(x) for x in home_pt]
                c0 = list(home_pt)
            else:
                rot, trans = poses[arm][link]
                rc = _apply(rot, [f.ctx.constant(x) for x in home_pt], f)
                c = [f.red(rc[i] + trans[i]) for i in range(3)]
                rot0, trans0 = home[arm][link]
                c0 = [f.red(sum((rot0[i][j] * home_pt[j] for j in range(3)), 0) + trans0[i])
                      for i in range(3)]
            local = _apply(rt, [f.red(c[i] - p[i]) for i in range(3)], f)
            gap = [f.red(local[i] - c0[i]) for i in range(3)]
            if position == "face":
                rot0 = (home[arm][link][0] if arm is not None else
                        [[1, 0, 0], [0, 1, 0], [0, 0, 1]])
                n0 = [f.red(sum((rot0[i][j] * home_nm[j] for j in range(3)), 0))
                      for i in range(3)]
                lin_rows.append(f.red(sum((n0[i] * gap[i] for i in keep), zero)))
            else:
                lin_rows += [gap[i] for i in keep]
            if position == "weld":
                if arm is None:
                    rel = rt
                else:
                    rot0 = home[arm][link][0]
                    rot0_t = [[f.lift(rot0[j][i]) for j in range(3)]
                              for i in range(3)]
                    rel = _matmul(_matmul(rt, poses[arm][link][0], f), rot0_t, f)
                vee = [f.red((rel[2][1] - rel[1][2]) / 2), f.red((rel[0][2] - rel[2][0]) / 2),
                       f.red((rel[1][0] - rel[0][1]) / 2)]
                ang_rows += [vee[2]] if planar else vee
        extra = [f.red(sum((f.lift(c) * z[k] for k, c in enumerate(row) if c), zero))
                 for row in self.slice_rows]
        return lin_rows + ang_rows + extra

    def _home(self, f) -> list:
        """The poses at the configuration, in ``f`` (computed once over Q)."""
        if self.point is None:
            return self._home_poses
        return self.chain.poses(f, lambda col, spec, fixed: self._fixed(f, col, fixed))[0]

    def contact_points(self) -> list[tuple]:
        """Each contact's point at the configuration (exact rationals, or
        :class:`~coopkin_sym.exact.numberfield.Number` over a number field), with its
        model."""
        out = []
        exact = RationalField() if self.point is None else self.series_field((), 0)
        for (arm, link, _, _, model), (home_pt, _) in zip(
                self.chain.data["contacts"], self.chain._bound(exact)[1],
                strict=True):
            if arm is None:
                pt = tuple(home_pt)
            else:
                rot0, trans0 = self._home_poses[arm][link]
                pt = tuple(sum((rot0[i][j] * home_pt[j] for j in range(3)), 0)
                           + trans0[i] for i in range(3))
            if self.point is not None:
                pt = tuple(exact.constant_term(exact.red(x)) for x in pt)
            out.append((pt, model))
        return out

    def joint_lines(self) -> tuple[list, list]:
        """Each joint's axis and point at the configuration (exact rationals, or
        :class:`~coopkin_sym.exact.numberfield.Number` over a number field; the point
        None for a prismatic joint), by column."""
        exact = RationalField() if self.point is None else self.series_field((), 0)
        _, axes, origins = self.chain.poses(
            exact, lambda col, spec, fixed: self._fixed(exact, col, fixed))
        if self.point is None:
            return axes, origins

        def number(v):
            return None if v is None else [exact.constant_term(exact.red(x)) for x in v]
        return [number(a) for a in axes], [number(o) for o in origins]

    def contact_normals(self) -> list[tuple]:
        """Each contact's normal at the configuration (as :meth:`contact_points`; None
        when the contact has none)."""
        exact = RationalField() if self.point is None else self.series_field((), 0)
        home = self._home(exact)
        out = []
        for (arm, link, _, _, _), (_, home_nm) in zip(
                self.chain.data["contacts"], self.chain._bound(exact)[1], strict=True):
            if home_nm is None:
                out.append(None)
                continue
            rot0 = home[arm][link][0] if arm is not None else None
            nm = tuple(home_nm) if rot0 is None else tuple(
                sum((rot0[i][j] * home_nm[j] for j in range(3)), 0) for i in range(3))
            if self.point is not None:
                nm = tuple(exact.constant_term(exact.red(exact.lift(x))) for x in nm)
            out.append(nm)
        return out

    def linear(self) -> list[list]:
        """The linear part ``J`` of ``F`` at the configuration (exact rationals, or
        :class:`~coopkin_sym.exact.numberfield.Number` over a number field)."""
        f = self.series_field(self.names, 1)
        rows = self.evaluate(f, f.gens)
        n = len(self.names)
        zero = 0 if self.point is None else self.point.field.number(0)
        out = []
        for r in rows:
            d = f.coefficients(r)
            out.append([d.get(tuple(1 if i == k else 0 for i in range(n)), zero)
                        for k in range(n)])
        return out
