"""The grid of a locus verification: the value sets of the free variables (cut to fit
a number of points) and the check of every point of their product.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping, Sequence
from fractions import Fraction

from coopkin_sym.analysis.locus.verify_checker import _Checker, _State
from coopkin_sym.analysis.locus.verify_exact import Tan, _Var
from coopkin_sym.analysis.locus.verify_results import DropPoint
from coopkin_sym.analysis.sweep import Value
from coopkin_sym.errors import VerifyError

#: Default value sets, in order of preference (a smaller set is a prefix): tangents of
#: half angles for revolute joints ("oo" is q = pi), displacements, positive parameters.
DEFAULT_VALUES: dict[str, tuple[str, ...]] = {
    "revolute": ("0", "oo", "1", "-1", "2", "-2", "1/2", "-1/2", "3", "-1/3"),
    "prismatic": ("0", "1", "-1", "2", "-2", "1/2", "-1/2", "3"),
    "parameter": ("1", "2", "1/2", "3", "1/3"),
}

_INFINITE = {"oo", "inf", "infinity", "pi"}


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
