"""pinjoint.PreslidingBatch: n presliding joints stepped together, bit for bit n
pinjoint.Presliding objects (full) and the levels' torque (Joint.evaluate); pickling,
threads and the released GIL; bad input named by argument and index."""

from __future__ import annotations

import pickle
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import pinjoint

MU = pinjoint.MU_C


def bits(x):
    return np.asarray(x, dtype=np.float64).view(np.int64)


def random_scene(rng, n, steps):
    """Angles, speeds and loads of a random scene: rests (omega 0, -0.0), creep, slides,
    reversals, unloaded joints and negative (signed) loads; half the steps hold the last
    speed and load."""
    angle = np.zeros(n)
    w = p = None
    for k in range(steps):
        angle = angle + rng.uniform(-2e-3, 2e-3, n)
        if w is None or rng.uniform() < 0.5:
            w = rng.choice([0.0, -0.0, 1e-4, -3e-3, 0.3, -2.0, 4.0], n) * rng.uniform(0.5, 1.5, n)
            p = rng.choice([0.0, 1.0, 1.0, 1.0, -1.0], n) * rng.uniform(2e3, 5e4, n)
        yield angle.copy(), w.copy(), p.copy()


@pytest.mark.parametrize("seed", range(4))
def test_equals_n_presliding_objects_bit_for_bit(seed):
    rng = np.random.default_rng(seed)
    n = 37
    law = (2e-3, 0.9, 0.02)
    a0 = rng.uniform(-1, 1, n)
    batch = pinjoint.PreslidingBatch(n, None, *law, angle=a0)
    objs = [pinjoint.Presliding(None, *law, angle=a) for a in a0]
    for k, (a, w, p) in enumerate(random_scene(rng, n, 60)):
        if k % 3 == 0:
            t = batch.step(a, w, p)
        else:
            t = batch.torque(a, w, p)
            batch.commit(a, w, p * (0.5 if k % 3 == 2 else 1.0))
        ref = [o.torque(a[i], w[i], p[i]) for i, o in enumerate(objs)]
        for i, o in enumerate(objs):
            o.commit(a[i], w[i], p[i] * (0.5 if k % 3 == 2 else 1.0))
        assert np.array_equal(bits(t), bits(ref)), k
        tau, ref_angle = batch.state
        assert np.array_equal(bits(tau), bits([o.state[0] for o in objs])), k
        assert np.array_equal(bits(ref_angle), bits([o.state[1] for o in objs])), k


def test_per_joint_parameters_and_temperatures_equal_their_own_objects():
    rng = np.random.default_rng(7)
    n = 12
    mu = rng.uniform(0.08, 0.16, n)
    temps = rng.choice([253.15, 293.15, 318.15], n)
    by_map = pinjoint.PreslidingBatch(n, per_joint={MU: mu})
    sets = [pinjoint.Params({MU: float(m)}) for m in mu]
    by_list = pinjoint.PreslidingBatch(n, sets)
    objs = [pinjoint.Presliding(s.with_values({"lubricant.temperature": float(t)})) for s, t in zip(sets, temps)]
    for a, w, p in random_scene(rng, n, 30):
        t1 = by_map.step(a, w, p, temps)
        t2 = by_list.step(a, w, p, temperature=temps)
        ref = []
        for i, o in enumerate(objs):
            ref.append(o.torque(a[i], w[i], p[i]))
            o.commit(a[i], w[i], p[i])
        assert np.array_equal(bits(t1), bits(ref))
        assert np.array_equal(bits(t2), bits(ref))
    # Joints share a model only where parameters and temperature agree.
    assert by_map.models_held == n


@pytest.mark.parametrize("fidelity", ["table", "boundary", "auto"])
def test_levels_give_the_vectorised_joints_torque(fidelity):
    rng = np.random.default_rng(3)
    n = 300
    w = rng.choice([0.0, 1.0], n) * np.exp(rng.uniform(np.log(1e-3), np.log(20.0), n)) * rng.choice([-1.0, 1.0], n)
    p = np.exp(rng.uniform(np.log(3e3), np.log(6e4), n))
    b = pinjoint.PreslidingBatch(n, fidelity=fidelity, tolerance=1e-3)
    joint = pinjoint.Joint(fidelity=fidelity, tolerance=1e-3)
    assert np.array_equal(bits(b.sliding_torque(w, p)), bits(joint.evaluate(p, w)["torque"]))
    assert b.models_held == 1
    # Steady sliding (the state at the bound) gives -sign(omega) T.
    # (0.5 rad: far beyond the presliding angle, within pi: not read modulo 2*pi as a reversal.)
    big = np.where(w >= 0, 1.0, -1.0) * 0.5
    b.commit(big, w, p)
    t = b.torque(big, w, p)
    moving = w != 0
    assert np.array_equal(bits(t[moving]), bits(-np.sign(w[moving]) * joint.evaluate(p, w)["torque"][moving]))


def test_pickle_mid_scene_steps_on_bit_for_bit():
    rng = np.random.default_rng(11)
    n = 25
    b = pinjoint.PreslidingBatch(n, per_joint={MU: rng.uniform(0.1, 0.14, n)}, host_inertia=750.0, fidelity="full")
    scene = list(random_scene(rng, n, 20))
    for a, w, p in scene[:10]:
        b.step(a, w, p)
    c = pickle.loads(pickle.dumps(b))
    assert np.array_equal(c.host_inertia, np.full(n, 750.0))
    for a, w, p in scene[10:]:
        assert np.array_equal(bits(b.step(a, w, p, 300.0)), bits(c.step(a, w, p, 300.0)))
    assert all(np.array_equal(bits(x), bits(y)) for x, y in zip(b.state, c.state))


def test_threads_and_the_released_gil():
    n = 200_000
    rng = np.random.default_rng(5)
    a, w, p = rng.uniform(-1e-3, 1e-3, n), rng.uniform(-3, 3, n), rng.uniform(5e3, 5e4, n)
    serial = [pinjoint.PreslidingBatch(n).torque(a, w * s, p) for s in (1.0, 0.5)]
    with ThreadPoolExecutor(2) as ex:
        threaded = list(ex.map(lambda s: pinjoint.PreslidingBatch(n).torque(a, w * s, p), (1.0, 0.5)))
    for s, t in zip(serial, threaded):
        assert np.array_equal(bits(s), bits(t))
    b = pinjoint.PreslidingBatch(n)
    ticks, stop = [], threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    th = threading.Thread(target=ticker)
    th.start()
    time.sleep(0.01)
    t0 = time.perf_counter()
    b.torque(a, w * 0.7, p)
    t1 = time.perf_counter()
    stop.set()
    th.join()
    during = [t for t in ticks if t0 < t < t1]
    assert t1 - t0 > 0.05, t1 - t0
    assert len(during) >= 5, (len(during), t1 - t0)


def test_bad_input_names_the_argument_and_the_index():
    b = pinjoint.PreslidingBatch(4)
    a, w, p = np.zeros(4), np.full(4, 0.1), np.full(4, 2e4)
    with pytest.raises(ValueError, match=r"angular_velocity has shape \(3,\), the batch has n = 4 joints"):
        b.torque(a, w[:3], p)
    with pytest.raises(ValueError, match=r"load has shape \(2, 2\)"):
        b.commit(a, w, p.reshape(2, 2))
    bad = p.copy()
    bad[2] = np.nan
    with pytest.raises(ValueError, match=r"^load = NaN N at index 2 is not a finite number$"):
        b.step(a, w, bad)
    bad = a.copy()
    bad[1] = np.inf
    with pytest.raises(ValueError, match=r"^angle = inf rad at index 1 is not a finite number$"):
        b.commit(bad, w, p)
    with pytest.raises(ValueError, match=r"temperature = NaN K at index 3"):
        b.torque(a, w, p, [293.15, 293.15, 293.15, np.nan])
    with pytest.raises(ValueError, match=r"temperature at index 0: .*lubricant.temperature = 1000 K"):
        b.torque(a, w, p, [1000.0, 293.15, 293.15, 293.15])
    big = p.copy()
    big[3] = 1e12
    with pytest.raises(ValueError, match=r"^at index 3: load = 1000000000000.0 N is beyond the asperity model's capacity"):
        b.torque(a, w, big)
    with pytest.raises(TypeError, match=r"angle \(rad\) must hold real numbers, not booleans"):
        b.torque(np.zeros(4, bool), w, p)
    with pytest.raises(TypeError, match=r"load \(N\) must hold real numbers, got dtype complex128"):
        b.torque(a, w, p.astype(complex))
    with pytest.raises(TypeError, match=r"angular_velocity \(rad/s\) must hold real numbers, got dtype <U"):
        b.torque(a, ["x"] * 4, p)
    # Nothing changed by the calls that raised; float32 and int inputs are taken.
    assert np.array_equal(b.state[0], np.zeros(4)) and np.array_equal(b.state[1], np.zeros(4))
    assert np.array_equal(b.torque(a.astype(np.float32), w, p.astype(np.int64)), b.torque(a, w, p))
    with pytest.raises(ValueError, match=r"per_joint\['friction.boundary_friction_coefficient'\] has shape \(3,\)"):
        pinjoint.PreslidingBatch(4, per_joint={MU: [0.1, 0.1, 0.1]})
    with pytest.raises(ValueError, match=r"parameters of joint 2: .*boundary_friction_coefficient = -1"):
        pinjoint.PreslidingBatch(4, per_joint={MU: [0.1, 0.1, -1.0, 0.1]})
    with pytest.raises(ValueError, match=r"per_joint: nonsense.key is not a parameter"):
        pinjoint.PreslidingBatch(2, per_joint={"nonsense.key": [1.0, 2.0]})
    with pytest.raises(ValueError, match=r"params has 3 parameter sets for n = 4 joints"):
        pinjoint.PreslidingBatch(4, [None] * 3)
    with pytest.raises(ValueError, match=r"n = 0 is not a number of joints"):
        pinjoint.PreslidingBatch(0)
    with pytest.raises(ValueError, match=r"host_inertia = -1 kg.m2 at index 0 is invalid"):
        pinjoint.PreslidingBatch(2, host_inertia=-1.0)


def wrap_report(x, how, turns):
    """The angle a host reports for the true angle x: as is (0), wrapped into (-pi, pi] (1),
    or shifted by whole turns (2)."""
    w = np.where(how == 1, np.remainder(x + np.pi, 2 * np.pi) - np.pi, x)
    w = np.where((how == 1) & (w == -np.pi), np.pi, w)
    return np.where(how == 2, x + turns * 2 * np.pi, w)


@pytest.mark.parametrize("seed", range(6))
def test_host_conventions_equal_n_presliding_objects_bit_for_bit(seed):
    """host_inertia, the host's steps (a number, an array, None), wrapped angles and
    angle=None: n Presliding objects driven the same way, bit for bit, states and last steps."""
    rng = np.random.default_rng(100 + seed)
    n = 23
    law = (2e-3, 0.9, 0.02)
    inertia = rng.choice([0.0, 0.3, 5.0, 750.0, 1e4], n) * rng.uniform(0.5, 1.5, n)
    unreferenced = seed % 2 == 0
    start = rng.choice([np.pi - 1e-3, -np.pi + 5e-4, 0.0, 2.0], n) + rng.uniform(-10, 10, n) * (rng.uniform(size=n) < 0.3)
    batch = pinjoint.PreslidingBatch(n, None, *law, host_inertia=inertia, angle=None if unreferenced else start)
    objs = [pinjoint.Presliding(None, *law, angle=None if unreferenced else float(start[i]), host_inertia=float(inertia[i])) for i in range(n)]
    assert np.array_equal(batch.host_inertia, inertia)
    assert np.array_equal(batch.unreferenced, np.full(n, unreferenced))
    for k, (da, w, p) in enumerate(random_scene(rng, n, 50)):
        a = wrap_report(start + da, rng.integers(0, 3, n), rng.integers(-3, 4, n))
        h = [None, 1e-3, rng.choice([0.0, 1e-4, 5e-3, 2e-2], n)][k % 3]
        load_c = p * (0.5 if k % 4 == 3 else 1.0)
        if k % 2 == 0:
            t = batch.step(a, w, p, step=h)
        else:
            t = batch.torque(a, w, p)
            batch.commit(a, w, load_c, None, h)
        ref = [o.torque(a[i], w[i], p[i]) for i, o in enumerate(objs)]
        for i, o in enumerate(objs):
            hi = None if h is None else float(np.broadcast_to(h, (n,))[i])
            o.commit(a[i], w[i], p[i] if k % 2 == 0 else load_c[i], step=hi)
        assert np.array_equal(bits(t), bits(ref)), k
        full = [o._native.full_state for o in objs]
        tau, ref_angle = batch.state
        step, omega = batch.last_step
        for c, got in enumerate((tau, ref_angle, step, omega)):
            assert np.array_equal(bits(got), bits([f[c] for f in full])), (k, c)
        assert np.array_equal(batch.unreferenced, [f[4] for f in full]), k


def test_the_damping_cap_and_the_wrapped_angle_act():
    """Not a no-op: the host inertia and the step change the torque as the scalar law says;
    a wrapped angle reads as the continuous one; an increment near pi is read against
    omega*step only when the step is given."""
    n = 3
    j = pinjoint.PreslidingBatch(n, host_inertia=[0.0, 1.0, 1.0])
    # In the elastic range at speed: the damping term differs with J and with the cap at h.
    j.commit([0.0] * n, 0.0, 2e4, step=[0.0, 0.0, 1e-2])
    t = j.torque(1e-5, 0.05, 2e4)
    assert t[0] != t[1] != t[2] and abs(t[2] - t[0]) > 0 and abs(t[1]) > abs(t[2])
    # A slide through pi, the host wrapping: with the step, the same torque as continuous.
    cont = pinjoint.PreslidingBatch(2, angle=np.pi - 0.01)
    wrapped = pinjoint.PreslidingBatch(2, angle=np.pi - 0.01)
    h, w = 1e-3, 2.0
    x = np.pi - 0.01
    for k in range(20):
        x = x + w * h
        xw = x - 2 * np.pi if x > np.pi else x
        tc = cont.step([x, x], w, 2e4, step=h)
        tw = wrapped.step([xw, x], w, 2e4, step=h)
        assert np.allclose(tc, tw, rtol=0, atol=1e-6), k
    assert x > np.pi
    # A true increment of 3.5 rad reported wrapped (3.5 - 2*pi) after a commit at 30 rad/s:
    # with the step 0.1 s (omega*h = 3 rad) read as +3.5 (sliding forward, torque -T at
    # rest); without it as the nearest to 0, -2.78 rad (a reversal: +T).
    for h, sign in ((0.1, -1.0), (None, 1.0)):
        r = pinjoint.PreslidingBatch(1)
        r.commit(0.0, 30.0, 2e4, step=h)
        t = r.torque(3.5 - 2 * np.pi, 0.0, 2e4)[0]
        assert sign * t > 0 and abs(t) == pytest.approx(r.sliding_torque(0.0, 2e4)[0]), (h, t)


def test_pickle_keeps_host_inertia_steps_and_pending_first_angles():
    rng = np.random.default_rng(12)
    n = 9
    inertia = rng.uniform(0.5, 50.0, n)
    b = pinjoint.PreslidingBatch(n, host_inertia=inertia, angle=None)
    c0 = pickle.loads(pickle.dumps(b))
    assert c0.unreferenced.all() and np.array_equal(c0.host_inertia, inertia)
    scene = list(random_scene(rng, n, 24))
    for k, (a, w, p) in enumerate(scene[:12]):
        b.step(a + 3.0, w, p, step=rng.choice([0.0, 1e-3, 1e-2], n))
        if k == 0:
            # The first angle became each joint's reference in b; the pickled copy still waits.
            assert not b.unreferenced.any() and c0.unreferenced.all()
    c = pickle.loads(pickle.dumps(b))
    assert np.array_equal(c.host_inertia, inertia)
    assert all(np.array_equal(bits(x), bits(y)) for x, y in zip(b.last_step, c.last_step))
    for a, w, p in scene[12:]:
        # Wrapped on one side, read against the last step's omega*h on both.
        a = np.remainder(a + 3.0 + np.pi, 2 * np.pi) - np.pi
        assert np.array_equal(bits(b.step(a, w, p, 300.0, 2e-3)), bits(c.step(a, w, p, 300.0, 2e-3)))
    assert all(np.array_equal(bits(x), bits(y)) for x, y in zip(b.state, c.state))
    # The copy pickled before the first angle starts where b started.
    a, w, p = scene[0]
    fresh = pinjoint.PreslidingBatch(n, host_inertia=inertia, angle=None)
    assert np.array_equal(bits(c0.step(a + 3.0, w, p)), bits(fresh.step(a + 3.0, w, p)))


def test_bad_steps_name_the_argument_and_the_index():
    b = pinjoint.PreslidingBatch(3, host_inertia=[1.0, 0.0, 2.0])
    a, w, p = np.zeros(3), np.full(3, 0.1), np.full(3, 2e4)
    with pytest.raises(ValueError, match=r"^step = -0.001 s at index 1 is invalid: it must be a finite number >= 0$"):
        b.commit(a + 1e-4, w, p, step=[1e-3, -1e-3, 1e-3])
    with pytest.raises(ValueError, match=r"^step = NaN s at index 0 is invalid"):
        b.step(a + 1e-4, w, p, step=np.nan)
    with pytest.raises(ValueError, match=r"step has shape \(2,\), the batch has n = 3 joints"):
        b.step(a + 1e-4, w, p, step=[1e-3, 1e-3])
    with pytest.raises(TypeError, match=r"step \(s\) must hold real numbers"):
        b.commit(a, w, p, step=[True, False, True])
    assert np.array_equal(b.state[0], np.zeros(3)) and np.array_equal(b.last_step[0], np.zeros(3))
    with pytest.raises(ValueError, match=r"host_inertia = 2000000000 kg.m2 at index 2 is invalid"):
        pinjoint.PreslidingBatch(3, host_inertia=[1.0, 1.0, 2e9])
    assert np.array_equal(pinjoint.PreslidingBatch(2, host_inertia=0.0).host_inertia, [0.0, 0.0])


def test_the_native_calls_check_their_arrays():
    """The native half takes its arrays positionally: too few or too many, or an array of
    another dtype, is a TypeError naming what it expected; sliding_torque's load stands in for
    the angle it does not read."""
    b = pinjoint.PreslidingBatch(3)
    native = b._native
    z = np.zeros(3)
    with pytest.raises(TypeError, match=r"the first 3 required; got 2 arguments"):
        native.torque(z, z)
    with pytest.raises(TypeError, match=r"got 6 arguments"):
        native.step(z, z, z, None, None, z)
    with pytest.raises(TypeError, match=r"argument 'load'"):
        native.step(z, z, np.zeros(3, dtype=np.int64))
    load = np.array([1e4, 2e4, 3e4])
    assert np.array_equal(native.sliding_torque(z + 0.1, load), b.sliding_torque(0.1, load))
    assert np.array_equal(native.sliding_torque(z + 0.1, load, None), b.sliding_torque(0.1, load))
    # A commit through the native half is the wrapper's commit.
    other = pinjoint.PreslidingBatch(3)
    native.commit(z + 1e-4, z, load, None, None)
    other.commit(1e-4, 0.0, load)
    for mine, theirs in zip(b.state, other.state):
        assert np.array_equal(mine, theirs)
    assert np.all(b.state[0] != 0.0) and np.all(b.state[1] == 1e-4)
