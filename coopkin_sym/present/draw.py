"""Pictures of a system: arms, joints, contacts, the object, and one of its motions.

Everything here is drawing, so everything here is floating point (each such line is
marked ``# float-ok``): the exact geometry of an :class:`~coopkin_sym.analysis.mobility.Analysis`
(current joint points and axes, contact points and normals, the columns of the blocks)
is evaluated exactly at rational values and only then turned into floats for
matplotlib. No rank, nullspace or singularity is decided here.

Parameters left symbolic are drawn at 1 and joints left symbolic at home (q = 0); the
title says so. At an angle whose ``tan(q/2)`` is irrational but algebraic
(``q1=-pi/6``) the numbers in the title are the exact ones there
(:mod:`coopkin_sym.analysis.irrational`) and the geometry is evaluated at a rational
within ``1e-30`` of each such tangent; the blocks are not computed there, so no motion
or ellipsoid is drawn (an :class:`~coopkin_sym.errors.OutputSkipped` warning says so
when one was asked for). On request the picture shows one motion:

* ``("coordinated", k)``: column ``k`` of ``C12`` and ``C22`` (paper eq. 8): the
  velocity of the object at each contact point, the object's twist (a translation
  arrow, or its screw axis dashed with a circular arrow) and the joint rates that
  realize it (curved arrows at revolute joints, straight ones at prismatic joints,
  with the exact rates as labels);
* ``("indeterminate", k)``: column ``k`` of ``C11``, an object motion with every joint
  locked (e.g. the free spin about the line through two hard-finger contacts);
* ``("redundant", k)``: column ``k`` of ``C23``, joint rates with the object fixed.

``k`` counts from 1. matplotlib is needed (``pip install matplotlib``); pictures are
drawn on a :class:`matplotlib.figure.Figure` with the Agg canvas, so no display is
needed.

Example
-------
>>> from coopkin_sym import load
>>> fig = draw_system(load("paper-case1-hard"), motion=("coordinated", 1))
>>> sorted(a.get_gid() for a in fig.axes[0].get_children()
...        if (a.get_gid() or "").startswith("link:"))
['link:a1/1', 'link:a2/1']
"""

from __future__ import annotations

import functools
import io
import itertools
import os
import re
import textwrap
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import flint
import numpy as np  # float-ok: drawing coordinates
import sympy as sp

from coopkin_sym import limits
from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.irrational import (
    IrrationalAnalysis,
    analyze_irrational,
    irrational_values,
)
from coopkin_sym.analysis.kinematics import spatial_twist
from coopkin_sym.analysis.mobility import Analysis, analyze
from coopkin_sym.analysis.numbers import Numbers
from coopkin_sym.errors import ConfigurationError, DrawError, OutputSkipped
from coopkin_sym.exact.angles import tangent_name
from coopkin_sym.exact.parse import brief
from coopkin_sym.exact.ring import Frac
from coopkin_sym.exact.sympy_bridge import rational_to_sympy
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.contacts import contact_kind
from coopkin_sym.model.model import Model, load_model, model_of
from coopkin_sym.present.files import check_output_path, write_files
from coopkin_sym.present.sentences import (
    contact_phrase,
    describe_joint_motion,
    describe_twist,
)

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["MOTION_KINDS", "DrawError", "draw_system", "gained_motion", "motion_counts",
           "parse_motion", "rate_labels",
           "rate_ratios", "ratio_text", "save_picture"]

#: Motion kinds and the blocks they come from.
MOTION_KINDS: dict[str, str] = {
    "coordinated": "C12, C22",
    "indeterminate": "C11",
    "redundant": "C23",
}

ARM_COLORS = ("tab:blue", "tab:green", "tab:purple", "tab:brown", "tab:olive", "tab:cyan",
              "tab:pink", "tab:gray")
OBJECT_MOTION_COLOR = "crimson"
JOINT_MOTION_COLOR = "darkorange"
SAVE_FORMATS = (".png", ".pdf", ".svg")
_LABEL_BOX = {"boxstyle": "round,pad=0.15", "facecolor": "white", "alpha": 0.7,
              "edgecolor": "none"}



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


@dataclass(frozen=True)
class _AtIrrational:
    """What a picture needs at a configuration with irrational tangents: the exact
    analysis there (its numbers), the geometry with those joints symbolic, and for
    each of their ``tan(q/2)`` a rational within ``1e-30`` to draw it at."""

    model: Model
    kinematics: Any
    configuration: Configuration
    exact: IrrationalAnalysis
    near: dict[str, sp.Rational]

    @property
    def numbers(self) -> Numbers:
        return self.exact.numbers


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
    return _AtIrrational(model, kinematics.build(model, config), config, exact,
                         {tangent_name(n): _near(v) for n, v in irrational.items()})


def _analysis(source: Any, at: str | Mapping | None) -> Analysis | _AtIrrational:
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


@functools.cache
def _mpl():
    """matplotlib's Agg canvas and a Figure that shows itself in notebooks."""
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError:  # pragma: no cover - depends on the installation
        raise DrawError("pictures need matplotlib: pip install matplotlib") from None

    class Picture(Figure):
        """A matplotlib Figure that Jupyter displays as PNG without any backend setup."""

        def _repr_png_(self) -> bytes:
            buffer = io.BytesIO()
            self.savefig(buffer, format="png", dpi=80)
            return buffer.getvalue()

    return Picture, FigureCanvasAgg


# ------------------------------------------------------------------ exact -> float


def _magnitude(value: sp.Rational) -> str:
    """``1e+300``-style size of a rational too large for a float."""
    whole = abs(int(value))
    return f"1e+{int(whole.bit_length() * 0.30103) if whole else 0}"  # float-ok: display


class _Values:
    """Rational values for the symbols left in an analysis: free joints at home,
    free parameters at 1."""

    def __init__(self, a: Analysis | _AtIrrational):
        ring = a.kinematics.ring
        self.unit = [n for n in ring.names if n in {p.name for p in a.model.parameters}]
        # t = tan(q/2) = 0 and a prismatic displacement 0 are home; lengths at 1; an
        # irrational tan(q/2) at a rational next to it
        self.near = dict(getattr(a, "near", {}))
        value = {n: self.near.get(n, sp.Integer(1 if n in self.unit else 0))
                 for n in ring.names}
        self.fmpq = [flint.fmpq(int(value[n].p), int(value[n].q)) for n in ring.names]
        syms = a.kinematics.symbols
        self.sympy = {syms[n]: value[n] for n in ring.names}

    def exact(self, f: Frac) -> sp.Rational:
        """A :class:`Frac` at the drawing values, exactly."""
        num = f.num(*self.fmpq)
        den = f.ring.den_poly(f.den)(*self.fmpq)
        return rational_to_sympy(num / den)

    def vec(self, v: Sequence[Frac] | None) -> list[float] | None:
        if v is None:
            return None
        out = []
        for x in v:
            value = self.exact(x)
            if abs(value) > limits.MAX_DRAWN_COORDINATE:
                raise DrawError(f"cannot draw this configuration: a coordinate of about "
                                f"{_magnitude(value)} is beyond what a picture can show "
                                f"(at most {limits.MAX_DRAWN_COORDINATE:.0e}; scale the "
                                "lengths down)")
            out.append(float(value))  # float-ok: drawing only
        return out

    def column(self, mat: sp.Matrix, k: int) -> list[sp.Rational]:
        """Column ``k`` (from 0) of a block at the drawing values, exactly."""
        return self.vector(mat.col(k))

    def vector(self, entries) -> list[sp.Rational]:
        """Exact entries at the drawing values."""
        return [sp.cancel(e.xreplace(self.sympy)) for e in entries]

    def note(self, a: Analysis) -> str:
        parts = []
        if self.unit:
            parts.append(f"{', '.join(self.unit)} symbolic, drawn at 1")
        joints = [j.name for j in a.model.joints if j.name in a.configuration.free
                  and tangent_name(j.name) not in self.near]
        if joints:
            parts.append(f"{', '.join(joints)} symbolic, drawn at home (0)")
        return "; ".join(parts)


# ------------------------------------------------------------------ geometry


class _Scene:
    """Float geometry of one analysis at the drawing values."""

    def __init__(self, a: Analysis, values: _Values):
        kin = a.kinematics
        model = a.model
        self.points = [np.array(values.vec(p)) for p in kin.points]  # float-ok
        self.normals = [None if n is None else np.array(values.vec(n))  # float-ok
                        for n in kin.normals]
        self.axes = [np.array(values.vec(s)) for s in kin.axes]  # float-ok
        origins = [None if o is None else np.array(values.vec(o))  # float-ok
                   for o in kin.origins]
        # the start of each link: its joint's point (or the previous start)
        self.starts: list[list] = []   # per arm: start point of link K = 0..nK
        for i, arm in enumerate(model.arms):
            off = model.joint_offset(i)
            own = [origins[off + k] for k in range(len(arm.joints))]
            first = next((o for o in own if o is not None), None)
            if first is None:
                on_arm = [p for c, p in zip(model.contacts, self.points, strict=True)
                          if c.arm == i]
                first = on_arm[0] if on_arm else np.zeros(3)  # float-ok
            starts = [first]
            for o in own:
                starts.append(o if o is not None else starts[-1])
            # starts[0] is the arm's fixed base, starts[K] the point of joint K
            self.starts.append(starts)
        self.joint_points = [self.starts[i][k + 1] for i, arm in enumerate(model.arms)
                             for k in range(len(arm.joints))]
        every = self.points + [p for s in self.starts for p in s]
        stack = np.array(every)  # float-ok
        self.low, self.high = stack.min(axis=0), stack.max(axis=0)  # float-ok
        self.size = float(max(np.max(self.high - self.low), 1e-9))  # float-ok
        if self.size <= 1e-9:  # float-ok: everything at one point
            self.size = 1.0  # float-ok
        self.center = (self.low + self.high) / 2  # float-ok
        pad = 0.18 * self.size  # float-ok
        self.span = np.maximum(self.high - self.low, 0.35 * self.size) + 2 * pad  # float-ok
        self.box = (self.center - self.span / 2, self.center + self.span / 2)  # float-ok

    def clip(self, point, direction):
        """The part of the line ``point + s direction`` inside the drawing box."""
        lo, hi = -float("inf"), float("inf")  # float-ok
        for k in range(3):
            if abs(direction[k]) < 1e-15:  # float-ok: parallel to this face pair
                continue
            a = (self.box[0][k] - point[k]) / direction[k]  # float-ok
            b = (self.box[1][k] - point[k]) / direction[k]  # float-ok
            lo, hi = max(lo, min(a, b)), min(hi, max(a, b))  # float-ok
        return point + lo * direction, point + hi * direction  # float-ok


def _shift(ax, right: float, up: float):
    """The axes' data transform moved by (right, up) points: labels beside a point."""
    from matplotlib.transforms import offset_copy

    return offset_copy(ax.transData, fig=ax.figure, x=right, y=up, units="points")


def _perp_basis(axis):
    """Two unit vectors perpendicular to ``axis`` and to each other."""
    a = axis / np.linalg.norm(axis)  # float-ok
    helper = np.array([1.0, 0, 0]) if abs(a[0]) < 0.9 else np.array([0, 1.0, 0])  # float-ok
    e1 = np.cross(a, helper)  # float-ok
    e1 /= np.linalg.norm(e1)  # float-ok
    return e1, np.cross(a, e1)  # float-ok


# ------------------------------------------------------------------ drawing


def draw_system(analysis_or_system: Any, at: str | Mapping | None = None,
                motion: str | Sequence | None = None, ax: Axes | None = None,
                title: str | None = None, ellipsoid: bool = False) -> Figure:
    """Draw a system in 3D: arms, joint axes, contacts and normals, the object, the
    ground, and optionally one motion.

    Parameters
    ----------
    analysis_or_system
        An :class:`~coopkin_sym.analysis.mobility.Analysis`, a :class:`~coopkin_sym.System`,
        or anything :func:`coopkin_sym.load` accepts (file, dict, example name).
    at
        Configuration to analyze and draw (not with an ``Analysis``, which has one);
        angles with an irrational ``tan(q/2)`` (``q1=-pi/6``) are drawn without a
        motion (see the module's note).
    motion
        ``None``, ``("coordinated", k)``, ``("indeterminate", k)``, ``("redundant", k)``
        or the same as text ``"coordinated:1"``; ``k`` counts from 1.
    ax
        A 3D axes to draw into (``projection="3d"``); a new figure otherwise.
    title
        Replaces the first title line (the system's name).
    ellipsoid
        Also draw the manipulability ellipsoid of the object's translations (see
        :mod:`coopkin_sym.analysis.manipulability`): the velocities of the object's
        reference point that unit joint speed gives, modulo the indeterminate motions;
        an ellipse in the plane for a planar system. Its scale is stated.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    DrawError
        A motion that does not exist, an ``ax`` that is not 3D, matplotlib missing.

    Example
    -------
    >>> from coopkin_sym import load
    >>> fig = draw_system(load("paper-case2-hard"), motion="indeterminate:1")
    >>> len([a for a in fig.axes[0].get_children()
    ...      if (a.get_gid() or "").startswith("contact:")])
    2
    """
    a = _analysis(analysis_or_system, at)
    request = parse_motion(motion, a)
    Figure, FigureCanvasAgg = _mpl()
    if ax is None:
        fig = Figure(figsize=(10.5, 7.5), layout="constrained")
        FigureCanvasAgg(fig)
        ax = fig.add_subplot(projection="3d")
    elif getattr(ax, "name", "") != "3d":
        raise DrawError("ax: a 3D axes is needed (add_subplot(projection='3d'))")
    fig = ax.figure
    try:
        return _draw_into(fig, ax, a, request, title, ellipsoid)
    except (np.linalg.LinAlgError, OverflowError, FloatingPointError,
            ZeroDivisionError) as exc:
        raise DrawError(f"cannot draw this configuration ({type(exc).__name__}: "
                        f"{' '.join(str(exc).split())[:80]})") from None


def _draw_into(fig, ax, a: Analysis, request, title: str | None, ellipsoid: bool = False):
    values = _Values(a)
    scene = _Scene(a, values)
    legend: list = []
    _draw_ground(ax, a, scene, legend)
    _draw_object(ax, a, scene, legend)
    _draw_arms(ax, a, scene, legend)
    _draw_contacts(ax, a, scene, legend)
    motion_line = ""
    if isinstance(a, _AtIrrational):
        motion_line = _not_drawn(request, ellipsoid)
    else:
        if request is not None:
            motion_line = _draw_motion(ax, a, scene, values, request, legend)
        if ellipsoid:
            line = _draw_ellipsoid(ax, a, scene, values, legend)
            motion_line = f"{motion_line}\n{line}" if motion_line else line
    _frame(ax, scene, a.model.planar)
    lines = [title if title is not None else a.model.name]
    if isinstance(a, _AtIrrational):
        where = ",".join(f"{k}={v}" for k, v in a.exact.at.items())
    else:
        where = a.configuration.at_text() or "home (all joints at 0)"
    n = a.numbers
    line = f"at {where}   Nm={n.Nm} Nc={n.Nc} Ni={n.Ni} Nr={n.Nr}"
    if len(line) > 110:   # a long configuration: broken after its commas
        line = _wrap(line.replace(",", ", "), 110)
    lines.append(line)
    note = values.note(a)
    if isinstance(a, _AtIrrational):
        exact = (f"{', '.join(f'tan({j}/2)' for j in a.exact.tangents)} irrational: "
                 "numbers exact over Q(alpha), drawn at float coordinates")
        note = f"{note}; {exact}" if note else exact
    if note:
        lines.append(note)
    if motion_line:
        lines.append(motion_line)
    ax.set_title("\n".join(lines), fontsize=10)
    seen: set[str] = set()
    unique = []
    for h in legend:
        if h.get_label() not in seen:
            seen.add(h.get_label())
            unique.append(h)
    ax.legend(handles=unique, loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8,
              frameon=False)
    return fig


def _not_drawn(request: tuple[str, int] | None, ellipsoid: bool) -> str:
    """At irrational angles: the motion and ellipsoid asked for are not drawn (the
    blocks are not computed there); a warning and the title line say so."""
    asked = ([f"{request[0]} motion {request[1]}"] if request else []) + (
        ["the manipulability ellipsoid"] if ellipsoid else [])
    if not asked:
        return ""
    line = (f"{' and '.join(asked)} not drawn: the blocks are not computed at a "
            "configuration with irrational coordinates (use one with rational "
            "tan(q/2), e.g. 2*atan(p/q))")
    warnings.warn(line, OutputSkipped, stacklevel=4)
    return _wrap(line, 110)


def _draw_ellipsoid(ax, a: Analysis, scene: _Scene, values: _Values, legend: list) -> str:
    """The manipulability ellipsoid of the translations, at the centre of the contacts,
    scaled to the picture; returns the title line that states the scale."""
    from matplotlib.lines import Line2D

    names = tuple(n for n in a.model.twist_names if n.startswith("v"))
    kin = a.kinematics
    # the velocity of the centre of the contacts, exact at the drawing values
    centre = [sum((values.exact(p[i]) for p in kin.points), sp.Integer(0)) / len(kin.points)
              for i in range(3)]
    m = a.manipulability(names, point=centre)
    shape = np.array([[float(x) for x in values.vector(m.shape.row(i))]  # float-ok: plot
                      for i in range(m.shape.rows)])
    lengths, directions = np.linalg.eigh(shape)  # float-ok: plot
    semi = np.sqrt(np.clip(lengths, 0.0, None))  # float-ok: plot
    center = np.array([float(x) for x in centre])  # float-ok: plot
    if float(semi.max()) <= 0:  # float-ok: exact rank 0 says the same
        return "manipulability ellipsoid: a point (no translation is driven)"
    scale = 0.35 * scene.size / float(semi.max())  # float-ok: plot
    color = "tab:purple"
    if len(names) == 2:
        phi = np.linspace(0, 2 * np.pi, 120)  # float-ok: plot
        ring = directions @ (semi[:, None] * np.vstack([np.cos(phi), np.sin(phi)]))
        ax.plot(center[0] + scale * ring[0], center[1] + scale * ring[1],
                np.full_like(phi, center[2]), color=color, linewidth=1.8)
    else:
        u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 28),  # float-ok: plot
                           np.linspace(0, np.pi, 14))  # float-ok: plot
        sphere = np.stack([np.cos(u) * np.sin(v), np.sin(u) * np.sin(v), np.cos(v)])
        shell = np.einsum("ij,jkl->ikl", directions * semi, sphere)  # float-ok: plot
        ax.plot_wireframe(center[0] + scale * shell[0], center[1] + scale * shell[1],
                          center[2] + scale * shell[2], color=color, linewidth=0.5,
                          alpha=0.6)
    legend.append(Line2D([], [], color=color, label="manipulability ellipsoid"))
    axes = ", ".join(f"{x:.3g}" for x in sorted(semi, reverse=True))  # float-ok: plot
    kind = "ellipse" if len(names) == 2 else "ellipsoid"
    speed = "motor" if a.model.passive_joints else "joint"
    return (f"manipulability {kind}: velocity of the contacts' centre at unit {speed} "
            f"speed, semi-axes {axes} (rank {m.rank}), drawn x{scale:.3g}")


def _frame(ax, scene: _Scene, planar: bool) -> None:
    """Limits, labels and the view: oblique, or from above (+z) for a planar system."""
    lo, hi = scene.box
    ax.set_xlim(lo[0], hi[0])  # float-ok
    ax.set_ylim(lo[1], hi[1])  # float-ok
    ax.set_zlim(lo[2], hi[2])  # float-ok
    ax.set_box_aspect(tuple(scene.span))  # float-ok
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    if planar:
        ax.view_init(elev=90, azim=-90)
        ax.set_proj_type("ortho")
        ax.set_zticks([])
        ax.set_zlabel("")
    else:
        ax.view_init(elev=28, azim=-58)
    ax.tick_params(labelsize=7)


def _draw_ground(ax, a: Analysis, scene: _Scene, legend: list) -> None:
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    z = scene.low[2] - 0.04 * scene.size  # float-ok
    m = 0.15 * scene.size  # float-ok
    x0, y0 = scene.low[:2] - m  # float-ok
    x1, y1 = scene.high[:2] + m  # float-ok
    quad = np.array([[x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]])  # float-ok
    ground = Poly3DCollection([quad], facecolor="0.6", alpha=0.12, edgecolor="0.6")
    ground.set_gid("ground")
    ax.add_collection3d(ground)
    legend.append(Patch(facecolor="0.6", alpha=0.3, label="ground"))
    # pedestals: each arm's fixed base, raised to it from the ground
    for i, arm in enumerate(a.model.arms):
        base = scene.starts[i][0]
        color = ARM_COLORS[i % len(ARM_COLORS)]
        (post,) = ax.plot([base[0], base[0]], [base[1], base[1]], [z, base[2]],  # float-ok
                          color="0.35", linewidth=3, solid_capstyle="butt")
        post.set_gid(f"base:{arm.name}")
        ax.scatter([base[0]], [base[1]], [z], marker="s", s=110, color=color,  # float-ok
                   edgecolor="0.25", depthshade=False)
    legend.append(Line2D([], [], color="0.35", linewidth=3, marker="s", markersize=8,
                         markerfacecolor="0.6", label="arm base (fixed)"))
    for c, p in zip(a.model.contacts, scene.points, strict=True):
        if c.arm is None:  # a contact on the ground itself
            (post,) = ax.plot([p[0], p[0]], [p[1], p[1]], [z, p[2]],  # float-ok
                              color="0.35", linewidth=2, linestyle=":")
            post.set_gid(f"link:base@{c.name}")


def _draw_object(ax, a: Analysis, scene: _Scene, legend: list) -> None:
    from matplotlib.patches import Patch
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    faces = _object_faces(scene)
    if not faces:
        return
    body = Poly3DCollection(faces, facecolor="wheat", alpha=0.28, edgecolor="peru",
                            linewidth=0.8)
    body.set_gid("object")
    ax.add_collection3d(body)
    legend.append(Patch(facecolor="wheat", edgecolor="peru", label="object"))


def _object_faces(scene: _Scene) -> list:
    """Faces of a translucent body through the contact points: their convex hull when
    they span space, a polygon when they lie in a plane, a bar when on a line."""
    pts = np.array(scene.points)  # float-ok
    centroid = pts.mean(axis=0)  # float-ok
    rel = pts - centroid  # float-ok
    tol = 1e-9 * scene.size  # float-ok: drawing only
    sv = np.linalg.svd(rel, compute_uv=False) if len(pts) > 1 else np.zeros(3)  # float-ok
    sv = np.concatenate([sv, np.zeros(3)])[:3]  # float-ok
    if sv[2] > tol:  # float-ok: a solid hull
        return _hull_faces(pts)
    if sv[1] > tol:  # float-ok: a polygon in a plane
        _, _, vt = np.linalg.svd(rel)  # float-ok
        e1, e2 = vt[0], vt[1]  # float-ok
        order = np.argsort(np.arctan2(rel @ e2, rel @ e1))  # float-ok
        return [pts[order]]
    # a bar along the line through the points (or a small cube at one point)
    if sv[0] > tol:  # float-ok
        direction = rel[np.argmax(np.linalg.norm(rel, axis=1))]  # float-ok
        d = direction / np.linalg.norm(direction)  # float-ok
        t = rel @ d  # float-ok
        a, b = centroid + t.min() * d, centroid + t.max() * d  # float-ok
    else:
        d = np.array([1.0, 0, 0])  # float-ok
        a = centroid - 0.1 * scene.size * d  # float-ok
        b = centroid + 0.1 * scene.size * d  # float-ok
    e1, e2 = _perp_basis(d)
    w = 0.12 * max(np.linalg.norm(b - a), 0.5 * scene.size)  # float-ok
    corners = [a + w * (s1 * e1 + s2 * e2) for s1, s2 in  # float-ok
               ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    far = [c + (b - a) for c in corners]  # float-ok
    faces = [corners, far]
    for k in range(4):
        faces.append([corners[k], corners[(k + 1) % 4], far[(k + 1) % 4], far[k]])
    return faces


def _hull_faces(pts) -> list:
    """Triangles of the convex hull of a few points in general position (brute force)."""
    faces = []
    scale = np.max(np.linalg.norm(pts - pts.mean(axis=0), axis=1))  # float-ok
    for i, j, k in itertools.combinations(range(len(pts)), 3):
        n = np.cross(pts[j] - pts[i], pts[k] - pts[i])  # float-ok
        if np.linalg.norm(n) < 1e-12 * scale**2:  # float-ok: degenerate triangle
            continue
        side = (pts - pts[i]) @ n  # float-ok
        if np.all(side <= 1e-9 * scale * np.linalg.norm(n)) or np.all(  # float-ok
                side >= -1e-9 * scale * np.linalg.norm(n)):  # float-ok
            faces.append([pts[i], pts[j], pts[k]])
    return faces


def _draw_arms(ax, a: Analysis, scene: _Scene, legend: list) -> None:
    from matplotlib.lines import Line2D

    model = a.model
    arrow = 0.16 * scene.size  # float-ok
    kinds = set()
    labels: dict[tuple, list[str]] = {}
    for i, arm in enumerate(model.arms):
        color = ARM_COLORS[i % len(ARM_COLORS)]
        legend.append(Line2D([], [], color=color, linewidth=3, label=f"arm {arm.name}"))
        starts = scene.starts[i]
        nlinks = len(arm.joints)
        for link in range(0, nlinks + 1):
            ends = [p for c, p in zip(model.contacts, scene.points, strict=True)
                    if c.arm == i and c.link == link]
            if link < nlinks:
                ends = [starts[link + 1], *ends]
            if link == 0 and len(ends) == 1:
                continue   # the base link is drawn only when a contact is on it
            if link == 0:
                ends = ends[1:]
            xs, ys, zs = [], [], []
            for e in ends:
                for coord, seg in zip((xs, ys, zs), zip(starts[link], e, strict=True),
                                      strict=True):
                    coord.extend([seg[0], seg[1], np.nan])  # float-ok
            if not ends:  # the outermost link with nothing on it: a stub
                xs, ys, zs = ([s, s] for s in starts[link])
            (line,) = ax.plot(xs, ys, zs, color=color, linewidth=4,  # float-ok
                              solid_capstyle="round", alpha=0.9)
            line.set_gid(f"link:{arm.name}/{link}")
        off = model.joint_offset(i)
        for k, joint in enumerate(arm.joints):
            o = starts[k + 1]
            s = scene.axes[off + k]
            s = s / np.linalg.norm(s)  # float-ok
            kinds.add(joint.type)
            style = "-" if joint.type == "revolute" else "--"
            q = ax.quiver(*o, *(arrow * s), color=color, linewidth=1.6,  # float-ok
                          linestyle=style, arrow_length_ratio=0.25)
            q.set_gid(f"joint:{joint.name}")
            marker = "o" if joint.type == "revolute" else "s"
            ax.scatter(*([v] for v in o), marker=marker, s=36, facecolor="white",  # float-ok
                       edgecolor=color, linewidth=1.5, depthshade=False, zorder=5)
            if joint.type == "revolute":  # a small ring about the axis
                e1, e2 = _perp_basis(s)
                phi = np.linspace(0, 2 * np.pi, 40)  # float-ok
                ring = (o[:, None] + 0.35 * arrow * s[:, None]  # float-ok
                        + 0.18 * arrow * (np.outer(e1, np.cos(phi))  # float-ok
                                          + np.outer(e2, np.sin(phi))))  # float-ok
                ax.plot(*ring, color=color, linewidth=1)
            key = tuple(np.round(o / scene.size, 6))  # float-ok: group coincident joints
            labels.setdefault(key, [o, color, []])[2].append(joint.name)
    for o, color, names in labels.values():
        ax.text(*o, ", ".join(names), fontsize=8, color=color, fontweight="bold",
                transform=_shift(ax, 7, -12), zorder=1000,
                bbox=_LABEL_BOX)
    if "revolute" in kinds:
        legend.append(Line2D([], [], color="0.2", marker="o", markerfacecolor="white",
                             label="revolute joint (axis)"))
    if "prismatic" in kinds:
        legend.append(Line2D([], [], color="0.2", linestyle="--", marker="s",
                             markerfacecolor="white", label="prismatic joint (axis)"))


def _draw_contacts(ax, a: Analysis, scene: _Scene, legend: list) -> None:
    from matplotlib.lines import Line2D

    seen = set()
    normal_len = 0.2 * scene.size  # float-ok
    for c, p, n in zip(a.model.contacts, scene.points, scene.normals, strict=True):
        marker = contact_marker(c.model)
        (dot,) = ax.plot([p[0]], [p[1]], [p[2]], linestyle="none", marker=marker,  # float-ok
                         markersize=10, markerfacecolor="gold", markeredgecolor="black",
                         zorder=900)
        dot.set_gid(f"contact:{c.name}")
        ax.text(*p, c.name, fontsize=9, fontweight="bold", color="black",
                transform=_shift(ax, 7, 8), ha="left", zorder=1000,
                bbox=_LABEL_BOX)
        if c.model not in seen:
            seen.add(c.model)
            legend.append(Line2D([], [], linestyle="none", marker=marker, markersize=8,
                                 markerfacecolor="gold", markeredgecolor="black",
                                 label=contact_phrase(c.model)))
        if n is not None:
            q = ax.quiver(*p, *(normal_len * n), color="black", linewidth=1.2,  # float-ok
                          arrow_length_ratio=0.3)
            q.set_gid(f"normal:{c.name}")
    if any(n is not None for n in scene.normals):
        legend.append(Line2D([], [], color="black", linewidth=1.2, label="contact normal"))


def contact_marker(model: str) -> str:
    """The Matplotlib marker of a contact of model ``model``: its entry's in
    :data:`~coopkin_sym.model.contacts.REGISTRY`.

    Example
    -------
    >>> contact_marker("hard"), contact_marker("soft")
    ('o', 'D')
    """
    kind = contact_kind(model)
    if kind is None:
        raise DrawError(f"no marker for the contact model {model!r}")
    return kind.marker


#: A ratio is shown as a fraction when its numerator and denominator are at most this.
SMALL_FRACTION = 99


def rate_ratios(rates: Sequence[sp.Rational]) -> list[sp.Rational]:
    """Joint rates divided by the largest magnitude among them: the same motion, with
    the fastest joint at rate 1 or -1 (directions kept).

    Example
    -------
    >>> rate_ratios([sp.Integer(137020), sp.Integer(-68510), sp.Integer(0)])
    [1, -1/2, 0]
    """
    top = max((abs(r) for r in rates), default=sp.Integer(0))
    if top == 0:
        return list(rates)
    return [sp.Rational(r) / top for r in rates]


def ratio_text(r: sp.Rational) -> str:
    """A ratio as a small exact fraction (``-1/2``), or about four digits when its
    fraction is not small (``~0.7071``, never a long integer).

    Example
    -------
    >>> ratio_text(sp.Rational(-1, 2)), ratio_text(sp.Rational(70711, 100000))
    ('-1/2', '~0.7071')
    """
    r = sp.Rational(r)
    if abs(r.p) <= SMALL_FRACTION and r.q <= SMALL_FRACTION:
        return sp.sstr(r)
    return f"~{float(r):.4g}"  # float-ok: label only


def rate_labels(names: Sequence[str], rates: Sequence[sp.Rational],
                places: Sequence[Any]) -> list[tuple[int, str]]:
    """The labels of joint rates on a picture: ratios to the fastest joint
    (:func:`rate_ratios`, :func:`ratio_text`), one label per place: joints at one
    point (the same key in ``places``) share one label. Returns (index of the first
    joint at the place, text) for every place with a moving joint.

    Example
    -------
    >>> rate_labels(["q4", "q5", "q6"], [sp.Integer(2), sp.Integer(-1), sp.Integer(0)],
    ...             ["wrist", "wrist", "wrist"])
    [(0, 'q4: 1, q5: -1/2')]
    """
    ratios = rate_ratios(rates)
    groups: dict[Any, list[int]] = {}
    for index, (r, place) in enumerate(zip(ratios, places, strict=True)):
        if r != 0:
            groups.setdefault(place, []).append(index)
    return [(members[0], ", ".join(f"{names[i]}: {ratio_text(ratios[i])}" for i in members))
            for members in groups.values()]


def _draw_motion(ax, a: Analysis, scene: _Scene, values: _Values,
                 request: tuple[str, int], legend: list) -> str:
    """Arrows for one motion; returns the title line describing it."""
    from matplotlib.lines import Line2D


    kind, k = request
    j = k - 1
    twist = rates = exact_q = None
    if kind == "coordinated":
        twist = values.vector(spatial_twist(a.twist_in_base(a.C12.col(j))))
        rates = values.column(a.C22, j)
        exact_q = a.C22.col(j)
        words = (f"coordinated motion {k} (C12, C22 column {k}): "
                 f"{describe_twist(a.C12.col(j), a)} by moving "
                 f"{_joint_words(exact_q, rates, a)}")
    elif kind == "indeterminate":
        twist = values.vector(spatial_twist(a.twist_in_base(a.C11.col(j))))
        words = (f"indeterminate motion {k} (C11 column {k}), joints locked: "
                 f"{describe_twist(a.C11.col(j), a)}")
    else:
        rates, exact_q = values.column(a.C23, j), a.C23.col(j)
        words = (f"redundant motion {k} (C23 column {k}), object fixed: "
                 f"{_joint_words(exact_q, rates, a)}")
    vanish = (twist is None or all(x == 0 for x in twist)) and (
        rates is None or all(x == 0 for x in rates))
    if twist is not None and any(x != 0 for x in twist):
        if _draw_twist(ax, a, scene, twist):
            legend.append(Line2D([], [], color=OBJECT_MOTION_COLOR, linewidth=2,
                                 label="object velocity at the contacts"))
        if any(x != 0 for x in twist[3:]):
            legend.append(Line2D([], [], color=OBJECT_MOTION_COLOR, linestyle="--",
                                 label="object rotation axis"))
        else:
            legend.append(Line2D([], [], color=OBJECT_MOTION_COLOR, linewidth=3.5,
                                 label="object translation"))
    if rates is not None and any(x != 0 for x in rates):
        _draw_rates(ax, a, scene, rates)
        legend.append(Line2D([], [], color=JOINT_MOTION_COLOR, linewidth=2,
                             label="joint rates (ratios to the fastest)"))
    if vanish:
        words += " (zero at the drawn configuration)"
    return _wrap(words, 110)


def _joint_words(exact: Sequence[sp.Expr], rates: Sequence[sp.Rational], a: Analysis) -> str:
    """The joint motion in words; when those carry long integers (``p1_2: 507500``),
    the ratios to the fastest joint instead, as on the labels."""
    words = describe_joint_motion(exact, a)
    if not re.search(r"(?<![\d.])\d{5,}", words):
        return words
    ratios = rate_ratios(rates)
    listed = ", ".join(f"{j}: {ratio_text(r)}" for j, r in zip(a.model.joint_names, ratios,
                                                               strict=True) if r != 0)
    return f"joints in the ratio {listed} (the fastest at 1)"


def _wrap(text: str, width: int) -> str:
    return "\n".join(textwrap.wrap(text, width))


def _draw_twist(ax, a: Analysis, scene: _Scene, twist: list[sp.Rational]) -> bool:
    """The object's velocity at each contact (v + w x c), and its twist: a translation
    arrow, or the screw axis (dashed) with a circular arrow. True when some contact
    moves."""
    v = np.array([float(x) for x in twist[:3]])  # float-ok
    w = np.array([float(x) for x in twist[3:]])  # float-ok
    pts = np.array(scene.points)  # float-ok
    vel = np.array([v + np.cross(w, p) for p in pts])  # float-ok
    center = pts.mean(axis=0)  # float-ok
    top = max(np.max(np.linalg.norm(vel, axis=1)), np.linalg.norm(v + np.cross(w, center)))
    scale = 0.3 * scene.size / top if top > 0 else 0.0  # float-ok
    moving = False
    for c, p, u in zip(a.model.contacts, pts, vel, strict=True):
        if np.linalg.norm(u) * scale < 1e-6 * scene.size:  # float-ok: nothing to draw
            continue
        moving = True
        q = ax.quiver(*p, *(scale * u), color=OBJECT_MOTION_COLOR,  # float-ok
                      linewidth=2.2, arrow_length_ratio=0.22)
        q.set_gid(f"motion:velocity:{c.name}")
    if not any(x != 0 for x in twist[3:]):   # exact test: a pure translation
        q = ax.quiver(*center, *(scale * v), color=OBJECT_MOTION_COLOR,  # float-ok
                      linewidth=3.5, arrow_length_ratio=0.25)
        q.set_gid("motion:translation")
        return moving
    ww = float(w @ w)  # float-ok
    point = np.cross(w, v) / ww  # float-ok: the axis passes here
    d = w / np.sqrt(ww)  # float-ok
    foot = point + ((center - point) @ d) * d  # float-ok: axis point nearest the object
    axis = np.array(scene.clip(foot, d)).T  # float-ok
    (line,) = ax.plot(*axis, color=OBJECT_MOTION_COLOR, linestyle="--", linewidth=1.8)
    line.set_gid("motion:axis")
    e1, e2 = _perp_basis(d)
    phi = np.linspace(0.2, 1.75 * np.pi, 50)  # float-ok
    rad = 0.12 * scene.size  # float-ok
    hub = foot + 0.22 * scene.size * d  # float-ok: the circular arrow, off the joints
    arc = (hub[:, None] + rad * (np.outer(e1, np.cos(phi))  # float-ok
                                  + np.outer(e2, np.sin(phi))))  # float-ok
    (curl,) = ax.plot(*arc, color=OBJECT_MOTION_COLOR, linewidth=2, zorder=800)
    curl.set_gid("motion:spin")
    tangent = -np.sin(phi[-1]) * e1 + np.cos(phi[-1]) * e2  # float-ok
    head = ax.quiver(*arc[:, -1], *(0.06 * scene.size * tangent),  # float-ok
                     color=OBJECT_MOTION_COLOR, linewidth=2, arrow_length_ratio=1.0)
    head.set_gid("motion:spin-head")
    pitch = float(w @ v) / ww  # float-ok
    if abs(pitch) > 1e-12 * scene.size:  # float-ok: a screw, not a pure rotation
        q = ax.quiver(*foot, *(np.sign(pitch) * 0.25 * scene.size * d),  # float-ok
                      color=OBJECT_MOTION_COLOR, linewidth=3, arrow_length_ratio=0.25)
        q.set_gid("motion:screw-translation")
    return moving


def _draw_rates(ax, a: Analysis, scene: _Scene, rates: list[sp.Rational]) -> None:
    """Curved arrows about revolute joints, straight arrows along prismatic ones, and
    labels with the exact ratios of the rates (``rates`` at the drawing values) to
    the fastest one (see :func:`rate_labels`)."""
    top = max(abs(float(x)) for x in rates)  # float-ok
    anchors: dict[int, Any] = {}
    for index, (joint, rate) in enumerate(zip(a.model.joints, rates, strict=True)):
        if rate == 0:
            continue
        o = scene.joint_points[index]
        s = scene.axes[index] / np.linalg.norm(scene.axes[index])  # float-ok
        size = (0.35 + 0.65 * abs(float(rate)) / top) * scene.size  # float-ok
        sign = 1.0 if rate > 0 else -1.0  # float-ok
        if joint.type == "revolute":
            e1, e2 = _perp_basis(s)
            rad = 0.1 * size  # float-ok
            phi = sign * np.linspace(0.3, 1.6 * np.pi, 40)  # float-ok
            centre = o + 0.08 * scene.size * s  # float-ok
            arc = (centre[:, None] + rad * (np.outer(e1, np.cos(phi))  # float-ok
                                            + np.outer(e2, np.sin(phi))))  # float-ok
            (curl,) = ax.plot(*arc, color=JOINT_MOTION_COLOR, linewidth=2.2, zorder=800)
            curl.set_gid(f"motion:rate:{joint.name}")
            tangent = sign * (-np.sin(phi[-1]) * e1 + np.cos(phi[-1]) * e2)  # float-ok
            head = ax.quiver(*arc[:, -1], *(0.05 * scene.size * tangent),  # float-ok
                             color=JOINT_MOTION_COLOR, linewidth=2.2,
                             arrow_length_ratio=1.0)
            head.set_gid(f"motion:rate-head:{joint.name}")
            anchor = arc[:, -1]
        else:
            q = ax.quiver(*o, *(sign * 0.25 * size * s), color=JOINT_MOTION_COLOR,  # float-ok
                          linewidth=3, arrow_length_ratio=0.3)
            q.set_gid(f"motion:rate:{joint.name}")
            anchor = o + sign * 0.25 * size * s  # float-ok: the arrow's tip
        anchors[index] = anchor
    # one label per place (joints at one point share it), at the first arrow head
    places = [tuple(np.round(p / scene.size, 6)) for p in scene.joint_points]  # float-ok
    names = [j.name for j in a.model.joints]
    for index, text in rate_labels(names, rates, places):
        label = ax.text(*anchors[index], text, fontsize=8, color="black", zorder=1001,
                        transform=_shift(ax, 6, 6), ha="left",
                        bbox={"boxstyle": "round,pad=0.2", "facecolor": "white",
                              "alpha": 0.8, "edgecolor": JOINT_MOTION_COLOR})
        label.set_gid(f"rate-label:{names[index]}")


# ------------------------------------------------------------------ files


def save_picture(analysis_or_system: Any, path: str | os.PathLike, *,
                 at: str | Mapping | None = None, motion: str | Sequence | None = None,
                 title: str | None = None, dpi: int = 150, ellipsoid: bool = False) -> Path:
    """Draw (see :func:`draw_system`) and write the picture to ``path``.

    The format follows the suffix (``.png``, ``.pdf``, ``.svg``). The file is written
    only when the picture is complete (a temporary file, then renamed); nothing is
    written on an error.

    Example
    -------
    >>> import tempfile, pathlib
    >>> from coopkin_sym import load
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "case1.png"
    >>> save_picture(load("paper-case1-hard"), out, motion="coordinated:1").read_bytes()[:4]
    b'\\x89PNG'
    """
    target, suffix = check_output_path(path, SAVE_FORMATS, DrawError, "picture")
    fig = draw_system(analysis_or_system, at=at, motion=motion, title=title,
                      ellipsoid=ellipsoid)

    def save(tmp: str) -> None:
        fig.savefig(tmp, dpi=dpi, format=suffix[1:])

    write_files({target: save}, DrawError)
    return target
