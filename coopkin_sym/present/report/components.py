"""The components in a report: their table, and for each its equations, numbers,
witness and float rank tests.

Example
-------
>>> from coopkin_sym.analysis.locus.types import Component
>>> generic = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
>>> _numbers_cells(Component(["t_q1"], dict(generic, Nm=3), None, True), generic)[:2]
[[('strong', '3')], [('text', '2')]]
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from coopkin_sym.analysis.classes import grasp_classes
from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.analysis.numbers import NUMBER_NAMES
from coopkin_sym.exact.angles import joint_of
from coopkin_sym.exact.polynomial import NamedPolynomial
from coopkin_sym.present.classes import class_changes_text
from coopkin_sym.present.conditions import (
    PolynomialNames,
    condition_text,
    is_long,
    short_condition,
)
from coopkin_sym.present.finite import finite_summary
from coopkin_sym.present.formula import latex as _latex
from coopkin_sym.present.remarks import remark_text
from coopkin_sym.present.report.blocks import (
    Bullets,
    Formula,
    Heading,
    Paragraph,
    Span,
    Table,
    _t,
)
from coopkin_sym.present.report.formulas import MAX_EQUATION
from coopkin_sym.present.report.words import (
    KIND_WORDS,
    VERDICT_WORDS,
    _changes,
    _component_name,
    _distance_text,
    _has_classes,
    _numbers_tuple,
    _verdict,
    witness_text,
)
from coopkin_sym.present.sentences import component_sentences


def _numbers_cells(c: Component, generic: Mapping[str, int]) -> list[list]:
    cells = []
    for k in NUMBER_NAMES:
        v = c.numbers.get(k)
        text = "?" if v is None else str(v)
        changed = v is not None and generic.get(k) is not None and v != generic[k]
        cells.append([("strong", text)] if changed else [_t(text)])
    return cells


def _float_cell(c: Component, generic: Mapping[str, int]) -> list[Span]:
    if not c.float_checks:
        return [_t("not run")]
    verdicts = [_verdict(f, generic) for f in c.float_checks]
    wrong = len(verdicts) - verdicts.count("agree")
    if not wrong:
        return [_t(f"agrees ({len(verdicts)}/{len(verdicts)})")]
    missed, false = verdicts.count("missed"), verdicts.count("false")
    kinds = ([f"{missed} missed"] if missed else []) + \
        ([f"{false} false alarm{'' if false == 1 else 's'}"] if false else [])
    return [("strong", f"{wrong}/{len(verdicts)} wrong"), _t(": " + ", ".join(kinds))]


def _algebraic_witness_cell(w: Mapping, equations: Sequence[NamedPolynomial] = (),
                            compact: bool = False) -> list:
    """An algebraic witness: exact in ``--at`` syntax when short, else its value to 12
    digits (the exact point is in the component's details); ``compact`` (tables) keeps
    only the joints of the equations, to 4 digits."""
    point = w["point"]
    if all(len(str(v)) <= 32 and "CRootOf" not in str(v) for v in point.values()):
        return [("at", witness_text(point))]
    approx = dict(point)
    approx.update({k: v for k, v in w.get("approx", {}).items()})
    if compact:
        used = {joint_of(n) or n for e in equations for n in e.variables}
        shown = {k: f"{float(v):.4g}" for k, v in w.get("approx", {}).items()  # float-ok
                 if k in used}
        if shown:
            return [_t("\u2248 "), ("at", witness_text(shown)), _t(" (exact: below)")]
    return [_t("\u2248 "), ("at", witness_text(approx))]


def _components_table(locus: Locus, names: PolynomialNames | None = None) -> Table:
    """The table of the components (long polynomials by their ``names``)."""
    rows = []
    for k, c in enumerate(locus.components):
        name = _component_name(k)
        if c.parent is not None:
            name += f" (in #{c.parent + 1})"
        where = [("cond", short_condition(c, names))]
        if not c.real:
            where.append(_t(" (real points: undecided)"))
        witness = [("at", witness_text(c.witness))] if c.witness else [_t("none")]
        if not c.witness and c.algebraic_witness:
            witness = _algebraic_witness_cell(c.algebraic_witness, c.equations,
                                              compact=True)
        rows.append([[_t(name)], where, [_t(KIND_WORDS.get(c.kind, c.kind))],
                     *_numbers_cells(c, locus.generic), witness,
                     _float_cell(c, locus.generic)])
    header = ["#", "where", "kind", *NUMBER_NAMES, "witness (--at)", "float test"]
    return Table(header, rows, "lll" + "c" * 7 + "ll",
                 {0: "0.9cm", 1: "2.3cm", 10: "2.6cm", 11: "1.6cm"}, css="components",
                 latex_skip=(2,))


def _equation_parts(equations: Sequence[NamedPolynomial],
                    names: PolynomialNames | None = None) -> list[Span]:
    """The equations; with ``names``, a long one by its name (written out in the
    appendix)."""
    parts: list[Span] = []
    for i, e in enumerate(equations):
        if i:
            parts.append(_t(", "))
        if names is not None and is_long(e):
            parts.append(("code", f"{names.name(e)}({', '.join(sorted(e.variables))}) = 0"))
        elif len(e.text) > MAX_EQUATION:
            parts.append(("code", e.text[:MAX_EQUATION] + " ..."))
            parts.append(_t(f" ({len(e.text)} characters; all of it in the JSON report) = 0"))
        else:
            parts.append(("eq0", Formula(e.text, _latex(e.to_sympy()))))
    return parts


def _component_blocks(locus: Locus, k: int, c: Component,
                      names: PolynomialNames | None = None) -> list:
    """One component's details (long polynomials by their ``names``)."""
    name = f"Component {_component_name(k)}: "
    out: list = [Heading(3, [_t(name), ("cond" if c.condition else "text",
                                        short_condition(c, names))], f"component-{k + 1}")]
    items: list[list[Span]] = []
    items.append([("strong", "Equations:"), _t(" "), *_equation_parts(c.equations, names)])
    if c.condition:
        items.append([("strong", "In angles:"), _t(" "), ("cond", condition_text(c, names))])
    if c.outside:
        items.append([("strong", "Except where:"), _t(" "),
                      *_equation_parts(c.outside, names),
                      _t(" (denominators of its parametrization; those points are "
                         "searched apart)")])
    kind = KIND_WORDS.get(c.kind, c.kind)
    where = f"depth {c.depth}"
    if c.parent is not None:
        where += f", inside component #{c.parent + 1}"
    items.append([("strong", "Kind:"), _t(" "), _t(f"{kind} ({where}); "
                                           + ("real points" if c.real
                                              else "real points: undecided"))])
    changes = _changes(c, locus.generic)
    numbers = [("strong", "Numbers:"), _t(f" {_numbers_tuple(c.numbers)} for "
                                          f"({', '.join(NUMBER_NAMES)})")]
    if changes:
        text = ", ".join(f"{n} {a} \u2192 {b}" for n, (a, b) in changes.items())
        numbers.append(_t(f": {text}; the others as generic"))
    else:
        numbers.append(_t(": as generic"))
    items.append(numbers)
    if _has_classes(c.numbers) and _has_classes(locus.generic):
        held = ", ".join(grasp_classes(c.numbers)) or "none"
        items.append([("strong", "Grasp classes:"), _t(f" {held} "
                      f"({class_changes_text(c.numbers, locus.generic)})")])
    if c.drops:
        items.append([("strong", "Rank drops in:"), _t(" "), _t(", ".join(c.drops))])
    if c.finite is not None:
        items.append([("strong", "Finite mobility at the witness:"), _t(" "),
                      _t(finite_summary(c.finite))])
    if c.witness:
        checked = ("; a direct exact analysis there gives the same numbers"
                   if c.witness_checked else "; not checked by a direct analysis")
        items.append([("strong", "Witness:"), _t(" "), ("at", witness_text(c.witness)),
                      _t(checked)])
    elif c.algebraic_witness:
        w = c.algebraic_witness
        checked = ("; a direct exact analysis over Q(alpha) there gives the same numbers"
                   if c.witness_checked else "")
        items.append([("strong", "Witness:"), _t(" none with rational coordinates; a real "
                                                  "point with algebraic ones: "),
                      *_algebraic_witness_cell(w), _t(checked)])
        items.append([("strong", "Exact point:"), _t(f" alpha = {w['alpha']} is the root "
                                                      f"of "), ("eq0", w["root_of"]),
                      _t(f" in ({w['interval'][0]}, {w['interval'][1]}]: alpha = "
                         f"{w['root']}")])
    else:
        items.append([("strong", "Witness:"), _t(" "), _t("none with rational coordinates")])
    if c.decided:
        items.append([("strong", "Decided:"), _t(" "), _t(remark_text(c.decided))])
    out.append(Bullets(items))
    meaning = component_sentences(c)
    if meaning:
        out.append(Paragraph([("strong", "What changes there:")]))
        out.append(Bullets([[_t(s)] for s in meaning]))
    if c.float_checks:
        out += _float_check_blocks(c, locus.generic)
    return out


def _float_check_blocks(c: Component, generic: Mapping[str, int]) -> list:
    header = ["where", "point", "exact numbers", "float numbers", "verdict"]
    widths = {0: "1.5cm", 1: "3.9cm", 4: "1.7cm"}
    rows, wrong = [], []
    for f in c.float_checks:
        verdict = _verdict(f, generic)
        where = _distance_text(f.distance) + (f", {f.scale}" if f.scale else "")
        row = [[_t(where)], [("at", witness_text(f.point))],
               [("nums", _numbers_tuple(f.exact))], [("nums", _numbers_tuple(f.float))],
               [_t(VERDICT_WORDS[verdict])] if verdict == "agree"
               else [("strong", VERDICT_WORDS[verdict])]]
        rows.append(row)
        if verdict != "agree":
            wrong.append(row)
    n = len(rows)
    count = f"{n} test{'' if n == 1 else 's'} at and near the witness, "
    count += f"{len(wrong)} wrong" if wrong else "all agree with the exact numbers"
    tests = f" (numpy matrix_rank, default tolerance): {count}"  # float-ok: words
    out: list = [Paragraph([("strong", "Float rank tests"),
                            _t(tests + (":" if wrong else "."))], only=("latex",)),
                 Paragraph([("strong", "Float rank tests"), _t(f"{tests}.")],
                           only=("markdown", "html")),
                 Table(header, rows, "lllll", widths, css="checks",
                       only=("markdown", "html"), details=f"the {n} float tests")]
    if wrong:
        out.append(Table(header, wrong, "lllll", widths, css="checks", only=("latex",)))
    return out
