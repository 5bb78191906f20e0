"""Plain-data results of a singularity-locus computation (see :mod:`.search`).

Everything here is plain data (strings, ints, dicts, and the exact objects a witness
shows), so a locus can be written as JSON, rendered as a report, or sent to another
process. No sentence is written here: :mod:`coopkin_sym.present.sentences` tells what
a component's :class:`WitnessMotions` show.

Example
-------
>>> c = Component(equations=["t_q1 - t_q2"], numbers={"Nm": 3}, witness={"q1": "pi/2"},
...               real=True)
>>> c.to_json()["equations"]
['t_q1 - t_q2']
"""

from __future__ import annotations

import copy
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, fields
from typing import TYPE_CHECKING, Any

from coopkin_sym.analysis.locus.conditions import Condition
from coopkin_sym.analysis.locus.facade import LocusMethods
from coopkin_sym.analysis.locus.remarks import NOT_USED, Remark
from coopkin_sym.analysis.numbers import numbers_line
from coopkin_sym.analysis.renderers import Displayable, clip
from coopkin_sym.errors import NumberError, TimeLimitReached
from coopkin_sym.exact.polynomial import NamedPolynomial

if TYPE_CHECKING:  # pragma: no cover
    from coopkin_sym.analysis.irrational import PointMotions
    from coopkin_sym.analysis.mobility import Analysis
    from coopkin_sym.analysis.numbers import Numbers
    from coopkin_sym.model.configuration import Point

# exact data and read-back text a component's JSON does not carry
_NOT_IN_JSON = ("shown", "stated_meaning")


@dataclass
class FloatCheck:
    """What a float rank test (numpy's matrix rank, default tolerance) says near a
    witness: ``distance`` is how far (in radians, on one joint) the point is from the
    witness, ``scale`` the value given to the length parameters; ``exact`` the exact
    numbers there, ``float`` the float ones.

    Example
    -------
    >>> check = FloatCheck(0.0, "L=1", {"q1": "pi/2"}, {"Nm": 3}, {"Nm": 2})
    >>> check.agree
    False
    """

    distance: float
    scale: str
    point: Point | Mapping[str, str]
    exact: dict[str, int]
    float: dict[str, int]

    @property
    def agree(self) -> bool:
        return self.exact == self.float

    def to_json(self) -> dict:
        """Plain JSON data (the point as its ``--at`` texts), with ``agree``."""
        return {"distance": self.distance, "scale": self.scale, "point": dict(self.point),
                "exact": dict(self.exact), "float": dict(self.float), "agree": self.agree}


@dataclass(frozen=True)
class WitnessMotions:
    """What a component's witness shows, exactly: the numbers there, which of them
    differ from the generic ones (``changed``), and the exact data behind them: the
    whole exact ``analysis`` at a rational witness, the exact ``motions`` behind ``Ni``
    and ``Nr`` at an algebraic witness over a quadratic field, or neither (the counts
    alone); ``object_dim`` is 6, or 3 for a planar system. The sentences are
    :func:`coopkin_sym.present.sentences.witness_sentences`.

    Example
    -------
    >>> from coopkin_sym import load
    >>> a = load("paper-case1-hard").analyze("q1=pi/2,q2=pi/2")
    >>> WitnessMotions(a.numbers, ("q1", "q2"), frozenset({"Nm"}), analysis=a).changed
    frozenset({'Nm'})
    """

    numbers: Numbers
    joints: tuple[str, ...]
    changed: frozenset[str]
    analysis: Analysis | None = None
    motions: PointMotions | None = None
    object_dim: int = 6


@dataclass
class Component(Displayable):
    """One irreducible family of configurations where the numbers differ from the
    generic ones.

    Attributes
    ----------
    equations
        Exact polynomials (:class:`~coopkin_sym.exact.polynomial.NamedPolynomial`) in
        the variables ``t_<joint>`` (tan of half the angle), ``s_<joint>`` (cot of half
        the angle, for the joints of :attr:`chart`), prismatic displacements and
        parameters, whose common zeros are the component. Texts given by hand are read
        by the one parser.
    numbers
        The seven numbers on the component (at its generic points).
    witness
        An exact point on it (a :class:`~coopkin_sym.model.configuration.Point`,
        read as its ``--at`` texts: ``{"q1": "pi/2", ...}``), or None; a report read
        back keeps the texts.
    real
        Whether the component has real points: True only with a real witness
        (rational, or algebraic in a certified isolating interval).
    kind
        ``"hypersurface"``, ``"subvariety"`` (codimension 2 or more), ``"isolated"``
        (a point), or ``"chart"`` (a joint at q = pi, outside the t chart).
    condition
        The equations in angles where they read simply, as data (a
        :class:`~.conditions.Condition`; its ``text`` is ``"q1 = q2"``, ``"q2 = 0"``).
    drops
        Which matrices lose rank there: subset of ``["Q", "HG^T", "HD"]``.
    changes
        Number name -> (generic, here), for the numbers that differ.
    shown
        What the witness shows, exactly (:class:`WitnessMotions`), for the sentences
        saying what motion is gained or lost there; None without a witness.
    stated_meaning
        The sentences a report read back states (a report is a document; a computed
        component leaves this empty and keeps ``shown``).
    decided
        How the numbers were decided, a :class:`~.remarks.Remark` (``decided_*``: over
        the component's function field, modulo its polynomial, at a point, over
        ``Q(alpha)``...); a report read back keeps its sentence (a string).
    witness_checked
        The witness's numbers from a direct exact analysis equal ``numbers``.
    float_checks
        Float rank tests at and near the witness.
    depth
        0 for a component of the generic locus, k for one found inside a depth-(k-1)
        component.
    parent
        Index (in :attr:`Locus.components`) of the component this one lies in; in the
        JSON and the reports, its number there (index + 1: ``#1`` is the first).
    outside
        Exact polynomials (same variables as ``equations``) that do not vanish on
        the component: it is the set where its equations hold and none of these
        vanish. They are the denominators of its parametrization; the points where one
        vanishes are searched as sets of their own.
    real_points
        ``"witness"`` (real, a witness is given) or ``"undecided"`` (no real witness
        found and no proof that there is none: never reported as real).
    finite
        The finite mobility at the witness, as plain data (dimension, bounds,
        first_order, classification, reason, order, branches: see
        :func:`coopkin_sym.analysis.finite.on_locus.finite_at_witnesses`), when it was
        asked for; None otherwise.
    chart
        The joints at q = pi in the chart the equations are written in (their variable
        is ``s_<joint>``, and a component of that chart lies where they are at pi);
        empty in the ``t`` chart.
    algebraic_witness
        When no rational witness exists: a real point with algebraic coordinates,
        ``{"point": {"q1": "-pi/6", ...}, "root_of": "t_q1**2 + 4*t_q1 + 1", "root":
        "-2 + sqrt(3)", "interval": [lo, hi], "approx": {...}}`` (exact texts; the
        ``root_of`` polynomial is irreducible, the root the one in ``interval``).

    Example
    -------
    >>> from coopkin_sym import load
    >>> c = load("paper-case1-hard").locus().components[0]
    >>> c.equations, c.condition.text, c.changes["Nm"]
    ([NamedPolynomial('t_q1 + 1'), NamedPolynomial('t_q2 + 1')], 'q1 = -pi/2, q2 = -pi/2', (2, 3))
    >>> c
    <Component q1 = -pi/2, q2 = -pi/2 (isolated): Nm 2->3, Nc 2->3, Nh 0->1>
    """

    equations: list[NamedPolynomial]
    numbers: dict[str, int]
    witness: Point | Mapping[str, str] | None
    real: bool
    kind: str = "hypersurface"
    condition: Condition = field(default_factory=Condition)
    drops: list[str] = field(default_factory=list)
    changes: dict[str, tuple[int, int]] = field(default_factory=dict)
    stated_meaning: list[str] = field(default_factory=list)
    decided: Remark | str = ""
    witness_checked: bool = False
    float_checks: list[FloatCheck] = field(default_factory=list)
    depth: int = 0
    parent: int | None = None
    algebraic_witness: dict | None = None
    real_points: str = ""
    outside: list[NamedPolynomial] = field(default_factory=list)
    finite: dict | None = None
    chart: tuple[str, ...] = ()
    shown: Any = field(default=None, repr=False, compare=False)

    def __post_init__(self) -> None:
        # a component written by hand may give texts: read once, by the one parser
        self.equations = [_polynomial(e, f"equation {k + 1}")
                          for k, e in enumerate(self.equations)]
        self.outside = [_polynomial(e, f"outside {k + 1}") for k, e in enumerate(self.outside)]
        if isinstance(self.condition, str):
            self.condition = Condition.parse(self.condition)
        self.chart = tuple(sorted(self.chart))

    def __repr__(self) -> str:
        where = self.condition.text or ", ".join(f"{e} = 0" for e in self.equations)
        depth = f", depth {self.depth}" if self.depth else ""
        changes = (", ".join(f"{k} {a}->{b}" for k, (a, b) in self.changes.items())
                   if self.changes else numbers_line(self.numbers))
        return f"<Component {clip(where, 120)} ({clip(self.kind, 20)}{depth}): {changes}>"

    def equation_polynomials(self, names: Sequence[str], where: str = ""
                             ) -> list[NamedPolynomial]:
        """The equations, checked to use only ``names`` (a package error names the
        entry, starting with ``where``, of one that uses another name).

        Example
        -------
        >>> c = Component(["t_q1 - t_q2"], {"Nm": 3}, None, True)
        >>> [p.variables for p in c.equation_polynomials(["t_q1", "t_q2"])]
        [('t_q1', 't_q2')]
        """
        return _within(self.equations, names, f"{where}equation")

    def outside_polynomials_of(self, names: Sequence[str], where: str = ""
                               ) -> list[NamedPolynomial]:
        """:attr:`outside`, checked as in :meth:`equation_polynomials`."""
        return _within(self.outside, names, f"{where}outside")

    def to_json(self) -> dict:
        """Plain JSON data; ``parent`` in the report's numbering (``#1`` is 1). The
        sentences are not data: the presentation layer adds them as ``"meaning"``."""
        out = {f.name: copy.deepcopy(getattr(self, f.name)) for f in fields(self)
               if f.name not in _NOT_IN_JSON}
        if self.parent is not None:
            out["parent"] = self.parent + 1
        out["equations"] = [p.text for p in self.equations]
        out["outside"] = [p.text for p in self.outside]
        out["condition"] = self.condition.text
        out["condition_data"] = self.condition.to_json()
        out["chart"] = list(self.chart)
        out["changes"] = {k: list(v) for k, v in self.changes.items()}
        out["decided"] = _remark_json(self.decided)
        out["witness"] = None if self.witness is None else dict(self.witness)
        out["float_checks"] = [f.to_json() for f in self.float_checks]
        return out


def _polynomial(p: NamedPolynomial | str, where: str) -> NamedPolynomial:
    return p if isinstance(p, NamedPolynomial) else NamedPolynomial.read(p, where)


def _within(polys: list[NamedPolynomial], names: Sequence[str], what: str
            ) -> list[NamedPolynomial]:
    for k, p in enumerate(polys):
        missing = [v for v in p.variables if v not in names]
        if missing:
            raise NumberError(f"{what} {k + 1}", f"{clip(p.text, 200)} uses "
                              f"{', '.join(missing)}, not among {', '.join(names) or 'no names'}")
    return list(polys)


def _remark_json(remark: Remark | str) -> dict | str:
    return remark.to_json() if isinstance(remark, Remark) else remark


@dataclass
class Check:
    """One test of the certificate.

    Attributes
    ----------
    chart
        ``"t chart"`` or the slice, e.g. ``"q1 = pi"``, ``"q1 = q3 = pi"``.
    depth
        0 for the generic drop sets; ``k`` for the numbers of a component of depth
        ``k``; ``k + 1`` for the drops inside it.
    inside
        Index (in the locus's components) of the component the test is about, or None.
    matrix
        ``"HG^T"``, ``"HD[arm]"``, ``"HD"`` (all arms), ``"Q"``.
    kind
        ``"drops"`` (the drop set lies in the components) or ``"numbers"`` (the
        component's numbers bound the ranks everywhere on it).
    certified
        Whether it is proved.
    why
        How it was decided without a Gröbner basis, or why it is not certified: a
        :class:`~.remarks.Remark` (``cert_*``), None when a backend proved it; a
        report read back keeps its sentence (a string).
    backend, seconds
        What decided it, and how long it took.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.locus.certify import certify_locus
    >>> system = load("paper-case1-hard")
    >>> check = certify_locus(system, system.locus(), timeout=60).checks[0]
    >>> check.chart, check.depth, check.certified
    ('t chart', 0, True)
    """

    chart: str
    depth: int
    inside: int | None
    matrix: str
    kind: str
    certified: bool = False
    why: Remark | str | None = None
    backend: str = ""
    seconds: float = 0.0

    def where(self) -> str:
        """Which test this is (chart, depth, component, matrix), as reports label it.

        Example
        -------
        >>> Check("t chart", 1, 4, "HG^T", "drops").where()
        't chart, depth 1, component #5, rank of HG^T'
        """
        inside = f", component #{self.inside + 1}" if self.inside is not None else ""
        what = "rank of" if self.kind == "drops" else "numbers, rank of"
        return f"{self.chart}, depth {self.depth}{inside}, {what} {self.matrix}"



@dataclass(repr=False)
class Certificate(Displayable):
    """Whether a locus is proved complete, chart by chart and depth by depth.

    Attributes
    ----------
    system
        The system's name.
    certified
        True only when every test is certified.
    refused
        Why no test could be run (a :class:`~.remarks.Remark`), or None.
    depths, charts
        Depth (or chart) -> ``{"certified": bool, "why": Check | Remark | None,
        "tests": int, "failed": int}``: ``why`` is the first test not certified there,
        or what was not tested.
    checks
        Every test.
    notes
        What the certificate assumed or could not use (remarks).
    untested_beyond
        The depth past which nothing was tested (``max_depth``), or None.
    seconds
        Wall time.

    :mod:`coopkin_sym.present.certificate` words it (its summary and JSON).

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.locus.certify import certify_locus
    >>> system = load("paper-case1-hard")
    >>> cert = certify_locus(system, system.locus(), timeout=60)
    >>> cert.certified, len(cert.checks), cert.depths[0]["failed"]
    (True, 46, 0)
    >>> cert
    <Certificate paper case 1, hard/hard: certified; 46 tests, 0 not certified>
    """

    system: str
    certified: bool = False
    refused: Remark | str | None = None
    depths: dict[int, dict] = field(default_factory=dict)
    charts: dict[str, dict] = field(default_factory=dict)
    checks: list[Check] = field(default_factory=list)
    notes: list[Remark | str] = field(default_factory=list)
    untested_beyond: int | None = None
    seconds: float = 0.0

    def __repr__(self) -> str:
        verdict = "certified" if self.certified else "not certified"
        failing = sum(1 for c in self.checks if not getattr(c, "certified", True))
        return (f"<Certificate {clip(self.system, 100)}: {verdict}; {len(self.checks)} "
                f"tests, {failing} not certified>")

    @classmethod
    def cut_at_bound(cls, system: str, seconds: float | None, where: str) -> Certificate:
        """The certificate of a locus whose certification the time bound of ``seconds``
        ended (``where``: the step): not certified, and it says why.

        Example
        -------
        >>> Certificate.cut_at_bound("demo", 20, "the completeness certificate").refused.kind
        'cert_time_bound'
        """
        return cls(system, refused=Remark.of("cert_time_bound", seconds=seconds,
                                             where=where))

    def certified_by(self) -> dict[str, int]:
        """How many tests each backend certified.

        Example
        -------
        >>> Certificate("demo").certified_by()
        {}
        """
        backends: dict[str, int] = {}
        for c in self.checks:
            if c.certified:
                backends[c.backend] = backends.get(c.backend, 0) + 1
        return dict(sorted(backends.items()))

    def to_json(self) -> dict:
        """Plain JSON data (remarks as their kind and facts, a table's reason as the
        index of its test in :attr:`checks` or a remark);
        :func:`coopkin_sym.present.certificate.certificate_json` words it.

        Example
        -------
        >>> Certificate("demo", True).to_json()["certified"]
        True
        """
        def why(value):
            if isinstance(value, Check):
                return {"check": next(k for k, c in enumerate(self.checks) if c is value)}
            return _data(value)

        return {"system": self.system, "certified": self.certified,
                "refused": _data(self.refused),
                "depths": {str(k): dict(v, why=why(v["why"])) for k, v in self.depths.items()},
                "charts": {k: dict(v, why=why(v["why"])) for k, v in self.charts.items()},
                "checks": [dict(vars(c), why=_data(c.why)) for c in self.checks],
                "notes": [_data(n) for n in self.notes],
                "untested_beyond": self.untested_beyond, "seconds": self.seconds}

    def failures(self) -> list[Check | Remark]:
        """Why it is not certified, in order: components and conditions not used, the
        tests not certified (shallowest first), depths not tested; empty when certified.

        Example
        -------
        >>> Certificate("demo", untested_beyond=0).failures()[0].kind
        'cert_depths_untested'
        """
        if self.refused is not None:
            return [self.refused]
        out: list[Check | Remark] = [n for n in self.notes
                                     if getattr(n, "kind", None) in NOT_USED]
        out += sorted((c for c in self.checks if not c.certified), key=lambda c: c.depth)
        if self.untested_beyond is not None:
            out.append(Remark.of("cert_depths_untested", depth=self.untested_beyond))
        return out


def _data(remark: Remark | str | None):
    return remark.to_json() if isinstance(remark, Remark) else remark


@dataclass
class Locus(LocusMethods, Displayable):
    """Where the numbers of a system change, exactly.

    Attributes
    ----------
    system
        The system's name.
    variables
        The free variables (``t_<joint>``, prismatic names, parameters).
    fixed
        Values set with ``at`` (``--at`` syntax), plus a note when all lengths were
        scaled to one parameter set to 1.
    generic
        The generic numbers (over the field of rational functions).
    components
        Every component found, depth first.
    parameter_conditions
        Parameter-only degeneracies (e.g. ``L``: a length of zero), reported apart.
    dropped
        Factors with no real points (dropped from the components).
    unexplored
        What was not explored within the bounds (depth, time, sets not solved).
    notes
        Anything else the reader should know (scaling, probabilistic steps).

    These four lists hold :class:`~.remarks.Remark` data, worded by
    :mod:`coopkin_sym.present.remarks`; a report read back holds its sentences
    (strings) there instead.
    certificate
        The completeness certificate
        (:class:`~coopkin_sym.analysis.locus.certify.Certificate`), or None when none
        was made (:func:`~coopkin_sym.analysis.locus.certify.certify_locus`).
    locked_joints
        The joints held still (no velocity) in this search: the actuated joints for
        the locus of a locked system, else empty.
    locked
        For a system with passive joints, the locus of the same system with every
        actuated joint held still: where the passive-joint numbers ``Nuo`` and ``Npi``
        change (:mod:`coopkin_sym.analysis.passive`); None otherwise.

    Example
    -------
    >>> from coopkin_sym import load
    >>> locus = load("paper-case1-hard").locus()
    >>> locus.variables, locus.generic["Nm"], len(locus.components)
    (['t_q1', 't_q2'], 2, 5)
    >>> print(repr(locus).replace("; ", ";\\n"))
    <Locus paper case 1, hard/hard at L=1: generic Nm=2 Nc=2 Ni=1 Nr=0 Ng=1 Nd=4 Nh=0;
    5 components, not certified>
    """

    system: str
    variables: list[str]
    fixed: str
    generic: dict[str, int]
    components: list[Component] = field(default_factory=list)
    parameter_conditions: list[Remark | str] = field(default_factory=list)
    dropped: list[Remark | str] = field(default_factory=list)
    unexplored: list[Remark | str] = field(default_factory=list)
    notes: list[Remark | str] = field(default_factory=list)
    seconds: float = 0.0
    certificate: Certificate | None = None
    locked_joints: list[str] = field(default_factory=list)
    locked: Locus | None = None

    def __repr__(self) -> str:
        at = f" at {clip(self.fixed, 60)}" if self.fixed else ""
        n = len(self.components)
        found = f"{n} component{'' if n == 1 else 's'}"
        if self.unexplored:
            found += f" ({len(self.unexplored)} unexplored)"
        return (f"<Locus {clip(self.system, 80)}{at}: generic {numbers_line(self.generic)}; "
                f"{found}, {'certified' if self.certified else 'not certified'}>")

    @property
    def certified(self) -> bool:
        """Whether a completeness certificate proves every component found.

        Example
        -------
        >>> from coopkin_sym.analysis.locus.certify import Certificate
        >>> Locus("demo", [], "", {}, certificate=Certificate("demo", True)).certified
        True
        """
        return self.certificate is not None and self.certificate.certified is True

    def float_summary(self) -> dict[str, int]:
        """How many singular configurations float tests called regular (missed), and
        how many regular ones they called singular (false alarms)."""
        missed = false_alarm = 0
        for c in self.components:
            for f in c.float_checks:
                if f.agree:
                    continue
                if f.distance == 0:
                    missed += 1
                elif f.exact == self.generic:
                    false_alarm += 1
                else:
                    missed += 1
        return {"missed_singular": missed, "false_singular": false_alarm}

    def to_json(self) -> dict:
        """Plain JSON data (remarks as their kind and facts: the presentation layer's
        :func:`~coopkin_sym.present.report.render_json` writes their sentences)."""
        return {
            "system": self.system,
            "variables": self.variables,
            "fixed": self.fixed,
            "generic": self.generic,
            "components": [c.to_json() for c in self.components],
            "parameter_conditions": [_remark_json(r) for r in self.parameter_conditions],
            "dropped": [_remark_json(r) for r in self.dropped],
            "unexplored": [_remark_json(r) for r in self.unexplored],
            "notes": [_remark_json(r) for r in self.notes],
            "float_summary": self.float_summary(),
            "seconds": self.seconds,
            "certificate": (None if self.certificate is None
                            else self.certificate.to_json()),
            "locked_joints": self.locked_joints,
            "locked": None if self.locked is None else self.locked.to_json(),
        }

    def completeness(self) -> tuple[bool, Check | Remark | str | None]:
        """Whether the locus is proved complete, and if not the first reason (a test
        not certified, a remark; None when no certificate was made).
        :func:`coopkin_sym.present.certificate.completeness_text` words it.

        Example
        -------
        >>> Locus("demo", [], "", {}).completeness()
        (False, None)
        """
        if self.certificate is None:
            return False, None
        if self.certificate.certified:
            return True, None
        failing = self.certificate.failures()
        return False, failing[0] if failing else None


#: The order of the kinds of components among siblings.
KIND_ORDER = ("hypersurface", "subvariety", "isolated", "chart")


def _sibling_key(c: Component) -> tuple:
    kind = KIND_ORDER.index(c.kind) if c.kind in KIND_ORDER else len(KIND_ORDER)
    return (kind, len(c.equations), [e.sort_key() for e in c.equations], c.condition.text,
            sorted(c.numbers.items()), sorted((c.witness or {}).items()))


def canonical_order(locus: Locus) -> list[int]:
    """Put the components of ``locus`` in their canonical order, whatever order the
    search found them in: depth first down the tree of parents, siblings sorted by
    kind, number of equations, then their texts (shortest first). Parents and the
    component indices held by remarks follow; returns the old index of each
    component, in the new order.

    Example
    -------
    >>> a = Component(["t_q1 - 1"], {"Nm": 3}, None, True, kind="isolated")
    >>> b = Component(["t_q1"], {"Nm": 3}, None, True)
    >>> inner = Component(["t_q1", "t_q2"], {"Nm": 4}, None, True, depth=1, parent=1)
    >>> locus = Locus("demo", ["t_q1", "t_q2"], "", {"Nm": 2}, [a, b, inner])
    >>> canonical_order(locus), [c.parent for c in locus.components]
    ([1, 2, 0], [None, 0, None])
    """
    comps = locus.components
    children: dict[int | None, list[int]] = {}
    for k, c in enumerate(comps):
        parent = c.parent if c.parent is not None and 0 <= c.parent < len(comps) else None
        children.setdefault(parent, []).append(k)
    order: list[int] = []

    def visit(parent: int | None) -> None:
        for k in sorted(children.get(parent, []), key=lambda k: _sibling_key(comps[k])):
            order.append(k)
            visit(k)

    visit(None)
    order += [k for k in range(len(comps)) if k not in set(order)]  # a cycle: kept last
    new = {old: i for i, old in enumerate(order)}
    locus.components = [comps[k] for k in order]
    for c in locus.components:
        if c.parent is not None:
            c.parent = new.get(c.parent, c.parent)
    for name in ("parameter_conditions", "dropped", "unexplored", "notes"):
        setattr(locus, name, [_renumbered(r, new) for r in getattr(locus, name)])
    return order


def _renumbered(remark: Remark | str, new: dict[int, int]) -> Remark | str:
    """``remark`` with the component index it holds (if any) in the new numbering."""
    if not isinstance(remark, Remark) or "component" not in dict(remark.facts):
        return remark
    facts = dict(remark.facts)
    if facts["component"] is not None:
        facts["component"] = new.get(facts["component"], facts["component"])
    return Remark.of(remark.kind, **facts)


def cut_short(bound, exc: TimeLimitReached) -> Locus:
    """The locus as far as it got when the wall-clock bound ran out inside a long
    computation (``bound`` is the :class:`~coopkin_sym.exact.deadline.Bound` the
    locus was registered with): what was cut is said in :attr:`Locus.unexplored`.

    Raises ``exc`` again, saying so, when the bound ran out before the generic
    numbers were known (there is no locus to report yet). The components found are put
    in their canonical order (:func:`canonical_order`), as for a whole search.
    """
    locus = bound.kept if bound is not None else None
    if not isinstance(locus, Locus):
        raise TimeLimitReached(exc.seconds, (exc.where + ", " if exc.where else "")
                               + "before the generic numbers were known: no locus "
                               "to report") from None
    locus.unexplored.append(Remark.of("time_whole_run", seconds=exc.seconds,
                                      where=exc.where))
    locus.seconds = round(time.monotonic() - bound.started, 3)
    canonical_order(locus)
    return locus


def ended_at_bound(exc: TimeLimitReached, whole_search: bool = False) -> Locus | None:
    """The locus of a search ended at its bound inside a step that cannot be
    interrupted (``exc.hard``; see :func:`coopkin_sym.exact.bounded.run_bounded`): the
    last copy of it the search kept, with the cut said in :attr:`Locus.unexplored`
    (not with ``whole_search``: the run was ended after the search, whose copy is
    whole); None when there is none (the bound came before the generic numbers).

    Example
    -------
    >>> generic = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
    >>> exc = TimeLimitReached(5.0, "a resultant", hard=True)
    >>> exc.kept = Locus("case 1", ["t_q1", "t_q2"], "L=1", generic)
    >>> [u.kind for u in ended_at_bound(exc).unexplored]
    ['time_whole_run']
    """
    locus = getattr(exc, "kept", None)
    if not (exc.hard and isinstance(locus, Locus)):
        return None
    if whole_search:
        return locus
    locus.unexplored.append(Remark.of("time_whole_run", seconds=exc.seconds,
                                      where=exc.where))
    canonical_order(locus)
    return locus
