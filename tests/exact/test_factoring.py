"""Factorization over Z: the kept factorizations of large polynomials are those of
equal polynomials only."""

from __future__ import annotations

import flint

from coopkin_sym.exact import factoring


def _product(content, factors, ctx):
    out = ctx.constant(content)
    for f, e in factors:
        out = out * f**e
    return out


def test_a_large_polynomial_met_again_gets_its_factorization_again(monkeypatch):
    monkeypatch.setattr(factoring, "KEEP_TERMS", 10)
    monkeypatch.setattr(factoring, "_kept", [])
    ctx = flint.fmpz_mpoly_ctx.get(("x", "y", "z"), "degrevlex")
    x, y, z = ctx.gens()
    p = 6 * (x + y + z + 1) ** 3 * (x * y - z + 2) ** 2
    first = factoring.factor(p)
    assert len(factoring._kept) == 1
    again = factoring.factor(p * 1)
    assert again == first and _product(*again, ctx) in (p, -p)
    # a different polynomial of the same size, and the same one in another ring
    q = 6 * (x - y + z + 1) ** 3 * (x * y + z + 2) ** 2
    assert len(q) == len(p)
    cq = factoring.factor(q)
    assert _product(*cq, ctx) in (q, -q) and cq != first
    other = flint.fmpz_mpoly_ctx.get(("x", "y", "w"), "degrevlex")
    a, b, w = other.gens()
    po = 6 * (a + b + w + 1) ** 3 * (a * b - w + 2) ** 2
    co = factoring.factor(po)
    assert all(f.context() is other for f, _ in co[1])


def test_only_the_last_few_are_kept(monkeypatch):
    monkeypatch.setattr(factoring, "KEEP_TERMS", 1)
    monkeypatch.setattr(factoring, "_kept", [])
    ctx = flint.fmpz_mpoly_ctx.get(("x",), "degrevlex")
    (x,) = ctx.gens()
    for k in range(factoring.KEPT + 5):
        factoring.factor(x**2 - k**2)
    assert len(factoring._kept) == factoring.KEPT
    assert factoring._kept[0][0] == x**2 - (factoring.KEPT + 4) ** 2
