"""How much LaTeX a notebook typesets: the size MathJax accepts, and math inside HTML.

Jupyter typesets ``text/latex`` outputs, and ``$$...$$`` inside ``text/html`` ones,
with MathJax. MathJax's TeX input keeps the expression in an internal buffer of
``5 * 1024`` characters (its ``maxBuffer`` option, the same default in MathJax 2 and
3) and refuses a longer one with "MathJax internal buffer size exceeded": the
factored coordinated motions of the paper's case 2 (12,218 characters) are refused. A
display keeps its LaTeX under :data:`MATHJAX_LATEX_LIMIT`, below that buffer with room
for the macros MathJax expands into it; a longer display gives no LaTeX (None), and
its HTML view carries the content instead.

Example
-------
>>> latex_or_none("$$x^2$$")
'$$x^2$$'
>>> latex_or_none("$$" + "x + " * 2000 + "x$$") is None
True
>>> math_html(r"C_{11} = \\left[\\begin{matrix}1 & 0\\end{matrix}\\right]")
'$$C_{11} = \\\\left[\\\\begin{matrix}1 &amp; 0\\\\end{matrix}\\\\right]$$'
"""

from __future__ import annotations

import html

import sympy as sp

__all__ = ["MATHJAX_LATEX_LIMIT", "TYPESET_ENTRY", "fits_mathjax", "latex_or_none",
           "math_html", "typesets"]

#: The longest LaTeX (in characters, ``$$`` included) a display gives: MathJax's TeX
#: buffer holds 5 * 1024 characters (refused: 12,218); this leaves a fifth of it for
#: the macros it expands.
MATHJAX_LATEX_LIMIT = 4000

#: A matrix is typeset inside an HTML view when each entry's LaTeX is at most this
#: long (a wider matrix does not fit a notebook's width: it is shown as text).
TYPESET_ENTRY = 80


def fits_mathjax(tex: str | None) -> bool:
    """Whether ``tex`` is short enough for MathJax (see :data:`MATHJAX_LATEX_LIMIT`).

    Example
    -------
    >>> fits_mathjax("x" * 4000), fits_mathjax("x" * 4001), fits_mathjax(None)
    (True, False, False)
    """
    return tex is not None and len(tex) <= MATHJAX_LATEX_LIMIT


def latex_or_none(tex: str | None) -> str | None:
    """``tex`` when MathJax accepts it, else None (the display then shows its HTML).

    Example
    -------
    >>> latex_or_none(None) is None
    True
    """
    return tex if fits_mathjax(tex) else None


def math_html(tex: str) -> str:
    """``tex`` (math, without delimiters) as display math inside HTML: ``$$...$$``,
    escaped for HTML (Jupyter's MathJax reads the text, ``&`` included).

    Example
    -------
    >>> math_html("a < b")
    '$$a &lt; b$$'
    """
    return "$$" + html.escape(tex, quote=False) + "$$"


def typesets(matrix: sp.MatrixBase, tex: str) -> bool:
    """Whether ``matrix`` (written ``tex``) is typeset inside an HTML view: not empty,
    MathJax takes it, and each entry fits (see :data:`TYPESET_ENTRY`).

    Example
    -------
    >>> m = sp.Matrix([[1, sp.Symbol("L")]])
    >>> typesets(m, sp.latex(m)), typesets(sp.Matrix([[sp.Symbol("x") ** 99 * 10**90]]), "")
    (True, False)
    """
    return (0 not in matrix.shape and fits_mathjax(tex)
            and all(len(sp.latex(e)) <= TYPESET_ENTRY for e in matrix))
