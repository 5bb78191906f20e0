"""What the checks of a locus verification share: the model at the locus's fixed
values, exact ranks and numbers at a point, membership in each component (at a rational
point, or on a line at a root of a polynomial), and the judgement of a decided point.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from fractions import Fraction

import flint
import sympy as sp

from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.analysis.locus.verify_exact import _angle_text, _Equations, _frac, _Line, _Var
from coopkin_sym.analysis.locus.verify_results import (
    MAX_LISTED,
    ComponentIssue,
    DropPoint,
    Verification,
)
from coopkin_sym.analysis.numbers import NUMBER_NAMES, numbers_from_ranks, ranks_of_q
from coopkin_sym.analysis.sweep import Value, compile_system
from coopkin_sym.errors import VerifyError
from coopkin_sym.exact.matrix import PolyMatrix
from coopkin_sym.exact.parse import (
    NumberError,
)
from coopkin_sym.exact.rationals import to_fraction
from coopkin_sym.model.configuration import (
    Configuration,
    ConfigurationError,
    split_assignments,
)
from coopkin_sym.model.model import Model

#: Membership of a point where a component's equations hold and one of its ``outside``
#: polynomials vanishes too (it may lie in the component's closure, or not).
BOUNDARY = 2


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
        for j, angle in self.config.revolute.items():
            fixed_values[j] = angle.tangent
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
