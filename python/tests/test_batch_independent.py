"""An independent check of pinjoint.PreslidingBatch (issue 30) with scenes the other tests
have not seen: n ``Presliding`` objects as the reference (rebuilt at each joint's
temperature when it changes, carrying their full state over), per-joint parameters, host
inertia, host steps, wrapped angles, pending first angles, every input dtype and memory
layout NumPy offers, pickling mid-scene, the released GIL, and bad input named by argument
and index with nothing changed."""

from __future__ import annotations

import pickle
import re
import threading
import time

import numpy as np
import pytest

import pinjoint

MU = pinjoint.MU_C
COLD_DAY = 273.15 - 54.0
LAW = (1.2e-3, 0.93, 0.015)


def bits(x):
    return np.ascontiguousarray(np.asarray(x, dtype=np.float64)).view(np.int64)


class Reference:
    """n Presliding objects; joint i's is rebuilt with ``lubricant.temperature`` = T when its
    temperature changes (the full state carried over: the scalar law at that temperature)."""

    def __init__(self, sets, host_inertia, angle):
        self.sets = sets
        self.j = np.zeros(len(sets)) if host_inertia is None else np.broadcast_to(np.asarray(host_inertia, float), (len(sets),))
        self.t = [s["lubricant.temperature"] for s in sets]
        self.objs = [
            pinjoint.Presliding(s, *LAW, angle=None if angle is None else float(angle[i]), host_inertia=float(self.j[i]))
            for i, s in enumerate(sets)
        ]

    def at(self, i, t):
        t = self.sets[i]["lubricant.temperature"] if t is None else float(t)
        if t != self.t[i] or np.float64(t).view(np.int64) != np.float64(self.t[i]).view(np.int64):
            old = self.objs[i]
            o = pinjoint.Presliding(self.sets[i].with_values({"lubricant.temperature": t}), *LAW, host_inertia=float(self.j[i]))
            o._native.set_full_state(*old._native.full_state)
            self.objs[i] = o
            self.t[i] = t
        return self.objs[i]

    def full(self):
        s = [o._native.full_state for o in self.objs]
        return [np.array([x[k] for x in s]) for k in range(5)]


def draw_sets(rng, n):
    sets = []
    for _ in range(n):
        v = {MU: float(rng.uniform(0.07, 0.17))}
        if rng.uniform() < 0.5:
            v["lubricant.viscosity"] = float(pinjoint.Params()["lubricant.viscosity"] * rng.uniform(0.6, 1.0))
        if rng.uniform() < 0.5:
            v["grease.yield_stress"] = float(pinjoint.Params()["grease.yield_stress"] * rng.uniform(0.5, 2.0))
        sets.append(pinjoint.Params(v))
    return sets


def layouts(rng, x):
    """`x` (float64, shape (n,)) as a caller may hand it over: the same values in another
    memory layout or dtype that holds them exactly (or a list)."""
    n = x.size
    how = rng.integers(0, 7)
    if how == 0:
        base = np.empty(3 * n)
        base[::3] = x
        return base[::3]  # strided view
    if how == 1:
        return x[::-1].copy()[::-1]  # negative strides
    if how == 2:
        return np.asfortranarray(np.stack([x, x], axis=1))[:, 1]  # a column of a Fortran array
    if how == 3:
        return x.astype(">f8")  # big-endian
    if how == 4:
        return list(x)
    if how == 5:
        ro = x.copy()
        ro.flags.writeable = False
        return ro
    return x


def wrap(x, how, turns):
    if how == 0:
        return x
    if how == 1:
        w = (x + np.pi) % (2 * np.pi) - np.pi
        return np.where(w == -np.pi, np.pi, w)
    return x + turns * 2 * np.pi


@pytest.mark.parametrize("seed", range(5))
def test_random_scene_equals_presliding_objects(seed):
    rng = np.random.default_rng(1000 + seed)
    n = int(rng.integers(1, 24))
    per_joint = seed % 2 == 0
    sets = draw_sets(rng, n) if per_joint else draw_sets(rng, 1) * n
    inertia = None if seed == 1 else np.where(rng.uniform(size=n) < 0.2, 0.0, 10 ** rng.uniform(-2, 4, n))
    pending = seed == 3
    a0 = None if pending else rng.uniform(-4, 4, n)
    if per_joint and seed % 4 == 0:
        # The per_joint mapping over one shared set (the reference: one set per joint).
        keys = [MU, "lubricant.viscosity", "grease.yield_stress"]
        batch = pinjoint.PreslidingBatch(n, None, *LAW, host_inertia=inertia, angle=a0, per_joint={k: np.array([s[k] for s in sets]) for k in keys})
    else:
        batch = pinjoint.PreslidingBatch(n, sets if per_joint else sets[0], *LAW, host_inertia=inertia, angle=a0)
    ref = Reference(sets, inertia, a0)
    theta = np.zeros(n) if a0 is None else a0.copy()
    w = rng.uniform(-2, 2, n)
    p = rng.uniform(2e3, 6e4, n)
    cold = 0
    for k in range(50):
        h = 0.0 if rng.uniform() < 0.2 else 10 ** rng.uniform(-4, -1.7)
        if rng.uniform() < 0.67:
            kind = rng.integers(0, 8, n)
            w = np.select([kind == 0, kind == 1, kind == 2, kind == 3], [0.0, -0.0, -w, rng.uniform(-1e-3, 1e-3, n)], w + rng.uniform(-0.3, 0.3, n))
            lk = rng.integers(0, 10, n)
            p = np.select([lk == 0, lk == 1, lk == 2, lk == 3], [0.0, -0.0, -rng.uniform(1e3, 6e4, n), rng.uniform(4.5e3, 5.5e3, n)], rng.uniform(5e2, 6.5e4, n))
        theta = theta + w * h + np.where(w == 0, rng.uniform(-2e-4, 2e-4, n), 0.0)
        reported = wrap(theta, rng.integers(0, 3), rng.integers(-3, 4))
        temps = None
        if rng.uniform() < 0.7:
            temps = rng.choice([COLD_DAY, 218.15, 253.15, 293.15, 343.15, float(rng.uniform(218.15, 350))], n)
        step = None if rng.uniform() < 0.4 else np.where(rng.uniform(size=n) < 0.1, 0.0, h)
        objs = [ref.at(i, None if temps is None else temps[i]) for i in range(n)]
        want = np.array([o.torque(reported[i], w[i], p[i]) for i, o in enumerate(objs)])
        args = [layouts(rng, reported), layouts(rng, w), layouts(rng, p)]
        targ = None if temps is None else layouts(rng, temps)
        sarg = None if step is None else layouts(rng, step)
        how = k % 3
        if how == 0:
            got = batch.step(*args, temperature=targ, step=sarg)
        else:
            got = batch.torque(*args, targ)
            batch.commit(*args, targ, step=sarg)
        for i, o in enumerate(objs):
            o.commit(reported[i], w[i], p[i], None if step is None else float(step[i]))
        assert np.array_equal(bits(got), bits(want)), (seed, k, got, want)
        full = batch._native.full_states
        for x, y in zip(full, ref.full()):
            if x.dtype == bool:
                assert np.array_equal(x, y), (seed, k)
            else:
                assert np.array_equal(bits(x), bits(y)), (seed, k)
        if temps is not None:
            cold += int(np.sum((temps <= COLD_DAY) & (p != 0)))
        # The sliding torque: each object's, at rest, the breakaway torque.
        if k % 10 == 0:
            bt = batch.sliding_torque(np.zeros(n), p, targ)
            assert np.all(bt >= 0) and np.all(bt[p == 0] == 0)
    assert cold > 0 or seed == 1


@pytest.mark.parametrize("fidelity", ["table", "boundary", "auto"])
def test_levels_sliding_torque_is_joint_evaluate(fidelity):
    rng = np.random.default_rng(5)
    n = 6
    sets = draw_sets(rng, n)
    env = (4e3, 50e3, 0.02, 8.0)
    batch = pinjoint.PreslidingBatch(n, sets, fidelity=fidelity, tolerance=5e-4, envelope=env)
    joints = {}
    for k in range(6):
        t = rng.choice([COLD_DAY, 253.15, 293.15, 343.15], n)
        w = rng.choice([0.0, -0.0, 0.01, 0.02, 0.5, -3.0, 8.0, 9.0], n) * rng.choice([1.0, 1.0001], n)
        p = rng.choice([-1.0, 1.0], n) * rng.uniform(3e3, 5.5e4, n)
        got = batch.sliding_torque(w, p, t)
        # At most four tables a call: the joints of the first four (set, temperature) keys in
        # joint order are the level's (every joint has its own set here: the first four
        # joints); at table and auto the others are the complete solve's.
        for i in range(n):
            level = fidelity if (i < 4 or fidelity == "boundary") else "full"
            key = (i, float(t[i]), level)
            if key not in joints:
                joints[key] = pinjoint.Joint(sets[i].with_values({"lubricant.temperature": float(t[i])}), level, 5e-4, env)
            want = joints[key].evaluate(p[i], w[i])["torque"]
            assert bits(got[i]) == bits(want), (fidelity, k, i, got[i], float(want))
        assert batch.tables_held <= 4


@pytest.mark.parametrize("fidelity", ["full", "boundary", "table"])
def test_pickle_mid_scene_continues_bit_for_bit(fidelity):
    rng = np.random.default_rng(11)
    n = 4 if fidelity == "table" else 9
    sets = draw_sets(rng, n)
    b = pinjoint.PreslidingBatch(n, sets, *LAW, host_inertia=rng.uniform(0, 50, n), fidelity=fidelity, angle=None)
    theta = np.zeros(n)
    for k in range(12 if fidelity == "table" else 40):
        w = rng.uniform(-1, 1, n) * (rng.uniform(size=n) < 0.7)
        theta = theta + w * 1e-3 + rng.uniform(-1e-4, 1e-4, n)
        p = rng.uniform(3e3, 5e4, n)
        t = rng.choice([COLD_DAY, 293.15, 330.0], n)
        if k == 5:
            c = pickle.loads(pickle.dumps(b))
            assert type(c) is pinjoint.PreslidingBatch
            for x, y in zip(b._native.full_states, c._native.full_states):
                assert np.array_equal(np.asarray(x).view(np.uint8), np.asarray(y).view(np.uint8))
        tb = b.step(theta, w, p, t, step=1e-3)
        if k >= 5:
            tc = c.step(theta, w, p, t, step=1e-3)
            assert np.array_equal(bits(tb), bits(tc)), k
    assert np.array_equal(bits(b.state[0]), bits(c.state[0]))


def test_gil_is_released_while_a_big_batch_steps():
    n = 200_000
    b = pinjoint.PreslidingBatch(n)
    a, w, p = np.zeros(n), np.linspace(-2, 2, n), np.linspace(3e3, 5e4, n)
    b.step(a, w, p)  # models built
    ticks = []
    stop = threading.Event()
    started = threading.Event()

    def spin():
        # A tick each millisecond the thread runs Python.
        started.set()
        last = 0.0
        while not stop.is_set():
            now = time.perf_counter()
            if now > last + 1e-3:
                ticks.append(now)
                last = now

    th = threading.Thread(target=spin)
    th.start()
    started.wait()
    try:
        t0 = time.perf_counter()
        out = b.step(a + 1e-4, w * 1.01, p * 0.99)
        t1 = time.perf_counter()
    finally:
        stop.set()
        th.join()
    assert out.shape == (n,) and np.all(np.isfinite(out))
    dt = t1 - t0
    assert dt > 0.05, dt
    # The other thread ran Python in the middle half of the call: with the GIL held through
    # the call it could run only before and after it.
    middle = [t for t in ticks if t0 + 0.25 * dt < t < t0 + 0.75 * dt]
    assert len(middle) >= 5, (len(middle), dt)


def state_bits(b):
    return [np.asarray(x).copy().view(np.uint8) for x in b._native.full_states]


def same_state(b, before):
    return all(np.array_equal(x, y) for x, y in zip(state_bits(b), before))


@pytest.mark.parametrize("n", [5, 1500])
def test_bad_input_names_argument_and_index_and_changes_nothing(n):
    rng = np.random.default_rng(3)
    b = pinjoint.PreslidingBatch(n, host_inertia=np.linspace(0, 10, n))
    a, w, p = rng.uniform(-1e-3, 1e-3, n), rng.uniform(-1, 1, n), rng.uniform(3e3, 5e4, n)
    b.step(a, w, p, step=1e-3)
    before = state_bits(b)
    ks = [0, n // 2 + 1, n - 1]
    for k in ks:
        for name in ["angle", "angular_velocity", "load", "temperature", "step"]:
            for bad in [np.nan, np.inf, -np.inf]:
                args = {"angle": a.copy(), "angular_velocity": w.copy(), "load": p.copy(), "temperature": np.full(n, 293.15), "step": np.full(n, 1e-3)}
                args[name][k] = bad
                # A strided view: the index is the view's, not the buffer's.
                base = np.zeros(2 * n)
                base[::2] = args[name]
                args[name] = base[::2]
                calls = ["commit", "step"] if name == "step" else ["torque", "commit", "step"]
                for call in calls:
                    kw = dict(args) if call != "torque" else {x: args[x] for x in ["angle", "angular_velocity", "load", "temperature"]}
                    with pytest.raises(ValueError) as e:
                        getattr(b, call)(**kw)
                    msg = str(e.value)
                    assert re.search(rf"\b{name} = ", msg), msg
                    assert f"index {k}" in msg, msg
                    assert same_state(b, before), (name, k, call)
    # Shapes that disagree: a ValueError naming the argument.
    for name in ["angle", "angular_velocity", "load", "temperature", "step"]:
        for shape in [(n + 1,), (n - 1,), (n, 1), (1, n), (2,) if n != 2 else (3,)]:
            args = {"angle": a, "angular_velocity": w, "load": p, "temperature": np.full(n, 293.15), "step": np.full(n, 1e-3)}
            args[name] = np.ones(shape)
            with pytest.raises(ValueError, match=rf"^{name} has shape"):
                b.step(**args)
            assert same_state(b, before)
    # A load beyond capacity, a temperature out of range, a negative step: named with the index.
    for name, val, pat in [("load", 1e13, "capacity"), ("temperature", 1e4, "lubricant.temperature"), ("temperature", 100.0, "lubricant.temperature"), ("step", -1e-3, "step")]:
        args = {"angle": a, "angular_velocity": w, "load": p.copy(), "temperature": np.full(n, 293.15), "step": np.full(n, 1e-3)}
        args[name] = args[name].copy()
        args[name][ks[1]] = val
        with pytest.raises(ValueError) as e:
            b.step(**args)
        assert pat in str(e.value) and f"index {ks[1]}" in str(e.value), str(e.value)
        assert same_state(b, before)


def test_dtypes_are_exact_or_refused():
    n = 7
    rng = np.random.default_rng(8)
    a = rng.uniform(-1e-3, 1e-3, n).astype(np.float32)
    w = rng.integers(-3, 4, n)
    p = rng.integers(2000, 50000, n)
    ref = pinjoint.PreslidingBatch(n)
    want = ref.torque(a.astype(np.float64), w.astype(np.float64), p.astype(np.float64))
    for conv in [lambda x: x, lambda x: x.astype(np.int32) if x.dtype.kind == "i" else x.astype(np.float16).astype(np.float32),
                 lambda x: x.astype(np.uint32) if x.dtype.kind == "i" and (x >= 0).all() else x,
                 lambda x: x.astype(object), lambda x: [float(v) if isinstance(v, np.floating) else int(v) for v in x]]:
        b = pinjoint.PreslidingBatch(n)
        aa, ww, pp = conv(a), conv(w), conv(p)
        got = b.torque(aa, ww, pp)
        exp = ref.torque(np.asarray(aa, dtype=np.float64), np.asarray(ww, dtype=np.float64), np.asarray(pp, dtype=np.float64))
        assert np.array_equal(bits(got), bits(exp))
    b = pinjoint.PreslidingBatch(n)
    assert np.array_equal(bits(b.torque(a, w, p)), bits(want))
    assert np.array_equal(bits(b.torque(a, w.astype(np.float16), p.astype(np.float32))), bits(want))
    before = state_bits(b)
    bad = {
        "complex": p.astype(np.complex128),
        "bool": p > 0,
        "str": p.astype(str),
        "bytes": p.astype("S8"),
        "object None": np.array([None] * n, dtype=object),
        "object str": np.array(["1"] * n, dtype=object),
        "datetime": np.array(["2026-01-01"] * n, dtype="datetime64[D]"),
        "timedelta": np.arange(n).astype("timedelta64[s]"),
        "structured": np.zeros(n, dtype=[("x", float)]),
    }
    for label, x in bad.items():
        with pytest.raises(TypeError, match="load") as e:
            b.step(a, w, x)
        assert same_state(b, before), label
        with pytest.raises(TypeError, match="angular_velocity"):
            b.commit(a, x, p)
        with pytest.raises(TypeError, match="temperature"):
            b.torque(a, w, p, temperature=x)
        assert same_state(b, before), label
    # A ragged list: a clear error, no state changed.
    with pytest.raises((ValueError, TypeError), match="angle"):
        b.step([[0.0], [0.0, 1.0]] + [0.0] * (n - 2), w, p)
    assert same_state(b, before)
    # Integers too large for a float64 to hold exactly: the load is beyond any capacity anyway.
    with pytest.raises(ValueError, match="index 0"):
        b.step(a, w, np.array([2**63 - 1] + [20000] * (n - 1), dtype=np.int64))
    assert same_state(b, before)


def test_non_contiguous_inputs_answer_as_contiguous():
    n = 1200
    rng = np.random.default_rng(21)
    big = rng.uniform(-1, 1, (4, 3 * n))
    big[0] *= 1e-3
    big[2] = 3e3 + 4e4 * np.abs(big[2])
    big[3] = 250 + 40 * np.abs(big[3])
    big = np.asfortranarray(big)
    a, w, p, t = big[0, ::3], big[1, 1::3], big[2, ::-3], big[3, 2::3]
    assert not (a.flags.c_contiguous or w.flags.c_contiguous or p.flags.c_contiguous or t.flags.c_contiguous)
    b1, b2 = pinjoint.PreslidingBatch(n), pinjoint.PreslidingBatch(n)
    for k in range(3):
        s = np.full(n, 1e-3)[::1]
        big[0] += 1e-4
        t1 = b1.step(a, w, p, t, step=s)
        t2 = b2.step(np.ascontiguousarray(a), np.ascontiguousarray(w), np.ascontiguousarray(p), np.ascontiguousarray(t), step=np.full(n, 1e-3))
        assert np.array_equal(bits(t1), bits(t2))
    for x, y in zip(state_bits(b1), state_bits(b2)):
        assert np.array_equal(x, y)
    # The native half copies a strided view too (bypassing the wrapper's contiguous copy).
    n2 = 4
    b3, b4 = pinjoint.PreslidingBatch(n2), pinjoint.PreslidingBatch(n2)
    base = np.arange(3 * n2, dtype=float)
    aa, ww, pp = base[::3] * 1e-5, base[1::3] * 0.1, 2e4 + 100 * base[2::3]
    r3 = b3._native.step(aa, ww, pp, None, None)
    r4 = b4._native.step(aa.copy(), ww.copy(), pp.copy(), None, None)
    assert np.array_equal(bits(r3), bits(r4))


def test_n_zero_and_n_one():
    with pytest.raises(ValueError, match="n = 0"):
        pinjoint.PreslidingBatch(0)
    b = pinjoint.PreslidingBatch(1, per_joint={MU: [0.11]})
    o = pinjoint.Presliding({MU: 0.11})
    for k in range(20):
        ang, w, p = 1e-4 * np.sin(k), 0.3 * np.cos(k / 2), 2e4 + 1e3 * k
        want = o.torque(ang, w, p)
        o.commit(ang, w, p, step=1e-3)
        got = b.step(ang, w, p, step=1e-3)
        assert got.shape == (1,) and bits(got[0]) == bits(want)


def test_scene_uncertainty_cold_day_reproducible_local_and_on_a_local_cluster(tmp_path, monkeypatch):
    """examples/scene_uncertainty.py at the cold day (-54 C) with distributions given by the
    user: the same seed gives the same files, on a 2-worker LocalCluster too; the summary's
    percentiles are the samples' (recomputed here by sorting); each sample's results are
    those of its scene run alone (a function of its own parameters: chunking changes
    nothing); another chunking gives the same files."""
    from conftest import ROOT, load_example

    monkeypatch.syspath_prepend(str(ROOT / "examples"))
    monkeypatch.setenv("PYTHONPATH", str(ROOT / "examples"))
    ex = load_example("scene_uncertainty")
    common = ["--samples", "90", "--end-time", "2.2", "--seed", "5", "--no-figure",
              "--param", f"{MU}=normal:0.12,0.008", "--param", "grease.yield_stress=lognormal:default,0.4"]
    runs = {"a": ["--chunk", "25"], "b": ["--chunk", "25"], "c": ["--chunk", "90"], "dask": ["--chunk", "25", "--workers", "2"]}
    for name, extra in runs.items():
        assert ex.main([*common, *extra, "--output", str(tmp_path / name)]) == 0
    for f in ("samples.csv", "summary.txt"):
        a = (tmp_path / "a" / f).read_bytes()
        for other in ("b", "c", "dask"):
            assert a == (tmp_path / other / f).read_bytes(), (f, other)
    rows = [r.split(",") for r in (tmp_path / "a" / "samples.csv").read_text().splitlines()]
    head, body = rows[0], rows[1:]
    assert head[:3] == ["index", MU, "grease.yield_stress"] and len(body) == 90
    col = {h: np.array([float(r[i]) for r in body]) for i, h in enumerate(head)}
    # The draws follow the distributions given (5 standard errors).
    assert abs(col[MU].mean() - 0.12) < 5 * 0.008 / np.sqrt(90)
    y0 = pinjoint.Params()["grease.yield_stress"]
    assert abs(np.log(col["grease.yield_stress"] / y0).mean()) < 5 * 0.4 / np.sqrt(90)
    # The summary's percentiles: observed values (inverted CDF), recomputed by sorting.
    summary = (tmp_path / "a" / "summary.txt").read_text().splitlines()
    assert "-54 C" in summary[0]
    table = {float(line.split()[0]): (float(line.split()[1]), float(line.split()[2])) for line in summary if re.match(r"^\s+\d+\s", line)}
    assert sorted(table) == [1, 5, 25, 50, 75, 95, 99]
    for q, (t, m) in table.items():
        k = int(np.ceil(q / 100 * 90)) - 1
        assert t == np.sort(col["time_to_lock"])[k] and m == np.sort(col["lock_margin"])[k], q
    # Each sample alone: its scene run by itself gives its row bit for bit.
    scene = pinjoint.scenes.FreeFall(end_time=2.2, step=1e-3)
    for i in (0, 31, 89):
        one = pinjoint.scenes.free_fall(1, scene, per_joint={MU: [col[MU][i]], "grease.yield_stress": [col["grease.yield_stress"][i]]}, temperature=273.15 - 54)
        for c in ("time_to_lock", "lock_margin", "friction_energy", "breakaway_torque", "speed_at_lock"):
            assert repr(float(one[c][0])) == body[i][head.index(c)], (i, c)
    # The cold day is colder than +20 C: a larger breakaway (the grease stiffens), a smaller margin.
    warm = pinjoint.scenes.free_fall(1, scene, per_joint={MU: [col[MU][0]], "grease.yield_stress": [col["grease.yield_stress"][0]]}, temperature=293.15)
    assert warm["breakaway_torque"][0] < col["breakaway_torque"][0] and warm["lock_margin"][0] > col["lock_margin"][0]


def test_per_joint_switches_take_bools_and_refuse_other_numbers():
    """A switch (model.paper, grease.enabled) set per joint: True/False (or 0/1) as
    ``Params`` takes them, each joint equal to its own Presliding; any other number is a
    ValueError naming per_joint[key], the value and the index (it was taken as True)."""
    n = 4
    flags = [False, True, False, True]
    objs = [pinjoint.Presliding({"grease.enabled": f}) for f in flags]
    a, w, p = np.full(n, 1e-4), np.array([0.3, 0.3, -1.0, 0.0]), np.full(n, 2e4)
    want = np.array([o.torque(a[i], w[i], p[i]) for i, o in enumerate(objs)])
    for given in (np.array(flags), flags, np.array(flags, dtype=np.int8), [0.0, 1.0, 0.0, 1.0]):
        b = pinjoint.PreslidingBatch(n, per_joint={"grease.enabled": given})
        assert np.array_equal(bits(b.torque(a, w, p)), bits(want)), given
        c = pickle.loads(pickle.dumps(b))
        assert np.array_equal(bits(c.torque(a, w, p)), bits(want))
    for key in ("grease.enabled", "model.paper"):
        for bad, k in (([0.0, 1.0, 0.5, 1.0], 2), ([2.0, 1.0, 0.0, 0.0], 0), ([1.0, 1.0, 0.0, -1.0], 3)):
            with pytest.raises(ValueError, match=rf"per_joint\['{re.escape(key)}'\] = .* at index {k} .*True or False"):
                pinjoint.PreslidingBatch(n, per_joint={key: bad})
    # Booleans stay refused for a number.
    with pytest.raises(TypeError, match="booleans"):
        pinjoint.PreslidingBatch(n, per_joint={MU: np.array(flags)})


def test_scene_uncertainty_names_the_sample_a_distribution_spoils(tmp_path, monkeypatch):
    """A user's distribution that draws a value the model does not take (a negative mu_c from
    a normal): the example refuses before running any scene, naming the sample's index in
    the study (not its index within a task) and the parameter."""
    from conftest import ROOT, load_example

    monkeypatch.syspath_prepend(str(ROOT / "examples"))
    ex = load_example("scene_uncertainty")
    spec = f"{MU}=normal:0.12,0.04"
    n = 400
    s = pinjoint.scenes.sample_parameters(n, 4, distributions=dict([pinjoint.scenes.parse_distribution(spec)]))
    bad = np.flatnonzero(s[MU] < 0)
    assert bad.size and bad[0] >= 50, bad  # beyond the first task of 50 scenes
    with pytest.raises(ValueError) as e:
        ex.main(["--samples", str(n), "--chunk", "50", "--seed", "4", "--param", spec, "--no-figure", "--output", str(tmp_path / "o")])
    msg = str(e.value)
    assert f"sample {bad[0]}" in msg and MU in msg and "out of range" in msg, msg
    assert not (tmp_path / "o" / "samples.csv").exists()
