"""The search inside families with no rational parametrization (curved families):
the drops cut out there by the minors of each block over the family's function field,
where two families meet, the bounds of that search (size, time, degree of the points)
and the size guards before the flint calls that cannot be interrupted.

Each family below is written by hand (its equations, the variable solved linearly) in
a small system, and what the search finds inside it is checked exactly: equations,
numbers, witnesses, and the numbers at each witness by an independent analysis.
"""

from __future__ import annotations

import flint
import pytest
import sympy as sp
from random_systems import random_system
from support import shipped_locus, texts

import coopkin_sym
from coopkin_sym.analysis.irrational import analyze_irrational
from coopkin_sym.analysis.locus import algebra
from coopkin_sym.analysis.locus.context import Place
from coopkin_sym.analysis.locus.search import codimension, compute_locus, fields, search_context
from coopkin_sym.analysis.locus.search import curved as curved_search
from coopkin_sym.analysis.locus.search.curved import inside_curved
from coopkin_sym.analysis.locus.verify import verify_locus
from coopkin_sym.analysis.mobility import analyze, numbers_modulo
from coopkin_sym.exact.quotient import Quotient
from coopkin_sym.exact.substitution import split_linear, substitute_rows
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.present.remarks import remark_texts
from coopkin_sym.present.verification import summary_lines

#: Two soft fingers, three joints: with q3 = pi, the curved family F below has the
#: generic numbers, and two points of it have one more indeterminate motion (Ni 1).
THREE_JOINTS = {
    "name": "two soft fingers, three joints", "parameters": [],
    "arms": [{"name": "a1", "joints": [
                 {"name": "q1", "type": "revolute", "axis": [0, 0, 1], "point": [-1, 1, 0]},
                 {"name": "q2", "type": "revolute", "axis": [0, 0, 1], "point": [0, 1, 0]}]},
             {"name": "a2", "joints": [
                 {"name": "q3", "type": "revolute", "axis": [0, 0, 1], "point": [-2, 0, 0]}]}],
    "contacts": [
        {"name": "c1", "link": "a1/2", "point": [1, -2, 0], "normal": [0, 1, 0], "model": "soft"},
        {"name": "c2", "link": "a2/1", "point": [-1, -2, 0], "normal": [0, -1, 0],
         "model": "soft"}]}
F = "2*t_q1**2*t_q2**2 + t_q1**2*t_q2 - t_q1**2 - 6*t_q1*t_q2 - 2*t_q1 - t_q2**2 - t_q2 + 2"
GENERIC = {"Nm": 2, "Nc": 2, "Ni": 0, "Nr": 0, "Ng": 2, "Nd": 5, "Nh": 1}
NI_1 = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 3, "Nd": 5, "Nh": 1}


def _numbers_at(system, at: str) -> dict:
    return analyze(system.model, Configuration.parse(system.model, at)).numbers.as_dict()


def test_inside_a_curved_candidate_the_minors_give_its_points():
    """F = 0 (degree 2 in both variables, linear in none) has the generic numbers; the
    minors of H G^T over its function field vanish with F at two rational points, and
    the left nullspace of H D at a point of degree 4, where the arm's H D drops."""
    system = coopkin_sym.load(THREE_JOINTS)
    ctx, rows = search_context(system, at="q3=pi")
    assert ctx.ring_names == ("t_q1", "t_q2") and ctx.generic.as_dict() == GENERIC
    t1, t2 = ctx.ring.zctx.gens()
    f = 2*t1**2*t2**2 + t1**2*t2 - t1**2 - 6*t1*t2 - 2*t1 - t2**2 - t2 + 2
    assert numbers_modulo(rows, ctx.model, ctx.row_contacts, Quotient(f, 0)) == ctx.generic
    inside_curved(ctx, Place(rows=rows, equations=[F], point={}, depth=0, base=ctx.generic),
                  f, 0)
    found = [(texts(c.equations), c.numbers, c.decided.kind) for c in ctx.locus.components]
    assert found == [
        ([F, "2*t_q1 + 1", "t_q2 + 1"], NI_1, "decided_at_point"),
        ([F, "t_q1", "t_q2 + 2"], NI_1, "decided_at_point"),
        ([F, "t_q1**4 - 4*t_q1**3 - 34*t_q1**2 - 4*t_q1 + 1",
          "t_q1**3 - 4*t_q1**2 - 35*t_q1 + 6*t_q2"],
         {"Nm": 2, "Nc": 1, "Ni": 0, "Nr": 1, "Ng": 2, "Nd": 6, "Nh": 1},
         "decided_algebraic")]
    assert [c.witness.at_text() for c in ctx.locus.components[:2]] == [
        "q3=pi,q1=2*atan(-1/2),q2=-pi/2", "q3=pi,q1=0,q2=2*atan(-2)"]
    for c in ctx.locus.components[:2]:   # an independent analysis at each point
        assert _numbers_at(system, c.witness.at_text()) == NI_1
    assert ctx.locus.unexplored == []
    # the whole search at q3 = pi: the points, and the hypersurface where H D drops,
    # which holds the point of degree 4 with its numbers (not listed again)
    locus = compute_locus(system, at="q3=pi")
    assert sorted(texts(c.equations) for c in locus.components) == sorted([
        ["3*t_q2**2 + 2*t_q2 - 3"], [F, "2*t_q1 + 1", "t_q2 + 1"], [F, "t_q1", "t_q2 + 2"]])
    v = verify_locus(system, locus, max_points=400, lines=6, seed=0)
    assert v.ok, summary_lines(v)


#: Random system 85 at q1 = pi: the curve h = 0, t_q3 = -c0/c1 (Ni 1), where the
#: search found no rational parametrization; the grid point q2 = q4 = pi/2 has Ni 2.
H85 = "6*t_q2**2*t_q4**2 + 11*t_q2**2 + t_q2*t_q4**2 + t_q2 - 12*t_q4**2 - 7"
Y85 = ("-6*t_q2*t_q4**2 - 11*t_q2 + 2*t_q3*t_q4**2 + 15*t_q3*t_q4 - 3*t_q3 + 7*t_q4**2 "
       "- 10*t_q4 - 8")
NI_2 = {"Nm": 4, "Nc": 4, "Ni": 2, "Nr": 0, "Ng": 4, "Nd": 4, "Nh": 2}


def _curve_85():
    system = coopkin_sym.load(random_system(85))
    ctx, rows = search_context(system, at="q1=pi")
    t2, t3, t4 = ctx.ring.zctx.gens()
    h = 6*t2**2*t4**2 + 11*t2**2 + t2*t4**2 + t2 - 12*t4**2 - 7
    y = -6*t2*t4**2 - 11*t2 + 2*t3*t4**2 + 15*t3*t4 - 3*t3 + 7*t4**2 - 10*t4 - 8
    k3 = ctx.ring_names.index("t_q3")
    c1, c0 = split_linear(y, k3)
    on = substitute_rows(rows, k3, c0, c1)
    base = numbers_modulo(on, ctx.model, ctx.row_contacts, Quotient(h, 0))
    place = Place(rows=on, equations=[H85, Y85], point={"t_q3": (c0, c1)}, depth=0,
                  base=base, charts=(c1,))
    return system, ctx, place, h


def test_inside_a_curve_of_codimension_two_the_minors_give_its_points():
    system, ctx, place, h = _curve_85()
    assert place.base.as_dict() == {"Nm": 4, "Nc": 4, "Ni": 1, "Nr": 0, "Ng": 3, "Nd": 4,
                                    "Nh": 2}
    inside_curved(ctx, place, h, 0)
    found = [(texts(c.equations)[2:], c.numbers) for c in ctx.locus.components]
    assert found == [
        (["23*t_q2 - 24", "6*t_q4 - 7"], NI_2),
        (["t_q2 - 1", "t_q4 - 1"], NI_2),
        (["553*t_q2**4 + 136*t_q2**3 - 1334*t_q2**2 - 152*t_q2 + 697",
          "553*t_q2**3 + 10090*t_q2**2 + 561*t_q2 + 3250*t_q4 - 8904"],
         {"Nm": 4, "Nc": 3, "Ni": 1, "Nr": 1, "Ng": 3, "Nd": 5, "Nh": 2})]
    assert all(texts(c.equations)[:2] == [H85, Y85] for c in ctx.locus.components)
    witnesses = [c.witness.at_text() for c in ctx.locus.components[:2]]
    assert witnesses == ["q1=pi,q2=2*atan(24/23),q3=2*atan(7/4),q4=2*atan(7/6)",
                         "q1=pi,q2=pi/2,q3=2*atan(2),q4=pi/2"]
    for at in witnesses:
        assert _numbers_at(system, at) == NI_2
    # where the curve meets 3 t_q2^2 - 2 t_q2 - 3 = 0 (H D of the first arm drops), two
    # values of t_q4 share each t_q2; in t_q4 + t_q2 they are separated, and none is
    # real: nothing is left undecided. Checked apart: on h = 0, t_q4^2 = -(11 t_q2^2 +
    # t_q2 - 7) / (6 t_q2^2 + t_q2 - 12), negative at both roots
    assert remark_texts(ctx.locus.unexplored) == []
    s2, s4, w = sp.symbols("t_q2 t_q4 w")
    square = sp.solve(sp.sympify(H85).subs(s4**2, w), w)[0]
    for root in sp.Poly(3 * s2**2 - 2 * s2 - 3, s2).real_roots():
        assert square.subs(s2, root).is_negative


def test_a_family_too_large_or_too_slow_to_search_inside_is_said(monkeypatch):
    _, ctx, place, h = _curve_85()
    terms = curved_search.INSIDE_TERMS
    monkeypatch.setattr(curved_search, "INSIDE_TERMS", 5)
    inside_curved(ctx, place, h, 0)
    assert ctx.locus.components == []
    (said,) = remark_texts(ctx.locus.unexplored)
    assert said.startswith(f"inside {H85}, {Y85} (enclosing numbers there): deeper drops "
                           "not searched (a family with no rational parametrization and ")
    assert said.endswith(" terms: more than 5)")
    _, ctx, place, h = _curve_85()
    monkeypatch.setattr(curved_search, "INSIDE_TERMS", terms)
    monkeypatch.setattr(curved_search, "INSIDE_STEPS", 0)
    inside_curved(ctx, place, h, 0)
    assert ctx.locus.components == [] and ctx.deferred == []
    assert remark_texts(ctx.locus.unexplored) == [
        f"inside {H85}, {Y85} (enclosing numbers there): deeper drops searched within a "
        "work budget of 0 steps only (the bound of one such family): what was found by "
        "then is listed, the rest not searched"]


def _inside_with_budget(monkeypatch, steps: int):
    _, ctx, place, h = _curve_85()
    monkeypatch.setattr(curved_search, "INSIDE_STEPS", steps)
    inside_curved(ctx, place, h, 0)
    return ([texts(c.equations) for c in ctx.locus.components],
            remark_texts(ctx.locus.unexplored))


def test_the_budget_inside_a_family_cuts_at_the_same_place_every_time(monkeypatch):
    """The bound is work, not seconds: the same budget gives the same locus (on any
    machine, under any load), and a larger one finds all a smaller one found."""
    full, _ = _inside_with_budget(monkeypatch, 10**9)
    assert len(full) == 3
    budgets = (50, 400, 1500, 4000)
    found = []
    for steps in budgets:
        first, second = (_inside_with_budget(monkeypatch, steps) for _ in range(2))
        assert first == second
        found.append(first[0])
        cut = any("work budget" in r for r in first[1])
        assert cut == (first[0] != full)
    assert any(comps != full for comps in found)   # some budget cuts this family
    for smaller, larger in zip(found, found[1:], strict=False):
        assert all(c in larger for c in smaller)
    assert all(c in full for comps in found for c in comps)


def test_points_of_higher_degree_are_not_decided_there_and_said(monkeypatch):
    _, ctx, place, h = _curve_85()
    monkeypatch.setattr(curved_search, "INSIDE_DEGREE", 3)
    inside_curved(ctx, place, h, 0)
    assert [texts(c.equations)[2:] for c in ctx.locus.components] == [
        ["23*t_q2 - 24", "6*t_q4 - 7"], ["t_q2 - 1", "t_q4 - 1"]]
    assert ("the real points where 553*t_q2**4 + 136*t_q2**3 - 1334*t_q2**2 - 152*t_q2 "
            "+ 697 = 0 (degree 4) inside a family with no rational parametrization: "
            "numbers not decided (points of degree up to 3 are decided there)"
            in remark_texts(ctx.locus.unexplored))


def test_a_resultant_over_its_budget_is_not_computed_and_said(monkeypatch):
    _, ctx, place, h = _curve_85()
    inside_curved(ctx, place, h, 0)
    full = [texts(c.equations) for c in ctx.locus.components]
    _, ctx, place, h = _curve_85()
    monkeypatch.setattr(algebra, "RESULTANT_TERMS", 10)
    inside_curved(ctx, place, h, 0)
    # only what needs no resultant is found (a minor's factor solved alone)
    found = [texts(c.equations) for c in ctx.locus.components]
    assert len(found) < len(full) and all(c in full for c in found)
    said = remark_texts(ctx.locus.unexplored)
    assert said and all(s.startswith("a resultant in t_q2, t_q4 of about ") and s.endswith(
        "terms (more than 10, and it cannot be interrupted) was not computed: the sets it "
        "would have solved were not searched") for s in said)


def test_equations_in_one_variable_with_no_common_real_root_leave_nothing_to_solve():
    """Inside the curved family F154 (seed 154, q4 = 0), two minors are free of all but
    t_q3 and share no real root there: the set is empty, so nothing is listed as not
    solved; one with a real root left is still said."""
    system = coopkin_sym.load(random_system(154))
    ctx, rows = search_context(system, at="q4=0")
    t1, t2, t3 = ctx.ring.zctx.gens()
    f = (2*t1**2*t2**2*t3**2 - 2*t1**2*t2*t3**2 - 2*t1**2*t2 + t1**2*t3**2 - t1**2
         - 2*t1*t2**2*t3**2 - 2*t1*t2**2 - 2*t1*t2*t3**2 - 2*t1*t2 + 2*t1*t3**2 + 2*t1
         + t2**2*t3**2 - t2**2 + 2*t2*t3**2 + 2*t2 + 2*t3**2)
    place = Place(rows=rows, equations=[], point={}, depth=0)
    codimension.isolated(ctx, place, [[f, 8*t3**2 - 8, 12*t3**2 + 16*t3 - 12],
                                      [f, t3**2 + 1]])
    assert ctx.locus.components == [] and ctx.locus.unexplored == []
    codimension.isolated(ctx, place, [[f, t3**2 - 2, t1**3 - t2 - 5]])
    assert any(u.kind == "lower_dimensional_not_solved" for u in ctx.locus.unexplored)


def test_roots_in_one_variable_times_points_in_the_others_are_solved():
    """Inside a family at an irrational angle of one joint, the remaining minors can be
    its equation (in that joint alone) and equations free of it in two other
    variables: their zeros are the roots times the points, solved as such."""
    system = coopkin_sym.load(random_system(154))
    ctx, rows = search_context(system, at="q4=0")
    t1, t2, t3 = ctx.ring.zctx.gens()
    names = ["t_q1", "t_q2", "t_q3"]
    # t3 = +-sqrt(2) or 1, and (t1, t2) = (3, 2) or (3, 3)
    system_ = [(t3**2 - 2) * (t3 - 1), t1 - 3, t2**2 - 5 * t2 + 6]
    points, algebraic, unresolved = codimension._product_points(ctx, system_, names, None, 1)
    assert sorted(tuple(sorted((k, str(v)) for k, v in p.items())) for p in points) == [
        (("t_q1", "3"), ("t_q2", "2"), ("t_q3", "1")),
        (("t_q1", "3"), ("t_q2", "3"), ("t_q3", "1"))]
    assert sorted((x, str(h), sorted((k, str(v)) for k, v in values.items()))
                  for x, h, values, _eqs, _alpha in algebraic) == [
        ("t_q3", "t_q3^2 - 2", [("t_q1", "3"), ("t_q2", "2")]),
        ("t_q3", "t_q3^2 - 2", [("t_q1", "3"), ("t_q2", "3")])]
    assert unresolved == []
    # t2 = 0 times the points t1 = t3 = +-sqrt(2) (over the field of t1)
    _, algebraic, _ = codimension._product_points(ctx, [t3**2 - 2, t1 - t3, t2], names,
                                                  None, 1)
    assert [(x, str(h), values["t_q2"]) for x, h, values, _e, _a in algebraic] == [
        ("t_q1", "t_q1^2 - 2", 0)]
    # not of this form: no variable's equations stand apart from the others
    assert codimension._product_points(ctx, [t3**2 - 2, t1 - t3, t2 - t1], names,
                                       None, 1) is None


def test_drops_at_an_irrational_angle_times_rational_points_are_found():
    """Random system 392: inside the family 7 t_q4^2 - 2 t_q4 - 7 = 0, Nm rises to 3
    where q1 = 2 atan(3) or 2 atan(-1/3) and q3 = 2/5 (q2 free). These were said not
    solved before, and missed; found, they make the certificate complete."""
    from coopkin_sym.analysis.locus.certify import certify_locus
    system = coopkin_sym.load(random_system(392))
    locus = compute_locus(system, timeout=60)
    raised = {"Nm": 3, "Nc": 2, "Ni": 0, "Nr": 1, "Ng": 3, "Nd": 6, "Nh": 2}
    found = [c for c in locus.components if c.numbers == raised]
    assert len(found) == 2
    for q1, comp in zip(("2*atan(3)", "2*atan(-1/3)"), found, strict=True):
        assert f"q1 = {q1}, q3 = 2/5" in str(comp.condition)
        for q4 in ("2*atan(1/7 + 5*sqrt(2)/7)", "2*atan(1/7 - 5*sqrt(2)/7)"):
            at = f"q1={q1},q2=2*atan(5),q3=2/5,q4={q4}"
            assert analyze_irrational(system.model, at).numbers.as_dict() == raised
            off = f"q1={q1},q2=2*atan(5),q3=1/2,q4={q4}"
            assert analyze_irrational(system.model, off).numbers.as_dict() != raised
    assert certify_locus(system, locus, timeout=120).certified


def test_finitely_many_points_in_three_variables_are_solved_by_elimination():
    """q1 is eliminated by resultants, the points in (t2, t3) solved, then q1 at each
    point from the gcd of the equations there."""
    system = coopkin_sym.load(random_system(154))
    ctx, rows = search_context(system, at="q4=0")
    t1, t2, t3 = ctx.ring.zctx.gens()
    names = ["t_q1", "t_q2", "t_q3"]
    # t3^2 = 2, t2 = 1, and t1 t3 = 2 (t1 = sqrt(2) = t3) or t1 = t2 + 1 = 2 ...
    polys = [t3**2 - 2, (t2 - 1) * t3, t1 * t3 - 2 * t2]
    points, algebraic, unresolved = codimension._eliminated_points(ctx, polys, names,
                                                                   None, 1)
    assert points == [] and unresolved == []
    assert [(x, str(h), sorted((k, str(v)) for k, v in values.items()))
            for x, h, values, _e, _a in algebraic] == [
        ("t_q3", "t_q3^2 - 2", [("t_q1", "x"), ("t_q2", "1")])]     # t1 = t3
    # rational points, one with t1 free: t2 = t3 = 0 makes every equation vanish
    polys = [t2 * (t2 - 1), t3 * (t3 - 2), t1 * t2 - t3]
    points, algebraic, _ = codimension._eliminated_points(ctx, polys, names, None, 1)
    assert sorted(sorted((k, str(v)) for k, v in p.items()) for p in points) == [
        [("t_q1", "0"), ("t_q2", "1"), ("t_q3", "0")],
        [("t_q1", "2"), ("t_q2", "1"), ("t_q3", "2")],
        [("t_q2", "0"), ("t_q3", "0")]]
    assert algebraic == []
    # a curve (t1 = t2 = t3) is not finitely many points: left to the others
    assert codimension._eliminated_points(ctx, [t1 - t2, t2 - t3], names, None, 1) is None


def test_finitely_many_points_in_four_variables_are_solved_by_elimination():
    """Two eliminations: t4 = t1, t1 t2 = 1, t2 = +-2, and t3 = +-sqrt(3) (the last
    equation is (t3^2 - 3) (t4 - t1 + 1)); the order that determines every point from
    one root is the one kept. A curve (t2 = t3 free) is not points."""
    system = coopkin_sym.load(random_system(154))
    ctx, _ = search_context(system)
    t1, t2, t3, t4 = ctx.ring.zctx.gens()
    names = list(ctx.ring_names)
    polys = [t4 - t1, t1 * t2 - 1, t2**2 - 4, (t3**2 - 3) * (t4 - t1 + 1)]
    points, algebraic, unresolved = codimension._eliminated_points(ctx, polys, names,
                                                                   None, 1)
    assert points == [] and unresolved == []
    found = sorted((x, str(h), sorted((k, str(v)) for k, v in values.items()))
                   for x, h, values, _e, _a in algebraic)
    assert found == [
        ("t_q3", "t_q3^2 - 3", [("t_q1", "(-1/2)"), ("t_q2", "-2"), ("t_q4", "-1/2")]),
        ("t_q3", "t_q3^2 - 3", [("t_q1", "1/2"), ("t_q2", "2"), ("t_q4", "1/2")])]
    for _x, _h, _values, eqs, _a in algebraic:     # the equations hold at the points
        assert len(eqs) == 4
    assert codimension._eliminated_points(ctx, [t4 - t1, t2 - t3, t1**2 - 2], names,
                                          None, 1) is None


def _rises_exactly_there(system, raised: dict, places) -> None:
    """For each ``(at, off)``: the exact numbers at ``at`` are ``raised`` (checked by
    the analysis over the field of the angles, apart from the search), at ``off``
    they are not."""
    for at, off in places:
        assert analyze_irrational(system.model, at).numbers.as_dict() == raised, at
        assert analyze_irrational(system.model, off).numbers.as_dict() != raised, off


def test_isolated_points_at_an_irrational_angle_are_found_and_certified():
    """Random system 395: where q1 = 0, q2 and q3 each 0 or pi and tan(q4/2) =
    2 +- sqrt(5), Nm is 7 (6 around): points of a system in three variables, said not
    solved and missed before; found, each pair of conjugate points one isolated
    component (also the one inside a set held at q2 = q3 = pi), the certificate is
    complete."""
    from coopkin_sym.analysis.locus.certify import certify_locus
    system = coopkin_sym.load(random_system(395))
    locus = compute_locus(system, timeout=60)
    top = {"Nm": 7, "Nc": 4, "Ni": 3, "Nr": 3, "Ng": 1, "Nd": 3, "Nh": 1}
    points = [c for c in locus.components if c.kind == "isolated" and c.numbers == top]
    assert len(points) == 4 and {c.chart for c in points} == {(), ("q2",), ("q3",),
                                                             ("q2", "q3")}
    _rises_exactly_there(system, top, [
        (at, at.replace("q1=0", "q1=1/3")) for q2 in ("0", "pi") for q3 in ("0", "pi")
        for q4 in ("2*atan(2 + sqrt(5))", "2*atan(2 - sqrt(5))")
        for at in [f"q1=0,q2={q2},q3={q3},q4={q4}"]])
    assert certify_locus(system, locus, timeout=120).certified


def test_sets_with_one_irrational_coordinate_are_searched_inside():
    """Random system 408: inside the family t_q4^2 + 2 t_q4 - 1 = 0 (q4 = pi/4 or
    -3 pi/4), the sets q1 = -q4 and q1 = q4 + pi (tan(q1/2) = tan(q4/2) + 2) have the
    family's numbers, and inside them Nm rises to 3 where q3 = +-pi/2 (q2 free). The
    sets have no rational parametrization (their coordinates lie in Q(sqrt(2))): they
    were said not searched, and the rise was missed; written as a family in q4 (the
    other coordinate a polynomial in it) they are searched like any curved family, and
    the certificate is complete."""
    from coopkin_sym.analysis.locus.certify import certify_locus
    system = coopkin_sym.load(random_system(408))
    locus = compute_locus(system, timeout=60)
    raised = {"Nm": 3, "Nc": 2, "Ni": 0, "Nr": 1, "Ng": 3, "Nd": 6, "Nh": 2}
    found = [c for c in locus.components if c.numbers == raised]
    # read in angles: the family's polynomials, which the values imply, left out
    assert sorted(c.condition.text for c in found) == sorted(
        f"q1 = -pi/4, q3 = {q3}, q4 = {q4a} or q1 = 3*pi/4, q3 = {q3}, q4 = {q4b}"
        for q4a, q4b in (("pi/4", "-3*pi/4"), ("-3*pi/4", "pi/4"))
        for q3 in ("-pi/2", "pi/2"))
    _rises_exactly_there(system, raised, [
        (f"q1={q1},q2=2*atan(5),q3={q3},q4={q4}", f"q1={q1},q2=2*atan(5),q3=pi/3,q4={q4}")
        for q4, q1s in (("pi/4", ("-pi/4", "3*pi/4")), ("-3*pi/4", ("3*pi/4", "-pi/4")))
        for q1 in q1s for q3 in ("pi/2", "-pi/2")])
    # q1 = q4 lies in the family too, with its numbers
    assert analyze_irrational(system.model, "q1=pi/4,q2=2*atan(5),q3=pi/2,q4=pi/4"
                              ).numbers.as_dict() != raised
    # the sets themselves are searched inside (a set deeper inside them, with a
    # coordinate of degree 4 in t_q3, may still have no rational parametrization)
    assert not any("no rational parametrization" in t
                   and t.split(" (")[0].endswith("t_q1 - t_q4 - 2")
                   for t in remark_texts(locus.unexplored))
    assert certify_locus(system, locus, timeout=120).certified


def test_a_family_recorded_in_the_t_chart_is_searched_inside_at_q_pi():
    """Random system 404: inside the family t_q4^2 - 11 t_q4 - 1 = 0, Nm rises to 3
    where q3 = 3/5 and q1 = 0, and also where q1 = pi. The family is recorded in the t
    chart; found again in the chart q1 = pi it is not recorded twice, but it is
    searched inside there: the drop at q1 = pi is found, nothing is said left out
    there, and the certificate proves the locus complete."""
    from coopkin_sym.analysis.locus.certify import certify_locus
    system = coopkin_sym.load(random_system(404))
    locus = compute_locus(system, timeout=60)
    raised = {"Nm": 3, "Nc": 2, "Ni": 0, "Nr": 1, "Ng": 4, "Nd": 7, "Nh": 3}
    found = sorted(str(c.condition).split(",")[0] for c in locus.components
                   if c.numbers == raised)
    assert found == ["q1 = 0", "q1 = pi"]
    assert not [r for r in locus.unexplored if r.kind == "pi_inside_not_searched"]
    _rises_exactly_there(system, raised, [
        (f"q1={q1},q2=2*atan(5),q3=3/5,q4={q4}", f"q1={q1},q2=2*atan(5),q3=1/2,q4={q4}")
        for q1 in ("0", "pi")
        for q4 in ("2*atan(11/2 + 5*sqrt(5)/2)", "2*atan(11/2 - 5*sqrt(5)/2)")])
    assert certify_locus(system, locus, timeout=120).certified


def test_a_family_is_written_in_a_coordinate_that_generates_its_field():
    """A point's coordinates given in a root x = 3 t_q4 of x^2 + 6 x - 9 (t_q4 = x/3,
    t_q1 = x/3 + 2) become the family t_q4^2 + 2 t_q4 - 1 = 0 with t_q1 = t_q4 + 2.
    Coordinates that each generate only part of the field (sqrt(2) and sqrt(3) apart,
    in Q(sqrt(2) + sqrt(3))) give a product family, two of them each a root of its
    own quadratic and the third written in both; two in one quadratic field give
    none."""
    system = coopkin_sym.load(random_system(408))
    ctx, rows = search_context(system)
    place = Place(rows=rows, equations=[], point={}, charts=(), depth=1)
    x = flint.fmpq_poly([0, 1])
    t4 = ctx.ring.zctx.gens()[ctx.ring_names.index("t_q4")]
    g = t4**2 + 6 * t4 - 9
    inside, (h, k) = fields.irrational_family(
        ctx, place, {"t_q4": x / 3, "t_q1": x / 3 + 2}, "t_q4", g, ["e"])
    assert (str(h), ctx.ring_names[k]) == ("t_q4^2 + 2*t_q4 - 1", "t_q4")
    f0, f1 = inside.point["t_q1"]
    assert (str(-f0), str(f1)) == ("t_q4 + 2", "1")
    assert inside.equations == ["e"]
    # x = sqrt(2) + sqrt(3): x^4 - 10 x^2 + 1; t_q4 = sqrt(2), t_q1 = sqrt(3)
    quartic = t4**4 - 10 * t4**2 + 1
    sqrt2, sqrt3 = (x**3 - 9 * x) / 2, (11 * x - x**3) / 2
    inside, (hs, ks) = fields.irrational_family(
        ctx, place, {"t_q4": sqrt2, "t_q1": sqrt3, "t_q3": (sqrt2 * sqrt3) % (
            x**4 - 10 * x**2 + 1)}, "t_q4", quartic, ["e"])
    # the first pair in the ring's order: sqrt 3 and sqrt 6, sqrt 2 = sqrt 3 sqrt 6 / 3
    assert [str(h) for h in hs] == ["t_q1^2 - 3", "t_q3^2 - 6"]
    assert [ctx.ring_names[k] for k in ks] == ["t_q1", "t_q3"]
    f0, f1 = inside.point["t_q4"]
    assert (str(-f0), str(f1)) == ("t_q1*t_q3", "3")
    assert set(inside.point) == {"t_q4"}
    assert fields.irrational_family(ctx, place, {"t_q4": sqrt2, "t_q1": 2 * sqrt2},
                                         "t_q4", quartic, ["e"]) is None



def test_points_sheared_into_one_field_are_solved_with_none_real():
    """Two coordinates x, y with y not determined by x (x = +-sqrt 2, y^2 = 3 or
    y^2 = -1): in z = y + x the real points are one field (z^4 - 10 z^2 + 1), and
    the system whose y is never real is solved too, with no point (an empty list, not
    the None of a system left unsolved: its points were said not decided)."""
    system = coopkin_sym.load(random_system(408))
    ctx, _rows = search_context(system)
    gens = dict(zip(ctx.ring_names, ctx.ring.zctx.gens(), strict=True))
    x, y = gens["t_q1"], gens["t_q2"]
    real = algebra.solve_sheared(ctx, [y**2 - 3, x**2 - 2], "t_q1", "t_q2")
    assert [(v, str(m)) for v, m, *_ in real] == [("t_q2", "t_q2^4 - 10*t_q2^2 + 1")]
    _v, m, values, equations, _alpha = real[0]
    z = flint.fmpq_poly([0, 1])
    g = algebra.univariate(ctx, m, "t_q2")
    assert (values["t_q1"] ** 2 - 2) % g == 0 and (values["t_q2"] ** 2 - 3) % g == 0
    assert (values["t_q1"] + values["t_q2"] - z) % g == 0
    assert algebra.solve_sheared(ctx, [y**2 + 1, x**2 - 2], "t_q1", "t_q2") == []

@pytest.mark.slow
@pytest.mark.parametrize("seed, point, numbers", [
    # a drop inside a curved family of the first level, inside a hypersurface linear in
    # q4, where it meets the family where Ni is 2
    (70, "q1=0,q2=-pi/2,q3=0,q4=-pi/2",
     {"Nm": 4, "Nc": 3, "Ni": 2, "Nr": 1, "Ng": 3, "Nd": 4, "Nh": 1}),
    # a point of a curve of codimension 2 at q1 = pi (above)
    (85, "q1=pi,q2=pi/2,q3=2*atan(2),q4=pi/2", NI_2),
    # inside q2 = pi/2, a curved set with the enclosing numbers holds curves where Ni is 1
    (101, "q1=0,q2=pi/2,q3=pi/2,q4=0",
     {"Nm": 3, "Nc": 2, "Ni": 1, "Nr": 1, "Ng": 3, "Nd": 5, "Nh": 1}),
    # a point of a curve of codimension 2 at q2 = pi
    (133, "q1=0,q2=pi,q3=-pi/2,q4=-pi/2", NI_2),
])
def test_drops_inside_curved_families_of_random_systems_are_found(seed, point, numbers):
    system = coopkin_sym.load(random_system(seed))
    assert _numbers_at(system, point) == numbers
    locus = compute_locus(system, timeout=300)
    v = verify_locus(system, locus, max_points=1500, lines=6, seed=seed)
    assert v.uncovered_total == 0, summary_lines(v)
    assert v.unsound == [], summary_lines(v)


def test_two_curved_families_in_disjoint_variables_meet_in_the_t_chart():
    """The five-bar's arms stretch at t_q2^2 + 2 t_q2 - 1 = 0 and t_q4^2 - 2 t_q4 - 1 = 0
    (q2 in {pi/4, -3pi/4}, q4 in {-pi/4, 3pi/4}), each a curved family. Where both hold,
    with q1 and q3 anywhere, rank H D falls by two. Inside the first family the right
    arm's minor is (1 + t_q4^2)(t_q4^2 - 2 t_q4 - 1)(1 + t_q3^2)^2: its factors are
    solved one by one, so the meeting is found in the t chart (not only at q1 = q3 = pi)."""
    locus = shipped_locus("five-bar")
    system = coopkin_sym.load("five-bar")
    at = "q1=2*atan(1/3),q2=pi/4,q3=2*atan(2/5),q4=-pi/4,L=1"
    numbers = analyze_irrational(system.model, at).numbers.as_dict()
    single = [c for c in locus.components if texts(c.equations) == ["t_q2**2 + 2*t_q2 - 1"]]
    assert single and single[0].numbers != numbers and numbers != locus.generic
    t2, t4 = sp.sqrt(2) - 1, 1 - sp.sqrt(2)          # tan(pi/8), tan(-pi/8)
    names = {v: sp.Symbol(v) for v in locus.variables}
    values = {names["t_q1"]: sp.Rational(1, 3), names["t_q2"]: t2,
              names["t_q3"]: sp.Rational(2, 5), names["t_q4"]: t4}
    holding = [c for c in locus.components
               if not any(e.startswith("s_") for e in texts(c.equations))
               and all(sp.simplify(sp.sympify(e, locals=names).subs(values)) == 0
                       for e in texts(c.equations))]
    # the point lies on a component of the t chart whose equations leave q1, q3 free
    assert [c.numbers for c in holding if c.numbers == numbers]
    assert all({"t_q1", "t_q3"}.isdisjoint(
        {str(s) for e in texts(c.equations) for s in sp.sympify(e, locals=names).free_symbols})
        for c in holding if c.numbers == numbers)


def test_proportional_polynomials_are_constant_multiples_of_each_other():
    _proportional = curved_search._proportional
    ctx = flint.fmpz_mpoly_ctx.get(("a", "b"), "degrevlex")
    a, b = ctx.gens()
    g = 2 * a**2 - 3 * b + 1
    assert _proportional(-6 * g, g) and _proportional(g, 4 * g)
    assert not _proportional(g + a, g)                  # one more term
    assert not _proportional(g - 2 * a**2 + 5 * a**2, g)  # same terms, not a multiple
    assert not _proportional(a * g, g)


@pytest.mark.parametrize(("seed", "family"), [(440, "t_q4**2 + 9*t_q4 - 1"),
                                              (456, "t_q4**2 - 2*t_q4 - 1")])
def test_a_root_times_an_algebraic_point_is_decided_and_searched(seed, family):
    """Random systems 440 and 456: inside the family ``family`` = 0 (q4 at one of two
    irrational angles), Nm rises to 3 where t_q1 and t_q3 take irrational values too,
    q2 free. The points are a root of one variable times an algebraic point of the
    others (two fields at once): said not solved before, and the sets they span had
    coordinates that each generate only part of their field (said with no rational
    parametrization). Now each orbit of conjugate pairs is one point over the
    compositum, the set is searched inside over the product of its coordinates'
    fields, nothing is said left out, the numbers at each witness agree with an
    independent analysis over the field of the angles, moving q1 off the set brings
    them back, and the certificate proves the locus complete on flint alone."""
    from coopkin_sym.analysis.locus.certify import certify_locus
    system = coopkin_sym.load(random_system(seed))
    locus = compute_locus(system, timeout=60)
    assert not locus.unexplored
    raised = {"Nm": 3, "Nc": 2, "Ni": 0, "Nr": 1, "Ng": 3, "Nd": 6, "Nh": 2}
    found = [c for c in locus.components if c.numbers == raised]
    assert found and all(c.kind == "subvariety" and c.parent == 0
                         and c.equations[0].text == family for c in found)
    for c in found:
        point = c.algebraic_witness["point"]
        at = ",".join(f"{k}={v}" for k, v in point.items())
        off = ",".join(f"{k}={'2*atan(1/7)' if k == 'q1' else v}"
                       for k, v in point.items())
        _rises_exactly_there(system, raised, [(at, off)])
    assert certify_locus(system, locus, timeout=120).certified


def test_where_a_family_parametrization_fails_its_points_are_searched():
    """The five-bar at q1 = pi: a curve in (t_q2, t_q3, t_q4) with Ni 1 is written
    t_q3 = -f0/f1, f1 = 2 (t_q4 + 1); where f0 = f1 = 0 (t_q4 = -1, t_q2 = -2, t_q3
    free) the parametrization says nothing. That set is now searched as a set of its
    own: its point t_q3 = 4/3 (the curve's limit there) has Ni 1, which an
    independent analysis confirms, and Ni is back to 0 along the set (t_q3 = 1/2)."""
    locus = shipped_locus("five-bar")
    system = coopkin_sym.load("five-bar")
    at = "q1=pi,q2=2*atan(-2),q3=2*atan(4/3),q4=-pi/2,L=1"
    (point,) = [c for c in locus.components if c.kind == "isolated" and c.chart == ("q1",)
                and str(c.condition) == "q1 = pi, q3 = 2*atan(4/3), q4 = -pi/2, q2 = "
                                        "2*atan(-2)"]
    assert point.numbers == {"Nm": 3, "Nc": 3, "Ni": 1, "Nr": 0, "Ng": 2, "Nd": 0, "Nh": 0}
    assert system.analyze(at=at).numbers.as_dict() == point.numbers
    off = system.analyze(at=at.replace("2*atan(4/3)", "2*atan(1/2)")).numbers
    assert off.Ni == 0
    (curve,) = [c for c in locus.components if c.chart == ("q1",) and c.kind == "subvariety"
                and c.numbers == point.numbers]
    assert [o.text for o in curve.outside] == ["t_q4 + 1"]
