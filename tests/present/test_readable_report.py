"""A locus report a person can read: remarks said once with their count, polynomials
named once, plots on free joints with distinct legend entries, LaTeX tables that
break across pages."""

from __future__ import annotations

import json

from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.present.display import locus_html, pretty_text
from coopkin_sym.present.remarks import grouped_remark_texts, remark_texts
from coopkin_sym.present.report import render_html, render_latex, render_markdown
from coopkin_sym.present.report.to_json import locus_from_json, render_json

GENERIC = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
# the 72 components whose deeper drops were not explored: #3, #5, ..., #145
INSIDE = [2 * k + 2 for k in range(72)]
GROUPED = ("deeper drops not explored (max depth 2), inside 72 components: #3, #5, #7, "
           "#9, #11, #13, #15, #17, #19, #21, #23, #25, ... (60 more, all listed in the "
           "JSON report)")


def deeper(k: int) -> Remark:
    return Remark.of("deeper_not_explored", component=k, condition=f"q1 = {k}",
                     reason="max_depth", bound=2)


def many_remarks() -> Locus:
    components = [Component([f"t_q1 - {k}"], dict(GENERIC, Nm=3), {"q1": "0"}, True)
                  for k in range(146)]
    unexplored = [deeper(k) for k in INSIDE]
    unexplored.append(Remark.of("time_depth", depth=3, equations=("t_q2",)))
    return Locus("planted", ["t_q1", "t_q2"], "", GENERIC, components, unexplored=unexplored)


def test_remarks_of_one_kind_are_said_once_with_their_count():
    locus = many_remarks()
    texts = grouped_remark_texts(locus.unexplored)
    assert texts == [GROUPED, "depth 3 inside t_q2: not explored, time bound reached"]
    # different facts apart from where they are: not grouped
    other = grouped_remark_texts([deeper(0), Remark.of("deeper_not_explored", component=1,
                                                      condition="q1 = 1",
                                                      reason="max_depth", bound=3)])
    assert other == remark_texts([deeper(0)]) + [
        "inside component #2 (q1 = 1): deeper drops not explored (max depth 3)"]
    # places that are not components: equations listed
    timed = [Remark.of("time_depth", depth=1, equations=(f"t_q1 - {k}",)) for k in (1, 2)]
    assert grouped_remark_texts(timed) == [
        "depth 1: not explored, time bound reached, inside 2 places: t_q1 - 1; t_q1 - 2"]


def test_every_format_says_the_grouped_remark_once():
    locus = many_remarks()
    md, html, tex = render_markdown(locus), render_html(locus), render_latex(locus)
    assert md.count("- " + GROUPED + "\n") == 1
    assert html.count("<li>" + GROUPED + "</li>") == 1
    assert tex.count(GROUPED.replace("#", r"\#")) == 1
    assert pretty_text(locus).count("not explored: deeper drops not explored (max depth "
                                    "2), inside 72 components: #3, #5,") == 1
    assert locus_html(locus).count("inside 72 components: #3, #5,") == 1
    for text in (md, html, tex, pretty_text(locus), locus_html(locus)):
        assert "inside component #" not in text
        assert text.count("deeper drops not explored") == 1


def test_the_json_keeps_every_remark():
    locus = many_remarks()
    data = json.loads(render_json(locus))
    assert len(data["unexplored"]) == 73
    assert data["unexplored"][:2] == remark_texts([deeper(2), deeper(4)])
    # read back, the remarks are sentences: equal ones are said once with their count
    back = locus_from_json(data)
    assert len(back.unexplored) == 73
    assert grouped_remark_texts(back.unexplored + back.unexplored[:1])[0] \
        == remark_texts([deeper(2)])[0] + " (2 times)"
