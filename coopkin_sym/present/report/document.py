"""The document of a locus report, built once for every format (see
:mod:`coopkin_sym.present.report.blocks`): the summary, the generic numbers, the
components, the passive joints, the float rank tests, the plots, the parameter
conditions, the dropped factors, what was not explored, the certificate and the notes.

Example
-------
>>> from coopkin_sym.analysis.locus.types import Locus
>>> doc = build_document(Locus("demo", [], "", {"Nm": 1}))
>>> doc.title, [b.kind for b in doc.blocks][:3]
('Singularity locus of demo', ['heading', 'paragraph', 'paragraph'])
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.analysis.numbers import NUMBER_NAMES
from coopkin_sym.present.classes import classes_text
from coopkin_sym.present.conditions import PolynomialNames, report_names, short_condition
from coopkin_sym.present.formula import Formula
from coopkin_sym.present.formula import latex as _latex
from coopkin_sym.present.remarks import grouped_remark_texts, remark_texts
from coopkin_sym.present.report.blocks import (
    Bullets,
    Document,
    Figure,
    Paragraph,
    Table,
    _h,
    _t,
)
from coopkin_sym.present.report.completeness import _certificate_blocks, _completeness_line
from coopkin_sym.present.report.components import _component_blocks, _components_table
from coopkin_sym.present.report.families import families_blocks
from coopkin_sym.present.report.formulas import MAX_EQUATION, _list_or
from coopkin_sym.present.report.locked import _passive_blocks
from coopkin_sym.present.report.pictures import (
    MAX_SYSTEM_PICTURES,
    SYSTEM_PICTURE,
    drawable_components,
)
from coopkin_sym.present.report.words import (
    KIND_PLURALS,
    KIND_WORDS,
    NUMBER_WORDS,
    _component_name,
    _has_classes,
    _verdict,
)


def build_document(locus: Locus, plots: Mapping[tuple[str, ...], Any] | None = None,
                   in_text: bool = True, max_pictures: int = MAX_SYSTEM_PICTURES
                   ) -> Document:
    """The report of ``locus``. ``plots`` maps joint pairs (or the keys of pictures of
    the system) to what a format needs of each picture; ``in_text``: the pictures are
    placed in a section of their own (Markdown, HTML; none when ``plots`` is None),
    else listed as files next to the report (LaTeX). ``max_pictures`` is the bound on
    the pictures of the system that the text mentions.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> doc = build_document(Locus("demo", [], "", {"Nm": 1}), {("q1", "q2"): "p.png"},
    ...                      in_text=False)
    >>> [f.caption for f in doc.files]
    ['Components in the (q1, q2) plane']
    """
    title = f"Singularity locus of {locus.system}"
    if in_text:
        return Document(title, locus.system,
                        _blocks(locus, plots, plots is not None, max_pictures))
    files = [Figure(_caption(pair), ref) for pair, ref in (plots or {}).items()]
    return Document(title, locus.system, _blocks(locus, None, False, max_pictures), files)


def _generic_table(locus: Locus) -> Table:
    rows = [[[("strong", k)], [_t(NUMBER_WORDS[k])], [_t(str(locus.generic.get(k, "?")))]]
            for k in NUMBER_NAMES]
    return Table(["number", "meaning", "generic value"], rows, "llc", {1: "7.5cm"},
                 css="numbers")


def _float_summary_blocks(locus: Locus, names: PolynomialNames | None = None) -> list:
    s = locus.float_summary()
    total = sum(len(c.float_checks) for c in locus.components)
    out: list = [_h(2, "Float rank tests", "float-tests")]
    if not total:
        out.append(Paragraph([_t("No float rank tests were run.")]))
        return out
    at_w = sum(1 for c in locus.components for f in c.float_checks if f.distance == 0)
    out.append(Paragraph([
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
        rows.append([[_t(_component_name(k))], [("cond", short_condition(c, names))],
                     [_t(str(len(v)))], [_t(str(v.count("agree")))],
                     [_t(str(v.count("missed")))], [_t(str(v.count("false")))]])
    out.append(Table(["#", "where", "tests", "agree", "missed singular",
                      "regular called singular"], rows, "llcccc",
                     {1: "3.4cm", 4: "1.5cm", 5: "1.7cm"}, css="floatsum"))
    return out


def _blocks(locus: Locus, plots: Mapping[tuple[str, ...], Any] | None,
            with_plots: bool, max_pictures: int = MAX_SYSTEM_PICTURES) -> list:
    out: list = [_h(1, f"Singularity locus of {locus.system}")]
    names = report_names(locus.components)
    out += _summary_blocks(locus)
    out.append(_h(2, "Generic numbers", "generic"))
    out.append(_generic_table(locus))
    if _has_classes(locus.generic):
        out.append(Paragraph([_t(classes_text(locus.generic) + ".")]))
    out += families_blocks(locus, names)
    out += _all_component_blocks(locus, names)
    if locus.locked is not None:
        out.extend(_passive_blocks(locus, locus.locked, names))
    out.extend(_float_summary_blocks(locus, names))
    if with_plots:
        out += _plot_blocks(locus, plots, max_pictures)
    out.append(_h(2, "Parameter conditions", "parameters"))
    out.extend(_list_or(remark_texts(locus.parameter_conditions),
                        "None: no degeneracy that involves the parameters alone.", True))
    out.append(_h(2, "Dropped factors (no real points)", "dropped"))
    out.extend(_list_or(remark_texts(locus.dropped), "None.", True))
    out.append(_h(2, "Not explored", "unexplored"))
    named = {p.text: label for label, p in names.named()}
    out.extend(_list_or(grouped_remark_texts(locus.unexplored, names=named),
                        "Nothing: the search finished within its bounds."))
    out.extend(_certificate_blocks(locus))
    if locus.notes:
        out.append(_h(2, "Notes", "notes"))
        out.extend(_list_or(grouped_remark_texts(locus.notes), ""))
    out.extend(_polynomial_blocks(names))
    return out


def _polynomial_blocks(names: PolynomialNames) -> list:
    """The appendix: each long polynomial of the report written once, by its name."""
    if not len(names):
        return []
    items = []
    for label, p in names.named():
        if len(p.text) > MAX_EQUATION:
            items.append([("code", f"{label} = {p.text[:MAX_EQUATION]} ..."),
                          _t(f" ({len(p.text)} characters; all of it in the JSON report)")])
        else:
            items.append([("eq", Formula(f"{label} = {p.text}",
                                         f"P_{{{label[1:]}}} = {_latex(p.to_sympy())}"))])
    return [_h(2, "Polynomials", "polynomials"),
            Paragraph([_t("The polynomials named in the tables and the components above, "
                          "each written once.")]), Bullets(items)]


def _summary_blocks(locus: Locus) -> list:
    """The setting (free variables, what is fixed), the count of components and the
    completeness."""
    out: list = []
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
    out.append(Paragraph(setting))
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
    out.append(Paragraph(summary, css="summary"))
    out.append(_completeness_line(locus))
    return out


def _all_component_blocks(locus: Locus, names: PolynomialNames | None = None) -> list:
    """The components: their table, then each one (long polynomials by their
    ``names``)."""
    out: list = [_h(2, "Components", "components")]
    if locus.components:
        out.append(Paragraph([_t("Numbers that differ from the generic ones are in bold. "
                                 "Witnesses are exact points, in the syntax of "),
                              ("code", "coopkin analyze --at"), _t(".")]))
        out.append(_components_table(locus, names))
        for k, c in enumerate(locus.components):
            out.extend(_component_blocks(locus, k, c, names))
    else:
        out.append(Paragraph([_t("None: the numbers are the generic ones at every "
                                 "configuration explored.")]))
    return out


def _plot_blocks(locus: Locus, plots: Mapping[tuple[str, ...], Any] | None,
                 max_pictures: int) -> list:
    """The plots of the components, then the pictures of the system."""
    out: list = [_h(2, "Plots", "plots")]
    if not plots:
        out.append(Paragraph([_t("No plots: no real component to draw.")]))
        return out
    out.append(Paragraph([_t("Real components drawn from their exact polynomials over "
                             "q in [-pi, pi] (t = tan(q/2) is infinite at q = pi); "
                             "isolated components as points; exact witnesses as stars.")]))
    pictures = [p for p in plots if p[0] == SYSTEM_PICTURE]
    for pair, ref in plots.items():
        if pictures and pair == pictures[0]:
            out.extend(_pictures_intro(locus, max_pictures))
        out.append(Figure(_caption(tuple(pair)), ref))
    return out


def _pictures_intro(locus: Locus, max_pictures: int = MAX_SYSTEM_PICTURES) -> list:
    """The heading and the sentence before the pictures of the system."""
    text = ("The system at the witness of each real component, with a motion it gains "
            "there (one of the kind whose count grows; the picture's title says which), "
            "joint rates as ratios to the fastest joint.")
    left = len(drawable_components(locus)) - max_pictures
    if left > 0:
        text += (f" {left} more components with a real witness are not drawn (at most "
                 f"{max_pictures} pictures, to keep the report small).")
    return [_h(3, "The system at each component", "system-pictures"), Paragraph([_t(text)])]


def _caption(pair: tuple[str, ...]) -> str:
    if pair[0] == SYSTEM_PICTURE:
        if len(pair) > 2:
            return pair[2]
        return f"The system at the witness of {pair[1]} (drawn with lengths as given)"
    return f"Components in the ({pair[0]}, {pair[1]}) plane"
