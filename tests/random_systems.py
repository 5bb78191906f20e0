"""Small random two-arm systems for checking the locus search (seeded, deterministic).

Each system has two planar arms of two joints (revolute about z; prismatic in the plane
one time in five), small integer geometry (so coincident points, contacts on a joint
axis and parallel axes come up often) and one contact on each arm's last link. The
contact models of the pair are ``MODELS[seed % k]`` and ``MODELS[seed // k % k]`` (``k``
the number of registered models, 4 as shipped), so any ``k**2`` consecutive seeds make
every pair.

Example
-------
>>> [c["model"] for c in random_system(6)["contacts"]]
['hard', 'soft']
"""

from __future__ import annotations

import random
from fractions import Fraction

from coopkin_sym.model.contacts import contact_names

#: The registered contact models, in registry order.
MODELS = contact_names()


def _number(x: Fraction):
    return int(x) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def _planar_unit(rng: random.Random) -> list:
    if rng.random() < 0.7:
        return rng.choice([[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]])
    a = Fraction(rng.choice([1, -1]), 2)            # (3/5, +-4/5)
    return [_number((1 - a * a) / (1 + a * a)), _number(2 * a / (1 + a * a)), 0]


def random_system(seed: int) -> dict:
    """The model (as a dict) of random system ``seed``.

    Example
    -------
    >>> m = random_system(3)
    >>> [j["type"] for a in m["arms"] for j in a["joints"]]
    ['revolute', 'revolute', 'revolute', 'revolute']
    """
    rng = random.Random(seed)
    arms, q = [], 0
    for a in (1, 2):
        joints = []
        for _ in range(2):
            q += 1
            point = [rng.randint(-2, 2), rng.randint(-2, 2), 0]
            if rng.random() < 0.2:
                joints.append({"name": f"q{q}", "type": "prismatic",
                               "axis": _planar_unit(rng), "point": point})
            else:
                joints.append({"name": f"q{q}", "type": "revolute", "axis": [0, 0, 1],
                               "point": point})
        arms.append({"name": f"a{a}", "joints": joints})
    k = len(MODELS)
    contacts = [{"name": f"c{i + 1}", "link": f"a{i + 1}/2",
                 "point": [rng.randint(-2, 2), rng.randint(-2, 2), 0],
                 "normal": _planar_unit(rng),
                 "model": MODELS[(seed if i == 0 else seed // k) % k]} for i in range(2)]
    return {"name": f"random system {seed}", "parameters": [], "arms": arms,
            "contacts": contacts}


def degeneracies(model: dict) -> list[str]:
    """Special geometry of a random system, in words: coincident revolute joint points,
    contacts on a revolute joint's axis, coincident contact points, a prismatic axis
    along the normal of its own arm's contact (at home).

    Example
    -------
    >>> degeneracies(random_system(4))
    ['c2 on q4']
    """
    out = []
    joints = [(k, j) for k, a in enumerate(model["arms"]) for j in a["joints"]]
    contacts = model["contacts"]
    for i, (_, a) in enumerate(joints):
        for _, b in joints[i + 1:]:
            if a["point"] == b["point"] and a["type"] == b["type"] == "revolute":
                out.append(f"{a['name']},{b['name']} same point")
    for k, c in enumerate(contacts):
        for arm, j in joints:
            if j["type"] == "revolute" and c["point"] == j["point"]:
                out.append(f"{c['name']} on {j['name']}")
            if arm == k and j["type"] == "prismatic" and [
                    Fraction(str(x)) for x in j["axis"]] == [
                    Fraction(str(x)) for x in c["normal"]]:
                out.append(f"{j['name']} along n_{c['name']}")
    if contacts[0]["point"] == contacts[1]["point"]:
        out.append("c1 = c2")
    return out
