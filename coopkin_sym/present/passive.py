"""The passive-joint analysis in words (the analysis itself:
:mod:`coopkin_sym.analysis.passive`).

Example
-------
>>> from coopkin_sym import load
>>> print(passive_lines(load("five-bar").analyze("L=1").passive)[0])
Passive joints: q2, q4 (actuated: q1, q3)
"""

from __future__ import annotations

from collections.abc import Mapping

from coopkin_sym.analysis.passive import PASSIVE_NUMBER_NAMES, PassiveAnalysis, PassiveNumbers

#: What each passive-joint number counts, in a few words.
PASSIVE_WORDS = {
    "Na": "actuated joints",
    "Np": "passive joints",
    "Nco": "object motions the motors control",
    "Nuo": "object motions possible with every motor still (uncontrolled)",
    "Npi": "passive joint motions with the object and the motors still",
    "Nar": "motor motions that leave the object still",
    "Nam": "independent motor velocities the contacts admit",
}


def passive_numbers_text(numbers: PassiveNumbers | Mapping[str, int]) -> str:
    """The passive-joint numbers on one line.

    Example
    -------
    >>> passive_numbers_text({"Na": 2, "Np": 2, "Nco": 2, "Nuo": 1, "Npi": 0,
    ...                       "Nar": 0, "Nam": 2})
    'Na = 2  Np = 2  Nco = 2  Nuo = 1  Npi = 0  Nar = 0  Nam = 2'
    """
    get = numbers.get if isinstance(numbers, Mapping) else lambda k: getattr(numbers, k)
    return "  ".join(f"{k} = {get(k)}" for k in PASSIVE_NUMBER_NAMES)


def passive_lines(p: PassiveAnalysis) -> list[str]:
    """What ``coopkin analyze`` prints about passive joints: the joints, the numbers
    and one sentence per nonzero count.

    Example
    -------
    >>> from coopkin_sym import load
    >>> passive_lines(load("five-bar").analyze("L=1").passive)[2]
    '- the motors control 2 object motions; 1 object motion stays free with every motor still'
    """
    n = p.numbers
    out = [f"Passive joints: {', '.join(p.passive) or 'none'} (actuated: "
           f"{', '.join(p.actuated) or 'none'})", passive_numbers_text(n)]
    said = f"- the motors control {_count(n.Nco, 'object motion')}"
    said += (f"; {_count(n.Nuo, 'object motion')} "
             f"{'stays' if n.Nuo == 1 else 'stay'} free with every motor still"
             if n.Nuo else "; no object motion is possible with every motor still")
    out.append(said)
    if n.Npi:
        out.append(f"- {_count(n.Npi, 'motion')} of the passive joints alone "
                   f"{'leaves' if n.Npi == 1 else 'leave'} the object and the motors still")
    if n.Nar:
        out.append(f"- {_count(n.Nar, 'motor motion')} {'leaves' if n.Nar == 1 else 'leave'} "
                   f"the object still (the passive joints follow)")
    out.append(f"- {_count(n.Nam, 'independent motor velocity', 'independent motor velocities')}"
               f" {'keeps' if n.Nam == 1 else 'keep'} every contact")
    return out


def _count(k: int, one: str, many: str | None = None) -> str:
    return f"{k} {one if k == 1 else (many or one + 's')}"


__all__ = ["PASSIVE_WORDS", "passive_lines", "passive_numbers_text"]
