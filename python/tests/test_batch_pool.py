"""Where a call runs and what it reads: the first thread to make a large one works as one of
its own pool's threads, every other thread's large calls go to a second pool, small calls stay
on the calling thread, and the answers are the same bits whichever runs them (PreslidingBatch
and Joint.evaluate); the inputs are read once each, after the GIL is released, from any
float64 layout (strided, unaligned, reversed), their lengths checked before anything is
allocated for them; a forked child steps on after its parent did, large batches and small."""

from __future__ import annotations

import subprocess
import sys
import threading
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import pinjoint

# Above two of the library's chunks (512 joints; Joint.evaluate's 2048 points): the parallel path.
N = 5000


def bits(x):
    return np.asarray(x, dtype=np.float64).view(np.int64)


def scene(seed, n=N, steps=12):
    rng = np.random.default_rng(seed)
    angle = rng.uniform(-1, 1, n)
    frames = []
    for _ in range(steps):
        angle = angle + rng.uniform(-3e-3, 3e-3, n)
        w = rng.choice([0.0, 1e-4, -0.02, 0.5, -3.0], n) * rng.uniform(0.5, 1.5, n)
        p = rng.uniform(3e3, 6e4, n)
        frames.append((angle.copy(), w, p))
    return frames


def run(frames, fidelity="full"):
    b = pinjoint.PreslidingBatch(len(frames[0][0]), fidelity=fidelity)
    out = [b.step(a, w, p) for a, w, p in frames]
    return np.array(out), b.state


@pytest.mark.parametrize("fidelity", ["full", "table"])
def test_every_thread_gives_the_same_bits(fidelity):
    frames = scene(1)
    main = run(frames, fidelity)
    # A plain thread and an executor's threads: the second pool (the main thread made the
    # process's first large call above, or earlier in the session).
    got = {}
    th = threading.Thread(target=lambda: got.setdefault("thread", run(frames, fidelity)))
    th.start()
    th.join()
    with ThreadPoolExecutor(2) as ex:
        pooled = list(ex.map(lambda _: run(frames, fidelity), range(2)))
    for other in [got["thread"], *pooled]:
        assert np.array_equal(bits(main[0]), bits(other[0]))
        assert all(np.array_equal(bits(x), bits(y)) for x, y in zip(main[1], other[1]))
    # And the scalar objects, joint by joint, at full fidelity.
    if fidelity == "full":
        idx = np.arange(0, N, 97)
        objs = [pinjoint.Presliding() for _ in idx]
        for k, (a, w, p) in enumerate(frames):
            ref = [o.torque(a[i], w[i], p[i]) for o, i in zip(objs, idx)]
            for o, i in zip(objs, idx):
                o.commit(a[i], w[i], p[i])
            assert np.array_equal(bits(main[0][k][idx]), bits(ref)), k


def test_joint_evaluate_gives_the_same_bits_on_every_thread():
    rng = np.random.default_rng(2)
    p, w = rng.uniform(3e3, 6e4, 3 * 2048), rng.uniform(1e-3, 8.0, 3 * 2048)
    j = pinjoint.Joint()
    main = j.evaluate(p, w)["torque"]
    with ThreadPoolExecutor(2) as ex:
        others = list(ex.map(lambda _: j.evaluate(p, w)["torque"], range(2)))
    for o in others:
        assert np.array_equal(bits(main), bits(o))


def unaligned(x):
    """x's values in an array whose data starts one byte past an 8-byte boundary."""
    raw = np.zeros(8 * x.size + 16, dtype=np.uint8)
    start = (-raw.ctypes.data) % 8 + 1
    v = np.frombuffer(raw.data, dtype=np.float64, count=x.size, offset=start)
    raw[start : start + 8 * x.size] = np.frombuffer(x.tobytes(), dtype=np.uint8)
    assert not v.flags.aligned and np.array_equal(bits(v), bits(x))
    return v


def test_strided_unaligned_and_readonly_inputs_give_the_same_bits():
    frames = scene(3, steps=4)
    ref = run(frames)
    layouts = {
        "strided": lambda x: np.repeat(x, 2)[::2],
        "reversed": lambda x: x[::-1].copy()[::-1],
        "unaligned": unaligned,
        "readonly": lambda x: np.frombuffer(x.tobytes(), dtype=np.float64),
    }
    for name, f in layouts.items():
        assert np.array_equal(bits(f(frames[0][0])), bits(frames[0][0])), name
        got = run([tuple(f(x) for x in fr) for fr in frames])
        assert np.array_equal(bits(ref[0]), bits(got[0])), name
        # The native call itself (the wrapper's coercion bypassed): the same.
        b = pinjoint.PreslidingBatch(N)
        out = [b._native.step(*(f(x) for x in fr), None, None) for fr in frames]
        assert np.array_equal(bits(ref[0]), bits(np.array(out))), name


def test_a_wrong_length_is_named_before_anything_is_allocated_for_it():
    b = pinjoint.PreslidingBatch(N)
    z, p = np.zeros(N), np.full(N, 1e4)
    huge = np.broadcast_to(0.0, (2**40,))  # 8 TiB as a copy
    for args, name in [((huge, z, p, None, None), "angle"), ((z, z, huge, None, None), "load"), ((z, z, p, None, huge), "step")]:
        with pytest.raises(ValueError, match=f"{name}.*{2**40}"):
            b._native.step(*args)
    with pytest.raises(ValueError, match="load"):
        b._native.sliding_torque(z, huge, None)
    with pytest.raises(ValueError, match="angular_velocity"):
        b._native.torque(z, z[:-1], huge, None)
    # Nothing changed: the batch steps on as a fresh one.
    assert np.array_equal(bits(b.step(z, z, p)), bits(pinjoint.PreslidingBatch(N).step(z, z, p)))


def test_inputs_written_during_a_call_leave_every_state_finite():
    # Another thread rewrites the input arrays (finite values) while the batch steps: each
    # joint reads some mix of old and new values, never a number checked as one value and
    # used as another; nothing becomes NaN, nothing raises.
    n = 50_000
    rng = np.random.default_rng(4)
    a, w, p = rng.uniform(-1e-2, 1e-2, n), rng.uniform(-3, 3, n), rng.uniform(5e3, 5e4, n)
    alt = (a[::-1].copy(), w[::-1].copy(), p[::-1].copy())
    b = pinjoint.PreslidingBatch(n, fidelity="table")
    stop = threading.Event()

    def writer():
        k = 0
        while not stop.is_set():
            src = alt if k % 2 else (a.copy(), w.copy(), p.copy())
            for dst, s in zip(inputs, src):
                dst[:] = s
            k += 1

    inputs = (a.copy(), w.copy(), p.copy())
    th = threading.Thread(target=writer)
    th.start()
    try:
        for _ in range(30):
            t = b.step(*inputs)
            assert np.isfinite(t).all()
    finally:
        stop.set()
        th.join()
    assert all(np.isfinite(x).all() for x in b.state)


FORK_SCRIPT = r"""
import multiprocessing, sys, threading
import numpy as np
import pinjoint

mode = sys.argv[1]
rng = np.random.default_rng(6)
n = 5000
a, w, p = rng.uniform(-1e-2, 1e-2, n), rng.uniform(-3, 3, n), rng.uniform(5e3, 5e4, n)

def large():
    return pinjoint.PreslidingBatch(n).step(a, w, p)

def small(temperatures):
    # A small batch that builds two models a call (two temperatures).
    m = 100
    return pinjoint.PreslidingBatch(m).step(np.zeros(m), np.full(m, 0.1), np.full(m, 1e4), np.resize(np.array(temperatures), m))

def in_thread(f):
    out = []
    t = threading.Thread(target=lambda: out.append(f()))
    t.start()
    t.join()
    return out[0]

if mode == "main-first":
    run = large
elif mode == "thread-first":
    # Another thread makes the process's first large call (it owns the pool); the main
    # thread's calls then go to the others' pool.
    in_thread(large)
    run = large
elif mode == "small":
    run = lambda: small([300.0, 310.0])
elif mode == "small-in-threads":
    large()  # the main thread owns a pool
    in_thread(lambda: small([300.0, 310.0]))
    run = lambda: in_thread(lambda: small([320.0, 330.0]))
ref = run()

def child(q):
    q.put(run())

ctx = multiprocessing.get_context("fork")
q = ctx.Queue()
proc = ctx.Process(target=child, args=(q,))
proc.start()
got = q.get(timeout=60)
proc.join(timeout=30)
assert proc.exitcode == 0, proc.exitcode
if mode != "small-in-threads":
    assert np.array_equal(ref.view(np.int64), got.view(np.int64))
print("ok")
"""


@pytest.mark.skipif(sys.platform != "linux", reason="fork is the Linux default start method")
@pytest.mark.parametrize("first", ["main-first", "thread-first", "small", "small-in-threads"])
def test_a_forked_child_steps_after_its_parent(first):
    # A child forked after its parent stepped has none of the parent's pool threads: its
    # first large call builds its own pools, and a small call (here one that builds two
    # models) uses none (rayon's global pool would wait for threads the child does not have).
    # In a fresh interpreter, so that the first call is the script's.
    r = subprocess.run([sys.executable, "-c", FORK_SCRIPT, first], capture_output=True, text=True, timeout=180)
    assert r.returncode == 0 and r.stdout.strip() == "ok", (r.returncode, r.stdout, r.stderr[-2000:])
