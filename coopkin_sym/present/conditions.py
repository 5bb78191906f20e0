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

import functools
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


class PolynomialNames:
    """The names ``P1``, ``P2``, ... of the long polynomials of one document, each
    distinct polynomial named once, in the order of first use (a report writes each
    ``P<k> = ...`` once, in its appendix).

    Example
    -------
    >>> from coopkin_sym.exact.polynomial import NamedPolynomial
    >>> names = PolynomialNames()
    >>> a, b = (NamedPolynomial.parse(t, ["t_q1", "t_q2"], "p")
    ...         for t in ("t_q1 - 2", "t_q2 + 1"))
    >>> names.name(b), names.name(a), names.name(b)
    ('P1', 'P2', 'P1')
    >>> [(label, p.text) for label, p in names.named()]
    [('P1', 't_q2 + 1'), ('P2', 't_q1 - 2')]
    """

    def __init__(self) -> None:
        self._numbers: dict[NamedPolynomial, int] = {}

    def name(self, p: NamedPolynomial) -> str:
        """The name of ``p``: its number once it has one, else the next one."""
        return f"P{self._numbers.setdefault(p, len(self._numbers) + 1)}"

    def named(self) -> list[tuple[str, NamedPolynomial]]:
        """Every polynomial named so far with its name, in the order of the names."""
        return [(f"P{k}", p) for p, k in self._numbers.items()]

    def __len__(self) -> int:
        return len(self._numbers)


def is_long(p: NamedPolynomial) -> bool:
    """Whether ``p`` is too long for a table or a title (it is named there).

    Example
    -------
    >>> from coopkin_sym.exact.polynomial import NamedPolynomial
    >>> is_long(NamedPolynomial.parse("t_q1 - 2", ["t_q1"], "p"))
    False
    """
    return len(p.text) + 4 > _LONG_CLAUSE


def condition_text(c: Component, names: PolynomialNames | None = None) -> Formula:
    """The whole condition (every alternative); every polynomial written out, or, with
    ``names``, the long ones by their names there (written out once elsewhere)."""
    return _written(c, False, names)


def short_condition(c: Component, names: PolynomialNames | None = None) -> Formula:
    """The condition with every long polynomial clause replaced by ``P<k>(vars) = 0``,
    and only the first of more than two alternatives. ``k`` is the polynomial's place
    among the component's equations (written out in the details), or with ``names``
    its name in the whole document.

    Example
    -------
    >>> c = Component(["t_a2", "3*t_a1**2*t_b1**2 + 8*t_a1*t_b1 + 3*t_a1**2 - 7*t_b1 + 1"],
    ...               {}, None, True, condition="a2 = 0, 3*t_a1**2*t_b1**2 + 8*t_a1*t_b1"
    ...               " + 3*t_a1**2 - 7*t_b1 + 1 = 0")
    >>> short_condition(c)
    'a2 = 0, P2(t_a1, t_b1) = 0'
    >>> names = PolynomialNames()
    >>> short_condition(c, names), names.named()[0][0]
    ('a2 = 0, P1(t_a1, t_b1) = 0', 'P1')
    """
    return _written(c, True, names)


def _namer(c: Component, short: bool, names: PolynomialNames | None):
    """How long polynomials are named: by ``names``, by their place among the
    component's equations (``short``), or not at all (None)."""
    if names is not None:
        return names.name
    if not short:
        return None

    def local(p: NamedPolynomial) -> str:
        k = next((i + 1 for i, e in enumerate(c.equations) if e == p), None)
        return f"P{k}" if k else "P"
    return local


def _written(c: Component, short: bool, names: PolynomialNames | None) -> Formula:
    alternatives = c.condition.alternatives
    namer = _namer(c, short, names)
    if not alternatives:
        if names is not None:
            clauses = [Vanishes(e) for e in c.equations]
            text = " and ".join(_clause_text(v, namer) for v in clauses)
            tex = ", ".join(_clause_tex(v, namer) for v in clauses)
            return Formula(text or "(no equations)", tex or r"\textit{(no equations)}")
        text = " and ".join(f"{e} = 0" for e in c.equations) or "(no equations)"
        tex = ", ".join(f"${_polynomial_tex(e)} = 0$" for e in c.equations)
        return Formula(text, tex or r"\textit{(no equations)}")
    more = short and len(alternatives) > 2
    shown = alternatives[:1] if more else alternatives
    texts = [", ".join(_chain(ch, namer, _clause_text) for ch in chains(alt))
             for alt in shown]
    texs = [", ".join(_chain(ch, namer, _clause_tex) for ch in chains(alt))
            for alt in shown]
    tail = " or ..." if more else ""
    return Formula(" or ".join(texts) + tail, " or ".join(texs) + tail)


def _chain(chain: tuple[Clause, ...], namer, write) -> str:
    """One clause, or ``a = b = v`` (``a = b`` then ``b = v``) in one piece."""
    if len(chain) == 1:
        return write(chain[0], namer)
    head, tail = chain[0], write(chain[1], namer)
    if tail.startswith("$"):
        return f"${_symbol(head.left)} = {tail[1:]}"
    return f"{head.left} = {tail}"


def _long_value(clause: Value) -> bool:
    text = clause.value_text
    return len(text) > _LONG_VALUE or clause.value.has(sp.CRootOf)


def _named_polynomial(p: NamedPolynomial, namer) -> tuple[str, list[str]] | None:
    """``(label, variables)`` for a polynomial too long for a title, else None."""
    if namer is None or not is_long(p):
        return None
    return namer(p), sorted(p.variables)


def _clause_text(clause: Clause, namer) -> str:
    if isinstance(clause, Value):
        if not _long_value(clause):
            return clause.text
        value = clause.approximation()  # float-ok: shown rounded, the exact value is kept
        if clause.kind == "revolute":
            return f"{clause.name} \u2248 {value * 180 / math.pi:.4g}\u00b0"  # float-ok
        return f"{clause.name} \u2248 {value:.4g}"
    if isinstance(clause, Vanishes):
        named = _named_polynomial(clause.polynomial, namer)
        if named is not None:
            return f"{named[0]}({', '.join(named[1])}) = 0"
    return clause.text


@functools.lru_cache(maxsize=4096)
def _symbol(name: str) -> str:
    return sp.latex(sp.Symbol(name))


@functools.lru_cache(maxsize=4096)
def _value_tex(value: sp.Expr) -> str:
    """The LaTeX of an exact value (kept: a picture writes the same clauses again)."""
    return _latex(value)


@functools.lru_cache(maxsize=4096)
def _polynomial_tex(p: NamedPolynomial) -> str:
    """The LaTeX of a polynomial (kept, as :func:`_value_tex`)."""
    return _latex(p.to_sympy())


def _clause_tex(clause: Clause, namer) -> str:
    if isinstance(clause, Value):
        if not _long_value(clause):
            return f"${_symbol(clause.name)} = {_value_tex(clause.value)}$"
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
    named = _named_polynomial(clause.polynomial, namer)
    if named is not None:
        label, names = named
        return f"${label[0]}_{{{label[1:]}}}({', '.join(map(_symbol, names))}) = 0$"
    return f"${_polynomial_tex(clause.polynomial)} = 0$"


def report_names(components: Sequence[Component]) -> PolynomialNames:
    """The names of a report's long polynomials as its components table gives them
    (first use in the order of the components' short conditions); a report and its
    pictures name a polynomial alike.

    Example
    -------
    >>> long = "3*t_a1**2*t_b1**2 + 8*t_a1*t_b1 + 3*t_a1**2 - 7*t_b1 + 1"
    >>> c = Component(["t_a2", long], {}, None, True, condition=f"a2 = 0, {long} = 0")
    >>> [(label, sorted(p.variables)) for label, p in report_names([c]).named()]
    [('P1', ['t_a1', 't_b1'])]
    """
    names = PolynomialNames()
    for c in components:
        short_condition(c, names)
    return names
