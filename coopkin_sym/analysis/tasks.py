"""Tasks of plain data mapped over any :class:`concurrent.futures.Executor`.

The sweep (:mod:`coopkin_sym.analysis.sweep`) and the batches of analyses
(:mod:`coopkin_sym.analysis.batch`) cut their work into tasks whose arguments and
results are plain data (integers, numpy arrays, dicts, small frozen dataclasses), so
they run in this process, in a process pool, or on a cluster
(a dask ``distributed.Client``, or its ``get_executor()``, or a pool with the
``apply_async`` of :class:`multiprocessing.pool.Pool`, as Ray's
``ray.util.multiprocessing.Pool`` has) alike: :func:`task_executor` checks what was
given (a client is asked for its executor, a pool is wrapped in a
:class:`PoolExecutor`; neither dask nor Ray is ever imported here).
:func:`run_tasks` submits them and yields each result with the position of its task
as it completes; the caller puts it in place, so the outcome never depends on the
order of completion. When the caller stops early (an error, an interrupt), the tasks
still pending are cancelled (those a pool already holds run to their end).

Example
-------
>>> from concurrent.futures import ThreadPoolExecutor
>>> from operator import mul
>>> with ThreadPoolExecutor(2) as pool:
...     sorted(run_tasks(mul, [(2, 3), (4, 5)], pool))
[(0, 6), (1, 20)]
>>> list(run_tasks(mul, [(2, 3)], None))
[(0, 6)]
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import Executor, Future, InvalidStateError, as_completed
from typing import Any

from coopkin_sym.errors import ArgumentTypeError
from coopkin_sym.exact.bounded import report

EXECUTORS = ("a concurrent.futures.Executor (ProcessPoolExecutor, ThreadPoolExecutor, "
             "a cluster's executor), a dask distributed.Client, a pool with "
             "apply_async(fn, args, callback=, error_callback=) (multiprocessing.Pool, "
             "ray.util.multiprocessing.Pool), or None to run here")


class PoolExecutor(Executor):
    """A pool with the ``apply_async`` of :class:`multiprocessing.pool.Pool` (Ray's
    ``ray.util.multiprocessing.Pool`` has the same) as a
    :class:`concurrent.futures.Executor`: each ``submit`` is one ``apply_async``
    whose callbacks complete a :class:`~concurrent.futures.Future`. The pool stays
    the caller's (``shutdown`` leaves it open); a task already given to the pool
    cannot be cancelled.

    Example
    -------
    >>> from multiprocessing.pool import ThreadPool
    >>> from operator import mul
    >>> with ThreadPool(2) as pool:
    ...     PoolExecutor(pool).submit(mul, 6, 7).result()
    42
    """

    def __init__(self, pool: Any):
        self.pool = pool

    def submit(self, fn: Callable[..., Any], /, *args: Any, **kwargs: Any) -> Future:
        future: Future = Future()
        future.set_running_or_notify_cancel()   # given to the pool: no longer cancellable

        def done(value: Any) -> None:
            try:
                future.set_result(value)
            except InvalidStateError:  # pragma: no cover - a pool calling back twice
                pass

        def failed(exc: BaseException) -> None:
            try:
                future.set_exception(exc)
            except InvalidStateError:  # pragma: no cover
                pass

        self.pool.apply_async(fn, args, kwargs, callback=done, error_callback=failed)
        return future


def _is_pool(executor: object) -> bool:
    return callable(getattr(executor, "apply_async", None))


def task_executor(executor: object, where: str = "executor") -> Executor | None:
    """The :class:`concurrent.futures.Executor` that runs the tasks given ``executor``:
    itself, None (run here, in order), the executor of a dask
    ``distributed.Client`` (recognized by its ``get_executor`` and ``submit``; its
    own ``submit`` returns dask futures, which :func:`concurrent.futures.as_completed`
    cannot wait on), or a :class:`PoolExecutor` around a pool with ``apply_async``
    (:class:`multiprocessing.pool.Pool`, ``ray.util.multiprocessing.Pool``).

    Raises
    ------
    ArgumentTypeError
        For anything else, naming ``where`` and what to pass.

    Example
    -------
    >>> from concurrent.futures import ThreadPoolExecutor
    >>> task_executor(None) is None
    True
    >>> with ThreadPoolExecutor(1) as pool:
    ...     task_executor(pool) is pool
    True
    >>> task_executor(4)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ArgumentTypeError: executor: expected a concurrent.futures.Executor ...int
    """
    if executor is None or isinstance(executor, Executor):
        return executor
    if _is_pool(executor):
        return PoolExecutor(executor)
    get = getattr(executor, "get_executor", None)
    if callable(get) and callable(getattr(executor, "submit", None)):
        pool = get()
        if isinstance(pool, Executor):
            return pool
    raise ArgumentTypeError(f"{where}: expected {EXECUTORS}; got "
                            f"{type(executor).__name__}")


def run_tasks(fn: Callable[..., Any], tasks: Sequence[tuple], executor: object, *,
              on_error: Callable[[BaseException], Any] | None = None
              ) -> Iterator[tuple[int, Any]]:
    """``(i, fn(*tasks[i]))`` for every task, as each completes.

    Parameters
    ----------
    fn
        A module-level function (it travels to the workers by reference).
    tasks
        The argument tuples, plain data.
    executor
        Any :class:`concurrent.futures.Executor`, a dask ``distributed.Client``, or
        None to run in order here (see :func:`task_executor`).
    on_error
        With an executor: what a task that failed outside ``fn`` (a worker process that
        died) yields instead of raising, given the exception.

    Example
    -------
    >>> list(run_tasks(divmod, [(7, 2), (9, 4)], None))
    [(0, (3, 1)), (1, (2, 1))]
    """
    executor = task_executor(executor)
    if executor is None:
        for i, args in enumerate(tasks):
            yield i, fn(*args)
        return
    futures = {executor.submit(fn, *args): i for i, args in enumerate(tasks)}
    try:
        for future in as_completed(futures):
            try:
                result = future.result()
            except Exception as exc:
                if on_error is None:
                    raise
                result = on_error(exc)
            yield futures[future], result
    finally:
        for future in futures:
            future.cancel()


class Progress:
    """The progress of a run of tasks, reported (when ``show``) through
    :func:`coopkin_sym.exact.bounded.report`: how many of the ``total`` are done,
    and the share: ``with Progress(show, total, "sweep", name) as advance:
    advance(k)``. The presentation layer's display shows it.

    Example
    -------
    >>> from coopkin_sym.exact.bounded import Reporter, reporting
    >>> seen = []
    >>> with reporting(Reporter(lambda step, done: seen.append((step, done)))):
    ...     with Progress(True, 10, "sweep", "case 1") as advance:
    ...         advance(4)
    >>> seen
    [('the sweep of case 1, 0 of 10 done', 0.0), ('the sweep of case 1, 4 of 10 done', 0.4)]
    """

    def __init__(self, show: bool, total: int, what: str, name: str):
        self.show, self.total, self.what, self.name = show, total, what, name
        self.done = 0

    def __enter__(self) -> Callable[[int], None]:
        if not self.show:
            return lambda k: None
        report(self._step(), 0.0)

        def advance(k: int) -> None:
            self.done += k
            report(self._step(), self.done / max(self.total, 1))
        return advance

    def _step(self) -> str:
        return f"the {self.what} of {self.name}, {self.done:,} of {self.total:,} done"

    def __exit__(self, *exc) -> bool:
        return False
