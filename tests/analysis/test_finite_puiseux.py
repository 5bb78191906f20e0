"""Real branches along a multiple tangent by Newton's polygon: cusps, tangent branches,
isolated points, and what stays undecided."""

from __future__ import annotations

import flint
import pytest
import sympy as sp

from coopkin_sym.analysis.finite import _decide_singular
from coopkin_sym.analysis.finite.puiseux import Tangent, along_tangent
from coopkin_sym.analysis.finite.reduce import Reduced
from coopkin_sym.analysis.finite.series import SeriesField

CTX = flint.fmpq_mpoly_ctx.get(("x", "y"), "deglex")
X, Y = CTX.gens()


@pytest.mark.parametrize(("g", "direction", "order", "expected"), [
    (Y**2 - X**3, (1, 0), 3, Tangent(0, 1, (2, 0))),             # a cusp, x > 0
    (Y**2 + X**3, (1, 0), 3, Tangent(0, 1, (0, 2))),             # a cusp, x < 0
    (Y**2 + X**4, (1, 0), 4, Tangent(0, 0, (0, 0))),             # the point alone
    (Y**2 - X**4, (1, 0), 4, Tangent(2, 0, (2, 2))),             # two tangent branches
    (Y**3 - X**4, (1, 0), 4, Tangent(0, 1, (1, 1))),             # y = x^(4/3)
    (Y**2 - X**3 + X * Y**3, (1, 0), 4, Tangent(0, 1, (2, 0))),  # higher terms
    ((X - 2 * Y)**2 - Y**3, (2, 1), 3, Tangent(0, 1, (2, 0))),   # tangent (2, 1)
    ((X - 2 * Y)**2 * (X + Y) - Y**4, (2, 1), 4, Tangent(0, 1, (2, 0))),
    (X**2 - Y**3, (0, 1), 3, Tangent(0, 1, (2, 0))),
    (Y**2 - X**3, (1, 0), 2, None),                              # x^3 not reached
    ((Y - X**2)**2 - X**5, (1, 0), 6, None),                     # a double edge root
])
def test_the_branches_along_a_multiple_tangent(g, direction, order, expected):
    assert along_tangent(g, direction, order) == expected


def test_terms_above_the_order_are_not_read():
    """Only terms of total degree at most ``order`` are exact: a term of degree 5
    does not change the branches decided at order 4."""
    assert along_tangent(Y**2 - X**4 + X**5 * Y, (1, 0), 4) == Tangent(2, 0, (2, 2))


class _Plane:
    """The constraint map of two free coordinates ``x, y`` in the plane (velocity
    ``(x, y, 0)``), for the decision alone."""

    names = ("x", "y", "r")
    scale = [1, 1, 1]
    planar = True
    joint_names: list = []
    moving: list = []
    point = None

    def series_field(self, names, order):
        return SeriesField(names, order)

    def linear(self):
        return [[0, 0, 0]]


def _decide(expr: str, order: int) -> dict:
    field = SeriesField(("x", "y"), order)
    x, y = field.ctx.gens()
    g = sp.lambdify(sp.symbols("x y"), sp.sympify(expr))(x, y)
    return _decide_singular(_Plane(), Reduced((), ("x", "y"), (), [g], order, 0, 1))


@pytest.mark.parametrize(("expr", "order", "kind", "dimension", "branches"), [
    ("y**2 - x**3", 3, "cusp", 1, 1),
    ("y**2 + x**4", 4, "shaky", 0, 0),
    ("y**2 - x**4", 4, "bifurcation", 1, 2),
    ("y**2*(x - y) - x**4", 4, "bifurcation", 1, 2),       # a cusp and a smooth branch
    ("y**2 - x**5", 4, "undecided", None, 0),
])
def test_a_multiple_tangent_is_decided_by_the_polygon(expr, order, kind, dimension,
                                                      branches):
    found = _decide(expr, order)
    assert (found["classification"], found["dimension"], len(found["branches"])) == (
        kind, dimension, branches)
    if dimension is not None:
        assert found["reason"] == "newton_polygon"
    for b in found["branches"]:
        assert b.dimension == 1 and len(b.tangent) == 1
