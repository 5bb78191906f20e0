"""Grids of exact points to sweep: ``q1=-pi/2..pi/2:5`` and point lists, parsed by the
package's one parser (see :mod:`coopkin_sym.analysis.sweep`).
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np
import sympy as sp

from coopkin_sym import limits
from coopkin_sym.analysis.sweep.values import SNAP_BOUND, Value, _pi_text, _tangent_of
from coopkin_sym.errors import SweepError
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.parse import NumberError, brief, parse_expression
from coopkin_sym.exact.rationals import to_fraction, to_sympy
from coopkin_sym.model.configuration import (
    ConfigurationError,
    split_assignments,
    top_level_parts,
)
from coopkin_sym.model.model import Model, model_of


def _split_point(point) -> list[tuple[str, object]]:
    try:
        return split_assignments(point, f"point {brief(point)}")
    except ConfigurationError as exc:
        raise SweepError(str(exc)) from None


# --- grids ----------------------------------------------------------------------------
@dataclass(frozen=True)
class Grid:
    """The exact points of a grid: every combination of the values of each joint
    (the last joint varies fastest).

    Attributes
    ----------
    joints
        The swept joints, in grid order.
    levels
        For each joint, its exact :class:`Value` list.
    bound
        The largest ``|dq|`` allowed to a snapped angle (radians).

    Example
    -------
    >>> from coopkin_sym import load
    >>> g = grid(load("paper-case1-hard"), "q1=-pi/2..pi/2:3,q2=0..0:1")
    >>> g.joints, len(g), [v.text for v in g.levels[0]]
    (('q1', 'q2'), 3, ['-pi/2', '0', 'pi/2'])
    """

    joints: tuple[str, ...]
    levels: tuple[tuple[Value, ...], ...]
    bound: float  # float-ok

    def __len__(self) -> int:
        return math.prod(len(v) for v in self.levels)

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(v) for v in self.levels)

    def index(self) -> np.ndarray:
        """``(points, joints)`` indices into :attr:`levels`, in grid order."""
        if not self.levels:
            return np.zeros((1, 0), dtype=np.int64)
        mesh = np.meshgrid(*[np.arange(len(v)) for v in self.levels], indexing="ij")
        return np.stack([g.ravel() for g in mesh], axis=1).astype(np.int64)

    def __iter__(self):
        for row in self.index():
            yield {j: self.levels[k][i].text for k, (j, i) in
                   enumerate(zip(self.joints, row, strict=True))}

    @property
    def snapped(self) -> list[dict]:
        """The snapped angles: joint, requested angle, exact angle used, ``|dq|``."""
        return [{"joint": j, "requested": v.requested, "used": v.text, "error_rad": v.error}
                for j, vs in zip(self.joints, self.levels, strict=True) for v in vs
                if v.snapped]


_INTEGER = re.compile(r"[+-]?[0-9]+")

def parse_grid(text: str) -> dict[str, tuple[str, str, int]]:
    """Read ``"q1=-pi..pi:181,q2=0..1/2:11"`` into ``{joint: (lo, hi, count)}``.

    Example
    -------
    >>> parse_grid("q1=-pi..pi:181, d4=0..1/2:3")
    {'q1': ('-pi', 'pi', 181), 'd4': ('0', '1/2', 3)}
    """
    axes: dict[str, tuple[str, str, int]] = {}
    for part in top_level_parts(text):
        part = part.strip()
        if not part:
            continue
        shape = f"--grid {brief(part)}: expected NAME=LO..HI:COUNT (e.g. q1=-pi..pi:181)"
        if "=" not in part:
            raise SweepError(shape)
        name, spec = (s.strip() for s in part.split("=", 1))
        if ".." not in spec or ":" not in spec:
            raise SweepError(shape)
        rng, _, count = spec.rpartition(":")
        lo, _, hi = rng.partition("..")
        if not name or not lo.strip() or not hi.strip():
            raise SweepError(shape)
        if len(count.strip()) > 12 and count.strip().isdigit():
            raise SweepError(f"--grid {brief(part)}: the count is over the limit of "
                             f"{limits.MAX_GRID_COUNT:,} points per joint")
        digits = count.strip()
        if len(digits) > 12 or not _INTEGER.fullmatch(digits):
            raise SweepError(f"--grid {brief(part)}: the count {brief(digits)} is not an "
                             f"integer")
        n = int(digits)
        if name in axes:
            raise SweepError(f"--grid: {name} given more than once")
        axes[name] = (lo.strip(), hi.strip(), n)
    if not axes:
        raise SweepError("--grid: no joint given (expected NAME=LO..HI:COUNT,...)")
    return axes


def grid(system: Model | Any, axes: str | Mapping[str, tuple], *,
         bound: float = SNAP_BOUND) -> Grid:  # float-ok: the snapping bound
    """The exact points of a grid over some joints.

    Parameters
    ----------
    system
        The system (or its model).
    axes
        ``{joint: (lo, hi, count)}`` (ends as exact text, e.g. ``("-pi", "pi", 181)``)
        or the text ``"q1=-pi..pi:181,q2=..."``; ``count`` evenly spaced values from
        ``lo`` to ``hi`` inclusive (``count = 1``: ``lo`` alone).
    bound
        A revolute value whose ``tan(q/2)`` is irrational is replaced by an angle whose
        ``tan(q/2)`` is a rational with a small denominator, within ``|dq| <= bound``
        radians, and listed in :attr:`Grid.snapped`. Prismatic values must be rational.

    Example
    -------
    >>> from coopkin_sym import load
    >>> g = grid(load("paper-case1-hard"), {"q1": ("-pi", "pi", 5), "q2": ("0", "0", 1)})
    >>> [v.text for v in g.levels[0]], len(g)
    (['-pi', '-pi/2', '0', 'pi/2', 'pi'], 5)
    >>> g2 = grid(load("paper-case1-hard"), "q1=0..pi/3:2")
    >>> g2.levels[0][1].text, g2.snapped[0]["requested"]
    ('2*atan(29681/51409)', 'pi/3')
    """
    model = model_of(system)
    spec = parse_grid(axes) if isinstance(axes, str) else dict(axes)
    kinds = {j.name: j.type for j in model.joints}
    params = {p.name for p in model.parameters}
    joints, levels = [], []
    for name, axis in spec.items():
        where = f"--grid {name}"
        if name not in kinds:
            what = (f"{name} is a parameter, not a joint (set it with --at)" if name in params
                    else f"unknown joint {brief(name)} (joints: {', '.join(model.joint_names)})")
            raise SweepError(f"{where}: {what}")
        try:
            lo, hi, count = axis
        except (TypeError, ValueError):
            raise SweepError(f"{where}: expected (lo, hi, count)") from None
        if isinstance(count, bool) or not isinstance(count, int | np.integer):
            raise SweepError(f"{where}: the count must be an integer, got {brief(count)}")
        if count < 1:
            raise SweepError(f"{where}: zero points (the count must be at least 1, "
                             f"got {count})")
        if count > limits.MAX_GRID_COUNT:
            raise SweepError(f"{where}: {count:,} points is over the limit of "
                             f"{limits.MAX_GRID_COUNT:,} per joint")
        total = math.prod(len(v) for v in levels) * int(count)
        if total > limits.MAX_GRID_POINTS:
            raise SweepError(f"{where}: the grid would have {total:,} points, over the "
                             f"limit of {limits.MAX_GRID_POINTS:,}")
        try:
            ends = [parse_expression(str(x), {}, where, max_length=limits.MAX_NUMBER_TEXT,
                                     kind="parameters") for x in (lo, hi)]
        except NumberError as exc:
            raise SweepError(str(exc)) from None
        if kinds[name] == "revolute":
            if any(abs(e) > limits.MAX_ANGLE_RADIANS for e in ends):
                raise SweepError(f"{where}: an end beyond {limits.MAX_ANGLE_RADIANS:,} "
                                 "radians (use an angle in [-pi, pi])")
            levels.append(tuple(_angle_levels(ends[0], ends[1], int(count), bound, where)))
        else:
            if not all(e.is_Rational for e in ends):
                raise SweepError(f"{where}: a prismatic range must have rational ends "
                                 f"(got {lo}..{hi})")
            a, b = (to_fraction(e) for e in ends)
            step = (b - a) / (count - 1) if count > 1 else Fraction(0)
            vals = [a + step * k for k in range(int(count))]
            levels.append(tuple(Value(str(v), v.numerator, v.denominator) for v in vals))
        joints.append(name)
    return Grid(tuple(joints), tuple(levels), bound)


def _angle_levels(lo: sp.Expr, hi: sp.Expr, count: int, bound: float,  # float-ok
                  where: str):
    steps = [Fraction(k, count - 1) if count > 1 else Fraction(0) for k in range(count)]
    rlo, rhi = lo / sp.pi, hi / sp.pi
    if rlo.is_Rational and rhi.is_Rational:          # multiples of pi: decided by Niven
        a, b = to_fraction(rlo), to_fraction(rhi)
        for s in steps:
            ratio = a + (b - a) * s
            text = _pi_text(ratio)
            t = _tangent_of(ratio)
            if t is not False:
                v = Value.from_tangent(t)
                yield Value(text, v.num, v.den)
            else:
                yield _snapped(text, float(ratio) * math.pi, bound)  # float-ok
        return
    for s in steps:
        q = lo + (hi - lo) * to_sympy(s)
        text = sp.sstr(q)
        if q.is_Rational:                             # tan(x) is irrational at x != 0
            if q == 0:
                yield Value("0", 0, 1)
            else:
                yield _snapped(text, float(q), bound)  # float-ok
            continue
        try:
            angle = ExactAngle.parse(q, where)
        except NumberError:
            yield _snapped(text, float(sp.N(q, 30)), bound)  # float-ok
            continue
        yield Value(text, angle.num, angle.den)


def _snapped(requested: str, q: float, bound: float) -> Value:  # float-ok
    try:
        angle, err = ExactAngle.snap(q, bound)
    except ValueError as exc:  # pragma: no cover - the simplest rational within the bound exists
        raise SweepError(str(exc)) from None
    exact = Value.from_tangent(angle.tangent)
    return Value(exact.text, exact.num, exact.den, requested, err)
