"""Finite mobility: the local dimension of the closed system's configuration space."""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp

from coopkin_sym import load
from coopkin_sym.analysis.finite import finite_mobility
from coopkin_sym.analysis.finite.constraints import ConstraintMap
from coopkin_sym.analysis.finite.on_locus import finite_data
from coopkin_sym.analysis.finite.reduce import reduce_map
from coopkin_sym.errors import FiniteMobilityError
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.present.finite import (
    classification_text,
    finite_latex,
    finite_lines,
    finite_summary,
)

POINTS = [
    ("paper-case1-hard", "q1=pi/2,q2=pi/2,L=1"),
    ("paper-case1-hard", "q1=2*atan(1/3),q2=2*atan(-2/5),L=1"),
    ("paper-case1-complete-hard", "q1=2*atan(1/3),q2=pi,L=1"),
    ("paper-case1-planar", "q1=2*atan(1/3),q2=2*atan(-2/5),L=1"),
    ("paper-case2-complete", "q1=2*atan(1/3),q2=2*atan(-2/5),q3=2*atan(1/7),q4=2,q5=1,"
                             "q6=2*atan(3),q7=pi,q8=-pi/2,L=1"),
    ("five-bar", "q1=2*atan(1/3),q2=2*atan(-2/5),q3=2*atan(1/7),q4=2*atan(2),L=1"),
]


@pytest.mark.parametrize(("name", "at"), POINTS)
def test_the_linear_part_of_the_constraint_map_is_q(name, at):
    """``J = -Q S`` exactly: the expansion's first order is the velocity analysis."""
    system = load(name)
    cmap = ConstraintMap(system.model, Configuration.parse(system.model, at))
    jac = sp.Matrix([[sp.Rational(str(x)) for x in row] for row in cmap.linear()])
    assert jac == -system.analyze(at).Q * sp.diag(*cmap.scale)


def test_case_1_planar_bifurcates_where_both_links_lie_on_the_contact_line():
    """At q1 = q2 = pi/2 the planar case 1 (a closed loop through the object) has two
    first-order motions but one finite one on each of two branches crossing there."""
    system = load("paper-case1-planar")
    red = reduce_map(ConstraintMap(system.model, Configuration.parse(
        system.model, "q1=pi/2,q2=pi/2,L=1")), 2)
    assert red.free == ("u_q1", "u_q2")
    assert [str(g) for g in red.g] == ["-4*u_q1*u_q2 + 4*u_q2^2"]
    fm = finite_mobility(system.model, "q1=pi/2,q2=pi/2")
    assert (fm.dimension, fm.bounds, fm.first_order) == (1, (1, 1), 2)
    assert (fm.classification, fm.reason) == ("bifurcation", "cone_regular_points")
    assert fm.orders == ((1, 2), (2, 1))
    q = system.analyze("q1=pi/2,q2=pi/2,L=1").Q
    tangents = {b.tangent for b in fm.branches}
    assert tangents == {((0, -2, 0, 2, 2),), ((0, 0, 2, 2, 0),)}
    for b in fm.branches:
        for v in b.tangent:
            assert q * sp.Matrix(v) == sp.zeros(q.rows, 1)
    assert fm.assumptions == ("unit_length",)


def test_a_regular_configuration_moves_with_its_first_order_motions():
    """Away from the locus the finite mobility is the number of first-order motions
    (constant rank theorem), and its branch is the kernel of Q."""
    system = load("paper-case1-hard")
    at = "q1=2*atan(1/3),q2=2*atan(1/5)"
    fm = finite_mobility(system.model, at)
    a = system.analyze(at + ",L=1")
    assert (fm.dimension, fm.classification, fm.reason) == (2, "regular", "submersion")
    assert fm.first_order == a.numbers.Nm == 2
    (branch,) = fm.branches
    span = sp.Matrix.hstack(*[sp.Matrix(v) for v in branch.tangent])
    assert a.Q * span == sp.zeros(a.Q.rows, 2)
    assert span.rank() == 2


def test_a_rank_drop_whose_expansion_vanishes_is_decided_by_the_loop_closure():
    """Case 1 with a complete contact at q2 = pi/2: arm 2's pin lies on joint 1's axis,
    so the object (welded to link 1) turns about it with q2 held: a curve of closed
    configurations (by hand: the pin at the origin stays there). The reduced equations
    vanish to every order, and the loop closure proves the curve is all there is."""
    fm = finite_mobility(load("paper-case1-complete-hard").model, "q1=0,q2=pi/2")
    assert (fm.dimension, fm.bounds, fm.first_order) == (1, (1, 1), 1)
    assert (fm.classification, fm.reason) == ("kinematic_singularity", "closure_bezout")
    assert fm.branches[0].tangent == ((0, 0, 0, 0, 0, 2, 2, 0),)


def test_two_reduced_equations_with_a_common_direction_stay_undecided():
    """Three parallel cranks lying on the ground line (q = pi/2): two first-order
    motions, two reduced equations sharing the direction u_q2 = u_q3; nothing is
    claimed beyond the bounds proved."""
    fm = finite_mobility(load("parallel-cranks").model, "q1=pi/2,q2=pi/2,q3=pi/2")
    assert (fm.dimension, fm.bounds, fm.first_order) == (None, (0, 1), 2)
    assert fm.classification == "undecided" and fm.reason == "undecided_at_order_4"
    u2, u3 = sp.symbols("u_q2 u_q3")
    lowest = [sum(t for t in sp.Add.make_args(sp.sympify(e.replace("^", "**")))
                  if sp.Poly(t, u2, u3).total_degree() == 2) for e in fm.equations]
    assert [sp.expand(a - b) for a, b in zip(lowest, [-2 * u2 * (u2 - u3),
                                                      -3 * (u2 - u3) * (u2 + u3)],
                                             strict=True)] == [0, 0]


def test_soft_contacts_and_free_lengths_are_refused_with_the_reason():
    with pytest.raises(FiniteMobilityError, match="contact 1 is soft: its no-spin"):
        finite_mobility(load("paper-case1-soft").model, "q1=0,q2=0")
    with pytest.raises(FiniteMobilityError, match="needs a value for L"):
        ConstraintMap(load("paper-case1-hard").model,
                      Configuration.parse(load("paper-case1-hard").model, "q1=0"))


def test_the_four_bar_bifurcates_when_folded_and_moves_once_elsewhere():
    system = load("four-bar")
    home = finite_mobility(system.model, "q1=0,q2=0")
    assert (home.dimension, home.first_order, home.classification) == (1, 1, "regular")
    for at in ("q1=-pi/2,q2=-pi/2", "q1=pi/2,q2=pi/2"):
        fm = finite_mobility(system.model, at)
        assert (fm.dimension, fm.first_order, fm.classification) == (1, 2, "bifurcation")
        assert len(fm.branches) == 2 and fm.orders == ((1, 2), (2, 1))
        q = system.analyze(at).Q
        assert all(q * sp.Matrix(b.tangent[0]) == sp.zeros(q.rows, 1) for b in fm.branches)
    folded = finite_mobility(system.model, "q1=-pi/2,q2=-pi/2")
    assert {b.tangent for b in folded.branches} == {
        ((0, 2, 0, 2, 2),), ((0, -2, sp.Rational(4, 3), sp.Rational(-2, 3), 2),)}


def test_pinned_bars_on_a_line_are_shaky():
    """One first-order motion (the pin across the line), no finite one."""
    system = load("shaky-pinned-bars")
    assert system.analyze("q1=0,q2=0").numbers.Nm == 1
    fm = finite_mobility(system.model, "q1=0,q2=0")
    assert (fm.dimension, fm.bounds, fm.first_order) == (0, (0, 0), 1)
    assert (fm.classification, fm.reason) == ("shaky", "real_cone_origin")
    assert fm.equations == ("4*u_q2^2",) and fm.branches == ()


def test_the_spin_about_the_contact_line_is_split_off_as_a_finite_motion():
    """Case 1 hard at q1 = pi/2, q2 = -pi/2: of three first-order motions only the
    object's spin about the line through the two contacts (a group keeping both
    contacts, joints still) is finite; the expansion decides the rest is rigid."""
    system = load("paper-case1-hard")
    at = "q1=pi/2,q2=-pi/2"
    fm = finite_mobility(system.model, at)
    assert (fm.dimension, fm.bounds, fm.first_order) == (1, (1, 1), 3)
    assert (fm.classification, fm.reason) == ("shaky", "real_cone_origin")
    assert fm.orders == ((1, 3), (2, 1))
    (spin,) = fm.group_motions
    q = system.analyze(at + ",L=1").Q
    assert q * sp.Matrix(spin) == sp.zeros(q.rows, 1)
    assert spin[3:6] != (0, 0, 0) and spin[6:] == (0, 0)


def test_the_command_says_it_and_refuses_what_it_cannot_expand(monkeypatch, tmp_path):
    from typer.testing import CliRunner

    from coopkin_sym.cli import app

    runner = CliRunner()
    out = runner.invoke(app, ["analyze", "shaky-pinned-bars", "--finite"])
    assert out.exit_code == 0, out.output
    assert ("Finite mobility: 0 (first-order motions: 1) - shaky: first-order motions "
            "exist, but no finite motion follows them.") in out.stdout
    bad = runner.invoke(app, ["analyze", "paper-case1-soft", "--finite"])
    assert bad.exit_code == 2
    assert bad.stderr.startswith("coopkin: error: contact 1 is soft: its no-spin")
    # the locus is not searched when its witnesses cannot be expanded: said first
    import coopkin_sym.analysis.locus.search as search

    def no_search(*args, **kwargs):
        raise AssertionError("the locus was searched")
    monkeypatch.setattr(search, "compute_locus", no_search)
    out = tmp_path / "soft.md"
    bad = runner.invoke(app, ["locus", "paper-case1-soft", "--finite", "--no-progress",
                              "-o", str(out)])
    assert bad.exit_code == 2, bad.output
    assert bad.stderr.startswith("coopkin: error: contact 1 is soft: its no-spin")
    assert not out.exists()                       # nothing half-written
    symbolic = runner.invoke(app, ["analyze", "four-bar", "--generic", "--finite"])
    assert symbolic.exit_code == 2 and "--finite needs every joint" in symbolic.stderr
    stray = runner.invoke(app, ["analyze", "four-bar", "--at", "q1=0", "--order", "3"])
    assert stray.exit_code == 2 and "give it with --finite" in stray.stderr
    latex = runner.invoke(app, ["analyze", "four-bar", "--at", "q1=pi/2,q2=pi/2",
                                "--finite", "--latex"])
    assert "Finite mobility $1$ (first-order motions: $2$): a bifurcation" in latex.stdout


def test_the_registry_says_which_contact_models_hold_on_positions():
    from coopkin_sym.analysis.finite.constraints import holonomic_models
    from coopkin_sym.model.contacts import REGISTRY

    assert holonomic_models() == ("complete", "hard", "frictionless")
    assert {k.name: k.position for k in REGISTRY.values()} == {
        "complete": "weld", "soft": "", "hard": "point", "frictionless": "face"}
    assert all(k.position or k.not_holonomic for k in REGISTRY.values())


def test_the_locus_keeps_the_finite_mobility_at_its_witnesses(tmp_path):
    """``Locus.finite_mobility()`` (``coopkin locus --finite``): the classification at
    every witness as data, written in the report and its JSON, read back equal, and
    valid for the locus schema."""
    import json

    from coopkin_sym.present.report import locus_from_json, render_json, render_markdown

    system = load("four-bar")
    locus = system.locus()
    assert locus.finite_mobility() == 4
    data = [c.finite for c in locus.components]
    assert [d["classification"] for d in data] == ["bifurcation", "shaky", "shaky",
                                                   "bifurcation"]
    assert [(d["dimension"], d["first_order"], d["branches"]) for d in data] == [
        (1, 2, [1, 1]), (1, 2, [1]), (0, 2, []), (1, 2, [1, 1])]
    text = render_json(locus)
    back = locus_from_json(text)
    assert [c.finite for c in back.components] == data
    jsonschema = pytest.importorskip("jsonschema")
    schema = json.loads((Path(__file__).resolve().parents[2] / "docs" /
                         "locus.schema.json").read_text())
    jsonschema.Draft202012Validator(schema).validate(json.loads(text))
    assert ("**Finite mobility at the witness:** 0 (first-order motions: 2): shaky: "
            "first-order motions exist, but no finite motion follows them"
            ) in render_markdown(locus)


def test_only_the_groups_rotations_at_a_drop_are_a_smooth_orbit_not_a_regular_point():
    """Paper case 1 (hard) at q1 = -5pi/6, q2 = 5pi/6 (a locus point: Nm 2 -> 3): every
    first-order motion is a rotation about the contact line, so the configuration
    space is that group's orbit, smooth of dimension 3; the numbers change, so it is a
    kinematic singularity (it read "regular: there is no first-order motion")."""
    system = load("paper-case1-hard")
    at = "q1=-5*pi/6,q2=5*pi/6,L=1"
    fm = system.finite_mobility(at)
    assert (fm.dimension, fm.bounds, fm.first_order) == (3, (3, 3), 3)
    assert (fm.classification, fm.reason) == ("kinematic_singularity", "group_orbit")
    assert len(fm.branches) == 1 and fm.branches[0].dimension == 3
    assert system.analyze(at).numbers.Nm != system.analyze(generic=True).numbers.Nm
    text = "\n".join(finite_lines(fm))
    assert "no first-order motion" not in text and "a rotation of the object" in text


def test_finite_mobility_of_a_generic_or_free_analysis_is_refused():
    """An analysis with symbolic joints has no one configuration to expand at: it is
    refused, naming the joints (it computed at q = 0 without a word)."""
    system = load("four-bar")
    with pytest.raises(FiniteMobilityError, match="joints q1, q2 are left free"):
        system.analyze(generic=True).finite_mobility()
    with pytest.raises(FiniteMobilityError, match="joint q2 is left free"):
        system.analyze("q1=0", free=["q2"]).finite_mobility()


def test_an_analysis_at_irrational_angles_has_the_finite_mobility_of_its_point():
    """``analyze("q1=-pi/4,...").finite_mobility()`` (over a number field) is the
    system's finite mobility there."""
    system = load("four-bar")
    at = "q1=-pi/4,q2=-pi/4"
    assert system.analyze(at).finite_mobility() == system.finite_mobility(at)
    assert system.finite_mobility(at).field is not None


def test_latex_and_locus_data_say_the_proof_and_how_the_model_was_read():
    """The LaTeX paragraph has the proof and the assumptions the text has (a
    frictionless contact read on a flat face); a locus component keeps them."""
    fm = load("underactuated-finger").finite_mobility("q1=0,q2=2*atan(1/2)")
    assert fm.assumptions == ("unit_length", "frictionless_flat_face")
    latex = finite_latex(fm)
    assert "Proof: the constraints are independent here" in latex
    assert "flat face of the object" in latex and "set to 1" in latex
    data = finite_data(fm)
    assert data["assumptions"] == ["unit_length", "frictionless_flat_face"]
    assert "flat face of the object" in finite_summary(data)


def test_an_overconstrained_loop_is_not_said_to_change_its_numbers_along_its_motion():
    """Bennett's linkage: the numbers differ from those of generic joint values (where
    the loop does not close), which the words say, without claiming they change along
    the motion."""
    fm = load("bennett-linkage").finite_mobility()
    assert (fm.dimension, fm.classification) == (1, "kinematic_singularity")
    words = classification_text(fm)
    assert "overconstrained loop" in words and "not decided" in words
    assert "overconstrained loop" in finite_summary(finite_data(fm))


@pytest.mark.parametrize(("name", "at", "expected"), [
    ("four-bar", "q1=-pi/2,q2=-pi/2", [("C12", 1, "finite", None), ("C12", 2, "fails", 2)]),
    ("four-bar", "q1=0,q2=0", [("C12", 1, "finite", None)]),
    ("shaky-pinned-bars", "q1=0,q2=0", [("C12", 1, "fails", 2)]),
    ("paper-case1-hard", "q1=pi/2,q2=-pi/2",
     [("C11", 1, "finite", None), ("C12", 1, "fails", 2), ("C12", 2, "fails", 2)]),
    ("parallel-cranks", "q1=pi/2,q2=pi/2,q3=pi/2",
     [("C12", 1, "undecided", 4), ("C12", 2, "fails", 2)]),
    ("bennett-linkage", None, [("C12", 1, "finite", None)]),
])
def test_each_column_of_the_blocks_is_said_finite_or_where_it_fails(name, at, expected):
    """Which columns of C11, C12/C22 and C23 are finite motions' velocities: a finite
    one lies in a branch's tangent (checked here); along a failing one the lowest
    term of a reduced constraint is not zero."""
    a = load(name).analyze(at)
    fm = a.finite_mobility()
    assert [(c.block, c.index, c.verdict, c.order) for c in fm.columns] == expected
    blocks = a.blocks()
    for c in fm.columns:
        v = (list(blocks["C11"][:, c.index - 1]) + [0] * blocks["C23"].rows
             if c.block == "C11" else
             list(blocks["C12"][:, c.index - 1]) + list(blocks["C22"][:, c.index - 1])
             if c.block == "C12" else
             [0] * blocks["C11"].rows + list(blocks["C23"][:, c.index - 1]))
        v = sp.Matrix(v).subs(sp.Symbol("L", positive=True), 1).subs(sp.Symbol("L"), 1)
        assert a.Q.subs(sp.Symbol("L", positive=True), 1).subs(sp.Symbol("L"), 1) * v \
            == sp.zeros(a.Q.rows, 1)
        on_branch = any(
            sp.Matrix([list(t) for t in b.tangent]).T.rank()
            == sp.Matrix([list(t) for t in b.tangent]).T.row_join(v).rank()
            for b in fm.branches if b.tangent is not None)
        assert on_branch == (c.verdict == "finite"), c
    assert (name != "four-bar" or at != "q1=-pi/2,q2=-pi/2"
            or "column 2 is not (the constraints fail along it at order 2)"
            in "\n".join(finite_lines(fm)))


def test_the_command_gives_the_columns_in_text_latex_and_json():
    from typer.testing import CliRunner

    from coopkin_sym.cli import app

    runner = CliRunner()
    args = ["analyze", "four-bar", "--at", "q1=-pi/2,q2=-pi/2", "--finite"]
    text = runner.invoke(app, args).stdout
    assert "Columns of C: C12/C22 column 1 is a finite motion's velocity" in text
    latex = runner.invoke(app, [*args, "--latex"]).stdout
    assert "$C_{12}/C_{22}$ column 2 is not" in latex
    import json
    data = json.loads(runner.invoke(app, [*args, "--json"]).stdout)
    assert data["finite"]["columns"] == [
        {"block": "C12", "index": 1, "verdict": "finite", "order": None},
        {"block": "C12", "index": 2, "verdict": "fails", "order": 2}]
