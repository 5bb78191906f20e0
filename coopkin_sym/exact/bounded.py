"""Bounded runs: a computation that ends at its wall-clock bound, whatever it is doing,
and says what it is doing while it runs.

:func:`run_bounded` is the one way a long computation gets a bound of ``seconds``:

* with a bound, the work runs in a forked child process (cheap: every module is
  already imported) inside a cooperative :func:`~coopkin_sym.exact.deadline.time_limit`
  a little shorter than the bound, so the loops of the exact layer stop in time and a
  caller that keeps a partial result (``deadline.keep``) gets it back. A step that
  cannot be interrupted (a flint factorization or resultant, a SymPy simplification,
  which hold the interpreter and ignore signals) cannot overshoot: at the bound the
  child, with any worker processes it started, is ended, and
  :class:`~coopkin_sym.errors.TimeLimitReached` names the step that was running
  (``hard`` is then true), and carries in ``kept`` the last copy of the partial
  result the work registered (``deadline.keep``), sent at most every
  :data:`SNAPSHOT_SECONDS` at a reported step, or None. The result comes back
  pickled (flint polynomials pickle, see :mod:`coopkin_sym.exact.pickling`); errors
  come back as themselves.
* without a bound (or where processes cannot be forked) the work runs here, unless
  it is asked to run apart (``separate``: a display then keeps moving while a step
  holds the interpreter).

The work says what it is doing with :func:`report` (a step and, when known, the share
done) and hands over partial output with :func:`deliver`; both go to the callbacks the
caller of :func:`run_bounded` gave (the presentation layer's progress display, a
printer), through the pipe from the child when there is one. Outside a bounded run
they go to the callbacks installed with :func:`reporting`, or nowhere (one context
variable read: cheap enough for any loop).

Example
-------
>>> steps = []
>>> def work():
...     report("the first step", 0.5)
...     return 6 * 7
>>> run_bounded(work, 30, progress=lambda step, done: steps.append((step, done)))
42
>>> steps[-1]
('the first step', 0.5)
>>> import time
>>> try:
...     run_bounded(lambda: (report("a long sleep"), time.sleep(60)), 0.5)
... except TimeLimitReached as exc:
...     print(exc, exc.hard)
time bound of 0.5 s reached during a long sleep True
"""

from __future__ import annotations

import contextvars
import os
import pickle
import signal
import sys
import time
import traceback
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any, TypeVar

from coopkin_sym.errors import TimeLimitReached, WorkerFailed
from coopkin_sym.exact import deadline

__all__ = ["Reporter", "TimeLimitReached", "checkpoint", "deliver", "report", "reporting",
           "run_bounded", "cooperative_seconds"]

T = TypeVar("T")

#: ``progress(step, done)``: ``done`` is the share done (0..1) or None.
ProgressCallback = Callable[[str, "float | None"], None]


class Reporter:
    """Where :func:`report`, :func:`deliver` and :func:`checkpoint` go: a progress
    callback, an output callback and a snapshot callback (any may be None).

    Example
    -------
    >>> seen = []
    >>> with reporting(Reporter(output=seen.append)):
    ...     deliver("a part")
    >>> seen
    ['a part']
    """

    def __init__(self, progress: ProgressCallback | None = None,
                 output: Callable[[Any], None] | None = None,
                 snapshot: Callable[[], None] | None = None):
        self.progress = progress
        self.output = output
        self.snapshot = snapshot


_REPORTER: contextvars.ContextVar[Reporter | None] = contextvars.ContextVar(
    "coopkin_reporter", default=None)

#: The step a bounded run is in when nothing was reported yet.
FIRST_STEP = "the start"

#: A bounded child sends a copy of its kept partial result at a reported step at most
#: this often (the parent has it if the child must be ended at the bound).
SNAPSHOT_SECONDS = 1.0


def report(step: str, done: float | None = None) -> None:
    """Say that the computation is now at ``step`` (``done``: the share of the work
    done, 0..1, when known); nothing happens outside a :func:`run_bounded` that shows
    progress.

    Example
    -------
    >>> steps = []
    >>> run_bounded(lambda: report("reading", 0.5), None,
    ...             progress=lambda step, done: steps.append((step, done)))
    >>> steps
    [('reading', 0.5)]
    """
    reporter = _REPORTER.get()
    if reporter is not None and reporter.progress is not None:
        reporter.progress(step, done)


def deliver(item: Any) -> None:
    """Hand over a finished part of the output (shown at once by the caller, even when
    the rest is then cut by the bound); ``item`` must pickle.

    Example
    -------
    >>> parts = []
    >>> run_bounded(lambda: deliver("the numbers"), None, output=parts.append)
    >>> parts
    ['the numbers']
    """
    reporter = _REPORTER.get()
    if reporter is not None and reporter.output is not None:
        reporter.output(item)


def checkpoint(value: Any) -> None:
    """Keep ``value`` (a result complete so far) with the current bound and hand a copy
    of it to the caller now, so that a run ended at its bound inside a step that cannot
    be interrupted (:attr:`~coopkin_sym.errors.TimeLimitReached.kept`) ends with this
    copy, not an older one; ``value`` must pickle.

    Example
    -------
    >>> def work():
    ...     checkpoint({"found": 3})
    ...     import time; time.sleep(5)
    >>> try:
    ...     run_bounded(work, 1.0, separate=True)
    ... except TimeLimitReached as exc:
    ...     print(exc.kept)
    {'found': 3}
    """
    deadline.keep(value)
    reporter = _REPORTER.get()
    if reporter is not None and reporter.snapshot is not None:
        reporter.snapshot()


@contextmanager
def reporting(reporter: Reporter | None) -> Iterator[None]:
    """Send :func:`report` and :func:`deliver` to ``reporter`` inside the block."""
    token = _REPORTER.set(reporter)
    try:
        yield
    finally:
        _REPORTER.reset(token)


def cooperative_seconds(seconds: float) -> float:
    """The cooperative bound inside a hard bound of ``seconds``: shorter by a tenth
    (at least half a second, at most five, never more than half the bound), so that
    a computation stopped by it still hands back its partial result in time although
    the step it is in (a flint call between two checks of the bound) may last a little
    longer.

    Example
    -------
    >>> cooperative_seconds(100), cooperative_seconds(2), cooperative_seconds(0.3)
    (95.0, 1.5, 0.15)
    """
    return seconds - min(max(0.1 * seconds, 0.5), 5.0, 0.5 * seconds)


def run_bounded(work: Callable[[], T], seconds: float | None, *, owner: str = "",
                progress: ProgressCallback | None = None,
                output: Callable[[Any], None] | None = None,
                tick: float = 0.2, separate: bool = False,
                started: float | None = None) -> T:
    """``work()``, ended at ``seconds`` (None: no bound) of wall-clock time.

    Parameters
    ----------
    work
        The computation (any callable: it is not pickled, the child is forked).
    seconds
        The bound; the cooperative one inside is :func:`cooperative_seconds`.
    owner
        The name of the cooperative bound (see :func:`deadline.active`).
    progress
        Called with each step the work reports, and every ``tick`` seconds with the
        last one (so that a display can show the time passing during a long step).
    output
        Called with each item the work delivers, in order.
    separate
        Without a bound too, run the work in a child process (so that ``progress``
        keeps being called while a step holds the interpreter).
    started
        When the bound started (``time.monotonic()``; default: now), e.g. when the
        command started, so that the time it took to get here counts.

    Raises
    ------
    TimeLimitReached
        When the work ran past the cooperative bound without keeping a result, or
        when it was ended at the bound (``hard``: true; ``where``: the step;
        ``kept``: the last copy of the partial result it registered, or None).

    Example
    -------
    >>> run_bounded(lambda: sum(range(10)), None)
    45
    """
    if not hasattr(os, "fork") or (seconds is None and not separate):
        # here (without fork, the bound is only cooperative)
        with reporting(Reporter(progress, output)), deadline.time_limit(seconds, owner):
            return work()
    seconds = None if seconds is None else float(seconds)  # float-ok: a time
    started = time.monotonic() if started is None else started
    return _run_in_child(work, seconds, owner, progress, output, tick, started)


def _run_in_child(work, seconds: float | None, owner: str, progress, output,
                  tick: float, started: float):
    import multiprocessing

    end = started + seconds if seconds is not None else float("inf")  # float-ok: time
    context = multiprocessing.get_context("fork")
    receive, send = context.Pipe(duplex=False)
    child = context.Process(target=_child, daemon=False,
                            args=(work, seconds, owner, send, started, os.getpid()))
    sys.stdout.flush()
    sys.stderr.flush()
    child.start()
    send.close()
    step, done, snapshot = FIRST_STEP, None, None
    try:
        while True:
            left = end - time.monotonic()
            if left <= 0:
                error = TimeLimitReached(seconds, step, hard=True)
                error.kept = None if snapshot is None else _unpickled(snapshot)
                raise error
            if not receive.poll(min(left, tick)):
                if progress is not None:
                    progress(step, done)
                continue
            try:
                kind, payload = receive.recv()
            except EOFError:
                child.join(1.0)
                raise WorkerFailed(f"the worker process of {owner or 'a bounded run'} "
                                   f"stopped without an answer (exit code "
                                   f"{child.exitcode})") from None
            if kind == "step":
                step, done = payload
                if progress is not None:
                    progress(step, done)
            elif kind == "output":
                if output is not None:
                    output(payload)
            elif kind == "kept":
                snapshot = payload
            elif kind == "done":
                return payload
            else:  # "error"
                error, trace = payload
                if trace:
                    error.__cause__ = _RemoteTraceback(trace)
                raise error
    finally:
        _end(child)
        receive.close()


def _unpickled(data: bytes):
    try:
        return pickle.loads(data)
    except Exception:  # noqa: BLE001 - a copy that does not come back: none
        return None


class _RemoteTraceback(Exception):
    """The traceback of an error in the child, as its text."""

    def __init__(self, text: str):
        super().__init__(text)

    def __str__(self) -> str:
        return "\n" + self.args[0]


def _end(child) -> None:
    """End the child and every process it started (its own process group)."""
    if child.exitcode is None:
        try:
            os.killpg(child.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            child.kill()
    child.join()


def _end_with_parent(parent: int) -> None:
    """Have this process killed when its parent ends, however it ends (Linux: the
    parent-death signal; elsewhere only the parent's own cleanup ends it)."""
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(1, int(signal.SIGKILL))          # PR_SET_PDEATHSIG
    except (OSError, AttributeError):  # pragma: no cover - not Linux
        return
    if os.getppid() != parent:                    # the parent ended before that
        os._exit(1)


def _child(work, seconds: float | None, owner: str, send, started: float,
           parent: int) -> None:
    """The forked side: its own process group (so that it and its workers end
    together), Ctrl-C left to the parent, ended with the parent, reports through the
    pipe."""
    try:
        os.setpgid(0, 0)
    except OSError:  # pragma: no cover - already a group leader
        pass
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _end_with_parent(parent)
    last = [0.0, None, time.monotonic()]

    def step(text: str, done: float | None) -> None:
        now = time.monotonic()
        if now - last[0] >= 0.05 or text != last[1]:   # at most 20 a second per step
            last[0], last[1] = now, text
            send.send(("step", (text, done)))
        if now - last[2] >= SNAPSHOT_SECONDS:
            last[2] = now
            value = deadline.kept()
            if value is not None:
                try:
                    send.send(("kept", pickle.dumps(value)))
                except Exception:  # noqa: BLE001, S110 - no copy this time, the next one
                    pass

    def item(value) -> None:
        send.send(("output", value))

    def snapshot() -> None:
        last[2] = time.monotonic()
        send.send(("kept", pickle.dumps(deadline.kept())))

    # the cooperative bound ends cooperative_seconds after ``started``
    margin = 0.0 if seconds is None else (seconds - cooperative_seconds(seconds)
                                          + time.monotonic() - started)
    with reporting(Reporter(step, item, snapshot)):
        try:
            with deadline.time_limit(seconds, owner, margin=margin):
                result = work()
            message = ("done", result)
        except BaseException as exc:  # noqa: BLE001 - every error goes to the parent
            trace = "" if isinstance(exc, TimeLimitReached) else traceback.format_exc()
            message = ("error", (exc, trace))
    try:
        send.send(message)
    except Exception as exc:  # noqa: BLE001 - an answer that does not pickle
        send.send(("error", (RuntimeError(f"the result could not be sent back: {exc}"),
                             traceback.format_exc())))
    send.close()
