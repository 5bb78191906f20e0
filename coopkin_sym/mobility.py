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
>>> from coopkin_sym.model import load_model
>>> from coopkin_sym.configuration import Configuration
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

from . import kinematics
from .configuration import Configuration
from .exact import elimination as el
from .exact.sympy_bridge import (
    columns_to_sympy,
    matrix_to_sympy,
    poly_from_sympy,
    poly_to_sympy,
    ratio_to_sympy,
)
from .model import Model

NUMBER_NAMES = ("Nm", "Nc", "Ni", "Nr", "Ng", "Nd", "Nh")


class InfeasibleMotion(ValueError):
    """A requested velocity that the system cannot realize without breaking a contact."""


@dataclass(frozen=True)
class Numbers:
    """Mobility ``Nm``, connectivity ``Nc``, indeterminacy ``Ni``, redundancy ``Nr``,
    and the force-domain graspable ``Ng`` (internal forces), defective ``Nd`` and
    hyperstatic ``Nh`` numbers."""

    Nm: int
    Nc: int
    Ni: int
    Nr: int
    Ng: int
    Nd: int
    Nh: int

    def as_dict(self) -> dict[str, int]:
        return {k: getattr(self, k) for k in NUMBER_NAMES}


@dataclass(frozen=True)
class Motion:
    """All velocities realizing a request: ``particular + span(free)``.

    ``particular`` is one exact solution (a SymPy column), ``free`` a matrix whose
    columns span the homogeneous part (redundant joint motions for
    :meth:`Analysis.joint_velocities`, indeterminate object motions for
    :meth:`Analysis.object_velocities`).
    """

    particular: sp.Matrix
    free: sp.Matrix


class Analysis:
    """The exact mobility and kinematic analysis of one system at one configuration.

    Built by :func:`analyze`; matrices are exposed as SymPy matrices for display
    (entries are polynomials or rational functions of :attr:`variables`).
    """

    def __init__(self, model: Model, config: Configuration, kin: kinematics.Kinematics):
        self.model = model
        self.configuration = config
        self.kinematics = kin
        ring = kin.ring
        r = len(model.joints)
        self.r = r
        self.m = len(kin.Q)
        q_rows = [ring.clear_row(row) for row in kin.Q]
        self._q_rows = q_rows
        basis = el.nullspace(q_rows, 6 + r, ring.zctx)
        self._basis = basis
        obj_first, piv1 = el.gauss_jordan(basis, 6 + r)
        with_object = [v for v, p in zip(obj_first, piv1, strict=True) if p < 6]
        self._c23 = [v[6:] for v, p in zip(obj_first, piv1, strict=True) if p >= 6]
        gt_rows = [row[:6] for row in q_rows]
        self._c11, c11_pivots = el.gauss_jordan(el.nullspace(gt_rows, 6, ring.zctx), 6)
        order = c11_pivots + [c for c in range(6 + r) if c not in c11_pivots]
        second, piv2 = el.gauss_jordan(with_object, 6 + r, column_order=order)
        self._coordinated = [v for v, p in zip(second, piv2, strict=True)
                             if p not in c11_pivots]
        nm, ni, nr = len(basis), len(self._c11), len(self._c23)
        m = self.m
        self.numbers = Numbers(Nm=nm, Nc=nm - nr, Ni=ni, Nr=nr, Ng=m - (6 - ni),
                               Nd=m - (r - nr), Nh=m - (6 + r - nm))

    # --- presentation -------------------------------------------------------------
    @property
    def ring(self):
        return self.kinematics.ring

    @property
    def variables(self) -> tuple[sp.Symbol, ...]:
        """The symbols left in the results (free joint variables, free parameters)."""
        return tuple(self.kinematics.symbols[n] for n in self.ring.names)

    def _sym(self, rows, shape=None) -> sp.Matrix:
        return matrix_to_sympy(rows, self.ring, self.kinematics.symbols, shape)

    def _cols(self, vectors, nrows) -> sp.Matrix:
        return columns_to_sympy(vectors, nrows, self.ring, self.kinematics.symbols)

    @cached_property
    def G(self) -> sp.Matrix:
        """The grasp matrix ``G`` (6 x 6n)."""
        return self._sym(self.kinematics.GT).T

    @cached_property
    def D(self) -> sp.Matrix:
        """``D`` (6n x r): joint velocities to the links' contact-frame velocities."""
        return self._sym(self.kinematics.D, (6 * len(self.model.contacts), self.r))

    @cached_property
    def H(self) -> sp.Matrix:
        """The contact-model selection ``H`` (m x 6n)."""
        return self._sym(self.kinematics.H, (0, 6 * len(self.model.contacts)))

    @cached_property
    def Q(self) -> sp.Matrix:
        """``Q = (H G^T | -H D)`` (m x (6 + r)), as rational functions."""
        return self._sym(self.kinematics.Q, (0, 6 + self.r))

    @cached_property
    def C(self) -> sp.Matrix:
        """``C`` in block form ``[[C11, C12, 0], [0, C22, C23]]``."""
        return sp.ImmutableMatrix(sp.BlockMatrix([
            [self.C11, self.C12, sp.zeros(6, self.numbers.Nr)],
            [sp.zeros(self.r, self.numbers.Ni), self.C22, self.C23]]).as_explicit())

    @cached_property
    def C11(self) -> sp.Matrix:
        """Basis of ``N(Gt^T)``: object motions with every joint locked (6 x Ni)."""
        return self._cols(self._c11, 6)

    @cached_property
    def C12(self) -> sp.Matrix:
        """Object part of the coordinated motions (6 x (Nc - Ni))."""
        return self._cols([v[:6] for v in self._coordinated], 6)

    @cached_property
    def C22(self) -> sp.Matrix:
        """Joint part of the coordinated motions (r x (Nc - Ni))."""
        return self._cols([v[6:] for v in self._coordinated], self.r)

    @cached_property
    def C23(self) -> sp.Matrix:
        """Basis of ``N(Dt)``: joint motions with the object fixed (r x Nr)."""
        return self._cols(self._c23, self.r)

    def blocks(self) -> dict[str, sp.Matrix]:
        return {"C11": self.C11, "C12": self.C12, "C22": self.C22, "C23": self.C23}

    def check(self) -> bool:
        """``Q C = 0`` exactly, on the integer-polynomial form of ``Q``."""
        cols = ([v + [self.ring.zctx.constant(0)] * self.r for v in self._c11]
                + self._coordinated
                + [[self.ring.zctx.constant(0)] * 6 + v for v in self._c23])
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
        x = self._solve(self._c11 + [v[:6] for v in self._coordinated], u, "object twist u")
        x2 = x[len(self._c11):]
        part = self._combine([v[6:] for v in self._coordinated], x2, self.r)
        return Motion(part, self.C23)

    def object_velocities(self, qdot: Sequence) -> Motion:
        """All object twists produced by joint velocities ``qdot`` (paper eq. 12):
        ``u = C12 x + C11 y``; raises :class:`InfeasibleMotion` when ``qdot`` is not
        in ``R(C2)`` (it would break a contact)."""
        x = self._solve([v[6:] for v in self._coordinated] + self._c23, qdot,
                        "joint velocity qdot")
        x2 = x[: len(self._coordinated)]
        part = self._combine([v[:6] for v in self._coordinated], x2, 6)
        return Motion(part, self.C11)

    def _solve(self, columns, rhs, what: str):
        """Exact ``x`` with ``sum x_j columns_j = rhs`` (columns independent), as
        (numerator, denominator) pairs of integer polynomials."""
        ring, syms = self.ring, self.kinematics.symbols
        n = len(columns[0]) if columns else len(rhs)
        if len(rhs) != n:
            raise InfeasibleMotion(f"{what}: expected {n} components, got {len(rhs)}")
        rows = []
        for i in range(n):
            num, den = sp.fraction(sp.together(sp.sympify(rhs[i])))
            try:
                pn = ring.to_zpoly(poly_from_sympy(num, ring, syms))
                pd = ring.to_zpoly(poly_from_sympy(den, ring, syms))
            except ValueError as exc:
                raise InfeasibleMotion(f"{what}[{i}]: {exc}") from None
            # scale to a common integer content: multiply the equation by den
            rows.append([c[i] * pd for c in columns] + [pn])
        k = len(columns)
        reduced, pivots = el.gauss_jordan(rows, k + 1)
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
        return {
            "system": self.model.name,
            "configuration": self.configuration.at_text(),
            "variables": [str(v) for v in self.variables],
            "joints": list(self.model.joint_names),
            "numbers": self.numbers.as_dict(),
            "blocks": {k: strs(v) for k, v in self.blocks().items()},
            "shapes": {k: list(v.shape) for k, v in self.blocks().items()},
        }

    def poly(self, p) -> sp.Expr:
        return poly_to_sympy(p, self.ring, self.kinematics.symbols)


def analyze(model: Model, config: Configuration) -> Analysis:
    """Analyze ``model`` at ``config`` exactly."""
    return Analysis(model, config, kinematics.build(model, config))
