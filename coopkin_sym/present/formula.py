r"""Mathematics written once from exact data: a text that carries its LaTeX, and
SymPy's LaTeX in plain-LaTeX commands.

Example
-------
>>> import sympy as sp
>>> latex(sp.atan(sp.Symbol("x")))
'\\arctan{\\left(x \\right)}'
"""

from __future__ import annotations

import re

import sympy as sp

__all__ = ["Formula", "latex"]


class Formula(str):
    """A span's text that carries its mathematics, written once from exact data:
    ``tex`` is its LaTeX (plain text formats show the text itself).

    Example
    -------
    >>> f = Formula("q1 = 0", "$q_{1} = 0$")
    >>> f, f.tex
    ('q1 = 0', '$q_{1} = 0$')
    """

    tex: str

    def __new__(cls, text: str, tex: str) -> Formula:
        out = super().__new__(cls, text)
        out.tex = tex
        return out

    def __reduce__(self):
        return (Formula, (str(self), self.tex))


def latex(expr: sp.Expr) -> str:
    """SymPy's LaTeX with plain-LaTeX commands only (no amsmath's \\operatorname)."""
    text = sp.latex(expr, inv_trig_style="full")
    return re.sub(r"\\operatorname\{(\w+)\}", r"\\mathrm{\1}", text)
