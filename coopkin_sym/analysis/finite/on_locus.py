"""The finite mobility at the witnesses of a locus: which singular families are
bifurcations, which are shaky, and which only change the first-order numbers.

Each component with an exact rational witness gets, as plain data in
:attr:`~coopkin_sym.analysis.locus.types.Component.finite`, the finite mobility there
(:func:`~coopkin_sym.analysis.finite.finite_mobility`): its dimension (None when
undecided), the bounds proved, the first-order motions, the classification, how it was
decided, the order of the expansion and the dimensions of the branches. A component
with only an algebraic witness gets it there, over the number field of the witness
(:mod:`coopkin_sym.analysis.finite.algebraic`), with that field under ``"field"``; a
component with no witness keeps None.

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
from coopkin_sym.analysis.finite.constraints import check_holonomic
from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.errors import CoopkinError
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
    out = {"dimension": fm.dimension, "bounds": list(fm.bounds),
           "first_order": fm.first_order, "classification": fm.classification,
           "reason": fm.reason, "order": fm.order,
           "branches": [b.dimension for b in fm.branches]}
    if fm.field is not None:
        out["field"] = dict(fm.field)
    return out


def finite_at_witnesses(locus: Locus, model: Model, order: int | None = None) -> int:
    """The finite mobility at every witness of ``locus`` (a locus of ``model``):
    rational ones, and algebraic ones where a component has no rational witness; kept
    in each component's ``finite``; how many were computed. Raises
    :class:`~coopkin_sym.errors.FiniteMobilityError` for a contact that is not
    holonomic, before computing any."""
    check_holonomic(model)                       # refuses soft contacts at once
    done = 0
    for component in locus.components:
        point = component.witness
        if not isinstance(point, Configuration):
            point = (component.algebraic_witness or {}).get("point")
            if not point:
                continue
            try:
                found = finite_mobility(model, dict(point), order)
            except CoopkinError:
                # a witness whose values this expansion cannot take (an angle in a
                # root of a quintic, a field over the degree limit): not computed
                continue
            component.finite = finite_data(found)
            done += 1
            continue
        component.finite = finite_data(finite_mobility(model, point, order))
        done += 1
    return done
