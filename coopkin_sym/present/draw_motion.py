"""One motion in a picture, in floats (``# float-ok``): the object's twist (an arrow,
or a screw axis with a circular arrow), the velocities at the contacts and the joint
rates (curved or straight arrows, labelled with the exact ratios of the rates).

Example
-------
>>> from sympy import Rational
>>> [ratio_text(r) for r in rate_ratios([Rational(2), Rational(-1)])]
['1', '-1/2']
"""

from __future__ import annotations

import re
import textwrap
from collections.abc import Sequence
from typing import Any

import numpy as np  # float-ok: drawing coordinates
import sympy as sp

from coopkin_sym.analysis.kinematics import spatial_twist
from coopkin_sym.analysis.mobility import Analysis
from coopkin_sym.present.draw_scene import (
    JOINT_MOTION_COLOR,
    OBJECT_MOTION_COLOR,
    _perp_basis,
    _Scene,
    _shift,
    _Values,
)
from coopkin_sym.present.sentences import describe_joint_motion, describe_twist

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

