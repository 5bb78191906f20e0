"""Denavit-Hartenberg tables to joints at home, exactly.

An arm may be given as a DH table: one row per joint, ``theta, d, a, alpha``, with the
joint variable added to ``theta`` (revolute) or ``d`` (prismatic). The engine works
with each joint's axis and a point on it at home (every joint variable zero), in the
base frame; this module computes them, and the frame of every link, from the table.

* **standard** (Denavit-Hartenberg): ``T(i-1, i) = Rz(theta_i) Tz(d_i) Tx(a_i)
  Rx(alpha_i)``; joint ``i`` turns (or slides) about the ``z`` axis of frame ``i-1``.
* **modified** (Craig): ``T(i-1, i) = Rx(alpha_(i-1)) Tx(a_(i-1)) Rz(theta_i)
  Tz(d_i)``, the row of joint ``i`` holding ``alpha_(i-1), a_(i-1)``; joint ``i``
  turns about the ``z`` axis of frame ``i``.

Frame 0 is the arm's base placement (``xyz`` and ``rpy``, roll-pitch-yaw about fixed
axes, ``R = Rz(yaw) Ry(pitch) Rx(roll)``: the URDF convention). Angles are exact: a
rotation by an angle without a rational tangent of its half (``pi/3``) has irrational
entries, and the loader refuses it, naming the nearest angles it accepts. Lengths
``d`` and ``a`` may use the model's parameters.

Example
-------
>>> import sympy as sp
>>> L = sp.Symbol("L", positive=True)
>>> rows = [DHRow("q1", "revolute", 0, 0, L, 0), DHRow("q2", "revolute", 0, 0, L, 0)]
>>> joints, frames = dh_joints(rows, "standard", IDENTITY)
>>> [(j.axis, j.point) for j in joints]
[((0, 0, 1), (0, 0, 0)), ((0, 0, 1), (L, 0, 0))]
>>> frames[2][1]   # the origin of the last link frame at home
(2*L, 0, 0)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import sympy as sp

from coopkin_sym import limits
from coopkin_sym.errors import ArgumentError, NumberError
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.exact.parse import brief

__all__ = ["CONVENTIONS", "DHJoint", "DHRow", "Frame", "IDENTITY", "dh_joints",
           "frame_from_xyz_rpy", "frame_then", "in_base", "rotation_rpy"]

#: The DH conventions a model file may name.
CONVENTIONS: tuple[str, ...] = ("standard", "modified")

Vector = tuple[sp.Expr, sp.Expr, sp.Expr]
#: A pose: a rotation (3 x 3, exact) and an origin, both in the base frame.
Frame = tuple[sp.Matrix, Vector]

IDENTITY: Frame = (sp.eye(3), (sp.Integer(0), sp.Integer(0), sp.Integer(0)))


@dataclass(frozen=True)
class DHRow:
    """One row of a DH table: the joint's name and type, the home values of ``theta``
    and ``d`` (the joint variable is added to ``theta`` or ``d``), ``a`` and ``alpha``.
    Angles are :class:`~coopkin_sym.exact.angles.ExactAngle` or exact numbers whose
    cosine and sine are rational; lengths are exact expressions.

    Example
    -------
    >>> DHRow("q1", "revolute", 0, 0, 1, ExactAngle.parse("pi/2", "alpha")).type
    'revolute'
    """

    name: str
    type: str
    theta: ExactAngle | int
    d: sp.Expr | int
    a: sp.Expr | int
    alpha: ExactAngle | int


def _cos_sin(angle: ExactAngle | int) -> tuple[sp.Rational, sp.Rational]:
    if isinstance(angle, ExactAngle):
        return angle.cos_sin
    if angle != 0:
        raise ArgumentError("a DH angle given as a number must be 0; use an ExactAngle")
    return sp.Integer(1), sp.Integer(0)


def _rz(angle) -> sp.Matrix:
    c, s = _cos_sin(angle)
    return sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def _ry(angle) -> sp.Matrix:
    c, s = _cos_sin(angle)
    return sp.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def _rx(angle) -> sp.Matrix:
    c, s = _cos_sin(angle)
    return sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])


def _vec(m: sp.Matrix) -> Vector:
    return (sp.expand(m[0]), sp.expand(m[1]), sp.expand(m[2]))


def frame_then(frame: Frame, rotation: sp.Matrix, shift: Sequence) -> Frame:
    """``frame`` followed by a translation by ``shift`` (in ``frame``'s axes) and then
    a rotation: the pose of a child frame placed by ``(shift, rotation)``.

    Example
    -------
    >>> frame_then(IDENTITY, sp.eye(3), [1, 2, 3])[1]
    (1, 2, 3)
    """
    r, p = frame
    origin = sp.Matrix(p) + r * sp.Matrix(shift)
    return r * rotation, _vec(origin)


def frame_from_xyz_rpy(xyz: Sequence, rpy: Sequence[ExactAngle | int]) -> Frame:
    """The pose with origin ``xyz`` and rotation ``Rz(yaw) Ry(pitch) Rx(roll)``.

    Example
    -------
    >>> r, p = frame_from_xyz_rpy([1, 0, 0], [0, 0, ExactAngle.parse("pi/2", "yaw")])
    >>> list(r * sp.Matrix([1, 0, 0])), p
    ([0, 1, 0], (1, 0, 0))
    """
    origin = tuple(x if isinstance(x, sp.Basic) else sp.Integer(x) for x in xyz)
    return rotation_rpy(rpy), origin


def rotation_rpy(rpy: Sequence[ExactAngle | int]) -> sp.Matrix:
    """``Rz(yaw) Ry(pitch) Rx(roll)``, exactly (roll, pitch, yaw about fixed axes).

    Example
    -------
    >>> list(rotation_rpy([ExactAngle.parse("pi/2", "roll"), 0, 0]) * sp.Matrix([0, 1, 0]))
    [0, 0, 1]
    """
    roll, pitch, yaw = rpy
    return _rz(yaw) * _ry(pitch) * _rx(roll)


def in_base(frame: Frame, point: Sequence, direction: Sequence | None = None
            ) -> tuple[Vector, Vector | None]:
    """A point (and a direction) given in ``frame``, in the base frame.

    Example
    -------
    >>> in_base(frame_from_xyz_rpy([0, 0, 1], [0, 0, 0]), [1, 0, 0], [0, 1, 0])
    ((1, 0, 1), (0, 1, 0))
    """
    r, p = frame
    where = _vec(sp.Matrix(p) + r * sp.Matrix(list(point)))
    return where, (_vec(r * sp.Matrix(list(direction))) if direction is not None else None)


@dataclass(frozen=True)
class DHJoint:
    """A joint at home from a DH table: its axis (exact unit vector) and a point on
    it, in the base frame (what :class:`~coopkin_sym.model.model.Joint` holds).

    Example
    -------
    >>> joints, _ = dh_joints([DHRow("d1", "prismatic", 0, 0, 0, 0)], "modified", IDENTITY)
    >>> joints[0]
    DHJoint(name='d1', type='prismatic', axis=(0, 0, 1), point=(0, 0, 0))
    """

    name: str
    type: str
    axis: Vector
    point: Vector


def _largest_bits(frame: Frame) -> int:
    """Bits of the largest numerator or denominator in a frame's entries."""
    r, p = frame
    bits = 0
    for entry in (*r, *p):
        numbers = (entry.atoms(sp.Rational) if isinstance(entry, sp.Basic)
                   else (sp.Rational(entry),))
        for number in numbers:
            bits = max(bits, abs(number.p).bit_length(), number.q.bit_length())
    return bits


def dh_joints(rows: Sequence[DHRow], convention: str, base: Frame, where: str = "dh"
              ) -> tuple[list[DHJoint], list[Frame]]:
    """The joints at home and the frames of links ``0..n`` (0: the base placement) of
    a DH table.

    Every row's rotation multiplies the denominators of the frames after it, so the
    numbers of the frames are bounded like numbers read from a file (at most
    :data:`~coopkin_sym.limits.MAX_DIGITS` digits): a table whose frames would have
    larger ones is refused at the row where they appear (``where`` names the table
    in the message), before it takes minutes.

    Raises
    ------
    NumberError
        A frame with a number of more than ``MAX_DIGITS`` digits.

    Example
    -------
    >>> half_turn = ExactAngle.parse("pi/2", "alpha")
    >>> rows = [DHRow("q1", "revolute", 0, 1, 0, half_turn),
    ...         DHRow("d2", "prismatic", 0, 0, 0, 0)]
    >>> joints, frames = dh_joints(rows, "standard", IDENTITY)
    >>> joints[1].axis, joints[1].point   # z of frame 1: the old -y
    ((0, -1, 0), (0, 0, 1))
    """
    if convention not in CONVENTIONS:
        raise ArgumentError(f"unknown DH convention {convention!r}")
    frames = [base]
    joints = []
    for row in rows:
        frame = frames[-1]
        if convention == "standard":
            r, p = frame
            axis, point = _vec(r[:, 2]), p
            frame = frame_then(frame, _rz(row.theta), [0, 0, 0])
            frame = frame_then(frame, _rx(row.alpha), [row.a, 0, row.d])
        else:
            frame = frame_then(frame, _rx(row.alpha), [0, 0, 0])
            frame = frame_then(frame, _rz(row.theta), [row.a, 0, 0])
            r, p = frame
            axis, point = _vec(r[:, 2]), p
            frame = frame_then(frame, sp.eye(3), [0, 0, row.d])
        if _largest_bits(frame) > limits.max_bits():
            raise NumberError(f"{where}[{len(joints)}] (joint {brief(row.name)})",
                              f"the link frame at home has a number of more than "
                              f"{limits.MAX_DIGITS} digits (the rotations of the rows "
                              f"up to here multiply their denominators); use angles "
                              f"whose tan(q/2) have fewer digits")
        joints.append(DHJoint(row.name, row.type, axis, point))
        frames.append(frame)
    return joints, frames
