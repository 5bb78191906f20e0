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


@pytest.mark.parametrize("name", ["four-bar", "paper-case1-hard", "underactuated-finger"])
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
