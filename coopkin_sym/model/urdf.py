"""The kinematic subset of URDF, read exactly.

A URDF file describes a robot as links joined by joints, each joint placed in its
parent link's frame by ``<origin xyz rpy>`` and turning (or sliding) about ``<axis>``.
This module reads the chain of one arm from its root link to a tip link (the last link
when the robot does not branch): ``revolute`` and ``continuous`` joints (both are
revolute here, limits are ignored), ``prismatic`` joints and ``fixed`` joints (merged
into the next link). It returns each moving joint's axis and a point on it at home and
the frame of every link on the chain, in the arm's base frame, like a DH table does.

Numbers are read exactly where they are exact: ``xyz`` entries are decimals (``0.4318``
is ``2159/5000``). Angles and axes written as floats are snapped: an ``rpy`` angle to
the nearest angle with a rational ``tan(q/2)`` within the bound (``1.5708`` is
``pi/2``), an axis to a nearby exact unit vector (``0.7071 0.7071 0`` is
``(1, 1, 0)/sqrt(2)``, which is not rational: the nearest rational unit vector within
the bound is taken). Every snap is recorded with its distance, so that reports can
state it. Anything else (floating or planar joints, mimic joints, closed loops, a
branching robot without a tip) is refused with one line naming the file and the
element. The file is parsed with ``defusedxml`` (no entities, no external references).

Example
-------
>>> text = '''<robot name="r">
...   <link name="base"/><link name="l1"/>
...   <joint name="q1" type="continuous"><parent link="base"/><child link="l1"/>
...     <origin xyz="0 0 0.5" rpy="0 0 1.5707963"/><axis xyz="0 0 1"/></joint>
... </robot>'''
>>> arm = read_urdf_text(text, "r.urdf", tip=None, bound=1e-6)
>>> arm.joints[0].point, arm.snapped[0].exact
((0, 0, 1/2), 'pi/2')
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

import sympy as sp

from coopkin_sym.errors import TreeError, UrdfError
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.parse import NumberError, brief, parse_number
from coopkin_sym.model.dh import IDENTITY, DHJoint, Frame, frame_then, rotation_rpy
from coopkin_sym.model.input_files import read_input_text

__all__ = ["DEFAULT_BOUND", "Snapped", "UrdfArm", "UrdfError", "read_urdf", "read_urdf_text"]

#: Default bound on snapping a URDF float (radians, for angles and axis directions).
DEFAULT_BOUND = 1e-6

_TYPES = {"revolute": "revolute", "continuous": "revolute", "prismatic": "prismatic",
          "fixed": None}


@dataclass(frozen=True)
class Snapped:
    """A float of a URDF file replaced by an exact value: where it was, the text
    given, the exact value, and how far apart they are (radians).

    Example
    -------
    >>> Snapped("joint 'q1' origin rpy[2]", "1.5708", "pi/2", 3.7e-06).exact
    'pi/2'
    """

    where: str
    given: str
    exact: str
    error: float


@dataclass(frozen=True)
class UrdfArm:
    """One arm read from a URDF file: its moving joints at home (base frame), the links
    on its chain (name, number of moving joints up to it, frame at home), and what was
    snapped.

    Example
    -------
    >>> arm = read_urdf_text('<robot name="r"><link name="b"/><link name="t"/>'
    ...     '<joint name="d1" type="prismatic"><parent link="b"/><child link="t"/>'
    ...     '<axis xyz="1 0 0"/></joint></robot>', "r.urdf")
    >>> [(name, k) for name, k, _ in arm.links]
    [('b', 0), ('t', 1)]
    """

    robot: str
    joints: tuple[DHJoint, ...]
    links: tuple[tuple[str, int, Frame], ...]
    snapped: tuple[Snapped, ...]


def read_urdf(path: str | Path, tip: str | None = None, base: Frame = IDENTITY,
              bound: float = DEFAULT_BOUND) -> UrdfArm:
    """The arm of a URDF file, from its root link to ``tip`` (see the module).

    Raises
    ------
    UrdfError
        The file cannot be read or used; the message names the file and the element.
    """
    path = Path(path)
    try:
        text = read_input_text(path)
    except TreeError as exc:
        raise UrdfError(f"{path}: {exc}") from None
    return read_urdf_text(text, path.name, tip, base, bound)


def read_urdf_text(text: str, source: str, tip: str | None = None, base: Frame = IDENTITY,
                   bound: float = DEFAULT_BOUND) -> UrdfArm:
    """:func:`read_urdf` for the text of a file (``source`` names it in errors)."""
    from defusedxml import DefusedXmlException  # only when a URDF file is read
    from defusedxml.ElementTree import ParseError, fromstring

    try:
        root = fromstring(text, forbid_dtd=True)
    except DefusedXmlException as exc:
        raise UrdfError(f"{source}: not a URDF file ({type(exc).__name__}: a DTD, entity "
                        f"or external reference is forbidden)") from None
    except ParseError as exc:
        raise UrdfError(f"{source}: not a URDF file ({' '.join(str(exc).split())})") from None
    if root.tag != "robot":
        raise UrdfError(f"{source}: the root element is <{str(root.tag)[:40]}>, expected "
                        f"<robot>")
    links = [e.get("name") for e in root.findall("link")]
    if not links or None in links:
        raise UrdfError(f"{source}: every <link> needs a name, and a robot at least one")
    parent_of: dict[str, object] = {}
    children: dict[str, list] = {name: [] for name in links}
    for joint in root.findall("joint"):
        name = joint.get("name")
        where = f"{source}: joint {brief(name)}"
        kind = joint.get("type")
        if kind not in _TYPES:
            raise UrdfError(f"{where}: type {brief(kind)} is not supported (revolute, "
                            f"continuous, prismatic and fixed joints make an arm)")
        if joint.find("mimic") is not None:
            raise UrdfError(f"{where}: mimics {brief(joint.find('mimic').get('joint'))}; "
                            f"coupled joints are not supported")
        parent, child = joint.find("parent"), joint.find("child")
        if name is None or parent is None or child is None:
            raise UrdfError(f"{where}: needs a name, a <parent link> and a <child link>")
        p, c = parent.get("link"), child.get("link")
        for link in (p, c):
            if link not in children:
                raise UrdfError(f"{where}: unknown link {brief(link)}")
        if c in parent_of:
            raise UrdfError(f"{where}: link {brief(c)} already has a parent joint: a closed "
                            f"loop is not supported")
        parent_of[c] = joint
        children[p].append(joint)
    roots = [name for name in links if name not in parent_of]
    if len(roots) != 1:
        raise UrdfError(f"{source}: expected one root link, found "
                        f"{', '.join(map(brief, roots)) or 'none (a closed loop)'}")
    chain = _chain(source, roots[0], tip, parent_of, children)
    return _walk(source, root.get("name") or source, roots[0], chain, base, bound)


def _chain(source: str, root: str, tip: str | None, parent_of: dict, children: dict
           ) -> list:
    """The joints from the root link to ``tip`` (the leaf when the robot is a chain)."""
    if tip is None:
        out, link = [], root
        while children[link]:
            if len(children[link]) > 1:
                names = ", ".join(brief(j.get("name")) for j in children[link])
                raise UrdfError(f"{source}: the robot branches at link {brief(link)} "
                                f"(joints {names}): name the arm's last link with tip")
            joint = children[link][0]
            out.append(joint)
            link = joint.find("child").get("link")
        return out
    if tip not in children:
        raise UrdfError(f"{source}: tip: no link {brief(tip)}")
    out, link = [], tip
    while link != root:
        joint = parent_of[link]
        out.append(joint)
        link = joint.find("parent").get("link")
    return out[::-1]


def _walk(source: str, robot: str, root: str, chain: list, base: Frame, bound: float
          ) -> UrdfArm:
    snapped: list[Snapped] = []
    frame = base
    links = [(root, 0, frame)]
    joints: list[DHJoint] = []
    for joint in chain:
        name = joint.get("name")
        where = f"joint {brief(name)}"
        origin = joint.find("origin")
        xyz = _numbers(source, where, "origin xyz",
                       origin.get("xyz") if origin is not None else None)
        rpy = [_angle(source, f"{where} origin rpy[{k}]", text, bound, snapped)
               for k, text in enumerate(_tokens(source, where, "origin rpy",
                                                origin.get("rpy") if origin is not None
                                                else None))]
        frame = frame_then(frame, rotation_rpy(rpy), xyz)
        kind = _TYPES[joint.get("type")]
        if kind is not None:
            axis_element = joint.find("axis")
            axis = _axis(source, where, axis_element.get("xyz") if axis_element is not None
                         else None, bound, snapped)
            r, p = frame
            direction = r * sp.Matrix(axis)
            joints.append(DHJoint(name, kind, tuple(sp.expand(x) for x in direction), p))
        links.append((joint.find("child").get("link"), len(joints), frame))
    return UrdfArm(robot, tuple(joints), tuple(links), tuple(snapped))


def _tokens(source: str, where: str, what: str, text: str | None) -> list[str]:
    parts = (text or "0 0 0").split()
    if len(parts) != 3:
        raise UrdfError(f"{source}: {where}: {what} {brief(text)}: expected 3 numbers")
    return parts


def _numbers(source: str, where: str, what: str, text: str | None) -> tuple:
    try:
        return tuple(parse_number(t, {}, f"{source}: {where}: {what}")
                     for t in _tokens(source, where, what, text))
    except NumberError as exc:
        raise UrdfError(str(exc)) from None


def _float(source: str, where: str, text: str) -> float:  # float-ok: URDF floats
    try:
        value = float(text)  # float-ok: a URDF float, snapped below
    except ValueError:
        raise UrdfError(f"{source}: {where}: {brief(text)} is not a number") from None
    if not math.isfinite(value):
        raise UrdfError(f"{source}: {where}: {brief(text)} is not a finite number")
    return value


def _angle(source: str, where: str, text: str, bound: float, snapped: list) -> ExactAngle:
    """An angle in radians: 0 exactly, else the exact angle nearest within ``bound``."""
    value = _float(source, where, text)  # float-ok: snapped to an exact angle
    angle, error = ExactAngle.snap(value, bound)
    if value != 0:
        snapped.append(Snapped(f"{where}", text, angle.text, error))
    return angle


def _axis(source: str, where: str, text: str | None, bound: float, snapped: list
          ) -> tuple:
    """An exact unit axis: the given one when it is exactly a unit vector, else the
    rational unit vector nearest to its direction within ``bound`` (radians)."""
    parts = _tokens(source, where, "axis xyz", text if text is not None else "1 0 0")
    try:
        exact = [Fraction(str(parse_number(t, {}, f"{source}: {where}: axis xyz")))
                 for t in parts]
    except NumberError as exc:
        raise UrdfError(str(exc)) from None
    if sum(x * x for x in exact) == 1:
        return tuple(sp.Rational(x.numerator, x.denominator) for x in exact)
    if not any(exact):
        raise UrdfError(f"{source}: {where}: axis xyz {brief(text)} is the zero vector")
    unit, error = _rational_unit([float(x) for x in exact], bound)  # float-ok: snapping
    snapped.append(Snapped(f"{where} axis", " ".join(parts),
                           "(" + ", ".join(str(x) for x in unit) + ")", error))
    return unit


def _rational_unit(v: list[float], bound: float) -> tuple[tuple, float]:  # float-ok
    """The rational unit vector nearest to ``v``'s direction within ``bound`` radians:
    the inverse stereographic image of rational approximations of its projection (from
    the pole away from ``v``), finer until within the bound."""
    norm = math.sqrt(sum(x * x for x in v))  # float-ok
    u = [x / norm for x in v]  # float-ok
    sign = 1 if u[2] >= 0 else -1
    a, b = u[0] / (1 + sign * u[2]), u[1] / (1 + sign * u[2])  # float-ok
    for digits in range(0, 16):
        fa = Fraction(a).limit_denominator(10**digits)
        fb = Fraction(b).limit_denominator(10**digits)
        s = 1 + fa * fa + fb * fb
        w = (2 * fa / s, 2 * fb / s, sign * (1 - fa * fa - fb * fb) / s)
        dot = sum(float(x) * y for x, y in zip(w, u, strict=True))  # float-ok
        error = math.acos(max(-1.0, min(1.0, dot)))  # float-ok
        if error <= bound:
            return tuple(sp.Rational(x.numerator, x.denominator) for x in w), error
    raise UrdfError(f"no rational unit vector within {bound:g} rad of {v}")
