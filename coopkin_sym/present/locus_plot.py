"""Pictures of a singularity locus on a pair of joint variables.

Each real component of a :class:`~coopkin_sym.analysis.locus.types.Locus` whose equations
involve the two chosen joints is drawn in the plane of those joints, from its exact
polynomials:

* the other joint variables are set to the component's witness (home, q = 0, when it
  has none) and parameters to the witness, to the values fixed in the locus, or else
  to 1 (the title says which);
* what is left is a set of polynomials in ``x = t_i`` and ``y = t_j``; their gcd ``g``
  is a curve, drawn as the zero contour of the bounded trigonometric polynomial
  ``g(tan(a/2), tan(b/2)) cos(a/2)^deg_x cos(b/2)^deg_y`` on a fine grid over
  ``a, b`` in ``[-pi, pi]`` (so q = pi, where t is infinite, is drawn too);
* the common zeros of the rest (finitely many, two variables with gcd 1) are marked
  as points, and so are the witnesses.

A prismatic joint is drawn over ``[-2, 2]`` (lengths at their drawing values).
Everything here is drawing: floats appear only after the exact substitution, and each
such line is marked ``# float-ok``. No singularity is decided here.

Example
-------
>>> from coopkin_sym.analysis.locus.types import Component, Locus
>>> generic = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
>>> here = dict(generic, Nm=3, Nc=3, Nh=1)
>>> locus = Locus("demo", ["t_q1", "t_q2", "L"], "", generic, [
...     Component(["t_q1 + 1", "t_q2 + 1"], here, {"q1": "-pi/2", "q2": "-pi/2"}, True,
...               kind="isolated", condition="q1 = q2 = -pi/2")])
>>> fig = plot_components(locus, None)
>>> sorted(a.get_gid() for a in fig.axes[0].get_children()
...        if (a.get_gid() or "").startswith("component:"))
['component:1']
"""

from __future__ import annotations

import functools
import io
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np  # float-ok: plotting grids only
import sympy as sp

from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.errors import PlotError
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.parse import NumberError, parse_angle, parse_number
from coopkin_sym.present.conditions import PolynomialNames, report_names, short_condition
from coopkin_sym.present.family_words import changes_text, family_name
from coopkin_sym.present.plot_legend import (
    LABEL_LINES,
    LABEL_WIDTH,
    OVERFLOW_STYLE,
    TITLE_WIDTH,
    _height,
    _legend,
    _wrapped,
    style,
)
from coopkin_sym.present.plot_plane import INFINITY, _Axis, _in_plane

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["PlotError", "components_on", "default_pairs", "free_joints", "plot_components",
           "plot_png"]

#: Grid points per axis for the zero contours.
GRID = 721
#: Range drawn for a prismatic joint (lengths at their drawing values).
PRISMATIC_RANGE = (-2.0, 2.0)  # float-ok: plotting range
#: Margin drawn beyond q = -pi and q = pi (radians).
MARGIN = 0.2  # float-ok: plotting range


@functools.cache
def _mpl():
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
        from matplotlib.lines import Line2D
    except ImportError:  # pragma: no cover - depends on the installation
        raise PlotError("plots need matplotlib: pip install matplotlib") from None
    return Figure, FigureCanvasAgg, Line2D


# ------------------------------------------------------------------ variables

# The variable of a revolute joint X is t_X = tan(X/2), or s_X = cot(X/2) in the second
# chart (s_X = 0 is X = pi); a prismatic joint's variable is its name.
CHARTS = ("t", "s")


@dataclass
class _Kinds:
    """Which variable belongs to which joint, and which variables are parameters."""

    joints: dict[str, str] = field(default_factory=dict)      # joint -> revolute|prismatic
    parameters: list[str] = field(default_factory=list)

    def variables(self, joint: str) -> list[str]:
        if self.joints[joint] == "revolute":
            return [f"{c}_{joint}" for c in CHARTS]
        return [joint]

    def joint_of(self, variable: str) -> tuple[str | None, str]:
        """The joint of a variable and its chart (``t``, ``s``, or ``d`` for a
        prismatic displacement); ``(None, "")`` for a parameter."""
        if variable in self.joints and self.joints[variable] == "prismatic":
            return variable, "d"
        head, sep, joint = variable.partition("_")
        if sep and head in CHARTS and self.joints.get(joint) == "revolute":
            return joint, head
        return None, ""


def _kinds(locus: Locus, system: Any) -> _Kinds:
    """Joint kinds from the system when given, else from the variable names (``t_X``
    is revolute joint X; other names are taken for parameters)."""
    out = _Kinds()
    if system is not None:
        model = getattr(system, "model", system)
        for j in model.joints:
            out.joints[j.name] = j.type
        out.parameters = [p.name for p in model.parameters]
        return out
    for v in locus.variables:
        if v.startswith("t_"):
            out.joints[v[2:]] = "revolute"
        else:
            out.parameters.append(v)
    return out


def _names(locus: Locus, kinds: _Kinds) -> tuple[str, ...]:
    extra = [v for j in kinds.joints for v in kinds.variables(j)] + kinds.parameters
    return tuple(dict.fromkeys([*locus.variables, *extra]))


def _free(c: Component, names: tuple[str, ...]) -> set[str]:
    """The variables the component's equations use."""
    try:
        return {v for p in c.equation_polynomials(names) for v in p.variables}
    except NumberError as exc:
        raise PlotError(str(exc)) from None


def _joints_in(c: Component, kinds: _Kinds, names: tuple[str, ...]) -> dict[str, str]:
    """Joint -> the variable of it that ``c``'s equations use."""
    out: dict[str, str] = {}
    for v in sorted(_free(c, names)):
        joint, _ = kinds.joint_of(v)
        if joint is not None:
            out.setdefault(joint, v)
    return out


def components_on(locus: Locus, system: Any, pair: Sequence[str]) -> list[int]:
    """Indices (from 0) of the real components whose equations involve either joint
    of ``pair``: the ones :func:`plot_components` draws.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Component, Locus
    >>> c = Component(["t_q2"], {}, {"q2": "0"}, True)
    >>> components_on(Locus("demo", ["t_q1", "t_q2"], "", {}, [c]), None, ("q1", "q2"))
    [0]
    """
    kinds = _kinds(locus, system)
    _check_pair(kinds, pair, locus)
    names = _names(locus, kinds)
    return [k for k, c in enumerate(locus.components)
            if c.real and set(_joints_in(c, kinds, names)) & set(pair)]


def _free_joints(locus: Locus, kinds: _Kinds) -> list[str]:
    free = set(locus.variables)
    return [j for j in kinds.joints if free.intersection(kinds.variables(j))]


def free_joints(locus: Locus, system: Any) -> list[str]:
    """The joints free in ``locus`` (a variable of theirs is one of its variables), in
    the system's order: the only ones a plot takes as axes.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> free_joints(Locus("demo", ["t_q2", "t_q3", "L"], "q1=0", {}), None)
    ['q2', 'q3']
    """
    return _free_joints(locus, _kinds(locus, system))


def _check_pair(kinds: _Kinds, pair: Sequence[str], locus: Locus | None = None) -> None:
    if len(pair) != 2:
        raise PlotError(f"pair: expected two joints, got {list(pair)!r}")
    for j in pair:
        if j not in kinds.joints:
            known = ", ".join(kinds.joints) or "none"
            raise PlotError(f"pair: unknown joint {j!r} (joints: {known})")
    if pair[0] == pair[1]:
        raise PlotError(f"pair: the two joints must differ, got {pair[0]!r} twice")
    free = _free_joints(locus, kinds) if locus is not None else list(kinds.joints)
    for j in pair:
        if j not in free:
            raise PlotError(f"pair ({pair[0]}, {pair[1]}): joint {j!r} is fixed in this "
                            f"locus, not an axis (free joints: {', '.join(free) or 'none'})")


def default_pairs(locus: Locus, system: Any, limit: int = 6) -> list[tuple[str, str]]:
    """The pairs of free joints worth plotting (:func:`free_joints`; a fixed joint is
    never an axis): those that appear together in the equations of a real component
    (most often first), then pairs for joints that appear alone.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Component, Locus
    >>> c = Component(["t_q1 - t_q2"], {}, None, True)
    >>> default_pairs(Locus("demo", ["t_q1", "t_q2", "t_q3"], "", {}, [c]), None)
    [('q1', 'q2')]
    """
    kinds = _kinds(locus, system)
    names = _names(locus, kinds)
    order = _free_joints(locus, kinds)
    counts: dict[tuple[str, str], int] = {}
    alone: list[str] = []
    for c in locus.components:
        if not c.real:
            continue
        joints = sorted((j for j in _joints_in(c, kinds, names) if j in order),
                        key=order.index)
        for a in range(len(joints)):
            for b in range(a + 1, len(joints)):
                key = (joints[a], joints[b])
                counts[key] = counts.get(key, 0) + 1
        if len(joints) == 1:
            alone.append(joints[0])
    pairs = sorted(counts, key=lambda p: (-counts[p], order.index(p[0]), order.index(p[1])))
    covered = {j for p in pairs for j in p}
    for j in dict.fromkeys(alone):
        if j in covered:
            continue
        other = next((o for o in order if o != j), None)
        if other is not None:
            pair = tuple(sorted((j, other), key=order.index))
            if pair not in pairs:
                pairs.append(pair)
            covered.update(pair)
    return pairs[:limit]


# ------------------------------------------------------------------ exact slices


def _chart_value(chart: str, cos: sp.Rational, sin: sp.Rational) -> sp.Rational | str:
    """tan(q/2) or cot(q/2) from exact (cos q, sin q); INFINITY where it has none."""
    if chart == "t":
        return INFINITY if cos == -1 else sp.Rational(sin / (1 + cos))
    return INFINITY if cos == 1 else sp.Rational(sin / (1 - cos))


def _value(kinds: _Kinds, name: str, text: str, params: dict) -> sp.Expr | str:
    """The exact value of variable ``name`` given in ``--at`` syntax, or INFINITY."""
    joint, chart = kinds.joint_of(name)
    if chart in CHARTS:
        cos, sin = parse_angle(text, f"{joint}={text}")
        return _chart_value(chart, cos, sin)
    return parse_number(text, params, f"{name}={text}")


def _fixed(locus: Locus) -> dict[str, str]:
    out = {}
    for part in (locus.fixed or "").split(","):
        name, sep, value = part.partition("=")
        if sep and name.strip().isidentifier():
            out[name.strip()] = value.strip()
    return out


def _slice(locus: Locus, kinds: _Kinds, c: Component, keep: set[str],
           names: tuple[str, ...]) -> tuple[dict[str, Any], list[str]]:
    """Exact values for every variable of ``c``'s equations but ``keep``; notes on
    the values that were chosen rather than given by the witness."""
    witness = dict(c.witness or {})
    fixed = _fixed(locus)
    params = {p: sp.Symbol(p, positive=True) for p in kinds.parameters}
    values: dict[str, Any] = {}
    notes: list[str] = []
    for name in sorted(_free(c, names)):
        if name in keep:
            continue
        joint, _ = kinds.joint_of(name)
        key = joint if joint is not None else name
        text = witness.get(key, fixed.get(key))
        if text is None:
            if joint is not None:
                values[name] = _value(kinds, name, "0", params)
                notes.append(f"{joint} at home (0)")
            else:
                values[name] = sp.Integer(1)
                notes.append(f"parameter {name}")
            continue
        try:
            values[name] = _value(kinds, name, str(text), params)
        except NumberError as exc:
            raise PlotError(f"component witness {key}={text}: {exc}") from None
    return values, notes


# ------------------------------------------------------------------ floats


def _half(grid, chart: str):  # float-ok: plotting values
    """(numerator, denominator) of the variable on a grid: tan(a/2) = sin/cos,
    cot(a/2) = cos/sin, a displacement = d/1."""
    if chart == "t":
        return np.sin(grid / 2), np.cos(grid / 2)  # float-ok
    if chart == "s":
        return np.cos(grid / 2), np.sin(grid / 2)  # float-ok
    return grid, np.ones_like(grid)  # float-ok


def _trig(poly: sp.Poly, a, b, charts: tuple[str, str]):  # float-ok: plotting values
    """``poly(x, y)`` times the denominators to the degrees of ``poly``: for t charts
    ``poly(tan(a/2), tan(b/2)) cos(a/2)^dx cos(b/2)^dy``, bounded for every angle."""
    dx, dy = poly.degree(0), poly.degree(1)
    na, da = _half(a, charts[0])
    nb, db = _half(b, charts[1])
    out = np.zeros_like(a)  # float-ok
    for (i, j), coeff in zip(poly.monoms(), poly.coeffs(), strict=True):
        out += float(coeff) * na**i * da**(dx - i) * nb**j * db**(dy - j)  # float-ok
    return out


def _axis_range(revolute: bool) -> tuple[float, float]:  # float-ok
    """Drawn range: a revolute joint over [-pi, pi] plus a margin (so that curves
    through q = pi, the same as -pi, show on the frame's inside)."""
    if revolute:
        return (-math.pi - MARGIN, math.pi + MARGIN)  # float-ok
    return PRISMATIC_RANGE


def _pi_ticks(axis) -> None:
    ticks = [-math.pi, -math.pi / 2, 0.0, math.pi / 2, math.pi]  # float-ok
    axis.set_ticks(ticks)
    axis.set_ticklabels(["\u2212\u03c0", "\u2212\u03c0/2", "0", "\u03c0/2", "\u03c0"])


def _both_edges(marks: list, rev: tuple[bool, bool]) -> list:  # float-ok: plotting
    """Points at q = pi also drawn at q = -pi (the same angle), and the reverse."""
    out = list(marks)
    for a, b in marks:
        for k, value in enumerate((a, b)):
            if rev[k] and abs(abs(value) - math.pi) < 1e-12:  # float-ok: the edge
                moved = [a, b]
                moved[k] = -value
                out.append(tuple(moved))
    return list(dict.fromkeys(out))


def _ring_size(placed: dict, marks: list) -> float:  # float-ok: marker sizes
    """A marker size that leaves the discs already drawn at these places visible."""
    keys = [(round(a, 6), round(b, 6)) for a, b in marks]  # float-ok
    count = max((placed.get(key, 0) for key in keys), default=0)
    for key in keys:
        placed[key] = placed.get(key, 0) + 1
    return max(17.0 - 5.0 * count, 6.0)  # float-ok


def _label(k: int, c: Component, width: int = LABEL_WIDTH,
           names: PolynomialNames | None = None) -> str:
    """The legend entry of component ``k`` (from 0): its number and condition (long
    polynomials by their ``names`` in the report), wrapped.

    Example
    -------
    >>> c = Component(["t_q1"], {}, None, True, condition="q1 = 0")
    >>> _label(0, c)
    '#1: q1 = 0'
    """
    return _wrapped(f"#{k + 1}: {short_condition(c, names)}", width, LABEL_LINES)


def _witness_xy(c: Component, pair: Sequence[str], kinds: _Kinds
                ) -> tuple[float, float] | None:  # float-ok
    if not c.witness and c.algebraic_witness:
        approx = c.algebraic_witness.get("approx", {})
        if all(j in approx for j in pair):
            return float(approx[pair[0]]), float(approx[pair[1]])  # float-ok: display
        return None
    if not c.witness or any(j not in c.witness for j in pair):
        return None
    out = []
    for j in pair:
        text = str(c.witness[j])
        try:
            if kinds.joints[j] == "revolute":
                out.append(ExactAngle.parse(text, f"{j}={text}").radians())  # float-ok
            else:
                out.append(float(parse_number(text, {}, f"{j}={text}")))  # float-ok
        except (NumberError, TypeError):
            return None
    return out[0], out[1]


#: With more components than this in a plane (and fewer families), ``by="auto"``
#: colours them by family.
FAMILY_COLOURS_FROM = 12


def plot_components(locus: Locus, system: Any, pair: Sequence[str] = ("q1", "q2"),
                    ax: Axes | None = None, by: str = "auto") -> Figure:
    """Draw the real components of ``locus`` that involve the joints ``pair``.

    Parameters
    ----------
    locus
        The locus (see :func:`coopkin_sym.analysis.locus.search.compute_locus`).
    system
        The system (for joint kinds and parameter names), or ``None``: then ``t_X``
        variables are revolute joints and other variables parameters.
    pair
        Two joint names: the horizontal and the vertical axis.
    ax
        Axes to draw on (a new figure when ``None``).
    by
        ``"component"``: a colour and marker per component, each in the legend;
        ``"family"``: one per family (:meth:`Locus.families
        <coopkin_sym.analysis.locus.facade.LocusMethods.families>`), the legend saying
        what changes; ``"auto"``: by family when more than
        :data:`FAMILY_COLOURS_FROM` components are drawn and they fall into fewer
        families.

    Returns
    -------
    matplotlib.figure.Figure
        Each drawn component is one artist with gid ``component:K`` (K from 1: a zero
        contour, or a line of markers for points); witnesses have gid ``witness:K``.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Component, Locus
    >>> c = Component(["t_q1 - t_q2"], {}, {"q1": "0", "q2": "0"}, True, condition="q1 = q2")
    >>> fig = plot_components(Locus("demo", ["t_q1", "t_q2"], "", {}, [c]), None)
    >>> fig.axes[0].get_xlabel()
    'q1 (rad)'
    """
    Figure, FigureCanvasAgg, Line2D = _mpl()
    kinds = _kinds(locus, system)
    _check_pair(kinds, pair, locus)
    names = _names(locus, kinds)
    own = ax is None
    if own:
        fig = Figure(figsize=(WIDTH, WIDTH), layout="constrained")  # float-ok: inches
        FigureCanvasAgg(fig)
        ax = fig.add_subplot()
    else:
        fig = ax.figure
    rev = (kinds.joints[pair[0]] == "revolute", kinds.joints[pair[1]] == "revolute")
    lo_a, hi_a = _axis_range(rev[0])
    lo_b, hi_b = _axis_range(rev[1])
    grid_a = np.linspace(lo_a, hi_a, GRID)  # float-ok
    grid_b = np.linspace(lo_b, hi_b, GRID)  # float-ok
    A, B = np.meshgrid(grid_a, grid_b)  # float-ok
    plane = _Plane(ax, locus, kinds, names, tuple(pair), rev, A, B, Line2D,
                   report_names(locus.components))
    drawn = components_on(locus, system, pair)
    plane.family_of = _family_styles(locus, drawn, by)
    for n, k in enumerate(drawn):
        _draw_component(plane, n, k)
    rows = 0.0  # float-ok: lines of the legend
    if plane.handles or plane.unlisted:
        rows = _legend(fig, ax, plane.handles, Line2D, own, plane.unlisted)
    else:
        ax.text(0.5, 0.5, "no real component involves these joints", ha="center",  # float-ok
                va="center", transform=ax.transAxes, color="0.4")
    _finish_axes(ax, pair, rev, ((lo_a, hi_a), (lo_b, hi_b)), own)
    title = _title(locus, pair, sorted(plane.notes), plane.has_others)
    # a fixed place (y given): the layout knows where a title of several lines ends
    ax.set_title(title, fontsize=10, y=1.0)  # float-ok: axes coordinates
    if own:
        fig.set_size_inches(WIDTH, _height(title, rows))
    return fig


@dataclass
class _Plane:
    """What drawing the components in the plane of a pair of joints shares: the axes,
    the grid of the contours, and what the components drawn so far left (legend
    entries, markers placed, notes on the values chosen for the other variables)."""

    ax: Any
    locus: Locus
    kinds: _Kinds
    names: tuple[str, ...]
    pair: tuple[str, ...]
    rev: tuple[bool, bool]
    A: Any
    B: Any
    Line2D: Any
    polynomials: PolynomialNames = field(default_factory=PolynomialNames)
    handles: list = field(default_factory=list)
    unlisted: int = 0
    placed: dict[tuple[float, float], int] = field(default_factory=dict)  # float-ok
    notes: set[str] = field(default_factory=set)
    has_others: bool = False
    #: component -> (its family's index, the legend entry of the family), when the
    #: components are coloured by family
    family_of: dict[int, tuple[int, str]] = field(default_factory=dict)
    families_listed: set[int] = field(default_factory=set)


def _family_styles(locus: Locus, drawn: Sequence[int], by: str
                   ) -> dict[int, tuple[int, str]]:
    """For each component of ``drawn``, its family's index and legend entry, when the
    plot colours by family (see :func:`plot_components`); else nothing."""
    if by not in ("auto", "component", "family"):
        raise PlotError(f"by: {by!r} is not one of 'auto', 'component', 'family'")
    if by == "component":
        return {}
    families = locus.families()
    of = {k: i for i, f in enumerate(families) for k in f.members}
    if by == "auto" and (len(drawn) <= FAMILY_COLOURS_FROM
                         or len({of[k] for k in drawn}) >= len(drawn)):
        return {}
    entries = {}
    for i, f in enumerate(families):
        count = f"{len(f.members)} component{'' if len(f.members) == 1 else 's'}"
        entries[i] = f"{family_name(i)}: {changes_text(f)} ({count}; e.g. #{f.example + 1})"
    return {k: (of[k], entries[of[k]]) for k in drawn}


def _draw_component(plane: _Plane, n: int, k: int) -> None:
    """Draw component ``k`` (the ``n``-th drawn) of the locus: its zero contour, else
    its points (concentric discs where several components meet), and its witness."""
    ax, kinds, names, pair, rev, Line2D = (plane.ax, plane.kinds, plane.names, plane.pair,
                                           plane.rev, plane.Line2D)
    c = plane.locus.components[k]
    family, family_label = plane.family_of.get(k, (None, ""))
    color, marker = style(n if family is None else family)
    listed = (color, marker) != OVERFLOW_STYLE
    if family is not None:   # one legend entry per family, at its first member drawn
        listed = listed and family not in plane.families_listed
        plane.families_listed.add(family)
    plane.unlisted += (color, marker) == OVERFLOW_STYLE
    gid = f"component:{k + 1}"
    used = _joints_in(c, kinds, names)
    axes = []
    for j in pair:
        v = used.get(j) or kinds.variables(j)[0]
        axes.append(_Axis(j, v, kinds.joint_of(v)[1]))
    values, chosen = _slice(plane.locus, kinds, c, {a.variable for a in axes}, names)
    plane.notes.update(chosen)
    plane.has_others = plane.has_others or any(kinds.joint_of(v)[0] for v in values)
    drawn = _in_plane(c, values, axes[0], axes[1], names)
    label = family_label or (_label(k, c, names=plane.polynomials)
                             + (" (the whole plane)" if drawn.whole else ""))
    marks = list(drawn.points)
    drawn_curve = False
    if drawn.curve is not None:
        F = _trig(drawn.curve, plane.A, plane.B, (axes[0].chart, axes[1].chart))
        if np.any(F > 0) and np.any(F < 0):  # float-ok: a contour exists
            cs = ax.contour(plane.A, plane.B, F, levels=[0.0], colors=[color],  # float-ok
                            linewidths=2.0)  # float-ok
            cs.set_gid(gid)
            drawn_curve = True
            _mark_curve(ax, cs, color, marker, f"marks:{k + 1}")
            if listed:
                plane.handles.append(Line2D([], [], color=color, lw=2.0,  # float-ok
                                            marker=marker, markeredgecolor="black",
                                            label=label))
    where = _witness_xy(c, pair, kinds)
    if not drawn_curve and not marks and where is not None:
        marks = [where]   # the witness is the only point we can place
    marks = _both_edges(marks, rev)
    if not drawn_curve:
        # points of several components at one place: concentric discs
        size = _ring_size(plane.placed, marks)
        xs, ys = zip(*marks, strict=True) if marks else ((), ())
        ax.plot(xs, ys, linestyle="none", marker=marker, markersize=size, color=color,
                markeredgecolor="black", gid=gid, zorder=3 + n / 100)  # float-ok
        if listed:
            plane.handles.append(Line2D([], [], linestyle="none", marker=marker,
                                        markersize=11, color=color, markeredgecolor="black",
                                        label=label))
    elif marks:
        xs, ys = zip(*marks, strict=True)
        ax.plot(xs, ys, linestyle="none", marker=marker, markersize=7, color=color,
                markeredgecolor="black", gid=f"points:{k + 1}", zorder=3)
    if where is not None:
        ax.plot([where[0]], [where[1]], linestyle="none", marker="*", markersize=10,
                color="white", markeredgecolor="black", gid=f"witness:{k + 1}",
                zorder=4)


def _mark_curve(ax: Axes, contour: Any, color: str, marker: str, gid: str) -> None:
    """The component's marker at a few places along its drawn curve (its legend entry
    shows the same colour and marker)."""
    points = [p.vertices for p in contour.get_paths() if len(p.vertices)]
    if not points:
        return
    xy = np.concatenate(points)  # float-ok: plotting
    at = np.linspace(0, len(xy) - 1, min(len(xy), 6)).astype(int)  # float-ok
    ax.plot(xy[at, 0], xy[at, 1], linestyle="none", marker=marker, markersize=6,
            color=color, markeredgecolor="black", gid=gid, zorder=3)  # float-ok


def _finish_axes(ax: Axes, pair: Sequence[str], rev: tuple[bool, bool],
                 ranges: tuple[tuple[float, float], tuple[float, float]],  # float-ok
                 own: bool) -> None:
    """Limits, ticks (multiples of pi on a revolute joint, whose edges -pi and pi are
    one), labels and grid."""
    ax.set_xlim(*ranges[0])
    ax.set_ylim(*ranges[1])
    if rev[0] == rev[1] and not own:
        ax.set_aspect("equal")
    # on a figure of our own the height is chosen for a nearly square axes: a fixed
    # aspect there would let constrained layout give the title too little room
    for axis, joint, r in ((ax.xaxis, pair[0], rev[0]), (ax.yaxis, pair[1], rev[1])):
        if r:
            _pi_ticks(axis)
            line = ax.axvline if axis is ax.xaxis else ax.axhline
            for edge in (-math.pi, math.pi):  # float-ok: q = -pi and q = pi are one
                line(edge, color="0.55", linestyle=":", linewidth=1.0, zorder=1)  # float-ok
        axis.set_label_text(f"{joint} (rad)" if r else f"{joint} (length)")
    ax.grid(True, color="0.9", linewidth=0.8)  # float-ok
    ax.axhline(0, color="0.75", linewidth=0.8, zorder=0)  # float-ok
    ax.axvline(0, color="0.75", linewidth=0.8, zorder=0)  # float-ok


#: Width of a plot (inches); its height grows with the title and the legend.
WIDTH = 7.0  # float-ok: inches
def _title(locus: Locus, pair: Sequence[str], notes: list[str], others: bool) -> str:
    lines = [f"{locus.system}: singular configurations in the ({pair[0]}, {pair[1]}) plane"]
    said = []
    if locus.fixed:
        said.append(f"at {locus.fixed}")
    params = sorted({n.split()[1] for n in notes if n.startswith("parameter ")})
    if params:
        said.append(", ".join(params) + " symbolic, drawn at 1")
    if others:
        said.append("other joints at each component's witness")
    homes = sorted({n.split()[0] for n in notes if "home" in n})
    if homes:
        said.append(f"{', '.join(homes)} at home (0)")
    if said:
        lines.append("; ".join(said))
    return "\n".join(_wrapped(line, TITLE_WIDTH) for line in lines)


def plot_png(locus: Locus, system: Any, pair: Sequence[str] = ("q1", "q2"),
             dpi: int = 110, by: str = "auto") -> bytes:
    """:func:`plot_components` as PNG bytes.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> plot_png(Locus("demo", ["t_q1", "t_q2"], "", {}), None)[:4]
    b'\\x89PNG'
    """
    fig = plot_components(locus, system, pair, by=by)
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=dpi)
    return buffer.getvalue()
