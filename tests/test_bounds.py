"""Time bounds that hold: every long command and API call ends at its ``--timeout`` /
``timeout=`` within a few percent, whatever step it is in, exits with 3 and one line
saying what was cut; large honest systems stop at the bound with that message.

The commands run as a user runs them (a new process, its real wall-clock time); the
bound is 2 s on computations known to take far longer (measured on the machine of the
suite: 200 arms x 6 joints, ``analyze --json`` about 65 s, their numbers alone about
9 s; 2,000 contacts, ``analyze --json`` about 29 s; the resultant below about 16 s).
Each must end within the bound plus 10 % plus 1.5 s for the start-up of Python (the
bound of a command counts from its start).
"""

from __future__ import annotations

import json
import os
import pty
import random
import re
import select
import signal
import subprocess
import sys
import time
from pathlib import Path

import flint
import pytest
from large_systems import many_arms, many_contacts
from support import texts
from typer.testing import CliRunner

from coopkin_sym import load
from coopkin_sym.cli import TIME_BOUND_EXIT, app
from coopkin_sym.errors import ModelError, TimeLimitReached, WorkerFailed
from coopkin_sym.exact import deadline
from coopkin_sym.exact.bounded import deliver, report, run_bounded
from coopkin_sym.model.builders import spatial_hand
from coopkin_sym.present.report import write_report

ROOT = Path(__file__).resolve().parents[1]
BOUND = 2.0
START_UP = 1.5


def _within(seconds: float, bound: float = BOUND) -> bool:
    return seconds < bound * 1.1 + START_UP


def _slow_resultant(step: str | None = "a resultant"):
    """A resultant of two dense random trivariate polynomials of degree 12: one flint
    call of about 16 s that holds the interpreter (no check, no signal gets in); it
    reports ``step`` first (None: nothing)."""
    rng = random.Random(1)
    ctx = flint.fmpz_mpoly_ctx.get(("x", "y", "z"), "degrevlex")
    x, y, z = ctx.gens()

    def dense(d):
        return sum(rng.randint(-9, 9) * x**i * y**j * z**k for i in range(d + 1)
                   for j in range(d + 1 - i) for k in range(d + 1 - i - j))
    f, g = dense(12), dense(12)
    if step is not None:
        report(step)
    return f.resultant(g, "x")


# ------------------------------------------------------------------ the mechanism


def test_results_and_errors_come_back_from_the_bounded_process():
    ctx = flint.fmpz_mpoly_ctx.get(("t", "L"), "degrevlex")
    t, L = ctx.gens()
    assert run_bounded(lambda: (t + L) ** 2, 30) == t**2 + 2 * t * L + L**2
    with pytest.raises(ModelError) as caught:
        run_bounded(lambda: load({"name": "x"}), 30)
    assert caught.value.problems == ["arms: at least one arm with one joint is needed",
                                     "contacts: at least one contact is needed"]
    parts: list = []
    assert run_bounded(lambda: [deliver(k) for k in range(3)] and "done", 30,
                       output=parts.append) == "done"
    assert parts == [0, 1, 2]


def test_a_cooperative_stop_hands_back_the_partial_result_before_the_bound():
    def partial():
        done = 0
        try:
            while True:
                deadline.check("counting")
                done += 1
        except TimeLimitReached as exc:
            return done > 0, str(exc)

    start = time.monotonic()
    assert run_bounded(partial, 1.0) == (True, "time bound of 1 s reached during counting")
    assert time.monotonic() - start < 1.0


def test_an_uninterruptible_flint_call_is_ended_at_the_bound():
    start = time.monotonic()
    with pytest.raises(TimeLimitReached) as caught:
        run_bounded(_slow_resultant, BOUND)
    took = time.monotonic() - start
    assert BOUND <= took < BOUND * 1.1 + 0.3
    assert str(caught.value) == "time bound of 2 s reached during a resultant"
    assert caught.value.hard


def test_processes_started_by_the_work_end_with_it():
    def sleeper():
        child = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
        deliver(child.pid)
        report("waiting")
        child.wait()

    pids: list[int] = []
    with pytest.raises(TimeLimitReached, match="during waiting"):
        run_bounded(sleeper, 1.0, output=pids.append)
    time.sleep(0.2)
    assert not _running(pids[0])


def _running(pid: int) -> bool:
    """Whether process ``pid`` exists and is not a zombie (ended, not yet reaped)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except FileNotFoundError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


# ------------------------------------------------------------------ every command


def _run(args: list[str], cwd: Path) -> tuple[int, str, str, float]:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    start = time.monotonic()
    done = subprocess.run([sys.executable, "-m", "coopkin_sym", *args], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=60)
    return done.returncode, done.stdout, done.stderr, time.monotonic() - start


CUT = re.compile(r"coopkin: error: time bound of 2 s reached during ([^;\n]+); ([^\n]+)\n")


@pytest.fixture(scope="module")
def models(tmp_path_factory):
    folder = tmp_path_factory.mktemp("large")
    (folder / "arms.json").write_text(json.dumps(many_arms(200, 6)))
    (folder / "contacts.json").write_text(json.dumps(many_contacts(2000)))
    (folder / "hand.json").write_text(json.dumps(spatial_hand(10, 3)))
    write_report(load("paper-case1-hard").locus(max_depth=0), folder / "case1.json")
    return folder


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs /proc")
def test_the_check_of_processes_sees_a_running_one():
    assert _running(os.getpid())


@pytest.mark.parametrize(("args", "outcome"), [
    (["analyze", "arms.json"], r"not shown: .*C23|nothing shown"),
    (["analyze", "contacts.json", "--json"], "nothing shown"),
    (["manipulability", "arms.json"], "nothing shown"),
    (["sweep", "hand.json", "--grid", "f1_1=-pi..pi:1400,f1_2=-pi..pi:1400", "-o",
      "table.csv", "--workers", "2"], "nothing written"),
    (["verify", "paper-case1-hard", "case1.json", "--lines", "5000"], "no verdict"),
    (["locus", "contacts.json", "-o", "report.md"], "nothing written"),
    (["draw", "arms.json", "-o", "arms.png"], "nothing written"),
], ids=["analyze-200-arms", "analyze-2000-contacts", "manipulability", "sweep", "verify",
        "locus", "draw-200-arms"])
def test_each_command_stops_at_its_bound_with_one_line(models, args, outcome):
    before = set(models.iterdir())
    status, out, err, took = _run([*args, "--timeout", str(BOUND)], models)
    assert status == TIME_BOUND_EXIT, err
    match = CUT.fullmatch(err)
    assert match, err
    assert re.fullmatch(outcome, match.group(2)), err
    assert _within(took), took
    assert set(models.iterdir()) == before          # nothing written, nothing left


@pytest.mark.slow
def test_a_locus_cut_at_a_check_writes_its_report_and_says_so(tmp_path):
    # its generic numbers take 1 to 2 s (more on a loaded machine); the search has 0.8
    # of the bound and stops at checks of the clock within a tenth of a second of its
    # cooperative bound (5.8 s after the start); the report is written in the rest
    (tmp_path / "hand.json").write_text(json.dumps(spatial_hand(3, 4)))
    status, out, err, took = _run(["locus", "hand.json", "-o", "r.json", "--no-progress",
                                   "--timeout", "8"], tmp_path)
    assert status == TIME_BOUND_EXIT, err
    assert err.endswith("; the report says what was not explored; wrote r.json\n"), err
    assert err.startswith("coopkin: error: time bound of 8 s reached during ")
    assert err.count("\n") == 1 and "not explored" in out
    assert _within(took, 8.0), took
    data = json.loads((tmp_path / "r.json").read_text())
    assert data["unexplored"]                       # what was cut, in the report


def test_a_locus_ended_inside_a_flint_call_writes_nothing(tmp_path, monkeypatch):
    import coopkin_sym.analysis.locus.search as search

    monkeypatch.setattr(search, "compute_locus", lambda *a, **k: _slow_resultant())
    start = time.monotonic()
    result = CliRunner().invoke(app, ["locus", "paper-case1-hard", "-o",
                                      str(tmp_path / "r.md"), "--timeout", "2"])
    assert time.monotonic() - start < BOUND * 1.1 + 0.5
    assert result.exit_code == TIME_BOUND_EXIT
    assert result.stderr == ("coopkin: error: time bound of 2 s reached during a "
                             "resultant; nothing written\n")
    assert list(tmp_path.iterdir()) == []


def test_a_locus_ended_inside_its_generic_numbers_names_that_step(tmp_path, monkeypatch):
    """Ended at the bound inside a step that cannot be interrupted while the generic
    numbers are computed, the command names that step (not the loading of the model)."""
    import coopkin_sym.analysis.locus.search as search

    monkeypatch.setattr(search, "decompose", lambda *a, **k: _slow_resultant(None))
    result = CliRunner().invoke(app, ["locus", "paper-case1-hard", "-o",
                                      str(tmp_path / "r.md"), "--timeout", "2"])
    assert result.exit_code == TIME_BOUND_EXIT
    assert result.stderr == ("coopkin: error: time bound of 2 s reached during the ranks "
                             "and the decomposition of the nullspace; nothing written\n")
    assert list(tmp_path.iterdir()) == []


def _found_one_then_a_resultant(*args, **kwargs):
    """A search that keeps a locus with one component, reports steps for a little more
    than a second, then runs into the resultant."""
    from coopkin_sym.analysis.locus.types import Component, Locus

    generic = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
    locus = Locus("paper case 1, hard/hard", ["t_q1", "t_q2"], "L=1", generic)
    locus.components.append(Component(["t_q1 - 1", "t_q2 - 1"], dict(generic, Nm=3),
                                      {"q1": "pi/2", "q2": "pi/2"}, True))
    deadline.keep(locus)
    for k in range(12):
        report(f"step {k}")
        time.sleep(0.1)
    return _slow_resultant()


def test_system_locus_ended_inside_a_flint_call_returns_what_it_had_kept(monkeypatch):
    import coopkin_sym.analysis.locus.search as search

    monkeypatch.setattr(search, "compute_locus", _found_one_then_a_resultant)
    start = time.monotonic()
    locus = load("paper-case1-hard").locus(timeout=2.5)
    assert time.monotonic() - start < 2.5 * 1.1 + 0.3
    assert [texts(c.equations) for c in locus.components] == [["t_q1 - 1", "t_q2 - 1"]]
    assert [(u.kind, u["seconds"], u["where"]) for u in locus.unexplored] == [
        ("time_whole_run", 2.5, "a resultant")]


def test_a_locus_ended_inside_a_flint_call_writes_what_it_had_kept(tmp_path, monkeypatch):
    """The search keeps its locus as it goes; the last copy reaches the command before
    the step that cannot be interrupted is ended, and is written with what was cut."""
    import coopkin_sym.analysis.locus.search as search

    monkeypatch.setattr(search, "compute_locus", _found_one_then_a_resultant)
    start = time.monotonic()
    result = CliRunner().invoke(app, ["locus", "paper-case1-hard", "-o",
                                      str(tmp_path / "r.json"), "--timeout", "2.5"])
    assert time.monotonic() - start < 2.5 * 1.1 + 0.5
    assert result.exit_code == TIME_BOUND_EXIT
    assert result.stderr == ("coopkin: error: time bound of 2.5 s reached during a "
                             "resultant; the report says what was not explored; wrote "
                             f"{tmp_path / 'r.json'}\n")
    data = json.loads((tmp_path / "r.json").read_text())
    assert [c["equations"] for c in data["components"]] == [["t_q1 - 1", "t_q2 - 1"]]
    assert data["unexplored"][-1].startswith("time bound of 2.5 s reached during a "
                                             "resultant")


def test_a_locus_ended_inside_a_flint_call_right_after_its_generic_numbers_writes(
        tmp_path, monkeypatch):
    """Once the generic numbers are known a cut locus writes its report, even when the
    search runs into a step that cannot be interrupted within the first second (before
    any step of the search could send a copy)."""
    import coopkin_sym.analysis.locus.search as search

    monkeypatch.setattr(search, "explore", lambda *a, **k: _slow_resultant())
    result = CliRunner().invoke(app, ["locus", "paper-case1-hard", "-o",
                                      str(tmp_path / "r.json"), "--timeout", "2"])
    assert result.exit_code == TIME_BOUND_EXIT
    assert result.stderr.splitlines()[-1] == (
        "coopkin: error: time bound of 2 s reached during a resultant; the report says "
        f"what was not explored; wrote {tmp_path / 'r.json'}")
    data = json.loads((tmp_path / "r.json").read_text())
    assert (data["generic"]["Nm"], data["components"]) == (2, [])
    assert data["unexplored"][-1].startswith("time bound of 2 s reached during a resultant")


def test_progress_is_shown_on_a_terminal_after_a_second(models):
    """stderr a terminal: the step being computed is shown, then removed; the error
    line stays."""
    main, other = pty.openpty()
    env = dict(os.environ, PYTHONPATH=str(ROOT), COLUMNS="120", TERM="xterm")
    proc = subprocess.Popen([sys.executable, "-m", "coopkin_sym", "analyze", "arms.json",
                             "--json", "--timeout", "3"], cwd=models, env=env,
                            stdout=subprocess.DEVNULL, stderr=other, close_fds=True)
    os.close(other)
    seen = b""
    try:
        while True:
            ready, _, _ = select.select([main], [], [], 10)
            if not ready:
                break
            try:
                chunk = os.read(main, 4096)
            except OSError:
                break
            if not chunk:
                break
            seen += chunk
    finally:
        if proc.poll() is None:
            proc.send_signal(signal.SIGKILL)
        proc.wait()
        os.close(main)
    text = seen.decode(errors="replace")
    assert proc.returncode == TIME_BOUND_EXIT
    assert "analyze: the " in text                   # the display, with its step
    assert text.rstrip().endswith("; nothing shown")


# ------------------------------------------------------------------ the API


@pytest.mark.slow
def test_the_api_takes_the_same_bound():
    arms = load(many_arms(200, 6))
    hand = load(spatial_hand(10, 3))
    from coopkin_sym.analysis.locus.types import Locus
    from coopkin_sym.analysis.locus.verify import verify_locus
    from coopkin_sym.analysis.sweep import grid

    points = grid(hand, "f1_1=-pi..pi:1400,f1_2=-pi..pi:1400")   # built outside the bound
    calls = {
        "analyze": lambda: arms.analyze(timeout=1.0),
        "sweep": lambda: hand.sweep(points, timeout=1.0),
        "manipulability": lambda: load(many_arms(100, 6)).analyze().manipulability(
            timeout=1.0),
        "verify": lambda: verify_locus(load("paper-case1-hard"), Locus(
            "case 1", ["t_q1", "t_q2"], "L=1", {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0,
                                                "Ng": 1, "Nd": 4, "Nh": 0}),
            lines=5000, timeout=1.0),
    }
    for name, call in calls.items():
        start = time.monotonic()
        with pytest.raises(TimeLimitReached, match="time bound of 1 s reached during "):
            call()
        assert time.monotonic() - start < 1.0 * 1.1 + 0.5, name   # + fork and stop


def test_the_analysis_reports_progress_and_never_draws_it():
    """Only the presentation layer imports rich: the analysis reports its steps."""
    import ast

    drawing = []
    for path in sorted((ROOT / "coopkin_sym").rglob("*.py")):
        layer = path.relative_to(ROOT / "coopkin_sym").parts[0]
        for node in ast.walk(ast.parse(path.read_text())):
            names = ([a.name for a in node.names] if isinstance(node, ast.Import)
                     else [node.module or ""] if isinstance(node, ast.ImportFrom) else [])
            if any(n.split(".")[0] == "rich" for n in names) and layer != "present":
                drawing.append(str(path.relative_to(ROOT)))
    assert drawing == []


@pytest.mark.skipif(not Path("/proc/self/task").exists(), reason="needs /proc")
@pytest.mark.parametrize("stop", [signal.SIGTERM, signal.SIGKILL])
def test_the_bounded_process_ends_with_the_command(models, stop):
    """``timeout 60 coopkin ...`` (SIGTERM) or a killed command (SIGKILL) leaves no
    computation running on its own."""
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.Popen([sys.executable, "-m", "coopkin_sym", "analyze", "arms.json",
                             "--timeout", "100"], cwd=models, env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    children: list[int] = []
    deadline_at = time.monotonic() + 10
    while not children and time.monotonic() < deadline_at:
        time.sleep(0.1)
        path = Path(f"/proc/{proc.pid}/task/{proc.pid}/children")
        children = [int(x) for x in path.read_text().split()] if path.exists() else []
    assert children, "the command started no bounded process"
    proc.send_signal(stop)
    proc.communicate(timeout=10)
    time.sleep(0.3)
    assert [c for c in children if _running(c)] == []
    assert proc.returncode == (128 + signal.SIGTERM if stop == signal.SIGTERM
                               else -signal.SIGKILL)


def test_a_bounded_sweep_refuses_an_executor_made_outside_it():
    from concurrent.futures import ThreadPoolExecutor

    from coopkin_sym.errors import SweepError

    with ThreadPoolExecutor(1) as pool, pytest.raises(SweepError) as caught:
        load("paper-case1-hard").sweep(["q1=0"], executor=pool, timeout=10)
    assert str(caught.value) == ("timeout: a bounded sweep runs in a process of its own "
                                 "and cannot use an executor made outside it (give one or "
                                 "the other)")


@pytest.mark.parametrize("args", [
    ["analyze", "paper-case1-hard"],
    ["analyze", "paper-case1-hard", "--generic", "--json"],
    ["manipulability", "paper-case1-hard", "--at", "q1=pi/2,q2=pi/2,L=1"],
    ["sweep", "paper-case1-hard", "--grid", "q1=-pi..pi:5,q2=0..1:3"],
], ids=["analyze", "analyze-json", "manipulability", "sweep"])
def test_a_run_within_its_bound_gives_what_an_unbounded_one_gives(args):
    runner = CliRunner()
    free = runner.invoke(app, args)
    bounded = runner.invoke(app, [*args, "--timeout", "60"])
    assert free.exit_code == bounded.exit_code == 0, bounded.output
    assert bounded.stdout == free.stdout and bounded.stderr == free.stderr == ""


def test_a_verification_within_its_bound_gives_its_verdict(tmp_path):
    report_path = tmp_path / "case1.json"
    write_report(load("paper-case1-hard").locus(max_depth=0), report_path)
    runner = CliRunner()
    args = ["verify", "paper-case1-hard", str(report_path), "--lines", "2"]
    free, bounded = runner.invoke(app, args), runner.invoke(app, [*args, "--timeout", "60"])
    assert free.exit_code == bounded.exit_code == 0, bounded.output
    assert bounded.stdout.startswith("Verification: passed")
    assert bounded.stdout.split("\n")[0] == free.stdout.split("\n")[0]


def test_a_worker_that_dies_without_an_answer_is_a_package_error():
    from coopkin_sym.exact.bounded import run_bounded

    with pytest.raises(WorkerFailed) as info:
        run_bounded(lambda: os._exit(7), 30, owner="a test")
    assert str(info.value) == ("the worker process of a test stopped without an answer "
                               "(exit code 7)")


@pytest.mark.slow
@pytest.mark.parametrize("drawing", ["one by one", "side by side"])
def test_a_locus_report_draws_its_pictures_within_the_bound(tmp_path, monkeypatch, drawing):
    """The search has a share of the bound, the report the rest: its text first, then
    its pictures while time is left (one by one, or side by side in worker processes);
    the ones left out are said, and the run is cut."""
    import coopkin_sym.present.report as report_module
    import coopkin_sym.present.report.side_by_side as side_by_side

    drawn = report_module.plot_png
    if drawing == "one by one":
        monkeypatch.setattr(side_by_side, "MIN_PICTURES", 1000)
    elif side_by_side.workers_for(4) == 0:
        pytest.skip("this machine draws one by one (one core or no fork)")
    # side by side, two plots take the time of one: each takes longer than the bound
    # leaves
    pause = 1.5 if drawing == "one by one" else 3.5

    def slow_plot(*args, **kwargs):
        time.sleep(pause)
        return drawn(*args, **kwargs)

    monkeypatch.setattr(report_module, "plot_png", slow_plot)
    start = time.monotonic()
    result = CliRunner().invoke(app, ["locus", "paper-case1-hard", "-o",
                                      str(tmp_path / "r.md"), "--timeout", "4",
                                      "--pair", "q1,q2", "--pair", "q2,q1"])
    assert time.monotonic() - start < 4 * 1.1 + 0.5
    assert result.exit_code == TIME_BOUND_EXIT, result.stderr
    lines = result.stderr.splitlines()
    assert "coopkin: note: plots of 1 more pairs of joints left out: the time bound was " \
           "reached" in lines or any("pictures of the system at" in x and "time bound" in x
                                     for x in lines), lines
    assert lines[-1].startswith("coopkin: error: time bound of 4 s reached during the "
                                "pictures of the report; the report says what was not "
                                f"explored; wrote {tmp_path / 'r.md'}")
    assert (tmp_path / "r.md").read_text().startswith("#")
