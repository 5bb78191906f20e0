"""The LaTeX renderer of a report: an appendix to ``\\input`` in a paper
(``\\section*`` and ``tabular`` only: it compiles with a plain ``article`` class).
Polynomials, points and conditions are written as mathematics (SymPy's LaTeX).

Example
-------
>>> print(LatexRenderer().inline([("text", "Witness: "), ("at", "q1=pi/2")]))
Witness: $q_{1} = \\frac{\\pi}{2}$
"""

from __future__ import annotations

from collections.abc import Sequence
from string import Template

import sympy as sp

from coopkin_sym.exact.parse import NumberError, parse_expression
from coopkin_sym.present.formula import latex as _latex
from coopkin_sym.present.report.blocks import (
    Bullets,
    Document,
    Figure,
    Formula,
    Heading,
    Paragraph,
    Span,
    Table,
)
from coopkin_sym.present.report.formulas import (
    MAX_EQUATION,
    _read,
    _tex_code,
    _tex_comment,
    _tex_escape,
)

# rows per LaTeX tabular
LATEX_ROWS = 30
_HEADS = {1: "section*", 2: "subsection*", 3: "subsubsection*"}
_TOP = Template("% Singularity-locus report of $subject (coopkin locus); \\input this "
                "file in a document.")


def _tex_eq(text: str, tail: str = "") -> str:
    if isinstance(text, Formula):  # written from the exact polynomial
        return f"${text.tex}{tail}$"
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


class LatexRenderer:
    """LaTeX: sections, paragraphs, ``itemize`` and ``tabular``; pictures (files next
    to the report) as ``\\includegraphics`` in comments (it needs graphicx).

    Example
    -------
    >>> LatexRenderer().heading(Heading(2, [("text", "Notes")], "notes"))
    ['\\\\subsection*{Notes}']
    """

    name = "latex"

    def inline(self, spans: Sequence[Span]) -> str:
        out = []
        for kind, value in spans:
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
                out.append(value.tex if isinstance(value, Formula) else _tex_code(value))
            else:
                out.append(_tex_code(value))
        return "".join(out)

    def heading(self, block: Heading) -> list[str]:
        return [f"\\{_HEADS[block.level]}{{{self.inline(block.spans)}}}"]

    def paragraph(self, block: Paragraph) -> list[str]:
        return [self.inline(block.spans), ""]

    def bullets(self, block: Bullets) -> list[str]:
        return [r"\begin{itemize}", *(r"\item " + self.inline(i) for i in block.items),
                r"\end{itemize}"]

    def table(self, block: Table) -> list[str]:
        """A table as ``tabular`` environments of at most LATEX_ROWS rows each (a
        ``tabular`` does not break across pages)."""
        keep = [i for i in range(len(block.header)) if i not in block.latex_skip]
        widths = block.latex_widths or {}
        spec = "|" + "|".join(f"p{{{widths[i]}}}" if i in widths else block.align[i]
                              for i in keep) + "|"
        head = " & ".join(r"\textbf{" + _tex_escape(block.header[i]) + "}" for i in keep)
        out: list[str] = []
        rows = block.rows
        chunks = [rows[k:k + LATEX_ROWS] for k in range(0, len(rows), LATEX_ROWS)] or [[]]
        for chunk in chunks:
            out.append(r"\begin{center}\footnotesize\setlength{\tabcolsep}{2pt}")
            out.append(f"\\begin{{tabular}}{{{spec}}}")
            out.append(r"\hline")
            out.append(head + r" \tabularnewline \hline")
            for row in chunk:
                cells = [(r"\raggedright " if i in widths else "") + self.inline(row[i])
                         for i in keep]
                out.append(" & ".join(cells) + r" \tabularnewline \hline")
            out.append(r"\end{tabular}")
            out.append(r"\end{center}")
        return out

    def figure(self, block: Figure) -> list[str]:
        return [f"% \\includegraphics[width=0.8\\textwidth]{{{block.ref}}}"
                f"  % {_tex_comment(block.caption)}"]

    def page(self, document: Document, body: list[str]) -> str:
        out = [_TOP.substitute(subject=_tex_comment(document.subject)), *body]
        if document.files:
            out.append("% Plots of the components (need \\usepackage{graphicx}):")
            for figure in document.files:
                out += self.figure(figure)
        return "\n".join(out).rstrip() + "\n"
