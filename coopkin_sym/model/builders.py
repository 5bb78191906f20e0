"""Scalable families of example systems, as model dicts.

Each function returns a plain dict that :func:`coopkin_sym.load` accepts, with exact
numbers only (integers, ``"p/q"`` strings, ``"p/q*L"`` expressions in the one
parameter ``L``). Directions come from a fixed table of 24 rational points of the unit
circle (Pythagorean triples, about 15 degrees apart), so every coordinate is rational
and the analysis stays exact.

The geometry is chosen so that the analysis at home (all joints at 0) gives the
generic numbers: fingers and arms are bent at home (no three consecutive joint points
on a line, no contact on a joint axis), so home is not a singular configuration by
accident. The structure that is intended stays: planar fingers have parallel axes,
spatial fingers have parallel flexion axes and an abduction axis through the first
flexion joint.

* :func:`planar_hand`: planar fingers around a disc, optional palm and inner-link
  contacts.
* :func:`spatial_hand`: spatial fingers rising from a palm around a ball.
* :func:`arm_cell`: several 6R-type arms around an object.

Example
-------
>>> from coopkin_sym import load
>>> load(planar_hand(2, 2)).analyze().numbers.as_dict()
{'Nm': 4, 'Nc': 4, 'Ni': 1, 'Nr': 0, 'Ng': 1, 'Nd': 2, 'Nh': 0}
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from typing import Any

from coopkin_sym.errors import ArgumentError
from coopkin_sym.model.contacts import contact_kind, contact_names

#: The shipped contact models (the registry may hold more; see
#: :mod:`coopkin_sym.model.contacts`).
CONTACT_MODELS = contact_names()

#: Rational tangent half-angles of 24 directions in the plane, about 7.5 + 15 k degrees.
_HALF_TANGENTS = tuple(Fraction(t) for t in (
    "1/12", "1/5", "1/3", "1/2", "2/3", "7/8", "8/7", "3/2", "2", "35/12", "5", "61/4",
    "-61/4", "-5", "-35/12", "-2", "-3/2", "-8/7", "-7/8", "-2/3", "-1/2", "-1/3", "-1/5",
    "-1/12"))

#: Rational (cos, sin) of the elevations of spatial fingertip contacts (below the equator).
_ELEVATIONS = ((Fraction(4, 5), Fraction(-3, 5)), (Fraction(12, 13), Fraction(-5, 13)),
               (Fraction(3, 5), Fraction(-4, 5)), (Fraction(15, 17), Fraction(-8, 17)),
               (Fraction(24, 25), Fraction(-7, 25)))

Vec3 = tuple[Fraction, Fraction, Fraction]


def circle_point(k: int) -> tuple[Fraction, Fraction]:
    """The exact point ``(cos, sin)`` of direction ``k`` (mod 24) of the table.

    Example
    -------
    >>> circle_point(2)
    (Fraction(4, 5), Fraction(3, 5))
    """
    t = _HALF_TANGENTS[k % 24]
    d = 1 + t * t
    return (1 - t * t) / d, 2 * t / d


def _spread(count: int) -> list[int]:
    """Table indices of ``count`` directions spread around the circle."""
    if count > 24:
        raise ArgumentError(f"at most 24 fingers or arms, got {count}")
    return [(24 * i) // count for i in range(count)]


def _cell_directions(count: int) -> list[tuple[Fraction, Fraction]]:
    """``count`` distinct exact horizontal directions: those of :func:`_spread` for up
    to 24; beyond, ring ``j = i // 24`` of ``R`` rings turns direction ``i mod 24`` of
    the table by ``2 atan(j / (16 R))`` (under 7.2 degrees; the table's directions are
    more than 13 degrees apart)."""
    if count <= 24:
        return [circle_point(k) for k in _spread(count)]
    rings = -(-count // 24)
    out = []
    for i in range(count):
        ring, k = divmod(i, 24)
        c, s = circle_point(k)
        t = Fraction(ring, 16 * rings)
        d = 1 + t * t
        cr, sr = (1 - t * t) / d, 2 * t / d
        out.append((c * cr - s * sr, s * cr + c * sr))
    return out


def _number(c: Fraction, scaled: bool) -> int | str:
    """Model-file form of ``c`` (times ``L`` when ``scaled``)."""
    c = Fraction(c)
    if c == 0:
        return 0
    if not scaled:
        return c.numerator if c.denominator == 1 else f"{c.numerator}/{c.denominator}"
    if c == 1:
        return "L"
    if c == -1:
        return "-L"
    return f"{c}*L"


def _point(p: Sequence[Fraction]) -> list[int | str]:
    return [_number(x, True) for x in p]


def _direction(d: Sequence[Fraction]) -> list[int | str]:
    assert sum(Fraction(x) ** 2 for x in d) == 1, d
    return [_number(x, False) for x in d]


def _local(u: tuple[Fraction, Fraction], a: Fraction, b: Fraction, z: Fraction) -> Vec3:
    """``a u + b v + z e_z`` with ``v = e_z x u`` (``u`` horizontal unit)."""
    c, s = u
    return (a * c - b * s, a * s + b * c, Fraction(z))


def _models(spec, count: int, what: str) -> list[str]:
    models = [spec] * count if isinstance(spec, str) else list(spec)
    if len(models) != count:
        raise ArgumentError(f"{what}: expected {count} contact models, got {len(models)}")
    for m in models:
        if contact_kind(m) is None:
            raise ArgumentError(f"{what}: unknown contact model {m!r} "
                                f"(one of {', '.join(contact_names())})")
    return models


def _optional_model(spec: bool | str, what: str) -> str | None:
    if spec is False or spec is None:
        return None
    if spec is True:
        return "hard"
    return _models(spec, 1, what)[0]


def _check_size(count: int, joints: int, what: str, max_joints: int | None = None) -> None:
    if count < 1 or joints < 1:
        raise ArgumentError(f"{what}: need at least one {what.split()[0]} and one joint each, "
                         f"got {count} and {joints}")
    if max_joints is not None and joints > max_joints:
        raise ArgumentError(f"{what}: at most {max_joints} joints each, got {joints}")


def _describe(models: list[str]) -> str:
    return models[0] if len(set(models)) == 1 else "/".join(models)


def planar_hand(fingers: int, joints_per_finger: int, tips: str | Sequence[str] = "hard",
                palm: bool | str = False, inner: bool | str = False,
                name: str | None = None) -> dict[str, Any]:
    """A planar hand: ``fingers`` planar chains around a disc of radius ``L``.

    Geometry (home pose, all in the plane z = 0, lengths in units of ``L``): finger i
    lies along the rational direction ``u_i`` of the 24-direction table (fingers
    spread evenly), with ``v_i = e_z x u_i``. With J joints per finger, joint k
    (k = 1..J, all revolute about z) is at ``(J + 2 - k) u_i + b_k v_i`` with the
    zigzag offset ``b_k = (-1)**k (1/2) (1 + ((i + k) mod 3) / 4)``; the fingertip
    (link J) touches the disc at ``L u_i`` with the inward normal ``-u_i``.

    Parameters
    ----------
    fingers, joints_per_finger
        Sizes (up to 24 fingers); ``r = fingers * joints_per_finger`` joints.
    tips
        Contact model of every fingertip, or a list with one model per finger.
    palm
        Add a palm contact (``link: base``) at ``(0, 0, -L)`` with normal ``e_z``;
        ``True`` means a hard contact, a string names the model.
    inner
        Add on link 1 of every finger a contact at ``L w_i``, ``w_i = (12/13) u_i +
        (5/13) v_i``, normal ``-w_i``; ``True`` means hard, a string names the model.
    name
        Model name (default: a description of the family and sizes).

    Joints are named ``f<i>_<k>``, contacts ``tip<i>``, ``palm``, ``inner<i>``.

    Example
    -------
    >>> from coopkin_sym import load
    >>> model = planar_hand(3, 3, tips="soft", palm=True)
    >>> model["arms"][0]["joints"][0]
    {'name': 'f1_1', 'type': 'revolute', 'axis': [0, 0, 1], 'point': ['587/145*L', '53/1160*L', 0]}
    >>> load(model).analyze().numbers.as_dict()
    {'Nm': 4, 'Nc': 1, 'Ni': 0, 'Nr': 3, 'Ng': 9, 'Nd': 9, 'Nh': 4}
    """
    _check_size(fingers, joints_per_finger, "fingers of planar_hand")
    tip_models = _models(tips, fingers, "tips")
    palm_model = _optional_model(palm, "palm")
    inner_model = _optional_model(inner, "inner")
    J = joints_per_finger
    arms, contacts = [], []
    for i, k_dir in enumerate(_spread(fingers)):
        u = circle_point(k_dir)
        joints = []
        for k in range(1, J + 1):
            b = Fraction((-1) ** k, 2) * (1 + Fraction((i + k) % 3, 4))
            joints.append({"name": f"f{i + 1}_{k}", "type": "revolute", "axis": [0, 0, 1],
                           "point": _point(_local(u, Fraction(J + 2 - k), b, 0))})
        arms.append({"name": f"f{i + 1}", "joints": joints})
        contacts.append({"name": f"tip{i + 1}", "link": f"f{i + 1}/{J}",
                         "point": _point(_local(u, 1, 0, 0)),
                         "normal": _direction(_local(u, -1, 0, 0)),
                         "model": tip_models[i]})
    if inner_model is not None:
        for i, k_dir in enumerate(_spread(fingers)):
            w = _local(circle_point(k_dir), Fraction(12, 13), Fraction(5, 13), 0)
            contacts.append({"name": f"inner{i + 1}", "link": f"f{i + 1}/1",
                             "point": _point(w), "normal": _direction([-x for x in w]),
                             "model": inner_model})
    if palm_model is not None:
        contacts.append({"name": "palm", "link": "base", "point": [0, 0, "-L"],
                         "normal": [0, 0, 1], "model": palm_model})
    extras = (", palm" if palm_model else "") + (", inner contacts" if inner_model else "")
    return {"name": name or (f"planar hand, {fingers} fingers x {J} joints, "
                             f"{_describe(tip_models)} tips{extras}"),
            "parameters": ["L"], "arms": arms, "contacts": contacts}


def spatial_hand(fingers: int, joints_per_finger: int, tips: str | Sequence[str] = "hard",
                 palm: bool | str = False, name: str | None = None) -> dict[str, Any]:
    """A spatial hand: ``fingers`` fingers rising from the palm z = -L around a ball of
    radius ``L`` centred at the origin.

    Geometry (home pose, lengths in units of ``L``; finger i along the rational
    horizontal direction ``u_i`` of the 24-direction table, ``v_i = e_z x u_i``):

    * joint 1, abduction: axis ``(4/5) u_i + (3/5) e_z`` through the finger base
      ``B = 2 u_i - e_z``;
    * joints 2..J, flexion: axes ``v_i`` (parallel); joint 2 at ``B`` (its axis meets
      the abduction axis), joint k >= 3 at ``B + (k-2)/(J-1) (T - B)`` plus a zigzag
      ``(-1)**k (1/4) p`` with ``p`` the in-plane normal of ``T - B``;
    * the fingertip (link J) touches the ball at ``T = c u_i + s e_z`` with the
      rational elevation ``(c, s)`` from ``(4/5, -3/5), (12/13, -5/13), (3/5, -4/5),
      (15/17, -8/17), (24/25, -7/25)`` (finger i takes entry ``i mod 5``), inward
      normal ``-T``.

    Parameters
    ----------
    fingers, joints_per_finger
        Sizes (up to 24 fingers).
    tips
        Contact model of every fingertip, or a list with one model per finger
        (e.g. ``["hard", "soft", "hard", "soft", "hard"]``).
    palm
        Add a palm contact (``link: base``) at ``(0, 0, -L)``, normal ``e_z``;
        ``True`` means hard, a string names the model.
    name
        Model name (default: a description of the family and sizes).

    Joints are named ``f<i>_<k>``, contacts ``tip<i>`` and ``palm``.

    Example
    -------
    >>> from coopkin_sym import load
    >>> model = spatial_hand(3, 3, tips=["hard", "soft", "hard"])
    >>> model["arms"][0]["joints"][0]["axis"]
    ['572/725', '96/725', '3/5']
    >>> load(model).analyze().numbers.as_dict()
    {'Nm': 5, 'Nc': 5, 'Ni': 0, 'Nr': 0, 'Ng': 4, 'Nd': 1, 'Nh': 0}
    """
    _check_size(fingers, joints_per_finger, "fingers of spatial_hand")
    tip_models = _models(tips, fingers, "tips")
    palm_model = _optional_model(palm, "palm")
    J = joints_per_finger
    arms, contacts = [], []
    for i, k_dir in enumerate(_spread(fingers)):
        u = circle_point(k_dir)
        c, s = _ELEVATIONS[i % len(_ELEVATIONS)]
        base = (Fraction(2), Fraction(-1))               # (radial, z)
        tip = (c, s)
        d = (tip[0] - base[0], tip[1] - base[1])
        p = (d[1], -d[0])                                 # in-plane normal of T - B
        joints = [{"name": f"f{i + 1}_1", "type": "revolute",
                   "axis": _direction(_local(u, Fraction(4, 5), 0, Fraction(3, 5))),
                   "point": _point(_local(u, base[0], 0, base[1]))}]
        for k in range(2, J + 1):
            f = Fraction(k - 2, J - 1)
            zig = Fraction((-1) ** k, 4) if k >= 3 else 0
            a = base[0] + f * d[0] + zig * p[0]
            z = base[1] + f * d[1] + zig * p[1]
            joints.append({"name": f"f{i + 1}_{k}", "type": "revolute",
                           "axis": _direction(_local(u, 0, 1, 0)),
                           "point": _point(_local(u, a, 0, z))})
        arms.append({"name": f"f{i + 1}", "joints": joints})
        t = _local(u, c, 0, s)
        contacts.append({"name": f"tip{i + 1}", "link": f"f{i + 1}/{J}", "point": _point(t),
                         "normal": _direction([-x for x in t]), "model": tip_models[i]})
    if palm_model is not None:
        contacts.append({"name": "palm", "link": "base", "point": [0, 0, "-L"],
                         "normal": [0, 0, 1], "model": palm_model})
    extras = ", palm" if palm_model else ""
    return {"name": name or (f"spatial hand, {fingers} fingers x {J} joints, "
                             f"{_describe(tip_models)} tips{extras}"),
            "parameters": ["L"], "arms": arms, "contacts": contacts}


#: Arm joints in the arm's frame (u, v, e_z), lengths in units of L: (axis, point).
#: Waist, shoulder, elbow, then a wrist with three non-concurrent axes, then two extra
#: oblique joints.
_ARM_JOINTS: tuple[tuple[Vec3, Vec3], ...] = tuple(
    (tuple(Fraction(x) for x in axis), tuple(Fraction(x) for x in point))
    for axis, point in (
        ((0, 0, 1), (4, 0, 0)),
        ((0, 1, 0), (4, 0, 1)),
        ((0, 1, 0), (3, 0, 3)),
        (("-4/5", 0, "-3/5"), ("7/5", 0, "9/5")),
        ((0, 1, 0), ("7/5", "1/10", "9/5")),
        (("3/5", 0, "-4/5"), ("13/10", 0, "19/10")),
        ((0, "3/5", "4/5"), ("6/5", "1/10", "19/10")),
        (("12/13", 0, "5/13"), ("11/10", "-1/10", 2)),
    ))


def arm_cell(arms: int, joints_per_arm: int, contact: str | Sequence[str] = "complete",
             name: str | None = None) -> dict[str, Any]:
    """A work cell: ``arms`` serial arms around an object (a ball of radius ``L``
    centred at ``(0, 0, 2L)``), each holding it at one contact.

    Geometry (home pose, lengths in units of ``L``): arm i stands at ``4 u_i`` on the
    floor, ``u_i`` a rational horizontal direction of the 24-direction table (with more
    than 24 arms, arm ``i`` takes direction ``i mod 24`` of the table turned by the
    exact angle ``2 atan(j / (16 R))``, ``j = i // 24`` of ``R`` rings: under 7.2
    degrees, less than the gaps of the table, so every arm has its own direction and
    contact point; the arms are not kept apart in space), and in
    its frame ``(u_i, v_i, e_z)`` its joints are, in order (axis @ point):
    waist ``e_z @ (4, 0, 0)``, shoulder ``v @ (4, 0, 1)``, elbow ``v @ (3, 0, 3)``,
    wrist ``(-4/5, 0, -3/5) @ (7/5, 0, 9/5)``, ``v @ (7/5, 1/10, 9/5)``,
    ``(3/5, 0, -4/5) @ (13/10, 0, 19/10)``, then two oblique joints
    ``(0, 3/5, 4/5) @ (6/5, 1/10, 19/10)`` and ``(12/13, 0, 5/13) @ (11/10, -1/10, 2)``
    (``joints_per_arm`` takes the first ones, at most 8). The last link touches the
    object at ``u_i + 2 e_z`` with inward normal ``-u_i``.

    Parameters
    ----------
    arms, joints_per_arm
        Sizes (any number of arms, 1..8 joints each).
    contact
        Contact model of every arm's contact, or a list with one per arm.
    name
        Model name (default: a description of the family and sizes).

    Joints are named ``a<i>_<k>``, contacts ``c<i>``.

    Example
    -------
    >>> from coopkin_sym import load
    >>> load(arm_cell(2, 6)).analyze().numbers.as_dict()
    {'Nm': 6, 'Nc': 6, 'Ni': 0, 'Nr': 0, 'Ng': 6, 'Nd': 0, 'Nh': 0}
    """
    _check_size(arms, joints_per_arm, "arms of arm_cell", max_joints=len(_ARM_JOINTS))
    models = _models(contact, arms, "contact")
    out_arms, contacts = [], []
    for i, u in enumerate(_cell_directions(arms)):
        joints = []
        for k, (axis, point) in enumerate(_ARM_JOINTS[:joints_per_arm], start=1):
            joints.append({"name": f"a{i + 1}_{k}", "type": "revolute",
                           "axis": _direction(_local(u, *axis)),
                           "point": _point(_local(u, *point))})
        out_arms.append({"name": f"a{i + 1}", "joints": joints})
        contacts.append({"name": f"c{i + 1}", "link": f"a{i + 1}/{joints_per_arm}",
                         "point": _point(_local(u, 1, 0, 2)),
                         "normal": _direction(_local(u, -1, 0, 0)), "model": models[i]})
    return {"name": name or (f"arm cell, {arms} arms x {joints_per_arm} joints, "
                             f"{_describe(models)} contacts"),
            "parameters": ["L"], "arms": out_arms, "contacts": contacts}
