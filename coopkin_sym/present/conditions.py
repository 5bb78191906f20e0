"""Conditions of locus components, written from their exact data
(:class:`~coopkin_sym.analysis.locus.conditions.Condition`): in words for tables and
titles (long polynomials named, long values rounded), and in LaTeX.

Nothing here reads text back: every clause is a value, a relation of two angles or a
polynomial, and each format writes it once.

Example
-------
>>> import sympy as sp
>>> from coopkin_sym.analysis.locus.conditions import Condition, Value
>>> from coopkin_sym.analysis.locus.types import Component
>>> c = Component(["t_q1 + 1"], {}, None, True, condition=Condition.of(
...     Value("q1", -sp.pi / 2, "revolute"), Value("q2", sp.pi / 2, "revolute")))
>>> shown = short_condition(c)
>>> shown, shown.tex
('q1 = -pi/2, q2 = pi/2', '$q_{1} = - \\\\frac{\\\\pi}{2}$, $q_{2} = \\\\frac{\\\\pi}{2}$')
>>> condition_text(Component(["t_q1 + 1"], {}, None, True))
't_q1 + 1 = 0'
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import sympy as sp

from coopkin_sym.analysis.locus.conditions import Clause, Related, Value, Vanishes, chains
from coopkin_sym.analysis.locus.types import Component
from coopkin_sym.exact.polynomial import NamedPolynomial
from coopkin_sym.present.formula import Formula
from coopkin_sym.present.formula import latex as _latex

# a clause of a condition longer than this is named, not written out, in tables/titles
_LONG_CLAUSE = 48
# an exact value longer than this is shown rounded (the exact one is in the witness)
_LONG_VALUE = 32


def condition_text(c: Component) -> Formula:
    """The whole condition (every alternative, every polynomial written out)."""
    return _written(c, short=False)


def short_condition(c: Component) -> Formula:
    """The condition with every long polynomial clause replaced by ``P<k>(vars) = 0``,
    ``k`` its place among the component's equations (written out in the details), and
    only the first of more than two alternatives.

    Example
    -------
    >>> c = Component(["t_a2", "3*t_a1**2*t_b1**2 + 8*t_a1*t_b1 + 3*t_a1**2 - 7*t_b1 + 1"],
    ...               {}, None, True, condition="a2 = 0, 3*t_a1**2*t_b1**2 + 8*t_a1*t_b1"
    ...               " + 3*t_a1**2 - 7*t_b1 + 1 = 0")
    >>> short_condition(c)
    'a2 = 0, P2(t_a1, t_b1) = 0'
    """
    return _written(c, short=True)


def _written(c: Component, short: bool) -> Formula:
    alternatives = c.condition.alternatives
    if not alternatives:
        text = " and ".join(f"{e} = 0" for e in c.equations) or "(no equations)"
        tex = ", ".join(f"${_latex(e.to_sympy())} = 0$" for e in c.equations)
        return Formula(text, tex or r"\textit{(no equations)}")
    more = short and len(alternatives) > 2
    shown = alternatives[:1] if more else alternatives
    texts = [", ".join(_chain(ch, c.equations, short, _clause_text) for ch in chains(alt))
             for alt in shown]
    texs = [", ".join(_chain(ch, c.equations, short, _clause_tex) for ch in chains(alt))
            for alt in shown]
    tail = " or ..." if more else ""
    return Formula(" or ".join(texts) + tail, " or ".join(texs) + tail)


def _chain(chain: tuple[Clause, ...], equations: Sequence[NamedPolynomial], short: bool,
           write) -> str:
    """One clause, or ``a = b = v`` (``a = b`` then ``b = v``) in one piece."""
    if len(chain) == 1:
        return write(chain[0], equations, short)
    head, tail = chain[0], write(chain[1], equations, short)
    if tail.startswith("$"):
        return f"${_symbol(head.left)} = {tail[1:]}"
    return f"{head.left} = {tail}"


def _long_value(clause: Value) -> bool:
    text = clause.value_text
    return len(text) > _LONG_VALUE or clause.value.has(sp.CRootOf)


def _named_polynomial(p: NamedPolynomial, equations: Sequence[NamedPolynomial]
                      ) -> tuple[str, list[str]] | None:
    """``(label, variables)`` for a polynomial too long for a title, else None."""
    if len(p.text) + 4 <= _LONG_CLAUSE:
        return None
    k = next((i + 1 for i, e in enumerate(equations) if e == p), None)
    return (f"P{k}" if k else "P"), sorted(p.variables)


def _clause_text(clause: Clause, equations: Sequence[NamedPolynomial], short: bool) -> str:
    if isinstance(clause, Value):
        if not _long_value(clause):
            return clause.text
        value = clause.approximation()  # float-ok: shown rounded, the exact value is kept
        if clause.kind == "revolute":
            return f"{clause.name} \u2248 {value * 180 / math.pi:.4g}\u00b0"  # float-ok
        return f"{clause.name} \u2248 {value:.4g}"
    if isinstance(clause, Vanishes) and short:
        named = _named_polynomial(clause.polynomial, equations)
        if named is not None:
            return f"{named[0]}({', '.join(named[1])}) = 0"
    return clause.text


def _symbol(name: str) -> str:
    return sp.latex(sp.Symbol(name))


def _clause_tex(clause: Clause, equations: Sequence[NamedPolynomial], short: bool) -> str:
    if isinstance(clause, Value):
        if not _long_value(clause):
            return f"${_symbol(clause.name)} = {_latex(clause.value)}$"
        value = clause.approximation()  # float-ok: shown rounded
        if clause.kind == "revolute":
            return (f"${_symbol(clause.name)} \\approx "
                    f"{value * 180 / math.pi:.4g}^\\circ$")  # float-ok: shown rounded
        return f"${_symbol(clause.name)} \\approx {value:.4g}$"  # float-ok: shown rounded
    if isinstance(clause, Related):
        a, b = _symbol(clause.left), _symbol(clause.right)
        if not clause.plus_pi:
            return f"${a} = {'-' if clause.sign < 0 else ''}{b}$"
        if clause.sign > 0:
            return f"${a} = {b} + \\pi \\pmod{{2\\pi}}$"
        return f"${a} + {b} = \\pi \\pmod{{2\\pi}}$"
    named = _named_polynomial(clause.polynomial, equations) if short else None
    if named is not None:
        label, names = named
        return f"${label[0]}_{{{label[1:]}}}({', '.join(map(_symbol, names))}) = 0$"
    return f"${_latex(clause.polynomial.to_sympy())} = 0$"
