"""The loop closure as exact polynomials: joints as dual quaternions, the object too.

Near the configuration, joint ``k`` turned by ``dq_k`` about its current axis (unit
direction ``d_k`` through the point ``o_k``) is the dual quaternion
``1 + v_k (d_k + e (o_k x d_k))`` with ``v_k = tan(dq_k/2)``, and a prismatic joint
moved by ``s_k`` along ``d_k`` is ``1 + e s_k d_k / 2``. A link moves by the product of
its arm's joints up to it, ``r + e t`` (polynomial, of degree one in each variable). It
maps a point ``x`` to ``(r x r~ + 2 t r~) / (r r~)`` (``r~`` the conjugate): the
rotation of the quaternion ``r``, then the translation ``2 t r~ / (r r~)``.

The object moves by its displacement ``p`` and Cayley vector ``w`` (the coordinates of
the expansion): ``x -> R(w) x + p`` with ``(1 + w.w) R(w) x = q x q~`` for the
quaternion ``q = 1 + w``, its dual quaternion ``q + e p q / 2``. With denominators
cleared (``1 + w.w`` and ``r r~``, both 1 at the configuration, so units near it) each
contact holds when (``x0`` its point and ``n0`` its normal at the configuration):

* hard: ``(1 + w.w) (r x0 r~ + 2 t r~) - (r r~) (q x0 q~ + (1 + w.w) p) = 0`` (the
  link's point is the object's; 3 rows, 2 in the plane);
* frictionless: ``(q n0 q~) . E = 0`` with ``E`` the hard rows (the link's point on the
  object's face through ``x0`` with normal ``n0``);
* complete: the link's dual quaternion proportional to the object's,
  ``D_link[0] D_obj[j] - D_obj[0] D_link[j] = 0``, for every component ``j`` but the
  dual scalar one: both lie on Study's quadric (``r0 t0 + r.t = 0``), so the dual
  scalar parts agree wherever the others do (the scalar parts being units).

Their zero set near the configuration is the closed system's configuration space, in
the coordinates of the expansion (:attr:`~.constraints.ConstraintMap.names`): each is
an invertible combination of the rows of the constraint map ``F``. The object's
coordinates are then eliminated through one contact where they can be, to keep the
saturations of :mod:`.closure` small (:func:`contact_polynomials`).

Example
-------
>>> from coopkin_sym.model import load_model
>>> from coopkin_sym.model.configuration import Configuration
>>> from coopkin_sym.analysis.finite.constraints import ConstraintMap
>>> model = load_model("four-bar")
>>> polys, names = contact_polynomials(ConstraintMap(model, Configuration.parse(model, None)))
>>> names, len(polys)
(('w3', 'u_q1', 'u_q2'), 2)
"""

from __future__ import annotations

from coopkin_sym.analysis.finite.constraints import ConstraintMap

#: No truncation: the series rings are used as polynomial rings here.
EXACT_ORDER = 10**6


def qmul(a, b) -> list:
    """The product of quaternions ``(a0, a1, a2, a3)``."""
    a0, a1, a2, a3 = a
    b0, b1, b2, b3 = b
    return [a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3, a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
            a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1, a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0]


def dqmul(a, b) -> list:
    """The product of dual quaternions ``(p, q)`` = ``p + e q`` (8 components)."""
    p = qmul(a[:4], b[:4])
    q1, q2 = qmul(a[:4], b[4:]), qmul(a[4:], b[:4])
    return p + [x + y for x, y in zip(q1, q2, strict=True)]


def _conj(a) -> list:
    return [a[0], -a[1], -a[2], -a[3]]


def link_motions(cmap: ConstraintMap, ring, gens: dict) -> list[list]:
    """The dual quaternion (8 components, in ``ring``) of each contact's link, its
    joints turned by the variables ``gens`` (column -> generator; the joints without
    one are held still); the identity for a contact on a fixed body."""
    data = cmap.chain.data
    axes, origins = cmap.joint_lines()
    one, zero = ring.one, ring.zero

    def factor(col: int) -> list:
        d = [ring.lift(x) for x in axes[col]]
        v = gens[col]
        if data["joints"][col]["kind"] == "prismatic":
            return [one, zero, zero, zero, zero] + [ring.red(v * x / 2) for x in d]
        o = [ring.lift(x) for x in origins[col]]
        m = [ring.red(o[1] * d[2] - o[2] * d[1]), ring.red(o[2] * d[0] - o[0] * d[2]),
             ring.red(o[0] * d[1] - o[1] * d[0])]
        return [one] + [v * x for x in d] + [zero] + [ring.red(v * x) for x in m]

    motions = []
    for arm, link, _, _, _ in data["contacts"]:
        dq = [one] + [zero] * 7
        if arm is not None:
            offset = data["offsets"][arm]
            for col in range(offset, offset + link):
                if col in gens:
                    dq = [ring.red(x) for x in dqmul(dq, factor(col))]
        motions.append(dq)
    return motions


def _point_map(dq: list, x: list, ring) -> tuple[list, object]:
    """``(r x r~ + 2 t r~, r r~)`` for the dual quaternion ``dq = r + e t`` and the pure
    quaternion ``x``: the moved point is the first over the second."""
    r, t = dq[:4], dq[4:]
    moved = qmul(qmul(r, x), _conj(r))
    shift = qmul(t, _conj(r))
    return ([ring.red(moved[i] + 2 * shift[i]) for i in range(4)],
            ring.red(qmul(r, _conj(r))[0]))


def _reference(positions: list[str]) -> int | None:
    """The contact that carries the object's motion: the first welded one, else the
    first hard one (None: only frictionless contacts)."""
    for kind in ("weld", "point"):
        if kind in positions:
            return positions.index(kind)
    return None


def contact_polynomials(cmap: ConstraintMap, ring=None) -> tuple[list, tuple[str, ...]]:
    """The polynomials of :mod:`this module <coopkin_sym.analysis.finite.loops>`, with the
    object's motion eliminated through one contact where it can be, and the variables
    they are in (``fmpq_mpoly`` over Q, or over the number field of the configuration
    with ``alpha`` as a last variable; the zero ones left out):

    * with a welded contact, the object moves as its link does (the dual quaternion
      ``D`` of that link): each other contact's conditions hold with ``D`` for the
      object's motion, in the joint variables alone;
    * else, with a hard one, the object's displacement ``p`` follows from it (its
      equation is linear in ``p`` with a unit coefficient): with ``L_i / |r_i|^2`` the
      point of contact ``i``'s link, ``(1 + w.w) (|r_1|^2 L_j - |r_j|^2 L_1) =
      |r_1|^2 |r_j|^2 q (x0_j - x0_1) q~`` for each other contact ``j``, in ``w`` and the
      joints;
    * else (frictionless contacts only) in ``p``, ``w`` and the joints.

    Near the configuration these cut out the closed system's configuration space, seen
    in the variables kept (the others are functions of them on it), so its local
    dimension is theirs.
    """
    names = tuple(cmap.names)
    nobj = 3 if cmap.planar else 6
    ref = _reference(cmap.positions)
    kept = names[nobj:] if ref is not None and cmap.positions[ref] == "weld" else (
        names[nobj - (1 if cmap.planar else 3):] if ref is not None else names)
    ring = ring or cmap.series_field(kept, EXACT_ORDER)
    gens = dict(zip(kept, ring.gens, strict=True))
    joints = {col: gens[name] for col, name in zip(cmap.moving, names[nobj:], strict=True)}
    motions = link_motions(cmap, ring, joints)
    points, normals = cmap.contact_points(), cmap.contact_normals()
    zero, one = ring.zero, ring.one

    def pure(v):
        return [zero] + [ring.lift(c) for c in v]

    if ref is not None and cmap.positions[ref] == "weld":
        obj = motions[ref]
        polys = []
        for j, (dq, position) in enumerate(zip(motions, cmap.positions, strict=True)):
            if j == ref:
                continue
            if position == "weld":
                polys += [ring.red(obj[0] * dq[k] - dq[0] * obj[k]) for k in (1, 2, 3, 5, 6, 7)]
                continue
            link, size = _point_map(dq, pure(points[j][0]), ring)
            held, obj_size = _point_map(obj, pure(points[j][0]), ring)
            gap = [ring.red(obj_size * link[i] - size * held[i]) for i in (1, 2, 3)]
            polys += _rows(gap, position, _turned(obj[:4], pure(normals[j] or (0, 0, 0)),
                                                  ring), cmap.planar, zero)
        return [f for f in polys if not f.is_zero()], kept
    w = [zero, zero, gens["w3"]] if cmap.planar else [gens[n] for n in ("w1", "w2", "w3")]
    q = [one] + list(w)
    ww = ring.red(one + w[0] ** 2 + w[1] ** 2 + w[2] ** 2)
    if ref is None:
        return _general(cmap, ring, gens, motions, q, ww), kept
    base, base_size = _point_map(motions[ref], pure(points[ref][0]), ring)
    polys = []
    for j, (dq, position) in enumerate(zip(motions, cmap.positions, strict=True)):
        if j == ref:
            continue
        link, size = _point_map(dq, pure(points[j][0]), ring)
        apart = qmul(qmul(q, pure([a - b for a, b in zip(points[j][0], points[ref][0],
                                                            strict=True)])), _conj(q))
        gap = [ring.red(ww * (base_size * link[i] - size * base[i])
                        - base_size * size * apart[i]) for i in (1, 2, 3)]
        polys += _rows(gap, position, _turned(q, pure(normals[j] or (0, 0, 0)), ring),
                       cmap.planar, zero)
    return [f for f in polys if not f.is_zero()], kept


def _turned(q: list, x: list, ring) -> list:
    """``q x q~`` (its vector part), reduced."""
    out = qmul(qmul(q, x), _conj(q))
    return [ring.red(c) for c in out[1:]]


def _rows(gap: list, position: str, normal: list, planar: bool, zero) -> list:
    """The rows a contact adds from the gap between its link's point and the object's:
    all of them (hard), or along the turned normal (frictionless)."""
    if position == "face":
        return [sum((normal[i] * gap[i] for i in range(3)), zero)]
    return gap[:2] if planar else gap


def _general(cmap: ConstraintMap, ring, gens: dict, motions: list, q: list, ww) -> list:
    """The polynomials with the object's displacement ``p`` kept (frictionless contacts
    only)."""
    names = cmap.names
    zero = ring.zero
    p = [gens["p1"], gens["p2"], zero] if cmap.planar else [gens[n] for n in names[0:3]]
    polys = []
    for dq, (x0, _), n0 in zip(motions, cmap.contact_points(), cmap.contact_normals(),
                               strict=True):
        x = [zero] + [ring.lift(c) for c in x0]
        link, size = _point_map(dq, x, ring)
        turned = qmul(qmul(q, x), _conj(q))
        gap = [ring.red(ww * link[i] - size * (turned[i] + ww * p[i - 1])) for i in (1, 2, 3)]
        polys += _rows(gap, "face", _turned(q, [zero] + [ring.lift(c) for c in n0], ring),
                       cmap.planar, zero)
    return [f for f in polys if not f.is_zero()]
