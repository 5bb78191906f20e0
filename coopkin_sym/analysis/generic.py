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
from contextlib import nullcontext
from dataclasses import dataclass, field
from fractions import Fraction

from coopkin_sym.analysis.numbers import Numbers, numbers_from_ranks
from coopkin_sym.errors import TimeLimitReached
from coopkin_sym.exact.deadline import check, time_limit
from coopkin_sym.exact.matrix import (
    POLYNOMIALS,
    RATIONALS,
    ArmBlock,
    PrimeField,
    eliminate_arm,
    rank,
    rank_triple,
)
from coopkin_sym.exact.ring import ClearedRows
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model

#: Random coordinates are drawn from the integers in ``[-2**SAMPLE_BITS, 2**SAMPLE_BITS]``.
SAMPLE_BITS = 62
#: Independent random points (each one multiplies the error exponent).
POINTS = 2
#: The prime of :func:`chain_numbers` (``2**61 - 1``).
CHAIN_PRIME = 2**61 - 1
#: Wall-clock seconds spent on the exact eliminations before the result is given as
#: probabilistic (the numbers themselves never wait on it longer).
CERTIFY_SECONDS = 2.0


@dataclass(frozen=True)
class RankBound:
    """One rank behind the numbers and how its value is known.

    ``how`` is ``"size"`` (it equals a bound from the matrix sizes or other certified
    ranks), ``"contacts"`` (``rank H G^T`` equal to its rank with every contact point
    and normal an independent variable, :func:`grasp_rank_bound`), ``"elimination"``
    (computed over the field of rational functions), ``"point"`` (no variable: the
    exact rank) or ``"sampled"`` (a lower bound at random points, not certified).

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


def _row_degree(row) -> int:
    return max((int(p.total_degree()) for p in row if not p.is_zero()), default=0)


def _minor_degree(q_rows, rows: Sequence[int], cols: Sequence[int], rank: int) -> int:
    """A bound on the total degree of any ``rank x rank`` minor of the block."""
    degrees = sorted((_row_degree([q_rows[i][c] for c in cols]) for i in rows), reverse=True)
    return sum(degrees[:rank])


# --- the numbers ------------------------------------------------------------------------
def _arm_blocks(model: Model, row_contacts: Sequence[int], dim: int) -> list[ArmBlock]:
    """One block of ``H D`` per arm (possibly without rows), in ``Q``'s columns."""
    owners = [model.contacts[c].arm for c in row_contacts]
    blocks = []
    for a, arm in enumerate(model.arms):
        col0 = dim + model.joint_offset(a)
        blocks.append(([i for i, o in enumerate(owners) if o == a], col0,
                       col0 + len(arm.joints)))
    return blocks


def _size(block: ArmBlock) -> int:
    rows, c0, c1 = block
    return min(len(rows), c1 - c0)


@dataclass
class _Sampled:
    """The best ranks found so far, and how each is known (None: sampled only)."""

    q: int
    gt: int
    arms: list[int]
    q_how: str | None = None
    gt_how: str | None = None
    arm_how: list[str | None] = field(default_factory=list)


def _sample(q_rows, n: int, dim: int, arms: list[ArmBlock], nvars: int, count: int,
            seed: int | None) -> _Sampled:
    """The largest ranks at ``count`` random integer points (lower bounds)."""
    rng = random.Random(seed) if seed is not None else random.SystemRandom()
    bound = 2 ** SAMPLE_BITS
    best = _Sampled(-1, -1, [-1] * len(arms))
    for _ in range(count):
        check("the ranks at random points")
        point = [rng.randint(-bound, bound) for _ in range(nvars)]
        values = (q_rows.values_at(point) if isinstance(q_rows, ClearedRows)
                  else _value_matrix(q_rows, point))
        ranks = rank_triple(values, n, dim, RATIONALS, arms)
        best.q, best.gt = max(best.q, ranks.q), max(best.gt, ranks.gt)
        best.arms = [max(b, ra) for b, ra in zip(best.arms, ranks.arms, strict=True)]
    return best


class _Certify:
    """The exact ranks over the fraction field the size bounds leave open, by
    fraction-free elimination (partial progress is kept in :attr:`best`)."""

    def __init__(self, q_rows, best: _Sampled, arms: list[ArmBlock], m: int, n: int,
                 dim: int, zctx):
        self.q_rows, self.best, self.arms = q_rows, best, arms
        self.m, self.n, self.dim, self.zctx = m, n, dim, zctx
        best.arm_how = [("size" if ra == _size(a) else None)
                        for a, ra in zip(arms, best.arms, strict=True)]
        best.gt_how = "size" if best.gt == min(m, dim) else None

    def q_bound(self) -> int:
        best = self.best
        d_bound = sum(ra if done else _size(a) for a, ra, done
                      in zip(self.arms, best.arms, best.arm_how, strict=True))
        g_bound = best.gt if best.gt_how else min(self.m, self.dim)
        return min(self.m, self.n, d_bound + g_bound, d_bound + self.dim)

    def settled(self) -> bool:
        best = self.best
        return (self.q_bound() == best.q and best.gt_how is not None
                and None not in best.arm_how)

    def run(self) -> None:
        best, q_rows, dim, zctx = self.best, self.q_rows, self.dim, self.zctx
        if best.gt_how is None:
            best.gt = rank([q_rows[i][:dim] for i in range(self.m)], dim, POLYNOMIALS, zctx)
            best.gt_how = "elimination"
        if self.q_bound() == best.q:
            if None not in best.arm_how:
                return
            # rank Q is known from the sizes: only the open arm blocks are ranked
            for k, (rows, c0, c1) in enumerate(self.arms):
                if best.arm_how[k] is None:
                    cols = range(c0, c1)
                    block = (q_rows.block(rows, cols) if isinstance(q_rows, ClearedRows)
                             else [[q_rows[i][c] for c in cols] for i in rows])
                    best.arms[k] = rank(block, c1 - c0, POLYNOMIALS, zctx)
                    best.arm_how[k] = "elimination"
            if self.q_bound() == best.q:
                return
        # arm by arm: each arm's joint columns eliminated from its own rows, then the
        # object rows left over from every arm ranked together (rank Q)
        in_arm = {i for rows, _, _ in self.arms for i in rows}
        leftover = [q_rows[i][:dim] for i in range(self.m) if i not in in_arm]
        for k, arm in enumerate(self.arms):
            if arm[0]:
                best.arms[k], left = eliminate_arm(q_rows, dim, arm)
                best.arm_how[k] = "elimination"
                leftover += left
        if self.q_bound() == best.q:
            return
        best.q = sum(best.arms) + rank(leftover, dim, POLYNOMIALS, zctx)
        best.q_how = "elimination"


def _error_bits(q_rows, checks, count: int) -> int | None:
    """``floor(log2(1 / error))`` of the ranks known by sampling only, exactly (None:
    no such rank)."""
    error = Fraction(0)
    size = 2 * 2 ** SAMPLE_BITS + 1
    for rows, cols, known in checks:
        if known is None:
            top = min(len(rows), len(cols))
            degree = max(_minor_degree(q_rows, rows, cols, top), 1)
            error += Fraction(degree, size) ** count
    return None if error == 0 else max(0, (error.denominator // error.numerator
                                           ).bit_length() - 1)


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
    m, dim, r = len(q_rows), model.object_dim, len(model.joints)
    arms = _arm_blocks(model, row_contacts, dim)
    nvars = zctx.nvars()
    count = points if nvars else 1
    best = _sample(q_rows, dim + r, dim, arms, nvars, count, seed)
    if not nvars:
        rd = sum(best.arms)
        ranks = [RankBound("Q", best.q, "point"), RankBound("Gt", best.gt, "point"),
                 RankBound("Dt", rd, "point")]
        return (numbers_from_ranks(m, r, best.q, best.gt, rd, dim=dim),
                NumbersCertificate.from_ranks(ranks, 0))
    certify = _Certify(q_rows, best, arms, m, dim + r, dim, zctx)
    _contacts_bound(model, best, certify)
    if not certify.settled():
        bound = nullcontext() if certify_seconds is None else time_limit(certify_seconds)
        try:
            with bound:
                certify.run()
        except TimeLimitReached:
            pass
    if best.q_how is None and certify.q_bound() == best.q:
        best.q_how = "size"
    ranks = [RankBound("Q", best.q, best.q_how or "sampled"),
             RankBound("Gt", best.gt, best.gt_how or "sampled")]
    ranks += [RankBound(f"Dt[{arm.name}]", ra, known or "sampled") for arm, ra, known
              in zip(model.arms, best.arms, best.arm_how, strict=True)]
    all_rows, all_cols = range(m), range(dim + r)
    checks = [(all_rows, all_cols, best.q_how), (all_rows, range(dim), best.gt_how)]
    checks += [(rows, range(c0, c1), known) for (rows, c0, c1), known
               in zip(arms, best.arm_how, strict=True)]
    bits = _error_bits(q_rows, checks, count)
    numbers = numbers_from_ranks(m, r, best.q, best.gt, sum(best.arms), dim=dim)
    return numbers, NumbersCertificate.from_ranks(ranks, count, bits)


def chain_numbers(model: Model, config: Configuration, *, points: int = POINTS,
                  seed: int | None = None) -> tuple[Numbers, NumbersCertificate] | None:
    """The numbers over the fraction field of the symbolic joints and parameters of
    ``config`` when the sizes certify every rank, found without building ``Q``
    symbolically; ``None`` otherwise (:func:`generic_numbers` then ranks the symbolic
    ``Q``).

    ``Q`` is evaluated at ``points`` random points modulo the prime
    :data:`CHAIN_PRIME` from the product of exponentials
    (:mod:`coopkin_sym.analysis.sweep.chains`: cost linear in the joints, nothing
    expanded). A rank modulo p at a point is at most the rank over the field (a minor
    that is nonzero there is a nonzero rational function), so these ranks are lower
    bounds, certain whatever the points drawn; where they reach the bounds the sizes
    give (as in :func:`generic_numbers`), every rank is certified (``"size"``).

    Example
    -------
    >>> from coopkin_sym.model import load_model
    >>> model = load_model("panda-two-arm-box")
    >>> numbers, cert = chain_numbers(model, Configuration.parse(model, None, "all"),
    ...                               seed=1)
    >>> numbers.as_dict()["Nm"], cert.exact, {r.how for r in cert.ranks}
    (8, True, {'size'})
    """
    from coopkin_sym.analysis.sweep import chains

    base = model.in_base_frame()
    swept = tuple(j.name for j in base.joints if j.name in config.free)
    data = chains.chain_data(base, config, swept)
    chain = chains.ChainQ(data)
    m, dim, r = data["m"], base.object_dim, len(base.joints)
    arms = _arm_blocks(base, chains.row_contacts(base), dim)
    rng = random.Random(seed) if seed is not None else random.SystemRandom()
    best = _Sampled(-1, -1, [-1] * len(arms))
    for _ in range(points):
        check("the ranks at random points")
        field = chains.ModularField(CHAIN_PRIME, [rng.randrange(2, CHAIN_PRIME)
                                                  for _ in data["params"]])
        try:
            rows = chain.rows(field, [(rng.randrange(CHAIN_PRIME), 1) for _ in swept])
        except chains.Unlucky:      # a denominator vanishes modulo the prime there
            continue
        ranks = rank_triple(rows, dim + r, dim, PrimeField(CHAIN_PRIME), arms)
        best.q, best.gt = max(best.q, ranks.q), max(best.gt, ranks.gt)
        best.arms = [max(b, ra) for b, ra in zip(best.arms, ranks.arms, strict=True)]
    certify = _Certify(None, best, arms, m, dim + r, dim, None)
    if None not in best.arm_how:
        _contacts_bound(base, best, certify)
    if not certify.settled():
        return None
    ranks = [RankBound("Q", best.q, "size"), RankBound("Gt", best.gt, best.gt_how)]
    ranks += [RankBound(f"Dt[{arm.name}]", ra, "size")
              for arm, ra in zip(base.arms, best.arms, strict=True)]
    numbers = numbers_from_ranks(m, r, best.q, best.gt, sum(best.arms), dim=dim)
    return numbers, NumbersCertificate.from_ranks(ranks, points)


def grasp_rank_bound(model: Model) -> int:
    """The rank of ``H G^T`` with every contact point and normal an independent
    indeterminate: an upper bound of its generic rank (putting the points and normals
    of the kinematics in their place is a ring homomorphism, which keeps or lowers a
    rank). Two hard contacts, for one, give 5: the object can always turn about the
    line through them.

    Example
    -------
    >>> from coopkin_sym.model import load_model
    >>> grasp_rank_bound(load_model("paper-case1-hard"))
    5
    """
    import flint

    from coopkin_sym.analysis import kinematics
    from coopkin_sym.model.contacts import contact_kind

    names = tuple(f"x{i}_{a}" for i in range(len(model.contacts)) for a in range(6))
    ctx = flint.fmpz_mpoly_ctx.get(names, "degrevlex")
    gens, zero, one = ctx.gens(), ctx.constant(0), ctx.constant(1)
    lin_rows, ang_rows = [], []
    for i, c in enumerate(model.contacts):
        (x, y, z), n = gens[6 * i:6 * i + 3], gens[6 * i + 3:6 * i + 6]
        lin = [[one, zero, zero, zero, z, -y], [zero, one, zero, -z, zero, x],
               [zero, zero, one, y, -x, zero]]
        ang = [[zero] * 3 + [one if a == b else zero for b in range(3)] for a in range(3)]
        if model.planar:
            lin = [[row[k] for k in kinematics.PLANAR_COLUMNS] for row in lin[:2]]
            ang = [[row[k] for k in kinematics.PLANAR_COLUMNS] for row in ang[2:]]

        def along(rows, n=n):
            return [sum((a * b for a, b in zip(n[:len(rows)], col, strict=True)), zero)
                    for col in zip(*rows, strict=True)]
        comps = contact_kind(c.model).components(model.planar)  # type: ignore[union-attr]
        axes = "z" if model.planar else "xyz"
        picked = kinematics.pick_rows(comps, dict(zip("xyz"[:len(lin)], lin, strict=True)),
                                      dict(zip(axes, ang, strict=True)), along)
        lin_rows += picked[0]
        ang_rows += picked[1]
    return rank(lin_rows + ang_rows, model.object_dim, POLYNOMIALS, ctx)


def _contacts_bound(model: Model, best: _Sampled, certify: _Certify) -> None:
    """Certify ``rank H G^T`` by :func:`grasp_rank_bound` where the sizes leave it open
    and the points reach it (``"contacts"``)."""
    if best.gt_how is None and best.gt >= 0 and best.gt == grasp_rank_bound(model):
        best.gt_how = "contacts"
