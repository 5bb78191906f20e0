"""Results in IPython and Jupyter: HTML summaries, LaTeX and multi-line text.

Importing this module registers its renderers with
:mod:`coopkin_sym.analysis.renderers`, so that an :class:`Analysis`, a
:class:`Locus`, a :class:`SweepResult`... show in a notebook as a summary: the
numbers with their meanings, the grasp classes, the blocks when they are small, the
components of a locus. :mod:`coopkin_sym` imports it. A renderer never starts a long
computation: a block is shown only when it is known to be small before it is built
(:meth:`Analysis.block_terms`), and a block over the term budget
(:class:`~coopkin_sym.errors.BlockTooLarge`) is said to be too large. Every word comes
from the modules that already say it (:mod:`~coopkin_sym.present.classes`,
:mod:`~coopkin_sym.present.sentences`, :mod:`~coopkin_sym.present.report`,
:mod:`~coopkin_sym.present.text`); every number shown is exact.

Example
-------
>>> from coopkin_sym import load
>>> a = load("paper-case1-hard").analyze("q1=pi/2,q2=pi/2")
>>> print(pretty_text(a))  # doctest: +ELLIPSIS
<Analysis paper case 1, hard/hard at q1=pi/2,q2=pi/2: Nm=3 Nc=3 Ni=1 Nr=0 Ng=1 Nd=4 Nh=1>
  Nm = 3  Nc = 3  Ni = 1  Nr = 0  Ng = 1  Nd = 4  Nh = 1
  Grasp classes: indeterminate (Ni = 1), graspable (Ng = 1), defective (Nd = 4), ...
  Blocks: C11 (6 x 1), C12 (6 x 2), C22 (2 x 2), C23 (2 x 0)
>>> "Nm" in a._repr_html_(), a._repr_latex_().startswith("$$")
(True, True)
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import sympy as sp

from coopkin_sym.analysis.batch import BatchResult
from coopkin_sym.analysis.factored import FactoredMotions
from coopkin_sym.analysis.irrational import IrrationalAnalysis
from coopkin_sym.analysis.locus.families import Family
from coopkin_sym.analysis.locus.types import Certificate, Component, Locus
from coopkin_sym.analysis.locus.verify_results import Verification
from coopkin_sym.analysis.manipulability import Manipulability
from coopkin_sym.analysis.mobility import Analysis
from coopkin_sym.analysis.numbers import NUMBER_NAMES, Numbers
from coopkin_sym.analysis.passive import PassiveAnalysis
from coopkin_sym.analysis.renderers import clip, register
from coopkin_sym.analysis.sweep.result import SweepResult
from coopkin_sym.errors import BlockTooLarge
from coopkin_sym.model.configuration import assignments_text
from coopkin_sym.model.model import Model
from coopkin_sym.present.certificate import completeness_text
from coopkin_sym.present.classes import class_changes_text, classes_text
from coopkin_sym.present.conditions import short_condition
from coopkin_sym.present.factored_display import factored_html, factored_latex, factored_pretty
from coopkin_sym.present.family_words import changes_text, family_name, members_text
from coopkin_sym.present.html_parts import bullet_list as _list
from coopkin_sym.present.html_parts import div as _div
from coopkin_sym.present.html_parts import escape as _e
from coopkin_sym.present.html_parts import numbers_strip as _numbers_strip
from coopkin_sym.present.html_parts import numbers_table as _numbers_table
from coopkin_sym.present.html_parts import table as _table
from coopkin_sym.present.mathjax import latex_or_none, math_html, typesets
from coopkin_sym.present.passive import passive_numbers_text
from coopkin_sym.present.remarks import grouped_remark_texts
from coopkin_sym.present.report import KIND_WORDS, NUMBER_WORDS, witness_text
from coopkin_sym.present.report import _changes as changes_of
from coopkin_sym.present.result_display import (
    analysis_passive,
    batch_html,
    batch_pretty,
    certificate_html,
    certificate_pretty,
    passive_html,
    passive_pretty,
    passive_section,
    verification_html,
    verification_pretty,
)
from coopkin_sym.present.sentences import (
    change_words,
    component_sentences,
    count_sentences,
    irrational_sentences,
    sentences,
)
from coopkin_sym.present.text import block_table, certificate_text

__all__ = ["analysis_html", "analysis_latex", "component_html", "install",
           "irrational_html", "irrational_latex", "locus_html", "manipulability_latex",
           "numbers_html", "numbers_latex", "pretty_text", "sweep_html", "system_html",
           "system_text"]

# a block is shown when its entries have at most this many terms in all (estimated
# before it is built), and each at most _ENTRY_TERMS
_BLOCK_TERMS = 400
_ENTRY_TERMS = 40
# rows of a table of components (or of numbers of a sweep) shown at most
_MAX_ROWS = 200
# rows of components shown open in the HTML form of a locus (the others folded)
_OPEN_ROWS = 12
# not-explored sentences shown open in the HTML form of a locus (the others folded)
_OPEN_REMARKS = 3
# lines of components in the text form of a locus
_MAX_LINES = 12
# the longest expression (in characters of its text) written in LaTeX
_MAX_LATEX = 2000

_BLOCK_NAMES = ("C11", "C12", "C22", "C23")


# ------------------------------------------------------------------ small pieces


def _numbers_spaced(numbers: Numbers | Mapping[str, int]) -> str:
    """``Nm = 2  Nc = 2 ...``, as ``coopkin analyze`` prints them."""
    get = numbers.get if isinstance(numbers, Mapping) else numbers.as_dict().get
    return "  ".join(f"{k} = {get(k, '?')}" for k in NUMBER_NAMES)


def _has_all(numbers: Numbers | Mapping[str, int]) -> bool:
    return not isinstance(numbers, Mapping) or all(k in numbers for k in NUMBER_NAMES)


def _classes(numbers: Numbers | Mapping[str, int]) -> str:
    return classes_text(numbers) if _has_all(numbers) else ""


def _shapes(a: Analysis) -> dict[str, tuple[int, int]]:
    n = a.numbers
    return {"C11": (a.dim, n.Ni), "C12": (a.dim, n.Nc - n.Ni),
            "C22": (a.r, n.Nc - n.Ni), "C23": (a.r, n.Nr)}


def _small_blocks(a: Analysis) -> dict[str, sp.Matrix | str]:
    """Each block, when it is known to be small before it is built; else why not."""
    terms = a.block_terms()
    out: dict[str, sp.Matrix | str] = {}
    for name, (rows, cols) in _shapes(a).items():
        size = rows * cols * max(terms[name], 1)
        if cols and (terms[name] > _ENTRY_TERMS or size > _BLOCK_TERMS):
            out[name] = (f"not shown here: entries of up to about {terms[name]:,} terms "
                         f"(analysis.{name} gives it)")
            continue
        try:
            out[name] = getattr(a, name)
        except BlockTooLarge as exc:
            out[name] = f"too large: {exc}"
    return out


def _tex_text(text: str) -> str:
    """Text inside math: runs of plain characters in ``\\text{...}``, the characters
    TeX reserves as math-mode commands (valid in LaTeX, MathJax and KaTeX)."""
    specials = {"\\": r"\backslash ", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&",
                "#": r"\#", "^": r"\hat{}", "_": r"\_", "%": r"\%", "~": r"\sim "}
    one = " ".join(re.sub(r"[\x00-\x1f\x7f-\x9f\u2028\u2029]", " ", str(text)).split())
    out, run = [], []
    for ch in one:
        if ch in specials:
            if run:
                out.append(r"\text{" + "".join(run) + "}")
                run = []
            out.append(specials[ch])
        else:
            run.append(ch)
    if run:
        out.append(r"\text{" + "".join(run) + "}")
    return "".join(out)


def _tex_number(name: str) -> str:
    return f"N_{{{name[1:]}}}"


def _tex_expr(expr: Any) -> str:
    """An exact expression or matrix in LaTeX, or its size when too long to read."""
    if isinstance(expr, sp.MatrixBase) and 0 in expr.shape:
        return r"\emptyset"
    text = sp.latex(expr)
    if len(text) > _MAX_LATEX:
        return _tex_text(f"(an expression of {len(sp.sstr(expr)):,} characters)")
    return text


def _math(lines: Sequence[str]) -> str:
    """Display math: one row per line, left aligned."""
    return "$$\\begin{array}{l}\n" + " \\\\\n".join(lines) + "\n\\end{array}$$"


def _numbers_array(numbers: Numbers | Mapping[str, int]) -> str:
    """The seven numbers with their meanings as a LaTeX array."""
    get = numbers.get if isinstance(numbers, Mapping) else numbers.as_dict().get
    rows = [f"{_tex_number(k)} = {get(k, '?')} & {_tex_text(NUMBER_WORDS[k])}"
            for k in NUMBER_NAMES]
    return "\\begin{array}{ll}\n" + " \\\\\n".join(rows) + "\n\\end{array}"


def _block_html(name: str, block: sp.Matrix | str, shape: tuple[int, int],
                labels: Sequence[str]) -> str:
    title = f"<p><strong>{name}</strong> ({shape[0]} x {shape[1]})"
    if isinstance(block, str):
        return f"{title}: {_e(block)}</p>"
    if block.cols == 0:
        return f"{title}: empty</p>"
    text = f"<pre>{_e(chr(10).join(block_table(block, list(labels))))}</pre>"
    tex = f"C_{{{name[1:]}}} = {sp.latex(block)}"
    if not typesets(block, tex):
        return f"{title}</p>{text}"
    # typeset by the notebook's MathJax; the text too, for a viewer without it
    return (f"{title}</p>{math_html(tex)}<details><summary>as text (rows: "
            f"{_e(', '.join(labels))})</summary>{text}</details>")


# ------------------------------------------------------------------ numbers


def numbers_latex(numbers: Numbers) -> str:
    """The seven numbers with their meanings and the grasp classes, as display math.

    Example
    -------
    >>> print(numbers_latex(Numbers(2, 2, 1, 0, 1, 4, 0)).splitlines()[4])
    N_{i} = 1 & \\text{indeterminacy: object motions left free with every joint locked} \\\\
    """
    return _math([_numbers_array(numbers), _tex_text(classes_text(numbers))])


def numbers_html(numbers: Numbers) -> str:
    """The seven numbers with their meanings and the grasp classes, as an HTML table.

    Example
    -------
    >>> "<td style=\\"text-align:center\\">4</td>" in numbers_html(Numbers(2, 2, 1, 0, 1, 4, 0))
    True
    """
    return _div([_numbers_table(numbers), f"<p>{_e(classes_text(numbers))}</p>"])


# ------------------------------------------------------------------ analyses


def _analysis_head(a: Analysis) -> str:
    return f"{a.model.name} {a.where}"


def analysis_latex(a: Analysis) -> str:
    """An analysis as display math: where, the numbers with their meanings, the grasp
    classes and the small blocks (the others said too large to show).

    Example
    -------
    >>> from coopkin_sym import load
    >>> tex = analysis_latex(load("paper-case1-hard").analyze("q1=pi/2,q2=pi/2,L=1"))
    >>> print(tex.splitlines()[-2].split(r" \\quad ")[0])
    C_{11} = \\left[\\begin{matrix}0\\\\0\\\\0\\\\1\\\\0\\\\0\\end{matrix}\\right]
    """
    lines = [_tex_text("Analysis of " + _analysis_head(a)), _numbers_array(a.numbers),
             _tex_text(classes_text(a.numbers))]
    passive = analysis_passive(a)
    if passive is not None:
        lines.append(_tex_text(passive if isinstance(passive, str) else
                               "Passive-joint numbers: " + passive_numbers_text(
                                   passive.numbers)))
    shown, missing = [], []
    for name, block in _small_blocks(a).items():
        label = f"C_{{{name[1:]}}}"
        if isinstance(block, str):
            rows, cols = _shapes(a)[name]
            missing.append(f"{label}\\ ({rows} \\times {cols}): " + _tex_text(block))
        else:
            shown.append(f"{label} = {_tex_expr(block)}")
    if shown:
        lines.append(r" \quad ".join(shown))
    lines += missing
    return _math(lines)


def analysis_html(a: Analysis) -> str:
    """An analysis as an HTML summary: where, the numbers with their meanings, the
    grasp classes, one sentence per number and the small blocks.

    Example
    -------
    >>> from coopkin_sym import load
    >>> page = analysis_html(load("planar-two-fingers").analyze())
    >>> "Grasp classes: graspable (Ng = 1)" in page, "<pre>" in page
    (True, True)
    """
    blocks = _small_blocks(a)
    small = not any(isinstance(b, str) for b in blocks.values())
    said = sentences(a) if small else count_sentences(a.numbers, a.r, a.dim)
    labels = {"C11": a.model.twist_names, "C12": a.model.twist_names,
              "C22": a.model.joint_names, "C23": a.model.joint_names}
    parts = [f"<p><strong>Analysis of {_e(a.model.name)}</strong> {_e(a.where)}</p>"]
    if a.variables:
        tangents = " (t_q = tan(q/2))" if any(str(v).startswith("t_") for v in a.variables) else ""
        parts.append(f"<p>Symbols: {_e(', '.join(map(str, a.variables)) + tangents)}</p>")
    parts.append(_numbers_table(a.numbers))
    doubt = certificate_text(a.certificate)
    if doubt:
        parts.append(f"<p><em>{_e(doubt)}</em></p>")
    parts += [f"<p>{_e(classes_text(a.numbers))}</p>", _list(said)]
    passive = analysis_passive(a)
    if passive is not None:    # what coopkin analyze prints about passive joints
        parts += ([f"<p>{_e(passive)}</p>"] if isinstance(passive, str)
                  else passive_section(passive))
    shapes = _shapes(a)
    parts += [_block_html(name, blocks[name], shapes[name], labels[name])
              for name in _BLOCK_NAMES]
    return _div(parts)


def _analysis_pretty(a: Analysis) -> str:
    shapes = _shapes(a)
    blocks = ", ".join(f"{n} ({r} x {c})" for n, (r, c) in shapes.items())
    lines = [repr(a), "  " + _numbers_spaced(a.numbers), "  " + classes_text(a.numbers)]
    passive = analysis_passive(a)
    if passive is not None:
        lines.append("  " + (passive if isinstance(passive, str) else
                             "Passive: " + passive_numbers_text(passive.numbers)))
    return "\n".join([*lines, f"  Blocks: {blocks}"])


def _irrational_head(result: IrrationalAnalysis) -> tuple[str, str]:
    at = assignments_text(result.at)
    tangents = ", ".join(f"tan({k}/2) = {v}" for k, v in result.tangents.items())
    field = (f"exact over Q(alpha), alpha = {result.alpha}, a root of "
             f"{result.minimal_polynomial}")
    return f"{result.system} at {at}", f"{tangents}; {field}"


def irrational_latex(result: IrrationalAnalysis) -> str:
    """The numbers at a configuration with irrational coordinates as display math:
    where, the number field, the numbers with their meanings and the grasp classes.

    Example
    -------
    >>> from coopkin_sym import load
    >>> tex = irrational_latex(load("paper-case1-hard").analyze("q1=-pi/6,q2=pi/6"))
    >>> "N_{i} = 3" in tex
    True
    """
    head, field = _irrational_head(result)
    return _math([_tex_text("Analysis of " + head), _tex_text(field),
                  _numbers_array(result.numbers), _tex_text(classes_text(result.numbers))])


def irrational_html(result: IrrationalAnalysis) -> str:
    """The numbers at a configuration with irrational coordinates as an HTML summary.

    Example
    -------
    >>> from coopkin_sym import load
    >>> page = irrational_html(load("paper-case1-hard").analyze("q1=-pi/6,q2=pi/6"))
    >>> "alpha = -2 + sqrt(3)" in page
    True
    """
    head, field = _irrational_head(result)
    return _div([f"<p><strong>Analysis of {_e(head)}</strong></p>", f"<p>{_e(field)}</p>",
                 _numbers_table(result.numbers),
                 f"<p>{_e(classes_text(result.numbers))}</p>",
                 _list(irrational_sentences(result)),
                 "<p>Blocks: not computed at a configuration with irrational coordinates."
                 "</p>"])


def _irrational_pretty(result: IrrationalAnalysis) -> str:
    _, field = _irrational_head(result)
    return "\n".join([repr(result), "  " + clip(field, 200),
                      "  " + _numbers_spaced(result.numbers),
                      "  " + classes_text(result.numbers)])


# ------------------------------------------------------------------ loci


def _changes_text(c: Component, generic: Mapping[str, int], arrow: str = "\u2192") -> str:
    changes = changes_of(c, generic)
    text = ", ".join(f"{k} {a} {arrow} {b}" for k, (a, b) in changes.items()) or "as generic"
    if _has_all(c.numbers) and _has_all(generic):
        classes = class_changes_text(c.numbers, generic)
        if classes != "as generic":
            text += f"; {classes}"
    return text


def _witness(c: Component) -> str:
    if c.witness:
        return witness_text(c.witness)
    if c.algebraic_witness:
        return witness_text(c.algebraic_witness.get("point")) + " (algebraic)"
    return "none"


def _component_row(k: int, c: Component, generic: Mapping[str, int]) -> list[str]:
    name = f"#{k + 1}" + (f" (in #{c.parent + 1})" if c.parent is not None else "")
    where = _e(clip(short_condition(c), 300))
    if not c.real:
        where += " (real points: undecided)"
    numbers = []
    for key in NUMBER_NAMES:
        v = c.numbers.get(key, "?")
        changed = key in generic and v != generic[key]
        numbers.append(f"<strong>{_e(v)}</strong>" if changed else _e(v))
    return [name, where, _e(KIND_WORDS.get(c.kind, c.kind)), *numbers,
            _e(_changes_text(c, generic)), f"<code>{_e(clip(_witness(c), 300))}</code>"]


def locus_html(locus: Locus) -> str:
    """A locus as an HTML summary: the generic numbers with their meanings, whether the
    locus is certified complete, and a table of its components (where, kind, numbers,
    what changes, a witness).

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Component, Locus
    >>> generic = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
    >>> locus = Locus("demo", ["t_q1"], "", generic, [Component(
    ...     ["t_q1 - 1"], dict(generic, Nm=3), {"q1": "pi/2"}, True, condition="q1 = pi/2")])
    >>> "<td style=\\"text-align:left\\">Nm 2 \u2192 3</td>" in locus_html(locus)
    True
    """
    n = len(locus.components)
    parts = [f"<p><strong>Singularity locus of {_e(locus.system)}</strong>"
             + (f" at <code>{_e(locus.fixed)}</code>" if locus.fixed else "") + "</p>",
             f"<p>Free variables: {_e(', '.join(locus.variables) or 'none')}. "
             f"{n} component{'' if n == 1 else 's'} where the numbers differ from the "
             f"generic ones. {_completeness(locus)}</p>",
             "<p>Generic numbers (their meanings on the names):</p>",
             _numbers_strip(locus.generic),
             f"<p>{_e(_classes(locus.generic))}</p>" if _classes(locus.generic) else ""]
    if locus.components:
        families = locus.families()
        if len(families) < n:
            parts.append(f"<p>By what changes: {len(families)} "
                         f"famil{'y' if len(families) == 1 else 'ies'}.</p>")
            parts.append(_families_table(locus, families))
        header = ["#", "where", "kind", *NUMBER_NAMES, "what changes", "witness (at)"]
        rows = [_component_row(k, c, locus.generic)
                for k, c in enumerate(locus.components[:_MAX_ROWS])]
        # with many components, the families say it first and the components are folded
        opened = 0 if n > _OPEN_ROWS and len(families) < n else _OPEN_ROWS
        if opened:
            parts.append(_table(header, rows[:opened], centered=range(3, 10)))
        if len(rows) > opened:
            parts.append(_folded(f"components #{opened + 1} to #{len(rows)}",
                                 _table(header, rows[opened:], centered=range(3, 10))))
        if n > _MAX_ROWS:
            parts.append(f"<p>... and {n - _MAX_ROWS} more components.</p>")
    if locus.unexplored:
        said = [clip(t, 400) for t in grouped_remark_texts(locus.unexplored)]
        items = len(locus.unexplored)
        counted = ("" if items == 1 else
                   f" ({items} items, said in {len(said)} "
                   f"sentence{'' if len(said) == 1 else 's'}; all of them in a report)")
        parts += [f"<p>Not explored{counted}:</p>", _list(said[:_OPEN_REMARKS])]
        if len(said) > _OPEN_REMARKS:
            parts.append(_folded(f"{len(said) - _OPEN_REMARKS} more",
                                 _list(said[_OPEN_REMARKS:])))
    return _div(parts)


def _members(family: Family) -> str:
    n = len(family.members)
    return (f"{n} components, e.g. #{family.example + 1}" if n > 1 else
            f"#{family.example + 1}")


def _families_table(locus: Locus, families: Sequence[Family]) -> str:
    """The families of ``locus`` (HTML): what changes, in words, the components, and
    one of them with its witness."""
    rows = []
    for i, family in enumerate(families):
        c = locus.components[family.example]
        where = f"#{family.example + 1}: " + _e(clip(short_condition(c), 200))
        if not family.real:
            where += " (real points: undecided)"
        witness = _e(clip(_witness(c), 200)).replace(",", ",<wbr/>")
        rows.append([_e(family_name(i)), _e(changes_text(family)),
                     _e(change_words(family.changes)), _e(members_text(family)),
                     f"{where}<br/>at <code>{witness}</code>"])
    return _table(["family", "what changes", "in words", "components",
                   "for example (witness)"], rows)


def _folded(summary: str, body: str) -> str:
    """``body`` folded under a line that says what it holds (HTML ``details``)."""
    return f"<details><summary>{_e(summary)}</summary>{body}</details>"


def _completeness(locus: Locus) -> str:
    """Whether the locus is proved complete, as its report says it (HTML)."""
    said = completeness_text(locus)
    if locus.certificate is None:
        return f"<strong>{_e(said[:1].upper() + said[1:])}</strong>."
    return f"Completeness: <strong>{_e(said)}</strong>."


def _locus_pretty(locus: Locus) -> str:
    said = completeness_text(locus)
    lines = [repr(locus), f"  {said if locus.certificate is None else 'completeness: ' + said}",
             "  generic: " + _numbers_spaced(locus.generic)]
    if _classes(locus.generic):
        lines.append("  " + _classes(locus.generic))
    families = locus.families()
    if len(families) < len(locus.components):
        lines += ["  " + clip(f"family {family_name(i)} ({_members(f)}): "
                              f"{changes_text(f, '->')}", 160)
                  for i, f in enumerate(families)]
    for k, c in enumerate(locus.components[:_MAX_LINES]):
        kind = KIND_WORDS.get(c.kind, c.kind)
        lines.append("  " + clip(f"#{k + 1} {short_condition(c)} ({kind}): "
                                 f"{_changes_text(c, locus.generic, '->')}", 160))
    if len(locus.components) > _MAX_LINES:
        lines.append(f"  ... and {len(locus.components) - _MAX_LINES} more components")
    lines += ["  not explored: " + clip(t, 160)
              for t in grouped_remark_texts(locus.unexplored)]
    return "\n".join(lines)


def component_html(c: Component) -> str:
    """One locus component as an HTML summary: where, its equations, kind, numbers,
    what changes (in words when its witness shows it) and a witness.

    Example
    -------
    >>> c = Component(["t_q1 - 1"], {"Nm": 3}, {"q1": "pi/2"}, True, condition="q1 = pi/2",
    ...               changes={"Nm": (2, 3)})
    >>> "<code>q1=pi/2</code>" in component_html(c)
    True
    """
    generic = {k: a for k, (a, _) in c.changes.items()}
    equations = ", ".join(e.text for e in c.equations)
    items = [f"<li>Equations: <code>{_e(clip(equations, 2000))}</code></li>",
             f"<li>Kind: {_e(KIND_WORDS.get(c.kind, c.kind))} (depth {c.depth})</li>",
             f"<li>Changes: {_e(_changes_text(c, generic))}</li>",
             f"<li>Witness: <code>{_e(_witness(c))}</code></li>"]
    said = component_sentences(c) if _witness_is_small(c) else []
    return _div([f"<p><strong>Component</strong> {_e(clip(short_condition(c), 300))}</p>",
                 "<ul>" + "".join(items) + "</ul>", _numbers_table(c.numbers), _list(said)])


def _witness_is_small(c: Component) -> bool:
    shown = c.shown
    analysis = getattr(shown, "analysis", None)
    return analysis is None or not any(isinstance(b, str)
                                       for b in _small_blocks(analysis).values())


# ------------------------------------------------------------------ sweeps


def _sweep_groups(result: SweepResult) -> list[tuple[tuple[int, ...], int, int]]:
    """Each tuple of numbers met, how many points have it and the first such point."""
    rows = [tuple(int(x) for x in r) for r in result.numbers.tolist()]
    counts = Counter(rows)
    first: dict[tuple[int, ...], int] = {}
    for i, r in enumerate(rows):
        first.setdefault(r, i)
    return [(r, n, first[r]) for r, n in counts.most_common()]


def sweep_html(result: SweepResult) -> str:
    """A sweep as an HTML summary: how many points, how they were decided, the generic
    numbers and each set of numbers met with how many points have it.

    Example
    -------
    >>> from coopkin_sym import load
    >>> res = load("paper-case1-hard").sweep(["q1=pi/2,q2=pi/2", "q1=0"])
    >>> "<code>q1=pi/2,q2=pi/2</code>" in sweep_html(res)
    True
    """
    c = result.summary()
    generic = tuple(result.generic.as_dict()[k] for k in NUMBER_NAMES)
    rows = []
    for numbers, count, first in _sweep_groups(result)[:_MAX_ROWS]:
        cells = [f"<strong>{v}</strong>" if v != g else str(v)
                 for v, g in zip(numbers, generic, strict=True)]
        rows.append([*cells, str(count), f"<code>{_e(result.at_text(first))}</code>"])
    parts = [f"<p><strong>Sweep of {_e(result.system)}</strong> over "
             f"{_e(', '.join(result.joints))}"
             + (f" at <code>{_e(result.at)}</code>" if result.at else "") + "</p>",
             f"<p>{c['points']} points: {c['certified_mod_p']} certified by their ranks "
             f"modulo p = {result.prime}, {c['rechecked_exact']} rechecked exactly over Q; "
             f"{result.not_generic()} with numbers other than the generic ones.</p>",
             "<p>Generic numbers (swept joints symbolic):</p>",
             _numbers_table(result.generic),
             _table([*NUMBER_NAMES, "points", "first point (at)"], rows,
                    centered=range(8))]
    return _div(parts)


def _sweep_pretty(result: SweepResult) -> str:
    lines = [repr(result)]
    for numbers, count, first in _sweep_groups(result)[:_MAX_LINES]:
        nums = "  ".join(f"{k} = {v}" for k, v in zip(NUMBER_NAMES, numbers, strict=True))
        lines.append(f"  {nums}: {count} point{'' if count == 1 else 's'}, first at "
                     + clip(result.at_text(first), 100))
    return "\n".join(lines)


# ------------------------------------------------------------------ manipulability


def manipulability_latex(m: Manipulability) -> str:
    """The manipulability ellipsoid as display math: its matrix ``E`` and ``det E``.

    Example
    -------
    >>> from coopkin_sym import load
    >>> m = load("paper-case1-hard").analyze("L=1").manipulability(["v_x", "v_y"])
    >>> print(manipulability_latex(m).splitlines()[2])
    E = \\left[\\begin{matrix}\\frac{1}{2} & 0\\\\0 & 0\\end{matrix}\\right] \\quad \\det E = 0
    """
    head = (f"manipulability of {', '.join(m.controlled)} (length {sp.sstr(m.length)}): "
            f"rank {m.rank} of {len(m.controlled)}")
    return _math([_tex_text(head), f"E = {_tex_expr(m.shape)} \\quad \\det E = "
                                   f"{_tex_expr(m.index)}"])


# ------------------------------------------------------------------ systems


def system_text(model: Model) -> str:
    """A system in a few lines: its arms and joints, contacts and parameters (what
    IPython prints for a :class:`~coopkin_sym.system.System`).

    Example
    -------
    >>> from coopkin_sym.model.model import load_model
    >>> print(system_text(load_model("paper-case1-hard")))
    paper case 1, hard/hard
      arms: a1 (q1 revolute), a2 (q2 revolute)
      contacts: c1 (hard, a1 link 1), c2 (hard, a2 link 1)
      parameters: L
    """
    lines = [model.name + (" (planar)" if model.planar else ""),
             "  arms: " + ", ".join(f"{arm.name} ({_joints(arm)})" for arm in model.arms),
             "  contacts: " + ", ".join(f"{c.name} ({c.model}, {_place(model, c)})"
                                        for c in model.contacts),
             "  parameters: " + (", ".join(p.name for p in model.parameters) or "none")]
    return "\n".join(lines)


def _joints(arm: Any) -> str:
    return ", ".join(f"{j.name} {j.type}" for j in arm.joints) or "no joints"


def _place(model: Model, contact: Any) -> str:
    if contact.arm is None:
        return "ground"
    arm = model.arms[contact.arm].name
    return f"{arm} base" if contact.link == 0 else f"{arm} link {contact.link}"


def system_html(model: Model) -> str:
    """A system as an HTML summary: its arms and joints, contacts and parameters.

    Example
    -------
    >>> from coopkin_sym.model.model import load_model
    >>> "<td style=\\"text-align:left\\">q1 revolute</td>" in system_html(
    ...     load_model("paper-case1-hard"))
    True
    """
    arms = [[_e(arm.name), _e(_joints(arm))] for arm in model.arms]
    contacts = [[_e(c.name), _e(c.model), _e(_place(model, c))] for c in model.contacts]
    return _div([f"<p><strong>{_e(model.name)}</strong>"
                 + (" (planar)" if model.planar else "") + "</p>",
                 _table(["arm", "joints"], arms),
                 _table(["contact", "model", "on"], contacts),
                 "<p>Parameters: "
                 + _e(", ".join(p.name for p in model.parameters) or "none") + "</p>"])


# ------------------------------------------------------------------ registration


def pretty_text(obj: Any) -> str:
    """The text IPython prints for a result: its ``repr`` and a few more lines.

    Example
    -------
    >>> print(pretty_text(Numbers(2, 2, 1, 0, 1, 4, 0)))
    Numbers(Nm=2, Nc=2, Ni=1, Nr=0, Ng=1, Nd=4, Nh=0)
    """
    for cls, render in _PRETTY.items():
        if isinstance(obj, cls):
            return render(obj)
    return repr(obj)


_PRETTY: dict[type, Callable[[Any], str]] = {
    Analysis: _analysis_pretty, IrrationalAnalysis: _irrational_pretty,
    Locus: _locus_pretty, SweepResult: _sweep_pretty, FactoredMotions: factored_pretty,
    PassiveAnalysis: passive_pretty, BatchResult: batch_pretty,
    Certificate: certificate_pretty, Verification: verification_pretty}

_RENDERERS: list[tuple[type, str, Callable[[Any], str]]] = [
    (Numbers, "latex", numbers_latex), (Numbers, "html", numbers_html),
    (Analysis, "latex", analysis_latex), (Analysis, "html", analysis_html),
    (IrrationalAnalysis, "latex", irrational_latex),
    (IrrationalAnalysis, "html", irrational_html),
    (Locus, "html", locus_html), (Component, "html", component_html),
    (SweepResult, "html", sweep_html), (Manipulability, "latex", manipulability_latex),
    (FactoredMotions, "latex", factored_latex), (FactoredMotions, "html", factored_html),
    (PassiveAnalysis, "html", passive_html), (BatchResult, "html", batch_html),
    (Certificate, "html", certificate_html), (Verification, "html", verification_html),
    *((cls, "pretty", render) for cls, render in _PRETTY.items())]


def install() -> None:
    """Register this module's renderers (done when it is imported); LaTeX is given
    only when MathJax accepts it (see :mod:`coopkin_sym.present.mathjax`), else the
    HTML view shows.

    Example
    -------
    >>> from coopkin_sym.analysis.renderers import render
    >>> install()
    >>> render(Numbers(2, 2, 1, 0, 1, 4, 0), "latex").startswith("$$")
    True
    """
    for cls, kind, renderer in _RENDERERS:
        register(cls, kind, _within_mathjax(renderer) if kind == "latex" else renderer)


def _within_mathjax(renderer: Callable[[Any], str | None]) -> Callable[[Any], str | None]:
    return lambda obj: latex_or_none(renderer(obj))


install()
