"""Pictures come with the default install, every part of an output left out is
announced (``coopkin: note: ...`` on stderr, an ``OutputSkipped`` warning in Python)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest
from typer.testing import CliRunner

from coopkin_sym import load
from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.cli import app
from coopkin_sym.errors import OutputSkipped
from coopkin_sym.present.report import write_report

runner = CliRunner()
ROOT = Path(__file__).resolve().parents[2]

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
    result = runner.invoke(app, ["locus", "paper-case1-hard", "--at", "q1=pi/2,L=1",
                                 "--max-depth", "0", "-o", str(tmp_path / "r.md")])
    assert result.exit_code == 0, result.output
    assert notes(result.stderr) == []
    assert len(list(tmp_path.glob("r_*.png"))) == 2


def test_write_report_warns_for_what_it_leaves_out(tmp_path):
    locus = Locus("demo", ["t_q1"], "", {"Nm": 1})
    with pytest.warns(OutputSkipped) as caught:
        written = write_report(locus, tmp_path / "r.html", load("paper-case1-hard"))
    assert [str(w.message) for w in caught] == [
        "no plot of the components: the locus has no component",
        "no picture of the system: no component has a real witness to draw it at"]
    assert [p.name for p in written] == ["r.html"]
