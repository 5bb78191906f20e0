"""The progress display: what a long command is doing, once it has run for about a
second, where the person waiting sees it.

The computations report their steps through :func:`coopkin_sym.exact.bounded.report`
(a step and, when known, the share done); :func:`progress_display` gives the callback
that shows them: the step, a bar when the share is known, and the time since the
command started. Where it is shown is found by :func:`progress_medium`:

* in a Jupyter kernel, one HTML output of the cell (a bar and a line of text), updated
  in place at most :data:`JUPYTER_UPDATES_PER_SECOND` times a second; it needs no
  widget package, and its last state (done, or where it stopped) stays in the cell;
* on a terminal (standard error is one), a rich progress line on standard error with
  a spinner, removed when the block ends;
* anywhere else (output piped or sent to a file), nothing.

Nothing is shown before ``delay`` seconds (a quick command stays quiet; see
:data:`DELAY`) nor when the display is not enabled (``--no-progress``,
``progress=False``).

Example
-------
>>> with progress_display(False, "locus") as show:
...     show("depth 0: the numbers", 0.25)
>>> show.shown
False
"""

from __future__ import annotations

import html
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["DELAY", "JUPYTER_UPDATES_PER_SECOND", "ProgressDisplay", "jupyter_kernel",
           "progress_display", "progress_medium"]

#: Seconds a command runs before its progress is shown (a quick one stays quiet).
DELAY = 1.0

#: At most this many updates a second of the display in a Jupyter cell (each one is a
#: message to the notebook, kept by it).
JUPYTER_UPDATES_PER_SECOND = 5


def jupyter_kernel() -> bool:
    """Whether this process is a Jupyter (IPython) kernel: IPython is running here with
    a kernel (a terminal IPython has none). IPython is not imported to find out.

    Example
    -------
    >>> jupyter_kernel()
    False
    """
    ipython = sys.modules.get("IPython")
    if ipython is None:
        return False
    try:
        shell = ipython.get_ipython()
    except Exception:                   # an IPython too old or half imported
        return False
    if shell is None:
        return False
    return getattr(shell, "kernel", None) is not None or "IPKernelApp" in getattr(
        shell, "config", {})


def progress_medium() -> str | None:
    """Where a progress display is seen here: ``"jupyter"`` (a Jupyter kernel),
    ``"terminal"`` (standard error is a terminal) or None (nowhere: be silent).

    Example
    -------
    >>> progress_medium() in ("jupyter", "terminal", None)
    True
    """
    if jupyter_kernel():
        return "jupyter"
    try:
        return "terminal" if sys.stderr.isatty() else None
    except (AttributeError, ValueError):          # no stderr, or a closed one
        return None


class ProgressDisplay:
    """A callback ``display(step, done)`` that shows the step ``delay`` seconds (default
    :data:`DELAY`) after ``started`` (default: now), when ``enabled``, where
    :func:`progress_medium` says it is seen (or on ``medium``: ``"jupyter"``,
    ``"terminal"``; None: found out).

    Example
    -------
    >>> display = ProgressDisplay(False, "sweep")
    >>> display("points", 0.5); display.step, display.done, display.shown
    ('points', 0.5, False)
    >>> display.text()
    'sweep: points, 50%, 0:00'
    """

    #: Units of the bar (the share done is shown in whole units of it).
    UNITS = 10_000

    def __init__(self, enabled: bool, what: str, delay: float | None = None,
                 started: float | None = None, medium: str | None = None):
        self.what = what
        self.delay = DELAY if delay is None else delay
        self.medium = (medium or progress_medium()) if enabled else None
        self.enabled = self.medium is not None
        self.started = time.monotonic() if started is None else started
        self.step, self.done = what, None
        self.shown = False
        self._bar = None
        self._task = None
        self._handle = None
        self._last = 0.0

    def __call__(self, step: str, done: float | None = None) -> None:
        self.step, self.done = step, done
        if not self.enabled:
            return
        if not self.shown:
            if time.monotonic() - self.started < self.delay:
                return
            self._open()
        elif self.medium == "jupyter":
            self._update()
        else:
            self._show()

    def elapsed(self) -> str:
        """The time since the command started, ``M:SS``."""
        seconds = int(time.monotonic() - self.started)
        return f"{seconds // 60}:{seconds % 60:02d}"

    def text(self, final: str | None = None) -> str:
        """The display as one line of text: what, the step, the share done, the time
        (``final``: the word that replaces the step once the block has ended)."""
        share = "" if self.done is None or final else f", {self._share():.0%}"
        step = final or self.step
        return f"{self.what}: {step}{share}, {self.elapsed()}"[:240]

    def _share(self) -> float:
        return 0.0 if self.done is None else min(max(self.done, 0.0), 1.0)

    def html(self, final: str | None = None) -> str:
        """The display as the HTML of a Jupyter output: a bar and :meth:`text`."""
        if final == "done":
            value = f' value="{self.UNITS}"'
        elif self.done is None:
            value = ""                    # no share known: the bar moves on its own
        else:
            value = f' value="{int(self._share() * self.UNITS)}"'
        bar = (f'<progress{value} max="{self.UNITS}" '
               'style="width:16em;vertical-align:middle"></progress>')
        return (f'<div class="coopkin-progress" style="font-family:monospace">{bar} '
                f"{html.escape(self.text(final))}</div>")

    def _open(self) -> None:
        self.shown = True
        if self.medium == "jupyter":
            from IPython.display import display
            self._handle = display(self._bundle(), raw=True, display_id=True)
            self._last = time.monotonic()
            return
        self._open_terminal()

    def _bundle(self, final: str | None = None) -> dict:
        return {"text/html": self.html(final), "text/plain": self.text(final)}

    def _update(self, final: str | None = None) -> None:
        now = time.monotonic()
        if final is None and now - self._last < 1.0 / JUPYTER_UPDATES_PER_SECOND:
            return
        self._last = now
        self._handle.update(self._bundle(final), raw=True)

    def _open_terminal(self) -> None:
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

    def _show(self) -> None:
        from rich.markup import escape

        units = None if self.done is None else int(self._share() * self.UNITS)
        self._bar.update(self._task, description=escape(f"{self.what}: {self.step}"[:200]),
                         total=None if units is None else self.UNITS,
                         completed=units or 0, elapsed=self.elapsed())

    def close(self, failed: bool = False) -> None:
        """End the display (if it was shown): on a terminal it is removed; in Jupyter
        its last state stays, ``done`` or, when ``failed``, where it stopped."""
        if self._bar is not None:
            self._bar.__exit__(None, None, None)
            self._bar = None
        if self._handle is not None:
            self._update(f"stopped during {self.step}" if failed else "done")
            self._handle = None


@contextmanager
def progress_display(enabled: bool, what: str, delay: float | None = None,
                     started: float | None = None) -> Iterator[ProgressDisplay]:
    """A :class:`ProgressDisplay` for the block, ended with it (``started``: when
    the command started, ``time.monotonic()``; default now).

    Example
    -------
    >>> with progress_display(True, "locus", delay=3600) as show:
    ...     show("depth 0: the numbers")
    >>> show.shown
    False
    """
    display = ProgressDisplay(enabled, what, delay, started)
    failed = True
    try:
        yield display
        failed = False
    finally:
        display.close(failed)
