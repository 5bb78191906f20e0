"""Singularity locus: where, exactly, the mobility numbers change.

The numbers follow from three ranks: ``rank Gt^T`` (Ni), ``rank Dt`` (Nr) and
``rank Q`` (Nm); Nc = Nm - Nr. Each arm's joint variables appear only in its own
contacts' rows, so the rank of ``Q`` splits (at any point) as

    rank Q = sum_a rank Dt_a + rank A,    A = [Y_a Gt_a]_a  (and the ground rows),

with ``Y_a`` a left-nullspace basis of ``Dt_a``. A point where every ``Dt_a`` keeps its
generic rank, every ``Y_a`` keeps full rank and ``A`` and ``Gt^T`` keep theirs has the
generic numbers. Each of these matrices is small in one dimension (six object columns,
or one arm), so the set where it drops rank, the common zeros of its maximal minors,
is cut out by a few random combinations ``det(P M R)`` of them (Cauchy-Binet; random
integer ``P``, ``R``). Their gcd, factored over Z, gives the hypersurface components;
the rest is solved when few variables remain (isolated configurations).

Every candidate component is then decided exactly: when its polynomial is linear in a
variable it is parametrized and the numbers are computed over its function field
(and the search recurses inside it for deeper drops); otherwise by ranks modulo its
irreducible polynomial (:mod:`coopkin_sym.exact.quotient`: over the function field of a
curved hypersurface, or over a number field ``Q(alpha)`` for points with irrational
coordinates, every conjugate point at once). Points of two variables come from
resultants, a gcd over ``Q(alpha)`` and, when one coordinate does not separate them,
the coordinate ``y + c x``; families of codimension 2 in three or four variables are
solved for two of them over the field of the others. Every reported component gets
an exact witness checked by a direct analysis: rational where one exists, else a real
algebraic point (radicals or ``CRootOf``). ``q = pi`` (``t = oo``) is checked joint
by joint in the second chart.

The search is split along its seams: :mod:`.charts` (the ring and rows of a chart,
the slices at q = pi), :mod:`.hypersurface` (candidate polynomials from the minors),
:mod:`.curved` (families linear in no variable), :mod:`.codimension` (points and
codimension-2 families), :mod:`.fields` (sets over number fields: points joined over
a compositum, sets with irrational coordinates as families), :mod:`.modular` (numbers
shown modulo a prime), :mod:`.components` (recording what is found) and
:mod:`.recursion` (explore a place, decide a factor, go deeper), joined here by
:func:`compute_locus`. The polynomial systems are solved in
:mod:`coopkin_sym.analysis.locus.algebra`, witnesses and float checks are made in
:mod:`coopkin_sym.analysis.locus.witness`, and the results are the plain data of
:mod:`coopkin_sym.analysis.locus.types`.

Example
-------
>>> from coopkin_sym import load
>>> locus = compute_locus(load("paper-case1-hard"))
>>> for c in locus.components:
...     print(c.condition)
q1 = -pi/2, q2 = -pi/2
q1 = -pi/2, q2 = pi/2
q1 = pi/2, q2 = -pi/2
q1 = pi/2, q2 = pi/2
q1 = -5*pi/6, q2 = 5*pi/6 or q1 = -pi/6, q2 = pi/6
"""

from __future__ import annotations

import random
import time
from math import comb

import sympy as sp

from coopkin_sym.analysis.locus.context import Place, Progress, SearchContext
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.locus.search.charts import (
    PI_SEARCH_WEIGHT,
    chart_of,
    default_pi_size,
    pi_slices,
    revolute_joints,
)
from coopkin_sym.analysis.locus.search.components import settle_realness
from coopkin_sym.analysis.locus.search.recursion import STEPS, explore
from coopkin_sym.analysis.locus.types import Locus, canonical_order, cut_short
from coopkin_sym.analysis.locus.witness import floats_left_out
from coopkin_sym.analysis.mobility import decompose
from coopkin_sym.errors import LocusError, TimeLimitReached
from coopkin_sym.exact import deadline
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.bounded import checkpoint, report
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model, model_of


def compute_locus(system, at=None, max_depth: int = 2, timeout: float | None = None,
                  progress: bool = False, free=None, pi_size: int | None = None) -> Locus:
    """Every family of configurations where the numbers differ from the generic ones.

    Parameters
    ----------
    system
        A :class:`~coopkin_sym.system.System` (or anything with a ``model``).
    at
        Values fixing some joints or parameters (``--at`` syntax); the other joint
        variables are free. When the model has one length parameter and it is not
        set, it is set to 1 (uniform scaling changes no number) and a note says so.
    max_depth
        How deep to recurse inside components (0: only the generic locus).
    timeout
        Seconds after which no new component is explored (the report says what was
        left out).
    progress
        Report the steps of the search and the share done (see
        :func:`coopkin_sym.exact.bounded.report`; the caller's display shows them, as
        ``System.locus(progress=True)`` and ``coopkin locus`` do).
    free
        The joints to keep free (names); the others not set in ``at`` stay at home
        (q = 0, d = 0). Default: every joint not set in ``at``.
    pi_size
        Sets of joints at q = pi (outside the t chart) are searched inside up to this
        many joints at once; larger sets get their numbers decided and a note. Default:
        every set for up to four free revolute joints, two for up to six, one for up
        to eight, else none (the numbers of every set are always decided).
    """
    if timeout is not None and not deadline.active("locus"):  # checked inside eliminations
        with deadline.time_limit(timeout, "locus") as bound:
            try:
                return compute_locus(system, at, max_depth, timeout, progress, free, pi_size)
            except TimeLimitReached as exc:
                return cut_short(bound, exc)
    started = time.monotonic()
    ctx, q_rows = search_context(system, at, free, max_depth, timeout, progress)
    locus, model = ctx.locus, ctx.model
    # from here on, a time bound returns what was found; a copy goes to the caller now,
    # so that a run ended inside a step that cannot be interrupted still has it
    checkpoint(locus)
    size = pi_size if pi_size is not None else default_pi_size(ctx)
    with ctx.reporter, ctx.reporter.parts(2):
        # the progress: half for the t chart, half for the slices at q = pi (shared
        # by the slices searched inside; the others only get their numbers decided)
        ctx.reporter.step("depth 0: the numbers and their candidates")
        explore(ctx, Place(rows=q_rows, equations=[], point={}, depth=0))
        ctx.reporter.step("q = pi")
        # a slice searched inside weighs more than one whose numbers alone are decided
        weights = _pi_weights(len(revolute_joints(ctx)), size)
        with ctx.reporter.parts(len(weights), weights):
            pi_slices(ctx, size)
        settle_realness(ctx)
        canonical_order(locus)
    if ctx.expired() and not any(getattr(u, "kind", None) == "time_whole_run"
                                 for u in locus.unexplored):
        # the bound passed between steps: what each step left is said, and this
        locus.unexplored.append(Remark.of("time_whole_run", seconds=timeout,
                                          where="the search"))
    left_out = floats_left_out(ctx)
    if left_out is not None:
        locus.notes.append(left_out)
    elif any(c.algebraic_witness for c in locus.components):
        locus.notes.append(Remark.of("irrational_witness_floats"))
    if model.passive_joints and not model.locked:
        # where the passive-joint numbers change: the locus of the locked system
        left = None if timeout is None else max(0.0, timeout - (time.monotonic() - started))
        try:
            locus.locked = compute_locus(model.with_actuators_locked(), at, max_depth,
                                         left, progress, free, pi_size)
        finally:  # cut inside it: what is kept is this locus, not the locked one
            deadline.keep(locus)
    locus.seconds = round(time.monotonic() - started, 3)
    return locus



#: The most slices at q = pi the progress bar gives a part each (the later ones share
#: the last part: there are 2^r - 1 slices for r free revolute joints).
MAX_PI_PARTS = 4096


def _pi_weights(revolute: int, size: int | None) -> list[int]:
    """The progress weights of the slices at q = pi, in the order they are searched
    (at most :data:`MAX_PI_PARTS`): one searched inside weighs more than one whose
    numbers alone are decided."""
    weights: list[int] = []
    for k in range(1, revolute + 1):
        weight = PI_SEARCH_WEIGHT if size is None or k <= size else 1
        weights += [weight] * min(comb(revolute, k), MAX_PI_PARTS - len(weights))
        if len(weights) >= MAX_PI_PARTS:
            break
    return weights

def search_configuration(model: Model, at=None, free=None
                         ) -> tuple[Configuration, list[Remark]]:
    """The configuration a search runs at: the values of ``at``, the joints neither
    set nor ``free`` at home (q = 0, d = 0), and a model's one length parameter set to
    1 when ``at`` leaves it free (with the note saying so).

    Example
    -------
    >>> from coopkin_sym import load
    >>> config, notes = search_configuration(load("paper-case1-hard").model, "q2=0")
    >>> sorted(config.free), config.at_text(), [n.kind for n in notes]
    (['q1'], 'q2=0,L=1', ['uniform_scaling'])
    """
    fixed = Configuration.parse(model, at)
    notes: list[Remark] = []
    params = dict(fixed.parameters)
    free_params = [p for p in model.parameters if p.name not in params]
    if len(free_params) == 1 and len(model.parameters) == 1:
        params[free_params[0].name] = sp.Integer(1)
        notes.append(Remark.of("uniform_scaling", parameter=free_params[0].name))
    free_joints = [j.name for j in model.joints
                   if j.name not in fixed.revolute and j.name not in fixed.prismatic]
    if free is not None:
        chosen = Configuration.parse(model, None, free).free
        free_joints = [j for j in free_joints if j in chosen]
    revolute, prismatic = dict(fixed.revolute), dict(fixed.prismatic)
    for j in model.joints:  # joints neither set nor free stay at home
        if j.name not in free_joints and j.name not in revolute | prismatic:
            if j.type == "revolute":
                revolute[j.name] = ExactAngle(0, 1)
            else:
                prismatic[j.name] = sp.Integer(0)
    if not free_joints:
        raise LocusError("every joint has a value: a locus needs at least one free joint")
    return Configuration(revolute, prismatic, params, frozenset(free_joints)), notes


def search_context(system, at=None, free=None, max_depth: int = 2,
                   timeout: float | None = None, progress: bool = False
                   ) -> tuple[SearchContext, list]:
    """The state a search starts from (its empty locus, with the generic numbers) and
    the rows of ``Q`` in its chart; :func:`compute_locus` runs the search from it.

    Example
    -------
    >>> from coopkin_sym import load
    >>> ctx, rows = search_context(load("paper-case1-hard"))
    >>> ctx.ring_names, len(rows), ctx.locus.generic["Nm"]
    (('t_q1', 't_q2'), 6, 2)
    """
    started = time.monotonic()
    model: Model = model_of(system).in_base_frame()  # numbers only
    config, notes = search_configuration(model, at, free)
    locus = Locus(system=model.name, variables=[], fixed=config.at_text(), generic={},
                  notes=list(notes), locked_joints=[j for j in model.joint_names
                                                    if j in model.locked])
    report("the kinematics (G, D, H, Q)")      # the steps named as in an analysis
    chart, q_rows = chart_of(model, config)
    report("the ranks and the decomposition of the nullspace")
    generic = decompose(q_rows, model, chart["row_contacts"], chart["ring"].zctx).numbers
    ctx = SearchContext(model=model, generic=generic, max_depth=max_depth, locus=locus,
                        rng=random.Random(1992), readings={}, chains={}, owners={},
                        deadline=None if timeout is None else started + timeout,
                        reporter=Progress(progress), steps=STEPS, **chart)
    locus.variables = list(ctx.ring_names)
    locus.generic = ctx.generic.as_dict()
    if model.snapped:
        locus.notes.append(Remark.of("snapped_model", count=len(model.snapped),
                                     largest=max(x.error for x in model.snapped)))
    locus.notes.append(Remark.of("candidates_probabilistic"))
    return ctx, q_rows


__all__ = ["LocusError", "compute_locus", "search_configuration", "search_context"]
