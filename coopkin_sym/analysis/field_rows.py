"""The rows of ``Q`` at a configuration with irrational (algebraic) ``tan(q/2)``, over
the number field they generate (the part of :mod:`coopkin_sym.analysis.irrational`
that the finite mobility needs too: its seven numbers at such a point).

Example
-------
>>> from coopkin_sym.model.model import load_model
>>> r = field_rows(load_model("paper-case1-hard"), "q1=-pi/6,q2=pi/6,L=1")
>>> r.names, sp.sstr(r.minimal), numbers_at(r).Nh
(['q1', 'q2'], 'alpha**2 + 4*alpha + 1', 1)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import sympy as sp
from sympy.polys.numberfields.subfield import primitive_element

from coopkin_sym import limits
from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.decomposition import numbers_modulo
from coopkin_sym.analysis.numbers import Numbers
from coopkin_sym.errors import ArgumentError, NotIrrational
from coopkin_sym.exact.angles import tangent_name
from coopkin_sym.exact.parse import NumberError, algebraic_half_angle, parse_angle
from coopkin_sym.exact.quotient import Quotient
from coopkin_sym.exact.substitution import substitute_rows
from coopkin_sym.model.configuration import (
    Configuration,
    ConfigurationError,
    split_assignments,
)
from coopkin_sym.model.model import Model

_ALPHA = sp.Symbol("alpha")


@dataclass(frozen=True)
class FieldRows:
    """The rows of ``Q`` with the irrational values put in, modulo the minimal
    polynomial of ``alpha`` (``quotient``), and what they were made from.

    Example
    -------
    >>> from coopkin_sym.model.model import load_model
    >>> field_rows(load_model("paper-case1-hard"), "q1=-pi/6,q2=pi/6").alpha
    -2 + sqrt(3)
    """

    rational: list
    irrational: dict
    names: list
    kin: object
    rows: list
    quotient: Quotient
    minimal: sp.Expr
    alpha: sp.Expr
    model: Model


def irrational_values(model: Model, at) -> tuple[list[tuple[str, object]], dict[str, sp.Expr]]:
    """The ``--at`` items split into the rational ones and the revolute joints whose
    ``tan(q/2)`` is irrational but algebraic (joint -> exact tangent). Values that are
    neither (``q1=1``: ``tan(1/2)`` is transcendental) raise the usual error."""
    joints = {j.name: j for j in model.joints}
    rational, irrational = [], {}
    for name, value in split_assignments(at, "--at"):
        joint = joints.get(name)
        if joint is None or joint.type != "revolute" or isinstance(value, tuple):
            rational.append((name, value))
            continue
        text = value if not isinstance(value, sp.Basic) else sp.sstr(value)
        try:
            parse_angle(str(text), f"--at {name}")
            rational.append((name, value))
        except NumberError as exc:
            try:
                irrational[name] = algebraic_half_angle(str(text), f"--at {name}")
            except NumberError:
                raise ConfigurationError(str(exc)) from None
    return rational, irrational


def field_rows(model: Model, at) -> FieldRows:
    """The rows of ``Q`` of ``model`` at ``at`` over the number field of its
    irrational values. Raises :class:`NotIrrational` when every value is rational."""
    rational, irrational = irrational_values(model, at)
    if not irrational:
        raise NotIrrational("every value is rational")
    config = Configuration.parse(model, dict(rational), free=list(irrational))
    kin = kinematics.build(model, config)
    rows = [kin.ring.clear_row(r) for r in kin.Q]
    names = list(irrational)
    degree = 1
    for n in names:
        degree *= sp.degree(sp.minimal_polynomial(irrational[n], _ALPHA), _ALPHA)
    if degree > limits.MAX_FIELD_DEGREE:
        raise ConfigurationError(
            f"--at: the irrational values ({', '.join(names)}) may generate a number "
            f"field of degree up to {degree}, over the limit of {limits.MAX_FIELD_DEGREE}")
    minimal, coeffs, reps = primitive_element([irrational[n] for n in names], _ALPHA,
                                              ex=True)
    alpha = sp.radsimp(sum(c * irrational[n] for c, n in zip(coeffs, names, strict=True)))
    x = tangent_name(names[0])
    kx = kin.ring.names.index(x)
    coeffs_g = [sp.Rational(c) for c in sp.Poly(minimal, _ALPHA).all_coeffs()[::-1]]
    scale = sp.ilcm(*[c.q for c in coeffs_g])
    g = _in_slot(kin.ring.zctx, [c * scale for c in coeffs_g], kx)
    # alpha lives in the slot of the first irrational joint: that joint's own value goes
    # first, then the others (polynomials in alpha) are put in
    order = sorted(range(len(names)), key=lambda i: i != 0)
    for i in order:
        k = kin.ring.names.index(tangent_name(names[i]))
        rep = [sp.Rational(c) for c in reps[i]][::-1]
        den = sp.ilcm(*[c.q for c in rep]) if rep else 1
        num = _in_slot(kin.ring.zctx, [c * den for c in rep], kx)
        rows = substitute_rows(rows, k, -num, kin.ring.zctx.constant(int(den)))
    quotient = Quotient(g, kx)
    return FieldRows(rational, irrational, names, kin, rows, quotient, minimal, alpha, model)


def numbers_at(rows: FieldRows) -> Numbers:
    """The seven numbers there, exact at every conjugate point at once."""
    return numbers_modulo(rows.rows, rows.model, rows.kin.row_contacts, rows.quotient)


def _in_slot(zctx, coeffs: Sequence, k: int):
    """The integer polynomial ``sum c_i x_k^i`` (``coeffs`` lowest degree first)."""
    n = len(zctx.gens())
    terms = {}
    for i, c in enumerate(coeffs):
        c = sp.Rational(c)
        if c:
            if c.q != 1:
                raise ArgumentError("integer coefficients expected")
            mon = [0] * n
            mon[k] = i
            terms[tuple(mon)] = int(c)
    return zctx.from_dict(terms)


__all__ = ["FieldRows", "field_rows", "irrational_values", "numbers_at"]
