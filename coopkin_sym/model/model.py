"""Validated, immutable description of a cooperating robot system.

A model is what a model file (YAML, JSON or a Python dict, DESIGN section 3) says,
checked and with every number exact: a SymPy ``Rational`` or a polynomial with
rational coefficients in the declared parameters (each a positive ``Symbol``).
Nothing here computes kinematics; see :mod:`coopkin_sym.analysis.kinematics`.

Example
-------
>>> from coopkin_sym.model.model import load_model
>>> m = load_model({
...     "name": "one arm", "parameters": ["L"],
...     "arms": [{"name": "a", "joints": [
...         {"name": "q1", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]}]}],
...     "contacts": [{"name": "c", "link": "a/1", "point": ["L", 0, 0],
...                   "normal": [1, 0, 0], "model": "hard"}]})
>>> [j.name for j in m.joints]
['q1']
"""

from __future__ import annotations

import difflib
import keyword
import os
import re
import reprlib
from collections.abc import Mapping
from dataclasses import dataclass, replace
from fractions import Fraction
from pathlib import Path
from typing import Any, Literal

import sympy as sp
from pydantic import BaseModel, ConfigDict, StrictBool, StrictStr, ValidationError

from coopkin_sym.errors import ArgumentTypeError, ModelError, UndeclaredSymbol, UrdfError
from coopkin_sym.exact.angles import ExactAngle, tangent_name
from coopkin_sym.exact.parse import NumberError, brief, parse_number
from coopkin_sym.model.contacts import contact_kind, contact_names, listed, planar_names
from coopkin_sym.model.dh import (
    CONVENTIONS,
    IDENTITY,
    DHRow,
    Frame,
    dh_joints,
    frame_from_xyz_rpy,
    in_base,
)
from coopkin_sym.model.examples import example_path, list_examples
from coopkin_sym.model.trees import TreeError, check_tree, read_file
from coopkin_sym.model.urdf import (
    DEFAULT_BOUND,
    IgnoredJoint,
    Renamed,
    Snapped,
    read_urdf,
    variable_names,
)

JointType = Literal["revolute", "prismatic"]
#: The name of a registered contact model (see :mod:`coopkin_sym.model.contacts`).
ContactModel = str
#: The shipped contact models (the registry may hold more: read
#: :func:`coopkin_sym.model.contacts.contact_names`).
CONTACT_MODELS: tuple[str, ...] = contact_names()
#: The components of an object twist, spatial and planar.
SPATIAL_TWIST: tuple[str, ...] = ("v_x", "v_y", "v_z", "w_x", "w_y", "w_z")
PLANAR_TWIST: tuple[str, ...] = ("v_x", "v_y", "w_z")
JOINT_TYPES: tuple[str, ...] = ("revolute", "prismatic")

Vector = tuple[sp.Expr, sp.Expr, sp.Expr]



@dataclass(frozen=True)
class Joint:
    """One joint, described at the home pose (all joint variables zero).

    ``axis`` is an exact unit vector for a revolute joint and a nonzero direction for
    a prismatic one; ``point`` is a point on a revolute joint's axis (``None`` for a
    prismatic joint without one).

    Example
    -------
    >>> j = load_model("paper-case1-hard").arms[0].joints[0]
    >>> j.name, j.type, j.axis
    ('q1', 'revolute', (0, 0, 1))
    """

    name: str
    type: JointType
    axis: Vector
    point: Vector | None
    actuated: bool = True


@dataclass(frozen=True)
class Arm:
    """A serial chain; ``joints`` run from the base outwards. ``frames`` are the link
    frames at home (``0`` the base placement, ``k`` the link moved by joint ``k``), in
    the base frame, for an arm given as a DH table; None otherwise. ``links`` names the
    links of an arm read from a URDF file: ``(name, k, frame)``, ``k`` the moving
    joints up to it.

    Example
    -------
    >>> arm = load_model("paper-case2-hard").arms[0]
    >>> arm.name, [j.name for j in arm.joints], arm.frames
    ('s1', ['q1', 'q2', 'q3', 'q4'], None)
    """

    name: str
    joints: tuple[Joint, ...]
    frames: tuple[Frame, ...] | None = None
    links: tuple[tuple[str, int, Frame], ...] | None = None


@dataclass(frozen=True)
class Contact:
    """A contact between the object and a link, at the home pose.

    ``arm`` is the index of the arm in :attr:`Model.arms`, or ``None`` for the ground
    (``link: base``); ``link`` is ``K`` for the link moved by joint ``K`` of that arm
    (1-based), 0 for the arm's fixed base (always 0 for the ground).
    ``normal`` is an exact unit vector, or ``None`` when the file gives none (allowed
    only for a model whose rows need no normal, e.g. ``hard`` and ``complete``).

    Example
    -------
    >>> c = load_model("paper-case1-hard").contacts[0]
    >>> c.name, c.arm, c.link, c.model
    ('c1', 0, 1, 'hard')
    """

    name: str
    arm: int | None
    link: int
    point: Vector
    normal: Vector | None
    model: ContactModel


@dataclass(frozen=True)
class Model:
    """A whole system: parameters, arms, contacts; ``object_frame`` is where object
    twists are referenced (a point, in the base frame) and the axes they are written
    in (a rotation whose columns are those axes), or None for the base origin and axes.
    ``snapped`` lists the floats of URDF files replaced by exact values, ``renamed``
    the names of URDF files that are not identifiers and the names used for them,
    ``ignored`` the joints off the chains of URDF arms that an arm could not have
    (mimic, floating, planar joints). A ``planar``
    system moves in the base's xy-plane: its object twists are ``(v_x, v_y, w_z)``.
    ``locked`` names joints held still: they keep their angle or displacement (a
    configuration variable) but have no velocity (their columns of ``D`` are zero);
    see :meth:`with_actuators_locked`.

    Example
    -------
    >>> m = load_model("paper-case1-hard")
    >>> m.joint_names, [p.name for p in m.parameters], len(m.contacts)
    (('q1', 'q2'), ['L'], 2)
    """

    name: str
    parameters: tuple[sp.Symbol, ...]
    arms: tuple[Arm, ...]
    contacts: tuple[Contact, ...]
    source: str | None = None
    object_frame: Frame | None = None
    snapped: tuple[Snapped, ...] = ()
    planar: bool = False
    locked: frozenset[str] = frozenset()
    renamed: tuple[Renamed, ...] = ()
    ignored: tuple[IgnoredJoint, ...] = ()

    @property
    def object_dim(self) -> int:
        """Components of an object twist: 6, or 3 for a planar system.

        Example
        -------
        >>> load_model("paper-case1-hard").object_dim
        6
        """
        return 3 if self.planar else 6

    @property
    def twist_names(self) -> tuple[str, ...]:
        """The components of an object twist, in order.

        Example
        -------
        >>> load_model("paper-case1-hard").twist_names[3:]
        ('w_x', 'w_y', 'w_z')
        """
        return PLANAR_TWIST if self.planar else SPATIAL_TWIST

    def in_base_frame(self) -> Model:
        """The same system with object twists at the base origin, in base axes (no
        number depends on the object frame: the searches for numbers use this one).

        Example
        -------
        >>> load_model("paper-case1-hard").in_base_frame().object_frame is None
        True
        """
        return self if self.object_frame is None else replace(self, object_frame=None)

    @property
    def joints(self) -> tuple[Joint, ...]:
        """All joints in file order: the column order of D and the order of qdot."""
        return tuple(j for arm in self.arms for j in arm.joints)

    @property
    def joint_names(self) -> tuple[str, ...]:
        return tuple(j.name for j in self.joints)

    @property
    def passive_joints(self) -> tuple[str, ...]:
        """The joints without a motor (``actuated: false``), in file order.

        Example
        -------
        >>> load_model("five-bar").passive_joints
        ('q2', 'q4')
        """
        return tuple(j.name for j in self.joints if not j.actuated)

    def with_actuators_locked(self) -> Model:
        """The same system with every actuated joint held still (``locked``): what
        moves then are the passive joints and the object. Its numbers give the
        motions the passive joints leave free (:mod:`coopkin_sym.analysis.passive`).

        Example
        -------
        >>> load_model("five-bar").with_actuators_locked().locked == {"q1", "q3"}
        True
        """
        return replace(self, locked=frozenset(j.name for j in self.joints if j.actuated))

    def joint_offset(self, arm: int) -> int:
        """Index in :attr:`joints` of the first joint of arm ``arm``."""
        return sum(len(a.joints) for a in self.arms[:arm])


# ----------------------------------------------------------------------------- loading

_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
#: A URDF link name that a contact can write after its arm (``ARM/LINK``): not all
#: digits (``ARM/K`` counts joints), no slash, no space.
_LINK_NAME = re.compile(r"(?!\d+$)[^/\s]+")

#: Names a parameter or joint may not have: they mean something else in SymPy text.
RESERVED_NAMES: frozenset[str] = frozenset(
    {"pi", "E", "I", "oo", "nan", "zoo", "atan", "sqrt", "Rational", "Integer"}
) | frozenset(keyword.kwlist)


class _Entry(BaseModel):
    """Structure of one entry of a model file (types only; meaning is checked later)."""

    model_config = ConfigDict(extra="forbid")


class _TopIn(_Entry):
    name: StrictStr | None = None
    parameters: list[Any] | None = None
    arms: list[Any] | None = None
    contacts: list[Any] | None = None
    object: Any = None
    planar: StrictBool | None = None


class _ObjectIn(_Entry):
    point: list[Any] | None = None
    rpy: list[Any] | None = None


class _ArmIn(_Entry):
    name: StrictStr
    joints: list[Any] | None = None
    dh: list[Any] | None = None
    convention: StrictStr | None = None
    base: Any = None
    urdf: StrictStr | None = None
    tip: StrictStr | None = None
    prefix: StrictStr | None = None
    snap: Any = None
    passive: list[StrictStr] | None = None


#: The keys of an arm that say what it is made of (and, for an arm read from a URDF
#: file, which chain and joint names): when one of them cannot be read, the arm is not
#: built, and contacts on it are not checked against it.
_ARM_SHAPE = frozenset({"joints", "dh", "urdf"})
_URDF_CHOICE = frozenset({"tip", "prefix"})


class _DHRowIn(_Entry):
    name: StrictStr
    type: StrictStr
    actuated: StrictBool = True
    theta: Any = 0
    d: Any = 0
    a: Any = 0
    alpha: Any = 0


class _PlacementIn(_Entry):
    xyz: list[Any] | None = None
    rpy: list[Any] | None = None


class _JointIn(_Entry):
    name: StrictStr
    type: StrictStr
    axis: list[Any]
    point: list[Any] | None = None
    actuated: StrictBool = True


class _ContactIn(_Entry):
    name: StrictStr
    link: StrictStr
    point: list[Any]
    normal: list[Any] | None = None
    model: StrictStr
    frame: StrictStr | None = None


def _join(path: str, loc: tuple[int | str, ...] | list[int | str]) -> str:
    """``arms[0]`` + ``("joints", 1, "type")`` -> ``arms[0].joints[1].type``."""
    out = path
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            out += f".{part}" if out else str(part)
    return out or "(top level)"


_REPR = reprlib.Repr()
_REPR.maxlevel, _REPR.maxstring, _REPR.maxother, _REPR.maxlong = 2, 60, 60, 60
_REPR.maxlist = _REPR.maxdict = _REPR.maxtuple = 4


def _brief(value: object) -> str:
    """A short view of a value (never the repr of a whole large one)."""
    try:
        text = _REPR.repr(value)
    except ValueError:           # an integer too long to print
        text = f"<{type(value).__name__}>"
    text = " ".join(text.split())
    return text if len(text) <= 60 else text[:57] + "..."


def _render(exc: ValidationError, path: str, cls: type[_Entry]) -> list[str]:
    """Pydantic's errors, one line each, in the model file's own terms."""
    out = []
    for err in exc.errors(include_url=False):
        loc, kind, value = tuple(err["loc"]), err["type"], err.get("input")
        if kind == "missing":
            out.append(f"{_join(path, loc[:-1])}: missing key '{loc[-1]}'")
        elif kind == "extra_forbidden":
            key = str(loc[-1])
            close = difflib.get_close_matches(key, list(cls.model_fields), n=1)
            hint = f" (did you mean '{close[0]}'?)" if close else ""
            out.append(f"{_join(path, loc[:-1])}: unknown key {brief(key)}{hint}")
        elif kind == "invalid_key":
            out.append(f"{_join(path, loc[:-1])}: key {_brief(loc[-1])} is not a name "
                       f"(keys are words such as 'name')")
        elif kind == "string_type":
            out.append(f"{_join(path, loc)}: expected text, got {_brief(value)}")
        elif kind == "list_type":
            out.append(f"{_join(path, loc)}: expected a list, got {_brief(value)}")
        elif kind in ("model_type", "model_attributes_type", "dict_type"):
            out.append(f"{_join(path, loc)}: expected a mapping (key: value), "
                       f"got {_brief(value)}")
        else:
            message = " ".join(str(err["msg"]).split())
            out.append(f"{_join(path, loc)}: {message[:1].lower()}{message[1:]}")
    return out


def _validate(cls: type[_Entry], raw: object, path: str,
              problems: list[str]) -> tuple[Any, set[str]]:
    """Validate ``raw`` against ``cls``; collect problems.

    Returns the validated entry and the set of fields that were wrong. When only some
    fields are wrong (unknown keys, bad optional fields) the rest is still returned,
    so that later checks can find more problems; otherwise the entry is ``None``.
    """
    try:
        return cls.model_validate(raw), set()
    except ValidationError as exc:
        problems.extend(_render(exc, path, cls))
        if not isinstance(raw, Mapping):
            return None, set()
        bad = {str(e["loc"][0]) for e in exc.errors() if e["loc"]}
        kept = {k: v for k, v in raw.items() if k in cls.model_fields and k not in bad}
        try:
            return cls.model_validate(kept), bad
        except ValidationError:
            return None, bad


class _Names:
    """Every name in the model must be unique (and valid); remembers where each is."""

    def __init__(self, problems: list[str]):
        self.problems = problems
        self.where: dict[str, str] = {}   # name -> path of its "name" field

    def add(self, name: str, path: str, *, symbol: bool) -> bool:
        if not _IDENTIFIER.fullmatch(name):
            self.problems.append(f"{path}: {brief(name)} is not a valid name (letters, digits "
                                 f"and underscores, not starting with a digit)")
            return False
        if symbol and name in RESERVED_NAMES:
            self.problems.append(f"{path}: '{name}' is reserved (it means something else "
                                 f"in SymPy text); choose another name")
            return False
        if name in self.where:
            self.problems.append(f"{path}: duplicate name '{name}' (already used at "
                                 f"{self.where[name]})")
            return False
        self.where[name] = path
        return True


class _UndeclaredProblem(str):
    """The line of a number that uses an undeclared name: not reported when the
    parameter list could not be read (the names it meant are unknown)."""


def _number_problem(exc: NumberError) -> str:
    return _UndeclaredProblem(exc) if isinstance(exc, UndeclaredSymbol) else str(exc)


def _vector(raw: list[Any], path: str, parameters: dict[str, sp.Symbol],
            problems: list[str], *, rational: bool) -> Vector | None:
    """Three exact numbers; ``rational`` forbids parameters."""
    if len(raw) != 3:
        problems.append(f"{path}: expected 3 numbers, got {len(raw)}")
        return None
    out = []
    for value in raw:
        try:
            number = parse_number(value, parameters, path)
        except NumberError as exc:
            problems.append(_number_problem(exc))
            return None
        if rational and not number.is_Rational:
            problems.append(f"{path}: {brief(value)} uses a parameter; this vector must have "
                            f"rational entries without parameters")
            return None
        out.append(number)
    return (out[0], out[1], out[2])


def _unit_problem(v: Vector) -> str | None:
    """Why ``v`` is not an exact unit vector, or ``None`` if it is one."""
    length2 = sum((x**2 for x in v), sp.Integer(0))
    if length2 == 1:
        return None
    if length2 == 0:
        return "not a unit vector (zero vector)"
    hint = ""
    root = sp.sqrt(length2)
    if root.is_Rational:
        hint = "; did you mean [" + ", ".join(str(x / root) for x in v) + "]?"
    return f"not a unit vector (squared length {length2}){hint}"


def _build(tree: object, source: str | None, default_name: str) -> Model:
    """Validate a model tree and convert it into a :class:`Model`."""
    problems: list[str] = []
    if tree is None:
        raise ModelError(["(top level): the model is empty"], source)
    top, top_bad = _validate(_TopIn, tree, "", problems)
    if top is None:
        raise ModelError(problems, source)
    names = _Names(problems)

    parameters: dict[str, sp.Symbol] = {}
    parameters_unknown = "parameters" in top_bad   # which names were meant is unknown
    for i, pname in enumerate(top.parameters or []):
        path = f"parameters[{i}]"
        if not isinstance(pname, str):
            problems.append(f"{path}: expected a name, got {_brief(pname)}")
            parameters_unknown = True
        elif pname in names.where:
            names.add(pname, path, symbol=True)   # a duplicate: declared all the same
        elif names.add(pname, path, symbol=True):
            parameters[pname] = sp.Symbol(pname, positive=True)
        else:
            parameters_unknown = True

    arms: list[Arm] = []
    snapped: list[Snapped] = []
    urdf_notes: tuple[list[Renamed], list[IgnoredJoint]] = ([], [])
    arm_joints: dict[str, tuple[int, int] | None] = {}   # name -> (index, joints)
    joint_paths: dict[str, str] = {}
    nameless_arm = False   # an arm without a usable name failed
    for i, raw_arm in enumerate(top.arms or []):
        apath = f"arms[{i}]"
        arm, arm_bad = _validate(_ArmIn, raw_arm, apath, problems)
        if arm is None:
            if isinstance(raw_arm, Mapping) and isinstance(raw_arm.get("name"), str):
                arm_joints.setdefault(raw_arm["name"], None)   # exists, but unusable
            else:
                nameless_arm = True
            continue
        duplicate = arm.name in names.where
        if not names.add(arm.name, f"{apath}.name", symbol=False) and not duplicate:
            arm_joints.setdefault(arm.name, None)   # contacts cannot name it
        if arm_bad & _ARM_SHAPE or (arm.urdf is not None and arm_bad & _URDF_CHOICE):
            # what the arm is made of could not be read: it has problems, not more
            arm_joints.setdefault(arm.name, None)
            continue
        if arm.urdf is not None:
            built = _urdf_arm(arm, apath, parameters, names, problems, joint_paths,
                              source, snapped, urdf_notes)
            arm_joints.setdefault(arm.name, (i, len(built.joints)) if built else None)
            if built is not None:
                arms.append(built)
            continue
        for key in ("tip", "prefix", "snap"):
            if getattr(arm, key) is not None:
                problems.append(f"{apath}.{key}: only an arm read from a URDF file (urdf) "
                                f"has a {key}")
        if arm.passive is not None:
            problems.append(f"{apath}.passive: only an arm read from a URDF file lists "
                            f"its passive joints; mark a joint or a DH row with "
                            f"actuated: false")
        if arm.dh is not None:
            built = _dh_arm(arm, apath, parameters, names, problems, joint_paths)
            arm_joints.setdefault(arm.name, (i, len(arm.dh)) if built else None)
            if built is not None:
                arms.append(built)
            continue
        for key in ("convention", "base"):
            if getattr(arm, key) is not None:
                problems.append(f"{apath}.{key}: only an arm given by a DH table (dh) has "
                                f"a {key}")
        if arm.joints is None:
            problems.append(f"{apath}: missing key 'joints' (or 'dh', a DH table)")
            arm_joints.setdefault(arm.name, None)
            continue
        arm_joints.setdefault(arm.name, (i, len(arm.joints)))
        if not arm.joints:
            problems.append(f"{apath}.joints: at least one joint is needed (contacts on "
                            f"the ground use link: base)")
        joints = []
        for k, raw_joint in enumerate(arm.joints):
            jpath = f"{apath}.joints[{k}]"
            joint = _joint(raw_joint, jpath, parameters, names, problems)
            if joint is not None:
                joints.append(joint)
                joint_paths[joint.name] = jpath
        arms.append(Arm(arm.name, tuple(joints)))
    if not top.arms and "arms" not in top_bad:
        problems.append("arms: at least one arm with one joint is needed")

    for jname, jpath in joint_paths.items():
        clash = tangent_name(jname)
        if clash in names.where:
            problems.append(f"{names.where[clash]}: name '{clash}' clashes with the "
                            f"half-angle variable t_{jname} of joint {jname} ({jpath})")

    contacts: list[Contact] = []
    contact_paths: list[str] = []
    frames = {arm.name: arm for arm in arms}
    for i, raw_contact in enumerate(top.contacts or []):
        contact = _contact(raw_contact, f"contacts[{i}]", parameters, names, arm_joints,
                           problems, frames, nameless_arm or not arm_joints)
        if contact is not None:
            contacts.append(contact)
            contact_paths.append(f"contacts[{i}]")
    if not top.contacts and "contacts" not in top_bad:
        problems.append("contacts: at least one contact is needed")

    object_frame = None
    if top.object is not None:
        entry, bad = _validate(_ObjectIn, top.object, "object", problems)
        if entry is not None and not bad:
            object_frame = _placement({"xyz": entry.point, "rpy": entry.rpy}, "object",
                                      parameters, problems, point_key="point")
            if object_frame is not None:
                object_frame = (sp.ImmutableMatrix(object_frame[0]), object_frame[1])

    if top.planar:
        _planar_problems(arms, joint_paths, zip(contact_paths, contacts, strict=True),
                         object_frame, problems)
    if parameters_unknown:   # numbers that use a parameter: its entry has the problem
        problems[:] = [p for p in problems if not isinstance(p, _UndeclaredProblem)]
    if problems:
        raise ModelError([str(p) for p in problems], source)
    return Model(name=top.name if top.name is not None else default_name,
                 parameters=tuple(parameters.values()), arms=tuple(arms),
                 contacts=tuple(contacts), source=source, object_frame=object_frame,
                 snapped=tuple(snapped), planar=bool(top.planar),
                 renamed=tuple(urdf_notes[0]), ignored=tuple(urdf_notes[1]))


def _vec_text(v) -> str:
    text = "(" + ", ".join(sp.sstr(x) for x in v) + ")"
    return text if len(text) <= 60 else text[:57] + "..."


def _is_zero(x: sp.Expr) -> bool:
    return sp.simplify(sp.expand(x)) == 0


def _planar_problems(arms: list[Arm], joint_paths: dict[str, str], contacts,
                     object_frame: Frame | None, problems: list[str]) -> None:
    """What keeps a ``planar: true`` system out of the xy-plane: revolute axes along
    z, prismatic axes, joint points, contact points and normals in the plane (at
    home, so at every configuration), no soft contact, an object frame turned about
    z only."""
    where = "planar: true needs"
    for arm in arms:
        for joint in arm.joints:
            path = joint_paths.get(joint.name, f"arm {arm.name}, joint {joint.name}")
            if joint.type == "revolute" and not (_is_zero(joint.axis[0])
                                                 and _is_zero(joint.axis[1])):
                problems.append(f"{path}.axis: {where} a revolute axis along z (0, 0, 1) "
                                f"or (0, 0, -1), got {_vec_text(joint.axis)}")
            if joint.type == "prismatic" and not _is_zero(joint.axis[2]):
                problems.append(f"{path}.axis: {where} a prismatic axis in the xy-plane "
                                f"(z = 0), got {_vec_text(joint.axis)}")
            if joint.point is not None and not _is_zero(joint.point[2]):
                problems.append(f"{path}.point: {where} joint points in the xy-plane "
                                f"(z = 0), got {_vec_text(joint.point)}")
    for path, contact in contacts:
        kind = contact_kind(contact.model)
        if kind is not None and kind.planar is None:
            why = f" ({kind.no_planar})" if kind.no_planar else ""
            problems.append(f"{path}.model: a {kind.name} contact has no planar model"
                            f"{why}; use {listed(planar_names())}")
        if not _is_zero(contact.point[2]):
            problems.append(f"{path}.point: {where} contact points in the xy-plane "
                            f"(z = 0 in the base frame at home), got "
                            f"{_vec_text(contact.point)}")
        if contact.normal is not None and not _is_zero(contact.normal[2]):
            problems.append(f"{path}.normal: {where} normals in the xy-plane (z = 0 in "
                            f"the base frame at home), got {_vec_text(contact.normal)}")
    if object_frame is not None:
        rotation, origin = object_frame
        if not _is_zero(origin[2]) or not _is_zero(rotation[2, 2] - 1):
            problems.append(f"object: {where} an object frame in the xy-plane turned "
                            f"about z only (point z = 0, rpy = [0, 0, yaw])")


def _joint(raw: object, path: str, parameters: dict[str, sp.Symbol], names: _Names,
           problems: list[str]) -> Joint | None:
    entry, bad = _validate(_JointIn, raw, path, problems)
    if entry is None:
        return None
    before = len(problems)
    names.add(entry.name, f"{path}.name", symbol=True)
    jtype = entry.type
    if jtype not in JOINT_TYPES:
        problems.append(f"{path}.type: unknown joint type {brief(jtype)} (expected revolute "
                        f"or prismatic)")
    axis = _vector(entry.axis, f"{path}.axis", parameters, problems, rational=True)
    if axis is not None and jtype == "revolute":
        why = _unit_problem(axis)
        if why:
            problems.append(f"{path}.axis: {why}")
    elif axis is not None and jtype == "prismatic" and all(x == 0 for x in axis):
        problems.append(f"{path}.axis: zero vector; a prismatic axis needs a nonzero "
                        f"direction")
    point = None
    if entry.point is not None:
        point = _vector(entry.point, f"{path}.point", parameters, problems, rational=False)
    elif jtype == "revolute" and "point" not in bad:
        problems.append(f"{path}.point: required for a revolute joint (a point on its "
                        f"axis)")
    if len(problems) > before or bad or axis is None:
        return None
    return Joint(entry.name, jtype, axis, point, entry.actuated)  # type: ignore[arg-type]


def _dh_arm(arm: Any, path: str, parameters: dict[str, sp.Symbol], names: _Names,
            problems: list[str], joint_paths: dict[str, str]) -> Arm | None:
    """An arm given by a DH table: its joints at home and its link frames."""
    before = len(problems)
    if arm.joints is not None:
        problems.append(f"{path}: give either joints or dh (a DH table), not both")
    convention = arm.convention if arm.convention is not None else "standard"
    if convention not in CONVENTIONS:
        problems.append(f"{path}.convention: expected standard (Denavit-Hartenberg) or "
                        f"modified (Craig), got {brief(convention)}")
    base = _placement(arm.base, f"{path}.base", parameters, problems)
    if not arm.dh:
        problems.append(f"{path}.dh: at least one row (joint) is needed")
    rows = []
    passive: set[str] = set()
    for k, raw_row in enumerate(arm.dh):
        rpath = f"{path}.dh[{k}]"
        row, bad = _validate(_DHRowIn, raw_row, rpath, problems)
        if row is None or bad:
            continue
        names.add(row.name, f"{rpath}.name", symbol=True)
        if row.type not in JOINT_TYPES:
            problems.append(f"{rpath}.type: unknown joint type {brief(row.type)} (expected "
                            f"revolute or prismatic)")
            continue
        theta = _angle(row.theta, f"{rpath}.theta", problems)
        alpha = _angle(row.alpha, f"{rpath}.alpha", problems)
        d = _number(row.d, f"{rpath}.d", parameters, problems)
        a = _number(row.a, f"{rpath}.a", parameters, problems)
        if None in (theta, alpha, d, a):
            continue
        rows.append(DHRow(row.name, row.type, theta, d, a, alpha))
        joint_paths[row.name] = rpath
        if not row.actuated:
            passive.add(row.name)
    if len(problems) > before or base is None:
        return None
    try:
        dh, frames = dh_joints(rows, convention, base, where=f"{path}.dh")
    except NumberError as exc:     # link frames whose numbers outgrow the budget
        problems.append(str(exc))
        return None
    joints = tuple(Joint(j.name, j.type, j.axis, j.point,  # type: ignore[arg-type]
                         j.name not in passive) for j in dh)
    return Arm(arm.name, joints, tuple((sp.ImmutableMatrix(r), p) for r, p in frames))


def _urdf_arm(arm: Any, path: str, parameters: dict[str, sp.Symbol], names: _Names,
              problems: list[str], joint_paths: dict[str, str], source: str | None,
              snapped: list[Snapped],
              notes: tuple[list[Renamed], list[IgnoredJoint]]) -> Arm | None:
    """An arm read from a URDF file (relative paths: from the model file's folder).
    Joint names that are not identifiers, are reserved or are parameters, and link
    names that ``ARM/LINK`` cannot write, get safe names
    (:func:`~coopkin_sym.model.urdf.variable_names`), listed in ``notes`` with the
    joints off the chain that were ignored."""
    before = len(problems)
    for key in ("joints", "dh", "convention"):
        if getattr(arm, key) is not None:
            problems.append(f"{path}.{key}: an arm read from a URDF file has no {key}")
    base = _placement(arm.base, f"{path}.base", parameters, problems)
    bound = DEFAULT_BOUND
    if arm.snap is not None:
        try:
            value = parse_number(arm.snap, {}, f"{path}.snap")
            if not 0 < value < 1:
                raise NumberError(f"{path}.snap", f"expected a bound between 0 and 1 "
                                  f"(radians), got {brief(arm.snap)}")
            bound = Fraction(str(value))
        except NumberError as exc:
            problems.append(str(exc))
    prefix = arm.prefix or ""
    if prefix and not _IDENTIFIER.fullmatch(prefix):
        problems.append(f"{path}.prefix: {brief(prefix)} is not a valid start of a name "
                        f"(letters, digits and underscores, not starting with a digit)")
    if len(problems) > before or base is None:
        return None
    where = Path(arm.urdf)
    if not where.is_absolute():
        where = (Path(source).parent if source else Path.cwd()) / where
    try:
        read = read_urdf(where, arm.tip, base, bound)
    except UrdfError as exc:
        problems.append(f"{path}.urdf: {exc}")
        return None
    label = f"{path} ({where.name})"
    safe = variable_names([j.name for j in read.joints], prefix,
                          RESERVED_NAMES | frozenset(parameters))
    joints = []
    passive = set(arm.passive or ())
    for k, j in enumerate(read.joints):
        name = safe[j.name]
        if name != prefix + j.name:
            notes[0].append(Renamed(label, "joint", j.name, name))
        if names.add(name, f"{path}.urdf: joint {k + 1} ({brief(j.name)})", symbol=True):
            joint_paths[name] = f"{path}.urdf"
        joints.append(Joint(name, j.type, j.axis, j.point,  # type: ignore[arg-type]
                            not passive & {j.name, name}))
    unknown = sorted(passive - {j.name for j in read.joints} - set(safe.values()))
    if unknown:
        what = "is not a moving joint" if len(unknown) == 1 else "are not moving joints"
        problems.append(f"{path}.passive: {', '.join(map(brief, unknown))} {what} of the "
                        f"chain read from {where.name} (its joints: "
                        f"{', '.join(j.name for j in read.joints)})")
    if len(problems) > before:
        return None
    snapped.extend(Snapped(f"{label}: {s.where}", s.given, s.exact, s.error)
                   for s in read.snapped)
    notes[1].extend(replace(ignored, where=label) for ignored in read.ignored)
    link_names = [name for name, _, _ in read.links]
    written = [name for name in link_names if _LINK_NAME.fullmatch(name)]
    link_safe = variable_names([n for n in link_names if not _LINK_NAME.fullmatch(n)],
                               reserved=frozenset(written), lead="link_")
    for given, name in link_safe.items():
        notes[0].append(Renamed(label, "link", given, name))
    links = tuple((link_safe.get(name, name), k, (sp.ImmutableMatrix(r), p))
                  for name, k, (r, p) in read.links)
    return Arm(arm.name, tuple(joints), None, links)


def _angle(value: Any, path: str, problems: list[str]) -> ExactAngle | None:
    """An exact angle with rational cosine and sine (the one angle parser)."""
    try:
        return ExactAngle.parse(value, path)
    except NumberError as exc:
        problems.append(str(exc))
        return None


def _number(value: Any, path: str, parameters: dict[str, sp.Symbol],
            problems: list[str]) -> sp.Expr | None:
    try:
        return parse_number(value, parameters, path)
    except NumberError as exc:
        problems.append(_number_problem(exc))
        return None


def _placement(raw: Any, path: str, parameters: dict[str, sp.Symbol],
               problems: list[str], point_key: str = "xyz") -> Frame | None:
    """A placement (``xyz``, ``rpy``), the identity when not given; ``point_key``
    names the origin's key in messages."""
    if raw is None:
        return IDENTITY
    entry, bad = _validate(_PlacementIn, raw, path, problems)
    if entry is None or bad:
        return None
    xyz = (_vector(entry.xyz, f"{path}.{point_key}", parameters, problems, rational=False)
           if entry.xyz is not None else (0, 0, 0))
    rpy_raw = entry.rpy if entry.rpy is not None else [0, 0, 0]
    if len(rpy_raw) != 3:
        problems.append(f"{path}.rpy: expected 3 angles (roll, pitch, yaw), got "
                        f"{len(rpy_raw)}")
        return None
    rpy = [_angle(v, f"{path}.rpy[{k}]", problems) for k, v in enumerate(rpy_raw)]
    if xyz is None or None in rpy:
        return None
    return frame_from_xyz_rpy(xyz, rpy)


def _contact(raw: object, path: str, parameters: dict[str, sp.Symbol], names: _Names,
             arm_joints: dict[str, tuple[int, int] | None],
             problems: list[str], frames: Mapping[str, Arm],
             nameless_arm: bool = False) -> Contact | None:
    """A contact; its link is not checked when it names an arm that could not be read
    (``arm_joints`` maps it to None: the arm's own entry says why), nor when it names
    an unknown arm while an arm without a usable name could not be read, or no arm
    could (``nameless_arm``). Its other entries are checked all the same."""
    entry, bad = _validate(_ContactIn, raw, path, problems)
    if entry is None:
        return None
    before = len(problems)
    names.add(entry.name, f"{path}.name", symbol=False)
    arm_index: int | None = None
    link = 0
    text = entry.link.strip()
    match = re.fullmatch(r"([^/\s]+)\s*/\s*(\d+)", text)
    named = re.fullmatch(r"([^/\s]+)\s*/\s*([^/\s]+)", text)
    link_frame = None
    head, slash, _ = text.rpartition("/")
    head = head.strip()
    on_failed_arm = bool(slash) and (arm_joints[head] is None if head in arm_joints
                                     else nameless_arm)
    if on_failed_arm:
        pass   # the arm's own entry says what is wrong
    elif match is None and named is not None and named.group(1) in frames \
            and frames[named.group(1)].links is not None:
        # a URDF link by its name: its moving joints, and its frame
        by_name = {name: (k, frame) for name, k, frame in frames[named.group(1)].links}
        if named.group(2) not in by_name:
            problems.append(f"{path}.link: arm {named.group(1)} has no link "
                            f"{brief(named.group(2))} on its chain (links: "
                            f"{', '.join(by_name)})")
            return None
        link, link_frame = by_name[named.group(2)]
        arm_index = arm_joints[named.group(1)][0]  # type: ignore[index]
        match = named
    elif text == "base":
        pass
    elif match is None:
        problems.append(f"{path}.link: expected ARM/K (the link moved by joint K of arm "
                        f"ARM, ARM/0 its base) or base, got {brief(entry.link)}")
    elif match.group(1) not in arm_joints:
        problems.append(f"{path}.link: unknown arm {brief(match.group(1))} "
                        f"(arms: {', '.join(arm_joints)})")
    elif arm_joints[match.group(1)] is not None:
        arm_index, count = arm_joints[match.group(1)]  # type: ignore[misc]
        digits = match.group(2)
        link = int(digits) if len(digits) <= 9 else count + 1
        if link > count:
            plural = "joint" if count == 1 else "joints"
            problems.append(f"{path}.link: arm {match.group(1)} has {count} {plural}, "
                            f"no link {digits if len(digits) <= 20 else digits[:12] + '...'}")
    point = _vector(entry.point, f"{path}.point", parameters, problems, rational=False)
    kind = contact_kind(entry.model)
    model = kind.name if kind is not None else entry.model
    if kind is None:
        problems.append(f"{path}.model: unknown contact model {brief(model)} (expected "
                        f"{listed(contact_names())})")
    normal = None
    if entry.normal is not None:
        normal = _vector(entry.normal, f"{path}.normal", parameters, problems,
                         rational=True)
        why = _unit_problem(normal) if normal is not None else None
        if why:
            problems.append(f"{path}.normal: {why}")
    elif kind is not None and kind.needs_normal and "normal" not in bad:
        problems.append(f"{path}.normal: required for a {model} contact")
    if entry.frame not in (None, "base", "link"):
        problems.append(f"{path}.frame: expected base (the default: point and normal in "
                        f"the base frame at home) or link (in the link's DH frame), got "
                        f"{brief(entry.frame)}")
    if len(problems) > before or bad or point is None or on_failed_arm:
        return None
    if entry.frame == "link":
        arm_name = match.group(1) if match is not None else None
        if arm_name is not None and arm_name not in frames:
            return None   # the arm itself could not be read: its entry says why
        arm_frames = frames[arm_name].frames if arm_name is not None else None
        if link_frame is None and arm_frames is None:
            problems.append(f"{path}.frame: link frames exist only for an arm given by a "
                            f"DH table or a URDF file (a URDF link by its name); "
                            f"{brief(entry.link)} is not on one")
            return None
        point, normal = in_base(link_frame if link_frame is not None else arm_frames[link],
                                point, normal)
    return Contact(entry.name, arm_index, link, point, normal, model)  # type: ignore[arg-type]


def _read_tree(path: Path, source: str) -> object:
    """Read a YAML or JSON file into a plain tree (see :mod:`coopkin_sym.model.trees`: every
    float kept as its text, budgets on size, nesting and aliases)."""
    if path.suffix.lower() == ".urdf":
        raise ModelError([f"a URDF file describes one robot, not a cooperating system: "
                          f"write a model file with an arm 'urdf: {path.name}' and "
                          f"contacts on its links (docs/model-format.md, Arms from URDF "
                          f"files)"], source)
    try:
        return read_file(path)
    except TreeError as exc:
        raise ModelError([str(exc)], source) from None


def _source_name(name: str) -> str:
    """A file name as shown in messages (very long ones shortened)."""
    return name if len(name) <= 200 else name[:120] + "..." + name[-40:]


def model_of(source: Any) -> Model:
    """The model of ``source``: a :class:`Model` itself, or the ``.model`` of an object
    that holds one (a :class:`~coopkin_sym.System`, an analysis). The layers below the
    public facade take either, without importing it.

    Example
    -------
    >>> from coopkin_sym import load
    >>> model_of(load("paper-case1-hard")).joint_names
    ('q1', 'q2')
    """
    model = source if isinstance(source, Model) else getattr(source, "model", None)
    if not isinstance(model, Model):
        raise ArgumentTypeError(f"expected a model or a system, got {type(source).__name__}")
    return model


def load_model(source: str | os.PathLike[str] | Mapping[str, Any]) -> Model:
    """Load and validate a model (DESIGN section 3).

    Parameters
    ----------
    source : str, path or mapping
        A ``.yaml``/``.yml``/``.json`` file, the name of a shipped example
        (``"paper-case1-hard"``, see :mod:`coopkin_sym.model.examples`), or the same tree
        as a Python mapping.

    Returns
    -------
    Model
        Every number exact (``Rational`` or a polynomial in the parameters, which are
        positive ``Symbol``).

    Raises
    ------
    ModelError
        With one line per problem, each naming the entry
        (``contacts[1].normal: not a unit vector``), and the file when there is one.

    Example
    -------
    >>> m = load_model("paper-case2-hard")
    >>> m.arms[0].joints[3].type, m.contacts[1].point
    ('prismatic', (3*L, L, L))
    """
    if isinstance(source, Mapping):
        try:
            check_tree(source)
        except TreeError as exc:
            raise ModelError([f"(top level): {exc}"]) from None
        return _build(source, None, "unnamed")
    if not isinstance(source, str | os.PathLike):
        raise ModelError([f"(top level): expected a file name, an example name or a "
                          f"mapping, got {type(source).__name__}"])
    name = os.fspath(source)
    if not isinstance(name, str):
        raise ModelError(["(top level): expected a file name as text, got bytes"])
    shown = _source_name(name)
    path = Path(name)
    try:
        exists = path.exists()
    except (OSError, ValueError) as exc:
        reason = getattr(exc, "strerror", None) or str(exc)
        raise ModelError([f"cannot read the file: {reason}"], shown) from None
    if not exists:
        if isinstance(source, str) and source in list_examples():
            path = example_path(source)
            return _build(_read_tree(path, str(path)), str(path), path.stem)
        shipped = ", ".join(list_examples())
        close = difflib.get_close_matches(name, list_examples(), n=1) \
            if isinstance(source, str) else []
        hint = f"; did you mean {close[0]}?" if close else ""
        raise ModelError([f"no such file (nor a shipped example: {shipped}){hint}"], shown)
    return _build(_read_tree(path, shown), shown, path.stem)
