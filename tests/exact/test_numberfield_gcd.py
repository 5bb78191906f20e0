"""The gcd over ``Q(alpha)`` from images modulo primes equals Euclid's over the field:
random irreducible ``g`` (monic or not, with rational coefficients), random common
factors of degree 0 to 3, rational coefficients with large heights; and it gives the
work back (``None``) rather than a wrong answer when the primes do not suffice."""

from __future__ import annotations

import random

import flint
import pytest

from coopkin_sym.exact.numberfield import NumberField
from coopkin_sym.exact.numberfield_gcd import modular_gcd


def _irreducible(rng: random.Random) -> flint.fmpq_poly:
    while True:
        degree = rng.randint(1, 6)
        g = flint.fmpz_poly([rng.randint(-9, 9) for _ in range(degree)] + [rng.randint(1, 5)])
        _, factors = g.factor()
        if len(factors) == 1 and factors[0][1] == 1 and g.degree() == degree:
            return flint.fmpq_poly(g) / rng.randint(1, 7)


def _element(rng: random.Random, field: NumberField, height: int) -> flint.fmpq_poly:
    degree = field.g.degree()
    return field.element(flint.fmpq_poly(
        [flint.fmpq(rng.randint(-height, height), rng.randint(1, height))
         for _ in range(degree)]))


def _poly(rng, field, degree, height):
    out = [_element(rng, field, height) for _ in range(degree)]
    lead = flint.fmpq_poly(0)
    while lead.is_zero():
        lead = _element(rng, field, height)
    return [*out, lead]


def _mul(field, a, b):
    out = [flint.fmpq_poly(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] = field.element(out[i + j] + x * y)
    return out


def _euclid(field: NumberField, polys):
    g = []
    for p in polys:
        b = field._trim(p)
        while b:
            g, b = b, (field._rem(g, b) if g else [])
    inv = field.inverse(g[-1])
    return [field.element(c * inv) for c in g]


@pytest.mark.parametrize("seed", range(40))
def test_the_modular_gcd_is_euclids(seed):
    rng = random.Random(seed)
    field = NumberField(_irreducible(rng))
    common = _poly(rng, field, rng.randint(0, 3), 10**rng.randint(1, 30))
    polys = [_mul(field, common, _poly(rng, field, rng.randint(1, 6), 50))
             for _ in range(rng.randint(2, 4))]
    got = modular_gcd(field.g, polys)
    assert got == _euclid(field, polys)
    assert got[-1] == 1 and len(got) >= len(common)
    assert field.gcd(polys) == got                     # the facade takes this path


def test_a_common_factor_with_huge_coefficients_is_lifted_over_many_primes():
    rng = random.Random(5)
    field = NumberField(flint.fmpq_poly([-5, 0, 0, 1]))          # 5^(1/3)
    x = flint.fmpq_poly([0, 1])
    common = [field.element(flint.fmpq(3**200, 7**150) * x**2 - x + flint.fmpq(1, 11**90)),
              flint.fmpq_poly(1)]                                # y + c, c ~ 900 bits
    polys = [_mul(field, common, _poly(rng, field, 3, 9)) for _ in range(2)]
    assert modular_gcd(field.g, polys) == common


def test_too_few_primes_give_the_work_back_not_a_guess():
    rng = random.Random(1)
    field = NumberField(flint.fmpq_poly([-2, 0, 1]))
    common = [field.element(flint.fmpq_poly([flint.fmpq(10**80 + 7, 3**60), 1])),
              flint.fmpq_poly(1)]
    polys = [_mul(field, common, _poly(rng, field, 2, 9)) for _ in range(2)]
    assert modular_gcd(field.g, polys, max_primes=3) is None
    assert field.gcd(polys) == common                   # Euclid then


def test_coprime_polynomials_are_proved_coprime_by_one_prime():
    field = NumberField(flint.fmpq_poly([1, 0, 1]))              # Q(i)
    x = flint.fmpq_poly([0, 1])
    # y^2 + 1 = (y - i)(y + i) and y - 2i share nothing
    assert modular_gcd(field.g, [[1, 0, 1], [-2 * x, 1]], max_primes=1) == [1]
    # with y - i they share y - i
    assert modular_gcd(field.g, [[1, 0, 1], [-x, 1]]) == [-x, 1]


@pytest.mark.parametrize("seed", range(40))
def test_a_change_of_generator_keeps_every_element(seed):
    """``change_generator``: the minimal polynomial it gives vanishes at ``t`` in
    ``Q[x]/(g)`` and has the degree of ``g``, every element written in ``t`` equals
    itself there; a ``t`` of a proper subfield (a rational, or ``u^2`` where
    ``g(x) = h(x^2)``) gives None."""
    from coopkin_sym.exact.numberfield import change_generator
    rng = random.Random(seed)
    g = _irreducible(rng)
    field = NumberField(g)
    t = _element(rng, field, 9)
    elements = [_element(rng, field, 20) for _ in range(3)]
    changed = change_generator(g, t, elements)
    d = g.degree()
    if changed is None:
        # then t lies in a proper subfield: its powers up to d - 1 are dependent
        powers = [flint.fmpq_poly([1])]
        for _ in range(d - 1):
            powers.append((powers[-1] * t) % g)
        assert flint.fmpq_mat(d, d, [p[i] for p in powers for i in range(d)]).rank() < d
        return
    minimal, written = changed
    assert minimal.degree() == d and minimal(t) % g == 0
    for e, w in zip(elements, written, strict=True):
        assert w.degree() < d and (w(t) - e) % g == 0
    assert change_generator(g, flint.fmpq_poly([flint.fmpq(3, 7)]), elements) is None \
        or d == 1


def test_a_generator_of_a_subfield_gives_none():
    from coopkin_sym.exact.numberfield import change_generator
    g = flint.fmpq_poly([1, 0, -10, 0, 1])          # sqrt(2) + sqrt(3)
    x = flint.fmpq_poly([0, 1])
    assert change_generator(g, x * x, [x]) is None  # x^2 = 5 + 2 sqrt(6)
    minimal, (back,) = change_generator(g, x + 1, [x])
    assert minimal == g(x - 1) and back == x - 1
