"""Singularity loci, exactly: paper case 1 and a constructed codimension-2 example."""

from __future__ import annotations

import itertools
import json

import pytest
import sympy as sp
import yaml
from independent import (
    at_from_text,
    reference_analysis,
    reference_jacobians,
    reference_numbers_algebraic,
)
from support import shipped_locus, texts
from sympy.polys.matrices import DomainMatrix

import coopkin_sym
import coopkin_sym.model.examples
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.locus.search import LocusError, compute_locus
from coopkin_sym.model.builders import planar_hand
from coopkin_sym.present.remarks import remark_text, remark_texts
from coopkin_sym.present.sentences import component_sentences

CASE1_GENERIC = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
# both links on the contact line: the object gains a rotation about z (checked by
# hand in tests/analysis/test_mobility.py::test_singular_configuration_found_exactly)
CASE1_ON_LINE = {"Nm": 3, "Nc": 3, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 1}
# c1 and c2 at the same point: two point contacts make a spherical joint, so with the
# joints locked the object can still turn about that point (Ni = 3)
CASE1_COINCIDENT = {"Nm": 3, "Nc": 3, "Ni": 3, "Nr": 0, "Ng": 3, "Nd": 4, "Nh": 1}
ON_LINE = {("t_q1 - 1", "t_q2 - 1"), ("t_q1 - 1", "t_q2 + 1"), ("t_q1 + 1", "t_q2 - 1"),
           ("t_q1 + 1", "t_q2 + 1")}
COINCIDENT = ("t_q1 + t_q2", "t_q1**2 + 4*t_q1 + 1")


@pytest.fixture(scope="module")
def case1():
    return shipped_locus("paper-case1-hard")


def test_case1_finds_exactly_the_five_isolated_families(case1):
    # hand check: c1 = L(-sin q1, cos q1), c2 = L(1 - sin q2, cos q2).
    # * both links along the contact line x: q1, q2 = +-pi/2 (four points);
    # * c1 = c2: cos q1 = cos q2 and sin q2 - sin q1 = 1, so q2 = -q1 and
    #   sin q1 = -1/2: q1 = -pi/6 or -5pi/6, i.e. t1 = tan(q1/2) = -2 +- sqrt(3), the
    #   roots of t^2 + 4t + 1, with t2 = -t1. No rational point: decided over Q(sqrt 3).
    assert case1.generic == CASE1_GENERIC
    found = {tuple(sorted(texts(c.equations))): c for c in case1.components}
    assert set(found) == ON_LINE | {COINCIDENT}
    for key, c in found.items():
        assert c.kind == "isolated" and c.real and c.witness_checked
        if key in ON_LINE:
            assert c.numbers == CASE1_ON_LINE
            assert c.changes == {"Nm": (2, 3), "Nc": (2, 3), "Nh": (0, 1)}
    c = found[COINCIDENT]
    assert c.numbers == CASE1_COINCIDENT
    assert c.condition.text == "q1 = -5*pi/6, q2 = 5*pi/6 or q1 = -pi/6, q2 = pi/6"
    assert c.decided == Remark.of("decided_algebraic", variable="t_q1",
                                  minimal_polynomial="alpha**2 + 4*alpha + 1")
    assert remark_text(c.decided) == ("exact over Q(alpha), alpha = t_q1 a root of "
                                      "alpha**2 + 4*alpha + 1 (every conjugate point at once)")
    assert c.witness is None  # no rational point (a witness only when rational)
    w = c.algebraic_witness
    assert w["point"] == {"L": "1", "q1": "-5*pi/6", "q2": "5*pi/6"}
    assert w["root"] == "-2 - sqrt(3)" and w["root_of"] == "alpha**2 + 4*alpha + 1"
    assert component_sentences(c)[2] == ("Ni = 3: with every joint locked, the object can "
                                   "still turn freely about c1 (= c2), in every direction.")


def _ranks_over_the_algebraic_numbers(q: sp.Matrix) -> tuple[int, int, int]:
    """Ranks of Q, H G^T and H D in the smallest number field holding the entries."""
    def rank(m):
        return DomainMatrix.from_Matrix(m, extension=True).rank()
    return rank(q), rank(q[:, :6]), rank(q[:, 6:])


def test_case1_witnesses_are_confirmed_by_an_independent_analysis(case1):
    model = yaml.safe_load(coopkin_sym.model.examples.example_path(
        "paper-case1-hard").read_text())
    conditions = set()
    for c in case1.components:
        if c.witness is not None:
            assert set(c.witness) == {"q1", "q2", "L"}
            assert c.witness["q1"] in ("pi/2", "-pi/2")
            assert c.witness["q2"] in ("pi/2", "-pi/2")
            ref = reference_analysis(model, at_from_text(model, ",".join(
                f"{k}={v}" for k, v in c.witness.items())))
            assert {k: ref[k] for k in c.numbers} == c.numbers
            conditions.add(c.condition.text)
            continue
        # the irrational witness, and the other real point of the family, in radicals
        for q1, q2 in ((-5 * sp.pi / 6, 5 * sp.pi / 6), (-sp.pi / 6, sp.pi / 6)):
            ref = reference_analysis(model, {"q1": (sp.cos(q1), sp.sin(q1)),
                                             "q2": (sp.cos(q2), sp.sin(q2)), "L": 1})
            rq, rg, rd = _ranks_over_the_algebraic_numbers(ref["Q"])
            assert (rq, rg, rd) == (5, 3, 2)          # Nm = 8 - 5, Ni = 6 - 3, Nr = 0
            assert c.numbers["Nm"] == 8 - rq and c.numbers["Ni"] == 6 - rg
    assert "q1 = -pi/2, q2 = -pi/2" in conditions


def test_case1_drops_non_real_factors_and_leaves_nothing_unexplored(case1):
    assert Remark.of("no_real_points", polynomial="t_q1**2 + 1") in case1.dropped
    assert "t_q1**2 + 1 = 0 (no real points)" in remark_texts(case1.dropped)
    assert case1.unexplored == []
    assert Remark.of("uniform_scaling", parameter="L") in case1.notes
    assert any("L = 1" in n for n in remark_texts(case1.notes))


def test_float_rank_tests_fail_near_the_locus_with_rescaled_lengths(case1):
    summary = case1.float_summary()
    assert summary["false_singular"] > 0
    bad = [(c, f) for c in case1.components for f in c.float_checks if not f.agree]
    # every disagreement is 1e-12 rad from a singular configuration, lengths rescaled:
    # numpy calls a regular configuration singular, with the numbers of the component
    assert bad and all(f.distance == 1e-12 and f.scale in ("L=1/1000", "L=1000")
                       for _, f in bad)
    # floats see motions that are not there (larger Nm or Ni), mostly the component's
    assert all(f.exact == CASE1_GENERIC for _, f in bad)
    assert all(f.float["Nm"] > 2 or f.float["Ni"] > 1 for _, f in bad)
    assert sum(f.float == c.numbers for c, f in bad) >= len(bad) - 1
    assert len(bad) == summary["false_singular"] == 6
    # at the singular configurations themselves floats agree
    assert all(f.agree for c in case1.components for f in c.float_checks if f.distance == 0)


def test_json_contract(case1):
    data = json.loads(json.dumps(case1.to_json()))
    assert data["generic"] == CASE1_GENERIC
    for comp in data["components"]:
        assert {"equations", "numbers", "witness", "real"} <= set(comp)
        assert isinstance(comp["equations"], list) and comp["real"] is True


TWO_FINGERS = {
    "name": "two planar 2R fingers", "parameters": ["L"],
    "arms": [
        {"name": "f1", "joints": [
            {"name": "a1", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]},
            {"name": "a2", "type": "revolute", "axis": [0, 0, 1], "point": [0, "L", 0]}]},
        {"name": "f2", "joints": [
            {"name": "b1", "type": "revolute", "axis": [0, 0, 1], "point": ["3*L", 0, 0]},
            {"name": "b2", "type": "revolute", "axis": [0, 0, 1],
             "point": ["3*L", "L", 0]}]}],
    "contacts": [
        {"name": "c1", "link": "f1/2", "point": [0, "2*L", 0], "normal": [1, 0, 0],
         "model": "hard"},
        {"name": "c2", "link": "f2/2", "point": ["3*L", "2*L", 0], "normal": [-1, 0, 0],
         "model": "hard"}]}


def test_recursion_finds_the_codimension_two_drop():
    locus = compute_locus(coopkin_sym.load(TWO_FINGERS), max_depth=2)
    by_eqs = {tuple(texts(c.equations)): c for c in locus.components}
    # one finger stretched straight: it can no longer move its tip along itself
    a2 = by_eqs[("t_a2",)]
    assert a2.kind == "hypersurface" and a2.condition.text == "a2 = 0"
    assert a2.changes == {"Nc": (4, 3), "Nr": (0, 1), "Nd": (2, 3)}
    # both stretched: found inside the first component (depth 1, codimension 2)
    both = by_eqs[("t_a2", "t_b2")]
    assert both.depth == 1 and both.parent == locus.components.index(a2)
    assert both.changes == {"Nc": (4, 2), "Nr": (0, 2), "Nd": (2, 4)}
    # and deeper still: both stretched along the contact line (isolated, depth 2)
    t_chart = [c for c in locus.components if not any(e.startswith("s_") for e in
                                                      texts(c.equations))]
    deepest = [c for c in t_chart if c.depth == 2]
    assert len(deepest) == 5 and all(c.numbers["Nm"] == 5 for c in deepest)
    # ... and both stretched with the tips at one point: tip1 = 2L(-sin a1, cos a1),
    # tip2 = (3L, 0) + 2L(-sin b1, cos b1), so b1 = -a1 and sin a1 = -3/4, i.e.
    # 3 t^2 + 8 t + 3 = 0 for t = tan(a1/2): irrational, Ni 1 -> 3 as in case 1
    (tips,) = [c for c in deepest if c.witness is None]
    assert texts(tips.equations) == ["t_a2", "t_b2", "3*t_a1**2 + 8*t_a1 + 3", "t_a1 + t_b1"]
    assert tips.changes["Ni"] == (1, 3) and tips.witness_checked
    assert tips.algebraic_witness["point"]["a1"] == "-2*atan(sqrt(7)/3 + 4/3)"
    # the approximations shown are the exact values to 12 digits
    approx = tips.algebraic_witness["approx"]
    assert set(approx) == {"a1", "a2", "b1", "b2"}      # the free joints (L is fixed)
    for name, text in approx.items():
        exact = sp.sympify(tips.algebraic_witness["point"][name]).evalf(30)
        assert text == f"{float(exact):.12g}"
    # q = pi, outside the t chart: the finger folded back is singular too, alone and
    # with the other finger folded back (both at once: Nr 2, as both stretched); the
    # sets with a1 or b1 at pi lie in these (their equations do not involve a1, b1)
    assert {c.condition.text for c in locus.components if c.kind == "chart"} == {
        "a2 = pi", "b2 = pi", "a2 = pi, b2 = pi"}
    (folded,) = [c for c in locus.components if texts(c.equations) == ["s_a2", "s_b2"]]
    assert folded.changes == both.changes
    # one folded back, the other stretched, and both along the contact line
    (mixed,) = [c for c in locus.components if texts(c.equations) == ["s_a2", "t_b2"]]
    assert mixed.changes == both.changes and mixed.witness == {
        "a1": "2*atan(1/2)", "a2": "pi", "b1": "2*atan(1/2)", "b2": "0", "L": "1"}
    inside = [c for c in locus.components if c.parent == locus.components.index(mixed)]
    assert {c.condition.text for c in inside} == {
        f"a2 = pi, b2 = 0, a1 = {x}, b1 = {y}" for x in ("pi/2", "-pi/2")
        for y in ("pi/2", "-pi/2")}
    assert all(c.numbers["Nm"] == 5 for c in inside)
    assert all(c.witness_checked for c in locus.components)
    assert all(c.real == (c.witness is not None or c.algebraic_witness is not None)
               for c in locus.components)


def test_max_depth_bounds_the_search_and_says_so():
    locus = compute_locus(coopkin_sym.load(TWO_FINGERS), max_depth=0)
    assert all(c.depth == 0 for c in locus.components)
    deeper = [u for u in locus.unexplored if u.kind == "deeper_not_explored"]
    assert deeper and all(u["reason"] == "max_depth" and u["bound"] == 0 for u in deeper)
    assert any("max depth 0" in u for u in remark_texts(locus.unexplored))


def test_a_locus_needs_a_free_joint():
    with pytest.raises(LocusError, match="free joint"):
        compute_locus(coopkin_sym.load("paper-case1-hard"), at="q1=0,q2=0")


# --- curved components and irrational points -------------------------------------------


def test_function_field_rank_agrees_with_the_parametrization():
    """Case 1 soft/hard has a hypersurface linear in t_q2 only: its numbers by
    substitution (t_q2 = ...) and by ranks modulo the polynomial in t_q1 (degree 2,
    the function-field route used for curved components) agree."""
    from coopkin_sym.analysis import kinematics
    from coopkin_sym.analysis.mobility import numbers_modulo
    from coopkin_sym.exact.quotient import Quotient
    from coopkin_sym.model.configuration import Configuration

    system = coopkin_sym.load("paper-case1-soft-hard")
    locus = compute_locus(system, max_depth=0)
    curve = "t_q1**2*t_q2 - t_q1**2 + 2*t_q1*t_q2 + 2*t_q1 - t_q2 + 1"
    (comp,) = [c for c in locus.components if texts(c.equations) == [curve]]
    assert comp.decided == Remark.of("decided_function_field")
    config = Configuration.parse(system.model, "L=1", free=["q1", "q2"])
    kin = kinematics.build(system.model, config)
    rows = [kin.ring.clear_row(r) for r in kin.Q]
    t1, t2 = kin.ring.zctx.gens()
    f = t1**2 * t2 - t1**2 + 2 * t1 * t2 + 2 * t1 - t2 + 1
    k = kin.ring.names.index("t_q1")
    assert f.degrees()[k] == 2
    numbers = numbers_modulo(rows, system.model, kin.row_contacts, Quotient(f, k))
    assert numbers.as_dict() == comp.numbers
    assert comp.changes == {"Nm": (1, 2), "Nc": (1, 2), "Ni": (0, 1), "Ng": (1, 2),
                            "Nh": (0, 1)}
    # and a curve through the four singular points is generic almost everywhere on it
    circle = Quotient(t1**2 + t2**2 - 2, k)
    assert numbers_modulo(rows, system.model, kin.row_contacts, circle).as_dict() == \
        locus.generic


@pytest.fixture(scope="module")
def three_fingers():
    model = planar_hand(3, 3)
    return model, compute_locus(coopkin_sym.load(model))


@pytest.mark.slow  # 15 to 45 s: left out of the quick suite (-m 'not slow')
def test_planar_three_finger_hand_finds_each_finger_stretched(three_fingers):
    model, locus = three_fingers
    assert locus.generic == {"Nm": 6, "Nc": 3, "Ni": 0, "Nr": 3, "Ng": 3, "Nd": 3, "Nh": 0}
    # each intersection follows the component it was found in (canonical order)
    assert sorted(c.depth for c in locus.components) == [0, 0, 0, 1, 1, 1]
    assert all(c.parent is not None and c.parent < k
               for k, c in enumerate(locus.components) if c.depth == 1)
    top = [c for c in locus.components if c.depth == 0]
    # two fingers stretched at once: the intersections, over Q(alpha, beta)
    pairs = [c for c in locus.components if c.depth == 1]
    assert {tuple(sorted({e.split("*")[1].split("_")[1] for e in texts(c.equations)
                          if "*t_f" in e})) for c in pairs} == {
        ("f1", "f2"), ("f1", "f3"), ("f2", "f3")}
    for c in pairs:
        assert c.changes == {"Nc": (3, 1), "Nr": (3, 5), "Nd": (3, 5)}
        assert c.witness_checked and c.decided == Remark.of("decided_joined_fields", fields=2)
    fingers = [{e.split("_")[1] for e in texts(c.equations) for e in [e] if "t_f" in e}
               for c in top]
    assert sorted(next(iter(f)) for f in fingers) == ["f1", "f2", "f3"]
    for f, c in zip(fingers, top, strict=True):
        # a finger whose tip and joints 2, 3 line up: codimension 2, irrational angles
        (finger,) = f
        names = {f"t_{finger}_2", f"t_{finger}_3"}
        assert c.kind == "subvariety" and c.real
        assert c.changes == {"Nc": (3, 2), "Nr": (3, 4), "Nd": (3, 4)}
        assert c.witness is None and c.witness_checked
        assert set(c.algebraic_witness["point"]) == {j["name"] for a in model["arms"]
                                                      for j in a["joints"]} | {"L"}
        assert len(c.condition.alternatives) == 4      # four real points per finger
        syms = sp.symbols(sorted(names))
        eqs = [sp.sympify(e, locals={str(s): s for s in syms}) for e in texts(c.equations)]
        assert set().union(*(e.free_symbols for e in eqs)) == set(syms)
    # what is not decided is said, with the reason: only families too large to reduce
    # modulo (the contact points in line, HG^T: a hypersurface of 12824 terms)
    undecided = [u for u in remark_texts(locus.unexplored) if "not decided" in u]
    assert all("ranks modulo a polynomial of more than 3000 terms" in u for u in undecided)


@pytest.mark.slow  # its fixture, the 3x3 hand's locus, takes 15 to 70 s: run by .ci/run
def test_three_finger_components_are_where_an_independent_jacobian_drops(three_fingers):
    """Independent check: the reference H D of finger 1 (4x4 transforms, SymPy) at
    symbolic angles has all its 2 x 2 minors in the ideal of the component's equations,
    while its generic rank is 2."""
    model, locus = three_fingers
    t2, t3 = sp.symbols("t_f1_2 t_f1_3")

    def circle(t):
        return (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)

    ref = reference_jacobians(model, {"f1_2": circle(t2), "f1_3": circle(t3), "L": 1})
    block = ref["HD"][0:3, 0:3]
    minors = [sp.numer(sp.together(block.extract(list(r), list(c)).det()))
              for r in itertools.combinations(range(3), 2)
              for c in itertools.combinations(range(3), 2)]
    assert any(sp.expand(m) != 0 for m in minors)       # rank 2 at generic angles
    (comp,) = [c for c in locus.components if "t_f1_2" in texts(c.equations)[0] and not c.depth]
    basis = sp.groebner([sp.sympify(e, locals={"t_f1_2": t2, "t_f1_3": t3})
                         for e in texts(comp.equations)], t2, t3, order="lex")
    assert all(basis.reduce(sp.expand(m))[1] == 0 for m in minors)


def test_two_fingers_tips_together_is_found_as_a_two_dimensional_family():
    """Codimension 2 in four variables, not inside any hypersurface: the two fingertips
    at one point (any point both reach). Solved over the field of two of the angles;
    checked independently at its irrational witness (radicals)."""
    locus = compute_locus(coopkin_sym.load(TWO_FINGERS), max_depth=0)
    (tips,) = [c for c in locus.components if c.kind == "subvariety"
               and not any(e.startswith("s_") for e in texts(c.equations))]
    assert tips.depth == 0 and len(texts(tips.equations)) == 2
    assert tips.changes == {"Nm": (4, 5), "Nc": (4, 5), "Ni": (1, 3), "Ng": (1, 3),
                            "Nh": (0, 1)}
    assert tips.witness is None and tips.witness_checked
    point = tips.algebraic_witness["point"]
    cs = {}
    for joint in ("a1", "a2", "b1", "b2"):
        t = sp.tan(sp.sympify(point[joint]) / 2)
        cs[joint] = (sp.radsimp((1 - t**2) / (1 + t**2)), sp.radsimp(2 * t / (1 + t**2)))
    ref = reference_analysis(TWO_FINGERS, {**cs, "L": 1})
    assert sp.simplify(ref["points"]["c1"] - ref["points"]["c2"]) == sp.zeros(3, 1)
    rq, rg, _ = _ranks_over_the_algebraic_numbers(ref["Q"])
    assert 6 - rg == tips.numbers["Ni"] == 3 and 10 - rq == tips.numbers["Nm"]
    # the equations vanish there, exactly
    syms = {f"t_{j}": sp.tan(sp.sympify(point[j]) / 2) for j in cs}
    for eq in texts(tips.equations):
        expr = sp.sympify(eq, locals={n: sp.Symbol(n) for n in syms}).subs(
            {sp.Symbol(n): v for n, v in syms.items()})
        assert sp.simplify(sp.radsimp(expr)) == 0


@pytest.mark.slow  # about 2.5 min: left out of the quick suite (-m 'not slow')
def test_irrational_witnesses_reanalyzed_from_their_text():
    """Each algebraic witness, read back from its --at text by the independent
    number-field path (fresh kinematics, a primitive element), has the reported
    numbers."""
    from coopkin_sym.analysis.irrational import analyze_irrational

    for model in ("paper-case1-hard", TWO_FINGERS, "paper-case2-hard"):
        system = coopkin_sym.load(model)
        locus = compute_locus(system, max_depth=1)
        checked = 0
        for c in locus.components:
            w = c.algebraic_witness
            if w is None or "CRootOf" in str(w["point"]):
                continue
            prismatic = {j.name for j in system.model.joints if j.type == "prismatic"}
            if any("sqrt" in w["point"][j] for j in prismatic if j in w["point"]):
                continue  # the number-field path takes rational displacements only
            again = analyze_irrational(system.model, w["point"])
            assert again.numbers.as_dict() == c.numbers, c.condition.text
            checked += 1
        assert checked >= 1


@pytest.mark.slow  # about 2.5 min: left out of the quick suite (-m 'not slow')
def test_case2_all_eight_joints_hand_checked():
    """Paper case 2, every joint free (one level of recursion).

    Robot s1 (axes along z): the contact lies on the axis of q3, so s1 is singular when
    the axes of q1, q2, q3 meet the plane in three collinear points: q2 = +-pi/2
    (hypersurfaces). Robot s2 (axes along x) works in the (y, z) plane with its axes at
    A = (L, L) (q6), B = (L, 2L) (q7), C = (0, 2L) (q8) and the contact at P = (L, L):
    A, B, C collinear needs C - B = (-L, 0) turned by q7 = +-pi/2, and P on that line
    needs P - C = (L, -L) (at -pi/4) turned by q7 + q8 to +-pi/2: q8 = pi/4 or -3pi/4,
    where tan(q8/2) = -1 +- sqrt(2) is irrational. Inside q2 = +-pi/2 both meet.
    The contact points meet (c1 = c2: x, y and z agree, codimension 3) where the object
    can turn about that point in every direction: Ni 1 -> 3.
    """
    model = yaml.safe_load(coopkin_sym.model.examples.example_path(
        "paper-case2-hard").read_text())
    locus = compute_locus(coopkin_sym.load("paper-case2-hard"), max_depth=1)
    one = {"Nc": (6, 5), "Nr": (2, 3), "Nd": (0, 1)}
    t_chart = [c for c in locus.components
               if not any(e.startswith("s_") for e in texts(c.equations))]
    by_depth = {d: [c for c in t_chart if c.depth == d] for d in (0, 1)}
    meet = {"Ni": (1, 3), "Ng": (1, 3)}
    assert sorted((c.kind, tuple(texts(c.equations))) for c in by_depth[0]
                  if c.changes == one) == [
        ("hypersurface", ("t_q2 + 1",)), ("hypersurface", ("t_q2 - 1",)),
        ("subvariety", ("t_q8**2 + 2*t_q8 - 1", "t_q7 + 1")),
        ("subvariety", ("t_q8**2 + 2*t_q8 - 1", "t_q7 - 1"))]
    contacts_meet = [c for c in by_depth[0] if c.changes != one]
    assert contacts_meet and all(c.changes == meet and c.kind == "subvariety"
                                 for c in contacts_meet)
    # the whole family: three equations, linear in q5 (x), in q4 (z), and y1 = y2
    assert any(len(texts(c.equations)) == 3 and texts(c.equations)[0].startswith("q5*")
               and texts(c.equations)[1].startswith("q4*") for c in contacts_meet)
    two = {"Nc": (6, 4), "Nr": (2, 4), "Nd": (0, 2)}
    both = {"Nc": (6, 5), "Ni": (1, 3), "Nr": (2, 3), "Ng": (1, 3), "Nd": (0, 1)}
    found = sorted(tuple(sorted(c.changes.items())) for c in by_depth[1])
    known = sorted([tuple(sorted(two.items()))] * 4 + [tuple(sorted(both.items()))] * 2)
    assert all(found.count(k) == known.count(k) for k in known)
    # anything else found there lies inside q2 = +-pi/2 and loses more
    for c in by_depth[1]:
        if tuple(sorted(c.changes.items())) not in known:
            assert texts(c.equations)[0] in ("t_q2 + 1", "t_q2 - 1")
            assert c.numbers["Nr"] > 3 and c.numbers["Ni"] == 3
    for c in locus.components:
        # a witness checked, or no real point found and none claimed
        assert c.witness_checked or (c.real_points == "undecided" and not c.real)
        if c.witness is None and c.changes in (one, two):  # irrational: the reference
            point = c.algebraic_witness["point"]
            at = {j: _cos_sin(v) for j, v in point.items()
                  if j.startswith("q") and j not in ("q4", "q5")}
            at.update({j: sp.sympify(point[j]) for j in ("q4", "q5")})
            assert reference_numbers_algebraic(model, {**at, "L": 1}) == c.numbers
    assert {c.condition.text for c in by_depth[0]
            if c.changes == one and c.kind == "subvariety"} == {
        "q7 = -pi/2, q8 = -3*pi/4 or q7 = -pi/2, q8 = pi/4",
        "q7 = pi/2, q8 = -3*pi/4 or q7 = pi/2, q8 = pi/4"}
    # joints at pi: no set of them changes a number by itself (q = pi is not special
    # for these robots), and what is found there has the numbers of the t chart's
    # families (the same robot in line, with a joint turned half a turn)
    at_pi = [c for c in locus.components if c not in t_chart]
    assert at_pi and not any(c.kind == "chart" for c in at_pi)
    in_t_chart = [c.changes for c in t_chart]
    assert all(c.changes in in_t_chart or (c.real_points == "undecided" and not c.real)
               for c in at_pi)


def _cos_sin(angle: str) -> tuple[sp.Expr, sp.Expr]:
    """Exact ``(cos q, sin q)`` from the tangent half-angle (radicals stay radicals)."""
    if angle == "pi":
        return sp.Integer(-1), sp.Integer(0)
    t = sp.radsimp(sp.tan(sp.sympify(angle) / 2))
    return sp.radsimp((1 - t**2) / (1 + t**2)), sp.radsimp(2 * t / (1 + t**2))


# --- families that dividing rows by their content used to hide; q = pi in every set ----


def test_content_of_a_row_is_a_candidate_case1_complete_hard():
    """Paper case 1 with c1 complete and c2 hard: where q2 = +-pi/2 (any q1) c2 lies on
    the line through both base joints and the numbers change (Nm 0 -> 1, Nh 1 -> 2).
    The rank drop there is the content of a row after constant pivots."""
    system = coopkin_sym.load("paper-case1-complete-hard")
    locus = compute_locus(system)
    by_eqs = {tuple(texts(c.equations)): c for c in locus.components}
    for eq, angle in (("t_q2 - 1", "pi/2"), ("t_q2 + 1", "-pi/2")):
        comp = by_eqs[(eq,)]
        assert comp.kind == "hypersurface" and comp.condition.text == f"q2 = {angle}"
        assert comp.changes == {"Nm": (0, 1), "Nc": (0, 1), "Nh": (1, 2)}
        assert comp.witness_checked and comp.real
    # a direct analysis anywhere on the family agrees (q1 = 0 and a generic q1)
    for q1 in ("0", "2*atan(2/7)", "pi"):
        numbers = system.analyze(at=f"q1={q1},q2=pi/2").numbers.as_dict()
        assert numbers == by_eqs[("t_q2 - 1",)].numbers


def test_two_fingers_with_bases_fixed_find_every_drop_q_pi_included():
    """The two fingers with a1 = b1 = 0: each finger straight (t = 0) or folded back
    (q = pi), and every combination of the two, with the numbers a direct analysis
    gives at each point."""
    system = coopkin_sym.load(TWO_FINGERS)
    locus = compute_locus(system, at="a1=0,b1=0")
    assert locus.generic == {"Nm": 4, "Nc": 4, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 2, "Nh": 0}
    one = {"Nm": 4, "Nc": 3, "Ni": 1, "Nr": 1, "Ng": 1, "Nd": 3, "Nh": 0}
    two = {"Nm": 4, "Nc": 2, "Ni": 1, "Nr": 2, "Ng": 1, "Nd": 4, "Nh": 0}
    assert {(c.condition.text, tuple(sorted(c.numbers.items()))) for c in locus.components} == {
        (cond, tuple(sorted(n.items()))) for cond, n in (
            ("a2 = 0", one), ("b2 = 0", one), ("a2 = pi", one), ("b2 = pi", one),
            ("a2 = 0, b2 = 0", two), ("a2 = pi, b2 = 0", two), ("b2 = pi, a2 = 0", two),
            ("a2 = pi, b2 = pi", two))}
    assert locus.unexplored == []
    for a2 in ("0", "pi", "2*atan(1/3)"):
        for b2 in ("0", "pi", "2*atan(-1/2)"):
            numbers = system.analyze(at=f"a1=0,b1=0,a2={a2},b2={b2}").numbers.as_dict()
            stretched = sum(v in ("0", "pi") for v in (a2, b2))
            assert numbers == (locus.generic, one, two)[stretched]


def test_no_real_zeros_is_a_proof_or_nothing():
    import flint

    from coopkin_sym.analysis.locus.algebra import no_real_zeros

    ctx = flint.fmpz_mpoly_ctx.get(("a", "b", "c"), "lex")
    a, b, c = ctx.gens()
    # positive definite in one variable for every value of the other: no real zero
    f = (3*a**2*b**2 - 2*a**2*b + 3*a**2 + 2*a*b**2 + 2*a + 3*b**2 - 2*b + 3)
    assert no_real_zeros(f) and no_real_zeros(a**2 + b**2 + c**2 + 1)
    assert no_real_zeros(ctx.constant(7)) and no_real_zeros(b**4 + a**2 + 2)
    # real zeros (a point, a curve, odd degree): never claimed empty
    for g in (a**2 + b**2, a**2 + b**2 - 1, a**3 + b + 5, a * b + 1, ctx.constant(0)):
        assert not no_real_zeros(g)


def test_factorization_answers_where_flint_cannot_sort_its_factors():
    """A random two-arm system whose locus needs a factorization that python-flint's
    ``factor`` cannot sort (OverflowError in its sort key): the fallback answers, and the
    factors multiply back to the polynomial."""
    import flint

    from coopkin_sym.exact.factoring import _factor_with_sympy, factor

    ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "lex")
    x, y = ctx.gens()
    p = 12 * (x**2 - y**2) * (x * y + 3) ** 2
    for content, factors in (factor(p), _factor_with_sympy(p)):
        product = ctx.constant(content)
        for f, e in factors:
            product *= f**e
        assert product == p or product == -p
        assert sorted(str(f) for f, _ in factors) == ["x + y", "x - y", "x*y + 3"]


def test_a_gcd_or_discriminant_too_large_for_flint_is_not_started(monkeypatch):
    """flint runs a gcd or a discriminant to its end once started: over their bounds
    they are not started. A gcd refused is said in the report (unless its caller has a
    safe way around it), and a discriminant refused proves nothing."""
    from types import SimpleNamespace

    import flint

    from coopkin_sym.analysis.locus import algebra

    zctx = flint.fmpz_mpoly_ctx.get(("a", "b"), "degrevlex")
    a, b = zctx.gens()
    ctx = SimpleNamespace(ring_names=("a", "b"), locus=SimpleNamespace(unexplored=[]))
    p, q = (a + b + 1) ** 3 * (a - b), (a + b + 1) * (a + 2) ** 3
    assert algebra.bounded_gcd(ctx, p, q) == a + b + 1
    monkeypatch.setattr(algebra, "GCD_TERMS", 3)
    assert algebra.bounded_gcd(ctx, p, q, report=False) is None
    assert ctx.locus.unexplored == []
    assert algebra.bounded_gcd(ctx, p, q) is None
    (remark,) = ctx.locus.unexplored
    assert remark.kind == "operation_too_large"
    assert dict(remark.facts)["operation"] == "gcd"
    assert algebra.bounded_gcd(ctx, p, zctx.constant(2)) == zctx.constant(1)  # small side
    f = 3*a**2*b**2 - 2*a**2*b + 3*a**2 + 2*a*b**2 + 2*a + 3*b**2 - 2*b + 3
    assert algebra.no_real_zeros(f)
    monkeypatch.setattr(algebra, "DISCRIMINANT_TERMS", 2)
    assert not algebra.no_real_zeros(f)



def test_a_resultant_that_would_outlast_the_time_left_is_not_started(monkeypatch):
    """Under a time bound, a resultant whose work (degrees, terms and coefficient bits)
    needs more than the time left is refused and said; without a bound it is taken."""
    from types import SimpleNamespace

    import flint

    from coopkin_sym.analysis.locus import algebra
    from coopkin_sym.exact import deadline

    zctx = flint.fmpz_mpoly_ctx.get(("a", "b"), "degrevlex")
    a, b = zctx.gens()
    ctx = SimpleNamespace(ring_names=("a", "b"), locus=SimpleNamespace(unexplored=[]))
    p, q = (2**90 * a**2 + 3 * b**2 - 1), (a - 7 * b**3 + 5)
    expected = p.resultant(q, "a")
    assert algebra.bounded_resultant(ctx, p, q, "a") == expected
    with deadline.time_limit(60):
        assert algebra.bounded_resultant(ctx, p, q, "a") == expected
        monkeypatch.setattr(algebra, "RESULTANT_WORK_RATE", 1)   # 1 unit of work a second
        assert algebra.bounded_resultant(ctx, p, q, "a") is None
    (remark,) = ctx.locus.unexplored
    facts = dict(remark.facts)
    assert remark.kind == "operation_too_slow" and facts["operation"] == "resultant"
    assert facts["variables"] == ("a", "b") and facts["left"] <= 60 < facts["seconds"]


def test_a_resultant_estimated_over_its_bound_is_not_started(monkeypatch):
    """With or without a time bound, a resultant estimated to take more than
    RESULTANT_SECONDS (flint cannot interrupt it) is refused and said; its work is
    decided from the sizes alone."""
    from types import SimpleNamespace

    import flint

    from coopkin_sym.analysis.locus import algebra
    from coopkin_sym.exact.sizes import resultant_work

    zctx = flint.fmpz_mpoly_ctx.get(("a", "b"), "degrevlex")
    a, b = zctx.gens()
    ctx = SimpleNamespace(ring_names=("a", "b"), locus=SimpleNamespace(unexplored=[]))
    p, q = (2**90 * a**2 + 3 * b**2 - 1), (a - 7 * b**3 + 5)
    work = resultant_work(p, q, 0)
    monkeypatch.setattr(algebra, "RESULTANT_WORK_RATE", work // 12)   # about 12 s
    assert algebra.bounded_resultant(ctx, p, q, "a") is None
    (remark,) = ctx.locus.unexplored
    assert remark.kind == "operation_over_bound"
    assert dict(remark.facts) == {"operation": "resultant", "variables": ("a", "b"),
                                  "seconds": 12, "bound": 10}
    monkeypatch.setattr(algebra, "RESULTANT_WORK_RATE", work // 9)    # about 9 s
    assert algebra.bounded_resultant(ctx, p, q, "a") == p.resultant(q, "a")


def test_linear_disjointness_over_its_degree_bound_is_not_claimed(monkeypatch):
    """Q(sqrt 2) and Q(sqrt 3) are linearly disjoint (degree 4 compositum); with the
    bound below 4 the resultant is not taken, and nothing is claimed."""
    from types import SimpleNamespace

    import flint

    from coopkin_sym.analysis.locus import algebra

    zctx = flint.fmpz_mpoly_ctx.get(("a", "b"), "degrevlex")
    a, b = zctx.gens()
    ctx = SimpleNamespace(ring_names=("a", "b"), locus=SimpleNamespace(unexplored=[]))
    assert algebra.linearly_disjoint(ctx, a**2 - 2, "a", b**2 - 3, "b")
    assert not algebra.linearly_disjoint(ctx, a**2 - 2, "a", b**2 - 8, "b")  # same field
    monkeypatch.setattr(algebra, "DISJOINT_DEGREE", 3)
    assert not algebra.linearly_disjoint(ctx, a**2 - 2, "a", b**2 - 3, "b")
