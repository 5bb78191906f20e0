"""The families of a locus in a report: one row for each kind of singular
configuration (the numbers that change, in words), with its components and one of them
as an example.

Example
-------
>>> from coopkin_sym import load
>>> families_table(load("paper-case1-hard").locus()).rows[1][3]
[('text', '#5')]
"""

from __future__ import annotations

from coopkin_sym.analysis.locus.families import Family
from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.present.conditions import PolynomialNames, short_condition
from coopkin_sym.present.family_words import changes_text, family_name, members_text
from coopkin_sym.present.finite import family_finite_text
from coopkin_sym.present.report.blocks import Paragraph, Span, Table, _h, _t
from coopkin_sym.present.report.components import _algebraic_witness_cell
from coopkin_sym.present.report.words import _component_name, witness_text
from coopkin_sym.present.sentences import change_words


def _example_cells(locus: Locus, family: Family, names: PolynomialNames | None
                   ) -> tuple[list[Span], list[Span]]:
    c = locus.components[family.example]
    where: list[Span] = [_t(_component_name(family.example) + ": "),
                         ("cond", short_condition(c, names))]
    if not family.real:
        where.append(_t(" (real points: undecided)"))
    if c.witness:
        return where, [("at", witness_text(c.witness))]
    if c.algebraic_witness:
        return where, _algebraic_witness_cell(c.algebraic_witness, c.equations,
                                              compact=True)
    return where, [_t("none")]


def families_table(locus: Locus, names: PolynomialNames | None = None) -> Table:
    """The table of the families of ``locus`` (long polynomials by their ``names``).

    Example
    -------
    >>> from coopkin_sym import load
    >>> table = families_table(load("paper-case1-hard").locus())
    >>> table.header[:3], [row[1] for row in table.rows][:1]
    (['family', 'what changes', 'in words'], [[('text', 'Nm 2 → 3, Nc 2 → 3, Nh 0 → 1')]])
    """
    rows = []
    finite = any(c.finite is not None for c in locus.components)
    for i, family in enumerate(locus.families()):
        where, witness = _example_cells(locus, family, names)
        row = [[_t(family_name(i))], [_t(changes_text(family))],
               [_t(change_words(family.changes))], [_t(members_text(family))]]
        if finite:          # which families are bifurcations, which only first-order
            row.append([_t(family_finite_text(
                [locus.components[m].finite for m in family.members]))])
        rows.append([*row, where, witness])
    header = ["family", "what changes", "in words", "components",
              *(["finite motion"] if finite else []), "for example", "witness (--at)"]
    if finite:
        return Table(header, rows, "lllllll", {1: "2.0cm", 2: "3.0cm", 3: "1.6cm",
                                                4: "2.2cm", 5: "2.6cm", 6: "2.4cm"},
                     css="families", latex_skip=(6,))
    return Table(header, rows, "llllll",
                 {1: "2.2cm", 2: "3.6cm", 3: "1.8cm", 4: "3.0cm", 5: "2.6cm"},
                 css="families", latex_skip=(5,))


def families_blocks(locus: Locus, names: PolynomialNames | None = None) -> list:
    """The section of the families: what they are, and their table (none for a locus
    without components).

    Example
    -------
    >>> from coopkin_sym import load
    >>> [b.kind for b in families_blocks(load("paper-case1-hard").locus())]
    ['heading', 'paragraph', 'table']
    """
    if not locus.components:
        return []
    families = locus.families()
    n, k = len(locus.components), len(families)
    said = ("The component below, by the numbers that change there:" if n == 1 else
            f"The {n} components below fall into {k} famil{'y' if k == 1 else 'ies'} by "
            "the numbers that change there: one kind of singular configuration each, "
            "wherever the search found it (symmetric copies, the same family with a "
            "joint at q = pi, pieces found inside other components).")
    return [_h(2, "Families", "families"), Paragraph([_t(said)]),
            families_table(locus, names)]
