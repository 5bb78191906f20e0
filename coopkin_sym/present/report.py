"""Singularity-locus reports: Markdown, HTML, LaTeX and JSON.

A report says, for a :class:`~coopkin_sym.analysis.locus.types.Locus`: the generic numbers;
every component (its equations, where it reads simply in angles, its numbers and what
changes, what the change means, an exact witness point in ``--at`` syntax, and what a
float rank test says there); how many singular configurations the float tests missed
and how many regular ones they called singular; parameter-only conditions, factors
dropped for having no real points, and what was not explored within the bounds.
Markdown and HTML reports carry plots of the components on pairs of joint variables
(see :mod:`coopkin_sym.present.locus_plot`); the HTML page is self-contained (the PNGs are
embedded). The LaTeX is an appendix to ``\\input`` in a paper (plain ``article``
class, no packages needed). The JSON is :meth:`Locus.to_json` for programs.

Example
-------
>>> from coopkin_sym.analysis.locus.types import Component, Locus
>>> generic = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
>>> locus = Locus("demo", ["t_q1", "t_q2"], "", generic, [Component(
...     ["t_q1 + 1", "t_q2 + 1"], dict(generic, Nm=3, Nc=3, Nh=1),
...     {"q1": "-pi/2", "q2": "-pi/2"}, True, kind="isolated")])
>>> row = next(x for x in render_markdown(locus).splitlines() if x.startswith("| #1"))
>>> row.split(" | ")[3:11]
['**3**', '**3**', '1', '0', '1', '4', '**1**', '`q1=-pi/2,q2=-pi/2`']
"""

from __future__ import annotations

import base64
import html
import io
import json
import os
import re
import time
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import sympy as sp

from coopkin_sym.analysis.classes import CLASS_NUMBERS, grasp_classes
from coopkin_sym.analysis.locus.types import Component, FloatCheck, Locus
from coopkin_sym.analysis.mobility import Analysis
from coopkin_sym.analysis.numbers import NUMBER_NAMES
from coopkin_sym.analysis.passive import PASSIVE_NUMBER_NAMES, passive_numbers
from coopkin_sym.errors import DrawError, OutputSkipped, ReportError, SkippedForTime
from coopkin_sym.exact.parse import FUNCTIONS, NumberError, brief, parse_expression
from coopkin_sym.model.configuration import Point
from coopkin_sym.present.certificate import certificate_json, completeness_text
from coopkin_sym.present.classes import class_changes_text, classes_text
from coopkin_sym.present.draw import MOTION_KINDS, draw_system, gained_motion, motion_counts
from coopkin_sym.present.files import check_output_path, write_files
from coopkin_sym.present.locus_plot import PlotError, default_pairs, plot_png
from coopkin_sym.present.passive import PASSIVE_WORDS
from coopkin_sym.present.remarks import remark_text, remark_texts
from coopkin_sym.present.report_input import ReportInputError, validate_report
from coopkin_sym.present.sentences import component_sentences

__all__ = ["FORMATS", "ReportError", "check_target", "locus_from_json", "parse_pairs",
           "render_html", "render_json", "render_latex", "render_markdown",
           "witness_text", "write_report"]

#: Report formats by file suffix.
FORMATS: dict[str, str] = {".md": "markdown", ".html": "html", ".tex": "latex",
                           ".json": "json"}

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
# names the parser reads itself (functions and constants), never variables
_PARSER_NAMES = {*FUNCTIONS, "pi", "CRootOf"}
# longest equation text shown in a report (the JSON always has all of it)
MAX_EQUATION = 1500
# rows per LaTeX tabular
LATEX_ROWS = 30



# ------------------------------------------------------------------ small texts


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


def _condition(c: Component) -> str:
    return c.condition or " and ".join(f"{e} = 0" for e in c.equations) or "(no equations)"


# a clause of a condition longer than this is named, not written out, in tables/titles
_LONG_CLAUSE = 48


def _short_condition(c: Component) -> str:
    """The condition with every long polynomial clause replaced by ``P<k>(vars) = 0``,
    ``k`` its place among the component's equations (written out in the details).

    Example
    -------
    >>> c = Component(["t_a2", "3*t_a1**2*t_b1**2 + 8*t_a1*t_b1 + 3*t_a1**2 - 7*t_b1 + 1"],
    ...               {}, None, True, condition="a2 = 0, 3*t_a1**2*t_b1**2 + 8*t_a1*t_b1"
    ...               " + 3*t_a1**2 - 7*t_b1 + 1 = 0")
    >>> _short_condition(c)
    'a2 = 0, P2(t_a1, t_b1) = 0'
    """
    text = _condition(c)
    alternatives = text.split(" or ")
    if len(alternatives) > 2:
        # several real points of one family: the first, and how many more
        text = f"{alternatives[0]} or ..."
    out = []
    for clause in text.split(", "):
        if len(clause) > _LONG_CLAUSE and clause.endswith(" = 0"):
            poly = clause[:-4]
            k = next((i + 1 for i, e in enumerate(c.equations) if e == poly), None)
            names = sorted(set(re.findall(r"\bt_[A-Za-z0-9_]+|\b[A-Za-z]\w*", poly)))
            label = f"P{k}" if k else "P"
            clause = f"{label}({', '.join(names)}) = 0"
        out.append(clause)
    return ", ".join(out)


# ------------------------------------------------------------------ document model
#
# The report is built once as a list of blocks; each format renders the blocks.
# Inline text is a list of (kind, value): "text", "code", "strong", "eq" (a polynomial),
# "at" (an --at text), "cond" (a condition in angles).


@dataclass
class _H:
    level: int
    text: str
    anchor: str = ""
    parts: list[tuple[str, str]] | None = None   # richer form, for LaTeX


@dataclass
class _P:
    parts: list[tuple[str, str]]
    css: str = ""
    only: tuple[str, ...] = ()


@dataclass
class _List:
    items: list[list[tuple[str, str]]]


@dataclass
class _Table:
    header: list[str]
    rows: list[list[list[tuple[str, str]]]]
    align: str = ""          # one letter per column: l, c, r
    latex_widths: dict[int, str] | None = None   # column -> p{width} in LaTeX
    css: str = ""
    latex_skip: tuple[int, ...] = ()    # columns left out of the LaTeX table
    only: tuple[str, ...] = ()          # formats that show it (all when empty)
    details: str = ""                   # HTML: a collapsed table with this summary


@dataclass
class _Plot:
    pair: tuple[str, str]
    ref: Any


def _t(text: str) -> tuple[str, str]:
    return ("text", text)


def _generic_table(locus: Locus) -> _Table:
    rows = [[[("strong", k)], [_t(NUMBER_WORDS[k])], [_t(str(locus.generic.get(k, "?")))]]
            for k in NUMBER_NAMES]
    return _Table(["number", "meaning", "generic value"], rows, "llc", {1: "7.5cm"},
                  css="numbers")


def _numbers_cells(c: Component, generic: Mapping[str, int]) -> list[list]:
    cells = []
    for k in NUMBER_NAMES:
        v = c.numbers.get(k)
        text = "?" if v is None else str(v)
        changed = v is not None and generic.get(k) is not None and v != generic[k]
        cells.append([("strong", text)] if changed else [_t(text)])
    return cells


def _float_cell(c: Component, generic: Mapping[str, int]) -> list[tuple[str, str]]:
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


def _algebraic_witness_cell(w: Mapping, equations: Sequence[str] = (),
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
        used = {n[2:] if n.startswith("t_") else n
                for e in equations for n in re.findall(r"[A-Za-z_]\w*", e)}
        shown = {k: f"{float(v):.4g}" for k, v in w.get("approx", {}).items()  # float-ok
                 if k in used}
        if shown:
            return [_t("\u2248 "), ("at", witness_text(shown)), _t(" (exact: below)")]
    return [_t("\u2248 "), ("at", witness_text(approx))]


def _components_table(locus: Locus) -> _Table:
    rows = []
    for k, c in enumerate(locus.components):
        name = _component_name(k)
        if c.parent is not None:
            name += f" (in #{c.parent + 1})"
        where = [("cond", _short_condition(c))]
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
    return _Table(header, rows, "lll" + "c" * 7 + "ll",
                  {0: "0.9cm", 1: "2.3cm", 10: "2.6cm", 11: "1.6cm"}, css="components",
                  latex_skip=(2,))


def _locked_numbers(locus: Locus, locked: Locus, numbers: Mapping[str, int]
                    ) -> dict[str, int | str]:
    """The passive-joint numbers the locked system's ``numbers`` give, with the
    system's generic ones (``?`` where a number is missing)."""
    try:
        p = passive_numbers(len(locked.locked_joints), 0, locus.generic, numbers)
    except (KeyError, TypeError):
        return {k: "?" for k in PASSIVE_NUMBER_NAMES}
    return p.as_dict()


def _passive_blocks(locus: Locus, locked: Locus) -> list:
    """Where the passive-joint numbers change: the generic ones and the components of
    the locus of the system with its motors held still."""
    out: list = [_H(2, "Passive joints", "passive")]
    motors = ", ".join(locked.locked_joints) or "none"
    out.append(_P([_t("Motors (actuated joints): "), ("code", motors),
                   _t("; every other joint is passive. With the motors held still, the "
                      "object motions left free (Nuo) and the motions of the passive "
                      "joints alone (Npi) are the locked system's Nc and Nr - Na: they "
                      "change exactly where its numbers change, a locus searched like the "
                      "one above. Nco = Nc - Nuo, Nar = Nr - Npi and Nam = Nco + Nar "
                      "change only on the components of either locus.")]))
    generic = _locked_numbers(locus, locked, locked.generic)
    rows = [[[("strong", k)], [_t(PASSIVE_WORDS[k])], [_t(str(generic[k]))]]
            for k in PASSIVE_NUMBER_NAMES if k not in ("Na", "Np")]
    out.append(_Table(["number", "meaning", "generic value"], rows, "llc", {1: "7.5cm"},
                      css="numbers"))
    said = completeness_text(locked)
    n = len(locked.components)
    out.append(_P([_t(f"Locus of the locked system: {n} component{'' if n == 1 else 's'}; "
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
        table.append([[_t(name)], [("cond", _condition(c))], *cells, witness])
    others = len(locked.components) - len(table)
    if table:
        out.append(_Table(["#", "where", "Nuo", "Npi", "witness (--at)"], table, "llccl",
                          {0: "0.9cm", 1: "6cm", 4: "4cm"}, css="components"))
    else:
        out.append(_P([_t("Nuo and Npi keep their generic values on every component "
                          "found.")]))
    if others:
        out.append(_P([_t(f"{others} other component{'' if others == 1 else 's'} of the "
                          f"locked system change{'s' if others == 1 else ''} only its "
                          f"other numbers (its JSON report lists "
                          f"{'it' if others == 1 else 'them'} under \"locked\").")]))
    if locked.unexplored:
        out.append(_P([_t("Not explored in the locked system:")]))
        out.extend(_list_or(remark_texts(locked.unexplored), ""))
    return out


def _equation_parts(equations: Sequence[str]) -> list[tuple[str, str]]:
    parts: list[tuple[str, str]] = []
    for i, e in enumerate(equations):
        if i:
            parts.append(_t(", "))
        if len(e) > MAX_EQUATION:
            parts.append(("code", e[:MAX_EQUATION] + " ..."))
            parts.append(_t(f" ({len(e)} characters; all of it in the JSON report) = 0"))
        else:
            parts.append(("eq0", e))
    return parts


def _component_blocks(locus: Locus, k: int, c: Component) -> list:
    name = f"Component {_component_name(k)}: "
    out: list = [_H(3, name + _short_condition(c), f"component-{k + 1}",
                    [_t(name), ("cond" if c.condition else "text", _short_condition(c))])]
    items: list[list[tuple[str, str]]] = []
    items.append([("strong", "Equations:"), _t(" "), *_equation_parts(c.equations)])
    if c.condition:
        items.append([("strong", "In angles:"), _t(" "), ("cond", c.condition)])
    if c.outside:
        items.append([("strong", "Except where:"), _t(" "), *_equation_parts(c.outside),
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
    out.append(_List(items))
    meaning = component_sentences(c)
    if meaning:
        out.append(_P([("strong", "What changes there:")]))
        out.append(_List([[_t(s)] for s in meaning]))
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
    out: list = [_P([("strong", "Float rank tests"),
                     _t(f" (numpy matrix_rank, default tolerance): {count}"  # float-ok: words
                        + (":" if wrong else "."))], only=("latex",)),
                 _P([("strong", "Float rank tests"),
                     _t(f" (numpy matrix_rank, default tolerance): {count}.")],  # float-ok: words
                    only=("markdown", "html")),
                 _Table(header, rows, "lllll", widths, css="checks",
                        only=("markdown", "html"), details=f"the {n} float tests")]
    if wrong:
        out.append(_Table(header, wrong, "lllll", widths, css="checks", only=("latex",)))
    return out


def _float_summary_blocks(locus: Locus) -> list:
    s = locus.float_summary()
    total = sum(len(c.float_checks) for c in locus.components)
    out: list = [_H(2, "Float rank tests", "float-tests")]
    if not total:
        out.append(_P([_t("No float rank tests were run.")]))
        return out
    at_w = sum(1 for c in locus.components for f in c.float_checks if f.distance == 0)
    out.append(_P([
        _t(f"At and near each witness the numbers were also computed with float rank "
           f"tests (numpy matrix_rank, default tolerance) and compared with the exact "  # float-ok
           f"ones: {total} tests ({at_w} at witnesses, {total - at_w} nearby). "),
        ("strong", f"Missed singular configurations: {s['missed_singular']}"),
        _t("; "),
        ("strong", f"regular configurations called singular: {s['false_singular']}"),
        _t(".")], css="summary"))
    rows = []
    for k, c in enumerate(locus.components):
        if not c.float_checks:
            continue
        v = [_verdict(f, locus.generic) for f in c.float_checks]
        rows.append([[_t(_component_name(k))], [("cond", _short_condition(c))],
                     [_t(str(len(v)))], [_t(str(v.count("agree")))],
                     [_t(str(v.count("missed")))], [_t(str(v.count("false")))]])
    out.append(_Table(["#", "where", "tests", "agree", "missed singular",
                       "regular called singular"], rows, "llcccc",
                      {1: "3.4cm", 4: "1.5cm", 5: "1.7cm"}, css="floatsum"))
    return out


#: Tests not certified listed one by one in a report (all are in its JSON).
SHOWN_FAILURES = 10


def _certificate_blocks(locus: Locus) -> list:
    """The completeness certificate: per depth, the tests not certified, its notes."""
    out: list = [_H(2, "Completeness certificate", "certificate")]
    if locus.certificate is None:
        said = completeness_text(locus)
        out.append(_P([_t(said[:1].upper() + said[1:]
                          + ": no proof was made that the components above hold every "
                            "configuration where the numbers change.")]))
        return out
    cert = certificate_json(locus.certificate)
    tests = cert.get("tests", 0)
    out.append(_P([("strong", cert["summary"]),
                   _t(f" ({tests} exact test{'' if tests == 1 else 's'} in "
                      f"{len(cert.get('charts', {}))} chart"
                      f"{'' if len(cert.get('charts', {})) == 1 else 's'}, "
                      f"{cert.get('seconds', 0):.1f} s).")], css="summary"))  # float-ok
    lines = []
    for depth, entry in cert.get("depths", {}).items():
        n, failed = entry.get("tests", 0), entry.get("failed", 0)
        if entry.get("certified"):
            lines.append([_t(f"Depth {depth}: certified ({n} test{'' if n == 1 else 's'}"
                             + (f"; {entry['why']}" if entry.get("why") else "") + ").")])
        else:
            lines.append([_t(f"Depth {depth}: not certified ({failed} of {n} tests): "
                             f"{entry.get('why', '')}.")])
    if lines:
        out.append(_List(lines))
    failed = cert.get("failed", [])
    if failed:
        shown = [[_t(f"{c.get('chart')}, depth {c.get('depth')}"
                     + (f", component #{c['inside'] + 1}" if c.get("inside") is not None
                        else "")
                     + (", rank of " if c.get("kind") == "drops" else ", numbers, rank of ")
                     + f"{c.get('matrix')}: {c.get('why')}")]
                 for c in failed[:SHOWN_FAILURES]]
        more = len(failed) - SHOWN_FAILURES
        out.append(_P([_t(f"Tests not certified ({len(failed)}"
                          + (f"; the first {SHOWN_FAILURES} here, all in the JSON"
                             if more > 0 else "") + "):")]))
        out.append(_List(shown))
    if cert.get("notes"):
        out.extend(_list_or(cert["notes"], ""))
    return out


def _formula(text: str) -> list[tuple[str, str]]:
    """``t_q1**2 + 1 = 0 (no real points)`` as an equation and its words; plain text
    when it is not a polynomial."""
    head, sep, tail = text.partition(" = 0")
    head = head if sep else text
    if _parses(head):
        return [("eq0" if sep else "eq", head)] + ([_t(tail)] if tail else [])
    return [_t(text)]


def _parses(text: str) -> bool:
    if not re.fullmatch(r"[A-Za-z0-9_+\-*/^() .]+", text) or not re.search(r"[A-Za-z]", text):
        return False
    return _read(text) is not None


def _read(text: str) -> sp.Expr | None:
    """``text`` read by the package's parser, every name in it a variable (but the
    parser's own functions and ``pi``), or ``None`` when it is not a formula."""
    names = [n for n in dict.fromkeys(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", text))
             if n not in _PARSER_NAMES]
    try:
        return parse_expression(text, names, "formula", max_length=MAX_EQUATION)
    except NumberError:
        return None


def _list_or(items: Sequence[str], none: str, formulas: bool = False) -> list:
    if not items:
        return [_P([_t(none)])]
    return [_List([_formula(s) if formulas else [_t(s)] for s in items])]


def _blocks(locus: Locus, plots: Mapping[tuple[str, str], Any] | None,
            with_plots: bool) -> list:
    out: list = [_H(1, f"Singularity locus of {locus.system}")]
    variables = ", ".join(locus.variables) or "none"
    setting = [_t("Free variables: "), ("code", variables)]
    if any(v.startswith("t_") for v in locus.variables):
        setting += [_t(" ("), ("code", "t_X = tan(X/2)"), _t(" for a revolute joint X)")]
    setting.append(_t(". Fixed: "))
    setting.append(("at", locus.fixed) if locus.fixed else
                   _t("nothing (every joint variable and parameter free)"))
    setting.append(_t("."))
    if locus.seconds:
        setting.append(_t(f" Computed in {locus.seconds:.1f} s."))  # float-ok: time
    out.append(_P(setting))
    real = [c for c in locus.components if c.real]
    counts = {}
    for c in real:
        counts[c.kind] = counts.get(c.kind, 0) + 1
    kinds = ", ".join(f"{n} {KIND_WORDS.get(k, k) if n == 1 else KIND_PLURALS.get(k, k)}"
                      for k, n in counts.items())
    summary = [_t(f"{len(locus.components)} component"
                  f"{'' if len(locus.components) == 1 else 's'} where the numbers differ "
                  f"from the generic ones")]
    if locus.components:
        summary.append(_t(f" ({len(real)} with real points" + (f": {kinds}" if kinds else "")
                          + ")"))
    summary.append(_t("."))
    if locus.unexplored:
        summary.append(_t(" "))
        summary.append(("strong", f"Not everything was explored: {len(locus.unexplored)} "
                                  f"item{'' if len(locus.unexplored) == 1 else 's'} "
                                  f"below."))
    out.append(_P(summary, css="summary"))
    said = completeness_text(locus)
    out.append(_P([("strong", said[:1].upper() + said[1:]), _t(".")]
                  if locus.certificate is None else
                  [_t("Completeness: "), ("strong", said), _t(".")], css="summary"))
    out.append(_H(2, "Generic numbers", "generic"))
    out.append(_generic_table(locus))
    if _has_classes(locus.generic):
        out.append(_P([_t(classes_text(locus.generic) + ".")]))
    out.append(_H(2, "Components", "components"))
    if locus.components:
        out.append(_P([_t("Numbers that differ from the generic ones are in bold. "
                          "Witnesses are exact points, in the syntax of "),
                       ("code", "coopkin analyze --at"), _t(".")]))
        out.append(_components_table(locus))
        for k, c in enumerate(locus.components):
            out.extend(_component_blocks(locus, k, c))
    else:
        out.append(_P([_t("None: the numbers are the generic ones at every configuration"
                          " explored.")]))
    if locus.locked is not None:
        out.extend(_passive_blocks(locus, locus.locked))
    out.extend(_float_summary_blocks(locus))
    if with_plots:
        out.append(_H(2, "Plots", "plots"))
        if plots:
            out.append(_P([_t("Real components drawn from their exact polynomials over "
                              "q in [-pi, pi] (t = tan(q/2) is infinite at q = pi); "
                              "isolated components as points; exact witnesses as stars.")]))
            pictures = [p for p in plots if p[0] == SYSTEM_PICTURE]
            for pair, ref in plots.items():
                if pictures and pair == pictures[0]:
                    out.extend(_pictures_intro(locus))
                out.append(_Plot(tuple(pair), ref))
        else:
            out.append(_P([_t("No plots: no real component to draw.")]))
    out.append(_H(2, "Parameter conditions", "parameters"))
    out.extend(_list_or(remark_texts(locus.parameter_conditions),
                        "None: no degeneracy that involves the parameters alone.", True))
    out.append(_H(2, "Dropped factors (no real points)", "dropped"))
    out.extend(_list_or(remark_texts(locus.dropped), "None.", True))
    out.append(_H(2, "Not explored", "unexplored"))
    out.extend(_list_or(remark_texts(locus.unexplored), "Nothing: the search finished within its "
                                          "bounds."))
    out.extend(_certificate_blocks(locus))
    if locus.notes:
        out.append(_H(2, "Notes", "notes"))
        out.extend(_list_or(remark_texts(locus.notes), ""))
    return out


# ------------------------------------------------------------------ Markdown


def _one_line(text: str) -> str:
    """Line breaks and other control characters as spaces: user text cannot start a
    new line (a heading, a table row, a LaTeX line outside a comment)."""
    return _CONTROL.sub(" ", text)


_CONTROL = re.compile(r"[\x00-\x1f\x7f-\x9f\u2028\u2029]")


def _md_escape(text: str) -> str:
    return re.sub(r"([\\`*_\[\]|<>])", r"\\\1", _one_line(text))


def _md_code(text: str) -> str:
    """A code span that no text can leave: its fence is longer than any run of
    backticks inside, and pipes are escaped for tables."""
    text = _one_line(text).replace("|", "\\|")
    longest = max((len(run) for run in re.findall(r"`+", text)), default=0)
    fence = "`" * (longest + 1)
    pad = " " if text.startswith("`") or text.endswith("`") or longest else ""
    return f"{fence}{pad}{text}{pad}{fence}"


def _md_inline(parts: Sequence[tuple[str, str]]) -> str:
    out = []
    for kind, value in parts:
        if kind == "text":
            out.append(_md_escape(value))
        elif kind == "strong":
            out.append(f"**{_md_escape(value)}**")
        elif kind == "nums":
            out.append(value)
        elif kind == "eq0":
            out.append(_md_code(f"{value} = 0"))
        else:
            out.append(_md_code(value))
    return "".join(out)


def render_markdown(locus: Locus, plots: Mapping[tuple[str, str], str] | None = None) -> str:
    """The report as Markdown (GitHub tables); ``plots`` maps joint pairs to the
    relative paths of their PNGs.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> print(render_markdown(Locus("demo", [], "", {"Nm": 1})).splitlines()[0])
    # Singularity locus of demo
    """
    lines: list[str] = []
    for b in _blocks(locus, plots, plots is not None):
        if "markdown" not in (getattr(b, "only", ()) or ("markdown",)):
            continue
        if isinstance(b, _H):
            lines += ["#" * b.level + " " + _md_escape(b.text), ""]
        elif isinstance(b, _P):
            lines += [_md_inline(b.parts), ""]
        elif isinstance(b, _List):
            lines += [f"- {_md_inline(item)}" for item in b.items] + [""]
        elif isinstance(b, _Table):
            align = {"l": ":--", "c": ":-:", "r": "--:"}
            lines.append("| " + " | ".join(_md_escape(h) for h in b.header) + " |")
            lines.append("|" + "|".join(align[a] for a in b.align) + "|")
            for row in b.rows:
                lines.append("| " + " | ".join(_md_inline(c) for c in row) + " |")
            lines.append("")
        elif isinstance(b, _Plot):
            lines += [f"![{_md_escape(_caption(b.pair))}]({b.ref})", ""]
    return "\n".join(lines).rstrip() + "\n"


# ------------------------------------------------------------------ HTML

_CSS = """
body { font-family: -apple-system, "Segoe UI", Helvetica, Arial, sans-serif;
  color: #1f2328; max-width: 1100px; margin: 2em auto; padding: 0 1.5em;
  line-height: 1.5; font-size: 15px; }
h1 { font-size: 1.7em; border-bottom: 2px solid #d0d7de; padding-bottom: .3em; }
h2 { font-size: 1.3em; margin-top: 1.8em; border-bottom: 1px solid #d8dee4;
  padding-bottom: .2em; }
h3 { font-size: 1.05em; margin-top: 1.5em; }
code { font-family: ui-monospace, Menlo, Consolas, monospace; font-size: .9em;
  background: #f3f4f6; padding: .1em .3em; border-radius: 4px; }
table { border-collapse: collapse; margin: .6em 0 1em; font-size: .92em; }
th, td { border: 1px solid #d0d7de; padding: .3em .6em; text-align: left;
  vertical-align: top; }
th { background: #f0f3f6; font-weight: 600; }
tr:nth-child(even) td { background: #fafbfc; }
td.c, th.c { text-align: center; }
table.components td strong, table.checks td strong, table.floatsum td strong {
  color: #b42318; }
table.components td.c strong { display: inline-block; min-width: 1.2em;
  background: #fde8e7; border-radius: 3px; }
p.summary { background: #f6f8fa; border-left: 4px solid #0969da; padding: .5em .9em; }
ul { padding-left: 1.4em; }
li { margin: .15em 0; }
figure { margin: 1em 0; }
figure img { max-width: 100%; border: 1px solid #d8dee4; border-radius: 4px; }
figcaption { color: #57606a; font-size: .9em; }
details { margin: .3em 0 1em; }
details summary { cursor: pointer; color: #0969da; }
table.checks code { word-break: break-all; font-size: .85em; }
table.components code, li code { overflow-wrap: anywhere; }
.nums { white-space: nowrap; }
"""


def _html_inline(parts: Sequence[tuple[str, str]]) -> str:
    out = []
    for kind, value in parts:
        if kind == "text":
            out.append(html.escape(value))
        elif kind == "nums":
            out.append(f'<span class="nums">{html.escape(value)}</span>')
        elif kind == "strong":
            out.append(f"<strong>{html.escape(value)}</strong>")
        elif kind == "eq0":
            out.append(f"<code>{html.escape(value)} = 0</code>")
        else:
            out.append(f"<code>{html.escape(value)}</code>")
    return "".join(out)


def render_html(locus: Locus, plots: Mapping[tuple[str, str], bytes] | None = None) -> str:
    """The report as one self-contained HTML page; ``plots`` maps joint pairs to PNG
    bytes (embedded as data URIs).

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> render_html(Locus("demo", [], "", {"Nm": 1})).startswith("<!DOCTYPE html>")
    True
    """
    body: list[str] = []
    for b in _blocks(locus, plots, plots is not None):
        if "html" not in (getattr(b, "only", ()) or ("html",)):
            continue
        if isinstance(b, _H):
            anchor = f' id="{b.anchor}"' if b.anchor else ""
            body.append(f"<h{b.level}{anchor}>{html.escape(b.text)}</h{b.level}>")
        elif isinstance(b, _P):
            css = f' class="{b.css}"' if b.css else ""
            body.append(f"<p{css}>{_html_inline(b.parts)}</p>")
        elif isinstance(b, _List):
            body.append("<ul>" + "".join(f"<li>{_html_inline(i)}</li>" for i in b.items)
                        + "</ul>")
        elif isinstance(b, _Table):
            cls = [' class="c"' if a == "c" else "" for a in b.align]
            head = "".join(f"<th{c}>{html.escape(h)}</th>"
                           for h, c in zip(b.header, cls, strict=True))
            rows = "".join("<tr>" + "".join(f"<td{c}>{_html_inline(cell)}</td>"
                                            for cell, c in zip(row, cls, strict=True))
                           + "</tr>" for row in b.rows)
            css = f' class="{b.css}"' if b.css else ""
            table = f"<table{css}><thead><tr>{head}</tr></thead><tbody>{rows}</tbody></table>"
            if b.details:
                table = (f"<details><summary>{html.escape(b.details)}</summary>{table}"
                         f"</details>")
            body.append(table)
        elif isinstance(b, _Plot):
            data = base64.b64encode(b.ref).decode("ascii")
            caption = _caption(b.pair)
            body.append(f'<figure><img alt="{html.escape(caption)}" '
                        f'src="data:image/png;base64,{data}">'
                        f"<figcaption>{html.escape(caption)}</figcaption></figure>")
    title = html.escape(f"Singularity locus of {locus.system}")
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            f"<title>{title}</title>\n<style>{_CSS}</style>\n</head>\n<body>\n"
            + "\n".join(body) + "\n</body>\n</html>\n")


# ------------------------------------------------------------------ LaTeX

_TEX_SPECIAL = {"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&",
                "#": r"\#", "^": r"\textasciicircum{}", "_": r"\_", "%": r"\%",
                "~": r"\textasciitilde{}", "\u2192": r"$\to$", "\u00b1": r"$\pm$",
                "<": r"$<$", ">": r"$>$", "|": r"$|$", "\u2260": r"$\neq$",
                "\u2264": r"$\leq$", "\u2265": r"$\geq$", "\u2248": r"$\approx$",
                "\u00b0": r"$^\circ$"}


def _tex_escape(text: str) -> str:
    return "".join(_TEX_SPECIAL.get(ch, ch) for ch in _one_line(text))


def _tex_comment(text: str) -> str:
    """Text inside a ``%`` comment: on one line, so nothing can leave the comment."""
    return " ".join(_one_line(text).split())


def _tex_code(text: str) -> str:
    # \texttt with break points after commas so long points wrap in narrow columns
    return r"\texttt{" + _tex_escape(text).replace(",", r",\allowbreak{}") + "}"


def _latex(expr: sp.Expr) -> str:
    """SymPy's LaTeX with plain-LaTeX commands only (no amsmath's \\operatorname)."""
    text = sp.latex(expr, inv_trig_style="full")
    return re.sub(r"\\operatorname\{(\w+)\}", r"\\mathrm{\1}", text)


def _tex_eq(text: str, tail: str = "") -> str:
    expr = _read(text)
    if expr is None:
        return _tex_code(text + tail)
    return f"${_latex(expr)}{tail}$"


def _tex_value(text: str) -> str | None:
    try:
        expr = parse_expression(text, [], "value", max_length=MAX_EQUATION)
    except NumberError:
        return None
    return _latex(expr)


def _tex_at(text: str) -> str:
    """``q1=pi/2,L=1`` as ``$q_{1} = \\frac{\\pi}{2}$, $L = 1$``."""
    out = []
    for part in text.split(","):
        name, sep, value = part.partition("=")
        name, value = name.strip(), value.strip()
        v = _tex_value(value) if sep and name.isidentifier() else None
        if v is None:
            return _tex_code(text)
        out.append(f"${sp.latex(sp.Symbol(name))} = {v}$")
    return ", ".join(out)


def _tex_side(text: str) -> str | None:
    text = text.strip()
    sign = ""
    if text.startswith("\u00b1"):
        sign, text = r"\pm ", text[1:]
    expr = _read(text) if text else None
    return None if expr is None else sign + _latex(expr)


def _tex_cond(text: str) -> str:
    """A condition in angles (``q1 = q2 = -pi/2``, ``q2 = ±pi/2, q1 = 0``) in math;
    alternatives joined by ``or`` are rendered one by one."""
    if " or " in text:
        return " or ".join(_tex_cond(part) for part in text.split(" or "))
    pieces = []
    for clause in re.split(r",\s*|\s+and\s+|\s+or\s+", text):
        sides = [_tex_side(s) for s in clause.split("=")]
        if len(sides) < 2 or any(s is None for s in sides):
            return _tex_code(text)
        pieces.append("$" + " = ".join(sides) + "$")
    return ", ".join(pieces)


def _tex_inline(parts: Sequence[tuple[str, str]]) -> str:
    out = []
    for kind, value in parts:
        if kind == "text":
            out.append(_tex_escape(value))
        elif kind == "strong":
            out.append(r"\textbf{" + _tex_escape(value) + "}")
        elif kind == "eq":
            out.append(_tex_eq(value))
        elif kind == "eq0":
            out.append(_tex_eq(value, " = 0"))
        elif kind == "nums":
            out.append(_tex_escape(value.replace(" ", "")))
        elif kind == "at":
            out.append(_tex_at(value))
        elif kind == "cond":
            out.append(_tex_cond(value))
        else:
            out.append(_tex_code(value))
    return "".join(out)


def _tex_table(b: _Table) -> list[str]:
    """A table as ``tabular`` environments of at most LATEX_ROWS rows each (a
    ``tabular`` does not break across pages)."""
    keep = [i for i in range(len(b.header)) if i not in b.latex_skip]
    widths = b.latex_widths or {}
    spec = "|" + "|".join(f"p{{{widths[i]}}}" if i in widths else b.align[i]
                          for i in keep) + "|"
    head = " & ".join(r"\textbf{" + _tex_escape(b.header[i]) + "}" for i in keep)
    out: list[str] = []
    chunks = [b.rows[k:k + LATEX_ROWS] for k in range(0, len(b.rows), LATEX_ROWS)] or [[]]
    for chunk in chunks:
        out.append(r"\begin{center}\footnotesize\setlength{\tabcolsep}{2pt}")
        out.append(f"\\begin{{tabular}}{{{spec}}}")
        out.append(r"\hline")
        out.append(head + r" \tabularnewline \hline")
        for row in chunk:
            cells = [(r"\raggedright " if i in widths else "") + _tex_inline(row[i])
                     for i in keep]
            out.append(" & ".join(cells) + r" \tabularnewline \hline")
        out.append(r"\end{tabular}")
        out.append(r"\end{center}")
    return out


def render_latex(locus: Locus, plots: Mapping[tuple[str, str], str] | None = None) -> str:
    """The report as a LaTeX appendix (``\\section*`` and ``tabular`` only: it
    compiles with a plain ``article`` class; ``\\input`` it in a paper). ``plots``
    maps joint pairs to PNG file names, listed in comments (``\\includegraphics``
    needs graphicx).

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> print(render_latex(Locus("demo", [], "", {"Nm": 1})).splitlines()[1])
    \\section*{Singularity locus of demo}
    """
    out = [f"% Singularity-locus report of {_tex_comment(locus.system)} (coopkin locus); "
           f"\\input this "
           f"file in a document."]
    heads = {1: "section*", 2: "subsection*", 3: "subsubsection*"}
    for b in _blocks(locus, None, False):
        if "latex" not in (getattr(b, "only", ()) or ("latex",)):
            continue
        if isinstance(b, _H):
            out.append(f"\\{heads[b.level]}{{{_tex_inline(b.parts or [_t(b.text)])}}}")
        elif isinstance(b, _P):
            out.append(_tex_inline(b.parts))
            out.append("")
        elif isinstance(b, _List):
            out.append(r"\begin{itemize}")
            out += [r"\item " + _tex_inline(i) for i in b.items]
            out.append(r"\end{itemize}")
        elif isinstance(b, _Table):
            out += _tex_table(b)
    if plots:
        out.append("% Plots of the components (need \\usepackage{graphicx}):")
        for pair, name in plots.items():
            out.append(f"% \\includegraphics[width=0.8\\textwidth]{{{name}}}"
                       f"  % {_tex_comment(_caption(pair))}")
    return "\n".join(out).rstrip() + "\n"


# ------------------------------------------------------------------ JSON


def _has_classes(numbers: Mapping) -> bool:
    """Whether ``numbers`` holds every number the grasp classes come from (a report
    read back may hold fewer)."""
    return all(isinstance(numbers.get(n), int) for n in CLASS_NUMBERS.values())


def _with_meaning(data: dict, component: Component) -> dict:
    """A component's JSON with its sentences as ``"meaning"``, after ``"changes"``, and
    how its numbers were decided in words."""
    out = {}
    for key, value in data.items():
        out[key] = value
        if key == "changes":
            out["meaning"] = component_sentences(component)
    out["decided"] = remark_text(component.decided)
    if _has_classes(component.numbers):
        out["classes"] = list(grasp_classes(component.numbers))
    return out


# the lists of remarks a locus holds, written as sentences
_REMARK_LISTS = ("parameter_conditions", "dropped", "unexplored", "notes")


def render_json(locus: Locus, verification: Mapping | None = None) -> str:
    """The locus as JSON (:meth:`Locus.to_json`), for programs; with a
    ``"verification"`` object when one is given.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> sorted(json.loads(render_json(Locus("demo", [], "", {"Nm": 1}))))[:4]
    ['certificate', 'completeness', 'components', 'dropped']
    """
    data = _worded_certificate(locus.to_json(), locus)
    for key in _REMARK_LISTS:
        data[key] = remark_texts(getattr(locus, key))
    data["components"] = [_with_meaning(d, c)
                          for d, c in zip(data["components"], locus.components, strict=True)]
    if _has_classes(locus.generic):
        data["generic_classes"] = list(grasp_classes(locus.generic))
    if locus.locked is not None:
        data["locked"] = json.loads(render_json(locus.locked))
    if verification is not None:
        data["verification"] = dict(verification)
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


def _worded_certificate(data: dict, locus: Locus) -> dict:
    """``data`` with the completeness in words (after ``seconds``) and the certificate's
    JSON (:func:`~coopkin_sym.present.certificate.certificate_json`)."""
    out = {}
    for key, value in data.items():
        if key == "certificate":
            value = None if locus.certificate is None else certificate_json(locus.certificate)
        out[key] = value
        if key == "seconds":
            out["completeness"] = completeness_text(locus)
    return out


def locus_from_json(data: Mapping | str) -> Locus:
    """A :class:`Locus` back from :func:`render_json` (text or parsed), validated like
    a model file: structure, names, and every expression read by the package's parser
    (see :mod:`coopkin_sym.present.report_input`). Nothing in it is ever evaluated.

    Raises
    ------
    ReportError
        One line per problem, each naming the entry.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> locus = Locus("demo", ["t_q1"], "", {"Nm": 1})
    >>> locus_from_json(render_json(locus)) == locus
    True
    """
    try:
        return validate_report(data)
    except ReportInputError as exc:
        raise ReportError(str(exc)) from None


# ------------------------------------------------------------------ files


def check_target(path: str | os.PathLike, note: bool = True) -> str:
    """Check a report path before any work: a known suffix (``.md``, ``.html``,
    ``.tex``, ``.json``) in an existing writable directory. Returns the format. With
    ``note``, the file's state is noted, so that writing it later notices another run
    that wrote it meanwhile (see :func:`coopkin_sym.present.files.write_files`).

    Example
    -------
    >>> check_target("report.html")
    'html'
    >>> check_target("report.txt")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ReportError: report.txt: unknown report format '.txt' ...
    """
    _, suffix = check_output_path(path, FORMATS, ReportError, "report", note=note)
    return FORMATS[suffix]


def parse_pairs(pairs: Sequence[str | Sequence[str]] | None, system: Any = None
                ) -> list[tuple[str, str]] | None:
    """Joint pairs from ``"q1,q2"`` texts (or pairs), checked against the system's
    joints when it is given.

    Example
    -------
    >>> parse_pairs(["q1,q2"])
    [('q1', 'q2')]
    """
    if pairs is None:
        return None
    joints = None
    if system is not None:
        joints = list(getattr(system, "model", system).joint_names)
    out = []
    for p in pairs:
        names = [s.strip() for s in p.split(",")] if isinstance(p, str) else list(p)
        if len(names) != 2 or not all(names):
            raise ReportError(f"pair {brief(p)}: expected two joints, e.g. q1,q2")
        if names[0] == names[1]:
            raise ReportError(f"pair {brief(p)}: the two joints must differ")
        for n in names:
            if joints is not None and n not in joints:
                raise ReportError(f"pair {brief(p)}: unknown joint {brief(n)} (joints: "
                                  f"{', '.join(joints)})")
        out.append((names[0], names[1]))
    return out


def _pictures_intro(locus: Locus) -> list:
    """The heading and the sentence before the pictures of the system."""
    text = ("The system at the witness of each real component, with a motion it gains "
            "there (one of the kind whose count grows; the picture's title says which), "
            "joint rates as ratios to the fastest joint.")
    left = len(drawable_components(locus)) - MAX_SYSTEM_PICTURES
    if left > 0:
        text += (f" {left} more components with a real witness are not drawn (at most "
                 f"{MAX_SYSTEM_PICTURES} pictures, to keep the report small).")
    return [_H(3, "The system at each component", "system-pictures"), _P([_t(text)])]


def _caption(pair: tuple[str, ...]) -> str:
    if pair[0] == SYSTEM_PICTURE:
        if len(pair) > 2:
            return pair[2]
        return f"The system at the witness of {pair[1]} (drawn with lengths as given)"
    return f"Components in the ({pair[0]}, {pair[1]}) plane"


# key of a picture of the system at a witness among the plots
SYSTEM_PICTURE = "system"
#: Pictures of the system a report carries at most (one per real component).
MAX_SYSTEM_PICTURES = 12
#: Resolution of those pictures (they are large figures; this keeps reports small).
SYSTEM_PICTURE_DPI = 72


def _witness_point(comp: Component) -> tuple[dict[str, str], bool] | None:
    """The point to draw a component at (``--at`` values) and whether it is exact and
    rational (else algebraic: drawn without its motions); None without a real
    witness."""
    if not comp.real:
        return None
    if comp.witness:
        return dict(comp.witness), True
    point = (comp.algebraic_witness or {}).get("point")
    if point:
        return dict(point), False
    return None


def _witness_analysis(system: Any, comp: Component) -> Analysis | None:
    """The exact analysis at a component's witness for its picture: the one the search
    made (when its model is the system's), else one at the exact point (nothing is
    parsed), else None (a witness read back as text)."""
    held = getattr(comp.shown, "analysis", None)
    if held is not None and held.model is system.model:
        return held
    if isinstance(comp.witness, Point):
        return Analysis(system.model, comp.witness)
    return None


def drawable_components(locus: Locus) -> list[int]:
    """The components (indices from 0) with a real witness to draw the system at.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Component, Locus
    >>> c = Component(["t_q1"], {"Nm": 3}, {"q1": "0"}, True)
    >>> without = Component(["t_q1"], {}, None, True)
    >>> drawable_components(Locus("demo", ["t_q1"], "", {}, [c, without]))
    [0]
    """
    return [k for k, c in enumerate(locus.components) if _witness_point(c) is not None]


def _counts_words(kind: str, here: Mapping, generic: Mapping) -> str:
    now, before = motion_counts(here)[kind], motion_counts(generic)[kind]
    return f"{kind} motions: {before} generically, {now} here"


def _system_caption(locus: Locus, k: int, comp: Component, at: Mapping[str, str],
                    exact: bool, motion: tuple[str, int] | None) -> str:
    where = ", ".join(f"{n}={v}" for n, v in at.items())
    head = f"Component {k + 1} ({comp.condition or 'see its equations'}): the system at "
    head += f"its witness {where}" if exact else f"its algebraic witness {where}"
    if motion is None:
        changed = ", ".join(f"{n} {a} \u2192 {b}" for n, (a, b) in comp.changes.items())
        return f"{head}; no motion of the object or the joints is gained there ({changed})."
    kind, index = motion
    counts = _counts_words(kind, comp.numbers, locus.generic)
    if not exact:
        return (f"{head}; it gains {kind} motions ({counts}), not drawn: the blocks are "
                "not computed at irrational angles.")
    return (f"{head}, with {kind} motion {index} ({MOTION_KINDS[kind]}), a motion gained "
            f"there ({counts}).")


def _system_pictures(locus: Locus, system: Any, dpi: int,
                     clock: _PictureClock | None = None) -> dict[tuple[str, ...], bytes]:
    """The system drawn at the witness of every real component (the first
    :data:`MAX_SYSTEM_PICTURES`), each with a motion gained there (see
    :func:`~coopkin_sym.present.draw.gained_motion`); a note
    (:class:`~coopkin_sym.errors.OutputSkipped`) for each one that cannot be drawn."""
    if system is None or not hasattr(system, "model"):
        return {}
    chosen = drawable_components(locus)
    if not chosen:
        _skipped("no picture of the system: no component has a real witness to draw it at")
        return {}
    if len(chosen) > MAX_SYSTEM_PICTURES:
        _skipped(f"pictures of the system at {len(chosen) - MAX_SYSTEM_PICTURES} more "
                 f"components left out (at most {MAX_SYSTEM_PICTURES})")
    out: dict[tuple[str, ...], bytes] = {}
    for drawn, k in enumerate(chosen[:MAX_SYSTEM_PICTURES]):
        if clock is not None and not clock.time_for_one_more():
            _skipped(f"pictures of the system at {len(chosen[:MAX_SYSTEM_PICTURES]) - drawn} "
                     f"more components left out: the time bound was reached", SkippedForTime)
            break
        comp = locus.components[k]
        at, exact = _witness_point(comp)
        motion = gained_motion(comp.numbers, locus.generic)
        at_text = ",".join(f"{n}={v}" for n, v in at.items())
        title = f"{locus.system}: component {k + 1}"
        held = _witness_analysis(system, comp) if exact else None
        drawn_at = (held, None) if held is not None else (system, at_text)
        try:
            try:
                fig = draw_system(*drawn_at, title=title,
                                  motion=f"{motion[0]}:{motion[1]}" if motion and exact
                                  else None)
            except DrawError:   # the motion is not there after all: the system alone
                if motion is None or not exact:
                    raise
                fig = draw_system(*drawn_at, title=title)
                motion = None
            buf = io.BytesIO()
            fig.savefig(buf, format="png", dpi=min(dpi, SYSTEM_PICTURE_DPI))
        except (ImportError, ValueError) as exc:  # the picture is optional here
            _skipped(f"no picture of the system at component {k + 1}: "
                     f"{' '.join(str(exc).split())}")
            continue
        caption = _system_caption(locus, k, comp, at, exact, motion)
        out[(SYSTEM_PICTURE, f"component {k + 1}", caption)] = buf.getvalue()
    return out


class _PictureClock:
    """Whether there is time for one more picture before ``until`` (a
    ``time.monotonic()`` value; None: always): the next one is taken to last as long
    as the longest drawn so far, so that the last one ends before the bound."""

    def __init__(self, until: float | None):
        self.until = until
        self.longest = 0.0
        self.started: float | None = None

    def time_for_one_more(self) -> bool:
        now = time.monotonic()
        if self.started is not None:
            self.longest = max(self.longest, now - self.started)
        self.started = now
        return self.until is None or now + self.longest < self.until


def _skipped(text: str, kind: type[OutputSkipped] = OutputSkipped) -> None:
    """Say that a part of the report is left out (shown by ``coopkin`` on stderr)."""
    warnings.warn(text, kind, stacklevel=3)


def _no_pairs(locus: Locus) -> str:
    """Why no pair of joints is plotted by default."""
    if not locus.components:
        return "the locus has no component"
    if not any(c.real for c in locus.components):
        return "no component has real points"
    return "no real component involves a joint"


def _png_name(stem: str, pair: tuple[str, str]) -> str:
    safe = [re.sub(r"[^A-Za-z0-9_.-]", "_", j) for j in pair[:2]]
    return f"{stem}_{safe[0]}_{safe[1]}.png"


def _plots(locus: Locus, system: Any, pairs: list[tuple[str, str]] | None,
           dpi: int, until: float | None = None
           ) -> tuple[dict[tuple[str, str], bytes], str | None]:
    try:
        chosen = pairs if pairs is not None else default_pairs(locus, system)
        if not chosen:
            _skipped(f"no plot of the components: {_no_pairs(locus)}")
        pngs = {}
        clock = _PictureClock(until)
        for k, p in enumerate(chosen):
            if not clock.time_for_one_more():
                _skipped(f"plots of {len(chosen) - k} more pairs of joints left out: the "
                         f"time bound was reached", SkippedForTime)
                break
            pngs[p] = plot_png(locus, system, p, dpi=dpi)
        pngs.update(_system_pictures(locus, system, dpi, clock))
        return pngs, None
    except PlotError as exc:
        if "matplotlib" in str(exc) and pairs is None:  # pragma: no cover
            _skipped(f"no plots: {exc}")
            return {}, str(exc)
        raise ReportError(str(exc)) from None


def write_report(locus: Locus, path: str | os.PathLike, system: Any = None, *,
                 pairs: Sequence[str | Sequence[str]] | None = None,
                 dpi: int = 110, verification: Mapping | None = None,
                 pictures_until: float | None = None) -> list[Path]:
    """Write the report in the format of ``path``'s suffix (``.md``, ``.html``,
    ``.tex``, ``.json``), with a PNG per joint pair next to it
    (``<stem>_<qi>_<qj>.png``; none for JSON). Everything is rendered first and
    written through temporary files renamed at the end: nothing is half-written on
    an error. Returns the files written, the report first. A part left out (no plot
    when no real component involves a joint, no picture of the system when it cannot
    be drawn) is announced by an :class:`~coopkin_sym.errors.OutputSkipped` warning
    (``coopkin locus`` prints it on stderr).

    Parameters
    ----------
    locus
        The locus.
    path
        The report file.
    system
        The system (joint kinds for the plots); optional.
    pairs
        Joint pairs to plot (``"q1,q2"`` or pairs); default: the pairs that occur
        together in a real component's equations.
    dpi
        Resolution of the PNGs.
    verification
        A verification (:meth:`~coopkin_sym.analysis.locus.verify.Verification.to_json`) to
        add to a JSON report.
    pictures_until
        A ``time.monotonic()`` value after which no more plot or picture is drawn (the
        ones left out are said); None: all of them.

    Example
    -------
    >>> import tempfile, pathlib
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "r.json"
    >>> [p.name for p in write_report(Locus("demo", [], "", {"Nm": 1}), out)]
    ['r.json']
    """
    target = Path(path)
    fmt = check_target(target, note=False)
    chosen = parse_pairs(pairs, system)
    files: dict[Path, bytes] = {}
    if fmt == "json":
        files[target] = render_json(locus, verification).encode()
    else:
        pngs, problem = _plots(locus, system, chosen, dpi, pictures_until)
        if problem:
            locus = Locus(**{**locus.__dict__, "notes": [*locus.notes, problem]})
        names = {p: _png_name(target.stem, p) for p in pngs}
        if fmt == "html":
            text = render_html(locus, pngs)
        elif fmt == "markdown":
            text = render_markdown(locus, names)
        else:
            text = render_latex(locus, names)
        files[target] = text.encode()
        for p, data in pngs.items():
            files[target.with_name(names[p])] = data
    _write_all(files)
    return list(files)


def _write_all(files: Mapping[Path, bytes]) -> None:
    """Write every file whole, or none (see :func:`coopkin_sym.present.files.write_files`)."""
    write_files(files, ReportError)
