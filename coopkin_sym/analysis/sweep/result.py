"""The numbers at every point of a sweep, with their exact values, as rows, a plain CSV
with its metadata file, JSON, a pandas DataFrame and Parquet (see
:mod:`coopkin_sym.analysis.sweep` and ``docs/sweep-files.md``).
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
from collections.abc import Mapping
from dataclasses import dataclass, fields
from fractions import Fraction
from pathlib import Path

import numpy as np

from coopkin_sym.analysis.numbers import NUMBER_NAMES, Numbers, numbers_line
from coopkin_sym.analysis.renderers import Displayable, clip
from coopkin_sym.analysis.sweep.saved import sweep_from_file, sweep_from_tree
from coopkin_sym.analysis.sweep.saved_csv import metadata_path, sweep_from_csv_file
from coopkin_sym.analysis.sweep.values import Value
from coopkin_sym.errors import MissingDependency, SweepError
from coopkin_sym.model.configuration import assignments_text


@dataclass(eq=False)
class SweepResult(Displayable):
    """The exact numbers at every point of a sweep.

    Attributes
    ----------
    system
        The system's name.
    joints
        The swept joints (columns of the points).
    at
        The other joints and the parameters, in ``--at`` syntax.
    generic
        The numbers with the swept joints symbolic.
    levels, index
        The exact values of each joint and, per point, which one it takes.
    numbers
        ``(points, 7)`` integers, columns ``Nm, Nc, Ni, Nr, Ng, Nd, Nh``.
    rechecked
        ``(points,)``: the modular pass could not certify the point (a candidate
        singular point), so its numbers were computed exactly over Q; every other
        point was certified by its ranks modulo :attr:`prime`.
    bound
        The snapping bound of the grid (radians), ``None`` for explicit points.
    kinds
        ``"revolute"`` or ``"prismatic"`` for each swept joint (revolute when not
        given): the float column next to each exact one is ``<joint>_rad`` (the angle
        in radians) or ``<joint>_float`` (the displacement).

    Example
    -------
    >>> from coopkin_sym import load
    >>> res = load("paper-case1-hard").sweep(["q1=pi/2,q2=pi/2", "q1=0"])
    >>> res.joints, res.numbers[:, 0].tolist(), res.rows()[0]["Nm"]
    (('q1', 'q2'), [3, 2], 3)
    >>> print(repr(res).replace("; ", ";\\n"))
    <SweepResult paper case 1, hard/hard over q1, q2: 2 points, 1 not generic;
    1 certified modulo p, 1 rechecked exactly;
    generic Nm=2 Nc=2 Ni=1 Nr=0 Ng=1 Nd=4 Nh=0>

    Written as JSON and read back, it is the same result:

    >>> SweepResult.from_json(res.json_text()) == res
    True
    """

    system: str
    joints: tuple[str, ...]
    at: str
    generic: Numbers
    levels: tuple[tuple[Value, ...], ...]
    index: np.ndarray
    numbers: np.ndarray
    rechecked: np.ndarray
    prime: int
    bound: float | None = None  # float-ok
    kinds: tuple[str, ...] = ()

    def __len__(self) -> int:
        return int(self.numbers.shape[0])

    def __eq__(self, other: object) -> bool:
        """The same points (each with the same exact values, requested angles included),
        numbers and header; the order of the value tables does not matter."""
        if not isinstance(other, SweepResult):
            return NotImplemented
        plain = [f.name for f in fields(self)
                 if f.name not in ("levels", "index", "numbers", "rechecked", "kinds")]
        return (all(getattr(self, n) == getattr(other, n) for n in plain)
                and [self._kind(k) for k in range(len(self.joints))]
                == [other._kind(k) for k in range(len(other.joints))]
                and np.array_equal(self.numbers, other.numbers)
                and np.array_equal(self.rechecked, other.rechecked)
                and self._point_values() == other._point_values())

    __hash__ = None  # type: ignore[assignment]  # mutable arrays

    def _point_values(self) -> list[tuple[Value, ...]]:
        return [tuple(self.levels[k][i] for k, i in enumerate(idx))
                for idx in self.index.tolist()]

    def __repr__(self) -> str:
        at = f" at {clip(self.at, 60)}" if self.at else ""
        c = self.summary()
        return (f"<SweepResult {clip(self.system, 80)} over {clip(', '.join(self.joints), 50)}"
                f"{at}: {c['points']} points, {self.not_generic()} not generic; "
                f"{c['certified_mod_p']} certified modulo p, {c['rechecked_exact']} rechecked "
                f"exactly; generic {numbers_line(self.generic)}>")

    def not_generic(self) -> int:
        """How many points have numbers other than the generic ones.

        Example
        -------
        >>> from coopkin_sym import load
        >>> load("paper-case1-hard").sweep(["q1=pi/2,q2=pi/2", "q1=0"]).not_generic()
        1
        """
        generic = np.array([getattr(self.generic, k) for k in NUMBER_NAMES])
        return int((self.numbers != generic).any(axis=1).sum()) if len(self) else 0

    @property
    def certified(self) -> np.ndarray:
        """Points certified by the modular pass (the complement of :attr:`rechecked`)."""
        return ~self.rechecked

    @property
    def snapped(self) -> list[dict]:
        """Snapped grid angles: joint, requested angle, exact angle used, ``|dq|``."""
        return [{"joint": j, "requested": v.requested, "used": v.text, "error_rad": v.error}
                for j, vs in zip(self.joints, self.levels, strict=True) for v in vs
                if v.snapped]

    def point(self, i: int) -> dict[str, str]:
        """The exact values (``--at`` syntax) of the swept joints at point ``i``."""
        return {j: self.levels[k][self.index[i, k]].text for k, j in enumerate(self.joints)}

    def at_text(self, i: int) -> str:
        """Point ``i`` with the fixed values, for :meth:`System.analyze`."""
        return ",".join([assignments_text(self.point(i))] + ([self.at] if self.at else []))

    def numbers_at(self, i: int) -> Numbers:
        return Numbers(*(int(x) for x in self.numbers[i]))

    def rows(self) -> list[dict]:
        """One dict per point: joint texts, the seven numbers, ``exact_recheck``."""
        texts = [[v.text for v in vs] for vs in self.levels]
        out = []
        for idx, nums, re in zip(self.index.tolist(), self.numbers.tolist(),
                                 self.rechecked.tolist(), strict=True):
            row = {j: texts[k][idx[k]] for k, j in enumerate(self.joints)}
            row.update(zip(NUMBER_NAMES, nums, strict=True))
            row["exact_recheck"] = re
            out.append(row)
        return out

    def _kind(self, k: int) -> str:
        return self.kinds[k] if k < len(self.kinds) else "revolute"

    def float_columns(self) -> dict[str, str]:
        """The float column next to each swept joint's exact one, with its meaning.

        Example
        -------
        >>> from coopkin_sym import load
        >>> load("paper-case1-hard").sweep(["q1=pi/2"]).float_columns()
        {'q1_rad': 'q1 in radians, a float (the exact value is in column q1)'}
        """
        out = {}
        for k, j in enumerate(self.joints):
            if self._kind(k) == "prismatic":
                out[f"{j}_float"] = f"{j} as a float (the exact value is in column {j})"
            else:
                out[f"{j}_rad"] = f"{j} in radians, a float (the exact value is in column {j})"
        return out

    def _floats(self) -> list[list[float]]:  # float-ok: labelled extra columns
        """The float value of every level of every joint (never used in a decision)."""
        out = []
        for k, vs in enumerate(self.levels):
            prismatic = self._kind(k) == "prismatic"
            out.append([_float_of(v, prismatic) for v in vs])
        return out

    def csv_columns(self) -> list[str]:
        """The CSV's columns: each swept joint (exact text) followed by its float
        column, the seven numbers, ``exact_recheck``.

        Example
        -------
        >>> from coopkin_sym import load
        >>> load("paper-case1-hard").sweep(["q1=pi/2,q2=0"]).csv_columns()[:4]
        ['q1', 'q1_rad', 'q2', 'q2_rad']
        """
        cols: list[str] = []
        for j, f in zip(self.joints, self.float_columns(), strict=True):
            cols += [j, f]
        return cols + list(NUMBER_NAMES) + ["exact_recheck"]

    def to_pandas(self):
        """The points as a :class:`pandas.DataFrame` with the columns of the CSV
        (:meth:`csv_columns`): exact joint values as text, their floats, the seven
        numbers as integers, ``exact_recheck`` as booleans; ``attrs["header"]`` holds
        :meth:`header`. Needs pandas (``pip install pandas``).

        Example
        -------
        >>> from coopkin_sym import load
        >>> res = load("paper-case1-hard").sweep(["q1=pi/2,q2=pi/2", "q1=0"])
        >>> df = res.to_pandas()  # doctest: +SKIP
        >>> df["Nm"].tolist(), str(df["Nm"].dtype)  # doctest: +SKIP
        ([3, 2], 'int64')
        """
        try:
            import pandas as pd
        except ImportError:
            raise MissingDependency("SweepResult.to_pandas needs pandas: pip install pandas") \
                from None
        floats = self._floats()
        data: dict[str, object] = {}
        names = list(self.float_columns())
        for k, j in enumerate(self.joints):
            texts = [v.text for v in self.levels[k]]
            data[j] = [texts[i] for i in self.index[:, k].tolist()]
            data[names[k]] = np.array(floats[k], dtype=np.float64)[self.index[:, k]]
        for k, name in enumerate(NUMBER_NAMES):
            data[name] = self.numbers[:, k].astype(np.int64)
        data["exact_recheck"] = self.rechecked.astype(bool)
        frame = pd.DataFrame(data, columns=self.csv_columns())
        frame.attrs["header"] = self.header()
        return frame

    def summary(self) -> dict[str, int]:
        """How many points: in all, certified modulo p, rechecked exactly, snapped."""
        return {"points": len(self), "certified_mod_p": int(self.certified.sum()),
                "rechecked_exact": int(self.rechecked.sum()),
                "snapped_values": len(self.snapped)}

    def _snap_note(self) -> str:
        snaps = self.snapped
        if not snaps:
            return "none: every angle is exact as requested"
        worst = max(s["error_rad"] for s in snaps)  # float-ok: reported
        return (f"{len(snaps)} grid angles with an irrational tan(q/2) were replaced by a "
                f"nearby angle with a rational tan(q/2), |dq| <= {self.bound:g} rad "
                f"(largest {worst:.3g} rad); the angles written are the exact ones used")

    def header(self) -> dict:
        """Everything but the points, as plain data, for the table (the CSV and its
        metadata file, :meth:`to_pandas`, Parquet): ``columns`` are those of the table
        (:meth:`csv_columns`) and ``float_columns`` gives the meaning of each float
        column. The JSON's header (:meth:`to_json`) has the same entries but for
        those: its ``columns`` are the keys of its points and ``kinds`` gives each
        swept joint's kind.

        Example
        -------
        >>> from coopkin_sym import load
        >>> h = load("paper-case1-hard").sweep(["q1=pi/2"]).header()
        >>> h["columns"][:3], h["float_columns"]["q1_rad"][:13]
        (['q1', 'q1_rad', 'Nm'], 'q1 in radians')
        """
        return {
            "system": self.system, "joints": list(self.joints), "at": self.at,
            "columns": self.csv_columns(), "float_columns": self.float_columns(),
            **self._rest_of_header(),
        }

    def _json_header(self) -> dict:
        """The JSON's header: the columns of its points and the kind of each joint."""
        return {
            "system": self.system, "joints": list(self.joints), "at": self.at,
            "columns": list(self.joints) + list(NUMBER_NAMES) + ["exact_recheck"],
            "kinds": {j: self._kind(k) for k, j in enumerate(self.joints)},
            **self._rest_of_header(),
        }

    def _rest_of_header(self) -> dict:
        return {
            "generic": self.generic.as_dict(),
            "method": (f"ranks modulo p = {self.prime} certify a point when they equal the "
                       "generic ranks (a rank modulo p never exceeds the rank over Q); "
                       "every other point is rechecked exactly over Q"),
            "prime": self.prime, "counts": self.summary(),
            "snapping": {"bound_rad": self.bound, "note": self._snap_note(),
                         "snapped": self.snapped},
        }

    def to_json(self) -> dict:
        """``{"header": {...}, "points": [{"q1": "pi/2", ..., "Nm": 2, ...}, ...]}``:
        exact values only; every column the header names is a key of every point
        (schema: ``docs/sweep.schema.json``)."""
        return {"header": self._json_header(), "points": self.rows()}

    @classmethod
    def from_json(cls, data: Mapping | str) -> SweepResult:
        """The result written by :meth:`to_json` (a tree) or :meth:`json_text` (text),
        read back: every entry checked, every exact value read by the package's parser.

        Raises
        ------
        SweepError
            One line naming the first bad entry (``points[2].q1: ...``).

        Example
        -------
        >>> SweepResult.from_json('{"header": {}, "points": []}')  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        coopkin_sym.errors.SweepError: not a sweep result: header.system: missing
        """
        return sweep_from_tree(data, cls)

    @classmethod
    def read(cls, path: str | os.PathLike) -> SweepResult:
        """The result in a file written by :meth:`write` (or ``coopkin sweep -o
        FILE``): JSON, read as :meth:`from_json` does, or a ``.csv`` table with its
        metadata file ``<name>.csv.json`` next to it; a ``.csv`` that starts with
        ``#`` lines (the form of earlier versions, metadata in the comments) is read
        too, without the snapped angles' requested values, which it does not hold.

        Raises
        ------
        SweepError
            One line naming the file and the first bad entry.

        Example
        -------
        >>> SweepResult.read("/")
        Traceback (most recent call last):
        ...
        coopkin_sym.errors.SweepError: /: is a directory, not a file
        """
        suffix = Path(path).suffix.lower()
        if suffix == ".csv":
            return sweep_from_csv_file(path, cls)
        if suffix == ".parquet":
            raise SweepError(f"{os.fspath(path)}: a Parquet table is read with "
                             "pandas.read_parquet (SweepResult.read reads the .csv and "
                             "the .json forms)")
        return sweep_from_file(path, cls)

    @staticmethod
    def metadata_path(path: str | os.PathLike) -> Path:
        """Where :meth:`write` puts the metadata of the CSV ``path``.

        Example
        -------
        >>> str(SweepResult.metadata_path("out/map.csv"))
        'out/map.csv.json'
        """
        return metadata_path(path)

    @staticmethod
    def check_parquet() -> None:
        """Nothing when a sweep can be written as Parquet (pandas and pyarrow are
        installed), else the :class:`~coopkin_sym.errors.MissingDependency` naming what
        to install; checked before a long sweep starts."""
        need_parquet()

    def files(self, path: str | os.PathLike) -> dict[Path, bytes]:
        """What :meth:`write` writes for ``path``, by its suffix: ``.csv`` the table
        (:meth:`to_csv`) and its metadata ``<name>.csv.json``
        (:meth:`csv_metadata`); ``.parquet`` the table as Parquet (needs pandas and
        pyarrow); any other suffix the JSON (:meth:`json_text`).

        Example
        -------
        >>> from coopkin_sym import load
        >>> res = load("paper-case1-hard").sweep(["q1=pi/2,q2=pi/2"])
        >>> [str(p) for p in res.files("map.csv")]
        ['map.csv', 'map.csv.json']
        """
        target = Path(path)
        suffix = target.suffix.lower()
        if suffix == ".csv":
            metadata = json.dumps(self.csv_metadata(), indent=2) + "\n"
            return {target: self.to_csv().encode(),
                    metadata_path(target): metadata.encode()}
        if suffix == ".parquet":
            return {target: self.parquet_bytes()}
        return {target: self.json_text().encode()}

    def write(self, path: str | os.PathLike) -> None:
        """Write the result to ``path`` as :meth:`files` says (read it back with
        :meth:`read`).

        Example
        -------
        >>> import tempfile, pathlib
        >>> from coopkin_sym import load
        >>> res = load("paper-case1-hard").sweep(["q1=pi/2,q2=pi/2"])
        >>> folder = pathlib.Path(tempfile.mkdtemp())
        >>> res.write(folder / "sweep.json")
        >>> SweepResult.read(folder / "sweep.json") == res
        True
        >>> res.write(folder / "sweep.csv")
        >>> sorted(p.name for p in folder.iterdir())
        ['sweep.csv', 'sweep.csv.json', 'sweep.json']
        >>> SweepResult.read(folder / "sweep.csv") == res
        True
        """
        for target, data in self.files(path).items():
            with open(target, "wb") as out:
                out.write(data)

    def json_text(self) -> str:
        """:meth:`to_json` as text: the header indented, one line per point."""
        points = ",\n".join("  " + json.dumps(row) for row in self.rows())
        header = json.dumps(self._json_header(), indent=2).replace("\n", "\n  ")
        return f'{{\n  "header": {header},\n  "points": [\n{points}\n  ]\n}}\n'

    def csv_metadata(self) -> dict:
        """The metadata of the CSV (:meth:`to_csv`), written next to it as
        ``<name>.csv.json``: ``{"header": ...}`` with :meth:`header` (schema:
        ``docs/sweep-csv.schema.json``)."""
        return {"header": self.header()}

    def to_csv(self) -> str:
        """A plain CSV (``pandas.read_csv`` reads it with no option): one line of
        column names ``q1,q1_rad,...,Nm,...,Nh,exact_recheck``, then one line per
        point: each swept joint's exact value (``2*atan(-15411/269)``) followed by
        the same value as a float (``q1_rad``, radians; ``d1_float`` for a prismatic
        joint), for plotting and pandas (:meth:`to_pandas`); the numbers are
        integers, ``exact_recheck`` is ``true`` or ``false``. What the table is (system,
        fixed values, generic numbers, counts, snapping) is in :meth:`csv_metadata`.

        Example
        -------
        >>> from coopkin_sym import load
        >>> print(load("paper-case1-hard").sweep(["q1=pi/2,q2=pi"]).to_csv(), end="")
        q1,q1_rad,q2,q2_rad,Nm,Nc,Ni,Nr,Ng,Nd,Nh,exact_recheck
        pi/2,1.5707963267948966,pi,3.141592653589793,2,2,1,0,1,4,0,false
        """
        out = io.StringIO()
        table = csv.writer(out, lineterminator="\n")
        table.writerow(self.csv_columns())
        texts = [[v.text for v in vs] for vs in self.levels]
        floats = [[repr(x) for x in fs] for fs in self._floats()]
        for idx, nums, re in zip(self.index.tolist(), self.numbers.tolist(),
                                 self.rechecked.tolist(), strict=True):
            cells = [c for k, i in enumerate(idx) for c in (texts[k][i], floats[k][i])]
            cells += [str(x) for x in nums]
            cells.append("true" if re else "false")
            table.writerow(cells)
        return out.getvalue()

    def parquet_bytes(self) -> bytes:
        """The table of :meth:`to_pandas` as Parquet (``header`` kept in the file's
        pandas metadata, ``pandas.read_parquet(...).attrs["header"]``). Needs pandas
        and pyarrow (``pip install pandas pyarrow``).

        Example
        -------
        >>> import io
        >>> from coopkin_sym import load
        >>> res = load("paper-case1-hard").sweep(["q1=pi/2,q2=pi"])
        >>> import pandas  # doctest: +SKIP
        >>> pandas.read_parquet(io.BytesIO(res.parquet_bytes()))["Nm"].tolist()  # doctest: +SKIP
        [2]
        """
        need_parquet()
        out = io.BytesIO()
        self.to_pandas().to_parquet(out, engine="pyarrow", index=False)
        return out.getvalue()


def need_parquet() -> None:
    """Nothing when pandas and pyarrow are installed (a sweep can be written as
    Parquet), else the :class:`~coopkin_sym.errors.MissingDependency` saying what to
    install.

    Example
    -------
    >>> need_parquet()  # doctest: +SKIP
    """
    try:
        import pandas  # noqa: F401
        import pyarrow  # noqa: F401
    except ImportError:
        raise MissingDependency("writing a sweep as .parquet needs pandas and pyarrow: "
                                "pip install pandas pyarrow") from None


def _float_of(value: Value, prismatic: bool) -> float:  # float-ok: a labelled extra column
    """The float of an exact swept value: a displacement, or the angle
    ``2 atan(num/den)`` in radians (``pi`` for ``(1, 0)``, ``-pi`` when written so)."""
    if prismatic:
        return float(Fraction(value.num, value.den))  # float-ok
    if value.den == 0:  # q = pi, written "-pi" when asked for as such
        return -math.pi if value.text.startswith("-") else math.pi  # float-ok
    return 2 * math.atan(Fraction(value.num, value.den))  # float-ok
