"""The two ways a component is cut by a picture's plane agree: flint (every value
rational) and SymPy (any exact value), on every component of shipped loci and every
default pair of joints: the same curve up to a constant factor, the same points."""

from __future__ import annotations

import pytest
import sympy as sp

from coopkin_sym import load
from coopkin_sym.present import locus_plot as lp
from coopkin_sym.present import plot_plane
from coopkin_sym.present.report import default_pairs


def _cuts(name):
    system = load(name)
    locus = system.locus()
    kinds = lp._kinds(locus, system)
    names = lp._names(locus, kinds)
    for pair in default_pairs(locus, system):
        for c in locus.components:
            if not c.real:
                continue
            used = lp._joints_in(c, kinds, names)
            axes = []
            for j in pair:
                v = used.get(j) or kinds.variables(j)[0]
                axes.append(plot_plane._Axis(j, v, kinds.joint_of(v)[1]))
            values, _ = lp._slice(locus, kinds, c, {a.variable for a in axes}, names)
            yield c, values, axes, names


@pytest.mark.parametrize("name", ["four-bar", "paper-case1-hard", "underactuated-finger",
                                  "planar-two-fingers"])
def test_flint_and_sympy_cut_every_component_alike(name):
    compared = 0
    for c, values, (ax, ay), names in _cuts(name):
        fast = plot_plane._in_plane_rational(c, values, ax, ay, names)
        if fast is None:
            continue
        slow = plot_plane._in_plane_sympy(c, values, ax, ay, names)
        compared += 1
        assert fast.whole == slow.whole
        assert (fast.curve is None) == (slow.curve is None)
        if fast.curve is not None:
            ratio = sp.cancel(fast.curve.as_expr() / slow.curve.as_expr())
            assert ratio.is_Rational and ratio != 0
        assert sorted(fast.points) == sorted(slow.points)
    assert compared > 0


def _flint_polys(texts, names=("x", "y")):
    import flint
    ctx = flint.fmpq_mpoly_ctx.get(names, "lex")
    syms = sp.symbols(names)
    out = []
    for t in texts:
        p = sp.Poly(t, *syms)
        out.append(ctx.from_dict({m: flint.fmpq(int(c.p), int(c.q))
                                  for m, c in p.as_dict().items()}))
    return out


def _sympy_real_points(texts):
    x, y = sp.symbols("x y")
    found = sp.solve_poly_system([sp.sympify(t) for t in texts], x, y) or []
    values = [(complex(sp.N(a, 30)), complex(sp.N(b, 30))) for a, b in found]
    return sorted((round(a.real, 9), round(b.real, 9)) for a, b in values
                  if abs(a.imag) < 1e-12 and abs(b.imag) < 1e-12)


@pytest.mark.parametrize("texts", [
    ["x**2 + y**2 - 1", "x - y"],                 # two points
    ["y", "2*x**2 - 8", "x + 2"],                # x + 2 divides 2x^2 - 8; y alone
    ["x**2 + 1", "y - 1"],                       # no real point
    ["x*y - 1", "x**2 - 2", "y**2 - 1/2"],       # irrational, three polynomials
    ["x**3 - 2", "y**3 - 2", "x - y"],           # one real point of nine complex ones
])
def test_real_common_zeros_are_sympys_real_solutions(texts):
    found = plot_plane._real_common_zeros(_flint_polys(texts), 0, 1)
    assert sorted((round(a, 9), round(b, 9)) for a, b in found) == _sympy_real_points(texts)


@pytest.mark.slow          # 40 systems against SymPy's solver: about 16 s
def test_real_common_zeros_on_random_systems():
    import random
    rng = random.Random(7)
    x, y = sp.symbols("x y")
    compared = 0
    for _ in range(40):
        polys = [sum(rng.randint(-3, 3) * x**i * y**j for i in range(3) for j in range(3)
                     if i + j <= 2) for _ in range(2)]
        texts = [str(sp.expand(p)) for p in polys]
        if any(sp.sympify(t).is_number for t in texts) or sp.gcd(*polys).free_symbols:
            continue
        found = plot_plane._real_common_zeros(_flint_polys(texts), 0, 1)
        assert sorted((round(a, 9), round(b, 9)) for a, b in found) == \
            _sympy_real_points(texts)
        compared += 1
    assert compared >= 25


def test_real_common_zeros_say_when_they_cannot():
    # x - y shared by both: every resultant vanishes, the caller falls back to SymPy
    assert plot_plane._real_common_zeros(_flint_polys(["x - y", "x**2 - x*y"]), 0, 1) is None
