"""Mobility and kinematic analysis (paper section 3), exact.

From ``Q = (Gt^T | -Dt)`` this computes a basis ``C`` of ``N(Q)`` and brings it, by
column operations, to the block form

    C = [[C11, C12, 0  ],
         [0,   C22, C23]]

``C11`` spans ``N(Gt^T)`` (object motions with every joint locked), ``C23`` spans
``N(Dt)`` (joint motions with the object fixed), ``[C12; C22]`` the coordinated
motions. Every block has canonical columns: each column is the primitive polynomial
multiple of a reduced-echelon basis vector, so equal subspaces give equal matrices.

* ``C11``: reduced echelon basis of ``N(Gt^T)``.
* ``C23``: reduced echelon basis of ``N(Dt)``.
* ``[C12; C22]``: reduced echelon basis of the vectors of ``N(Q)`` that vanish at
  the pivot coordinates of ``C11`` and ``C23`` (a complement of both, found from the
  reduced echelon form of ``N(Q)``, with the ``C11`` pivot columns taken first).

The numbers: ``Nm = rank C``, ``Nc = rank C1``, ``Ni = cols C11``, ``Nr = cols C23``,
and the force-domain ``Ng = m - rank Gt``, ``Nd = m - rank Dt``, ``Nh = m - rank Q``.

Example
-------
>>> from coopkin_sym.model.model import load_model
>>> from coopkin_sym.model.configuration import Configuration
>>> a = analyze(load_model("paper-case1-hard"), Configuration())
>>> a.numbers.as_dict()
{'Nm': 2, 'Nc': 2, 'Ni': 1, 'Nr': 0, 'Ng': 1, 'Nd': 4, 'Nh': 0}
>>> a.C12.T, a.C22.T
(Matrix([[L, 0, 0, 0, 0, 0]]), Matrix([[-1, -1]]))
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.classes import grasp_classes
from coopkin_sym.analysis.decomposition import Decomposition, _ArmMap, decompose
from coopkin_sym.analysis.decomposition import numbers_modulo as numbers_modulo
from coopkin_sym.analysis.factored import FactoredMotions, factored_motions
from coopkin_sym.analysis.generic import (
    NumbersCertificate,
    RankBound,
    chain_numbers,
    generic_numbers,
)
from coopkin_sym.analysis.manipulability import MAX_TERMS as MANIPULABILITY_TERMS
from coopkin_sym.analysis.manipulability import manipulability
from coopkin_sym.analysis.numbers import (
    Numbers,
    numbers_from_ranks,
    numbers_line,
)
from coopkin_sym.analysis.passive import PassiveAnalysis, passive_analysis
from coopkin_sym.analysis.points import point_ranks
from coopkin_sym.analysis.renderers import Displayable, clip
from coopkin_sym.errors import BlockTooLarge, InfeasibleMotion
from coopkin_sym.exact import elimination as el
from coopkin_sym.exact.angles import tangent_name
from coopkin_sym.exact.bounded import report, run_bounded
from coopkin_sym.exact.matrix import PolyMatrix
from coopkin_sym.exact.parse import exact_expr
from coopkin_sym.exact.ratfunc import RatFunc
from coopkin_sym.exact.ring import ClearedRows
from coopkin_sym.exact.sympy_bridge import (
    columns_to_sympy,
    matrix_to_sympy,
    poly_from_sympy,
    poly_to_sympy,
    ratio_to_sympy,
)
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model

# the largest primitive coordinated column (in terms of one entry) shown as polynomials
DEFAULT_TERM_BUDGET = 20_000



@dataclass(frozen=True)
class Motion:
    """All velocities realizing a request: ``particular + span(free)``.

    ``particular`` is one exact solution (a SymPy column), ``free`` a matrix whose
    columns span the homogeneous part (redundant joint motions for
    :meth:`Analysis.joint_velocities`, indeterminate object motions for
    :meth:`Analysis.object_velocities`).

    Example
    -------
    >>> from coopkin_sym import load
    >>> a = load("paper-case1-hard").analyze("q1=pi/2,q2=pi/2,L=1")
    >>> m = a.object_velocities([1, 0])
    >>> m.particular.T, m.free.shape
    (Matrix([[0, 0, 0, 0, 0, 1]]), (6, 1))
    """

    particular: sp.Matrix
    free: sp.Matrix


class Analysis(Displayable):
    """The exact mobility and kinematic analysis of one system at one configuration.

    Built by :func:`analyze`; matrices are exposed as SymPy matrices for display
    (entries are polynomials or rational functions of :attr:`variables`).

    Example
    -------
    >>> from coopkin_sym import load
    >>> a = load("paper-case1-hard").analyze("q1=pi/2,q2=pi/2")
    >>> a.numbers.Nm, a.Q.shape, a.C23.shape
    (3, (6, 8), (2, 0))
    >>> a
    <Analysis paper case 1, hard/hard at q1=pi/2,q2=pi/2: Nm=3 Nc=3 Ni=1 Nr=0 Ng=1 Nd=4 Nh=1>
    """

    def __init__(self, model: Model, config: Configuration,
                 kin: kinematics.Kinematics | None = None,
                 term_budget: int | None = DEFAULT_TERM_BUDGET):
        self.model = model
        self.configuration = config
        self.term_budget = term_budget
        self.r = len(model.joints)
        self.dim = model.object_dim
        if kin is not None:
            self.__dict__["kinematics"] = kin

    # --- the numbers first; everything else when it is asked for --------------------
    @cached_property
    def kinematics(self) -> kinematics.Kinematics:
        """``G``, ``D``, ``H`` and ``Q`` over the ring of the symbolic variables."""
        report("the kinematics (G, D, H, Q)")
        return kinematics.build(self.model, self.configuration)

    @cached_property
    def m(self) -> int:
        """The number of rows of ``Q`` (contact constraints)."""
        return len(self.kinematics.Q)

    @cached_property
    def _cleared(self) -> ClearedRows:
        return ClearedRows(self.kinematics.ring, self.kinematics.Q)

    @cached_property
    def _q_rows(self) -> list:
        return list(self._cleared)

    @cached_property
    def _decomposition(self) -> Decomposition:
        q_rows = self._q_rows
        report("the ranks and the decomposition of the nullspace")
        return decompose(q_rows, self.model, self.kinematics.row_contacts,
                         self.ring.zctx)

    @property
    def _c11(self) -> list:
        return self._decomposition.c11

    @property
    def _c23(self) -> list:
        return self._decomposition.c23

    @property
    def _arm_maps(self) -> list[_ArmMap]:
        return self._decomposition.arm_maps

    @property
    def _coord_u(self) -> list:
        return self._decomposition.coord_u

    @cached_property
    def _first_numbers(self) -> tuple[Numbers, NumbersCertificate]:
        """The numbers before any subspace: exact ranks of ``Q`` at the point (compiled
        after the first point of a model), or generic numbers from exact ranks at random
        points with their certificate (see :mod:`coopkin_sym.analysis.generic`)."""
        compiled = point_ranks(self.model, self.configuration)
        if compiled is not None:
            m, ranks = compiled
            self.__dict__.setdefault("m", m)
            ranks_known = [RankBound(name, rank, "point") for name, rank
                           in zip(("Q", "Gt", "Dt"), ranks, strict=True)]
            return (numbers_from_ranks(m, self.r, *ranks, dim=self.dim),
                    NumbersCertificate.from_ranks(ranks_known, 0))
        if self.configuration.free:      # the sizes may certify ranks at points mod p
            sampled = chain_numbers(self.model, self.configuration)
            if sampled is not None:
                return sampled
        kin = self.kinematics
        return generic_numbers(self._cleared, self.model, kin.row_contacts, kin.ring.zctx)

    @property
    def numbers(self) -> Numbers:
        """The seven numbers (exact; see :attr:`certificate` for how they are known).

        Example
        -------
        >>> from coopkin_sym import load
        >>> load("paper-case1-hard").analyze("q1=pi/2,q2=pi/2").numbers.Nm
        3
        """
        if "_decomposition" in self.__dict__:
            return self._decomposition.numbers
        return self._first_numbers[0]

    @property
    def certificate(self) -> NumbersCertificate:
        """How :attr:`numbers` are known: exact ranks (at the point, bounded by the
        sizes, or by elimination over the field of rational functions) or, when a
        certificate was too costly, exact ranks at random points with the probability
        of an error bounded (``error_bits``).

        Example
        -------
        >>> from coopkin_sym import load
        >>> load("paper-case2-hard").analyze(generic=True).certificate.exact
        True
        """
        if "_decomposition" in self.__dict__:
            return NumbersCertificate.by_elimination()
        return self._first_numbers[1]

    def decompose_rows(self, model: Model, q_rows) -> Decomposition:
        """The decomposition of other integer-polynomial rows of ``Q`` over this
        analysis' ring, contacts and rows (used for the locked system of
        :attr:`passive`)."""
        return decompose(q_rows, model, self.kinematics.row_contacts, self.ring.zctx)

    @cached_property
    def passive(self) -> PassiveAnalysis:
        """What the motors control and what the passive joints leave free (see
        :mod:`coopkin_sym.analysis.passive`); with every joint actuated, the paper's
        subspaces again (``Nuo = Ni``, ``Npi = 0``).

        Example
        -------
        >>> from coopkin_sym import load
        >>> load("five-bar").analyze("L=1").passive.numbers.Nco
        2
        """
        return passive_analysis(self)

    def __repr__(self) -> str:
        return (f"<Analysis {clip(self.model.name, 80)} {clip(self.where, 120)}: "
                f"{numbers_line(self.numbers)}>")

    @property
    def where(self) -> str:
        """The configuration in short: ``"at q1=pi/2,L=1"``, ``"at home"`` (every
        joint at 0), the symbolic joints, or ``"generic"`` (every joint symbolic).

        Example
        -------
        >>> from coopkin_sym import load
        >>> load("paper-case1-soft").analyze("L=2", free=["q1"]).where
        'at L=2, symbolic q1'
        """
        config, joints = self.configuration, self.model.joint_names
        parts = [f"at {config.at_text()}"] if config.at_text() else []
        if config.free and set(joints) <= config.free:
            parts.append("generic")
        elif config.free:
            parts.append("symbolic " + ", ".join(j for j in joints if j in config.free))
        return ", ".join(parts) or "at home"

    def block_terms(self) -> dict[str, int]:
        """For each block, about how many terms its largest entry has (a bound for
        ``C12`` and ``C22``), known without building the blocks: to tell a block small
        enough to show before computing it.

        Example
        -------
        >>> from coopkin_sym import load
        >>> load("paper-case1-hard").analyze("q1=pi/2,q2=pi/2").block_terms()
        {'C11': 1, 'C12': 2, 'C22': 2, 'C23': 0}
        """
        def most(vectors) -> int:
            return max((len(x) for v in vectors for x in v), default=0)
        coordinated = max(most(self._coord_u), self.coordinated_terms)
        return {"C11": most(self._c11), "C12": coordinated, "C22": coordinated,
                "C23": most(self._c23)}

    @property
    def classes(self) -> tuple[str, ...]:
        """The grasp classes of this configuration (see
        :mod:`coopkin_sym.analysis.classes`).

        Example
        -------
        >>> from coopkin_sym import load
        >>> load("planar-two-fingers").analyze().classes
        ('graspable',)
        """
        return grasp_classes(self.numbers)

    @property
    def coordinated_terms(self) -> int:
        """An upper bound on the terms of one entry of the coordinated joint motions
        ``C22`` (as rational functions), known before building them."""
        if not self._coord_u:
            return 0
        u_terms = max(len(x) for u in self._coord_u for x in u)
        coef = max((len(e) for arm in self._arm_maps for _, row in arm.solved
                    for e in row[arm.joints:]), default=0)
        den = max((len(row[p]) for arm in self._arm_maps for p, row in arm.solved), default=1)
        return u_terms * coef + den

    def _within_budget(self, what: str) -> None:
        size = self.coordinated_terms
        if self.term_budget is not None and size > self.term_budget:
            raise BlockTooLarge(
                f"{what}: the coordinated joint motions would have entries of up to about "
                f"{size:,} terms, over the budget of {self.term_budget:,}; keep fewer "
                "joints symbolic (free=[...] / --free), use coordinated_factored(), or set "
                "analysis.term_budget = None")

    @cached_property
    def _coord_q(self) -> list[list[RatFunc]]:
        return [self._joint_motion(u) for u in self._coord_u]

    def _joint_motion(self, u) -> list[RatFunc]:
        """The joint velocities realizing the object twist ``u`` (a feasible twist),
        vanishing at the pivot coordinates of the redundant motions."""
        out: list[RatFunc] = []
        for arm_map in self._arm_maps:
            out += arm_map.joints_for(u)
        return out

    @cached_property
    def _coordinated(self) -> list[list] | None:
        """The coordinated columns ``(C12; C22)`` as primitive polynomial vectors, or
        ``None`` when clearing the joint part's denominators would exceed the term
        budget (the blocks then show the joint part as rational functions)."""
        self._within_budget("C22")
        return self._coordinated_columns(self.term_budget)

    @cached_property
    def _unbounded_coordinated(self) -> list[list]:
        """The coordinated columns as polynomial vectors, whatever their size."""
        return self._coordinated_columns(None)

    def _coordinated_columns(self, budget: int | None) -> list[list] | None:
        """The coordinated columns, primitive, or None over ``budget`` terms."""
        budget = budget if budget is not None else 10**18
        zctx = self.ring.zctx
        out = []
        for u, q in zip(self._coord_u, self._coord_q, strict=True):
            common = zctx.constant(1)
            for e in q:
                if e.den.is_one() or e.den == common:
                    continue
                g = common.gcd(e.den)
                if len(common) * len(e.den) > budget:
                    return None
                common = common * (e.den / g)
            if common.is_one():
                out.append(el.primitive(list(u) + [e.num for e in q]))
                continue
            if max(len(x) for x in u) * len(common) > budget:
                return None
            scaled = []
            for e in q:
                quotient = common / e.den
                if len(e.num) * len(quotient) > budget:   # bound the product's terms
                    return None
                scaled.append(e.num * quotient)
            col = [x * common for x in u] + scaled
            out.append(el.primitive(col))
        return out

    # --- presentation -------------------------------------------------------------
    @property
    def ring(self):
        return self.kinematics.ring

    @property
    def variables(self) -> tuple[sp.Symbol, ...]:
        """The symbols left in the results (free joint variables, free parameters);
        known without building the kinematics."""
        if "kinematics" in self.__dict__:
            return tuple(self.kinematics.symbols[n] for n in self.ring.names)
        ring, symbols = kinematics.ring_for(self.model, self.configuration)
        return tuple(symbols[n] for n in ring.names)

    def _sym(self, rows, shape=None) -> sp.Matrix:
        return matrix_to_sympy(rows, self.ring, self.kinematics.symbols, shape)

    def _cols(self, vectors, nrows) -> sp.Matrix:
        return columns_to_sympy(vectors, nrows, self.ring, self.kinematics.symbols)

    @cached_property
    def G(self) -> sp.Matrix:
        """The grasp matrix ``G`` (6 x 6n; 3 x 3n for a planar system)."""
        return self._sym(self.kinematics.GT).T

    @cached_property
    def D(self) -> sp.Matrix:
        """``D`` (6n x r): joint velocities to the links' contact-frame velocities."""
        return self._sym(self.kinematics.D, (self.dim * len(self.model.contacts), self.r))

    @cached_property
    def H(self) -> sp.Matrix:
        """The contact-model selection ``H`` (m x 6n)."""
        return self._sym(self.kinematics.H, (0, self.dim * len(self.model.contacts)))

    @cached_property
    def Q(self) -> sp.Matrix:
        """``Q = (H G^T | -H D)`` (m x (6 + r)), as rational functions."""
        return self._sym(self.kinematics.Q, (0, self.dim + self.r))

    @cached_property
    def C(self) -> sp.Matrix:
        """``C`` in block form ``[[C11, C12, 0], [0, C22, C23]]``."""
        return sp.ImmutableMatrix(sp.BlockMatrix([
            [self.C11, self.C12, sp.zeros(self.dim, self.numbers.Nr)],
            [sp.zeros(self.r, self.numbers.Ni), self.C22, self.C23]]).as_explicit())

    @cached_property
    def C11(self) -> sp.Matrix:
        """Basis of ``N(Gt^T)``: object motions with every joint locked (6 x Ni)."""
        self._fits("C11", self._c11, "indeterminate object motions")
        return self._cols(self._c11, self.dim)

    def _fits(self, name: str, vectors, what: str) -> None:
        """Refuse a block whose largest entry (known before it is written out) has more
        terms than the budget, with the size it would have had."""
        size = max((len(x) for v in vectors for x in v), default=0)
        if self.term_budget is not None and size > self.term_budget:
            raise BlockTooLarge(
                f"{name}: the {what} would have entries of {size:,} terms, over the "
                f"budget of {self.term_budget:,}; keep fewer joints symbolic (free=[...] "
                "/ --free) or set analysis.term_budget = None")

    @cached_property
    def _twists(self) -> sp.Matrix:
        """The coordinated object twists (``C12`` before its columns are scaled to clear
        the joint part's denominators), written out once."""
        return self._cols(self._coord_u, self.dim)

    @property
    def coordinated_form(self) -> str:
        """``"primitive"`` when each coordinated column ``(C12; C22)`` is a primitive
        polynomial vector, ``"rational"`` when that would exceed the term budget and
        ``C12`` is a primitive polynomial vector with ``C22`` its exact joint
        velocities as rational functions (same column space, canonical either way)."""
        try:
            return "primitive" if self._coordinated is not None else "rational"
        except BlockTooLarge:
            return "rational"

    def coordinated_factored(self) -> FactoredMotions:
        """The coordinated motions factored: ``C12`` and, arm by arm, the small map
        ``K_a`` with ``qdot_a = K_a u`` (see :mod:`coopkin_sym.analysis.factored`); the
        form to use when ``C22`` is too big to expand.

        Example
        -------
        >>> from coopkin_sym import load
        >>> f = load("planar-two-fingers").analyze(generic=True).coordinated_factored()
        >>> len(f.arms), f.twists.shape
        (2, (3, 3))
        """
        return factored_motions(self)

    @cached_property
    def C12(self) -> sp.Matrix:
        """Object part of the coordinated motions (6 x (Nc - Ni))."""
        try:
            coordinated = self._coordinated
        except BlockTooLarge:
            coordinated = None
        if coordinated is None:
            self._fits("C12", self._coord_u, "coordinated object motions")
            return self._twists
        return self._cols([v[:self.dim] for v in coordinated], self.dim)

    @cached_property
    def C22(self) -> sp.Matrix:
        """Joint part of the coordinated motions (r x (Nc - Ni))."""
        if self._coordinated is None:
            size = max((len(e.num) + len(e.den) for q in self._coord_q for e in q),
                       default=0)
            if self.term_budget is not None and size > self.term_budget:
                raise BlockTooLarge(
                    f"C22: the coordinated joint motions have entries of {size:,} terms, "
                    f"over the budget of {self.term_budget:,}; keep fewer joints symbolic "
                    "(free=[...] / --free), use coordinated_factored(), or set "
                    "analysis.term_budget = None")
            syms = self.kinematics.symbols
            cols = [[ratio_to_sympy(e.num, e.den, self.ring, syms) for e in q]
                    for q in self._coord_q]
            return sp.ImmutableMatrix(sp.Matrix(cols).T) if cols else sp.ImmutableMatrix(
                sp.zeros(self.r, 0))
        return self._cols([v[self.dim:] for v in self._coordinated], self.r)

    @cached_property
    def C23(self) -> sp.Matrix:
        """Basis of ``N(Dt)``: joint motions with the object fixed (r x Nr)."""
        self._fits("C23", self._c23, "redundant joint motions")
        return self._cols(self._c23, self.r)

    def twist_in_base(self, u: Sequence) -> list[sp.Expr]:
        """An object twist of this analysis (a column of ``C11`` or ``C12``, written
        in the model's object frame) as ``(v, w)`` with ``v`` at the base origin and
        both in base axes (the same twist when the model names no object frame).

        Example
        -------
        >>> from coopkin_sym import load
        >>> a = load("paper-case1-hard").analyze()
        >>> a.twist_in_base(a.C11.col(0)) == list(a.C11.col(0))
        True
        """
        return kinematics.twist_in_base(u, self.model.object_frame)

    def in_angles(self, matrix: sp.Matrix) -> sp.Matrix:
        """A block's columns rewritten in ``cos q``, ``sin q`` instead of ``t = tan(q/2)``.

        Each column (defined up to a nonzero factor) is scaled by
        ``(1 + t^2)^(-m)`` per variable, ``2m`` its degree in ``t`` rounded up to even;
        every monomial ``t^j / (1 + t^2)^m`` is then ``sin^j(q/2) cos^(2m-j)(q/2)``,
        a polynomial in ``cos q`` and ``sin q``. Same column space, exact.

        Example
        -------
        >>> from coopkin_sym import load
        >>> a = load("paper-case1-soft").analyze(free=["q1"])
        >>> a.in_angles(a.C12).T
        Matrix([[-L*cos(q1), -L*sin(q1), 0, 0, 0, sin(q1)]])
        """
        kinds = {tangent_name(j.name): j.name for j in self.model.joints if j.type == "revolute"}
        tsyms = {self.kinematics.symbols[n]: sp.Symbol(q, real=True)
                 for n, q in kinds.items() if n in self.kinematics.symbols}
        if not tsyms:
            return matrix
        cols = []
        for k in range(matrix.cols):
            col = [sp.together(e) for e in matrix.col(k)]
            dens = sp.lcm([sp.fraction(e)[1] for e in col])
            nums = [sp.expand(sp.cancel(e * dens)) for e in col]
            cols.append([_to_angles(e, tsyms, nums) for e in nums])
        out = sp.Matrix(cols).T if cols else sp.zeros(matrix.rows, 0)
        return sp.ImmutableMatrix(out.applyfunc(sp.factor))

    def manipulability(self, controlled: Sequence[str] | None = None, length=1,
                       point: Sequence | None = None, *, timeout: float | None = None,
                       max_terms: int | None = MANIPULABILITY_TERMS):
        """The manipulability ellipsoid of the driven object motions (see
        :mod:`coopkin_sym.analysis.manipulability`): of the components ``controlled``
        (default: the whole twist), angular velocities scaled by ``length``, ``v`` of
        the object point ``point`` when given; ``timeout``: a wall-clock bound in
        seconds (see :func:`coopkin_sym.exact.bounded.run_bounded`; past it,
        :class:`~coopkin_sym.errors.TimeLimitReached`); ``max_terms``: the budget of
        terms of an entry on the way, over rational functions (None: none; past it,
        :class:`~coopkin_sym.errors.BlockTooLarge` names the step).

        Example
        -------
        >>> from coopkin_sym import load
        >>> m = load("paper-case1-hard").analyze("L=1").manipulability(["v_x", "v_y"])
        >>> m.shape
        Matrix([
        [1/2, 0],
        [  0, 0]])
        """
        return run_bounded(lambda: manipulability(self, controlled, length, point,
                                                  max_terms=max_terms),
                           timeout, owner="manipulability")

    def finite_mobility(self, order: int | None = None):
        """The finite mobility here: the local dimension of the closed system's
        configuration space, its branches and whether the first-order motions are
        finite ones (see :func:`coopkin_sym.analysis.finite.finite_mobility`; every
        joint at a rational ``tan(q/2)``; hard, complete and frictionless contacts),
        with the verdict of every column of ``C11``, ``C12``/``C22`` and ``C23``
        (:mod:`coopkin_sym.analysis.finite.columns`).

        Example
        -------
        >>> from coopkin_sym import load
        >>> fm = load("four-bar").analyze("q1=-pi/2,q2=-pi/2").finite_mobility()
        >>> fm.dimension, fm.first_order, fm.classification
        (1, 2, 'bifurcation')
        """
        from coopkin_sym.analysis.finite import finite_mobility
        from coopkin_sym.analysis.finite.columns import with_columns

        found = finite_mobility(self.model, self.configuration, order)
        return with_columns(found, self.model, self.configuration, self.blocks())

    def blocks(self) -> dict[str, sp.Matrix]:
        return {"C11": self.C11, "C12": self.C12, "C22": self.C22, "C23": self.C23}

    def check(self) -> bool:
        """``Q C = 0`` exactly, on the integer-polynomial form of ``Q``."""
        cols = ([v + [self.ring.zctx.constant(0)] * self.r for v in self._c11]
                + self._polynomial_coordinated()
                + [[self.ring.zctx.constant(0)] * self.dim + v for v in self._c23])
        prod = el.matmul(self._q_rows, [list(c) for c in zip(*cols, strict=True)],
                         self.ring.zctx) if cols else []
        return all(e.is_zero() for row in prod for e in row)

    # --- kinematic maps (paper eqs. 10-12) ----------------------------------------
    def joint_velocities(self, u: Sequence) -> Motion:
        """All joint velocities that move the object with twist ``u = (v, w)``
        (paper eq. 11): ``qdot = C22 x + C23 y``.

        Raises :class:`InfeasibleMotion` when ``u`` is not in ``R(C1)``. With
        ``Ni > 0``, ``u`` may include indeterminate motion: the joints cannot affect it.

        Example
        -------
        >>> from coopkin_sym import load
        >>> a = load("paper-case1-soft").analyze(at="L=2")
        >>> a.joint_velocities([-2, 0, 0, 0, 0, 0]).particular.T
        Matrix([[1, 1]])
        """
        coordinated = self._polynomial_coordinated()
        d = self.dim
        x = self._solve(self._c11 + [v[:d] for v in coordinated], u, "object twist u",
                        d)
        x2 = x[len(self._c11):]
        part = self._combine([v[d:] for v in coordinated], x2, self.r)
        return Motion(part, self.C23)

    def object_velocities(self, qdot: Sequence) -> Motion:
        """All object twists produced by joint velocities ``qdot`` (paper eq. 12):
        ``u = C12 x + C11 y``; raises :class:`InfeasibleMotion` when ``qdot`` is not
        in ``R(C2)`` (it would break a contact)."""
        coordinated = self._polynomial_coordinated()
        d = self.dim
        x = self._solve([v[d:] for v in coordinated] + self._c23, qdot,
                        "joint velocity qdot", self.r)
        x2 = x[: len(coordinated)]
        part = self._combine([v[:d] for v in coordinated], x2, d)
        return Motion(part, self.C11)

    def _polynomial_coordinated(self) -> list[list]:
        """Coordinated columns as polynomial vectors, whatever their size."""
        if self._coordinated is not None:
            return self._coordinated
        self._within_budget("kinematic maps")
        return self._unbounded_coordinated

    def _solve(self, columns, rhs, what: str, size: int):
        """Exact ``x`` with ``sum x_j columns_j = rhs`` (columns independent, of
        ``size`` components), as (numerator, denominator) pairs of integer
        polynomials."""
        ring, syms = self.ring, self.kinematics.symbols
        symbols = {**{p.name: p for p in self.model.parameters}, **syms}
        if isinstance(rhs, str) or not isinstance(rhs, Sequence | sp.MatrixBase):
            raise InfeasibleMotion(f"{what}: expected a list of numbers, got "
                                   f"{type(rhs).__name__}")
        n = size
        if len(rhs) != n:
            raise InfeasibleMotion(f"{what}: expected {n} components, got {len(rhs)}")
        rows = []
        for i in range(n):
            value = exact_expr(rhs[i], symbols, f"{what}[{i}]")
            num, den = sp.fraction(sp.together(value))
            try:
                pn = ring.to_zpoly(poly_from_sympy(num, ring, syms))
                pd = ring.to_zpoly(poly_from_sympy(den, ring, syms))
            except ValueError as exc:
                raise InfeasibleMotion(f"{what}[{i}]: {exc}") from None
            # scale to a common integer content: multiply the equation by den
            rows.append([c[i] * pd for c in columns] + [pn])
        k = len(columns)
        reduced, pivots = PolyMatrix(rows, k + 1).rref()
        if k in pivots:
            raise InfeasibleMotion(
                f"{what} is not feasible: it is not a combination of the motions the "
                "contacts allow (it would break a contact)")
        sol = [(ring.zctx.constant(0), ring.zctx.constant(1))] * k
        for row, p in zip(reduced, pivots, strict=True):
            sol[p] = (row[k], row[p])
        return sol

    def _combine(self, columns, coeffs, nrows) -> sp.Matrix:
        ring, syms = self.ring, self.kinematics.symbols
        if not columns:
            return sp.ImmutableMatrix(sp.zeros(nrows, 1))
        common = ring.zctx.constant(1)
        for _, d in coeffs:
            common = common * d / common.gcd(d)
        scaled = [n * (common / d) for n, d in coeffs]
        out = []
        for i in range(nrows):
            acc = ring.zctx.constant(0)
            for c, s in zip(columns, scaled, strict=True):
                acc = acc + c[i] * s
            out.append(ratio_to_sympy(acc, common, ring, syms) if not acc.is_zero()
                       else sp.Integer(0))
        return sp.ImmutableMatrix(out)

    def as_json(self) -> dict:
        """The analysis as plain data, entries as exact strings."""
        def strs(mat: sp.Matrix):
            return [[sp.sstr(e) for e in mat.row(i)] for i in range(mat.rows)]
        blocks, omitted = self.available_blocks()
        shapes = {"C11": [self.dim, self.numbers.Ni],
                  "C12": [self.dim, len(self._coord_u)],
                  "C22": [self.r, len(self._coord_u)], "C23": [self.r, self.numbers.Nr]}
        out = {
            "system": self.model.name,
            "configuration": self.configuration.at_text(),
            "point": "symbolic" if self.configuration.free else "rational",
            "variables": [str(v) for v in self.variables],
            "joints": list(self.model.joint_names),
            "twist": list(self.model.twist_names),
            "numbers": self.numbers.as_dict(),
            "classes": list(self.classes),
            "blocks": {k: strs(v) if v is not None else None for k, v in blocks.items()},
            "shapes": shapes,
            "coordinated_form": None if omitted else self.coordinated_form,
            "object_frame": frame_json(self.model.object_frame),
            "snapped": snapped_json(self.model.snapped),
            "field": None,
        }
        out["certificate"] = self.certificate.as_dict()
        if omitted:
            out["omitted"] = omitted
        if self.model.passive_joints:
            p = self.passive
            out["passive"] = {
                "actuated": list(p.actuated), "passive": list(p.passive),
                "numbers": p.numbers.as_dict(),
                **{k: strs(getattr(p, k)) for k in ("controlled", "uncontrolled",
                                                    "internal", "actuated_redundant")}}
        return out

    def available_blocks(self) -> tuple[dict[str, sp.Matrix | None], dict[str, str]]:
        """The blocks that fit the term budget (``None`` for the others), and why each
        missing one was left out."""
        blocks: dict[str, sp.Matrix | None] = {}
        omitted: dict[str, str] = {}
        for name in ("C11", "C12", "C22", "C23"):
            try:
                blocks[name] = getattr(self, name)
            except BlockTooLarge as exc:
                blocks[name] = None
                omitted[name] = str(exc)
        return blocks, omitted

    def poly(self, p) -> sp.Expr:
        return poly_to_sympy(p, self.ring, self.kinematics.symbols)


def _to_angles(expr: sp.Expr, tsyms: dict, column: list[sp.Expr]) -> sp.Expr:
    """``expr`` (a polynomial in the t's) times ``prod (1+t^2)^-m`` in cos q, sin q."""
    if expr == 0:
        return expr
    out = sp.Integer(0)
    gens = list(tsyms)
    degs = {t: max((sp.degree(e, t) for e in column if e != 0), default=0) for t in gens}
    half = {t: (d + 1) // 2 for t, d in degs.items()}
    poly = sp.Poly(expr, *gens)
    for monom, coeff in poly.terms():
        term = coeff
        for t, j in zip(gens, monom, strict=True):
            q = tsyms[t]
            k = 2 * half[t] - j
            c, s_ = sp.cos(q), sp.sin(q)
            if j % 2 == 0:
                term *= ((1 - c) / 2) ** (j // 2) * ((1 + c) / 2) ** (k // 2)
            else:
                term *= (s_ / 2) * ((1 - c) / 2) ** ((j - 1) // 2) * ((1 + c) / 2) ** (
                    (k - 1) // 2)
        out += term
    return sp.expand(out)


def analyze(model: Model, config: Configuration) -> Analysis:
    """Analyze ``model`` at ``config`` exactly."""
    return Analysis(model, config)


def snapped_json(snapped) -> list[dict]:
    """The URDF floats snapped to exact values, as plain data."""
    return [{"where": x.where, "given": x.given, "exact": x.exact, "error": x.error}
            for x in snapped]


def frame_json(frame) -> dict | None:
    """The object frame as exact texts: its point and its axes (base coordinates)."""
    if frame is None:
        return None
    rotation, origin = frame
    return {"point": [sp.sstr(x) for x in origin],
            "axes": {name: [sp.sstr(x) for x in rotation[:, k]]
                     for k, name in enumerate("xyz")}}
