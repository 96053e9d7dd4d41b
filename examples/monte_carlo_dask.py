#!/usr/bin/env python3
"""Monte Carlo of rig cycles and an operating-point map, on a Dask cluster.

    python examples/monte_carlo_dask.py --samples 200 --output out/mc
    python examples/monte_carlo_dask.py --scheduler tcp://10.0.0.5:8786 --samples 5000 --output out/mc
    python examples/monte_carlo_dask.py --serial --samples 20 --output out/mc-serial

Without --scheduler a LocalCluster of --workers processes is started on this machine; with
it, the same code runs on the remote cluster (its workers need `pip install ./python`, the
same pinjoint version). --serial computes everything in this process, without Dask.

1. Monte Carlo: --samples rig runs (pinjoint.simulate_cycle: --cycles sine strokes of
   +-amplitude at --frequency, from rest), each with its own boundary friction coefficient
   mu_c ~ U(0.10, 0.14), roughness scale s ~ U(0.8, 1.2) applied to every surface height
   (sigma, sigma_b, sigma_s, d_d), inlet viscosity eta_0 = 12.45 mPa.s * exp(N(0, 0.3)) and
   load P ~ U(5, 60) kN, drawn from --seed. For each: the peak and the mean |recorded torque|
   over the strokes after the first (start-up) one.
2. Operating-point map: pinjoint.Joint.evaluate over --map-loads x --map-speeds points
   (5-60 kN x 1e-3-80 rad/s, log-spaced: 800 rpm, the paper's top speed; faster, the film
   at 5 kN passes the diametral clearance, an error: docs/conventions.md), split by load rows into tasks; the Joint travels
   to the workers pickled.

Writes to --output: monte_carlo.csv (inputs and torques of every sample), operating_map.csv,
torque_distribution.png (histograms of peak and mean torque, mean torque against load, the
map's mu) and summary.txt. Numbers are written with repr(), so a Dask run and a serial run
can be compared file for file (they are equal bit for bit: each task is deterministic).
Progress goes to standard error.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np

import pinjoint

MU_C = (0.10, 0.14)
ROUGHNESS_SCALE = (0.8, 1.2)
VISCOSITY_LN_SIGMA = 0.3
LOAD = (5e3, 60e3)
ROUGHNESS_KEYS = ("pin_rms_roughness", "bush_rms_roughness", "summit_height_std", "summit_mean_plane_offset")


def draw_samples(n: int, seed: int) -> list:
    """The Monte Carlo inputs, drawn in the client so that every run sees the same ones."""
    rng = np.random.default_rng(seed)
    mu = rng.uniform(*MU_C, n)
    scale = rng.uniform(*ROUGHNESS_SCALE, n)
    eta = pinjoint.default_params()["lubricant.viscosity"] * np.exp(rng.normal(0.0, VISCOSITY_LN_SIGMA, n))
    load = rng.uniform(*LOAD, n)
    return [
        {"index": i, "mu_c": float(mu[i]), "roughness_scale": float(scale[i]), "viscosity": float(eta[i]), "load": float(load[i])}
        for i in range(n)
    ]


def sample_params(s: dict) -> pinjoint.Params:
    base = pinjoint.default_params()
    values = {"friction.boundary_friction_coefficient": s["mu_c"], "lubricant.viscosity": s["viscosity"]}
    for k in ROUGHNESS_KEYS:
        values[f"surface.{k}"] = base[f"surface.{k}"] * s["roughness_scale"]
    return base.with_values(values)


def rig_task(s: dict, frequency: float, amplitude: float, cycles: int, samples_per_cycle: int) -> dict:
    """One rig run: peak and mean |torque| over the strokes after the first."""
    c = pinjoint.simulate_cycle(
        frequency, amplitude, s["load"], cycles=cycles, samples_per_cycle=samples_per_cycle, params=sample_params(s)
    )
    skip = 1 if cycles >= 2 else 0
    window = c["time"] >= skip / frequency - 1e-9 / frequency
    t, tq = c["time"][window], np.abs(c["torque"][window])
    mean = float(np.sum(0.5 * (tq[1:] + tq[:-1]) * np.diff(t)) / (t[-1] - t[0]))
    return {**s, "peak_torque": float(tq.max()), "mean_torque": mean}


def map_task(joint: pinjoint.Joint, loads: np.ndarray, speeds: np.ndarray) -> dict:
    """One block of map rows."""
    out = joint.evaluate(loads[:, None], speeds[None, :])
    return {k: out[k] for k in ("load", "speed", "friction_coefficient", "torque", "regime")}


def progress(label: str, done: int, total: int) -> None:
    end = "\n" if done == total else ""
    print(f"\r{label}: {done}/{total}", end=end, file=sys.stderr, flush=True)


def compute(args, client=None):
    """Both studies; on `client` (a dask.distributed.Client) or serially when None."""
    samples = draw_samples(args.samples, args.seed)
    amplitude = np.radians(args.amplitude_deg)
    joint = pinjoint.Joint()
    loads = np.geomspace(5e3, 60e3, args.map_loads)
    speeds = np.geomspace(1e-3, 80.0, args.map_speeds)
    blocks = np.array_split(loads, max(1, min(len(loads), args.map_tasks)))
    rig_args = (args.frequency, amplitude, args.cycles, args.samples_per_cycle)
    if client is None:
        mc = []
        for i, s in enumerate(samples):
            mc.append(rig_task(s, *rig_args))
            progress("Monte Carlo", i + 1, len(samples))
        maps = [map_task(joint, b, speeds) for b in blocks]
        progress("map blocks", len(blocks), len(blocks))
    else:
        from dask.distributed import as_completed

        futures = client.map(rig_task, samples, *[[a] * len(samples) for a in rig_args], pure=False)
        joint_f = client.scatter(joint, broadcast=True)
        map_futures = [client.submit(map_task, joint_f, b, speeds, pure=False) for b in blocks]
        for i, _ in enumerate(as_completed(futures)):
            progress("Monte Carlo", i + 1, len(futures))
        mc = client.gather(futures)
        for i, _ in enumerate(as_completed(map_futures)):
            progress("map blocks", i + 1, len(map_futures))
        maps = client.gather(map_futures)
    mc.sort(key=lambda r: r["index"])
    grid = {k: np.concatenate([m[k] for m in maps], axis=0) for k in maps[0]}
    return mc, grid


MC_COLUMNS = ("index", "mu_c", "roughness_scale", "viscosity", "load", "peak_torque", "mean_torque")
MAP_COLUMNS = ("load", "speed", "friction_coefficient", "torque", "regime")


def write_outputs(out: Path, mc: list, grid: dict) -> None:
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "monte_carlo.csv", "w") as f:
        f.write(",".join(MC_COLUMNS) + "\n")
        for r in mc:
            f.write(",".join(repr(r[c]) for c in MC_COLUMNS) + "\n")
    with open(out / "operating_map.csv", "w") as f:
        f.write(",".join(MAP_COLUMNS) + "\n")
        flat = {k: grid[k].ravel() for k in MAP_COLUMNS}
        for i in range(flat["load"].size):
            f.write(",".join(str(flat[c][i]) if c == "regime" else repr(float(flat[c][i])) for c in MAP_COLUMNS) + "\n")
    peak = np.array([r["peak_torque"] for r in mc])
    mean = np.array([r["mean_torque"] for r in mc])
    lines = [f"samples: {len(mc)}"]
    for name, v in (("peak |torque| (N.m)", peak), ("mean |torque| (N.m)", mean)):
        q = np.percentile(v, [5, 50, 95])
        lines.append(f"{name}: mean {v.mean():.6g}, std {v.std():.6g}, 5/50/95 % {q[0]:.6g} / {q[1]:.6g} / {q[2]:.6g}")
    (out / "summary.txt").write_text("\n".join(lines) + "\n")
    plot(out / "torque_distribution.png", mc, peak, mean, grid)


def plot(path: Path, mc: list, peak, mean, grid) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    bins = max(5, min(40, len(mc) // 4))
    ax[0, 0].hist(peak, bins=bins, color="tab:red", alpha=0.8)
    ax[0, 0].set(title="Peak |torque| over the averaged strokes", xlabel="N·m", ylabel="samples")
    ax[0, 1].hist(mean, bins=bins, color="tab:blue", alpha=0.8)
    ax[0, 1].set(title="Mean |torque| over the averaged strokes", xlabel="N·m", ylabel="samples")
    load = np.array([r["load"] for r in mc])
    mu = np.array([r["mu_c"] for r in mc])
    sc = ax[1, 0].scatter(load / 1e3, mean, c=mu, s=12, cmap="viridis")
    fig.colorbar(sc, ax=ax[1, 0], label="μ_c")
    ax[1, 0].set(title="Mean |torque| against load", xlabel="load (kN)", ylabel="N·m")
    im = ax[1, 1].pcolormesh(grid["speed"][0], grid["load"][:, 0] / 1e3, grid["friction_coefficient"], shading="auto")
    ax[1, 1].set_xscale("log")
    fig.colorbar(im, ax=ax[1, 1], label="μ")
    ax[1, 1].set(title="Operating map: friction coefficient (paper's joint)", xlabel="speed (rad/s)", ylabel="load (kN)")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scheduler", metavar="ADDRESS", help="address of a running Dask scheduler (default: a LocalCluster)")
    p.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (default 2)")
    p.add_argument("--threads-per-worker", type=int, default=1)
    p.add_argument("--serial", action="store_true", help="no Dask: compute in this process")
    p.add_argument("--samples", type=int, default=200, help="Monte Carlo rig runs")
    p.add_argument("--seed", type=int, default=2024)
    p.add_argument("--frequency", type=float, default=1.0, help="stroke frequency, Hz")
    p.add_argument("--amplitude-deg", type=float, default=40.0, help="stroke amplitude, degrees (+-)")
    p.add_argument("--cycles", type=int, default=3, help="strokes per run (the first is left out of the statistics)")
    p.add_argument("--samples-per-cycle", type=int, default=1000)
    p.add_argument("--map-loads", type=int, default=56)
    p.add_argument("--map-speeds", type=int, default=400)
    p.add_argument("--map-tasks", type=int, default=8, help="tasks the map is split into")
    p.add_argument("--output", type=Path, default=Path("out/monte_carlo"))
    return p


def main(argv=None) -> int:
    args = parser().parse_args(argv)
    t0 = time.perf_counter()
    if args.serial:
        mc, grid = compute(args)
    else:
        from dask.distributed import Client, LocalCluster

        # Run as a script, the task functions live in __main__ and go to the workers by value
        # (cloudpickle); imported as a module, the workers must be able to import it too.
        if args.scheduler:
            with Client(args.scheduler) as client:
                mc, grid = compute(args, client)
        else:
            with LocalCluster(n_workers=args.workers, threads_per_worker=args.threads_per_worker,
                              processes=True, dashboard_address=None) as cluster, Client(cluster) as client:
                mc, grid = compute(args, client)
    write_outputs(args.output, mc, grid)
    print(f"wrote {args.output}/monte_carlo.csv, operating_map.csv, torque_distribution.png, summary.txt "
          f"in {time.perf_counter() - t0:.1f} s", file=sys.stderr)
    print((args.output / "summary.txt").read_text(), end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
