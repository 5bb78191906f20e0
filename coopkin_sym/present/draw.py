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

``k`` counts from 1. The inputs (the motion asked for, the analysis) are read in
:mod:`~coopkin_sym.present.draw_inputs`, the scene (arms, joints, contacts, object,
ellipsoid) is drawn in :mod:`~coopkin_sym.present.draw_scene`, a motion in
:mod:`~coopkin_sym.present.draw_motion`; this module puts them together and re-exports
their public names. matplotlib is needed (``pip install matplotlib``); pictures are
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

import os
import warnings
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np  # float-ok: drawing coordinates

from coopkin_sym.analysis.mobility import Analysis
from coopkin_sym.errors import DrawError, OutputSkipped
from coopkin_sym.exact.bounded import report
from coopkin_sym.present.draw_inputs import (
    MOTION_KINDS,
    _analysis,
    _AtIrrational,
    gained_motion,
    motion_counts,
    parse_motion,
)
from coopkin_sym.present.draw_labels import check_labels, spread_labels
from coopkin_sym.present.draw_motion import (
    SMALL_FRACTION,
    _draw_motion,
    _wrap,
    rate_labels,
    rate_ratios,
    ratio_text,
)
from coopkin_sym.present.draw_scene import (
    ARM_COLORS,
    JOINT_MOTION_COLOR,
    OBJECT_MOTION_COLOR,
    SAVE_FORMATS,
    _draw_arms,
    _draw_contacts,
    _draw_ellipsoid,
    _draw_ground,
    _draw_object,
    _frame,
    _mpl,
    _Scene,
    _Values,
    contact_marker,
)
from coopkin_sym.present.files import check_output_path, write_files
from coopkin_sym.present.sentences import configuration_words

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure


__all__ = ["ARM_COLORS", "JOINT_MOTION_COLOR", "MOTION_KINDS", "OBJECT_MOTION_COLOR",
           "SAVE_FORMATS", "SMALL_FRACTION", "DrawError", "contact_marker", "draw_system",
           "gained_motion", "motion_counts", "parse_motion", "rate_labels", "rate_ratios",
           "ratio_text", "save_picture"]


# ------------------------------------------------------------------ drawing


def draw_system(analysis_or_system: Any, at: str | Mapping | None = None,
                motion: str | Sequence | None = None, ax: Axes | None = None,
                title: str | None = None, ellipsoid: bool = False,
                labels: bool | str = True) -> Figure:
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
    labels
        The name labels of joints and contacts (see
        :mod:`coopkin_sym.present.draw_labels`): ``True`` names, long ones shortened,
        ``"short"`` joint numbers in their arm, ``False`` none; labels are moved apart
        so that none covers another.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    DrawError
        A motion that does not exist, an ``ax`` that is not 3D, ``labels`` not one of
        the three, matplotlib missing.

    Example
    -------
    >>> from coopkin_sym import load
    >>> fig = draw_system(load("paper-case2-hard"), motion="indeterminate:1")
    >>> len([a for a in fig.axes[0].get_children()
    ...      if (a.get_gid() or "").startswith("contact:")])
    2
    """
    labels = check_labels(labels)
    report("the analysis")
    a = _analysis(analysis_or_system, at)
    request = parse_motion(motion, a)
    names = len(a.model.joints) + len(a.model.contacts)
    if labels and names > MAX_NAME_LABELS:
        warnings.warn(f"name labels left out: {names:,} names (joints and contacts) would "
                      f"cover the picture (at most {MAX_NAME_LABELS}; labels=False, "
                      "--labels none)", OutputSkipped, stacklevel=2)
        labels = False
    report("the picture")
    Figure, FigureCanvasAgg = _mpl()
    if ax is None:
        fig = Figure(figsize=(10.5, 7.5), layout="constrained")
        FigureCanvasAgg(fig)
        ax = fig.add_subplot(projection="3d")
    elif getattr(ax, "name", "") != "3d":
        raise DrawError("ax: a 3D axes is needed (add_subplot(projection='3d'))")
    fig = ax.figure
    try:
        return _draw_into(fig, ax, a, request, title, ellipsoid, labels)
    except (np.linalg.LinAlgError, OverflowError, FloatingPointError,
            ZeroDivisionError) as exc:
        raise DrawError(f"cannot draw this configuration ({type(exc).__name__}: "
                        f"{' '.join(str(exc).split())[:80]})") from None


def _draw_into(fig, ax, a: Analysis, request, title: str | None, ellipsoid: bool = False,
               labels: bool | str = True):
    values = _Values(a)
    scene = _Scene(a, values)
    legend: list = []
    _draw_ground(ax, a, scene, legend)
    _draw_object(ax, a, scene, legend)
    _draw_arms(ax, a, scene, legend, labels)
    _draw_contacts(ax, a, scene, legend, labels)
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
        where = a.short_at()
    else:
        where = configuration_words(a)
    n = a.numbers
    line = f"at {where}   Nm={n.Nm} Nc={n.Nc} Ni={n.Ni} Nr={n.Nr}"
    if len(line) > 110:   # a long configuration: broken after its commas
        line = _wrap(line.replace(",", ", "), 110)
    lines.append(line)
    note = values.note(a)
    if isinstance(a, _AtIrrational):
        rounded = " (shown rounded)" if a.rounded else ""
        exact = (f"{', '.join(f'tan({j}/2)' for j in a.tangents)} irrational{rounded}: "
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
    ax.legend(handles=_folded(unique), loc="upper left", bbox_to_anchor=(1.02, 1.0),
              fontsize=8, frameon=False)
    if labels:
        spread_labels(ax)
    return fig


#: The most name labels (joints and contacts) a picture is drawn with; past it the
#: names are left out (and a note says so): they would cover it.
MAX_NAME_LABELS = 200
#: The most arms the legend names one by one; the others are one entry.
LEGEND_ARMS = 12


def _folded(handles: list) -> list:
    """The legend entries with the arms past :data:`LEGEND_ARMS` folded into one
    (their colours repeat those named): a legend of 200 arms would not fit the figure."""
    arms = [h for h in handles if h.get_gid() == "legend:arm"]
    if len(arms) <= LEGEND_ARMS:
        return handles
    from matplotlib.lines import Line2D

    shown = arms[:LEGEND_ARMS - 1]
    rest = len(arms) - len(shown)
    more = Line2D([], [], color="0.55", linewidth=3,
                  label=f"{rest} more arms")
    out = []
    for h in handles:
        if h.get_gid() != "legend:arm" or h in shown:
            out.append(h)
            if h is shown[-1]:
                out.append(more)
    return out


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


# ------------------------------------------------------------------ files


def save_picture(analysis_or_system: Any, path: str | os.PathLike, *,
                 at: str | Mapping | None = None, motion: str | Sequence | None = None,
                 title: str | None = None, dpi: int = 150, ellipsoid: bool = False,
                 labels: bool | str = True) -> Path:
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
                      ellipsoid=ellipsoid, labels=labels)
    report("writing the picture")

    def save(tmp: str) -> None:
        fig.savefig(tmp, dpi=dpi, format=suffix[1:])

    write_files({target: save}, DrawError)
    return target
