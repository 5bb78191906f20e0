"""A locus report draws the system at the witness of every real component, with a
motion gained there, and says which component and which motion."""

from __future__ import annotations

import pytest
from support import shipped_locus

pytest.importorskip("matplotlib")

from coopkin_sym import load  # noqa: E402
from coopkin_sym.present import report  # noqa: E402
from coopkin_sym.present.draw import gained_motion  # noqa: E402
from coopkin_sym.present.report import drawable_components, write_report  # noqa: E402


@pytest.fixture(scope="module")
def case1():
    return load("paper-case1-hard"), shipped_locus("paper-case1-hard")


def test_one_picture_per_component_with_a_real_witness(tmp_path, case1):
    system, locus = case1
    drawable = drawable_components(locus)
    assert drawable == [0, 1, 2, 3, 4]        # four rational witnesses, one algebraic
    written = write_report(locus, tmp_path / "r.md", system=system)
    names = [p.name for p in written]
    assert [n for n in names if "_system_" in n] == [
        f"r_system_component_{k + 1}.png" for k in drawable]
    text = (tmp_path / "r.md").read_text()
    captions = [line for line in text.splitlines() if line.startswith("![Component ")]
    assert len(captions) == len(drawable)
    for k, caption in zip(drawable, captions, strict=True):
        assert caption.startswith(f"![Component {k + 1} (")
        assert f"](r_system_component_{k + 1}.png)" in caption
    # q1 = q2 = +-pi/2: a coordinated motion more than generically, drawn
    assert "with coordinated motion 2 (C12, C22), a motion gained there " \
           "(coordinated motions: 1 generically, 2 here)" in captions[0]
    # c1 = c2 at irrational angles: the gained indeterminate motions are named
    assert "indeterminate motions: 1 generically, 3 here" in captions[4]
    assert "not drawn" in captions[4]


def test_gained_motion_and_the_cap(tmp_path, case1, monkeypatch):
    system, locus = case1
    assert gained_motion(locus.components[0].numbers, locus.generic) == ("coordinated", 2)
    assert gained_motion(locus.components[4].numbers, locus.generic) == ("indeterminate", 3)
    monkeypatch.setattr(report, "MAX_SYSTEM_PICTURES", 2)
    with pytest.warns(UserWarning, match="3 more components left out"):
        written = write_report(locus, tmp_path / "r.html", system=system)
    text = written[0].read_text()
    assert text.count("<figcaption>Component ") == 2
    assert "3 more components with a real witness are not drawn (at most 2 pictures" in text


def test_an_irrational_length_is_drawn_at_a_rational_value_and_said():
    """Paper case 2's q4 is prismatic: at an algebraic witness with q4 = -3*sqrt(3)/5
    the picture is drawn with q4 within 1e-9 of it (angles stay exact), and its
    caption gives that value."""
    from fractions import Fraction

    from coopkin_sym.analysis.locus.types import Component, Locus
    from coopkin_sym.present.report.pictures import system_picture_jobs

    system = load("paper-case2-hard")
    generic = system.analyze(generic=True).numbers.as_dict()
    point = {"q1": "pi/3", "q2": "0", "q3": "0", "q4": "-3*sqrt(3)/5", "q5": "0",
             "q6": "0", "q7": "0", "q8": "0", "L": "1"}
    comp = Component(["t_q1**2 - 3"], dict(generic, Nm=generic["Nm"] + 1), None, True,
                     kind="hypersurface", algebraic_witness={
                         "point": point, "alpha": "t_q1", "root_of": "alpha**2 - 3",
                         "root": "sqrt(3)", "interval": ["1", "2"],
                         "approx": {"q1": "1.0471975512", "q4": "-1.03923048454"}})
    locus = Locus("paper-case2-hard", ["t_q1"], "", generic, [comp])
    ((key, job),) = system_picture_jobs(locus, system, dpi=40)
    png, (_, name, caption) = job()
    assert png.startswith(b"\x89PNG") and name == "component 1"
    drawn = caption.split("Drawn with q4 = ")[1].split(" ")[0]
    assert abs(Fraction(drawn) + Fraction(3) * Fraction("1.7320508075688772") / 5) < 1e-9
    assert "its algebraic witness q1=pi/3" in caption and "q4=-3*sqrt(3)/5" in caption


def test_a_picture_at_an_algebraic_witness_uses_what_the_search_knows(case1, monkeypatch):
    """The search's exact numbers there and the witness's approximations: no analysis
    is made again, no algebraic value read back; the same numbers and, within 1e-9,
    the same drawing values as the analysis from the witness's text."""
    from coopkin_sym.present import draw_inputs
    from coopkin_sym.present.report.pictures import _witness_point, system_picture_jobs

    system, locus = case1
    comp = locus.components[4]
    at, exact = _witness_point(comp)
    assert not exact
    from_text = draw_inputs._at_irrational(system.model, at)
    given = draw_inputs.at_algebraic_witness(system.model, at,
                                             comp.algebraic_witness["approx"],
                                             comp.shown.numbers)
    assert given.numbers == from_text.numbers and given.tangents == tuple(from_text.tangents)
    assert given.configuration == from_text.configuration
    assert given.near.keys() == from_text.near.keys()
    assert all(abs(given.near[n] - from_text.near[n]) < 1e-9 for n in given.near)

    def refused(*args, **kwargs):
        raise AssertionError("analyzed again")
    monkeypatch.setattr(draw_inputs, "analyze_irrational", refused)
    monkeypatch.setattr(draw_inputs, "irrational_values", refused)
    jobs = system_picture_jobs(locus, system, dpi=40)
    png, (_, name, caption) = jobs[4][1]()
    assert png.startswith(b"\x89PNG") and name == "component 5"
    assert "indeterminate motions: 1 generically, 3 here" in caption
