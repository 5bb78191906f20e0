"""Running a command or a snippet in a fresh interpreter under a time and a memory
bound, so that a regression that hangs (a reader blocked on a named pipe, a loop that
never ends, ``/dev/zero`` read to its end) fails its test instead of hanging the
suite."""

from __future__ import annotations

import os
import resource
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


@dataclass(frozen=True)
class Finished:
    """How a bounded run ended: exit code, outputs and wall-clock seconds."""

    returncode: int
    stdout: str
    stderr: str
    seconds: float


#: Address space of a bounded run: a regression that reads ``/dev/zero`` into memory
#: fails with a MemoryError instead of filling the machine.
MEMORY_BYTES = 4 * 1024**3


def _bound_memory() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_BYTES, MEMORY_BYTES))


def _run(argv: list[str], timeout: float, cwd: Path | None) -> Finished:
    env = {**os.environ, "PYTHONPATH": str(ROOT) + os.pathsep
           + os.environ.get("PYTHONPATH", "")}
    start = time.monotonic()
    try:
        done = subprocess.run(argv, capture_output=True, text=True, timeout=timeout,
                              env=env, cwd=cwd or ROOT, stdin=subprocess.DEVNULL,
                              preexec_fn=_bound_memory)
    except subprocess.TimeoutExpired:
        raise AssertionError(f"still running after {timeout} s: {argv[2:]}") from None
    return Finished(done.returncode, done.stdout, done.stderr, time.monotonic() - start)


def run_coopkin(*args: str, timeout: float = 30, cwd: Path | None = None) -> Finished:
    """``coopkin ARGS`` in a fresh interpreter, ended (and the test failed) at
    ``timeout`` seconds."""
    return _run([sys.executable, "-m", "coopkin_sym", *args], timeout, cwd)


def run_python(code: str, timeout: float = 30) -> Finished:
    """``python -c CODE`` in a fresh interpreter, ended (and the test failed) at
    ``timeout`` seconds."""
    return _run([sys.executable, "-c", code], timeout, None)
