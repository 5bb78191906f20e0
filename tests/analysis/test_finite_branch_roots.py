"""Branches along irrational roots of a binary form (two first-order motions, a lowest
form of degree three or more): each branch's tangent exactly, as a real algebraic
number (minimal polynomial over Q and an isolating interval) and a velocity linear in
it, over Q and over a number field; checked by hand, by exact root counts and by the
independent mpmath sampler."""

from __future__ import annotations

import json
import random
import sys
from fractions import Fraction
from pathlib import Path

import flint
import mpmath as mp
import pytest
import sympy as sp
from typer.testing import CliRunner

from coopkin_sym import load
from coopkin_sym.analysis.finite.forms import field_directions, real_directions
from coopkin_sym.cli import app
from coopkin_sym.exact.field_roots import real_root_count, real_roots
from coopkin_sym.exact.numberfield import RealNumberField
from coopkin_sym.exact.realroot import RealRoot
from coopkin_sym.present.finite import finite_json, finite_latex, finite_lines

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from finite_sampler import Sampler  # noqa: E402

S = sp.Symbol("s")
R = sp.Rational
CUBIC = 14739 * S**3 - 21675 * S**2 + 4403 * S + 1169
# the branch velocity (u, qdot) with s = u_q4/u_q7 along it (joints q1..q7)
TANGENT = (0, 0, R(-70, 17), 0, R(-14, 17), 0, S - R(7, 17), 2 * S - R(14, 17),
           S - R(7, 17), 2 * S, R(26, 17), R(10, 17), 2)


def _field(g: list[int], index: int) -> RealNumberField:
    return RealNumberField(flint.fmpq_poly(g), RealRoot.all_of(g)[index])


def _isolates(poly: sp.Expr, lo: Fraction, hi: Fraction) -> bool:
    """Exactly one root of ``poly`` in ``(lo, hi]`` (SymPy's exact count)."""
    p = sp.Poly(poly, S)
    return p.count_roots(sp.Rational(lo.numerator, lo.denominator),
                         sp.Rational(hi.numerator, hi.denominator)) == 1 and \
        p.eval(sp.Rational(lo.numerator, lo.denominator)) != 0


def _check_seven_r(fm) -> None:
    assert (fm.dimension, fm.bounds, fm.first_order) == (1, (1, 1), 2)
    assert (fm.classification, fm.reason) == ("bifurcation", "binary_form_roots")
    assert fm.orders == ((1, 2), (2, 2), (3, 1))
    assert len(fm.branches) == 3
    intervals = []
    for branch in fm.branches:
        d = branch.direction
        assert d.free == ("u_q4", "u_q7") and branch.dimension == 1
        assert sp.expand(d.polynomial - CUBIC) == 0
        assert d.tangent == tuple(sp.sympify(x) for x in TANGENT)
        assert _isolates(CUBIC, *d.interval)
        assert d.interval[1] - d.interval[0] <= Fraction(1, 1000)
        intervals.append(d.interval)
        # the exact tangent is the velocity at the root (a CRootOf of the cubic)
        (v,) = branch.tangent
        assert [sp.expand(a - b.subs(S, d.root.expression())) for a, b in
                zip(v, d.tangent, strict=True)] == [0] * 13
    assert all(a[1] < b[0] for a, b in zip(intervals, intervals[1:], strict=False))


def test_three_branches_cross_along_the_roots_of_an_irreducible_cubic():
    """seven-r-loop at home: the second-order constraint vanishes, the third-order one
    is the irreducible cubic of the file's header, with three simple real roots."""
    system = load("seven-r-loop")
    fm = system.finite_mobility()
    _check_seven_r(fm)
    (equation,) = fm.equations
    u4, u7 = sp.symbols("u_q4 u_q7")
    # the reduced constraint's lowest form is the cubic, homogenized in u_q4/u_q7
    assert sp.factor(sp.sympify(equation.replace("^", "**")).subs(u7, 1)) == \
        sp.factor(sp.Rational(6, 5) * CUBIC.subs(S, u4) / 14739)
    assert sp.Poly(CUBIC, S).is_irreducible
    assert sp.Poly(CUBIC, S).count_roots() == 3
    q = system.analyze().Q
    for branch in fm.branches:                        # Q v(s) = 0 for every s
        assert sp.expand(q * sp.Matrix(branch.direction.tangent)) == sp.zeros(12, 1)


def test_the_same_loop_over_a_number_field_gives_the_same_branches():
    """Turning the last joint of an arm only welds the object elsewhere on its link:
    the loop is the same, so at q4 = pi/3 (over Q(sqrt 3)) and at q4 = pi/3,
    q7 = pi/4 (a field of degree four) the branches, computed over those fields,
    are those at home, exactly."""
    system = load("seven-r-loop")
    for at, degree in (("q4=pi/3", 2), ("q4=pi/3,q7=pi/4", 4)):
        fm = system.finite_mobility(at)
        assert fm.field is not None
        assert sp.degree(sp.sympify(fm.field["minimal_polynomial"]), sp.Symbol("alpha")) \
            == degree
        _check_seven_r(fm)


def test_text_latex_and_json_give_the_root_exactly():
    fm = load("seven-r-loop").finite_mobility()
    lines = finite_lines(fm)
    assert lines[0] == ("Finite mobility: 1 (first-order motions: 2) - a bifurcation: 3 "
                        "branches of 1 motion cross here.")
    lo, hi = fm.branches[1].direction.interval
    assert lines[3] == (
        "  Branch 2: 1 motion, tangent to the span of (0, 0, -70/17, 0, -14/17, 0, "
        "s - 7/17, 2*s - 14/17, s - 7/17, 2*s, 26/17, 10/17, 2) in (u, qdot), where s "
        "(= u_q4/u_q7 along the branch) is the real root of 14739*s**3 - 21675*s**2 + "
        f"4403*s + 1169 in ({lo}, {hi}]")
    latex = finite_latex(fm)
    assert ("where $s$ is the real root of $14739 s^{3} - 21675 s^{2} + 4403 s + 1169 = 0$"
            in latex)
    data = json.loads(json.dumps(finite_json(fm)))
    direction = data["branches"][1]["direction"]
    assert direction == {"free": ["u_q4", "u_q7"],
                         "minimal_polynomial": "14739*s**3 - 21675*s**2 + 4403*s + 1169",
                         "interval": [str(lo), str(hi)],
                         "tangent": [str(sp.sympify(x)) for x in TANGENT]}
    out = CliRunner().invoke(app, ["analyze", "seven-r-loop", "--finite", "--json"])
    assert out.exit_code == 0, out.output
    assert json.loads(out.stdout)["finite"]["branches"][1]["direction"] == direction


def test_real_roots_over_a_field_follow_its_real_embedding():
    """x - sqrt(2): its norm x^2 - 2 has two real roots, only one a root of x - alpha,
    and which one depends on the embedding (alpha = +sqrt 2 or -sqrt 2)."""
    for index, expected in ((1, sp.sqrt(2)), (0, -sp.sqrt(2))):
        k = _field([-2, 0, 1], index)
        (root,) = real_roots(k, [k.element([0, -1]), 1])
        assert root.expression() == expected
    k = _field([-2, 0, 1], 1)
    (root,) = real_roots(k, [k.element([0, -1]), 0, 0, 1])     # x^3 - sqrt 2
    assert root.coeffs == (-2, 0, 0, 0, 0, 0, 1) and root.contains(sp.root(2, 6))
    # (x - 2) (x - sqrt 2): both roots, increasing
    assert [r.expression() for r in real_roots(k, [k.element([0, 2]), k.element([-2, -1]),
                                                   1])] == [sp.sqrt(2), 2]


def test_real_roots_over_fields_agree_with_sympy_on_random_polynomials():
    """Random polynomials over Q(sqrt 2) and Q(cbrt 3): as many real roots as SymPy's
    numerical roots of the same polynomial (at 50 digits, a check), each inside its
    isolating interval, a root of its minimal polynomial."""
    rng = random.Random(7)
    x = sp.Symbol("x")
    for g, index in (([-2, 0, 1], 1), ([-3, 0, 0, 1], 0)):
        k = _field(g, index)
        alpha = k.root.expression()
        for _ in range(6):
            coeffs = [[rng.randint(-4, 4) for _ in range(len(g) - 1)] for _ in range(4)]
            coeffs[-1][0] = coeffs[-1][0] or 1
            p = [k.element(c) for c in coeffs]
            expr = sum(sum(c * alpha**i for i, c in enumerate(cs)) * x**j
                       for j, cs in enumerate(coeffs))
            numeric = [r for r in sp.Poly(sp.expand(expr), x).nroots(n=50)
                       if abs(sp.im(r)) < 1e-30]             # float-ok: a check
            found = real_roots(k, p)
            assert len(found) == len(numeric) == real_root_count(k, p)
            for r, value in zip(found, sorted(sp.re(v) for v in numeric), strict=True):
                lo, hi = r.refine(Fraction(1, 10**30))
                assert lo - Fraction(1, 10**25) <= Fraction(str(sp.Float(value, 50))) \
                    <= hi + Fraction(1, 10**25)


def test_binary_directions_say_multiple_roots():
    """x^2 (x - sqrt 2) y over Q(sqrt 2): the direction x = 0 is a double root (the
    branches there are not decided), y = 0 and x = sqrt(2) y simple."""
    k = _field([-2, 0, 1], 1)
    s2 = k.number([0, 1])
    found, multiple = field_directions({(3, 1): k.number(1), (2, 2): -s2}, k)
    assert multiple
    assert [m for _, m in found] == [1, 2, 1]
    ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "deglex")
    xx, yy = ctx.gens()
    directions = real_directions([xx**3 - 2 * yy**3], 2)   # over Q: 2^(1/3), degree 3
    ((root, one), m), = directions
    assert (one, m, root.coeffs) == (1, 1, (-2, 0, 0, 1))


@pytest.mark.slow
def test_the_sampler_follows_each_of_the_three_branches():
    """60-digit mpmath: starting a small step along each branch's tangent (its root
    located from the minimal polynomial and interval alone), the projection onto the
    loop closure stays along that branch, and away from the other two."""
    system = load("seven-r-loop")
    fm = system.finite_mobility()
    sampler = Sampler(system.model, {}, {})
    tangents = []
    for branch in fm.branches:
        d = branch.direction
        lo, hi = d.root.refine(Fraction(1, 10**40))
        s = mp.mpf(lo.numerator) / lo.denominator
        v = [mp.mpf(sp.Rational(x.subs(S, 0)).p) / sp.Rational(x.subs(S, 0)).q
             + s * mp.mpf(sp.Rational(x.coeff(S)).p) / sp.Rational(x.coeff(S)).q
             for x in (sp.sympify(t) for t in d.tangent)]
        norm = mp.sqrt(sum(c * c for c in v))
        tangents.append([c / norm for c in v])
    for k, t in enumerate(tangents):
        start = [mp.mpf(10) ** -4 * c for c in t]
        point = sampler.project(start)
        assert point is not None
        size = mp.sqrt(sum(c * c for c in point))
        along = [c / size for c in point]
        off = [mp.sqrt(sum((a - b) ** 2 for a, b in zip(along, u, strict=True)))
               for u in tangents]
        off = [min(o, mp.sqrt(sum((a + b) ** 2 for a, b in zip(along, u, strict=True))))
               for o, u in zip(off, tangents, strict=True)]
        assert off[k] < mp.mpf(10) ** -3, off
        assert all(o > mp.mpf(10) ** -1 for i, o in enumerate(off) if i != k), off
