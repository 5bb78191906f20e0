"""Wall-clock bounds (``locus --timeout``) and Ctrl-C."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import flint
import pytest
from typer.testing import CliRunner

from coopkin_sym import load
from coopkin_sym.analysis.locus.search import compute_locus
from coopkin_sym.cli import app
from coopkin_sym.errors import CoopkinError, TimeLimitReached
from coopkin_sym.exact import deadline
from coopkin_sym.exact import elimination as el
from coopkin_sym.model.builders import spatial_hand
from coopkin_sym.present.remarks import remark_texts

runner = CliRunner()
ROOT = Path(__file__).resolve().parents[2]


def test_the_deadline_is_cheap_nested_and_keeps_partial_results():
    assert not deadline.active() and deadline.remaining() is None
    deadline.check()                                  # no bound: nothing happens
    with deadline.time_limit(10) as outer:
        with deadline.time_limit(100) as inner:      # the tighter bound applies
            assert inner.end == outer.end and 9 < deadline.remaining() <= 10
        with deadline.time_limit(0) as bound:
            deadline.keep("partial")
            with pytest.raises(TimeLimitReached, match="time bound of 0 s reached during "
                                                       "step"):
                deadline.check("step")
            assert bound.kept == "partial"
    assert not deadline.active()
    assert issubclass(TimeLimitReached, CoopkinError)
    with deadline.time_limit(50, "outer"), deadline.time_limit(60):
        assert deadline.active("outer") and not deadline.active("locus")


def _hard_matrix(n: int = 9):
    ctx = flint.fmpz_mpoly_ctx.get(tuple(f"x{i}" for i in range(n)), "degrevlex")
    xs = ctx.gens()
    return [[(xs[i] + xs[j] + 1) ** ((i * j) % 4 + 1) + xs[(i + j) % n] * xs[i]
             for j in range(n)] for i in range(n)]


def test_eliminations_check_the_clock_inside():
    rows = _hard_matrix()
    for compute in (lambda: el.determinant(rows), lambda: el.nullspace(rows),
                    lambda: el.gauss_jordan(rows, len(rows))):
        with deadline.time_limit(0.0):
            start = time.monotonic()
            with pytest.raises(TimeLimitReached):
                compute()
            assert time.monotonic() - start < 0.5


# the generic numbers of this hand take about 0.6 s alone: a bound of 3 s leaves them
# room on a loaded machine, and the whole search needs far more
def test_locus_timeout_bounds_the_whole_run_and_keeps_what_was_found():
    system = load(spatial_hand(10, 3))
    start = time.monotonic()
    result = compute_locus(system, timeout=3.0)
    assert time.monotonic() - start < 8          # the bound plus the last step
    assert any(u.kind == "time_whole_run" and u["seconds"] == 3.0 for u in result.unexplored)
    cut = [u for u in remark_texts(result.unexplored) if "time bound of 3 s reached" in u]
    assert cut and "not explored" in cut[0]
    assert result.generic["Nm"] >= 0


def test_locus_timeout_is_enforced_inside_another_bound():
    system = load(spatial_hand(10, 3))
    start = time.monotonic()
    with deadline.time_limit(600, "caller"):
        result = compute_locus(system, timeout=3.0)
    assert time.monotonic() - start < 8
    assert any("time bound of 3 s reached" in u for u in remark_texts(result.unexplored))


def test_locus_timeout_before_the_generic_numbers_is_an_error():
    system = load(spatial_hand(24, 8))
    start = time.monotonic()
    with pytest.raises(TimeLimitReached, match="no locus to report"):
        compute_locus(system, timeout=0.5)
    assert time.monotonic() - start < 5


def test_cli_locus_timeout_exits_with_one_line(tmp_path):
    import json

    path = tmp_path / "hand.json"
    path.write_text(json.dumps(spatial_hand(24, 8)))
    result = runner.invoke(app, ["locus", str(path), "-o", str(tmp_path / "r.md"),
                                 "--timeout", "0.5", "--no-progress"])
    assert result.exit_code == 3                  # cut by the bound, not bad input
    assert result.stderr.startswith("coopkin: error: time bound of 0.5 s reached during ")
    assert result.stderr.endswith("; nothing written\n")
    assert result.stderr.count("\n") == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["hand.json"]


def test_code_outside_the_checks_is_ended_at_the_bound():
    from coopkin_sym.exact.bounded import report, run_bounded

    def endless():
        report("a loop without checks")
        while True:          # pure Python: no check() here
            time.sleep(0.01)

    start = time.monotonic()
    with pytest.raises(TimeLimitReached) as caught:
        run_bounded(endless, 0.5)
    assert time.monotonic() - start < 0.5 * 1.1 + 0.3
    assert str(caught.value) == "time bound of 0.5 s reached during a loop without checks"
    assert caught.value.hard


# ------------------------------------------------------------------ Ctrl-C


def _interrupt(args: list[str], after: float, cwd: Path) -> tuple[int, str, float]:
    """Run ``python -m coopkin_sym args``, send SIGINT after ``after`` seconds; return
    the exit status, stderr and how long it took to stop."""
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.Popen([sys.executable, "-m", "coopkin_sym", *args], cwd=cwd,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=env,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    time.sleep(after)
    assert proc.poll() is None, "the command finished before it could be interrupted"
    sent = time.monotonic()
    proc.send_signal(signal.SIGINT)
    try:
        _, err = proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
    return proc.returncode, err, time.monotonic() - sent


@pytest.mark.parametrize("command", ["locus", "sweep"])
def test_ctrl_c_stops_within_a_second_with_one_line(tmp_path, command):
    import json

    model = tmp_path / "hand.json"
    model.write_text(json.dumps(spatial_hand(6, 4)))
    out = tmp_path / "out"
    out.mkdir()
    args = (["locus", str(model), "-o", str(out / "r.md"), "--no-progress"]
            if command == "locus" else
            ["sweep", str(model), "--grid", "f1_1=-pi..pi:1400,f1_2=-pi..pi:1400",
             "-o", str(out / "t.csv"), "--workers", "2"])
    status, err, took = _interrupt(args, 4.0, tmp_path)
    assert status == 130, err[-2000:]          # what it said, if it ended otherwise
    assert err == "coopkin: interrupted\n"
    assert took < 1.5
    assert list(out.iterdir()) == []             # nothing partial left


def test_a_bound_reached_in_the_locked_locus_keeps_the_main_one(monkeypatch):
    """The locus with the motors held still is searched last, under the same bound;
    cut there, the locus handed back is the system's own (with what was cut), not the
    locked one the inner search had registered."""
    from coopkin_sym.analysis.locus import search

    original = search.compute_locus

    def cut_when_locked(system, *args, **kwargs):
        if getattr(system, "locked", None):           # the locked model
            deadline.keep("the locked locus, unfinished")
            raise TimeLimitReached(60.0, "the locked locus")
        return original(system, *args, **kwargs)

    monkeypatch.setattr(search, "compute_locus", cut_when_locked)
    result = original(load("five-bar"), timeout=60.0)
    assert result.system == "five-bar linkage with passive elbows"
    assert result.locked is None and result.components
    assert [u["where"] for u in result.unexplored if u.kind == "time_whole_run"] == [
        "the locked locus"]
