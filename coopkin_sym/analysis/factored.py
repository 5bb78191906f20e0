"""The coordinated motions in factored form: small per-arm maps instead of big blocks.

Every coordinated motion is an object twist ``u`` (a column of ``C12``) together with
the joint velocities that realize it. Arm by arm, those are ``qdot_a = K_a u``: ``K_a``
is a matrix of rational functions of arm ``a``'s own joint variables (and the
parameters), the same for every column. Expanded, ``K u`` mixes every arm's variables
and can have millions of terms; factored, it is a few small matrices. The distinct
irreducible factors of the denominators of every ``K_a`` are named once (``d1``,
``d2``, ...).

Exactly: ``K_a`` is the linear map of :meth:`~coopkin_sym.analysis.decomposition._ArmMap.joints_for`
(the pivot joints of ``[Dt_a | Gt_a]`` solved with the free joints at rest, then
reduced against the redundant motions), applied to the unit twists; its columns are
those joint velocities. ``[C12; K C12]`` spans the same subspace as ``[C12; C22]``.

Example
-------
>>> from coopkin_sym import load
>>> f = load("planar-two-fingers").analyze(generic=True).coordinated_factored()
>>> [arm.name for arm in f.arms], f.maps()["left"].shape
(['left', 'right'], (2, 3))
>>> f.factors[:3]
(('d1', L), ('d2', t_q2 - 1), ('d3', t_q2 + 1))
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import sympy as sp

from coopkin_sym.analysis.renderers import Displayable, clip
from coopkin_sym.errors import ArgumentTypeError, ConfigurationError
from coopkin_sym.exact.angles import ExactAngle, tangent_name
from coopkin_sym.exact.factoring import factor
from coopkin_sym.exact.parse import brief
from coopkin_sym.exact.ratfunc import RatFunc
from coopkin_sym.exact.rationals import to_sympy
from coopkin_sym.exact.sympy_bridge import poly_to_sympy
from coopkin_sym.model.configuration import Configuration


@dataclass(frozen=True)
class ArmMap:
    """One arm's map ``qdot_a = K_a u``: its name, its joints and the entries of ``K_a``
    as ``(numerator, {factor index: exponent})`` (SymPy numerator, the denominator as
    powers of the named factors; a constant of the denominator is in the numerator).

    Example
    -------
    >>> from coopkin_sym import load
    >>> f = load("planar-two-fingers").analyze(generic=True).coordinated_factored()
    >>> f.arms[0].name, f.arms[0].joints
    ('left', ('q1', 'q2'))
    """

    name: str
    joints: tuple[str, ...]
    entries: tuple[tuple[tuple[sp.Expr, tuple[tuple[int, int], ...]], ...], ...]


@dataclass(frozen=True)
class FactoredMotions(Displayable):
    """The coordinated motions ``[C12; K C12]`` with ``K`` given arm by arm.

    Attributes
    ----------
    twists
        The object twists of the coordinated motions (columns): ``C12`` before its
        columns are scaled to clear the joint part's denominators (written out when
        first asked for).
    arms
        One :class:`ArmMap` per arm with joints.
    factors
        The named irreducible factors of the denominators: ``(name, polynomial)``.
    symbols
        The symbols of the entries (joint tangents ``t_q``, parameters).
    twist_names
        The rows of ``twists``.

    Example
    -------
    >>> from coopkin_sym import load
    >>> a = load("paper-case1-hard").analyze(generic=True)
    >>> f = a.coordinated_factored()
    >>> f.maps()["a1"]
    Matrix([[0, (-t_q1**2/2 - 1/2)/(d1*d2), 0, 0, 0, 1]])
    >>> f.factors
    (('d1', L), ('d2', t_q1), ('d3', t_q2))
    >>> f
    <FactoredMotions paper case 1, hard/hard: 1 coordinated motions; arms a1 (1 joints), \
a2 (1 joints); 3 named factors>
    """

    arms: tuple[ArmMap, ...]
    factors: tuple[tuple[str, sp.Expr], ...]
    symbols: tuple[sp.Symbol, ...]
    twist_names: tuple[str, ...]
    model: Any = field(default=None, repr=False, compare=False)
    #: The number of coordinated motions (the columns of :attr:`twists`).
    motions: int = 0
    #: Writes :attr:`twists` out when they are first asked for (the maps alone, as
    #: ``coopkin analyze`` shows them, do not need them; they can be large).
    write_twists: Callable[[], sp.Matrix] | None = field(default=None, repr=False,
                                                           compare=False)

    @cached_property
    def twists(self) -> sp.Matrix:
        """The object twists of the coordinated motions (columns)."""
        if self.write_twists is None:
            raise ArgumentTypeError("these factored motions carry no twists")
        return self.write_twists()

    def factor_symbols(self) -> dict[str, sp.Symbol]:
        """The factor names as SymPy symbols."""
        return {name: sp.Symbol(name) for name, _ in self.factors}

    def maps(self, expand_factors: bool = False) -> dict[str, sp.Matrix]:
        """``K_a`` of each arm, denominators written with the factor names (or, with
        ``expand_factors``, with the factors themselves)."""
        names = [name for name, _ in self.factors]
        values = [sp.Symbol(n) for n in names] if not expand_factors else [
            f for _, f in self.factors]
        out = {}
        for arm in self.arms:
            rows = []
            for row in arm.entries:
                cells = []
                for num, powers in row:
                    den = sp.Mul(*[values[i] ** e for i, e in powers])
                    cells.append(num / den if powers else num)
                rows.append(cells)
            out[arm.name] = sp.Matrix(rows) if rows else sp.zeros(0, len(self.twist_names))
        return out

    def latex(self) -> str:
        """The factored form as LaTeX: ``\\dot q_{arm} = K_{arm} u`` for each arm, each
        ``K`` with the named factors, then the factors.

        Example
        -------
        >>> from coopkin_sym import load
        >>> f = load("planar-two-fingers").analyze(generic=True).coordinated_factored()
        >>> print(f.latex().splitlines()[-1])
        d_{7} = t_{q3}^{2} + 1
        """
        lines = []
        maps = self.maps()
        for arm in self.arms:
            name = r"\mathrm{" + arm.name.replace("_", r"\_") + "}"
            lines.append(rf"\dot q_{{{name}}} = K_{{{name}}}\, u \quad "
                         r"(u \text{ each column of } C_{12})")
            lines.append(rf"K_{{{name}}} = {sp.latex(maps[arm.name])}")
        for fname, poly in self.factors:
            lines.append(rf"{sp.latex(sp.Symbol(fname))} = {sp.latex(poly)}")
        return "\n".join(lines)

    def __repr__(self) -> str:
        arms = ", ".join(f"{arm.name} ({len(arm.joints)} joints)" for arm in self.arms)
        name = clip(getattr(self.model, "name", "") or "a system", 100)
        return (f"<FactoredMotions {name}: {self.motions} coordinated motions; "
                f"arms {arms or 'none'}; {len(self.factors)} named factors>")

    def joint_motions(self) -> sp.Matrix:
        """``K C12`` expanded into rational functions (``C22`` up to the scale of each
        column): what the factored form avoids; only for small systems."""
        ks = self.maps(expand_factors=True)
        blocks = [ks[arm.name] * self.twists for arm in self.arms]
        return sp.Matrix.vstack(*blocks).applyfunc(sp.cancel) if blocks else sp.zeros(
            0, self.twists.cols)

    def at(self, values: str | Mapping[Any, Any]) -> tuple[sp.Matrix, sp.Matrix]:
        """The exact coordinated motions at a point: ``(C12, K C12)``.

        ``values`` is ``--at`` text or a mapping by joint and parameter name
        (``"q1=2*atan(1/3),L=2"``; unset joints at home, as for
        :meth:`~coopkin_sym.system.System.analyze`), or a mapping of the symbols
        (``{t_q1: Rational(1, 3), L: 2}``, every symbol given an exact rational). A
        denominator factor that vanishes there is an error (the map is not defined at
        that point), and so is ``q = pi`` (outside the ``t = tan(q/2)`` chart).

        Example
        -------
        >>> from coopkin_sym import load
        >>> f = load("paper-case1-hard").analyze(generic=True).coordinated_factored()
        >>> u, qdot = f.at("q1=pi/2,q2=2*atan(1/3),L=1")
        >>> u.T, qdot.T
        (Matrix([[0, 16/9, 0, 0, 0, -16/9]]), Matrix([[-32/9, -16/9]]))
        """
        subs = self._point(values)
        missing = [s for s in self.symbols if s not in subs]
        if missing:
            raise ConfigurationError(f"no value for {', '.join(map(str, missing))}")
        factor_values = [f.subs(subs) for _, f in self.factors]
        for (name, _), v in zip(self.factors, factor_values, strict=True):
            if v == 0:
                raise ConfigurationError(f"the denominator factor {name} vanishes at this point")
        u = self.twists.subs(subs)
        blocks = []
        for arm in self.arms:
            rows = []
            for row in arm.entries:
                cells = []
                for num, powers in row:
                    den = sp.Integer(1)
                    for i, e in powers:
                        den *= factor_values[i] ** e
                    cells.append(num.subs(subs) / den)
                rows.append(cells)
            blocks.append(sp.Matrix(rows) * u if rows else sp.zeros(0, u.cols))
        return u, sp.Matrix.vstack(*blocks) if blocks else sp.zeros(0, u.cols)


    def _point(self, values: str | Mapping[Any, Any]) -> dict[sp.Symbol, sp.Expr]:
        """The value of each symbol at the point ``values`` (see :meth:`at`)."""
        if isinstance(values, Mapping) and values and all(
                isinstance(k, sp.Symbol) for k in values):
            known = set(self.symbols)
            out = {}
            for symbol, value in values.items():
                if symbol not in known:
                    raise ConfigurationError(
                        f"{symbol}: not a variable of the factored motions (variables: "
                        f"{', '.join(map(str, self.symbols))})")
                try:
                    out[symbol] = to_sympy(value)
                except ArgumentTypeError:
                    raise ConfigurationError(f"{symbol}: expected an exact rational, got "
                                             f"{brief(repr(value))}") from None
            return out
        if self.model is None:
            raise ConfigurationError("values: a mapping of the symbols is needed (these "
                                     "factored motions carry no model to read names with)")
        config = Configuration.parse(self.model, values)
        by_name: dict[str, sp.Expr] = dict(config.parameters)
        for joint in self.model.joints:
            if joint.type == "revolute":
                t = config.revolute.get(joint.name, ExactAngle(0, 1)).tangent
                if t is None and tangent_name(joint.name) in map(str, self.symbols):
                    raise ConfigurationError(
                        f"--at {joint.name}: q = pi lies outside the t = tan(q/2) chart of "
                        f"the factored form")
                by_name[tangent_name(joint.name)] = None if t is None else to_sympy(t)
            else:
                by_name[joint.name] = config.prismatic.get(joint.name, sp.Integer(0))
        return {x: by_name[str(x)] for x in self.symbols
                if by_name.get(str(x)) is not None and by_name[str(x)].is_Rational}


def factored_motions(analysis: Any) -> FactoredMotions:
    """The factored coordinated motions of ``analysis`` (an
    :class:`~coopkin_sym.analysis.mobility.Analysis`; see the module text)."""
    ring = analysis.ring
    zctx = ring.zctx
    syms = analysis.kinematics.symbols
    dim = analysis.dim
    units = [[zctx.constant(1 if i == k else 0) for i in range(dim)] for k in range(dim)]
    taken = {str(s) for s in syms.values()}
    factor_index: dict[str, int] = {}
    factors: list[tuple[str, sp.Expr]] = []

    def name_of(k: int) -> str:
        name = f"d{k}"
        while name in taken:
            name += "_"
        return name

    def entry(value: RatFunc):
        if value.num.is_zero():
            return sp.Integer(0), ()
        content, parts = factor(value.den)
        powers = []
        for f, e in parts:
            key = str(f)
            if key not in factor_index:
                factor_index[key] = len(factors)
                factors.append((name_of(len(factors) + 1),
                                poly_to_sympy(f, ring, syms)))
            powers.append((factor_index[key], int(e)))
        num = poly_to_sympy(value.num, ring, syms) / sp.Integer(int(content))
        return num, tuple(sorted(powers))

    arms = []
    for arm, arm_map in zip(analysis.model.arms, analysis._arm_maps, strict=True):
        if not arm.joints:
            continue
        columns = [arm_map.joints_for(u) for u in units]
        rows = tuple(tuple(entry(columns[k][j]) for k in range(dim))
                     for j in range(len(arm.joints)))
        arms.append(ArmMap(arm.name, tuple(j.name for j in arm.joints), rows))
    return FactoredMotions(tuple(arms), tuple(factors), tuple(syms[n] for n in ring.names),
                           tuple(analysis.model.twist_names), analysis.model,
                           len(analysis._coord_u), lambda: analysis._twists)
