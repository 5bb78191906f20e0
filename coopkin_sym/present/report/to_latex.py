"""The LaTeX renderer of a report: an appendix to ``\\input`` in a paper
(``\\section*`` and ``tabular`` only: it compiles with a plain ``article`` class, and
its tables break across pages between rows).
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
    text_of,
)
from coopkin_sym.present.report.formulas import (
    MAX_EQUATION,
    _read,
    _tex_code,
    _tex_comment,
    _tex_escape,
)

# the end of one row's tabular: the next one follows with no space between them
_END_ROW = r"\end{tabular}\par\nointerlineskip"
#: Widest column (em) whose width is taken from its entries; longer ones wrap.
LATEX_MAX_WIDTH = 14


def _em(block: Table, column: int) -> str:
    """A width for a column with none given: its longest entry (header included) at
    about half an em per character of footnote size, at most LATEX_MAX_WIDTH em."""
    longest = max([len(block.header[column]) + 1,
                   *(len(text_of(row[column])) for row in block.rows)])
    return f"{min(max(longest * 0.55 + 0.4, 1.2), LATEX_MAX_WIDTH):.1f}em"  # float-ok: width
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
        """A table as one ``tabular`` per row, stacked with no space between them: a
        page may break between any two rows (one ``tabular`` never breaks: rows past
        the foot of the page were lost), with no package needed (``longtable``). Every
        column has a fixed width (given, else from its longest entry, at most
        :data:`LATEX_MAX_WIDTH` em), so the rules of the rows line up; no break right
        after the header."""
        keep = [i for i in range(len(block.header)) if i not in block.latex_skip]
        widths = block.latex_widths or {}
        spec = "|" + "|".join(f"p{{{widths.get(i) or _em(block, i)}}}" for i in keep) + "|"
        head = " & ".join(r"\textbf{" + _tex_escape(block.header[i]) + "}" for i in keep)
        out: list[str] = [r"\begin{center}\footnotesize\setlength{\tabcolsep}{2pt}"
                          r"\setlength{\parskip}{0pt}",
                          f"\\begin{{tabular}}{{{spec}}}", r"\hline",
                          head + r" \tabularnewline \hline", _END_ROW + r"\nobreak"]
        for row in block.rows:
            cells = [(r"\raggedright " if i in widths else "") + self.inline(row[i])
                     for i in keep]
            out.append(f"\\begin{{tabular}}{{{spec}}}")
            out.append(" & ".join(cells) + r" \tabularnewline \hline")
            out.append(_END_ROW + r"\penalty0")
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
