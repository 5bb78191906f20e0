"""Finite mobility at configurations with an irrational tan(q/2), over Q(alpha)."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import mpmath as mp
import pytest
import sympy as sp
from typer.testing import CliRunner

from coopkin_sym import load
from coopkin_sym.analysis.finite import finite_mobility
from coopkin_sym.cli import app
from coopkin_sym.errors import CoopkinError

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from finite_sampler import Sampler  # noqa: E402

# A parallelogram four-bar whose links leave the ground at 45 degrees at home: crank
# (pivot 0, tip (1, 1): length sqrt(2)) and rocker (pivot (2, 0), tip (3, 1)) pinned to
# a coupler of length 2. At q1 = q2 = -pi/4 (tan(q/2) = 1 - sqrt(2)) all four links
# lie on the ground line, folded: the parallelogram and anti-parallelogram motions
# cross there, as in the four-bar at q = -pi/2.
SLANTED = """\
name: slanted four-bar
planar: true
arms:
  - name: crank
    joints:
      - {name: q1, type: revolute, axis: [0, 0, 1], point: [0, 0, 0]}
  - name: rocker
    joints:
      - {name: q2, type: revolute, axis: [0, 0, 1], point: [2, 0, 0]}
contacts:
  - {name: c1, link: crank/1, point: [1, 1, 0], normal: [0, 1, 0], model: hard}
  - {name: c2, link: rocker/1, point: [3, 1, 0], normal: [0, 1, 0], model: hard}
"""


@pytest.fixture
def slanted(tmp_path):
    path = tmp_path / "slanted-four-bar.yaml"
    path.write_text(SLANTED)
    return load(str(path))



def test_the_folded_slanted_four_bar_bifurcates_over_q_sqrt2(slanted):
    """By hand: the parallelogram branch turns both links equally (qdot = (2, 2)),
    the coupler translating with the crank's tip (sqrt(2), 0): u = (0, 2 sqrt(2), 0);
    the other branch is the anti-parallelogram one."""
    fm = slanted.finite_mobility("q1=-pi/4,q2=-pi/4")
    assert (fm.dimension, fm.first_order, fm.classification, fm.reason) == (
        1, 2, "bifurcation", "cone_regular_points")
    assert fm.field["minimal_polynomial"] == "alpha**2 - 2*alpha - 1"
    assert fm.field["tangents"] == {"q1": "1 - sqrt(2)", "q2": "1 - sqrt(2)"}
    s2 = sp.sqrt(2)
    tangents = [b.tangent[0] for b in fm.branches]
    assert [sp.simplify(x - y) for x, y in zip(tangents[0], (0, 2 * s2, 0, 2, 2),
                                               strict=True)] == [0] * 5
    assert [sp.simplify(x - y) for x, y in zip(
        tangents[1], (0, -2 * s2, -4 + 4 * s2, -6 + 4 * s2, 2), strict=True)] == [0] * 5


def test_the_sampler_sees_the_slanted_four_bar_bifurcate(slanted):
    """mpmath at 60 digits: perturbations projected onto the closure near
    q1 = q2 = -pi/4 lie on a curve (local dimension 1) along the two exact branches."""
    fm = slanted.finite_mobility("q1=-pi/4,q2=-pi/4")
    sampler = Sampler(slanted.model, {"q1": -mp.pi / 4, "q2": -mp.pi / 4}, {})
    assert sampler.dimension(6) == fm.dimension == 1
    spans = [mp.matrix([[mp.mpf(str(sp.N(x, 70))) for x in b.tangent[0]]]).T
             for b in fm.branches]
    met = [False, False]
    for d in sampler.directions(6):
        v = mp.matrix(d)
        off = [mp.norm(v - s * mp.lu_solve(s.T * s, s.T * v)) for s in spans]
        k = min(range(2), key=lambda i: off[i])
        assert off[k] < mp.mpf(10) ** -2, (d, off)
        met[k] = True
    assert all(met)


def test_a_parallelogram_at_pi_3_is_regular(slanted):
    """q1 = q2 = pi/3 (tan(q/2) = sqrt(3)/3): independent constraints, one motion,
    the coupler translating with the crank's tip R(pi/3) (1, 1)."""
    fm = slanted.finite_mobility("q1=pi/3,q2=pi/3")
    assert (fm.dimension, fm.first_order, fm.classification, fm.reason) == (
        1, 1, "regular", "submersion")
    s3 = sp.sqrt(3)
    tip = sp.Matrix([[sp.Rational(1, 2), -s3 / 2], [s3 / 2, sp.Rational(1, 2)]]) * \
        sp.Matrix([1, 1])
    expected = (-2 * tip[1], 2 * tip[0], 0, 2, 2)      # omega x tip, qdot = 2
    assert [sp.simplify(x - y) for x, y in zip(fm.branches[0].tangent[0], expected,
                                               strict=True)] == [0] * 5


def test_case_1_planar_at_pi_4_matches_its_numbers():
    """Away from the singular set the irrational configuration is regular with the
    motions the irrational analysis counts."""
    system = load("paper-case1-planar")
    fm = finite_mobility(system.model, "q1=pi/4,q2=-pi/4")
    assert (fm.dimension, fm.first_order, fm.reason) == (1, 1, "submersion")
    assert fm.assumptions == ("unit_length",)
    assert fm.field["alpha"] == "-1 + sqrt(2)"


def test_a_rational_configuration_keeps_no_field():
    fm = load("four-bar").finite_mobility("q1=-pi/2,q2=-pi/2")
    assert fm.field is None and fm.classification == "bifurcation"


def test_the_locus_finite_covers_algebraic_witnesses():
    """paper-case1-hard's fifth family has only a witness at q1 = -5 pi/6 (in
    Q(sqrt 3)): its finite mobility is computed there, over that field."""
    system = load("paper-case1-hard")
    locus = system.locus()
    system.finite_locus(locus)
    algebraic = [c for c in locus.components if not c.witness and c.algebraic_witness]
    assert algebraic
    for c in algebraic:
        assert c.finite is not None
        assert c.finite["field"]["minimal_polynomial"] == "alpha**2 + 4*alpha + 1"
        assert c.finite["dimension"] == 3           # the turns about the contact point


def test_analyze_finite_at_an_irrational_angle_on_the_command_line():
    runner = CliRunner()
    text = runner.invoke(app, ["analyze", "paper-case1-planar", "--at", "q1=pi/3,q2=pi/3",
                               "--finite"])
    assert text.exit_code == 0, text.output
    assert "Finite mobility: 1 (first-order motions: 1)" in text.output
    assert "number field Q(alpha), alpha = sqrt(3)/3" in text.output
    data = runner.invoke(app, ["analyze", "paper-case1-planar", "--at", "q1=pi/3,q2=pi/3",
                               "--finite", "--json"])
    assert data.exit_code == 0, data.output
    finite = json.loads(data.output)["finite"]
    assert finite["field"]["minimal_polynomial"] == "3*alpha**2 - 1"
    latex = runner.invoke(app, ["analyze", "paper-case1-planar", "--at",
                                "q1=pi/3,q2=pi/3", "--finite", "--latex"])
    assert latex.exit_code == 0, latex.output
    assert ("Computed exactly over $\\mathbb{Q}(\\alpha)$, $\\alpha = \\frac{\\sqrt{3}}{3}$, "
            "a root of $3 \\alpha^{2} - 1$.") in latex.output


def test_a_transcendental_angle_is_still_refused():
    with pytest.raises(CoopkinError, match="not an algebraic number|not exact"):
        finite_mobility(load("four-bar").model, "q1=1,q2=0")


def test_signs_in_the_number_field_are_exact_near_zero():
    """577/408 - sqrt(2) is about 2e-6 > 0, and 1393/985 - sqrt(2) about -4e-7 < 0:
    decided on refined rational intervals, not in floating point."""
    import flint

    from coopkin_sym.exact.numberfield import RealNumberField
    from coopkin_sym.exact.realroot import RealRoot

    root = [r for r in RealRoot.all_of([-2, 0, 1]) if r.lo >= 0][0]
    k = RealNumberField(flint.fmpq_poly([-2, 0, 1]), root)
    s = k.number([0, 1])
    assert (flint.fmpq(577, 408) - s).sign() == 1
    assert (flint.fmpq(1393, 985) - s).sign() == -1
    assert (s * s - 2).sign() == 0
    tiny = s - 1
    for _ in range(6):                 # (sqrt(2) - 1)^64: about 3e-25, positive
        tiny = tiny * tiny
    assert tiny > 0 and -tiny < 0


def test_the_locus_report_with_an_algebraic_finite_mobility_reads_back(tmp_path):
    from coopkin_sym.present.report_input import validate_report

    runner = CliRunner()
    out = tmp_path / "case1.json"
    done = runner.invoke(app, ["locus", "paper-case1-hard", "--finite", "-o", str(out)])
    assert done.exit_code == 0, done.output
    data = json.loads(out.read_text())
    fields = [c["finite"].get("field") for c in data["components"] if c["finite"]]
    assert any(f and f["alpha"] == "-2 - sqrt(3)" for f in fields)
    back = validate_report(out.read_text())
    assert any(c.finite and "field" in c.finite for c in back.components)


def test_tangents_over_a_field_of_degree_four_are_first_order_motions():
    """q1 = pi/3, q2 = pi/4 need Q(sqrt 2, sqrt 3): each branch vector, scaled back to
    the coordinates (``z = v / S``), is in the kernel of the exact linear part J."""
    from coopkin_sym.analysis.finite import _sym
    from coopkin_sym.analysis.finite.algebraic import algebraic_point
    from coopkin_sym.analysis.finite.constraints import ConstraintMap

    model = load("paper-case1-hard").model
    fm = finite_mobility(model, "q1=pi/3,q2=pi/4")
    assert (fm.dimension, fm.reason) == (2, "submersion")
    assert sp.degree(sp.sympify(fm.field["minimal_polynomial"]), sp.Symbol("alpha")) == 4
    config, point = algebraic_point(model, "q1=pi/3,q2=pi/4,L=1")
    cmap = ConstraintMap(model, config, point=point)
    jac = sp.Matrix([[_sym(x) for x in row] for row in cmap.linear()])
    for v in fm.branches[0].tangent:
        z = sp.Matrix([x / s for x, s in zip(v, cmap.scale, strict=True)])
        assert all(sp.simplify(e) == 0 for e in jac * z)
    assert sp.Matrix(fm.branches[0].tangent).rank(simplify=True) == 2
