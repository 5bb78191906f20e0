"""Configurations over a number field: joints whose ``tan(q/2)`` is irrational.

An angle such as ``q1 = pi/3`` has ``tan(q/2) = sqrt(3)/3``. As in
:mod:`coopkin_sym.analysis.irrational`, one algebraic number ``alpha`` generates all
those values (a primitive element, found by SymPy), each ``tan(q/2)`` a polynomial in
it; ``cos q`` and ``sin q`` are then elements of ``Q(alpha)``, computed modulo its
minimal polynomial. The real embedding of ``alpha`` (which root it is) is an isolating
interval with rational ends (:class:`~coopkin_sym.exact.realroot.RealRoot`), so every
sign the finite mobility needs is decided exactly
(:class:`~coopkin_sym.exact.numberfield.RealNumberField`).

Example
-------
>>> from coopkin_sym.model.model import load_model
>>> config, point = algebraic_point(load_model("paper-case1-planar"), "q1=pi/3,q2=0,L=1")
>>> point.minimal_polynomial, point.alpha, sorted(point.cos_sin)
('3*alpha**2 - 1', 'sqrt(3)/3', ['q1'])
>>> [str(x) for x in point.cos_sin["q1"]]
['1/2', '3/2*x']
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import flint
import sympy as sp
from sympy.polys.numberfields.subfield import primitive_element

from coopkin_sym import limits
from coopkin_sym.exact.numberfield import RealNumberField
from coopkin_sym.exact.realroot import RealRoot
from coopkin_sym.model.configuration import Configuration, ConfigurationError
from coopkin_sym.model.model import Model

_ALPHA = sp.Symbol("alpha")


@dataclass(frozen=True)
class AlgebraicPoint:
    """The joints of a configuration with an irrational ``tan(q/2)``: ``cos_sin``
    (joint -> ``(cos q, sin q)`` as ``fmpq_poly`` in ``alpha``, modulo its minimal
    polynomial), the field with its real embedding, ``alpha`` and its minimal
    polynomial as text, each ``tan(q/2)`` (``tangents``), and the assignments as given
    (``at``: name -> text).

    Example
    -------
    >>> from coopkin_sym.model.model import load_model
    >>> _, point = algebraic_point(load_model("four-bar"), "q1=pi/4,q2=0")
    >>> point.as_json()["minimal_polynomial"], point.tangents
    ('alpha**2 + 2*alpha - 1', {'q1': '-1 + sqrt(2)'})
    """

    field: RealNumberField
    cos_sin: dict
    alpha: str
    minimal_polynomial: str
    tangents: dict
    at: dict = field(default_factory=dict)

    def with_parameter(self, name: str, value: str) -> AlgebraicPoint:
        """The same point with the parameter ``name`` set in :attr:`at`."""
        return replace(self, at={**self.at, name: value})

    def as_json(self) -> dict:
        """The field, as the ``field`` of an irrational analysis's JSON."""
        return {"alpha": self.alpha, "minimal_polynomial": self.minimal_polynomial,
                "tangents": dict(self.tangents)}


def _fmpq_poly(coeffs) -> flint.fmpq_poly:
    return flint.fmpq_poly([flint.fmpq(int(sp.Rational(c).p), int(sp.Rational(c).q))
                            for c in coeffs])


def algebraic_point(model: Model, at) -> tuple[Configuration, AlgebraicPoint] | None:
    """The configuration ``at`` (``--at`` text or mapping) with its joints of
    irrational ``tan(q/2)`` left free, and their values over the number field
    (:class:`AlgebraicPoint`); None when every value is rational."""
    from coopkin_sym.analysis.field_rows import irrational_values
    from coopkin_sym.model.configuration import split_assignments

    if isinstance(at, Configuration) or at is None:
        return None
    rational, irrational = irrational_values(model, at)
    if not irrational:
        return None
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
    poly = sp.Poly(minimal, _ALPHA)
    ints = [int(c) for c in poly.all_coeffs()[::-1]]
    g = flint.fmpq_poly(ints)
    (root,) = [r for r in RealRoot.all_of(ints) if r.contains(alpha)]
    k = RealNumberField(g, root, alpha)
    cos_sin = {}
    for n, rep in zip(names, reps, strict=True):
        t = k.element(_fmpq_poly([sp.Rational(c) for c in rep][::-1]))
        inv = k.inverse(k.element(1 + t * t))
        cos_sin[n] = (k.element((1 - t * t) * inv), k.element(2 * t * inv))
    config = Configuration.parse(model, dict(rational), free=names)
    given = {name: value if isinstance(value, str) else sp.sstr(value)
             for name, value in split_assignments(at, "--at")}
    point = AlgebraicPoint(k, cos_sin, sp.sstr(alpha), sp.sstr(minimal),
                           {n: sp.sstr(irrational[n]) for n in names}, given)
    return config, point
