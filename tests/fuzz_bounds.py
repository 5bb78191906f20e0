"""One fuzz case within a wall-clock bound and a memory bound.

:func:`run_bounded` runs a call in a forked child process. The child's address space
is limited (``RLIMIT_AS``: what it had at the fork plus ``memory`` bytes), so that an
input that would take gigabytes fails with ``MemoryError`` instead of taking the
machine; the parent ends the child (``SIGKILL``) at ``seconds``, so that even a call
that cannot be interrupted (a flint call, a loop in C) ends at its bound. The outcome
says how the call ended: a result, the package's own error, another exception (with
its traceback), the time bound, or the child's death by a signal.

Example
-------
>>> run_bounded(lambda: 6 * 7).value
42
>>> run_bounded(lambda: 1 / 0).kind
'crash'
>>> import time
>>> run_bounded(lambda: time.sleep(5), seconds=0.2).kind
'timeout'
>>> run_bounded(lambda: len(bytearray(3 * CASE_MEMORY))).error_type
'MemoryError'
"""

from __future__ import annotations

import os
import pickle
import resource
import select
import signal
import time
import traceback
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from coopkin_sym.errors import CoopkinError

#: Wall-clock bound on one fuzz case (seconds). The budgets keep honest cases far
#: below it; it is loose because the machine may be shared.
CASE_SECONDS = 10.0
#: Memory one fuzz case may add to the process (bytes).
CASE_MEMORY = 2 * 1024**3


@dataclass(frozen=True)
class Outcome:
    """How one bounded call ended.

    ``kind`` is ``"result"`` (``value`` holds what the call returned),
    ``"error"`` (a :class:`~coopkin_sym.errors.CoopkinError`: ``error_type`` and
    ``message``), ``"crash"`` (any other exception, ``detail`` holds its traceback),
    ``"timeout"`` or ``"died"`` (the child ended without an answer, ``detail`` says
    how). ``seconds`` is the wall-clock time the call took.

    Example
    -------
    >>> Outcome("error", error_type="ModelError", message="x: bad").failure is None
    True
    >>> Outcome("timeout", seconds=10.0).failure
    'no answer within 10 s'
    """

    kind: str
    value: Any = None
    error_type: str = ""
    message: str = ""
    detail: str = ""
    seconds: float = 0.0  # float-ok: a time measurement

    @property
    def failure(self) -> str | None:
        """What went wrong (None for a result or a package error)."""
        if self.kind == "timeout":
            return f"no answer within {self.seconds:g} s"
        if self.kind in ("crash", "died"):
            return f"{self.error_type}: {self.message}\n{self.detail}".strip()
        return None


def _address_space() -> int:
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmSize:"):
                return int(line.split()[1]) * 1024
    return 0


def _child(call: Callable[[], Any], memory: int, out: int) -> None:
    limit = _address_space() + memory
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    try:
        answer: tuple = ("result", call())
    except CoopkinError as exc:
        answer = ("error", type(exc).__name__, str(exc))
    except BaseException as exc:  # noqa: B036 - the child reports whatever happened
        answer = ("crash", type(exc).__name__, str(exc)[:4000],
                  traceback.format_exc()[-8000:])
    try:
        data = pickle.dumps(answer)
    except Exception as exc:  # an unpicklable result: say what it was
        data = pickle.dumps(("result", f"<unpicklable {type(answer[1]).__name__}: "
                                       f"{type(exc).__name__}>"))
    view = memoryview(data)
    while view:
        view = view[os.write(out, view):]


def run_bounded(call: Callable[[], Any], seconds: float = CASE_SECONDS,
                memory: int = CASE_MEMORY) -> Outcome:
    """Run ``call()`` in a forked child within ``seconds`` and ``memory`` bytes more
    than the process has (see the module).

    Example
    -------
    >>> from coopkin_sym import load
    >>> out = run_bounded(lambda: load({"name": "x"}))
    >>> out.kind, out.error_type
    ('error', 'ModelError')
    """
    read_end, write_end = os.pipe()
    start = time.monotonic()
    pid = os.fork()
    if pid == 0:  # the child: never returns into the caller's code
        status = 0
        try:
            os.close(read_end)
            _child(call, memory, write_end)
        except BaseException:  # noqa: B036
            status = 1
        finally:
            os._exit(status)
    os.close(write_end)
    chunks: list[bytes] = []
    timed_out = False
    try:
        while True:
            left = seconds - (time.monotonic() - start)
            if left <= 0:
                timed_out = True
                break
            ready, _, _ = select.select([read_end], [], [], left)
            if not ready:
                continue
            chunk = os.read(read_end, 1 << 16)
            if not chunk:
                break
            chunks.append(chunk)
    finally:
        if timed_out:
            os.kill(pid, signal.SIGKILL)
        _, status = os.waitpid(pid, 0)
        os.close(read_end)
    took = time.monotonic() - start
    if timed_out:
        return Outcome("timeout", seconds=seconds)
    if not chunks:
        how = (f"killed by signal {os.WTERMSIG(status)}" if os.WIFSIGNALED(status)
               else f"exit status {os.WEXITSTATUS(status)}")
        return Outcome("died", error_type="child", message=how, seconds=took)
    answer = pickle.loads(b"".join(chunks))
    if answer[0] == "result":
        return Outcome("result", value=answer[1], seconds=took)
    if answer[0] == "error":
        return Outcome("error", error_type=answer[1], message=answer[2], seconds=took)
    return Outcome("crash", error_type=answer[1], message=answer[2], detail=answer[3],
                   seconds=took)
