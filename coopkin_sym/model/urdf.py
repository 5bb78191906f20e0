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
element; a closed loop is named by its joints and links. The file is parsed with
``defusedxml`` (no entities, no external references), and the parse stops at the first
element over a budget of :mod:`coopkin_sym.limits`: links
(:data:`~coopkin_sym.limits.MAX_URDF_LINKS`), joints
(:data:`~coopkin_sym.limits.MAX_URDF_JOINTS`), XML elements
(:data:`~coopkin_sym.limits.MAX_URDF_ELEMENTS`) and their nesting
(:data:`~coopkin_sym.limits.MAX_DEPTH`); an arm's chain has at most
:data:`~coopkin_sym.limits.MAX_URDF_CHAIN` joints.

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

from coopkin_sym import limits
from coopkin_sym.errors import TreeError, UrdfError
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.parse import NumberError, brief, parse_number
from coopkin_sym.model.dh import IDENTITY, DHJoint, Frame, frame_then, rotation_rpy
from coopkin_sym.model.input_files import read_input_text, size_text

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
    if len(text) > limits.MAX_FILE_BYTES:
        raise UrdfError(f"{source}: the text is longer than "
                        f"{size_text(limits.MAX_FILE_BYTES)} (the limit for a URDF file)")
    root = _parse(text, source)
    if root.tag != "robot":
        raise UrdfError(f"{source}: the root element is <{str(root.tag)[:40]}>, expected "
                        f"<robot>")
    links = [e.get("name") for e in root.findall("link")]
    if not links or None in links:
        raise UrdfError(f"{source}: every <link> needs a name, and a robot at least one")
    children: dict[str, list] = {}
    for name in links:
        if name in children:
            raise UrdfError(f"{source}: two links are named {brief(name)}")
        children[name] = []
    parent_of: dict[str, object] = {}
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
            raise UrdfError(f"{where}: link {brief(c)} already has the parent joint "
                            f"{brief(parent_of[c].get('name'))}: a closed loop is not "
                            f"supported")
        parent_of[c] = joint
        children[p].append(joint)
    _refuse_loops(source, links, parent_of)
    roots = [name for name in links if name not in parent_of]
    if len(roots) != 1:
        raise UrdfError(f"{source}: expected one root link, found {_listed(roots)}")
    chain = _chain(source, roots[0], tip, parent_of, children)
    return _walk(source, root.get("name") or source, roots[0], chain, base, bound)


class _BoundedBuilder:
    """The target of the XML parser: builds the element tree (with ``builder``) and
    stops the parse at the first element over a budget of :mod:`coopkin_sym.limits`
    (elements, links, joints, nesting), before the rest of the file is parsed."""

    def __init__(self, source: str, builder):
        self.source, self.builder = source, builder
        self.depth = self.elements = 0
        self.counts = {"link": 0, "joint": 0}

    def start(self, tag: str, attributes: dict):
        self.elements += 1
        if self.elements > limits.MAX_URDF_ELEMENTS:
            raise UrdfError(f"{self.source}: more than {limits.MAX_URDF_ELEMENTS:,} XML "
                            f"elements (the limit for a URDF file)")
        if self.depth >= limits.MAX_DEPTH:
            raise UrdfError(f"{self.source}: XML elements nested more than "
                            f"{limits.MAX_DEPTH} deep (the limit for a URDF file)")
        if self.depth == 1 and tag in self.counts:
            self.counts[tag] += 1
            most = limits.MAX_URDF_LINKS if tag == "link" else limits.MAX_URDF_JOINTS
            if self.counts[tag] > most:
                raise UrdfError(f"{self.source}: more than {most:,} {tag}s (the limit "
                                f"for a URDF file)")
        self.depth += 1
        return self.builder.start(tag, attributes)

    def end(self, tag: str):
        self.depth -= 1
        return self.builder.end(tag)

    def data(self, text: str) -> None:
        self.builder.data(text)

    def close(self):
        return self.builder.close()


def _parse(text: str, source: str):
    """The root element of a URDF text, parsed by ``defusedxml`` (no DTD, entity or
    external reference) within the budgets of :class:`_BoundedBuilder`."""
    from xml.etree.ElementTree import TreeBuilder  # only when a URDF file is read

    from defusedxml import DefusedXmlException
    from defusedxml.ElementTree import DefusedXMLParser, ParseError

    parser = DefusedXMLParser(target=_BoundedBuilder(source, TreeBuilder()),
                              forbid_dtd=True)
    try:
        parser.feed(text)
        return parser.close()
    except DefusedXmlException as exc:
        raise UrdfError(f"{source}: not a URDF file ({type(exc).__name__}: a DTD, entity "
                        f"or external reference is forbidden)") from None
    except ParseError as exc:
        raise UrdfError(f"{source}: not a URDF file ({' '.join(str(exc).split())})") from None


def _listed(names: list, most: int = 6) -> str:
    """Names for a message: the first ``most``, and how many in all."""
    if not names:
        return "none"
    shown = ", ".join(map(brief, names[:most]))
    return shown if len(names) <= most else f"{shown}, ... ({len(names)} in all)"


def _refuse_loops(source: str, links: list[str], parent_of: dict) -> None:
    """Refuse a link that is its own ancestor, naming the joints and links of the loop.
    Each link has at most one parent joint here, so following parents from every link
    (each link walked once) finds every loop."""
    done: set[str] = set()
    for start in links:
        path: list[str] = []
        on_path: dict[str, int] = {}
        link = start
        while link in parent_of and link not in done:
            if link in on_path:
                loop = path[on_path[link]:][::-1]     # from parent to child
                joints = [parent_of[x].get("name") for x in (*loop[1:], loop[0])]
                through = f" through {_listed(loop[1:])}" if len(loop) > 1 else ""
                raise UrdfError(f"{source}: a closed loop: joint"
                                f"{'s' if len(joints) > 1 else ''} {_listed(joints)} lead"
                                f"{'' if len(joints) > 1 else 's'} from link "
                                f"{brief(loop[0])}{through} back to {brief(loop[0])} (a "
                                f"link cannot be its own ancestor)")
            on_path[link] = len(path)
            path.append(link)
            link = parent_of[link].find("parent").get("link")
        done.update(path)


def _chain(source: str, root: str, tip: str | None, parent_of: dict, children: dict
           ) -> list:
    """The joints from the root link to ``tip`` (the leaf when the robot is a chain),
    at most :data:`~coopkin_sym.limits.MAX_URDF_CHAIN` of them."""
    if tip is None:
        out, link = [], root
        while children[link]:
            if len(children[link]) > 1:
                names = _listed([j.get("name") for j in children[link]])
                raise UrdfError(f"{source}: the robot branches at link {brief(link)} "
                                f"(joints {names}): name the arm's last link with tip")
            joint = children[link][0]
            out.append(joint)
            _check_chain_length(source, root, out)
            link = joint.find("child").get("link")
        return out
    if tip not in children:
        raise UrdfError(f"{source}: tip: no link {brief(tip)}")
    out, link = [], tip
    while link != root:
        joint = parent_of[link]
        out.append(joint)
        _check_chain_length(source, root, out)
        link = joint.find("parent").get("link")
    return out[::-1]


def _check_chain_length(source: str, root: str, chain: list) -> None:
    if len(chain) > limits.MAX_URDF_CHAIN:
        raise UrdfError(f"{source}: the chain from link {brief(root)} has more than "
                        f"{limits.MAX_URDF_CHAIN} joints (the limit for one arm)")


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
