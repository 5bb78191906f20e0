"""Numbers at configurations with irrational coordinates, exactly.

An angle such as ``q1 = -pi/6`` has the irrational tangent half-angle
``t = -2 + sqrt(3)``: the rational pipeline cannot evaluate there. Every such value is
algebraic, so the configuration lives in a number field ``Q(alpha)``: SymPy finds one
generator ``alpha`` for all the irrational values (a primitive element) and writes each
value as a polynomial in it; the rows of ``Q`` (built with those joints free) get the
values substituted, and their ranks are computed modulo the minimal polynomial of
``alpha`` (:mod:`coopkin_sym.exact.quotient`). The numbers are then exact at every
conjugate point at once (the ranks are the same at each). For a quadratic field the
subspaces that make the numbers (object motions with the joints locked, joint motions
with the object fixed) are also computed exactly (:class:`PointMotions`; the sentences
that tell them are :func:`coopkin_sym.present.sentences.point_sentences`).

Example
-------
>>> from coopkin_sym.model.model import load_model
>>> a = analyze_irrational(load_model("paper-case1-hard"), "q1=-pi/6,q2=pi/6,L=1")
>>> a.numbers.as_dict()                     # the two contacts at one point
{'Nm': 3, 'Nc': 3, 'Ni': 3, 'Nr': 0, 'Ng': 3, 'Nd': 4, 'Nh': 1}
>>> a.minimal_polynomial, a.alpha
('alpha**2 + 4*alpha + 1', '-2 + sqrt(3)')
>>> len(a.motions.object_twists)            # the three free turns, exactly
3
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import sympy as sp

from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.classes import grasp_classes
from coopkin_sym.analysis.field_rows import field_rows, irrational_values
from coopkin_sym.analysis.mobility import frame_json, numbers_modulo, snapped_json
from coopkin_sym.analysis.numbers import Numbers, numbers_line
from coopkin_sym.analysis.passive import (
    PassiveNumbers,
    motors_held_still,
    passive_numbers,
)
from coopkin_sym.analysis.renderers import Displayable, clip
from coopkin_sym.errors import NotAvailable, NotIrrational
from coopkin_sym.exact.angles import tangent_name
from coopkin_sym.exact.matrix import PolyMatrix
from coopkin_sym.exact.parse import exact_expr
from coopkin_sym.exact.quotient import Quotient
from coopkin_sym.exact.realroot import radical_normal
from coopkin_sym.exact.sympy_bridge import poly_to_sympy, ratfunc_to_sympy
from coopkin_sym.model.configuration import (
    assignments_text,
    split_assignments,
)
from coopkin_sym.model.model import Model

_ALPHA = sp.Symbol("alpha")



@dataclass(frozen=True)
class PointMotions:
    """The motions behind ``Ni`` and ``Nr`` at a point over a quadratic field, exactly.

    ``object_twists`` is a basis of the object twists ``(v, w)`` left free with every
    joint locked (empty when ``Ni`` was not asked for or is 0), ``joint_motions`` a
    basis of the joint rates with the object fixed (likewise for ``Nr``), and
    ``contact_points`` names each contact point, so that lines can be named by them;
    the twists are written in ``object_frame`` (the model's; None: base origin and axes).
    Entries are SymPy numbers in radicals.

    Example
    -------
    >>> from coopkin_sym.model.model import load_model
    >>> a = analyze_irrational(load_model("paper-case1-hard"), "q1=-pi/6,q2=pi/6,L=1")
    >>> [name for name, _ in a.motions.contact_points]
    ['c1', 'c2']
    """

    object_twists: list[list[sp.Expr]]
    joint_motions: list[list[sp.Expr]]
    contact_points: list[tuple[str, list[sp.Expr]]]
    object_frame: tuple | None = None

    def twists_in_base(self) -> list[list[sp.Expr]]:
        """:attr:`object_twists` (written in the model's object frame) with ``v`` at
        the base origin, in base axes."""
        return [kinematics.twist_in_base(u, self.object_frame) for u in self.object_twists]


#: The parts of a rational :class:`~coopkin_sym.analysis.mobility.Analysis` that an
#: analysis over a number field does not compute.
RATIONAL_ONLY = frozenset({
    "C", "C11", "C12", "C22", "C23", "D", "G", "H", "Q", "blocks", "available_blocks",
    "block_terms", "coordinated_factored", "coordinated_form", "coordinated_terms",
    "decompose_rows", "in_angles", "joint_velocities", "object_velocities",
    "manipulability", "kinematics", "twist_in_base", "classes", "certificate", "check",
    "where", "ring", "poly", "m", "configuration", "term_budget", "r", "dim"})


@dataclass(frozen=True)
class IrrationalAnalysis(Displayable):
    """The numbers at a configuration with irrational coordinates.

    ``alpha`` generates the number field of the configuration, a root of
    ``minimal_polynomial``; ``tangents`` gives each irrational ``tan(q/2)`` exactly;
    ``motions`` holds the exact motions behind ``Ni`` and ``Nr`` for a quadratic field
    (None for a field of higher degree); ``joints`` names the joints; ``passive`` has
    the passive-joint numbers (:mod:`coopkin_sym.analysis.passive`) of a model with
    passive joints, else None; ``model`` is the model analyzed; ``variables`` the
    symbols left (parameters without a value).

    Example
    -------
    >>> from coopkin_sym.model.model import load_model
    >>> a = analyze_irrational(load_model("paper-case1-hard"), "q1=-pi/6,q2=pi/6")
    >>> a.at, a.numbers.Ni
    ({'q1': '-pi/6', 'q2': 'pi/6'}, 3)
    >>> print(repr(a).replace(": ", ":\\n"))
    <IrrationalAnalysis paper case 1, hard/hard at q1=-pi/6,q2=pi/6 in Q(-2 + sqrt(3)):
    Nm=3 Nc=3 Ni=3 Nr=0 Ng=3 Nd=4 Nh=1>
    """

    at: dict[str, str]
    numbers: Numbers
    minimal_polynomial: str
    alpha: str
    tangents: dict[str, str]
    motions: PointMotions | None
    joints: tuple[str, ...]
    object_dim: int = 6
    system: str = ""
    passive: PassiveNumbers | None = None
    model: Model | None = field(default=None, repr=False, compare=False)
    variables: tuple[str, ...] = ()

    def __getattr__(self, name: str):
        # only called for names the dataclass does not have: the parts of a rational
        # analysis that are not computed over a number field get a package error
        if name in RATIONAL_ONLY:
            at = assignments_text(self.at)
            raise NotAvailable(
                f"{name} is not available at a configuration with irrational coordinates "
                f"({clip(at, 100)}, over Q({clip(self.alpha, 50)})): only the numbers"
                f"{', the motions behind Ni and Nr (.motions)' if self.motions else ''} "
                f"and the finite mobility (.finite_mobility()) are computed there; the "
                f"blocks, matrices and maps need a rational "
                f"configuration (tan(q/2) rational, e.g. q = 2*atan(p/q))")
        if name.startswith("_"):
            raise AttributeError(f"'IrrationalAnalysis' object has no attribute {name!r}")
        raise NotAvailable(f"an analysis has no {clip(name, 40)!r}: at irrational "
                           f"coordinates it has {', '.join(available_attributes())}")

    def finite_mobility(self, order: int | None = None):
        """The finite mobility here, exactly over the number field of the
        configuration (see :func:`coopkin_sym.analysis.finite.finite_mobility`).

        Example
        -------
        >>> from coopkin_sym.model.model import load_model
        >>> a = analyze_irrational(load_model("four-bar"), "q1=-pi/4,q2=-pi/4")
        >>> a.finite_mobility().dimension
        1
        """
        from coopkin_sym.analysis.finite import finite_mobility

        if self.model is None:
            raise NotAvailable("finite_mobility needs the model analyzed (this analysis "
                               "was built without it)")
        return finite_mobility(self.model, assignments_text(self.at), order)

    def __repr__(self) -> str:
        at = assignments_text(self.at)
        return (f"<IrrationalAnalysis {clip(self.system, 80)} at {clip(at, 100)} in "
                f"Q({clip(self.alpha, 50)}): {numbers_line(self.numbers)}>")

    def as_json(self) -> dict:
        """The JSON of ``coopkin analyze`` here, with the keys of a rational analysis
        (:meth:`~coopkin_sym.analysis.mobility.Analysis.as_json`): the blocks and their
        coordinated form are null (not computed here), their shapes follow from the
        numbers. Without words (the presentation layer adds why the blocks are
        ``"omitted"`` and the sentences as ``"meaning"``).

        Example
        -------
        >>> from coopkin_sym.model.model import load_model
        >>> a = analyze_irrational(load_model("paper-case1-hard"), "q1=-pi/6,q2=pi/6")
        >>> data = a.as_json()
        >>> data["blocks"]["C11"], data["shapes"]["C11"], data["variables"]
        (None, [6, 3], ['L'])
        """
        n, r, dim = self.numbers, len(self.joints), self.object_dim
        driven = n.Nc - n.Ni
        model = self.model
        return {
            "system": self.system,
            "configuration": assignments_text(self.at),
            "point": "irrational",
            "variables": list(self.variables),
            "joints": list(self.joints),
            "twist": list(model.twist_names) if model is not None else [],
            "numbers": n.as_dict(),
            "classes": list(grasp_classes(n)),
            "blocks": dict.fromkeys(("C11", "C12", "C22", "C23")),
            "shapes": {"C11": [dim, n.Ni], "C12": [dim, driven], "C22": [r, driven],
                       "C23": [r, n.Nr]},
            "coordinated_form": None,
            "object_frame": frame_json(model.object_frame) if model is not None else None,
            "snapped": snapped_json(model.snapped) if model is not None else [],
            "field": {"alpha": self.alpha, "minimal_polynomial": self.minimal_polynomial,
                      "tangents": self.tangents},
            # ranks modulo the minimal polynomial: exact at every conjugate point
            "certificate": {"exact": True, "error_bits": None, "points": 0, "ranks": []},
            **({"passive": self._passive_json()} if self.passive else {})}

    def _passive_json(self) -> dict:
        """The passive-joint numbers; their subspaces are not computed here (null)."""
        joints = self.model.joints if self.model is not None else ()
        return {"actuated": [j.name for j in joints if j.actuated],
                "passive": [j.name for j in joints if not j.actuated],
                "numbers": self.passive.as_dict(),
                **dict.fromkeys(("controlled", "uncontrolled", "internal",
                                 "actuated_redundant"))}


def available_attributes() -> list[str]:
    """The public attributes an :class:`IrrationalAnalysis` has, sorted.

    Example
    -------
    >>> available_attributes()[:5]
    ['alpha', 'as_json', 'at', 'finite_mobility', 'joints']
    """
    names = {*IrrationalAnalysis.__dataclass_fields__, *vars(IrrationalAnalysis)}
    return sorted(n for n in names if not n.startswith("_"))


def analyze_irrational(model: Model, at) -> IrrationalAnalysis:
    """The numbers of ``model`` at ``at``, where some angles have an irrational (but
    algebraic) ``tan(q/2)``, exactly over the number field they generate.

    Raises :class:`NotIrrational` when every value is rational.
    """
    rows_at = field_rows(model, at)
    rational, irrational, names = rows_at.rational, rows_at.irrational, rows_at.names
    kin, rows, quotient, minimal = rows_at.kin, rows_at.rows, rows_at.quotient, rows_at.minimal
    alpha = rows_at.alpha
    numbers = numbers_modulo(rows, model, kin.row_contacts, quotient)
    passive = None
    if model.passive_joints and not model.locked:
        locked = numbers_modulo(motors_held_still(model, rows, kin.ring.zctx),
                                model.with_actuators_locked(), kin.row_contacts, quotient)
        motors = sum(j.actuated for j in model.joints)
        passive = passive_numbers(motors, len(model.joints) - motors, numbers, locked)
    values = {kin.symbols[tangent_name(n)]: irrational[n] for n in names}
    motions = point_motions(model, numbers, rows, quotient, kin, values,
                            degree=sp.degree(minimal, _ALPHA))
    given = {**{n: str(v) for n, v in rational}, **{n: str(dict(split_assignments(
        at, "--at"))[n]) for n in names}}
    order_names = [j.name for j in model.joints] + [p.name for p in model.parameters]
    return IrrationalAnalysis(
        at={k: given[k] for k in order_names if k in given}, numbers=numbers,
        minimal_polynomial=sp.sstr(minimal), alpha=sp.sstr(alpha),
        tangents={n: sp.sstr(irrational[n]) for n in names}, motions=motions,
        joints=model.joint_names, object_dim=model.object_dim, system=model.name,
        passive=passive, model=model,
        variables=tuple(n for n in kin.ring.names if n not in
                        {tangent_name(x) for x in names}))


def point_motions(model: Model, numbers: Numbers, rows, quotient: Quotient, kin,
                  values: Mapping[sp.Symbol, sp.Expr], degree: int,
                  changed: set[str] | None = None) -> PointMotions | None:
    """The exact motions behind ``Ni`` and ``Nr`` (those in ``changed`` when given) at a
    point over ``Q(alpha)``: the rows of ``Q`` there (``rows``, modulo ``quotient``) and
    the exact value of every remaining variable (``values``, SymPy). None for a field of
    degree above 2, or when neither number is asked for."""
    keys = {"Ni", "Nr"} if changed is None else {"Ni", "Nr"} & changed
    if degree > 2 or not keys:
        return None

    def exact(e) -> sp.Expr:
        # every key a symbol: replacing them is substituting them, without subs's search
        return radical_normal(exact_expr(e, None, "value").xreplace(values))

    def written(v) -> list[sp.Expr]:
        return [sp.Integer(0) if e.is_zero() else
                exact(poly_to_sympy(e, kin.ring, kin.symbols)) for e in v]

    def vectors(block, ncols):
        return [written(v) for v in PolyMatrix(block, ncols, quotient).nullspace()]

    twists: list[list[sp.Expr]] = []
    contacts: list[tuple[str, list[sp.Expr]]] = []
    joint_motions: list[list[sp.Expr]] = []
    if "Ni" in keys and numbers.Ni:
        contacts = [(c.name, [exact(ratfunc_to_sympy(v, kin.symbols)) for v in point])
                    for c, point in zip(model.contacts, kin.points, strict=True)]
        twists = vectors([r[:model.object_dim] for r in rows], model.object_dim)
    if "Nr" in keys and numbers.Nr:
        joint_motions = [written(v) for v in _joint_nullspace(model, rows, kin.row_contacts,
                                                              quotient)]
    return PointMotions(object_twists=twists, joint_motions=joint_motions,
                        contact_points=contacts, object_frame=model.object_frame)


def _joint_nullspace(model: Model, rows, row_contacts, quotient: Quotient) -> list[list]:
    """A basis of ``N(Dt)``, the nullspace of the joint columns of ``rows``, arm by arm:
    ``Dt`` is block diagonal (an arm's rows are zero in the other arms' joints), so the
    reduced-echelon basis of the whole is that of each arm's block, each vector zero
    outside its arm (the same vectors, in the same order)."""
    zero, one = quotient.zctx.constant(0), quotient.zctx.constant(1)
    dim, r = model.object_dim, len(model.joints)
    out: list[list] = []
    for a, arm in enumerate(model.arms):
        start = model.joint_offset(a)
        width = len(arm.joints)
        if not width:
            continue
        block = [row[dim + start:dim + start + width]
                 for row, c in zip(rows, row_contacts, strict=True)
                 if model.contacts[c].arm == a]
        found = (PolyMatrix(block, width, quotient).nullspace() if block else
                 [[one if i == k else zero for i in range(width)] for k in range(width)])
        out += [[zero] * start + list(v) + [zero] * (r - start - width) for v in found]
    return out


__all__ = ["IrrationalAnalysis", "NotIrrational", "PointMotions", "analyze_irrational",
           "available_attributes", "irrational_values", "point_motions"]

