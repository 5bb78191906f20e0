"""A locus report a person can read: remarks said once with their count, polynomials
named once, plots on free joints with distinct legend entries, LaTeX tables that
break across pages."""

from __future__ import annotations

import json

import matplotlib
import pytest

matplotlib.use("Agg")
from matplotlib.colors import to_hex  # noqa: E402

from coopkin_sym import load  # noqa: E402
from coopkin_sym.analysis.locus.remarks import Remark  # noqa: E402
from coopkin_sym.analysis.locus.types import Component, Locus  # noqa: E402
from coopkin_sym.errors import PlotError  # noqa: E402
from coopkin_sym.present.certificate import CERTIFIED, CertificateRead  # noqa: E402
from coopkin_sym.present.display import locus_html, pretty_text  # noqa: E402
from coopkin_sym.present.locus_plot import (  # noqa: E402
    default_pairs,
    free_joints,
    plot_components,
)
from coopkin_sym.present.plot_legend import LEGEND_ENTRIES  # noqa: E402
from coopkin_sym.present.remarks import grouped_remark_texts, remark_texts  # noqa: E402
from coopkin_sym.present.report import render_html, render_latex, render_markdown  # noqa: E402
from coopkin_sym.present.report.to_json import locus_from_json, render_json  # noqa: E402

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


# --- named polynomials -----------------------------------------------------------------

L1 = "3*t_q1**2*t_q2**2 + 8*t_q1*t_q2 + 3*t_q1**2 - 7*t_q2 + 1"
L2 = "5*t_q1**3*t_q2 + 2*t_q1*t_q2**2 - 9*t_q1**2 + 4*t_q2**3 - 11"
P1 = "3*t_q1**2*t_q2**2 + 3*t_q1**2 + 8*t_q1*t_q2 - 7*t_q2 + 1"   # L1 as written
P2 = "5*t_q1**3*t_q2 - 9*t_q1**2 + 2*t_q1*t_q2**2 + 4*t_q2**3 - 11"


def long_polynomials() -> Locus:
    """L1 in #1 (its second equation) and #3 (its first), L2 in #2."""
    nm3 = dict(GENERIC, Nm=3)
    return Locus("planted", ["t_q1", "t_q2", "t_q3"], "", GENERIC, [
        Component(["t_q3", L1], nm3, {"q1": "0"}, True, condition=f"q3 = 0, {L1} = 0"),
        Component([L2], nm3, None, True),
        Component([L1], nm3, None, True, condition=f"{L1} = 0")])


def test_long_polynomials_are_named_once_across_the_report():
    md = render_markdown(long_polynomials())
    rows = [line for line in md.splitlines()
            if line.startswith("| #") and " | where |" not in line]
    assert [r.split(" | ")[1] for r in rows] == [
        "`q3 = 0, P1(t_q1, t_q2) = 0`", "`P2(t_q1, t_q2) = 0`", "`P1(t_q1, t_q2) = 0`"]
    # the details refer to the names; each polynomial is written once, in the appendix
    assert "- **Equations:** `t_q3 = 0`, `P1(t_q1, t_q2) = 0`\n" in md
    assert "- **Equations:** `P2(t_q1, t_q2) = 0`\n" in md
    assert md.endswith("## Polynomials\n\nThe polynomials named in the tables and the "
                       "components above, each written once.\n\n"
                       f"- `P1 = {P1}`\n- `P2 = {P2}`\n")
    assert md.count(P1) == 1 and md.count(P2) == 1
    html = render_html(long_polynomials())
    assert html.count(P1) == 1 and html.count(P2) == 1
    assert (f'<h2 id="polynomials">Polynomials</h2>\n<p>The polynomials named in the '
            f"tables and the components above, each written once.</p>\n<ul><li><code>P1 = "
            f"{P1}</code></li><li><code>P2 = {P2}</code></li></ul>") in html
    tex = render_latex(long_polynomials())
    assert (r"\item $P_{1} = 3 t_{q1}^{2} t_{q2}^{2} + 3 t_{q1}^{2} + 8 t_{q1} t_{q2} "
            r"- 7 t_{q2} + 1$") in tex
    assert r"$q_{3} = 0$, $P_{1}(t_{q1}, t_{q2}) = 0$" in tex
    assert "P_{3}" not in tex


def test_the_locked_system_names_polynomials_as_the_report_does():
    locked_generic = dict(GENERIC, Nm=1, Nc=1)
    locked = Locus("planted", ["t_q2"], "", locked_generic,
                   [Component([L1], dict(locked_generic, Nm=2, Nc=2), None, True)],
                   locked_joints=["q1"])
    locus = Locus("planted", ["t_q1", "t_q2"], "", GENERIC,
                  [Component([L1], dict(GENERIC, Nm=3), None, True)], locked=locked)
    md = render_markdown(locus)
    assert "| L1 | `P1(t_q1, t_q2) = 0` | **2** |" in md
    assert md.count(P1) == 1 and md.endswith(f"- `P1 = {P1}`\n")


def test_short_polynomials_are_not_named():
    md = render_markdown(many_remarks())
    assert "## Polynomials" not in md and "P1" not in md


def test_the_witness_column_wraps_and_wide_tables_scroll():
    html = render_html(long_polynomials())
    assert "table.components td code { word-break: break-all; }" in html
    assert "div.table { overflow-x: auto; max-width: 100%; }" in html
    assert html.count('<div class="table"><table') == html.count("<table")


# --- plots ------------------------------------------------------------------------------


def test_plots_take_only_free_joints_as_axes():
    system = load("planar-two-fingers")
    locus = system.locus(free=["q3", "q4"])
    assert locus.fixed == "q1=0,q2=0,L=1" and free_joints(locus, system) == ["q3", "q4"]
    # its components involve q4 alone: the other axis is the other free joint, not q1
    assert default_pairs(locus, system) == [("q3", "q4")]
    assert default_pairs(system.locus(free=["q2", "q3"]), system) == [("q2", "q3")]
    with pytest.raises(PlotError, match=r"^pair \(q1, q4\): joint 'q1' is fixed in this "
                                        r"locus, not an axis \(free joints: q3, q4\)$"):
        plot_components(locus, system, ("q1", "q4"))
    fig = plot_components(locus, system, ("q3", "q4"))
    assert (fig.axes[0].get_xlabel(), fig.axes[0].get_ylabel()) == ("q3 (rad)", "q4 (rad)")


def planted_lines(n: int) -> Locus:
    """``n`` components q1 = constant (vertical lines in the (q1, q2) plane)."""
    nm3 = dict(GENERIC, Nm=3)
    return Locus("planted", ["t_q1", "t_q2"], "", GENERIC,
                 [Component([f"{n + 1}*t_q1 - {2 * k - n}"], nm3, None, True)
                  for k in range(n)])


def _styles(lines) -> list[tuple[str, str]]:
    return [(to_hex(h.get_color()), h.get_marker()) for h in lines]


@pytest.mark.parametrize("n", [30, pytest.param(102, marks=pytest.mark.slow)])
def test_every_legend_entry_and_every_component_has_its_own_style(n):
    fig = plot_components(planted_lines(n), None, ("q1", "q2"), by="component")
    entries = [h for h in fig.legends[0].legend_handles if h.get_label().startswith("#")]
    assert len(entries) == min(n, LEGEND_ENTRIES)
    assert len(set(_styles(entries))) == len(entries)
    marks = [a for a in fig.axes[0].get_lines() if (a.get_gid() or "").startswith("marks:")]
    assert sorted(int(a.get_gid()[6:]) for a in marks) == list(range(1, n + 1))
    assert len(set(_styles(marks))) == n
    # the legend says what it left out
    labels = [h.get_label() for h in fig.legends[0].legend_handles]
    assert labels[-1] == "exact witness point"
    assert (labels[-2] == f"\u2026 and {n - LEGEND_ENTRIES} more (see the report)") \
        == (n > LEGEND_ENTRIES)


def test_many_components_of_few_families_are_coloured_by_family():
    nm4 = dict(GENERIC, Nm=4)
    locus = planted_lines(30)
    locus.components += [Component(["t_q2"], nm4, None, True)]
    fig = plot_components(locus, None, ("q1", "q2"))                 # by="auto"
    labels = [h.get_label() for h in fig.legends[0].legend_handles]
    assert labels == ["A: Nm 2 \u2192 3 (30 components; e.g. #1)",
                      "B: Nm 2 \u2192 4 (1 component; e.g. #31)", "exact witness point"]
    lines = fig.axes[0].get_lines()
    marks = [a for a in lines if (a.get_gid() or "").startswith("marks:")]
    assert len(marks) == 31 and set(_styles(marks[:30])) == {_styles(marks[:1])[0]}
    assert _styles(marks[30:]) != _styles(marks[:1])
    few = plot_components(planted_lines(5), None, ("q1", "q2"))       # five: by component
    assert sum(h.get_label().startswith("#") for h in few.legends[0].legend_handles) == 5
    with pytest.raises(PlotError, match="by: 'colour' is not one of"):
        plot_components(locus, None, ("q1", "q2"), by="colour")


def test_the_certificate_notes_are_said_once_with_their_count():
    note = "Only depths up to 2 were tested."
    locus = many_remarks()
    locus.certificate = CertificateRead("planted", True, summary=CERTIFIED, tests=3,
                                        backends={"flint": 3}, notes=[note] * 5)
    md = render_markdown(locus)
    assert md.count(note) == 1 and f"- {note} (5 times)\n" in md


def test_places_of_a_grouped_remark_are_told_apart_and_cut():
    long = " + ".join(f"t_q1**{k}" for k in range(1, 40))
    remarks = [Remark.of("enclosing_not_searched", equations=eqs,
                         reason="no_parametrization", bound=None)
               for eqs in (("t_q2", "t_q1 - 1"), ("t_q3",), (long,))]
    assert grouped_remark_texts(remarks) == [
        "deeper drops not searched (no rational parametrization; enclosing numbers "
        "there), inside 3 places: t_q2, t_q1 - 1; t_q3; " + long[:116] + " ..."]


def test_a_grouped_remark_names_the_polynomials_the_report_named():
    locus = long_polynomials()
    locus.unexplored = [Remark.of("time_depth", depth=2, equations=eqs)
                        for eqs in (("t_q3", P1), (P2,), ("t_q1 - 1",))]
    md = render_markdown(locus)
    assert ("- depth 2: not explored, time bound reached, inside 3 places: t\\_q3, P1; P2; "
            "t\\_q1 - 1\n") in md
    assert md.count(P1) == 1
    # a remark said alone names them too
    locus.unexplored = [Remark.of("time_depth", depth=2, equations=("t_q3", P2))]
    assert "- depth 2 inside t\\_q3; P2: not explored, time bound reached\n" \
        in render_markdown(locus)


def test_the_families_say_which_are_bifurcations_and_which_only_first_order():
    """With the finite mobility at the witnesses, each family's row counts what its
    members are (the four-bar: family A bifurcates at two folded points and is shaky
    at the third; B is shaky), in every format, and read back from the JSON."""
    system = load("four-bar")
    locus = system.locus()
    locus.finite_mobility()
    md = render_markdown(locus)
    assert "| finite motion |" in md
    assert "| #1, #3, #4 | bifurcation at 2, shaky at 1 (of 3) |" in md
    assert "| #2 | shaky (its witness) |" in md
    assert "bifurcation at 2, shaky at 1 (of 3)" in render_html(locus)
    assert "bifurcation at 2, shaky at 1 (of 3)" in render_latex(locus)
    again = locus_from_json(render_json(locus))
    assert "bifurcation at 2, shaky at 1 (of 3)" in render_markdown(again)
    plain = system.locus()
    assert "finite motion" not in render_markdown(plain)
