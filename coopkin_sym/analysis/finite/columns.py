"""Which first-order motions of the paper's blocks are finite ones.

Each column of ``C11`` (object motions with the joints still), of ``C12``/``C22``
(the driven motions) and of ``C23`` (the redundant joint motions) is a velocity
``v = (u, qdot)`` with ``Q v = 0``. It is a finite motion's velocity when it lies in
the tangent space of a branch found by :func:`~coopkin_sym.analysis.finite.finite_mobility`
(or is a rotation of the group split off there). Otherwise its coordinates ``x`` in
the first-order motions of the reduction are put into the lowest-order terms ``h`` of
the reduced constraints ``g``: an arc ``x(t) = t x + O(t^2)`` gives
``g(x(t)) = t^d h(x) + O(t^(d+1))``, so where ``h(x) != 0`` no finite motion has that
velocity, and the column extends to order ``d - 1`` exactly. Where every lowest term
vanishes at ``x`` and no branch holds it, the column extends at least to the order
reached, and beyond that is not decided.

Example
-------
>>> from coopkin_sym import load
>>> a = load("four-bar").analyze("q1=-pi/2,q2=-pi/2")
>>> [(c.block, c.verdict, c.order) for c in a.finite_mobility().columns]
[('C12', 'finite', None), ('C12', 'fails', 2)]
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import flint
import sympy as sp

from coopkin_sym.analysis.finite import FiniteMobility, _configuration, stabilizer
from coopkin_sym.analysis.finite.constraints import ConstraintMap
from coopkin_sym.analysis.finite.reduce import reduce_map
from coopkin_sym.exact.matrix import RATIONALS, rank

#: The verdicts of a column.
VERDICTS = ("finite", "fails", "undecided")


@dataclass(frozen=True)
class ColumnVerdict:
    """What becomes of one column of the paper's blocks: ``block`` (``"C11"``,
    ``"C12"`` for the driven columns of ``C12``/``C22``, ``"C23"``), ``index`` (from
    1), ``verdict`` (one of :data:`VERDICTS`) and ``order``: for ``"fails"`` the
    order at which the constraints fail along it (it extends to ``order - 1``), for
    ``"undecided"`` the order it is proved to extend to; None for ``"finite"``.

    Example
    -------
    >>> ColumnVerdict("C23", 1, "fails", 2).extends_to
    1
    """

    block: str
    index: int
    verdict: str
    order: int | None = None

    @property
    def extends_to(self) -> int | None:
        """The highest order to which the column extends as proved (None: all)."""
        if self.verdict == "finite":
            return None
        return self.order - 1 if self.verdict == "fails" else self.order


def block_columns(blocks: dict, dim: int) -> list[tuple[str, int, list]]:
    """The columns of ``C`` as velocities ``(u, qdot)``, each with its block and index
    (``blocks``: ``C11``, ``C12``, ``C22``, ``C23`` as SymPy matrices; ``dim`` the
    object twist's size)."""
    out = []
    c11, c12, c22, c23 = (blocks[k] for k in ("C11", "C12", "C22", "C23"))
    r = c22.rows if c22.rows else c23.rows
    for j in range(c11.cols):
        out.append(("C11", j + 1, list(c11[:, j]) + [0] * r))
    for j in range(c12.cols):
        out.append(("C12", j + 1, list(c12[:, j]) + list(c22[:, j])))
    for j in range(c23.cols):
        out.append(("C23", j + 1, [0] * dim + list(c23[:, j])))
    return out


def _rational(x) -> bool:
    """Whether ``x`` (a SymPy number or a Python integer) is rational."""
    return bool(x.is_Rational) if isinstance(x, sp.Basic) else isinstance(x, int)


def _in_span(v: list, basis: tuple) -> bool:
    """Whether the rational ``v`` lies in the span of ``basis`` (exact numbers: over
    Q with flint, SymPy only for a tangent written with radicals)."""
    if not any(x != 0 for x in v):
        return True
    if not basis:
        return False
    rows = [list(b) for b in basis]
    if all(_rational(x) for row in rows for x in row):
        rows = [[flint.fmpq(str(x)) for x in row] for row in rows]
        return rank(rows, len(v), RATIONALS) == rank(
            [*rows, [flint.fmpq(str(x)) for x in v]], len(v), RATIONALS)
    m = sp.Matrix(rows).T
    return m.rank(simplify=True) == m.row_join(sp.Matrix(v)).rank(simplify=True)


def _coordinates(cmap: ConstraintMap, v: list) -> list | None:
    """The coordinates ``z`` (in :attr:`ConstraintMap.names`) of the velocity ``v``
    (None when it moves a joint the map holds still)."""
    nobj = 3 if cmap.planar else 6
    moving = set(cmap.moving)
    if any(v[nobj + k] != 0 for k in range(len(cmap.joint_names)) if k not in moving):
        return None
    raw = list(v[:nobj]) + [v[nobj + k] for k in cmap.moving]
    return [sp.Rational(x) / s for x, s in zip(raw, cmap.scale, strict=True)]


def column_verdicts(model, config, fm, blocks: dict, slice_rows=(),
                    group: tuple = ()) -> tuple[ColumnVerdict, ...]:
    """The verdict of every column of ``blocks`` (at the rational configuration
    ``config`` where ``fm`` was found; ``slice_rows`` and ``group``: the group split
    off there, :func:`~coopkin_sym.analysis.finite.stabilizer`). Empty when an entry
    is not a rational number."""
    nobj = 3 if model.planar else 6
    columns = block_columns(blocks, nobj)
    if any(not _rational(x) for _, _, v in columns for x in v):
        return ()
    tangents = [b.tangent for b in fm.branches if b.tangent is not None]
    base = ConstraintMap(model, config)
    motions = [_coordinates(base, list(m)) for m in group]
    out, lowest = [], []
    for block, index, v in columns:
        if fm.dimension is not None and any(_in_span(v, t) for t in tangents):
            out.append(ColumnVerdict(block, index, "finite"))
            continue
        if not lowest:                      # the reduction, once, where it is needed
            lowest.append(_lowest_terms(model, config, slice_rows, fm.order))
        work, red, lows = lowest[0]
        z = _coordinates(base, v)
        if z is None:
            out.append(ColumnVerdict(block, index, "undecided", 1))
            continue
        z = _on_slice(z, slice_rows, motions)
        x = [flint.fmpq(int(z[work.names.index(f)].p), int(z[work.names.index(f)].q))
             for f in red.free]
        failed = next((d for d, h in lows if h(*x) != 0), None) if x else None
        out.append(ColumnVerdict(block, index, "fails", failed) if failed is not None
                   else ColumnVerdict(block, index, "undecided", red.order))
    return tuple(out)


def _lowest_terms(model, config, slice_rows, order: int):
    """The map on the slice, its reduction to ``order`` and the lowest-order terms of
    the reduced constraints (degree, form), lowest first."""
    work = ConstraintMap(model, config, slice_rows)
    red = reduce_map(work, max(order, 1))
    field = work.series_field(red.free, red.order)
    lows = sorted(((d, h) for d, h in (field.lowest(g) for g in red.g) if d <= red.order),
                  key=lambda dh: dh[0])
    return work, red, lows


def _on_slice(z: list, rows, motions: list) -> list:
    """``z`` less its part along the group's motions, so that it meets the slice's
    linear forms ``rows`` (each motion given in the same coordinates)."""
    if not rows:
        return z
    a = sp.Matrix([[sum(sp.Rational(r) * m for r, m in zip(row, mot, strict=True))
                    for mot in motions] for row in rows])
    b = sp.Matrix([sum(sp.Rational(r) * x for r, x in zip(row, z, strict=True))
                   for row in rows])
    coef = a.LUsolve(b)
    return [x - sum((coef[j] * motions[j][i] for j in range(len(motions))), sp.Integer(0))
            for i, x in enumerate(z)]


def with_columns(fm: FiniteMobility, model, at, blocks: dict) -> FiniteMobility:
    """``fm`` (found at the rational configuration ``at`` of ``model``) with the
    verdict of every column of ``blocks`` (the analysis's ``C11``, ``C12``, ``C22``,
    ``C23`` there) in :attr:`FiniteMobility.columns`; unchanged at an algebraic
    configuration."""
    config, _, point = _configuration(model, at)
    if point is not None:
        return fm
    exact = {}
    for k, m in blocks.items():
        values = {x: config.parameters[x.name] for x in m.free_symbols
                  if x.name in config.parameters}
        exact[k] = m.subs(values) if values else m
    rows, motions = stabilizer(ConstraintMap(model, config))
    return replace(fm, columns=column_verdicts(model, config, fm, exact, rows,
                                               tuple(motions)))
