"""Generic analysis over Q(t, L) against SymPy, and how its cost grows (measured, not
asserted).

(a) ``generic vs SymPy``: the whole generic analysis (model to numbers and the SymPy
    blocks ``C``, every joint symbolic, ``L`` symbolic) against SymPy computing only a
    nullspace of the same ``Q`` (a SymPy matrix of rational functions, built by the
    package's kinematics, untimed), three ways: ``Matrix.nullspace``,
    ``DomainMatrix.from_Matrix(Q).to_field().nullspace()`` over ``ZZ(t, L)``, and
    ``DomainMatrix.nullspace()`` over ``ZZ[t, L]`` (fraction-free, after SymPy clears
    each row of its denominators; the clearing is timed). Cases: paper case study 2
    (all eight joints), hands of 2..6 fingers, and a spatial 5-finger hand with 4
    joints per finger and mixed hard/soft tips.
(b) ``scaling``: our generic analysis (numbers and blocks) and our exact analysis at
    one rational configuration (baseline: SymPy ``DomainMatrix`` nullspace over QQ of
    the same ``Q``) for planar and spatial hands of growing size.

Every measurement runs in a worker process with a wall-clock cap and a memory cap
(``resource.RLIMIT_AS``); a baseline that does not finish is killed at the cap and the
cap is reported as a lower bound on the ratio. ``ratio = baseline_s / ours_s``.

Run ``python benchmarks/bench_generic.py [--quick]``, or
``python benchmarks/bench_generic.py --profile "spatial_hand(5, 4, tips=MIXED5)"``
for the time per stage of one generic analysis.
"""

from __future__ import annotations

import cProfile
import multiprocessing as mp
import os
import pstats
import resource
import sys
import time
import traceback
from collections.abc import Callable
from fractions import Fraction

import coopkin_sym
from coopkin_sym.analysis import kinematics, mobility
from coopkin_sym.exact.sympy_bridge import matrix_to_sympy
from coopkin_sym.model.builders import arm_cell, planar_hand, spatial_hand

MIXED5 = ["hard", "soft", "hard", "soft", "hard"]
TOO_LARGE = getattr(mobility, "BlockTooLarge", ())   # the package's term budget
BASELINE_CAP = {False: 120.0, True: 20.0}      # seconds, by quick
OURS_CAP = {False: 300.0, True: 60.0}
SCALING_CAP = {False: 60.0, True: 15.0}
MEMORY_CAP = 6 << 30                             # bytes of address space per worker
WORKERS = max(1, min(2, os.cpu_count() or 1))    # baselines run side by side, one per CPU

BUILDERS: dict[str, Callable] = {"planar_hand": planar_hand, "spatial_hand": spatial_hand,
                                 "arm_cell": arm_cell}


# ------------------------------------------------------------------------------ cases
class Case:
    """A system to measure: a shipped example name or a builder call."""

    def __init__(self, label: str, source, series: str | None = None, size: int = 0,
                 target: str | None = None):
        self.label = label
        self.source = source            # example name, or (builder name, args, kwargs)
        self.series = series            # cases of one series grow with ``size``
        self.size = size
        self.target = target

    def model(self):
        if isinstance(self.source, str):
            return self.source
        name, args, kwargs = self.source
        return BUILDERS[name](*args, **kwargs)


def hand(kind: str, fingers: int, joints: int, tips="hard", series: str | None = None,
         target: str | None = None) -> Case:
    short = "planar" if kind == "planar_hand" else "spatial"
    tip_text = tips if isinstance(tips, str) else "/".join(t[0] for t in tips)
    return Case(f"{short} hand {fingers}x{joints} {tip_text}", (kind, (fingers, joints),
                {"tips": tips}), series=series, size=fingers, target=target)


PAPER_TARGET = "generic analysis < 0.5 s and >= 50x faster than the best DomainMatrix form"
HAND_TARGET = "generic analysis < 10 s where SymPy does not finish in 120 s"


def generic_cases(quick: bool) -> list[Case]:
    cases = [Case("paper case 1 hard (2 joints + L)", "paper-case1-hard"),
             Case("paper case 2 hard (8 joints + L)", "paper-case2-hard",
                  series="paper case 2", size=6, target=PAPER_TARGET)]
    if not quick:      # complete contacts: the rows of hard contacts and 6 more
        cases.append(Case("paper case 2 complete (8 joints + L)", "paper-case2-complete",
                          series="paper case 2", size=12, target=PAPER_TARGET))
    cases += [hand("planar_hand", f, 2, series="planar x2") for f in range(2, 7)]
    if quick:
        cases.append(hand("spatial_hand", 3, 4, ["hard", "soft", "hard"]))
    else:
        cases.append(hand("spatial_hand", 5, 4, MIXED5, target=HAND_TARGET))
    return cases


def scaling_cases(quick: bool) -> list[Case]:
    fingers = range(2, 5) if quick else range(2, 7)
    joints = (2, 3) if quick else (2, 3, 4)
    cases = []
    for kind in ("planar_hand", "spatial_hand"):
        for j in joints:
            short = "planar" if kind == "planar_hand" else "spatial"
            cases += [hand(kind, f, j, series=f"{short} hand, {j} joints/finger")
                      for f in fingers]
    return cases


# ----------------------------------------------------------- work done in the workers
def _q_sympy(model):
    """``Q`` of ``model`` with every joint free, as a SymPy matrix (the kinematics of
    the package; the same matrix as ``Analysis.Q``, without running the analysis)."""
    system = coopkin_sym.load(model)
    config = system.configuration(None, "all")
    kin = kinematics.build(system.model, config)
    return matrix_to_sympy(kin.Q, kin.ring, kin.symbols, (0, 6 + len(system.model.joints)))


def _entry_terms(expr) -> int:
    import sympy as sp
    num = sp.numer(expr)
    return len(sp.Add.make_args(num)) if num != 0 else 0


def ours_generic(model) -> dict:
    """Model to numbers (``analyze(generic=True)``) and SymPy blocks (``a.C``).

    If the package refuses the blocks (their entries would exceed its term budget,
    ``BlockTooLarge``), ``seconds`` is the time to the numbers and ``refused`` says why.
    """
    t0 = time.perf_counter()
    system = coopkin_sym.load(model)
    a = system.analyze(generic=True)
    numbers = a.numbers.as_dict()
    t1 = time.perf_counter()
    out = {"numbers": numbers, "numbers_s": t1 - t0, "r": len(system.model.joints)}
    try:
        c = a.C
    except TOO_LARGE as exc:
        return {**out, "seconds": t1 - t0, "blocks_s": None, "refused": str(exc),
                "max_terms": None}
    t2 = time.perf_counter()
    terms = max((_entry_terms(e) for e in c), default=0)
    return {**out, "seconds": t2 - t0, "blocks_s": t2 - t1, "max_terms": terms,
            "refused": None}


def _ours_note(res: dict) -> str:
    head = f"{_fmt_numbers(res['numbers'])}; numbers {res['numbers_s']:.3f} s"
    if res.get("refused"):
        return (f"{head}; blocks refused by the term budget, ours_s is numbers only "
                f"({res['refused'].split(';')[0]})")
    return (f"{head} + blocks {res['blocks_s']:.3f} s; largest block entry "
            f"{res['max_terms']} terms")


def random_point(model, seed: int = 1) -> dict:
    """A fixed pseudo-random rational configuration: q = 2 atan(p/q), L rational."""
    import random
    rng = random.Random(seed)
    system = coopkin_sym.load(model)
    at = {}
    for j in system.model.joints:
        t = Fraction(rng.randint(-40, 40), rng.randint(1, 40))
        at[j.name] = f"2*atan({t})" if j.type == "revolute" else str(t)
    at["L"] = str(Fraction(rng.randint(1, 40), rng.randint(1, 40)))
    return at


def ours_point(model) -> dict:
    """The exact analysis at one rational configuration, numbers and blocks, from a
    loaded system (loading and validating the model is timed apart)."""
    at = random_point(model)
    t0 = time.perf_counter()
    system = coopkin_sym.load(model)
    t1 = time.perf_counter()
    a = system.analyze(at)
    numbers = a.numbers.as_dict()
    t2 = time.perf_counter()
    _ = a.C
    t3 = time.perf_counter()
    return {"seconds": t3 - t1, "load_s": t1 - t0, "numbers_s": t2 - t1, "numbers": numbers}


def baseline_point(model) -> dict:
    """SymPy ``DomainMatrix`` over QQ: nullspace of ``Q`` at the same configuration."""
    from sympy.polys.matrices import DomainMatrix
    a = coopkin_sym.load(model).analyze(random_point(model))
    q = a.Q
    t0 = time.perf_counter()
    ns = DomainMatrix.from_Matrix(q).to_field().nullspace()
    return {"seconds": time.perf_counter() - t0, "nullity": ns.shape[0]}


def _clear_rows(q):
    import sympy as sp
    rows = []
    for i in range(q.rows):
        row = [sp.together(e) for e in q.row(i)]
        den = sp.lcm([sp.denom(e) for e in row])
        rows.append([sp.cancel(e * den) for e in row])
    return sp.Matrix(rows)


def _matrix_nullspace(q) -> int:
    return len(q.nullspace())


def _domain_field_nullspace(q) -> int:
    from sympy.polys.matrices import DomainMatrix
    return DomainMatrix.from_Matrix(q).to_field().nullspace().shape[0]


def _domain_ring_nullspace(q) -> int:
    from sympy.polys.matrices import DomainMatrix
    return DomainMatrix.from_Matrix(_clear_rows(q)).nullspace().shape[0]


BASELINES: dict[str, Callable] = {
    "SymPy Matrix.nullspace": _matrix_nullspace,
    "DomainMatrix ZZ(t,L) to_field().nullspace()": _domain_field_nullspace,
    "DomainMatrix ZZ[t,L] nullspace (rows cleared)": _domain_ring_nullspace,
}


def baseline_generic(model, method: str) -> dict:
    q = _q_sympy(model)
    t0 = time.perf_counter()
    nullity = BASELINES[method](q)
    return {"seconds": time.perf_counter() - t0, "nullity": nullity}


# ------------------------------------------------------------- capped worker processes
def _worker(conn, func, args):
    try:
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_CAP, MEMORY_CAP))
    except (ValueError, OSError):
        pass
    t0 = time.perf_counter()
    try:
        conn.send({"status": "ok", **func(*args)})
    except MemoryError:
        conn.send({"status": "memory", "seconds": time.perf_counter() - t0})
    except BaseException as exc:  # reported in the table, never hidden
        conn.send({"status": "error", "seconds": time.perf_counter() - t0,
                   "message": f"{type(exc).__name__}: {exc}",
                   "trace": traceback.format_exc(limit=3)})
    finally:
        conn.close()


def _context():
    methods = mp.get_all_start_methods()
    return mp.get_context("fork" if "fork" in methods else methods[0])


def run_capped(jobs: list[tuple[Callable, tuple]], cap: float, workers: int = 1,
               after: list[int | None] | None = None) -> list[dict]:
    """Run ``func(*args)`` for each job in its own process, at most ``workers`` at a
    time, each killed after ``cap`` seconds (status ``"timeout"``, ``seconds = cap``).

    ``after[k] = j`` starts job ``k`` only once job ``j`` has finished, and skips it
    (status ``"skipped"``, ``"after"`` = j) if job ``j`` did not succeed. Results are
    dicts with ``status`` ``ok | timeout | memory | error | died | skipped``.
    """
    ctx = _context()
    after = after or [None] * len(jobs)
    results: list[dict | None] = [None] * len(jobs)
    pending = list(range(len(jobs)))
    running: dict[int, tuple] = {}
    while pending or running:
        for k in list(pending):
            if len(running) >= workers:
                break
            j = after[k]
            if j is not None and results[j] is None:
                continue
            pending.remove(k)
            if j is not None and results[j]["status"] != "ok":
                results[k] = {"status": "skipped", "seconds": None, "after": j}
                continue
            parent, child = ctx.Pipe(duplex=False)
            proc = ctx.Process(target=_worker, args=(child, *jobs[k]), daemon=True)
            proc.start()
            child.close()
            running[k] = (proc, parent, time.perf_counter())
        time.sleep(0.02)
        for k, (proc, conn, start) in list(running.items()):
            elapsed = time.perf_counter() - start
            if conn.poll():
                try:
                    results[k] = conn.recv()
                except EOFError:
                    results[k] = {"status": "died", "seconds": elapsed}
            elif not proc.is_alive():
                results[k] = {"status": "died", "seconds": elapsed,
                              "message": f"worker exit code {proc.exitcode}"}
            elif elapsed > cap:
                proc.kill()
                results[k] = {"status": "timeout", "seconds": cap}
            else:
                continue
            proc.join(5)
            if proc.is_alive():
                proc.kill()
                proc.join()
            conn.close()
            del running[k]
    return results  # type: ignore[return-value]


# ------------------------------------------------------------------------------ rows
def _fmt_numbers(n: dict) -> str:
    return " ".join(f"{k}={v}" for k, v in n.items())


def _failure(res: dict, cap: float, who: str) -> str:
    status = res["status"]
    if status == "timeout":
        return f"{who} did not finish in {cap:g} s"
    if status == "memory":
        return f"{who} ran out of memory ({MEMORY_CAP >> 30} GB cap) after {res['seconds']:.1f} s"
    if status == "died" and "-6" in res.get("message", ""):
        return (f"{who} aborted after {res['seconds']:.1f} s (SIGABRT: FLINT aborts when an "
                f"allocation fails, here under the {MEMORY_CAP >> 30} GB cap)")
    return f"{who} failed ({status}): {res.get('message', '')}"


def bench_generic_vs_sympy(quick: bool, log=print) -> list[dict]:
    cap, ours_cap = BASELINE_CAP[quick], OURS_CAP[quick]
    cases = generic_cases(quick)
    ours_all = []
    for case in cases:
        log(f"  generic: ours on {case.label} ...")
        ours_all.append(run_capped([(ours_generic, (case.model(),))], ours_cap)[0])
    # every baseline of every case, side by side; along a series of growing systems a
    # method runs on a system only if it finished on the previous one
    jobs, keys, after = [], [], []
    last: dict[tuple[str, str], int] = {}
    for c, case in enumerate(cases):
        for method in BASELINES:
            after.append(last.get((case.series, method)) if case.series else None)
            if case.series:
                last[(case.series, method)] = len(jobs)
            jobs.append((baseline_generic, (case.model(), method)))
            keys.append((c, method))
    log(f"  generic: {len(jobs)} SymPy baselines (cap {cap:g} s, {WORKERS} at a time) ...")
    results = run_capped(jobs, cap, WORKERS, after)
    by_key = dict(zip(keys, results, strict=True))
    rows: list[dict] = []
    for c, case in enumerate(cases):
        ours = ours_all[c]
        ours_ok = ours["status"] == "ok"
        ours_s = ours["seconds"] if ours_ok else None
        base_note = (_ours_note(ours) if ours_ok
                     else _failure(ours, ours_cap, "our generic analysis"))
        best = None
        for method in BASELINES:
            res = by_key[(c, method)]
            note = base_note
            if res["status"] == "skipped":
                j = res["after"]
                while results[j]["status"] == "skipped":
                    j = results[j]["after"]
                smaller = cases[keys[j][0]].label
                row = {"baseline_s": None, "ratio": None,
                       "note": f"not run: baseline did not finish on the smaller "
                               f"{smaller}; " + note}
            else:
                bs = res["seconds"]
                ratio = bs / ours_s if ours_ok and ours_s > 0 else None
                if res["status"] == "ok":
                    nm = ours.get("numbers", {}).get("Nm", res["nullity"])
                    if res["nullity"] != nm:
                        note = f"baseline nullity {res['nullity']} != Nm; " + note
                else:
                    note = _failure(res, cap, "baseline") + (
                        "; ratio is a lower bound; " if ratio else "; ") + note
                row = {"baseline_s": bs, "ratio": ratio, "note": note}
                if method.startswith("DomainMatrix") and (best is None or bs < best[0]):
                    best = (bs, res["status"] != "ok")
            rows.append({"benchmark": "generic vs SymPy", "case": case.label,
                         "ours_s": ours_s, "baseline": method, **row})
        if case.target:
            rows.append(_target_row(case, ours_s, best))
    return rows


def _target_row(case: Case, ours_s: float | None, best) -> dict:
    if case.target == PAPER_TARGET:
        limit, factor = 0.5, 50.0
    else:
        limit, factor = 10.0, None
    parts = []
    if ours_s is None:
        parts.append(f"MISSED: our analysis did not finish (limit {limit:g} s)")
    elif ours_s <= limit:
        parts.append(f"met: {ours_s:.3f} s <= {limit:g} s")
    else:
        parts.append(f"MISSED: {ours_s:.3f} s > {limit:g} s (x{ours_s / limit:.1f} over)")
    if factor is not None and best is not None and ours_s:
        ratio = best[0] / ours_s
        bound = ">= " if best[1] else ""
        verdict = "met" if ratio >= factor else "MISSED"
        parts.append(f"{verdict}: best DomainMatrix form {bound}{ratio:.0f}x (target {factor:g}x)")
    elif factor is None and best is not None:
        parts.append("SymPy did not finish" if best[1] else
                     f"NOTE: SymPy DomainMatrix finished in {best[0]:.1f} s")
    return {"benchmark": "target", "case": case.label, "ours_s": ours_s, "baseline": None,
            "baseline_s": None, "ratio": None, "note": f"{case.target}: " + "; ".join(parts)}


def bench_scaling(quick: bool, log=print) -> list[dict]:
    cap = SCALING_CAP[quick]
    rows: list[dict] = []
    stopped: dict[str, str] = {}
    for case in scaling_cases(quick):
        r = case.size * int(case.label.split("x")[1].split()[0])
        if case.series in stopped:
            rows.append({"benchmark": "scaling: generic", "case": case.label, "ours_s": None,
                         "baseline": None, "baseline_s": None, "ratio": None,
                         "note": f"not run: {stopped[case.series]}"})
        else:
            log(f"  scaling: generic {case.label} ...")
            res = run_capped([(ours_generic, (case.model(),))], cap)[0]
            if res["status"] == "ok":
                note = f"r={r}; " + _ours_note(res)
                rows.append({"benchmark": "scaling: generic", "case": case.label,
                             "ours_s": res["seconds"], "baseline": None, "baseline_s": None,
                             "ratio": None, "note": note,
                             "plot": [{"panel": "generic analysis over Q(t, L)",
                                       "series": f"{case.series}: numbers", "x": r,
                                       "y": res["numbers_s"]}]
                             + ([{"panel": "generic analysis over Q(t, L)",
                                  "series": f"{case.series}: numbers + SymPy blocks",
                                  "x": r, "y": res["seconds"]}]
                                if res.get("blocks_s") is not None else [])})
            else:
                why = _failure(res, cap, "our generic analysis")
                stopped[case.series] = f"{why} on {case.label}"
                rows.append({"benchmark": "scaling: generic", "case": case.label,
                             "ours_s": None, "baseline": None, "baseline_s": None,
                             "ratio": None, "note": f"r={r}; {why}"})
        log(f"  scaling: exact point {case.label} ...")
        ours, base = run_capped([(ours_point, (case.model(),)),
                                 (baseline_point, (case.model(),))], cap)
        ok = ours["status"] == "ok" and base["status"] == "ok"
        ratio = base["seconds"] / ours["seconds"] if ok else None
        note = (f"r={r}; {_fmt_numbers(ours['numbers'])}; numbers {ours['numbers_s']:.4f} s "
                f"+ blocks; load {ours['load_s']:.3f} s (not in ours_s)"
                if ours["status"] == "ok" else _failure(ours, cap, "ours"))
        if base["status"] == "ok" and ours["status"] == "ok" and \
                base["nullity"] != ours["numbers"]["Nm"]:
            note += f"; baseline nullity {base['nullity']} != Nm"
        row = {"benchmark": "scaling: exact at a rational point", "case": case.label,
               "ours_s": ours.get("seconds") if ours["status"] == "ok" else None,
               "baseline": "DomainMatrix QQ nullspace",
               "baseline_s": base["seconds"] if base["status"] == "ok" else None,
               "ratio": ratio, "note": note + "; ours includes blocks, baseline nullspace only"}
        if ours["status"] == "ok":
            row["plot"] = [{"panel": "exact analysis at a rational point",
                            "series": f"{case.series}: numbers + blocks", "x": r,
                            "y": ours["seconds"]}]
            if base["status"] == "ok":
                row["plot"].append({"panel": "exact analysis at a rational point",
                                    "series": f"{case.series}: DomainMatrix QQ nullspace",
                                    "x": r, "y": base["seconds"]})
        rows.append(row)
    return rows


def run(quick: bool = False, log=print) -> list[dict]:
    """All rows of this benchmark (see the module docstring)."""
    return bench_generic_vs_sympy(quick, log) + bench_scaling(quick, log)


# ------------------------------------------------------------------------ profiling
def profile(expr: str, top: int = 25) -> None:
    """Time per stage of one generic analysis (``expr`` a builder call or an example
    name), with cProfile's top functions of the package."""
    from coopkin_sym.analysis import mobility
    names = {**BUILDERS, "MIXED5": MIXED5}
    model = eval(expr, {"__builtins__": {}}, names) if "(" in expr else expr
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_CAP, MEMORY_CAP))
    system = coopkin_sym.load(model)
    config = system.configuration(None, "all")
    prof = cProfile.Profile()
    prof.enable()
    t0 = time.perf_counter()
    kin = kinematics.build(system.model, config)
    t1 = time.perf_counter()
    a = mobility.Analysis(system.model, config, kin)
    t2 = time.perf_counter()
    blocks = {}
    for name in ("C11", "C12", "C22", "C23"):
        tb = time.perf_counter()
        try:
            m = getattr(a, name)
            blocks[name] = (time.perf_counter() - tb, m.shape,
                            max((_entry_terms(e) for e in m), default=0))
        except TOO_LARGE as exc:
            blocks[name] = (time.perf_counter() - tb, None, str(exc).split(";")[0])
    t3 = time.perf_counter()
    prof.disable()
    q_terms = max(len(e) for row in a._q_rows for e in row)
    print(f"{expr}: r={a.r}, m={a.m}, ring variables={len(kin.ring.names)}")
    print(f"numbers: {_fmt_numbers(a.numbers.as_dict())}")
    print(f"kinematics.build      {t1 - t0:9.3f} s")
    print(f"Analysis (numbers)    {t2 - t1:9.3f} s")
    print(f"blocks to SymPy       {t3 - t2:9.3f} s")
    for name, (sec, shape, size) in blocks.items():
        what = f"shape {shape}, largest entry {size} terms" if shape else f"refused: {size}"
        print(f"  {name:<19} {sec:9.3f} s   {what}")
    print(f"largest entry of Q cleared of denominators: {q_terms} terms")
    stats = pstats.Stats(prof)
    stats.sort_stats("cumulative")
    width = len(os.path.dirname(coopkin_sym.__file__)) + 1
    print(f"\n{'cumulative s':>12} {'own s':>8} {'calls':>7}  function")
    shown = 0
    for (path, line, func), (_cc, nc, tt, ct, _callers) in sorted(
            stats.stats.items(), key=lambda kv: -kv[1][3]):
        if "coopkin_sym" not in path:
            continue
        print(f"{ct:12.3f} {tt:8.3f} {nc:7d}  {path[width:]}:{line}({func})")
        shown += 1
        if shown >= top:
            break


if __name__ == "__main__":
    if len(sys.argv) > 2 and sys.argv[1] == "--profile":
        profile(sys.argv[2])
    else:
        for row in run("--quick" in sys.argv[1:]):
            print({k: v for k, v in row.items() if k != "plot"})
