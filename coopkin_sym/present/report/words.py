"""The small texts of a report: the numbers' meanings, the kinds of components, a
witness in ``--at`` syntax, a component's changes and the verdict of a float test.

Example
-------
>>> witness_text({"q1": "pi/2", "q2": "0"})
'q1=pi/2,q2=0'
"""

from __future__ import annotations

from collections.abc import Mapping

from coopkin_sym.analysis.classes import CLASS_NUMBERS
from coopkin_sym.analysis.locus.types import Component, FloatCheck
from coopkin_sym.analysis.numbers import NUMBER_NAMES

NUMBER_WORDS = {
    "Nm": "mobility: independent motions of object and joints that keep every contact",
    "Nc": "connectivity: independent motions of the object",
    "Ni": "indeterminacy: object motions left free with every joint locked",
    "Nr": "redundancy: joint motions that leave the object fixed",
    "Ng": "internal contact forces (no net wrench on the object)",
    "Nd": "defective directions: contact forces the joints cannot balance",
    "Nh": "hyperstatic directions: contact forces that neither the object nor the "
          "joints balance",
}
KIND_WORDS = {"hypersurface": "hypersurface", "subvariety": "subvariety (codimension 2+)",
              "isolated": "isolated point", "chart": "at q = pi (second chart)"}
KIND_PLURALS = {"hypersurface": "hypersurfaces", "subvariety": "subvarieties",
                "isolated": "isolated points", "chart": "at q = pi (second chart)"}

def witness_text(witness: Mapping[str, str] | None) -> str:
    """A witness in ``--at`` syntax (``"q1=pi/2,q2=0"``), or ``"none"``.

    Example
    -------
    >>> witness_text({"q1": "pi/2", "L": "1"})
    'q1=pi/2,L=1'
    """
    if not witness:
        return "none"
    return ",".join(f"{k}={v}" for k, v in witness.items())


def _numbers_tuple(numbers: Mapping[str, int]) -> str:
    return "(" + ", ".join(str(numbers.get(k, "?")) for k in NUMBER_NAMES) + ")"


def _changes(c: Component, generic: Mapping[str, int]) -> dict[str, tuple[int, int]]:
    if c.changes:
        return {k: tuple(v) for k, v in c.changes.items()}
    return {k: (generic[k], c.numbers[k]) for k in NUMBER_NAMES
            if k in generic and k in c.numbers and generic[k] != c.numbers[k]}


def _verdict(f: FloatCheck, generic: Mapping[str, int]) -> str:
    """``agree``, ``missed`` (a singular configuration given wrong numbers) or
    ``false`` (a regular configuration called singular); as Locus.float_summary."""
    if f.agree:
        return "agree"
    if f.distance != 0 and f.exact == dict(generic):
        return "false"
    return "missed"


VERDICT_WORDS = {"agree": "agrees", "missed": "wrong: missed a singular configuration",
                 "false": "wrong: called a regular configuration singular"}


def _distance_text(d: float) -> str:  # float-ok: reported distance, not a decision
    return "at the witness" if d == 0 else f"{d:.0e} rad away"  # float-ok


def _component_name(k: int) -> str:
    return f"#{k + 1}"


def _has_classes(numbers: Mapping) -> bool:
    """Whether ``numbers`` holds every number the grasp classes come from (a report
    read back may hold fewer)."""
    return all(isinstance(numbers.get(n), int) for n in CLASS_NUMBERS.values())
