"""Pictures of the system in a report: drawn at the witness of each real component,
with a motion gained there, within a bound on the time.

Example
-------
>>> from coopkin_sym.analysis.locus.types import Component, Locus
>>> c = Component(["t_q1"], {"Nm": 3}, {"q1": "0"}, True)
>>> drawable_components(Locus("demo", ["t_q1"], "", {}, [c]))
[0]
"""

from __future__ import annotations

import io
import warnings
from collections.abc import Mapping
from fractions import Fraction
from typing import Any

from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.analysis.mobility import Analysis
from coopkin_sym.errors import DrawError, OutputSkipped
from coopkin_sym.model.configuration import Point
from coopkin_sym.present.conditions import report_names, short_condition
from coopkin_sym.present.draw import MOTION_KINDS, draw_system, gained_motion, motion_counts
from coopkin_sym.present.draw_inputs import at_algebraic_witness
from coopkin_sym.present.draw_labels import name_labels

# key of a picture of the system at a witness among the plots
SYSTEM_PICTURE = "system"
#: Pictures of the system a report carries at most (one per real component).
MAX_SYSTEM_PICTURES = 12
#: Resolution of those pictures (they are large figures; this keeps reports small).
SYSTEM_PICTURE_DPI = 72


def _witness_point(comp: Component) -> tuple[dict[str, str], bool] | None:
    """The point to draw a component at (``--at`` values) and whether it is exact and
    rational (else algebraic: drawn without its motions); None without a real
    witness."""
    if not comp.real:
        return None
    if comp.witness:
        return dict(comp.witness), True
    point = (comp.algebraic_witness or {}).get("point")
    if point:
        return dict(point), False
    return None


def _witness_analysis(system: Any, comp: Component) -> Analysis | None:
    """The exact analysis at a component's witness for its picture: the one the search
    made (when its model is the system's), else one at the exact point (nothing is
    parsed), else None (a witness read back as text)."""
    held = getattr(comp.shown, "analysis", None)
    if held is not None and held.model is system.model:
        return held
    if isinstance(comp.witness, Point):
        return Analysis(system.model, comp.witness)
    return None


def _at_witness(system: Any, comp: Component, at: Mapping[str, str]):
    """What the picture at an algebraic witness is drawn from: the search's exact
    numbers there and the witness's approximations (nothing is analyzed again, no
    algebraic value read back); None when the component does not carry them (a
    witness read back as text: then it is analyzed from its text)."""
    shown = getattr(comp, "shown", None)
    approx = (comp.algebraic_witness or {}).get("approx")
    if shown is None or not approx:
        return None
    try:
        return at_algebraic_witness(system.model, at, approx, shown.numbers)
    except KeyError:        # a value without its approximation
        return None


def drawable_components(locus: Locus) -> list[int]:
    """The components (indices from 0) with a real witness to draw the system at.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Component, Locus
    >>> c = Component(["t_q1"], {"Nm": 3}, {"q1": "0"}, True)
    >>> without = Component(["t_q1"], {}, None, True)
    >>> drawable_components(Locus("demo", ["t_q1"], "", {}, [c, without]))
    [0]
    """
    return [k for k, c in enumerate(locus.components) if _witness_point(c) is not None]


def _counts_words(kind: str, here: Mapping, generic: Mapping) -> str:
    now, before = motion_counts(here)[kind], motion_counts(generic)[kind]
    return f"{kind} motions: {before} generically, {now} here"


def _system_caption(locus: Locus, k: int, comp: Component, at: Mapping[str, str],
                    exact: bool, motion: tuple[str, int] | None) -> str:
    where = ", ".join(f"{n}={v}" for n, v in at.items())
    named = short_condition(comp, report_names(locus.components))
    head = f"Component {k + 1} ({named}): the system at "
    head += f"its witness {where}" if exact else f"its algebraic witness {where}"
    if motion is None:
        changed = ", ".join(f"{n} {a} \u2192 {b}" for n, (a, b) in comp.changes.items())
        return f"{head}; no motion of the object or the joints is gained there ({changed})."
    kind, index = motion
    counts = _counts_words(kind, comp.numbers, locus.generic)
    if not exact:
        return (f"{head}; it gains {kind} motions ({counts}), not drawn: the blocks are "
                "not computed at irrational angles.")
    return (f"{head}, with {kind} motion {index} ({MOTION_KINDS[kind]}), a motion gained "
            f"there ({counts}).")


def system_picture_jobs(locus: Locus, system: Any, dpi: int,
                        limit: int = MAX_SYSTEM_PICTURES
                        ) -> list[tuple[tuple[str, ...] | None, Any]]:
    """The pictures of the system to draw at the witnesses of the real components (the
    first ``limit``): ``(key, job)`` pairs, ``job()`` giving ``(png, key)`` with the
    caption of what it drew (see :func:`~coopkin_sym.present.draw.gained_motion`);
    a note (:class:`~coopkin_sym.errors.OutputSkipped`) for those left out. Nothing
    is drawn here."""
    if system is None or not hasattr(system, "model"):
        return []
    chosen = drawable_components(locus)
    if not chosen:
        _skipped("no picture of the system: no component has a real witness to draw it at")
        return []
    if len(chosen) > limit:
        _skipped(f"pictures of the system at {len(chosen) - limit} more "
                 f"components left out (at most {limit})")
    return [(None, _SystemPicture(locus, system, k, dpi)) for k in chosen[:limit]]


class _SystemPicture:
    """Drawing the system at the witness of component ``k`` (a job)."""

    def __init__(self, locus: Locus, system: Any, k: int, dpi: int):
        self.locus, self.system, self.k, self.dpi = locus, system, k, dpi

    def __call__(self) -> tuple[bytes, tuple[str, ...]]:
        locus, system, k = self.locus, self.system, self.k
        comp = locus.components[k]
        at, exact = _witness_point(comp)
        motion = gained_motion(comp.numbers, locus.generic)
        at_text = ",".join(f"{n}={v}" for n, v in at.items())
        title = f"{locus.system}: component {k + 1}"
        near = {} if exact else _lengths_near(system, comp, at)
        if near:
            at_text = ",".join(f"{n}={near.get(n, v)}" for n, v in at.items())
        held = _witness_analysis(system, comp) if exact else _at_witness(
            system, comp, {n: near.get(n, v) for n, v in at.items()})
        drawn_at = (held, None) if held is not None else (system, at_text)
        try:
            fig = draw_system(*drawn_at, title=title,
                              motion=f"{motion[0]}:{motion[1]}" if motion and exact
                              else None)
        except DrawError:   # the motion is not there after all: the system alone
            if motion is None or not exact:
                raise
            fig = draw_system(*drawn_at, title=title)
            motion = None
        keep_layout(fig)
        buf = io.BytesIO()
        fig.savefig(buf, format="png", dpi=min(self.dpi, SYSTEM_PICTURE_DPI))
        caption = _system_caption(locus, k, comp, at, exact, motion)
        if near:
            caption += (" Drawn with " + ", ".join(f"{n} = {v}" for n, v in near.items())
                        + " (rational values within 1e-9 of the witness's lengths).")
        return buf.getvalue(), (SYSTEM_PICTURE, f"component {k + 1}", caption)


def keep_layout(fig: Any) -> bool:
    """Keep the layout a picture of the system was given when its name labels were
    moved apart (that drew it once, laid out): saving it then draws it once more,
    instead of laying it out again first. True if kept; a picture drawn without name
    labels (never laid out yet) keeps its layout engine.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.present.draw import draw_system
    >>> fig = draw_system(load("paper-case1-hard"))
    >>> keep_layout(fig), fig.get_layout_engine()
    (True, None)
    """
    import matplotlib

    if not any(name_labels(ax) for ax in fig.axes):
        return False
    with matplotlib.rc_context({"figure.autolayout": False,
                                "figure.constrained_layout.use": False}):
        fig.set_layout_engine(None)
    return True


def _lengths_near(system: Any, comp: Component, at: Mapping[str, str]) -> dict[str, str]:
    """For a picture at an algebraic witness: the prismatic joints and parameters whose
    value there is irrational (a length the picture cannot be given exactly), each with
    a rational value within 1e-9 of it (from the witness's own approximation). Angles
    are drawn exactly; the picture is a drawing, its numbers are the component's.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.locus.types import Component
    >>> c = Component(["t_q1"], {"Nm": 3}, None, True)
    >>> c.algebraic_witness = {"point": {"q1": "0", "q4": "sqrt(2)"},
    ...                        "approx": {"q1": "0", "q4": "1.41421356237"}}
    >>> _lengths_near(load("paper-case2-hard"), c, {"q1": "0", "q4": "sqrt(2)"})
    {'q4': '1217471/860882'}
    """
    if system is None or not hasattr(system, "model"):
        return {}
    lengths = {j.name for j in system.model.joints if j.type == "prismatic"} | {
        p.name for p in system.model.parameters}
    approx = (comp.algebraic_witness or {}).get("approx", {})
    out = {}
    for name, value in at.items():
        if name not in lengths or name not in approx:
            continue
        try:
            Fraction(value)
            continue                     # rational already
        except ValueError:
            pass
        near = Fraction(approx[name]).limit_denominator(10**6)
        if abs(near - Fraction(approx[name])) > Fraction(1, 10**9):
            near = Fraction(approx[name])
        out[name] = str(near)
    return out


def system_picture_failed(job: Any, error: BaseException) -> None:
    """A picture of the system that could not be drawn: said (the picture is optional
    in a report) when it is an :class:`ImportError` or :class:`ValueError`, else
    ``error`` raised."""
    if not isinstance(error, (ImportError, ValueError)):
        raise error
    _skipped(f"no picture of the system at component {job.k + 1}: "
             f"{' '.join(str(error).split())}")


def _skipped(text: str, kind: type[OutputSkipped] = OutputSkipped) -> None:
    """Say that a part of the report is left out (shown by ``coopkin`` on stderr)."""
    warnings.warn(text, kind, stacklevel=3)
