"""What a picture is drawn from: the motion asked for (``coordinated:1``), how many
motions of each kind a system has and gains at a point, and the analysis (rational,
or at an irrational angle the exact numbers with the geometry at a rational next to
it). Used by :mod:`coopkin_sym.present.draw`, which re-exports the public names.

Example
-------
>>> motion_counts({"Nc": 3, "Ni": 1, "Nr": 0})
{'coordinated': 2, 'indeterminate': 1, 'redundant': 0}
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import sympy as sp

from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.irrational import (
    IrrationalAnalysis,
    analyze_irrational,
    irrational_values,
)
from coopkin_sym.analysis.mobility import Analysis, analyze
from coopkin_sym.analysis.numbers import Numbers
from coopkin_sym.errors import ConfigurationError, DrawError
from coopkin_sym.exact.angles import tangent_name
from coopkin_sym.exact.parse import NumberError, brief, parse_angle
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model, load_model, model_of

#: Motion kinds and the blocks they come from.
MOTION_KINDS: dict[str, str] = {
    "coordinated": "C12, C22",
    "indeterminate": "C11",
    "redundant": "C23",
}


# ------------------------------------------------------------------ inputs


def parse_motion(motion: str | Sequence | None, analysis: Analysis) -> tuple[str, int] | None:
    """Check a motion request against ``analysis``; return ``(kind, k)`` (k from 1).

    ``motion`` is ``None``, a pair ``("coordinated", 1)`` or the text
    ``"coordinated:1"`` (kinds: coordinated, indeterminate, redundant).

    Example
    -------
    >>> from coopkin_sym import load
    >>> a = load("paper-case1-hard").analyze()
    >>> parse_motion("indeterminate:1", a)
    ('indeterminate', 1)
    >>> parse_motion(("coordinated", 2), a)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.DrawError: motion: there is no coordinated motion 2: this system ...
    """
    if motion is None:
        return None
    if isinstance(motion, str):
        kind, sep, index = motion.partition(":")
        if not sep:
            raise DrawError(f"motion: expected KIND:K (e.g. coordinated:1), got {brief(motion)}")
    elif isinstance(motion, Sequence) and len(motion) == 2:
        kind, index = motion
    else:
        raise DrawError(f"motion: expected (kind, k) or 'kind:k', got {brief(motion)}")
    kind = str(kind).strip()
    if kind not in MOTION_KINDS:
        raise DrawError(f"motion: unknown kind {brief(kind)} (expected "
                        f"{', '.join(MOTION_KINDS)})")
    try:
        k = int(str(index).strip())
    except ValueError:
        raise DrawError(f"motion: the index must be a whole number, got {brief(index)}") from None
    count = _motion_count(kind, analysis)
    if not 1 <= k <= count:
        if count == 0:
            raise DrawError(f"motion: this system has no {kind} motion here "
                            f"({MOTION_KINDS[kind]} empty)")
        raise DrawError(f"motion: there is no {kind} motion {k}: this system has {count} "
                        f"(the columns of {MOTION_KINDS[kind]})")
    return kind, k


def _motion_count(kind: str, a: Analysis) -> int:
    return motion_counts(a.numbers.as_dict())[kind]


def motion_counts(numbers: Mapping[str, int]) -> dict[str, int]:
    """How many motions of each kind (:data:`MOTION_KINDS`) numbers give: the columns
    of ``C12, C22`` (``Nc - Ni``), ``C11`` (``Ni``) and ``C23`` (``Nr``).

    Example
    -------
    >>> motion_counts({"Nc": 3, "Ni": 1, "Nr": 0})
    {'coordinated': 2, 'indeterminate': 1, 'redundant': 0}
    """
    return {"coordinated": numbers["Nc"] - numbers["Ni"], "indeterminate": numbers["Ni"],
            "redundant": numbers["Nr"]}


def gained_motion(here: Mapping[str, int], generic: Mapping[str, int]
                  ) -> tuple[str, int] | None:
    """A motion a configuration has that the generic one has not: the kind whose count
    grows (indeterminate first, then redundant, then coordinated) and its last column
    (``k`` from 1, as :func:`draw_system` takes it); None when no count grows.

    Which column is new is not defined (only the count is): the last one is drawn;
    any motion of that kind beyond the generic count shows what is gained.

    Example
    -------
    >>> generic = {"Nc": 2, "Ni": 1, "Nr": 0}
    >>> gained_motion({"Nc": 3, "Ni": 3, "Nr": 0}, generic)
    ('indeterminate', 3)
    >>> gained_motion({"Nc": 3, "Ni": 1, "Nr": 0}, generic)
    ('coordinated', 2)
    >>> gained_motion(generic, generic) is None
    True
    """
    if not all(isinstance(n.get(k), int) for n in (here, generic) for k in ("Nc", "Ni", "Nr")):
        return None
    now, before = motion_counts(here), motion_counts(generic)
    for kind in ("indeterminate", "redundant", "coordinated"):
        if now[kind] > before[kind]:
            return kind, now[kind]
    return None


#: The longest exact value a picture's title writes as it is (longer ones: rounded).
SHORT_VALUE = 30


@dataclass(frozen=True)
class _AtIrrational:
    """What a picture needs at a configuration with irrational tangents: the exact
    assignments ``at`` (texts) and ``numbers`` there, the joints whose ``tan(q/2)`` is
    irrational (``tangents``), the geometry with those joints symbolic, and for each of
    their ``tan(q/2)`` a rational next to it to draw it at (``near``)."""

    model: Model
    kinematics: Any
    configuration: Configuration
    at: Mapping[str, str]
    tangents: tuple[str, ...]
    numbers: Numbers
    near: dict[str, sp.Rational]

    def short_at(self) -> str:
        """The configuration for a title: each value exactly, but an irrational angle
        whose exact text is long (a root of a quartic) as its approximation
        (``q1~0.636476``, with the sign for "approximately").

        Example
        -------
        >>> from coopkin_sym.model import load_model
        >>> a = at_algebraic_witness(load_model("paper-case1-hard"),
        ...     {"q1": "2*atan(CRootOf(x**4 - 10*x**2 + 1, 2))", "q2": "-pi/6"},
        ...     {"q1": "0.636476277", "q2": "-0.523598776"}, Numbers(2, 2, 1, 0, 1, 4, 0))
        >>> a.short_at() == "q1\u22480.636476,q2=-pi/6"
        True
        """
        parts = []
        for name, text in self.at.items():
            if name in self.tangents and len(str(text)) > SHORT_VALUE:
                half = float(self.near[tangent_name(name)])       # float-ok: display
                parts.append(f"{name}\u2248{2 * math.atan(half):.6g}")  # float-ok
            else:
                parts.append(f"{name}={text}")
        return ",".join(parts)

    @property
    def rounded(self) -> bool:
        """Whether :meth:`short_at` rounds a value."""
        return any(len(str(self.at[n])) > SHORT_VALUE for n in self.tangents)


def _near(value: sp.Expr) -> sp.Rational:
    """A rational within ``1e-30`` of a real algebraic number (for drawing only)."""
    return sp.Rational(sp.N(value, 45))


def _at_irrational(model: Model, at: str | Mapping) -> _AtIrrational | None:
    """The picture's data at ``at`` when some angle there has an irrational (but
    algebraic) ``tan(q/2)``; None when every value is rational."""
    rational, irrational = irrational_values(model, at)
    if not irrational:
        return None
    exact = analyze_irrational(model, at)
    config = Configuration.parse(model, dict(rational), free=list(irrational))
    return _AtIrrational(model, kinematics.build(model, config), config, dict(exact.at),
                         tuple(exact.tangents), exact.numbers,
                         {tangent_name(n): _near(v) for n, v in irrational.items()})


def at_algebraic_witness(model: Model, at: Mapping[str, str], approx: Mapping[str, str],
                         numbers: Numbers) -> _AtIrrational:
    """What :func:`~coopkin_sym.present.draw.draw_system` draws at a locus component's
    algebraic witness, from what the search knows of it: its exact values ``at`` (the
    title), their approximations ``approx`` (the drawing: a revolute joint whose
    ``tan(q/2)`` is irrational at a rational next to it, a length at a rational within
    1e-9) and its exact ``numbers`` (no analysis is made again, no algebraic value is
    read back).

    Example
    -------
    >>> from coopkin_sym.analysis.numbers import Numbers
    >>> from coopkin_sym.model import load_model
    >>> m = load_model("paper-case1-hard")
    >>> w = at_algebraic_witness(m, {"q1": "2*atan(sqrt(2))", "q2": "0"},
    ...                          {"q1": "1.91063323625", "q2": "0"},
    ...                          Numbers(2, 2, 1, 0, 1, 4, 0))
    >>> w.tangents, w.configuration.free, round(float(w.near["t_q1"]), 9)  # float-ok
    (('q1',), frozenset({'q1'}), 1.414213562)
    """
    joints = {j.name: j for j in model.joints}
    rational: dict[str, str] = {}
    irrational: dict[str, sp.Rational] = {}
    for name, text in at.items():
        joint = joints.get(name)
        if joint is not None and joint.type == "revolute":
            try:
                parse_angle(text, name)
                rational[name] = text
            except NumberError:         # drawn at a rational tangent next to it
                half = math.tan(float(approx[name]) / 2)              # float-ok: drawing
                irrational[name] = sp.Rational(Fraction(half).limit_denominator(10**12))
            continue
        try:
            Fraction(text)
            rational[name] = text
        except ValueError:              # a length: a rational within 1e-9 of it
            rational[name] = str(Fraction(approx[name]).limit_denominator(10**9))
    config = Configuration.parse(model, rational, free=list(irrational))
    return _AtIrrational(model, kinematics.build(model, config), config, dict(at),
                         tuple(irrational), numbers,
                         {tangent_name(n): v for n, v in irrational.items()})


def _analysis(source: Any, at: str | Mapping | None) -> Analysis | _AtIrrational:
    if isinstance(source, _AtIrrational):
        if at is not None:
            raise DrawError("at: this drawing already has its configuration")
        return source
    if isinstance(source, Analysis):
        if at is not None:
            raise DrawError("at: this analysis already has its configuration; pass the "
                            "system (or analyze it at the configuration) instead")
        return source
    if isinstance(source, IrrationalAnalysis):
        if at is not None or source.model is None:
            raise DrawError("at: pass the system and the configuration to draw an "
                            "analysis at irrational angles")
        model, at = source.model, dict(source.at)
    elif isinstance(source, Model) or hasattr(source, "model"):
        model = model_of(source)
    else:
        model = load_model(source)
    try:
        config = Configuration.parse(model, at)
    except ConfigurationError:
        there = _at_irrational(model, at) if at is not None else None
        if there is None:
            raise
        return there
    return analyze(model, config)

