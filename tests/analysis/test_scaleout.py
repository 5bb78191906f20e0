"""Scale-out: sweeps and batches of analyses on a dask cluster (two worker processes)
give exactly the serial results; tasks are plain data; one bad item of a batch is
reported alone."""

from __future__ import annotations

import multiprocessing
import pickle
import random
from concurrent.futures import Executor, Future, ProcessPoolExecutor

import numpy as np
import pytest
from random_systems import random_system

import coopkin_sym
from coopkin_sym.analysis.batch import BatchResult, run_batch
from coopkin_sym.analysis.sweep import compile_system, grid
from coopkin_sym.errors import ArgumentTypeError
from coopkin_sym.model.examples import list_examples
from coopkin_sym.present.text import analysis_document

CASE1 = coopkin_sym.load("paper-case1-hard")
CASE2 = coopkin_sym.load("paper-case2-hard")
# q2 = +-pi/2 are on the singular line of case 2 (Nr = 3): 40 points rechecked exactly
GRID = "q1=-pi..pi:20,q2=-pi/2..pi/2:20"


@pytest.fixture(scope="module")
def dask_executor():
    distributed = pytest.importorskip("distributed")
    before = set(multiprocessing.active_children())
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            yield client.get_executor()
    left = set(multiprocessing.active_children()) - before
    assert not left, f"worker processes left running: {left}"


def _half_angle(rng: random.Random) -> str:
    return f"2*atan({rng.randint(-9, 9)}/{rng.randint(1, 9)})"


def _items() -> list:
    """Shipped examples at home, random rational configurations of the two case studies,
    random systems as mappings, an irrational angle, and bad items."""
    rng = random.Random(11)
    items: list = list(list_examples())
    for _ in range(6):
        items.append(("paper-case1-hard", f"q1={_half_angle(rng)},q2={_half_angle(rng)},L=1"))
        at = {j: _half_angle(rng) for j in ("q1", "q2", "q6", "q7")}
        items.append(("paper-case2-hard", {**at, "q5": f"{rng.randint(1, 5)}/3", "L": 2}))
    items += [random_system(seed) for seed in range(4)]
    items += [("paper-case1-hard", "q1=-pi/6,q2=pi/6"),       # over Q(sqrt 3)
              ("paper-case1-hard", "q1=1"),                   # not an exact angle
              ("no-such-example", None),
              ("five-bar", "q1=0", "extra"),
              ("paper-case1-hard", "q1=pi/2,q2=pi/2")]
    return items


BAD = {-4: "--at q1: angle '1' is not exact: tan(q/2) = tan(1/2) is irrational",
       -3: "no-such-example: no such file (nor a shipped example: allegro-hand-sphere, "
           "bennett-linkage, bricard-linkage, dh-three-finger-hand",
       -2: "expected a model source or a pair (source, at), got a sequence of 3"}


def _check_batch(results: list[BatchResult], items: list) -> None:
    """Input order, the numbers of ``System.analyze`` item by item, the bad ones alone."""
    assert [r.index for r in results] == list(range(len(items)))
    for k, text in BAD.items():
        assert not results[k].ok and results[k].error.startswith(text), results[k]
        assert results[k].numbers is None
    assert results[-1].numbers.as_dict() == {"Nm": 3, "Nc": 3, "Ni": 1, "Nr": 0,
                                              "Ng": 1, "Nd": 4, "Nh": 1}
    assert results[-5].numbers.Ni == 3
    good = [k for k in range(len(items)) if k - len(items) not in BAD]
    for k in good:
        source, at = items[k] if isinstance(items[k], tuple) else (items[k], None)
        assert results[k].ok, results[k]
        assert results[k].numbers == coopkin_sym.load(source).analyze(at).numbers


# --- sweeps ----------------------------------------------------------------------------
def test_the_plan_and_a_chunk_pickle_to_equal_data():
    plan = compile_system(CASE2, ("q1", "q2"), "L=1").plan
    back = pickle.loads(pickle.dumps(plan))
    assert back.keys() == plan.keys()
    for key, value in plan.items():
        if isinstance(value, np.ndarray):
            assert back[key].dtype == value.dtype and np.array_equal(back[key], value), key
        else:
            assert back[key] == value, key


def test_sweep_on_a_dask_cluster_is_the_serial_sweep(dask_executor):
    g = grid(CASE2, GRID)
    serial = CASE2.sweep(g, at="L=1")
    spread = CASE2.sweep(g, at="L=1", executor=dask_executor, chunk=37)
    assert serial.numbers.shape == (400, 7)
    assert np.array_equal(spread.numbers, serial.numbers)
    assert np.array_equal(spread.rechecked, serial.rechecked)
    assert spread.rows() == serial.rows()
    assert int(serial.rechecked.sum()) == 40
    assert sorted(set(serial.numbers[:, 3].tolist())) == [2, 3]     # Nr


# --- batches ---------------------------------------------------------------------------
def test_serial_batch_is_analyze_item_by_item():
    items = _items()
    _check_batch(coopkin_sym.analyze_many(items), items)


def test_batch_on_a_dask_cluster_is_the_serial_batch(dask_executor):
    items = _items()
    serial = coopkin_sym.analyze_many(items, json=True, chunk=3)
    spread = coopkin_sym.analyze_many(items, json=True, executor=dask_executor, chunk=3)
    assert spread == serial
    _check_batch(spread, items)
    k = len(items) - 1
    assert spread[k].document == analysis_document(CASE1.analyze("q1=pi/2,q2=pi/2"))


def test_system_batch_on_a_dask_cluster(dask_executor):
    points = ["q1=pi/2,q2=pi/2", {"q1": "-pi/2"}, None, "q1=-pi/6,q2=pi/6", "q3=0"]
    serial = CASE1.analyze_many(points)
    spread = CASE1.analyze_many(points, executor=dask_executor, chunk=1)
    assert spread == serial
    assert [r.numbers.Nm if r.ok else r.error for r in serial] == [
        3, 2, 2, 3, "--at q3: unknown name 'q3' (known: q1, q2, L)"]
    assert [r.at for r in serial][:3] == ["q1=pi/2,q2=pi/2", "q1=-pi/2", None]


def test_batch_on_a_process_pool_is_the_serial_batch():
    items = [("paper-case2-hard", f"q1=pi/2,q2={a},L=1") for a in ("0", "pi/2", "x")]
    with ProcessPoolExecutor(2) as pool:
        spread = coopkin_sym.analyze_many(items, executor=pool, chunk=1)
    assert spread == coopkin_sym.analyze_many(items)
    assert [r.numbers.Nr if r.ok else None for r in spread] == [2, 3, None]


class _Broken(Executor):
    """An executor whose every task fails (as when a worker process dies)."""

    def submit(self, fn, /, *args, **kwargs):
        future: Future = Future()
        future.set_exception(RuntimeError("worker lost"))
        return future


def _numbers(model, at):
    return coopkin_sym.System(model).analyze(at).numbers, None


def test_a_failed_task_is_an_error_of_its_items_only():
    results = run_batch(_numbers, ["five-bar", ("five-bar", 3)], executor=_Broken())
    assert [r.error for r in results] == [
        "the task running this item failed: RuntimeError: worker lost",
        "at: expected --at text or a mapping, got int"]
    assert repr(results[1]) == ("<BatchResult 1 five-bar at 3: error: at: expected "
                                "--at text or a mapping, got int>")


def test_result_as_plain_data():
    r = coopkin_sym.analyze_many([("paper-case1-hard", {"q1": "pi/2", "q2": "pi/2"})],
                                 json=True)[0]
    data = r.as_dict()
    assert data["at"] == "q1=pi/2,q2=pi/2" and data["error"] is None
    assert data["numbers"] == data["document"]["numbers"] == r.numbers.as_dict()
    assert pickle.loads(pickle.dumps(r)) == r


# --- what executor= takes ------------------------------------------------------------------
def test_a_dask_client_itself_is_taken_as_executor():
    distributed = pytest.importorskip("distributed")
    g = grid(CASE1, "q1=-pi/2..pi/2:5,q2=-pi/2..pi/2:5")
    items = [("paper-case1-hard", "q1=pi/2,q2=pi/2"), "five-bar", ("five-bar", "q1=1")]
    with distributed.Client(processes=False, n_workers=1, threads_per_worker=2,
                            dashboard_address=None) as client:
        spread = CASE1.sweep(g, at="L=1", executor=client, chunk=4)
        batch = coopkin_sym.analyze_many(items, executor=client, chunk=1)
        points = CASE1.analyze_many(["q1=pi/2,q2=pi/2", "q1=0"], executor=client)
    assert spread == CASE1.sweep(g, at="L=1")
    corners = [k for k, n in enumerate(spread.numbers[:, 0].tolist()) if n == 3]
    assert corners == [0, 4, 20, 24] and int(spread.rechecked.sum()) == 4   # Nm = 3
    assert batch == coopkin_sym.analyze_many(items)
    assert [r.numbers.Nm if r.ok else None for r in batch] == [3, 3, None]
    assert [r.numbers.Nm for r in points] == [3, 2]


class _ClientLike:
    """Has ``get_executor`` and ``submit`` but its executor is not one."""

    def submit(self, fn, *args):
        raise AssertionError("never called")

    def get_executor(self):
        return "not an executor"


class _ActorPoolLike:
    """The interface of ``ray.util.ActorPool`` (``submit(fn, value)``, ``get_next``): not
    an executor; the error says what to pass instead (its multiprocessing Pool)."""

    def submit(self, fn, value):
        raise AssertionError("never called")

    def get_next(self):
        raise AssertionError("never called")


WHAT_TO_PASS = ("executor: expected a concurrent.futures.Executor (ProcessPoolExecutor, "
                "ThreadPoolExecutor, a cluster's executor), a dask distributed.Client, "
                "a pool with apply_async(fn, args, callback=, error_callback=) "
                "(multiprocessing.Pool, ray.util.multiprocessing.Pool), "
                "or None to run here; got ")


@pytest.mark.parametrize(("executor", "name"), [(4, "int"), (object(), "object"),
                                                (_ClientLike(), "_ClientLike"),
                                                (_ActorPoolLike(), "_ActorPoolLike"),
                                                (ProcessPoolExecutor, "type")])
def test_any_other_executor_is_one_error_saying_what_to_pass(executor, name):
    message = WHAT_TO_PASS + name
    calls = [lambda: CASE1.sweep(["q1=0"], executor=executor),
             lambda: coopkin_sym.analyze_many(["five-bar"], executor=executor),
             lambda: CASE1.analyze_many(["q1=0"], executor=executor)]
    for call in calls:
        with pytest.raises(ArgumentTypeError) as info:
            call()
        assert str(info.value) == message


# --- a pool with apply_async: multiprocessing.Pool, ray.util.multiprocessing.Pool --------
class _RayLikePool:
    """The interface of ``ray.util.multiprocessing.Pool`` that the tasks use:
    ``apply_async(func, args=None, kwargs=None, callback=None, error_callback=None)``,
    the calls run on threads of its own (ray itself is not needed)."""

    def __init__(self):
        from multiprocessing.pool import ThreadPool
        self._threads = ThreadPool(2)
        self.calls = 0

    def apply_async(self, func, args=None, kwargs=None, callback=None,
                    error_callback=None):
        self.calls += 1
        return self._threads.apply_async(func, args or (), kwargs or {},
                                         callback=callback, error_callback=error_callback)

    def close(self):
        self._threads.close()
        self._threads.join()


def test_a_ray_like_pool_is_taken_as_executor():
    pool = _RayLikePool()
    try:
        g = grid(CASE1, "q1=-pi/2..pi/2:5,q2=-pi/2..pi/2:5")
        items = [("paper-case1-hard", "q1=pi/2,q2=pi/2"), "five-bar", ("five-bar", "q1=1")]
        spread = CASE1.sweep(g, at="L=1", executor=pool, chunk=4)
        batch = coopkin_sym.analyze_many(items, executor=pool, chunk=1)
        points = CASE1.analyze_many(["q1=pi/2,q2=pi/2", "q1=0"], executor=pool)
    finally:
        pool.close()
    assert pool.calls >= 7 + 3 + 1
    assert spread == CASE1.sweep(g, at="L=1")
    assert batch == coopkin_sym.analyze_many(items)
    assert [r.numbers.Nm if r.ok else None for r in batch] == [3, 3, None]
    assert [r.numbers.Nm for r in points] == [3, 2]


def test_a_multiprocessing_pool_is_the_serial_batch():
    items = [("paper-case1-hard", "q1=pi/2,q2=pi/2"), "five-bar"]
    with multiprocessing.get_context("spawn").Pool(1) as pool:
        spread = coopkin_sym.analyze_many(items, executor=pool, chunk=1)
    assert spread == coopkin_sym.analyze_many(items)


class _FailingPool:
    """A pool whose every task fails outside the computation (a lost worker)."""

    def apply_async(self, func, args=(), kwargs=None, callback=None, error_callback=None):
        error_callback(RuntimeError("worker lost"))


def test_a_task_the_pool_loses_is_the_error_of_its_items():
    results = run_batch(_numbers, ["five-bar", ("five-bar", 3)], executor=_FailingPool())
    assert results[0].error == "the task running this item failed: RuntimeError: worker lost"
