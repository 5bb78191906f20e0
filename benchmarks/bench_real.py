"""Real robots at real sizes (measured, not asserted).

Four systems, through the public API (``load``, ``System.analyze``, ``System.locus``):

* two Franka Panda arms holding a box: the shipped ``panda-two-arm-box`` (14 joints,
  2 complete contacts: 12 constraints);
* a four-finger 16-joint hand: the shipped ``allegro-hand-sphere`` (16 joints, 4 soft
  fingertips: 16 constraints);
* a 10-finger hand: ``spatial_hand(10, 4)`` (40 joints, 10 hard fingertips: 30
  constraints);
* a cell of 200 arms: ``arm_cell(200, 6)`` (1,200 joints, 200 complete contacts: 1,200
  constraints).

For each, in fresh workers with caps (``bench_speed.run_stages``):

(a) ``point``: ``System.analyze(at=point).numbers`` at random exact configurations
    (``bench_speed.random_points``, parameters at 1): the first call, the second (it
    compiles ``Q``) and the median of the others, against the float pipeline of
    ``bench_speed`` (the lambdified numpy ``Q`` of every ``tan(q/2)`` and three
    ``numpy.linalg.matrix_rank``), whose build is reported where it finishes under its
    cap.
(b) ``generic``: ``System.analyze(generic=True).numbers`` and the certificate.
(c) ``locus``: ``System.locus(at, free=[two joints], certify=True, timeout=...)``, every
    other joint at a random exact value: the components found, whether the locus is
    certified (and why not), what was not explored. Wall time, and CPU time of the
    worker and its children.

Growth: the same three measurements for hands ``spatial_hand(f, 4)`` (f fingers),
cells ``arm_cell(n, 6)`` (n arms) and two arms of j joints ``arm_cell(2, j)``, the
exponent of CPU time against the joints ``r`` fitted by least squares of the logs
(``fit_exponent``); ``python benchmarks/run.py`` plots them in ``scaling_real.png``.

Targets: a 7-DOF arm's 1,000 random exact configurations at most 2x the float pipeline,
compile included (one Panda arm holding its grip, and the random 7R arm of
``bench_compile``); building the exact evaluator of ``Q`` (the second analysis) at most
5x one generic analysis; polynomial growth (every fitted exponent at most 3).

``ratio = baseline_s / ours_s`` (above 1: ours is faster). The machine may be shared:
CPU times are given beside wall times. Run ``python benchmarks/bench_real.py
[--quick] [--plot FILE]``.
"""

from __future__ import annotations

import math
import os
import random
import statistics
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import bench_compile
import bench_speed
from bench_speed import _why, fit_exponent, run_stages

import coopkin_sym
from coopkin_sym.model.builders import arm_cell, spatial_hand

HERE = Path(__file__).resolve().parent
PLOT_PATH = HERE / "scaling_real.png"
POINTS_GOAL = 2.0        # 1,000 configurations: ours <= 2x the float pipeline, compile in
COMPILE_GOAL = 5.0       # the second analysis (compiling Q) <= 5x one generic analysis
GROWTH_GOAL = 3.0        # every fitted exponent of time against r at most 3


def panda_arm() -> dict:
    """One Panda arm of the shipped example (its left arm) holding its grip: a real
    7-DOF arm with one complete contact."""
    from coopkin_sym.model.examples import example_path
    from coopkin_sym.model.trees import read_file

    tree = read_file(example_path("panda-two-arm-box"))
    tree["name"] = "one Franka Panda arm, rigid grasp (DH)"
    tree["arms"], tree["contacts"] = tree["arms"][:1], tree["contacts"][:1]
    return tree


BUILDERS = {"spatial_hand": spatial_hand, "arm_cell": arm_cell, "panda_arm": panda_arm}

#: (label, source, the two free joints of the slice)
SYSTEMS = [
    ("two Pandas holding a box (panda-two-arm-box)", "panda-two-arm-box", ("l2", "l4")),
    ("4-finger 16-joint hand (allegro-hand-sphere)", "allegro-hand-sphere", ("i1", "i2")),
    ("10-finger hand, spatial_hand(10, 4)", ("spatial_hand", (10, 4), {}),
     ("f1_2", "f1_3")),
    ("cell of 200 arms, arm_cell(200, 6)", ("arm_cell", (200, 6), {}), ("a1_2", "a1_3")),
]


def _model(source):
    """An example name, or ``(builder, args, kwargs)`` (picklable for the workers)."""
    if isinstance(source, str):
        return source
    name, args, kwargs = source
    return BUILDERS[name](*args, **kwargs)


def _caps(quick: bool) -> dict[str, float]:
    """Seconds: each stage's cap, the locus search's own bound (``locus``; its worker
    gets 15 s more, and the certificate's), each test of the certificate
    (``certify``; the whole certificate twice that)."""
    return ({"point": 60.0, "generic": 30.0, "locus": 25.0, "float": 5.0, "certify": 5.0}
            if quick else
            {"point": 180.0, "generic": 120.0, "locus": 120.0, "float": 45.0,
             "certify": 30.0})


def _clock() -> tuple[float, float]:
    """Wall time, and CPU time of this process and of its children waited for."""
    t = os.times()
    return time.perf_counter(), time.process_time() + t.children_user + t.children_system


def _since(start: tuple[float, float]) -> dict:
    wall, cpu = _clock()
    return {"seconds": wall - start[0], "cpu": cpu - start[1]}


def _slice_at(system, free) -> str:
    """Every joint but ``free`` at a random exact value, parameters at 1."""
    rng = random.Random(11)
    values = bench_speed.random_points(system, rng, 6)[3]       # not a special point
    parts = [f"{j.name}=2*atan({v})" if j.type == "revolute" else f"{j.name}={v}"
             for j, v in zip(system.model.joints, values, strict=True) if j.name not in free]
    parts += [f"{p.name}=1" for p in system.model.parameters]
    return ",".join(parts)


# ------------------------------------------------------------------- worker stages
def stages_points(source, count: int) -> Iterator[dict]:
    """The first analysis, the second (compiling ``Q``), then ``count`` more."""
    start = _clock()
    system = coopkin_sym.load(_model(source))
    load = _since(start)
    points = [bench_speed.as_mapping(system, v) for v in
              bench_speed.random_points(system, random.Random(7), count + 2)]
    for stage, at in (("first", points[0]), ("compile", points[1])):
        start = _clock()
        numbers = system.analyze(at=at).numbers.as_dict()
        yield {"stage": stage, **_since(start), "numbers": numbers, "load": load}
    each = []
    start = _clock()
    for at in points[2:]:
        t0 = time.perf_counter()
        system.analyze(at=at).numbers  # noqa: B018 - what is measured
        each.append(time.perf_counter() - t0)
    yield {"stage": "points", **_since(start), "median": statistics.median(each),
           "count": len(each)}


def stages_float(source, count: int) -> Iterator[dict]:
    """The float pipeline of ``bench_speed``: its build, then ``count`` points."""
    system = coopkin_sym.load(_model(source))
    start = _clock()
    f, shape = bench_speed.float_pipeline(system)
    yield {"stage": "build", **_since(start)}
    revolute = [j.type == "revolute" for j in system.model.joints]
    each = []
    for v in bench_speed.random_points(system, random.Random(7), count):
        angles = [2 * math.atan2(x.numerator, x.denominator) if rev  # float-ok
                  else x.numerator / x.denominator for x, rev in zip(v, revolute,  # float-ok
                                                                   strict=True)]
        t0 = time.perf_counter()
        bench_speed._float_point(f, angles, revolute, shape, system.model.object_dim)
        each.append(time.perf_counter() - t0)
    yield {"stage": "points", "seconds": sum(each), "median": statistics.median(each)}


def stages_generic(source) -> Iterator[dict]:
    system = coopkin_sym.load(_model(source))
    start = _clock()
    a = system.analyze(generic=True)
    numbers = a.numbers.as_dict()
    cert = a.certificate
    hows = sorted({r.how for r in cert.ranks})
    yield {"stage": "generic", **_since(start), "numbers": numbers,
           "certificate": ("exact" if cert.exact else
                           f"probabilistic, error below 2^-{cert.error_bits}")
           + (f" (ranks: {', '.join(hows)})" if hows else "")}


def stages_locus(source, free, timeout: float, certify: float | None) -> Iterator[dict]:
    """The locus on the slice of ``free``, certified within ``certify`` seconds."""
    system = coopkin_sym.load(_model(source))
    at = _slice_at(system, free)
    start = _clock()
    locus = system.locus(at, free=list(free), timeout=timeout)
    found = _since(start)
    kinds = [c.kind for c in locus.components]
    out = {"stage": "locus", **found, "components": len(kinds),
           "kinds": {k: kinds.count(k) for k in sorted(set(kinds))},
           "unexplored": len(locus.unexplored),
           "cut": any(str(getattr(u, "kind", "")).startswith("time_")
                      for u in locus.unexplored),
           "notes": sorted({getattr(n, "kind", str(n)) for n in locus.notes})}
    if certify is not None:
        from coopkin_sym.present.certificate import completeness_text

        start = _clock()
        locus.certify(timeout=certify, budget=certify * 2)
        out.update(certify=_since(start), certified=bool(locus.completeness()[0]),
                   why=" ".join(completeness_text(locus).split())[:200])
    yield out


def stages_thousand(source, count: int) -> Iterator[dict]:
    """``count`` analyses of a fresh system, first call and compile included."""
    system = coopkin_sym.load(_model(source))
    points = [bench_speed.as_mapping(system, v) for v in
              bench_speed.random_points(system, random.Random(7), count)]
    start = _clock()
    each = []
    for at in points:
        t0 = time.perf_counter()
        system.analyze(at=at).numbers  # noqa: B018 - what is measured
        each.append(time.perf_counter() - t0)
    yield {"stage": "points", **_since(start), "first": each[0], "second": each[1],
           "median": statistics.median(each[2:])}


# ------------------------------------------------------------------------ the rows
def _row(benchmark: str, case: str, ours=None, baseline=None, baseline_s=None,
         note: str = "", **extra) -> dict:
    ratio = baseline_s / ours if ours and baseline_s else None
    return {"benchmark": benchmark, "case": case, "ours_s": ours, "baseline": baseline,
            "baseline_s": baseline_s, "ratio": ratio, "note": note, **extra}


def _fmt(n: dict) -> str:
    return " ".join(f"{k}={v}" for k, v in n.items())


def _wc(r: dict) -> str:
    return f"{r['seconds']:.3g} s wall, {r['cpu']:.3g} s CPU"


def measure_system(label: str, source, free, quick: bool, log=print) -> list[dict]:
    caps = _caps(quick)
    count = 20 if quick else 100
    log(f"  real systems: {label}: point analysis ...")
    pts = run_stages(stages_points, (source, count), ["first", "compile", "points"],
                     caps["point"])
    log(f"  real systems: {label}: float pipeline (cap {caps['float']:g} s) ...")
    flt = run_stages(stages_float, (source, count), ["build", "points"], caps["float"])
    log(f"  real systems: {label}: generic numbers ...")
    gen = run_stages(stages_generic, (source,), ["generic"], caps["generic"])["generic"]
    log(f"  real systems: {label}: locus on the slice of {', '.join(free)} ...")
    loc = run_stages(stages_locus, (source, free, caps["locus"], caps["certify"]),
                     ["locus"], caps["locus"] + 2 * caps["certify"] + 15, daemon=False)["locus"]
    rows = [_point_row(label, pts, flt, caps["float"], count)]
    if gen["status"] == "ok":
        rows.append(_row("real: generic numbers", label, gen["cpu"], note=(
            f"{_fmt(gen['numbers'])}; certificate: {gen['certificate']}; {_wc(gen)}")))
        comp = pts["compile"]
        if comp["status"] == "ok":
            times = comp["cpu"] / gen["cpu"] if gen["cpu"] else float("inf")
            verdict = "met" if times <= COMPILE_GOAL else "MISSED"
            rows.append(_row("target", f"compiling Q, {label}", comp["cpu"], note=(
                f"the second analysis (it compiles Q) <= {COMPILE_GOAL:g}x one generic "
                f"analysis: {verdict}, {times:.2g}x ({comp['cpu']:.3g} s vs "
                f"{gen['cpu']:.3g} s CPU)")))
    else:
        rows.append(_row("real: generic numbers", label, note=_why(gen, caps["generic"])))
    rows.append(_locus_row(label, free, loc, caps))
    return rows


def _point_row(label: str, pts: dict, flt: dict, cap: float, count: int) -> dict:
    first, comp, each = pts["first"], pts["compile"], pts["points"]
    if each["status"] != "ok":
        return _row("real: point analysis", label, note=f"ours: {_why(each, cap)}")
    note = (f"{_fmt(comp['numbers'])} at the second point; median of {each['count']} "
            f"random exact configurations after the first call ({_wc(first)}, load "
            f"{first['load']['seconds']:.3g} s) and the second, which compiles Q "
            f"({_wc(comp)}); the {each['count']} points in all {_wc(each)}")
    build, fpts = flt["build"], flt["points"]
    if build["status"] == "ok" and fpts["status"] == "ok":
        note += (f"; float build {_wc(build)} (excluded), float per point median "
                 f"{fpts['median'] * 1e3:.3g} ms")
        return _row("real: point analysis", label, each["median"],
                    "lambdified numpy Q + matrix_rank x3 (warm)", fpts["median"], note)
    return _row("real: point analysis", label, each["median"],
                "lambdified numpy Q + matrix_rank x3", None,
                note + f"; float pipeline: build {_why(build, cap)}")


def _locus_row(label: str, free, loc: dict, caps: dict) -> dict:
    case = f"{label}, slice of {', '.join(free)}"
    if loc["status"] != "ok":
        return _row("real: one-slice locus", case,
                    note=f"{_why(loc, caps['locus'] + 2 * caps['certify'] + 15)}")
    kinds = ", ".join(f"{v} {k}" for k, v in loc["kinds"].items()) or "none"
    note = (f"{loc['components']} components ({kinds}); {loc['unexplored']} items not "
            f"explored{' (the search was cut by its time bound)' if loc['cut'] else ''}; "
            f"notes: {', '.join(loc['notes']) or '-'}; search {_wc(loc)}")
    if "certified" in loc:
        note += f"; certificate ({_wc(loc['certify'])}): {loc['why']}"
    return _row("real: one-slice locus", case, loc["cpu"], note=note)


# ------------------------------------------------------------------------ growth
def growth_series(quick: bool) -> list[tuple[str, list[tuple[int, object, tuple]]]]:
    """(series, [(r, source, free pair)])."""
    if quick:
        fingers, arms, joints = (2, 4, 6), (2, 6, 20), (3, 5, 7)
    else:
        fingers, arms, joints = (2, 3, 4, 6, 8, 10), (2, 5, 10, 25, 50, 100, 200), \
            (3, 4, 5, 6, 7, 8)
    return [
        ("hands: f fingers x 4 joints",
         [(4 * f, ("spatial_hand", (f, 4), {}), ("f1_2", "f1_3")) for f in fingers]),
        ("cells: n arms x 6 joints",
         [(6 * n, ("arm_cell", (n, 6), {}), ("a1_2", "a1_3")) for n in arms]),
        ("two arms of j joints",
         [(2 * j, ("arm_cell", (2, j), {}), ("a1_2", "a1_3")) for j in joints]),
    ]


MEASURES = {"point": "point analysis (median)", "compile": "second analysis (compiles Q)",
            "generic": "generic numbers", "locus": "one-slice locus"}


def bench_growth(quick: bool, log=print) -> list[dict]:
    caps = _caps(quick)
    rows: list[dict] = []
    for series, sizes in growth_series(quick):
        fits: dict[str, list[tuple[int, float]]] = {k: [] for k in MEASURES}
        for r, source, free in sizes:
            name = f"{source[0]}{source[1]}"
            log(f"  growth: {name} (r = {r}) ...")
            pts = run_stages(stages_points, (source, 10), ["first", "compile", "points"],
                             caps["point"])
            gen = run_stages(stages_generic, (source,), ["generic"], caps["generic"])
            loc = run_stages(stages_locus, (source, free, caps["locus"], None),
                             ["locus"], caps["locus"] + 15, daemon=False)
            got = {"point": pts["points"], "compile": pts["compile"],
                   "generic": gen["generic"], "locus": loc["locus"]}
            parts = []
            for key, res in got.items():
                if res["status"] != "ok":
                    parts.append(f"{key} {_why(res, caps.get(key, caps['point']))}")
                    continue
                y = res["median"] if key == "point" else res["cpu"]
                if res.get("cut"):           # a partial search says nothing of growth
                    parts.append(f"{key} cut by its bound of {caps['locus']:g} s")
                    continue
                fits[key].append((r, y))
                parts.append(f"{key} {y:.3g} s")
            extra = (f"; {loc['locus']['components']} components"
                     if loc["locus"]["status"] == "ok" else "")
            rows.append(_row(f"growth: {series}", f"{name}, r={r}",
                             pts["points"].get("median") if pts["points"]["status"] == "ok"
                             else None, note="CPU: " + "; ".join(parts) + extra))
        for key, label in MEASURES.items():
            k = fit_exponent(fits[key])
            pts_text = ", ".join(str(x) for x, _ in fits[key])
            rows.append(_row("growth exponent", f"{label}, {series}", note=(
                f"time ~ r^{k:.2f} over r = {pts_text}" if k is not None else
                f"fewer than two sizes finished ({len(fits[key])})"),
                real_plot={"panel": series, "series": label, "points": fits[key],
                           "exponent": k}))
    exps = [(r["case"], r["real_plot"]["exponent"]) for r in rows
            if r.get("real_plot") and r["real_plot"]["exponent"] is not None]
    if exps:
        worst = max(exps, key=lambda x: x[1])
        verdict = "met" if worst[1] <= GROWTH_GOAL else "MISSED"
        rows.append(_row("target", "polynomial growth", note=(
            f"every fitted exponent <= {GROWTH_GOAL:g}: {verdict}; largest {worst[1]:.2f} "
            f"({worst[0]}); all: " + ", ".join(f"{c.split(',')[0]} "
                                                f"[{c.split(', ', 1)[1]}] {k:.2f}"
                                                for c, k in exps))))
    return rows


# ------------------------------------------------------------- 1,000 configurations
def bench_thousand(quick: bool, log=print) -> list[dict]:
    count = 200 if quick else 1000
    cap = _caps(quick)["float"] * (1 if quick else 2)
    source = ("panda_arm", (), {})
    label = "one Panda arm (7 joints, one complete contact)"
    log(f"  {count} configurations of {label}: ours ...")
    ours = run_stages(stages_thousand, (source, count), ["points"], cap * 4)["points"]
    log(f"  {count} configurations of {label}: float pipeline (cap {cap:g} s) ...")
    flt = run_stages(stages_float, (source, count), ["build", "points"], cap)
    case = f"{label}, {count} random exact configurations, compile included"
    rows = []
    if ours["status"] != "ok":
        rows.append(_row("points", case, note=f"ours: {_why(ours, cap * 4)}"))
    else:
        build, fpts = flt["build"], flt["points"]
        note = (f"ours {_wc(ours)} (first call {ours['first']:.3g} s, second "
                f"{ours['second']:.3g} s, then median {ours['median'] * 1e6:.0f} us)")
        if build["status"] == "ok" and fpts["status"] == "ok":
            total = build["seconds"] + fpts["seconds"]
            note += (f"; float build {_wc(build)}, points {fpts['seconds']:.3g} s "
                     f"(median {fpts['median'] * 1e6:.0f} us)")
            lower = False
        else:
            total = cap if build["status"] == "timeout" else None
            note += f"; float build: {_why(build, cap)}"
            lower = True
        rows.append(_row("points", case, ours["seconds"],
                         "lambdified numpy Q + matrix_rank x3, build included", total,
                         note + ("; the ratio is a lower bound (capped)" if lower and total
                                 else "")))
        if total:
            times = ours["seconds"] / total
            verdict = "met" if times <= POINTS_GOAL else "MISSED"
            goal = f"{verdict} ({times:.3g}x{', at most' if lower else ''})"
        else:
            goal = f"not decided (the float build {_why(build, cap)})"
        rows.append(_row("target", f"{count} configurations, {label}", ours["seconds"],
                         note=f"ours <= {POINTS_GOAL:g}x the float pipeline, compile "
                              f"included: {goal}"))
    # the random 7R arm of bench_compile (its float build is the slowest)
    rows += bench_compile.bench_points_of(7, count, cap, log)
    return rows


def run(quick: bool = False, log=print) -> list[dict]:
    """All rows of this benchmark (see the module docstring)."""
    parts = [(label, lambda s=source, f=free, lab=label: measure_system(lab, s, f, quick,
                                                                         log))
             for label, source, free in SYSTEMS]
    parts += [("1,000 configurations", lambda: bench_thousand(quick, log)),
              ("growth", lambda: bench_growth(quick, log))]
    return bench_speed.run_parts(parts)


def plot_real(rows: list[dict], path: Path = PLOT_PATH) -> bool:
    """Log-log figure of the growth rows (one panel per series), fitted exponents in
    the legend."""
    return bench_speed.plot_growth(
        rows, "real_plot", path, size=(6.2, 5.4), rotate=True,
        ylabel="seconds (CPU; point analysis: median wall per point)",
        suptitle="coopkin_sym on real-size systems: cost against size (log-log, fitted "
                 "exponents)")


if __name__ == "__main__":
    argv = sys.argv[1:]
    t0 = time.perf_counter()
    out = run("--quick" in argv, log=lambda m: print(m, file=sys.stderr, flush=True))
    sys.path.insert(0, str(HERE))
    from run import text_table
    print(text_table(out, note_width=400))
    print(f"\n{'quick' if '--quick' in argv else 'full'} run: "
          f"{time.perf_counter() - t0:.0f} s")
    if "--plot" in argv:
        where = Path(argv[argv.index("--plot") + 1])
        if plot_real(out, where):
            print(f"wrote {where}")
