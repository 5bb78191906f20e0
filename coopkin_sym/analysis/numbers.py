"""The seven numbers of a cooperating system, from three ranks: the one formula.

With ``m`` contact constraint rows, ``r`` joints and object twists of ``d``
components (``d = 6``, or 3 for a planar system), ``Q = [-H G^T | H D]`` is
``m x (d + r)``. Its rank and the ranks of its two column blocks give every number of
Bicchi, Melchiorri and Balluchi (ICRA 1992):

* mobility ``Nm = d + r - rank Q`` (the dimension of ``ker Q``),
* redundancy ``Nr = r - rank HD`` (joint motions with the object fixed),
* connectivity ``Nc = Nm - Nr`` (object motions compatible with the contacts),
* indeterminacy ``Ni = d - rank HG^T`` (object motions with every joint locked),
* graspable ``Ng = m - rank HG^T`` (internal forces), defective
  ``Nd = m - rank HD``, hyperstatic ``Nh = m - rank Q``.

Every path of the package (the exact decomposition, the sweep's modular ranks, the
float comparison, the locus) counts through :func:`seven_numbers`.

Example
-------
>>> numbers_from_ranks(6, 2, 6, 5, 2, dim=6).as_dict()    # paper case 1, hard contacts
{'Nm': 2, 'Nc': 2, 'Ni': 1, 'Nr': 0, 'Ng': 1, 'Nd': 4, 'Nh': 0}
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from coopkin_sym.analysis.renderers import Displayable
from coopkin_sym.exact.matrix import PolyMatrix

#: The seven numbers, in the order every table and file of the package uses.
NUMBER_NAMES = ("Nm", "Nc", "Ni", "Nr", "Ng", "Nd", "Nh")


@dataclass(frozen=True)
class Numbers(Displayable):
    """Mobility ``Nm``, connectivity ``Nc``, indeterminacy ``Ni``, redundancy ``Nr``,
    and the force-domain graspable ``Ng`` (internal forces), defective ``Nd`` and
    hyperstatic ``Nh`` numbers.

    Example
    -------
    >>> Numbers(2, 2, 1, 0, 1, 4, 0).as_dict()["Ni"]
    1
    """

    Nm: int
    Nc: int
    Ni: int
    Nr: int
    Ng: int
    Nd: int
    Nh: int

    def as_dict(self) -> dict[str, int]:
        return {k: getattr(self, k) for k in NUMBER_NAMES}


def numbers_line(numbers: Numbers | Mapping[str, int]) -> str:
    """The seven numbers on one line, ``Nm=2 Nc=2 ...`` (``?`` for one a mapping
    lacks), for the short ``repr`` of the results.

    Example
    -------
    >>> numbers_line(Numbers(3, 3, 1, 0, 0, 4, 0))
    'Nm=3 Nc=3 Ni=1 Nr=0 Ng=0 Nd=4 Nh=0'
    """
    get = numbers.get if isinstance(numbers, Mapping) else numbers.as_dict().get
    return " ".join(f"{k}={get(k, '?')}" for k in NUMBER_NAMES)


def seven_numbers(m, r, rank_q, rank_gt, rank_dt, *, dim: int) -> tuple:
    """``(Nm, Nc, Ni, Nr, Ng, Nd, Nh)`` from ``m`` rows, ``r`` joints, object twists
    of ``dim`` components (6, or 3 in the plane) and the ranks of ``Q``, ``H G^T`` and
    ``H D``. Plain arithmetic, so the ranks may be integers or numpy integer arrays
    (one entry per point).

    Example
    -------
    >>> seven_numbers(6, 2, 6, 5, 2, dim=6)
    (2, 2, 1, 0, 1, 4, 0)
    """
    nm, nr = dim + r - rank_q, r - rank_dt
    return (nm, nm - nr, dim - rank_gt, nr, m - rank_gt, m - rank_dt, m - rank_q)


def numbers_from_ranks(m: int, r: int, rank_q: int, rank_gt: int, rank_dt: int, *,
                       dim: int) -> Numbers:
    """The seven numbers of a system with ``m`` constraint rows, ``r`` joints and
    object twists of ``dim`` components from the ranks of ``Q``, ``H G^T`` and ``H D``.

    Example
    -------
    >>> numbers_from_ranks(6, 2, 6, 5, 2, dim=6).Nm
    2
    """
    return Numbers(*(int(n) for n in seven_numbers(m, r, rank_q, rank_gt, rank_dt,
                                                    dim=dim)))


def ranks_of_q(q: PolyMatrix, *, dim: int) -> tuple[int, int, int]:
    """The three ranks the numbers come from: of ``Q``, of its ``dim`` object columns
    (``H G^T``) and of its joint columns (``H D``), over ``q``'s domain.

    Example
    -------
    >>> import flint
    >>> ctx = flint.fmpz_mpoly_ctx.get(("L",), "degrevlex")
    >>> one, zero = ctx.constant(1), ctx.constant(0)
    >>> ranks_of_q(PolyMatrix([[one] + [zero] * 6, [zero] * 6 + [one]], 7), dim=6)
    (2, 1, 1)
    """
    return q.split_ranks(dim)


def ranks_from_numbers(numbers, r: int, *, dim: int) -> tuple[int, int, int]:
    """The ranks of ``Q``, ``H G^T`` and ``H D`` that give ``numbers`` (a
    :class:`Numbers` or a mapping with ``Nm``, ``Ni``, ``Nr``) for ``r`` joints and
    object twists of ``dim`` components: the formula of :func:`seven_numbers` read
    backwards.

    Example
    -------
    >>> ranks_from_numbers({"Nm": 2, "Ni": 1, "Nr": 0}, 2, dim=6)
    (6, 5, 2)
    """
    get = numbers.get if isinstance(numbers, dict) else lambda k: getattr(numbers, k)
    return dim + r - get("Nm"), dim - get("Ni"), r - get("Nr")
