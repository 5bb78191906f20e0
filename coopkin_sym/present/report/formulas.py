"""Formulas in a report: a text read as a polynomial by the package's parser (never
evaluated), SymPy's LaTeX of it, the escaping of text for LaTeX and for one line, and
lists of remarks whose formulas are shown as formulas.

Example
-------
>>> _parses("t_q1**2 + 1"), _parses("no real points")
(True, False)
"""

from __future__ import annotations

import re
from collections.abc import Sequence

import sympy as sp

from coopkin_sym.exact.parse import FUNCTIONS, NumberError, parse_expression
from coopkin_sym.present.report.blocks import Bullets, Paragraph, Span, _t

# names the parser reads itself (functions and constants), never variables
_PARSER_NAMES = {*FUNCTIONS, "pi", "CRootOf"}
# longest equation text shown in a report (the JSON always has all of it)
MAX_EQUATION = 1500


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


def _one_line(text: str) -> str:
    """Line breaks and other control characters as spaces: user text cannot start a
    new line (a heading, a table row, a LaTeX line outside a comment)."""
    return _CONTROL.sub(" ", text)


_CONTROL = re.compile(r"[\x00-\x1f\x7f-\x9f\u2028\u2029]")


_TEX_SPECIAL = {"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&",
                "#": r"\#", "^": r"\textasciicircum{}", "_": r"\_", "%": r"\%",
                "~": r"\textasciitilde{}", "\u2192": r"$\to$", "\u00b1": r"$\pm$",
                "<": r"$<$", ">": r"$>$", "|": r"$|$", "\u2260": r"$\neq$",
                "\u2264": r"$\leq$", "\u2265": r"$\geq$", "\u2248": r"$\approx$",
                "\u00b0": r"$^\circ$"}


def _tex_escape(text: str) -> str:
    r"""Text as LaTeX that prints it as it is (``--`` stays two hyphens, not a dash).

    Example
    -------
    >>> print(_tex_escape("run with --certify: 50% of t_q1"))
    run with -{}-certify: 50\% of t\_q1
    """
    escaped = "".join(_TEX_SPECIAL.get(ch, ch) for ch in _one_line(text))
    return re.sub(r"-(?=-)", "-{}", escaped)


def _tex_comment(text: str) -> str:
    r"""Text inside a ``%`` comment: on one line, so nothing can leave the comment, and
    with its backslashes written out, so that no command is seen in it either.

    Example
    -------
    >>> print(_tex_comment("\\input{x}\nnext"))
    \textbackslash{}input{x} next
    """
    return " ".join(_one_line(text).replace("\\", r"\textbackslash{}").split())


def _tex_code(text: str) -> str:
    # \texttt with break points after commas so long points wrap in narrow columns
    return r"\texttt{" + _tex_escape(text).replace(",", r",\allowbreak{}") + "}"


def _formula(text: str) -> list[Span]:
    """``t_q1**2 + 1 = 0 (no real points)`` as an equation and its words; plain text
    when it is not a polynomial."""
    head, sep, tail = text.partition(" = 0")
    head = head if sep else text
    if _parses(head):
        return [("eq0" if sep else "eq", head)] + ([_t(tail)] if tail else [])
    return [_t(text)]


def _list_or(items: Sequence[str], none: str, formulas: bool = False) -> list:
    if not items:
        return [Paragraph([_t(none)])]
    return [Bullets([_formula(s) if formulas else [_t(s)] for s in items])]
