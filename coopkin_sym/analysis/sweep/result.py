"""The numbers at every point of a sweep, with their exact values, as rows, CSV and
JSON (see :mod:`coopkin_sym.analysis.sweep`).
"""

from __future__ import annotations

import io
import json
from dataclasses import dataclass

import numpy as np

from coopkin_sym.analysis.numbers import NUMBER_NAMES, Numbers, numbers_line
from coopkin_sym.analysis.renderers import Displayable, clip
from coopkin_sym.analysis.sweep.values import Value


@dataclass
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

    def __len__(self) -> int:
        return int(self.numbers.shape[0])

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
        parts = [f"{j}={t}" for j, t in self.point(i).items()]
        return ",".join(parts + ([self.at] if self.at else []))

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
        """Everything but the points, as plain data."""
        return {
            "system": self.system, "joints": list(self.joints), "at": self.at,
            "columns": list(self.joints) + list(NUMBER_NAMES) + ["exact_recheck"],
            "generic": self.generic.as_dict(),
            "method": (f"ranks modulo p = {self.prime} certify a point when they equal the "
                       "generic ranks (a rank modulo p never exceeds the rank over Q); "
                       "every other point is rechecked exactly over Q"),
            "prime": self.prime, "counts": self.summary(),
            "snapping": {"bound_rad": self.bound, "note": self._snap_note(),
                         "snapped": self.snapped},
        }

    def to_json(self) -> dict:
        """``{"header": {...}, "points": [{"q1": "pi/2", ..., "Nm": 2, ...}, ...]}``."""
        return {"header": self.header(), "points": self.rows()}

    def json_text(self) -> str:
        """:meth:`to_json` as text: the header indented, one line per point."""
        points = ",\n".join("  " + json.dumps(row) for row in self.rows())
        header = json.dumps(self.header(), indent=2).replace("\n", "\n  ")
        return f'{{\n  "header": {header},\n  "points": [\n{points}\n  ]\n}}\n'

    def to_csv(self) -> str:
        """CSV with ``#`` comment lines first (system, fixed values, generic numbers,
        counts, snapping), then ``q1,...,Nm,...,Nh,exact_recheck`` rows."""
        h = self.header()
        out = io.StringIO()
        out.write(f"# system: {self.system}\n")
        out.write(f"# fixed: {self.at or 'home, parameters symbolic'}\n")
        out.write("# generic numbers (swept joints symbolic): "
                  + " ".join(f"{k}={v}" for k, v in h["generic"].items()) + "\n")
        c = h["counts"]
        out.write(f"# points: {c['points']}; certified modulo p = {self.prime}: "
                  f"{c['certified_mod_p']}; rechecked exactly over Q: "
                  f"{c['rechecked_exact']}\n")
        out.write(f"# snapped: {self._snap_note()}\n")
        out.write(",".join(h["columns"]) + "\n")
        texts = [[v.text for v in vs] for vs in self.levels]
        for idx, nums, re in zip(self.index.tolist(), self.numbers.tolist(),
                                 self.rechecked.tolist(), strict=True):
            cells = [texts[k][i] for k, i in enumerate(idx)] + [str(x) for x in nums]
            cells.append("true" if re else "false")
            out.write(",".join(cells) + "\n")
        return out.getvalue()
