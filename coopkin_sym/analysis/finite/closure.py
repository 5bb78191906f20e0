"""Welded loops: an exact proof that the first-order motions are finite where the loop
closure is overconstrained.

When every contact is ``complete`` (each arm's link welded to the object), the object
moves as each holding link does, and the closed system is the set of joint values at
which all those links make the same rigid motion. Near the configuration, with joint
``k`` turned by ``dq_k`` about its current axis (direction ``d_k``, a point ``o_k``),
the motion of an arm's link is the product of the joints' dual quaternions
``1 + v_k (d_k + e (o_k x d_k))`` (``v_k = tan(dq_k/2) / |d_k|``; a prismatic joint
moved by ``s_k`` along ``d_k``: ``1 + e s_k d_k / 2``), each of degree one in its
variable. Two links make the same motion exactly when their dual quaternions are
proportional, so the closed system is, near the configuration (where the scalar parts
do not vanish), the zero set of the polynomials ``E = D1[0] Di[j] - Di[0] D1[j]``.

The proof: ``r`` of them with independent linear parts at the configuration (``r`` the
rank of the Jacobian of ``E`` there) cut out a smooth manifold ``M`` of dimension
``N - r`` near it (the implicit function theorem); each other ``f`` vanishes on ``M``
near the configuration when the saturation ``I : f^oo`` of the ideal ``I`` they
generate holds a polynomial ``h`` with ``h(0) != 0`` (then ``h f^k`` lies in ``I``, so
``f^k = h f^k / h`` vanishes on ``M`` where ``h`` does not). Then the closed system *is*
``M`` near the configuration: smooth, of dimension ``N - r``. The saturations are exact
Gröbner bases (:func:`~coopkin_sym.exact.saturation.saturate`) with a time bound; a
saturation not computed in time, or without such an ``h``, proves nothing, and the
question stays open. With one first-order motion whose joint components are equal up
to sign in pairs (a symmetric linkage), the same proof is tried first on the subspace
where the joints of each pair turn equally, in fewer variables: a smooth curve of
closed configurations there lies in ``M`` (of dimension 1), so it is ``M`` near the
configuration (:func:`welded_loop_dimension`).

This is what decides Bennett's and Bricard's linkages, whose closure conditions are
dependent at every configuration of their motion (overconstrained: the rank of ``Q``
there is below its rank for generic joint values), so that no expansion to a finite
order can tell their motion from a first-order one that stops.

Example
-------
>>> from coopkin_sym.model import load_model
>>> from coopkin_sym.model.configuration import Configuration
>>> from coopkin_sym.analysis.finite.constraints import ConstraintMap
>>> model = load_model("bennett-linkage")
>>> cmap = ConstraintMap(model, Configuration.parse(model, None))
>>> welded_loop_dimension(cmap, 1)
1
"""

from __future__ import annotations

import time

import flint

from coopkin_sym.analysis.finite.constraints import ConstraintMap
from coopkin_sym.analysis.sweep.chains import RationalField
from coopkin_sym.exact.saturation import saturate

#: The time bound of the saturations of one proof, in seconds.
TIMEOUT = 4.0


def _qmul(a, b):
    a0, a1, a2, a3 = a
    b0, b1, b2, b3 = b
    return [a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3, a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
            a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1, a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0]


def _dqmul(a, b):
    """The product of dual quaternions ``(p, q)`` = ``p + e q`` (8 components)."""
    p = _qmul(a[:4], b[:4])
    q1, q2 = _qmul(a[:4], b[4:]), _qmul(a[4:], b[:4])
    return p + [x + y for x, y in zip(q1, q2, strict=True)]


def closure_polynomials(cmap: ConstraintMap) -> tuple[list, tuple[str, ...]] | None:
    """The polynomials ``E`` of :mod:`this module <coopkin_sym.analysis.finite.closure>`
    (``fmpq_mpoly`` in ``v_<joint>``, one per moving joint, 0 at the configuration), or
    None unless every contact is ``complete`` and there are at least two.

    Example
    -------
    >>> from coopkin_sym.model import load_model
    >>> from coopkin_sym.model.configuration import Configuration
    >>> model = load_model("bennett-linkage")
    >>> polys, names = closure_polynomials(ConstraintMap(model, Configuration.parse(model, None)))
    >>> names, len(polys), max(p.total_degree() for p in polys)
    (('v_q1', 'v_q2', 'v_q4', 'v_q3'), 7, 4)
    """
    if len(cmap.positions) < 2 or any(p != "weld" for p in cmap.positions):
        return None
    data = cmap.chain.data
    _, axes, origins = cmap.chain.poses(RationalField(), lambda col, spec, fixed: fixed)
    names = tuple("v_" + cmap.joint_names[k] for k in cmap.moving)
    ctx = flint.fmpq_mpoly_ctx.get(names or ("_",), "degrevlex")
    one, zero = ctx.constant(1), ctx.constant(0)
    gens = dict(zip(cmap.moving, ctx.gens()[: len(names)], strict=True))

    def factor(col: int) -> list:
        d = [ctx.constant(x) for x in axes[col]]
        v = gens[col]
        if data["joints"][col]["kind"] == "prismatic":
            return [one, zero, zero, zero, zero] + [v * x / 2 for x in d]
        o = [ctx.constant(x) for x in origins[col]]
        m = [o[1] * d[2] - o[2] * d[1], o[2] * d[0] - o[0] * d[2], o[0] * d[1] - o[1] * d[0]]
        return [one] + [v * x for x in d] + [zero] + [v * x for x in m]

    motions = []
    for arm, link, _, _, _ in data["contacts"]:
        dq = [one] + [zero] * 7
        if arm is not None:
            offset = data["offsets"][arm]
            for col in range(offset, offset + link):
                if col in gens:
                    dq = _dqmul(dq, factor(col))
        motions.append(dq)
    first = motions[0]
    polys = [first[0] * other[j] - other[0] * first[j]
             for other in motions[1:] for j in range(1, 8)]
    return [p for p in polys if not p.is_zero()], names


def _linear(p, n: int) -> list:
    terms = p.to_dict()
    return [terms.get(tuple(int(i == k) for i in range(n)), flint.fmpq(0)) for k in range(n)]


def _integer(p) -> dict:
    """``p`` times its denominators, primitive, as an exponent map of integers."""
    terms = p.to_dict()
    den = 1
    for c in terms.values():
        den = den * int(c.q) // flint.fmpz(den).gcd(int(c.q))
    ints = {tuple(int(e) for e in k): int(c * den) for k, c in terms.items()}
    g = 0
    for c in ints.values():
        g = int(flint.fmpz(g).gcd(c))
    return {k: c // g for k, c in ints.items()}


def _germ_dimension(polys: list, n: int, timeout: float) -> int | None:
    """``n - r`` when the polynomials (``fmpq_mpoly`` in ``n`` variables, 0 at the
    origin) that are dependent at the origin are proved to vanish near it on the set of
    ``r`` independent ones (a smooth manifold of dimension ``n - r``), else None."""
    polys = [p for p in polys if not p.is_zero()]
    if not polys:
        return n
    jac = [_linear(p, n) for p in polys]
    mat = flint.fmpq_mat(len(jac), n, [x for row in jac for x in row])
    rank = mat.rank()
    # r rows with independent linear parts: the pivots of the transposed echelon form
    rref, _ = mat.transpose().rref()
    rows = [next(j for j in range(len(jac)) if rref[i, j] != 0) for i in range(rank)]
    ideal = [_integer(polys[i]) for i in rows]
    origin = (0,) * n
    end = time.monotonic() + timeout
    for k, p in enumerate(polys):
        if k in rows:
            continue
        f = _integer(p)
        left = end - time.monotonic()
        sat = saturate(ideal, f, n, timeout=left) if left > 0 else None
        if sat is None or not any(g.get(origin, 0) != 0 for g in sat):
            return None
        ideal.append(f)       # it vanishes near the configuration: the same germ
    return n - rank


def _paired(polys: list, names: tuple[str, ...], tangent: list) -> list | None:
    """The polynomials on the subspace where the joints whose tangent components are
    equal up to sign turn equally in pairs (``v_j = +-v_i``), in the other variables;
    None unless some pair is found and every nonzero component has at most one
    partner."""
    groups: dict = {}
    for k, x in enumerate(tangent):
        if x != 0:
            groups.setdefault(abs(x), []).append(k)
    pairs = [g for g in groups.values() if len(g) == 2]
    if not pairs or any(len(g) > 2 for g in groups.values()):
        return None
    follows = {j: (i, tangent[j] / tangent[i]) for i, j in pairs}
    kept = [k for k in range(len(names)) if k not in follows]
    ctx = flint.fmpq_mpoly_ctx.get(tuple(names[k] for k in kept), "degrevlex")
    gens = dict(zip(kept, ctx.gens(), strict=True))
    images = [gens[k] if k in gens else gens[follows[k][0]] * follows[k][1]
              for k in range(len(names))]
    return [p.compose(*images, ctx=ctx) for p in polys]


def welded_loop_dimension(cmap: ConstraintMap, first_order: int,
                          timeout: float = TIMEOUT) -> int | None:
    """``first_order`` when the closed system is proved smooth of that dimension near
    the configuration (:mod:`this module <coopkin_sym.analysis.finite.closure>`), else
    None (nothing proved).

    Two proofs are tried. In the whole joint space: the closure polynomials dependent
    at the configuration vanish near it on the manifold ``M`` cut out by independent
    ones, so the closed system is ``M``. And, with one first-order motion whose joint
    components are equal up to sign in pairs (as in a symmetric linkage), on the
    subspace ``L`` where the joints of each pair turn equally: the same proof in fewer
    variables gives a smooth curve of closed configurations in ``L`` through the
    configuration; the closed system contains it, lies in the manifold of the
    independent closure polynomials of the whole space (of dimension ``first_order``),
    and so is that manifold near the configuration.
    """
    found = closure_polynomials(cmap)
    if found is None:
        return None
    polys, names = found
    n = len(names)
    start = time.monotonic()
    if first_order == 1 and _on_pairs(polys, names, timeout / 4):
        return 1
    whole = _germ_dimension(polys, n, timeout - (time.monotonic() - start))
    return whole if whole == first_order else None


def _on_pairs(polys: list, names: tuple[str, ...], timeout: float) -> bool:
    """Whether the proof on the subspace of paired joints gives a smooth curve of closed
    configurations there (with one first-order motion)."""
    n = len(names)
    jac = [_linear(p, n) for p in polys]
    if not jac or n - flint.fmpq_mat(len(jac), n, [x for row in jac for x in row]).rank() != 1:
        return False
    import sympy as sp

    kernel = sp.Matrix([[sp.Rational(int(x.p), int(x.q)) for x in row] for row in jac]
                       ).nullspace()
    tangent = [flint.fmpq(int(sp.Rational(x).p), int(sp.Rational(x).q)) for x in kernel[0]]
    restricted = _paired(polys, names, tangent)
    if not restricted:
        return False
    return _germ_dimension(restricted, restricted[0].context().nvars(), timeout) == 1
