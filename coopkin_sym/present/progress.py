"""The progress display: what a long command is doing, on standard error, once it has
run for about a second.

The computations report their steps through :func:`coopkin_sym.exact.bounded.report`
(a step and, when known, the share done); :func:`progress_display` gives the callback
that shows them: a spinner, the step, a bar when the share is known, and the time
since the command started. Nothing is shown before ``delay`` seconds (a quick command
stays quiet) nor when the display is not enabled (``--no-progress``, or standard error is not a
terminal); the display disappears when the block ends.

Example
-------
>>> with progress_display(False, "locus") as show:
...     show("depth 0: the numbers", 0.25)
>>> show.shown
False
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["ProgressDisplay", "progress_display"]


class ProgressDisplay:
    """A callback ``display(step, done)`` that draws a rich progress line on stderr
    ``delay`` seconds after ``started`` (default: now), when ``enabled``.

    Example
    -------
    >>> display = ProgressDisplay(False, "sweep")
    >>> display("points", 0.5); display.step, display.done, display.shown
    ('points', 0.5, False)
    """

    #: Units of the bar (the share done is shown in whole units of it).
    UNITS = 10_000

    def __init__(self, enabled: bool, what: str, delay: float = 1.0,
                 started: float | None = None):
        self.enabled, self.what, self.delay = enabled, what, delay
        self.started = time.monotonic() if started is None else started
        self.step, self.done = what, None
        self.shown = False
        self._bar = None
        self._task = None

    def __call__(self, step: str, done: float | None = None) -> None:
        self.step, self.done = step, done
        if not self.enabled:
            return
        if self._bar is None:
            if time.monotonic() - self.started < self.delay:
                return
            self._open()
        self._show()

    def _open(self) -> None:
        from rich.console import Console
        from rich.progress import (
            BarColumn,
            Progress,
            SpinnerColumn,
            TaskProgressColumn,
            TextColumn,
        )
        from rich.table import Column

        # a description of fixed width, so that the bar keeps its place
        text = TextColumn("{task.description}",
                          table_column=Column(width=52, no_wrap=True, overflow="ellipsis"))
        # the time since the command started (not since the display did)
        self._bar = Progress(SpinnerColumn(), text, BarColumn(), TaskProgressColumn(),
                             TextColumn("{task.fields[elapsed]}"),
                             console=Console(stderr=True), transient=True)
        self._task = self._bar.add_task("", total=None, elapsed="")
        self._show()                     # the first frame drawn already says it all
        self._bar.__enter__()
        self.shown = True

    def _show(self) -> None:
        from rich.markup import escape

        units = None if self.done is None else int(min(max(self.done, 0), 1) * self.UNITS)
        seconds = int(time.monotonic() - self.started)
        self._bar.update(self._task, description=escape(f"{self.what}: {self.step}"[:200]),
                         total=None if units is None else self.UNITS,
                         completed=units or 0,
                         elapsed=f"{seconds // 60}:{seconds % 60:02d}")

    def close(self) -> None:
        """Remove the display (if it was shown)."""
        if self._bar is not None:
            self._bar.__exit__(None, None, None)
            self._bar = None


@contextmanager
def progress_display(enabled: bool, what: str, delay: float = 1.0,
                     started: float | None = None) -> Iterator[ProgressDisplay]:
    """A :class:`ProgressDisplay` for the block, removed at its end (``started``: when
    the command started, ``time.monotonic()``; default now)."""
    display = ProgressDisplay(enabled, what, delay, started)
    try:
        yield display
    finally:
        display.close()
