"""The scene of a picture, in floats (each such line is marked ``# float-ok``): the
exact geometry of an analysis evaluated at rational values (:class:`_Values`,
:class:`_Scene`), then the frame, the ground, the object, the arms with their joints,
the contacts (each model's marker and words from the registry,
:mod:`coopkin_sym.model.contacts`) and the manipulability ellipsoid. No rank,
nullspace or singularity is decided here.

Example
-------
>>> contact_marker("complete")
's'
"""

from __future__ import annotations

import functools
import io
import itertools
from collections.abc import Sequence

import flint
import numpy as np  # float-ok: drawing coordinates
import sympy as sp

from coopkin_sym import limits
from coopkin_sym.analysis.mobility import Analysis
from coopkin_sym.errors import DrawError
from coopkin_sym.exact.angles import tangent_name
from coopkin_sym.exact.ratfunc import RatFunc
from coopkin_sym.exact.sympy_bridge import rational_to_sympy
from coopkin_sym.model.contacts import contact_kind
from coopkin_sym.present.draw_inputs import _AtIrrational
from coopkin_sym.present.draw_labels import arm_prefix, contact_label, joint_label
from coopkin_sym.present.sentences import contact_phrase

ARM_COLORS = ("tab:blue", "tab:green", "tab:purple", "tab:brown", "tab:olive", "tab:cyan",
              "tab:pink", "tab:gray")
OBJECT_MOTION_COLOR = "crimson"
JOINT_MOTION_COLOR = "darkorange"
SAVE_FORMATS = (".png", ".pdf", ".svg")
_LABEL_BOX = {"boxstyle": "round,pad=0.15", "facecolor": "white", "alpha": 0.7,
              "edgecolor": "none"}


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

    def exact(self, f: RatFunc) -> sp.Rational:
        """A :class:`~coopkin_sym.exact.ratfunc.RatFunc` of the kinematics (over the
        known factors of its ring) at the drawing values, exactly."""
        num = f.num(*self.fmpq)
        den = f.ring.den_poly(f.powers)(*self.fmpq)
        return rational_to_sympy(num / den)

    def vec(self, v: Sequence[RatFunc] | None) -> list[float] | None:
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


def _draw_arms(ax, a: Analysis, scene: _Scene, legend: list,
               labels: bool | str = True) -> None:
    from matplotlib.lines import Line2D

    model = a.model
    arrow = 0.16 * scene.size  # float-ok
    kinds = set()
    at_point: dict[tuple, list] = {}    # joints at one point: one label
    for i, arm in enumerate(model.arms):
        color = ARM_COLORS[i % len(ARM_COLORS)]
        legend.append(Line2D([], [], color=color, linewidth=3, label=f"arm {arm.name}",
                             gid="legend:arm"))
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
            prefix = arm_prefix([j.name for j in arm.joints])
            at_point.setdefault(key, [o, color, [], [], prefix])[2].append(joint.name)
            at_point[key][3].append(k + 1)
    for o, color, names, numbers, prefix in at_point.values() if labels else ():
        text = ax.text(*o, joint_label(names, numbers, labels, prefix), fontsize=8,
                       color=color,
                       fontweight="bold", transform=_shift(ax, 7, -12), zorder=1000,
                       bbox=_LABEL_BOX)
        text.set_gid("label:joint:" + ",".join(names))
    if "revolute" in kinds:
        legend.append(Line2D([], [], color="0.2", marker="o", markerfacecolor="white",
                             label="revolute joint (axis)"))
    if "prismatic" in kinds:
        legend.append(Line2D([], [], color="0.2", linestyle="--", marker="s",
                             markerfacecolor="white", label="prismatic joint (axis)"))


def _draw_contacts(ax, a: Analysis, scene: _Scene, legend: list,
                   labels: bool | str = True) -> None:
    from matplotlib.lines import Line2D

    seen = set()
    normal_len = 0.2 * scene.size  # float-ok
    for c, p, n in zip(a.model.contacts, scene.points, scene.normals, strict=True):
        marker = contact_marker(c.model)
        (dot,) = ax.plot([p[0]], [p[1]], [p[2]], linestyle="none", marker=marker,  # float-ok
                         markersize=10, markerfacecolor="gold", markeredgecolor="black",
                         zorder=900)
        dot.set_gid(f"contact:{c.name}")
        if labels:
            text = ax.text(*p, contact_label(c.name, labels), fontsize=9,
                           fontweight="bold", color="black", transform=_shift(ax, 7, 8),
                           ha="left", zorder=1000, bbox=_LABEL_BOX)
            text.set_gid(f"label:contact:{c.name}")
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

