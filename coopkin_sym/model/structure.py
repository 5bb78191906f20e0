"""The parts of a validated model: :class:`Joint`, :class:`Arm`, :class:`Contact` and
the whole :class:`Model`, immutable, every number exact. They are built from model
files by :func:`coopkin_sym.model.model.load_model` (which re-exports them).

Example
-------
>>> from coopkin_sym.model.model import load_model
>>> m = load_model("paper-case1-hard")
>>> type(m).__name__, [type(a).__name__ for a in m.arms]
('Model', ['Arm', 'Arm'])
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Literal

import sympy as sp

from coopkin_sym.model.contacts import contact_names
from coopkin_sym.model.dh import Frame
from coopkin_sym.model.urdf import IgnoredJoint, Renamed, Snapped

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
    >>> from coopkin_sym.model.model import load_model
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
    joints up to it. ``sites`` are the sites of an arm read from an MJCF file:
    ``(name, k, point, frame)``, the point at home and the frame of the site's body
    at home, both in the base frame; None for other arms.

    Example
    -------
    >>> from coopkin_sym.model.model import load_model
    >>> arm = load_model("paper-case2-hard").arms[0]
    >>> arm.name, [j.name for j in arm.joints], arm.frames
    ('s1', ['q1', 'q2', 'q3', 'q4'], None)
    """

    name: str
    joints: tuple[Joint, ...]
    frames: tuple[Frame, ...] | None = None
    links: tuple[tuple[str, int, Frame], ...] | None = None
    sites: tuple[tuple[str, int, Vector, Frame], ...] | None = None


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
    >>> from coopkin_sym.model.model import load_model
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
    >>> from coopkin_sym.model.model import load_model
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
        >>> from coopkin_sym.model.model import load_model
        >>> load_model("paper-case1-hard").object_dim
        6
        """
        return 3 if self.planar else 6

    @property
    def twist_names(self) -> tuple[str, ...]:
        """The components of an object twist, in order.

        Example
        -------
        >>> from coopkin_sym.model.model import load_model
        >>> load_model("paper-case1-hard").twist_names[3:]
        ('w_x', 'w_y', 'w_z')
        """
        return PLANAR_TWIST if self.planar else SPATIAL_TWIST

    def in_base_frame(self) -> Model:
        """The same system with object twists at the base origin, in base axes (no
        number depends on the object frame: the searches for numbers use this one).

        Example
        -------
        >>> from coopkin_sym.model.model import load_model
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
        >>> from coopkin_sym.model.model import load_model
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
        >>> from coopkin_sym.model.model import load_model
        >>> load_model("five-bar").with_actuators_locked().locked == {"q1", "q3"}
        True
        """
        return replace(self, locked=frozenset(j.name for j in self.joints if j.actuated))

    def joint_offset(self, arm: int) -> int:
        """Index in :attr:`joints` of the first joint of arm ``arm``."""
        return sum(len(a.joints) for a in self.arms[:arm])
