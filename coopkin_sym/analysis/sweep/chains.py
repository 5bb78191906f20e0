"""``Q`` at one exact point from the product of exponentials, without symbolic expansion.

A system's home data (joint axes and points, contact points and normals, each an exact
number or a polynomial in the parameters left symbolic) are read once into plain data
(:func:`chain_data`). At a point, every joint's motion is exact: a revolute joint with
``tan(q/2) = a/b`` turns by ``cos q = (b^2 - a^2)/(a^2 + b^2)``,
``sin q = 2 a b/(a^2 + b^2)`` (``q = pi`` is ``(a, b) = (1, 0)``) and a prismatic one
slides by ``a/b``. The link poses are composed along each chain, every prefix once,
and the rows of ``Q = (H G^T | -H D)`` are built from the current contact points and
normals and the current joint axes and points (as
:mod:`coopkin_sym.analysis.kinematics` assembles them). The cost is linear in the
joints of a chain for each contact.

The arithmetic is that of a :class:`Field`: residues modulo a prime
(:class:`ModularField`, with the parameters at fixed residues; a denominator that
vanishes modulo the prime raises :class:`Unlucky`), exact rationals
(:class:`RationalField`, flint's ``fmpq``), or polynomials over Q in the parameters
left symbolic (:class:`PolynomialField`, flint's ``fmpq_mpoly``: the entries of ``Q``
at a point are polynomials in them).

Example
-------
>>> from coopkin_sym.model import load_model
>>> from coopkin_sym.model.configuration import Configuration
>>> model = load_model("paper-case1-hard")
>>> chain = ChainQ(chain_data(model, Configuration.parse(model, "L=1"), ("q1", "q2")))
>>> rows = chain.rows(RationalField(), [(1, 1), (0, 1)])    # q1 = pi/2, q2 = 0
>>> [str(x) for x in rows[1]]
['0', '1', '0', '0', '0', '-1', '1', '0']
"""

from __future__ import annotations

import math
import operator
from collections.abc import Mapping, Sequence
from typing import Any

import flint
import sympy as sp

from coopkin_sym.analysis.kinematics import pick_rows
from coopkin_sym.errors import CoopkinError
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.contacts import contact_kind
from coopkin_sym.model.model import Model

#: An exact number as plain data: ``((exponents of the symbolic parameters, numerator,
#: denominator), ...)``, a polynomial with rational coefficients (``()`` is zero).
Terms = tuple[tuple[tuple[int, ...], int, int], ...]


class Unlucky(CoopkinError):
    """A denominator vanishes modulo the prime of a :class:`ModularField` (the point is
    then evaluated exactly).

    Example
    -------
    >>> ModularField(7).ratio(1, 14)
    Traceback (most recent call last):
    ...
    coopkin_sym.analysis.sweep.chains.Unlucky: a denominator vanishes modulo 7
    """


# --- plain data --------------------------------------------------------------------------
def _terms(value: Any, subs: Mapping, symbols: Sequence[sp.Symbol]) -> Terms:
    """``value`` (an exact SymPy number or polynomial in the model's parameters) as
    :data:`Terms` in ``symbols``, the parameters ``subs`` set."""
    e = sp.Integer(0) if value is None else value
    if not isinstance(e, sp.Basic):
        e = sp.Rational(e)
    if subs:
        e = e.subs(subs)
    if not symbols or not e.free_symbols:
        r = sp.Rational(e)
        return ((((0,) * len(symbols)), int(r.p), int(r.q)),) if r else ()
    coeff, rest = e.as_coeff_Mul()          # c * x**k, the common form: no Poly needed
    base, power = rest.as_base_exp()
    if coeff.is_Rational and base in symbols and power.is_Integer and power > 0:
        exps = tuple(int(power) if s == base else 0 for s in symbols)
        return ((exps, int(coeff.p), int(coeff.q)),)
    poly = sp.Poly(sp.expand(e), *symbols)
    return tuple((tuple(int(x) for x in mono), int(c.p), int(c.q))
                 for mono, c in poly.terms() if c)


def chain_data(model: Model, base: Configuration, swept: Sequence[str]) -> dict:
    """The plain data of :class:`ChainQ`: ``model`` (in its base frame) with the joints
    ``swept`` given values point by point and the others at their values in ``base``
    (home if unset); the parameters ``base`` leaves unset stay symbolic.

    Example
    -------
    >>> from coopkin_sym.model import load_model
    >>> model = load_model("paper-case1-hard")
    >>> data = chain_data(model, Configuration.parse(model, None), ("q1", "q2"))
    >>> data["params"], data["m"], data["n"]
    (['L'], 6, 8)
    """
    free = [p for p in model.parameters if p.name not in base.parameters]
    subs = {p: base.parameters[p.name] for p in model.parameters
            if p.name in base.parameters}

    def vec(v) -> tuple[Terms, Terms, Terms] | None:
        return None if v is None else tuple(_terms(x, subs, free) for x in v)

    position = {j: k for k, j in enumerate(swept)}
    joints = []
    for arm_index, arm in enumerate(model.arms):
        for joint in arm.joints:
            fixed: Any = None
            if joint.name not in position:
                if joint.type == "revolute":
                    angle = base.revolute.get(joint.name)
                    c, s = (1, 0) if angle is None else angle.cos_sin
                    fixed = (_terms(c, {}, free), _terms(s, {}, free))
                else:
                    fixed = _terms(base.prismatic.get(joint.name, 0), subs, free)
            joints.append({"kind": joint.type, "arm": arm_index, "axis": vec(joint.axis),
                           "point": vec(joint.point), "locked": joint.name in model.locked,
                           "swept": position.get(joint.name), "fixed": fixed})
    contacts = [(c.arm, c.link, vec(c.point), vec(c.normal), c.model)
                for c in model.contacts]
    dim = model.object_dim
    m = len(row_contacts(model))
    return {"planar": model.planar, "dim": dim, "m": m, "n": dim + len(joints),
            "params": [p.name for p in free], "joints": joints, "contacts": contacts,
            "offsets": [model.joint_offset(a) for a in range(len(model.arms))],
            "swept": len(swept)}


def row_contacts(model: Model) -> list[int]:
    """The contact of each row of ``Q``, in the order of
    :mod:`coopkin_sym.analysis.kinematics` (linear rows of every contact, then angular
    ones).

    Example
    -------
    >>> from coopkin_sym.model import load_model
    >>> row_contacts(load_model("paper-case1-soft"))
    [0, 0, 0, 1, 1, 1, 0, 1]
    """
    lin: list[int] = []
    ang: list[int] = []
    for i, c in enumerate(model.contacts):
        comps = contact_kind(c.model).components(model.planar)  # type: ignore[union-attr]
        lin += [i] * sum(x[0] == "v" for x in comps)
        ang += [i] * sum(x[0] == "w" for x in comps)
    return lin + ang


# --- fields ------------------------------------------------------------------------------
class Field:
    """The arithmetic of an evaluation: its constants and joint values (elements with
    ``+``, ``-`` and ``*``), and ``red``, applied to every entry computed.

    Example
    -------
    >>> RationalField().revolute(1, 1)         # q = pi/2
    (0, 1)
    """

    one: Any = 1
    zero: Any = 0

    def const(self, terms: Terms) -> Any:  # pragma: no cover - abstract
        raise NotImplementedError

    #: Applied to every entry computed (the identity, or reduction modulo a prime).
    red = staticmethod(operator.pos)

    def revolute(self, a: int, b: int) -> tuple[Any, Any]:
        """``(cos q, sin q)`` for ``tan(q/2) = a/b``."""
        w = a * a + b * b
        return self.ratio(b * b - a * a, w), self.ratio(2 * a * b, w)

    def ratio(self, a: int, b: int) -> Any:  # pragma: no cover - abstract
        raise NotImplementedError


class ModularField(Field):
    """Residues modulo the prime ``p``; the symbolic parameters at the residues
    ``params``.

    Example
    -------
    >>> ModularField(7).revolute(1, 2)        # tan(q/2) = 1/2: cos 3/5, sin 4/5
    (2, 5)
    """

    def __init__(self, p: int, params: Sequence[int] = ()):
        self.p = p
        self.params = list(params)
        self.red = p.__rmod__              # x -> x % p

    def ratio(self, a: int, b: int) -> int:
        if b % self.p == 0:
            raise Unlucky(f"a denominator vanishes modulo {self.p}")
        return a * pow(b, -1, self.p) % self.p

    def revolute(self, a: int, b: int) -> tuple[int, int]:
        inverse = self.ratio(1, a * a + b * b)          # one inverse for both
        return (b * b - a * a) * inverse % self.p, 2 * a * b * inverse % self.p

    def const(self, terms: Terms) -> int:
        p, out = self.p, 0
        for exps, num, den in terms:
            term = self.ratio(num, den)
            for v, e in zip(self.params, exps, strict=True):
                term = term * pow(v, e, p) % p
            out += term
        return out % p


class RationalField(Field):
    """Exact rationals (flint ``fmpq``); no parameter is symbolic.

    Example
    -------
    >>> RationalField().revolute(1, 0)         # q = pi
    (-1, 0)
    """

    one, zero = flint.fmpq(1), flint.fmpq(0)

    def ratio(self, a: int, b: int) -> flint.fmpq:
        return flint.fmpq(a, b)

    def const(self, terms: Terms) -> flint.fmpq:
        return sum((flint.fmpq(num, den) for _, num, den in terms), flint.fmpq(0))


class PolynomialField(Field):
    """Polynomials over Q in the symbolic parameters ``names`` (flint ``fmpq_mpoly``).

    Example
    -------
    >>> f = PolynomialField(["L"])
    >>> str(f.const((((1,), 1, 2), ((0,), 3, 1))))
    '1/2*L + 3'
    """

    def __init__(self, names: Sequence[str]):
        self.ctx = flint.fmpq_mpoly_ctx.get(tuple(names), "degrevlex")
        self.one, self.zero = self.ctx.constant(1), self.ctx.constant(0)

    def ratio(self, a: int, b: int) -> flint.fmpq_mpoly:
        return self.ctx.constant(flint.fmpq(a, b))

    def const(self, terms: Terms) -> flint.fmpq_mpoly:
        return self.ctx.from_dict({exps: flint.fmpq(num, den) for exps, num, den in terms})


# --- Q at a point --------------------------------------------------------------------------
def _skew(v):
    z = 0
    return [[z, -v[2], v[1]], [v[2], z, -v[0]], [-v[1], v[0], z]]


def _mat(a, b, red):
    return [[red(a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j])
             for j in range(3)] for i in range(3)]


def _vec(a, v, red):
    return [red(a[i][0] * v[0] + a[i][1] * v[1] + a[i][2] * v[2]) for i in range(3)]


class ChainQ:
    """``Q`` of the system described by :func:`chain_data` at exact values of its swept
    joints, in any :class:`Field` (constants converted once per field).

    Example
    -------
    >>> from coopkin_sym.model import load_model
    >>> model = load_model("paper-case1-hard")
    >>> chain = ChainQ(chain_data(model, Configuration.parse(model, "L=1"), ("q1", "q2")))
    >>> len(chain.rows(ModularField(101), [(1, 0), (1, 0)]))     # q1 = q2 = pi
    6
    """

    def __init__(self, data: dict):
        self.data = data
        self.m, self.n, self.dim = data["m"], data["n"], data["dim"]
        # how far each arm's chain is needed: the deepest link holding a contact
        self.depth = [0] * len(data["offsets"])
        for arm, link, *_ in data["contacts"]:
            if arm is not None:
                self.depth[arm] = max(self.depth[arm], link)
        self._constants: dict[int, tuple] = {}

    def _bound(self, field: Field) -> tuple:
        """The home data in ``field``: per joint ``(axis, point, K, K^2, fixed value)``,
        per contact ``(point, normal)``."""
        key = id(field)
        hit = self._constants.get(key)
        if hit is not None and hit[0] is field:
            return hit[1]
        const, red = field.const, field.red
        joints = []
        for j in self.data["joints"]:
            axis = [const(x) for x in j["axis"]]
            point = None if j["point"] is None else [const(x) for x in j["point"]]
            fixed = j["fixed"]
            if fixed is not None:
                fixed = ((const(fixed[0]), const(fixed[1])) if j["kind"] == "revolute"
                         else const(fixed))
            k = k2 = None
            if j["kind"] == "revolute":
                k = _skew(axis)
                k = [[red(x) for x in row] for row in k]
                k2 = _mat(k, k, red)
            joints.append((axis, point, k, k2, fixed))
        contacts = [([const(x) for x in pt], None if nm is None else [const(x) for x in nm])
                    for _, _, pt, nm, _ in self.data["contacts"]]
        bound = (joints, contacts)
        self._constants[key] = (field, bound)      # the field is kept: its id stays its own
        if len(self._constants) > 4:
            del self._constants[next(iter(self._constants))]
        return bound

    def rows(self, field: Field, values: Sequence[tuple[int, int]]) -> list[list[Any]]:
        """The rows of ``Q`` (entries in ``field``) with the swept joints at
        ``values``: ``(a, b)`` with ``tan(q/2) = a/b`` for a revolute joint, ``d = a/b``
        for a prismatic one. Raises :class:`Unlucky` when a denominator vanishes in
        ``field``."""
        joints, contacts = self._bound(field)

        def value(col: int, spec: dict, fixed: Any) -> Any:
            if spec["swept"] is None:
                return fixed
            a, b = values[spec["swept"]]
            return field.revolute(a, b) if spec["kind"] == "revolute" else field.ratio(a, b)

        poses, axes, origins = self.poses(field, value, self.depth)
        return self._assemble(field, contacts, poses, axes, origins)

    def poses(self, field: Field, value, depth: Sequence[int] | None = None
              ) -> tuple[list[list], list, list]:
        """The pose ``(R, t)`` of every link of every arm (``poses[arm][link]``, link 0
        the base: ``x -> R x + t`` maps its home points to the current ones), and each
        joint's current axis and point, with each joint at ``value(col, spec, fixed)``
        (``(cos q, sin q)`` or the displacement, in ``field``; ``fixed`` is its value
        when not swept) and each arm followed up to ``depth[arm]`` links (default: all).

        Example
        -------
        >>> from coopkin_sym.model import load_model
        >>> model = load_model("paper-case1-hard")
        >>> chain = ChainQ(chain_data(model, Configuration.parse(model, "L=1"), ()))
        >>> field = RationalField()
        >>> poses, _, _ = chain.poses(field, lambda col, spec, fixed: (0, 1))  # q = pi/2
        >>> [str(x) for x in poses[0][1][1]]
        ['0', '0', '0']
        """
        data = self.data
        red, one, zero = field.red, field.one, field.zero
        joints, _ = self._bound(field)
        if depth is None:
            depth = [len([j for j in data["joints"] if j["arm"] == arm])
                     for arm in range(len(data["offsets"]))]
        axes: list = [None] * len(joints)
        origins: list = [None] * len(joints)
        poses: list[list] = []
        ident = [[one, zero, zero], [zero, one, zero], [zero, zero, one]]
        for arm, offset in enumerate(data["offsets"]):
            rot, trans = ident, [zero, zero, zero]
            arm_poses = [(rot, trans)]
            for col in range(offset, offset + depth[arm]):
                spec = data["joints"][col]
                axis, point, k, k2, fixed = joints[col]
                current = value(col, spec, fixed)
                axes[col] = _vec(rot, axis, red)
                if point is not None:
                    rp = _vec(rot, point, red)
                    origins[col] = [red(rp[i] + trans[i]) for i in range(3)]
                if spec["kind"] == "revolute":
                    # x -> R (Rj (x - o) + o) + t = (R Rj) x + (current o) - (R Rj) o
                    c, s = current
                    v = one - c
                    turn = [[red((one if i == j else zero) + s * k[i][j] + v * k2[i][j])
                             for j in range(3)] for i in range(3)]
                    rot = _mat(rot, turn, red)
                    moved = _vec(rot, point, red)
                    trans = [red(o - x) for o, x in zip(origins[col], moved, strict=True)]
                else:
                    trans = [red(trans[i] + current * axes[col][i]) for i in range(3)]
                arm_poses.append((rot, trans))
            poses.append(arm_poses)
        return poses, axes, origins

    def _assemble(self, field, contacts, poses, axes, origins) -> list[list[Any]]:
        data = self.data
        red, zero = field.red, field.zero
        n, dim, planar = self.n, self.dim, data["planar"]
        lin_rows: list[list] = []
        ang_rows: list[list] = []
        for (arm, link, _, _, model), (point, normal) in zip(data["contacts"], contacts,
                                                            strict=True):
            if arm is None:
                c, nm = point, normal
            else:
                rot, trans = poses[arm][link]
                rc = _vec(rot, point, red)
                c = [red(rc[i] + trans[i]) for i in range(3)]
                nm = None if normal is None else _vec(rot, normal, red)
            # spatial rows of (G^T | -D) for the velocity components of this contact
            lin = [[zero] * (6 + n - dim) for _ in range(3)]
            ang = [[zero] * (6 + n - dim) for _ in range(3)]
            for a in range(3):
                lin[a][a] = field.one
                ang[a][3 + a] = field.one
            # -S(c): rows [0, cz, -cy], [-cz, 0, cx], [cy, -cx, 0]
            lin[0][4], lin[0][5] = c[2], red(-c[1])
            lin[1][3], lin[1][5] = red(-c[2]), c[0]
            lin[2][3], lin[2][4] = c[1], red(-c[0])
            if arm is not None:
                offset = data["offsets"][arm]
                for col in range(offset, offset + link):
                    spec = data["joints"][col]
                    if spec["locked"]:
                        continue
                    s = axes[col]
                    if spec["kind"] == "prismatic":
                        for a in range(3):
                            lin[a][6 + col] = red(-s[a])
                        continue
                    o = origins[col]
                    d = [c[i] - o[i] for i in range(3)]
                    lv = (s[1] * d[2] - s[2] * d[1], s[2] * d[0] - s[0] * d[2],
                          s[0] * d[1] - s[1] * d[0])
                    for a in range(3):
                        lin[a][6 + col] = red(-lv[a])
                        ang[a][6 + col] = red(-s[a])
            if planar:
                keep = (0, 1, 5)
                lin = [[row[k] for k in keep] + row[6:] for row in lin[:2]]
                ang = [[row[k] for k in keep] + row[6:] for row in ang[2:]]
            comps = contact_kind(model).components(planar)  # type: ignore[union-attr]
            picked = pick_rows(comps, dict(zip("xyz"[:len(lin)], lin, strict=True)),
                               dict(zip("z" if planar else "xyz", ang, strict=True)),
                               lambda rows, nm=nm: _combine(nm, rows, red))
            lin_rows += picked[0]
            ang_rows += picked[1]
        return lin_rows + ang_rows


def _combine(normal, rows, red) -> list:
    """The row ``sum_a normal[a] rows[a]`` (over the first ``len(rows)`` axes)."""
    if len(rows) == 2:
        return [red(normal[0] * x + normal[1] * y) for x, y in zip(*rows, strict=True)]
    return [red(normal[0] * x + normal[1] * y + normal[2] * z)
            for x, y, z in zip(*rows, strict=True)]


# --- ranks ---------------------------------------------------------------------------------
def integer_rows(rows: Sequence[Sequence[flint.fmpq]]) -> list[list[flint.fmpz]]:
    """Each row of rationals times the least common multiple of its denominators.

    Example
    -------
    >>> integer_rows([[flint.fmpq(1, 2), flint.fmpq(2, 3)]])
    [[3, 4]]
    """
    out = []
    for row in rows:
        scale = math.lcm(*(int(x.q) for x in row)) if row else 1
        out.append([flint.fmpz(x.p * (scale // int(x.q))) for x in row])
    return out
