"""The pictures of a report drawn side by side: they do not depend on one another, so
on a machine with several cores they are drawn in forked worker processes, and come
back in order, with what each one warned, within the report's time bound. Where that
cannot be done (one core, no ``fork``, inside a daemon process, or too few pictures to
gain anything) they are drawn one after another here.

Example
-------
>>> [k for k, (value, _) in draw_in_order([lambda: 1, lambda: 2, lambda: 3])]
[0, 1, 2]
>>> [value for _, (value, _) in draw_in_order([lambda: 1, lambda: 2, lambda: 3])]
[1, 2, 3]
"""

from __future__ import annotations

import multiprocessing
import os
import time
import warnings
from collections.abc import Callable, Iterator, Sequence
from typing import Any

#: Worker processes at most (pictures are small jobs; more would only cost memory).
MAX_WORKERS = 4
#: Fewer pictures than this are drawn here: starting workers would cost more.
MIN_PICTURES = 3

# the jobs of the drawing under way: set before the workers are forked, so that
# they inherit them and nothing but an index and the result is pickled
_JOBS: Sequence[Callable[[], Any]] = ()


class PictureFailed(Exception):
    """A picture that could not be drawn: ``error`` is what its job raised (kept
    whole when it comes back from a worker process).

    Example
    -------
    >>> import pickle
    >>> pickle.loads(pickle.dumps(PictureFailed(ValueError("no witness")))).error
    ValueError('no witness')
    """

    def __init__(self, error: BaseException):
        super().__init__(str(error))
        self.error = error

    def __reduce__(self):
        return (PictureFailed, (self.error,))


def _one(job: Callable[[], Any]) -> tuple[Any, list[warnings.WarningMessage]]:
    with warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always")
        try:
            value = job()
        except Exception as exc:  # handed back to the caller, which decides
            value = PictureFailed(exc)
    return value, said


def _in_worker(k: int) -> tuple[Any, list[tuple[str, type[Warning]]]]:
    value, said = _one(_JOBS[k])
    return value, [(str(w.message), w.category) for w in said]


def workers_for(n: int) -> int:
    """How many worker processes draw ``n`` pictures (0: drawn here, one by one).

    Example
    -------
    >>> workers_for(1)
    0
    """
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (
        os.cpu_count() or 1)
    if (n < MIN_PICTURES or cores < 2
            or "fork" not in multiprocessing.get_all_start_methods()
            or multiprocessing.current_process().daemon):
        return 0
    return min(cores, MAX_WORKERS, n)


def draw_in_order(jobs: Sequence[Callable[[], Any]], until: float | None = None,
                  workers: int | None = None
                  ) -> Iterator[tuple[int, tuple[Any, list[tuple[str, type[Warning]]]]]]:
    """``(k, (value, warnings))`` for the jobs in order, each job's value (or a
    :class:`PictureFailed`) with the warnings it gave as ``(text, category)``; it stops
    early, with the remaining jobs not run, once ``until`` (a ``time.monotonic()``
    value) has passed, the next job is not ready by then, or the caller stops asking.
    ``workers``: worker processes (default :func:`workers_for`; 0: one by one here).

    Example
    -------
    >>> list(draw_in_order([lambda: 1], until=time.monotonic() - 1))
    []
    """
    global _JOBS
    n = workers_for(len(jobs)) if workers is None else workers
    if n == 0:
        longest = 0.0
        for k, job in enumerate(jobs):
            started = time.monotonic()
            # the next one is taken to last as long as the longest so far, so that
            # the last one ends before the bound
            if until is not None and started + longest >= until:
                return
            value, said = _one(job)
            longest = max(longest, time.monotonic() - started)
            yield k, (value, [(str(w.message), w.category) for w in said])
        return
    _JOBS = jobs
    pool = multiprocessing.get_context("fork").Pool(n)
    try:
        pending = [pool.apply_async(_in_worker, (k,)) for k in range(len(jobs))]
        for k, result in enumerate(pending):
            left = None if until is None else until - time.monotonic()
            if left is not None and left <= 0:
                return
            try:
                yield k, result.get(timeout=left)
            except multiprocessing.TimeoutError:
                return
    finally:
        pool.terminate()
        pool.join()
        _JOBS = ()
