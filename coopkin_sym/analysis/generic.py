"""Generic numbers from exact ranks at random points, with their certificate.

The numbers come from three ranks over the field ``Q(t, L)`` of the symbolic variables:
of ``Q``, of its object columns ``H G^T`` and of its joint columns ``H D``. Building
bases of the nullspaces over that field (the blocks) can take long; the ranks alone
need much less:

* **Lower bounds, certified.** At any point, the exact rank of the integer matrix
  ``Q(point)`` is at most the generic rank. The ranks at a few random integer points
  (flint's ``fmpz_mat``) are lower bounds; ``H D`` is ranked arm by arm (each arm's
  joints act only in its own contacts' rows).
* **Upper bounds, certified where it is cheap.**

  - *Size*: a rank is at most the number of rows and of columns; ``rank Q`` is at most
    ``rank H G^T + rank H D`` and ``rank H D + dim``.
  - *Elimination*: the blocks the sizes leave open are ranked exactly over the field
    by fraction-free elimination: ``H G^T`` (six columns), each arm's joint columns
    eliminated from its own rows (``rank H D``), then the six object columns left
    over from every arm (their rank added to ``rank H D`` is ``rank Q``). This runs
    within a time bound.

* **Otherwise probabilistic, and said so.** A rank below its generic value at a point
  means a nonzero minor vanishes there; with coordinates drawn uniformly from
  ``2 B + 1`` integers, that has probability at most ``deg / (2 B + 1)``
  (Schwartz-Zippel), ``deg`` bounded by the sum of the row degrees. Over ``s``
  independent points and the uncertified ranks, the error is below ``2^-k``, and the
  certificate states ``k``.

Example
-------
>>> from coopkin_sym import load
>>> a = load("paper-case1-hard").analyze(generic=True)
>>> a.numbers.as_dict()["Ni"], a.certificate.exact
(1, True)
"""

from __future__ import annotations

import random
from collections.abc import Sequence
from dataclasses import dataclass, field
from fractions import Fraction

import flint

from coopkin_sym.analysis.numbers import Numbers, numbers_from_ranks
from coopkin_sym.errors import TimeLimitReached
from coopkin_sym.exact.deadline import check, time_limit
from coopkin_sym.exact.matrix import PolyMatrix
from coopkin_sym.exact.ring import ClearedRows
from coopkin_sym.model.model import Model

#: Random coordinates are drawn from the integers in ``[-2**SAMPLE_BITS, 2**SAMPLE_BITS]``.
SAMPLE_BITS = 62
#: Independent random points (each one multiplies the error exponent).
POINTS = 2
#: Wall-clock seconds spent on the exact eliminations before the result is given as
#: probabilistic (the numbers themselves never wait on it longer).
CERTIFY_SECONDS = 2.0


@dataclass(frozen=True)
class RankBound:
    """One rank behind the numbers and how its value is known.

    ``how`` is ``"size"`` (it equals a bound from the matrix sizes or other certified
    ranks), ``"elimination"`` (computed over
    the field of rational functions), ``"point"`` (no variable: the exact rank) or
    ``"sampled"`` (a lower bound at random points, not certified).

    Example
    -------
    >>> RankBound("Q", 15, "size").certified
    True
    """

    matrix: str
    rank: int
    how: str

    @property
    def certified(self) -> bool:
        return self.how != "sampled"


@dataclass(frozen=True)
class NumbersCertificate:
    """How the numbers of an analysis are known.

    Attributes
    ----------
    exact
        Every rank is certified: the numbers are exact.
    error_bits
        When not exact: the probability that a number is wrong is below
        ``2**-error_bits`` (over the random points drawn); ``None`` when exact.
    points
        Random points ranked (0 for a configuration with no symbolic variable, or
        when the numbers come from elimination over the field).
    ranks
        Each rank and how it is known.

    Example
    -------
    >>> c = NumbersCertificate.from_ranks([RankBound("Q", 3, "elimination")], points=2)
    >>> c.exact, c.error_bits
    (True, None)
    """

    exact: bool
    error_bits: int | None
    points: int
    ranks: tuple[RankBound, ...] = field(default_factory=tuple)

    @classmethod
    def from_ranks(cls, ranks: Sequence[RankBound], points: int,
                   error_bits: int | None = None) -> NumbersCertificate:
        exact = all(r.certified for r in ranks)
        return cls(exact, None if exact else error_bits, points, tuple(ranks))

    @classmethod
    def by_elimination(cls) -> NumbersCertificate:
        """The certificate of numbers computed over the field of rational functions."""
        return cls(True, None, 0, ())

    def as_dict(self) -> dict:
        """Plain data (the ``certificate`` of ``coopkin analyze --json``)."""
        return {"exact": self.exact, "error_bits": self.error_bits, "points": self.points,
                "ranks": [{"matrix": r.matrix, "rank": r.rank, "how": r.how}
                          for r in self.ranks]}


# --- evaluation at points ---------------------------------------------------------------
def _value_matrix(q_rows, point: Sequence[int]) -> list[list[int]]:
    return [[0 if p.is_zero() else int(p(*point)) for p in row] for row in q_rows]


def _rank(values: list[list[int]], rows: Sequence[int], cols: Sequence[int]) -> int:
    if not rows or not cols:
        return 0
    return flint.fmpz_mat([[values[i][c] for c in cols] for i in rows]).rank()


def _row_degree(row) -> int:
    return max((int(p.total_degree()) for p in row if not p.is_zero()), default=0)


def _minor_degree(q_rows, rows: Sequence[int], cols: Sequence[int], rank: int) -> int:
    """A bound on the total degree of any ``rank x rank`` minor of the block."""
    degrees = sorted((_row_degree([q_rows[i][c] for c in cols]) for i in rows), reverse=True)
    return sum(degrees[:rank])


# --- the numbers ------------------------------------------------------------------------
@dataclass
class _Sampled:
    q: int = 0
    gt: int = 0
    arms: list[int] = field(default_factory=list)


def generic_numbers(q_rows, model: Model, row_contacts: Sequence[int], zctx, *,
                    points: int = POINTS, seed: int | None = None,
                    certify_seconds: float | None = CERTIFY_SECONDS
                    ) -> tuple[Numbers, NumbersCertificate]:
    """The numbers over the fraction field of ``zctx``'s ring, from exact ranks at
    ``points`` random integer points, with their :class:`NumbersCertificate`.

    Parameters
    ----------
    q_rows
        The rows of ``Q`` cleared to integer polynomials (``ring.clear_row``), or a
        :class:`~coopkin_sym.exact.ring.ClearedRows` that clears a row only when an
        elimination uses it and gives the values at the points from the fractions.
    model, row_contacts
        The model and the contact of each row (arm by arm structure).
    zctx
        The polynomial context of the rows (the symbolic variables).
    points, seed
        How many random points, and a seed (``None``: fresh system randomness).
    certify_seconds
        Wall-clock bound of the exact eliminations (``None``: no bound).

    Example
    -------
    >>> from coopkin_sym.analysis import kinematics
    >>> from coopkin_sym.model import load_model
    >>> from coopkin_sym.model.configuration import Configuration
    >>> model = load_model("paper-case2-hard")
    >>> kin = kinematics.build(model, Configuration.parse(model, None, "all"))
    >>> rows = [kin.ring.clear_row(r) for r in kin.Q]
    >>> numbers, cert = generic_numbers(rows, model, kin.row_contacts, kin.ring.zctx,
    ...                                 seed=1)
    >>> numbers.as_dict()["Nm"], cert.exact
    (8, True)
    """
    m = len(q_rows)
    dim = model.object_dim
    r = len(model.joints)
    n = dim + r
    owners = [model.contacts[c].arm for c in row_contacts]
    arm_blocks = []
    for a, arm in enumerate(model.arms):
        col0 = dim + model.joint_offset(a)
        arm_blocks.append(([i for i, o in enumerate(owners) if o == a],
                           list(range(col0, col0 + len(arm.joints)))))
    all_rows, gt_cols, all_cols = list(range(m)), list(range(dim)), list(range(n))
    nvars = zctx.nvars()
    rng = random.Random(seed) if seed is not None else random.SystemRandom()
    bound = 2 ** SAMPLE_BITS
    count = points if nvars else 1
    best = _Sampled(arms=[-1] * len(arm_blocks))
    best.q = best.gt = -1
    for _ in range(count):
        check("the ranks at random points")
        point = [rng.randint(-bound, bound) for _ in range(nvars)]
        values = (q_rows.values_at(point) if isinstance(q_rows, ClearedRows)
                  else _value_matrix(q_rows, point))
        rq = _rank(values, all_rows, all_cols)
        if rq > best.q:
            best.q = rq
        rg = _rank(values, all_rows, gt_cols)
        if rg > best.gt:
            best.gt = rg
        for k, (rows, cols) in enumerate(arm_blocks):
            ra = _rank(values, rows, cols)
            if ra > best.arms[k]:
                best.arms[k] = ra
    rd = sum(best.arms)
    if not nvars:
        ranks = [RankBound("Q", best.q, "point"), RankBound("Gt", best.gt, "point"),
                 RankBound("Dt", rd, "point")]
        return (numbers_from_ranks(m, r, best.q, best.gt, rd, dim=dim),
                NumbersCertificate.from_ranks(ranks, 0))
    arm_how = [("size" if ra == min(len(rows), len(cols)) else None)
               for (rows, cols), ra in zip(arm_blocks, best.arms, strict=True)]
    how = {"Gt": "size" if best.gt == min(m, dim) else None, "Q": None}

    def q_bound() -> int:
        d_bound = sum(ra if done else min(len(rows), len(cols)) for (rows, cols), ra, done
                      in zip(arm_blocks, best.arms, arm_how, strict=True))
        g_bound = best.gt if how["Gt"] else min(m, dim)
        return min(m, n, d_bound + g_bound, d_bound + dim)

    def certify() -> None:
        """Exact ranks over the fraction field, by fraction-free elimination, of the
        blocks the bounds leave open (partial progress is kept)."""
        if how["Gt"] is None:
            best.gt = PolyMatrix([q_rows[i][:dim] for i in all_rows], dim,
                                 context=zctx).rank()
            how["Gt"] = "elimination"
        if q_bound() == best.q and None not in arm_how:
            return
        if q_bound() == best.q:
            # rank Q is known from the sizes: only the open arm blocks are ranked
            for k, (rows, cols) in enumerate(arm_blocks):
                if arm_how[k] is None:
                    block = (q_rows.block(rows, cols) if isinstance(q_rows, ClearedRows)
                             else [[q_rows[i][c] for c in cols] for i in rows])
                    best.arms[k] = PolyMatrix(block, len(cols), context=zctx).rank()
                    arm_how[k] = "elimination"
            if q_bound() == best.q:
                return
        # arm by arm: each arm's joint columns eliminated from its own rows, then the
        # object rows left over from every arm ranked together (rank Q)
        leftover = [q_rows[i][:dim] for i, o in enumerate(owners) if o is None]
        for k, (rows, cols) in enumerate(arm_blocks):
            block = [[q_rows[i][c] for c in cols] + q_rows[i][:dim] for i in rows]
            if not block:
                continue
            pivots, left = PolyMatrix(block, len(cols) + dim, context=zctx).eliminate(
                range(len(cols)))
            best.arms[k], arm_how[k] = pivots, "elimination"
            leftover += [row[len(cols):] for row in left]
        if q_bound() == best.q:
            return
        best.q = sum(best.arms) + PolyMatrix(leftover, dim, context=zctx).rank()
        how["Q"] = "elimination"

    if q_bound() != best.q or how["Gt"] is None or None in arm_how:
        try:
            if certify_seconds is None:
                certify()
            else:
                with time_limit(certify_seconds):
                    certify()
        except TimeLimitReached:
            pass
    if how["Q"] is None and q_bound() == best.q:
        how["Q"] = "size"
    q_how, gt_how = how["Q"], how["Gt"]
    rd = sum(best.arms)
    ranks = [RankBound("Q", best.q, q_how or "sampled"),
             RankBound("Gt", best.gt, gt_how or "sampled")]
    ranks += [RankBound(f"Dt[{arm.name}]", ra, known or "sampled") for arm, ra, known
              in zip(model.arms, best.arms, arm_how, strict=True)]
    error = Fraction(0)
    size = 2 * bound + 1
    checks = [("Q", all_rows, all_cols, best.q, q_how), ("Gt", all_rows, gt_cols, best.gt,
                                                        gt_how)]
    checks += [("Dt", rows, cols, ra, known) for (rows, cols), ra, known
               in zip(arm_blocks, best.arms, arm_how, strict=True)]
    for _, rows, cols, _rank_found, known in checks:
        if known is None:
            top = min(len(rows), len(cols))
            degree = max(_minor_degree(q_rows, rows, cols, top), 1)
            error += Fraction(degree, size) ** count
    # floor(log2(1 / error)), exactly
    bits = None if error == 0 else max(0, (error.denominator // error.numerator
                                           ).bit_length() - 1)
    numbers = numbers_from_ranks(m, r, best.q, best.gt, rd, dim=dim)
    return numbers, NumbersCertificate.from_ranks(ranks, count, bits)

