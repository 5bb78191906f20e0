"""Subfields and products of number fields, exactly: the minimal polynomial of an
element, an element written in a basis, two elements whose fields make the whole one
(``Q(sqrt 2, sqrt 3)``), and the pairs of roots of two polynomials as one field per
orbit (``Q[w, z]/(h, g)`` split by the factors of a primitive element's minimal
polynomial). Checked on fields built by hand and on random pairs of quadratics and
cubics, every claim verified by substitution."""

from __future__ import annotations

import random

import flint
import pytest

from coopkin_sym.exact.subfields import (
    compositum,
    express,
    minimal_polynomial,
    product_generators,
)

X = flint.fmpq_poly([0, 1])
#: x = sqrt 2 + sqrt 3
QUARTIC = flint.fmpq_poly([1, 0, -10, 0, 1])
SQRT2 = (X**3 - 9 * X) / 2
SQRT3 = (11 * X - X**3) / 2


def _at(p: flint.fmpq_poly, e: flint.fmpq_poly, g: flint.fmpq_poly) -> flint.fmpq_poly:
    """``p(e)`` in ``Q[x]/(g)``."""
    out = flint.fmpq_poly([])
    for c in reversed(p.coeffs()):
        out = (out * e + c) % g
    return out


@pytest.mark.parametrize(("element", "expected"), [
    (SQRT2, "x^2 + (-2)"), (SQRT3, "x^2 + (-3)"), ((SQRT2 * SQRT3) % QUARTIC, "x^2 + (-6)"),
    (X, "x^4 + (-10)*x^2 + 1"), (flint.fmpq_poly([3]), "x + (-3)"),
    (SQRT2 + 1, "x^2 + (-2)*x + (-1)")])
def test_minimal_polynomials_in_a_biquadratic_field(element, expected):
    m = minimal_polynomial(QUARTIC, element)
    assert str(m) == expected
    assert _at(m, element, QUARTIC) == 0


def test_an_element_is_written_in_a_basis_exactly_when_it_lies_in_its_span():
    basis = [flint.fmpq_poly([1]), SQRT2]
    assert express(QUARTIC, basis, 3 * SQRT2 - flint.fmpq(1, 2)) == flint.fmpq_poly(
        [flint.fmpq(-1, 2), 3])
    assert express(QUARTIC, basis, SQRT3) is None
    assert express(QUARTIC, basis, flint.fmpq_poly([])) == flint.fmpq_poly([])


def test_two_coordinates_in_disjoint_fields_make_the_field():
    six = (SQRT2 * SQRT3) % QUARTIC
    i, j, mi, mj, rest = product_generators(QUARTIC, [SQRT2, SQRT3, six, SQRT2 + 7])
    assert (i, j, str(mi), str(mj)) == (0, 1, "x^2 + (-2)", "x^2 + (-3)")
    assert rest == [{(1, 1): 1}, {(0, 0): 7, (1, 0): 1}]
    # the same quadratic subfield twice, or a generator alone, is no product
    assert product_generators(QUARTIC, [SQRT2, 2 * SQRT2]) is None
    assert product_generators(QUARTIC, [X]) is None
    # a field of prime degree has no such pair
    cubic = flint.fmpq_poly([-2, 0, 0, 1])
    assert product_generators(cubic, [X, X**2 % cubic]) is None


def test_pairs_of_roots_of_two_fields_are_one_orbit_when_disjoint():
    c, m, w, (z,) = compositum(flint.fmpq_poly([-2, 0, 1]), flint.fmpq_poly([-3, 0, 1]),
                               [X])
    (factor, _e), = m.factor()[1]
    assert m.degree() == 4 and factor.degree() == 4
    assert (w * w) % m == 2 and (z * z) % m == 3
    assert (w + c * z) % m == X


def test_pairs_of_roots_of_the_same_field_split_into_orbits():
    """w^2 = 2 and z^2 = 2: the pairs (w, z) are w = z (two points) and w = -z (two
    points), one factor of the minimal polynomial each."""
    two = flint.fmpq_poly([-2, 0, 1])
    _c, m, w, (z,) = compositum(two, two, [X])
    factors = [f for f, _e in m.factor()[1]]
    assert sorted(f.degree() for f in factors) == [2, 2]
    relations = sorted(("w = z" if (w - z) % f == 0 else "w = -z" if (w + z) % f == 0
                        else "?") for f in factors)
    assert relations == ["w = -z", "w = z"]


def _irreducible(rng: random.Random, degree: int) -> flint.fmpq_poly:
    while True:
        p = flint.fmpz_poly([rng.randint(-6, 6) for _ in range(degree)] + [rng.randint(1, 3)])
        _, factors = p.factor()
        if len(factors) == 1 and factors[0][1] == 1 and p.degree() == degree:
            return flint.fmpq_poly(p)


@pytest.mark.parametrize("seed", range(40))
def test_orbits_of_random_pairs_hold_both_roots(seed):
    """For random irreducible h, g (degrees 2 or 3) and an element e of Q[z]/(g): in
    each orbit, h(w) = 0, g(z) = 0 and e is e(z); the orbits' degrees add up to
    deg h * deg g; theta = w + c z."""
    rng = random.Random(seed)
    h, g = _irreducible(rng, rng.choice((2, 3))), _irreducible(rng, rng.choice((2, 3)))
    e = flint.fmpq_poly([rng.randint(-5, 5) for _ in range(g.degree())])
    c, m, w, (z, e_theta) = compositum(h, g, [X, e])
    factors = [f for f, _e in m.factor()[1]]
    assert all(k == 1 for _f, k in m.factor()[1])
    assert sum(f.degree() for f in factors) == h.degree() * g.degree()
    for f in factors:
        assert _at(h, w % f, f) == 0
        assert _at(g, z % f, f) == 0
        assert (e_theta - _at(e, z % f, f)) % f == 0
        assert (w + c * z - X) % f == 0


def test_an_element_of_a_quadratic_subfield_reads_in_its_own_radicals():
    """At each real root of x^4 - 10 x^2 + 1 (+-sqrt 2 +- sqrt 3, in increasing
    order), sqrt 2 and sqrt 3 read with the right signs, sqrt 6 and the rationals too;
    an element of degree 4 has none."""
    import sympy as sp

    from coopkin_sym.exact.realroot import RealRoot, element_expression
    roots = RealRoot.all_of([1, 0, -10, 0, 1])
    signs = [(-1, -1), (1, -1), (-1, 1), (1, 1)]
    for root, (s2, s3) in zip(roots, signs, strict=True):
        assert element_expression(SQRT2, root) == s2 * sp.sqrt(2)
        assert element_expression(SQRT3 - 1, root) == s3 * sp.sqrt(3) - 1
        assert element_expression((SQRT2 * SQRT3) % QUARTIC, root) == s2 * s3 * sp.sqrt(6)
        assert root.in_subfield(flint.fmpq_poly([5])).expression() == 5
        assert root.in_subfield(X) is None
