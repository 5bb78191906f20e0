"""Output files: checked before any work, written whole or not at all, never through a
planted symlink, never lost silently; workers capped; Analysis pickles."""

from __future__ import annotations

import concurrent.futures
import os
import pickle
import stat
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import pytest
from typer.testing import CliRunner

from coopkin_sym import load
from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.cli import app, worker_count
from coopkin_sym.present.files import check_output_path, plain_file_mode, write_files
from coopkin_sym.present.report import ReportError, write_report

runner = CliRunner()


class Oops(Exception):
    pass


def test_the_directory_is_checked_before_any_work(tmp_path):
    start = time.monotonic()
    result = runner.invoke(app, ["sweep", "paper-case2-hard", "--grid",
                                 "q1=-pi..pi:1000,q2=-pi..pi:1000",
                                 "-o", str(tmp_path / "nodir" / "x.csv")])
    assert result.exit_code == 2
    assert "no such directory" in result.stderr
    assert time.monotonic() - start < 3            # the million points were not swept
    (tmp_path / "taken.csv").mkdir()
    result = runner.invoke(app, ["sweep", "paper-case1-hard", "--grid", "q1=0..1:2",
                                 "-o", str(tmp_path / "taken.csv")])
    assert result.exit_code == 2 and "taken.csv: is a directory" in result.stderr
    result = runner.invoke(app, ["draw", "paper-case1-hard", "-o",
                                 str(tmp_path / "nodir" / "x.png")])
    assert result.exit_code == 2 and "no such directory" in result.stderr


def test_a_symlink_at_the_old_partial_name_redirects_nothing(tmp_path):
    victim = tmp_path / "victim.txt"
    victim.write_text("precious")
    out = tmp_path / "out.csv"
    (tmp_path / "out.csv.partial").symlink_to(victim)
    result = runner.invoke(app, ["sweep", "paper-case1-hard", "--grid", "q1=0..1:3",
                                 "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert victim.read_text() == "precious"
    assert out.is_file() and not out.is_symlink()
    assert out.read_text().startswith("q1,q1_rad,Nm,")            # the table
    assert (tmp_path / "out.csv.json").is_file()                  # and its metadata


def test_a_symlink_at_the_target_is_replaced_not_followed(tmp_path):
    victim = tmp_path / "victim.txt"
    victim.write_text("precious")
    target = tmp_path / "t.csv"
    target.symlink_to(victim)
    write_files({target: b"new"}, ValueError)
    assert victim.read_text() == "precious"
    assert not target.is_symlink() and target.read_bytes() == b"new"


def test_plain_file_mode_under_the_umask(tmp_path):
    old = os.umask(0o027)
    try:
        assert plain_file_mode() == 0o640
        (path,) = write_files({tmp_path / "m.csv": b"x"}, ValueError)
        assert stat.S_IMODE(path.stat().st_mode) == 0o640
    finally:
        os.umask(old)


def test_nothing_partial_on_error_or_interruption(tmp_path):
    def failing(tmp: str) -> None:
        Path(tmp).write_text("half")
        raise OSError(28, "No space left on device")

    with pytest.raises(ValueError, match="a.png: cannot write: No space left on device"):
        write_files({tmp_path / "a.csv": b"whole", tmp_path / "a.png": failing}, ValueError)
    assert list(tmp_path.iterdir()) == []

    def interrupted(tmp: str) -> None:
        Path(tmp).write_text("half")
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        write_files({tmp_path / "b.csv": b"whole", tmp_path / "b.png": interrupted},
                    ValueError)
    assert list(tmp_path.iterdir()) == []


def test_cleanup_that_cannot_unlink_is_quiet(tmp_path, monkeypatch):
    def no_unlink(path):
        raise PermissionError(13, "Read-only file system")

    def failing(tmp: str) -> None:
        raise Oops("render failed")

    monkeypatch.setattr(os, "unlink", no_unlink)
    with pytest.raises(Oops):
        write_files({tmp_path / "c.png": failing}, ValueError)


def test_concurrent_runs_never_lose_data_silently(tmp_path):
    target, _ = check_output_path(tmp_path / "t.csv", (".csv",), ValueError, "table")
    target.write_text("written by another run")            # meanwhile
    with pytest.raises(ValueError, match="another run wrote this file") as info:
        write_files({target: b"this run"}, ValueError)
    assert target.read_text() == "written by another run"
    kept = tmp_path / "t.1.csv"
    assert kept.read_text() == "this run" and str(kept) in str(info.value)
    # without a change in between, the target is simply replaced
    target, _ = check_output_path(tmp_path / "t.csv", (".csv",), ValueError, "table")
    write_files({target: b"again"}, ValueError)
    assert target.read_text() == "again"


def test_a_plot_path_that_is_a_directory_fails_before_anything_is_written(tmp_path):
    generic = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
    locus = Locus("demo", ["t_q1", "t_q2"], "", generic, [Component(
        ["t_q1 + t_q2"], dict(generic, Nm=3), {"q1": "0", "q2": "0"}, True)])
    (tmp_path / "r_q1_q2.png").mkdir()
    with pytest.raises(ReportError, match="r_q1_q2.png: is a directory"):
        write_report(locus, tmp_path / "r.md", load("paper-case1-hard"), pairs=["q1,q2"])
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r_q1_q2.png"]


def test_workers_are_capped(monkeypatch):
    assert worker_count(1000, 10, cpus=2) == 2
    assert worker_count(1000, 1, cpus=64) == 1
    assert worker_count(3, 100, cpus=64) == 3
    started = []

    class Recording(concurrent.futures.ProcessPoolExecutor):
        def __init__(self, max_workers=None, *args, **kwargs):
            started.append(max_workers)
            super().__init__(max_workers, *args, **kwargs)

    monkeypatch.setattr(concurrent.futures, "ProcessPoolExecutor", Recording)
    result = runner.invoke(app, ["sweep", "paper-case1-hard", "--grid", "q1=0..1:10",
                                 "--workers", "1000"])
    assert result.exit_code == 0 and result.stdout.count("\n") > 10
    expected = min(os.cpu_count() or 1, 10)
    assert started == ([expected] if expected > 1 else [])     # never 999 processes


# ------------------------------------------------------------------ pickling


def _analysis_in_a_worker(name: str, at: str | None):
    return load(name).analyze(at)


def test_analysis_pickles_and_comes_back_from_a_worker():
    a = load("paper-case1-soft").analyze("L=2")
    b = pickle.loads(pickle.dumps(a))
    assert b.numbers == a.numbers and b.C12 == a.C12 and b.C22 == a.C22 and b.check()
    assert b.joint_velocities([-2, 0, 0, 0, 0, 0]).particular.T.tolist() == [[1, 1]]
    with ProcessPoolExecutor(1) as pool:
        c = pool.submit(_analysis_in_a_worker, "paper-case2-hard", None).result()
    assert c.numbers == load("paper-case2-hard").analyze().numbers
    generic = pickle.loads(pickle.dumps(load("paper-case1-hard").analyze(generic=True)))
    assert generic.check() and generic.variables == load("paper-case1-hard").analyze(
        generic=True).variables


def test_a_report_written_by_another_run_meanwhile_is_not_lost(tmp_path, monkeypatch):
    import coopkin_sym.analysis.locus.search as search_module

    target = tmp_path / "r.json"
    generic = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}

    def another_run_meanwhile(system, **kwargs):
        target.write_text("the other run's report")
        return Locus(system.name, ["t_q1", "t_q2"], "", generic)

    monkeypatch.setattr(search_module, "compute_locus", another_run_meanwhile)
    result = runner.invoke(app, ["locus", "paper-case1-hard", "-o", str(target),
                                 "--no-progress"])
    assert result.exit_code == 2
    assert "another run wrote this file" in result.stderr
    assert target.read_text() == "the other run's report"
    assert '"system": "paper case 1' in (tmp_path / "r.1.json").read_text()


def test_a_table_and_its_metadata_written_meanwhile_are_both_kept(tmp_path, monkeypatch):
    """Another run writes ``out.csv`` and ``out.csv.json`` while this one computes: this
    run's two files are kept under new names, the other run's pair is left whole."""
    import coopkin_sym.cli as cli

    out = tmp_path / "out.csv"
    real = cli._sweep

    def meanwhile(*args, **kwargs):
        out.write_text("theirs")
        (tmp_path / "out.csv.json").write_text("their metadata")
        return real(*args, **kwargs)

    monkeypatch.setattr(cli, "_sweep", meanwhile)
    result = runner.invoke(app, ["sweep", "paper-case1-hard", "--grid", "q1=0..1:3",
                                 "-o", str(out), "--no-progress"])
    assert result.exit_code == 2
    assert "another run wrote this file while this one was computing" in result.stderr
    assert out.read_text() == "theirs"
    assert (tmp_path / "out.csv.json").read_text() == "their metadata"
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        "out.1.csv", "out.csv", "out.csv.1.json", "out.csv.json"]
    assert (tmp_path / "out.1.csv").read_text().startswith("q1,q1_rad,")
