"""The arm-by-arm decomposition of ``N(Q)``, exactly, and the numbers on a component.

Each arm's joint variables appear only in the rows of its own contacts, so the joints
are eliminated arm by arm (:class:`_ArmMap`), leaving constraints on the object twist
alone; ``N(Gt^T)`` comes from the object columns. :func:`numbers_modulo` gives the
numbers at the generic point of a component ``f = 0``, through the rank service.
"""

from __future__ import annotations

from dataclasses import dataclass

from coopkin_sym.analysis.numbers import Numbers, numbers_from_ranks, ranks_from_numbers
from coopkin_sym.exact.deadline import check
from coopkin_sym.exact.elimination import ranks_at_random_point
from coopkin_sym.exact.matrix import PolyMatrix, rank_triple
from coopkin_sym.exact.ratfunc import RatFunc
from coopkin_sym.model.model import Model

__all__ = ["Decomposition", "attains", "decompose", "numbers_modulo"]


@dataclass
class Decomposition:
    """The arm-by-arm decomposition of ``N(Q)`` (see :func:`decompose`).

    Example
    -------
    >>> from coopkin_sym.analysis import kinematics
    >>> from coopkin_sym.model import load_model
    >>> from coopkin_sym.model.configuration import Configuration
    >>> model = load_model("paper-case1-hard")
    >>> kin = kinematics.build(model, Configuration.parse(model, "q1=pi/2,q2=pi/2,L=1"))
    >>> rows = [kin.ring.clear_row(r) for r in kin.Q]
    >>> d = decompose(rows, model, kin.row_contacts, kin.ring.zctx)
    >>> d.numbers.Nm, len(d.c11), len(d.c23)
    (3, 1, 0)
    """

    numbers: Numbers
    c11: list
    c11_pivots: list[int]
    c23: list
    arm_maps: list[_ArmMap]
    coord_u: list


def decompose(q_rows, model: Model, row_contacts: list[int], zctx) -> Decomposition:
    """Numbers and canonical subspaces from the integer-polynomial rows of ``Q``.

    Each arm's joint variables appear only in the rows of its own contacts, so the
    joints are eliminated arm by arm (:class:`_ArmMap`), leaving constraints on the
    object twist alone (six columns); ``N(Gt^T)`` comes from the first six columns.
    Everything is exact over the fraction field of the ring of ``zctx``.
    """
    r = len(model.joints)
    m = len(q_rows)
    dim = model.object_dim
    gt_rows = [row[:dim] for row in q_rows]
    c11, c11_pivots = PolyMatrix(gt_rows, dim, context=zctx).nullspace_rref()
    owners = [model.contacts[c].arm for c in row_contacts]
    constraints = [gt_rows[i] for i, a in enumerate(owners) if a is None]
    c23: list[list] = []
    arm_maps: list[_ArmMap] = []
    zero = zctx.constant(0)
    for a, arm in enumerate(model.arms):
        check("the decomposition of the nullspace, arm by arm")
        off = model.joint_offset(a)
        arm_map = _ArmMap.build(q_rows, [i for i, o in enumerate(owners) if o == a],
                                dim + off, len(arm.joints), zctx, dim)
        constraints += arm_map.constraints
        for v in arm_map.null:
            c23.append([zero] * off + v + [zero] * (r - off - len(v)))
        arm_maps.append(arm_map)
    # feasible object twists U = R(C1): those every arm can follow
    order = c11_pivots + [c for c in range(dim) if c not in c11_pivots]
    feasible, pivots = PolyMatrix(constraints, dim, context=zctx).nullspace_rref(order)
    coord_u = [v for v, p in zip(feasible, pivots, strict=True) if p not in c11_pivots]
    nc, ni, nr = len(feasible), len(c11), len(c23)
    nm = nc + nr
    numbers = numbers_from_ranks(
        m, r, *ranks_from_numbers({"Nm": nm, "Ni": ni, "Nr": nr}, r, dim=dim), dim=dim)
    return Decomposition(numbers, c11, c11_pivots, c23, arm_maps, coord_u)


def attains(q_rows, model: Model, numbers: Numbers) -> bool:
    """Whether the ranks of ``Q``, its object columns and its joint columns at one
    random point (modulo a prime) are those of ``numbers``. Where ``Q`` is a
    specialization of a matrix whose generic numbers are ``numbers`` (a slice of its
    chart), its generic ranks are at most those and at least the ranks at any point:
    True proves its generic numbers are ``numbers`` (False proves nothing).

    Example
    -------
    >>> from coopkin_sym.analysis.kinematics import build, q_at_pi
    >>> from coopkin_sym.analysis.numbers import numbers_from_ranks
    >>> from coopkin_sym.model import load_model
    >>> from coopkin_sym.model.configuration import Configuration
    >>> m = load_model("paper-case1-hard")
    >>> chart = build(m, Configuration.parse(m, "L=1", free=["q1", "q2"]))
    >>> ring, _, q = q_at_pi(chart, ["q1"])                # the slice q1 = pi
    >>> generic = numbers_from_ranks(6, 2, 6, 5, 2, dim=6)   # the chart's: Nm = 2
    >>> attains([ring.clear_row(r) for r in q], m, generic)
    True
    """
    dim, r = model.object_dim, len(model.joints)
    want = ranks_from_numbers(numbers, r, dim=dim)
    got = ranks_at_random_point(q_rows, [range(dim + r), range(dim), range(dim, dim + r)])
    return tuple(got) == tuple(want)


@dataclass
class _ArmMap:
    """One arm's share of the analysis.

    ``constraints``: rows ``y Gt_a`` (``y`` in the left nullspace of ``Dt_a``) that
    every feasible object twist satisfies; ``null``: reduced echelon basis of
    ``N(Dt_a)``; ``solved``: for each pivot joint of the reduced echelon form of
    ``[Dt_a | Gt_a]``, the row that gives its velocity from the object twist.
    """

    joints: int
    constraints: list
    null: list
    null_pivots: list[int]
    solved: list[tuple[int, list]]

    @classmethod
    def build(cls, q_rows, rows: list[int], col0: int, joints: int, zctx,
              dim: int) -> _ArmMap:
        d_rows = [[q_rows[i][col0 + k] for k in range(joints)] for i in rows]
        m_rows = [d + q_rows[i][:dim] for d, i in zip(d_rows, rows, strict=True)]
        reduced, pivots = PolyMatrix(m_rows, joints + dim).rref()
        constraints = [row[joints:] for row, p in zip(reduced, pivots, strict=True)
                       if p >= joints]
        solved = [(p, row) for row, p in zip(reduced, pivots, strict=True) if p < joints]
        null, null_pivots = PolyMatrix(d_rows, joints, context=zctx).nullspace_rref()
        return cls(joints, constraints, null, null_pivots, solved)

    def joints_for(self, u) -> list[RatFunc]:
        """Joint velocities of this arm that follow the object twist ``u``: the pivot
        joints of ``[Dt_a | Gt_a]`` solved with the free joints at rest, then reduced
        so they vanish at the pivots of the redundant motions."""
        zctx = u[0].context()
        zero = RatFunc.poly(zctx.constant(0))
        q = [zero] * self.joints
        for p, row in self.solved:
            acc = zctx.constant(0)
            for k in range(len(u)):
                if not row[self.joints + k].is_zero() and not u[k].is_zero():
                    acc = acc + row[self.joints + k] * u[k]
            if not acc.is_zero():
                q[p] = RatFunc.make(-acc, row[p])
        for v, p in zip(self.null, self.null_pivots, strict=True):
            if q[p].is_zero():
                continue
            factor = q[p] / RatFunc.poly(v[p])
            q = [qi - factor * RatFunc.poly(vi) if not vi.is_zero() else qi
                 for qi, vi in zip(q, v, strict=True)]
        return q


def numbers_modulo(q_rows, model: Model, row_contacts: list[int], quotient) -> Numbers:
    """The numbers at the generic point of the component ``f = 0`` of an irreducible
    ``f`` (a :class:`~coopkin_sym.exact.quotient.Quotient`), exactly: ranks over its
    function field (or, for a univariate ``f``, at its roots, which are conjugate).

    ``rank Q`` is found arm by arm: each arm's joint columns are eliminated from its own
    rows, then the object rows left over from every arm are ranked together.
    """
    dim = model.object_dim
    owners = [model.contacts[c].arm for c in row_contacts]
    arms = [([i for i, o in enumerate(owners) if o == a], dim + model.joint_offset(a),
             dim + model.joint_offset(a) + len(arm.joints))
            for a, arm in enumerate(model.arms)]
    ranks = rank_triple(q_rows, dim + len(model.joints), dim, quotient, arms, by_arms=True)
    return numbers_from_ranks(len(q_rows), len(model.joints), *ranks.triple, dim=dim)
