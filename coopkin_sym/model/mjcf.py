"""The kinematic subset of MJCF (MuJoCo's XML), read exactly.

An MJCF file nests ``<body>`` elements in ``<worldbody>``: each is placed in its parent
by ``pos`` and an orientation (``quat``, ``axisangle``, ``euler`` or none) and moved by
the ``<joint>`` elements it holds (``hinge``: revolute about ``axis`` through ``pos``,
in the body's frame; ``slide``: prismatic along ``axis``), applied in order. This module
reads the chain of one arm from the top body above ``tip`` (the only leaf when the tree
does not branch) down to ``tip``, and the ``<site>`` elements of its bodies (points a
contact can name). ``<default>`` classes (``class``, ``childclass``, nested defaults)
and ``<compiler angle eulerseq>`` are honoured; MJCF measures angles in degrees unless
``angle="radian"``.

Numbers are read exactly as the decimals they are and snapped as URDF ones are
(:mod:`coopkin_sym.model.urdf`): an orientation to a rotation by an exact angle about
an exact rational axis, an axis to an exact rational unit vector, each snap within the
bound and recorded. Ball and free joints on the chain are refused with the reason;
off the chain they are ignored and listed. ``<include>`` (another file) is refused.
The file is parsed by ``defusedxml`` within the budgets of :mod:`coopkin_sym.limits`.

Example
-------
>>> text = '''<mujoco><compiler angle="radian"/><worldbody>
...   <body name="upper" pos="0 0 0.5"><joint name="q1" axis="0 0 1"/>
...     <body name="lower" pos="1 0 0" euler="0 0 1.5707963"><joint name="q2"/>
...       <site name="tip" pos="0.5 0 0"/></body></body></worldbody></mujoco>'''
>>> arm = read_mjcf_text(text, "two.xml")
>>> [(j.name, j.point) for j in arm.joints], arm.sites[0]
([('q1', (0, 0, 1/2)), ('q2', (1, 0, 1/2))], ('tip', 2, (1, 1/2, 1/2)))
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

import mpmath
import sympy as sp

from coopkin_sym.errors import MjcfError, UrdfError
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.axes import snap_axis
from coopkin_sym.exact.parse import brief
from coopkin_sym.model.dh import IDENTITY, DHJoint, Frame, frame_then
from coopkin_sym.model.input_files import read_text_file
from coopkin_sym.model.urdf import (
    DEFAULT_BOUND,
    IgnoredJoint,
    Snapped,
    _decimal_exactly,
    _parse,
)

__all__ = ["MjcfArm", "read_mjcf", "read_mjcf_text"]

_KINDS = {"hinge": "revolute", "slide": "prismatic"}
_DEFAULTED = ("joint", "site")


@dataclass(frozen=True)
class MjcfArm:
    """One arm read from an MJCF file: its moving joints at home (base frame), the
    bodies on its chain (name, number of moving joints up to it, frame at home), its
    sites (name, number of moving joints up to their body, position at home) and the
    body of each site (``site_bodies``, in the same order), what was snapped, and the
    joints off the chain that were ignored.

    Example
    -------
    >>> arm = read_mjcf_text('<mujoco><worldbody><body name="b"><joint name="d" '
    ...     'type="slide" axis="1 0 0"/></body></worldbody></mujoco>', "m.xml")
    >>> [(name, k) for name, k, _ in arm.links], arm.joints[0].type
    ([('world', 0), ('b', 1)], 'prismatic')
    """

    model: str
    joints: tuple[DHJoint, ...]
    links: tuple[tuple[str, int, Frame], ...]
    sites: tuple[tuple[str, int, tuple], ...]
    snapped: tuple[Snapped, ...]
    ignored: tuple[IgnoredJoint, ...] = ()
    site_bodies: tuple[str, ...] = ()


def read_mjcf(path: str | Path, tip: str | None = None, base: Frame = IDENTITY,
              bound: Fraction | float = DEFAULT_BOUND) -> MjcfArm:
    """The arm of an MJCF file, from its top body to the body ``tip`` (see the module).

    Raises
    ------
    MjcfError
        The file cannot be read or used; the message names the file and the element.
    """
    path = Path(path)
    return read_mjcf_text(read_text_file(path, MjcfError), path.name, tip, base, bound)


def read_mjcf_text(text: str, source: str, tip: str | None = None,
                   base: Frame = IDENTITY, bound: Fraction | float = DEFAULT_BOUND
                   ) -> MjcfArm:
    """:func:`read_mjcf` for the text of a file (``source`` names it in errors)."""
    try:
        root = _parse(text, source)
    except UrdfError as exc:
        raise MjcfError(str(exc).replace("URDF", "MJCF")) from None
    if root.tag != "mujoco":
        raise MjcfError(f"{source}: the root element is <{str(root.tag)[:40]}>, expected "
                        f"<mujoco>")
    if root.find(".//include") is not None:
        raise MjcfError(f"{source}: <include> reads another file, which a model file "
                        f"never does: write one MJCF file (MuJoCo's compile command "
                        f"saves it)")
    reader = _Reader(source, root, Fraction(bound))
    return reader.arm(tip, base)


class _Reader:
    def __init__(self, source: str, root, bound: Fraction):
        self.source, self.root, self.bound = source, root, bound
        compiler = root.find("compiler")
        self.degrees = compiler is None or compiler.get("angle", "degree") != "radian"
        self.eulerseq = (compiler.get("eulerseq") if compiler is not None else None) or "xyz"
        self.defaults = self._defaults(root.find("default"), "main", {})
        self.snapped: list[Snapped] = []

    # --- defaults --------------------------------------------------------------------
    def _defaults(self, element, name: str, inherited: dict) -> dict:
        out: dict[str, dict] = {}
        if element is None:
            return {"main": {}}
        own = {tag: dict(inherited.get(tag, {})) for tag in _DEFAULTED}
        for tag in _DEFAULTED:
            child = element.find(tag)
            if child is not None:
                own[tag].update(child.attrib)
        out[name] = own
        for sub in element.findall("default"):
            out.update(self._defaults(sub, sub.get("class", name), own))
        return out

    def attributes(self, element, childclass: str | None, label: str) -> dict:
        cls = element.get("class") or childclass or "main"
        if cls not in self.defaults:
            raise MjcfError(f"{self.source}: {element.tag} {brief(label)}: "
                            f"unknown default class {brief(cls)}")
        merged = dict(self.defaults[cls].get(element.tag, {}))
        merged.update(element.attrib)
        return merged

    # --- the chain -------------------------------------------------------------------
    def arm(self, tip: str | None, base: Frame) -> MjcfArm:
        world = self.root.find("worldbody")
        if world is None:
            raise MjcfError(f"{self.source}: no <worldbody>")
        parent: dict[int, object] = {}
        bodies = {}
        for body in world.iter("body"):
            name = body.get("name")
            if name is not None:
                if name in bodies:
                    raise MjcfError(f"{self.source}: two bodies are named {brief(name)}")
                bodies[name] = body
            for child in body.findall("body"):
                parent[id(child)] = body
        if tip is None:
            leaves = [b for b in world.iter("body") if b.find("body") is None]
            if len(leaves) != 1:
                raise MjcfError(f"{self.source}: the bodies branch ({len(leaves)} leaves): "
                                f"name the arm's last body with tip")
            end = leaves[0]
        elif tip not in bodies:
            raise MjcfError(f"{self.source}: no body named {brief(tip)}")
        else:
            end = bodies[tip]
        chain = [end]
        while id(chain[-1]) in parent:
            chain.append(parent[id(chain[-1])])
        chain.reverse()
        on_chain = {id(b) for b in chain}
        ignored = tuple(
            IgnoredJoint(self.source, j.get("name") or f"{b.get('name')}_joint{k + 1}",
                         j.get("type"), None)
            for b in world.iter("body") if id(b) not in on_chain
            for k, j in enumerate(b.findall("joint")) if j.get("type", "hinge") not in _KINDS)
        return self._walk(chain, base, ignored)

    def _walk(self, chain: list, base: Frame, ignored: tuple) -> MjcfArm:
        frame = base
        links = [("world", 0, frame)]
        joints: list[DHJoint] = []
        sites: list[tuple[str, int, tuple]] = []
        bodies: list[str] = []
        childclass = None
        for body in chain:
            name = body.get("name") or f"body{len(links)}"
            where = f"body {brief(name)}"
            frame = frame_then(frame, self.orientation(body, where),
                               self.vector(body.get("pos"), where, "pos"))
            childclass = body.get("childclass") or childclass
            for k, joint in enumerate(body.findall("joint")):
                attrs = self.attributes(joint, childclass,
                                        joint.get("name") or f"{name}_joint{k + 1}")
                kind = attrs.get("type", "hinge")
                if kind not in _KINDS:
                    raise MjcfError(f"{self.source}: {where}: a {kind} joint is not "
                                    f"supported on the arm's chain (hinge and slide "
                                    f"joints make an arm)")
                jname = attrs.get("name") or f"{name}_joint{k + 1}"
                axis = self.axis(attrs.get("axis", "0 0 1"), f"joint {brief(jname)}")
                point = self.vector(attrs.get("pos"), f"joint {brief(jname)}", "pos")
                r, p = frame
                direction = tuple(sp.expand(x) for x in r * sp.Matrix(axis))
                origin = tuple(sp.expand(x) for x in sp.Matrix(p) + r * sp.Matrix(point))
                joints.append(DHJoint(jname, _KINDS[kind], direction, origin))
            links.append((name, len(joints), frame))
            for k, site in enumerate(body.findall("site")):
                attrs = self.attributes(site, childclass,
                                        site.get("name") or f"{name}_site{k + 1}")
                r, p = frame
                at = self.vector(attrs.get("pos"), f"site {brief(attrs.get('name'))}", "pos")
                place = tuple(sp.expand(x) for x in sp.Matrix(p) + r * sp.Matrix(at))
                sites.append((attrs.get("name") or f"{name}_site{k + 1}", len(joints), place))
                bodies.append(name)
        model = self.root.get("model") or self.source
        return MjcfArm(model, tuple(joints), tuple(links), tuple(sites),
                       tuple(self.snapped), ignored, tuple(bodies))

    # --- numbers -------------------------------------------------------------------------
    def numbers(self, text: str | None, where: str, what: str, count: int) -> list[Fraction]:
        parts = (text or "").split()
        if len(parts) != count:
            raise MjcfError(f"{self.source}: {where}: {what} {brief(text)}: expected "
                            f"{count} numbers")
        try:
            return [_decimal_exactly(self.source, f"{where} {what}", t) for t in parts]
        except UrdfError as exc:
            raise MjcfError(str(exc)) from None

    def vector(self, text: str | None, where: str, what: str) -> tuple:
        values = self.numbers(text or "0 0 0", where, what, 3)
        return tuple(sp.Rational(x.numerator, x.denominator) for x in values)

    def axis(self, text: str, where: str) -> tuple:
        exact = self.numbers(text, where, "axis", 3)
        if not any(exact):
            raise MjcfError(f"{self.source}: {where}: axis {brief(text)} is the zero vector")
        unit, error = snap_axis(tuple(exact), self.bound)
        if sum(x * x for x in exact) != 1:
            self.snapped.append(Snapped(f"{where} axis", text,
                                        "(" + ", ".join(str(x) for x in unit) + ")", error))
        return tuple(sp.Rational(x.numerator, x.denominator) for x in unit)

    def angle(self, value: Fraction | mpmath.mpf, where: str, given: str) -> ExactAngle:
        """An angle (radians, exact or a 60-digit approximation) snapped exactly."""
        q = value if isinstance(value, Fraction) else Fraction(mpmath.nstr(value, 60))
        angle, error = ExactAngle.snap(q, self.bound)
        if q != 0:
            self.snapped.append(Snapped(where, given, angle.text, error))
        return angle

    def radians(self, x: Fraction):
        return x * mpmath.pi / 180 if self.degrees else x

    def orientation(self, body, where: str) -> sp.Matrix:
        given = [k for k in ("quat", "axisangle", "euler", "xyaxes", "zaxis")
                 if body.get(k) is not None]
        if len(given) > 1:
            raise MjcfError(f"{self.source}: {where}: more than one orientation "
                            f"({', '.join(given)})")
        if not given:
            return sp.eye(3)
        key = given[0]
        text = body.get(key)
        with mpmath.workdps(60):
            if key == "quat":
                w, x, y, z = self.numbers(text, where, "quat", 4)
                norm = mpmath.sqrt(x * x + y * y + z * z)
                if norm == 0:
                    return sp.eye(3)
                theta = 2 * mpmath.atan2(norm, mpmath.mpf(w.numerator) / w.denominator)
                return self.rotation((x, y, z), theta, where, text)
            if key == "axisangle":
                x, y, z, a = self.numbers(text, where, "axisangle", 4)
                return self.rotation((x, y, z), self.radians(a), where, text)
            if key == "euler":
                angles = self.numbers(text, where, "euler", 3)
                return self.euler(angles, where, text)
        raise MjcfError(f"{self.source}: {where}: orientation by {key} is not read; "
                        f"give quat, axisangle or euler")

    def rotation(self, axis, theta, where: str, given: str) -> sp.Matrix:
        """The rotation by ``theta`` about ``axis``, both snapped exactly."""
        if isinstance(theta, Fraction) and theta == 0:
            return sp.eye(3)
        unit, error = snap_axis(tuple(Fraction(a) for a in axis), self.bound)
        if sum(Fraction(a) ** 2 for a in axis) != 1:
            self.snapped.append(Snapped(f"{where} orientation axis", given,
                                        "(" + ", ".join(str(x) for x in unit) + ")", error))
        angle = self.angle(theta, f"{where} orientation angle", given)
        c, s = angle.cos_sin
        k = sp.Matrix([[0, -unit[2], unit[1]], [unit[2], 0, -unit[0]],
                       [-unit[1], unit[0], 0]]).applyfunc(lambda v: sp.Rational(str(v)))
        return sp.eye(3) + s * k + (1 - c) * k * k

    def euler(self, angles, where: str, given: str) -> sp.Matrix:
        seq = self.eulerseq
        if len(seq) != 3 or set(seq.lower()) - set("xyz"):
            raise MjcfError(f"{self.source}: compiler eulerseq {brief(seq)}: expected "
                            f"three of x, y, z")
        units = {"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1)}
        out = sp.eye(3)
        for axis_name, value in zip(seq, angles, strict=True):
            turn = self.rotation(units[axis_name.lower()], self.radians(value), where, given)
            # lowercase: about the moving axes (post-multiply); uppercase: fixed axes
            out = out * turn if axis_name.islower() else turn * out
        return out
