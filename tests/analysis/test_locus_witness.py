"""Witnesses are exact points (:class:`~coopkin_sym.model.configuration.Point`), and
their float checks come from the exact point the search holds: no text is read again."""

from __future__ import annotations

import inspect

import pytest
import sympy as sp

from coopkin_sym import load
from coopkin_sym.analysis.floatcheck import float_numbers
from coopkin_sym.analysis.locus import witness as witness_module
from coopkin_sym.analysis.locus.search import compute_locus
from coopkin_sym.analysis.mobility import Analysis
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.model.configuration import Configuration, Point


@pytest.fixture(scope="module")
def case1():
    system = load("paper-case1-hard")
    return system, compute_locus(system)


def test_a_witness_is_an_exact_point(case1):
    _, locus = case1
    first = locus.components[0]
    assert isinstance(first.witness, Point)
    assert first.witness.revolute["q1"] == ExactAngle(-1, 1) == first.witness.revolute["q2"]
    assert first.witness.revolute["q1"].cos_sin == (0, -1)
    assert first.witness.parameters == {"L": 1}
    assert first.witness == {"q1": "-pi/2", "q2": "-pi/2", "L": "1"}
    assert first.to_json()["witness"] == {"q1": "-pi/2", "q2": "-pi/2", "L": "1"}
    check = first.float_checks[1]
    assert isinstance(check.point, Point) and check.distance == 1e-6
    # the joint of the last equation moved, exactly
    assert [k for k in ("q1", "q2") if check.point.revolute[k] != first.witness.revolute[k]
            ] == ["q2"]
    assert check.point["q2"].startswith("2*atan(")


def test_the_search_reads_no_point_text(monkeypatch):
    """Inside the search only the user's ``at`` is parsed; the witnesses and the
    points of their float checks are built exactly."""
    original = Configuration.parse.__func__
    callers = []

    def parse(cls, *args, **kwargs):
        caller = inspect.stack()[1]
        callers.append(("/".join(caller.filename.rsplit("/", 3)[-3:]), caller.function))
        return original(cls, *args, **kwargs)

    monkeypatch.setattr(Configuration, "parse", classmethod(parse))
    made = []
    init = Analysis.__init__

    def count(self, *args, **kwargs):
        made.append(1)
        init(self, *args, **kwargs)

    monkeypatch.setattr(Analysis, "__init__", count)
    compute_locus(load("paper-case1-hard"))
    assert [c for c in callers if c[0].startswith(("locus/", "search/"))] == [
        ("locus/search/__init__.py", "search_configuration")]
    assert len(made) == 5    # one per witness (the float checks need none)


def test_float_checks_from_the_chains_equal_those_of_analyses(case1):
    """Every float check of case 1 (at, near and with L rescaled): the exact and the
    float numbers from the compiled chains are those of an exact analysis there."""
    system, locus = case1
    points = 0
    for c in locus.components:
        for check in c.float_checks:
            a = Analysis(system.model, check.point)
            probe = witness_module._FloatProbe(system.model, check.point.parameters)
            assert probe.numbers(check.point) == (a.numbers.as_dict(), float_numbers(a))
            assert (check.exact, check.float) == (a.numbers.as_dict(), float_numbers(a)) \
                or check.distance == 0   # an irrational witness's own numbers at 0
            points += 1
    assert points == 5 * 12


def test_point_moved_and_compared():
    p = Point.of({"q1": ExactAngle(0, 1)}, {"d2": sp.Rational(1, 2)},
                 {"L": sp.Integer(2)})
    assert dict(p) == {"q1": "0", "d2": "1/2", "L": "2"}
    moved = p.moved("L", sp.Rational(1, 1000))
    assert moved["L"] == "1/1000" and list(moved) == ["q1", "d2", "L"]
    assert moved != p and p == Point.of({"q1": (1, 0)}, {"d2": sp.Rational(1, 2)},
                                        {"L": 2})
    assert p.moved("e", sp.Integer(3))["e"] == "3" and len(p.moved("e", 3)) == 4


def test_float_checks_are_left_out_over_the_size_and_the_locus_says_so(case1, monkeypatch):
    """Over FLOAT_CHECK_ENTRIES entries of Q no float SVD is run at the witnesses (its
    cost is the cube of the size): every component is found as before, without float
    checks, and one note says why."""
    from coopkin_sym.analysis.locus.remarks import Remark
    from coopkin_sym.present.remarks import remark_texts

    system, full = case1
    monkeypatch.setattr(witness_module, "FLOAT_CHECK_ENTRIES", 47)     # Q is 6 x 8
    locus = compute_locus(system)
    assert [c.equations for c in locus.components] == [c.equations for c in full.components]
    assert [c.numbers for c in locus.components] == [c.numbers for c in full.components]
    assert all(c.float_checks == [] for c in locus.components)
    note = Remark.of("float_checks_left_out", rows=6, columns=8, bound=47)
    assert note in locus.notes and Remark.of("irrational_witness_floats") not in locus.notes
    assert remark_texts([note]) == ["No float rank tests at the witnesses: Q is 6 x 8, over "
                                    "47 entries (a float SVD costs the cube of its size)."]
    assert all(c.float_checks for c in full.components)


@pytest.mark.slow   # about 30 s
def test_a_slice_of_a_cell_of_200_arms_is_searched_without_float_checks():
    """The first arm's shoulder and elbow free, the 1,199 other joints at exact
    values: the search works on Q (1,200 x 1,206) without a float SVD and says so; every
    component has numbers of its own, and its witness is checked exactly."""
    import random

    from coopkin_sym.analysis.locus.remarks import Remark
    from coopkin_sym.model.builders import arm_cell

    system = load(arm_cell(200, 6))
    rng = random.Random(5)
    free = ["a1_2", "a1_3"]
    at = ",".join(f"{j}=2*atan({rng.randint(-9, 9)}/{rng.randint(1, 9)})"
                  for j in system.joint_names if j not in free) + ",L=1"
    locus = system.locus(at, free=free)
    # one of the fixed arms stands at a singular configuration of its own (an angle
    # at 0 among the values drawn): one redundant motion on the whole slice
    assert locus.generic == {"Nm": 6, "Nc": 5, "Ni": 0, "Nr": 1, "Ng": 1194, "Nd": 1,
                             "Nh": 0}
    inside = system.analyze(at + ",a1_2=2*atan(1/7),a1_3=2*atan(-3/11)")
    assert inside.numbers.as_dict() == locus.generic
    assert Remark.of("float_checks_left_out", rows=1200, columns=1206,
                     bound=witness_module.FLOAT_CHECK_ENTRIES) in locus.notes
    assert len(locus.components) == 4
    for c in locus.components:
        assert c.numbers != locus.generic and c.float_checks == []
        assert c.witness is None or c.witness_checked
