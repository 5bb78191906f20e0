"""Exact values for the locus verification: ``tan(q/2)`` of a revolute joint (None for
q = pi), the components' equations as polynomials in the free variables' charts, and
rational lines (each free variable a polynomial in ``lam``, in one of its charts).
"""

from __future__ import annotations

import functools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction

import flint
import sympy as sp

from coopkin_sym.errors import VerifyError
from coopkin_sym.exact.angles import ExactAngle, cotangent_name, tangent_name
from coopkin_sym.exact.polynomial import NamedPolynomial
from coopkin_sym.exact.rationals import to_fmpq, to_fraction, to_sympy
from coopkin_sym.model.model import Model

Tan = Fraction | None          # a revolute value: tan(q/2), None for q = pi


@functools.lru_cache(maxsize=4096)
def _angle_text(t: Tan) -> str:
    return ExactAngle.from_tangent(t).text


@dataclass(frozen=True)
class _Var:
    name: str     # t_q1, q4, L
    kind: str     # revolute, prismatic, parameter
    source: str   # the joint or parameter


class _Equations:
    """Component equations as polynomials in the free variables' charts.

    The ring has, per free revolute joint, ``t_<joint>`` and ``s_<joint>``; per free
    prismatic joint and parameter its name. Values fixed by the locus are substituted
    when the equations are read; an equation undefined at a fixed value (``t_q3`` with
    ``q3 = pi``) makes its component empty.
    """

    def __init__(self, model: Model, free: list[_Var], fixed: Mapping[str, object]):
        self.free = free
        names: list[str] = []
        self.role: list[tuple[int, str]] = []     # ring variable -> (free index, t|s|x)
        for i, v in enumerate(free):
            if v.kind == "revolute":
                names += [tangent_name(v.source), cotangent_name(v.source)]
                self.role += [(i, "t"), (i, "s")]
            else:
                names.append(v.name)
                self.role.append((i, "x"))
        self.names = names
        self.ctx = flint.fmpq_mpoly_ctx.get(tuple(names) or ("_",), "degrevlex")
        self.fixed = fixed                      # ring-less names -> Tan or Fraction
        self.symbols: dict[str, sp.Symbol] = {}
        for j in model.joints:
            if j.type == "revolute":
                self.symbols[tangent_name(j.name)] = sp.Symbol(tangent_name(j.name))
                self.symbols[cotangent_name(j.name)] = sp.Symbol(cotangent_name(j.name))
            else:
                self.symbols[j.name] = sp.Symbol(j.name)
        for p in model.parameters:
            self.symbols[p.name] = sp.Symbol(p.name)

    def polynomial(self, poly: NamedPolynomial, where: str
                   ) -> tuple[flint.fmpq_mpoly, list[int]] | None:
        """``(polynomial, ring variables used)`` of an equation of the locus (an exact
        polynomial over its variables), or None when it is undefined at the fixed
        values. Term by term: each monomial is put in the ring, or its fixed values
        substituted."""
        out = self.ctx.constant(0)
        for exps, c in poly.terms:
            factors = [to_sympy(c)]
            for name, e in zip(poly.variables, exps, strict=True):
                if name not in self.symbols:
                    raise VerifyError(f"{where}: {name} is neither a free variable of the "
                                      "locus nor a joint or parameter of the model")
                factors.append(self.symbols[name] ** e)
            converted = self._convert(sp.Mul(*factors), where)
            if converted is None:
                return None
            out += converted
        used = [k for k, d in enumerate(out.degrees()) if d] if self.names else []
        return out, used

    def _convert(self, expr: sp.Expr, where: str):
        syms = sorted(expr.free_symbols, key=lambda s: s.name)
        gens = self.ctx.gens()
        poly = sp.Poly(expr, *syms) if syms else None
        if poly is None:
            return self.ctx.constant(_fmpq(sp.Rational(expr)))
        out = self.ctx.constant(0)
        values = []
        for s in syms:
            if s.name in self.names:
                values.append(gens[self.names.index(s.name)])
                continue
            value = self._fixed_value(s.name, where)
            if value is None:
                return None
            values.append(self.ctx.constant(_fmpq(value)))
        for monom, c in poly.terms():
            term = self.ctx.constant(_fmpq(c))
            for v, e in zip(values, monom, strict=True):
                if e:
                    term *= v ** int(e)
            out += term
        return out

    def _fixed_value(self, name: str, where: str) -> Fraction | None:
        """The fixed value of a variable that is not free; None where undefined."""
        if name.startswith(("t_", "s_")) and name[2:] in self.fixed:
            t = self.fixed[name[2:]]
            if name[0] == "t":
                return t
            return None if t == 0 else (Fraction(0) if t is None else 1 / t)
        if name in self.fixed:
            return self.fixed[name]
        raise VerifyError(f"{where}: {name} is neither a free variable of the locus nor "
                          "fixed by it")

    def holds_at(self, eq, point: Sequence) -> bool:
        """Whether ``eq`` vanishes at a rational point (free values in order)."""
        poly, used = eq
        args = [flint.fmpq(0)] * len(self.names)
        for k in used:
            i, role = self.role[k]
            value = point[i]
            if role == "t":
                if value is None:
                    return False
                args[k] = _fmpq(value)
            elif role == "s":
                if value == 0:
                    return False
                args[k] = flint.fmpq(0) if value is None else _fmpq(1 / value)
            else:
                args[k] = _fmpq(value)
        if not self.names:
            return poly.is_zero()
        return poly(*args) == 0

    def on_line(self, eq, line: _Line) -> tuple[flint.fmpq_poly, list[flint.fmpq_poly]]:
        """``eq`` on a line: a polynomial in ``lam`` (the equation times powers of the
        coordinates that enter as reciprocals) and those coordinates, which must not
        vanish where the equation is to be defined."""
        poly, used = eq
        one = flint.fmpq_poly([1])
        parts: dict[int, tuple[flint.fmpq_poly, flint.fmpq_poly]] = {}
        for k in used:
            i, role = self.role[k]
            chart, c = line.coords[i]
            if role == "x" or (role == "t" and chart == "t") or (role == "s" and chart == "s"):
                parts[k] = (c, one)
            else:
                parts[k] = (one, c)
        degrees = poly.degrees() if self.names else ()
        total = flint.fmpq_poly([0])
        for monom, coef in poly.to_dict().items():
            term = flint.fmpq_poly([coef])
            for k in used:
                num, den = parts[k]
                e = monom[k]
                if e:
                    term *= num ** e
                if not den.is_one() and degrees[k] - e:
                    term *= den ** (degrees[k] - e)
            total += term
        dens = [den for num, den in parts.values() if not den.is_one()]
        return total, dens


def _fmpq(x) -> flint.fmpq:
    if not isinstance(x, Fraction | int):
        x = sp.Rational(x)
        return to_fmpq(x)
    x = Fraction(x)
    return flint.fmpq(x.numerator, x.denominator)


def _frac(x) -> Fraction:
    x = sp.Rational(x)
    return to_fraction(x)


@dataclass
class _Line:
    """``coords[i] = (chart, c(lam))``: chart ``t`` (``t = c``), ``s`` (``1/t = c``) or
    ``x`` (a displacement or parameter ``= c``)."""

    coords: list[tuple[str, flint.fmpq_poly]]
    domain: tuple[Fraction | None, Fraction | None]   # lam where the parameters are > 0

    def text(self, free: list[_Var]) -> dict[str, str]:
        out = {}
        for v, (chart, c) in zip(free, self.coords, strict=True):
            name = cotangent_name(v.source) if chart == "s" else v.name
            out[name] = _poly_text(c)
        return out

    def point(self, lam: Fraction) -> list:
        out = []
        for chart, c in self.coords:
            value = _eval_q(c, lam)
            if chart == "s":
                out.append(None if value == 0 else 1 / value)
            else:
                out.append(value)
        return out


def _eval_q(p: flint.fmpq_poly, x: Fraction) -> Fraction:
    acc = Fraction(0)
    for c in reversed(p.coeffs()):
        acc = acc * x + to_fraction(c)
    return acc


def _poly_text(p: flint.fmpq_poly, var: str = "lam") -> str:
    coeffs = [to_fraction(c) for c in p.coeffs()]
    x = sp.Symbol(var)
    return sp.sstr(sum((to_sympy(c) * x**i
                        for i, c in enumerate(coeffs)), sp.Integer(0)))
