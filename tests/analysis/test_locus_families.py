"""The families of a locus: its components grouped by their numbers, in every format."""

from __future__ import annotations

import pytest
from support import shipped_locus, texts

from coopkin_sym.analysis.locus.families import group_families
from coopkin_sym.analysis.locus.types import Component
from coopkin_sym.present.display import locus_html, pretty_text
from coopkin_sym.present.family_words import family_name, members_text
from coopkin_sym.present.report import render_html, render_latex, render_markdown
from coopkin_sym.present.sentences import change_words

GENERIC = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}


def _partition_holds(locus) -> None:
    families = locus.families()
    members = sorted(k for f in families for k in f.members)
    assert members == list(range(len(locus.components)))          # each exactly once
    assert len({tuple(sorted(f.numbers.items())) for f in families}) == len(families)
    for f in families:
        assert all(locus.components[k].numbers == f.numbers for k in f.members)
        assert list(f.members) == sorted(f.members) and f.example in f.members
        assert f.real == any(locus.components[k].real for k in f.members)
        assert f.changes == {k: (locus.generic[k], v) for k, v in f.numbers.items()
                             if locus.generic.get(k) != v}
    firsts = [f.members[0] for f in families]
    assert firsts == sorted(firsts)


def test_paper_case1_has_two_families_the_line_and_the_meeting_contacts():
    locus = shipped_locus("paper-case1-hard")
    families = locus.families()
    assert [(f.members, f.example, f.real) for f in families] == [
        ((0, 1, 2, 3), 0, True), ((4,), 4, True)]
    assert families[0].changes == {"Nm": (2, 3), "Nc": (2, 3), "Nh": (0, 1)}
    assert families[1].changes == {"Nm": (2, 3), "Nc": (2, 3), "Ni": (1, 3),
                                   "Ng": (1, 3), "Nh": (0, 1)}
    _partition_holds(locus)


@pytest.mark.parametrize("name", ["paper-case1-soft-hard", "four-bar", "planar-two-fingers",
                                  "paper-case1-planar"])
def test_families_partition_the_components(name):
    _partition_holds(shipped_locus(name))


def test_the_example_is_real_with_a_witness_and_shallow_first():
    deep = Component(["t_q1", "t_q2"], dict(GENERIC, Nm=3), {"q1": "0"}, True, depth=1)
    shallow = Component(["t_q1"], dict(GENERIC, Nm=3), {"q1": "0"}, True)
    unreal = Component(["t_q3"], dict(GENERIC, Nm=3), None, False)
    (family,) = group_families([unreal, deep, shallow], GENERIC)
    assert family.members == (0, 1, 2) and family.example == 2 and family.real
    (alone,) = group_families([unreal], GENERIC)
    assert alone.example == 0 and not alone.real


def test_the_example_is_in_the_widest_chart_before_the_shallowest():
    # the five-bar's two arms stretched at once: found with q1 = q3 = pi at depth 0,
    # and with q1, q3 free inside the first arm's family (depth 1): the latter is shown
    at_pi = Component(["s_q1", "s_q3", "t_q2 + t_q4", "t_q4**2 - 2*t_q4 - 1"],
                      dict(GENERIC, Nm=3), {"q1": "pi"}, True)
    free = Component(["t_q2**2 + 2*t_q2 - 1", "t_q2 + t_q4"], dict(GENERIC, Nm=3),
                     {"q1": "0"}, True, depth=1)
    (family,) = group_families([at_pi, free], GENERIC)
    assert family.example == 1
    locus = shipped_locus("five-bar")
    stretched = next(f for f in locus.families() if f.changes.get("Nd") == (0, 2))
    assert not any(e.startswith("s_") for e in
                   texts(locus.components[stretched.example].equations))


def test_the_change_in_words():
    assert change_words({"Nm": (8, 10), "Nc": (6, 5), "Ni": (1, 3), "Nr": (2, 5)}) == (
        "the object loses one direction of motion; with every joint locked the object "
        "gains two free motions; the arms gain three self-motions that leave the object "
        "fixed")
    assert change_words({"Ng": (3, 1), "Nd": (2, 1), "Nh": (1, 0)}) == (
        "two internal forces fewer; one contact force fewer that the joints cannot "
        "balance; one internal force fewer that the joints cannot control")
    assert change_words({"Nm": (2, 3)}) == "Nm 2 -> 3"         # told by nothing else
    assert [family_name(k) for k in (0, 1, 25, 26)] == ["A", "B", "Z", "F27"]


def test_every_format_states_the_families():
    locus = shipped_locus("paper-case1-hard")
    md, html, tex = render_markdown(locus), render_html(locus), render_latex(locus)
    line = next(x for x in md.splitlines() if x.startswith("| A |"))
    assert line == ("| A | Nm 2 → 3, Nc 2 → 3, Nh 0 → 1 | the object gains one direction "
                    "of motion; one more internal force the joints cannot control | #1, #2, "
                    "#3, #4 | #1: `q1 = -pi/2, q2 = -pi/2` | `q1=-pi/2,q2=-pi/2,L=1` |")
    assert "The 5 components below fall into 2 families" in md
    assert md.index("## Families") < md.index("## Components")
    assert "<td>#1, #2, #3, #4</td>" in html.replace(' style="text-align:left"', "")
    assert r"\subsection*{Families}" in tex
    assert (r"A & \raggedright Nm 2 $\to$ 3, Nc 2 $\to$ 3, Nh 0 $\to$ 1 & \raggedright the "
            r"object gains one direction of motion; one more internal force the joints "
            r"cannot control & \raggedright \#1, \#2, \#3, \#4 & \raggedright \#1: "
            r"$q_{1} = - \frac{\pi}{2}$, $q_{2} = - \frac{\pi}{2}$ \tabularnewline \hline"
            ) in tex.splitlines()
    assert "families" in locus_html(locus) and "family A (4 components, e.g. #1)" in \
        pretty_text(locus)


def test_members_are_listed_up_to_eight():
    locus = shipped_locus("paper-case1-hard")
    (many,) = group_families(locus.components[:4] * 3, locus.generic)
    assert members_text(many) == "#1, #2, #3, #4, #5, #6, #7, #8, ... (12 in all)"
