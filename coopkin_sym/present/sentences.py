"""Plain-language meaning of an analysis: one sentence per number, motions in words.

A twist ``u = (v, w)`` (reference point at the base origin) is a translation along
``v`` when ``w = 0``; otherwise a screw about the line through ``p = w x v / |w|^2``
with direction ``w`` and pitch ``w.v / |w|^2`` (a pure rotation when the pitch is 0).
Lines are named by the contact points on them when there are any.

Example
-------
>>> from coopkin_sym import load
>>> from coopkin_sym.present.sentences import sentences
>>> for s in sentences(load("paper-case1-hard").analyze()):
...     print(s)  # doctest: +ELLIPSIS
Nm = 2: ...
Nc = 2: ...
Ni = 1: with every joint locked, the object can still rotate about the line through c1 and c2.
...
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import sympy as sp

from coopkin_sym.analysis.kinematics import spatial_twist
from coopkin_sym.analysis.mobility import Analysis
from coopkin_sym.errors import ArgumentError
from coopkin_sym.exact.entry_field import ExprArithmetic, field_of
from coopkin_sym.exact.parse import exact_expr
from coopkin_sym.exact.sympy_bridge import ratfunc_to_sympy
from coopkin_sym.model.contacts import contact_kind

if TYPE_CHECKING:  # pragma: no cover
    from coopkin_sym.analysis.irrational import IrrationalAnalysis, PointMotions
    from coopkin_sym.analysis.locus.types import Component, WitnessMotions

# entries larger than this (in operations) are not simplified for words
_MAX_OPS = 400

# a point, direction, pitch or ratio longer than this (characters) is named, not written
_MAX_VALUE = 160

# a motion whose entries are too large to put in words; like every motion phrase it
# starts with a verb ("the object can still ...", "... by moving ...")
_TOO_LARGE = "make a motion too large to describe in words (see the blocks)"

_WORDS = ["no", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine",
          "ten"]


def contact_words(model: str) -> str:
    """The name of the contact model ``model`` (as a model stores it) in sentences,
    tables and legends: the words of its entry in
    :data:`~coopkin_sym.model.contacts.REGISTRY`.

    Example
    -------
    >>> contact_words("hard"), contact_words("complete")
    ('hard finger', 'complete constraint')
    """
    kind = contact_kind(model)
    if kind is None or not kind.words:
        raise ArgumentError(f"no words for the contact model {model!r}")
    return kind.words


def contact_phrase(model: str) -> str:
    """A contact of model ``model`` in words, as a legend or a table names it.

    Example
    -------
    >>> contact_phrase("soft")
    'soft finger contact'
    """
    return f"{contact_words(model)} contact"


def _count(n: int, noun: str) -> str:
    word = _WORDS[n] if n < len(_WORDS) else str(n)
    return f"{word} {noun}{'' if n == 1 else 's'}"


def _exact_points(contacts) -> list[tuple[str, list[sp.Expr]]]:
    return [(name, [exact_expr(x, None, f"point of {name}") for x in c])
            for name, c in contacts]


def _field_of(vectors: Sequence[Sequence[sp.Expr]],
              contacts: Sequence[tuple[str, Sequence[sp.Expr]]] = ()) -> ExprArithmetic:
    """One field for the entries of ``vectors`` and the points of ``contacts``."""
    return field_of(vectors, [c for _, c in contacts])


def _cross(a: Sequence, b: Sequence) -> list:
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _det3(rows: Sequence[Sequence]):
    return _dot(rows[0], _cross(rows[1], rows[2]))


def _dot(a: Sequence, b: Sequence):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _too_big(vec) -> bool:
    return any(sp.count_ops(e) > _MAX_OPS for e in vec)


def _written(text: str, what: str) -> str:
    """``text``, or ``what`` named when it is too long to read in a sentence."""
    return text if len(text) <= _MAX_VALUE else \
        f"{what} too large to write here"


def _direction(d: list, field: ExprArithmetic) -> str:
    nz = [i for i, e in enumerate(d) if not field.is_zero(e)]
    if len(nz) == 1:
        sign = "-" if (field.to_sympy(d[nz[0]]).is_negative is True) else ""
        return f"{sign}{'xyz'[nz[0]]}"
    return _written("(" + ", ".join(field.text(e) for e in d) + ")", "a direction")


def _contact_points(analysis: Analysis) -> list[tuple[str, list[sp.Expr]]]:
    kin = analysis.kinematics
    return [(contact.name, [ratfunc_to_sympy(x, kin.symbols) for x in point])
            for contact, point in zip(analysis.model.contacts, kin.points, strict=True)]


def _line_name(n: list, ww, w: list, contacts: Sequence[tuple[str, Sequence[sp.Expr]]],
               field: ExprArithmetic) -> str:
    """The axis through ``p = n / ww`` along ``w`` (``n = w x v``, ``ww = w.w``), named
    by the contacts ``c`` on it: ``(ww c - n) x w = 0``, without dividing."""
    on_line: list[tuple[str, Sequence[sp.Expr]]] = []
    for name, c in contacts:
        rel = [ww * field.of(c[i]) - n[i] for i in range(3)]
        if all(field.is_zero(e) for e in _cross(rel, w)):
            on_line.append((name, c))
    places = _places(on_line, field)
    if len(places) >= 2:
        return f"the line through {' and '.join(places[:2])}"
    where = (f"through {places[0]}" if places else "through " + _written(
        "(" + ", ".join(field.text(field.div(e, ww)) for e in n) + ")", "a point"))
    return f"the line {where} along {_direction(w, field)}"


def _places(contacts: Sequence[tuple[str, Sequence[sp.Expr]]],
            field: ExprArithmetic | None = None) -> list[str]:
    """Contact names grouped by position: ``["c1 (= c2)", "c3"]``."""
    if field is None:
        contacts = _exact_points(contacts)
        field = _field_of((), contacts)
    groups: list[tuple[Sequence[sp.Expr], list[str]]] = []
    for name, c in contacts:
        for where, names in groups:
            if all(field.is_zero(field.of(a) - field.of(b))
                   for a, b in zip(where, c, strict=True)):
                names.append(name)
                break
        else:
            groups.append((c, [name]))
    return [names[0] + (f" (= {', '.join(names[1:])})" if len(names) > 1 else "")
            for _, names in groups]


def object_motions_words(vectors, contacts: Sequence[tuple[str, Sequence[sp.Expr]]] = ()
                         ) -> str:
    """Several object twists in words; three rotations about axes through one contact
    point read as turning freely about it.

    Example
    -------
    >>> rotations = [[0, 0, 0, 1, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, 0, 0, 0, 1]]
    >>> object_motions_words(rotations, [("c1", [0, 0, 0]), ("c2", [0, 0, 0])])
    'turn freely about c1 (= c2), in every direction'
    """
    vectors = [spatial_twist([exact_expr(e, None, "twist") for e in v]) for v in vectors]
    contacts = _exact_points(contacts)
    if len(vectors) == 3 and not any(_too_big(v) for v in vectors):
        field = _field_of(vectors, contacts)
        twists = [[field.of(e) for e in v] for v in vectors]
        for place, c in _places_with_points(contacts, field):
            # u = (v, w) fixes the point c when v + w x c = 0
            point = [field.of(x) for x in c]
            if all(all(field.is_zero(a + b) for a, b in zip(
                    u[:3], _cross(u[3:], point), strict=True)) for u in twists) and \
                    not field.is_zero(_det3([u[3:] for u in twists])):
                return f"turn freely about {place}, in every direction"
    return "; ".join(twist_words(v, contacts) for v in vectors)


def _places_with_points(contacts, field: ExprArithmetic):
    names = _places(contacts, field)
    points = []
    for name in names:
        first = name.split(" ")[0]
        points.append(next(c for n, c in contacts if n == first))
    return list(zip(names, points, strict=True))


def twist_words(u, contacts: Sequence[tuple[str, Sequence[sp.Expr]]] = ()) -> str:
    """A rigid-body velocity ``u = (v, w)`` in words, as a verb phrase ("rotate about
    ...", "translate along ...", "make a motion too large to describe in words" when
    the entries are too large); lines are named by the contact points (``(name,
    point)`` pairs) on them.

    The geometry is exact: the entries and the contact points are taken into one
    field of rational functions (over the rationals or a number field) where SymPy can
    build it, so that no expression has to be simplified.

    Example
    -------
    >>> twist_words([0, 0, 0, 0, 0, 1], [("c1", [0, 0, 0]), ("c2", [0, 0, 5])])
    'rotate about the line through c1 and c2'
    """
    u = spatial_twist([exact_expr(e, None, "twist") for e in u])
    if _too_big(u):
        return _TOO_LARGE
    contacts = _exact_points(contacts)
    field = _field_of([u], contacts)
    x = [field.of(e) for e in u]
    v, w = x[:3], x[3:]
    if all(field.is_zero(e) for e in w):
        return f"translate along {_direction(v, field)}"
    ww = _dot(w, w)
    line = _line_name(_cross(w, v), ww, w, contacts, field)
    wv = _dot(w, v)
    if field.is_zero(wv):
        return f"rotate about {line}"
    pitch = _written(f"pitch {field.text(field.div(wv, ww))}", "a pitch")
    return f"screw about {line} with {pitch}"


def describe_twist(u, analysis: Analysis) -> str:
    """A rigid-body velocity ``u = (v, w)`` in words, as a verb phrase ("rotate about
    the line through c1 and c2", "translate along x")."""
    symbols = _symbols(analysis)
    u = analysis.twist_in_base([exact_expr(e, symbols, f"u[{i}]") for i, e in enumerate(u)])
    return twist_words(u, _contact_points(analysis))


def joint_motion_words(qdot, names: Sequence[str]) -> str:
    """Joint velocities in words ("joint q3 alone", "joints q1 and q2 at equal speed").

    Example
    -------
    >>> joint_motion_words([1, -1, 0], ["q1", "q2", "q3"])
    'joints q1 and q2 at opposite speeds'
    """
    q = [exact_expr(e, None, "joint velocity") for e in qdot]
    field = _field_of([q])
    x = [field.of(e) for e in q]
    moving = [(n, e) for n, e in zip(names, x, strict=True) if not field.is_zero(e)]
    if len(moving) == 1:
        return f"joint {moving[0][0]} alone"
    if len(moving) == 2 and field.is_zero(moving[0][1] - moving[1][1]):
        return f"joints {moving[0][0]} and {moving[1][0]} at equal speed"
    if len(moving) == 2 and field.is_zero(moving[0][1] + moving[1][1]):
        return f"joints {moving[0][0]} and {moving[1][0]} at opposite speeds"
    if _too_big([e for e, xe in zip(q, x, strict=True) if not field.is_zero(xe)]):
        return f"joints {', '.join(n for n, _ in moving)} together"
    parts = ", ".join(f"{n}: {field.text(e)}" for n, e in moving)
    if len(parts) > _MAX_VALUE:
        return f"joints {', '.join(n for n, _ in moving)} together"
    return f"joints in the ratio {parts}"


def describe_joint_motion(qdot, analysis: Analysis) -> str:
    """Joint velocities in words ("joint q3 alone", "joints q1 and q2 at equal speed")."""
    symbols = _symbols(analysis)
    return joint_motion_words([exact_expr(e, symbols, f"qdot[{i}]")
                               for i, e in enumerate(qdot)], analysis.model.joint_names)


def _symbols(analysis: Analysis) -> dict[str, sp.Symbol]:
    """The names a text argument may use: the analysis's variables and parameters."""
    symbols = dict(analysis.kinematics.symbols)
    symbols.update({p.name: p for p in analysis.model.parameters})
    return symbols


def _mobility_sentence(n) -> str:
    keep = "keeps" if n.Nm == 1 else "keep"
    return (f"Nm = {n.Nm}: the object and the joints together have "
            f"{_count(n.Nm, 'independent motion')} that {keep} every contact.")


def _connectivity_words(n, dim: int) -> str:
    if n.Nc == dim:
        return "the object can move in every direction (full connectivity)"
    if n.Nc == 0:
        return "the object cannot move at all"
    return f"the object can move in {_count(n.Nc, 'independent direction')} only"


def _number_word(k: int) -> str:
    return _WORDS[k] if k < len(_WORDS) else str(k)


def _connectivity_sentence(n, dim: int, coordinated: Sequence[str] = ()) -> str:
    """``Nc``: how many object motions the joints drive (each told when given) and how
    many they leave free."""
    parts = []
    driven = n.Nc - n.Ni
    if driven and n.Nc:
        parts.append(f"{_number_word(driven)} driven by the joints"
                     + (f" ({'; '.join(coordinated)})" if coordinated else ""))
    if n.Ni and n.Nc:
        parts.append(f"{_number_word(n.Ni)} left free (Ni)")
    return (f"Nc = {n.Nc}: {_connectivity_words(n, dim)}"
            + (": " + " and ".join(parts) if parts else "") + ".")


def _indeterminacy_sentence(n, free: str | None = None) -> str:
    """``Ni``: the object motions with every joint locked (``free`` in words, or their
    count)."""
    if n.Ni == 0:
        return ("Ni = 0: with every joint locked, the object cannot move (no "
                "indeterminate motion).")
    free = free or f"make {_count(n.Ni, 'independent motion')}"
    return f"Ni = {n.Ni}: with every joint locked, the object can still {free}."


def _redundancy_sentence(n, motions: str | None = None) -> str:
    """``Nr``: the joint motions with the object fixed (in words, or their count)."""
    if n.Nr == 0:
        return "Nr = 0: no joint can move while the object stays fixed (no redundancy)."
    if motions:
        return f"Nr = {n.Nr}: with the object fixed, the arms can still move: {motions}."
    return (f"Nr = {n.Nr}: with the object fixed, the arms can still make "
            f"{_count(n.Nr, 'independent motion')}.")


def _force_sentences(n, r: int) -> list[str]:
    """``Ng``, ``Nd`` and ``Nh``: the force domain, from the numbers alone."""
    return [
        f"Ng = {n.Ng}: the contacts can exert {_count(n.Ng, 'independent internal force')}"
        " (squeezing the object without moving it).",
        f"Nd = {n.Nd}: {_count(n.Nd, 'contact force combination')} "
        f"{'produces' if n.Nd == 1 else 'produce'} no torque at the {r} joints: "
        "the joints can neither exert nor feel them (defective grasp)." if n.Nd else
        "Nd = 0: every contact force loads some joint (not defective).",
        f"Nh = {n.Nh}: {_count(n.Nh, 'internal force')} the joints cannot control "
        "(hyperstatic: internal forces that load no joint)." if n.Nh else
        "Nh = 0: every internal force can be controlled by the joints (not "
        "hyperstatic).",
    ]


#: What one more (first) or one less (second) of each number means, for
#: :func:`change_words`; ``{n}`` is the count in words.
_CHANGE_WORDS = {
    "Nc": ("the object gains {n} direction{s} of motion",
           "the object loses {n} direction{s} of motion"),
    "Ni": ("with every joint locked the object gains {n} free motion{s}",
           "with every joint locked the object loses {n} free motion{s}"),
    "Nr": ("the arms gain {n} self-motion{s} that leave{v} the object fixed",
           "the arms lose {n} self-motion{s} that leave{v} the object fixed"),
    "Ng": ("{n} more internal force{s}", "{n} internal force{s} fewer"),
    "Nd": ("{n} more contact force{s} the joints cannot balance",
           "{n} contact force{s} fewer that the joints cannot balance"),
    "Nh": ("{n} more internal force{s} the joints cannot control",
           "{n} internal force{s} fewer that the joints cannot control"),
}


def change_words(changes: Mapping[str, tuple[int, int]]) -> str:
    """What a change of the numbers means for the motions and forces, in words
    (``Nm`` is told by ``Nc`` and ``Nr``, since ``Nm = Nc + Nr``).

    Example
    -------
    >>> change_words({"Nc": (6, 5), "Nr": (2, 3), "Nd": (0, 1)})
    'the object loses one direction of motion; the arms gain one self-motion that leaves \
the object fixed; one more contact force the joints cannot balance'
    >>> change_words({"Nm": (2, 3)})
    'Nm 2 -> 3'
    """
    parts = []
    for name, (before, after) in changes.items():
        words = _CHANGE_WORDS.get(name)
        if name == "Nm" and ("Nc" in changes or "Nr" in changes):
            continue
        if words is None or before == after:
            parts.append(f"{name} {before} -> {after}")
            continue
        k = abs(after - before)
        parts.append(words[after < before].format(
            n=_number_word(k), s="" if k == 1 else "s", v="s" if k == 1 else ""))
    return "; ".join(parts)


def configuration_words(analysis: Analysis) -> str:
    """Where an analysis is: the values set, the joints at home, the symbolic joints.

    Example
    -------
    >>> from coopkin_sym import load
    >>> s = load("paper-case1-hard")
    >>> configuration_words(s.analyze())
    'home (all joints at 0)'
    >>> configuration_words(s.analyze(generic=True))
    'generic: every joint symbolic (q1, q2)'
    >>> configuration_words(s.analyze(free=["q2"]))
    'q2 symbolic, the other joints at home (q1 = 0)'
    >>> configuration_words(s.analyze("q1=pi/2", free=["q2"]))
    'q1=pi/2; q2 symbolic'
    """
    config = analysis.configuration
    at = config.at_text()
    free = sorted(config.free)
    if not free:
        return at or "home (all joints at 0)"
    named = ", ".join(free)
    home = [j for j in analysis.model.joint_names if j not in free
            and j not in config.revolute and j not in config.prismatic]
    if not home:
        return (f"{at}; {named} symbolic" if at
                else f"generic: every joint symbolic ({named})")
    zeros = ", ".join(f"{j} = 0" for j in home)
    if at:
        return f"{at}; {named} symbolic, the other joints at home ({zeros})"
    return f"{named} symbolic, the other joints at home ({zeros})"


def sentences(analysis: Analysis) -> list[str]:
    """One plain sentence per number of ``analysis``, its motions told in words.

    Example
    -------
    >>> from coopkin_sym import load
    >>> print(sentences(load("paper-case1-hard").analyze())[3])
    Nr = 0: no joint can move while the object stays fixed (no redundancy).
    """
    n = analysis.numbers
    driven = n.Nc - n.Ni
    blocks, _ = analysis.available_blocks()    # a block over the term budget is None
    c11, c12, c22, c23 = (blocks[k] for k in ("C11", "C12", "C22", "C23"))
    coordinated = [f"{describe_twist(c12.col(k), analysis)} by moving "
                   f"{describe_joint_motion(c22.col(k), analysis)}"
                   for k in range(c12.cols)] if (0 < driven <= 3 and c12 is not None
                                                 and c22 is not None) else []
    free = object_motions_words([analysis.twist_in_base(c11.col(k)) for k in range(n.Ni)],
                                _contact_points(analysis)) if n.Ni and c11 is not None \
        else None
    redundant = "; ".join(describe_joint_motion(c23.col(k), analysis)
                          for k in range(n.Nr)) if n.Nr and c23 is not None else None
    return [_mobility_sentence(n), _connectivity_sentence(n, analysis.dim, coordinated),
            _indeterminacy_sentence(n, free), _redundancy_sentence(n, redundant),
            *_force_sentences(n, analysis.r)]


def count_sentences(numbers, r: int, dim: int = 6) -> list[str]:
    """One plain sentence per number from the numbers alone (where no basis of the
    subspaces is at hand, e.g. at an irrational point), for ``r`` joints and object
    twists of ``dim`` components (3 for a planar system).

    Example
    -------
    >>> from coopkin_sym.analysis.numbers import Numbers
    >>> print(count_sentences(Numbers(3, 3, 1, 0, 1, 4, 1), 2)[2])
    Ni = 1: with every joint locked, the object can still make one independent motion.
    """
    return [_mobility_sentence(numbers), _connectivity_sentence(numbers, dim),
            _indeterminacy_sentence(numbers), _redundancy_sentence(numbers),
            *_force_sentences(numbers, r)]


def _key(sentence: str) -> str:
    return sentence.split(" ")[0]


def point_sentences(numbers, joints: Sequence[str], motions: PointMotions | None,
                    changed: set[str] | frozenset[str] | None = None,
                    dim: int = 6) -> list[str]:
    """One sentence per number (those in ``changed`` when given) at a point where only
    the numbers and, for a quadratic field, the exact motions behind ``Ni`` and ``Nr``
    are known (:class:`~coopkin_sym.analysis.irrational.PointMotions`): those two are
    told in words, the others by their counts.

    Example
    -------
    >>> from coopkin_sym.analysis.irrational import analyze_irrational
    >>> from coopkin_sym.model.model import load_model
    >>> a = analyze_irrational(load_model("paper-case1-hard"), "q1=-pi/6,q2=pi/6,L=1")
    >>> print(point_sentences(a.numbers, a.joints, a.motions)[2].split(": ")[1])
    with every joint locked, the object can still turn freely about c1 (= c2), in every direction.
    """
    out = [s for s in count_sentences(numbers, len(joints), dim)
           if changed is None or _key(s) in changed]
    if motions is None:
        return out
    keys = {"Ni", "Nr"} if changed is None else {"Ni", "Nr"} & set(changed)
    words = {}
    if "Ni" in keys and numbers.Ni:
        words["Ni"] = _indeterminacy_sentence(numbers, object_motions_words(
            motions.twists_in_base(), motions.contact_points))
    if "Nr" in keys and numbers.Nr:
        words["Nr"] = _redundancy_sentence(numbers, "; ".join(
            joint_motion_words(v, joints) for v in motions.joint_motions))
    return [words.get(_key(s), s) for s in out]


def irrational_sentences(result: IrrationalAnalysis) -> list[str]:
    """The sentences of an analysis at a configuration with irrational coordinates.

    Example
    -------
    >>> from coopkin_sym.analysis.irrational import analyze_irrational
    >>> from coopkin_sym.model.model import load_model
    >>> a = analyze_irrational(load_model("paper-case1-hard"), "q1=-pi/6,q2=pi/6,L=1")
    >>> irrational_sentences(a)[0].startswith("Nm = 3")
    True
    """
    return point_sentences(result.numbers, result.joints, result.motions,
                           dim=result.object_dim)


def witness_sentences(shown: WitnessMotions) -> list[str]:
    """What changes at a locus component's witness, one sentence per changed number:
    from the exact analysis at a rational witness, from the exact motions at an
    algebraic one, or from the counts alone.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.locus.types import WitnessMotions
    >>> a = load("paper-case1-hard").analyze("q1=pi/2,q2=pi/2")
    >>> shown = WitnessMotions(a.numbers, ("q1", "q2"), frozenset({"Nm"}), analysis=a)
    >>> witness_sentences(shown)[0][:8]
    'Nm = 3: '
    """
    if shown.analysis is not None:
        return [s for s in sentences(shown.analysis) if _key(s) in shown.changed]
    return point_sentences(shown.numbers, shown.joints, shown.motions, shown.changed,
                           shown.object_dim)


def component_sentences(component: Component) -> list[str]:
    """What changes on a locus component, in words: from the exact data at its witness,
    or, for a report read back, the sentences it states (empty without a witness).

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Component
    >>> component_sentences(Component(["t_q1"], {"Nm": 3}, None, True))
    []
    """
    if component.shown is not None:
        return witness_sentences(component.shown)
    return list(component.stated_meaning)
