"""Size estimates before the flint calls that cannot be interrupted, and the split of a
polynomial into its coefficients in one variable that the reductions modulo a
polynomial use: each against the operation itself (the estimates are upper bounds of
what it makes), on random polynomials."""

from __future__ import annotations

import random

import flint
import pytest
import sympy as sp

from coopkin_sym.exact.elimination import determinant
from coopkin_sym.exact.quotient import Quotient
from coopkin_sym.exact.sizes import determinant_terms, resultant_terms, terms_bound
from coopkin_sym.exact.substitution import coefficients_in

CTX = flint.fmpz_mpoly_ctx.get(("a", "b", "x"), "degrevlex")
A, B, X = CTX.gens()


def _random(rng: random.Random, terms: int, degrees=(3, 3, 3)):
    out = CTX.constant(0)
    for _ in range(terms):
        mono = CTX.constant(rng.randint(-9, 9))
        for g, d in zip((A, B, X), degrees, strict=True):
            mono *= g ** rng.randint(0, d)
        out += mono
    return out


def test_the_bound_of_terms_is_exact_for_dense_polynomials():
    assert terms_bound([2, 3], 5) == 12            # 3 * 4 monomials, all of degree <= 5
    assert terms_bound([2, 3], 2) == 6             # degree <= 2 in two variables: C(4, 2)
    assert terms_bound([0, 0], 7) == 1 and terms_bound([], 0) == 1


@pytest.mark.parametrize("seed", range(12))
def test_a_resultant_has_at_most_the_terms_estimated(seed):
    rng = random.Random(seed)
    p = _random(rng, rng.randint(3, 25), (rng.randint(1, 4), rng.randint(1, 4), 3))
    q = _random(rng, rng.randint(3, 25), (rng.randint(1, 4), rng.randint(1, 4), 2))
    if p.degrees()[2] == 0 or q.degrees()[2] == 0:
        return
    res = p.resultant(q, "x")
    assert len(res) <= resultant_terms(p, q, 2)
    # the degree bounds behind it, one variable at a time and in total
    m, n = p.degrees()[2], q.degrees()[2]
    for i in (0, 1):
        assert res.degrees()[i] <= n * p.degrees()[i] + m * q.degrees()[i]
    assert res.total_degree() <= n * p.total_degree() + m * q.total_degree()


@pytest.mark.parametrize("seed", range(8))
def test_a_determinant_has_at_most_the_terms_estimated(seed):
    rng = random.Random(100 + seed)
    size = rng.randint(2, 4)
    m = [[_random(rng, rng.randint(0, 4), (2, 2, 1)) for _ in range(size)]
         for _ in range(size)]
    det = determinant(m)
    if any(all(e.is_zero() for e in row) for row in m):
        assert determinant_terms(m) == 0 and det.is_zero()
    else:
        assert len(det) <= determinant_terms(m)


SYMBOLS = sp.symbols("a b x")


def _sympy(p) -> sp.Expr:
    return sp.Add(*(int(c) * sp.Mul(*(s ** int(e) for s, e in zip(SYMBOLS, m, strict=True)))
                    for m, c in p.to_dict().items()))


@pytest.mark.parametrize("seed", range(10))
def test_the_coefficients_in_one_variable_are_those_of_sympy(seed):
    rng = random.Random(200 + seed)
    p = _random(rng, rng.randint(1, 30))
    expr = _sympy(p)
    for k, var in enumerate(SYMBOLS):
        got = coefficients_in(p, k)
        want = sp.Poly(expr, var).all_coeffs()[::-1] if not p.is_zero() else []
        assert len(got) == len(want)
        for g, w in zip(got, want, strict=True):
            assert sp.expand(_sympy(g) - w) == 0


@pytest.mark.parametrize("seed", range(10))
def test_a_reduction_is_a_multiple_of_the_polynomial_away_from_it(seed):
    """``reduce(p)`` has degree below ``deg_x f`` and ``lead^n p - reduce(p)`` is a
    multiple of ``f`` (checked by exact division), ``lead`` the leading coefficient of
    ``f`` in ``x``."""
    rng = random.Random(300 + seed)
    f = _random(rng, rng.randint(2, 8), (2, 2, 2)) + X ** 3 * (A + 2)
    p = _random(rng, rng.randint(1, 30), (3, 3, 7))
    quotient = Quotient(f, 2)
    reduced, n = quotient._reduce_counted(p)
    assert reduced.is_zero() or reduced.degrees()[2] < 3
    rest = quotient.lead ** n * p - reduced
    assert rest.is_zero() or (rest / f) * f == rest
