#!/usr/bin/env python3
"""The Python part of pinjoint-bench's batch section: PreslidingBatch against the vectorised
Joint.evaluate of as many points (its floor) and against n Presliding objects in a Python
loop, and table against full through PreslidingBatch, in one run. Prints JSON.

    .venv-python/bin/python benches/batch_step.py [--quick]

Inputs: n joints each swinging +-0.05-0.5 rad at 0.2-2 Hz under 5-50 kN +-20 % (one in ten
held at rest), a 1 ms step; every repeat runs the same steps. The table's envelope covers the
scene's loads (ENVELOPE, as the Rust part's); `batch_table_default_ns` is the table over the
default envelope (5-60 kN), which the lightest loads leave. Times are per joint-step
(wall time / joints / steps), the fastest of the repeats (interleaved round-robin); the
ratios of table to full are the median over the repeats of each repeat's own ratio.
"""

from __future__ import annotations

import argparse
import json
import platform
import sys
import time

import numpy as np

import pinjoint

#: The table's envelope: the scene's loads (4-60 kN) and speeds down to 1e-3 rad/s (as the
#: Rust part's; a joint reversing passes below it, where the complete solve answers).
ENVELOPE = (4e3, 60e3, 1e-3, 10.0)


def inputs(n: int, steps: int, seed: int = 30):
    rng = np.random.default_rng(seed)
    amp = rng.uniform(0.05, 0.5, n)
    w = 2 * np.pi * rng.uniform(0.2, 2.0, n)
    p = 5e3 * 10 ** rng.uniform(0.0, 1.0, n)
    rest = rng.uniform(size=n) < 0.1
    frames = []
    for k in range(steps):
        t = 0.37 + 1e-3 * k
        sn, cs = np.sin(w * t), np.cos(w * t)
        frames.append((np.where(rest, 1e-5 * sn, amp * sn), np.where(rest, 0.0, amp * w * cs), p * (1 + 0.2 * sn)))
    return frames


#: The host-driven scenes (as the Rust part's, crates/bench/src/bench_batch.rs): joints of
#: 5-50 kN under a drive r*T_s (T_s the sliding torque at rest), J = 20 kg.m^2, a host damping
#: T_s/2.5 rad/s, integrated explicitly at 1 ms; (name, r range, share reversing, frequency).
SCENES = {
    "held": ((0.3, 0.8), 0.0),
    "creeping": ((0.8, 0.99), 0.0),
    "reversing": ((1.2, 3.0), 1.0),
    "sliding": ((1.6, 3.0), 0.0),
    "mixed": ((0.3, 3.0), 0.5),
}
INERTIA, SPEED, H = 20.0, 2.5, 1e-3


def scene(name: str, n: int, fidelity: str, warm: int, steps: int, seed: int = 39) -> float:
    """ns a joint-step of PreslidingBatch.step (its calls alone) in scene `name`."""
    (r0, r1), reversing = SCENES[name]
    rng = np.random.default_rng(seed)
    p = 5e3 * 10 ** rng.uniform(0.0, 1.0, n)
    r = r0 * (r1 / r0) ** rng.uniform(size=n) if name == "mixed" else rng.uniform(r0, r1, n)
    f = np.where(rng.uniform(size=n) < reversing, rng.uniform(0.5, 2.0, n), 0.0)
    b = pinjoint.PreslidingBatch(n, host_inertia=np.full(n, INERTIA), fidelity=fidelity, envelope=ENVELOPE)
    ts = b.sliding_torque(np.zeros(n), p)
    theta, omega = np.zeros(n), np.zeros(n)
    h = np.full(n, H)
    spent = 0.0
    for k in range(warm + steps):
        t0 = time.perf_counter()
        torque = b.step(theta, omega, p, None, h)
        if k >= warm:
            spent += time.perf_counter() - t0
        shape = np.where(f == 0.0, 1.0, np.sin(2 * np.pi * f * k * H))
        omega = omega + H * (r * ts * shape + torque - ts / SPEED * omega) / INERTIA
        theta = theta + H * omega
    return spent * 1e9 / (n * steps)


def scenes(quick: bool) -> dict:
    n, warm, steps, repeats = (1000, 100, 50, 1) if quick else (2000, 300, 100, 3)
    out = {}
    for name in SCENES:
        full, table, ratios = float("inf"), float("inf"), []
        for _ in range(repeats):
            a = scene(name, n, "full", warm, steps)
            b = scene(name, n, "table", warm, steps)
            full, table = min(full, a), min(table, b)
            ratios.append(b / a)
        out[name] = dict(full_ns=full, table_ns=table, ratio=float(np.median(ratios)), n=n)
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true")
    a = ap.parse_args()
    n, steps, repeats, loop_n = (2000, 5, 1, 200) if a.quick else (10_000, 50, 7, 2000)
    frames = inputs(n, steps)
    joint = pinjoint.Joint()
    full = pinjoint.PreslidingBatch(n)
    table = pinjoint.PreslidingBatch(n, fidelity="table", envelope=ENVELOPE)
    table_default = pinjoint.PreslidingBatch(n, fidelity="table")
    table.step(*frames[0])  # builds the table
    table_default.step(*frames[0])
    full.step(*frames[0])
    objs = [pinjoint.Presliding() for _ in range(loop_n)]
    best = {k: float("inf") for k in ("evaluate", "batch_step", "batch_torque_commit", "batch_table", "batch_table_default", "loop")}
    last = {}

    def timed(key, fn, count):
        t0 = time.perf_counter()
        fn()
        dt = (time.perf_counter() - t0) * 1e9 / count
        best[key] = min(best[key], dt)
        last[key] = dt

    def evaluate():
        for ang, w, p in frames:
            joint.evaluate(p, w)

    def step(b):
        def run():
            for ang, w, p in frames:
                b.step(ang, w, p)
        return run

    def torque_commit():
        for ang, w, p in frames:
            full.torque(ang, w, p)
            full.commit(ang, w, p)

    def loop():
        for ang, w, p in frames:
            al, wl, pl = ang[:loop_n].tolist(), w[:loop_n].tolist(), p[:loop_n].tolist()
            for i, o in enumerate(objs):
                o.torque(al[i], wl[i], pl[i])
                o.commit(al[i], wl[i], pl[i])

    # Warm-up, untimed: each Presliding object's own joint solves the rows of its start table
    # at first use (the batch's shared model did so in its first step above).
    for o, ang, w, p in zip(objs, *(x[:loop_n].tolist() for x in frames[0])):
        o.torque(ang, w, p)
    # Table against full paired within each repeat (measured back to back), the median taken.
    ratios, ratios_default = [], []
    for _ in range(repeats):
        timed("evaluate", evaluate, n * steps)
        timed("batch_step", step(full), n * steps)
        timed("batch_table", step(table), n * steps)
        timed("batch_table_default", step(table_default), n * steps)
        ratios.append(last["batch_table"] / last["batch_step"])
        ratios_default.append(last["batch_table_default"] / last["batch_step"])
        timed("batch_torque_commit", torque_commit, n * steps)
        timed("loop", loop, loop_n * steps)
    out = {f"{k}_ns": v for k, v in best.items()}
    out.update(table_ratio=float(np.median(ratios)), table_default_ratio=float(np.median(ratios_default)))
    out.update(n=n, steps=steps, repeats=repeats, loop_joints=loop_n, numpy=np.__version__, python=platform.python_version())
    out["scenes"] = scenes(a.quick)
    json.dump(out, sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main())
