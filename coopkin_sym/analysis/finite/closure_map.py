"""The loop closure's polynomials as a constraint map to expand, without what they
prove redundant.

The constraint map ``F`` of :mod:`.constraints` has a row for every component of
every contact, and some of them can hold identically near a configuration (a planar
loop seen in space: its out-of-plane rows) or follow from the others. Their reduced
equations vanish to every order, so the expansion of ``F`` cannot decide, even where
the other rows would. The closure polynomials of :mod:`.loops` (or of a welded loop,
:func:`~.closure.closure_polynomials`) cut out the same configurations near the point
in fewer coordinates, and leave out the conditions that vanish identically; those
dependent ones that are proved to vanish on the manifold of the independent ones
(:func:`~.closure.proved_redundant`) are left out too. What is left is expanded and
decided as ``F`` is (:class:`ClosureMap` has the interface of
:class:`~.constraints.ConstraintMap` that :mod:`.reduce` and the decisions use), and
its first-order motions are written back as velocities ``(u, qdot)``: the coordinates
eliminated (the object's) follow from the others by ``J z = 0``.

Example
-------
>>> from coopkin_sym.model import load_model
>>> from coopkin_sym.model.configuration import Configuration
>>> from coopkin_sym.analysis.finite.constraints import ConstraintMap
>>> model = load_model("four-bar")
>>> cm = closure_map(ConstraintMap(model, Configuration.parse(model, "q1=-pi/2,q2=-pi/2")))
>>> cm.names, len(cm.polys)
(('w3', 'u_q1', 'u_q2'), 2)
"""

from __future__ import annotations

import sympy as sp

from coopkin_sym.analysis.finite.closure import (
    _linear,
    closure_polynomials,
    proved_redundant,
)
from coopkin_sym.analysis.finite.constraints import ConstraintMap
from coopkin_sym.analysis.finite.loops import contact_polynomials


class ClosureMap:
    """The closure polynomials ``polys`` (in ``names``, coordinates of ``base``; with
    ``alpha`` last over a number field) as a constraint map near the configuration of
    ``base`` (a :class:`~.constraints.ConstraintMap`).

    Example
    -------
    >>> from coopkin_sym.model import load_model
    >>> from coopkin_sym.model.configuration import Configuration
    >>> model = load_model("parallel-cranks")
    >>> cm = closure_map(ConstraintMap(model, Configuration.parse(model, None)))
    >>> [[str(x) for x in row] for row in cm.linear()][0], cm.extend({"w3": 0, "u_q1": 1})
    (['0', '2', '-2', '0'], {'w3': 0, 'u_q1': 1, 'p1': -2, 'p2': 0, 'u_q2': 1, 'u_q3': 1})
    """

    def __init__(self, base: ConstraintMap, polys: list, names: tuple[str, ...]):
        self.base = base
        self.polys = polys
        self.names = names
        self.point = base.point
        self._field = None if base.point is None else base.point.field

    def series_field(self, names, order: int):
        return self.base.series_field(names, order)

    def linear(self) -> list[list]:
        """The linear parts (exact rationals, or numbers of the field)."""
        return [_linear(p, len(self.names), self._field) for p in self.polys]

    def evaluate(self, field, z) -> list:
        """The polynomials at the series ``z`` (in the order of :attr:`names`)."""
        images = list(z) + ([field.alpha] if self._field is not None else [])
        return [field.red(p.compose(*images, ctx=field.ctx)) for p in self.polys]

    def extend(self, z: dict) -> dict:
        """A first-order motion in :attr:`names` (name -> exact value) with the
        coordinates of ``base`` it leaves out, from ``J z = 0``."""
        names = self.base.names
        missing = [k for k, name in enumerate(names) if name not in z]
        if not missing:
            return z
        from coopkin_sym.analysis.finite import _sym

        jac = sp.Matrix([[_sym(x) for x in row] for row in self.base.linear()])
        known = sp.Matrix([z.get(name, 0) for name in names])
        rhs = -(jac * known)
        sub = jac[:, missing]
        solution, params = sub.gauss_jordan_solve(rhs)
        values = solution.subs({p: 0 for p in params})
        out = dict(z)
        for k, v in zip(missing, values, strict=True):
            out[names[k]] = sp.radsimp(sp.expand(v))
        return out


def closure_map(cmap: ConstraintMap, timeout: float = 2.0) -> ClosureMap | None:
    """The closure polynomials of ``cmap``'s loop as a :class:`ClosureMap`, without
    the dependent ones proved redundant within ``timeout`` seconds; None when the
    system is not a loop (fewer than two contacts)."""
    if len(cmap.positions) < 2:
        return None
    welded = closure_polynomials(cmap)
    if welded is not None:
        polys, _ = welded
        nobj = 3 if cmap.planar else 6
        names = tuple(cmap.names[nobj:])
    else:
        polys, names = contact_polynomials(cmap)
    field = None if cmap.point is None else cmap.point.field
    polys = proved_redundant(polys, len(names), timeout, field)
    return ClosureMap(cmap, polys, tuple(names))
