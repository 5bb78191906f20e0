"""The contact models, in one registry: what a model file may call each one, which
components of the relative twist at the contact it transmits (spatial and planar),
the words that name it and the glyph that draws it.

Every consumer reads :data:`REGISTRY`: model files (:mod:`coopkin_sym.model.model`),
the rows of ``H`` (:mod:`coopkin_sym.analysis.kinematics` and the sweeps), the words
(:func:`coopkin_sym.present.sentences.contact_words`) and the pictures
(:mod:`coopkin_sym.present.draw`). A new contact model is one more entry.

A component is ``v_x``, ``v_y``, ``v_z``, ``w_x``, ``w_y``, ``w_z`` (one axis of the
linear or angular velocity), or ``v.n``, ``w.n`` (along the contact normal).

Example
-------
>>> kind = contact_kind("soft")
>>> kind.spatial, kind.planar, kind.needs_normal
(('v_x', 'v_y', 'v_z', 'w.n'), None, True)
>>> contact_names()
('complete', 'soft', 'hard', 'frictionless')
"""

from __future__ import annotations

from dataclasses import dataclass

from coopkin_sym.errors import ArgumentError

#: The components a spatial contact may transmit, linear then angular.
SPATIAL_COMPONENTS: tuple[str, ...] = ("v_x", "v_y", "v_z", "v.n", "w_x", "w_y", "w_z", "w.n")
#: The conditions a contact model may put on positions ("" when it puts none: it is not
#: holonomic); each transmits the components of its rows (see :class:`ContactKind`).
POSITIONS: tuple[str, ...] = ("", "point", "weld", "face")
#: The components a planar contact may transmit (the plane is xy).
PLANAR_COMPONENTS: tuple[str, ...] = ("v_x", "v_y", "v.n", "w_z")


@dataclass(frozen=True)
class ContactKind:
    """One contact model.

    ``name`` is how a model stores it, ``aliases`` the other spellings a model file
    may use; ``spatial`` and ``planar`` the components of the relative twist it
    transmits, in the order of their rows (``planar`` is ``None`` for a model with no
    planar form, ``no_planar`` then says why); ``words`` names it in sentences and
    tables, ``marker`` (a Matplotlib marker) draws it. ``position`` is the condition
    it puts on positions, for the finite mobility (:data:`POSITIONS`: ``"point"``, the
    contact point fixed on both bodies; ``"weld"``, the link welded to the object;
    ``"face"``, the link's point on a flat face of the object), or ``""`` when it is
    not holonomic, ``not_holonomic`` then saying why.

    Example
    -------
    >>> k = ContactKind("glued", ("bonded",), ("v_x", "v_y", "v_z", "w_x", "w_y", "w_z"),
    ...                 ("v_x", "v_y", "w_z"), "glued joint", "*")
    >>> k.rows(planar=False), k.rows(planar=True), k.needs_normal
    (6, 3, False)
    """

    name: str
    aliases: tuple[str, ...]
    spatial: tuple[str, ...]
    planar: tuple[str, ...] | None
    words: str
    marker: str
    no_planar: str = ""
    position: str = ""
    not_holonomic: str = ("its condition bounds velocities, not positions (it is not "
                          "holonomic)")

    def __post_init__(self) -> None:
        if self.position not in POSITIONS:
            raise ArgumentError(f"contact model {self.name!r}: position "
                                f"{self.position!r} (one of {', '.join(map(repr, POSITIONS))})")
        if not self.name or not self.words or not self.marker:
            raise ArgumentError(f"contact model {self.name!r}: a name, words and a "
                                f"marker are required")
        for comps, allowed, which in ((self.spatial, SPATIAL_COMPONENTS, "spatial"),
                                      (self.planar or (), PLANAR_COMPONENTS, "planar")):
            if any(c not in allowed for c in comps) or len(set(comps)) != len(comps):
                raise ArgumentError(f"contact model {self.name!r}: {which} components "
                                    f"{comps} (each once, from {', '.join(allowed)})")
            if list(comps) != sorted(comps, key=allowed.index):
                raise ArgumentError(f"contact model {self.name!r}: {which} components "
                                    f"in the order {', '.join(allowed)}")

    @property
    def needs_normal(self) -> bool:
        """Whether its rows depend on the contact normal (``v.n`` or ``w.n``).

        Example
        -------
        >>> contact_kind("frictionless").needs_normal
        True
        """
        return any(c.endswith(".n") for c in self.spatial + (self.planar or ()))

    def components(self, planar: bool) -> tuple[str, ...]:
        """The transmitted components, spatial or planar (empty without a planar form).

        Example
        -------
        >>> contact_kind("complete").components(planar=True)
        ('v_x', 'v_y', 'w_z')
        """
        return (self.planar or ()) if planar else self.spatial

    def rows(self, planar: bool) -> int:
        """How many rows of ``H`` the contact has.

        Example
        -------
        >>> contact_kind("hard").rows(planar=False)
        3
        """
        return len(self.components(planar))


#: The registered contact models by name, in the order they are listed to users.
REGISTRY: dict[str, ContactKind] = {}


def register(kind: ContactKind) -> ContactKind:
    """Add ``kind`` to :data:`REGISTRY` (its name and aliases must be new).

    Example
    -------
    >>> register(contact_kind("hard"))
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ArgumentError: contact model 'hard' is already registered
    """
    taken = {spelling for k in REGISTRY.values() for spelling in (k.name, *k.aliases)}
    clash = [s for s in (kind.name, *kind.aliases) if s in taken]
    if clash:
        raise ArgumentError(f"contact model {clash[0]!r} is already registered")
    REGISTRY[kind.name] = kind
    return kind


def contact_kind(spelling: str) -> ContactKind | None:
    """The contact model a model file calls ``spelling`` (its name or an alias), or
    ``None``.

    Example
    -------
    >>> contact_kind("hard").words, contact_kind("sticky")
    ('hard finger', None)
    """
    if spelling in REGISTRY:
        return REGISTRY[spelling]
    return next((k for k in REGISTRY.values() if spelling in k.aliases), None)


def contact_names() -> tuple[str, ...]:
    """The names of the registered contact models, in order.

    Example
    -------
    >>> "frictionless" in contact_names()
    True
    """
    return tuple(REGISTRY)


def planar_names() -> tuple[str, ...]:
    """The names of the contact models that have a planar form.

    Example
    -------
    >>> planar_names()
    ('complete', 'hard', 'frictionless')
    """
    return tuple(k.name for k in REGISTRY.values() if k.planar is not None)


def listed(names: tuple[str, ...], last: str = "or") -> str:
    """``a, b, c or d``.

    Example
    -------
    >>> listed(("a", "b", "c"))
    'a, b or c'
    """
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} {last} {names[-1]}"


register(ContactKind("complete", (), ("v_x", "v_y", "v_z", "w_x", "w_y", "w_z"),
                     ("v_x", "v_y", "w_z"), "complete constraint", "s", position="weld"))
register(ContactKind("soft", (), ("v_x", "v_y", "v_z", "w.n"), None, "soft finger", "D",
                     no_planar="its spin about the normal is out of the plane",
                     not_holonomic="its no-spin condition is not holonomic (it bounds "
                                   "velocities, not positions)"))
register(ContactKind("hard", (), ("v_x", "v_y", "v_z"), ("v_x", "v_y"), "hard finger", "o",
                     position="point"))
register(ContactKind("frictionless", (), ("v.n",), ("v.n",), "frictionless", "^",
                     position="face"))
