"""Many analyses at once: many systems, many configurations, on any executor.

A batch is a list of *items*, each plain data: a model source (the name of a shipped
example, a model file, a model as a mapping) or a pair ``(source, at)`` with ``at`` in
``--at`` syntax (``"q1=pi/2,L=1"``) or a mapping. :func:`run_batch` cuts the batch into
chunks of consecutive items and maps them over any
:class:`concurrent.futures.Executor` (a process pool, a cluster's executor) or runs
them here; each chunk loads its models (once per distinct source) and computes every
item with the function it is given. Results come back in input order, the same as a
serial run, as :class:`BatchResult`: the exact numbers, a JSON document when asked,
or the error of that item alone (a bad configuration, a model that does not load),
so one bad item never stops the others.

The function computing one item is a parameter (the public
:func:`coopkin_sym.analyze_many` passes one that runs ``System.analyze`` and, on
request, writes its JSON document), so this layer needs nothing from the ones above.

Example
-------
>>> from coopkin_sym.analysis.mobility import analyze
>>> from coopkin_sym.model.configuration import Configuration
>>> def numbers(model, at):
...     return analyze(model, Configuration.parse(model, at)).numbers, None
>>> results = run_batch(numbers, [("paper-case1-hard", "q1=pi/2,q2=pi/2"),
...                               ("paper-case1-hard", "q9=0")])
>>> results[0].numbers.Nm, results[1].ok, results[1].error
(3, False, "--at q9: unknown name 'q9' (known: q1, q2, L)")
"""

from __future__ import annotations

import json
import os
from collections.abc import Callable, Iterable, Mapping
from concurrent.futures import Executor
from contextlib import closing
from dataclasses import dataclass
from typing import Any

from coopkin_sym.analysis.numbers import Numbers, numbers_line
from coopkin_sym.analysis.renderers import Displayable
from coopkin_sym.analysis.tasks import Progress, run_tasks, task_executor
from coopkin_sym.errors import CoopkinError
from coopkin_sym.model.configuration import assignments_text
from coopkin_sym.model.model import Model, load_model

#: What one item computes: ``compute(model, at, *options) -> (numbers, document)``.
Compute = Callable[..., tuple[Numbers, dict | None]]


@dataclass(frozen=True)
class BatchResult(Displayable):
    """The outcome of one item of a batch: its exact numbers (and JSON document when
    asked), or the error that stopped it.

    ``index`` is the item's position in the batch, ``source`` names its model (the
    example or file as given, or the model's name), ``at`` is its configuration as given
    (None: home).

    Example
    -------
    >>> r = BatchResult(0, "paper-case1-hard", "q1=pi/2", Numbers(3, 3, 1, 0, 1, 4, 0))
    >>> r.ok, r.as_dict()["numbers"]["Nm"]
    (True, 3)
    >>> BatchResult(1, "five-bar", "q9=0", error="--at: unknown name q9")
    <BatchResult 1 five-bar at q9=0: error: --at: unknown name q9>
    """

    index: int
    source: str
    at: str | None
    numbers: Numbers | None = None
    document: dict | None = None
    error: str | None = None

    @property
    def ok(self) -> bool:
        """Whether the item was computed (no error)."""
        return self.error is None

    def as_dict(self) -> dict[str, Any]:
        """Plain data (for JSON or a table): index, source, at, numbers, error, and the
        document when there is one."""
        out: dict[str, Any] = {
            "index": self.index, "source": self.source, "at": self.at,
            "numbers": None if self.numbers is None else self.numbers.as_dict(),
            "error": self.error}
        if self.document is not None:
            out["document"] = self.document
        return out

    def __repr__(self) -> str:
        where = f" at {self.at}" if self.at else ""
        what = f"error: {self.error}" if self.error is not None else numbers_line(
            self.numbers) if self.numbers is not None else "no numbers"
        return f"<BatchResult {self.index} {self.source}{where}: {what}>"


def run_batch(compute: Compute, items: Iterable[Any], *, options: tuple = (),
              executor: Executor | None = None, progress: bool = False,
              chunk: int | None = None) -> list[BatchResult]:
    """Compute every item of a batch; results in input order, the same on any executor.

    Parameters
    ----------
    compute
        A module-level function ``compute(model, at, *options)`` returning the numbers
        and a document (or None) of one item; it travels to the workers by reference.
    items
        Each a model source (example name, file, mapping, or a :class:`Model`) or a
        pair ``(source, at)``.
    options
        Plain data passed to every call of ``compute``.
    executor
        Any :class:`concurrent.futures.Executor`, a dask ``distributed.Client`` or a
        pool with ``apply_async`` (``multiprocessing.Pool``,
        ``ray.util.multiprocessing.Pool``; see
        :func:`~coopkin_sym.analysis.tasks.task_executor`); None runs here, in order.
    progress
        Report the items done (see :func:`coopkin_sym.exact.bounded.report`; the
        caller's display shows them).
    chunk
        Items per task (default: about 32 tasks, at most 64 items each).

    Example
    -------
    >>> from coopkin_sym.analysis.mobility import analyze
    >>> from coopkin_sym.model.configuration import Configuration
    >>> def numbers(model, at):
    ...     return analyze(model, Configuration.parse(model, at)).numbers, None
    >>> [r.numbers.Nm for r in run_batch(numbers, ["paper-case1-hard", "five-bar"])]
    [2, 3]
    """
    executor = task_executor(executor)
    results: list[BatchResult | None] = []
    work: list[tuple[int, Any, Any]] = []
    for index, item in enumerate(items):
        source, at, problem = _split_item(item)
        if problem is None:
            work.append((index, source, at))
            results.append(None)
        else:
            results.append(BatchResult(index, _label(source), _at_label(at), error=problem))
    size = chunk if chunk is not None else max(1, min(64, len(work) // 32))
    size = max(1, int(size))
    tasks = [(compute, work[s:s + size], tuple(options)) for s in range(0, len(work), size)]
    with Progress(progress, len(results), "analyses", "the batch") as advance:
        advance(len(results) - len(work))
        on_error = _task_failed if executor is not None else None
        with closing(run_tasks(_run_items, tasks, executor, on_error=on_error)) as done:
            for k, out in done:
                part = tasks[k][1]
                if isinstance(out, str):          # the task itself failed: say so per item
                    out = [BatchResult(i, _label(s), _at_label(a), error=out)
                           for i, s, a in part]
                for r in out:
                    results[r.index] = r
                advance(len(part))
    return results  # type: ignore[return-value]


def _task_failed(exc: BaseException) -> str:
    return f"the task running this item failed: {type(exc).__name__}: {exc}"


def _split_item(item: Any) -> tuple[Any, Any, str | None]:
    """``(source, at, problem)`` of one item (problem None when it is well formed)."""
    if isinstance(item, tuple | list):
        if len(item) != 2:
            return None, None, (f"expected a model source or a pair (source, at), got "
                                f"a sequence of {len(item)}")
        source, at = item
    else:
        source, at = item, None
    if not isinstance(source, str | os.PathLike | Mapping | Model):
        return source, at, (f"expected a model source (an example name, a file, a "
                            f"mapping), got {type(source).__name__}")
    if at is not None and not isinstance(at, str | Mapping):
        return source, at, f"at: expected --at text or a mapping, got {type(at).__name__}"
    return source, at, None


def _label(source: Any) -> str:
    if isinstance(source, Model):
        return source.name
    if isinstance(source, Mapping):
        name = source.get("name")
        return name if isinstance(name, str) else "unnamed"
    if isinstance(source, str | os.PathLike):
        return str(os.fspath(source))
    return type(source).__name__


def _at_label(at: Any) -> str | None:
    if at is None or isinstance(at, str):
        return at
    if isinstance(at, Mapping):
        return assignments_text(at)
    return repr(at)


def _source_key(source: Any) -> Any:
    """A key telling equal sources apart (None: do not share the loaded model)."""
    if isinstance(source, Model):
        return ("model", id(source))
    if isinstance(source, Mapping):
        try:
            return ("tree", json.dumps(source, sort_keys=True))
        except (TypeError, ValueError):
            return None
    return ("file", os.fspath(source))


def _error_text(exc: Exception) -> str:
    if isinstance(exc, CoopkinError):
        return str(exc)
    return f"{type(exc).__name__}: {exc}"


def _run_items(compute: Compute, part: list[tuple[int, Any, Any]],
               options: tuple) -> list[BatchResult]:
    """One task: the items of a chunk, each model loaded once. Plain data in and out."""
    models: dict[Any, Model | str] = {}
    out = []
    for index, source, at in part:
        label, shown = _label(source), _at_label(at)
        key = _source_key(source)
        model = models.get(key) if key is not None else None
        if model is None:
            try:
                model = source if isinstance(source, Model) else load_model(source)
            except Exception as exc:  # reported for this item alone
                model = _error_text(exc)
            if key is not None:
                models[key] = model
        if isinstance(model, str):
            out.append(BatchResult(index, label, shown, error=model))
            continue
        try:
            numbers, document = compute(model, at, *options)
        except Exception as exc:  # reported for this item alone
            out.append(BatchResult(index, label, shown, error=_error_text(exc)))
        else:
            out.append(BatchResult(index, label, shown, numbers, document))
    return out
