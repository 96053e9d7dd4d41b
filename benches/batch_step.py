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
    json.dump(out, sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main())
