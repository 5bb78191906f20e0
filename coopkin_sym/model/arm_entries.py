"""The arms of a model file: joints given one by one, DH tables and URDF files, each
checked and read into an :class:`~coopkin_sym.model.structure.Arm` (problems are
collected, one line each, naming the entry).

Example
-------
>>> from coopkin_sym.model.entries import _Names
>>> problems = []
>>> read = read_arms([{"name": "a", "joints": [
...     {"name": "q1", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]}]}],
...     set(), {}, _Names(problems), problems, None)
>>> [j.name for j in read.arms[0].joints], read.arm_joints, problems
(['q1'], {'a': (0, 1)}, [])
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from fractions import Fraction
from pathlib import Path
from typing import Any

import sympy as sp

from coopkin_sym.errors import MjcfError, UrdfError
from coopkin_sym.exact.angles import tangent_name
from coopkin_sym.exact.parse import NumberError, brief, parse_number
from coopkin_sym.model.dh import CONVENTIONS, DHRow, dh_joints
from coopkin_sym.model.entries import (
    _ARM_SHAPE,
    _IDENTIFIER,
    _LINK_NAME,
    _URDF_CHOICE,
    RESERVED_NAMES,
    _angle,
    _ArmIn,
    _DHRowIn,
    _JointIn,
    _Names,
    _number,
    _placement,
    _unit_problem,
    _validate,
    _vector,
)
from coopkin_sym.model.mjcf import read_mjcf
from coopkin_sym.model.structure import JOINT_TYPES, Arm, Joint
from coopkin_sym.model.urdf import (
    DEFAULT_BOUND,
    IgnoredJoint,
    Renamed,
    Snapped,
    read_urdf,
    variable_names,
)


@dataclass
class ArmsRead:
    """What the arms of a model file gave: the arms built, the URDF floats snapped
    and the URDF names renamed or joints ignored, ``arm_joints`` (arm name -> its
    index and number of joints, ``None`` for an arm that could not be read: contacts
    on it are not checked against it), where each joint was given, and whether an
    arm without a usable name failed.

    Example
    -------
    >>> ArmsRead().arms, ArmsRead().nameless_arm
    ([], False)
    """

    arms: list[Arm] = field(default_factory=list)
    snapped: list[Snapped] = field(default_factory=list)
    notes: tuple[list[Renamed], list[IgnoredJoint]] = field(default_factory=lambda: ([], []))
    arm_joints: dict[str, tuple[int, int] | None] = field(default_factory=dict)
    joint_paths: dict[str, str] = field(default_factory=dict)
    nameless_arm: bool = False


def read_arms(raw_arms: list[Any], top_bad: set[str], parameters: dict[str, sp.Symbol],
              names: _Names, problems: list[str], source: str | None) -> ArmsRead:
    """The arms of a model file (``raw_arms``: its ``arms`` list), with the problems
    they have; ``top_bad`` are the top-level keys that could not be read.

    Example
    -------
    >>> problems = []
    >>> read = read_arms([], set(), {}, _Names(problems), problems, None)
    >>> read.arms, problems
    ([], ['arms: at least one arm with one joint is needed'])
    """
    read = ArmsRead()
    for i, raw_arm in enumerate(raw_arms):
        _read_arm(i, raw_arm, parameters, names, problems, source, read)
    if not raw_arms and "arms" not in top_bad:
        problems.append("arms: at least one arm with one joint is needed")
    for jname, jpath in read.joint_paths.items():
        clash = tangent_name(jname)
        if clash in names.where:
            problems.append(f"{names.where[clash]}: name '{clash}' clashes with the "
                            f"half-angle variable t_{jname} of joint {jname} ({jpath})")
    return read


def _read_arm(i: int, raw_arm: object, parameters: dict[str, sp.Symbol], names: _Names,
              problems: list[str], source: str | None, read: ArmsRead) -> None:
    """Arm ``i`` of the file, into ``read``."""
    apath = f"arms[{i}]"
    arm, arm_bad = _validate(_ArmIn, raw_arm, apath, problems)
    arm_joints = read.arm_joints
    if arm is None:
        if isinstance(raw_arm, Mapping) and isinstance(raw_arm.get("name"), str):
            arm_joints.setdefault(raw_arm["name"], None)   # exists, but unusable
        else:
            read.nameless_arm = True
        return
    duplicate = arm.name in names.where
    if not names.add(arm.name, f"{apath}.name", symbol=False) and not duplicate:
        arm_joints.setdefault(arm.name, None)   # contacts cannot name it
    robot_file = arm.urdf is not None or arm.mjcf is not None
    if arm_bad & _ARM_SHAPE or (robot_file and arm_bad & _URDF_CHOICE):
        # what the arm is made of could not be read: it has problems, not more
        arm_joints.setdefault(arm.name, None)
        return
    if robot_file:
        built = _urdf_arm(arm, apath, parameters, names, problems, read.joint_paths,
                          source, read.snapped, read.notes)
        arm_joints.setdefault(arm.name, (i, len(built.joints)) if built else None)
    else:
        _not_for_joints(arm, apath, problems)
        if arm.dh is not None:
            built = _dh_arm(arm, apath, parameters, names, problems, read.joint_paths)
            arm_joints.setdefault(arm.name, (i, len(arm.dh)) if built else None)
        else:
            built = _joints_arm(i, arm, apath, parameters, names, problems, read)
    if built is not None:
        read.arms.append(built)


def _not_for_joints(arm: Any, apath: str, problems: list[str]) -> None:
    """The keys only an arm read from a URDF file has."""
    for key in ("tip", "prefix", "snap"):
        if getattr(arm, key) is not None:
            problems.append(f"{apath}.{key}: only an arm read from a URDF file (urdf) "
                            f"has a {key}")
    if arm.passive is not None:
        problems.append(f"{apath}.passive: only an arm read from a URDF file lists "
                        f"its passive joints; mark a joint or a DH row with "
                        f"actuated: false")


def _joints_arm(i: int, arm: Any, apath: str, parameters: dict[str, sp.Symbol],
                names: _Names, problems: list[str], read: ArmsRead) -> Arm | None:
    """An arm given joint by joint."""
    for key in ("convention", "base"):
        if getattr(arm, key) is not None:
            problems.append(f"{apath}.{key}: only an arm given by a DH table (dh) has "
                            f"a {key}")
    if arm.joints is None:
        problems.append(f"{apath}: missing key 'joints' (or 'dh', a DH table)")
        read.arm_joints.setdefault(arm.name, None)
        return None
    read.arm_joints.setdefault(arm.name, (i, len(arm.joints)))
    if not arm.joints:
        problems.append(f"{apath}.joints: at least one joint is needed (contacts on "
                        f"the ground use link: base)")
    joints = []
    for k, raw_joint in enumerate(arm.joints):
        jpath = f"{apath}.joints[{k}]"
        joint = _joint(raw_joint, jpath, parameters, names, problems)
        if joint is not None:
            joints.append(joint)
            read.joint_paths[joint.name] = jpath
    return Arm(arm.name, tuple(joints))


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
    """An arm read from a URDF file, or an MJCF one (``mjcf:``, the same keys; its
    bodies are the links), relative paths from the model file's folder. Joint names
    that are not identifiers, are reserved or are parameters, and link names that
    ``ARM/LINK`` cannot write, get safe names
    (:func:`~coopkin_sym.model.urdf.variable_names`), listed in ``notes`` with the
    joints off the chain that were ignored."""
    before = len(problems)
    kind = "urdf" if arm.mjcf is None else "mjcf"
    if arm.urdf is not None and arm.mjcf is not None:
        problems.append(f"{path}: an arm is read from one robot file: urdf or mjcf")
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
    where = Path(getattr(arm, kind))
    if not where.is_absolute():
        where = (Path(source).parent if source else Path.cwd()) / where
    try:
        read = (read_urdf if kind == "urdf" else read_mjcf)(where, arm.tip, base, bound)
    except (UrdfError, MjcfError) as exc:
        problems.append(f"{path}.{kind}: {exc}")
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
        if names.add(name, f"{path}.{kind}: joint {k + 1} ({brief(j.name)})", symbol=True):
            joint_paths[name] = f"{path}.{kind}"
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
    sites = _sites(read, links, link_safe) if kind == "mjcf" else None
    return Arm(arm.name, tuple(joints), None, links, sites)


def _sites(read: Any, links: tuple, link_safe: Mapping[str, str]) -> tuple:
    """The sites of an arm read from an MJCF file: name, moving joints up to the
    site's body, position at home and the body's frame (base frame)."""
    body_frames = {name: frame for name, _, frame in links}
    return tuple((name, k, point, body_frames[link_safe.get(body, body)])
                 for (name, k, point), body in zip(read.sites, read.site_bodies,
                                                   strict=True))
