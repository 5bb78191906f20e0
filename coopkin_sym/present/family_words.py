"""The words that name the families of a locus (see
:meth:`Locus.families <coopkin_sym.analysis.locus.facade.LocusMethods.families>`): a
family's name, the numbers that change, its members.

Example
-------
>>> family_name(0), family_name(25), family_name(26)
('A', 'Z', 'F27')
"""

from __future__ import annotations

from coopkin_sym.analysis.locus.families import Family

#: How many member numbers a family's row lists before "... (N in all)".
MAX_MEMBERS_LISTED = 8


def family_name(index: int) -> str:
    """The name of the family at ``index``: ``A`` to ``Z``, then ``F27``, ``F28``...

    Example
    -------
    >>> family_name(2)
    'C'
    """
    return chr(ord("A") + index) if index < 26 else f"F{index + 1}"


def changes_text(family: Family, arrow: str = "\u2192") -> str:
    """The numbers that change, ``"Nc 6 → 5, Nr 2 → 3"``.

    Example
    -------
    >>> changes_text(Family({"Nm": 3}, {"Nm": (2, 3)}, (0,), 0, True), "->")
    'Nm 2 -> 3'
    """
    return ", ".join(f"{k} {a} {arrow} {b}" for k, (a, b) in family.changes.items()) \
        or "as generic"


def members_text(family: Family) -> str:
    """The members by their numbers in the report (``"#1, #36 (2)"``), the first
    :data:`MAX_MEMBERS_LISTED` of them.

    Example
    -------
    >>> members_text(Family({}, {}, tuple(range(10)), 0, True))
    '#1, #2, #3, #4, #5, #6, #7, #8, ... (10 in all)'
    """
    shown = ", ".join(f"#{k + 1}" for k in family.members[:MAX_MEMBERS_LISTED])
    if len(family.members) > MAX_MEMBERS_LISTED:
        return f"{shown}, ... ({len(family.members)} in all)"
    return shown
