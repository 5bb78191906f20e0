"""The ``coopkin`` command: JSON content, human output, exit codes, clean errors."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
from typer.testing import CliRunner

from coopkin_sym.cli import app

runner = CliRunner()

EXAMPLES = ["allegro-hand-sphere", "bennett-linkage", "bricard-linkage",
            "dh-three-finger-hand", "dh-two-puma560-box",
            "five-bar", "four-bar", "panda-two-arm-box", "paper-case1-complete-hard",
            "paper-case1-hard", "paper-case1-planar",
            "paper-case1-soft", "paper-case1-soft-hard", "paper-case2-complete",
            "paper-case2-hard", "parallel-cranks", "planar-two-fingers",
            "quadruped-standing", "seven-r-loop", "shaky-pinned-bars",
            "underactuated-finger", "urdf-two-fingers"]


def run_ok(*args: str) -> str:
    result = runner.invoke(app, list(args))
    assert result.exit_code == 0, result.output
    return result.stdout


def run_error(*args: str) -> str:
    result = runner.invoke(app, list(args))
    assert result.exit_code == 2, result.output
    assert result.stdout == ""
    assert "Traceback" not in result.stderr
    assert result.stderr.startswith("coopkin: error: ")
    return result.stderr


def test_paper_case2_hard_json():
    out = json.loads(run_ok("analyze", "paper-case2-hard", "--json"))
    assert out["numbers"] == {"Nm": 8, "Nc": 6, "Ni": 1, "Nr": 2, "Ng": 1, "Nd": 0, "Nh": 0}
    assert out["blocks"]["C11"] == [["0"], ["L"], ["-L"], ["1"], ["0"], ["0"]]
    c23 = out["blocks"]["C23"]
    assert [row for row in c23] == [["0", "0"], ["0", "0"], ["1", "0"], ["0", "0"],
                                    ["0", "0"], ["0", "1"], ["0", "0"], ["0", "0"]]
    assert out["shapes"] == {"C11": [6, 1], "C12": [6, 5], "C22": [8, 5], "C23": [8, 2]}


def test_at_sets_angles_and_parameters_exactly():
    out = json.loads(run_ok("analyze", "paper-case1-hard", "--at",
                            "q1=pi/2,q2=2*atan(1/3),L=1000", "--json"))
    assert out["configuration"] == "q1=pi/2,q2=2*atan(1/3),L=1000"
    assert out["variables"] == []
    assert out["numbers"]["Nm"] == 2


def test_generic_keeps_joints_symbolic():
    out = json.loads(run_ok("analyze", "paper-case1-hard", "--generic", "--json"))
    assert out["variables"] == ["t_q1", "t_q2", "L"]
    assert out["numbers"]["Ni"] == 1


def test_human_output_explains_each_number():
    out = run_ok("analyze", "paper-case1-hard")
    assert "Nm = 2  Nc = 2  Ni = 1  Nr = 0" in out
    assert "rotate about the line through c1 and c2" in out
    assert ("one driven by the joints (translate along x by moving joints q1 and q2 at "
            "equal speed)") in out
    out2 = run_ok("analyze", "paper-case2-hard")
    assert "joint q3 alone; joint q6 alone" in out2


def test_latex_output():
    out = run_ok("analyze", "paper-case2-complete", "--latex")
    assert r"C_{12} = \left[\begin{matrix}L & 0 & 0" in out
    assert r"$N_{m} = 3$" in out


def test_latex_and_text_at_an_irrational_angle():
    out = run_ok("analyze", "paper-case1-hard", "--at", "q1=-pi/6,q2=pi/6", "--latex")
    assert out.splitlines()[0] == "% paper case 1, hard/hard at q1=-pi/6,q2=pi/6"
    assert "$N_{i} = 3$" in out and "% blocks not computed" in out
    text = run_ok("analyze", "paper-case1-hard", "--at", "q1=-pi/6,q2=pi/6")
    assert text.splitlines()[:2] == ["System: paper case 1, hard/hard",
                                     "Configuration: q1=-pi/6,q2=pi/6"]
    assert "Grasp classes: indeterminate (Ni = 3)" in text


def test_examples_lists_the_paper_cases():
    out = run_ok("examples")
    assert [line.split()[0] for line in out.splitlines()] == EXAMPLES


@pytest.mark.parametrize("args, fragment", [
    (["analyze", "no-such-model.yaml"], "no-such-model.yaml"),
    (["analyze", "paper-case1-hard", "--at", "q1=1/2"], "nearest exact"),
    (["analyze", "paper-case1-hard", "--at", "q9=0"], "unknown name 'q9'"),
    (["analyze", "paper-case1-hard", "--at", "L=-1"], "positive"),
    (["analyze", "paper-case1-hard", "--at", "q1"], "expected NAME=VALUE"),
    (["analyze", "paper-case1-hard", "--free", "q7"], "unknown joint q7"),
])
def test_errors_are_one_clear_line(args, fragment):
    assert fragment in run_error(*args)


def test_bad_model_file_names_the_entry(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: x\narms:\n  - name: a\n    joints:\n"
                   "      - {name: q1, type: revolute, axis: [0, 0, 2], point: [0, 0, 0]}\n"
                   "contacts:\n  - {name: c, link: a/1, point: [1, 0, 0], model: hard}\n")
    err = run_error("analyze", str(bad))
    assert "bad.yaml" in err and "arms[0].joints[0].axis" in err


def test_module_entry_point_exit_codes():
    ok = subprocess.run([sys.executable, "-m", "coopkin_sym", "analyze", "paper-case1-soft",
                         "--json"], capture_output=True, text=True, check=False)
    assert ok.returncode == 0 and json.loads(ok.stdout)["numbers"]["Nm"] == 1
    bad = subprocess.run([sys.executable, "-m", "coopkin_sym", "analyze", "paper-case1-soft",
                          "--at", "q1=1"], capture_output=True, text=True, check=False)
    assert bad.returncode == 2 and bad.stdout == ""
    assert "Traceback" not in bad.stderr and "q1" in bad.stderr


def test_locus_free_keeps_the_other_joints_at_home(tmp_path):
    """``--free`` as in ``analyze``: only q2 free, q1 at home (0), in paper case 1 with
    c1 complete and c2 hard: the numbers change where c2 lies on the line through both
    base joints (q2 = +-pi/2), and nowhere else (q2 = pi included)."""
    out = tmp_path / "free.json"
    result = runner.invoke(app, ["locus", "paper-case1-complete-hard", "--free", "q2",
                                 "-o", str(out), "--no-progress"])
    assert result.exit_code == 0, result.output
    data = json.loads(out.read_text())
    assert data["variables"] == ["t_q2"] and data["fixed"] == "q1=0,L=1"
    # q2 = +-pi/2: c2 on the line through both base joints (Nm 0 -> 1)
    assert sorted((c["condition"], c["numbers"]["Nm"], c["parent"], c["real_points"])
                  for c in data["components"]) == [
        ("q2 = -pi/2", 1, None, "witness"), ("q2 = pi/2", 1, None, "witness")]
    bad = runner.invoke(app, ["locus", "paper-case1-hard", "--free", "q9", "-o",
                              str(tmp_path / "x.json"), "--no-progress"])
    assert bad.exit_code != 0 and "q9" in bad.stderr


def test_version_is_the_installed_packages():
    from importlib.metadata import version

    assert run_ok("--version") == f"coopkin {version('coopkin_sym')}\n"
    import coopkin_sym
    assert coopkin_sym.version() == coopkin_sym.__version__ == version("coopkin_sym")


@pytest.mark.parametrize("command", ["analyze", "locus", "sweep", "draw", "verify",
                                     "manipulability", "examples"])
def test_flags_are_plain_flags_in_the_help(command):
    out = run_ok(command, "--help")
    assert "<bool>" not in out and "--help" in out
    if command == "analyze":
        lines = {line.split()[1]: line for line in out.splitlines()
                 if line.startswith("│ --")}
        for flag in ("--generic", "--json", "--latex", "--finite", "--no-progress"):
            assert not lines[flag].split()[2].startswith("<"), lines[flag]  # no value
        assert lines["--at"].split()[2] == "<str>"                  # options keep theirs
        assert "q1=90deg" in out


def test_at_in_degrees_is_the_exact_angle():
    degrees = json.loads(run_ok("analyze", "paper-case1-hard", "--at", "q1=90deg,q2=-90*deg",
                                "--json"))
    radians = json.loads(run_ok("analyze", "paper-case1-hard", "--at", "q1=pi/2,q2=-pi/2",
                                "--json"))
    assert degrees["configuration"] == "q1=pi/2,q2=-pi/2"
    assert degrees == radians
    err = run_error("analyze", "paper-case1-hard", "--at", "q1=90degx")
    assert err == ("coopkin: error: --at q1: '90degx' cannot be parsed (an angle in "
                   "degrees is written 90deg or 90*deg)\n")


def test_examples_print_whole_first_sentences():
    out = run_ok("examples")
    lines = dict(line.split(None, 1) for line in out.splitlines())
    assert lines["five-bar"].endswith("are pinned to the moving platform (the \"object\") at "
                                      "one point.")
    assert lines["four-bar"].endswith("hold the coupler (length 2) with pins (hard "
                                      "contacts) at their tips.")
    assert lines["paper-case1-hard"] == ("Paper case study 1 (fig. 2), both contacts hard "
                                         "finger: two one-link arms hold an object.")
    assert lines["bennett-linkage"].startswith("Bennett's linkage, a loop of four revolute")
    assert lines["bricard-linkage"] == (
        "A line-symmetric Bricard linkage, a movable loop of six revolute joints in "
        "space, as two three-joint arms welded to one object.")
    assert all(text.endswith(".") for text in lines.values()), lines
    assert run_ok("examples", "four-bar") == out.splitlines()[6] + "\n"


def test_examples_show_prints_the_model_file(tmp_path):
    import coopkin_sym

    text = run_ok("examples", "paper-case1-hard", "--show")
    assert text == coopkin_sym.example_path("paper-case1-hard").read_text(encoding="utf-8")
    copy = tmp_path / "mine.yaml"
    copy.write_text(text)       # a model to start from: it loads and analyzes as the example
    assert json.loads(run_ok("analyze", str(copy), "--json"))["numbers"] == json.loads(
        run_ok("analyze", "paper-case1-hard", "--json"))["numbers"]
    assert "unknown example 'nope'" in run_error("examples", "nope", "--show")
    assert "--show: name the example" in run_error("examples", "--show")


@pytest.mark.parametrize("args, line", [
    ([], "Configuration: home (all joints at 0)"),
    (["--generic"], "Configuration: generic: every joint symbolic (q1, q2)"),
    (["--free", "q2"], "Configuration: q2 symbolic, the other joints at home (q1 = 0)"),
    (["--free", "q2", "--at", "q1=pi/2"], "Configuration: q1=pi/2; q2 symbolic"),
])
def test_the_configuration_line_says_where_the_analysis_is(args, line):
    assert run_ok("analyze", "paper-case1-hard", *args).splitlines()[1] == line


def test_a_locus_cut_by_its_time_bound_exits_3_and_says_what_was_cut(tmp_path):
    """Paper case 2's locus (all eight joints free) takes far longer than its bound."""
    from coopkin_sym.cli import TIME_BOUND_EXIT

    report = tmp_path / "r.json"
    result = runner.invoke(app, ["locus", "paper-case2-hard", "-o", str(report),
                                 "--timeout", "1.5", "--no-progress"])
    assert result.exit_code == TIME_BOUND_EXIT == 3, result.output
    assert result.stderr.startswith("coopkin: error: time bound of 1.5 s reached during ")
    assert result.stderr.count("\n") == 1
    if report.exists():      # cut after the generic numbers: the report says what was cut
        assert result.stderr.endswith(f"the report says what was not explored; wrote "
                                      f"{report}\n")
        assert json.loads(report.read_text())["unexplored"]
    else:
        assert result.stderr.endswith("; nothing written\n")


@pytest.mark.parametrize("certify_sleeps", [pytest.param("at a step", marks=pytest.mark.slow),
                                            "inside one call"])
def test_a_certificate_cut_by_the_bound_keeps_the_whole_search(tmp_path, monkeypatch,
                                                               certify_sleeps):
    """The search ends, then the certificate is ended by the bound (between its steps,
    or inside a call that cannot be interrupted): the report has every component the
    search found, and says the certificate was cut, not that it was not asked for."""
    import time

    from coopkin_sym.cli import TIME_BOUND_EXIT
    from coopkin_sym.exact import deadline
    from coopkin_sym.system import System

    def slow_certificate(self, locus, **kwargs):
        for _ in range(100):
            time.sleep(0.1)
            if certify_sleeps == "at a step":
                deadline.check()
        raise AssertionError("not ended by the bound")

    monkeypatch.setattr(System, "certify_locus", slow_certificate)
    report = tmp_path / "r.json"
    result = runner.invoke(app, ["locus", "paper-case1-hard", "-o", str(report),
                                 "--certify", "--timeout", "4", "--no-progress"])
    assert result.exit_code == TIME_BOUND_EXIT, result.output
    assert result.stdout.startswith("5 components (5 real); not certified: time bound of "
                                    "4")
    assert "s reached during the completeness certificate, before every test was run; " \
           "wrote " in result.stdout
    assert result.stderr.startswith("coopkin: error: time bound of 4 s reached during the "
                                    "completeness certificate")
    data = json.loads(report.read_text())
    assert len(data["components"]) == 5
    assert not any("the rest of the search was not explored" in str(u)
                   for u in data["unexplored"])


def test_a_generic_manipulability_cut_by_its_time_bound_exits_3():
    from coopkin_sym.cli import TIME_BOUND_EXIT

    result = runner.invoke(app, ["manipulability", "planar-two-fingers", "--generic",
                                 "--length", "L", "--timeout", "0.5", "--no-progress",
                                 "--max-terms", "1000000"])
    assert result.exit_code == TIME_BOUND_EXIT, result.output
    assert result.stdout == ""
    assert result.stderr.startswith("coopkin: error: time bound of 0.5 s reached during ")
    assert result.stderr.endswith("; nothing shown\n")


def test_a_generic_manipulability_over_its_term_budget_exits_3():
    """A budget of 2,000 terms stops the generic two-finger ellipsoid at once (its
    inverse of A grows past it), saying where; a larger one lets a smaller case
    through, a smaller one cuts it."""
    from coopkin_sym.cli import TIME_BOUND_EXIT

    result = runner.invoke(app, ["manipulability", "planar-two-fingers", "--generic",
                                 "--length", "L", "--no-progress", "--max-terms", "2000"])
    assert result.exit_code == TIME_BOUND_EXIT, result.output
    assert result.stdout == ""
    assert result.stderr.startswith("coopkin: error: manipulability: the inverse of A: an "
                                    "entry of ")
    assert result.stderr.endswith(" terms, over the budget of 2,000 (terms of its numerator "
                                  "and denominator; max_terms= or --max-terms N raises "
                                  "it); the ellipsoid is not computed\n")
    assert len(result.stderr.splitlines()) == 1
    small = ["manipulability", "planar-two-fingers", "--free", "q2", "--length", "L"]
    assert "rank E = 3 of 3" in run_ok(*small, "--max-terms", "50")
    cut = runner.invoke(app, [*small, "--max-terms", "3"])
    assert cut.exit_code == TIME_BOUND_EXIT and "over the budget of 3 " in cut.stderr


def test_the_help_of_max_terms_states_the_default_budget():
    from coopkin_sym.analysis.manipulability import MAX_TERMS
    from coopkin_sym.cli_options import ManipulabilityOptions

    assert ManipulabilityOptions().max_terms is None
    result = runner.invoke(app, ["manipulability", "--help"], env={"COLUMNS": "200"})
    assert f"default {MAX_TERMS}" in " ".join(result.stdout.split())


def test_each_command_is_one_paragraph_in_the_command_list():
    import typer

    commands = typer.main.get_command(app).commands
    assert commands["analyze"].short_help == (
        "Mobility Nm, connectivity Nc, indeterminacy Ni, redundancy Nr (and Ng, Nd, Nh), "
        "with the block decomposition of the paper, exactly; with --finite, whether the "
        "first-order motions are finite ones.")
    assert all("\n" not in c.short_help and "  " not in c.short_help
               for c in commands.values())
