"""Substituting ``x_k = -f0/f1`` with denominators cleared: the shared powers give
the same polynomials as the definition, row by row and entry by entry."""

from __future__ import annotations

import random

import flint
import sympy as sp

from coopkin_sym.exact.substitution import Powers, common_part, substitute, substitute_rows

CTX = flint.fmpz_mpoly_ctx.get(("x", "y", "z"), "degrevlex")


def _random_poly(rng: random.Random, terms: int, degree: int):
    return CTX.from_dict({tuple(rng.randint(0, degree) for _ in range(3)):
                          rng.randint(-9, 9) for _ in range(terms)})


def _by_definition(p, k: int, f0, f1, deg: int):
    """``p(x_k = -f0/f1) f1^deg`` through SymPy's rational functions."""
    x = sp.symbols("x y z")
    expr = sp.sympify(str(p).replace("^", "**"), locals=dict(zip("xyz", x, strict=True)))
    num = sp.sympify(str(f0).replace("^", "**"), locals=dict(zip("xyz", x, strict=True)))
    den = sp.sympify(str(f1).replace("^", "**"), locals=dict(zip("xyz", x, strict=True)))
    return sp.expand(sp.cancel(expr.subs(x[k], -num / den) * den**deg))


def test_shared_powers_give_the_definition():
    rng = random.Random(7)
    for _ in range(12):
        k = rng.randrange(3)
        f0, f1 = _random_poly(rng, 3, 2), _random_poly(rng, 2, 1)
        if f1.is_zero():
            continue
        powers = Powers(f0, f1)
        for _ in range(3):
            p = _random_poly(rng, 5, 3)
            deg = int(p.degrees()[k]) + rng.randint(0, 2)
            once = substitute(p, k, f0, f1, deg)
            assert once == substitute(p, k, f0, f1, deg, powers)    # the table reused
            got = sp.sympify(str(once).replace("^", "**"),
                             locals=dict(zip("xyz", sp.symbols("x y z"), strict=True)))
            assert sp.expand(got - _by_definition(p, k, f0, f1, deg)) == 0


def test_rows_are_cleared_by_the_power_of_their_highest_degree():
    x, y, z = CTX.gens()
    rows = [[x**2 + y, x * z, CTX.constant(0)], [y, z, CTX.constant(3)]]
    out = substitute_rows(rows, 0, -y, z + 1)         # x = y / (z + 1)
    # row 1 times (z + 1)^2; row 2 has no x and stays as it is
    assert out[0] == [y**2 + y * (z + 1)**2, y * z * (z + 1), CTX.constant(0)]
    assert out[1] == rows[1]
    assert Powers(-y, z + 1).term(2, 3) == y**2 * (z + 1)


def test_the_part_of_a_content_dividing_a_power_is_the_gcd_with_that_power():
    rng = random.Random(5)
    x, y, z = CTX.gens()
    factors = [x + 1, y - 2 * z, x * y + 3, CTX.constant(2), z]
    for _ in range(40):
        f1 = CTX.constant(1)
        content = CTX.constant(rng.choice([1, 3, 4]))
        for f in factors:
            f1 *= f ** rng.randint(0, 2)
            content *= f ** rng.randint(0, 4)
        content *= _random_poly(rng, 2, 1) if rng.random() < 0.5 else 1
        if f1.is_constant() or content.is_zero():
            continue
        deg = rng.randint(1, 3)
        assert common_part([content], f1, deg) == content.gcd(f1 ** deg)


def test_the_common_part_of_a_row_is_that_of_its_content_never_a_gcd_of_two_entries():
    """Over several entries, the part of their content that divides ``f1^deg`` is the
    gcd of all of them with ``f1^deg`` (their integer content for a constant ``f1``),
    found with gcds that each have ``f1`` or a factor of it on one side."""
    rng = random.Random(11)
    x, y, z = CTX.gens()
    factors = [x + 1, y - 2 * z, x * y + 3, z]
    for _ in range(40):
        f1 = CTX.constant(rng.choice([1, 2]))
        for f in factors:
            f1 *= f ** rng.randint(0, 2)
        shared = CTX.constant(rng.choice([1, 6]))
        for f in factors:
            shared *= f ** rng.randint(0, 3)
        entries = [shared * _random_poly(rng, 2, 1) for _ in range(rng.randint(1, 4))]
        entries = [e for e in entries if not e.is_zero()]
        if not entries:
            continue
        deg = rng.randint(1, 3)
        content = entries[0]
        for e in entries[1:]:
            content = content.gcd(e)
        expected = (CTX.constant(content.content()) if f1.is_constant()
                    else content.gcd(f1 ** deg))
        assert common_part(entries, f1, deg) == expected
