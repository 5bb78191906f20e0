"""Wall-clock bounds for long exact computations.

A computation runs inside :func:`time_limit`; the loops of the exact layer (fraction-
free elimination, determinants, nullspaces, reductions modulo a polynomial) call
:func:`check`, which costs one clock reading, and raise
:class:`~coopkin_sym.errors.TimeLimitReached` once the bound has passed. The bound
lives in a context variable, so it follows the code that set it (threads and tasks
each have their own) and nested bounds keep the tighter one. A caller that wants a
partial result back registers it with :func:`keep`; after the error, it is on the
bound (``bound.kept``).

Example
-------
>>> import time
>>> with time_limit(0.01) as bound:
...     try:
...         keep(["partial"])
...         while True:
...             check("a long loop")
...     except TimeLimitReached as exc:
...         message, kept = str(exc), bound.kept
>>> message, kept
('time bound of 0.01 s reached during a long loop', ['partial'])
"""

from __future__ import annotations

import contextvars
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

from coopkin_sym.errors import TimeLimitReached

__all__ = ["Bound", "TimeLimitReached", "active", "check", "keep", "kept", "remaining",
           "time_limit"]


@dataclass
class Bound:
    """One wall-clock bound: it ends at ``end`` (``time.monotonic()``), ``seconds``
    after ``started``; ``kept`` is what the computation registered with :func:`keep`.

    Example
    -------
    >>> with time_limit(60, "an example") as bound:
    ...     bound.seconds
    60.0
    """

    end: float
    seconds: float
    started: float
    kept: object = None
    owner: str = ""
    outer: Bound | None = None


_CURRENT: contextvars.ContextVar[Bound | None] = contextvars.ContextVar(
    "coopkin_time_limit", default=None)


@contextmanager
def time_limit(seconds: float | None, owner: str = "",
               margin: float = 0.0) -> Iterator[Bound | None]:
    """Run the body under a bound of ``seconds`` (``None``: no new bound), set by
    ``owner`` (see :func:`active`). Inside an outer bound the tighter of the two
    applies. With a ``margin`` the bound ends that many seconds early (time left to
    hand back a partial result), its messages still naming ``seconds``."""
    if seconds is None:
        yield _CURRENT.get()
        return
    now = time.monotonic()
    outer = _CURRENT.get()
    seconds = float(seconds)  # float-ok: a time
    bound = Bound(now + max(seconds - margin, 0.0), seconds, now, owner=owner, outer=outer)
    if outer is not None and outer.end < bound.end:
        bound.end, bound.seconds = outer.end, outer.seconds
    token = _CURRENT.set(bound)
    try:
        yield bound
    finally:
        _CURRENT.reset(token)


def check(where: str = "") -> None:
    """Raise :class:`TimeLimitReached` when the current bound has passed (cheap: call
    it in every loop that can run long)."""
    bound = _CURRENT.get()
    if bound is not None and time.monotonic() > bound.end:
        raise TimeLimitReached(bound.seconds, where)


def active(owner: str | None = None) -> bool:
    """Whether a bound applies here (with ``owner``: a bound set by that owner, in
    this bound or an enclosing one)."""
    bound = _CURRENT.get()
    if owner is None:
        return bound is not None
    while bound is not None:
        if bound.owner == owner:
            return True
        bound = bound.outer
    return False


def remaining() -> float | None:
    """Seconds left under the current bound (``None`` without one)."""
    bound = _CURRENT.get()
    return None if bound is None else bound.end - time.monotonic()


def kept() -> object:
    """What the current bound, or the nearest enclosing one, keeps (None: nothing)."""
    bound = _CURRENT.get()
    while bound is not None:
        if bound.kept is not None:
            return bound.kept
        bound = bound.outer
    return None


def keep(value: object) -> None:
    """Register ``value`` (a result being filled in) with the current bound, so the
    caller still has it after :class:`TimeLimitReached`."""
    bound = _CURRENT.get()
    if bound is not None:
        bound.kept = value
