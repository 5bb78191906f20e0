"""Hypothesis strategies for random, valid cooperating-robot models.

Everything is exact: unit vectors come from stereographic projection of rational points
(so they are exactly unit), angles from rational tangent half-angles.  Numbers in the
generated model dicts are ``int`` when integral and ``"p/q"`` strings otherwise (or
parameter expressions such as ``"2*L"``), exactly as in a YAML model file.

Strategies
----------
rational_unit_vectors()
    ``[x, y, z]`` exact unit vectors, entries ``int`` / ``"p/q"``.
exact_angles()
    ``((cos, sin), text)`` with SymPy Rationals and the CLI form of the angle
    (``"0"``, ``"pi"``, ``"pi/2"``, ``"-pi/2"``, ``"2*atan(p/q)"``).
random_systems(max_arms=3, max_joints=4, max_contacts=4, with_parameter=False)
    Model dicts.
random_configurations(model)
    ``(at, at_text)``: ``at`` in the format of ``independent.reference_analysis``
    and the same configuration as a CLI ``--at`` string.
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from hypothesis import strategies as st

from coopkin_sym.model.contacts import contact_names

#: The registered contact models (read from the registry: a new one is sampled too).
CONTACT_MODELS = contact_names()


def model_number(value: sp.Rational) -> int | str:
    """Model-file form of an exact rational: ``int`` when integral, else ``"p/q"``."""
    value = sp.Rational(value)
    return int(value) if value.q == 1 else f"{value.p}/{value.q}"


def rational_text(value: sp.Rational) -> str:
    """CLI form of an exact rational: ``"3"``, ``"-1/2"``."""
    value = sp.Rational(value)
    return str(value.p) if value.q == 1 else f"{value.p}/{value.q}"


def small_rationals(max_num: int = 4, max_den: int = 4) -> st.SearchStrategy[sp.Rational]:
    """Rationals p/q with |p| <= max_num, 1 <= q <= max_den."""
    return st.builds(
        sp.Rational,
        st.integers(-max_num, max_num),
        st.integers(1, max_den),
    )


# --------------------------------------------------------------------- unit vectors


def _stereographic(a: sp.Rational, b: sp.Rational) -> list[sp.Rational]:
    d = a**2 + b**2 + 1
    return [2 * a / d, 2 * b / d, (a**2 + b**2 - 1) / d]


@st.composite
def _projected_unit(draw) -> list[sp.Rational]:
    a = draw(small_rationals(3, 3))
    b = draw(small_rationals(3, 3))
    v = _stereographic(a, b)
    perm = draw(st.permutations([0, 1, 2]))
    signs = draw(st.lists(st.sampled_from([1, -1]), min_size=3, max_size=3))
    return [signs[i] * v[perm[i]] for i in range(3)]


_AXES = [
    [sp.Integer(x) for x in v]
    for v in ([1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1])
]


def rational_unit_vectors_exact() -> st.SearchStrategy[list[sp.Rational]]:
    """Exact unit 3-vectors as lists of SymPy Rationals."""
    return st.one_of(st.sampled_from(_AXES), _projected_unit())


def rational_unit_vectors() -> st.SearchStrategy[list[int | str]]:
    """Exact unit 3-vectors in model-file form (``[0, 0, 1]``, ``["3/5", "4/5", 0]``)."""
    return rational_unit_vectors_exact().map(lambda v: [model_number(x) for x in v])


# --------------------------------------------------------------------------- angles


def angle_from_half_tangent(t: sp.Rational) -> tuple[tuple[sp.Rational, sp.Rational], str]:
    """``((cos, sin), text)`` of q = 2*atan(t), with the simplest CLI text."""
    t = sp.Rational(t)
    pair = ((1 - t**2) / (1 + t**2), 2 * t / (1 + t**2))
    simple = {0: "0", 1: "pi/2", -1: "-pi/2"}
    text = simple[int(t)] if t in (0, 1, -1) else f"2*atan({rational_text(t)})"
    return pair, text


PI = ((sp.Integer(-1), sp.Integer(0)), "pi")


def special_angles() -> st.SearchStrategy[tuple[tuple[sp.Rational, sp.Rational], str]]:
    """0, pi/2, -pi/2 and pi."""
    return st.sampled_from([angle_from_half_tangent(sp.Integer(t)) for t in (0, 1, -1)] + [PI])


def exact_angles() -> st.SearchStrategy[tuple[tuple[sp.Rational, sp.Rational], str]]:
    """``((cos, sin), text)``: rational half-angle tangents in [-5, 5], plus 0 and pi."""
    generic = small_rationals(5, 5).map(angle_from_half_tangent)
    return st.one_of(generic, special_angles())


# -------------------------------------------------------------------------- systems


@st.composite
def _point(draw, with_parameter: bool) -> list[int | str]:
    coords: list[int | str] = []
    for _ in range(3):
        x = draw(small_rationals(3, 2))
        if with_parameter and draw(st.integers(0, 3)) == 0:
            k = draw(st.sampled_from(["L", "-L", "2*L", "L/2", "L + 1", "3*L - 1/2"]))
            coords.append(k)
        else:
            coords.append(model_number(x))
    return coords


@st.composite
def random_systems(
    draw,
    max_arms: int = 3,
    max_joints: int = 4,
    max_contacts: int = 4,
    with_parameter: bool = False,
) -> dict[str, Any]:
    """Random valid model dicts.

    1..max_arms arms ``a1, a2, ...`` of 1..max_joints joints each (joint names ``q1, q2,
    ...`` in file order, revolute or prismatic, exact unit axes, small rational points;
    prismatic joints sometimes omit ``point``), 1..max_contacts contacts ``c1, ...`` on
    random links (moving links including inner ones, arm bases ``aK/0``, the ground
    ``base``; repeated links are likely), with mixed contact models and an exact unit
    normal always given.  With ``with_parameter`` the model declares ``L`` and uses it
    in some coordinates (``"2*L"`` ...).
    """
    n_arms = draw(st.integers(1, max_arms))
    arms = []
    links = ["base"]
    q = 0
    for a in range(1, n_arms + 1):
        joints = []
        n_joints = draw(st.integers(1, max_joints))
        for _ in range(n_joints):
            q += 1
            kind = draw(st.sampled_from(["revolute", "revolute", "prismatic"]))
            joint: dict[str, Any] = {
                "name": f"q{q}",
                "type": kind,
                "axis": draw(rational_unit_vectors()),
            }
            if kind == "revolute" or draw(st.booleans()):
                joint["point"] = draw(_point(with_parameter))
            joints.append(joint)
        arms.append({"name": f"a{a}", "joints": joints})
        links += [f"a{a}/{k}" for k in range(n_joints + 1)]
    moving = [x for x in links if x != "base" and not x.endswith("/0")]

    contacts = []
    n_contacts = draw(st.integers(1, max_contacts))
    for i in range(1, n_contacts + 1):
        choice = draw(st.integers(0, 9))
        if choice < 2 and contacts:
            link = contacts[-1]["link"]  # several contacts on one link
        elif choice < 3:
            link = draw(st.sampled_from(links))  # anything, base and ARM/0 included
        else:
            link = draw(st.sampled_from(moving))
        contacts.append(
            {
                "name": f"c{i}",
                "link": link,
                "point": draw(_point(with_parameter)),
                "normal": draw(rational_unit_vectors()),
                "model": draw(st.sampled_from(contact_names())),
            }
        )
    return {
        "name": "random system",
        "parameters": ["L"] if with_parameter else [],
        "arms": arms,
        "contacts": contacts,
    }


@st.composite
def random_configurations(draw, model: dict[str, Any]) -> tuple[dict[str, Any], str]:
    """``(at, at_text)`` giving an exact value to every joint and parameter of ``model``.

    ``at`` maps revolute joints to ``(cos, sin)`` Rationals, prismatic joints and
    parameters to Rationals (the format of ``independent.reference_analysis``);
    ``at_text`` is the same as a CLI ``--at`` string, e.g.
    ``"q1=pi/2,q2=2*atan(1/3),q3=1/2,L=2"``.  Some draws are "special" (many joints at
    0, pi/2, pi), others generic-looking.
    """
    special = draw(st.booleans())
    at: dict[str, Any] = {}
    parts: list[str] = []
    for arm in model.get("arms") or []:
        for joint in arm["joints"]:
            name = joint["name"]
            if joint["type"] == "revolute":
                angles = special_angles() if special and draw(st.booleans()) else exact_angles()
                pair, text = draw(angles)
                at[name] = pair
                parts.append(f"{name}={text}")
            else:
                if special and draw(st.booleans()):
                    d = sp.Integer(0)
                else:
                    d = draw(small_rationals(3, 3))
                at[name] = d
                parts.append(f"{name}={rational_text(d)}")
    for p in model.get("parameters") or []:
        value = draw(
            st.builds(sp.Rational, st.integers(1, 5), st.integers(1, 3))
            if not special
            else st.just(sp.Integer(1))
        )
        at[str(p)] = value
        parts.append(f"{p}={rational_text(value)}")
    return at, ",".join(parts)
