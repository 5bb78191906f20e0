"""``coopkin manipulability``: the exact ellipsoid, where it degenerates, the float
semi-axes at a point, JSON, and clear errors."""

from __future__ import annotations

import json

import numpy as np
import pytest
import sympy as sp
from typer.testing import CliRunner

import coopkin_sym
from coopkin_sym.cli import app
from coopkin_sym.errors import ManipulabilityError
from coopkin_sym.present.manipulability import degeneracy_text, semi_axes

runner = CliRunner()


def test_five_bar_pin_at_home_text_and_json():
    done = runner.invoke(app, ["manipulability", "five-bar", "--at", "L=1",
                               "--controlled", "v_x,v_y", "--point", "0,2,0"])
    assert done.exit_code == 0, done.output
    assert "unit motor speed" in done.stdout
    assert "E = [[1/2, 0], [0, 1/2]]" in done.stdout and "det E = 1/4" in done.stdout
    assert "Semi-axes (floats): 0.707107, 0.707107" in done.stdout
    done = runner.invoke(app, ["manipulability", "five-bar", "--at", "L=1",
                               "--controlled", "v_x,v_y", "--point", "0,2,0", "--json"])
    data = json.loads(done.stdout)
    assert data["shape"] == [["1/2", "0"], ["0", "1/2"]] and data["rank"] == 2
    assert data["speed"] == "motor"
    assert np.allclose(data["semi_axes_float"], [2 ** -0.5] * 2)  # float-ok: labelled


def test_degeneracy_in_angles_where_the_finger_straightens():
    """planar-two-fingers loses a direction where a finger is stretched or folded
    (q2 = +-pi/2): the factors of det E say so, in angles."""
    done = runner.invoke(app, ["manipulability", "planar-two-fingers", "--free", "q2",
                               "--length", "L"])
    assert done.exit_code == 0, done.output
    assert "E loses rank where: q2 = pi/2 or q2 = -pi/2" in done.stdout
    assert "Semi-axes" not in done.stdout       # E still depends on t_q2
    a = coopkin_sym.load("planar-two-fingers").analyze("q2=pi/2,L=1")
    assert a.manipulability(length=1).rank == 2 == a.numbers.Nc


def test_semi_axes_only_at_a_point():
    m = coopkin_sym.load("planar-two-fingers").analyze(free=["q2"]).manipulability()
    with pytest.raises(ManipulabilityError, match="E still depends on"):
        semi_axes(m)


def test_degeneracy_text():
    t = sp.Symbol("t_q1")
    assert degeneracy_text(t) == "q1 = 0"
    assert degeneracy_text(2 * t - 1) == "q1 = 2*atan(1/2)"
    assert degeneracy_text(t * sp.Symbol("t_q2") - 1) == "t_q1*t_q2 - 1 = 0"


@pytest.mark.parametrize("args, fragment", [
    (["--controlled", "v_z"], "unknown object motion 'v_z'"),
    (["--at", "q1=pi/6"], "rational configurations only"),
    (["--length", "-1"], "positive length"),
])
def test_errors_are_one_line(args, fragment):
    done = runner.invoke(app, ["manipulability", "five-bar", *args])
    assert done.exit_code == 2 and "Traceback" not in done.output
    assert fragment in done.stderr
