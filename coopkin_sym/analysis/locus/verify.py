"""An independent check of a singularity locus: exact numbers on a rational grid
(q = pi included) and at every rank-drop point of random rational lines.

Nothing here uses the locus search: the numbers come straight from the ranks of
``Q``, ``H G^T`` and ``H D`` (``Nm = d + r - rank Q``, ``Ni = d - rank H G^T``,
``Nr = r - rank H D``, the others from these; ``d`` is 6, or 3 for a planar system),
computed exactly at each point.

* **Soundness.** A component is the set where its equations vanish and none of its
  ``outside`` polynomials does. At each component's witness (rational, or algebraic
  over its number field) the equations must vanish and a direct analysis must give
  the component's numbers. A point of the grid or of a line that lies on a component cannot have a
  rank above the component's (a rank never rises at a special point of a family):
  such a point proves the component wrong.
* **The grid.** Every combination of values of the free variables (``tan(q/2)`` in a
  set that contains infinity, i.e. ``q = pi``; small rational displacements; small
  positive parameters), or of smaller value sets when the product is larger than
  ``max_points`` (the result says which sets were used). Every point whose numbers
  differ from the generic ones must lie on a component with exactly those numbers.
* **Lines.** Random rational lines, each revolute variable in one of its two charts
  (``t = tan(q/2)``, or ``s = cot(q/2)`` so that the line crosses ``q = pi``), some
  with variables held at grid values (lines inside coordinate subspaces, at ``q = pi``
  too). The three matrices restricted to a line are univariate polynomial matrices
  (each row times a factor ``(1 + t^2)^k`` with no real zero); the points where a rank
  drops below its value on the line are the real roots of the gcd of random
  combinations ``det(A M B)`` of its maximal minors (a multiple of the gcd of all of
  them, so no drop point is lost), factored; at each factor with a real root the
  numbers are decided exactly (at a rational root directly, at an irrational one over
  ``Q[x]/(f)``) and the point's membership in the components too. The points where a
  chart variable vanishes are decided as well. A line whose own numbers differ from
  the generic ones must lie inside a component with those numbers.

A point lies on a component when every equation vanishes there, each revolute joint
taking ``t_<joint>`` in Q or infinity: an equation with ``t_<joint>`` is not satisfied
at ``t = oo`` (``q = pi``), one with ``s_<joint> = 1/t_<joint>`` not at ``t = 0``.

What this cannot prove: families with no rational point, of codimension two or more,
and not met by a line (an isolated point with irrational coordinates, say) are checked
only through their own witnesses; a pass says "nothing found", not "complete".

Example
-------
>>> from coopkin_sym import load
>>> from coopkin_sym.analysis.locus.types import Locus
>>> empty = Locus("paper case 1, hard/hard", ["t_q1", "t_q2"], "L=1",
...               {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0})
>>> v = verify_locus(load("paper-case1-hard"), empty, lines=0)
>>> v.grid_points, v.uncovered_total, sorted(u.point["q1"] for u in v.uncovered)[:2]
(100, 4, ['-pi/2', '-pi/2'])
"""

from __future__ import annotations

import random
import time
from collections.abc import Mapping, Sequence

from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.analysis.locus.verify_checker import BOUNDARY as BOUNDARY
from coopkin_sym.analysis.locus.verify_checker import _Checker as _Checker
from coopkin_sym.analysis.locus.verify_checker import _State
from coopkin_sym.analysis.locus.verify_exact import Tan as Tan
from coopkin_sym.analysis.locus.verify_exact import _eval_q as _eval_q
from coopkin_sym.analysis.locus.verify_exact import _Line as _Line
from coopkin_sym.analysis.locus.verify_grid import DEFAULT_VALUES as DEFAULT_VALUES
from coopkin_sym.analysis.locus.verify_grid import _check_grid, _fit, _tan_text, _value_sets
from coopkin_sym.analysis.locus.verify_lines import _check_line
from coopkin_sym.analysis.locus.verify_lines import _line_ranks as _line_ranks
from coopkin_sym.analysis.locus.verify_lines import _line_rows as _line_rows
from coopkin_sym.analysis.locus.verify_lines import _to_mpoly as _to_mpoly
from coopkin_sym.analysis.locus.verify_results import MAX_LISTED as MAX_LISTED
from coopkin_sym.analysis.locus.verify_results import ComponentIssue as ComponentIssue
from coopkin_sym.analysis.locus.verify_results import DropPoint as DropPoint
from coopkin_sym.analysis.locus.verify_results import Verification as Verification
from coopkin_sym.analysis.locus.verify_witness import _check_witnesses
from coopkin_sym.analysis.numbers import NUMBER_NAMES
from coopkin_sym.errors import VerifyError
from coopkin_sym.exact.bounded import report, run_bounded
from coopkin_sym.model.configuration import assignments_text
from coopkin_sym.model.model import Model, model_of

__all__ = ["DEFAULT_VALUES", "ComponentIssue", "DropPoint", "Verification", "VerifyError",
           "verify_locus"]



def verify_locus(system, locus: Locus, *, at: str | Mapping | None = None,
                 values: Mapping[str, Sequence] | None = None, max_points: int = 50_000,
                 lines: int = 12, seed: int = 0,
                 timeout: float | None = None) -> Verification:
    """Check ``locus`` against ``system`` exactly, independently of the search.

    Parameters
    ----------
    system
        The :class:`~coopkin_sym.system.System` (or its model) the locus is about.
    locus
        The locus (from :func:`~coopkin_sym.analysis.locus.search.compute_locus`, or read back with
        :func:`~coopkin_sym.present.report.locus_from_json`).
    at
        The values the locus was computed at (``--at`` syntax); default
        ``locus.fixed``. A parameter neither free nor fixed is taken as 1.
    values
        Grid value sets: keys ``"revolute"`` (tangents of half angles, ``"oo"`` for
        q = pi), ``"prismatic"``, ``"parameter"`` (positive), or a variable name
        (``"t_q1"``, ``"q4"``, ``"L"``); defaults :data:`DEFAULT_VALUES`.
    max_points
        Largest grid; beyond it every set is cut to a prefix, longest first.
    lines
        Random rational lines to check.
    seed
        Seed of the lines (the grid is exhaustive).
    timeout
        Wall-clock bound in seconds (see
        :func:`coopkin_sym.exact.bounded.run_bounded`); past it,
        :class:`~coopkin_sym.errors.TimeLimitReached` names the step.

    Returns
    -------
    Verification
        Counts, the uncovered points and the unsound components, exactly.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> generic = {"Nm": 1, "Nc": 1, "Ni": 0, "Nr": 0, "Ng": 0, "Nd": 3, "Nh": 0}
    >>> v = verify_locus(load("paper-case1-soft"),
    ...                  Locus("case 1 soft", ["t_q1", "t_q2"], "L=1", generic), lines=2)
    >>> v.ok, v.grid_points, v.lines
    (False, 100, 2)
    """
    if timeout is not None:
        return run_bounded(lambda: verify_locus(system, locus, at=at, values=values,
                                                max_points=max_points, lines=lines,
                                                seed=seed), timeout, owner="verify")
    started = time.monotonic()
    model: Model = model_of(system).in_base_frame()  # numbers only
    if max_points < 1:
        raise VerifyError(f"max_points: expected a positive number, got {max_points}")
    if lines < 0:
        raise VerifyError(f"lines: expected a number >= 0, got {lines}")
    checker = _Checker(model, locus, at)
    requested = _value_sets(checker.free, values)
    used, reduced = _fit(requested, max_points)
    result = _new_result(checker, locus, used, reduced, max_points, seed)
    state = _State(checker, result)
    _check_generic(checker, state, locus)
    report("the witnesses")
    _check_witnesses(checker, state)
    report("the grid", 0.0)
    _check_grid(checker, state, used)
    rng = random.Random(seed)
    for k in range(lines):
        report(f"the random line {k + 1} of {lines}", (k + 1) / (lines + 1))
        _check_line(checker, state, used, rng, k)
    result.lines = lines
    result.witnesses_checked = len(state.witnessed)
    for i in range(len(locus.components)):
        if i not in state.witnessed and not state.hits[i]:
            result.unchecked.append(i)
    result.seconds = round(time.monotonic() - started, 3)
    return result



def _new_result(checker: _Checker, locus: Locus, used: list[list], reduced: bool,
                max_points: int, seed: int) -> Verification:
    """The result before any check: the locus, the value sets used, the notes."""
    return Verification(
        system=locus.system, variables=list(locus.variables),
        fixed=assignments_text(checker.fixed_items),
        generic=checker.generic,
        values={v.name: [_tan_text(x) if v.kind == "revolute" else str(x) for x in xs]
                for v, xs in zip(checker.free, used, strict=True)},
        reduced=reduced, max_points=max_points, seed=seed,
        components=len(locus.components), notes=list(checker.notes))



def _check_generic(checker: _Checker, state: _State, locus: Locus) -> None:
    """The locus's generic numbers, and no component claiming them."""
    result = state.result
    if {k: locus.generic.get(k) for k in NUMBER_NAMES} != checker.generic:
        result.unsound.append(ComponentIssue(-1, "generic", None, dict(locus.generic),
                                             f"exact generic numbers: {checker.generic}"))
    for i, claim in enumerate(checker.claims):
        if claim == checker.generic:
            state.issue(i, "generic-numbers", None, claim)

