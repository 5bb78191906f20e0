"""The compiled point path against the size of one arm (measured, not asserted).

(1) ``second analysis``: one arm of N revolute joints (random exact unit axes and
    points, one hard contact on its last link), N = 4..8: wall and CPU time of the
    first ``System.analyze(at).numbers`` of a freshly loaded system, of the second (it
    compiles ``Q``) and of the third; the growth exponent of the second against N is
    fitted (least squares of log time against log N).
(2) ``1,000 configurations``: ``analyze(at).numbers`` of a 7-joint arm (and a 5-joint
    one, whose float build finishes within the cap) at 1,000 random
    exact configurations (``2*atan(p/q)``, some 0 and +-pi/2), the first call and the
    compilation included, against the float pipeline of ``bench_speed`` (the
    lambdified numpy ``Q`` of the kinematics and three ``numpy.linalg.matrix_rank``)
    at the same points, its build (symbolic ``Q`` and ``lambdify``) included. Each
    side runs in a fresh worker with a cap (time, and memory as in ``bench_speed``); a
    float build stopped at the time cap gives a lower bound of the ratio. Goal: ours <=
    2x the float pipeline, compile included.

``ratio = baseline_s / ours_s`` (above 1: ours is faster). Run
``python benchmarks/bench_compile.py [--quick]``.
"""

from __future__ import annotations

import math
import random
import statistics
import sys
import time
from collections.abc import Iterator
from fractions import Fraction

import bench_speed
from bench_speed import fit_exponent, run_stages

import coopkin_sym

POINTS_GOAL = 2.0        # ours <= 2x the float pipeline over the points, compile included


def _unit(rng: random.Random) -> list[str]:
    """An exact unit vector (inverse stereographic projection of a rational point)."""
    a = Fraction(rng.randint(-5, 5), rng.randint(1, 5))
    b = Fraction(rng.randint(-5, 5), rng.randint(1, 5))
    d = 1 + a * a + b * b
    return [str(x) for x in (2 * a / d, 2 * b / d, (a * a + b * b - 1) / d)]


def long_arm(joints: int, seed: int = 0) -> dict:
    """One arm of ``joints`` revolute joints, random exact axes and points, one hard
    contact on its last link."""
    rng = random.Random(seed)

    def point() -> list[str]:
        return [str(Fraction(rng.randint(-9, 9), rng.randint(1, 4))) for _ in range(3)]

    chain = [{"name": f"q{k + 1}", "type": "revolute", "axis": _unit(rng), "point": point()}
             for k in range(joints)]
    return {"name": f"{joints}R arm", "parameters": [], "arms": [{"name": "a", "joints": chain}],
            "contacts": [{"name": "c", "link": f"a/{joints}", "point": point(),
                          "normal": _unit(rng), "model": "hard"}]}


def _clock() -> tuple[float, float]:
    return time.perf_counter(), time.process_time()


def _since(start: tuple[float, float]) -> tuple[float, float]:
    wall, cpu = _clock()
    return wall - start[0], cpu - start[1]


# ------------------------------------------------------------------- worker stages
def stages_calls(joints: int) -> Iterator[dict]:
    """The first three analyses of a fresh system, one message each."""
    system = coopkin_sym.load(long_arm(joints))
    rng = random.Random(1)
    for stage in ("first", "second", "third"):
        at = ",".join(f"q{k + 1}=2*atan({rng.randint(-9, 9)}/{rng.randint(1, 9)})"
                      for k in range(joints))
        start = _clock()
        numbers = system.analyze(at).numbers.as_dict()
        wall, cpu = _since(start)
        yield {"stage": stage, "seconds": wall, "cpu": cpu, "numbers": numbers}


def _configurations(system, count: int) -> list[list[Fraction]]:
    return bench_speed.random_points(system, random.Random(7), count)


def stages_ours(joints: int, count: int) -> Iterator[dict]:
    """``analyze(at).numbers`` at ``count`` points of a fresh system, all timed."""
    system = coopkin_sym.load(long_arm(joints))
    points = [bench_speed.as_mapping(system, v) for v in _configurations(system, count)]
    each = []
    start = _clock()
    ranks = []
    for at in points:
        t0 = time.perf_counter()
        numbers = system.analyze(at=at).numbers.as_dict()
        each.append(time.perf_counter() - t0)
        ranks.append(bench_speed._ranks_from(numbers, 6, joints))
    wall, cpu = _since(start)
    yield {"stage": "points", "seconds": wall, "cpu": cpu, "first": each[0],
           "second": each[1], "median": statistics.median(each[2:]), "ranks": ranks}


def stages_float(joints: int, count: int) -> Iterator[dict]:
    """The float pipeline: its build, then ``count`` points."""
    system = coopkin_sym.load(long_arm(joints))
    values = _configurations(system, count)
    start = _clock()
    f, shape = bench_speed.float_pipeline(system)
    wall, cpu = _since(start)
    yield {"stage": "build", "seconds": wall, "cpu": cpu}
    revolute = [True] * joints
    each, ranks = [], []
    start = _clock()
    for v in values:
        angles = [2 * math.atan2(x.numerator, x.denominator) for x in v]  # float-ok
        t0 = time.perf_counter()
        ranks.append(bench_speed._float_point(f, angles, revolute, shape, 6))
        each.append(time.perf_counter() - t0)
    wall, cpu = _since(start)
    yield {"stage": "points", "seconds": wall, "cpu": cpu,
           "median": statistics.median(each), "ranks": ranks}


# ------------------------------------------------------------------------ benchmarks
def bench_second_call(quick: bool, log=print) -> list[dict]:
    sizes = range(4, 7) if quick else range(4, 9)
    cap = 120.0 if quick else 600.0
    rows, fit = [], []
    for joints in sizes:
        log(f"  second analysis: {joints}R arm ...")
        res = run_stages(stages_calls, (joints,), ["first", "second", "third"], cap)
        parts = []
        for stage in ("first", "second", "third"):
            r = res[stage]
            parts.append(f"{stage} {r['seconds']:.4f} s wall, {r['cpu']:.4f} s CPU"
                         if r["status"] == "ok" else f"{stage} {r['status']}")
        second = res["second"]
        if second["status"] == "ok":
            fit.append((joints, second["cpu"]))
        rows.append({"benchmark": "second analysis", "case": f"{joints}R arm, one hard contact",
                     "ours_s": second["seconds"] if second["status"] == "ok" else None,
                     "baseline": "the first analysis (no compiling)",
                     "baseline_s": res["first"].get("seconds"),
                     "ratio": (res["first"]["seconds"] / second["seconds"]
                               if second["status"] == "ok" and res["first"]["status"] == "ok"
                               else None),
                     "note": "; ".join(parts)})
    k = fit_exponent(fit)
    rows.append({"benchmark": "scaling exponent", "case": "second analysis (CPU) against N",
                 "ours_s": None, "baseline": None, "baseline_s": None, "ratio": None,
                 "note": f"time ~ N^{k:.2f} over N = {fit[0][0]}..{fit[-1][0]}" if k is not None
                 else "no fit",
                 "plot": [{"panel": "compiled point path", "series": "second analysis",
                           "x": x, "y": y} for x, y in fit]})
    return rows


def bench_points(quick: bool, log=print) -> list[dict]:
    cases = [(5, 100)] if quick else [(5, 1000), (7, 1000)]
    return [row for joints, count in cases
            for row in bench_points_of(joints, count, 300.0 if quick else 600.0, log)]


def bench_points_of(joints: int, count: int, cap: float, log=print) -> list[dict]:
    log(f"  {count} configurations of a {joints}R arm: ours ...")
    ours = run_stages(stages_ours, (joints, count), ["points"], cap)["points"]
    log(f"  {count} configurations of a {joints}R arm: float pipeline (cap {cap:g} s) ...")
    flt = run_stages(stages_float, (joints, count), ["build", "points"], cap)
    case = f"{joints}R arm, one hard contact, {count} random exact configurations"
    if ours["status"] != "ok":
        return [{"benchmark": "points", "case": case, "ours_s": None, "baseline": None,
                 "baseline_s": None, "ratio": None, "note": f"ours: {ours['status']}"}]
    build, points = flt["build"], flt["points"]
    note = (f"ours {ours['seconds']:.3f} s wall, {ours['cpu']:.3f} s CPU (first call "
            f"{ours['first']:.4f} s, second {ours['second']:.4f} s, then median "
            f"{ours['median'] * 1e6:.0f} us)")
    if build["status"] == "ok" and points["status"] == "ok":
        total = build["seconds"] + points["seconds"]
        total_cpu = build["cpu"] + points["cpu"]
        wrong = sum(a != b for a, b in zip(ours["ranks"], points["ranks"], strict=True))
        note += (f"; float build {build['seconds']:.2f} s wall, {build['cpu']:.2f} s CPU, "
                 f"points {points['seconds']:.3f} s wall, {points['cpu']:.3f} s CPU (median "
                 f"{points['median'] * 1e6:.0f} us); CPU in all: ours {ours['cpu']:.3f} s, "
                 f"float {total_cpu:.2f} s; float ranks differ at {wrong}")
        ratio, lower = total / ours["seconds"], False
    else:
        total = cap if build["status"] == "timeout" else None
        note += f"; float build: {bench_speed._why(build, cap)}"
        ratio, lower = (total / ours["seconds"] if total else None), True
    rows = [{"benchmark": "points", "case": case + ", compile included",
             "ours_s": ours["seconds"], "baseline": "lambdified numpy Q + matrix_rank x3, "
             "build included", "baseline_s": total, "ratio": ratio,
             "note": note + ("; the ratio is a lower bound (capped)" if ratio and lower
                             else "")}]
    if points.get("status") == "ok":
        rows.append({"benchmark": "points", "case": case + ", per point (median)",
                     "ours_s": ours["median"], "baseline": "the same float pipeline, warm",
                     "baseline_s": points["median"],
                     "ratio": points["median"] / ours["median"], "note": "build excluded"})
    goal = f"ours <= {POINTS_GOAL:g}x the float pipeline, compile included: "
    if ratio is not None:
        verdict = "met" if ratio >= 1 / POINTS_GOAL else "MISSED"
        goal += f"{verdict} ({1 / ratio:.3g}x{', at most' if lower else ''})"
    else:
        goal += f"not decided (the float build {bench_speed._why(build, cap)})"
    rows.append({"benchmark": "target", "case": case, "ours_s": ours["seconds"],
                 "baseline": None, "baseline_s": None, "ratio": None, "note": goal})
    return rows


def run(quick: bool = False, log=print) -> list[dict]:
    return bench_second_call(quick, log) + bench_points(quick, log)


def _show(rows: list[dict]) -> None:
    for row in rows:
        values = [row["benchmark"], row["case"]]
        for key in ("ours_s", "baseline_s", "ratio"):
            v = row[key]
            values.append(f"{key}={v:.4g}" if isinstance(v, float) else f"{key}={v}")
        print(" | ".join(values + [row["note"]]))


if __name__ == "__main__":
    _show(run("--quick" in sys.argv[1:], log=lambda m: print(m, file=sys.stderr)))
