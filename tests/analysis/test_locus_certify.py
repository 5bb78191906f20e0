"""The completeness certificate of a singularity locus and its Gröbner-basis layer.

Known loci, derived by hand (paper case 1: joints at (0,0) and (L,0) about z, contacts
at c1 = L(-sin q1, cos q1), c2 = (L - L sin q2, L cos q2)):

* hard/hard: ``rank Q`` drops where a wrench can pass between the contacts; with
  ``d = c1 - c2 != 0`` it must lie along ``d`` and be orthogonal to both contact
  velocities ``e_z x (c_i - o_i)``, so both links lie on the line through the joints
  (the x-axis): ``cos q1 = cos q2 = 0``, the four points ``q1, q2 = +-pi/2``; with
  ``d = 0`` (``c1 = c2``: ``cos q1 = cos q2``, ``sin q2 - sin q1 = 1``) the points
  ``q1 = -q2 = -pi/6, -5pi/6`` (``t1 + t2 = 0, t1^2 + 4 t1 + 1 = 0``), where also
  ``rank Gt^T`` falls from 5 to 3. ``Dt`` (one column per arm, never zero) never drops.
  At ``q = pi`` no link lies on the x-axis and ``c1 != c2``: nothing.
* complete/hard: the object moves with link 1, so c2 must move as a point of link 1 and
  of link 2 at once: ``q1dot c2 = q2dot (c2 - o2)`` (in the plane), possible exactly
  when c2, the origin and o2 are collinear: ``cos q2 = 0``, i.e. ``q2 = +-pi/2`` for
  every ``q1`` (q1 = pi included): Nm 0 -> 1, Nh 1 -> 2.
"""

from __future__ import annotations

import copy
import json
import random

import flint
import pytest
from support import shipped_locus, texts
from typer.testing import CliRunner

from coopkin_sym import load
from coopkin_sym.analysis.locus.certify import CertifyError, _integer_polynomial, certify_locus
from coopkin_sym.analysis.locus.certify_real import no_real_zero
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.locus.search import compute_locus
from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.cli import app
from coopkin_sym.exact import deadline
from coopkin_sym.exact import groebner as gb
from coopkin_sym.exact.eliminants import residual_eliminants
from coopkin_sym.exact.parse import NumberError
from coopkin_sym.exact.polynomial import NamedPolynomial
from coopkin_sym.present.certificate import certificate_json, completeness_text
from coopkin_sym.present.certificate import certificate_summary as summary
from coopkin_sym.present.remarks import remark_text, remark_texts
from coopkin_sym.present.report import (
    ReportError,
    locus_from_json,
    render_json,
    render_latex,
    render_markdown,
)

CTX = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
X, Y = CTX.gens()
EXACT = ["flint", "sympy"] + (["singular"] if gb.singular_path() else [])
needs_msolve = pytest.mark.skipif(
    gb.msolve_path() is None,
    reason="msolve not installed (the optional extra: pip install coopkin_sym[certify])")

CASE1_GENERIC = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
ON_THE_LINE = {"Nm": 3, "Nc": 3, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 1}
C1_IS_C2 = {"Nm": 3, "Nc": 3, "Ni": 3, "Nr": 0, "Ng": 3, "Nd": 4, "Nh": 1}
COMPLETE_HARD_GENERIC = {"Nm": 0, "Nc": 0, "Ni": 0, "Nr": 0, "Ng": 3, "Nd": 7, "Nh": 1}
Q2_ACROSS = {"Nm": 1, "Nc": 1, "Ni": 0, "Nr": 0, "Ng": 3, "Nd": 7, "Nh": 2}


def case1_hard_components() -> list[Component]:
    comps = [Component([f"t_q1 - ({a})", f"t_q2 - ({b})"], dict(ON_THE_LINE), None, True)
             for a in (1, -1) for b in (1, -1)]
    comps.append(Component(["t_q1**2 + 4*t_q1 + 1", "t_q1 + t_q2"], dict(C1_IS_C2), None,
                           True))
    return comps


def case1_locus(components, generic=CASE1_GENERIC) -> Locus:
    return Locus("paper case 1", ["t_q1", "t_q2"], "L=1", dict(generic), components)


# --- the Gröbner-basis layer (ideals checked by hand) -----------------------------------
@pytest.mark.parametrize("backend", EXACT)
def test_unit_ideal_exact(backend):
    # x = -y gives x^2 + y^2 = -4 != 1: no common zero
    verdict = gb.is_unit_ideal([X**2 + Y**2 - 1, X * Y - 2, X + Y], timeout=60,
                               backend=backend)
    assert (verdict.holds, verdict.exact, verdict.backend) == (True, True, backend)
    # circle and hyperbola meet (over C): not the unit ideal
    verdict = gb.is_unit_ideal([X**2 + Y**2 - 1, X * Y - 2], timeout=60, backend=backend)
    assert (verdict.holds, verdict.exact) == (False, True)


@pytest.mark.parametrize("backend", EXACT)
def test_radical_membership(backend):
    # V(x^2, y) = {0}: x and x + y vanish there, x + 1 does not
    assert gb.contains_radical([X**2, Y], X + Y, timeout=60, backend=backend).proved
    assert gb.contains_radical([X**3, Y**2], X * Y + X, timeout=60, backend=backend).proved
    assert gb.contains_radical([X**2, Y], X + 1, timeout=60,
                               backend=backend).holds is False
    # V(x^2 - y^2, x - y) is the line x = y: x does not vanish on it, x - y does
    assert gb.contains_radical([X**2 - Y**2, X - Y], X, timeout=60,
                               backend=backend).holds is False
    assert gb.contains_radical([X**2 - Y**2, X - Y], X - Y, timeout=60,
                               backend=backend).proved


@pytest.mark.parametrize("backend", EXACT)
def test_covers(backend):
    # V(x (y - 1), x y) = {x = 0}
    ideal = [X * (Y - 1), X * Y]
    assert gb.covers(ideal, [[X]], timeout=60, backend=backend).proved
    assert gb.covers(ideal, [[Y], [X - 1]], timeout=60, backend=backend).holds is False
    # V(x y, x (x - 1)) = {x = 0} and the point (1, 0): a component with two generators
    ideal = [X * Y, X * (X - 1)]
    assert gb.covers(ideal, [[X], [X - 1, Y]], timeout=60, backend=backend).proved
    assert gb.covers(ideal, [[X], [X - 1, Y - 1]], timeout=60,
                     backend=backend).holds is False
    # V(x y) is two lines; y = 0 is missing
    assert gb.covers([X * Y], [[X], [Y - 1]], timeout=60, backend=backend).holds is False
    # the two points (+-i, 0) lie only on the allowed set x^2 + 1 = 0
    assert gb.covers([X**2 + 1, Y], [], timeout=60, backend=backend).holds is False
    assert gb.covers([X**2 + 1, Y], [], timeout=60, backend=backend,
                     allowed=[[X**2 + 1]]).proved
    # nothing to cover / a component that is the whole plane
    assert gb.covers([CTX.constant(3)], [], timeout=60, backend=backend).proved
    assert gb.covers([X], [[]], timeout=60, backend=backend).proved


def test_plain_exponent_maps_and_errors():
    # x - 1 and x: no common zero (exponent maps in one variable)
    assert gb.is_unit_ideal([{(1,): 1, (0,): -1}, {(1,): 1}], timeout=60).proved
    with pytest.raises(gb.GroebnerError, match="unknown backend 'maple'"):
        gb.is_unit_ideal([X], backend="maple")
    with pytest.raises(gb.GroebnerError, match="mixed"):
        gb.is_unit_ideal([X, {(1, 0, 0): 1}])
    other = flint.fmpz_mpoly_ctx.get(("x", "y", "z"), "degrevlex")
    with pytest.raises(gb.GroebnerError, match="polynomials in 3 and 2 variables mixed"):
        gb.covers([X], [[other.gens()[0]]], timeout=10)


def test_time_bound():
    # cyclic-6 takes flint's naive Buchberger far longer than 0.3 s
    n = 6
    ctx = flint.fmpz_mpoly_ctx.get(tuple(f"u{i}" for i in range(n)), "degrevlex")
    u = ctx.gens()

    def product(items):
        acc = ctx.constant(1)
        for v in items:
            acc = acc * v
        return acc

    system = [sum(product(u[(i + j) % n] for j in range(k)) for i in range(n))
              for k in range(1, n)]
    system.append(product(u) - 1)
    verdict = gb.is_unit_ideal(system, timeout=0.3, backend="flint")
    assert (verdict.holds, verdict.exact, verdict.detail) == (None, False,
                                                              "timed out after 0.3 s")
    # the worker is replaced after the kill: the next test still runs
    assert gb.is_unit_ideal([X, X - 1], timeout=60, backend="flint").proved


@needs_msolve
def test_msolve_is_a_screen_never_a_proof():
    unit = gb.is_unit_ideal([X**2 + Y**2 - 1, X * Y - 2, X + Y], timeout=60,
                            backend="msolve")
    assert (unit.holds, unit.exact, unit.backend) == (True, False, "msolve")
    assert not unit.proved
    proper = gb.is_unit_ideal([X**2 + Y**2 - 1, X * Y - 2], timeout=60, backend="msolve")
    assert (proper.holds, proper.exact) == (False, False)
    # coefficients are reduced modulo the prime: 2^31 - 1 is zero there
    assert gb.is_unit_ideal([{(1, 0): gb.MSOLVE_PRIME}], timeout=60,
                            backend="msolve").holds is False


def test_text_for_the_binaries():
    p = {(2, 0): -3, (0, 1): 1, (0, 0): 5}
    assert gb.polynomial_text(p, ["x0", "x1"]) == "-3*x0^2+x1+5"
    assert gb.polynomial_text({(1, 1): -1, (0, 0): 1}, ["x0", "x1"]) == "-x0*x1+1"
    assert gb.msolve_text([p], 2, 7) == "x0,x1\n7\n-3*x0^2+x1+5\n"


# --- reading equations --------------------------------------------------------------------
def test_equations_read_by_the_package_parser():
    # rational coefficients are scaled to a primitive integer polynomial
    got = _integer_polynomial("-(t_q1 - 1)*(t_q1+1)^2/3 - 2", ("t_q1",), "eq")
    assert got == {(3,): -1, (2,): -1, (1,): 1, (0,): -5}
    assert _integer_polynomial("s_q1", ("t_q2", "s_q1"), "eq") == {(0, 1): 1}
    assert _integer_polynomial("0.5*t_q1 + 1e-1", ("t_q1",), "eq") == {(1,): 5, (0,): 1}
    long = " + ".join(f"{k}*t_q1**{k % 7}*t_q2**4" for k in range(1, 400))
    assert len(_integer_polynomial(long, ("t_q1", "t_q2"), "eq")) == 7
    for bad, message in [("t_q1 + x", "undeclared symbol x"),
                         ("__import__('os')", "eq: "),
                         ("t_q1**t_q1", "eq: "),
                         ("1/t_q1", "not a polynomial"),
                         ("pi*t_q1", "'pi\\*t_q1' is not a polynomial"),
                         ("(t_q1 + 1", "eq: "),
                         ("t_q1**1001", "too large"),
                         ("(t_q1 + t_q2 + 7)**999*(t_q1 - t_q2)**999", "too large")]:
        with pytest.raises(NumberError, match=message) as info:
            _integer_polynomial(bad, ("t_q1", "t_q2"), "eq")
        assert "\n" not in str(info.value)


# --- certificates -------------------------------------------------------------------------
def test_case1_hard_complete_locus_is_certified():
    system = load("paper-case1-hard")
    # the numbers of the hand-made components, where they are rational points
    for a in ("pi/2", "-pi/2"):
        for b in ("pi/2", "-pi/2"):
            assert system.analyze(f"q1={a},q2={b}").numbers.as_dict() == ON_THE_LINE
    # q = pi: generic numbers (no link on the x-axis, c1 != c2)
    for at in ("q1=pi,q2=0", "q1=pi,q2=pi/2", "q1=pi/2,q2=pi", "q1=pi,q2=pi"):
        assert system.analyze(at).numbers.as_dict() == CASE1_GENERIC
    cert = certify_locus(system, case1_locus(case1_hard_components()), timeout=60)
    assert summary(cert) == "complete (certified)"
    assert cert.certified
    assert sorted(cert.charts) == ["q1 = pi", "q1 = q2 = pi", "q2 = pi", "t chart"]
    assert all(entry["certified"] and entry["failed"] == 0
               for entry in list(cert.charts.values()) + list(cert.depths.values()))
    assert sorted(cert.depths) == [0, 1]
    # every component's numbers and the drops inside it (none) were tested, t chart
    inside = {(c.inside, c.kind, c.matrix) for c in cert.checks if c.chart == "t chart"
              and c.inside is not None}
    assert inside == {(i, kind, m) for i in range(5) for kind in ("numbers", "drops")
                      for m in ("HG^T", "HD", "Q")}
    data = json.loads(json.dumps(certificate_json(cert)))
    assert data["summary"] == "complete (certified)"
    assert data["depths"]["0"]["certified"] is True
    assert data["failed"] == [] and data["tests"] == 46 == sum(data["certified_by"].values())
    assert "checks" not in data
    every = json.loads(json.dumps(certificate_json(cert, every_check=True)))
    assert len(every["checks"]) == 46
    assert {"chart", "depth", "inside", "matrix", "kind", "certified", "why", "backend",
            "seconds"} <= set(every["checks"][0])


def test_max_depth():
    cert = certify_locus(load("paper-case1-hard"), case1_locus(case1_hard_components()),
                         timeout=60, max_depth=0)
    assert summary(cert) == "not certified: depths beyond 0 were not tested"
    assert cert.depths[0] == {"certified": True, "why": None, "tests": 46 - 15, "failed": 0}
    assert cert.depths[1] == {"certified": False, "why": Remark.of("cert_not_tested"),
                              "tests": 0, "failed": 0}
    data = certificate_json(cert)
    assert data["depths"]["0"]["why"] == "" and data["depths"]["1"]["why"] == (
        "not tested (max_depth)")


@pytest.mark.parametrize("missing", range(5))
def test_case1_hard_without_one_component_fails(missing):
    comps = case1_hard_components()
    del comps[missing]
    cert = certify_locus(load("paper-case1-hard"), case1_locus(comps), timeout=60)
    assert not cert.certified
    failed = {(c.chart, c.depth, c.matrix) for c in cert.checks if not c.certified}
    if missing < 4:         # a point where both links lie on the x-axis: only Q drops
        assert failed == {("t chart", 0, "Q")}
        assert summary(cert) == ("not certified: t chart, depth 0, rank of Q: the rank drops "
                                "below its generic value at points on no listed component")
    else:                   # c1 = c2: Gt^T drops too
        assert failed == {("t chart", 0, "HG^T"), ("t chart", 0, "Q")}
        assert summary(cert).startswith("not certified: t chart, depth 0, rank of HG^T: ")
    assert cert.depths[0]["certified"] is False and cert.depths[1]["certified"] is True
    assert cert.charts["q1 = pi"]["certified"] is True


def test_wrong_numbers_on_a_component_fail():
    system = load("paper-case1-hard")
    comps = case1_hard_components()
    # c1 = c2 claimed with Gt^T at its generic rank (Ni 1): it is smaller everywhere there
    comps[4].numbers = dict(ON_THE_LINE)
    cert = certify_locus(system, case1_locus(comps), timeout=60)
    failed = [(c.chart, c.depth, c.inside, c.kind, c.matrix) for c in cert.checks
              if not c.certified]
    assert failed == [("t chart", 1, 4, "drops", "HG^T")]
    assert summary(cert) == ("not certified: t chart, depth 1, component #5, rank of HG^T: the "
                            "rank drops below its value on the component at points on no "
                            "component listed after it")
    # a line of generic configurations claimed to have the numbers of the four points:
    # Q has a larger rank on most of it
    comps = case1_hard_components() + [Component(["2*t_q1 - 1"], dict(ON_THE_LINE), None,
                                                 True)]
    cert = certify_locus(system, case1_locus(comps), timeout=60)
    failed = [(c.chart, c.depth, c.inside, c.kind, c.matrix) for c in cert.checks
              if not c.certified]
    # (the line q1 = 2 atan(1/2) crosses the slice q2 = pi too)
    assert failed == [("t chart", 0, 5, "numbers", "Q"), ("q2 = pi", 0, 5, "numbers", "Q")]
    assert summary(cert) == ("not certified: t chart, depth 0, component #6, numbers, rank of "
                            "Q: the rank is larger than the component's numbers give at some "
                            "of its points (and 1 more)")
    # numbers that do not fit one another are refused outright
    comps = case1_hard_components()
    comps[0].numbers = dict(ON_THE_LINE, Nh=0)
    cert = certify_locus(system, case1_locus(comps), timeout=60)
    assert summary(cert).startswith("not certified: component #1: its numbers (Nm 3, Nc 3, "
                                   "Ni 1, Nr 0, Ng 1, Nd 4, Nh 0) do not fit one another")


def test_case1_complete_hard_search_result_fails():
    # the locus search of this version reports no component at all for this system
    # (its row-content division hides q2 = +-pi/2): frozen here as it was reported
    system = load("paper-case1-complete-hard")
    assert system.analyze("q1=0,q2=pi/2").numbers.as_dict() == Q2_ACROSS
    assert system.analyze("q1=pi,q2=-pi/2").numbers.as_dict() == Q2_ACROSS
    searched = case1_locus([], COMPLETE_HARD_GENERIC)
    searched.dropped = ["t_q1**2 + 1 = 0 (no real points)",
                        "t_q1**2 + t_q1 + 1 = 0 (no real points)",
                        "t_q2**2 + 1 = 0 (no real points)"]
    cert = certify_locus(system, searched, timeout=60)
    failed = sorted((c.chart, c.depth, c.matrix) for c in cert.checks if not c.certified)
    assert failed == [("q1 = pi", 0, "Q"), ("t chart", 0, "Q")]
    assert summary(cert) == ("not certified: t chart, depth 0, rank of Q: the rank drops "
                            "below its generic value at points on no listed component "
                            "(and 1 more)")
    # the complete locus: q2 = +-pi/2 for every q1 (pi included), nothing deeper
    complete = case1_locus([Component(["t_q2 - 1"], dict(Q2_ACROSS), None, True),
                            Component(["t_q2 + 1"], dict(Q2_ACROSS), None, True)],
                           COMPLETE_HARD_GENERIC)
    cert = certify_locus(system, complete, timeout=60)
    assert summary(cert) == "complete (certified)"


def test_case1_soft_hard_misses_q2_at_pi():
    # with q2 = pi, c2 = (L, -L) and the soft contact's normal n1 = (cos q1, sin q1):
    # n1 . (c1 - c2) = sin q1 - cos q1 vanishes at q1 = pi/4, -3pi/4
    # (t1^2 + 2 t1 - 1 = 0): the object's rotation about c1 c2 is free there (Ni 0 -> 1)
    generic = {"Nm": 1, "Nc": 1, "Ni": 0, "Nr": 0, "Ng": 1, "Nd": 5, "Nh": 0}
    family = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 2, "Nd": 5, "Nh": 1}
    cubic = "t_q1**2*t_q2 - t_q1**2 + 2*t_q1*t_q2 + 2*t_q1 - t_q2 + 1"
    comps = [Component([cubic], dict(family), None, True)]
    locus = Locus("soft/hard", ["t_q1", "t_q2"], "L=1", generic, comps)
    cert = certify_locus(load("paper-case1-soft-hard"), locus, timeout=60,
                         first_failure=True)
    assert not cert.certified
    bad = [c for c in cert.checks if not c.certified]
    assert len(bad) == 1 and bad[0].depth == 0
    assert Remark.of("cert_stopped_early") in cert.notes
    assert ("Stopped at the first test not certified; the tests after it were not run."
            in remark_texts(cert.notes))


def test_case2_complete_locus_is_certified():
    # both SCARA-type arms lose a joint direction where their three revolute axes lie
    # in one plane (q2 = +-pi/2, q7 = +-pi/2); inside both, q1 = +-pi/2 and q6 = +-pi/2
    # add a hyperstatic direction (the locus of paper case 2, 8 joints free)
    d0 = {"Nm": 3, "Nc": 2, "Ni": 0, "Nr": 1, "Ng": 6, "Nd": 5, "Nh": 1}
    d1 = {"Nm": 3, "Nc": 1, "Ni": 0, "Nr": 2, "Ng": 6, "Nd": 6, "Nh": 1}
    d2 = {"Nm": 4, "Nc": 2, "Ni": 0, "Nr": 2, "Ng": 6, "Nd": 6, "Nh": 2}
    comps: list[Component] = []
    for sign in ("+", "-"):
        parent = len(comps)
        comps.append(Component([f"t_q2 {sign} 1"], dict(d0), None, True))
        for s7 in ("+", "-"):
            mid = len(comps)
            comps.append(Component([f"t_q2 {sign} 1", f"t_q7 {s7} 1"], dict(d1), None,
                                   True, depth=1, parent=parent))
            for s1 in ("+", "-"):
                for s6 in ("+", "-"):
                    comps.append(Component([f"t_q2 {sign} 1", f"t_q7 {s7} 1",
                                            f"t_q1 {s1} 1", f"t_q6 {s6} 1"], dict(d2),
                                           None, True, depth=2, parent=mid))
    comps += [Component([f"t_q7 {s} 1"], dict(d0), None, True) for s in ("+", "-")]
    names = ["t_q1", "t_q2", "t_q3", "q4", "q5", "t_q6", "t_q7", "t_q8"]
    generic = {"Nm": 3, "Nc": 3, "Ni": 0, "Nr": 0, "Ng": 6, "Nd": 4, "Nh": 1}
    system = load("paper-case2-complete")
    assert system.analyze("q2=pi/2,q7=-pi/2,q1=pi/2,q6=pi/2").numbers.as_dict() == d2
    cert = certify_locus(system, Locus("case 2", names, "L=1", generic, comps), timeout=60)
    assert summary(cert) == "complete (certified)"
    assert len(cert.charts) == 64 and sorted(cert.depths) == [0, 1, 2, 3]
    # without one depth-2 point, the drops inside its parent are not covered
    del comps[3]
    cert = certify_locus(system, Locus("case 2", names, "L=1", generic, comps), timeout=60,
                         first_failure=True)
    bad = [c for c in cert.checks if not c.certified]
    assert [(c.chart, c.depth, c.inside, c.kind) for c in bad] == [
        ("t chart", 2, 1, "drops")]


@needs_msolve
def test_case2_hard_search_result_misses_coincident_contacts():
    # the search of this version lists the families of q2, q7, q8 below but not the
    # configurations where the two contact points meet (Gt^T: rank 5 -> 3), e.g. every
    # joint at home and q5 = -2 L: c1 = c2 = (L, L, L)
    system = load("paper-case2-hard")
    generic = {"Nm": 8, "Nc": 6, "Ni": 1, "Nr": 2, "Ng": 1, "Nd": 0, "Nh": 0}
    assert system.analyze("L=1").numbers.as_dict() == generic
    assert system.analyze("L=1,q5=-2").numbers.as_dict()["Ni"] == 3
    one = {"Nm": 8, "Nc": 5, "Ni": 1, "Nr": 3, "Ng": 1, "Nd": 1, "Nh": 0}
    comps = [Component([f"t_q2 {s} 1"], dict(one), None, True) for s in ("+", "-")]
    comps += [Component(["t_q8**2 + 2*t_q8 - 1", f"t_q7 {s} 1"], dict(one), None, True)
              for s in ("+", "-")]
    names = ["t_q1", "t_q2", "t_q3", "q4", "q5", "t_q6", "t_q7", "t_q8"]
    cert = certify_locus(system, Locus("case 2", names, "L=1", generic, comps), timeout=60,
                         first_failure=True)
    bad = [c for c in cert.checks if not c.certified]
    assert [(c.chart, c.depth, c.matrix) for c in bad] == [("t chart", 0, "HG^T")]
    assert remark_text(bad[0].why).startswith(
        "the rank drops below its generic value at points on no listed component")


def test_case2_hard_on_flint_alone_says_what_timed_out():
    # flint's Buchberger neither proves nor refutes the c1 = c2 test of case 2 in 2 s
    system = load("paper-case2-hard")
    generic = {"Nm": 8, "Nc": 6, "Ni": 1, "Nr": 2, "Ng": 1, "Nd": 0, "Nh": 0}
    names = ["t_q1", "t_q2", "t_q3", "q4", "q5", "t_q6", "t_q7", "t_q8"]
    cert = certify_locus(system, Locus("case 2", names, "L=1", generic), timeout=2,
                         backend="flint", first_failure=True)
    bad = [c for c in cert.checks if not c.certified]
    assert [(c.chart, c.depth, c.matrix, c.backend) for c in bad] == [
        ("t chart", 0, "HG^T", "flint")]
    assert remark_text(bad[0].why).startswith("timed out after 2 s")
    assert summary(cert).startswith("not certified: t chart, depth 0, rank of HG^T: timed "
                                   "out after 2 s")


def test_bad_locus_input():
    system = load("paper-case1-hard")
    with pytest.raises(CertifyError, match="certify with the values the locus was computed"):
        certify_locus(system, Locus("x", ["t_q1"], "L=1", dict(CASE1_GENERIC)))
    comps = case1_hard_components()
    comps[0].equations = [NamedPolynomial.read("t_q1 - __import__", "test")]
    cert = certify_locus(system, case1_locus(comps), timeout=60)
    assert not cert.certified
    assert summary(cert).startswith("not certified: component #1, equation 1: "
                                   "-__import__ + t_q1 uses __import__, not among t_q1")
    wrong = dict(CASE1_GENERIC, Nm=3)
    cert = certify_locus(system, case1_locus(case1_hard_components(), wrong), timeout=60)
    assert summary(cert) == ("not certified: the locus's generic numbers (Nm 3, Nc 2, Ni 1, "
                            "Nr 0, Ng 1, Nd 4, Nh 0) differ from the exact ones (Nm 2, Nc 2, "
                            "Ni 1, Nr 0, Ng 1, Nd 4, Nh 0)")


def test_without_the_extra_flint_alone(monkeypatch):
    monkeypatch.setattr(gb, "singular_path", lambda: None)
    monkeypatch.setattr(gb, "msolve_path", lambda: None)
    import coopkin_sym.analysis.locus.certify as lc

    monkeypatch.setattr(lc, "singular_path", lambda: None)
    monkeypatch.setattr(lc, "msolve_path", lambda: None)
    cert = certify_locus(load("paper-case1-hard"), case1_locus(case1_hard_components()),
                         timeout=60)
    assert summary(cert) == "complete (certified)"
    assert {c.backend for c in cert.checks} <= {"flint", "none"}
    assert remark_texts(cert.notes) == [
        "Singular is not installed (pip install coopkin_sym[certify]): the proofs ran on "
        "flint's exact Buchberger algorithm, which is slow beyond small systems.",
        "msolve is not installed (pip install coopkin_sym[certify]): what is missing was "
        "looked for exactly on small subspaces only."]


@needs_msolve
def test_msolve_alone_never_certifies():
    cert = certify_locus(load("paper-case1-hard"), case1_locus(case1_hard_components()),
                         timeout=60, backend="msolve")
    assert not cert.certified
    proved_elsewhere = {c.backend for c in cert.checks if c.certified}
    assert proved_elsewhere <= {"none"}
    assert any(c.why == Remark.of("cert_modular_only", backend="msolve")
               for c in cert.checks)


# --- the certificate of the search's own loci, the command line, reports -------------------
def _without(locus: Locus, equations: list[str]) -> tuple[Locus, int | None]:
    """The locus without the component cut out by ``equations`` (parents renumbered),
    and the index its parent has afterwards."""
    index = next(k for k, c in enumerate(locus.components) if texts(c.equations) == equations)
    out = copy.deepcopy(locus)
    parent = out.components.pop(index).parent
    for c in out.components:
        if c.parent is not None and c.parent > index:
            c.parent -= 1
    return out, parent


@pytest.fixture(scope="module")
def soft_hard():
    """Paper case 1 (soft and hard contacts) and the search's locus of it."""
    system = load("paper-case1-soft-hard")
    return system, compute_locus(system)


def test_search_locus_with_a_planted_missing_component_fails(soft_hard):
    system, locus = soft_hard
    assert summary(certify_locus(system, locus)) == "complete (certified)"
    # the point q1 = -pi/2, q2 = pi/2 inside the family t_q2 = 1 left out
    planted, parent = _without(locus, ["t_q2 - 1", "t_q1 + 1"])
    assert texts(planted.components[parent].equations) == ["t_q2 - 1"]
    cert = certify_locus(system, planted)
    assert not cert.certified
    failed = [(c.chart, c.depth, c.inside, c.kind, c.matrix) for c in cert.checks
              if not c.certified]
    assert failed == [("t chart", 1, parent, "drops", "Q")]
    assert summary(cert) == (f"not certified: t chart, depth 1, component #{parent + 1}, rank "
                            "of Q: the rank drops below its value on the component at points "
                            "on no component listed after it")
    assert cert.depths[0]["certified"] and not cert.depths[1]["certified"]
    data = certificate_json(cert)
    assert [f["why"] for f in data["failed"]] == [
        remark_text(c.why) for c in cert.checks if not c.certified]
    assert data["depths"]["1"]["failed"] == 1 and data["charts"]["t chart"]["failed"] == 1
    # a family at q2 = pi left out: the slice q2 = pi, depth 0
    planted, _ = _without(locus, ["s_q2", "t_q1**2 + 2*t_q1 - 1"])
    cert = certify_locus(system, planted)
    assert {(c.chart, c.depth, c.matrix) for c in cert.checks if not c.certified} == {
        ("q2 = pi", 0, "HG^T"), ("q2 = pi", 0, "Q")}
    assert summary(cert).startswith("not certified: q2 = pi, depth 0, rank of HG^T: the rank "
                                   "drops below its generic value at points on no listed "
                                   "component")


def test_cli_certify_report_and_json_round_trip(tmp_path):
    runner = CliRunner()
    js = tmp_path / "case1.json"
    result = runner.invoke(app, ["locus", "paper-case1-hard", "--certify", "--no-progress",
                                 "--certify-timeout", "120", "-o", str(js)])
    assert result.exit_code == 0, result.output
    assert "; complete (certified); wrote" in result.output
    data = json.loads(js.read_text())
    assert data["completeness"] == "complete (certified)"
    cert = data["certificate"]
    assert cert["certified"] is True and cert["failed"] == [] and cert["tests"] == 46
    assert cert["depths"] == {"0": {"certified": True, "why": "", "tests": 31, "failed": 0},
                              "1": {"certified": True, "why": "", "tests": 15, "failed": 0}}
    assert sorted(cert["charts"]) == ["q1 = pi", "q1 = q2 = pi", "q2 = pi", "t chart"]
    back = locus_from_json(js.read_text())
    assert certificate_json(back.certificate) == cert
    assert completeness_text(back) == "complete (certified)"
    assert back.certified and back.completeness() == (True, None)
    assert json.loads(render_json(back)) == data
    text = render_markdown(back)
    assert "Completeness: **complete (certified)**." in text
    assert "## Completeness certificate" in text
    assert "- Depth 0: certified (31 tests)." in text
    assert "- Depth 1: certified (15 tests)." in text


def test_report_without_certificate_says_so(tmp_path):
    out = tmp_path / "case1.json"
    result = CliRunner().invoke(app, ["locus", "paper-case1-complete-hard", "--no-progress",
                                      "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert "; completeness not certified (run with --certify); wrote" in result.output
    data = json.loads(out.read_text())
    assert data["certificate"] is None
    assert data["completeness"] == "completeness not certified (run with --certify)"
    locus = locus_from_json(data)
    text = render_markdown(locus)
    assert "**Completeness not certified (run with --certify)**." in text
    assert "## Completeness certificate" in text


def test_failed_certificate_in_reports_and_read_back():
    system = load("paper-case1-hard")
    comps = case1_hard_components()
    del comps[4]
    locus = case1_locus(comps)
    locus.certificate = certify_locus(system, locus, timeout=60)
    why = ("not certified: t chart, depth 0, rank of HG^T: the rank drops below its generic "
           "value at points on no listed component (and 1 more)")
    assert completeness_text(locus) == why
    assert locus.completeness() == (False, locus.certificate.failures()[0])
    text = render_markdown(locus)
    assert f"Completeness: **{why}**." in text
    assert ("- Depth 0: not certified (2 of 28 tests): t chart, depth 0, rank of HG^T: the "
            "rank drops below its generic value at points on no listed component.") in text
    assert "- Depth 1: certified (12 tests)." in text
    assert "Tests not certified (2):" in text
    assert ("- t chart, depth 0, rank of Q: the rank drops below its generic value at points "
            "on no listed component") in text
    latex = render_latex(locus)
    assert "not certified: t chart, depth 0, rank of HG" in latex
    data = json.loads(render_json(locus))
    assert (certificate_json(locus_from_json(data).certificate)
            == certificate_json(locus.certificate))
    # read back: the summary must agree with the verdict, indices must exist
    bad = copy.deepcopy(data)
    bad["certificate"]["certified"] = True
    with pytest.raises(ReportError, match="certificate.summary: .* does not agree with "
                                          "certified = true"):
        locus_from_json(bad)
    bad = copy.deepcopy(data)
    bad["certificate"]["failed"][0]["inside"] = 9
    with pytest.raises(ReportError, match=r"certificate.failed\[0\].inside: no component"):
        locus_from_json(bad)
    bad = copy.deepcopy(data)
    bad["certificate"]["depths"]["0"]["oops"] = 1
    with pytest.raises(ReportError, match="unknown key 'oops'"):
        locus_from_json(bad)
    bad = copy.deepcopy(data)
    bad["completeness"] = "complete (certified)"
    with pytest.raises(ReportError, match="completeness: .* does not agree"):
        locus_from_json(bad)


def test_time_bound_of_the_whole_certificate(soft_hard):
    # the search's own locus of case 1 within a bound far too short for its 4 charts
    system, locus = soft_hard
    cert = certify_locus(system, locus, budget=0)
    assert not cert.certified
    assert summary(cert).startswith("not certified: ")
    assert "time bound of 0 s reached" in summary(cert)
    # an outer bound of the exact layer applies too
    with deadline.time_limit(0):
        cert = certify_locus(system, locus, budget=60)
    assert "time bound of 0 s reached" in summary(cert)


def test_merged_hypersurfaces_stay_within_the_term_budget(monkeypatch):
    # V(f) u V(g) = V(f g): merging is exact, but the product of many factors grows
    # without bound; past the budget the factors stay components of their own
    monkeypatch.setattr(gb, "MAX_PRODUCT_TERMS", 40)
    n = 3
    ctx = gb._ctx(n)
    rng = random.Random(5)
    factors = [ctx.from_dict({(rng.randint(0, 2), rng.randint(0, 2), k % 3): 1,
                              (0, 0, 0): rng.randint(1, 5)}) for k in range(12)]
    comps = [[gb._plain(f)] for f in factors] + [[{(1, 0, 0): 1}, {(0, 1, 0): 1}]]
    merged = gb._merge_hypersurfaces(comps, n)
    assert merged[0] == [{(1, 0, 0): 1}, {(0, 1, 0): 1}]     # two generators: kept
    singles = [c[0] for c in merged[1:]]
    assert all(len(c) == 1 for c in merged[1:]) and 1 < len(singles) < len(factors)
    assert len(singles[0]) <= 40 * max(len(f) for f in factors)
    whole, parts = ctx.constant(1), ctx.constant(1)
    for f in factors:
        whole *= f
    for g in singles:
        parts *= ctx.from_dict(g)
    assert parts == whole                                     # the same union


# --- components found through a parametrization -------------------------------------
def test_saturation_is_the_ideal_of_the_closure():
    from coopkin_sym.exact.saturation import saturate

    ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    x, y = ctx.gens()
    # V(x*y) minus V(x) is the line y = 0 (without the origin): its closure is y = 0
    (ideal,), _ = gb.as_dicts([x * y])
    assert saturate([ideal], gb.as_dicts([x])[0][0], 2, timeout=30) == [{(0, 1): 1}]
    # a twisted cubic minus a point: the closure is the whole curve again
    cubic = gb.as_dicts([y - x**2, x * (y - x**2)])[0]
    assert saturate(cubic, gb.as_dicts([x])[0][0], 2, timeout=30) == [
        {(2, 0): 1, (0, 1): -1}]
    # the empty set: the unit ideal
    assert saturate(gb.as_dicts([x])[0], gb.as_dicts([x])[0][0], 2, timeout=30) == [
        {(0, 0): 1}]
    assert saturate([ideal], gb.as_dicts([x])[0][0], 2, timeout=0) is None


def _five_bar_depth0(monkeypatch=None):
    system = load("five-bar")
    cert = certify_locus(system, shipped_locus("five-bar"), timeout=60, max_depth=0)
    return [c for c in cert.checks if c.depth == 0 and c.inside is None]


@pytest.mark.slow
def test_five_bar_components_with_denominators_are_used_through_their_closure():
    # component #3 is a family with a denominator in its parametrization; its closure
    # (the saturation) takes part in the coverings: every depth-0 test is proved
    depth0 = _five_bar_depth0()
    assert depth0 and all(c.certified for c in depth0), [
        (c.where(), c.why) for c in depth0 if not c.certified]


@pytest.mark.slow
def test_without_the_saturation_the_points_at_a_denominator_are_covered_apart(monkeypatch):
    import coopkin_sym.analysis.locus.certify as certify

    monkeypatch.setattr(certify, "SATURATION_SECONDS", 0.0)
    # (the covering without those components, tried first, proves some of them: the
    # test before this one fails without it)
    monkeypatch.setattr(certify, "WITHOUT_DENOMINATORS_SHARE", 0.0)
    failed = [c for c in _five_bar_depth0() if not c.certified]
    # never certified on V(equations) alone: the points where the denominator vanishes
    # must lie in the other components, and here they do not
    assert failed and {c.why.kind for c in failed} <= {"cert_denominator_residual",
                                                        "cert_undecided"}
    assert any(c.why.kind == "cert_denominator_residual" for c in failed)


@pytest.mark.parametrize("name", ["four-bar", "shaky-pinned-bars", "underactuated-finger",
                                  "paper-case1-soft", "paper-case1-planar",
                                  "paper-case1-soft-hard", "parallel-cranks"])
def test_small_shipped_loci_are_certified_on_the_default_install(name):
    # as docs/locus-report.md says: flint alone proves every test of these
    system = load(name)
    cert = certify_locus(system, shipped_locus(name), timeout=60, backend="flint")
    assert cert.certified, [(c.where(), c.why) for c in cert.checks if not c.certified]


def test_hypersurfaces_with_huge_coefficients_are_stripped():
    """python-flint's ``factor`` fails to sort factors with coefficients beyond a C
    long; the certificate's stripping of hypersurface factors still factors them."""
    ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    x, y = ctx.gens()
    big, bigger = x + 2**70 * y, x + 3 * y + 2**71
    with pytest.raises(OverflowError):
        (big * bigger).factor()
    gens, comps = gb._strip_hypersurfaces([big * bigger * (x - y)], [[big], [bigger]])
    assert [str(g) for g in gens] == [str(x - y)]
    assert gb._strip_hypersurfaces([big * bigger], [[big], [bigger]]) is None


def test_stripping_divides_out_the_hypersurfaces_and_keeps_the_rest_square_free():
    ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    x, y = ctx.gens()
    hyper = (x - 1) * (y + 2)
    gens, _ = gb._strip_hypersurfaces([6 * (x - 1)**3 * (x + y)**2 * (x - y)], [[hyper]])
    assert gens == [(x + y) * (x - y)]
    # only the components are factored: a generator is never given to factor()
    factored = []
    original = gb.factor

    def spy(p):
        factored.append(p)
        return original(p)

    try:
        gb.factor = spy
        assert gb._strip_hypersurfaces([(y + 2)**2 * (x - 1)], [[hyper]]) is None
    finally:
        gb.factor = original
    assert factored == [hyper]


def test_stripping_skips_the_factoring_of_a_large_component(monkeypatch):
    ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    x, y = ctx.gens()
    monkeypatch.setattr(gb, "STRIP_FACTOR_TERMS", 3)
    hyper = (x - 1) * (y + 2)        # 4 terms: divided out whole, not factored
    monkeypatch.setattr(gb, "factor", lambda p: pytest.fail("factored"))
    gens, _ = gb._strip_hypersurfaces([hyper**2 * (x - y), (x - 1) * (x + y)], [[hyper]])
    assert gens == [x - y, (x - 1) * (x + y)]


def test_the_covering_product_is_abandoned_before_a_large_multiplication(monkeypatch):
    ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "degrevlex")
    x, y = ctx.gens()
    ideal = [gb._plain(x * y)]
    comps = [[gb._plain(x + y + 1)], [gb._plain(x**2 + y - 3)], [gb._plain(y**3 - x)]]
    made = gb.covering_system(ideal, comps, 2, max_terms=10_000)
    assert made is not None
    monkeypatch.setattr(gb, "MAX_PRODUCT_PAIRS", 8)   # 3 x 3 term pairs
    assert gb.covering_system(ideal, comps, 2, max_terms=10_000) is None
    # the separate form is still there, and the inclusion is still decided
    assert gb.covering_system(ideal, comps, 2, separate=True) is not None
    assert gb.covers([x * y], [[x], [y]], timeout=30, backend="flint").holds is True


def _proved_without_real_points(ideal, components, allowed=()):
    return any(no_real_zero(g) for g in residual_eliminants(
        ideal, components, timeout=60, allowed=allowed))


def test_residual_eliminants_vanish_outside_the_components():
    # x (x^2 + y^2 + 1) = 0 = y: outside x = 0 only (+-i, 0)
    ideal = [X**3 + X * Y**2 + X, Y]
    assert gb.covers(ideal, [[X]], timeout=60, backend="flint").holds is False
    found = list(residual_eliminants(ideal, [[X]], timeout=60))
    assert X**2 + 1 in found and Y in found
    assert _proved_without_real_points(ideal, [[X]])
    # every eliminant vanishes at the points outside: here the real circle minus x = 0
    ideal = [X * (X**2 + Y**2 - 1)]
    found = list(residual_eliminants(ideal, [[X]], timeout=60))
    from fractions import Fraction as F
    for px, py in ((F(3, 5), F(4, 5)), (F(-4, 5), F(3, 5)), (F(1), F(0))):
        for g in found:
            assert sum(int(c) * px**int(a) * py**int(b) for (a, b), c in g.to_dict().items()) == 0
    assert not _proved_without_real_points(ideal, [[X]])
    # a component with two generators: the residual through the covering system
    ideal = [Y * (X**2 + 1), X * Y * (Y - 1)]
    assert not _proved_without_real_points(ideal, [[X, Y - 1]])      # y = 0 is real
    assert _proved_without_real_points(ideal, [[Y]])                  # only y = 1, x = +-i
    # covered outright: a nonzero constant
    assert [str(g) for g in residual_eliminants([X], [[X]], timeout=60)] == ["1"]


def test_drop_sets_without_real_points_outside_the_locus_are_certified():
    # planar-two-fingers with q1 = pi: rank HG^T drops on a complex curve over
    # 2 t3^2 t4^2 + 6 t3^2 - 3 t3 t4^2 + ... = 0, which has no real point; only real
    # configurations matter, and the certificate proves so
    system = load("planar-two-fingers")
    locus = compute_locus(system, at="q1=pi", max_depth=2)
    cert = certify_locus(system, locus, timeout=60, backend="flint")
    assert cert.certified, [(c.where(), c.why) for c in cert.checks if not c.certified]
    real_only = [c for c in cert.checks if c.why == Remark.of("cert_real_points_only")]
    assert real_only and all(c.certified for c in real_only)
    assert "proved at the real points" in remark_text(real_only[0].why)
    assert Remark.of("cert_real_points_tests", count=len(real_only)) in cert.notes
    # and it still fails when a component with real points is left out
    for k in range(len(locus.components)):
        partial = copy.deepcopy(locus)
        del partial.components[k]
        assert not certify_locus(system, partial, timeout=60, backend="flint",
                                 first_failure=True).certified, k


def test_components_without_real_points_need_no_tests():
    # random system 379 (frictionless and hard contacts, four revolute joints): two
    # components at q3 = pi and q4 = pi have no real point, and their numbers are
    # larger than claimed at every real point of those slices; only real
    # configurations matter, and the certificate proves they have none
    from random_systems import random_system
    system = load(random_system(379))
    locus = compute_locus(system, timeout=60)
    cert = certify_locus(system, locus, timeout=60, backend="flint")
    assert cert.certified, [(c.where(), c.why) for c in cert.checks if not c.certified]
    skipped = [c for c in cert.checks if c.why == Remark.of("cert_component_not_real")]
    assert {c.inside for c in skipped} and all(
        not locus.components[c.inside].real for c in skipped)
    # a component with real points is never passed over: without one, no certificate
    real = next(i for i, c in enumerate(locus.components) if c.real and c.depth == 0)
    partial = copy.deepcopy(locus)
    del partial.components[real]
    assert not certify_locus(system, partial, timeout=60, backend="flint",
                             first_failure=True).certified


def test_residual_coverings_share_the_bound_of_their_test(monkeypatch):
    """The coverings of the points where a parametrization's denominator vanishes run
    within the bound of their test, not each with a bound of its own."""
    import time
    from types import SimpleNamespace

    from coopkin_sym.analysis.locus import certify as C

    asked = []

    def slow_covers(ideal, pieces, *, timeout, **kwargs):
        asked.append(timeout)
        time.sleep(0.05)
        return gb.Verdict(True, True, "flint", 0.05)
    monkeypatch.setattr(C, "covers", slow_covers)
    runner = C._Runner.__new__(C._Runner)
    runner.backend = "flint"
    runner.outs = {0: [X - 1, X - 2, X - 3], 1: [Y - 1, Y - 2, Y - 3]}
    chart = SimpleNamespace(units=[], names=("x", "y"))
    started = time.monotonic()
    verdict, residual = runner.cover([X * Y], [(0, [X]), (1, [Y])], 0.3, chart, [])
    assert time.monotonic() - started < 0.3 + 0.1     # one covering past the bound at most
    assert all(t <= 0.3 for t in asked) and sorted(asked, reverse=True) == asked
    assert verdict.holds is None and "timed out after 0.3 s" in verdict.detail
    assert residual is not None


@pytest.mark.slow     # the whole certificate: about 50 s of Groebner bases
def test_a_component_whose_larger_rank_lies_where_its_slope_has_no_real_zero():
    """Random system 463: a family t_q2 = -c0 / c1 over a surface, with c1 = t_q3^2
    (t_q4^2 + 2 t_q4 + 3) + ... never zero at a real point (its discriminant in t_q3 is
    -4 (t_q4^4 + 5 t_q4^2 + 5)). Its equations also hold where c1 = c0 = 0, with t_q2
    free, and there the rank of H G^T is the generic one: over C the family's numbers
    do not hold on all of it, and the test failed. At the real points it holds, and
    the certificate is complete."""
    from random_systems import random_system

    from coopkin_sym.analysis.locus.certify_real import nonreal_slopes

    system = load(random_system(463))
    locus = compute_locus(system, timeout=60)
    family = next(c for c in locus.components if c.kind == "subvariety" and not c.chart
                  and len(c.equations) == 2 and c.numbers["Ng"] == 1
                  and "t_q2" in c.equations[1].variables)
    ctx = flint.fmpz_mpoly_ctx.get(("t_q1", "t_q2", "t_q3", "t_q4"), "degrevlex")
    own = [ctx.from_dict({tuple(e.get(n, 0) for n in ctx.names()): int(c)
                          for e, c in _terms(p)}) for p in family.equations]
    t3, t4 = ctx.gens()[2:]
    c1 = (t3**2 * (t4**2 + 2 * t4 + 3) + t3 * (2 * t4**2 + 2 * t4 - 2)
          + 2 * t4**2 - 2 * t4 + 2)
    assert c1 in nonreal_slopes(own)
    cert = certify_locus(system, locus, timeout=120)
    assert cert.certified
    assert any(n.kind == "cert_real_points_tests" for n in cert.notes)


def _terms(p):
    """The terms of a named polynomial as ``({variable: exponent}, coefficient)``."""
    for exps, c in p.terms:
        assert c.denominator == 1
        yield dict(zip(p.variables, exps, strict=True)), c.numerator
