#!/usr/bin/env python3
"""The uncertainty of a scene: will the gear lock on a cold day, over the scatter of mu_c and
of the grease between joints and batches?

    python examples/scene_uncertainty.py --samples 10000 --temperature-c -54 --output out/su
    python examples/scene_uncertainty.py --calibration fit.json --samples 10000 --output out/su
    python examples/scene_uncertainty.py --param friction.boundary_friction_coefficient=normal:0.12,0.01 --output out/su
    python examples/scene_uncertainty.py --scheduler tcp://10.0.0.5:8786 --samples 100000 --output out/su
    python examples/scene_uncertainty.py --workers 2 --samples 10000 --output out/su     # a LocalCluster

The cold-day free-fall scene (``pinjoint.scenes.free_fall``: the leg released from up swings
down under gravity against the throttled actuator; its two trunnion pins are presliding joints
of ``pinjoint.PreslidingBatch``) is run for --samples parameter sets drawn from --seed:

* --calibration FILE: the estimates and covariance of a fit (the JSON of
  ``pinjoint calibrate --json`` or of ``pinjoint.calibrate(...).to_json()``), sampled as a
  multivariate normal;
* --param KEY=KIND:A,B (repeatable): any parameter file key, KIND normal (mean, sd),
  lognormal (median or "default", sigma of ln) or uniform (low, high);
* neither: ``pinjoint.scenes.DEFAULT_SCATTER`` (mu_c uniform 0.10-0.14, and the grease's
  yield stress and consistency log-normal, sigma 0.3, where the model has them).

The samples are cut into --chunk scenes a task; without --scheduler or --workers the tasks run
here one after another (each on every core), with --workers on a LocalCluster of that many
processes, with --scheduler on a running Dask cluster (its workers need ``pip install ./python``,
the same pinjoint version). Each task is a function of its inputs alone, so the three give the
same numbers bit for bit.

Writes to --output: samples.csv (every sample's parameters and results, numbers by repr),
summary.txt (percentiles of the time to lock and of the lock margin, the fraction locked by
end_time and with a positive margin), scene_uncertainty.png (their distributions, and the
nominal joint's angle against time at +20, -20, -40 and -54 C where the model takes that
temperature). Progress goes to standard error.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

import pinjoint
from pinjoint import scenes

FIGURE_TEMPERATURES_C = (20.0, -20.0, -40.0, -54.0)


def progress(label: str, done: int, total: int) -> None:
    end = "\n" if done == total else ""
    print(f"\r{label}: {done}/{total}", end=end, file=sys.stderr, flush=True)


def draw(args) -> dict:
    """The samples by key, drawn here (the client) from --seed."""
    calibration = None
    if args.calibration:
        calibration = json.loads(Path(args.calibration).read_text())
    dists = dict(scenes.parse_distribution(p) for p in args.param) if args.param else None
    return scenes.sample_parameters(args.samples, args.seed, calibration=calibration, distributions=dists)


def check_samples(values: dict) -> None:
    """Every sample's parameter set is one the model takes, else a ValueError naming the
    sample's index in the study and the parameter (before any scene runs: a task's error
    would name the joint's index within its task)."""
    base = pinjoint.Params()
    n = len(next(iter(values.values()))) if values else 0
    for i in range(n):
        try:
            base.with_values({k: float(v[i]) for k, v in values.items()})
        except ValueError as e:
            raise ValueError(f"sample {i} of the study: {e} (the distributions drew a value the model does not take)") from None


def chunks(values: dict, size: int) -> list:
    n = len(next(iter(values.values())))
    return [{k: v[a : a + size] for k, v in values.items()} for a in range(0, n, size)]


def compute(args, client=None) -> tuple:
    """(samples by key, results by name), every sample in order; on `client` when given."""
    scene = scenes.FreeFall(end_time=args.end_time, step=args.step)
    temperature = args.temperature_c + 273.15
    values = draw(args)
    check_samples(values)
    parts = chunks(values, args.chunk)
    if client is None:
        results = []
        for i, part in enumerate(parts):
            results.append(scenes.free_fall_chunk(scene, part, temperature, args.fidelity))
            progress("scenes", min((i + 1) * args.chunk, args.samples), args.samples)
    else:
        from dask.distributed import as_completed

        futures = client.map(scenes.free_fall_chunk, [scene] * len(parts), parts, [temperature] * len(parts), [args.fidelity] * len(parts), pure=False)
        for i, _ in enumerate(as_completed(futures)):
            progress("tasks", i + 1, len(futures))
        results = client.gather(futures)
    out = {k: np.concatenate([r[k] for r in results]) for k in results[0]}
    return values, out


def write(args, values: dict, out: dict, seconds: float) -> None:
    d = Path(args.output)
    d.mkdir(parents=True, exist_ok=True)
    keys = list(values)
    cols = ["time_to_lock", "speed_at_lock", "lock_margin", "breakaway_torque", "friction_energy"]
    with open(d / "samples.csv", "w") as f:
        f.write(",".join(["index", *keys, *cols]) + "\n")
        for i in range(args.samples):
            row = [str(i), *(repr(float(values[k][i])) for k in keys), *(repr(float(out[c][i])).replace("nan", "nan") for c in cols)]
            f.write(",".join(row) + "\n")
    t, m = out["time_to_lock"], out["lock_margin"]
    lines = [
        f"The cold-day free-fall scene over {args.samples} parameter samples (seed {args.seed}), "
        f"{args.temperature_c:g} C, step {args.step:g} s, end time {args.end_time:g} s, fidelity {args.fidelity}.",
        f"Sampled keys: {', '.join(keys)}.",
        f"Locked by the end time: {np.mean(out['locked']) * 100:.2f} % of the samples; lock margin > 0: {np.mean(m > 0) * 100:.2f} %.",
        "",
        "percentile  time_to_lock_s  lock_margin",
    ]
    pt, pm = scenes.percentiles(t), scenes.percentiles(m)
    for q in scenes.PERCENTILES:
        lines.append(f"{q:>10g}  {pt[q]!r:>14}  {pm[q]!r}")
    (d / "summary.txt").write_text("\n".join(lines) + "\n")
    print("\n".join(lines), file=sys.stderr)
    print(f"{args.samples} scenes in {seconds:.1f} s", file=sys.stderr)


def figure(args, out: dict) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    t = out["time_to_lock"]
    locked = np.isfinite(t)
    ax[0].hist(t[locked], bins=60, color="tab:blue")
    ax[0].set_xlabel("time to lock (s)")
    ax[0].set_ylabel("samples")
    ax[0].set_title(f"{np.mean(locked) * 100:.1f} % locked by {args.end_time:g} s")
    ax[1].hist(out["lock_margin"], bins=60, color="tab:orange")
    ax[1].axvline(0.0, color="k", lw=0.8)
    ax[1].set_xlabel("lock margin (-)")
    ax[1].set_title(f"at {args.temperature_c:g} C, {args.samples} samples")
    scene = scenes.FreeFall(end_time=args.end_time, step=args.step)
    notes = []
    for tc in FIGURE_TEMPERATURES_C:
        try:
            r = scenes.free_fall(1, scene, temperature=tc + 273.15, fidelity=args.fidelity, record=True)
        except ValueError as e:  # a temperature the installed model does not take
            msg = str(e)
            at = msg.find("lubricant.temperature")
            notes.append(f"{tc:+g} C not run: {msg[at:] if at >= 0 else msg}"[:110])
            continue
        s = r["series"]
        ax[2].plot(s["time"], s["angle"][:, 0], label=f"{tc:+g} C, margin {r['lock_margin'][0]:.2f}")
    ax[2].set_xlabel("time (s)")
    ax[2].set_ylabel("leg angle from down-locked (rad)")
    ax[2].set_title("nominal joint")
    ax[2].legend(fontsize=8)
    if notes:
        ax[2].text(0.02, 0.02, "\n".join(notes), transform=ax[2].transAxes, fontsize=6, va="bottom")
        print("\n".join(notes), file=sys.stderr)
    fig.tight_layout()
    fig.savefig(Path(args.output) / "scene_uncertainty.png", dpi=110)
    plt.close(fig)


def parse(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("--samples", type=int, default=10_000)
    ap.add_argument("--seed", type=int, default=30)
    ap.add_argument("--temperature-c", type=float, default=-54.0, help="the joints' temperature, C (default -54)")
    ap.add_argument("--calibration", help="JSON of a fit (pinjoint calibrate --json): its estimates and covariance")
    ap.add_argument("--param", action="append", default=[], metavar="KEY=KIND:A,B", help="a parameter's distribution (repeatable)")
    ap.add_argument("--end-time", type=float, default=30.0)
    ap.add_argument("--step", type=float, default=1e-3)
    ap.add_argument("--fidelity", default="full", choices=["full", "table", "boundary", "auto"])
    ap.add_argument("--chunk", type=int, default=1000, help="scenes a task (memory: each scene's joint has its own model)")
    ap.add_argument("--scheduler", help="address of a running Dask scheduler")
    ap.add_argument("--workers", type=int, default=0, help="a LocalCluster of this many worker processes (0: run here)")
    ap.add_argument("--output", default="out/scene_uncertainty")
    ap.add_argument("--no-figure", action="store_true")
    a = ap.parse_args(argv)
    if a.samples < 1 or a.chunk < 1:
        ap.error("--samples and --chunk must be >= 1")
    return a


def main(argv=None) -> int:
    args = parse(argv)
    t0 = time.perf_counter()
    if args.scheduler or args.workers:
        from dask.distributed import Client, LocalCluster

        if args.scheduler:
            client, cluster = Client(args.scheduler), None
        else:
            cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None)
            client = Client(cluster)
        try:
            values, out = compute(args, client)
        finally:
            client.close()
            if cluster is not None:
                cluster.close()
    else:
        values, out = compute(args)
    write(args, values, out, time.perf_counter() - t0)
    if not args.no_figure:
        figure(args, out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
