"""The Z pre-test of the rational points of a curved family: a specialization has a
rational root exactly when SymPy finds one."""

from fractions import Fraction

import flint
import sympy as sp

from coopkin_sym.analysis.locus.algebra import _has_rational_root, _specialized


def test_specialization_over_z_has_a_rational_root_exactly_when_sympy_finds_one():
    ctx = flint.fmpz_mpoly_ctx.get(("x", "y", "z"), "lex")
    x, y, z = ctx.gens()
    f = 4 * x**3 * y - x * z + 3 * x**2 * z**2 - y * z
    X, Y, Z = sp.symbols("x y z")
    expr = 4 * X**3 * Y - X * Z + 3 * X**2 * Z**2 - Y * Z
    seen = set()
    terms = list(f.to_dict().items())
    values = [Fraction(1, 2), Fraction(2), Fraction(-1, 3), Fraction(0), Fraction(-5, 3)]
    for vy in values:
        for vz in values:
            uni = _specialized(terms, 0, [1, 2], f.degrees(), (vy, vz))
            sym = sp.Poly(expr.subs({Y: sp.Rational(vy.numerator, vy.denominator),
                                     Z: sp.Rational(vz.numerator, vz.denominator)}), X)
            if sym.degree() <= 0:
                assert uni.degree() <= 0
                continue
            assert uni.degree() == sym.degree()
            found = [r for r in sp.roots(sym, filter="Q") if r.is_Rational]
            assert _has_rational_root(uni) == bool(found)
            seen.add(bool(found))
    assert seen == {True, False}
