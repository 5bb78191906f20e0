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
from collections.abc import Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.analysis.numbers import Numbers
from coopkin_sym.exact.bounded import report
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model

__all__ = ["Place", "Progress", "SearchContext"]


class Progress:
    """Where the search stands, as a share of the work, reported (when ``enabled``)
    through :func:`coopkin_sym.exact.bounded.report` for the caller's display.

    The work is a tree: :meth:`parts` splits the current part into ``n`` equal parts
    (the factors at one depth, the slices at q = pi), :meth:`step` moves to the next
    one, and a part split further (a component searched inside) shares its own span
    among its parts. ``done`` (an exact fraction) is the start of the current part:
    it only grows, reaches 1 only when the search ends, and moves while long steps
    run deep in the tree. ``text`` is the current step. Each change is reported.

    Example
    -------
    >>> seen = []
    >>> with Progress(False) as bar:
    ...     with bar.parts(2):
    ...         bar.step("depth 0: t_q1")
    ...         with bar.parts(4):
    ...             bar.step("depth 1: t_q2")
    ...             bar.step("depth 1: t_q2 - 1")
    ...             seen.append(bar.done)
    ...         bar.step("depth 0: t_q2")
    ...         seen.append((bar.done, bar.text))
    >>> seen
    [Fraction(1, 8), (Fraction(1, 2), 'depth 0: t_q2')]
    >>> bar.done
    Fraction(1, 1)
    """

    #: Units of the share reported (it is reported in whole units of it).
    UNITS = 10_000

    def __init__(self, enabled: bool):
        self.enabled = enabled
        self.done = Fraction(0)
        self.text = "locus"
        # per level: [start, width, bounds of its parts (0 .. total weight), index
        # of the current part (-1: none yet), its text]
        self._levels: list[list] = [[Fraction(0), Fraction(1), [0, 1], 0, self.text]]

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.done = Fraction(1)
        self._show()

    def _part(self) -> tuple[Fraction, Fraction]:
        """Start and width of the current part."""
        start, width, bounds, index, _ = self._levels[-1]
        i = max(index, 0)
        total = bounds[-1]
        return start + width * bounds[i] / total, width * (bounds[i + 1] - bounds[i]) / total

    @contextmanager
    def parts(self, n: int, weights: Sequence[int] | None = None):
        """Split the current part into ``n`` parts (at least one), equal or in the
        proportions ``weights`` (one positive whole number per part), for the block's
        :meth:`step` calls; at the end the whole part is done."""
        weights = list(weights) if weights is not None else [1] * max(n, 1)
        if not weights:
            weights = [1]
        bounds = [0]
        for w in weights:
            bounds.append(bounds[-1] + max(int(w), 1))
        start, width = self._part()
        self._levels.append([start, width, bounds, -1, self.text])
        try:
            yield self
        finally:
            self._levels.pop()
            self.text = self._levels[-1][4]     # back to the step this split was in
            self._advance(start + width)

    def step(self, text: str) -> None:
        """Move to the next part of the innermost split, described by ``text``."""
        level = self._levels[-1]
        level[3] = min(level[3] + 1, len(level[2]) - 2)
        self.text = level[4] = text[:60]
        self._advance(self._part()[0])

    def _advance(self, to: Fraction) -> None:
        self.done = max(self.done, min(to, Fraction(1)))
        self._show()

    def _show(self) -> None:
        if self.enabled:   # the share in whole units: full only when done is 1
            report(self.text, int(self.done * self.UNITS) / self.UNITS)


@dataclass
class SearchContext:
    """What the search reads in one chart, and the counters it keeps.

    ``ring_names`` are the free variables (``t_<joint>``, prismatic joints, free
    parameters) and ``kinds`` maps each to ``(kind, joint or parameter)``; ``rows0`` and
    ``kin`` are ``Q`` and the kinematics with every free variable (``kin`` is None in a
    slice at q = pi until a witness there builds it); ``readings`` (equation
    text -> the equation in angles) and ``chains`` (component id -> its context and
    linear parametrization) are shared by the charts; ``hidden`` and ``splits`` count how
    deep the search is inside candidate sets with the enclosing numbers and inside zero
    sets of single minors; ``pi`` are the joints at q = pi in this chart; ``deferred``
    holds, per level, searches run after that level's components; ``polys`` maps
    equation texts to their polynomials; ``owners`` (component id -> its context) is
    shared by the charts; ``analyses`` holds the exact analyses at the points tried
    (``--at`` text -> analysis).

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
    steps: Any = None  # the search's recursive steps (search.components.Steps)
    analyses: dict = field(default_factory=dict)
    # id of a recorded component -> (its equations, as a tuple, and as a frozenset)
    equation_sets: dict = field(default_factory=dict)
    # the families with no rational parametrization searched inside (their equations),
    # and how many such searches are running (a point found there that a recorded
    # component with its numbers holds, in any chart, is not recorded again)
    searched: set = field(default_factory=set)
    inside: int = 0
    # steps left of the budget of the searches inside sets held by a component of
    # another chart (None: not started)
    held_left: int | None = None
    # the systems in one or two variables solved (the ring, their texts, the
    # variables, the degree bound) -> the points found (the search meets the same
    # system again from other components)
    solved: dict = field(default_factory=dict)

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
