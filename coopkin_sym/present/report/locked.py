"""The passive joints in a report: where the numbers of the passive joints change,
from the locus of the system with its motors held still.

Example
-------
>>> from coopkin_sym.analysis.locus.types import Locus
>>> locked = Locus("demo", [], "", {}, locked_joints=["q1"])
>>> [b.kind for b in _passive_blocks(Locus("demo", [], "", {}), locked)][:3]
['heading', 'paragraph', 'table']
"""

from __future__ import annotations

from collections.abc import Mapping

from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.analysis.passive import PASSIVE_NUMBER_NAMES, passive_numbers
from coopkin_sym.present.certificate import completeness_text
from coopkin_sym.present.conditions import PolynomialNames, condition_text
from coopkin_sym.present.passive import PASSIVE_WORDS
from coopkin_sym.present.remarks import grouped_remark_texts
from coopkin_sym.present.report.blocks import Paragraph, Table, _h, _t
from coopkin_sym.present.report.formulas import _list_or
from coopkin_sym.present.report.words import witness_text


def _locked_numbers(locus: Locus, locked: Locus, numbers: Mapping[str, int]
                    ) -> dict[str, int | str]:
    """The passive-joint numbers the locked system's ``numbers`` give, with the
    system's generic ones (``?`` where a number is missing)."""
    try:
        p = passive_numbers(len(locked.locked_joints), 0, locus.generic, numbers)
    except (KeyError, TypeError):
        return {k: "?" for k in PASSIVE_NUMBER_NAMES}
    return p.as_dict()


def _passive_blocks(locus: Locus, locked: Locus, names: PolynomialNames | None = None
                    ) -> list:
    """Where the passive-joint numbers change: the generic ones and the components of
    the locus of the system with its motors held still (long polynomials by their
    ``names`` in the report)."""
    out: list = [_h(2, "Passive joints", "passive")]
    motors = ", ".join(locked.locked_joints) or "none"
    out.append(Paragraph([_t("Motors (actuated joints): "), ("code", motors),
                          _t("; every other joint is passive. With the motors held still, the "
                             "object motions left free (Nuo) and the motions of the passive "
                             "joints alone (Npi) are the locked system's Nc and Nr - Na: they "
                             "change exactly where its numbers change, a locus searched like the "
                             "one above. Nco = Nc - Nuo, Nar = Nr - Npi and Nam = Nco + Nar "
                             "change only on the components of either locus.")]))
    generic = _locked_numbers(locus, locked, locked.generic)
    rows = [[[("strong", k)], [_t(PASSIVE_WORDS[k])], [_t(str(generic[k]))]]
            for k in PASSIVE_NUMBER_NAMES if k not in ("Na", "Np")]
    out.append(Table(["number", "meaning", "generic value"], rows, "llc", {1: "7.5cm"},
                     css="numbers"))
    said = completeness_text(locked)
    n = len(locked.components)
    out.append(Paragraph([_t(f"Locus of the locked system: {n} component{'' if n == 1 else 's'}; "
                             f"{said}."
                             + (f" Not explored there: {len(locked.unexplored)} item"
                                f"{'' if len(locked.unexplored) == 1 else 's'}, listed below "
                                f"the table." if locked.unexplored else ""))], css="summary"))
    table = []
    for k, c in enumerate(locked.components):
        values = _locked_numbers(locus, locked, c.numbers)
        if all(values[key] == generic[key] for key in ("Nuo", "Npi")):
            continue   # only the locked system's other numbers change there
        name = f"L{k + 1}" + (f" (in L{c.parent + 1})" if c.parent is not None else "")
        cells = [[("strong", str(values[key]))] if values[key] != generic[key]
                 else [_t(str(values[key]))] for key in ("Nuo", "Npi")]
        witness = [("at", witness_text(c.witness))] if c.witness else [_t("none")]
        if not c.real:
            witness.append(_t(" (real points: undecided)"))
        table.append([[_t(name)], [("cond", condition_text(c, names))], *cells, witness])
    others = len(locked.components) - len(table)
    if table:
        out.append(Table(["#", "where", "Nuo", "Npi", "witness (--at)"], table, "llccl",
                         {0: "0.9cm", 1: "6cm", 4: "4cm"}, css="components"))
    else:
        out.append(Paragraph([_t("Nuo and Npi keep their generic values on every component "
                                 "found.")]))
    if others:
        out.append(Paragraph([_t(f"{others} other component{'' if others == 1 else 's'} of the "
                                 f"locked system change{'s' if others == 1 else ''} only its "
                                 f"other numbers (its JSON report lists "
                                 f"{'it' if others == 1 else 'them'} under \"locked\").")]))
    if locked.unexplored:
        out.append(Paragraph([_t("Not explored in the locked system:")]))
        out.extend(_list_or(grouped_remark_texts(locked.unexplored), ""))
    return out
