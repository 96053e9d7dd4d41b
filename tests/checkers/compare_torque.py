"""Compare a result CSV written by an external FMU host (Reference-FMUs' fmusim, the FMU
Compliance Checker) with the library, evaluated by `pinjoint sweep` at the same inputs.

Python standard library only (runs before any virtualenv exists).

PinJoint (`--kind joint`): each row's `torque` must equal the FMU's documented law at the
row's own recorded `angular_velocity` ω, `load` P (and `temperature` when recorded):
  |ω| >= ω_b:  -sign(ω) T(P, |ω|)          (relative difference <= --rtol)
  |ω| <  ω_b:  -T(P, ω_b) ω / ω_b          (difference <= --rtol * T(P, ω_b))
  P = 0:       0
with T the library's torque magnitude μ R P (eq. 11) and ω_b the FMU's default speed band.

PinJointRig (`--kind rig`): on every row where the rig slips (`stuck` = 0, ω != 0, P != 0),
`friction_torque` must be -sign(ω) T(P, |ω|) and `friction_coefficient` the library's μ at
the row's (P, |ω|); stuck rows carry the reaction torque, not the friction law, and are counted
but not compared.

Prints one summary line; exits 1 when a row disagrees or nothing could be compared.
"""

import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile


def read_rows(path):
    """The CSV's rows as dicts of floats (fmusim quotes its header, the checker writes %.16E)."""
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        rows = []
        for raw in reader:
            rows.append({k.strip(): float(v) for k, v in raw.items() if k is not None and v not in (None, "")})
    return rows


def library(points, pinjoint, with_temperature):
    """`pinjoint sweep` at each (load, speed[, temperature]) point: list of (μ, T) pairs."""
    with tempfile.TemporaryDirectory() as tmp:
        src = os.path.join(tmp, "in.csv")
        dst = os.path.join(tmp, "out.csv")
        with open(src, "w") as f:
            f.write("load,speed,temperature\n" if with_temperature else "load,speed\n")
            for p in points:
                f.write(",".join(repr(x) for x in p) + "\n")
        subprocess.run([pinjoint, "sweep", "--input", src, "--output", dst], check=True)
        with open(dst, newline="") as f:
            return [(float(r["friction_coefficient"]), float(r["torque"])) for r in csv.DictReader(f)]


def point_of(row, speed, with_temperature):
    p = (abs(row["load"]), speed)
    return p + (row["temperature"],) if with_temperature else p


def compare_joint(rows, pinjoint, band, rtol):
    with_t = "temperature" in rows[0]
    loaded = [r for r in rows if r["load"] != 0.0]
    # Outside the band the model at |ω|; inside it, at the band edge (the ramp's end value).
    pts = [point_of(r, max(abs(r["angular_velocity"]), band), with_t) for r in loaded]
    lib = library(pts, pinjoint, with_t) if pts else []
    out_n = in_n = 0
    out_worst = in_worst = 0.0
    bad = []
    for r, (_, t) in zip(loaded, lib):
        w, got = r["angular_velocity"], r["torque"]
        if abs(w) >= band:
            want = -math.copysign(t, w)
            d = abs(got - want) / abs(want)
            out_n += 1
            out_worst = max(out_worst, d)
        else:
            want = -t * w / band
            d = abs(got - want) / t
            in_n += 1
            in_worst = max(in_worst, d)
        if not d <= rtol:
            bad.append((r.get("time"), w, r["load"], got, want))
    zero = [r for r in rows if r["load"] == 0.0 and r["torque"] != 0.0]
    ok = not bad and not zero and out_n > 0
    summary = (f"{out_n} rows outside the band, largest relative difference {out_worst:.3g}; "
               f"{in_n} inside (difference / T(P, band) {in_worst:.3g})")
    return ok, summary, bad[:5] + [("zero load", r) for r in zero[:5]]


def compare_rig(rows, pinjoint, rtol):
    with_t = "temperature" in rows[0]
    slipping = [r for r in rows if r["stuck"] == 0.0 and r["angular_velocity"] != 0.0 and r["load"] != 0.0]
    stuck = sum(1 for r in rows if r["stuck"] != 0.0)
    lib = library([point_of(r, abs(r["angular_velocity"]), with_t) for r in slipping], pinjoint, with_t) if slipping else []
    worst_t = worst_mu = 0.0
    bad = []
    for r, (mu, t) in zip(slipping, lib):
        want = -math.copysign(t, r["angular_velocity"])
        dt = abs(r["friction_torque"] - want) / abs(want)
        dmu = abs(r["friction_coefficient"] - mu) / mu
        worst_t, worst_mu = max(worst_t, dt), max(worst_mu, dmu)
        if not (dt <= rtol and dmu <= rtol):
            bad.append((r.get("time"), r["angular_velocity"], r["load"], r["friction_torque"], want))
    ok = not bad and len(slipping) > 0
    summary = (f"{len(slipping)} slipping rows, largest relative difference: friction_torque "
               f"{worst_t:.3g}, friction_coefficient {worst_mu:.3g}; {stuck} stuck rows (not compared)")
    return ok, summary, bad[:5]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv", help="result CSV of the external host")
    ap.add_argument("--kind", choices=["joint", "rig"], required=True)
    ap.add_argument("--label", default="")
    ap.add_argument("--pinjoint", required=True, help="path to the `pinjoint` binary")
    ap.add_argument("--band", type=float, default=0.01, help="PinJoint's zero_velocity.speed_band (rad/s)")
    ap.add_argument("--rtol", type=float, default=1e-12)
    a = ap.parse_args()
    rows = read_rows(a.csv)
    if not rows:
        print(f"{a.label}: FAIL, {a.csv} has no rows")
        return 1
    if a.kind == "joint":
        ok, summary, bad = compare_joint(rows, a.pinjoint, a.band, a.rtol)
    else:
        ok, summary, bad = compare_rig(rows, a.pinjoint, a.rtol)
    print(f"{a.label}: {'agrees' if ok else 'FAIL'} with the library (rtol {a.rtol:g}): {summary}")
    for b in bad:
        print(f"  disagreement (time, omega, load, got, want): {b}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
