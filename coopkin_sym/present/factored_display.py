"""The factored coordinated motions in a notebook: LaTeX when MathJax takes it, else
(and always in the HTML view) the maps ``K_arm`` entry by entry, the named factors of
their denominators once, and how to get all of it.

Example
-------
>>> from coopkin_sym import load
>>> f = load("paper-case2-hard").analyze(generic=True).coordinated_factored()
>>> factored_latex(f) is None                      # over what MathJax accepts
True
>>> page = factored_html(f)
>>> "<code>t_q8**2 + 2*t_q8 - 1</code>" in page, len(page) < 20_000
(True, True)
"""

from __future__ import annotations

import sympy as sp

from coopkin_sym.analysis.factored import FactoredMotions
from coopkin_sym.analysis.renderers import clip
from coopkin_sym.present.html_parts import div, escape, table
from coopkin_sym.present.mathjax import latex_or_none, math_html, typesets
from coopkin_sym.present.text import block_table, factored_lines

__all__ = ["ENTRY_CHARACTERS", "factored_html", "factored_latex", "factored_pretty"]

#: The longest entry (characters of its text) shown whole in the HTML view.
ENTRY_CHARACTERS = 300

_ALL = ("All of it: <code>.latex()</code> (LaTeX), <code>.maps()</code> (SymPy matrices, "
        "the factors by name; <code>.maps(expand_factors=True)</code> with them written "
        "out), <code>.at(...)</code> (exact values at a point).")


def _name(f: FactoredMotions) -> str:
    return getattr(f.model, "name", "") or "the system"


def factored_latex(f: FactoredMotions) -> str | None:
    """The factored form as display math (:meth:`FactoredMotions.latex`), or None
    when it is longer than MathJax accepts (see :mod:`coopkin_sym.present.mathjax`).

    Example
    -------
    >>> from coopkin_sym import load
    >>> f = load("paper-case1-hard").analyze(generic=True).coordinated_factored()
    >>> factored_latex(f)[:40]
    '$$\\\\dot q_{\\\\mathrm{a1}} = K_{\\\\mathrm{a1}}'
    """
    return latex_or_none("$$" + r" \\ ".join(f.latex().splitlines()) + "$$")


def _entry(value: sp.Expr) -> str:
    text = sp.sstr(value)
    return f"<code>{escape(clip(text, ENTRY_CHARACTERS))}</code>"


def _map_html(f: FactoredMotions, arm, matrix: sp.Matrix) -> tuple[str, bool]:
    """``K_arm`` as LaTeX when small, else its nonzero entries one per row; whether an
    entry was cut."""
    arm_tex = r"\mathrm{" + arm.name.replace("_", r"\_") + "}"
    title = (f"<p><strong>K_{escape(arm.name)}</strong> (rows: joints "
             f"{escape(', '.join(arm.joints))}; columns: {escape(', '.join(f.twist_names))})")
    tex = rf"K_{{{arm_tex}}} = {sp.latex(matrix)}"
    if typesets(matrix, tex):
        return title + "</p>" + math_html(tex), False
    rows = [[escape(joint), escape(f.twist_names[j]), _entry(matrix[i, j])]
            for i, joint in enumerate(arm.joints) for j in range(matrix.cols)
            if matrix[i, j] != 0]
    cut = any(len(sp.sstr(e)) > ENTRY_CHARACTERS for e in matrix)
    return (title + ": the entries other than 0</p>"
            + table(["joint", "column", "entry"], rows)), cut


def _twists_html(f: FactoredMotions) -> str:
    tex = rf"C_{{12}} = {sp.latex(f.twists)}"
    if f.twists.cols and typesets(f.twists, tex):
        return math_html(tex)
    if not f.twists.cols:
        return "<p>C12 is empty: no coordinated motions.</p>"
    text = "\n".join(block_table(f.twists, list(f.twist_names)))
    return f"<pre>{escape(text)}</pre>"


def factored_html(f: FactoredMotions) -> str:
    """The factored form as HTML: ``C12``, each arm's map ``K_arm`` (as LaTeX when
    small enough, else entry by entry, long entries cut), the named factors of the
    denominators once, and how to get all of it.

    Example
    -------
    >>> from coopkin_sym import load
    >>> f = load("paper-case1-hard").analyze(generic=True).coordinated_factored()
    >>> "$$K_{\\\\mathrm{a1}} = " in factored_html(f)
    True
    """
    parts = [f"<p><strong>Coordinated motions of {escape(_name(f))}, factored</strong>: "
             "the joint velocities of each arm are K_arm u for each column u of C12.</p>",
             _twists_html(f)]
    maps, cut = f.maps(), False
    for arm in f.arms:
        shown, was_cut = _map_html(f, arm, maps[arm.name])
        parts.append(shown)
        cut = cut or was_cut
    if f.factors:
        rows = [[f"<code>{escape(name)}</code>", f"<code>{escape(sp.sstr(poly))}</code>"]
                for name, poly in f.factors]
        parts += ["<p>Factors of the denominators:</p>",
                  table(["name", "factor"], rows)]
    if cut:
        parts.append(f"<p>Entries longer than {ENTRY_CHARACTERS} characters are cut "
                     "here.</p>")
    parts.append(f"<p>{_ALL}</p>")
    return div(parts)


def factored_pretty(f: FactoredMotions) -> str:
    """The text IPython prints: the ``repr`` and the factored form as text.

    Example
    -------
    >>> from coopkin_sym import load
    >>> f = load("paper-case1-hard").analyze(generic=True).coordinated_factored()
    >>> print(factored_pretty(f).splitlines()[-1])
        d3 = t_q2
    """
    return "\n".join([repr(f), *("  " + line for line in factored_lines(f))])
