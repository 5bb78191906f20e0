"""Angles of algebraic tangents: rational multiples of pi recognized by arithmetic.

``RealRoot.angle_at`` decides whether ``2 atan(t)``, ``t`` in ``Q(root)``, is ``k pi/n``
from the minimal polynomial of ``2 cos q`` and rational intervals, without SymPy's
simplification. Checked here against SymPy's own minimal polynomials of
``tan(k pi/(2n))`` (every real root of each is some ``tan(j pi/(2n))``), and on
elements of a field other than its generator.
"""

from __future__ import annotations

import math
from fractions import Fraction
from math import gcd

import flint
import pytest
import sympy as sp

from coopkin_sym.exact.angles import algebraic_angle
from coopkin_sym.exact.numberfield import NumberField
from coopkin_sym.exact.realroot import RealRoot, element_expression

T = sp.Symbol("t")
X = flint.fmpq_poly([0, 1])


def _roots_of_tangent(k: int, n: int) -> tuple[list[RealRoot], RealRoot]:
    """The real roots of the minimal polynomial (SymPy's) of ``tan(k pi/(2n))``, and
    the one that is it."""
    tangent = sp.tan(sp.pi * k / (2 * n))
    poly = sp.Poly(sp.minimal_polynomial(tangent, T), T)
    roots = RealRoot.all_of([int(c) for c in reversed(poly.all_coeffs())])
    (it,) = [r for r in roots if r.contains(tangent)]
    return roots, it


@pytest.mark.parametrize("n", [*range(2, 11), 12])
def test_every_angle_k_pi_over_n_is_recognised(n):
    for k in range(1 - n, n):
        if k == 0 or gcd(k, n) != 1:
            continue
        roots, it = _roots_of_tangent(k, n)
        assert it.angle() == sp.pi * sp.Rational(k, n)
        assert it.pi_multiple(X) == Fraction(k, n)
        for r in roots:  # the conjugates are angles too, each the right one
            ratio = r.pi_multiple(X)
            assert ratio is not None
            assert math.isclose(math.tan(math.pi * ratio / 2), float(r), rel_tol=1e-9,
                                abs_tol=1e-12)


def test_rational_tangents():
    root = RealRoot.all_of([-2, 0, 1])[1]
    assert [root.pi_multiple(Fraction(t)) for t in (0, 1, -1)] == \
        [0, Fraction(1, 2), Fraction(-1, 2)]
    assert root.pi_multiple(Fraction(1, 2)) is None
    assert root.angle_at(Fraction(-1)) == -sp.pi / 2
    assert root.angle_at(Fraction(1, 3)) == 2 * sp.atan(sp.Rational(1, 3))


def test_elements_of_q_sqrt2():
    root = RealRoot.all_of([-2, 0, 1])[1]  # sqrt(2)
    assert root.angle_at(X - 1) == sp.pi / 4                     # tan(pi/8)
    assert root.angle_at(X + 1) == 3 * sp.pi / 4                 # tan(3 pi/8)
    assert root.angle_at(-X - 1) == -3 * sp.pi / 4
    assert root.angle_at(X) == 2 * sp.atan(sp.sqrt(2))           # cos q = -1/3
    assert root.angle_at(X * X * X - 3) == 2 * sp.atan(2 * sp.sqrt(2) - 3)  # reduced
    assert root.angle_at(X / 2) == 2 * sp.atan(sp.sqrt(2) / 2)


def test_an_element_of_a_larger_field():
    """In Q(tan(pi/16)), 2 alpha/(1 - alpha^2) is tan(pi/8): the angle pi/4."""
    _, root = _roots_of_tangent(1, 8)
    field = NumberField(flint.fmpq_poly(list(root.coeffs)))
    double = field.element(2 * X * field.inverse(1 - X * X))
    assert root.pi_multiple(double) == Fraction(1, 4)
    assert root.pi_multiple(-double) == Fraction(-1, 4)
    assert root.pi_multiple(field.element(X + 1)) is None
    assert root.angle() == sp.pi / 8


def test_a_near_miss_is_left_as_atan():
    """1 + sqrt(2) is tan(3 pi/8); a tangent 1e-12 away is no multiple of pi."""
    tangent = sp.sqrt(2) + 1
    assert algebraic_angle(tangent) == 3 * sp.pi / 4
    assert algebraic_angle(tangent + sp.Rational(1, 10**12)) == \
        2 * sp.atan(tangent + sp.Rational(1, 10**12))


def test_element_expression_keeps_the_root_itself():
    root = RealRoot.all_of([1, -3, 0, 1])[0]
    assert element_expression(X, root) == root.expression()
    assert element_expression(Fraction(2, 3), root) == sp.Rational(2, 3)
