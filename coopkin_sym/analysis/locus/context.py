"""The state of one singularity-locus search: what every step reads, and where it is.

A :class:`SearchContext` holds what is fixed for one chart of the search (the model,
the configuration, the ring of its free variables, the generic numbers, the locus being
filled, the bounds) and the few counters the search keeps; a :class:`Place` says where
the search stands inside that chart: the rows of ``Q`` there, the equations that led
there, the parametrization of the variables solved so far, the numbers around it, its
depth and the component it lies in. Each step of :mod:`.search` takes the two.

Example
-------
>>> place = Place(rows=[], equations=["t_q1 - t_q2"], point={}, depth=0)
>>> place.inside(depth=1, parent=0).depth, place.equations
(1, ['t_q1 - t_q2'])
"""

from __future__ import annotations

import dataclasses
import random
import time
from dataclasses import dataclass, field
from typing import Any

from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.analysis.numbers import Numbers
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model

__all__ = ["Place", "Progress", "SearchContext"]


class Progress:
    """A rich progress bar on standard error, or nothing (``enabled`` false).

    Example
    -------
    >>> with Progress(False) as bar:
    ...     bar.add(3)
    ...     bar.step("depth 0: t_q1")
    """

    def __init__(self, enabled: bool):
        self.enabled = enabled
        self._progress = None
        self._task = None

    def __enter__(self):
        if self.enabled:
            from rich.progress import Progress as RichProgress  # optional, at use

            self._progress = RichProgress(transient=True)
            self._progress.__enter__()
            self._task = self._progress.add_task("locus", total=0)
        return self

    def __exit__(self, *exc):
        if self._progress is not None:
            self._progress.__exit__(*exc)

    def add(self, n: int) -> None:
        if self._progress is not None:
            total = self._progress.tasks[0].total or 0
            self._progress.update(self._task, total=total + n)

    def step(self, text: str) -> None:
        if self._progress is not None:
            self._progress.update(self._task, advance=1, description=text[:60])


@dataclass
class SearchContext:
    """What the search reads in one chart, and the counters it keeps.

    ``ring_names`` are the free variables (``t_<joint>``, prismatic joints, free
    parameters) and ``kinds`` maps each to ``(kind, joint or parameter)``; ``rows0`` and
    ``kin`` are ``Q`` and the kinematics with every free variable; ``readings`` (equation
    text -> the equation in angles) and ``chains`` (component id -> its context and
    linear parametrization) are shared by the charts; ``hidden`` and ``splits`` count how
    deep the search is inside candidate sets with the enclosing numbers and inside zero
    sets of single minors; ``pi`` are the joints at q = pi in this chart; ``deferred``
    holds, per level, searches run after that level's components; ``polys`` maps
    equation texts to their polynomials; ``owners`` (component id -> its context) is
    shared by the charts.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.search import compute_locus
    >>> from coopkin_sym import load
    >>> compute_locus(load("paper-case1-hard")).variables    # the context's ring_names
    ['t_q1', 't_q2']
    """

    model: Model
    config: Configuration
    ring_names: tuple[str, ...]
    kinds: dict[str, tuple[str, str]]
    row_contacts: list[int]
    symbols: dict
    ring: Any
    generic: Numbers
    deadline: float | None
    max_depth: int
    locus: Locus
    rng: random.Random
    rows0: list
    kin: Any
    readings: dict
    chains: dict
    reporter: Progress
    hidden: int = 0
    splits: int = 0
    pi: frozenset = frozenset()
    deferred: list = field(default_factory=list)
    polys: dict = field(default_factory=dict)
    owners: dict | None = None

    def expired(self) -> bool:
        """Whether the time bound has passed."""
        return self.deadline is not None and time.monotonic() > self.deadline


@dataclass(frozen=True)
class Place:
    """Where the search stands in a chart.

    Attributes
    ----------
    rows
        The rows of ``Q`` here (variables substituted, denominators cleared), or None
        where there is no rational parametrization.
    equations
        The equations (texts) whose common zeros lead here.
    point
        The parametrized variables: name -> ``(f0, f1)``, the variable being
        ``-f0/f1``; None where there is no rational parametrization.
    depth
        0 in the generic locus, ``k`` inside a component of depth ``k - 1``.
    parent
        The index of the component this place lies in (None at depth 0).
    base
        The numbers everywhere here (the enclosing ones), when known.
    charts
        The denominators ``f1`` of the parametrization: the rows hold where none
        vanishes.

    Example
    -------
    >>> start = Place(rows=[], equations=[], point={}, depth=0)
    >>> start.inside(equations=["t_q1"], depth=1, parent=0).parent
    0
    """

    rows: list | None
    equations: list[str]
    point: dict | None
    depth: int
    parent: int | None = None
    base: Numbers | None = None
    charts: tuple = ()

    def inside(self, **changes) -> Place:
        """This place with some attributes changed (a place found inside it)."""
        return dataclasses.replace(self, **changes)
