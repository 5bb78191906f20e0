"""Run every benchmark in one process, print a table, write ``RESULTS.md`` and
``scaling.png`` (and ``scaling_speed.png`` from ``bench_speed``) next to this file.

    python benchmarks/run.py [--quick] [--rows FILE] [--replay FILE [--again MODULE]]
                             [--before FILE]

Each benchmark module has ``run(quick) -> list[dict]`` with rows
``{"benchmark", "case", "ours_s", "baseline", "baseline_s", "ratio", "note"}``
(``ratio = baseline_s / ours_s``; a row may carry a ``"plot"`` entry, a list of
``{"panel", "series", "x", "y"}`` points for the log-log scaling figure). A module
that is missing or fails is reported as a row, and the others still run. The output
files are written only after everything has run; ``--rows FILE`` also saves the rows
as JSON after each module, and ``--replay FILE`` writes the table, ``RESULTS.md`` and the
plots from such a file without measuring again (a run stopped late loses nothing);
with ``--again MODULE`` that one module is measured again first, its rows and time
replacing the saved ones in the file (a module that failed, rerun after a fix).
``--before FILE`` (rows saved by an earlier run) adds a before/after table of our times
to ``RESULTS.md``, case by case, each side with the package commit it measured.
"""

from __future__ import annotations

import argparse
import datetime as _dt
import importlib
import json
import os
import platform
import sys
import time
import traceback
from pathlib import Path

HERE = Path(__file__).resolve().parent
MODULES = ("bench_sweep", "bench_generic", "bench_locus", "bench_certify", "bench_scaleout",
           "bench_speed", "bench_compile", "bench_finite", "bench_real")
COLUMNS = ("benchmark", "case", "ours_s", "baseline", "baseline_s", "ratio", "note")


def _log(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)


def run_module(name: str, quick: bool) -> tuple[list[dict], float]:
    t0 = time.perf_counter()
    try:
        module = importlib.import_module(name)
    except ModuleNotFoundError as exc:
        if exc.name != name:
            raise
        return [_row(name, "(module missing)", f"benchmarks/{name}.py does not exist yet; "
                     "skipped")], 0.0
    try:
        kwargs = {"log": _log} if "log" in module.run.__code__.co_varnames else {}
        rows = list(module.run(quick, **kwargs))
    except Exception as exc:
        traceback.print_exc()
        rows = [_row(name, "(failed)", f"{type(exc).__name__}: {exc}")]
    return rows, time.perf_counter() - t0


def _row(benchmark: str, case: str, note: str) -> dict:
    return {"benchmark": benchmark, "case": case, "ours_s": None, "baseline": None,
            "baseline_s": None, "ratio": None, "note": note}


def _seconds(v) -> str:
    if v is None:
        return "-"
    if isinstance(v, str):          # already written (a capped run: ">= 60")
        return v
    if v >= 100:
        return f"{v:.0f}"
    if v >= 1:
        return f"{v:.2f}"
    if v >= 0.001:
        return f"{v:.4f}"
    return f"{v:.2e}"


def _ratio(row: dict) -> str:
    v = row.get("ratio")
    if v is None:
        return "-"
    if isinstance(v, str):
        return v
    bound = ">= " if "lower bound" in (row.get("note") or "") else ""
    return f"{bound}{v:.3g}"


def cells(row: dict) -> list[str]:
    return [str(row.get("benchmark") or "-"), str(row.get("case") or "-"),
            _seconds(row.get("ours_s")), str(row.get("baseline") or "-"),
            _seconds(row.get("baseline_s")), _ratio(row), str(row.get("note") or "")]


def text_table(rows: list[dict], note_width: int = 70) -> str:
    data = [list(COLUMNS)] + [cells(r) for r in rows]
    for d in data:
        if len(d[-1]) > note_width:
            d[-1] = d[-1][: note_width - 3] + "..."
    widths = [max(len(d[i]) for d in data) for i in range(len(COLUMNS))]
    lines = ["  ".join(c.ljust(w) for c, w in zip(d, widths, strict=True)).rstrip()
             for d in data]
    lines.insert(1, "  ".join("-" * w for w in widths))
    return "\n".join(lines)


def markdown_table(rows: list[dict]) -> str:
    def esc(s: str) -> str:
        return s.replace("|", "\\|")
    out = ["| " + " | ".join(COLUMNS) + " |", "|" + "---|" * len(COLUMNS)]
    out += ["| " + " | ".join(esc(c) for c in cells(r)) + " |" for r in rows]
    return "\n".join(out)


def package_code() -> str:
    """The last commit that changed the package (``coopkin_sym/``), ``+`` when it has
    changes not committed; ``?`` outside a git checkout."""
    import subprocess
    root = HERE.parent
    try:
        commit = subprocess.run(["git", "log", "-1", "--format=%h", "--", "coopkin_sym"],
                                cwd=root, capture_output=True, text=True, check=True
                                ).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--", "coopkin_sym"],
                               cwd=root, capture_output=True, text=True, check=True
                               ).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "?"
    return (commit or "?") + ("+" if dirty else "")


def machine() -> list[tuple[str, str]]:
    import flint
    import numpy
    import sympy
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            names = [ln.split(":", 1)[1].strip() for ln in f if ln.startswith("model name")]
        if names:
            cpu = names[0]
    except OSError:
        pass
    ground = getattr(sympy.external.gmpy, "GROUND_TYPES", "?")
    return [("date", _dt.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z")),
            ("CPU", f"{cpu}, {os.cpu_count()} logical CPUs"),
            ("platform", platform.platform()),
            ("python", platform.python_version()),
            ("python-flint", flint.__version__),
            ("sympy", f"{sympy.__version__} (ground types: {ground})"),
            ("numpy", numpy.__version__),
            ("package code", f"commit {package_code()} (the last that changed coopkin_sym/)")]


def plot(rows: list[dict], path: Path) -> bool:
    """Log-log figure of the rows' ``"plot"`` points (lists of ``{"panel", "series",
    "x", "y"}``), one panel per ``panel``."""
    panels: dict[str, dict[str, list[tuple[float, float]]]] = {}
    for r in rows:
        for p in r.get("plot") or []:
            if p.get("y"):
                panels.setdefault(p["panel"], {}).setdefault(p["series"], []).append(
                    (p["x"], p["y"]))
    if not panels:
        return False
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import NullFormatter, ScalarFormatter
    fig, axes = plt.subplots(1, len(panels), figsize=(7 * len(panels), 7.5), squeeze=False)
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for ax, (title, series) in zip(axes[0], panels.items(), strict=True):
        families = sorted({name.split(":")[0] for name in series})
        # ours first (solid lines), baselines after (dashed)
        kinds = sorted({name.split(":", 1)[-1] for name in series},
                       key=lambda k: ("DomainMatrix" in k, k))
        xs = set()
        for name, pts in sorted(series.items()):
            pts.sort()
            xs.update(x for x, _ in pts)
            family, kind = name.split(":")[0], name.split(":", 1)[-1]
            k = kinds.index(kind)
            ax.plot([x for x, _ in pts], [y for _, y in pts], ("-", "--", ":")[k % 3],
                    marker="os^D"[k % 4], markersize=4, label=name,
                    color=colors[families.index(family) % len(colors)])
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.xaxis.set_major_formatter(ScalarFormatter())
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_xticks(sorted(xs))
        ax.set_xlabel("joints r")
        ax.set_ylabel("seconds")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2,
                  frameon=False)
    fig.suptitle("coopkin_sym: cost against size (log-log)")
    fig.tight_layout()
    tmp = path.with_name(path.stem + ".tmp.png")
    fig.savefig(tmp, dpi=110)
    plt.close(fig)
    os.replace(tmp, path)
    return True


def _replace_module(rows: list[dict], name: str, new: list[dict]) -> list[dict]:
    """``rows`` with those of module ``name`` replaced by ``new``, in their place."""
    at = next((i for i, r in enumerate(rows) if r.get("module") == name), len(rows))
    kept = [r for r in rows if r.get("module") != name]
    return kept[:at] + new + kept[at:]


def _save_rows(path: Path, rows: list[dict], durations: list, quick: bool,
               info: list, again: list[str] = ()) -> None:
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(json.dumps({"quick": quick, "durations": durations, "machine": info,
                               "rows": rows, "again": list(again)}, default=str))
    os.replace(tmp, path)


def _commit_of(info) -> str:
    """The package commit a run's machine table names."""
    for k, v in info:
        if k == "package code":
            return v.split()[1] if v.startswith("commit ") else v
    return "?"


def before_after(before: dict, rows: list[dict], info,
                 again: list[tuple[str, str]] = ()) -> list[str]:
    """The lines of the before/after table: our time of every (benchmark, case) that
    both runs measured (its first row), with the ratio of the two. With ``again``
    (modules measured again by ``--again``, with their package commit), only their
    rows: the others were not measured again."""
    earlier: dict[tuple, dict] = {}
    for r in before["rows"]:
        earlier.setdefault((r.get("benchmark"), r.get("case")), r)
    old, new = _commit_of(before["machine"]), _commit_of(info)
    only = ""
    if again:
        modules = {name for name, _ in again}
        rows = [r for r in rows if r.get("module") in modules]
        new = ", ".join(sorted({code for _, code in again}))
        measured = {code for name, code in before.get("again", []) if name in modules}
        if measured:   # the earlier run measured these modules again too
            old = ", ".join(sorted(measured))
        only = " Only the modules measured again: " + ", ".join(sorted(modules)) + "."
    out = [f"## Before and after: package commit {old} and {new}", "",
           "Our time of each case both runs measured (`speedup = before / after`; the "
           "earlier run is `" + before.get("source", "--rows") + "`)." + only, "",
           f"| benchmark | case | before ({old}) | after ({new}) | speedup |",
           "|---|---|---|---|---|"]
    seen = set()
    for r in rows:
        key = (r.get("benchmark"), r.get("case"))
        b = earlier.get(key)
        if key in seen or b is None:
            continue
        seen.add(key)
        a_s, b_s = r.get("ours_s"), b.get("ours_s")
        ratio = (f"{b_s / a_s:.3g}" if isinstance(a_s, float | int) and a_s
                 and isinstance(b_s, float | int) else "-")
        out.append(f"| {key[0]} | {key[1]} | {_seconds(b_s)} | {_seconds(a_s)} | {ratio} |")
    return out + [""]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small sizes, short caps")
    parser.add_argument("--rows", type=Path, metavar="FILE",
                        help="save the rows as JSON after each module")
    parser.add_argument("--replay", type=Path, metavar="FILE",
                        help="write the outputs from rows saved by --rows; measure nothing")
    parser.add_argument("--again", choices=MODULES, metavar="MODULE",
                        help="with --replay: measure this module again, in place of its "
                             "saved rows")
    parser.add_argument("--before", type=Path, metavar="FILE",
                        help="rows of an earlier run (saved by --rows): a before/after "
                             "table of our times in RESULTS.md")
    args = parser.parse_args(argv)
    if args.again and not args.replay:
        parser.error("--again needs --replay FILE")
    sys.path.insert(0, str(HERE))
    if args.replay:
        saved = json.loads(args.replay.read_text())
        rows, durations, args.quick = saved["rows"], saved["durations"], saved["quick"]
        info = [tuple(kv) for kv in saved["machine"]]
        again = [a for a in saved.get("again", []) if a[0] != args.again]
        if args.again:
            again.append((args.again, package_code()))
            _log(f"{args.again} ...")
            module_rows, seconds = run_module(args.again, args.quick)
            rows = _replace_module(rows, args.again,
                                   [{**r, "module": args.again} for r in module_rows])
            durations = [(n, seconds if n == args.again else s) for n, s in durations]
            _save_rows(args.replay, rows, durations, args.quick, info, again)
        total = sum(s for _, s in durations)
        importlib.import_module("bench_speed")      # their plots
        importlib.import_module("bench_real")
    else:
        info = machine()
        again = []
        t0 = time.perf_counter()
        rows = []
        durations = []
        for name in MODULES:
            _log(f"{name} ...")
            module_rows, seconds = run_module(name, args.quick)
            rows += [{**r, "module": name} for r in module_rows]
            durations.append((name, seconds))
            if args.rows:
                _save_rows(args.rows, rows, durations, args.quick, info)
        total = time.perf_counter() - t0
    print(text_table(rows))
    print(f"\n{'quick' if args.quick else 'full'} run: {total:.0f} s")
    has_plot = plot(rows, HERE / "scaling.png")
    speed = sys.modules.get("bench_speed")
    has_speed_plot = bool(speed and speed.plot_speed(rows, HERE / "scaling_speed.png"))
    real = sys.modules.get("bench_real")
    has_real_plot = bool(real and real.plot_real(rows, HERE / "scaling_real.png"))
    lines = ["# Benchmark results", "",
             f"Generated by `python benchmarks/run.py{' --quick' if args.quick else ''}` "
             f"({'quick' if args.quick else 'full'} run, {total:.0f} s in all: "
             + ", ".join(f"{n} {s:.0f} s" for n, s in durations) + ")"
             + "".join(f"; {name} measured again later by `--again`, package code at "
                       f"commit {code}" for name, code in again) + ".", "",
             "| machine | |", "|---|---|"]
    lines += [f"| {k} | {v} |" for k, v in info]
    lines += ["", "Times in seconds; `ratio = baseline_s / ours_s` (above 1: ours is faster); "
              "`>=` marks a lower bound (the baseline was stopped at its cap). "
              "See `benchmarks/README.md` for what each row measures.", "",
              markdown_table(rows), ""]
    if args.before:
        lines += before_after(json.loads(args.before.read_text()), rows, info, again)
    if has_plot:
        lines += ["![scaling](scaling.png)", ""]
    if has_speed_plot:
        lines += ["![scaling of the speed goals](scaling_speed.png)", ""]
    if has_real_plot:
        lines += ["![real robots: growth with the joints](scaling_real.png)", ""]
    out = HERE / "RESULTS.md"
    tmp = out.with_suffix(".md.tmp")
    tmp.write_text("\n".join(lines))
    os.replace(tmp, out)
    _log(f"wrote {out}" + (f" and {HERE / 'scaling.png'}" if has_plot else "")
         + (f" and {HERE / 'scaling_speed.png'}" if has_speed_plot else "")
         + (f" and {HERE / 'scaling_real.png'}" if has_real_plot else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
