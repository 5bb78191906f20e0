"""The finite mobility at the witnesses of a locus: which singular families are
bifurcations, which are shaky, and which only change the first-order numbers.

Each component with an exact rational witness gets, as plain data in
:attr:`~coopkin_sym.analysis.locus.types.Component.finite`, the finite mobility there
(:func:`~coopkin_sym.analysis.finite.finite_mobility`): its dimension (None when
undecided), the bounds proved, the first-order motions, the classification, how it was
decided, the order of the expansion and the dimensions of the branches. A component
with an algebraic witness, or none, keeps None.

Example
-------
>>> from coopkin_sym import load
>>> system = load("four-bar")
>>> locus = system.locus()
>>> finite_at_witnesses(locus, system.model)
4
>>> [c.finite["classification"] for c in locus.components]
['bifurcation', 'shaky', 'shaky', 'bifurcation']
"""

from __future__ import annotations

from coopkin_sym.analysis.finite import FiniteMobility, finite_mobility
from coopkin_sym.analysis.finite.constraints import ConstraintMap
from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model


def finite_data(fm: FiniteMobility) -> dict:
    """The plain data a component keeps of a finite mobility.

    Example
    -------
    >>> from coopkin_sym import load
    >>> finite_data(load("shaky-pinned-bars").finite_mobility())["classification"]
    'shaky'
    """
    return {"dimension": fm.dimension, "bounds": list(fm.bounds),
            "first_order": fm.first_order, "classification": fm.classification,
            "reason": fm.reason, "order": fm.order,
            "branches": [b.dimension for b in fm.branches]}


def finite_at_witnesses(locus: Locus, model: Model, order: int | None = None) -> int:
    """The finite mobility at every rational witness of ``locus`` (a locus of
    ``model``), kept in each component's ``finite``; how many were computed. Raises
    :class:`~coopkin_sym.errors.FiniteMobilityError` for a contact that is not
    holonomic, before computing any."""
    done = 0
    for component in locus.components:
        point = component.witness
        if not isinstance(point, Configuration):
            continue
        if done == 0:
            ConstraintMap(model, point)          # refuses soft contacts at once
        component.finite = finite_data(finite_mobility(model, point, order))
        done += 1
    return done
