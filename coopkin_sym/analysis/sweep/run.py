"""The sweep driver: batches evaluated modulo a prime, non-generic points rechecked
exactly over Q, on any :class:`concurrent.futures.Executor` (see
:mod:`coopkin_sym.analysis.sweep`).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from concurrent.futures import Executor
from contextlib import closing
from typing import Any

import numpy as np

from coopkin_sym import limits
from coopkin_sym.analysis.numbers import seven_numbers
from coopkin_sym.analysis.sweep.compiled import _exact_for, _joint_vector, compile_system
from coopkin_sym.analysis.sweep.grid import Grid, _split_point
from coopkin_sym.analysis.sweep.result import SweepResult
from coopkin_sym.analysis.sweep.values import Value
from coopkin_sym.analysis.tasks import Progress, run_tasks, task_executor
from coopkin_sym.errors import SweepError
from coopkin_sym.exact import modular
from coopkin_sym.exact.matrix import batch_rank_profile
from coopkin_sym.exact.parse import brief
from coopkin_sym.model.model import Model, model_of

#: Points evaluated together in one numpy block (cache-sized).
BLOCK = 4096


# --- the sweep ------------------------------------------------------------------------
def _run_chunk(plan: dict, pairs: list[list[tuple[int, int]]],
               index: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Ranks ``(points, 3)`` (Q, its object columns, its last r columns) of one chunk and which
    points needed the exact recheck. Plain data in and out (runs in any process)."""
    p = plan["prime"]
    m, n = plan["m"], plan["n"]
    count = index.shape[0]
    ranks = np.zeros((count, 3), dtype=np.int64)
    rechecked = np.zeros(count, dtype=bool)
    if m == 0 or count == 0:
        return ranks, rechecked
    if plan.get("pointwise"):          # Q from the product of exponentials, point by point
        exact, generic = _exact_for(plan), tuple(plan["generic"])
        for i in range(count):
            point = [pairs[j][index[i, j]] for j in range(len(pairs))]
            ranks[i], rechecked[i] = exact.certified_ranks(point, generic, p)
        return ranks, rechecked
    columns = []                       # per joint: residues of its variables per value
    for kind, ps in zip(plan["kinds"], pairs, strict=True):
        vectors = [_joint_vector([kind], [pair]) for pair in ps]
        columns.append([modular.residues(col, p) for col in zip(*vectors, strict=True)])
    object_cols, joint_cols = plan["object_cols"], plan["joint_cols"]
    generic = np.array(plan["generic"], dtype=np.int64)
    for start in range(0, count, BLOCK):
        idx = index[start:start + BLOCK]
        size = idx.shape[0]
        rows = []
        for j, cols in enumerate(columns):
            rows += [col[idx[:, j]] for col in cols]
        rows += [np.full(size, v, dtype=np.int64) for v in plan["params"]]
        values = np.stack(rows) if rows else np.zeros((0, size), dtype=np.int64)
        flat = modular.evaluate(plan["exps"], plan["coefs"], plan["entries"], m * n,
                                values, p).reshape(m, n, size)
        block = ranks[start:start + size]
        if joint_cols or object_cols:
            rq, rr = batch_rank_profile(flat[:, joint_cols + object_cols, :], p,
                                        prefix=len(joint_cols))
            block[:, 0], block[:, 2] = rq, rr
        if object_cols:
            block[:, 1] = batch_rank_profile(flat[:, object_cols, :], p)[0]
    if (ranks > generic).any():  # pragma: no cover - impossible: rank mod p <= rank
        raise AssertionError("a rank modulo p exceeds the generic rank")
    doubt = np.flatnonzero((ranks != generic).any(axis=1))
    if doubt.size:
        exact = _exact_for(plan)
        for i in doubt:
            ranks[i] = exact.ranks([pairs[j][index[i, j]] for j in range(len(pairs))])
        rechecked[doubt] = True
    return ranks, rechecked


def sweep(system: Model | Any, points: Grid | Iterable[str | Mapping], *,
          at: str | Mapping | None = None,
          executor: Executor | None = None, progress: bool = False,
          chunk: int = 16384, prime: int = modular.PRIME) -> SweepResult:
    """Exact numbers at many points.

    Parameters
    ----------
    system
        The system (or its model).
    points
        A :class:`Grid` (see :func:`grid`), or an iterable of points, each a mapping
        ``{joint: value}`` or text ``"q1=pi/2,q2=2*atan(1/3)"`` of exact values (the
        swept joints are those named; one left out of a point takes its value from
        ``at``, else home).
    at
        Values of the other joints and of parameters.
    executor
        Any :class:`concurrent.futures.Executor` (a process pool, a cluster's
        executor such as ``distributed.Client(...).get_executor()``), a dask
        ``distributed.Client`` itself, or a pool with ``apply_async``
        (``ray.util.multiprocessing.Pool``, ``multiprocessing.Pool``): chunks of points
        are mapped over it as plain data; the result is the serial one. Anything else is an
        :class:`~coopkin_sym.errors.ArgumentTypeError` saying what to pass.
    progress
        Report the points done (see :func:`coopkin_sym.exact.bounded.report`; the
        caller's display shows them, as ``System.sweep(progress=True)`` does).
    chunk
        Points per task.
    prime
        The prime of the modular pass (below ``2**31``).

    Example
    -------
    >>> from coopkin_sym import load
    >>> res = sweep(load("paper-case1-hard"), ["q1=pi/2,q2=pi/2", "q1=0,q2=0"])
    >>> res.numbers[:, 0].tolist(), res.rechecked.tolist()
    ([3, 2], [True, False])
    """
    executor = task_executor(executor)
    model = model_of(system)
    bound = None
    if isinstance(points, Grid):
        joints, levels, bound = points.joints, points.levels, points.bound
        index = points.index()
        compiled = compile_system(model, joints, at, prime)
    else:
        joints, levels, index, compiled = _explicit_points(model, points, at, prime)
    pairs = [[(v.num, v.den) for v in vs] for vs in levels]
    total = index.shape[0]
    ranks = np.zeros((total, 3), dtype=np.int64)
    rechecked = np.zeros(total, dtype=bool)
    chunk = max(1, int(chunk))
    starts = list(range(0, total, chunk))
    with Progress(progress, total, "sweep", model.name) as advance:
        tasks = []
        for s in starts:
            if executor is None:
                tasks.append((compiled.plan, pairs, index[s:s + chunk]))
            else:   # a chunk sent away carries only the values it uses
                sub, local_pairs = _localize(index[s:s + chunk], pairs)
                tasks.append((compiled.plan, local_pairs, sub))
        with closing(run_tasks(_run_chunk, tasks, executor)) as done:
            for k, (r, re) in done:
                s = starts[k]
                ranks[s:s + chunk], rechecked[s:s + chunk] = r, re
                advance(len(r))
    m, r = compiled.m, compiled.r
    numbers = np.stack(seven_numbers(m, r, ranks[:, 0], ranks[:, 1], ranks[:, 2],
                                     dim=compiled.dim), axis=1)
    kinds = {j.name: j.type for j in model.joints}
    return SweepResult(model.name, tuple(joints), compiled.at_text, compiled.generic,
                       tuple(levels), index, numbers, rechecked, prime, bound,
                       tuple(kinds[j] for j in joints))


def _explicit_points(model: Model, points: Iterable[str | Mapping], at, prime: int):
    """The swept joints, their value tables, the index of every point and the compiled
    system, for an iterable of explicit points (see :func:`sweep`)."""
    parsed = []
    for pt in points:
        parsed.append(_split_point(pt))
        if len(parsed) > limits.MAX_GRID_POINTS:
            raise SweepError(f"points: more than {limits.MAX_GRID_POINTS:,} points "
                             "(the limit of one sweep)")
    if not parsed:
        raise SweepError("no points to sweep")
    names = {n for items in parsed for n, _ in items}
    joints = tuple(j for j in model.joint_names if j in names)
    unknown = sorted(names - set(joints))
    if unknown:
        params = {p.name for p in model.parameters}
        bad = unknown[0]
        what = (f"{bad} is a parameter: set it with at=" if bad in params
                else f"unknown joint {brief(bad)} (joints: {', '.join(model.joint_names)})")
        raise SweepError(f"points: {what}")
    compiled = compile_system(model, joints, at, prime)
    table: list[dict] = [{} for _ in joints]
    lv: list[list[Value]] = [[] for _ in joints]
    index = np.zeros((len(parsed), len(joints)), dtype=np.int64)
    for i, items in enumerate(parsed):
        given = dict(items)
        for k, j in enumerate(joints):
            raw = given.get(j)
            key = ("default",) if raw is None else _hashable(raw)
            pos = table[k].get(key)
            if pos is None:
                v = compiled.defaults[k] if raw is None else compiled.value(j, raw)
                pos = table[k].get((v.num, v.den))
                if pos is None:
                    pos = table[k][(v.num, v.den)] = len(lv[k])
                    lv[k].append(v)
                table[k][key] = pos
            index[i, k] = pos
    return joints, tuple(tuple(v) for v in lv), index, compiled


def _hashable(value):
    try:
        hash(value)
    except TypeError:
        return ("repr", repr(value))
    return (type(value).__name__, value)


def _localize(index: np.ndarray, pairs: list[list[tuple[int, int]]]):
    """The chunk's own value tables (only the values it uses) and its re-indexed points."""
    sub = np.empty_like(index)
    local = []
    for k, ps in enumerate(pairs):
        used, inverse = np.unique(index[:, k], return_inverse=True)
        sub[:, k] = inverse.ravel()
        local.append([ps[i] for i in used.tolist()])
    return sub, local
