"""A sweep's table read back: the plain CSV of :meth:`SweepResult.to_csv` with its
metadata file ``<name>.csv.json`` (:meth:`SweepResult.csv_metadata`, schema
``docs/sweep-csv.schema.json``), or the CSV of earlier versions, whose metadata is in
``#`` lines before the table.

The table is untrusted input as a JSON result is (see
:mod:`coopkin_sym.analysis.saved`): the file is read within the budgets, the column
line must be the one the metadata names, every exact value and every number is read
by the package's parser, and the first problem is one
:class:`~coopkin_sym.errors.SweepError` naming the file, the line and the column.
The float columns are checked to be numbers and otherwise ignored: the exact columns
are the values. The commented form does not list the snapped angles' requested values
(nor, when nothing was snapped, the grid's bound): a result read from it has none.

Example
-------
>>> import tempfile, pathlib
>>> from coopkin_sym import load
>>> from coopkin_sym.analysis.sweep import SweepResult
>>> path = pathlib.Path(tempfile.mkdtemp()) / "old.csv"
>>> _ = path.write_text("# system: s\\n# fixed: L=1\\nq1,q1_rad\\n")
>>> sweep_from_csv_file(path, SweepResult)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
coopkin_sym.errors.SweepError: not a sweep result: .../old.csv: line 3: expected \
'# generic numbers (swept joints symbolic): Nm=... Nc=... Ni=... Nr=... Ng=... Nd=... Nh=...'
"""

from __future__ import annotations

import csv
import os
import re
from fractions import Fraction
from pathlib import Path

from coopkin_sym import limits
from coopkin_sym.analysis.numbers import NUMBER_NAMES
from coopkin_sym.analysis.saved import Entries
from coopkin_sym.analysis.sweep.saved import Head, build, read_header
from coopkin_sym.errors import NumberError, SweepError, TreeError
from coopkin_sym.exact.parse import brief, parse_number
from coopkin_sym.model.input_files import read_input_text

_COMMENTS = (
    ("system", "# system: <name>", r"# system: (.*)"),
    ("fixed", "# fixed: <values>", r"# fixed: (.*)"),
    ("generic", "# generic numbers (swept joints symbolic): "
                + " ".join(f"{n}=..." for n in NUMBER_NAMES),
     r"# generic numbers \(swept joints symbolic\): "
     + " ".join(rf"{n}=(\d{{1,6}})" for n in NUMBER_NAMES)),
    ("points", "# points: N; certified modulo p = P: N; rechecked exactly over Q: N",
     r"# points: (\d{1,9}); certified modulo p = (\d{1,12}): (\d{1,9}); "
     r"rechecked exactly over Q: (\d{1,9})"),
    ("snapped", "# snapped: <note>", r"# snapped: (.*)"),
)
_HOME = "home, parameters symbolic"
_BOUND = re.compile(r"\|dq\| <= ([0-9.e+-]{1,30}) rad")
_BOOLEANS = {"true": True, "false": False, "True": True, "False": False}


def metadata_path(path: str | os.PathLike) -> Path:
    """The metadata file of the CSV ``path``: ``<name>.csv.json`` next to it.

    Example
    -------
    >>> str(metadata_path("out/map.csv"))
    'out/map.csv.json'
    """
    return Path(os.fspath(path) + ".json")


def sweep_from_csv_file(path: str | os.PathLike, make: type):
    """The sweep result (a ``make``: :class:`~.result.SweepResult`) in the CSV file
    ``path``: with its metadata file (:func:`metadata_path`), or in the commented form
    of earlier versions (see the module)."""
    shown = os.fspath(path)
    e = Entries(SweepError, f"not a sweep result: {shown}")
    try:
        text = read_input_text(path)
    except TreeError as exc:
        raise SweepError(f"{shown}: {exc}") from None
    lines = text.removeprefix("\ufeff").splitlines()
    if lines and lines[0].startswith("#"):
        head, first = _commented_head(e, lines)
    else:
        head, first = _metadata_head(shown, path), 0
    return _table(e, head, lines, first, make)


def _metadata_head(shown: str, path: str | os.PathLike) -> Head:
    """The header in the metadata file next to the CSV."""
    meta = metadata_path(path)
    if not os.path.lexists(meta):
        raise SweepError(f"{shown}: no metadata file {os.fspath(meta)} next to it (written "
                         "with the table by SweepResult.write and coopkin sweep -o FILE.csv; "
                         "a table on standard output has none: use --json or -o)")
    m = Entries(SweepError, f"not a sweep result: {os.fspath(meta)}")
    tree = m.file(meta)
    m.keys(tree, ("header",), "")
    return read_header(m, tree["header"], table=True)


def _table(e: Entries, head: Head, lines: list[str], first: int, make: type):
    """The result of the table whose column line is ``lines[first]``."""
    columns = head.table_columns()
    rows = csv.reader(lines[first:])
    if next(rows, None) != columns:
        raise e.fail(f"line {first + 1}", f"expected the columns {','.join(columns)}")
    roles = _roles(head)
    points: list[dict] = []
    numbered: list[int] = []
    cache: dict[tuple[str, str], object] = {}
    for n, cells in enumerate(rows, start=first + 2):
        if not cells:
            continue
        if len(points) >= limits.MAX_GRID_POINTS:
            raise e.fail(f"line {n}", f"more than {limits.MAX_GRID_POINTS:,} points")
        if len(cells) != len(columns):
            raise e.fail(f"line {n}", f"expected {len(columns)} cells, got {len(cells)}")
        row = {}
        for name, role, cell in zip(columns, roles, cells, strict=True):
            value = cache.get((role, cell))
            if value is None:
                value = cache[role, cell] = _cell(e, role, cell, f"line {n}, column {name}")
            if role != "float":
                row[name] = value
        points.append(row)
        numbered.append(n)
    return build(e, head, points, lambda i, key: f"line {numbered[i]}, column {key}", make)


def _roles(head: Head) -> list[str]:
    """What each column of the table holds: ``exact``, ``float``, ``count``, ``flag``."""
    return ["exact", "float"] * len(head.joints) + ["count"] * len(NUMBER_NAMES) + ["flag"]


def _cell(e: Entries, role: str, cell: str, where: str) -> object:
    """One cell, read: an exact text as it is (the builder reads it), a float checked
    to be a number, a count as an integer, a flag as a boolean."""
    if role == "exact":
        return cell
    if role == "flag":
        if cell not in _BOOLEANS:
            raise e.fail(where, f"expected true or false, got {brief(cell)}")
        return _BOOLEANS[cell]
    try:
        number = parse_number(cell, {}, where)
    except NumberError as exc:
        raise e.fail("", str(exc)) from None
    if role == "float":
        return True
    if number.q != 1 or number.p < 0:
        raise e.fail(where, f"expected a count (an integer, 0 or more), got {brief(cell)}")
    return int(number.p)


def _commented_head(e: Entries, lines: list[str]) -> tuple[Head, int]:
    """The header of the commented form, from its ``#`` lines, and the position of its
    column line."""
    found: dict[str, tuple[str, ...]] = {}
    for k, (key, shape, pattern) in enumerate(_COMMENTS):
        match = re.fullmatch(pattern, lines[k]) if k < len(lines) else None
        if match is None:
            raise e.fail(f"line {k + 1}", f"expected {shape!r}")
        found[key] = match.groups()
    first = len(_COMMENTS)
    meanings: dict[str, str] = {}
    while first < len(lines) and lines[first].startswith("#"):
        match = re.fullmatch(r"# (\S{1,200}): (.*)", lines[first])
        if match is None:
            raise e.fail(f"line {first + 1}", "expected '# <float column>: <meaning>'")
        meanings[match[1]] = match[2]
        first += 1
    columns = next(csv.reader(lines[first:first + 1]), [])
    swept = columns[:max(0, len(columns) - len(NUMBER_NAMES) - 1)]
    if list(meanings) != swept[1::2]:
        raise e.fail(f"line {len(_COMMENTS) + 1}", "expected one '# <float column>: "
                                                   f"<meaning>' line per float column "
                                                   f"of line {first + 1}")
    count = [_number(e, x, "line 4") for x in found["points"]]
    note = found["snapped"][0]
    bound = _BOUND.search(note)
    tree = {"system": found["system"][0], "joints": swept[0::2],
            "at": "" if found["fixed"][0] == _HOME else found["fixed"][0],
            "columns": columns, "float_columns": meanings,
            "generic": {n: _number(e, x, "line 3")
                        for n, x in zip(NUMBER_NAMES, found["generic"], strict=True)},
            "method": "", "prime": count[1],
            "counts": {"points": count[0], "certified_mod_p": count[2],
                       "rechecked_exact": count[3], "snapped_values": 0},
            "snapping": {"bound_rad": None if bound is None else _bound(e, bound[1]),
                         "note": note, "snapped": []}}
    return read_header(e, tree, table=True), first


def _number(e: Entries, digits: str, where: str) -> int:
    return int(_cell(e, "count", digits, where))  # type: ignore[call-overload]


def _bound(e: Entries, text: str) -> float:  # float-ok: the reported snapping bound
    try:
        number = parse_number(text, {}, "line 5")
    except NumberError as exc:
        raise e.fail("", str(exc)) from None
    return float(Fraction(int(number.p), int(number.q)))  # float-ok


__all__ = ["metadata_path", "sweep_from_csv_file"]
