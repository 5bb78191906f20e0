"""An independent check of a singularity locus: exact numbers on a rational grid
(q = pi included) and at every rank-drop point of random rational lines.

Nothing here uses the locus search: the numbers come straight from the ranks of
``Q``, ``H G^T`` and ``H D`` (``Nm = d + r - rank Q``, ``Ni = d - rank H G^T``,
``Nr = r - rank H D``, the others from these; ``d`` is 6, or 3 for a planar system),
computed exactly at each point.

* **Soundness.** A component is the set where its equations vanish and none of its
  ``outside`` polynomials does. At each component's witness (rational, or algebraic
  over its number field) the equations must vanish and a direct analysis must give
  the component's numbers. A point of the grid or of a line that lies on a component cannot have a
  rank above the component's (a rank never rises at a special point of a family):
  such a point proves the component wrong.
* **The grid.** Every combination of values of the free variables (``tan(q/2)`` in a
  set that contains infinity, i.e. ``q = pi``; small rational displacements; small
  positive parameters), or of smaller value sets when the product is larger than
  ``max_points`` (the result says which sets were used). Every point whose numbers
  differ from the generic ones must lie on a component with exactly those numbers.
* **Lines.** Random rational lines, each revolute variable in one of its two charts
  (``t = tan(q/2)``, or ``s = cot(q/2)`` so that the line crosses ``q = pi``), some
  with variables held at grid values (lines inside coordinate subspaces, at ``q = pi``
  too). The three matrices restricted to a line are univariate polynomial matrices
  (each row times a factor ``(1 + t^2)^k`` with no real zero); the points where a rank
  drops below its value on the line are the real roots of the gcd of random
  combinations ``det(A M B)`` of its maximal minors (a multiple of the gcd of all of
  them, so no drop point is lost), factored; at each factor with a real root the
  numbers are decided exactly (at a rational root directly, at an irrational one over
  ``Q[x]/(f)``) and the point's membership in the components too. The points where a
  chart variable vanishes are decided as well. A line whose own numbers differ from
  the generic ones must lie inside a component with those numbers.

A point lies on a component when every equation vanishes there, each revolute joint
taking ``t_<joint>`` in Q or infinity: an equation with ``t_<joint>`` is not satisfied
at ``t = oo`` (``q = pi``), one with ``s_<joint> = 1/t_<joint>`` not at ``t = 0``.

What this cannot prove: families with no rational point, of codimension two or more,
and not met by a line (an isolated point with irrational coordinates, say) are checked
only through their own witnesses; a pass says "nothing found", not "complete".

Example
-------
>>> from coopkin_sym import load
>>> from coopkin_sym.analysis.locus.types import Locus
>>> empty = Locus("paper case 1, hard/hard", ["t_q1", "t_q2"], "L=1",
...               {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0})
>>> v = verify_locus(load("paper-case1-hard"), empty, lines=0)
>>> v.grid_points, v.uncovered_total, sorted(u.point["q1"] for u in v.uncovered)[:2]
(100, 4, ['-pi/2', '-pi/2'])
"""

from __future__ import annotations

import functools
import itertools
import math
import random
import time
from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass, field
from fractions import Fraction

import flint
import sympy as sp
from sympy.polys.numberfields.subfield import primitive_element

from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.analysis.mobility import analyze
from coopkin_sym.analysis.numbers import NUMBER_NAMES, numbers_from_ranks, ranks_of_q
from coopkin_sym.analysis.sweep import Value, compile_system
from coopkin_sym.errors import VerifyError
from coopkin_sym.exact.angles import cotangent_name, tangent_name
from coopkin_sym.exact.bounded import report, run_bounded
from coopkin_sym.exact.factoring import factor
from coopkin_sym.exact.matrix import POLYNOMIALS, PolyMatrix
from coopkin_sym.exact.parse import (
    NumberError,
    algebraic_half_angle,
    parse_angle,
    parse_expression,
    parse_number,
)
from coopkin_sym.exact.polynomial import NamedPolynomial
from coopkin_sym.exact.quotient import Quotient
from coopkin_sym.exact.rationals import to_fmpq, to_fraction, to_sympy
from coopkin_sym.model.configuration import (
    Configuration,
    ConfigurationError,
    split_assignments,
)
from coopkin_sym.model.model import Model, model_of

__all__ = ["DEFAULT_VALUES", "ComponentIssue", "DropPoint", "Verification", "VerifyError",
           "verify_locus"]

#: Default value sets, in order of preference (a smaller set is a prefix): tangents of
#: half angles for revolute joints ("oo" is q = pi), displacements, positive parameters.
DEFAULT_VALUES: dict[str, tuple[str, ...]] = {
    "revolute": ("0", "oo", "1", "-1", "2", "-2", "1/2", "-1/2", "3", "-1/3"),
    "prismatic": ("0", "1", "-1", "2", "-2", "1/2", "-1/2", "3"),
    "parameter": ("1", "2", "1/2", "3", "1/3"),
}
_INFINITE = {"oo", "inf", "infinity", "pi"}
#: Uncovered points kept in the result (all are counted).
MAX_LISTED = 200
#: Membership of a point where a component's equations hold and one of its ``outside``
#: polynomials vanishes too (it may lie in the component's closure, or not).
BOUNDARY = 2

Tan = Fraction | None          # a revolute value: tan(q/2), None for q = pi



# --- results --------------------------------------------------------------------------
@dataclass
class DropPoint:
    """A point where the numbers differ from the generic ones and no component with
    exactly those numbers contains it.

    ``kind`` is ``"point"`` (a rational point: ``point`` in ``--at`` syntax, fixed
    values included), ``"root"`` (a point with irrational coordinates on a line:
    ``point`` holds approximate values, radians and lengths, and ``algebraic`` the
    exact description: the line, each free variable as a polynomial in ``lam`` with
    ``s_<joint>`` for the second chart, the irreducible ``root_of`` in ``lam`` and an
    isolating interval of the real root) or ``"line"`` (every point of a line whose
    own numbers are not the generic ones: ``point`` is the line). ``on``: components
    containing it, with other numbers.

    Example
    -------
    >>> p = DropPoint("grid", {"q1": "pi/2", "q2": "pi/2"}, {"Nm": 3})
    >>> p.kind, p.point["q1"]
    ('point', 'pi/2')
    """

    source: str
    point: dict[str, str]
    numbers: dict[str, int]
    kind: str = "point"
    algebraic: dict | None = None
    on: list[int] = field(default_factory=list)


@dataclass
class ComponentIssue:
    """What is wrong with component ``component`` (index in the locus).

    ``kind``: ``"witness-off"`` (an equation does not vanish at the witness),
    ``"witness-numbers"`` (the witness has other numbers; ``detail`` says when it
    contradicts the locus's fixed values),
    ``"rank-above"`` (a point on the component has a rank above the component's, so
    its numbers cannot hold there), ``"generic-numbers"`` (its numbers are the generic
    ones), or ``"generic"`` (``component`` is -1: the locus's generic numbers are
    wrong). ``point`` and ``numbers`` are the evidence.

    Example
    -------
    >>> issue = ComponentIssue(0, "witness-off", {"q1": "0"}, {"Nm": 2})
    >>> issue.component, issue.kind
    (0, 'witness-off')
    """

    component: int
    kind: str
    point: dict[str, str] | None = None
    numbers: dict[str, int] | None = None
    detail: str = ""


@dataclass
class Verification:
    """The result of :func:`verify_locus`, as plain exact data.

    Attributes
    ----------
    values
        The value set used on the grid for each free variable (``tan(q/2)`` for
        ``t_<joint>``, ``"oo"`` being q = pi).
    reduced
        Whether the requested sets did not fit ``max_points`` (then ``values`` are
        the smaller sets used).
    grid_points, grid_drops
        Points of the grid, and those with numbers other than the generic ones.
    lines, line_points, line_drops, singular_lines
        Lines checked; points decided exactly on them (drop candidates and chart
        zeros, one per irreducible factor); those with non-generic numbers; lines
        whose own numbers are not the generic ones.
    uncovered, uncovered_total
        Points with non-generic numbers on no component with those numbers (at most
        :data:`MAX_LISTED` listed; all counted).
    unsound
        Components shown wrong, with the evidence.
    unchecked
        Components with no witness checked and no point of the grid or of a line on
        them: nothing here confirms them.
    unread_witnesses
        Components whose witness this check cannot read (a ``CRootOf`` value), and why.
    boundary_points
        Points on a component's equations where one of its ``outside`` polynomials
        vanishes, with ranks not above the component's: taken as on it (its closure).

    Example
    -------
    >>> from coopkin_sym import load
    >>> system = load("paper-case1-hard")
    >>> check = verify_locus(system, system.locus(), max_points=200)
    >>> check.ok, check.grid_points > 0
    (True, True)
    """

    system: str
    variables: list[str]
    fixed: str
    generic: dict[str, int]
    values: dict[str, list[str]]
    reduced: bool
    max_points: int
    grid_points: int = 0
    grid_drops: int = 0
    lines: int = 0
    line_points: int = 0
    line_drops: int = 0
    singular_lines: int = 0
    seed: int = 0
    components: int = 0
    witnesses_checked: int = 0
    boundary_points: int = 0
    uncovered: list[DropPoint] = field(default_factory=list)
    uncovered_total: int = 0
    unsound: list[ComponentIssue] = field(default_factory=list)
    unchecked: list[int] = field(default_factory=list)
    unread_witnesses: dict[int, str] = field(default_factory=dict)
    notes: list[Remark] = field(default_factory=list)
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        """Nothing uncovered and nothing unsound."""
        return not self.uncovered_total and not self.unsound

    @property
    def unsound_components(self) -> list[int]:
        return sorted({i.component for i in self.unsound})

    def to_json(self) -> dict:
        """Plain JSON data (notes as remark data: the presentation layer's
        :func:`~coopkin_sym.present.verification.verification_json` words them)."""
        out = asdict(self)
        out["notes"] = [n.to_json() for n in self.notes]
        out["ok"] = self.ok
        return out


# --- exact values -----------------------------------------------------------------------
def _rational(text, where: str) -> Fraction:
    try:
        return Fraction(str(text).strip())
    except (ValueError, ZeroDivisionError):
        raise VerifyError(f"{where}: {text!r} is not a rational number") from None


def _tangent(text, where: str) -> Tan:
    if text is None or str(text).strip().lower() in _INFINITE:
        return None
    return _rational(text, where)


def _tan_text(t: Tan) -> str:
    return "oo" if t is None else str(t)


@functools.lru_cache(maxsize=4096)
def _angle_text(t: Tan) -> str:
    return Value.from_tangent(t).text


@dataclass(frozen=True)
class _Var:
    name: str     # t_q1, q4, L
    kind: str     # revolute, prismatic, parameter
    source: str   # the joint or parameter


# --- equations --------------------------------------------------------------------------
class _Equations:
    """Component equations as polynomials in the free variables' charts.

    The ring has, per free revolute joint, ``t_<joint>`` and ``s_<joint>``; per free
    prismatic joint and parameter its name. Values fixed by the locus are substituted
    when the equations are read; an equation undefined at a fixed value (``t_q3`` with
    ``q3 = pi``) makes its component empty.
    """

    def __init__(self, model: Model, free: list[_Var], fixed: Mapping[str, object]):
        self.free = free
        names: list[str] = []
        self.role: list[tuple[int, str]] = []     # ring variable -> (free index, t|s|x)
        for i, v in enumerate(free):
            if v.kind == "revolute":
                names += [tangent_name(v.source), cotangent_name(v.source)]
                self.role += [(i, "t"), (i, "s")]
            else:
                names.append(v.name)
                self.role.append((i, "x"))
        self.names = names
        self.ctx = flint.fmpq_mpoly_ctx.get(tuple(names) or ("_",), "degrevlex")
        self.fixed = fixed                      # ring-less names -> Tan or Fraction
        self.symbols: dict[str, sp.Symbol] = {}
        for j in model.joints:
            if j.type == "revolute":
                self.symbols[tangent_name(j.name)] = sp.Symbol(tangent_name(j.name))
                self.symbols[cotangent_name(j.name)] = sp.Symbol(cotangent_name(j.name))
            else:
                self.symbols[j.name] = sp.Symbol(j.name)
        for p in model.parameters:
            self.symbols[p.name] = sp.Symbol(p.name)

    def polynomial(self, poly: NamedPolynomial, where: str
                   ) -> tuple[flint.fmpq_mpoly, list[int]] | None:
        """``(polynomial, ring variables used)`` of an equation of the locus (an exact
        polynomial over its variables), or None when it is undefined at the fixed
        values. Term by term: each monomial is put in the ring, or its fixed values
        substituted."""
        out = self.ctx.constant(0)
        for exps, c in poly.terms:
            factors = [to_sympy(c)]
            for name, e in zip(poly.variables, exps, strict=True):
                if name not in self.symbols:
                    raise VerifyError(f"{where}: {name} is neither a free variable of the "
                                      "locus nor a joint or parameter of the model")
                factors.append(self.symbols[name] ** e)
            converted = self._convert(sp.Mul(*factors), where)
            if converted is None:
                return None
            out += converted
        used = [k for k, d in enumerate(out.degrees()) if d] if self.names else []
        return out, used

    def _convert(self, expr: sp.Expr, where: str):
        syms = sorted(expr.free_symbols, key=lambda s: s.name)
        gens = self.ctx.gens()
        poly = sp.Poly(expr, *syms) if syms else None
        if poly is None:
            return self.ctx.constant(_fmpq(sp.Rational(expr)))
        out = self.ctx.constant(0)
        values = []
        for s in syms:
            if s.name in self.names:
                values.append(gens[self.names.index(s.name)])
                continue
            value = self._fixed_value(s.name, where)
            if value is None:
                return None
            values.append(self.ctx.constant(_fmpq(value)))
        for monom, c in poly.terms():
            term = self.ctx.constant(_fmpq(c))
            for v, e in zip(values, monom, strict=True):
                if e:
                    term *= v ** int(e)
            out += term
        return out

    def _fixed_value(self, name: str, where: str) -> Fraction | None:
        """The fixed value of a variable that is not free; None where undefined."""
        if name.startswith(("t_", "s_")) and name[2:] in self.fixed:
            t = self.fixed[name[2:]]
            if name[0] == "t":
                return t
            return None if t == 0 else (Fraction(0) if t is None else 1 / t)
        if name in self.fixed:
            return self.fixed[name]
        raise VerifyError(f"{where}: {name} is neither a free variable of the locus nor "
                          "fixed by it")

    def holds_at(self, eq, point: Sequence) -> bool:
        """Whether ``eq`` vanishes at a rational point (free values in order)."""
        poly, used = eq
        args = [flint.fmpq(0)] * len(self.names)
        for k in used:
            i, role = self.role[k]
            value = point[i]
            if role == "t":
                if value is None:
                    return False
                args[k] = _fmpq(value)
            elif role == "s":
                if value == 0:
                    return False
                args[k] = flint.fmpq(0) if value is None else _fmpq(1 / value)
            else:
                args[k] = _fmpq(value)
        if not self.names:
            return poly.is_zero()
        return poly(*args) == 0

    def on_line(self, eq, line: _Line) -> tuple[flint.fmpq_poly, list[flint.fmpq_poly]]:
        """``eq`` on a line: a polynomial in ``lam`` (the equation times powers of the
        coordinates that enter as reciprocals) and those coordinates, which must not
        vanish where the equation is to be defined."""
        poly, used = eq
        one = flint.fmpq_poly([1])
        parts: dict[int, tuple[flint.fmpq_poly, flint.fmpq_poly]] = {}
        for k in used:
            i, role = self.role[k]
            chart, c = line.coords[i]
            if role == "x" or (role == "t" and chart == "t") or (role == "s" and chart == "s"):
                parts[k] = (c, one)
            else:
                parts[k] = (one, c)
        degrees = poly.degrees() if self.names else ()
        total = flint.fmpq_poly([0])
        for monom, coef in poly.to_dict().items():
            term = flint.fmpq_poly([coef])
            for k in used:
                num, den = parts[k]
                e = monom[k]
                if e:
                    term *= num ** e
                if not den.is_one() and degrees[k] - e:
                    term *= den ** (degrees[k] - e)
            total += term
        dens = [den for num, den in parts.values() if not den.is_one()]
        return total, dens


def _fmpq(x) -> flint.fmpq:
    if not isinstance(x, Fraction | int):
        x = sp.Rational(x)
        return to_fmpq(x)
    x = Fraction(x)
    return flint.fmpq(x.numerator, x.denominator)


# --- points and lines ------------------------------------------------------------------
@dataclass
class _Line:
    """``coords[i] = (chart, c(lam))``: chart ``t`` (``t = c``), ``s`` (``1/t = c``) or
    ``x`` (a displacement or parameter ``= c``)."""

    coords: list[tuple[str, flint.fmpq_poly]]
    domain: tuple[Fraction | None, Fraction | None]   # lam where the parameters are > 0

    def text(self, free: list[_Var]) -> dict[str, str]:
        out = {}
        for v, (chart, c) in zip(free, self.coords, strict=True):
            name = cotangent_name(v.source) if chart == "s" else v.name
            out[name] = _poly_text(c)
        return out

    def point(self, lam: Fraction) -> list:
        out = []
        for chart, c in self.coords:
            value = _eval_q(c, lam)
            if chart == "s":
                out.append(None if value == 0 else 1 / value)
            else:
                out.append(value)
        return out


def _eval_q(p: flint.fmpq_poly, x: Fraction) -> Fraction:
    acc = Fraction(0)
    for c in reversed(p.coeffs()):
        acc = acc * x + to_fraction(c)
    return acc


def _poly_text(p: flint.fmpq_poly, var: str = "lam") -> str:
    coeffs = [to_fraction(c) for c in p.coeffs()]
    x = sp.Symbol(var)
    return sp.sstr(sum((to_sympy(c) * x**i
                        for i, c in enumerate(coeffs)), sp.Integer(0)))


class _Checker:
    """Everything the checks share: the model at the locus's fixed values, the free
    variables, exact evaluation at points and on lines, and the parsed components."""

    def __init__(self, model: Model, locus: Locus, at):
        self.model = model
        self.locus = locus
        fixed_cfg, params = self._read_fixed(model, locus, at)
        variables = list(locus.variables)
        for p in model.parameters:
            if p.name not in params and p.name not in variables:
                params[p.name] = sp.Integer(1)
                self.fixed_items.append((p.name, "1"))
                self.notes.append(Remark.of("verify_parameter_unset", parameter=p.name))
        free_joints = [j.name for j in model.joints
                       if j.name not in fixed_cfg.revolute and j.name not in fixed_cfg.prismatic]
        self.config = Configuration(fixed_cfg.revolute, fixed_cfg.prismatic, params,
                                    frozenset(free_joints))
        kin = kinematics.build(model, self.config)
        if list(kin.ring.names) != variables:
            raise VerifyError(
                f"the locus's variables {variables} do not match the model at its fixed "
                f"values (free variables there: {list(kin.ring.names)})")
        self.kin = kin
        self._read_free(model, variables)
        self.r = len(model.joints)
        self.m = len(kin.Q)
        self._number_cache: dict[tuple, dict[str, int]] = {}
        rows = [kin.ring.clear_row(row) for row in kin.Q]
        self.dim = model.object_dim
        n = self.dim + self.r
        self.generic_ranks = ranks_of_q(PolyMatrix(rows, n, context=kin.ring.zctx),
                                        dim=self.dim)
        self.generic = self.numbers(self.generic_ranks)
        self.equations = _Equations(model, self.free, self._fixed_values(params))
        self._read_components(locus)
        self._memo: list[dict] = [{} for _ in self.components]
        self.flats = [f for f in (self._flat(eqs) for eqs, empty, _, _ in self.components
                                  if not empty)
                      if f and len(f) < len(self.free)
                      and all(x > 0 for i, x in f.items() if self.free[i].kind == "parameter")]
        self._compiled: dict[tuple, object] = {}

    def _read_fixed(self, model: Model, locus: Locus, at):
        """The locus's fixed values as a configuration and its parameters; sets
        ``fixed_items`` and the first notes."""
        at_text = locus.fixed if at is None else at
        try:
            items = split_assignments(at_text, "fixed") if at_text else []
            fixed_cfg = Configuration.parse(model, dict(items))
        except ConfigurationError as exc:
            raise VerifyError(f"the locus's fixed values: {exc}") from None
        self.fixed_items = [(str(k), str(v)) for k, v in items]
        params = dict(fixed_cfg.parameters)
        self.notes: list[Remark] = []
        if locus.system and locus.system != model.name:
            self.notes.append(Remark.of("verify_other_system", locus_system=locus.system,
                                        model_system=model.name))
        return fixed_cfg, params

    def _read_free(self, model: Model, variables: list[str]) -> None:
        """The free variables (``free``) and the free joints (``joints``)."""
        kinds = {j.name: j.type for j in model.joints}
        self.free: list[_Var] = []
        for name in variables:
            if name.startswith("t_") and kinds.get(name[2:]) == "revolute":
                self.free.append(_Var(name, "revolute", name[2:]))
            elif name in kinds:
                self.free.append(_Var(name, "prismatic", name))
            else:
                self.free.append(_Var(name, "parameter", name))
        self.joints = [v.source for v in self.free if v.kind != "parameter"]

    def _fixed_values(self, params) -> dict[str, object]:
        """The fixed joints and parameters: ``tan(q/2)`` (None for q = pi) or a value."""
        fixed_values: dict[str, object] = {}
        for j, (c, s) in self.config.revolute.items():
            fixed_values[j] = None if c == -1 else _frac(s) / (1 + _frac(c))
        for j, d in self.config.prismatic.items():
            if not d.is_Rational:
                raise VerifyError(f"the locus fixes {j} = {d}: not a number")
            fixed_values[j] = _frac(d)
        for p, value in params.items():
            fixed_values[p] = _frac(value)
        return fixed_values

    def _read_components(self, locus: Locus) -> None:
        """Each component's equations, ``outside`` polynomials and claimed numbers."""
        self.components = []
        self.outside: list[list] = []               # each component's denominators
        self.claims: list[dict[str, int]] = []      # each component's seven numbers
        for i, comp in enumerate(locus.components):
            eqs = []
            empty = False
            if not comp.equations:
                raise VerifyError(f"component {i + 1}: no equations")
            names = list(self.equations.symbols)
            try:
                polys = comp.equation_polynomials(names, f"component {i + 1}, ")
                outside = comp.outside_polynomials_of(names, f"component {i + 1}, ")
            except NumberError as exc:
                raise VerifyError(str(exc)) from None
            for k, poly in enumerate(polys):
                eq = self.equations.polynomial(poly, f"component {i + 1}, equation {k + 1}")
                if eq is None:
                    empty = True
                else:
                    eqs.append(eq)
            outs = []
            for k, poly in enumerate(outside):
                out = self.equations.polynomial(poly, f"component {i + 1}, outside {k + 1}")
                if out is not None:      # undefined at the fixed values: never vanishes
                    outs.append(out)
            self.outside.append(outs)
            missing = [x for x in NUMBER_NAMES if x not in comp.numbers]
            if missing:
                raise VerifyError(f"component {i + 1}: numbers {', '.join(missing)} missing")
            self.claims.append({x: comp.numbers[x] for x in NUMBER_NAMES})
            relevant = sorted({self.equations.role[k][0] for _, used in eqs + outs
                               for k in used})
            self.components.append((eqs, empty, relevant, self.ranks_of(comp.numbers)))

    def _flat(self, eqs) -> dict[int, object] | None:
        """``{free index: value}`` when every equation fixes one variable at a
        rational value (``t_q2 - 1``, ``s_q3``, ``2*q4 + 1``), else None."""
        out: dict[int, object] = {}
        for poly, used in eqs:
            if len(used) != 1 or poly.degrees()[used[0]] != 1:
                return None
            k = used[0]
            terms = poly.to_dict()
            slope = next(c for m, c in terms.items() if m[k] == 1)
            const = next((c for m, c in terms.items() if m[k] == 0), flint.fmpq(0))
            value = -to_fraction(const) / Fraction(int(slope.p),
                                                                       int(slope.q))
            i, role = self.role_of(k)
            if role == "s":
                value = None if value == 0 else 1 / value
            if i in out and out[i] != value:
                return None
            out[i] = value
        return out

    def role_of(self, k: int) -> tuple[int, str]:
        return self.equations.role[k]

    # numbers and ranks
    def numbers(self, ranks: tuple[int, int, int]) -> dict[str, int]:
        hit = self._number_cache.get(ranks)
        if hit is None:
            hit = self._number_cache[ranks] = numbers_from_ranks(
                self.m, self.r, *ranks, dim=self.dim).as_dict()
        return hit

    def ranks_of(self, numbers: Mapping[str, int]) -> tuple[int, int, int]:
        return (self.dim + self.r - numbers["Nm"], self.dim - numbers["Ni"],
                self.r - numbers["Nr"])

    def compiled(self, params: Sequence[Fraction]):
        key = tuple(params)
        hit = self._compiled.get(key)
        if hit is None:
            at = dict(self.fixed_items)
            pvars = [v for v in self.free if v.kind == "parameter"]
            at.update({v.name: str(x) for v, x in zip(pvars, params, strict=True)})
            hit = self._compiled[key] = compile_system(self.model, self.joints, at)
        return hit

    def point_ranks(self, point: Sequence) -> tuple[int, int, int]:
        """Exact ranks of Q, H G^T, H D at a rational point (free values in order)."""
        values, params = [], []
        for v, x in zip(self.free, point, strict=True):
            if v.kind == "revolute":
                values.append(Value.from_tangent(x))
            elif v.kind == "prismatic":
                values.append(Value(str(x), x.numerator, x.denominator))
            else:
                params.append(x)
        return self.compiled(params).ranks(values)

    def at_text(self, point: Sequence) -> dict[str, str]:
        """The point in ``--at`` syntax, fixed values included."""
        given = dict(self.fixed_items)
        for v, x in zip(self.free, point, strict=True):
            given[v.source] = _angle_text(x) if v.kind == "revolute" else str(x)
        order = [j.name for j in self.model.joints] + [p.name for p in self.model.parameters]
        return {k: given[k] for k in order if k in given}

    # membership
    def contains(self, index: int, point: Sequence, ids: Sequence[int] | None = None) -> int:
        """1 when component ``index`` contains the rational ``point``, :data:`BOUNDARY`
        when its equations hold there but one of its ``outside`` polynomials vanishes
        too, else 0 (memoized on the variables its equations use; ``ids``, small
        integers naming the point's values, make the key cheaper on the grid)."""
        eqs, empty, relevant, _ = self.components[index]
        if empty:
            return 0
        key = tuple(ids[i] for i in relevant) if ids is not None else (
            "v", *(point[i] for i in relevant))
        memo = self._memo[index]
        hit = memo.get(key)
        if hit is None:
            hit = memo[key] = (
                0 if not all(self.equations.holds_at(eq, point) for eq in eqs) else
                BOUNDARY if any(self.equations.holds_at(o, point)
                                for o in self.outside[index]) else 1)
        return hit


# --- the checks -------------------------------------------------------------------------
def verify_locus(system, locus: Locus, *, at: str | Mapping | None = None,
                 values: Mapping[str, Sequence] | None = None, max_points: int = 50_000,
                 lines: int = 12, seed: int = 0,
                 timeout: float | None = None) -> Verification:
    """Check ``locus`` against ``system`` exactly, independently of the search.

    Parameters
    ----------
    system
        The :class:`~coopkin_sym.system.System` (or its model) the locus is about.
    locus
        The locus (from :func:`~coopkin_sym.analysis.locus.search.compute_locus`, or read back with
        :func:`~coopkin_sym.present.report.locus_from_json`).
    at
        The values the locus was computed at (``--at`` syntax); default
        ``locus.fixed``. A parameter neither free nor fixed is taken as 1.
    values
        Grid value sets: keys ``"revolute"`` (tangents of half angles, ``"oo"`` for
        q = pi), ``"prismatic"``, ``"parameter"`` (positive), or a variable name
        (``"t_q1"``, ``"q4"``, ``"L"``); defaults :data:`DEFAULT_VALUES`.
    max_points
        Largest grid; beyond it every set is cut to a prefix, longest first.
    lines
        Random rational lines to check.
    seed
        Seed of the lines (the grid is exhaustive).
    timeout
        Wall-clock bound in seconds (see
        :func:`coopkin_sym.exact.bounded.run_bounded`); past it,
        :class:`~coopkin_sym.errors.TimeLimitReached` names the step.

    Returns
    -------
    Verification
        Counts, the uncovered points and the unsound components, exactly.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> generic = {"Nm": 1, "Nc": 1, "Ni": 0, "Nr": 0, "Ng": 0, "Nd": 3, "Nh": 0}
    >>> v = verify_locus(load("paper-case1-soft"),
    ...                  Locus("case 1 soft", ["t_q1", "t_q2"], "L=1", generic), lines=2)
    >>> v.ok, v.grid_points, v.lines
    (False, 100, 2)
    """
    if timeout is not None:
        return run_bounded(lambda: verify_locus(system, locus, at=at, values=values,
                                                max_points=max_points, lines=lines,
                                                seed=seed), timeout, owner="verify")
    started = time.monotonic()
    model: Model = model_of(system).in_base_frame()  # numbers only
    if max_points < 1:
        raise VerifyError(f"max_points: expected a positive number, got {max_points}")
    if lines < 0:
        raise VerifyError(f"lines: expected a number >= 0, got {lines}")
    checker = _Checker(model, locus, at)
    requested = _value_sets(checker.free, values)
    used, reduced = _fit(requested, max_points)
    result = _new_result(checker, locus, used, reduced, max_points, seed)
    state = _State(checker, result)
    _check_generic(checker, state, locus)
    report("the witnesses")
    _check_witnesses(checker, state)
    report("the grid", 0.0)
    _check_grid(checker, state, used)
    rng = random.Random(seed)
    for k in range(lines):
        report(f"the random line {k + 1} of {lines}", (k + 1) / (lines + 1))
        _check_line(checker, state, used, rng, k)
    result.lines = lines
    result.witnesses_checked = len(state.witnessed)
    for i in range(len(locus.components)):
        if i not in state.witnessed and not state.hits[i]:
            result.unchecked.append(i)
    result.seconds = round(time.monotonic() - started, 3)
    return result


def _new_result(checker: _Checker, locus: Locus, used: list[list], reduced: bool,
                max_points: int, seed: int) -> Verification:
    """The result before any check: the locus, the value sets used, the notes."""
    return Verification(
        system=locus.system, variables=list(locus.variables),
        fixed=",".join(f"{k}={v}" for k, v in checker.fixed_items),
        generic=checker.generic,
        values={v.name: [_tan_text(x) if v.kind == "revolute" else str(x) for x in xs]
                for v, xs in zip(checker.free, used, strict=True)},
        reduced=reduced, max_points=max_points, seed=seed,
        components=len(locus.components), notes=list(checker.notes))


def _check_generic(checker: _Checker, state: _State, locus: Locus) -> None:
    """The locus's generic numbers, and no component claiming them."""
    result = state.result
    if {k: locus.generic.get(k) for k in NUMBER_NAMES} != checker.generic:
        result.unsound.append(ComponentIssue(-1, "generic", None, dict(locus.generic),
                                             f"exact generic numbers: {checker.generic}"))
    for i, claim in enumerate(checker.claims):
        if claim == checker.generic:
            state.issue(i, "generic-numbers", None, claim)


class _State:
    def __init__(self, checker: _Checker, result: Verification):
        self.checker = checker
        self.result = result
        self.hits = [0] * len(checker.components)
        self.witnessed: set[int] = set()
        self.seen: set[tuple] = set()
        self.issues: set[tuple] = set()

    def issue(self, index: int, kind: str, point, numbers, detail: str = "") -> None:
        key = (index, kind)
        if key in self.issues:      # one piece of evidence per component and kind
            return
        self.issues.add(key)
        self.result.unsound.append(ComponentIssue(index, kind, point, numbers, detail))

    def judge(self, ranks, numbers, inside: Mapping[int, int], drop: DropPoint) -> bool:
        """Record a decided point (``inside``: the components containing it, each with
        1 or :data:`BOUNDARY`; ``drop`` what to report if it is uncovered). Returns
        whether its numbers are not the generic ones.

        A component is the closure of the set where its equations hold and no
        ``outside`` polynomial vanishes; a point where one vanishes may or may not be
        in that closure. A rank above the component's there proves it is not (ranks
        never rise at a limit point); otherwise it is taken as on the component."""
        checker, result = self.checker, self.result
        covered = False
        for i, how in list(inside.items()):
            claim = checker.components[i][3]
            above = any(a > b for a, b in zip(ranks, claim, strict=True))
            if how == BOUNDARY:
                if above:
                    del inside[i]
                    continue
                result.boundary_points += 1
            self.hits[i] += 1
            if above:
                self.issue(i, "rank-above", drop.point, numbers)
            if checker.claims[i] == numbers:
                covered = True
        if numbers == checker.generic:
            return False
        if not covered:
            key = (drop.kind, tuple(sorted(drop.point.items())),
                   drop.algebraic and drop.algebraic.get("root_of"))
            if key not in self.seen:
                self.seen.add(key)
                result.uncovered_total += 1
                if len(result.uncovered) < MAX_LISTED:
                    drop.numbers = numbers
                    drop.on = list(inside)
                    result.uncovered.append(drop)
        return True


def _value_sets(free: list[_Var], values: Mapping[str, Sequence] | None) -> list[list]:
    values = dict(values or {})
    known = {"revolute", "prismatic", "parameter"} | {v.name for v in free}
    unknown = sorted(set(values) - known)
    if unknown:
        raise VerifyError(f"values: unknown key {', '.join(unknown)} (expected "
                          f"{', '.join(sorted(known))})")
    out = []
    for v in free:
        raw = values.get(v.name, values.get(v.kind, DEFAULT_VALUES[v.kind]))
        where = f"values[{v.name}]"
        if v.kind == "revolute":
            xs = [_tangent(x, where) for x in raw]
        else:
            xs = [_rational(x, where) for x in raw]
            if v.kind == "parameter" and any(x <= 0 for x in xs):
                raise VerifyError(f"{where}: parameters are lengths and must be positive")
        xs = list(dict.fromkeys(xs))
        if not xs:
            raise VerifyError(f"{where}: no values")
        out.append(xs)
    return out


def _fit(sets: list[list], max_points: int) -> tuple[list[list], bool]:
    """Prefixes of the sets whose product fits ``max_points`` (longest cut first)."""
    sets = [list(s) for s in sets]
    reduced = False
    while math.prod(len(s) for s in sets) > max_points:
        longest = max(range(len(sets)), key=lambda i: (len(sets[i]), i))
        sets[longest].pop()
        reduced = True
    return sets, reduced


# witnesses
def _check_witnesses(checker: _Checker, state: _State) -> None:
    for i, comp in enumerate(checker.locus.components):
        witness = comp.witness
        if not witness and comp.algebraic_witness:
            witness = comp.algebraic_witness.get("point")
        if not witness:
            continue
        try:
            point, curve, modulus = _read_witness(checker, witness)
        except _Unreadable as exc:
            state.result.unread_witnesses[i] = str(exc)
            continue
        except _Conflict as exc:
            state.issue(i, "witness-off", {str(k): str(x) for k, x in witness.items()},
                        None, str(exc))
            continue
        state.witnessed.add(i)
        if point is not None:
            at = checker.at_text(point)
            numbers = analyze(checker.model, Configuration.parse(checker.model, at)) \
                .numbers.as_dict()
            inside = checker.contains(i, point)
        else:
            at = {**dict(checker.fixed_items), **{str(k): str(x) for k, x in witness.items()}}
            rows = [[_to_mpoly(p) for p in row] for row in _line_rows(checker, curve)]
            modulus_z = _to_mpoly(modulus * int(modulus.denom()))
            numbers = checker.numbers(_line_ranks(rows, Quotient(modulus_z, 0), checker.r,
                                                  checker.dim))
            inside = _on_curve(checker, i, curve, modulus)
        if not inside:
            state.issue(i, "witness-off", at, numbers)
        if numbers != checker.claims[i]:
            state.issue(i, "witness-numbers", at, numbers)


class _Unreadable(Exception):
    """A witness this check cannot read (a ``CRootOf`` value, say)."""


class _Conflict(Exception):
    """A witness that contradicts the locus's fixed values."""


def _read_witness(checker: _Checker, witness: Mapping):
    """``(point, None, None)`` for a rational witness; ``(None, curve, g)`` for one with
    irrational algebraic values: every free variable a polynomial in ``alpha``, a
    primitive element of their field with minimal polynomial ``g``."""

    model = checker.model
    fixed = dict(checker.fixed_items)
    given = {str(k): str(x) for k, x in witness.items()}
    free_names = {v.source for v in checker.free}
    for k, x in given.items():
        if k in free_names:
            continue
        if k not in fixed:
            raise _Unreadable(f"{k} is neither free nor fixed in the locus")
        try:
            same = (Configuration.parse(model, {k: x}) == Configuration.parse(model, {k: fixed[k]}))
        except ConfigurationError as exc:
            raise _Unreadable(str(exc)) from None
        if not same:
            raise _Conflict(f"the witness sets {k}={x}, the locus fixes {k}={fixed[k]}")
    symbols = {p.name: p for p in model.parameters}
    values: list = []
    irrational: dict[int, sp.Expr] = {}
    for i, v in enumerate(checker.free):
        text = given.get(v.source)
        where = f"witness {v.source}"
        if text is None:
            if v.kind == "parameter":
                raise _Unreadable(f"no value for {v.source}")
            values.append(Fraction(0))
            continue
        try:
            if v.kind == "revolute":
                try:
                    c, s_ = parse_angle(text, where)
                    values.append(None if c == -1 else _frac(s_) / (1 + _frac(c)))
                except NumberError:
                    irrational[i] = algebraic_half_angle(text, where)
                    values.append(None)
                continue
            try:
                x = parse_number(text, symbols, where)
                x = x.subs({symbols[n]: sp.Rational(given.get(n, fixed.get(n, "0")))
                            for n in map(str, x.free_symbols) if n in symbols})
            except NumberError:
                x = parse_expression(text, {}, where)
                sp.minimal_polynomial(x, sp.Symbol("t"))
            if x.free_symbols or x.is_real is False:
                raise _Unreadable(f"{where}: {text} is not a real number")
            if x.is_Rational:
                values.append(_frac(x))
            else:
                irrational[i] = sp.radsimp(x)
                values.append(None)
        except (NumberError, ValueError, TypeError, NotImplementedError,
                sp.polys.polyerrors.NotAlgebraic) as exc:
            raise _Unreadable(str(exc)) from None
    if not irrational:
        return values, None, None
    alpha = sp.Symbol("alpha")
    order = list(irrational)
    minimal, _, reps = primitive_element([irrational[i] for i in order], alpha, ex=True)
    g = flint.fmpq_poly([_fmpq(c) for c in reversed(sp.Poly(minimal, alpha).all_coeffs())])
    rep = {i: flint.fmpq_poly([_fmpq(c) for c in reversed(list(r))])
           for i, r in zip(order, reps, strict=True)}
    coords = []
    for i, (v, x) in enumerate(zip(checker.free, values, strict=True)):
        chart = "t" if v.kind == "revolute" else "x"
        if i in rep:
            coords.append((chart, rep[i]))
        elif v.kind == "revolute" and x is None:
            coords.append(("s", flint.fmpq_poly([0])))
        else:
            coords.append((chart, flint.fmpq_poly([_fmpq(x)])))
    return None, _Line(coords, (None, None)), g


def _on_curve(checker: _Checker, index: int, curve: _Line,
              modulus: flint.fmpq_poly | None) -> int:
    """Whether component ``index`` contains the point of ``curve`` at a root of the
    irreducible ``modulus`` (``None``: its generic point): 1, :data:`BOUNDARY` or 0
    as in :meth:`_Checker.contains`."""
    eqs, empty, _, _ = checker.components[index]
    if empty:
        return 0
    for eq in eqs:
        poly, dens = checker.equations.on_line(eq, curve)
        if modulus is None:
            if not poly.is_zero() or any(d.is_zero() for d in dens):
                return False
        elif not (poly % modulus).is_zero() or any((d % modulus).is_zero() for d in dens):
            return False
    for out in checker.outside[index]:
        poly, dens = checker.equations.on_line(out, curve)
        if modulus is None:
            if poly.is_zero() and not any(d.is_zero() for d in dens):
                return BOUNDARY
        elif (poly % modulus).is_zero() and not any((d % modulus).is_zero() for d in dens):
            return BOUNDARY
    return 1


def _frac(x) -> Fraction:
    x = sp.Rational(x)
    return to_fraction(x)


# the grid
def _check_grid(checker: _Checker, state: _State, sets: list[list]) -> None:
    free = checker.free
    pidx = [i for i, v in enumerate(free) if v.kind == "parameter"]
    jidx = [i for i, v in enumerate(free) if v.kind != "parameter"]
    result = state.result
    ncomp = len(checker.components)
    for pvals in itertools.product(*[sets[i] for i in pidx]):
        compiled = checker.compiled(pvals)
        jvalues = []
        for i in jidx:
            v = free[i]
            if v.kind == "revolute":
                jvalues.append([(k, x, Value.from_tangent(x)) for k, x in enumerate(sets[i])])
            else:
                jvalues.append([(k, x, Value(str(x), x.numerator, x.denominator))
                                for k, x in enumerate(sets[i])])
        point = [None] * len(free)
        ids = [0] * len(free)
        for i, x in zip(pidx, pvals, strict=True):
            point[i] = x
            ids[i] = sets[i].index(x)
        for combo in itertools.product(*jvalues):
            for i, (k, x, _) in zip(jidx, combo, strict=True):
                point[i] = x
                ids[i] = k
            ranks = compiled.ranks([val for _, _, val in combo])
            result.grid_points += 1
            inside = {c: m for c in range(ncomp) if (m := checker.contains(c, point, ids))}
            if ranks == checker.generic_ranks and not inside:
                continue
            numbers = checker.numbers(ranks)
            if state.judge(ranks, numbers, inside,
                           DropPoint("grid", checker.at_text(point), numbers)):
                result.grid_drops += 1


# lines
def _random_rational(rng: random.Random, nonzero: bool = False, positive: bool = False):
    while True:
        num = rng.randint(1 if positive else -6, 6)
        if num or not nonzero:
            return Fraction(num, rng.randint(1, 4))


def _make_line(checker: _Checker, sets: list[list], rng: random.Random, k: int) -> _Line:
    """Line ``k``, in turn: a general line; one holding some variables at grid values;
    one inside a component that fixes variables at rational values (to look for drops
    inside it; else like the previous kind); one holding some revolute joints at
    q = pi (the ends of families in the other chart)."""
    free = checker.free
    n = len(free)
    held: dict[int, object] = {}
    revolute = [i for i, v in enumerate(free) if v.kind == "revolute"]
    kind = k % 4
    if kind == 2 and checker.flats and n > 1:
        held = dict(checker.flats[(k // 4) % len(checker.flats)])
    elif kind == 3 and revolute and n > 1:
        for i in rng.sample(revolute, rng.randint(1, min(len(revolute), n - 1))):
            held[i] = None
    elif kind and n > 1:
        for i in rng.sample(range(n), rng.randint(1, n - 1)):
            held[i] = rng.choice(sets[i])
    coords = []
    lo: Fraction | None = None
    hi: Fraction | None = None
    for i, v in enumerate(free):
        if i in held:
            x = held[i]
            if v.kind == "revolute" and x is None:
                coords.append(("s", flint.fmpq_poly([0])))
            else:
                coords.append(("t" if v.kind == "revolute" else "x",
                               flint.fmpq_poly([_fmpq(x)])))
            continue
        chart = rng.choice("ts") if v.kind == "revolute" else "x"
        a = _random_rational(rng, positive=v.kind == "parameter")
        b = _random_rational(rng, nonzero=True)
        coords.append((chart, flint.fmpq_poly([_fmpq(a), _fmpq(b)])))
        if v.kind == "parameter":           # a + b lam > 0
            edge = -a / b
            if b > 0:
                lo = edge if lo is None else max(lo, edge)
            else:
                hi = edge if hi is None else min(hi, edge)
    return _Line(coords, (lo, hi))


def _line_rows(checker: _Checker, line: _Line) -> list[list[flint.fmpq_poly]]:
    """The rows of Q on the line, each times ``prod (1 + t_j^2)^k`` (no real zero), as
    polynomials in ``lam`` with integer coefficients."""
    kin = checker.kin
    ring = kin.ring
    den_index = {name: k for k, name in enumerate(ring.den_names)}
    coords = line.coords
    one = flint.fmpq_poly([1])
    weights = []
    for (_, c), v in zip(coords, checker.free, strict=True):
        weights.append(one + c * c if v.kind == "revolute" else one)
    powers: dict[tuple[int, int], flint.fmpq_poly] = {}

    def power(i: int, e: int) -> flint.fmpq_poly:
        key = (i, e)
        if key not in powers:
            powers[key] = coords[i][1] ** e if e else one
        return powers[key]

    wpowers: dict[tuple[int, int], flint.fmpq_poly] = {}

    def wpower(i: int, e: int) -> flint.fmpq_poly:
        key = (i, e)
        if key not in wpowers:
            wpowers[key] = weights[i] ** e if e else one
        return wpowers[key]

    var_den = [den_index.get(name) for name in ring.names]
    out = []
    for row in kin.Q:
        top = [max(es) for es in zip(*(f.den for f in row), strict=True)] if ring.den_names \
            else []
        new_row = []
        for f in row:
            if f.num.is_zero():
                new_row.append(flint.fmpq_poly([0]))
                continue
            acc = flint.fmpq_poly([0])
            for monom, coef in f.num.to_dict().items():
                term = flint.fmpq_poly([coef])
                for i, e in enumerate(monom):
                    d = var_den[i]
                    if d is not None and coords[i][0] == "s":
                        top_e = 2 * f.den[d]
                        if e > top_e:  # pragma: no cover - entries of Q are bounded
                            raise AssertionError("an entry of Q unbounded at q = pi")
                        term *= power(i, top_e - e)
                    elif e:
                        term *= power(i, e)
                acc += term
            for i, d in enumerate(var_den):
                if d is not None and top[d] - f.den[d]:
                    acc *= wpower(i, top[d] - f.den[d])
            new_row.append(acc)
        denominators = [int(p.denom()) for p in new_row if not p.is_zero()]
        scale = math.lcm(*denominators) if denominators else 1
        out.append([p * scale for p in new_row])
    return out


_LAM = flint.fmpz_mpoly_ctx.get(("lam",), "degrevlex")


def _to_mpoly(p: flint.fmpq_poly) -> flint.fmpz_mpoly:
    coeffs = p.coeffs()
    return _LAM.from_dict({(i,): int(c.p) for i, c in enumerate(coeffs) if c != 0})


def _from_mpoly(p: flint.fmpz_mpoly) -> flint.fmpq_poly:
    d = p.to_dict()
    top = max((m[0] for m in d), default=0)
    coeffs = [0] * (top + 1)
    for m, c in d.items():
        coeffs[m[0]] = int(c)
    return flint.fmpq_poly(coeffs)


def _drop_polynomial(rows: list[list[flint.fmpz_mpoly]], ncols: int, rank: int,
                     rng: random.Random) -> flint.fmpz_mpoly | None:
    """A multiple of the gcd of the ``rank`` x ``rank`` minors: the gcd of two random
    combinations ``det(A M B)`` (Cauchy-Binet). None when the rank is 0."""
    if rank == 0:
        return None
    m = len(rows)
    zero = _LAM.constant(0)
    g = zero
    tries = 0
    while tries < 8:
        tries += 1
        a = [[rng.randint(-50, 50) for _ in range(m)] for _ in range(rank)]
        b = [[rng.randint(-50, 50) for _ in range(rank)] for _ in range(ncols)]
        am = []
        for arow in a:
            acc = [zero] * ncols
            for coef, row in zip(arow, rows, strict=True):
                if coef:
                    acc = [x + coef * y for x, y in zip(acc, row, strict=True)]
            am.append(acc)
        amb = [[sum((row[j] * b[j][c] for j in range(ncols) if b[j][c]), zero)
                for c in range(rank)] for row in am]
        det = PolyMatrix(amb, len(amb)).det()
        if det.is_zero():
            continue
        g = det if g.is_zero() else g.gcd(det)
        if tries >= 2 and not g.is_zero():
            break
        if g.is_constant():
            break
    if g.is_zero():   # pragma: no cover - a rank-`rank` matrix has a nonzero minor
        raise AssertionError("no nonzero combination of minors found")
    return g


def _line_ranks(rows, quotient: Quotient | None, r: int,
                dim: int) -> tuple[int, int, int]:
    n = dim + r
    if not rows:
        return (0, 0, 0)
    return ranks_of_q(PolyMatrix(rows, n, quotient or POLYNOMIALS), dim=dim)


def _real_roots_in(f: flint.fmpq_poly, domain) -> list[tuple[Fraction, Fraction]]:
    """Isolating intervals (rational ends) of the real roots of the irreducible ``f``
    (degree >= 2) inside the open interval ``domain``."""
    x = sp.Symbol("lam")
    poly = sp.Poly([sp.Rational(int(c.p), int(c.q)) for c in reversed(f.coeffs())], x)
    lo, hi = domain
    kwargs = {}
    if lo is not None:
        kwargs["inf"] = to_sympy(lo)
    if hi is not None:
        kwargs["sup"] = to_sympy(hi)
    out = []
    for (a, b), _ in poly.intervals(**kwargs):
        out.append((Fraction(int(sp.Rational(a).p), int(sp.Rational(a).q)),
                    Fraction(int(sp.Rational(b).p), int(sp.Rational(b).q))))
    return out


def _approximate(checker: _Checker, line: _Line, f: flint.fmpq_poly,
                 interval: tuple[Fraction, Fraction]) -> dict[str, str]:
    """Approximate coordinates of the root in ``interval`` (for reading only)."""
    x = sp.Symbol("lam")
    poly = sp.Poly([sp.Rational(int(c.p), int(c.q)) for c in reversed(f.coeffs())], x)
    a, b = poly.refine_root(sp.Rational(interval[0].numerator, interval[0].denominator),
                            sp.Rational(interval[1].numerator, interval[1].denominator),
                            eps=sp.Rational(1, 10**15))
    mid = (Fraction(int(sp.Rational(a).p), int(sp.Rational(a).q))
           + Fraction(int(sp.Rational(b).p), int(sp.Rational(b).q))) / 2
    out = {}
    for v, value in zip(checker.free, line.point(mid), strict=True):
        if v.kind == "revolute":
            angle = math.pi if value is None else 2 * math.atan(float(value))  # float-ok
            out[v.source] = f"{angle:.12g}"                                     # float-ok
        else:
            out[v.source] = f"{float(value):.12g}"                              # float-ok
    for k, x_ in checker.fixed_items:
        out.setdefault(k, x_)
    return out


def _check_line(checker: _Checker, state: _State, sets: list[list], rng: random.Random,
                k: int) -> None:
    line = _make_line(checker, sets, rng, k)
    source = f"line {k + 1}"
    rows_q = _line_rows(checker, line)
    rows = [[_to_mpoly(p) for p in row] for row in rows_q]
    r = checker.r
    dim = checker.dim
    ranks = _line_ranks(rows, None, r, dim)
    numbers = checker.numbers(ranks)
    result = state.result
    text = line.text(checker.free)
    # the generic point of the line
    inside = {c: m for c in range(len(checker.components))
              if (m := _on_curve(checker, c, line, None))}
    if numbers != checker.generic:
        result.singular_lines += 1
    state.judge(ranks, numbers, inside, DropPoint(source, dict(text), numbers, "line"))
    # candidate points: drops of the three ranks, zeros of the chart variables
    factors: list[flint.fmpz_mpoly] = []
    n = dim + r
    pieces = [(rows, n, ranks[0]), ([x[:dim] for x in rows], dim, ranks[1])]
    if r:
        pieces.append(([x[dim:] for x in rows], r, ranks[2]))
    for mat, ncols, rank in pieces:
        g = _drop_polynomial(mat, ncols, rank, rng) if mat else None
        if g is not None and not g.is_constant():
            factors += [f for f, _ in factor(g)[1]]
    for (_, c), v in zip(line.coords, checker.free, strict=True):
        if v.kind == "revolute" and c.degree() == 1:
            factors.append(_to_mpoly(c * int(c.denom())))
    distinct: dict[str, flint.fmpz_mpoly] = {}
    for f in factors:
        f = _primitive_positive(f)
        distinct.setdefault(str(f), f)
    for f in sorted(distinct.values(), key=lambda p: (p.total_degree(), str(p))):
        fq = _from_mpoly(f)
        if fq.degree() == 1:
            c0, c1 = fq.coeffs()
            lam = -to_fraction(c0) / to_fraction(c1)
            lo, hi = line.domain
            if (lo is not None and lam <= lo) or (hi is not None and lam >= hi):
                continue
            point = line.point(lam)
            result.line_points += 1
            pranks = checker.point_ranks(point)
            pnumbers = checker.numbers(pranks)
            inside = {c: m for c in range(len(checker.components))
                      if (m := checker.contains(c, point))}
            if state.judge(pranks, pnumbers, inside,
                           DropPoint(source, checker.at_text(point), pnumbers)):
                result.line_drops += 1
            continue
        roots = _real_roots_in(fq, line.domain)
        if not roots:
            continue
        result.line_points += 1
        quotient = Quotient(f, 0)
        pranks = _line_ranks(rows, quotient, r, checker.dim)
        pnumbers = checker.numbers(pranks)
        inside = {c: m for c in range(len(checker.components))
                  if (m := _on_curve(checker, c, line, fq))}
        if pnumbers == checker.generic and not inside:
            continue
        point = _approximate(checker, line, fq, roots[0])
        algebraic = {"line": text, "root_of": _poly_text(fq),
                     "interval": [str(roots[0][0]), str(roots[0][1])]}
        if state.judge(pranks, pnumbers, inside,
                       DropPoint(source, point, pnumbers, "root", algebraic)):
            result.line_drops += 1


def _primitive_positive(f: flint.fmpz_mpoly) -> flint.fmpz_mpoly:
    coeffs = [int(c) for c in f.to_dict().values()]
    g = math.gcd(*coeffs) or 1
    f = f / g if g != 1 else f
    top = max(f.to_dict().items(), key=lambda t: t[0])
    return -f if int(top[1]) < 0 else f

