"""Conditions of components in a report: a condition in words, shortened for tables
and titles, and written as mathematics in LaTeX.

Kept apart so that how a condition is split (on ``" or "``, ``", "`` and ``"="``) is
one module.

Example
-------
>>> from coopkin_sym.analysis.locus.types import Component
>>> _condition(Component(["t_q1 + 1"], {}, None, True))
't_q1 + 1 = 0'
>>> print(_tex_cond("q1 = -pi/2, q2 = pi/2"))
$q_{1} = - \\frac{\\pi}{2}$, $q_{2} = \\frac{\\pi}{2}$
"""

from __future__ import annotations

import re

from coopkin_sym.analysis.locus.types import Component
from coopkin_sym.present.report.formulas import _latex, _read, _tex_code


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
