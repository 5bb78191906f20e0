"""Actuated and passive joints: which object motions the motors control, which the
passive joints leave free, and how the passive joints move, exactly.

A joint marked ``actuated: false`` has no motor: it moves as the contacts and the
other joints let it (an underactuated finger, the passive joints of a closed chain).
Split the joint velocities into actuated ``qa`` and passive ``qp`` (and the columns of
``Dt = H D`` into ``Dt_a``, ``Dt_p``). The kinematic relation of the paper,
``Gt^T u = Dt qdot``, becomes

    Gt^T u - Dt_p qp' = Dt_a qa'                                   (1)

as in Bicchi and Prattichizzo, "Manipulability of cooperating robots with unactuated
joints and closed-chain mechanisms" (IEEE T-RA 2000), whose analysis starts from the
same split of the joints. The equation numbers of that paper could not be checked
against its text here, so none are quoted; what follows is derived from (1) alone,
with the subspaces of Bicchi, Melchiorri and Balluchi (ICRA 1992) as the building
blocks.

With the motors held still (``qa' = 0``), (1) is the analysis of the *locked system*
(:meth:`~coopkin_sym.model.model.Model.with_actuators_locked`: the same geometry, the
actuated columns of ``D`` zero). Its nullspace gives

* the **uncontrolled object motions** ``Nuo``: object twists possible with every motor
  still (the object part of ``N(Gt^T | -Dt_p)``; they contain the indeterminate
  ones, ``Nuo >= Ni``): the motors cannot drive or stop them;
* the **internal passive motions** ``Npi = dim N(Dt_p)``: passive joint motions with
  the object and the motors still.

With the motors moving, the object motions compatible with the contacts (``Nc`` of
them) are known modulo the uncontrolled ones, so the motors control

* ``Nco = Nc - Nuo`` **controlled object motions**;
* ``Nar = Nr - Npi`` **actuated redundant motions**: motor motions that leave the
  object still (the passive joints following), the actuated part of ``N(Dt)``;
* ``Nam = Nm - Nuo - Npi = Nco + Nar`` **actuated mobility**: independent motor
  velocities the contacts admit.

In the locked system's own numbers (``Na`` joints locked): ``Nuo = Nc'``,
``Npi = Nr' - Na``. With every joint actuated, ``Nuo = Ni``, ``Npi = 0``,
``Nco = Nc - Ni``, ``Nar = Nr``: the paper's numbers. Every rank and nullspace is
exact, over the rationals at a point or over the field of rational functions of the
free variables (generic numbers).

Example
-------
>>> from coopkin_sym import load
>>> p = load("five-bar").analyze("L=1").passive
>>> p.numbers.as_dict()
{'Na': 2, 'Np': 2, 'Nco': 2, 'Nuo': 1, 'Npi': 0, 'Nar': 0, 'Nam': 2}
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from coopkin_sym.analysis.renderers import Displayable, clip
from coopkin_sym.exact.matrix import POLYNOMIALS, rank

#: The numbers of an analysis with passive joints, in the order tables use.
PASSIVE_NUMBER_NAMES = ("Na", "Np", "Nco", "Nuo", "Npi", "Nar", "Nam")


@dataclass(frozen=True)
class PassiveNumbers:
    """Actuated ``Na`` and passive ``Np`` joints, controlled ``Nco`` and uncontrolled
    ``Nuo`` object motions, internal passive motions ``Npi``, actuated redundant motions
    ``Nar`` and actuated mobility ``Nam`` (see the module text).

    Example
    -------
    >>> n = passive_numbers(2, 2, {"Nm": 3, "Nc": 3, "Nr": 0}, {"Nm": 3, "Nc": 1, "Nr": 2})
    >>> n.Nco, n.Nuo, n.Nam
    (2, 1, 2)
    """

    Na: int
    Np: int
    Nco: int
    Nuo: int
    Npi: int
    Nar: int
    Nam: int

    def as_dict(self) -> dict[str, int]:
        return {k: getattr(self, k) for k in PASSIVE_NUMBER_NAMES}


def passive_numbers(actuated: int, passive: int, numbers, locked) -> PassiveNumbers:
    """The passive-joint numbers from the numbers of the system (``Nm``, ``Nc``,
    ``Nr``) and of its locked system (every actuated joint held still), each a
    :class:`~coopkin_sym.analysis.numbers.Numbers` or a mapping.

    Example
    -------
    >>> passive_numbers(2, 0, {"Nm": 2, "Nc": 2, "Nr": 0},
    ...                 {"Nm": 3, "Nc": 1, "Nr": 2}).as_dict()
    {'Na': 2, 'Np': 0, 'Nco': 1, 'Nuo': 1, 'Npi': 0, 'Nar': 0, 'Nam': 1}
    """
    def get(source, key: str) -> int:
        return int(source[key] if isinstance(source, dict) else getattr(source, key))

    nuo = get(locked, "Nc")
    npi = get(locked, "Nr") - actuated
    nco = get(numbers, "Nc") - nuo
    nar = get(numbers, "Nr") - npi
    return PassiveNumbers(actuated, passive, nco, nuo, npi, nar, nco + nar)


@dataclass(frozen=True, repr=False)
class PassiveAnalysis(Displayable):
    """What the motors control and what the passive joints leave free, at one
    configuration (or generically), exact.

    Attributes
    ----------
    actuated, passive
        The joint names of each kind, in file order.
    numbers
        The :class:`PassiveNumbers`.
    controlled
        Object twists (columns, ``d x Nco``) that, with the uncontrolled ones, span
        every object motion the contacts allow: what the motors drive.
    uncontrolled
        Object twists (``d x Nuo``) possible with every motor still.
    internal
        Joint motions (``r x Npi``, zero on the actuated joints) of the passive joints
        alone, with the object and the motors still.
    actuated_redundant
        Motor velocities (``Na x Nar``) that leave the object still.

    Example
    -------
    >>> from coopkin_sym import load
    >>> p = load("five-bar").analyze("L=1").passive
    >>> p.uncontrolled.T      # the spin about the pin at (0, 2)
    Matrix([[2, 0, 1]])
    >>> p
    <PassiveAnalysis passive q2, q4 (actuated q1, q3): Na=2 Np=2 Nco=2 Nuo=1 Npi=0 Nar=0 Nam=2>
    """

    actuated: tuple[str, ...]
    passive: tuple[str, ...]
    numbers: PassiveNumbers
    controlled: sp.Matrix
    uncontrolled: sp.Matrix
    internal: sp.Matrix
    actuated_redundant: sp.Matrix

    def __repr__(self) -> str:
        numbers = " ".join(f"{k}={v}" for k, v in self.numbers.as_dict().items())
        joints = (f"passive {clip(', '.join(self.passive) or 'none', 80)} (actuated "
                  f"{clip(', '.join(self.actuated) or 'none', 80)})")
        return f"<PassiveAnalysis {joints}: {numbers}>"


def passive_analysis(analysis) -> PassiveAnalysis:
    """The passive-joint analysis of an :class:`~coopkin_sym.analysis.mobility.Analysis`
    (all of it exact; numbers, then the four subspaces).

    Example
    -------
    >>> from coopkin_sym import load
    >>> passive_analysis(load("paper-case1-hard").analyze()).numbers.Nco
    1
    """
    model = analysis.model
    zctx = analysis.ring.zctx
    dim, r = analysis.dim, analysis.r
    flags = [j.actuated for j in model.joints]
    act = [k for k, a in enumerate(flags) if a]
    locked = analysis.decompose_rows(model.with_actuators_locked(),
                                     motors_held_still(model, analysis._q_rows, zctx))
    numbers = passive_numbers(len(act), r - len(act), analysis.numbers, locked.numbers)
    # the locked system's reduced echelon N(Dt): the actuated unit vectors, and the
    # vectors of N(Dt_p), zero on every actuated joint
    internal = [v for v in locked.c23 if all(v[k].is_zero() for k in act)]
    uncontrolled = list(locked.c11) + list(locked.coord_u)
    controlled = _extend(uncontrolled, list(analysis._c11) + list(analysis._coord_u),
                         dim, zctx)
    actuated_redundant = _extend([], [[v[k] for k in act] for v in analysis._c23],
                                 len(act), zctx)
    assert len(internal) == numbers.Npi and len(uncontrolled) == numbers.Nuo
    assert len(controlled) == numbers.Nco and len(actuated_redundant) == numbers.Nar
    cols = analysis._cols
    names = model.joint_names
    return PassiveAnalysis(tuple(names[k] for k in act),
                           tuple(n for k, n in enumerate(names) if not flags[k]),
                           numbers, cols(controlled, dim), cols(uncontrolled, dim),
                           cols(internal, r), cols(actuated_redundant, len(act)))


def motors_held_still(model, q_rows, zctx) -> list:
    """The integer-polynomial rows of ``Q`` with every actuated joint's column zero:
    ``Q`` of :meth:`~coopkin_sym.model.model.Model.with_actuators_locked`, without
    building its kinematics again.

    Example
    -------
    >>> import flint
    >>> from coopkin_sym import load
    >>> model = load("five-bar").model           # planar: 3 object columns, then q1..q4
    >>> ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
    >>> [str(e) for e in motors_held_still(model, [[ctx.constant(1)] * 7], ctx)[0]]
    ['1', '1', '1', '0', '1', '0', '1']
    """
    dim, zero = model.object_dim, zctx.constant(0)
    motors = {dim + k for k, j in enumerate(model.joints) if j.actuated}
    return [[zero if c in motors else e for c, e in enumerate(row)] for row in q_rows]


def _extend(basis: list, candidates: list, n: int, zctx) -> list:
    """The candidates (in order) that each raise the rank of ``basis``: a basis of
    a complement of ``span(basis)`` in ``span(basis + candidates)``."""
    chosen: list = []
    current = rank(basis, n, POLYNOMIALS, zctx)
    for v in candidates:
        if all(e.is_zero() for e in v):
            continue
        trial = rank(basis + chosen + [v], n, POLYNOMIALS, zctx)
        if trial > current:
            chosen.append(v)
            current = trial
    return chosen


__all__ = ["PASSIVE_NUMBER_NAMES", "PassiveAnalysis", "PassiveNumbers", "motors_held_still",
           "passive_analysis", "passive_numbers"]
