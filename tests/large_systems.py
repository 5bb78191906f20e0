"""Large honest systems for the time-bound tests: many arms, or many contacts.

Both are built from :func:`coopkin_sym.model.builders.arm_cell` (exact, valid models):
:func:`many_arms` repeats its arms around the object (arm ``k`` is a copy of arm
``k mod 24``, with its own joints and contact), :func:`many_contacts` puts many
frictionless contacts on the last links of a few arms, at distinct points of the
object's equator.
"""

from __future__ import annotations

from fractions import Fraction

from coopkin_sym.model.builders import arm_cell, circle_point


def many_arms(arms: int = 200, joints: int = 6, contact: str = "hard") -> dict:
    """``arms`` arms of ``joints`` joints, each holding the object at one contact."""
    cell = arm_cell(24, joints, contact)
    out_arms, contacts = [], []
    for i in range(arms):
        arm, c = cell["arms"][i % 24], cell["contacts"][i % 24]
        name = f"b{i + 1}"
        out_arms.append({"name": name, "joints": [
            dict(j, name=f"{name}_{k}") for k, j in enumerate(arm["joints"], start=1)]})
        contacts.append(dict(c, name=f"k{i + 1}", link=f"{name}/{joints}"))
    return {"name": f"{arms} arms x {joints} joints", "parameters": ["L"],
            "arms": out_arms, "contacts": contacts}


def many_contacts(contacts: int = 2000, arms: int = 4, joints: int = 6) -> dict:
    """``contacts`` frictionless contacts shared out over the last links of ``arms``
    arms, each at its own point of the equator of the object, normal towards its centre."""
    cell = arm_cell(arms, joints, "frictionless")
    out = []
    for k in range(contacts):
        c, s = circle_point(k)
        scale = Fraction(k // 24 + 1, k // 24 + 2)   # a new ring every 24 contacts
        point = [str(c * scale), str(s * scale), "2*L"]
        out.append({"name": f"k{k + 1}", "link": f"a{k % arms + 1}/{joints}",
                    "point": [f"({p})*L" if i < 2 else p for i, p in enumerate(point)],
                    "normal": [str(-c), str(-s), 0], "model": "frictionless"})
    return {"name": f"{contacts} contacts", "parameters": ["L"],
            "arms": cell["arms"], "contacts": out}
