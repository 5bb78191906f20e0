"""Where a locus component lies, in angles, as exact data.

A :class:`Condition` is a disjunction of conjunctions of clauses: the real points of
an algebraic family are alternatives (``q1 = -5*pi/6, q2 = 5*pi/6 or q1 = -pi/6, q2 =
pi/6``), the equations of one component a conjunction. A clause is a joint or
parameter at an exact value (:class:`Value`), two angles related (:class:`Related`:
``q1 = q2``, ``q1 = -q2``, ``q1 = q2 + pi``, ``q1 + q2 = pi``) or a polynomial that
vanishes (:class:`Vanishes`). :attr:`Condition.text` is the condition in the
package's notation, exactly; the presentation layer writes it for people (shortened,
approximated, in HTML or LaTeX: :mod:`coopkin_sym.present.report.conditions`).

Example
-------
>>> import sympy as sp
>>> c = Condition.of(Value("q1", sp.pi / 2, "revolute"), Related("q2", "q3", -1, True))
>>> c.text
'q1 = pi/2, q2 + q3 = pi (mod 2*pi)'
>>> (c | Condition.of(Value("q1", sp.Integer(0), "revolute"))).text
'q1 = pi/2, q2 + q3 = pi (mod 2*pi) or q1 = 0'
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property
from typing import Union

import sympy as sp

from coopkin_sym.errors import NumberError
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.parse import brief, parse_expression
from coopkin_sym.exact.polynomial import NamedPolynomial

__all__ = ["Clause", "Condition", "Related", "Value", "Vanishes"]


@dataclass(frozen=True)
class Value:
    """``name = value``: a joint or a parameter at an exact value (``value`` a SymPy
    number, in radians for a revolute joint: ``pi/2``, ``2*atan(1/3)``,
    ``2*atan(-2 + sqrt(3))``); ``kind`` is ``"revolute"``, ``"prismatic"`` or
    ``"parameter"``.

    Example
    -------
    >>> Value("d4", sp.Rational(1, 2), "prismatic").text
    'd4 = 1/2'
    >>> Value("q1", -2 * sp.atan(sp.Rational(1, 3)), "revolute").text
    'q1 = 2*atan(-1/3)'
    """

    name: str
    value: sp.Expr
    kind: str

    @property
    def text(self) -> str:
        return f"{self.name} = {self.value_text}"

    @cached_property
    def value_text(self) -> str:
        """The value as ``--at`` writes it: an angle with a rational tangent half-angle
        as :class:`~coopkin_sym.exact.angles.ExactAngle` does (``2*atan(-1/3)``); kept
        once written (an algebraic value's text takes milliseconds)."""
        if self.kind == "revolute" and self.value.is_real is not False:
            half = sp.tan(self.value / 2)
            if half.is_Rational:
                return ExactAngle.from_tangent(Fraction(int(half.p), int(half.q))).text
        return sp.sstr(self.value)

    def approximation(self) -> float:  # float-ok: for display only
        """The value as a float (radians for an angle), for display only."""
        return self._approximation

    @cached_property
    def _approximation(self) -> float:  # float-ok: display only; kept once evaluated
        return float(sp.N(self.value, 30))  # float-ok: display only


@dataclass(frozen=True)
class Related:
    """``left = sign * right`` (``sign`` is 1 or -1), plus ``pi`` (mod 2*pi) when
    ``plus_pi``: two revolute joints.

    Example
    -------
    >>> [Related("a", "b", s, p).text for s in (1, -1) for p in (False, True)]
    ['a = b', 'a = b + pi (mod 2*pi)', 'a = -b', 'a + b = pi (mod 2*pi)']
    """

    left: str
    right: str
    sign: int
    plus_pi: bool = False

    @property
    def text(self) -> str:
        if not self.plus_pi:
            return f"{self.left} = {'-' if self.sign < 0 else ''}{self.right}"
        if self.sign > 0:
            return f"{self.left} = {self.right} + pi (mod 2*pi)"
        return f"{self.left} + {self.right} = pi (mod 2*pi)"


@dataclass(frozen=True)
class Vanishes:
    """``polynomial = 0``, where it does not read more simply in angles.

    Example
    -------
    >>> Vanishes(NamedPolynomial.variable("t_q1")).text
    't_q1 = 0'
    """

    polynomial: NamedPolynomial

    @property
    def text(self) -> str:
        return f"{self.polynomial.text} = 0"


Clause = Union[Value, Related, Vanishes]  # noqa: UP007 - a runtime alias


@dataclass(frozen=True)
class Condition:
    """Alternatives (``or``), each a conjunction of clauses (written ``, ``).

    Example
    -------
    >>> a = Condition.of(Value("q1", sp.Integer(0), "revolute"))
    >>> b = Condition.of(Value("q2", sp.pi, "revolute"))
    >>> (a & b).text, bool(Condition()), (a & b).clauses()[1].name
    ('q1 = 0, q2 = pi', False, 'q2')
    """

    alternatives: tuple[tuple[Clause, ...], ...] = ()

    @classmethod
    def of(cls, *clauses: Clause) -> Condition:
        """One conjunction of ``clauses`` (no clause: no condition)."""
        return cls((tuple(clauses),) if clauses else ())

    @classmethod
    def either(cls, conditions: Iterable[Condition]) -> Condition:
        """Any of ``conditions`` (their alternatives, in order)."""
        return cls(tuple(alt for c in conditions for alt in c.alternatives))

    def __or__(self, other: Condition) -> Condition:
        return Condition.either((self, other))

    def __and__(self, other: Condition) -> Condition:
        """Both: every alternative of one with every alternative of the other."""
        if not self.alternatives:
            return other
        if not other.alternatives:
            return self
        return Condition(tuple(a + tuple(c for c in b if c not in a)
                               for a in self.alternatives for b in other.alternatives))

    def __bool__(self) -> bool:
        return bool(self.alternatives)

    def clauses(self) -> list[Clause]:
        """Every clause, alternative after alternative."""
        return [c for alt in self.alternatives for c in alt]

    def polynomials(self) -> list[NamedPolynomial]:
        """The polynomials of the :class:`Vanishes` clauses."""
        return [c.polynomial for c in self.clauses() if isinstance(c, Vanishes)]

    @property
    def text(self) -> str:
        """The condition in the package's notation, exactly (values never rounded)."""
        return " or ".join(", ".join(_chain_text(chain) for chain in chains(alt))
                           for alt in self.alternatives)

    def __str__(self) -> str:
        return self.text

    def __format__(self, spec: str) -> str:
        return format(self.text, spec)

    @classmethod
    def parse(cls, text: str, kinds: Mapping[str, str] | None = None,
              where: str = "condition",
              polynomial: Callable[[str, str], NamedPolynomial] = NamedPolynomial.read
              ) -> Condition:
        """A condition from its :attr:`text` (the package's notation), every value and
        polynomial through the one parser; ``kinds`` names the kind of each joint or
        parameter (else an angle is a value with ``pi`` or ``atan``); ``polynomial``
        reads the polynomial of a clause ``... = 0`` (text, entry).

        Raises :class:`~coopkin_sym.errors.NumberError` (naming ``where``) on a clause
        it does not read.

        Example
        -------
        >>> c = Condition.parse("q1 = q2 = -pi/2 or q1 + q2 = pi (mod 2*pi)")
        >>> [type(k).__name__ for k in c.clauses()], c.clauses()[1].value
        (['Related', 'Value', 'Related'], -pi/2)
        """
        if not str(text).strip():
            return cls()
        alternatives = []
        for k, alt in enumerate(str(text).split(" or ")):
            clauses: list[Clause] = []
            for clause in alt.split(", "):
                for c in _read_clause(clause.strip(), kinds or {},
                                      f"{where}, clause {k + 1}", polynomial):
                    if c not in clauses:
                        clauses.append(c)
            alternatives.append(tuple(clauses))
        return cls(tuple(alternatives))

    def to_json(self) -> list[list[dict]]:
        """Plain JSON data: a list of alternatives, each a list of clauses, each
        ``{"value": ...}``, ``{"related": ...}`` or ``{"vanishes": ...}`` (exact texts)."""
        return [[clause_json(c) for c in alt] for alt in self.alternatives]


def chains(clauses: Sequence[Clause]) -> list[tuple[Clause, ...]]:
    """The clauses of one alternative as they are written: ``a = b`` followed by
    ``b = v`` is one chain ``a = b = v``; every other clause stands alone.

    Example
    -------
    >>> [len(c) for c in chains(Condition.parse("q1 = q2 = -pi/2, q3 = 0").clauses())]
    [2, 1]
    """
    out: list[tuple[Clause, ...]] = []
    for c in clauses:
        last = out[-1][-1] if out else None
        if (isinstance(c, Value) and isinstance(last, Related) and last.sign > 0
                and not last.plus_pi and last.right == c.name and len(out[-1]) == 1):
            out[-1] = (*out[-1], c)
        else:
            out.append((c,))
    return out


def _chain_text(chain: tuple[Clause, ...]) -> str:
    if len(chain) == 2:
        return f"{chain[0].left} = {chain[1].text}"
    return chain[0].text


def clause_json(clause: Clause) -> dict:
    """One clause as plain JSON data (exact values as text).

    Example
    -------
    >>> clause_json(Related("q1", "q2", -1))
    {'related': ['q1', 'q2'], 'sign': -1, 'plus_pi': False}
    """
    if isinstance(clause, Value):
        return {"value": clause.name, "equals": clause.value_text, "kind": clause.kind}
    if isinstance(clause, Related):
        return {"related": [clause.left, clause.right], "sign": clause.sign,
                "plus_pi": clause.plus_pi}
    return {"vanishes": clause.polynomial.text}


_NAME = re.compile(r"-?[A-Za-z_][A-Za-z0-9_]*")
_MOD = " (mod 2*pi)"


def _read_clause(text: str, kinds: Mapping[str, str], where: str,
                 polynomial: Callable[[str, str], NamedPolynomial]) -> list[Clause]:
    if text.endswith(_MOD):
        sides = [s.strip() for s in text[: -len(_MOD)].split("=")]
        if len(sides) == 2 and sides[1] == "pi" and " + " in sides[0]:
            left, right = (s.strip() for s in sides[0].split(" + ", 1))
            if _NAME.fullmatch(left) and _NAME.fullmatch(right):
                return [Related(left, right, -1, True)]
        if len(sides) == 2 and sides[1].endswith(" + pi") and _NAME.fullmatch(sides[0]):
            return [Related(sides[0], sides[1][: -len(" + pi")].strip(), 1, True)]
        raise NumberError(where, f"{brief(text)} is not a relation of two angles")
    sides = [s.strip() for s in text.split("=")]
    if len(sides) < 2 or not all(sides):
        raise NumberError(where, f"{brief(text)} is not an equation")
    if len(sides) == 2 and sides[1] == "0" and not _NAME.fullmatch(sides[0]):
        return [Vanishes(polynomial(sides[0], where))]
    out: list[Clause] = []
    for left, right in zip(sides, sides[1:], strict=False):
        if not _NAME.fullmatch(left) or left.startswith("-"):
            raise NumberError(where, f"{brief(left)} is not a name")
        if _NAME.fullmatch(right) and right.lstrip("-") not in ("pi", "E", "I"):
            out.append(Related(left, right.lstrip("-"), -1 if right.startswith("-") else 1))
            continue
        value = parse_expression(right, [], where)
        kind = kinds.get(left) or ("revolute" if value.has(sp.pi, sp.atan) else "prismatic")
        out.append(Value(left, value, kind))
    return out


def vanishing(polynomials: Sequence[NamedPolynomial]) -> Condition:
    """The condition that every one of ``polynomials`` vanishes."""
    return Condition.of(*(Vanishes(p) for p in polynomials))
