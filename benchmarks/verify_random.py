"""The locus search on many small random systems, each checked by the independent
verifier (measured, not asserted).

For each seed, ``random_system(seed)`` (two planar arms of two joints, every pair of
contact models over 16 seeds; see ``tests/random_systems.py``) is run in its own
process with an address-space limit and a hard wall-clock kill: ``compute_locus`` under
its own time bound (``--timeout``), then ``verify_locus(system, locus, max_points=1500,
lines=6, seed=seed)``. One row per system, and a total:

* ``uncovered``: points with non-generic numbers on no component with those numbers;
* ``unsound``: components shown wrong (witness, ranks above the claimed ones);
* ``status``: ``ok``, ``FAIL`` (uncovered or unsound with the search finished),
  ``timeout`` (the search was cut by its bound; uncovered points then are expected),
  ``killed`` (hard wall-clock or memory limit) or ``error``.

Each result is appended as one JSON line to ``--out`` (default
``benchmarks/results/verify_random.jsonl``); seeds already there are skipped, so an
interrupted run resumes. ``--report`` writes the table as markdown. ``--certify S``
also certifies each locus (``certify_locus``, S seconds in all, 30 s per test, on the
backends installed): the ``cert`` column, and a total of the certified systems that the
verifier found wrong (which must be none).

Run ``python benchmarks/verify_random.py --seeds 20..219,0..19 --timeout 120``.
"""

from __future__ import annotations

import argparse
import faulthandler
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

from random_systems import degeneracies, random_system  # noqa: E402

DEFAULT_OUT = HERE / "results" / "verify_random.jsonl"
ROOT = HERE.parent
GIB = 1 << 30


def parse_seeds(text: str) -> list[int]:
    """Seeds from ``A..B`` (inclusive) and single numbers, comma separated, in order."""
    seeds: list[int] = []
    for part in text.split(","):
        part = part.strip()
        if ".." in part:
            a, b = part.split("..", 1)
            seeds += range(int(a), int(b) + 1)
        elif part:
            seeds.append(int(part))
    return list(dict.fromkeys(seeds))


def describe(seed: int) -> dict:
    model = random_system(seed)
    joints = "".join("R" if j["type"] == "revolute" else "P"
                     for a in model["arms"] for j in a["joints"])
    return {"seed": seed, "models": "/".join(c["model"] for c in model["contacts"]),
            "joints": joints, "degenerate": degeneracies(model)}


def run_one(seed: int, timeout: float, lines: int, max_points: int,
            certify: float = 0.0) -> dict:
    """Search and verify one system (in this process); the result row. With
    ``certify`` (seconds for the whole certificate), the locus is also certified on
    the backends installed (30 s per test at most)."""
    import coopkin_sym
    from coopkin_sym.analysis.locus.search import compute_locus
    from coopkin_sym.analysis.locus.verify import verify_locus
    from coopkin_sym.errors import TimeLimitReached
    from coopkin_sym.present.remarks import remark_texts

    row = describe(seed)
    row["source"] = str(Path(coopkin_sym.__file__).parent.parent)
    system = coopkin_sym.load(random_system(seed))
    started = time.monotonic()
    with tempfile.TemporaryFile("w+") as dump:
        # where the search is when 90% of its time is gone (a slow step, for triage)
        faulthandler.dump_traceback_later(0.9 * timeout, file=dump)
        try:
            locus = compute_locus(system, timeout=timeout)
        except TimeLimitReached as exc:
            locus = None
            row.update(status="timeout", detail=str(exc))
        faulthandler.cancel_dump_traceback_later()
        dump.seek(0)
        stack = [x.strip() for x in dump.read().splitlines() if "coopkin_sym" in x]
    row["locus_s"] = round(time.monotonic() - started, 2)
    if stack:
        row["stack_at_90pct"] = stack
    if locus is None:
        return row
    row["components"] = len(locus.components)
    row["generic"] = locus.generic
    row["unexplored"] = remark_texts(locus.unexplored)
    row["timed_out"] = any(u.kind.startswith("time_") for u in locus.unexplored)
    row["locus"] = locus.to_json()
    started = time.monotonic()
    v = verify_locus(system, locus, max_points=max_points, lines=lines, seed=seed)
    row["verify_s"] = round(time.monotonic() - started, 2)
    row["uncovered"] = v.uncovered_total
    row["unsound"] = len(v.unsound_components)
    row["unchecked"] = len(v.unchecked)
    row["grid_points"], row["grid_drops"] = v.grid_points, v.grid_drops
    row["line_points"], row["line_drops"] = v.line_points, v.line_drops
    row["uncovered_points"] = [vars(u) | {} for u in v.uncovered[:40]]
    row["unsound_issues"] = [vars(i) | {} for i in v.unsound[:40]]
    if row["timed_out"]:
        row["status"] = "timeout"
    else:
        row["status"] = "ok" if v.ok else "FAIL"
    if certify > 0:
        from coopkin_sym.analysis.locus.certify import certify_locus
        from coopkin_sym.present.remarks import remark_text
        started = time.monotonic()
        cert = certify_locus(system, locus, timeout=min(30.0, certify), budget=certify)
        row["cert_s"] = round(time.monotonic() - started, 2)
        row["certified"] = cert.certified
        row["cert_failures"] = [f"{c.where()}: {remark_text(c.why) if c.why else '?'}"
                                for c in cert.checks if not c.certified][:5]
        row["cert_real_only"] = sum(c.why is not None and c.why.kind == "cert_real_points_only"
                                    for c in cert.checks)
    return row


def _limit_memory(gib: float) -> None:
    limit = int(gib * GIB)
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def run_isolated(seed: int, args) -> dict:
    """``run_one`` in a child process with a memory limit and a hard wall-clock kill."""
    cmd = [sys.executable, __file__, "--one", str(seed), "--timeout", str(args.timeout),
           "--lines", str(args.lines), "--max-points", str(args.max_points),
           "--certify", str(args.certify)]
    env = dict(os.environ, PYTHONPATH=str(args.source))
    started = time.monotonic()
    try:
        done = subprocess.run(cmd, capture_output=True, text=True, timeout=args.hard, env=env,
                              preexec_fn=lambda: _limit_memory(args.memory), check=False)
    except subprocess.TimeoutExpired:
        return describe(seed) | {"status": "killed", "detail": f"hard bound {args.hard} s",
                                 "locus_s": round(time.monotonic() - started, 2)}
    lines = [x for x in done.stdout.splitlines() if x.startswith("{")]
    if done.returncode == 0 and lines:
        return json.loads(lines[-1])
    tail = (done.stderr or "").strip().splitlines()[-3:]
    status = "killed" if "MemoryError" in (done.stderr or "") else "error"
    if done.returncode < 0:
        tail.append(f"killed by signal {-done.returncode}")
    return describe(seed) | {"status": status, "detail": " | ".join(tail),
                             "locus_s": round(time.monotonic() - started, 2)}


COLUMNS = ("seed", "models", "joints", "comps", "locus_s", "verify_s", "uncov", "unsound",
           "status", "cert")


def _cert(r: dict) -> str:
    """The certificate in a word: ``yes`` (with the tests proved at real points only),
    ``no``, or ``-`` when not run."""
    if "certified" not in r:
        return "-"
    if not r["certified"]:
        return "no"
    return f"yes ({r['cert_real_only']} real)" if r.get("cert_real_only") else "yes"


def table_row(r: dict) -> list[str]:
    return [str(r["seed"]), r["models"], r["joints"], str(r.get("components", "-")),
            f"{r.get('locus_s', 0):.1f}", f"{r.get('verify_s', 0):.1f}",
            str(r.get("uncovered", "-")), str(r.get("unsound", "-")), r["status"], _cert(r)]


def totals(rows: list[dict]) -> dict:
    times = [r.get("locus_s", 0) + r.get("verify_s", 0) for r in rows]
    count = {s: sum(r["status"] == s for r in rows)
             for s in ("ok", "FAIL", "timeout", "killed", "error")}
    certified = [r for r in rows if r.get("certified")]
    return {"systems": len(rows), **count,
            "with uncovered": sum(bool(r.get("uncovered")) for r in rows),
            "with unsound": sum(bool(r.get("unsound")) for r in rows),
            "certificates run": sum("certified" in r for r in rows),
            "certified": len(certified),
            "certified with uncovered or unsound": sum(
                bool(r.get("uncovered") or r.get("unsound")) for r in certified),
            "median s": round(statistics.median(times), 1) if times else 0,
            "max s": round(max(times), 1) if times else 0}


def markdown(rows: list[dict]) -> str:
    out = ["| " + " | ".join(COLUMNS) + " |", "|" + "---|" * len(COLUMNS)]
    out += ["| " + " | ".join(table_row(r)) + " |" for r in sorted(rows, key=_order)]
    t = totals(rows)
    out += ["", "Total: " + ", ".join(f"{k} {v}" for k, v in t.items())]
    return "\n".join(out) + "\n"


def _order(r: dict):
    return r["seed"]


def read_results(path: Path) -> dict[int, dict]:
    done: dict[int, dict] = {}
    if path.exists():
        for line in path.read_text().splitlines():
            if line.strip():
                r = json.loads(line)
                done[r["seed"]] = r
    return done


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--seeds", default="0..219", help="A..B and single seeds, comma separated")
    p.add_argument("--timeout", type=float, default=120.0, help="locus time bound (s)")
    p.add_argument("--hard", type=float, default=None,
                   help="hard wall-clock kill per system (s; default timeout + 300)")
    p.add_argument("--memory", type=float, default=6.0, help="address-space limit (GiB)")
    p.add_argument("--lines", type=int, default=6)
    p.add_argument("--max-points", type=int, default=1500)
    p.add_argument("--jobs", type=int, default=1, help="systems run at once")
    p.add_argument("--certify", type=float, default=0.0,
                   help="also certify each locus, within this many seconds (0: no)")
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, help="JSON lines (resumable)")
    p.add_argument("--report", type=Path, default=None, help="write the table as markdown")
    p.add_argument("--rerun", action="store_true", help="run seeds already in --out again")
    p.add_argument("--report-only", action="store_true",
                   help="run nothing: the table of the seeds already in --out")
    p.add_argument("--source", type=Path, default=ROOT,
                   help="the source tree whose coopkin_sym is measured (default: this one)")
    p.add_argument("--one", type=int, default=None, help=argparse.SUPPRESS)
    args = p.parse_args(argv)
    if args.one is not None:
        sys.path.insert(0, os.environ.get("PYTHONPATH", str(ROOT)).split(os.pathsep)[0])
        print(json.dumps(run_one(args.one, args.timeout, args.lines, args.max_points,
                                 args.certify)))
        return 0
    if args.hard is None:
        args.hard = args.timeout + args.certify + 300
    seeds = parse_seeds(args.seeds)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    done = read_results(args.out)
    todo = [] if args.report_only else [s for s in seeds if args.rerun or s not in done]
    print(" ".join(f"{c:>8}" for c in COLUMNS), flush=True)
    for s in seeds:
        if s in done and s not in todo:
            print(" ".join(f"{x:>8}" for x in table_row(done[s])) + "  (earlier run)")

    def finish(r: dict) -> None:
        done[r["seed"]] = r
        with args.out.open("a") as f:
            f.write(json.dumps(r) + "\n")
        print(" ".join(f"{x:>8}" for x in table_row(r)), r.get("degenerate") or "",
              flush=True)

    if args.jobs <= 1:
        for s in todo:
            finish(run_isolated(s, args))
    else:
        from concurrent.futures import ThreadPoolExecutor
        with ThreadPoolExecutor(args.jobs) as pool:
            for r in pool.map(lambda s: run_isolated(s, args), todo):
                finish(r)
    rows = [done[s] for s in seeds if s in done]
    print("Total: " + ", ".join(f"{k} {v}" for k, v in totals(rows).items()))
    if args.report:
        args.report.write_text(markdown(rows))
    return 0


if __name__ == "__main__":
    os.environ.setdefault("PYTHONHASHSEED", "0")
    sys.exit(main())
