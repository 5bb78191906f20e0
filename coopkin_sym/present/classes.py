"""Grasp classes in words (the classes themselves: :mod:`coopkin_sym.analysis.classes`).

Example
-------
>>> from coopkin_sym.analysis.numbers import Numbers
>>> classes_text(Numbers(2, 2, 1, 0, 1, 4, 0))
'Grasp classes: indeterminate (Ni = 1), graspable (Ng = 1), defective (Nd = 4)'
"""

from __future__ import annotations

from collections.abc import Mapping

from coopkin_sym.analysis.classes import (
    CLASS_NUMBERS,
    class_changes,
    grasp_classes,
    number_of,
)
from coopkin_sym.analysis.numbers import Numbers


def classes_text(numbers: Numbers | Mapping[str, int]) -> str:
    """One line: the grasp classes with the numbers that make them.

    Example
    -------
    >>> classes_text({"Nm": 0, "Nc": 0, "Ni": 0, "Nr": 0, "Ng": 0, "Nd": 0, "Nh": 0})
    'Grasp classes: none (not redundant, indeterminate, graspable, defective or hyperstatic)'
    """
    held = grasp_classes(numbers)
    if not held:
        return ("Grasp classes: none (not redundant, indeterminate, graspable, defective "
                "or hyperstatic)")
    return "Grasp classes: " + ", ".join(
        f"{c} ({CLASS_NUMBERS[c]} = {number_of(numbers, CLASS_NUMBERS[c])})" for c in held)


def class_changes_text(numbers: Numbers | Mapping[str, int],
                       generic: Numbers | Mapping[str, int]) -> str:
    """The classes gained and lost against the generic ones, or ``"as generic"``.

    Example
    -------
    >>> generic = {"Nm": 3, "Nc": 3, "Ni": 0, "Nr": 0, "Ng": 1, "Nd": 0, "Nh": 0}
    >>> class_changes_text({**generic, "Nr": 1, "Nd": 1, "Nc": 2}, generic)
    'becomes redundant and defective'
    """
    changes = class_changes(numbers, generic)
    gained = [c for c, g in changes.items() if g]
    lost = [c for c, g in changes.items() if not g]
    parts = []
    if gained:
        parts.append("becomes " + _and(gained))
    if lost:
        parts.append("is no longer " + _and(lost))
    return "; ".join(parts) if parts else "as generic"


def _and(words: list[str]) -> str:
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]


__all__ = ["class_changes_text", "classes_text"]
