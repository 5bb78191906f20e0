"""Exact numbers at many configurations, fast.

The matrix ``Q`` of a system is built once with the swept joints symbolic and every
other joint at its value (:class:`Compiled`); each row is cleared to integer
polynomials and *homogenized*: a swept revolute joint enters through
``tan(q/2) = a/b`` and a swept prismatic one through ``d = a/b``, so a row becomes a
polynomial in the integers ``(a, b)`` that is a nonzero multiple of the row of ``Q``
at every point, ``q = pi`` included (``(a, b) = (1, 0)``). Evaluating those integer
polynomials gives a matrix with the ranks of ``Q``, ``H G^T`` and ``H D`` at the
point, hence all seven numbers.

:func:`sweep` evaluates a whole batch modulo the prime ``p = 2**31 - 1`` and
eliminates it with numpy (:mod:`coopkin_sym.exact.modular`). A rank modulo ``p``
never exceeds the rank over Q, which never exceeds the generic rank (computed once,
exactly, over ``Q(t, L)``), so every point whose three modular ranks equal the generic
ones is *certified*; every other point (candidate singular) is *rechecked* exactly
over Q with flint. No rank is ever decided in floating point.

:func:`grid` builds the exact points of a grid. A grid angle whose ``tan(q/2)`` is
irrational is snapped to a nearby angle with a rational ``tan(q/2)`` within
``|dq| <= bound`` (floats are used only to choose that rational) and the result says so.

Example
-------
>>> from coopkin_sym import load
>>> system = load("paper-case1-hard")
>>> result = sweep(system, grid(system, "q1=-pi/2..pi/2:3,q2=-pi/2..pi/2:3"))
>>> [r["Nm"] for r in result.rows()]
[3, 2, 3, 2, 2, 2, 3, 2, 3]
>>> result.rows()[0]["q1"], result.rows()[0]["exact_recheck"]
('-pi/2', True)
"""

from __future__ import annotations

import hashlib
import io
import math
import random
from collections import OrderedDict
from collections.abc import Iterable, Mapping, Sequence
from concurrent.futures import Executor, as_completed
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import flint
import numpy as np
import sympy as sp

from coopkin_sym import limits
from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.mobility import NUMBER_NAMES, Numbers, numbers_from_ranks
from coopkin_sym.errors import SweepError
from coopkin_sym.exact import elimination as el
from coopkin_sym.exact import modular
from coopkin_sym.exact.parse import NumberError, brief, parse_angle, parse_expression
from coopkin_sym.model.configuration import (
    Configuration,
    ConfigurationError,
    split_assignments,
    top_level_parts,
)
from coopkin_sym.model.model import Model, model_of

__all__ = ["Compiled", "Grid", "SweepError", "SweepResult", "Value", "compile_system",
           "grid", "parse_grid", "sweep"]

#: Largest angle change allowed when a grid angle is snapped to a rational tan(q/2).
SNAP_BOUND = 1e-9  # float-ok: a tolerance for choosing snapped angles, never for ranks
#: Points evaluated together in one numpy block (cache-sized).
BLOCK = 4096



# --- exact values ---------------------------------------------------------------------
@dataclass(frozen=True)
class Value:
    """One exact value of a swept joint, in homogeneous coordinates.

    A revolute angle has ``tan(q/2) = num/den`` (``(1, 0)`` is ``q = pi``); a prismatic
    displacement is ``num/den``. ``text`` is exact (``"pi/2"``, ``"2*atan(1/3)"``,
    ``"3/4"``). A snapped grid angle keeps the angle that was asked for
    (``requested``) and how far the exact one lies from it (``error``, radians).

    Example
    -------
    >>> v = Value.from_tangent(Fraction(1, 3))
    >>> v.text, v.num, v.den
    ('2*atan(1/3)', 1, 3)
    >>> Value.from_cos_sin(-1, 0).text
    'pi'
    """

    text: str
    num: int
    den: int
    requested: str | None = None
    error: float | None = None  # float-ok: reported distance of a snapped angle

    @classmethod
    def from_tangent(cls, t: Fraction | int | None) -> Value:
        """The angle with ``tan(q/2) = t`` (``None``: ``q = pi``)."""
        if t is None:
            return cls("pi", 1, 0)
        t = Fraction(t)
        named = {0: "0", 1: "pi/2", -1: "-pi/2"}
        text = named.get(t, f"2*atan({t})")
        return cls(text, t.numerator, t.denominator)

    @classmethod
    def from_cos_sin(cls, cos, sin) -> Value:
        """The angle with exact rational ``(cos q, sin q)``."""
        c, s = Fraction(str(cos)), Fraction(str(sin))
        return cls.from_tangent(None if c == -1 else s / (1 + c))

    @property
    def snapped(self) -> bool:
        return self.requested is not None


def _tangent_of(ratio: Fraction) -> Fraction | None | bool:
    """``tan(pi * ratio / 2)`` when rational (``None`` for infinity), else ``False``.

    Niven: for rational ``ratio`` the half-angle tangent is rational only at multiples
    of ``pi/2``.
    """
    r = ratio % 2
    table = {Fraction(0): Fraction(0), Fraction(1, 2): Fraction(1), Fraction(1): None,
             Fraction(3, 2): Fraction(-1)}
    return table.get(r, False)


def _snap(q: float, bound: float) -> tuple[int, int, float]:  # float-ok: snapping only
    """Homogeneous ``(a, b)`` with ``|2 atan2(a, b) - q| <= bound``: the first continued
    fraction convergent of ``tan(q/2)`` (of ``cot(q/2)`` beyond 1) that meets the bound."""
    q = math.remainder(q, 2 * math.pi)  # float-ok
    t = math.tan(q / 2)  # float-ok
    inverse = abs(t) > 1  # float-ok
    for f in _convergents(Fraction(1 / t if inverse else t)):  # float-ok
        if inverse:
            a, b = (1, 0) if f == 0 else (f.denominator * (1 if f > 0 else -1),
                                          abs(f.numerator))
        else:
            a, b = f.numerator, f.denominator
        err = abs(math.remainder(2 * math.atan2(a, b) - q, 2 * math.pi))  # float-ok
        if err <= bound:  # float-ok
            return a, b, err
    raise SweepError(f"cannot snap the angle {q!r} within {bound} rad")  # pragma: no cover


def _convergents(x: Fraction):
    """The continued fraction convergents of ``x``, in order (the last is ``x``)."""
    p, q = x.numerator, x.denominator
    h0, h1, k0, k1 = 0, 1, 1, 0
    while q:
        a, r = divmod(p, q)
        h0, h1 = h1, a * h1 + h0
        k0, k1 = k1, a * k1 + k0
        yield Fraction(h1, k1)
        p, q = q, r


def _pi_text(ratio: Fraction) -> str:
    """``ratio * pi`` as SymPy prints it (``"-89*pi/90"``, ``"pi/6"``, ``"0"``)."""
    if ratio == 0:
        return "0"
    num, den = abs(ratio.numerator), ratio.denominator
    text = ("-" if ratio < 0 else "") + ("pi" if num == 1 else f"{num}*pi")
    return text + (f"/{den}" if den != 1 else "")


# --- compilation ----------------------------------------------------------------------
class _Exact:
    """Exact evaluation of the homogenized integer polynomials, in one process.

    With every parameter set, the polynomials become one straight-line program on
    Python integers (each monomial once, from a smaller one times one variable; then
    each entry as an integer combination of monomials), generated from the exponents
    and integer coefficients alone, and the ranks come from flint's ``fmpz_mat``.
    With parameters left symbolic, the entries are partially evaluated with flint and
    ranked over ``Q(L)`` by :mod:`coopkin_sym.exact.elimination`.
    """

    def __init__(self, plan: dict):
        self.m, self.n = plan["m"], plan["n"]
        self.kinds = plan["kinds"]
        self.njv = plan["njv"]
        self.params = plan["nvars"] - plan["njv"]
        if self.params:
            self.ctx = flint.fmpz_mpoly_ctx.get(tuple(plan["names"]), "degrevlex")
            self.entries = [(k, self.ctx.from_dict(dict(t))) for k, t in plan["terms"]]
        else:
            self.program = _straight_line(plan["terms"], plan["nvars"], self.m, self.n)
            n = self.n                          # column selections, applied in C
            self.first = flint.fmpz_mat(n, 6, [int(i == j) for i in range(n)
                                               for j in range(6)])
            self.last = flint.fmpz_mat(n, n - 6, [int(i == j + 6) for i in range(n)
                                                  for j in range(n - 6)])

    def ranks(self, pairs: Sequence[tuple[int, int]]) -> tuple[int, int, int]:
        """Exact ranks of ``Q``, of its first 6 and of its last ``r`` columns."""
        m, n = self.m, self.n
        if m == 0:
            return 0, 0, 0
        args = _joint_vector(self.kinds, pairs)
        if not self.params:
            full = flint.fmpz_mat(m, n, self.program(args))
            return (full.rank(), (full * self.first).rank(),
                    (full * self.last).rank() if n > 6 else 0)
        subs = {i: flint.fmpz(args[i]) for i in range(self.njv)}
        zero = self.ctx.constant(0)
        flat = [zero] * (m * n)
        for k, poly in self.entries:
            flat[k] = poly.subs(subs) if subs else poly
        rows = [flat[i * n:(i + 1) * n] for i in range(m)]
        return (el.rank(rows, n), el.rank([r[:6] for r in rows], 6),
                el.rank([r[6:] for r in rows], n - 6) if n > 6 else 0)


def _straight_line(terms: list, nvars: int, m: int, n: int):
    """A Python function ``x -> entries of Q`` (a flat, row-major list of ints)
    evaluating the integer polynomials ``terms`` at the integer vector ``x``. The
    generated text holds only integers and local names."""
    names: dict[tuple[int, ...], str] = {(0,) * nvars: "1"}
    lines: list[str] = []

    def monomial(e: tuple[int, ...]) -> str:
        if e in names:
            return names[e]
        used = [v for v, x in enumerate(e) if x]
        parents = [(v, e[:v] + (e[v] - 1,) + e[v + 1:]) for v in used]
        v, parent = next(((v, q) for v, q in parents if q in names), parents[-1])
        base = monomial(parent)
        if base == "1":
            names[e] = f"x{v}"
        else:
            names[e] = f"m{len(lines)}"
            lines.append(f"    {names[e]} = {base} * x{v}")
        return names[e]

    for e in sorted({tuple(e) for _, entry in terms for e, _ in entry}, key=sum):
        monomial(e)
    cells = ["0"] * (m * n)
    for k, entry in terms:
        expr = ""
        for e, c in entry:
            mono = monomial(tuple(e))
            mag = abs(c)
            term = str(mag) if mono == "1" else (mono if mag == 1 else f"{mag}*{mono}")
            expr += (" - " if c < 0 else " + ") + term
        name = f"e{k}"
        lines.append(f"    {name} = {expr[3:] if expr.startswith(' + ') else '-' + expr[3:]}")
        cells[k] = name
    head = ["def _evaluate(x):"]
    if nvars:
        head.append("    " + "".join(f"x{i}, " for i in range(nvars)) + "= x")
    source = "\n".join(head + lines + [f"    return [{', '.join(cells)}]"])
    namespace: dict = {"__builtins__": {}}
    # the source is generated here from the package's own exact integer polynomials
    # (integers and local names only, see above): no external text reaches it
    exec(compile(source, "<coopkin_sym: compiled Q>", "exec"), namespace)  # parse-ok
    return namespace["_evaluate"]


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
        top = [max(es) for es in zip(*(f.den for f in frac_row), strict=True)]
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
        model = model_of(system)
        if not (2 < prime < 2**31 and sp.isprime(prime)):
            raise ValueError(f"prime: expected an odd prime below 2**31, got {prime}")
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
        kin = kinematics.build(model, self.base)
        ring = kin.ring
        self.r = len(model.joints)
        self.m = len(kin.Q)
        n = self.n = 6 + self.r
        var_of = {}
        for j, kind in zip(joints, self.kinds, strict=True):
            var_of[j] = ring.names.index(f"t_{j}" if kind == "revolute" else j)
        param_vars = [i for i, nm in enumerate(ring.names) if nm not in
                      {ring.names[v] for v in var_of.values()}]
        names = []
        for j, kind in zip(joints, self.kinds, strict=True):
            names += ([f"{j}.w", f"{j}.c", f"{j}.s"] if kind == "revolute"
                      else [f"{j}.num", f"{j}.den"])
        njv = len(names)
        names += [ring.names[i] for i in param_vars]
        rows = [ring.clear_row(row) for row in kin.Q]
        terms = _compile_rows(kin.Q, rows, ring, joints, self.kinds, var_of, param_vars,
                              names, n)
        generic = (el.rank(rows, n) if rows else 0,
                   el.rank([r[:6] for r in rows], 6) if rows else 0,
                   el.rank([r[6:] for r in rows], n - 6) if rows else 0)
        self.generic_ranks = generic
        self.generic = self._numbers(*generic)
        flat_terms = [(k, e, c) for k, ts in terms for e, c in ts]
        nvars = len(names)
        exps = np.array([e for _, e, _ in flat_terms], dtype=np.int64).reshape(-1, nvars)
        used = sorted({k % n for k, _ in terms})
        key = hashlib.sha1(repr((names, terms, self.m, n)).encode()).hexdigest()
        self.plan = {
            "key": key, "prime": prime, "m": self.m, "n": n, "names": names,
            "kinds": list(self.kinds), "njv": njv, "nvars": nvars, "terms": terms,
            "exps": exps,
            "coefs": modular.residues([c for _, _, c in flat_terms], prime),
            "entries": np.array([k for k, _, _ in flat_terms], dtype=np.int64),
            "params": [random.Random(f"coopkin:{names[i]}").randrange(2, prime)
                       for i in range(njv, nvars)],
            "cols6": [c for c in used if c < 6], "colsr": [c for c in used if c >= 6],
            "generic": generic,
        }

    def _default(self, full: Configuration, joint: str) -> Value:
        if joint in full.revolute:
            return Value.from_cos_sin(*full.revolute[joint])
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
        return numbers_from_ranks(self.m, self.r, rq, r6, rr)

    def value(self, joint: str, value) -> Value:
        """The exact :class:`Value` of ``joint`` for ``value`` (an angle in SymPy syntax,
        a ``(cos, sin)`` pair, a displacement, or a :class:`Value`)."""
        if isinstance(value, Value):
            return value
        if joint not in self.joints:
            raise SweepError(f"{joint} is not a swept joint (swept: {', '.join(self.joints)})")
        if self._kind(joint) == "revolute":
            cfg = Configuration.parse(self.model, {joint: value})
            return Value.from_cos_sin(*cfg.revolute[joint])
        given = dict(self.base.parameters)
        cfg = Configuration.parse(self.model, {joint: value, **given})
        return self._rational(joint, cfg.prismatic[joint], value)

    def ranks(self, values: Sequence[Value]) -> tuple[int, int, int]:
        """Exact ranks of ``Q``, ``H G^T`` and ``H D`` at the swept values (in the order
        of :attr:`joints`)."""
        return _exact_for(self.plan).ranks([(v.num, v.den) for v in values])

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
        sorted((str(k), str(v)) for k, v in at.items()))
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


def _split_point(point) -> list[tuple[str, object]]:
    try:
        return split_assignments(point, f"point {brief(point)}")
    except ConfigurationError as exc:
        raise SweepError(str(exc)) from None


# --- grids ----------------------------------------------------------------------------
@dataclass(frozen=True)
class Grid:
    """The exact points of a grid: every combination of the values of each joint
    (the last joint varies fastest).

    Attributes
    ----------
    joints
        The swept joints, in grid order.
    levels
        For each joint, its exact :class:`Value` list.
    bound
        The largest ``|dq|`` allowed to a snapped angle (radians).
    """

    joints: tuple[str, ...]
    levels: tuple[tuple[Value, ...], ...]
    bound: float  # float-ok

    def __len__(self) -> int:
        return math.prod(len(v) for v in self.levels)

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(v) for v in self.levels)

    def index(self) -> np.ndarray:
        """``(points, joints)`` indices into :attr:`levels`, in grid order."""
        if not self.levels:
            return np.zeros((1, 0), dtype=np.int64)
        mesh = np.meshgrid(*[np.arange(len(v)) for v in self.levels], indexing="ij")
        return np.stack([g.ravel() for g in mesh], axis=1).astype(np.int64)

    def __iter__(self):
        for row in self.index():
            yield {j: self.levels[k][i].text for k, (j, i) in
                   enumerate(zip(self.joints, row, strict=True))}

    @property
    def snapped(self) -> list[dict]:
        """The snapped angles: joint, requested angle, exact angle used, ``|dq|``."""
        return [{"joint": j, "requested": v.requested, "used": v.text, "error_rad": v.error}
                for j, vs in zip(self.joints, self.levels, strict=True) for v in vs
                if v.snapped]


def parse_grid(text: str) -> dict[str, tuple[str, str, int]]:
    """Read ``"q1=-pi..pi:181,q2=0..1/2:11"`` into ``{joint: (lo, hi, count)}``.

    Example
    -------
    >>> parse_grid("q1=-pi..pi:181, d4=0..1/2:3")
    {'q1': ('-pi', 'pi', 181), 'd4': ('0', '1/2', 3)}
    """
    axes: dict[str, tuple[str, str, int]] = {}
    for part in top_level_parts(text):
        part = part.strip()
        if not part:
            continue
        shape = f"--grid {brief(part)}: expected NAME=LO..HI:COUNT (e.g. q1=-pi..pi:181)"
        if "=" not in part:
            raise SweepError(shape)
        name, spec = (s.strip() for s in part.split("=", 1))
        if ".." not in spec or ":" not in spec:
            raise SweepError(shape)
        rng, _, count = spec.rpartition(":")
        lo, _, hi = rng.partition("..")
        if not name or not lo.strip() or not hi.strip():
            raise SweepError(shape)
        if len(count.strip()) > 12 and count.strip().isdigit():
            raise SweepError(f"--grid {brief(part)}: the count is over the limit of "
                             f"{limits.MAX_GRID_COUNT:,} points per joint")
        try:
            n = int(count.strip()) if len(count.strip()) <= 12 else None
            if n is None:
                raise ValueError(count)
        except ValueError:
            raise SweepError(f"--grid {brief(part)}: the count {brief(count.strip())} is not an "
                             f"integer") from None
        if name in axes:
            raise SweepError(f"--grid: {name} given more than once")
        axes[name] = (lo.strip(), hi.strip(), n)
    if not axes:
        raise SweepError("--grid: no joint given (expected NAME=LO..HI:COUNT,...)")
    return axes


def grid(system: Model | Any, axes: str | Mapping[str, tuple], *,
         bound: float = SNAP_BOUND) -> Grid:  # float-ok: the snapping bound
    """The exact points of a grid over some joints.

    Parameters
    ----------
    system
        The system (or its model).
    axes
        ``{joint: (lo, hi, count)}`` (ends as exact text, e.g. ``("-pi", "pi", 181)``)
        or the text ``"q1=-pi..pi:181,q2=..."``; ``count`` evenly spaced values from
        ``lo`` to ``hi`` inclusive (``count = 1``: ``lo`` alone).
    bound
        A revolute value whose ``tan(q/2)`` is irrational is replaced by an angle whose
        ``tan(q/2)`` is a rational with a small denominator, within ``|dq| <= bound``
        radians, and listed in :attr:`Grid.snapped`. Prismatic values must be rational.

    Example
    -------
    >>> from coopkin_sym import load
    >>> g = grid(load("paper-case1-hard"), {"q1": ("-pi", "pi", 5), "q2": ("0", "0", 1)})
    >>> [v.text for v in g.levels[0]], len(g)
    (['-pi', '-pi/2', '0', 'pi/2', 'pi'], 5)
    >>> g2 = grid(load("paper-case1-hard"), "q1=0..pi/3:2")
    >>> g2.levels[0][1].text, g2.snapped[0]["requested"]
    ('2*atan(29681/51409)', 'pi/3')
    """
    model = model_of(system)
    spec = parse_grid(axes) if isinstance(axes, str) else dict(axes)
    kinds = {j.name: j.type for j in model.joints}
    params = {p.name for p in model.parameters}
    joints, levels = [], []
    for name, axis in spec.items():
        where = f"--grid {name}"
        if name not in kinds:
            what = (f"{name} is a parameter, not a joint (set it with --at)" if name in params
                    else f"unknown joint {brief(name)} (joints: {', '.join(model.joint_names)})")
            raise SweepError(f"{where}: {what}")
        try:
            lo, hi, count = axis
        except (TypeError, ValueError):
            raise SweepError(f"{where}: expected (lo, hi, count)") from None
        if isinstance(count, bool) or not isinstance(count, int | np.integer):
            raise SweepError(f"{where}: the count must be an integer, got {brief(count)}")
        if count < 1:
            raise SweepError(f"{where}: zero points (the count must be at least 1, "
                             f"got {count})")
        if count > limits.MAX_GRID_COUNT:
            raise SweepError(f"{where}: {count:,} points is over the limit of "
                             f"{limits.MAX_GRID_COUNT:,} per joint")
        total = math.prod(len(v) for v in levels) * int(count)
        if total > limits.MAX_GRID_POINTS:
            raise SweepError(f"{where}: the grid would have {total:,} points, over the "
                             f"limit of {limits.MAX_GRID_POINTS:,}")
        try:
            ends = [parse_expression(str(x), {}, where, max_length=limits.MAX_NUMBER_TEXT,
                                     kind="parameters") for x in (lo, hi)]
        except NumberError as exc:
            raise SweepError(str(exc)) from None
        if kinds[name] == "revolute":
            if any(abs(e) > limits.MAX_ANGLE_RADIANS for e in ends):
                raise SweepError(f"{where}: an end beyond {limits.MAX_ANGLE_RADIANS:,} "
                                 "radians (use an angle in [-pi, pi])")
            levels.append(tuple(_angle_levels(ends[0], ends[1], int(count), bound, where)))
        else:
            if not all(e.is_Rational for e in ends):
                raise SweepError(f"{where}: a prismatic range must have rational ends "
                                 f"(got {lo}..{hi})")
            a, b = (Fraction(int(e.p), int(e.q)) for e in ends)
            step = (b - a) / (count - 1) if count > 1 else Fraction(0)
            vals = [a + step * k for k in range(int(count))]
            levels.append(tuple(Value(str(v), v.numerator, v.denominator) for v in vals))
        joints.append(name)
    return Grid(tuple(joints), tuple(levels), bound)


def _angle_levels(lo: sp.Expr, hi: sp.Expr, count: int, bound: float,  # float-ok
                  where: str):
    steps = [Fraction(k, count - 1) if count > 1 else Fraction(0) for k in range(count)]
    rlo, rhi = lo / sp.pi, hi / sp.pi
    if rlo.is_Rational and rhi.is_Rational:          # multiples of pi: decided by Niven
        a, b = Fraction(int(rlo.p), int(rlo.q)), Fraction(int(rhi.p), int(rhi.q))
        for s in steps:
            ratio = a + (b - a) * s
            text = _pi_text(ratio)
            t = _tangent_of(ratio)
            if t is not False:
                v = Value.from_tangent(t)
                yield Value(text, v.num, v.den)
            else:
                yield _snapped(text, float(ratio) * math.pi, bound)  # float-ok
        return
    for s in steps:
        q = lo + (hi - lo) * sp.Rational(s.numerator, s.denominator)
        text = sp.sstr(q)
        if q.is_Rational:                             # tan(x) is irrational at x != 0
            if q == 0:
                yield Value("0", 0, 1)
            else:
                yield _snapped(text, float(q), bound)  # float-ok
            continue
        try:
            c, sn = parse_angle(q, where)
        except NumberError:
            yield _snapped(text, float(sp.N(q, 30)), bound)  # float-ok
            continue
        v = Value.from_cos_sin(c, sn)
        yield Value(text, v.num, v.den)


def _snapped(requested: str, q: float, bound: float) -> Value:  # float-ok
    a, b, err = _snap(q, bound)
    exact = Value.from_tangent(None if b == 0 else Fraction(a, b))
    return Value(exact.text, exact.num, exact.den, requested, err)


# --- the sweep ------------------------------------------------------------------------
def _run_chunk(plan: dict, pairs: list[list[tuple[int, int]]],
               index: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Ranks ``(points, 3)`` (Q, first 6 columns, last r columns) of one chunk and which
    points needed the exact recheck. Plain data in and out (runs in any process)."""
    p = plan["prime"]
    m, n = plan["m"], plan["n"]
    count = index.shape[0]
    ranks = np.zeros((count, 3), dtype=np.int64)
    rechecked = np.zeros(count, dtype=bool)
    if m == 0 or count == 0:
        return ranks, rechecked
    columns = []                       # per joint: residues of its variables per value
    for kind, ps in zip(plan["kinds"], pairs, strict=True):
        vectors = [_joint_vector([kind], [pair]) for pair in ps]
        columns.append([modular.residues(col, p) for col in zip(*vectors, strict=True)])
    cols6, colsr = plan["cols6"], plan["colsr"]
    generic = np.array(plan["generic"], dtype=np.int64)
    for start in range(0, count, BLOCK):
        idx = index[start:start + BLOCK]
        size = idx.shape[0]
        rows = []
        for j, cols in enumerate(columns):
            rows += [col[idx[:, j]] for col in cols]
        rows += [np.full(size, v, dtype=np.int64) for v in plan["params"]]
        values = np.stack(rows) if rows else np.zeros((0, size), dtype=np.int64)
        flat = modular.evaluate(plan["exps"], plan["coefs"], plan["entries"], m * n,
                                values, p).reshape(m, n, size)
        block = ranks[start:start + size]
        if colsr or cols6:
            rq, rr = modular.rank_profile(flat[:, colsr + cols6, :], p, prefix=len(colsr))
            block[:, 0], block[:, 2] = rq, rr
        if cols6:
            block[:, 1] = modular.rank_profile(flat[:, cols6, :], p)[0]
    if (ranks > generic).any():  # pragma: no cover - impossible: rank mod p <= rank
        raise AssertionError("a rank modulo p exceeds the generic rank")
    doubt = np.flatnonzero((ranks != generic).any(axis=1))
    if doubt.size:
        exact = _exact_for(plan)
        for i in doubt:
            ranks[i] = exact.ranks([pairs[j][index[i, j]] for j in range(len(pairs))])
        rechecked[doubt] = True
    return ranks, rechecked


@dataclass
class SweepResult:
    """The exact numbers at every point of a sweep.

    Attributes
    ----------
    system
        The system's name.
    joints
        The swept joints (columns of the points).
    at
        The other joints and the parameters, in ``--at`` syntax.
    generic
        The numbers with the swept joints symbolic.
    levels, index
        The exact values of each joint and, per point, which one it takes.
    numbers
        ``(points, 7)`` integers, columns ``Nm, Nc, Ni, Nr, Ng, Nd, Nh``.
    rechecked
        ``(points,)``: the modular pass could not certify the point (a candidate
        singular point), so its numbers were computed exactly over Q; every other
        point was certified by its ranks modulo :attr:`prime`.
    bound
        The snapping bound of the grid (radians), ``None`` for explicit points.
    """

    system: str
    joints: tuple[str, ...]
    at: str
    generic: Numbers
    levels: tuple[tuple[Value, ...], ...]
    index: np.ndarray
    numbers: np.ndarray
    rechecked: np.ndarray
    prime: int
    bound: float | None = None  # float-ok

    def __len__(self) -> int:
        return int(self.numbers.shape[0])

    @property
    def certified(self) -> np.ndarray:
        """Points certified by the modular pass (the complement of :attr:`rechecked`)."""
        return ~self.rechecked

    @property
    def snapped(self) -> list[dict]:
        """Snapped grid angles: joint, requested angle, exact angle used, ``|dq|``."""
        return [{"joint": j, "requested": v.requested, "used": v.text, "error_rad": v.error}
                for j, vs in zip(self.joints, self.levels, strict=True) for v in vs
                if v.snapped]

    def point(self, i: int) -> dict[str, str]:
        """The exact values (``--at`` syntax) of the swept joints at point ``i``."""
        return {j: self.levels[k][self.index[i, k]].text for k, j in enumerate(self.joints)}

    def at_text(self, i: int) -> str:
        """Point ``i`` with the fixed values, for :meth:`System.analyze`."""
        parts = [f"{j}={t}" for j, t in self.point(i).items()]
        return ",".join(parts + ([self.at] if self.at else []))

    def numbers_at(self, i: int) -> Numbers:
        return Numbers(*(int(x) for x in self.numbers[i]))

    def rows(self) -> list[dict]:
        """One dict per point: joint texts, the seven numbers, ``exact_recheck``."""
        texts = [[v.text for v in vs] for vs in self.levels]
        out = []
        for idx, nums, re in zip(self.index.tolist(), self.numbers.tolist(),
                                 self.rechecked.tolist(), strict=True):
            row = {j: texts[k][idx[k]] for k, j in enumerate(self.joints)}
            row.update(zip(NUMBER_NAMES, nums, strict=True))
            row["exact_recheck"] = re
            out.append(row)
        return out

    def summary(self) -> dict[str, int]:
        """How many points: in all, certified modulo p, rechecked exactly, snapped."""
        return {"points": len(self), "certified_mod_p": int(self.certified.sum()),
                "rechecked_exact": int(self.rechecked.sum()),
                "snapped_values": len(self.snapped)}

    def _snap_note(self) -> str:
        snaps = self.snapped
        if not snaps:
            return "none: every angle is exact as requested"
        worst = max(s["error_rad"] for s in snaps)  # float-ok: reported
        return (f"{len(snaps)} grid angles with an irrational tan(q/2) were replaced by a "
                f"nearby angle with a rational tan(q/2), |dq| <= {self.bound:g} rad "
                f"(largest {worst:.3g} rad); the angles written are the exact ones used")

    def header(self) -> dict:
        """Everything but the points, as plain data."""
        return {
            "system": self.system, "joints": list(self.joints), "at": self.at,
            "columns": list(self.joints) + list(NUMBER_NAMES) + ["exact_recheck"],
            "generic": self.generic.as_dict(),
            "method": (f"ranks modulo p = {self.prime} certify a point when they equal the "
                       "generic ranks (a rank modulo p never exceeds the rank over Q); "
                       "every other point is rechecked exactly over Q"),
            "prime": self.prime, "counts": self.summary(),
            "snapping": {"bound_rad": self.bound, "note": self._snap_note(),
                         "snapped": self.snapped},
        }

    def to_json(self) -> dict:
        """``{"header": {...}, "points": [{"q1": "pi/2", ..., "Nm": 2, ...}, ...]}``."""
        return {"header": self.header(), "points": self.rows()}

    def json_text(self) -> str:
        """:meth:`to_json` as text: the header indented, one line per point."""
        import json

        points = ",\n".join("  " + json.dumps(row) for row in self.rows())
        header = json.dumps(self.header(), indent=2).replace("\n", "\n  ")
        return f'{{\n  "header": {header},\n  "points": [\n{points}\n  ]\n}}\n'

    def to_csv(self) -> str:
        """CSV with ``#`` comment lines first (system, fixed values, generic numbers,
        counts, snapping), then ``q1,...,Nm,...,Nh,exact_recheck`` rows."""
        h = self.header()
        out = io.StringIO()
        out.write(f"# system: {self.system}\n")
        out.write(f"# fixed: {self.at or 'home, parameters symbolic'}\n")
        out.write("# generic numbers (swept joints symbolic): "
                  + " ".join(f"{k}={v}" for k, v in h["generic"].items()) + "\n")
        c = h["counts"]
        out.write(f"# points: {c['points']}; certified modulo p = {self.prime}: "
                  f"{c['certified_mod_p']}; rechecked exactly over Q: "
                  f"{c['rechecked_exact']}\n")
        out.write(f"# snapped: {self._snap_note()}\n")
        out.write(",".join(h["columns"]) + "\n")
        texts = [[v.text for v in vs] for vs in self.levels]
        for idx, nums, re in zip(self.index.tolist(), self.numbers.tolist(),
                                 self.rechecked.tolist(), strict=True):
            cells = [texts[k][i] for k, i in enumerate(idx)] + [str(x) for x in nums]
            cells.append("true" if re else "false")
            out.write(",".join(cells) + "\n")
        return out.getvalue()


def sweep(system: Model | Any, points: Grid | Iterable[str | Mapping], *,
          at: str | Mapping | None = None,
          executor: Executor | None = None, progress: bool = False,
          chunk: int = 16384, prime: int = modular.PRIME) -> SweepResult:
    """Exact numbers at many points.

    Parameters
    ----------
    system
        The system (or its model).
    points
        A :class:`Grid` (see :func:`grid`), or an iterable of points, each a mapping
        ``{joint: value}`` or text ``"q1=pi/2,q2=2*atan(1/3)"`` of exact values (the
        swept joints are those named; one left out of a point takes its value from
        ``at``, else home).
    at
        Values of the other joints and of parameters.
    executor
        Any :class:`concurrent.futures.Executor` (a process pool, a cluster's
        executor): chunks of points are mapped over it as plain data.
    progress
        Show a progress bar (on stderr).
    chunk
        Points per task.
    prime
        The prime of the modular pass (below ``2**31``).

    Example
    -------
    >>> from coopkin_sym import load
    >>> res = sweep(load("paper-case1-hard"), ["q1=pi/2,q2=pi/2", "q1=0,q2=0"])
    >>> res.numbers[:, 0].tolist(), res.rechecked.tolist()
    ([3, 2], [True, False])
    """
    model = model_of(system)
    bound = None
    if isinstance(points, Grid):
        joints, levels, bound = points.joints, points.levels, points.bound
        index = points.index()
        compiled = compile_system(model, joints, at, prime)
    else:
        parsed = []
        for pt in points:
            parsed.append(_split_point(pt))
            if len(parsed) > limits.MAX_GRID_POINTS:
                raise SweepError(f"points: more than {limits.MAX_GRID_POINTS:,} points "
                                 "(the limit of one sweep)")
        if not parsed:
            raise SweepError("no points to sweep")
        names = {n for items in parsed for n, _ in items}
        joints = tuple(j for j in model.joint_names if j in names)
        unknown = sorted(names - set(joints))
        if unknown:
            params = {p.name for p in model.parameters}
            bad = unknown[0]
            what = (f"{bad} is a parameter: set it with at=" if bad in params
                    else f"unknown joint {brief(bad)} (joints: {', '.join(model.joint_names)})")
            raise SweepError(f"points: {what}")
        compiled = compile_system(model, joints, at, prime)
        table: list[dict] = [{} for _ in joints]
        lv: list[list[Value]] = [[] for _ in joints]
        index = np.zeros((len(parsed), len(joints)), dtype=np.int64)
        for i, items in enumerate(parsed):
            given = dict(items)
            for k, j in enumerate(joints):
                raw = given.get(j)
                key = ("default",) if raw is None else _hashable(raw)
                pos = table[k].get(key)
                if pos is None:
                    v = compiled.defaults[k] if raw is None else compiled.value(j, raw)
                    pos = table[k].get((v.num, v.den))
                    if pos is None:
                        pos = table[k][(v.num, v.den)] = len(lv[k])
                        lv[k].append(v)
                    table[k][key] = pos
                index[i, k] = pos
        levels = tuple(tuple(v) for v in lv)
    pairs = [[(v.num, v.den) for v in vs] for vs in levels]
    total = index.shape[0]
    ranks = np.zeros((total, 3), dtype=np.int64)
    rechecked = np.zeros(total, dtype=bool)
    chunk = max(1, int(chunk))
    starts = list(range(0, total, chunk))
    with _progress(progress, total, model.name) as advance:
        if executor is None:
            for s in starts:
                r, re = _run_chunk(compiled.plan, pairs, index[s:s + chunk])
                ranks[s:s + chunk], rechecked[s:s + chunk] = r, re
                advance(len(r))
        else:
            futures = {}
            for s in starts:
                sub, local_pairs = _localize(index[s:s + chunk], pairs)
                futures[executor.submit(_run_chunk, compiled.plan, local_pairs, sub)] = s
            for fut in as_completed(futures):
                s = futures[fut]
                r, re = fut.result()
                ranks[s:s + chunk], rechecked[s:s + chunk] = r, re
                advance(len(r))
    m, r = compiled.m, compiled.r
    rq, r6, rr = ranks[:, 0], ranks[:, 1], ranks[:, 2]
    nm, nr = 6 + r - rq, r - rr
    numbers = np.stack([nm, nm - nr, 6 - r6, nr, m - r6, m - rr, m - rq], axis=1)
    return SweepResult(model.name, tuple(joints), compiled.at_text, compiled.generic,
                       tuple(levels), index, numbers, rechecked, prime, bound)


def _hashable(value):
    try:
        hash(value)
    except TypeError:
        return ("repr", repr(value))
    return (type(value).__name__, value)


def _localize(index: np.ndarray, pairs: list[list[tuple[int, int]]]):
    """The chunk's own value tables (only the values it uses) and its re-indexed points."""
    sub = np.empty_like(index)
    local = []
    for k, ps in enumerate(pairs):
        used, inverse = np.unique(index[:, k], return_inverse=True)
        sub[:, k] = inverse.ravel()
        local.append([ps[i] for i in used.tolist()])
    return sub, local


class _progress:
    """A rich progress bar on stderr (or nothing)."""

    def __init__(self, show: bool, total: int, name: str):
        self.show, self.total, self.name = show, total, name
        self.bar = None

    def __enter__(self):
        if not self.show:
            return lambda k: None
        from rich.console import Console
        from rich.progress import (
            BarColumn,
            MofNCompleteColumn,
            Progress,
            TextColumn,
            TimeRemainingColumn,
        )

        self.bar = Progress(TextColumn("sweep {task.description}"), BarColumn(),
                            MofNCompleteColumn(), TimeRemainingColumn(),
                            console=Console(stderr=True), transient=True)
        self.bar.__enter__()
        task = self.bar.add_task(self.name, total=self.total)
        return lambda k: self.bar.advance(task, k)

    def __exit__(self, *exc):
        if self.bar is not None:
            self.bar.__exit__(*exc)
        return False
