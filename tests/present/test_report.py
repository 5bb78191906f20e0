"""Singularity-locus reports: Markdown, HTML, LaTeX and JSON content, plots, files,
and the ``coopkin locus`` command."""

from __future__ import annotations

import base64
import json
import math
import re
import shutil
import subprocess

import pytest

pytest.importorskip("matplotlib")

import matplotlib.image  # noqa: E402
from support import shipped_locus, texts  # noqa: E402
from typer.testing import CliRunner  # noqa: E402

from coopkin_sym import load  # noqa: E402
from coopkin_sym.analysis.locus.search import compute_locus  # noqa: E402
from coopkin_sym.analysis.locus.types import Component, FloatCheck, Locus  # noqa: E402
from coopkin_sym.cli import app  # noqa: E402
from coopkin_sym.exact.polynomial import NamedPolynomial
from coopkin_sym.present.locus_plot import (  # noqa: E402
    PlotError,
    components_on,
    default_pairs,
    plot_components,
)
from coopkin_sym.present.report import (  # noqa: E402
    ReportError,
    locus_from_json,
    render_html,
    render_json,
    render_latex,
    render_markdown,
    write_report,
)

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
GENERIC = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
# paper case 1 (hard contacts) where both links lie on the contact line
ON_LINE = {"Nm": 3, "Nc": 3, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 1}
runner = CliRunner()


def hand_made() -> Locus:
    """Paper case 1 with hard contacts, both angles free: two of its isolated
    configurations, float checks with one miss and one false alarm, a non-real
    component, bounds that left something out."""
    missed = FloatCheck(0.0, "L=1", {"q1": "-pi/2", "q2": "-pi/2", "L": "1"}, ON_LINE,
                        GENERIC)
    false_alarm = FloatCheck(1e-12, "L=1000", {"q1": "2*atan(-999999/1000000)",
                                               "q2": "-pi/2", "L": "1000"},
                             GENERIC, ON_LINE)
    agree = FloatCheck(1e-6, "L=1", {"q1": "2*atan(-99/100)", "q2": "-pi/2", "L": "1"},
                       GENERIC, GENERIC)
    return Locus(
        system="paper case 1, hard/hard", variables=["t_q1", "t_q2", "L"], fixed="",
        generic=dict(GENERIC),
        components=[
            Component(["t_q1 + 1", "t_q2 + 1"], dict(ON_LINE), {"q1": "-pi/2", "q2": "-pi/2"},
                      True, kind="isolated", condition="q1 = q2 = -pi/2", drops=["Q"],
                      changes={"Nm": (2, 3), "Nc": (2, 3), "Nh": (0, 1)},
                      stated_meaning=["Both links lie on the contact line."],
                      decided="exact at the point", witness_checked=True,
                      float_checks=[missed, false_alarm, agree]),
            Component(["t_q1 - 1", "t_q2 - 1"], dict(ON_LINE), {"q1": "pi/2", "q2": "pi/2"},
                      True, kind="isolated", condition="q1 = q2 = pi/2"),
            Component(["t_q1**2 + 1"], dict(ON_LINE), None, False),
        ],
        dropped=["t_q2**2 + 1 = 0 (no real points)"],
        unexplored=["inside component 1: deeper than max_depth = 0"],
        notes=["Every length is a multiple of L."])


def three_joints() -> Locus:
    """A made-up locus on three revolute joints: a chart component (q1 = pi), a
    curve, a point reached through the third joint's witness, a component of q3
    alone, and a non-real one."""
    n = dict(ON_LINE)
    return Locus("three joints", ["t_q1", "t_q2", "t_q3", "L"], "", dict(GENERIC), [
        Component(["s_q1"], n, {"q1": "pi", "q2": "0", "q3": "0"}, True, kind="chart",
                  condition="q1 = pi"),
        Component(["t_q1 - t_q2"], n, {"q1": "0", "q2": "0", "q3": "0"}, True,
                  condition="q1 = q2"),
        Component(["t_q1 - t_q3", "t_q2*t_q3 - 1"], n,
                  {"q1": "pi/2", "q2": "pi/2", "q3": "pi/2"}, True, kind="subvariety"),
        Component(["t_q3"], n, {"q1": "0", "q2": "0", "q3": "0"}, True,
                  condition="q3 = 0"),
        Component(["t_q1**2 + t_q2**2 + 1"], n, None, False),
    ])


@pytest.fixture(scope="module")
def case1() -> Locus:
    return shipped_locus("paper-case1-hard")


# --- the engine's result, as the reports see it ----------------------------------------


def test_case1_hard_real_locus_is_five_isolated_families(case1):
    assert case1.generic == GENERIC
    assert sorted(tuple(texts(c.equations)) for c in case1.components) == [
        ("t_q1 + 1", "t_q2 + 1"), ("t_q1 + 1", "t_q2 - 1"),
        ("t_q1 - 1", "t_q2 + 1"), ("t_q1 - 1", "t_q2 - 1"),
        ("t_q1**2 + 4*t_q1 + 1", "t_q1 + t_q2")]
    for c in case1.components:
        assert c.kind == "isolated" and c.real
    assert [c.numbers == ON_LINE for c in case1.components] == [True] * 4 + [False]
    # the brief's check: a direct analysis at the witness gives the same numbers
    c = next(c for c in case1.components if texts(c.equations) == ["t_q1 + 1", "t_q2 + 1"])
    assert c.witness == {"q1": "-pi/2", "q2": "-pi/2", "L": "1"}
    assert load("paper-case1-hard").analyze("q1=-pi/2,q2=-pi/2").numbers.as_dict() == ON_LINE


# --- Markdown --------------------------------------------------------------------------


def test_markdown_generic_numbers_and_components_table():
    md = render_markdown(hand_made())
    lines = md.splitlines()
    assert lines[0] == "# Singularity locus of paper case 1, hard/hard"
    assert "| **Nm** | mobility: independent motions of object and joints that keep every " \
           "contact | 2 |" in lines
    assert "| **Nd** | defective directions: contact forces the joints cannot balance | 4 |" \
        in lines
    assert ("| #1 | `q1 = q2 = -pi/2` | isolated point | **3** | **3** | 1 | 0 | 1 | 4 | "
            "**1** | `q1=-pi/2,q2=-pi/2` | **2/3 wrong**: 1 missed, 1 false alarm |") in lines
    assert ("| #3 | `t_q1**2 + 1 = 0` (real points: undecided) | hypersurface | **3** | **3** | "
            "1 | "
            "0 | 1 | 4 | **1** | none | not run |") in lines


def test_markdown_component_details():
    lines = render_markdown(hand_made()).splitlines()
    i = lines.index("### Component #1: q1 = q2 = -pi/2")
    assert lines[i + 2:i + 11] == [
        "- **Equations:** `t_q1 + 1 = 0`, `t_q2 + 1 = 0`",
        "- **In angles:** `q1 = q2 = -pi/2`",
        "- **Kind:** isolated point (depth 0); real points",
        "- **Numbers:** (3, 3, 1, 0, 1, 4, 1) for (Nm, Nc, Ni, Nr, Ng, Nd, Nh): "
        "Nm 2 \u2192 3, Nc 2 \u2192 3, Nh 0 \u2192 1; the others as generic",
        "- **Grasp classes:** indeterminate, graspable, defective, hyperstatic (becomes "
        "hyperstatic)",
        "- **Rank drops in:** Q",
        "- **Witness:** `q1=-pi/2,q2=-pi/2`; a direct exact analysis there gives the "
        "same numbers",
        "- **Decided:** exact at the point",
        "",
    ]
    assert "- Both links lie on the contact line." in lines
    assert ("| at the witness, L=1 | `q1=-pi/2,q2=-pi/2,L=1` | (3, 3, 1, 0, 1, 4, 1) | "
            "(2, 2, 1, 0, 1, 4, 0) | **wrong: missed a singular configuration** |") in lines
    assert ("| 1e-12 rad away, L=1000 | `q1=2*atan(-999999/1000000),q2=-pi/2,L=1000` | "
            "(2, 2, 1, 0, 1, 4, 0) | (3, 3, 1, 0, 1, 4, 1) | "
            "**wrong: called a regular configuration singular** |") in lines


def test_markdown_float_summary_counts():
    locus = hand_made()
    assert locus.float_summary() == {"missed_singular": 1, "false_singular": 1}
    md = render_markdown(locus)
    assert ("compared with the exact ones: 3 tests (1 at witnesses, 2 nearby). "
            "**Missed singular configurations: 1**; "
            "**regular configurations called singular: 1**.") in md
    assert "| #1 | `q1 = q2 = -pi/2` | 3 | 1 | 1 | 1 |" in md.splitlines()


def test_markdown_unexplored_dropped_and_notes_sections():
    lines = render_markdown(hand_made()).splitlines()
    i = lines.index("## Not explored")
    assert lines[i + 2] == "- inside component 1: deeper than max\\_depth = 0"
    i = lines.index("## Dropped factors (no real points)")
    assert lines[i + 2] == "- `t_q2**2 + 1 = 0` (no real points)"
    i = lines.index("## Parameter conditions")
    assert lines[i + 2] == "None: no degeneracy that involves the parameters alone."
    assert "- Every length is a multiple of L." in lines
    done = Locus("demo", ["t_q1"], "", dict(GENERIC))
    lines = render_markdown(done).splitlines()
    i = lines.index("## Not explored")
    assert lines[i + 2] == "Nothing: the search finished within its bounds."
    assert lines[lines.index("## Components") + 2] == (
        "None: the numbers are the generic ones at every configuration explored.")


def test_markdown_links_the_plots_only_when_given():
    md = render_markdown(hand_made(), {("q1", "q2"): "report_q1_q2.png"})
    assert "![Components in the (q1, q2) plane](report_q1_q2.png)" in md
    assert "## Plots" not in render_markdown(hand_made())


def test_markdown_of_the_real_case1(case1):
    lines = render_markdown(case1).splitlines()
    assert ("| #4 | `q1 = pi/2, q2 = pi/2` | isolated point | **3** | **3** | 1 | 0 | 1 | 4 "
            "| **1** | `q1=pi/2,q2=pi/2,L=1` |") in "\n".join(lines)
    # c1 = c2: irrational, decided over Q(sqrt 3), its real points read as angles
    assert ("| #5 | `q1 = -5*pi/6, q2 = 5*pi/6 or q1 = -pi/6, q2 = pi/6` | isolated point "
            "| **3** | **3** | **3** | 0 | **3** | 4 | **1** | `q1=-5*pi/6,q2=5*pi/6,L=1` |"
            ) in "\n".join(lines)
    assert ("- **Exact point:** alpha = t\\_q1 is the root of `alpha**2 + 4*alpha + 1 = 0` "
            "in (-4, -3\\]: alpha = -2 - sqrt(3)") in lines
    assert "- **Equations:** `t_q1 - 1 = 0`, `t_q2 - 1 = 0`" in lines


# --- HTML ------------------------------------------------------------------------------


def test_html_is_self_contained_with_tables_and_the_plot():
    png = PNG_SIGNATURE + b"rest"
    page = render_html(hand_made(), {("q1", "q2"): png})
    assert page.startswith("<!DOCTYPE html>")
    assert "<title>Singularity locus of paper case 1, hard/hard</title>" in page
    # every resource inline: the only src is the embedded PNG
    srcs = re.findall(r'src="([^"]*)"', page)
    assert srcs == ["data:image/png;base64," + base64.b64encode(png).decode()]
    assert "<link" not in page and "<script" not in page
    assert ('<tr><td>#1</td><td><code>q1 = q2 = -pi/2</code></td><td>isolated point</td>'
            '<td class="c"><strong>3</strong></td><td class="c"><strong>3</strong></td>'
            '<td class="c">1</td><td class="c">0</td><td class="c">1</td>'
            '<td class="c">4</td><td class="c"><strong>1</strong></td>'
            '<td><code>q1=-pi/2,q2=-pi/2</code></td>') in page
    assert "<strong>Missed singular configurations: 1</strong>" in page
    assert "<strong>regular configurations called singular: 1</strong>" in page
    assert "<li>inside component 1: deeper than max_depth = 0</li>" in page
    assert "<details><summary>the 3 float tests</summary>" in page


def test_html_escapes_text():
    locus = Locus("a <b> & c", [], "", dict(GENERIC),
                  unexplored=["x < y & z"])
    page = render_html(locus)
    assert "<h1>Singularity locus of a &lt;b&gt; &amp; c</h1>" in page
    assert "<li>x &lt; y &amp; z</li>" in page


# --- LaTeX -----------------------------------------------------------------------------


def test_latex_structure():
    tex = render_latex(hand_made(), {("q1", "q2"): "r_q1_q2.png"})
    lines = tex.splitlines()
    assert lines[1] == r"\section*{Singularity locus of paper case 1, hard/hard}"
    assert r"\subsection*{Generic numbers}" in lines
    assert r"\subsubsection*{Component \#1: $q_{1} = q_{2} = - \frac{\pi}{2}$}" in lines
    assert (r"\item \textbf{Equations:} $t_{q1} + 1 = 0$, $t_{q2} + 1 = 0$") in lines
    assert (r"\item \textbf{Witness:} $q_{1} = - \frac{\pi}{2}$, $q_{2} = - \frac{\pi}{2}$; "
            r"a direct exact analysis there gives the same numbers") in lines
    row = next(x for x in lines if x.startswith(r"\raggedright \#1 &"))
    cells = [c.strip() for c in row.split(" & ")]
    assert cells[2:9] == [r"\textbf{3}", r"\textbf{3}", "1", "0", "1", "4", r"\textbf{1}"]
    assert r"\textbf{Missed singular configurations: 1}" in tex
    assert r"\item inside component 1: deeper than max\_depth = 0" in lines
    assert (r"% \includegraphics[width=0.8\textwidth]{r_q1_q2.png}  % Components in the "
            "(q1, q2) plane") in lines
    # no package needed: no longtable, no \usepackage, balanced environments
    code = "\n".join(x for x in lines if not x.startswith("%"))
    assert "longtable" not in code and r"\usepackage" not in code
    for env in ("tabular", "itemize", "center"):
        assert tex.count(rf"\begin{{{env}}}") == tex.count(rf"\end{{{env}}}") > 0
    body = re.sub(r"\\[{}$%&#_]", "", code)
    assert body.count("{") == body.count("}")
    assert body.count("$") % 2 == 0


def test_latex_shows_only_the_wrong_float_tests():
    tex = render_latex(hand_made())
    assert "3 tests at and near the witness, 2 wrong:" in tex
    assert tex.count("wrong: missed a singular configuration") == 1
    assert tex.count("agrees") == 0


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex not installed")
def test_latex_compiles_with_a_plain_article(tmp_path, case1):
    for name, locus in (("hand", hand_made()), ("case1", case1)):
        (tmp_path / f"{name}.tex").write_text(render_latex(locus))
        (tmp_path / f"doc_{name}.tex").write_text(
            "\\documentclass{article}\n\\begin{document}\n\\input{" + name
            + ".tex}\n\\end{document}\n")
        done = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error",
                               f"doc_{name}.tex"], cwd=tmp_path, capture_output=True,
                              text=True, timeout=120)
        assert done.returncode == 0, done.stdout[-2000:]
        assert (tmp_path / f"doc_{name}.pdf").read_bytes()[:5] == b"%PDF-"


def _pdflatex(tmp_path, name: str) -> subprocess.CompletedProcess:
    (tmp_path / f"doc_{name}.tex").write_text(
        "\\documentclass{article}\n\\begin{document}\n\\input{" + name
        + ".tex}\n\\end{document}\n")
    return subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error",
                           f"doc_{name}.tex"], cwd=tmp_path, capture_output=True,
                          text=True, timeout=300)


@pytest.mark.slow   # a 33-page compile
@pytest.mark.skipif(shutil.which("pdflatex") is None or shutil.which("pdftotext") is None,
                    reason="pdflatex or pdftotext (poppler-utils) not installed")
def test_latex_tables_lose_no_row_across_pages(tmp_path):
    # the five-bar report: its tables run over several pages (one tabular per page
    # lost every row past the foot of the page: L12 to L38 of the locked system)
    done = CliRunner().invoke(app, ["locus", "five-bar", "-o", str(tmp_path / "r.tex")])
    assert done.exit_code == 0, done.output
    tex = (tmp_path / "r.tex").read_text()
    rows = re.findall(r"^(?:\\raggedright )?(L\d+|\\#\d+)(?: \(in L\d+\))? &", tex,
                      flags=re.MULTILINE)
    labels = [r.replace("\\#", "#") for r in rows]
    # every component has its row in the source (#1..#n, none skipped), and the locked
    # system's rows (L1.., some grouped) run far enough to fill several pages
    numbers = {x[0]: {int(y[1:]) for y in labels if y[0] == x[0]} for x in "#L"}
    assert numbers["#"] == set(range(1, max(numbers["#"]) + 1)) and len(numbers["#"]) > 15
    assert 1 in numbers["L"] and max(numbers["L"]) > 30
    compiled = _pdflatex(tmp_path, "r")
    assert compiled.returncode == 0, compiled.stdout[-2000:]
    text = subprocess.run(["pdftotext", "doc_r.pdf", "-"], cwd=tmp_path, capture_output=True,
                          text=True, timeout=120, check=True).stdout
    # every row of every table is in the PDF (the components' rows are #1.., the
    # locked system's L1..: pdftotext writes each cell on its own line)
    words = set(text.split())
    assert [x for x in labels if x not in words] == []
    assert int(re.search(r"Output written on doc_r.pdf \((\d+) pages",
                         compiled.stdout).group(1)) > 10


# --- JSON ------------------------------------------------------------------------------


def test_json_contract_and_round_trip(case1):
    for locus in (hand_made(), case1):
        data = json.loads(render_json(locus))
        assert data["generic"] == GENERIC
        for c in data["components"]:
            assert {"equations", "numbers", "witness", "real"} <= set(c)
            assert all(isinstance(e, str) for e in c["equations"])
            assert c["witness"] is None or all(isinstance(v, str)
                                               for v in c["witness"].values())
        # a report read back states what changes in words; the computed locus keeps
        # the exact data behind them: the documents are the same
        assert render_json(locus_from_json(data)) == render_json(locus)
        assert render_json(locus_from_json(render_json(locus))) == render_json(locus)
        back = locus_from_json(data)
        # the exact polynomials and conditions: read back from the report, they are
        # the ones the search found
        assert [(c.equations, c.outside, c.condition, c.chart) for c in back.components] \
            == [(c.equations, c.outside, c.condition, c.chart) for c in locus.components]
        names = list(locus.variables)
        assert all(isinstance(p, NamedPolynomial)
                   for c in back.components for p in c.equation_polynomials(names))
    data = json.loads(render_json(hand_made()))
    assert data["components"][0]["witness"] == {"q1": "-pi/2", "q2": "-pi/2"}
    assert data["components"][2]["witness"] is None
    assert data["components"][2]["real"] is False
    assert data["float_summary"] == {"missed_singular": 1, "false_singular": 1}
    assert data["unexplored"] == ["inside component 1: deeper than max_depth = 0"]


def test_json_that_is_not_a_locus():
    with pytest.raises(ReportError, match="not a locus report"):
        locus_from_json({"generic": {}})


# --- plots -----------------------------------------------------------------------------


def component_gids(fig) -> list[str]:
    return sorted(a.get_gid() for a in fig.axes[0].get_children()
                  if (a.get_gid() or "").startswith("component:"))


def artist(fig, gid: str):
    (found,) = [a for a in fig.axes[0].get_children() if a.get_gid() == gid]
    return found


def test_plot_case1_one_point_per_component_at_the_exact_places(case1):
    fig = plot_components(case1, load("paper-case1-hard"))
    assert component_gids(fig) == [f"component:{k + 1}" for k in range(5)]
    half = math.pi / 2
    # c1 = c2 (isolated, irrational): both real points, the witness at the first
    xs, ys = artist(fig, "component:5").get_data()
    assert sorted((float(x), float(y)) for x, y in zip(xs, ys, strict=True)) == [
        pytest.approx((-5 * math.pi / 6, 5 * math.pi / 6), abs=1e-9),
        pytest.approx((-math.pi / 6, math.pi / 6), abs=1e-9)]
    wx, wy = artist(fig, "witness:5").get_data()
    assert (float(wx[0]), float(wy[0])) == pytest.approx((-5 * math.pi / 6, 5 * math.pi / 6),
                                                         abs=1e-9)
    for k, c in enumerate(case1.components[:4]):
        xs, ys = artist(fig, f"component:{k + 1}").get_data()
        expected = (half if texts(c.equations)[0] == "t_q1 - 1" else -half,
                    half if texts(c.equations)[1] == "t_q2 - 1" else -half)
        assert [(float(x), float(y)) for x, y in zip(xs, ys, strict=True)] == \
            [pytest.approx(expected, abs=1e-12)]
        wx, wy = artist(fig, f"witness:{k + 1}").get_data()
        assert (float(wx[0]), float(wy[0])) == pytest.approx(expected, abs=1e-12)
    assert fig.axes[0].get_title().splitlines()[1] == "at L=1"


def test_plot_three_joints_draws_each_component_involving_the_pair():
    locus = three_joints()
    # t_q3 alone does not involve (q1, q2); the non-real one is never drawn
    assert components_on(locus, None, ("q1", "q2")) == [0, 1, 2]
    fig = plot_components(locus, None, ("q1", "q2"))
    assert component_gids(fig) == ["component:1", "component:2", "component:3"]
    # q1 = q2: a zero contour whose vertices lie on the diagonal
    line = artist(fig, "component:2")
    vertices = [v for p in line.get_paths() for v in p.vertices]
    assert len(vertices) > 10
    # (q = pi + e is q = -pi + e: the margins beyond +-pi repeat the diagonal)
    assert all(abs(math.remainder(x - y, 2 * math.pi)) < 2e-2 for x, y in vertices)
    # q1 = pi (second chart): a contour at q1 = pi and at q1 = -pi, the same angle
    edge = artist(fig, "component:1")
    xs = sorted({round(float(v[0]), 2) for p in edge.get_paths() for v in p.vertices})
    assert xs == [round(-math.pi, 2), round(math.pi, 2)]
    # q3 at its witness pi/2: q1 = q3 = pi/2 and t_q2 = 1 / t_q3 = 1, a point
    xs, ys = artist(fig, "component:3").get_data()
    assert [(float(x), float(y)) for x, y in zip(xs, ys, strict=True)] == \
        [pytest.approx((math.pi / 2, math.pi / 2), abs=1e-12)]
    assert "other joints at each component's witness" in fig.axes[0].get_title()
    assert "L symbolic" not in fig.axes[0].get_title()


def test_plot_pairs_and_errors():
    locus = three_joints()
    assert default_pairs(locus, None) == [("q1", "q2"), ("q1", "q3"), ("q2", "q3")]
    fig = plot_components(locus, None, ("q2", "q3"))
    assert component_gids(fig) == ["component:2", "component:3", "component:4"]
    with pytest.raises(PlotError, match="unknown joint 'q9'"):
        plot_components(locus, None, ("q1", "q9"))
    with pytest.raises(PlotError, match="must differ"):
        plot_components(locus, None, ("q1", "q1"))


def test_plot_legend_names_each_component():
    fig = plot_components(hand_made(), None)
    texts = [t.get_text() for t in fig.legends[0].get_texts()]
    assert texts == ["#1: q1 = q2 = -pi/2", "#2: q1 = q2 = pi/2", "exact witness point"]
    # no plotted equation involves L, so the title says nothing of it
    assert fig.axes[0].get_title() == ("paper case 1, hard/hard: singular configurations "
                                       "in the (q1, q2) plane")


# --- files -----------------------------------------------------------------------------


def test_write_markdown_with_png_next_to_it(tmp_path, case1):
    out = tmp_path / "report.md"
    written = write_report(case1, out, load("paper-case1-hard"))
    pictures = [f"report_system_component_{k}.png" for k in range(1, 6)]
    assert written == [out, tmp_path / "report_q1_q2.png",
                       *(tmp_path / name for name in pictures)]
    assert "![Components in the (q1, q2) plane](report_q1_q2.png)" in out.read_text()
    png = (tmp_path / "report_q1_q2.png").read_bytes()
    assert png.startswith(PNG_SIGNATURE)
    image = matplotlib.image.imread(tmp_path / "report_q1_q2.png")
    assert image.ndim == 3 and image.shape[0] > 300 and image.shape[1] > 300
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        "report.md", "report_q1_q2.png", *pictures]


def test_write_html_embeds_the_png_it_writes(tmp_path, case1):
    out = tmp_path / "r.html"
    write_report(case1, out, pairs=["q2,q1"])
    png = (tmp_path / "r_q2_q1.png").read_bytes()
    assert base64.b64encode(png).decode() in out.read_text()


def test_write_json_and_tex(tmp_path):
    write_report(hand_made(), tmp_path / "r.json")
    assert locus_from_json((tmp_path / "r.json").read_text()) == hand_made()
    write_report(hand_made(), tmp_path / "r.tex")
    assert (tmp_path / "r.tex").read_text() == render_latex(
        hand_made(), {("q1", "q2"): "r_q1_q2.png"})
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.json", "r.tex", "r_q1_q2.png"]


def test_write_errors_leave_nothing(tmp_path):
    with pytest.raises(ReportError, match=r"unknown report format '\.txt'"):
        write_report(hand_made(), tmp_path / "r.txt")
    with pytest.raises(ReportError, match="no such directory"):
        write_report(hand_made(), tmp_path / "missing" / "r.md")
    with pytest.raises(ReportError, match="unknown joint 'q7'"):
        write_report(hand_made(), tmp_path / "r.md", load("paper-case1-hard"),
                     pairs=["q1,q7"])
    # the report's name is taken by a directory: refused before anything is written
    (tmp_path / "taken.html").mkdir()
    with pytest.raises(ReportError, match="taken.html: is a directory"):
        write_report(hand_made(), tmp_path / "taken.html")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["taken.html"]
    assert list((tmp_path / "taken.html").iterdir()) == []


# --- the command -----------------------------------------------------------------------


def run_error(*args: str) -> str:
    result = runner.invoke(app, list(args))
    assert result.exit_code == 2, result.output
    assert result.stdout == ""
    assert "Traceback" not in result.stderr
    assert result.stderr.startswith("coopkin: error: ")
    assert result.stderr.count("\n") == 1
    return result.stderr


def test_cli_locus_writes_the_report(tmp_path):
    out = tmp_path / "case1.json"
    result = runner.invoke(app, ["locus", "paper-case1-hard", "-o", str(out),
                                 "--max-depth", "1", "--timeout", "600", "--no-progress"])
    assert result.exit_code == 0, result.output
    assert result.stdout.startswith("5 components (5 real)")
    data = json.loads(out.read_text())
    assert data["generic"] == GENERIC
    assert {tuple(c["equations"]) for c in data["components"]} == {
        ("t_q1 - 1", "t_q2 - 1"), ("t_q1 - 1", "t_q2 + 1"), ("t_q1 + 1", "t_q2 - 1"),
        ("t_q1 + 1", "t_q2 + 1"), ("t_q1**2 + 4*t_q1 + 1", "t_q1 + t_q2")}


def test_cli_locus_errors_write_nothing(tmp_path):
    assert "unknown report format '.txt'" in run_error(
        "locus", "paper-case1-hard", "-o", str(tmp_path / "r.txt"))
    assert "no such directory" in run_error(
        "locus", "paper-case1-hard", "-o", str(tmp_path / "nope" / "r.md"))
    assert "no such file" in run_error("locus", "no-such-model", "-o",
                                       str(tmp_path / "r.md"))
    assert "unknown joint 'q9'" in run_error(
        "locus", "paper-case1-hard", "-o", str(tmp_path / "r.md"), "--pair", "q1,q9")
    assert "expected two joints" in run_error(
        "locus", "paper-case1-hard", "-o", str(tmp_path / "r.md"), "--pair", "q1")
    assert "not exact" in run_error(
        "locus", "paper-case1-hard", "-o", str(tmp_path / "r.md"), "--at", "q1=pi/3")
    assert list(tmp_path.iterdir()) == []


def test_report_carries_a_picture_of_the_system_at_a_witness(tmp_path):
    from coopkin_sym.present.report import write_report

    system = load("paper-case1-hard")
    written = write_report(compute_locus(system), tmp_path / "r.md", system=system)
    names = [p.name for p in written]
    assert "r_system_component_1.png" in names
    picture = tmp_path / "r_system_component_1.png"
    assert picture.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    text = (tmp_path / "r.md").read_text()
    assert "![Component 1 (q1 = -pi/2, q2 = -pi/2): the system at its witness" in text
