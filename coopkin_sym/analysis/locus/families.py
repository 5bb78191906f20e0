"""The components of a locus grouped by what changes there: one family for each set of
numbers met (the same kind of singular configuration, wherever the search found it:
symmetric copies, the same family written in another chart, pieces at other depths).

Example
-------
>>> from coopkin_sym.analysis.locus.types import Component
>>> generic = {"Nm": 2, "Nc": 2}
>>> parts = [Component(["t_q1 - 1"], {"Nm": 3, "Nc": 3}, {"q1": "pi/2"}, True),
...          Component(["t_q1 + 1"], {"Nm": 3, "Nc": 3}, {"q1": "-pi/2"}, True)]
>>> [(f.changes, f.members) for f in group_families(parts, generic)]
[({'Nm': (2, 3), 'Nc': (2, 3)}, (0, 1))]
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from coopkin_sym.analysis.numbers import NUMBER_NAMES


@dataclass(frozen=True)
class Family:
    """Components of a locus with the same numbers.

    Attributes
    ----------
    numbers
        The numbers on every member (at its generic points).
    changes
        Number name -> (generic, here), for the numbers that differ, in the order of
        :data:`~coopkin_sym.analysis.numbers.NUMBER_NAMES`.
    members
        Indices of the members in :attr:`Locus.components`, in their order there.
    example
        The member to show first: one with real points and a rational witness where
        there is one, with the fewest joints pinned at ``q = pi`` (the widest chart),
        the shallowest, then the one with the fewest equations.
    real
        Whether some member has real points.

    Example
    -------
    >>> from coopkin_sym import load
    >>> families = load("paper-case1-hard").locus().families()
    >>> [(f.changes["Nc"], len(f.members)) for f in families]
    [((2, 3), 4), ((2, 3), 1)]
    """

    numbers: dict[str, int]
    changes: dict[str, tuple[int, int]]
    members: tuple[int, ...]
    example: int
    real: bool


def _changes(numbers: Mapping[str, Any], generic: Mapping[str, Any]
             ) -> dict[str, tuple[int, int]]:
    names = [n for n in NUMBER_NAMES if n in numbers] + \
        sorted(n for n in numbers if n not in NUMBER_NAMES)
    return {n: (generic[n], numbers[n]) for n in names
            if n in generic and numbers[n] != generic[n]}


def _at_pi(component: Any) -> int:
    """How many joints the component pins at ``q = pi`` (its ``s_`` equations)."""
    return sum(1 for e in component.equations
               if str(getattr(e, "text", e)).startswith("s_"))


def _example_key(component: Any, index: int) -> tuple:
    return (not component.real, component.witness is None, _at_pi(component),
            component.depth, len(component.equations), index)


def group_families(components: Sequence[Any], generic: Mapping[str, int]) -> list[Family]:
    """The families of ``components`` (each with ``numbers``, ``real``, ``witness``,
    ``depth`` and ``equations``), in the order of their first member.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Component
    >>> a = Component(["t_q1"], {"Nm": 3}, None, False)
    >>> b = Component(["t_q2"], {"Nm": 4}, {"q2": "0"}, True)
    >>> [f.members for f in group_families([a, b, a], {"Nm": 2})]
    [(0, 2), (1,)]
    """
    groups: dict[tuple, list[int]] = {}
    for k, c in enumerate(components):
        key = tuple(sorted((n, v) for n, v in c.numbers.items()))
        groups.setdefault(key, []).append(k)
    families = []
    for members in groups.values():
        numbers = dict(components[members[0]].numbers)
        example = min(members, key=lambda k: _example_key(components[k], k))
        families.append(Family(numbers, _changes(numbers, generic), tuple(members), example,
                               any(components[k].real for k in members)))
    return families
