"""Scale-out: a sweep and a batch of analyses, serial against a local dask cluster.

    python benchmarks/bench_scaleout.py [--quick]

Cases: paper case 2 with hard contacts swept over a 200x200 grid of ``(q1, q2)`` at
``L=1`` (``--quick``: 60x60), and a batch of 400 analyses (``--quick``: 80) at
pseudo-random rational configurations of the same system. ``baseline`` is the serial
run, ``ours`` the same call with ``executor=client.get_executor()`` on a
``LocalCluster`` of two worker processes (started before the clock, and each worker
warmed up by one small task first); ``ratio = serial / cluster``. Both runs must give
the same results (the note says so). Without ``distributed`` the rows say it is missing.
"""

from __future__ import annotations

import random
import sys
import time

import numpy as np

import coopkin_sym
from coopkin_sym.analysis.sweep import grid


def _batch_items(count: int) -> list:
    rng = random.Random(5)

    def half() -> str:
        return f"2*atan({rng.randint(-9, 9)}/{rng.randint(1, 9)})"

    return [("paper-case2-hard",
             f"q1={half()},q2={half()},q3={half()},q6={half()},q7={half()},L=1")
            for _ in range(count)]


def _row(case: str, cluster_s: float | None, serial_s: float | None, note: str) -> dict:
    ratio = serial_s / cluster_s if cluster_s and serial_s else None
    return {"benchmark": "scaleout", "case": case, "ours_s": cluster_s,
            "baseline": "serial", "baseline_s": serial_s, "ratio": ratio, "note": note}


def run(quick: bool = False) -> list[dict]:
    try:
        from distributed import Client, LocalCluster
    except ImportError:
        return [_row("(distributed missing)", None, None,
                     "pip install coopkin_sym[cluster] to measure the cluster")]
    system = coopkin_sym.load("paper-case2-hard")
    n = 60 if quick else 200
    g = grid(system, f"q1=-pi..pi:{n},q2=-pi..pi:{n}")
    items = _batch_items(80 if quick else 400)
    rows = []
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        executor = client.get_executor()
        coopkin_sym.analyze_many(items[:2], executor=executor, chunk=1)    # warm up
        system.sweep(grid(system, "q1=-pi..pi:4,q2=0..0:1"), at="L=1",
                     executor=executor, chunk=2)
        chunk = max(1, n * n // 16)
        t0 = time.perf_counter()
        serial = system.sweep(g, at="L=1", chunk=chunk)
        t1 = time.perf_counter()
        spread = system.sweep(g, at="L=1", chunk=chunk, executor=executor)
        t2 = time.perf_counter()
        same = (np.array_equal(serial.numbers, spread.numbers)
                and np.array_equal(serial.rechecked, spread.rechecked))
        rows.append(_row(f"sweep paper-case2-hard {n}x{n}", t2 - t1, t1 - t0,
                         f"{n * n} points in 16 chunks, {int(serial.rechecked.sum())} "
                         f"rechecked; {'same' if same else 'DIFFERENT'} results"))
        t0 = time.perf_counter()
        serial_b = coopkin_sym.analyze_many(items)
        t1 = time.perf_counter()
        spread_b = coopkin_sym.analyze_many(items, executor=executor)
        t2 = time.perf_counter()
        failed = sum(not r.ok for r in serial_b)
        rows.append(_row(f"batch of {len(items)} analyses (paper-case2-hard)", t2 - t1,
                         t1 - t0, f"{failed} errors; "
                         f"{'same' if serial_b == spread_b else 'DIFFERENT'} results"))
    return rows


if __name__ == "__main__":
    for row in run("--quick" in sys.argv):
        print(f"{row['case']}: serial {row['baseline_s'] or 0:.2f} s, cluster(2) "
              f"{row['ours_s'] or 0:.2f} s, ratio {row['ratio'] or 0:.2f} ({row['note']})")
