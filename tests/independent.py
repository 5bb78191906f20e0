"""Independent reference computation of the Bicchi-Melchiorri-Balluchi mobility numbers.

This module deliberately imports nothing from ``coopkin_sym``: it is the yardstick the
test-suite holds the package against.  It is written naively and directly:

* every number in the model is parsed with SymPy and evaluated at the given parameter
  values (a reference works only at fully numeric, rational configurations);
* each arm is walked base-outwards with explicit 4x4 homogeneous transforms,
  ``T_k = M_1(q_1) M_2(q_2) ... M_k(q_k)``, where ``M_i`` is the exact Rodrigues rotation
  about joint i's *home* axis through its *home* point (or a translation along the home
  axis for a prismatic joint);
* joint i's current axis and point are its home axis and point carried by ``T_{i-1}``;
  a contact on link K is carried by ``T_K``;
* ``G``, ``D``, ``H`` are filled entry by entry in the paper's ordering (all linear
  blocks first, then all angular blocks) and ranks/nullspaces come from SymPy's exact
  ``Matrix.rank()`` / ``Matrix.nullspace()`` on rational matrices.

Public functions
----------------
reference_analysis(model, at=None) -> dict
    Exact numbers and matrices (see its docstring for the keys).
reference_jacobians(model, at=None) -> dict
    ``H G^T`` and ``H D`` only, also at symbolic angles.
reference_numbers_algebraic(model, at) -> dict
    The numbers at ``(cos, sin)`` pairs in radicals, ranked over their number field.
reference_numbers_float(model, at=None, tol=None) -> dict
    The same seven numbers decided by numpy float SVD ranks (the only float code here).
at_from_text(model, text) -> dict
    Parse a CLI ``--at`` string ("q1=pi/2,q2=2*atan(1/3),d=1/2,L=2") into the ``at``
    format of ``reference_analysis``.
angle_from_text(text) -> (cos, sin)
    Exact cosine/sine of an angle whose tangent half-angle is rational (or of pi).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import sympy as sp

MODELS = ("complete", "soft", "hard", "frictionless")
NUMBER_KEYS = ("Nm", "Nc", "Ni", "Nr", "Ng", "Nd", "Nh")


# ----------------------------------------------------------------------------- parsing


def _param_symbols(model: Mapping[str, Any]) -> dict[str, sp.Symbol]:
    return {str(p): sp.Symbol(str(p), positive=True) for p in model.get("parameters") or []}


def _number(value: Any, params: Mapping[str, sp.Symbol], values: Mapping[str, sp.Rational]):
    """Parse one model number exactly and evaluate it at the parameter values."""
    if isinstance(value, bool):
        raise TypeError(f"not a number: {value!r}")
    if isinstance(value, int):
        return sp.Integer(value)
    if isinstance(value, float):
        raise TypeError(f"floats are not exact model numbers: {value!r}")
    if isinstance(value, sp.Basic):
        expr = value
    elif isinstance(value, str):
        expr = sp.sympify(value, locals=dict(params), rational=True)
    else:
        raise TypeError(f"not a number: {value!r}")
    free = {s.name for s in expr.free_symbols}
    missing = free - set(values)
    if missing:
        raise ValueError(f"parameter(s) {sorted(missing)} need values in `at` for {value!r}")
    expr = expr.subs({params[k]: values[k] for k in free})
    if not expr.is_Rational:
        raise ValueError(f"{value!r} does not evaluate to a rational number: {expr}")
    return expr


def _vector(values, params, pvals) -> sp.Matrix:
    if values is None or len(values) != 3:
        raise ValueError(f"expected a 3-vector, got {values!r}")
    return sp.Matrix([_number(v, params, pvals) for v in values])


def angle_from_text(text: str) -> tuple[sp.Rational, sp.Rational]:
    """Exact ``(cos q, sin q)`` of an angle given in SymPy syntax.

    The angle must have a rational tangent half-angle (``0``, ``pi/2``, ``-pi/2``,
    ``2*atan(p/q)``) or be ``pi`` / ``-pi``.
    """
    q = sp.sympify(str(text))
    if sp.simplify(q - sp.pi) == 0 or sp.simplify(q + sp.pi) == 0:
        return sp.Integer(-1), sp.Integer(0)
    t = sp.simplify(sp.tan(q / 2))
    if not t.is_Rational:
        raise ValueError(f"angle {text!r} has no rational tangent half-angle (t = {t})")
    return (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)


def _joint_list(model: Mapping[str, Any]) -> list[dict]:
    return [j for arm in model.get("arms") or [] for j in arm["joints"]]


def at_from_text(model: Mapping[str, Any], text: str) -> dict[str, Any]:
    """Parse a CLI ``--at`` string into the ``at`` dict of :func:`reference_analysis`.

    Revolute joints get ``(cos, sin)`` pairs, prismatic joints and parameters Rationals.
    """
    kinds = {j["name"]: j["type"] for j in _joint_list(model)}
    params = {str(p) for p in model.get("parameters") or []}
    at: dict[str, Any] = {}
    for item in filter(None, (s.strip() for s in text.split(","))):
        name, _, value = item.partition("=")
        name, value = name.strip(), value.strip()
        if kinds.get(name) == "revolute":
            at[name] = angle_from_text(value)
        elif name in kinds or name in params:
            v = sp.sympify(value, rational=True)
            if not v.is_Rational:
                raise ValueError(f"{name}={value}: not a rational number")
            at[name] = v
        else:
            raise ValueError(f"{name}: neither a joint nor a parameter")
    return at


# ------------------------------------------------------------------------- kinematics


def _skew(v: sp.Matrix) -> sp.Matrix:
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def _rodrigues(axis: sp.Matrix, c, s) -> sp.Matrix:
    """Rotation matrix about the unit ``axis`` by the angle with cosine c and sine s."""
    k = _skew(axis)
    return sp.eye(3) + s * k + (1 - c) * (k * k)


def _homogeneous(rot: sp.Matrix, trans: sp.Matrix) -> sp.Matrix:
    t = sp.eye(4)
    t[:3, :3] = rot
    t[:3, 3] = trans
    return t


def _apply_point(t: sp.Matrix, p: sp.Matrix) -> sp.Matrix:
    return (t * sp.Matrix([p[0], p[1], p[2], 1]))[:3, 0]


def _apply_dir(t: sp.Matrix, d: sp.Matrix) -> sp.Matrix:
    return t[:3, :3] * d


def _joint_value(joint: Mapping[str, Any], at: Mapping[str, Any]):
    name = joint["name"]
    if joint["type"] == "revolute":
        if name not in at:
            return sp.Integer(1), sp.Integer(0)
        value = at[name]
        if isinstance(value, str):
            return angle_from_text(value)
        c, s = (sp.Rational(x) if not isinstance(x, sp.Basic) else x for x in value)
        if sp.simplify(c**2 + s**2 - 1) != 0:
            raise ValueError(f"{name}: (cos, sin) = ({c}, {s}) is not on the unit circle")
        return c, s
    if joint["type"] == "prismatic":
        value = at.get(name, 0)
        return sp.Rational(value) if not isinstance(value, sp.Basic) else value
    raise ValueError(f"{name}: unknown joint type {joint['type']!r}")


def _walk_arms(model, at, params, pvals):
    """Per arm: list of cumulative transforms [T_0 = I, T_1, ..., T_k] and current joints.

    Returns ``(frames, joints)`` with ``frames[arm] = [T_0, ..., T_k]`` and ``joints`` a
    list, in file order, of dicts ``{name, type, arm, index, s, o}`` (current axis/point).
    """
    frames: dict[str, list[sp.Matrix]] = {}
    joints: list[dict] = []
    for arm in model.get("arms") or []:
        t = sp.eye(4)
        chain = [t]
        for k, joint in enumerate(arm["joints"], start=1):
            s_home = _vector(joint["axis"], params, pvals)
            p = joint.get("point")
            p_home = _vector(p, params, pvals) if p is not None else sp.zeros(3, 1)
            if joint["type"] == "revolute":
                if sp.simplify(s_home.dot(s_home) - 1) != 0:
                    raise ValueError(f"{joint['name']}: revolute axis is not a unit vector")
            # current axis / point: home ones carried by the links before this joint
            joints.append(
                {
                    "name": joint["name"],
                    "type": joint["type"],
                    "arm": arm["name"],
                    "index": k,
                    "s": _apply_dir(t, s_home),
                    "o": _apply_point(t, p_home),
                }
            )
            value = _joint_value(joint, at)
            if joint["type"] == "revolute":
                c, s = value
                rot = _rodrigues(s_home, c, s)
                motion = _homogeneous(rot, p_home - rot * p_home)
            else:
                motion = _homogeneous(sp.eye(3), value * s_home)
            t = t * motion
            chain.append(t)
        frames[arm["name"]] = chain
    return frames, joints


def _contact_link(link: str, frames) -> tuple[str | None, int]:
    if link == "base":
        return None, 0
    arm, _, k = link.partition("/")
    if arm not in frames:
        raise ValueError(f"link {link!r}: unknown arm")
    k = int(k)
    if not 0 <= k < len(frames[arm]):
        raise ValueError(f"link {link!r}: no such link")
    return arm, k


# ------------------------------------------------------------------------ the analysis


def _build(model: Mapping[str, Any], at: Mapping[str, Any] | None):
    at = dict(at or {})
    params = _param_symbols(model)
    pvals = {}
    for name in params:
        if name not in at:
            raise ValueError(f"parameter {name} needs a value in `at`")
        pvals[name] = sp.Rational(at[name]) if not isinstance(at[name], sp.Basic) else at[name]
    frames, joints = _walk_arms(model, at, params, pvals)
    contacts = model.get("contacts") or []
    n, r = len(contacts), len(joints)

    points, normals, kinds, placement = {}, {}, [], []
    for contact in contacts:
        arm, k = _contact_link(str(contact["link"]), frames)
        c_home = _vector(contact["point"], params, pvals)
        n_home = _vector(contact["normal"], params, pvals) if "normal" in contact else None
        if arm is None:
            c_cur, n_cur = c_home, n_home
        else:
            t = frames[arm][k]
            c_cur = _apply_point(t, c_home)
            n_cur = _apply_dir(t, n_home) if n_home is not None else None
        model_kind = contact.get("model", "hard")
        if model_kind not in MODELS:
            raise ValueError(f"{contact['name']}: unknown contact model {model_kind!r}")
        if model_kind in ("soft", "frictionless") and n_cur is None:
            raise ValueError(f"{contact['name']}: a {model_kind} contact needs a normal")
        points[contact["name"]] = c_cur
        normals[contact["name"]] = n_cur
        kinds.append(model_kind)
        placement.append((arm, k))

    # G: 6 x 6n, top [I ... I | 0 ... 0], bottom [S(c_1) ... S(c_n) | I ... I]
    G = sp.zeros(6, 6 * n)
    for i, contact in enumerate(contacts):
        c = points[contact["name"]]
        for a in range(3):
            G[a, 3 * i + a] = 1
            G[3 + a, 3 * n + 3 * i + a] = 1
        G[3:6, 3 * i : 3 * i + 3] = _skew(c)

    # D: 6n x r; linear rows 3i..3i+2, angular rows 3n+3i..3n+3i+2
    D = sp.zeros(6 * n, r)
    for i, contact in enumerate(contacts):
        arm, k = placement[i]
        c = points[contact["name"]]
        for col, joint in enumerate(joints):
            if arm is None or joint["arm"] != arm or joint["index"] > k:
                continue
            s, o = joint["s"], joint["o"]
            if joint["type"] == "revolute":
                lin, ang = s.cross(c - o), s
            else:
                lin, ang = s, sp.zeros(3, 1)
            for a in range(3):
                D[3 * i + a, col] = lin[a]
                D[3 * n + 3 * i + a, col] = ang[a]

    # H: linear-block rows contact by contact, then angular-block rows contact by contact
    rows = []
    for i, contact in enumerate(contacts):
        row_kind = kinds[i]
        if row_kind in ("complete", "soft", "hard"):
            for a in range(3):
                row = sp.zeros(1, 6 * n)
                row[0, 3 * i + a] = 1
                rows.append(row)
        else:  # frictionless
            row = sp.zeros(1, 6 * n)
            row[0, 3 * i : 3 * i + 3] = normals[contact["name"]].T
            rows.append(row)
    for i, contact in enumerate(contacts):
        row_kind = kinds[i]
        if row_kind == "complete":
            for a in range(3):
                row = sp.zeros(1, 6 * n)
                row[0, 3 * n + 3 * i + a] = 1
                rows.append(row)
        elif row_kind == "soft":
            row = sp.zeros(1, 6 * n)
            row[0, 3 * n + 3 * i : 3 * n + 3 * i + 3] = normals[contact["name"]].T
            rows.append(row)
    H = sp.Matrix.vstack(*rows) if rows else sp.zeros(0, 6 * n)
    return {
        "G": G,
        "D": D,
        "H": H,
        "points": points,
        "normals": normals,
        "joints": {j["name"]: (j["s"], j["o"]) for j in joints},
        "n": n,
        "r": r,
    }


def _rank(m: sp.Matrix) -> int:
    return 0 if 0 in m.shape else int(m.rank())


def _nullspace(m: sp.Matrix) -> list[sp.Matrix]:
    if m.cols == 0:
        return []
    if m.rows == 0:
        return [sp.eye(m.cols)[:, j] for j in range(m.cols)]
    return m.nullspace()


def reference_jacobians(
    model: Mapping[str, Any], at: Mapping[str, Any] | None = None
) -> dict[str, sp.Matrix]:
    """``H G^T`` and ``H D`` alone (no ranks, no nullspaces): ``at`` may hold symbolic
    ``(cos, sin)`` pairs, e.g. rational functions of a tangent half-angle."""
    built = _build(model, at)
    return {"HGt": built["H"] * built["G"].T, "HD": built["H"] * built["D"]}


def reference_numbers_algebraic(model: Mapping[str, Any], at: Mapping[str, Any]) -> dict:
    """The seven numbers from :func:`reference_jacobians` at a configuration whose
    ``(cos, sin)`` pairs are algebraic numbers (radicals), ranked exactly by SymPy's
    ``DomainMatrix`` over the number field the entries generate."""
    from sympy.polys.matrices import DomainMatrix

    ref = reference_jacobians(model, at)
    gt, hd = ref["HGt"], ref["HD"]
    m, r = gt.rows, hd.cols
    if any(e.has(sp.sin, sp.cos, sp.tan, sp.atan) for e in (*gt, *hd)):
        # DomainMatrix would take cos(2*atan(2)) for a new transcendental generator
        raise ValueError("give (cos, sin) as radicals or rationals, not trigonometric "
                         "expressions")

    def rank(a: sp.Matrix) -> int:
        if 0 in a.shape:
            return 0
        return DomainMatrix.from_Matrix(a.applyfunc(sp.radsimp), extension=True
                                        ).to_dense().rank()

    rq, rg, rd = rank(gt.row_join(-hd)), rank(gt), rank(hd)
    nm, nr = 6 + r - rq, r - rd
    return {"Nm": nm, "Nc": nm - nr, "Ni": 6 - rg, "Nr": nr, "Ng": m - rg, "Nd": m - rd,
            "Nh": m - rq}


def reference_analysis(
    model: Mapping[str, Any], at: Mapping[str, Any] | None = None
) -> dict[str, Any]:
    """Exact mobility analysis of ``model`` at the configuration ``at``.

    Parameters
    ----------
    model : dict
        Model in the model-file format (numbers: int, "p/q" strings or
        expressions in the declared parameters).
    at : dict, optional
        ``{joint: (cos, sin)}`` for revolute joints (a text angle such as ``"pi/2"`` is
        also accepted), ``{joint: Rational}`` for prismatic displacements and
        ``{parameter: Rational}`` for every declared parameter. Unset joints are at home.

    Returns
    -------
    dict
        ``Nm, Nc, Ni, Nr, Ng, Nd, Nh`` (ints); ``G`` (6 x 6n), ``D`` (6n x r), ``H``
        (m x 6n), ``Q = (H G^T | -H D)`` (m x (6+r)) as SymPy matrices; ``N_Q``,
        ``N_GT``, ``N_D`` nullspace bases of Q, H G^T, H D (lists of column matrices);
        ``m``, ``n``, ``r``; ``points``/``normals`` (current contact point / normal by
        contact name) and ``joints`` (current ``(axis, point)`` by joint name).

    Examples
    --------
    >>> model = {"parameters": ["L"], "arms": [
    ...     {"name": "a1", "joints": [{"name": "q1", "type": "revolute",
    ...                                "axis": [0, 0, 1], "point": [0, 0, 0]}]}],
    ...     "contacts": [{"name": "c1", "link": "a1/1", "point": [0, "L", 0],
    ...                   "normal": [1, 0, 0], "model": "hard"}]}
    >>> reference_analysis(model, {"L": 1})["Nm"]
    4
    """
    built = _build(model, at)
    G, D, H = built["G"], built["D"], built["H"]
    m, r = H.rows, built["r"]
    GT = H * G.T
    HD = H * D
    Q = GT.row_join(-HD)
    N_Q = _nullspace(Q)
    N_GT = _nullspace(GT)
    N_D = _nullspace(HD)
    C1 = sp.Matrix.hstack(*[c[:6, 0] for c in N_Q]) if N_Q else sp.zeros(6, 0)
    rank_q, rank_gt, rank_d = _rank(Q), _rank(GT), _rank(HD)
    out = {
        "Nm": len(N_Q),
        "Nc": _rank(C1),
        "Ni": len(N_GT),
        "Nr": len(N_D),
        "Ng": m - rank_gt,
        "Nd": m - rank_d,
        "Nh": m - rank_q,
        "Q": Q,
        "G": G,
        "D": D,
        "H": H,
        "N_Q": N_Q,
        "N_GT": N_GT,
        "N_D": N_D,
        "m": m,
        "n": built["n"],
        "r": r,
        "points": built["points"],
        "normals": built["normals"],
        "joints": built["joints"],
    }
    assert out["Nm"] == 6 + r - rank_q and out["Ni"] == 6 - rank_gt and out["Nr"] == r - rank_d
    return out


def reference_numbers_float(
    model: Mapping[str, Any], at: Mapping[str, Any] | None = None, tol: float | None = None
) -> dict[str, int]:
    """The seven numbers with every rank decided by numpy float SVD (``matrix_rank``).

    The matrices are built exactly and converted to float64; only the rank decisions are
    floating point (numpy's default tolerance unless ``tol`` is given). Meant for
    cross-checks at well-conditioned points, and to show where float rank tests fail.
    """
    import numpy as np  # float-ok

    built = _build(model, at)
    G, D, H = built["G"], built["D"], built["H"]
    m, r = H.rows, built["r"]

    def to_float(mat):  # float-ok
        return np.array(mat.tolist(), dtype=float).reshape(mat.rows, mat.cols)  # float-ok

    gt = to_float(H * G.T)  # float-ok
    hd = to_float(H * D)  # float-ok
    q = np.hstack([gt, -hd])  # float-ok

    def rank(a) -> int:  # float-ok
        if 0 in a.shape:  # float-ok
            return 0
        return int(np.linalg.matrix_rank(a, tol=tol))  # float-ok

    rank_q, rank_gt, rank_d = rank(q), rank(gt), rank(hd)  # float-ok
    if q.shape[0] == 0:  # float-ok
        basis = np.eye(q.shape[1])  # float-ok
    else:
        _, _, vh = np.linalg.svd(q)  # float-ok
        basis = vh[rank_q:].T  # float-ok
    return {
        "Nm": 6 + r - rank_q,
        "Nc": rank(basis[:6, :]),  # float-ok
        "Ni": 6 - rank_gt,
        "Nr": r - rank_d,
        "Ng": m - rank_gt,
        "Nd": m - rank_d,
        "Nh": m - rank_q,
    }
