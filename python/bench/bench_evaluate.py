#!/usr/bin/env python3
"""Points per second of pinjoint.Joint.evaluate against a SciPy-style per-point loop of the
same model (reference_model.py) and against the CLI (`pinjoint sweep`), in one run.

    .venv-python/bin/python python/bench/bench_evaluate.py [--points 1000000] [--loop-points 300]

The per-point loop is first checked to agree with evaluate to 1e-9 (relative) on the points
it times; it is too slow to run 1e6 points (tens of ms a point), so its rate is measured on
--loop-points of the same points. The CLI is timed end to end on a CSV of all the points
(parse, evaluate on every core, write). Every figure is from this one run on this machine;
the ratios are what to quote.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import pinjoint

sys.path.insert(0, str(Path(__file__).resolve().parent))
from reference_model import ReferenceJoint  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--points", type=int, default=1_000_000)
    ap.add_argument("--loop-points", type=int, default=300)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cli", type=Path, default=Path(os.environ.get("PINJOINT_CLI", ROOT / "target/release/pinjoint")))
    a = ap.parse_args()

    rng = np.random.default_rng(a.seed)
    loads = np.exp(rng.uniform(np.log(1e3), np.log(1e5), a.points))
    speeds = rng.choice([-1.0, 1.0], a.points) * np.exp(rng.uniform(np.log(1e-3), np.log(1e3), a.points))
    joint = pinjoint.Joint()
    print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}", flush=True)

    joint.evaluate(loads[:1000], speeds[:1000])  # warm-up (the F_3/2 table, the thread pool)
    t0 = time.perf_counter()
    out = joint.evaluate(loads, speeds)
    t_eval = time.perf_counter() - t0
    rate_eval = a.points / t_eval
    print(f"pinjoint.Joint.evaluate: {a.points} points in {t_eval:.3f} s = {rate_eval:.4g} points/s", flush=True)

    ref = ReferenceJoint()
    k = min(a.loop_points, a.points)
    t0 = time.perf_counter()
    rows = [ref.point(float(l), float(w)) for l, w in zip(loads[:k], speeds[:k])]
    t_loop = time.perf_counter() - t0
    worst = 0.0
    for name in pinjoint.RESULT_COLUMNS[:-1]:
        r = np.array([row[name] for row in rows])
        worst = max(worst, float(np.max(np.abs(out[name][:k] - r) / np.maximum(np.abs(r), 1e-300))))
    if worst > 1e-9:
        print(f"the per-point loop disagrees with evaluate by {worst:.3g} (relative): not timing it", file=sys.stderr)
        return 1
    rate_loop = k / t_loop
    print(f"SciPy per-point loop: {k} points in {t_loop:.3f} s = {rate_loop:.4g} points/s "
          f"(agrees with evaluate to {worst:.2g} relative; 1e6 points would take {1e6 / rate_loop:.0f} s)", flush=True)

    rate_cli = None
    if a.cli.exists():
        with tempfile.TemporaryDirectory() as d:
            src, dst = Path(d) / "in.csv", Path(d) / "out.csv"
            with open(src, "w") as f:
                f.write("load,speed\n")
                f.writelines(f"{l!r},{w!r}\n" for l, w in zip(loads.tolist(), speeds.tolist()))
            t0 = time.perf_counter()
            subprocess.run([str(a.cli), "sweep", "--input", str(src), "--output", str(dst)], check=True,
                           stderr=subprocess.DEVNULL)
            t_cli = time.perf_counter() - t0
        rate_cli = a.points / t_cli
        print(f"pinjoint sweep (CLI, CSV in and out): {a.points} points in {t_cli:.3f} s = {rate_cli:.4g} points/s", flush=True)
    else:
        print(f"no CLI at {a.cli} (cargo build --release --bin pinjoint): CLI not timed", flush=True)

    print(f"ratio evaluate / SciPy per-point loop: {rate_eval / rate_loop:.4g}")
    if rate_cli:
        print(f"ratio evaluate / CLI sweep: {rate_eval / rate_cli:.4g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
