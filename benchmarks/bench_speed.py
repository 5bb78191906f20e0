"""The speed goals, each measured in one run against its baselines (measured, not
asserted).

(1) ``point analysis``: ``System.analyze(at=point).numbers`` per configuration (median
    over random rational configurations, given as a mapping of SymPy values and as
    ``--at`` text) against (a) a lambdified numpy ``Q`` and ``numpy.linalg.matrix_rank``
    of ``Q``, of its object columns and of its joint columns, (b) SymPy
    ``DomainMatrix`` over QQ (the same three ranks and a nullspace of the exact ``Q`` at
    the point) and (c) the floor modulo a 31-bit prime (the three ranks of ``Q`` mod p,
    flint ``nmod_mat``). Goal: ours <= 2x the float pipeline.
(2) ``cold CLI``: wall time of ``python -m coopkin_sym analyze ...`` against
    ``python -c "import sympy"`` and ``python -c "pass"``. Goal: within 1.5x of
    ``import sympy``.
(3) ``generic numbers``: ``System.analyze(generic=True).numbers`` in a fresh worker
    process with a cap, against one exact point analysis and the floor modulo p at one
    point. Goals: ``spatial_hand(5, 2)`` under 1 s; the 5-finger 4-joint hand with
    hard/soft tips under 50x one point analysis.
(4) ``blocks``: ``a.blocks()`` of generic analyses, in a worker with a cap.
(5) ``scale-out``: a 200x200 sweep serially and on a two-worker ``distributed``
    cluster.
(6) ``scaling``: generic numbers, blocks and point analysis against the size of
    spatial hands (fingers at 3 joints, joints at 5 fingers); exponents fitted by least
    squares of log time against log r (``r`` joints), plotted in ``scaling_speed.png``.

Workers start from a fork server that has imported the package (fresh state, no
caches of the parent). ``ratio = baseline_s / ours_s`` (above 1: ours is faster).

Run ``python benchmarks/bench_speed.py [--quick] [--plot FILE]``.
"""

from __future__ import annotations

import compileall
import gc
import math
import multiprocessing as mp
import os
import random
import resource
import statistics
import subprocess
import sys
import time
import traceback
from collections.abc import Callable, Iterator
from fractions import Fraction
from pathlib import Path

import numpy as np
import sympy as sp

import coopkin_sym
from coopkin_sym.model.builders import planar_hand, spatial_hand

HERE = Path(__file__).resolve().parent
MIXED5 = ["hard", "soft", "hard", "soft", "hard"]
PRIME = 2**31 - 1                          # a 31-bit prime
MEMORY_CAP = 6 << 30                       # bytes of address space per worker
POINT_GOAL = 2.0                           # ours <= 2x the float pipeline per point
CLI_GOAL = 1.5                             # CLI within 1.5x of `import sympy`
GENERIC_SMALL_GOAL = 1.0                   # spatial_hand(5, 2) generic numbers, seconds
GENERIC_POINTS_GOAL = 50.0                 # 5x4 hand: generic <= 50 point analyses
PLOT_PATH = HERE / "scaling_speed.png"

BUILDERS: dict[str, Callable] = {"planar_hand": planar_hand, "spatial_hand": spatial_hand}


def _model(source):
    """An example name, or ``(builder, args, kwargs)`` (picklable for the workers)."""
    if isinstance(source, str):
        return source
    name, args, kwargs = source
    return BUILDERS[name](*args, **kwargs)


def _label(source) -> str:
    if isinstance(source, str):
        return source
    name, args, kwargs = source
    extra = "".join(f", {k}={'/'.join(t[0] for t in v) if isinstance(v, list) else v}"
                    for k, v in kwargs.items())
    return f"{name}({', '.join(map(str, args))}{extra})"


def _note_certificate(analysis) -> str:
    """The analysis' ``certificate`` (or its numbers'), where the package gives one."""
    for obj in (analysis, getattr(analysis, "numbers", None)):
        cert = getattr(obj, "certificate", None)
        if cert is not None:
            text = " ".join(str(cert).split())
            return f"; certificate: {text[:200]}{'...' if len(text) > 200 else ''}"
    return ""


def _fmt(n: dict) -> str:
    return " ".join(f"{k}={v}" for k, v in n.items())


# ---------------------------------------------------------------- random configurations
def _params_at_one(system) -> dict[str, int]:
    return {p.name: 1 for p in system.model.parameters}


def random_points(system, rng: random.Random, count: int) -> list[list[Fraction]]:
    """``count`` configurations: ``tan(q/2)`` of each revolute joint (some 0 and +-1),
    the displacement of each prismatic one, all rational."""
    points = []
    for i in range(count):
        values = []
        for j in system.model.joints:
            if j.type == "revolute" and i % 10 == 5:
                values.append(Fraction(rng.choice([0, 1, -1])))
            else:
                values.append(Fraction(rng.randint(-99, 99), rng.randint(1, 99)))
        points.append(values)
    return points


def as_mapping(system, values: list[Fraction]) -> dict:
    out: dict = {}
    for j, v in zip(system.model.joints, values, strict=True):
        rat = sp.Rational(v.numerator, v.denominator)
        out[j.name] = 2 * sp.atan(rat) if j.type == "revolute" else rat
    return {**out, **_params_at_one(system)}


def as_text(system, values: list[Fraction]) -> str:
    parts = [f"{j.name}=2*atan({v})" if j.type == "revolute" else f"{j.name}={v}"
             for j, v in zip(system.model.joints, values, strict=True)]
    return ",".join(parts + [f"{k}={v}" for k, v in _params_at_one(system).items()])


# ------------------------------------------------------------------------- baselines
def float_pipeline(system):
    """A lambdified float ``Q`` of the ``tan(q/2)`` of every joint (displacements for
    prismatic ones), parameters at 1, and its shape. Built from the package's
    kinematics (``Analysis.Q`` of the system with every joint free, without running
    the analysis); falls back to ``analyze(free=...).Q``."""
    at = ",".join(f"{k}={v}" for k, v in _params_at_one(system).items()) or None
    try:
        from coopkin_sym.analysis import kinematics
        from coopkin_sym.exact.sympy_bridge import matrix_to_sympy
        config = system.configuration(at, "all")
        kin = kinematics.build(system.model, config)
        r = len(system.model.joints)
        q = matrix_to_sympy(kin.Q, kin.ring, kin.symbols, (0, 6 + r))
        variables = list(kin.symbols.values())[:r]
    except Exception:                  # the internal layer changed: the public way
        a = system.analyze(at, free=list(system.joint_names))
        q, variables = a.Q, list(a.variables)
    f = sp.lambdify(variables, list(q), modules="numpy", cse=True)  # float-ok
    return f, q.shape


def _float_ranks(mat: np.ndarray, dim: int) -> tuple[int, int, int]:  # float-ok
    return (int(np.linalg.matrix_rank(mat)), int(np.linalg.matrix_rank(mat[:, :dim])),  # float-ok
            int(np.linalg.matrix_rank(mat[:, dim:])))                                  # float-ok


def domain_ranks(q: sp.Matrix, dim: int) -> tuple[tuple[int, int, int], int]:
    """SymPy ``DomainMatrix`` over QQ: the three ranks and the nullity of ``Q``."""
    from sympy.polys.matrices import DomainMatrix
    dm = DomainMatrix.from_Matrix(q).to_field()
    ranks = (dm.rank(), dm[:, :dim].rank(), dm[:, dim:].rank())
    return ranks, dm.nullspace().shape[0]


def modp_entries(q: sp.Matrix, p: int = PRIME) -> list[list[int]]:
    """The exact rational ``Q`` at a point reduced modulo ``p`` (untimed preparation;
    ``None`` if a denominator vanishes mod p)."""
    rows = []
    for i in range(q.rows):
        row = []
        for e in q.row(i):
            num, den = int(sp.numer(e)), int(sp.denom(e))
            if den % p == 0:
                return None
            row.append(num * pow(den, -1, p) % p)
        rows.append(row)
    return rows


def modp_ranks(rows: list[list[int]], dim: int, p: int = PRIME) -> tuple[int, int, int]:
    """The floor: ranks of ``Q``, its object and its joint columns modulo ``p``."""
    import flint
    m, n = len(rows), len(rows[0])
    flat = [x for row in rows for x in row]
    full = flint.nmod_mat(m, n, flat, p)
    obj = flint.nmod_mat(m, dim, [x for row in rows for x in row[:dim]], p)
    jnt = flint.nmod_mat(m, n - dim, [x for row in rows for x in row[dim:]], p)
    return full.rank(), obj.rank(), jnt.rank()


def _ranks_from(numbers: dict, dim: int, r: int) -> tuple[int, int, int]:
    return dim + r - numbers["Nm"], dim - numbers["Ni"], r - numbers["Nr"]


# ------------------------------------------------------------------- (1) point analysis
POINT_CASES = ["paper-case2-hard", ("planar_hand", (4, 3), {}),
               ("spatial_hand", (5, 4), {"tips": MIXED5})]


def _timed(fn: Callable, *args) -> tuple:
    """``fn(*args)`` and its wall time, with the garbage collector paused as ``timeit``
    does: the methods take turns at each point, and none is charged for collecting the
    garbage of another."""
    gc.collect()
    gc.disable()
    try:
        t0 = time.perf_counter()
        out = fn(*args)
        return out, time.perf_counter() - t0
    finally:
        gc.enable()


def _analysis_numbers(system, at):
    """The public point analysis, numbers computed (the analysis returned)."""
    a = system.analyze(at=at)
    _ = a.numbers
    return a


def _float_point(f, angles, revolute, shape, dim):
    """The float pipeline at one point: ``tan(q/2)``, the lambdified ``Q``, three SVD
    ranks."""
    args = [math.tan(x / 2) if rev else x for x, rev in zip(angles, revolute,  # float-ok
                                                             strict=True)]
    return _float_ranks(np.array(f(*args), dtype=float).reshape(*shape), dim)  # float-ok


def bench_point(source, count: int, log=print) -> list[dict]:
    system = coopkin_sym.load(_model(source))
    label = _label(source)
    r, dim = len(system.model.joints), system.model.object_dim
    rng = random.Random(7)
    points = random_points(system, rng, count)
    text_points = random_points(system, random.Random(8), count)
    warm = random_points(system, random.Random(9), 1)[0]
    t0 = time.perf_counter()
    first = system.analyze(at=as_mapping(system, warm))
    _ = first.numbers
    first_s = time.perf_counter() - t0
    t0 = time.perf_counter()
    f, (m, cols) = float_pipeline(system)
    lambdify_s = time.perf_counter() - t0
    revolute = [j.type == "revolute" for j in system.model.joints]
    ours, ours_text, flt, dom, modp = [], [], [], [], []
    float_wrong = dom_wrong = modp_wrong = 0
    cert = ""
    log(f"  point analysis: {label}, {count} points ...")
    for values, tvalues in zip(points, text_points, strict=True):
        mapping, text = as_mapping(system, values), as_text(system, tvalues)
        angles = [2 * math.atan2(v.numerator, v.denominator) if rev  # float-ok
                  else v.numerator / v.denominator for v, rev in zip(values, revolute,  # float-ok
                                                                    strict=True)]
        a, seconds = _timed(_analysis_numbers, system, mapping)
        ours.append(seconds)
        numbers = a.numbers.as_dict()
        cert = cert or _note_certificate(a)
        ours_text.append(_timed(_analysis_numbers, system, text)[1])
        exact = _ranks_from(numbers, dim, r)

        # (a) floats: tan(q/2), lambdified Q, three SVD ranks
        franks, seconds = _timed(_float_point, f, angles, revolute, (m, cols), dim)
        flt.append(seconds)
        float_wrong += franks != exact
        # (b) SymPy DomainMatrix over QQ of the exact Q at the point (Q untimed)
        q = a.Q
        (dranks, _nullity), seconds = _timed(domain_ranks, q, dim)
        dom.append(seconds)
        dom_wrong += dranks != exact
        # (c) the floor: ranks mod p (entries reduced mod p untimed)
        rows = modp_entries(q)
        if rows is not None:
            pranks, seconds = _timed(modp_ranks, rows, dim)
            modp.append(seconds)
            modp_wrong += pranks != exact
    med = statistics.median
    o, ot = med(ours), med(ours_text)
    case = f"{label}, r={r}, median of {count} random rational configurations"
    common = (f"first call {first_s:.3f} s and lambdify {lambdify_s:.3f} s excluded; "
              f"Q {m}x{cols}{cert}")
    rows_out = [
        {"benchmark": "point analysis", "case": case + " (mapping)", "ours_s": o,
         "baseline": "lambdified numpy Q + numpy.linalg.matrix_rank x3",
         "baseline_s": med(flt), "ratio": med(flt) / o,
         "note": f"{common}; float ranks differ from exact at {float_wrong}"},
        {"benchmark": "point analysis", "case": case + " (--at text)", "ours_s": ot,
         "baseline": "lambdified numpy Q + numpy.linalg.matrix_rank x3",
         "baseline_s": med(flt), "ratio": med(flt) / ot,
         "note": "the same as text \"q=2*atan(p/q),...,L=1\" (other random points)"},
        {"benchmark": "point analysis", "case": case + " (mapping)", "ours_s": o,
         "baseline": "SymPy DomainMatrix QQ: from_Matrix + rank x3 + nullspace",
         "baseline_s": med(dom), "ratio": med(dom) / o,
         "note": f"exact Q at the point from a.Q (untimed); ranks differ at {dom_wrong}"},
        {"benchmark": "point analysis", "case": case + " (mapping)", "ours_s": o,
         "baseline": f"floor: flint nmod_mat rank x3 mod {PRIME}",
         "baseline_s": med(modp) if modp else None,
         "ratio": med(modp) / o if modp else None,
         "note": f"entries reduced mod p untimed; {len(modp)} points; ranks mod p differ "
                 f"from exact at {modp_wrong} (where p is unlucky)"},
    ]
    base = med(flt)
    parts = []
    for what, v in (("mapping", o), ("text", ot)):
        verdict = "met" if v <= POINT_GOAL * base else "MISSED"
        parts.append(f"{verdict} ({what}): {v / base:.1f}x the float pipeline")
    rows_out.append({"benchmark": "target", "case": f"point analysis, {label}",
                     "ours_s": o, "baseline": None, "baseline_s": None, "ratio": None,
                     "note": f"ours <= {POINT_GOAL:g}x the float pipeline per point: "
                             + "; ".join(parts)})
    return rows_out


# ------------------------------------------------------------------------ (2) cold CLI
def _walls(cmds: dict[str, list[str]], env: dict, repeats: int
           ) -> dict[str, tuple[float, int]]:
    """Median wall time and any nonzero exit code of each command, the commands run in
    turn ``repeats`` times (interleaved, so that a busy moment slows all of them)."""
    times: dict[str, list[float]] = {k: [] for k in cmds}
    rcs = dict.fromkeys(cmds, 0)
    for _ in range(repeats):
        for key, cmd in cmds.items():
            t0 = time.perf_counter()
            proc = subprocess.run(cmd, env=env, stdout=subprocess.DEVNULL,
                                  stderr=subprocess.PIPE, check=False)
            times[key].append(time.perf_counter() - t0)
            rcs[key] = rcs[key] or proc.returncode
    return {k: (statistics.median(v), rcs[k]) for k, v in times.items()}


def bench_cli(repeats: int, log=print) -> list[dict]:
    root = str(Path(coopkin_sym.__file__).resolve().parents[1])
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([root] + ([env["PYTHONPATH"]]
                                                  if env.get("PYTHONPATH") else []))
    py = sys.executable
    at = "q1=pi/2,L=1"
    # byte-compiled first, as a regular install is (an editable one under
    # PYTHONDONTWRITEBYTECODE would compile every module at every start)
    compileall.compile_dir(str(Path(coopkin_sym.__file__).resolve().parent), quiet=1)
    log(f"  cold CLI: {repeats} runs of each command ...")
    walls = _walls({"cli": [py, "-m", "coopkin_sym", "analyze", "paper-case2-hard", "--at",
                            at],
                    "import cli": [py, "-c", "import coopkin_sym.cli"],
                    "import sympy": [py, "-c", "import sympy"],
                    "bare": [py, "-c", "pass"]}, env, repeats)
    (cli, cli_rc), (imp_cli, _) = walls["cli"], walls["import cli"]
    imp_sympy, bare = walls["import sympy"][0], walls["bare"][0]
    case = f"python -m coopkin_sym analyze paper-case2-hard --at \"{at}\""
    head = (f"median of {repeats} interleaved runs, package byte-compiled"
            + (f"; CLI exit code {cli_rc}" if cli_rc else ""))
    rows = [
        {"benchmark": "cold CLI", "case": case, "ours_s": cli,
         "baseline": "python -c \"import sympy\"", "baseline_s": imp_sympy,
         "ratio": imp_sympy / cli, "note": head},
        {"benchmark": "cold CLI", "case": case, "ours_s": cli,
         "baseline": "python -c \"pass\"", "baseline_s": bare, "ratio": bare / cli,
         "note": head},
        {"benchmark": "cold CLI", "case": "python -c \"import coopkin_sym.cli\"",
         "ours_s": imp_cli, "baseline": "python -c \"import sympy\"", "baseline_s": imp_sympy,
         "ratio": imp_sympy / imp_cli,
         "note": f"{head}; the analysis itself is about {max(cli - imp_cli, 0):.3f} s"},
    ]
    verdict = "met" if cli <= CLI_GOAL * imp_sympy else "MISSED"
    rows.append({"benchmark": "target", "case": "cold CLI", "ours_s": cli, "baseline": None,
                 "baseline_s": None, "ratio": None,
                 "note": f"CLI within {CLI_GOAL:g}x of `import sympy`: {verdict}, "
                         f"{cli / imp_sympy:.2f}x ({cli:.2f} s vs {imp_sympy:.2f} s; "
                         f"bare interpreter {bare:.2f} s)"})
    return rows


# --------------------------------------------------------- capped workers with stages
def stages_generic(source, blocks: bool) -> Iterator[dict]:
    """Generic numbers, then (if ``blocks``) ``a.blocks()``, one message per stage."""
    system = coopkin_sym.load(_model(source))
    t0 = time.perf_counter()
    a = system.analyze(generic=True)
    numbers = a.numbers.as_dict()
    yield {"stage": "numbers", "seconds": time.perf_counter() - t0, "numbers": numbers,
           "r": len(system.model.joints), "certificate": _note_certificate(a)}
    if blocks:
        t0 = time.perf_counter()
        b = a.blocks()
        shapes = {k: tuple(v.shape) for k, v in b.items()}
        yield {"stage": "blocks", "seconds": time.perf_counter() - t0, "shapes": shapes}


def stages_point(source, count: int, floor: bool = True) -> Iterator[dict]:
    """The exact analysis at one point (median over ``count`` points after a first
    call), then (if ``floor``) the floor mod p at one point."""
    system = coopkin_sym.load(_model(source))
    dim = system.model.object_dim
    pts = random_points(system, random.Random(3), count + 1)
    t0 = time.perf_counter()
    a = system.analyze(at=as_mapping(system, pts[0]))
    numbers = a.numbers.as_dict()
    first = time.perf_counter() - t0
    times = []
    for values in pts[1:]:
        t0 = time.perf_counter()
        a = system.analyze(at=as_mapping(system, values))
        numbers = a.numbers.as_dict()
        times.append(time.perf_counter() - t0)
    yield {"stage": "point", "seconds": statistics.median(times), "first_s": first,
           "numbers": numbers, "certificate": _note_certificate(a)}
    if not floor:
        return
    rows = modp_entries(a.Q)
    t0 = time.perf_counter()
    if rows is not None:
        modp_ranks(rows, dim)
    yield {"stage": "modp", "seconds": time.perf_counter() - t0 if rows else None}


def _stage_worker(conn, func, args):
    try:
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_CAP, MEMORY_CAP))
    except (ValueError, OSError):
        pass
    t0 = time.perf_counter()
    try:
        for msg in func(*args):
            conn.send({"status": "ok", **msg})
            t0 = time.perf_counter()
    except MemoryError:
        conn.send({"status": "memory", "seconds": time.perf_counter() - t0})
    except BaseException as exc:  # reported in the table, never hidden
        conn.send({"status": "error", "seconds": time.perf_counter() - t0,
                   "message": f"{type(exc).__name__}: {str(exc)[:200]}",
                   "trace": traceback.format_exc(limit=3)})
    finally:
        conn.close()


_CTX = None


def _context():
    """A fork server that has imported the package: fresh workers, no parent caches."""
    global _CTX
    if _CTX is None:
        if "forkserver" in mp.get_all_start_methods():
            _CTX = mp.get_context("forkserver")
            _CTX.set_forkserver_preload(["coopkin_sym", "sympy", "numpy", "flint"])
        else:
            _CTX = mp.get_context("spawn")
    return _CTX


def run_stages(func, args, stages: list[str], cap: float, daemon: bool = True
               ) -> dict[str, dict]:
    """Run the generator ``func(*args)`` in a worker; each stage (one message) gets
    ``cap`` seconds. Returns ``{stage: result}`` with ``status`` ``ok | timeout |
    memory | error | died | not run``. A worker that starts processes of its own (a
    bounded locus search, a certificate) is not a daemon (``daemon=False``)."""
    ctx = _context()
    parent, child = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=_stage_worker, args=(child, func, args), daemon=daemon)
    proc.start()
    child.close()
    results: dict[str, dict] = {}
    last = time.perf_counter()

    def pending() -> str | None:
        return next((s for s in stages if s not in results), None)

    while pending() is not None:
        if parent.poll(0.02):
            try:
                msg = parent.recv()
            except EOFError:
                results[pending()] = {"status": "died", "seconds": time.perf_counter() - last,
                                      "message": f"worker exit code {proc.exitcode}"}
                break
            if msg["status"] == "ok":
                results[msg["stage"]] = msg
                last = time.perf_counter()
                continue
            results[pending()] = msg
            break
        if not proc.is_alive() and not parent.poll():
            proc.join()
            results[pending()] = {"status": "died", "seconds": time.perf_counter() - last,
                                  "message": f"worker exit code {proc.exitcode}"}
            break
        if time.perf_counter() - last > cap:
            proc.kill()
            results[pending()] = {"status": "timeout", "seconds": cap}
            break
    proc.join(5)
    if proc.is_alive():
        proc.kill()
        proc.join()
    parent.close()
    for s in stages:
        results.setdefault(s, {"status": "not run", "seconds": None})
    return results


def _why(res: dict, cap: float) -> str:
    status = res["status"]
    if status == "timeout":
        return f"did not finish in {cap:g} s"
    if status == "memory":
        return f"ran out of memory ({MEMORY_CAP >> 30} GB cap)"
    if status == "died" and "-6" in res.get("message", ""):
        return "aborted (SIGABRT; FLINT aborts when an allocation fails)"
    return f"{status}: {res.get('message', '')}".rstrip(": ")


# -------------------------------------------------------------- (3) generic numbers
def bench_generic_numbers(quick: bool, log=print) -> list[dict]:
    cap = 20.0 if quick else 120.0
    cases = [(("spatial_hand", (5, 2), {}), "small"),
             (("spatial_hand", (5, 4), {"tips": MIXED5}), "points")]
    rows = []
    for source, goal in cases:
        label = _label(source)
        log(f"  generic numbers: {label} (cap {cap:g} s) ...")
        gen = run_stages(stages_generic, (source, False), ["numbers"], cap)["numbers"]
        pt = run_stages(stages_point, (source, 3 if quick else 10), ["point", "modp"], cap)
        ok = gen["status"] == "ok"
        ours = gen["seconds"] if ok else (cap if gen["status"] == "timeout" else None)
        capped = gen["status"] == "timeout"
        head = (f"{_fmt(gen['numbers'])}{gen['certificate']}" if ok
                else f"ours {_why(gen, cap)}")
        if capped:
            head += "; ours_s is the cap, ratio an upper bound"
        for stage, what in (("point", "one exact point analysis (median, warm)"),
                            ("modp", f"floor: ranks x3 of Q mod {PRIME} at one point")):
            res = pt[stage]
            bs = res["seconds"] if res["status"] == "ok" else None
            note = head if bs is not None else f"{head}; baseline {_why(res, cap)}"
            rows.append({"benchmark": "generic numbers", "case": label, "ours_s": ours,
                         "baseline": what, "baseline_s": bs,
                         "ratio": bs / ours if bs and ours else None, "note": note})
        if goal == "small":
            target = f"generic numbers < {GENERIC_SMALL_GOAL:g} s"
            verdict = ("met" if ok and ours < GENERIC_SMALL_GOAL else "MISSED")
            detail = (f"{'>= ' if capped else ''}{ours:.2f} s" if ours is not None
                      else _why(gen, cap))
        else:
            target = f"generic numbers < {GENERIC_POINTS_GOAL:g}x one point analysis"
            point_s = pt["point"]["seconds"] if pt["point"]["status"] == "ok" else None
            if ours is None or point_s is None:
                verdict, detail = "MISSED", "not measured"
            else:
                times = ours / point_s
                verdict = "met" if ok and times < GENERIC_POINTS_GOAL else "MISSED"
                detail = f"{'>= ' if capped else ''}{times:.0f}x ({ours:.2f} s vs {point_s:.4f} s)"
        rows.append({"benchmark": "target", "case": f"generic numbers, {label}",
                     "ours_s": ours, "baseline": None, "baseline_s": None, "ratio": None,
                     "note": f"{target}: {verdict}, {detail}"})
    return rows


# ----------------------------------------------------------------------- (4) blocks
def bench_blocks(quick: bool, log=print) -> list[dict]:
    cap = 30.0 if quick else 120.0
    rows = []
    for source in ("paper-case2-hard", ("planar_hand", (4, 2), {})):
        label = _label(source)
        log(f"  blocks: {label} (cap {cap:g} s) ...")
        res = run_stages(stages_generic, (source, True), ["numbers", "blocks"], cap)
        num, blk = res["numbers"], res["blocks"]
        if blk["status"] == "ok":
            ours = blk["seconds"]
            note = ", ".join(f"{k} {v[0]}x{v[1]}" for k, v in blk["shapes"].items())
        else:
            ours = cap if blk["status"] == "timeout" else None
            note = f"blocks {_why(blk, cap)}" if num["status"] == "ok" else \
                f"generic numbers {_why(num, cap)}"
        rows.append({"benchmark": "blocks", "case": f"{label}, generic a.blocks()",
                     "ours_s": ours, "baseline": "generic numbers of the same analysis",
                     "baseline_s": num["seconds"] if num["status"] == "ok" else None,
                     "ratio": None, "note": note})
    return rows


# -------------------------------------------------------------------- (5) scale-out
def bench_scale_out(quick: bool, log=print) -> list[dict]:
    n = 50 if quick else 200
    case = f"paper-case2-hard, q2 x q3 grid {n}x{n} (L=1)"
    try:
        import distributed
    except ImportError:
        return [{"benchmark": "scale-out", "case": case, "ours_s": None, "baseline": None,
                 "baseline_s": None, "ratio": None,
                 "note": "distributed is not installed (pip install distributed); not run"}]
    import logging

    from coopkin_sym.analysis.sweep import grid
    system = coopkin_sym.load("paper-case2-hard")
    spec = f"q2=-pi/2..pi/2:{n},q3=-pi..pi:{n}"
    points = grid(system, spec)
    log(f"  scale-out: serial sweep {n}x{n} ...")
    serial = []
    for _ in range(2):
        t0 = time.perf_counter()
        res_serial = system.sweep(points, at="L=1")
        serial.append(time.perf_counter() - t0)
    log("  scale-out: LocalCluster(2 workers) ...")
    t0 = time.perf_counter()
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=None,
                                       silence_logs=logging.ERROR)
    client = distributed.Client(cluster)
    start_s = time.perf_counter() - t0
    para = []
    try:
        executor = client.get_executor()
        for _ in range(2):
            t0 = time.perf_counter()
            res_para = system.sweep(points, at="L=1", executor=executor)
            para.append(time.perf_counter() - t0)
    finally:
        client.close()
        cluster.close()
    same = bool(np.array_equal(res_serial.numbers, res_para.numbers))
    return [{"benchmark": "scale-out", "case": case, "ours_s": para[1],
             "baseline": "the same sweep serially (no executor)", "baseline_s": serial[1],
             "ratio": serial[1] / para[1],
             "note": f"ours: distributed.LocalCluster(n_workers=2, threads_per_worker=1) "
                     f"via client.get_executor(), second run (first {para[0]:.2f} s; "
                     f"cluster start {start_s:.1f} s excluded); serial first run "
                     f"{serial[0]:.2f} s; numbers {'agree' if same else 'DIFFER'}; "
                     f"{os.cpu_count()} CPUs"}]


# ---------------------------------------------------------------------- (6) scaling
STAGE_NAMES = {"numbers": "generic numbers", "blocks": "blocks", "point": "point analysis"}


def scaling_series(quick: bool) -> list[tuple[str, list[tuple[int, int]]]]:
    """Spatial hands: fingers at 3 joints, and joints at 5 fingers (3 in quick)."""
    if quick:
        return [("f fingers x 3 joints", [(f, 3) for f in range(2, 5)]),
                ("3 fingers x j joints", [(3, j) for j in range(2, 5)])]
    return [("f fingers x 3 joints", [(f, 3) for f in range(2, 9)]),
            ("5 fingers x j joints", [(5, j) for j in range(2, 6)])]


def fit_exponent(pts: list[tuple[float, float]]) -> float | None:
    """Least-squares slope of log y against log x (``None`` below two sizes)."""
    if len({x for x, _ in pts}) < 2:
        return None
    lx = np.log([x for x, _ in pts])                                 # float-ok: a fit
    ly = np.log([y for _, y in pts])                                 # float-ok
    return float(np.polyfit(lx, ly, 1)[0])                           # float-ok


def bench_scaling(quick: bool, log=print) -> list[dict]:
    """One worker per size for the generic numbers and blocks, one for the point
    analysis. A series stops (for that measurement) after two sizes in a row hit the
    cap: cost is not monotone in size (``spatial_hand(5, 2)`` is far slower than
    ``spatial_hand(5, 3)``), so one capped size does not end it."""
    cap = 10.0 if quick else 60.0
    rows: list[dict] = []
    for series, sizes in scaling_series(quick):
        stopped: dict[str, str] = {}
        capped_in_a_row = {s: 0 for s in STAGE_NAMES}
        points: dict[str, list[tuple[int, float]]] = {s: [] for s in STAGE_NAMES}
        for f, j in sizes:
            source = ("spatial_hand", (f, j), {})
            r = f * j
            log(f"  scaling: spatial_hand({f}, {j}) (cap {cap:g} s) ...")
            res: dict[str, dict] = {}
            if "numbers" in stopped:
                res["numbers"] = res["blocks"] = {"status": "skipped"}
            else:
                res.update(run_stages(stages_generic, (source, True), ["numbers", "blocks"],
                                      cap))
            if "point" in stopped:
                res["point"] = {"status": "skipped"}
            else:
                res.update({"point": run_stages(stages_point, (source, 3, False), ["point"],
                                                cap)["point"]})
            for stage, name in STAGE_NAMES.items():
                rr = res[stage]
                if rr["status"] == "ok":
                    capped_in_a_row[stage] = 0
                    points[stage].append((r, rr["seconds"]))
                    note = f"r={r}"
                    if stage == "numbers":
                        note += f"; {_fmt(rr['numbers'])}{rr['certificate']}"
                elif rr["status"] == "skipped":
                    note = f"r={r}; not run: {stopped[stage if stage != 'blocks' else 'numbers']}"
                elif rr["status"] == "not run":
                    note = f"r={r}; not run: the generic numbers did not finish"
                else:
                    why = _why(rr, cap)
                    note = f"r={r}; {why}"
                    capped_in_a_row[stage] += rr["status"] == "timeout"
                    if capped_in_a_row[stage] >= 2 and stage != "blocks":
                        stopped[stage] = (f"{why} on spatial_hand({f}, {j}) and the size "
                                          f"before")
                rows.append({"benchmark": f"scaling: {name}", "case":
                             f"spatial_hand({f}, {j}), series {series}",
                             "ours_s": rr["seconds"] if rr["status"] == "ok" else None,
                             "baseline": None, "baseline_s": None, "ratio": None,
                             "note": note})
        for stage, name in STAGE_NAMES.items():
            pts = points[stage]
            k = fit_exponent(pts)
            rows.append({"benchmark": "scaling exponent", "case": f"{name}, {series}",
                         "ours_s": None, "baseline": None, "baseline_s": None,
                         "ratio": None,
                         "note": (f"time ~ r^{k:.2f} (least squares over r = "
                                  f"{', '.join(str(x) for x, _ in pts)})" if k is not None
                                  else f"fewer than two sizes finished ({len(pts)})"),
                         "speed_plot": {"panel": series, "series": name, "points": pts,
                                        "exponent": k}})
    return rows


def run_parts(parts: list[tuple[str, Callable[[], list[dict]]]]) -> list[dict]:
    """The rows of each ``(name, part)`` in turn; a part that fails is one row saying
    why (its traceback on stderr), and the others still run."""
    rows: list[dict] = []
    for name, part in parts:
        try:
            rows += part()
        except Exception as exc:
            traceback.print_exc()
            rows.append({"benchmark": name, "case": "(failed)", "ours_s": None,
                         "baseline": None, "baseline_s": None, "ratio": None,
                         "note": f"{type(exc).__name__}: {exc}"})
    return rows


def plot_speed(rows: list[dict], path: Path = PLOT_PATH) -> bool:
    """Log-log figure of the scaling rows (one panel per series of hands), the fitted
    exponents in the legend."""
    return plot_growth(rows, "speed_plot", path, panel_title="spatial hands, {}",
                       suptitle="coopkin_sym speed: cost against hand size (log-log, "
                                "fitted exponents)")


def plot_growth(rows: list[dict], key: str, path: Path, *, panel_title: str = "{}",
                suptitle: str, ylabel: str = "seconds", size: tuple = (6.5, 5.5),
                rotate: bool = False) -> bool:
    """Log-log figure of the rows carrying ``key`` (``{"panel", "series", "points",
    "exponent"}``): one panel per ``panel``, one line per series, the fitted exponents
    in the legend. Returns whether there was anything to draw."""
    panels: dict[str, list[dict]] = {}
    for r in rows:
        p = r.get(key)
        if p and p["points"]:
            panels.setdefault(p["panel"], []).append(p)
    if not panels:
        return False
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import NullFormatter, ScalarFormatter
    fig, axes = plt.subplots(1, len(panels), figsize=(size[0] * len(panels), size[1]),
                             squeeze=False)
    for ax, (title, series) in zip(axes[0], panels.items(), strict=True):
        xs = set()
        for k, s in enumerate(series):
            pts = sorted(s["points"])
            xs.update(x for x, _ in pts)
            exp = f"r^{s['exponent']:.2f}" if s["exponent"] is not None else "no fit"
            ax.plot([x for x, _ in pts], [y for _, y in pts], "-", marker="os^D"[k % 4],
                    markersize=4, label=f"{s['series']} ({exp})")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.xaxis.set_major_formatter(ScalarFormatter())
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_xticks(sorted(xs))
        if rotate:
            ax.tick_params(axis="x", labelrotation=45)
        ax.set_xlabel("joints r")
        ax.set_ylabel(ylabel)
        ax.set_title(panel_title.format(title))
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, loc="best", framealpha=0.7)
    fig.suptitle(suptitle)
    fig.tight_layout()
    tmp = path.with_name(path.stem + ".tmp.png")
    fig.savefig(tmp, dpi=110)
    plt.close(fig)
    os.replace(tmp, path)
    return True


# ---------------------------------------------------------------------------- all
def run(quick: bool = False, log=print) -> list[dict]:
    """All rows of this benchmark (see the module docstring)."""
    rows: list[dict] = []
    count = 20 if quick else 200
    parts: list[tuple[str, Callable[[], list[dict]]]] = [
        (f"point analysis {_label(s)}", lambda s=s: bench_point(s, count, log))
        for s in POINT_CASES]
    parts += [("cold CLI", lambda: bench_cli(3 if quick else 11, log)),
              ("generic numbers", lambda: bench_generic_numbers(quick, log)),
              ("blocks", lambda: bench_blocks(quick, log)),
              ("scale-out", lambda: bench_scale_out(quick, log)),
              ("scaling", lambda: bench_scaling(quick, log))]
    rows += run_parts(parts)
    return rows


if __name__ == "__main__":
    argv = sys.argv[1:]
    out = run("--quick" in argv, log=lambda m: print(m, file=sys.stderr, flush=True))
    sys.path.insert(0, str(HERE))
    from run import text_table
    print(text_table(out, note_width=110))
    if "--plot" in argv:
        where = Path(argv[argv.index("--plot") + 1])
        if plot_speed(out, where):
            print(f"wrote {where}")
