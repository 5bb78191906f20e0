"""Wall-clock bounds and work budgets for long exact computations.

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
import math
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

from coopkin_sym.errors import TimeLimitReached, WorkLimitReached

__all__ = ["Bound", "TimeLimitReached", "WorkLimitReached", "active", "check", "give_up", "keep",
           "budget_left", "kept", "remaining", "spend", "time_limit",
           "work_limit"]


@dataclass
class Bound:
    """One wall-clock bound: it ends at ``end`` (``time.monotonic()``), ``seconds``
    after ``started``; ``kept`` is what the computation registered with :func:`keep`.
    Under a work budget, ``budget`` is ``[steps left]`` (shared by the bounds set
    inside it) and ``steps`` the budget given.

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
    budget: list | None = None
    steps: int | None = None


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
    if outer is not None:
        bound.budget, bound.steps = outer.budget, outer.steps
    token = _CURRENT.set(bound)
    try:
        yield bound
    finally:
        _CURRENT.reset(token)


@contextmanager
def work_limit(steps: int, owner: str = "") -> Iterator[Bound]:
    """Run the body under a budget of ``steps`` calls of :func:`check` (each spends
    one), set by ``owner`` (see :func:`active`); any enclosing time bound still
    applies, and inside an outer budget the steps spent count against it too.

    Example
    -------
    >>> with work_limit(3, "an example") as bound:
    ...     try:
    ...         for _ in range(10):
    ...             check("a loop")
    ...     except WorkLimitReached as exc:
    ...         message = str(exc)
    >>> message, bound.budget
    ('work budget of 3 steps used up during a loop', [-1])
    """
    outer = _CURRENT.get()
    now = time.monotonic()
    left = steps if outer is None or outer.budget is None else min(steps, outer.budget[0])
    bound = Bound(math.inf if outer is None else outer.end,
                  math.inf if outer is None else outer.seconds, now, owner=owner,
                  outer=outer, budget=[left], steps=steps)
    token = _CURRENT.set(bound)
    try:
        yield bound
    finally:
        _CURRENT.reset(token)
        if outer is not None and outer.budget is not None:
            outer.budget[0] -= left - bound.budget[0]


def check(where: str = "") -> None:
    """Raise :class:`TimeLimitReached` when the current bound has passed, and
    :class:`WorkLimitReached` when the current work budget is used up (cheap: call it
    in every loop that can run long)."""
    bound = _CURRENT.get()
    if bound is None:
        return
    if bound.budget is not None:
        bound.budget[0] -= 1
        if bound.budget[0] < 0:
            raise WorkLimitReached(bound.steps, where)
    if time.monotonic() > bound.end:
        raise TimeLimitReached(bound.seconds, where)


def spend(steps: int, where: str = "") -> None:
    """Spend ``steps`` of the current work budget at once (before an operation that
    cannot be interrupted, in proportion to its size), then :func:`check`: an
    operation larger than the budget left is never started."""
    bound = _CURRENT.get()
    if bound is not None and bound.budget is not None:
        bound.budget[0] -= max(int(steps), 0)
    check(where)


def give_up(where: str = "") -> None:
    """Raise :class:`TimeLimitReached` now, under a time bound: an operation that
    cannot be interrupted and would outlast the time left is not started.

    Example
    -------
    >>> with time_limit(60, "an example"):
    ...     try:
    ...         give_up("a large gcd")
    ...     except TimeLimitReached as exc:
    ...         message = str(exc)
    >>> message
    'time bound of 60 s reached during a large gcd'
    """
    bound = _CURRENT.get()
    raise TimeLimitReached(bound.seconds if bound is not None else 0.0, where)


def budget_left() -> int | None:
    """Steps left of the current work budget (``None`` without one)."""
    bound = _CURRENT.get()
    return None if bound is None or bound.budget is None else max(bound.budget[0], 0)


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
    """Seconds left under the current bound (``None`` without one: a work budget
    alone is no time bound)."""
    bound = _CURRENT.get()
    if bound is None or bound.end == math.inf:
        return None
    return bound.end - time.monotonic()


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
