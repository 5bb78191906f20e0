"""``Q`` compiled for exact evaluation at many points (see :mod:`coopkin_sym.analysis.sweep`).

A point is evaluated from the system's home data by the product of exponentials
(:mod:`coopkin_sym.analysis.sweep.chains`): nothing is expanded, and compiling costs
no more than reading the model. The generic ranks come from ranks modulo a prime at
random points when these reach the bounds the sizes give; otherwise from the rows of
``Q`` with the swept joints symbolic (over ``Q(t, L)``), which a sweep's batch
evaluation (rows cleared to integer polynomials and homogenized) also uses.
"""

from __future__ import annotations

import hashlib
import math
import random
from collections import OrderedDict
from collections.abc import Mapping, Sequence
from functools import cached_property
from typing import Any

import flint
import numpy as np
import sympy as sp

from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.generic import generic_numbers, grasp_rank_bound
from coopkin_sym.analysis.numbers import (
    Numbers,
    numbers_from_ranks,
    ranks_from_numbers,
    ranks_of_q,
)
from coopkin_sym.analysis.sweep import chains
from coopkin_sym.analysis.sweep.grid import _split_point
from coopkin_sym.analysis.sweep.values import Value
from coopkin_sym.errors import ArgumentError, SweepError, TimeLimitReached
from coopkin_sym.exact import modular
from coopkin_sym.exact.angles import tangent_name
from coopkin_sym.exact.deadline import time_limit
from coopkin_sym.exact.matrix import (
    RATIONALS,
    PolyMatrix,
    PrimeField,
    rank_triple,
)
from coopkin_sym.exact.ring import ClearedRows
from coopkin_sym.model.configuration import (
    Configuration,
)
from coopkin_sym.model.model import Model, model_of

# --- compilation ----------------------------------------------------------------------
#: The prime of the point analysis' modular ranks (``2**61 - 1``).
POINT_PRIME = 2**61 - 1


class _Exact:
    """Exact ranks of ``Q`` at points, in one process, from :mod:`.chains` (the product
    of exponentials evaluated at each point; nothing is expanded).

    A point is first evaluated modulo :data:`POINT_PRIME` (symbolic parameters at fixed
    random residues) when the generic ranks are known; otherwise, or where those ranks
    are not reached, exactly: over the integers (flint's ``fmpz_mat``, each row scaled
    to integers) with every parameter set, over ``Q(L)`` (:mod:`coopkin_sym.exact.
    elimination`) with parameters left symbolic.
    """

    def __init__(self, plan: dict):
        self.m, self.n, self.dim = plan["m"], plan["n"], plan["dim"]
        self.kinds = plan["kinds"]
        self.arm_blocks = plan["arm_blocks"]
        self.chain = chains.ChainQ(plan["chain"])
        names = plan["chain"]["params"]
        self.modular = chains.ModularField(POINT_PRIME, plan["point_params"])
        self._other: chains.ModularField | None = None
        self.field = chains.PolynomialField(names) if names else chains.RationalField()
        self.ctx = (flint.fmpz_mpoly_ctx.get(tuple(names), "degrevlex") if names
                    else None)

    def ranks(self, pairs: Sequence[tuple[int, int]],
              generic: tuple[int, int, int] | None = None) -> tuple[int, int, int]:
        """Exact ranks of ``Q``, of its object columns and of its last ``r`` columns.

        With the exact ``generic`` ranks known, a point whose ranks modulo a prime equal
        them has exactly those ranks (a rank modulo p is at most the rank over Q, which
        is at most the generic rank); the others are ranked exactly.
        """
        return self.certified_ranks(pairs, generic)[0]

    def certified_ranks(self, pairs: Sequence[tuple[int, int]],
                        generic: tuple[int, int, int] | None = None,
                        prime: int = 0) -> tuple[tuple[int, int, int], bool]:
        """:meth:`ranks` and whether the point was ranked exactly (not certified by
        its ranks modulo ``prime``, by default :data:`POINT_PRIME`)."""
        if self.m == 0:
            return (0, 0, 0), False
        if generic is not None:
            field = self.modular if prime in (0, POINT_PRIME) else self._field_modulo(prime)
            try:
                rows = self.chain.rows(field, pairs)
            except chains.Unlucky:
                rows = None
            if rows is not None and self._generic_modulo(rows, generic, field.p):
                return generic, False
        return self._exact_ranks(pairs), True

    def _exact_ranks(self, pairs: Sequence[tuple[int, int]]) -> tuple[int, int, int]:
        rows = self.chain.rows(self.field, pairs)
        if self.ctx is not None:
            cleared = [_cleared_polynomials(row, self.ctx) for row in rows]
            return ranks_of_q(PolyMatrix(cleared, self.n, context=self.ctx), dim=self.dim)
        # H D is block diagonal: one block per arm
        return rank_triple(chains.integer_rows(rows), self.n, self.dim, RATIONALS,
                           self.arm_blocks).triple

    def _field_modulo(self, prime: int) -> chains.ModularField:
        if self._other is None or self._other.p != prime:
            self._other = chains.ModularField(prime, [v % prime for v in
                                                      self.modular.params])
        return self._other

    def _generic_modulo(self, rows: list[list[int]], generic: tuple[int, int, int],
                        p: int = POINT_PRIME) -> bool:
        """Whether the ranks of ``Q`` modulo ``p`` (``rows``) are the generic ones."""
        return rank_triple(rows, self.n, self.dim, PrimeField(p),
                           self.arm_blocks).triple == tuple(generic)


def _cleared_polynomials(row: Sequence, ctx) -> list:
    """A row of polynomials over Q as integer polynomials (times one positive integer)."""
    dicts = [x.to_dict() for x in row]
    dens = [int(c.q) for d in dicts for c in d.values()]
    scale = math.lcm(*dens) if dens else 1
    return [ctx.from_dict({e: int(c.p) * (scale // int(c.q)) for e, c in d.items()})
            for d in dicts]


_EXACT_CACHE: OrderedDict[str, _Exact] = OrderedDict()


def _exact_for(plan: dict) -> _Exact:
    ev = _EXACT_CACHE.get(plan["key"])
    if ev is None:
        ev = _EXACT_CACHE[plan["key"]] = _Exact(plan)
        while len(_EXACT_CACHE) > 8:
            _EXACT_CACHE.popitem(last=False)
    return ev


def _joint_vector(kinds: Sequence[str], pairs: Sequence[tuple[int, int]]) -> list[int]:
    """The variables of the compiled polynomials at one point: for a revolute joint with
    ``tan(q/2) = a/b``, ``(a^2 + b^2, b^2 - a^2, 2 a b)`` (proportional to
    ``(1, cos q, sin q)``); for a prismatic one ``(a, b)``."""
    out: list[int] = []
    for kind, (a, b) in zip(kinds, pairs, strict=True):
        if kind == "revolute":
            a2, b2 = a * a, b * b
            out += [a2 + b2, b2 - a2, 2 * a * b]
        else:
            out += [a, b]
    return out


def _compile_rows(frac_rows, rows, ring, joints, kinds, var_of, param_vars, names, n):
    """The rows of ``Q`` as integer polynomials in the variables of :func:`_joint_vector`.

    Row ``i`` of ``Q`` times its denominator is the integer polynomial ``rows[i]`` in
    ``t = tan(q/2)`` (and displacements ``d``); homogenized with ``t = a/b`` to the
    degree ``2 e`` of its denominator ``(1 + t^2)^e`` (and ``d = a/b`` to its degree in
    ``d``), it is ``Q``'s row times a nonzero number at every point, ``q = pi`` included.
    Every revolute part is a form of even degree in ``(a, b)``, rewritten in
    ``w = a^2 + b^2``, ``c = b^2 - a^2``, ``s = 2 a b`` (much sparser: ``Q`` is built from
    cosines and sines); the row is then scaled to primitive integer coefficients.
    Returns ``[(flat entry index, [(exponents, integer coefficient), ...]), ...]``.
    """
    qctx = flint.fmpq_mpoly_ctx.get(tuple(names), "degrevlex")
    gens = qctx.gens()
    half = flint.fmpq(1, 2)
    starts, pos = [], 0
    for kind in kinds:
        starts.append(pos)
        pos += 3 if kind == "revolute" else 2
    cache: dict[tuple[int, int, int], flint.fmpq_mpoly] = {}

    def factor(jj: int, i: int, k: int) -> flint.fmpq_mpoly:
        key = (jj, i, k)
        if key not in cache:
            o = starts[jj]
            if kinds[jj] == "revolute":          # a^i b^k, i + k even
                w, c, s = gens[o], gens[o + 1], gens[o + 2]
                f = ((w - c) * half) ** (i // 2) * ((w + c) * half) ** (k // 2)
                cache[key] = f * (s * half) if i % 2 else f
            else:
                cache[key] = gens[o] ** i * gens[o + 1] ** k
        return cache[key]

    nparams = len(param_vars)
    njv = len(names) - nparams
    terms = []
    for i, (frac_row, row) in enumerate(zip(frac_rows, rows, strict=True)):
        top = [max(es) for es in zip(*(f.powers for f in frac_row), strict=True)]
        degree = []
        for j, kind in zip(joints, kinds, strict=True):
            v = var_of[j]
            if kind == "revolute":
                degree.append(2 * top[ring.den_names.index(ring.names[v])])
            else:
                degree.append(max((p.degrees()[v] for p in row if not p.is_zero()),
                                  default=0))
        converted = []
        for k, poly in enumerate(row):
            if poly.is_zero():
                continue
            acc = qctx.constant(0)
            for e, c in poly.to_dict().items():
                term = qctx.from_dict({(0,) * njv + tuple(e[v] for v in param_vars): int(c)})
                for jj, (j, d) in enumerate(zip(joints, degree, strict=True)):
                    ej = e[var_of[j]]
                    if ej > d:  # pragma: no cover - entries of Q are bounded at t = oo
                        raise AssertionError("row degree above its denominator")
                    term = term * factor(jj, ej, d - ej)
                acc += term
            converted.append((k, acc.to_dict()))
        dens = [int(c.q) for _, d in converted for c in d.values()]
        scale = math.lcm(*dens) if dens else 1
        ints = [(k, {e: int(c.p) * (scale // int(c.q)) for e, c in d.items()})
                for k, d in converted]
        g = math.gcd(*(c for _, d in ints for c in d.values())) or 1
        for k, d in ints:
            if d:
                terms.append((i * n + k, sorted((tuple(e), c // g) for e, c in d.items())))
    return terms


def _arm_blocks(model: Model, row_contacts: Sequence[int], dim: int) -> list:
    """The blocks of ``H D``, one per arm with rows and joints, as ``(rows, first
    column, end column)`` in ``Q``'s columns (rows of contacts on no arm have no joint
    entries)."""
    owners = [model.contacts[c].arm for c in row_contacts]
    blocks = []
    for a, arm in enumerate(model.arms):
        rows = [i for i, o in enumerate(owners) if o == a]
        c0 = dim + model.joint_offset(a)
        if rows and arm.joints:
            blocks.append((rows, c0, c0 + len(arm.joints)))
    return blocks


class Compiled:
    """``Q`` of a system compiled for exact evaluation with some joints swept.

    Parameters
    ----------
    system
        A :class:`~coopkin_sym.system.System` (or its model).
    joints
        The swept joints (symbolic at compile time, given values point by point).
    at
        Values of the other joints and of parameters (``"q3=pi/2,L=1"`` or a mapping);
        a value given here for a swept joint is its default at points that leave it
        out. Unset joints are at home, unset parameters symbolic (the numbers are then
        those over ``Q(L)``, as :meth:`System.analyze` gives them).
    prime
        The prime of the modular pass (below ``2**31``).

    Attributes
    ----------
    generic : Numbers
        The numbers with the swept joints symbolic (over ``Q(t, L)``).

    Example
    -------
    >>> from coopkin_sym import load
    >>> c = compile_system(load("paper-case2-hard"), ["q1", "q2"], "L=1")
    >>> c.generic.as_dict()["Nm"]
    8
    >>> c.numbers("q1=2*atan(1/3),q2=pi/2").Nr         # a singular configuration
    3
    """

    def __init__(self, system: Model | Any, joints: Sequence[str],
                 at: str | Mapping | None = None,
                 prime: int = modular.PRIME):
        model = model_of(system).in_base_frame()  # numbers only
        if not (2 < prime < 2**31 and sp.isprime(prime)):
            raise ArgumentError(f"prime: expected an odd prime below 2**31, got {prime}")
        self.model = model
        self.prime = prime
        kinds = {j.name: j.type for j in model.joints}
        joints = tuple(dict.fromkeys(joints))
        for j in joints:
            if j not in kinds:
                params = {p.name for p in model.parameters}
                what = "a parameter, not a joint" if j in params else "not a joint"
                raise SweepError(f"{j} is {what} (joints: {', '.join(model.joint_names)})")
        self.joints = joints
        self.kinds = tuple(kinds[j] for j in joints)
        full = Configuration.parse(model, at)
        swept = set(joints)
        self.base = Configuration(
            {k: v for k, v in full.revolute.items() if k not in swept},
            {k: v for k, v in full.prismatic.items() if k not in swept},
            dict(full.parameters), frozenset(swept))
        self.at_text = self.base.at_text()
        self.defaults = tuple(self._default(full, j) for j in joints)
        self.r = len(model.joints)
        self.dim = dim = model.object_dim
        self.n = dim + self.r
        chain = chains.chain_data(model, self.base, joints)
        self.m = chain["m"]
        row_contacts = chains.row_contacts(model)
        key = hashlib.sha1(repr((joints, self.kinds, chain)).encode()).hexdigest()
        self._plan = {
            "key": key, "prime": prime, "m": self.m, "n": self.n, "dim": dim,
            "kinds": list(self.kinds), "chain": chain,
            "point_params": [random.Random(f"coopkin:{name}").randrange(2, POINT_PRIME)
                             for name in chain["params"]],
            "arm_blocks": _arm_blocks(model, row_contacts, dim),
        }

    @cached_property
    def _symbolic(self) -> tuple:
        """``Q`` with the swept joints symbolic, rows cleared to integer polynomials
        (exponential in the joints of a chain: built only for what the point
        evaluation cannot give, the sweep's batch polynomials and generic ranks that
        the sizes do not certify)."""
        kin = kinematics.build(self.model, self.base)
        return kin, ClearedRows(kin.ring, kin.Q)      # each row cleared when used

    def _expansion(self) -> dict:
        """The homogenized integer polynomials of ``Q`` evaluated modulo a prime at a
        whole batch of points by :func:`~coopkin_sym.analysis.sweep.run.sweep`."""
        kin, cleared = self._symbolic
        rows = list(cleared)
        ring, joints, n, dim, prime = kin.ring, self.joints, self.n, self.dim, self.prime
        var_of = {}
        for j, kind in zip(joints, self.kinds, strict=True):
            var_of[j] = ring.names.index(tangent_name(j) if kind == "revolute" else j)
        param_vars = [i for i, nm in enumerate(ring.names) if nm not in
                      {ring.names[v] for v in var_of.values()}]
        names = []
        for j, kind in zip(joints, self.kinds, strict=True):
            names += ([f"{j}.w", f"{j}.c", f"{j}.s"] if kind == "revolute"
                      else [f"{j}.num", f"{j}.den"])
        njv = len(names)
        names += [ring.names[i] for i in param_vars]
        terms = _compile_rows(kin.Q, rows, ring, joints, self.kinds, var_of, param_vars,
                              names, n)
        flat_terms = [(k, e, c) for k, ts in terms for e, c in ts]
        nvars = len(names)
        exps = np.array([e for _, e, _ in flat_terms], dtype=np.int64).reshape(-1, nvars)
        used = sorted({k % n for k, _ in terms})
        return {
            "names": names, "njv": njv, "nvars": nvars, "exps": exps,
            "coefs": modular.residues([c for _, _, c in flat_terms], prime),
            "entries": np.array([k for k, _, _ in flat_terms], dtype=np.int64),
            "params": [random.Random(f"coopkin:{names[i]}").randrange(2, prime)
                       for i in range(njv, nvars)],
            "object_cols": [c for c in used if c < dim],
            "joint_cols": [c for c in used if c >= dim],
        }

    def _size_bounds(self, g_bound: int | None = None) -> tuple[int, int, list[int]]:
        """Upper bounds of the generic ranks of ``Q`` and ``H G^T`` and of each arm
        block of ``H D`` from the sizes (a block's columns: its arm's joints that move
        one of its contacts and are not held still), given a bound ``g_bound`` of
        ``rank H G^T`` if one is known."""
        model, dim, m = self.model, self.dim, self.m
        owners = [model.contacts[c].arm for c in chains.row_contacts(model)]
        arm_bounds = []
        for a, arm in enumerate(model.arms):       # the blocks of _arm_blocks, in order
            rows = owners.count(a)
            if rows and arm.joints:
                depth = max(c.link for c in model.contacts if c.arm == a)
                moving = sum(j.name not in model.locked for j in arm.joints[:depth])
                arm_bounds.append(min(rows, moving))
        d_bound = sum(arm_bounds)
        g_bound = min(m, dim) if g_bound is None else min(m, dim, g_bound)
        return min(m, self.n, d_bound + g_bound, d_bound + dim), g_bound, arm_bounds

    def _grasp_bound(self) -> int:
        """The rank of ``H G^T`` with every contact point and normal an independent
        indeterminate (see :func:`~coopkin_sym.analysis.generic.grasp_rank_bound`)."""
        return grasp_rank_bound(self.model)

    def _sampled_generic(self) -> tuple[int, int, int] | None:
        """The generic ranks when ranks modulo :data:`POINT_PRIME` at random points
        (lower bounds: a rank modulo p is at most the rank over Q at the point, at most
        the generic rank) reach the bounds of :meth:`_size_bounds` (with that of
        :meth:`_grasp_bound` where the sizes leave ``rank H G^T`` open); else ``None``."""
        if self.m == 0:
            return 0, 0, 0
        q_bound, g_bound, arm_bounds = self._size_bounds()
        exact = _exact_for(self._plan)
        rng = random.Random(0)
        best = [0, 0, [0] * len(arm_bounds)]
        for _ in range(SAMPLES):
            field = chains.ModularField(POINT_PRIME, [rng.randrange(2, POINT_PRIME)
                                                      for _ in self._plan["point_params"]])
            pairs = [(rng.randrange(POINT_PRIME), 1) for _ in self.joints]
            try:
                rows = exact.chain.rows(field, pairs)
            except chains.Unlucky:    # pragma: no cover - a denominator divisible by p
                continue
            ranks = rank_triple(rows, self.n, self.dim, PrimeField(POINT_PRIME),
                                self._plan["arm_blocks"])
            best[0], best[1] = max(best[0], ranks.q), max(best[1], ranks.gt)
            best[2] = [max(b, ra) for b, ra in zip(best[2], ranks.arms, strict=True)]
            if best[1] < g_bound and best[2] == arm_bounds:
                q_bound, g_bound, _ = self._size_bounds(self._grasp_bound())
            if best[0] == q_bound and best[1] == g_bound and best[2] == arm_bounds:
                return q_bound, g_bound, sum(arm_bounds)
        return None

    def _generic_within(self, seconds: float | None) -> tuple[int, int, int] | None:
        sampled = self._sampled_generic()
        if sampled is not None:
            return sampled
        try:
            with time_limit(seconds, "the generic ranks of a compiled system"):
                kin, rows = self._symbolic
                numbers, cert = generic_numbers(rows, self.model, kin.row_contacts,
                                                kin.ring.zctx, seed=0,
                                                certify_seconds=seconds)
        except TimeLimitReached:
            if seconds is None:        # an enclosing bound: not this one's to absorb
                raise
            return None
        return ranks_from_numbers(numbers, self.r, dim=self.dim) if cert.exact else None

    @cached_property
    def quick_generic_ranks(self) -> tuple[int, int, int] | None:
        """The generic ranks when they are certified within a few seconds, else
        ``None`` (the point analysis then ranks every point exactly)."""
        if "generic_ranks" in self.__dict__:
            return self.generic_ranks
        return self._generic_within(GENERIC_SECONDS)

    @cached_property
    def generic_ranks(self) -> tuple[int, int, int]:
        """The exact ranks of ``Q``, ``H G^T`` and ``H D`` with the swept joints
        symbolic: ranks modulo a prime at random points where they reach the size
        bounds, else found arm by arm (see :mod:`coopkin_sym.analysis.generic`: exact
        ranks at random points, then elimination over ``Q(t, L)`` of the blocks the
        size bounds leave open)."""
        quick = self.__dict__.get("quick_generic_ranks")
        return quick if quick is not None else self._generic_within(None)

    @cached_property
    def generic(self) -> Numbers:
        """The numbers with the swept joints symbolic (over ``Q(t, L)``)."""
        return self._numbers(*self.generic_ranks)

    @property
    def plan(self) -> dict:
        """Everything a worker process needs, as plain data (the generic ranks
        included)."""
        if "generic" not in self._plan:
            self._plan["generic"] = self.generic_ranks
        if "pointwise" not in self._plan:
            self._plan["pointwise"] = self.chain_joints > EXPANDED_JOINTS
            if not self._plan["pointwise"]:
                self._plan.update(self._expansion())
        return self._plan

    @property
    def chain_joints(self) -> int:
        """The most swept joints on the path from a base to a contact (the expansion
        of ``Q`` grows exponentially with it).

        Example
        -------
        >>> from coopkin_sym import load
        >>> compile_system(load("paper-case2-hard"), ["q1", "q2", "q5"]).chain_joints
        2
        """
        swept, model, most = set(self.joints), self.model, 0
        for c in model.contacts:
            if c.arm is not None:
                path = model.arms[c.arm].joints[:c.link]
                most = max(most, sum(j.name in swept for j in path))
        return most

    def _default(self, full: Configuration, joint: str) -> Value:
        if joint in full.revolute:
            return Value.from_angle(full.revolute[joint])
        if joint in full.prismatic:
            return self._rational(joint, full.prismatic[joint], joint)
        return Value.from_tangent(0) if self._kind(joint) == "revolute" else Value("0", 0, 1)

    def _kind(self, joint: str) -> str:
        return self.kinds[self.joints.index(joint)]

    @staticmethod
    def _rational(joint: str, d: sp.Expr, shown) -> Value:
        if not d.is_Rational:
            raise SweepError(f"{joint}={shown}: a swept displacement must be a number "
                             f"(got {d}; set the parameters it uses)")
        return Value(sp.sstr(d), int(d.p), int(d.q))

    def _numbers(self, rq: int, r6: int, rr: int) -> Numbers:
        return numbers_from_ranks(self.m, self.r, rq, r6, rr, dim=self.dim)

    def value(self, joint: str, value) -> Value:
        """The exact :class:`Value` of ``joint`` for ``value`` (an angle in ``--at``
        syntax, an :class:`~coopkin_sym.exact.angles.ExactAngle` or an exact
        ``(cos, sin)`` pair, a displacement, or a :class:`Value`)."""
        if isinstance(value, Value):
            return value
        if joint not in self.joints:
            raise SweepError(f"{joint} is not a swept joint (swept: {', '.join(self.joints)})")
        if self._kind(joint) == "revolute":
            cfg = Configuration.parse(self.model, {joint: value})
            return Value.from_angle(cfg.revolute[joint])
        given = dict(self.base.parameters)
        cfg = Configuration.parse(self.model, {joint: value, **given})
        return self._rational(joint, cfg.prismatic[joint], value)

    def ranks(self, values: Sequence[Value]) -> tuple[int, int, int]:
        """Exact ranks of ``Q``, ``H G^T`` and ``H D`` at the swept values (in the order
        of :attr:`joints`)."""
        return _exact_for(self._plan).ranks([(v.num, v.den) for v in values])

    def numbers_at(self, values: Sequence[Value]) -> Numbers:
        """The exact numbers at the swept values (in the order of :attr:`joints`).

        Example
        -------
        >>> from coopkin_sym import load
        >>> c = compile_system(load("paper-case1-hard"), ["q1", "q2"])
        >>> c.numbers_at([Value.from_tangent(-1), Value.from_tangent(-1)]).Nm
        3
        """
        return self._numbers(*self.ranks(values))

    def numbers(self, point: str | Mapping | None = None) -> Numbers:
        """The exact numbers at one point (``"q1=pi/2,q2=0"`` or a mapping of swept
        joints; swept joints left out take their default)."""
        items = dict(_split_point(point))
        values = []
        for j, default in zip(self.joints, self.defaults, strict=True):
            values.append(self.value(j, items.pop(j)) if j in items else default)
        if items:
            raise SweepError(f"{', '.join(items)}: not a swept joint "
                             f"(swept: {', '.join(self.joints)})")
        return self.numbers_at(values)


_COMPILED: OrderedDict[tuple, tuple[Model, Compiled]] = OrderedDict()


def compile_system(system: Model | Any, joints: Sequence[str],
                   at: str | Mapping | None = None,
                   prime: int = modular.PRIME) -> Compiled:
    """:class:`Compiled` for ``system``, ``joints`` swept, the rest at ``at`` (cached).

    Example
    -------
    >>> from coopkin_sym import load
    >>> compile_system(load("paper-case1-hard"), ["q1"]).generic.as_dict()
    {'Nm': 2, 'Nc': 2, 'Ni': 1, 'Nr': 0, 'Ng': 1, 'Nd': 4, 'Nh': 0}
    """
    model = model_of(system)
    at_key = at if at is None or isinstance(at, str) else tuple(
        sorted((str(k), f"{int(v.p)}/{int(v.q)}" if getattr(v, "is_Rational", False)
                else str(v)) for k, v in at.items()))
    key = (id(model), tuple(joints), at_key, prime)
    hit = _COMPILED.get(key)
    if hit is not None and hit[0] is model:
        _COMPILED.move_to_end(key)
        return hit[1]
    compiled = Compiled(model, joints, at, prime)
    _COMPILED[key] = (model, compiled)
    while len(_COMPILED) > 16:
        _COMPILED.popitem(last=False)
    return compiled


#: A sweep evaluates the expanded polynomials of ``Q`` in batches when at most this many
#: swept joints lie on one chain (their expansion grows about fivefold per joint), and
#: otherwise point by point from the product of exponentials.
EXPANDED_JOINTS = 4
#: Random points whose ranks modulo a prime are compared with the size bounds.
SAMPLES = 2
#: Seconds the point analysis spends, once per compiled system, certifying the generic
#: ranks that let most points be ranked modulo a prime.
GENERIC_SECONDS = 2.0
_JOINTS: OrderedDict[int, tuple[Model, tuple[str, ...], tuple[str, ...]]] = OrderedDict()


def _joints_of(model: Model) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """The joint names and kinds of ``model`` (cached: read at every point)."""
    hit = _JOINTS.get(id(model))
    if hit is None or hit[0] is not model:
        hit = (model, tuple(j.name for j in model.joints),
               tuple(j.type for j in model.joints))
        _JOINTS[id(model)] = hit
        while len(_JOINTS) > 64:
            _JOINTS.popitem(last=False)
    return hit[1], hit[2]


def point_ranks(model: Model, config: Configuration) -> tuple[int, tuple[int, int, int]] | None:
    """``m`` and the exact ranks of ``Q``, ``H G^T`` and ``H D`` at a configuration
    that gives every joint a value, on the compiled path: ``Q`` compiled once (all
    joints swept, the parameters at their values, cached), then evaluated exactly.

    ``None`` when the compiled path does not apply: a joint is left symbolic or a
    displacement depends on a symbolic parameter. (:func:`coopkin_sym.analysis.points.
    point_ranks` calls this from a model's second point on.)

    Example
    -------
    >>> from coopkin_sym.model import load_model
    >>> model = load_model("paper-case1-hard")
    >>> point_ranks(model, Configuration.parse(model, "q1=pi/2,q2=pi/2,L=1"))
    (6, (5, 5, 2))
    """
    if config.free:
        return None
    joints, kinds = _joints_of(model)
    revolute, prismatic = config.revolute, config.prismatic
    pairs: list[tuple[int, int]] = []
    for joint, kind in zip(joints, kinds, strict=True):
        if kind == "revolute":
            value = revolute.get(joint)
            if value is None:                         # home
                pairs.append((0, 1))
                continue
            pairs.append((value.num, value.den))      # tan(q/2); (1, 0) at q = pi
        else:
            d = prismatic.get(joint, 0)
            if isinstance(d, int):
                pairs.append((d, 1))
            elif getattr(d, "is_Rational", False):
                pairs.append((int(d.p), int(d.q)))
            else:
                return None
    at = config.parameters
    at_key = tuple(sorted((str(k), f"{int(v.p)}/{int(v.q)}") for k, v in at.items()))
    key = (id(model), joints, at_key, modular.PRIME)
    hit = _COMPILED.get(key)
    if hit is not None and hit[0] is model:
        compiled = hit[1]
        return compiled.m, _exact_for(compiled._plan).ranks(pairs,
                                                            compiled.quick_generic_ranks)
    compiled = compile_system(model, joints, at)
    return compiled.m, _exact_for(compiled._plan).ranks(pairs, compiled.quick_generic_ranks)
