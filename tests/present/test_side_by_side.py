"""The pictures of a report drawn side by side in worker processes: in order, with
their warnings and failures handed back, within the bound, and the same pictures as
drawn one by one."""

import os
import time
import warnings

import pytest

import coopkin_sym
import coopkin_sym.present.report.side_by_side as side_by_side
from coopkin_sym.errors import DrawError
from coopkin_sym.present.report.side_by_side import PictureFailed, draw_in_order

SIDE_BY_SIDE = side_by_side.workers_for(4) > 0
needs_cores = pytest.mark.skipif(not SIDE_BY_SIDE,
                                 reason="this machine draws one by one (one core or no fork)")


def _pid():
    return os.getpid()


def _warns():
    warnings.warn("a picture said this", UserWarning, stacklevel=1)
    return "drawn"


def _fails():
    raise DrawError("joint q9 is not in the model")


def _sleeps():
    time.sleep(2)
    return "late"


@pytest.mark.parametrize("workers", [0, 2])
def test_values_come_back_in_order_with_their_warnings_and_failures(workers):
    if workers and not SIDE_BY_SIDE:
        pytest.skip("no fork here")
    jobs = [lambda: 1, _warns, _fails, lambda: b"png"]
    got = list(draw_in_order(jobs, workers=workers))
    assert [k for k, _ in got] == [0, 1, 2, 3]
    values = [v for _, (v, _) in got]
    assert values[0] == 1 and values[1] == "drawn" and values[3] == b"png"
    assert isinstance(values[2], PictureFailed)
    assert isinstance(values[2].error, DrawError)
    assert str(values[2].error) == "joint q9 is not in the model"
    assert got[1][1][1] == [("a picture said this", UserWarning)]
    assert got[0][1][1] == [] and got[2][1][1] == []


@needs_cores
def test_side_by_side_the_jobs_run_in_other_processes():
    pids = {v for _, (v, _) in draw_in_order([_pid] * 4, workers=2)}
    assert os.getpid() not in pids and 1 <= len(pids) <= 2


@pytest.mark.parametrize("workers", [0, 2])
def test_no_job_is_waited_for_past_the_bound(workers):
    if workers and not SIDE_BY_SIDE:
        pytest.skip("no fork here")
    start = time.monotonic()
    got = list(draw_in_order([lambda: 1, _sleeps, lambda: 3], until=start + 0.5,
                             workers=workers))
    if workers:     # the sleeping job is left at the bound, and the one after it
        assert [k for k, _ in got] == [0] and time.monotonic() - start < 1.5
    else:           # one by one a job runs to its end: the next is not started
        assert [k for k, _ in got] == [0, 1] and time.monotonic() - start < 3.5


def test_few_pictures_or_one_core_are_drawn_here(monkeypatch):
    assert side_by_side.workers_for(side_by_side.MIN_PICTURES - 1) == 0
    monkeypatch.setattr(os, "sched_getaffinity", lambda _pid: {0}, raising=False)
    monkeypatch.setattr(os, "cpu_count", lambda: 1)
    assert side_by_side.workers_for(10) == 0


@pytest.mark.slow
@needs_cores
def test_a_report_has_the_same_pictures_drawn_either_way(tmp_path, monkeypatch):
    system = coopkin_sym.load("paper-case1-hard")
    locus = system.locus()
    (tmp_path / "side").mkdir()
    (tmp_path / "alone").mkdir()
    side = coopkin_sym.write_report(locus, tmp_path / "side" / "r.md", system)
    monkeypatch.setattr(side_by_side, "MIN_PICTURES", 1000)
    alone = coopkin_sym.write_report(locus, tmp_path / "alone" / "r.md", system)
    assert [p.name for p in side] == [p.name for p in alone]
    assert len(side) == 7       # the report, one plot, five pictures of the system
    for a, b in zip(side, alone, strict=True):
        assert a.read_bytes() == b.read_bytes(), a.name
