"""The result of a locus verification
(:func:`~coopkin_sym.analysis.locus.verify.verify_locus`) as plain exact data: the
points with numbers that no component explains, the components shown wrong, the counts.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field

from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.renderers import Displayable, clip

#: Uncovered points kept in the result (all are counted).
MAX_LISTED = 200


@dataclass
class DropPoint:
    """A point where the numbers differ from the generic ones and no component with
    exactly those numbers contains it.

    ``kind`` is ``"point"`` (a rational point: ``point`` in ``--at`` syntax, fixed
    values included), ``"root"`` (a point with irrational coordinates on a line:
    ``point`` holds approximate values, radians and lengths, and ``algebraic`` the
    exact description: the line, each free variable as a polynomial in ``lam`` with
    ``s_<joint>`` for the second chart, the irreducible ``root_of`` in ``lam`` and an
    isolating interval of the real root) or ``"line"`` (every point of a line whose
    own numbers are not the generic ones: ``point`` is the line). ``on``: components
    containing it, with other numbers.

    Example
    -------
    >>> p = DropPoint("grid", {"q1": "pi/2", "q2": "pi/2"}, {"Nm": 3})
    >>> p.kind, p.point["q1"]
    ('point', 'pi/2')
    """

    source: str
    point: dict[str, str]
    numbers: dict[str, int]
    kind: str = "point"
    algebraic: dict | None = None
    on: list[int] = field(default_factory=list)


@dataclass
class ComponentIssue:
    """What is wrong with component ``component`` (index in the locus).

    ``kind``: ``"witness-off"`` (an equation does not vanish at the witness),
    ``"witness-numbers"`` (the witness has other numbers; ``detail`` says when it
    contradicts the locus's fixed values),
    ``"rank-above"`` (a point on the component has a rank above the component's, so
    its numbers cannot hold there), ``"generic-numbers"`` (its numbers are the generic
    ones), or ``"generic"`` (``component`` is -1: the locus's generic numbers are
    wrong). ``point`` and ``numbers`` are the evidence.

    Example
    -------
    >>> issue = ComponentIssue(0, "witness-off", {"q1": "0"}, {"Nm": 2})
    >>> issue.component, issue.kind
    (0, 'witness-off')
    """

    component: int
    kind: str
    point: dict[str, str] | None = None
    numbers: dict[str, int] | None = None
    detail: str = ""


@dataclass(repr=False)
class Verification(Displayable):
    """The result of :func:`~coopkin_sym.analysis.locus.verify.verify_locus`, as plain
    exact data.

    Attributes
    ----------
    values
        The value set used on the grid for each free variable (``tan(q/2)`` for
        ``t_<joint>``, ``"oo"`` being q = pi).
    reduced
        Whether the requested sets did not fit ``max_points`` (then ``values`` are
        the smaller sets used).
    grid_points, grid_drops
        Points of the grid, and those with numbers other than the generic ones.
    lines, line_points, line_drops, singular_lines
        Lines checked; points decided exactly on them (drop candidates and chart
        zeros, one per irreducible factor); those with non-generic numbers; lines
        whose own numbers are not the generic ones.
    uncovered, uncovered_total
        Points with non-generic numbers on no component with those numbers (at most
        :data:`MAX_LISTED` listed; all counted).
    unsound
        Components shown wrong, with the evidence.
    unchecked
        Components with no witness checked and no point of the grid or of a line on
        them: nothing here confirms them.
    unread_witnesses
        Components whose witness this check cannot read (a ``CRootOf`` value), and why.
    boundary_points
        Points on a component's equations where one of its ``outside`` polynomials
        vanishes, with ranks not above the component's: taken as on it (its closure).

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.locus.verify import verify_locus
    >>> system = load("paper-case1-hard")
    >>> check = verify_locus(system, system.locus(), max_points=200)
    >>> check.ok, check.grid_points > 0
    (True, True)
    >>> check
    <Verification paper case 1, hard/hard: passed (0 uncovered points, 0 unsound components)>
    """

    system: str
    variables: list[str]
    fixed: str
    generic: dict[str, int]
    values: dict[str, list[str]]
    reduced: bool
    max_points: int
    grid_points: int = 0
    grid_drops: int = 0
    lines: int = 0
    line_points: int = 0
    line_drops: int = 0
    singular_lines: int = 0
    seed: int = 0
    components: int = 0
    witnesses_checked: int = 0
    boundary_points: int = 0
    uncovered: list[DropPoint] = field(default_factory=list)
    uncovered_total: int = 0
    unsound: list[ComponentIssue] = field(default_factory=list)
    unchecked: list[int] = field(default_factory=list)
    unread_witnesses: dict[int, str] = field(default_factory=dict)
    notes: list[Remark] = field(default_factory=list)
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        """Nothing uncovered and nothing unsound."""
        return not self.uncovered_total and not self.unsound

    @property
    def unsound_components(self) -> list[int]:
        return sorted({i.component for i in self.unsound})

    def __repr__(self) -> str:
        n, m = self.uncovered_total, len(self.unsound_components)
        return (f"<Verification {clip(self.system, 100)}: "
                f"{'passed' if self.ok else 'FAILED'} ({n} uncovered point"
                f"{'' if n == 1 else 's'}, {m} unsound component{'' if m == 1 else 's'})>")

    def to_json(self) -> dict:
        """Plain JSON data (notes as remark data: the presentation layer's
        :func:`~coopkin_sym.present.verification.verification_json` words them)."""
        out = asdict(self)
        out["notes"] = [n.to_json() for n in self.notes]
        out["ok"] = self.ok
        return out
