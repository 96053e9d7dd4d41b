"""Pickling (for Dask and multiprocessing workers), threads and the released GIL."""

from __future__ import annotations

import pickle
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import pinjoint

L = np.geomspace(1e3, 1e5, 40)[:, None]
W = np.geomspace(1e-3, 10.0, 50)  # inside the film bound at 1 kN (docs/conventions.md)


def same(a, b):
    return all(np.array_equal(np.asarray(a[k]), np.asarray(b[k])) for k in pinjoint.RESULT_COLUMNS)


@pytest.mark.parametrize(
    "joint",
    [
        pinjoint.Joint(),
        pinjoint.Joint({"friction.boundary_friction_coefficient": 0.1, "lubricant.viscosity": 0.02}),
        pinjoint.Joint(fidelity="table", tolerance=1e-3, envelope=(5e3, 8e4, 1e-2, 10.0)),
        pinjoint.Joint(fidelity="auto"),
    ],
)
def test_pickled_joint_gives_bit_identical_results(joint):
    again = pickle.loads(pickle.dumps(joint, protocol=pickle.HIGHEST_PROTOCOL))
    assert again.params == joint.params
    assert (again.fidelity, again.tolerance, again.envelope, again.level) == (
        joint.fidelity, joint.tolerance, joint.envelope, joint.level)
    assert same(again.evaluate(L, W), joint.evaluate(L, W))


def test_params_pickle():
    p = pinjoint.Params({"surface.asperity_radius": 3.3e-6})
    assert pickle.loads(pickle.dumps(p)) == p


def test_threads_share_a_joint_and_match_serial():
    joint = pinjoint.Joint()
    rng = np.random.default_rng(11)
    jobs = [(rng.uniform(1e3, 6e4, 5000), rng.uniform(-10, 10, 5000)) for _ in range(8)]
    serial = [joint.evaluate(l, w) for l, w in jobs]
    with ThreadPoolExecutor(4) as ex:
        threaded = list(ex.map(lambda a: joint.evaluate(*a), jobs))
    for s, t in zip(serial, threaded):
        assert same(s, t)


def test_the_gil_is_released_during_evaluate():
    joint = pinjoint.Joint()
    l = np.full(400_000, 2e4)
    w = np.geomspace(1e-3, 300.0, 400_000)  # inside the film bound at 20 kN (docs/conventions.md)
    ticks = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    t0 = time.perf_counter()
    joint.evaluate(l, w)
    alone = time.perf_counter() - t0
    th = threading.Thread(target=ticker)
    th.start()
    time.sleep(0.01)
    n0 = len(ticks)
    t0 = time.perf_counter()
    joint.evaluate(l, w)
    t1 = time.perf_counter()
    stop.set()
    th.join()
    during = [t for t in ticks[n0:] if t0 < t < t1]
    # With the GIL held the ticker could not run at all while evaluate ran.
    assert alone > 0.05, alone
    assert len(during) >= 5, (len(during), t1 - t0)
