"""The kinematic subset of URDF, read exactly.

A URDF file describes a robot as links joined by joints, each joint placed in its
parent link's frame by ``<origin xyz rpy>`` and turning (or sliding) about ``<axis>``.
This module reads the chain of one arm from its root link to a tip link (the last link
when the robot does not branch): ``revolute`` and ``continuous`` joints (both are
revolute here, limits are ignored), ``prismatic`` joints and ``fixed`` joints (merged
into the next link). It returns each moving joint's axis and a point on it at home and
the frame of every link on the chain, in the arm's base frame, like a DH table does.

Numbers are read exactly: ``xyz`` entries are decimals (``0.4318`` is ``2159/5000``),
and so are angles and axes, which are then snapped: an ``rpy`` angle to the simplest
exact angle within the bound (:meth:`~coopkin_sym.exact.angles.ExactAngle.snap`:
``1.5708`` is ``pi/2``), an axis to an exact rational unit vector within the bound
(:func:`~coopkin_sym.exact.axes.snap_axis`: ``0.7071 0.7071 0`` is near
``(1, 1, 0)/sqrt(2)``, which is not rational). Every snap is decided exactly and
recorded with its distance, so that reports can state it. Only the chain is checked:
joints off it that an arm could not have (mimic, floating, planar or unknown types)
are ignored and listed (:class:`IgnoredJoint`); on the chain they are refused with the
reason. Names that are not identifiers get safe names in the model layer
(:func:`variable_names`). Anything else (closed loops, a branching robot without a
tip, a xacro file, whose expansion would run the expressions it holds) is refused
with one line naming the file and the element; a closed loop is named by its joints
and links. The file is parsed with
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
import re
from dataclasses import dataclass, replace
from fractions import Fraction
from pathlib import Path

import sympy as sp

from coopkin_sym import limits
from coopkin_sym.errors import UrdfError
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.axes import snap_axis
from coopkin_sym.exact.parse import NumberError, brief, parse_number
from coopkin_sym.model.dh import IDENTITY, DHJoint, Frame, frame_then, rotation_rpy
from coopkin_sym.model.input_files import read_text_file, size_text

__all__ = ["DEFAULT_BOUND", "IgnoredJoint", "Renamed", "Snapped", "UrdfArm", "UrdfError",
           "read_urdf", "read_urdf_text", "variable_names"]

#: Default bound on snapping a URDF float (radians, for angles and axis directions).
DEFAULT_BOUND = Fraction(1, 10**6)

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
class IgnoredJoint:
    """A joint of a URDF file off the arm's chain that the arm could not have had
    (a mimic joint, or a type other than revolute, continuous, prismatic and fixed):
    where (the file), its name, its type and the joint it mimics (None: no mimic).

    Example
    -------
    >>> IgnoredJoint("panda.urdf", "panda_finger_joint2", "prismatic",
    ...              "panda_finger_joint1").mimics
    'panda_finger_joint1'
    """

    where: str
    joint: str | None
    type: str | None
    mimics: str | None


@dataclass(frozen=True)
class Renamed:
    """A name of a URDF file that is not a usable variable (or link) name, and the
    name it was given: where (the file), what (``joint`` or ``link``), the name in
    the file and the name used.

    Example
    -------
    >>> Renamed("allegro.urdf", "joint", "joint_0.0", "joint_0_0").name
    'joint_0_0'
    """

    where: str
    what: str
    given: str
    name: str


@dataclass(frozen=True)
class UrdfArm:
    """One arm read from a URDF file: its moving joints at home (base frame), the links
    on its chain (name, number of moving joints up to it, frame at home), what was
    snapped, and the joints off the chain that were ignored.

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
    ignored: tuple[IgnoredJoint, ...] = ()


def read_urdf(path: str | Path, tip: str | None = None, base: Frame = IDENTITY,
              bound: Fraction | float = DEFAULT_BOUND) -> UrdfArm:
    """The arm of a URDF file, from its root link to ``tip`` (see the module).

    Raises
    ------
    UrdfError
        The file cannot be read or used; the message names the file and the element.
    """
    path = Path(path)
    return read_urdf_text(read_text_file(path, UrdfError), path.name, tip, base, bound)


def read_urdf_text(text: str, source: str, tip: str | None = None, base: Frame = IDENTITY,
                   bound: Fraction | float = DEFAULT_BOUND) -> UrdfArm:
    """:func:`read_urdf` for the text of a file (``source`` names it in errors)."""
    if len(text) > limits.MAX_FILE_BYTES:
        raise UrdfError(f"{source}: the text is longer than "
                        f"{size_text(limits.MAX_FILE_BYTES)} (the limit for a URDF file)")
    try:
        text.encode("utf-8")
    except UnicodeEncodeError as exc:      # a lone surrogate: no file holds one
        raise UrdfError(f"{source}: not valid text (character {exc.start + 1} is a lone "
                        f"surrogate, which no UTF-8 file holds)") from None
    _refuse_xacro(source, text)
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
    for joint in chain:
        _check_on_chain(source, joint)
    on_chain = {id(joint) for joint in chain}
    ignored = tuple(IgnoredJoint(source, joint.get("name"), joint.get("type"),
                                 _mimicked(joint))
                    for joint in root.findall("joint")
                    if id(joint) not in on_chain and (joint.get("type") not in _TYPES
                                                     or joint.find("mimic") is not None))
    arm = _walk(source, root.get("name") or source, roots[0], chain, base, bound)
    return replace(arm, ignored=ignored)


def _refuse_xacro(source: str, text: str) -> None:
    """Refuse a xacro file (a ``.xacro`` name, a ``<xacro:`` element, or a
    ``xmlns:xacro`` declaration with ``${...}`` or ``$(...)`` in the text): expanding
    one evaluates the Python expressions it holds, which a model file never runs;
    ROS's ``xacro`` command writes the plain URDF. Its output keeps the declaration
    alone, and is read."""
    marks = [m for m in ("xmlns:xacro", "<xacro:") if m in text]
    expands = "<xacro:" in text or ("xmlns:xacro" in text and ("${" in text
                                                               or "$(" in text))
    if not expands and not source.lower().endswith(".xacro"):
        return
    why = f"it has {' and '.join(marks)}" if marks else "its name ends in .xacro"
    if source.lower().endswith(".xacro"):
        stem = source[:-6] if source[:-6].lower().endswith(".urdf") else f"{source[:-6]}.urdf"
    else:
        stem = f"{Path(source).stem}.expanded.urdf"
    raise UrdfError(f"{source}: a xacro file ({why}) is not read: expanding it runs the "
                    f"expressions it contains; write the plain URDF first with ROS's xacro "
                    f"command (xacro {source} > {stem}) and read that file")


def _mimicked(joint) -> str | None:
    """The joint a ``<mimic>`` element names ('' when it names none), or None."""
    mimic = joint.find("mimic")
    return None if mimic is None else mimic.get("joint") or ""


def _check_on_chain(source: str, joint) -> None:
    """Refuse a joint on the arm's chain that the arm cannot have: a type other than
    revolute, continuous, prismatic and fixed, or a mimic (coupled) joint."""
    where = f"{source}: joint {brief(joint.get('name'))}"
    kind = joint.get("type")
    if kind not in _TYPES:
        raise UrdfError(f"{where}: type {brief(kind)} is not supported on the arm's chain "
                        f"(revolute, continuous, prismatic and fixed joints make an arm)")
    mimicked = _mimicked(joint)
    if mimicked is not None:
        raise UrdfError(f"{where}: mimics {brief(mimicked)}; a mimic (coupled) joint on "
                        f"the arm's chain is not supported (each joint is a variable of "
                        f"its own): make it fixed in a copy of the file, or choose a tip "
                        f"whose chain has none")


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


def _walk(source: str, robot: str, root: str, chain: list, base: Frame,
          bound: Fraction | float) -> UrdfArm:
    bound = Fraction(bound)
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


def _decimal_exactly(source: str, where: str, text: str) -> Fraction:
    """A float of the file, read exactly as the decimal it is (``1.5708`` is
    ``19635/12500``), within the budgets of the one number parser."""
    try:
        value = float(text)  # float-ok: only checks that the text is a finite float
    except ValueError:
        raise UrdfError(f"{source}: {where}: {brief(text)} is not a number") from None
    if not math.isfinite(value):
        raise UrdfError(f"{source}: {where}: {brief(text)} is not a finite number")
    try:
        return Fraction(str(parse_number(text, {}, f"{source}: {where}")))
    except NumberError as exc:
        raise UrdfError(str(exc)) from None


def _angle(source: str, where: str, text: str, bound: Fraction, snapped: list
           ) -> ExactAngle:
    """An angle in radians: 0 exactly, else the simplest exact angle within ``bound``
    of the decimal given (:meth:`~coopkin_sym.exact.angles.ExactAngle.snap`)."""
    value = _decimal_exactly(source, where, text)
    angle, error = ExactAngle.snap(value, bound)
    if value != 0:
        snapped.append(Snapped(f"{where}", text, angle.text, error))
    return angle


def _axis(source: str, where: str, text: str | None, bound: Fraction, snapped: list
          ) -> tuple:
    """An exact unit axis: the given one when it is exactly a unit vector, else the
    unit vector :func:`~coopkin_sym.exact.axes.snap_axis` gives within ``bound``."""
    parts = _tokens(source, where, "axis xyz", text if text is not None else "1 0 0")
    exact = [_decimal_exactly(source, f"{where} axis xyz", t) for t in parts]
    if sum(x * x for x in exact) == 1:
        return tuple(sp.Rational(x.numerator, x.denominator) for x in exact)
    if not any(exact):
        raise UrdfError(f"{source}: {where}: axis xyz {brief(text)} is the zero vector")
    unit, error = snap_axis(tuple(exact), bound)
    snapped.append(Snapped(f"{where} axis", " ".join(parts),
                           "(" + ", ".join(str(x) for x in unit) + ")", error))
    return tuple(sp.Rational(x.numerator, x.denominator) for x in unit)


_NOT_NAME = re.compile(r"[^A-Za-z0-9_]+")
_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def variable_names(names: list[str], prefix: str = "", reserved: frozenset[str] = frozenset(),
                   lead: str = "j_") -> dict[str, str]:
    """Safe, unique, deterministic names for the names of a URDF file (after
    ``prefix``): a name that is an identifier (letters, digits, ``_``, not starting
    with a digit) and not ``reserved`` is kept; in any other, each run of other
    characters becomes ``_``, ``lead`` goes before a leading digit, ``_`` after a
    reserved word; a name taken by a kept name or an earlier one gets the first free
    suffix ``_2``, ``_3``, ... Names are taken in the order given.

    Example
    -------
    >>> variable_names(["joint_0.0", "joint_0_0", "3-finger"])
    {'joint_0.0': 'joint_0_0_2', 'joint_0_0': 'joint_0_0', '3-finger': 'j_3_finger'}
    >>> variable_names(["lambda", "a b"], reserved=frozenset({"lambda"}))
    {'lambda': 'lambda_', 'a b': 'a_b'}
    """
    def usable(name: str) -> bool:
        return bool(_NAME.fullmatch(name)) and name not in reserved

    out: dict[str, str] = {}
    taken = {prefix + n for n in names if usable(prefix + n)}
    for given in names:
        name = prefix + given
        if usable(name):
            out[given] = name
            continue
        safe = _NOT_NAME.sub("_", name) or "_"
        if safe[0].isdigit():
            safe = lead + safe
        if safe in reserved:
            safe += "_"
        candidate, k = safe, 2
        while candidate in taken or candidate in reserved:
            candidate, k = f"{safe}_{k}", k + 1
        taken.add(candidate)
        out[given] = candidate
    return out
