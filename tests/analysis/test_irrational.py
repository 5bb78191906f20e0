"""Numbers at configurations with irrational tan(q/2), exact over a number field,
against the independent reference (4x4 transforms, SymPy) ranked over the same field."""

from __future__ import annotations

import json

import pytest
import sympy as sp
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st
from independent import reference_numbers_algebraic
from typer.testing import CliRunner

import coopkin_sym
import coopkin_sym.model.examples
from coopkin_sym.analysis.irrational import NotIrrational, analyze_irrational
from coopkin_sym.cli import app
from coopkin_sym.errors import NotAvailable
from coopkin_sym.model.configuration import ConfigurationError
from coopkin_sym.model.model import load_model
from coopkin_sym.present.sentences import irrational_sentences

runner = CliRunner()


def reference_numbers(name: str, angles: dict[str, sp.Expr], L: int = 1) -> dict:
    model = yaml.safe_load(coopkin_sym.model.examples.example_path(name).read_text())
    at = {j: (sp.cos(q), sp.sin(q)) for j, q in angles.items()}
    return reference_numbers_algebraic(model, {**at, "L": L})


def test_coincident_contacts_of_case1_in_radicals():
    a = analyze_irrational(load_model("paper-case1-hard"), "q1=-pi/6,q2=pi/6")
    assert a.numbers.as_dict() == reference_numbers(
        "paper-case1-hard", {"q1": -sp.pi / 6, "q2": sp.pi / 6}) == {
        "Nm": 3, "Nc": 3, "Ni": 3, "Nr": 0, "Ng": 3, "Nd": 4, "Nh": 1}
    assert a.tangents == {"q1": "-2 + sqrt(3)", "q2": "2 - sqrt(3)"}
    assert a.minimal_polynomial == "alpha**2 + 4*alpha + 1"
    assert irrational_sentences(a)[2] == ("Ni = 3: with every joint locked, the object can "
                                   "still turn freely about c1 (= c2), in every direction.")


def test_two_independent_radicals_give_a_degree_four_field():
    a = analyze_irrational(load_model("paper-case1-hard"), "q1=pi/4,q2=pi/3,L=2")
    assert sp.degree(sp.sympify(a.minimal_polynomial), sp.Symbol("alpha")) == 4
    assert a.numbers.as_dict() == reference_numbers(
        "paper-case1-hard", {"q1": sp.pi / 4, "q2": sp.pi / 3}, L=2)


ANGLES = [k * sp.pi / 12 for k in range(-11, 12)]


@settings(max_examples=25, deadline=None)
@given(st.sampled_from(["paper-case1-hard", "paper-case1-soft", "paper-case2-hard"]),
       st.lists(st.sampled_from(ANGLES), min_size=2, max_size=2))
def test_random_multiples_of_pi_over_12_match_the_reference(name, angles):
    model = load_model(name)
    joints = [j.name for j in model.joints if j.type == "revolute"][:2]
    chosen = dict(zip(joints, angles, strict=True))
    at = ",".join(f"{j}={sp.sstr(q)}" for j, q in chosen.items())
    try:
        a = analyze_irrational(model, at + ",L=1")
    except NotIrrational:
        return  # every tangent rational (0, +-pi/2): the rational path's business
    assert a.numbers.as_dict() == reference_numbers(name, chosen)


def test_rational_configurations_and_transcendental_angles_are_refused():
    model = load_model("paper-case1-hard")
    with pytest.raises(NotIrrational):
        analyze_irrational(model, "q1=pi/2,q2=0")
    with pytest.raises(ConfigurationError, match="not exact"):
        analyze_irrational(model, "q1=1")


def test_cli_analyze_at_an_irrational_witness():
    result = runner.invoke(app, ["analyze", "paper-case1-hard", "--at",
                                 "q1=-5*pi/6,q2=5*pi/6,L=1"])
    assert result.exit_code == 0, result.output
    assert "Nm = 3  Nc = 3  Ni = 3  Nr = 0  Ng = 3  Nd = 4  Nh = 1" in result.stdout
    assert "alpha = -2 - sqrt(3), a root of alpha**2 + 4*alpha + 1" in result.stdout
    data = json.loads(runner.invoke(app, ["analyze", "paper-case1-hard", "--at",
                                          "q1=-5*pi/6,q2=5*pi/6", "--json"]).stdout)
    assert data["numbers"]["Ni"] == 3
    assert data["blocks"] == {"C11": None, "C12": None, "C22": None, "C23": None}
    assert data["field"]["tangents"] == {"q1": "-2 - sqrt(3)", "q2": "sqrt(3) + 2"}


def test_cli_transcendental_angle_is_one_clear_error():
    result = runner.invoke(app, ["analyze", "paper-case1-hard", "--at", "q1=1"])
    assert result.exit_code == 2
    assert result.stderr.startswith("coopkin: error: --at q1: angle '1' is not exact")
    assert result.stderr.count("\n") == 1


def test_rational_only_parts_are_a_package_error_naming_what_is_missing():
    a = coopkin_sym.load("paper-case1-hard").analyze("q1=-pi/6,q2=pi/6")
    for name in ("C12", "Q", "joint_velocities", "coordinated_factored"):
        with pytest.raises(NotAvailable) as info:
            getattr(a, name)
        assert str(info.value) == (
            f"{name} is not available at a configuration with irrational coordinates "
            "(q1=-pi/6,q2=pi/6, over Q(-2 + sqrt(3))): only the numbers, the motions "
            "behind Ni and Nr (.motions) and the finite mobility (.finite_mobility()) are "
            "computed there; the blocks, matrices and maps "
            "need a rational configuration (tan(q/2) rational, e.g. q = 2*atan(p/q))")
        assert isinstance(info.value, AttributeError) and not hasattr(a, name)
    with pytest.raises(NotAvailable) as info:
        _ = a.no_such_part
    assert str(info.value) == (
        "an analysis has no 'no_such_part': at irrational coordinates it has alpha, "
        "as_json, at, finite_mobility, joints, minimal_polynomial, model, motions, "
        "numbers, object_dim, "
        "passive, system, tangents, variables")
    assert "not available at a configuration" not in str(info.value)


def test_every_part_of_a_rational_analysis_is_there_or_not_available():
    """Each public attribute of a rational analysis (class or instance) is either an
    attribute of the irrational one or raises NotAvailable naming it."""
    from coopkin_sym.analysis.mobility import Analysis

    rational = coopkin_sym.load("paper-case1-hard").analyze("q1=pi/2,q2=pi/2")
    names = {n for n in (*dir(Analysis), *vars(rational)) if not n.startswith("_")}
    a = coopkin_sym.load("paper-case1-hard").analyze("q1=-pi/6,q2=pi/6")
    for name in sorted(names):
        if name in type(a).__dataclass_fields__ or name in vars(type(a)):
            continue
        with pytest.raises(NotAvailable, match=f"^{name} is not available"):
            getattr(a, name)


@pytest.mark.parametrize("name, free", [("paper-case2-hard", ["q2", "q5"]),
                                        ("allegro-hand-sphere", ["i1", "t2"]),
                                        ("panda-two-arm-box", ["l2", "r4"])])
def test_the_joint_nullspace_arm_by_arm_is_that_of_the_whole(name, free):
    """Over a number field (a quadratic in one free variable), the basis of N(Dt)
    found arm by arm is the reduced-echelon basis of the whole joint block."""
    import flint

    from coopkin_sym.analysis import kinematics
    from coopkin_sym.analysis.irrational import _joint_nullspace
    from coopkin_sym.exact.matrix import PolyMatrix
    from coopkin_sym.exact.quotient import Quotient

    model = load_model(name)
    kin = kinematics.build(model, model_configuration(model, free))
    rows = [kin.ring.clear_row(r) for r in kin.Q]
    t = kin.ring.zctx.gens()[0]
    quotient = Quotient(t**2 - 2 * t - 1, 0)          # t = 1 +- sqrt(2)
    dim = model.object_dim
    whole = PolyMatrix([r[dim:] for r in rows], len(model.joints), quotient).nullspace()
    ours = _joint_nullspace(model, rows, kin.row_contacts, quotient)
    assert len(ours) == len(whole) > 0
    assert all(str(a) == str(b) for u, v in zip(ours, whole, strict=True)
               for a, b in zip(u, v, strict=True))
    assert isinstance(ours[0][0], flint.fmpz_mpoly)


def model_configuration(model, free):
    from coopkin_sym.model.configuration import Configuration
    return Configuration.parse(model, None, free)
