"""Pictures come with the default install, every part of an output left out is
announced (``coopkin: note: ...`` on stderr, an ``OutputSkipped`` warning in Python),
and ``draw`` works at angles with an irrational ``tan(q/2)``."""

from __future__ import annotations

import tomllib
import warnings
from pathlib import Path

import pytest
from typer.testing import CliRunner

from coopkin_sym import load
from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.cli import app
from coopkin_sym.errors import OutputSkipped
from coopkin_sym.present.draw import draw_system
from coopkin_sym.present.report import write_report

runner = CliRunner()
ROOT = Path(__file__).resolve().parents[2]
PNG = b"\x89PNG\r\n\x1a\n"

# one prismatic joint pushing a hard finger: its numbers never change, so its locus
# has no component and there is nothing to plot
SLIDER = """\
name: one slider
arms:
  - name: a1
    joints:
      - {name: d1, type: prismatic, axis: [1, 0, 0], point: [0, 0, 0]}
contacts:
  - {name: c1, link: a1/1, point: [1, 0, 0], normal: [1, 0, 0], model: hard}
"""


def notes(stderr: str) -> list[str]:
    return [line for line in stderr.splitlines() if line.startswith("coopkin: note: ")]


# --- pictures in the default install -------------------------------------------------------
def test_matplotlib_is_a_required_dependency():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert any(d.startswith("matplotlib") for d in project["dependencies"])
    readme = (ROOT / "README.md").read_text()
    assert "pip install . " in readme   # the first command installs the pictures too


# --- skipped outputs are announced ---------------------------------------------------------
def test_locus_announces_plots_left_out(tmp_path):
    model = tmp_path / "slider.yaml"
    model.write_text(SLIDER)
    out = tmp_path / "r.md"
    result = runner.invoke(app, ["locus", str(model), "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert "wrote" in result.stdout and out.exists()
    assert notes(result.stderr) == [
        "coopkin: note: no plot of the components: the locus has no component",
        "coopkin: note: no picture of the system: no component has a real witness to "
        "draw it at"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.md", "slider.yaml"]


def test_locus_json_has_no_plots_and_no_notes(tmp_path):
    model = tmp_path / "slider.yaml"
    model.write_text(SLIDER)
    result = runner.invoke(app, ["locus", str(model), "-o", str(tmp_path / "r.json")])
    assert result.exit_code == 0, result.output
    assert result.stderr == ""


def test_locus_with_plots_has_no_notes(tmp_path):
    result = runner.invoke(app, ["locus", "planar-two-fingers", "--free", "q3,q4",
                                 "--max-depth", "0", "-o", str(tmp_path / "r.md")])
    assert result.exit_code == 0, result.output
    assert notes(result.stderr) == []
    assert len(list(tmp_path.glob("r_*.png"))) == 3     # a plot, the system at 2 components


def test_a_locus_with_one_free_joint_is_not_plotted_on_a_fixed_one(tmp_path):
    # q1 is fixed: the components are points of q2 alone, and q1 is no axis
    result = runner.invoke(app, ["locus", "paper-case1-hard", "--at", "q1=pi/2,L=1",
                                 "--max-depth", "0", "-o", str(tmp_path / "r.md")])
    assert result.exit_code == 0, result.output
    assert notes(result.stderr) == [
        "coopkin: note: no plot of the components: a plot takes two free joints as its "
        "axes, and the free joints are q2 (a fixed joint is never an axis)"]
    assert len(list(tmp_path.glob("r_*.png"))) == 2     # the system at 2 components


def test_write_report_warns_for_what_it_leaves_out(tmp_path):
    locus = Locus("demo", ["t_q1"], "", {"Nm": 1})
    with pytest.warns(OutputSkipped) as caught:
        written = write_report(locus, tmp_path / "r.html", load("paper-case1-hard"))
    assert [str(w.message) for w in caught] == [
        "no plot of the components: the locus has no component",
        "no picture of the system: no component has a real witness to draw it at"]
    assert [p.name for p in written] == ["r.html"]


# --- draw at irrational angles -------------------------------------------------------------
def test_draw_at_irrational_angles(tmp_path):
    out = tmp_path / "x.png"
    result = runner.invoke(app, ["draw", "paper-case1-hard", "--at", "q1=-pi/6,q2=pi/6",
                                 "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert result.stdout == f"wrote {out}\n" and result.stderr == ""
    assert out.read_bytes().startswith(PNG)


def test_draw_at_irrational_angles_says_the_motion_is_not_drawn(tmp_path):
    out = tmp_path / "y.png"
    result = runner.invoke(app, ["draw", "paper-case2-hard", "--at", "q1=pi/3,q3=-pi/4",
                                 "--motion", "coordinated:1", "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert notes(result.stderr) == [
        "coopkin: note: coordinated motion 1 not drawn: the blocks are not computed at a "
        "configuration with irrational coordinates (use one with rational tan(q/2), "
        "e.g. 2*atan(p/q))"]
    assert out.read_bytes().startswith(PNG)
    # the motion is still checked against the exact numbers there (Nc - Ni = 5)
    result = runner.invoke(app, ["draw", "paper-case2-hard", "--at", "q1=pi/3",
                                 "--motion", "coordinated:6", "-o", str(out)])
    assert result.exit_code == 2
    assert "there is no coordinated motion 6: this system has 5" in result.stderr
    assert "Traceback" not in result.stderr


def test_draw_refuses_transcendental_angles(tmp_path):
    result = runner.invoke(app, ["draw", "paper-case1-hard", "--at", "q1=1",
                                 "-o", str(tmp_path / "z.png")])
    assert result.exit_code == 2
    assert result.stderr.startswith("coopkin: error: --at q1: angle '1' is not exact")
    assert not (tmp_path / "z.png").exists()


def test_the_picture_at_irrational_angles():
    case1 = load("paper-case1-hard")
    with warnings.catch_warnings():
        warnings.simplefilter("error", OutputSkipped)    # nothing asked is left out
        fig = draw_system(case1, at="q1=-pi/6,q2=pi/6,L=2")
    title = fig.axes[0].get_title()
    assert "at q1=-pi/6,q2=pi/6,L=2   Nm=3 Nc=3 Ni=3 Nr=0" in title   # exact numbers
    assert "tan(q1/2), tan(q2/2) irrational" in title
    assert "drawn at home" not in title
    # both contacts meet at the tip, at (L cos(pi/3), L sin(pi/3)) = (1, sqrt(3))
    dots = [a for a in fig.axes[0].get_children()
            if (a.get_gid() or "").startswith("contact:")]
    for dot in dots:
        x, y, _ = (float(v[0]) for v in dot.get_data_3d())
        assert x == pytest.approx(1.0, abs=1e-12)
        assert y == pytest.approx(3 ** 0.5, abs=1e-12)
    # the analysis itself can be drawn, and a motion asked for is announced
    analysis = case1.analyze("q1=-pi/6,q2=pi/6")
    with pytest.warns(OutputSkipped, match="indeterminate motion 1 not drawn"):
        fig = draw_system(analysis, motion="indeterminate:1")
    assert "not drawn" in fig.axes[0].get_title()
    assert case1.draw("q1=pi/3").axes
