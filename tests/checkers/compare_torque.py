"""Compare a result CSV written by an external FMU host (Reference-FMUs' fmusim, the FMU
Compliance Checker) with the library, evaluated by `pinjoint sweep` at the same inputs.

Python standard library only (runs before any virtualenv exists).

PinJoint (`--kind joint`): each row's `torque` must equal the FMU's documented law at the
row's own recorded `angular_velocity` ω, `load` P (and `temperature` when recorded):
  |ω| >= ω_b:  -sign(ω) T(P, |ω|)          (relative difference <= --rtol)
  |ω| <  ω_b:  -T(P, ω_b) ω / ω_b          (difference <= --rtol * T(P, ω_b))
  P = 0:       0
with T the library's torque magnitude μ R P (eq. 11) and ω_b the FMU's default speed band.
These are the band's rows (the hosts set zero_velocity.model = band).

PinJoint with the default zero-velocity model (`--kind joint-presliding`, the presliding state,
driven by ω): on every loaded row |torque| <= T(P, |ω|) (the sliding torque: the damping is
capped there; defaults t_d = 0.01 s, φ_s = 1.5e-3 rad) and the
torque never drives the motion in sliding; in steady sliding, i.e. after 2° of travel since
the last reversal (the travel ∫|ω|dt integrated from the rows by the trapezoidal rule) on rows
whose travel since the previous row is at least 40 (1 - β) φ_s = 3e-3 rad (over which the state
settles on a sliding torque that moves with ω), torque = -sign(ω) T(P, |ω|) within --rtol.
With --state (Model Exchange: the host's integrator owns the state, whose error the damping
term amplifies by t_d |ω| / ((1 - β) φ_s), about 100 at 0.8 rad/s) the rows must record
`presliding_torque` τ, and every loaded row's torque must instead be the law's at the recorded
state, -(clamp(τ, ±T) + t_d (T/φ_s) ω max(g, 0)), g = 1 for s τ <= β T, else
(T - s τ)/(T - β T), s = sign(ω), within --rtol of T.

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


PRESLIDING_ANGLE, DAMPING_TIME, ELASTIC_LIMIT = 1.5e-3, 0.01, 0.95


def presliding_torque(tau, w, t):
    """The presliding law's torque at the state tau, speed w and sliding torque t (> 0)."""
    held = max(-t, min(t, tau))
    if w == 0.0:
        return -held
    u = tau if w > 0 else -tau
    g = 1.0 if u <= ELASTIC_LIMIT * t else (t - u) / (t - ELASTIC_LIMIT * t)
    if g <= 0.0:
        return -held
    # The damping adds to the held torque up to the sliding torque.
    return -max(-t, min(t, held + DAMPING_TIME * (t / PRESLIDING_ANGLE) * w * min(g, 1.0)))


def compare_joint_presliding(rows, pinjoint, rtol, state):
    with_t = "temperature" in rows[0]
    loaded = [r for r in rows if r["load"] != 0.0]
    lib = library([point_of(r, abs(r["angular_velocity"]), with_t) for r in loaded], pinjoint, with_t) if loaded else []
    travel, last, sign = 0.0, None, 0.0
    steady_n, worst, bad = 0, 0.0, []
    for r, (_, t) in zip(loaded, lib):
        w, got = r["angular_velocity"], r["torque"]
        step = 0.0 if last is None else 0.5 * (abs(w) + abs(last["angular_velocity"])) * (r["time"] - last["time"])
        s = math.copysign(1.0, w) if w != 0.0 else sign
        if s != sign:
            travel, sign = 0.0, s
        travel += step
        last = r
        bound = t  # never beyond the sliding torque (the damping is capped there)
        if not abs(got) <= bound * (1.0 + 1e-12):
            bad.append((r.get("time"), w, r["load"], got, f"beyond the bound {bound!r}"))
        if state:
            want = presliding_torque(r["presliding_torque"], w, t)
            d = abs(got - want) / t
            worst = max(worst, d)
            if not d <= rtol:
                bad.append((r.get("time"), w, r["load"], got, want))
        if travel >= math.radians(2.0):
            if got * w > 0.0:
                bad.append((r.get("time"), w, r["load"], got, "drives the motion in sliding"))
            if state:
                steady_n += 1
            elif step >= 40 * (1 - ELASTIC_LIMIT) * PRESLIDING_ANGLE:
                want = -math.copysign(t, w)
                d = abs(got - want) / abs(want)
                steady_n += 1
                worst = max(worst, d)
                if not d <= rtol:
                    bad.append((r.get("time"), w, r["load"], got, want))
    zero = [r for r in rows if r["load"] == 0.0 and r["torque"] != 0.0]
    ok = not bad and not zero and steady_n > 0
    against = "the law at the recorded state, every row" if state else "the library in steady sliding"
    summary = (f"{len(loaded)} loaded rows within the presliding bound; {steady_n} in steady sliding; "
               f"against {against}: largest relative difference {worst:.3g}")
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
    ap.add_argument("--kind", choices=["joint", "joint-presliding", "rig"], required=True)
    ap.add_argument("--label", default="")
    ap.add_argument("--pinjoint", required=True, help="path to the `pinjoint` binary")
    ap.add_argument("--band", type=float, default=0.01, help="PinJoint's zero_velocity.speed_band (rad/s)")
    ap.add_argument("--rtol", type=float, default=1e-12)
    ap.add_argument("--state", action="store_true", help="joint-presliding: check against the law at the recorded presliding_torque (Model Exchange)")
    a = ap.parse_args()
    rows = read_rows(a.csv)
    if not rows:
        print(f"{a.label}: FAIL, {a.csv} has no rows")
        return 1
    if a.kind == "joint":
        ok, summary, bad = compare_joint(rows, a.pinjoint, a.band, a.rtol)
    elif a.kind == "joint-presliding":
        ok, summary, bad = compare_joint_presliding(rows, a.pinjoint, a.rtol, a.state)
    else:
        ok, summary, bad = compare_rig(rows, a.pinjoint, a.rtol)
    print(f"{a.label}: {'agrees' if ok else 'FAIL'} with the library (rtol {a.rtol:g}): {summary}")
    for b in bad:
        print(f"  disagreement (time, omega, load, got, want): {b}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
