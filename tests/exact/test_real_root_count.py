"""Counting the distinct real roots of a polynomial over Q: flint's certified isolation
of the complex roots (above degree 4) against Sturm's theorem, on random polynomials
with repeated, clustered and conjugate roots."""

from __future__ import annotations

import random

import flint

from coopkin_sym.exact.realroot import STURM_DEGREE, real_root_count, sturm_real_root_count


def _from_roots(real: list[int], pairs: list[tuple[int, int]], den: int):
    """The product of ``den x - r`` and of ``x^2 - 2 a x + a^2 + b^2`` (roots a +- b i)."""
    p = flint.fmpq_poly([1])
    for r in real:
        p *= flint.fmpq_poly([-r, den])
    for a, b in pairs:
        p *= flint.fmpq_poly([a * a + b * b, -2 * a, 1])
    return p


def test_isolation_agrees_with_sturm_on_random_polynomials():
    rng = random.Random(11)
    for _ in range(60):
        real = [rng.randint(-20, 20) for _ in range(rng.randint(0, 7))]
        real += real[: rng.randint(0, 2)]                       # repeated roots
        pairs = [(rng.randint(-5, 5), rng.randint(1, 4)) for _ in range(rng.randint(0, 3))]
        p = _from_roots(real, pairs, rng.randint(1, 9)) * rng.randint(1, 5)
        if p.degree() <= STURM_DEGREE:
            continue
        assert real_root_count(p) == sturm_real_root_count(p) == len(set(real))


def test_close_roots_and_large_coefficients():
    # two roots 1e-30 apart, and a root pair just off the real line
    eps = 10**30
    p = flint.fmpq_poly([-eps, eps]) * flint.fmpq_poly([-(eps + 1), eps])     # x = 1, 1 + 1e-30
    p *= flint.fmpq_poly([flint.fmpq(1) + flint.fmpq(1, 10**40),
                          -2, 1])                                             # 1 +- 1e-20 i
    p *= flint.fmpq_poly([5, 0, 0, 1])                                        # one more real
    assert real_root_count(p) == sturm_real_root_count(p) == 3
    rng = random.Random(3)
    q = flint.fmpq_poly([rng.randint(-10**20, 10**20) for _ in range(41)])
    assert real_root_count(q) == sturm_real_root_count(q)


def test_radical_normal_is_radsimp_of_expand():
    import sympy as sp

    from coopkin_sym.exact.realroot import radical_normal
    rng = random.Random(3)
    r2, r5 = sp.sqrt(2), sp.sqrt(5)
    cases = [(1 + r2) ** 2, 1 / (1 + r2), (r5 - 1) / 2 * (r5 + 1) / 2, r2 * sp.sqrt(3),
             sp.Rational(3, 7), sp.Integer(0), (2 + r5) / (3 - r5), sp.I * r2 + 1]
    for _ in range(60):
        a, b = (sp.Rational(rng.randint(-9, 9), rng.randint(1, 9)) for _ in range(2))
        root = sp.sqrt(rng.choice([2, 3, 5, 7, 13]))
        cases.append((a + b * root) ** rng.randint(1, 3) * rng.choice([1, root, 1 + root]))
    for e in cases:
        assert radical_normal(e) == sp.radsimp(sp.expand(e)), e
