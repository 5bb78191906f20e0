"""Grasp classes: the names grasp analysis gives to the subspaces behind the numbers.

Prattichizzo and Trinkle ("Grasping", Springer Handbook of Robotics, the section on
grasp classifications) classify a grasp by the nullspaces of the grasp matrix ``G``
and the hand Jacobian ``J``; with the contact constraints ``H`` of the paper,
``G^T`` is ``H G^T`` and ``J`` is ``H D``:

=============  ==========================  ===================================  ======
class          condition                   meaning                              number
=============  ==========================  ===================================  ======
redundant      ``N(J) != 0``               joint motions with the object fixed  ``Nr``
indeterminate  ``N(G^T) != 0``             object motions with the joints       ``Ni``
                                           locked
graspable      ``N(G) != 0``               internal contact forces (squeezing   ``Ng``
                                           the object; what force closure
                                           needs, friction permitting)
defective      ``N(J^T) != 0``             contact forces no joint torque       ``Nd``
                                           balances
hyperstatic    ``N(G) & N(J^T) != 0``      internal forces the joints cannot    ``Nh``
                                           control
=============  ==========================  ===================================  ======

A class holds exactly when its number is positive, so the classes come from the
numbers alone: exact wherever the numbers are, generic or at a point, and they change
on the locus components where those numbers change.

Example
-------
>>> from coopkin_sym.analysis.numbers import Numbers
>>> grasp_classes(Numbers(2, 2, 1, 0, 1, 4, 0))          # paper case 1, hard contacts
('indeterminate', 'graspable', 'defective')
"""

from __future__ import annotations

from collections.abc import Mapping

from coopkin_sym.analysis.numbers import Numbers

#: The grasp classes, in the order every output uses.
GRASP_CLASSES: tuple[str, ...] = ("redundant", "indeterminate", "graspable", "defective",
                                  "hyperstatic")

#: The number whose positivity makes each class.
CLASS_NUMBERS: dict[str, str] = {"redundant": "Nr", "indeterminate": "Ni",
                                 "graspable": "Ng", "defective": "Nd", "hyperstatic": "Nh"}


def number_of(numbers: Numbers | Mapping[str, int], name: str) -> int:
    """One number, from :class:`Numbers` or a mapping of them.

    Example
    -------
    >>> number_of({"Nr": 2}, "Nr")
    2
    """
    return numbers[name] if isinstance(numbers, Mapping) else getattr(numbers, name)


def grasp_classes(numbers: Numbers | Mapping[str, int]) -> tuple[str, ...]:
    """The classes a grasp with these numbers belongs to, in :data:`GRASP_CLASSES` order.

    Example
    -------
    >>> grasp_classes({"Nm": 3, "Nc": 3, "Ni": 0, "Nr": 0, "Ng": 1, "Nd": 0, "Nh": 0})
    ('graspable',)
    """
    return tuple(c for c in GRASP_CLASSES if number_of(numbers, CLASS_NUMBERS[c]) > 0)


def class_changes(numbers: Numbers | Mapping[str, int], generic: Numbers | Mapping[str, int]
                  ) -> dict[str, bool]:
    """The classes gained (True) or lost (False) where the numbers are ``numbers``
    instead of ``generic``.

    Example
    -------
    >>> generic = {"Nm": 3, "Nc": 3, "Ni": 0, "Nr": 0, "Ng": 1, "Nd": 0, "Nh": 0}
    >>> class_changes({**generic, "Nc": 2, "Nr": 1, "Nd": 1}, generic)
    {'redundant': True, 'defective': True}
    """
    here, there = set(grasp_classes(numbers)), set(grasp_classes(generic))
    return {c: c in here for c in GRASP_CLASSES if (c in here) != (c in there)}


__all__ = ["CLASS_NUMBERS", "GRASP_CLASSES", "class_changes", "grasp_classes", "number_of"]
