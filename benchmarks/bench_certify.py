"""Completeness certificates of singularity loci, and the Gröbner-basis backends behind
them (measured, not asserted).

Backends: one covering test of paper case 2 with hard contacts (all eight joints free,
t chart, the drop set of ``rank Gt^T``: the two contact points meet, a 5-dimensional
family in 8 variables) as the unit-ideal question the certificate asks, on every
backend, in both forms of the covering system (one ``z`` for the product of the
components, or one per component):

* *true*: the components of the locus search plus the family ``c1 = c2`` itself;
* *false*: the search's components alone (the family is missing), on the whole space
  and restricted to a random affine subspace of dimension 3 (where it shows as points).

Ours is Singular (exact ``std`` over Q); the baselines are flint's Buchberger (exact),
SymPy's F5B (exact) and msolve (modulo a prime: a screen, not a proof). A backend
that is not installed is a row that says so.

Certificates: for each shipped example, the locus of the current search
(``compute_locus``, every joint free, not timed here), then ``certify_locus`` with the
default backends (ours), with ``max_depth=0`` (in the note), and with flint alone (the
baseline, capped by a time budget).

Run ``python benchmarks/bench_certify.py [--quick]``.
"""

from __future__ import annotations

import multiprocessing
import random
import resource
import sys
import time

import coopkin_sym
from coopkin_sym.analysis.locus.certify import (
    _chart,
    _configuration,
    _drop_generators,
    _in_chart,
    _read_components,
    _RealZeros,
    _Setup,
    certify_locus,
)
from coopkin_sym.analysis.locus.search import compute_locus
from coopkin_sym.exact import groebner as gb
from coopkin_sym.present.certificate import certificate_summary
from coopkin_sym.present.remarks import remark_text

#: Memory (bytes) each timed run may use: a baseline that needs more (flint's and
#: SymPy's Buchberger can grow without bound inside one call, past any time cap)
#: stops with MemoryError in its own process and is reported as such.
MEMORY_CAP = 6 * 1024**3

EXAMPLES = ("paper-case1-hard", "paper-case1-complete-hard", "paper-case1-soft",
            "paper-case1-soft-hard", "paper-case2-complete", "paper-case2-hard")


def _covering_systems():
    """The covering systems of paper case 2 (hard contacts), t chart, rank of Gt^T."""
    system = coopkin_sym.load("paper-case2-hard")
    locus = compute_locus(system)
    model = system.model
    config = _configuration(model, locus.fixed)
    revolute = [j.name for j in model.joints if j.name in config.free
                and j.type == "revolute"]
    setup = _Setup(model, config, revolute, (), {}, [], [], set())
    chart = _chart(setup, ())
    setup.full_names = tuple(chart.names) + tuple(f"s_{j}" for j in revolute)
    gens = _drop_generators(chart.matrices["HG^T"], 5, chart, _RealZeros(chart, set()),
                            random.Random(1))
    comps = [_in_chart(setup, c[0], chart) for c in _read_components(
        locus, setup.full_names, []) if c is not None]
    comps = [c for c in comps if c is not None]
    allowed = [[u] for u in chart.units]
    polys, n = gb.as_dicts(gens)
    listed = [gb.as_dicts(c, n)[0] for c in comps + allowed]
    family = [gb.as_dicts(gens, n)[0]]
    out = {}
    for name, sets in (("c1 = c2 listed (true)", listed + family),
                       ("c1 = c2 missing (false)", listed)):
        merged = gb._merge_hypersurfaces(sets, n)
        for separate in (False, True):
            form = "one z per component" if separate else "one z for the product"
            # None past the term budget: the certificate never builds it either
            out[f"{name}, {form}"] = gb.covering_system(
                polys, merged, n, separate=separate,
                max_terms=None if separate else gb.MAX_PRODUCT_TERMS)
    ctx = gb._ctx(n)
    cut = gb._section([ctx.from_dict(p) for p in polys],
                      [[ctx.from_dict(g) for g in c] for c in listed], 3,
                      random.Random(1992))
    if cut is not None:
        out["c1 = c2 missing (false), random 3-dimensional subspace"] = \
            gb.covering_system(cut[0], gb._merge_hypersurfaces(cut[1], 3), 3)
    return out, len(locus.components)


def _in_child(out, fn, args) -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_CAP, MEMORY_CAP))
    try:
        out.put(("ok", fn(*args)))
    except MemoryError:
        out.put(("memory", None))
    except BaseException as exc:  # reported as a row, the other rows still run
        out.put(("error", f"{type(exc).__name__}: {exc}"))


def _isolated(fn, args, wall: float):
    """``fn(*args)`` in a forked process with :data:`MEMORY_CAP` bytes and ``wall``
    seconds: ``(result, None)``, or ``(None, why it did not finish)``."""
    context = multiprocessing.get_context("fork")
    out = context.Queue()
    child = context.Process(target=_in_child, args=(out, fn, args))
    child.start()
    try:
        status, value = out.get(timeout=wall)
    except Exception:   # queue.Empty: past the wall time
        status, value = "wall", None
    child.join(5)
    if child.is_alive():
        child.kill()
        child.join()
    if status == "ok":
        return value, None
    if status == "memory":
        return None, f"ran out of memory ({MEMORY_CAP / 1024**3:g} GB)"
    if status == "wall":
        return None, f"did not finish in {wall:g} s"
    return None, value


def _time(backend: str, system, m: int, cap: float):
    """Seconds and a note for one covering test, in its own bounded process."""
    result, why = _isolated(_timed, (backend, system, m, cap), 3 * cap + 60)
    return result if result is not None else (None, why)


def _timed(backend: str, system, m: int, cap: float):
    started = time.perf_counter()
    if backend == "msolve":
        if gb.msolve_path() is None:
            return None, "msolve not installed"
        verdict = gb._screen(system, m, cap)
    else:
        if backend == "singular" and gb.singular_path() is None:
            return None, "Singular not installed"
        verdict = gb._prove(system, m, cap, backend)
    seconds = time.perf_counter() - started
    if verdict.holds is None:
        return None, verdict.detail
    return seconds, f"unit ideal: {verdict.holds} ({'exact' if verdict.exact else 'modulo p'})"


def _backend_rows(quick: bool) -> list[dict]:
    cap = 15.0 if quick else 60.0
    systems, count = _covering_systems()
    rows = []
    for case, built in systems.items():
        if built is None:
            rows.append({
                "benchmark": "covering test backends (Singular vs others)",
                "case": f"paper-case2-hard, t chart, rank of Gt^T: {case}",
                "ours_s": None, "baseline": None, "baseline_s": None, "ratio": None,
                "note": f"not built: the product of the {count} components' equations is "
                        f"over the term budget ({gb.MAX_PRODUCT_TERMS}), as in the "
                        f"certificate"})
            continue
        system, m = built
        ours, ours_note = _time("singular", system, m, cap)
        size = f"{m} variables, {sum(len(p) for p in system)} terms"
        for baseline in ("flint", "sympy", "msolve"):
            theirs, their_note = _time(baseline, system, m, cap)
            rows.append({
                "benchmark": "covering test backends (Singular vs others)",
                "case": f"paper-case2-hard, t chart, rank of Gt^T: {case}; {size}",
                "ours_s": ours if ours is not None else f">={cap:g}",
                "baseline": baseline,
                "baseline_s": theirs if theirs is not None else f">={cap:g}",
                "ratio": _ratio(ours, theirs, cap),
                "note": f"Singular: {ours_note}; {baseline}: {their_note}; the search "
                        f"listed {count} components"})
    return rows


def _ratio(ours, theirs, cap):
    if ours is None:
        return ""
    if theirs is None:
        return f">={cap / ours:.3g}"
    return round(theirs / ours, 3)


def _certificate_rows(quick: bool) -> list[dict]:
    examples = EXAMPLES[:4] if quick else EXAMPLES
    cap = 60.0 if quick else 300.0
    rows = []
    for name in examples:
        system = coopkin_sym.load(name)
        started = time.perf_counter()
        locus = compute_locus(system)
        search_s = time.perf_counter() - started
        started = time.perf_counter()
        cert = certify_locus(system, locus, timeout=30)
        ours = time.perf_counter() - started
        started = time.perf_counter()
        depth0 = certify_locus(system, locus, timeout=30, max_depth=0)
        depth0_s = time.perf_counter() - started
        started = time.perf_counter()
        certified, unfinished = _flint_certificate(system, locus, cap)
        theirs = time.perf_counter() - started
        rows.append({
            "benchmark": "completeness certificate of the search's locus",
            "case": f"{name}, all joints free ({len(locus.components)} components)",
            "ours_s": round(ours, 3), "baseline": "the same certificate, flint alone",
            "baseline_s": round(theirs, 3), "ratio": round(theirs / ours, 3),
            "note": f"{certificate_summary(cert)[:160]}; {len(cert.checks)} tests in "
                    f"{len(cert.charts)} charts; depth 0 alone {depth0_s:.2f} s "
                    f"({'certified' if depth0.depths[0]['certified'] else 'not certified'}); "
                    f"search {search_s:.2f} s; flint alone: "
                    f"{'certified' if certified else 'not certified'}, "
                    f"{unfinished} tests timed out or not run (budget {cap:g} s)"})
    return rows


def _flint_certificate(system, locus, cap: float) -> tuple[bool, int]:
    """The certificate with flint alone: whether it certifies, and how many tests
    timed out or were not run."""
    cert = certify_locus(system, locus, timeout=30, backend="flint", budget=cap)
    unfinished = sum(c.why is not None and c.why.kind in ("cert_undecided",
                                                          "cert_chart_not_run")
                     and remark_text(c.why).startswith(("timed out", "not run"))
                     for c in cert.checks)
    return cert.certified, unfinished


def run(quick: bool = False) -> list[dict]:
    return _backend_rows(quick) + _certificate_rows(quick)


if __name__ == "__main__":
    quick = "--quick" in sys.argv
    for row in run(quick):
        print(" | ".join(str(row[k]) for k in ("benchmark", "case", "ours_s", "baseline",
                                                "baseline_s", "ratio", "note")))
