"""The contacts of a model file: each one's link (``ARM/K``, a URDF link by its name,
or ``base``) and point, or an MJCF site (``site: ARM/SITE``, which gives both),
normal, contact model (read from the registry, :mod:`coopkin_sym.model.contacts`)
and frame, checked and read into a
:class:`~coopkin_sym.model.structure.Contact`; and what keeps a planar system in its
plane.

Example
-------
>>> from coopkin_sym.model.arm_entries import read_arms
>>> from coopkin_sym.model.entries import _Names
>>> problems = []
>>> names = _Names(problems)
>>> arms = read_arms([{"name": "a", "joints": [
...     {"name": "q1", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]}]}],
...     set(), {}, names, problems, None)
>>> contacts, paths = read_contacts(
...     [{"name": "c", "link": "a/1", "point": [1, 0, 0], "model": "sticky"}],
...     set(), {}, names, arms, problems)
>>> contacts, problems
([], ["contacts[0].model: unknown contact model 'sticky' (expected complete, soft, hard or \
frictionless)"])
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import sympy as sp

from coopkin_sym.exact.parse import brief
from coopkin_sym.model.arm_entries import ArmsRead
from coopkin_sym.model.contacts import contact_kind, contact_names, listed, planar_names
from coopkin_sym.model.dh import Frame, in_base
from coopkin_sym.model.entries import (
    _ContactIn,
    _is_zero,
    _Names,
    _unit_problem,
    _validate,
    _vec_text,
    _vector,
)
from coopkin_sym.model.structure import Arm, Contact


def read_contacts(raw_contacts: list[Any], top_bad: set[str],
                  parameters: dict[str, sp.Symbol], names: _Names, arms: ArmsRead,
                  problems: list[str]) -> tuple[list[Contact], list[str]]:
    """The contacts of a model file (``raw_contacts``: its ``contacts`` list) on the
    arms read, and the path of each in the file; problems are collected.

    Example
    -------
    >>> problems = []
    >>> read_contacts([], set(), {}, _Names(problems), ArmsRead(), problems)
    ([], [])
    >>> problems
    ['contacts: at least one contact is needed']
    """
    contacts: list[Contact] = []
    contact_paths: list[str] = []
    frames = {arm.name: arm for arm in arms.arms}
    for i, raw_contact in enumerate(raw_contacts):
        contact = _contact(raw_contact, f"contacts[{i}]", parameters, names,
                           arms.arm_joints, problems, frames,
                           arms.nameless_arm or not arms.arm_joints)
        if contact is not None:
            contacts.append(contact)
            contact_paths.append(f"contacts[{i}]")
    if not raw_contacts and "contacts" not in top_bad:
        problems.append("contacts: at least one contact is needed")
    return contacts, contact_paths


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



@dataclass(frozen=True)
class _Link:
    """Where a contact is: its arm (``None`` for the ground), link, the link's frame
    for a URDF link named by its name, the arm's name as written, and whether that
    arm could not be read (nothing more is checked against it)."""

    arm: int | None
    link: int
    frame: Frame | None
    arm_name: str | None
    on_failed_arm: bool


def _contact_link(entry: Any, path: str, arm_joints: dict[str, tuple[int, int] | None],
                  frames: Mapping[str, Arm], nameless_arm: bool,
                  problems: list[str]) -> _Link | None:
    """The link of a contact; ``None`` for a URDF arm without the link it names."""
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
    return _Link(arm_index, link, link_frame, match.group(1) if match is not None else None,
                 on_failed_arm)


def _site_link(entry: Any, path: str, arm_joints: dict[str, tuple[int, int] | None],
               frames: Mapping[str, Arm], nameless_arm: bool, problems: list[str]
               ) -> tuple[_Link, tuple, Frame] | None:
    """The link, the point at home (base frame) and the body's frame of a contact
    placed on an MJCF site (``site: ARM/SITE``); None when there is none (said in
    ``problems``, unless the arm itself could not be read)."""
    text = entry.site.strip()
    match = re.fullmatch(r"([^/\s]+)\s*/\s*([^/\s]+)", text)
    if entry.link is not None or entry.point is not None:
        given = " and ".join(k for k in ("link", "point") if getattr(entry, k) is not None)
        problems.append(f"{path}.site: a contact on a site takes its link and point from "
                        f"the site; remove {given}")
        return None
    if match is None:
        problems.append(f"{path}.site: expected ARM/SITE (a site of an arm read from an "
                        f"MJCF file), got {brief(entry.site)}")
        return None
    arm_name, site_name = match.groups()
    if arm_name not in arm_joints:
        if not nameless_arm:
            problems.append(f"{path}.site: unknown arm {brief(arm_name)} "
                            f"(arms: {', '.join(arm_joints)})")
        return None
    if arm_joints[arm_name] is None or arm_name not in frames:
        return None   # the arm's own entry says what is wrong
    sites = frames[arm_name].sites
    if sites is None:
        problems.append(f"{path}.site: sites exist only on an arm read from an MJCF file "
                        f"(mjcf:); arm {brief(arm_name)} is not")
        return None
    by_name = {name: (k, point, frame) for name, k, point, frame in sites}
    if site_name not in by_name:
        known = ", ".join(by_name) or "none"
        problems.append(f"{path}.site: arm {brief(arm_name)} has no site "
                        f"{brief(site_name)} on its chain (sites: {known})")
        return None
    k, point, frame = by_name[site_name]
    arm_index = arm_joints[arm_name][0]  # type: ignore[index]
    return _Link(arm_index, k, frame, arm_name, False), point, frame


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
    site_frame = None
    if entry.site is not None:
        on_site = _site_link(entry, path, arm_joints, frames, nameless_arm, problems)
        if on_site is None:
            return None
        where, point, site_frame = on_site
    else:
        for key in ("link", "point"):
            if getattr(entry, key) is None:
                problems.append(f"{path}: missing key '{key}'")
        if entry.link is None:
            return None
        where = _contact_link(entry, path, arm_joints, frames, nameless_arm, problems)
        if where is None or entry.point is None:
            return None
        point = _vector(entry.point, f"{path}.point", parameters, problems,
                        rational=False)
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
    if len(problems) > before or bad or point is None or where.on_failed_arm:
        return None
    if site_frame is not None and entry.frame == "link":
        normal = in_base(site_frame, (0, 0, 0), normal)[1]
    elif entry.frame == "link":
        arm_name = where.arm_name
        if arm_name is not None and arm_name not in frames:
            return None   # the arm itself could not be read: its entry says why
        arm_frames = frames[arm_name].frames if arm_name is not None else None
        if where.frame is None and arm_frames is None:
            problems.append(f"{path}.frame: link frames exist only for an arm given by a "
                            f"DH table or a URDF file (a URDF link by its name); "
                            f"{brief(entry.link)} is not on one")
            return None
        point, normal = in_base(where.frame if where.frame is not None
                                else arm_frames[where.link], point, normal)
    return Contact(entry.name, where.arm, link=where.link, point=point, normal=normal,
                   model=model)
