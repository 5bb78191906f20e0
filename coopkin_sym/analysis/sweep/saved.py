"""A sweep result read back from its JSON (:meth:`SweepResult.to_json`), checked entry
by entry (see :mod:`coopkin_sym.analysis.saved`; the schema is
``docs/sweep.schema.json``).

Example
-------
>>> from coopkin_sym import load
>>> from coopkin_sym.analysis.sweep import SweepResult
>>> res = load("paper-case1-hard").sweep(["q1=pi/2,q2=2*atan(1/3)"])
>>> sweep_from_tree(res.to_json(), SweepResult).point(0)
{'q1': 'pi/2', 'q2': '2*atan(1/3)'}
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from coopkin_sym import limits
from coopkin_sym.analysis.numbers import NUMBER_NAMES, Numbers
from coopkin_sym.analysis.saved import Entries
from coopkin_sym.analysis.sweep.values import Value
from coopkin_sym.errors import NumberError, SweepError
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.parse import brief, parse_number

_COMMON = ("system", "joints", "at", "columns", "generic", "method", "prime", "counts",
           "snapping")
_SNAPPED = ("joint", "requested", "used", "error_rad")
_KINDS = ("revolute", "prismatic")


@dataclass(frozen=True)
class Head:
    """A sweep's header, read: what the points are checked against.

    Example
    -------
    >>> from coopkin_sym import load
    >>> data = load("paper-case1-hard").sweep(["q1=pi/2"]).to_json()
    >>> head = read_header(Entries(SweepError, "not a sweep result"), data["header"],
    ...                    table=False)
    >>> head.columns[:2], head.table_columns()[:3]
    (['q1', 'Nm'], ['q1', 'q1_rad', 'Nm'])
    """

    tree: Mapping
    system: str
    joints: tuple[str, ...]
    at: str
    kinds: tuple[str, ...]
    generic: Numbers
    prime: int
    bound: float | None  # float-ok: the grid's snapping bound
    snapped: dict

    @property
    def columns(self) -> list[str]:
        """The keys of every point: the joints, the seven numbers, ``exact_recheck``."""
        return [*self.joints, *NUMBER_NAMES, "exact_recheck"]

    def table_columns(self) -> list[str]:
        """The columns of the table (CSV): each joint followed by its float column."""
        cols: list[str] = []
        for j, kind in zip(self.joints, self.kinds, strict=True):
            cols += [j, f"{j}_rad" if kind == "revolute" else f"{j}_float"]
        return [*cols, *NUMBER_NAMES, "exact_recheck"]


def sweep_from_file(path: str | os.PathLike, make: type):
    """The sweep result (a ``make``: :class:`~.result.SweepResult`) in the JSON file
    ``path`` (see :func:`sweep_from_tree`)."""
    entries = Entries(SweepError, "not a sweep result")
    return _read(entries, entries.file(path), make)


def sweep_from_tree(data: Mapping | str, make: type):
    """The sweep result (a ``make``: :class:`~.result.SweepResult`) of JSON text or of
    its tree; a bad entry is one :class:`~coopkin_sym.errors.SweepError` naming it."""
    entries = Entries(SweepError, "not a sweep result")
    return _read(entries, entries.tree(data), make)


def _read(e: Entries, tree: Mapping, make: type):
    e.keys(tree, ("header", "points"), "")
    head = read_header(e, tree["header"], table=False)
    points = e.field(tree, "points", list, "")
    if len(points) > limits.MAX_GRID_POINTS:
        raise e.fail("points", f"more than {limits.MAX_GRID_POINTS:,} points")
    for i, row in enumerate(points):
        e.keys(row, head.columns, f"points[{i}]")
    return build(e, head, points, lambda i, key: f"points[{i}].{key}", make)


def read_header(e: Entries, tree: object, *, table: bool) -> Head:
    """The header of a sweep's JSON (``table=False``: its columns are the points'
    keys, with ``kinds``, or ``float_columns`` as files of earlier versions have it)
    or of its table's metadata (``table=True``: the columns of the CSV, with
    ``float_columns``)."""
    optional = () if table else ("kinds", "float_columns")
    h = e.keys(tree, (*_COMMON, "float_columns") if table else _COMMON, "header", optional)
    system, at = e.field(h, "system", str, "header"), e.field(h, "at", str, "header")
    joints = tuple(e.texts(h, "joints", "header"))
    if len(set(joints)) != len(joints):
        raise e.fail("header.joints", "a joint is named twice")
    if "kinds" in h and "float_columns" in h:
        raise e.fail("header.float_columns", "not with kinds (a header has one of them)")
    if "float_columns" in h:
        kinds = _kinds(e, h, joints)
    elif "kinds" in h:
        kinds = _named_kinds(e, h, joints)
    else:
        raise e.fail("header.kinds", "missing")
    generic = _numbers(e, e.keys(h["generic"], NUMBER_NAMES, "header.generic"),
                       "header.generic")
    e.field(h, "method", str, "header")
    prime = e.field(h, "prime", int, "header")
    if not 2 <= prime < 2**31:
        raise e.fail("header.prime", f"expected a prime below 2**31, got {prime}")
    bound, snapped = _snapping(e, h, joints)
    head = Head(h, system, joints, at, kinds, generic, prime, bound, snapped)
    columns = head.table_columns() if table else head.columns
    if e.texts(h, "columns", "header") != columns:
        raise e.fail("header.columns", f"expected {', '.join(columns)}")
    return head


def build(e: Entries, head: Head, points: Sequence[Mapping], name, make: type):
    """The result of the points (each a mapping with the keys :attr:`Head.columns`,
    checked); ``name(i, key)`` names an entry in an error."""
    joints = head.joints
    levels: list[list[Value]] = [[] for _ in joints]
    where_of: list[dict[str, int]] = [{} for _ in joints]
    index = np.zeros((len(points), len(joints)), dtype=np.int64)
    numbers = np.zeros((len(points), len(NUMBER_NAMES)), dtype=np.int64)
    rechecked = np.zeros(len(points), dtype=bool)
    for i, row in enumerate(points):
        for k, j in enumerate(joints):
            text = e.value(row[j], str, name(i, j))
            pos = where_of[k].get(text)
            if pos is None:
                value = _value(e, text, head.kinds[k], head.snapped.get((j, text)),
                               name(i, j))
                pos = where_of[k][text] = len(levels[k])
                levels[k].append(value)
            index[i, k] = pos
        numbers[i] = [_count(e, row[n], name(i, n)) for n in NUMBER_NAMES]
        rechecked[i] = e.value(row["exact_recheck"], bool, name(i, "exact_recheck"))
    result = make(head.system, joints, head.at, head.generic,
                  tuple(tuple(v) for v in levels), index, numbers, rechecked, head.prime,
                  head.bound, head.kinds)
    _check_counts(e, head.tree, result)
    return result


def _named_kinds(e: Entries, h: Mapping, joints: tuple[str, ...]) -> tuple[str, ...]:
    """Each joint's kind, from ``kinds``: ``{joint: "revolute" | "prismatic"}``."""
    kinds = e.keys(h["kinds"], joints, "header.kinds")
    out = []
    for j in joints:
        kind = e.field(kinds, j, str, "header.kinds")
        if kind not in _KINDS:
            raise e.fail(f"header.kinds.{j}", f"expected revolute or prismatic, got "
                                              f"{brief(kind)}")
        out.append(kind)
    return tuple(out)


def _kinds(e: Entries, h: Mapping, joints: tuple[str, ...]) -> tuple[str, ...]:
    """Each joint's kind, from the name of its float column."""
    columns = e.field(h, "float_columns", dict, "header")
    names = list(columns)
    if len(names) != len(joints):
        raise e.fail("header.float_columns", "expected one float column per joint")
    kinds = []
    for j, name in zip(joints, names, strict=True):
        e.value(columns[name], str, f"header.float_columns.{name}")
        if name == f"{j}_rad":
            kinds.append("revolute")
        elif name == f"{j}_float":
            kinds.append("prismatic")
        else:
            raise e.fail(f"header.float_columns.{name}", f"expected {j}_rad or {j}_float")
    return tuple(kinds)


def _snapping(e: Entries, h: Mapping, joints: tuple[str, ...]):
    """The grid's snapping bound and, per (joint, exact text), the angle asked for
    and its distance."""
    s = e.keys(h["snapping"], ("bound_rad", "note", "snapped"), "header.snapping")
    bound = e.field(s, "bound_rad", float, "header.snapping", none=True)
    e.field(s, "note", str, "header.snapping")
    out: dict[tuple[str, str], tuple[str, float]] = {}  # float-ok: distances shown
    for k, item in enumerate(e.field(s, "snapped", list, "header.snapping")):
        where = f"header.snapping.snapped[{k}]"
        e.keys(item, _SNAPPED, where)
        joint = e.field(item, "joint", str, where)
        if joint not in joints:
            raise e.fail(f"{where}.joint", f"not a swept joint: {joint!r}")
        key = (joint, e.field(item, "used", str, where))
        out.setdefault(key, (e.field(item, "requested", str, where),
                             float(e.field(item, "error_rad", float, where))))  # float-ok
    return None if bound is None else float(bound), out  # float-ok: the grid's bound


def _value(e: Entries, text: str, kind: str, snap, where: str) -> Value:
    """One exact swept value, read by the package's parser."""
    try:
        if kind == "prismatic":
            number = parse_number(text, {}, where)
            exact = Fraction(int(number.p), int(number.q))
            num, den = exact.numerator, exact.denominator
        else:
            angle = ExactAngle.parse(text, where)
            num, den = angle.num, angle.den
    except NumberError as exc:
        raise e.fail("", str(exc)) from None
    requested, error = snap if snap is not None else (None, None)
    return Value(text, num, den, requested, error)


def _count(e: Entries, value: object, where: str) -> int:
    n = e.value(value, int, where)
    if n < 0:
        raise e.fail(where, f"expected a count (0 or more), got {n}")
    return n


def _numbers(e: Entries, tree: Mapping, where: str) -> Numbers:
    return Numbers(*(_count(e, tree[n], f"{where}.{n}") for n in NUMBER_NAMES))


def _check_counts(e: Entries, h: Mapping, result) -> None:
    """The header's counts are those of the points read."""
    counts = e.keys(h["counts"], tuple(result.summary()), "header.counts")
    for key, value in result.summary().items():
        if e.field(counts, key, int, "header.counts") != value:
            raise e.fail(f"header.counts.{key}", f"{counts[key]} does not match the "
                                                 f"points ({value})")


__all__ = ["Head", "build", "read_header", "sweep_from_file", "sweep_from_tree"]
