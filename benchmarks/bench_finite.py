"""Finite mobility at the witnesses of the shipped loci (measured, not asserted).

For every shipped example whose contacts are holonomic (hard, complete, frictionless)
and whose locus takes seconds, the locus is computed once; then, at each rational
witness, ``finite_mobility`` (the exact expansion and its decision) is timed against
the independent numerical sampler of the tests (``tests/finite_sampler.py``: random
displacements projected onto the loop closure by Gauss-Newton in mpmath at 60 digits,
the local dimension read from the Jacobian's numerical rank), which decides nothing
exactly and only estimates the dimension. The row says how many witnesses were decided
and how many agree with the sampler.

``ratio = baseline_s / ours_s`` (above 1: ours is faster). Run
``python benchmarks/bench_finite.py [--quick]``.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import sympy as sp

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import mpmath as mp  # noqa: E402
from finite_sampler import Sampler  # noqa: E402

from coopkin_sym import load  # noqa: E402
from coopkin_sym.analysis.finite import finite_mobility  # noqa: E402
from coopkin_sym.errors import FiniteMobilityError  # noqa: E402

EXAMPLES = ("paper-case1-hard", "paper-case1-planar", "paper-case1-complete-hard",
            "four-bar", "shaky-pinned-bars", "five-bar", "planar-two-fingers",
            "bennett-linkage")
QUICK = EXAMPLES[:4]

#: Single configurations: branches along the roots of a cubic, overconstrained loops
#: proved by the loop closure, over Q and over number fields (Bricard's linkage at
#: home: its locus search is cut by its size bound, with no witness).
_BENNETT = "2*atan((65*sqrt(3)-70)/311)"
CASES = (("seven-r-loop", "q1=0"), ("seven-r-loop", "q4=pi/3"),
         ("parallel-cranks", "q1=0"), ("parallel-cranks", "q1=pi/3,q2=pi/3,q3=pi/3"),
         ("bennett-linkage", f"q1=pi/6,q2={_BENNETT},q3=pi/6,q4={_BENNETT}"),
         ("paper-case1-complete-hard", "q1=0,q2=pi/2"), ("bricard-linkage", "q1=0"))


def _radians(text: str):
    return mp.mpf(str(sp.N(sp.sympify(text), 70)))


def run(quick: bool = False, log=print) -> list[dict]:
    rows = []
    for name in QUICK if quick else EXAMPLES:
        system = load(name)
        locus = system.locus()
        witnesses = [c.witness for c in locus.components if c.witness]
        ours = base = 0.0
        decided = agree = 0
        for witness in witnesses:
            at = ",".join(f"{k}={v}" for k, v in witness.items()
                          if k in {j.name for j in system.model.joints})
            t = time.perf_counter()
            try:
                fm = finite_mobility(system.model, at)
            except FiniteMobilityError as exc:
                log(f"{name} {at}: {exc}")
                continue
            ours += time.perf_counter() - t
            if fm.dimension is None:
                continue
            decided += 1
            t = time.perf_counter()
            values = {k: _radians(v) for k, v in witness.items()
                      if k in {j.name for j in system.model.joints}}
            sampler = Sampler(system.model, values, {p.name: 1
                                                     for p in system.model.parameters})
            agree += sampler.dimension(6) == fm.dimension
            base += time.perf_counter() - t
        rows.append({"benchmark": "finite", "case": f"{name}: {len(witnesses)} witnesses",
                     "ours_s": round(ours, 3), "baseline": "mpmath sampler",
                     "baseline_s": round(base, 3),
                     "ratio": round(base / ours, 1) if ours and base else None,
                     "note": f"{decided} decided, {agree} agree with the sampler"})
        log(str(rows[-1]))
    for name, at in CASES[:2] if quick else CASES:
        rows.append(_case(name, at))
        log(str(rows[-1]))
    return rows


def _case(name: str, at: str) -> dict:
    """One configuration: the exact finite mobility against the sampler's dimension."""
    system = load(name)
    t = time.perf_counter()
    fm = finite_mobility(system.model, at)
    ours = time.perf_counter() - t
    values = {k: _radians(v) for k, v in (item.split("=", 1) for item in at.split(","))}
    t = time.perf_counter()
    sampled = Sampler(system.model, values, {p.name: 1 for p in system.model.parameters}
                      ).dimension(6)
    base = time.perf_counter() - t
    return {"benchmark": "finite", "case": f"{name} at {at}", "ours_s": round(ours, 3),
            "baseline": "mpmath sampler", "baseline_s": round(base, 3),
            "ratio": round(base / ours, 1) if ours and base else None,
            "note": f"finite {fm.dimension} ({fm.reason}), sampler {sampled}"}


if __name__ == "__main__":
    quick = "--quick" in sys.argv
    for row in run(quick):
        print(" | ".join(str(row[k]) for k in ("benchmark", "case", "ours_s", "baseline",
                                                "baseline_s", "ratio", "note")))
