"""Compare what tests/platforms/host.c printed on each platform with the native reference
run and with the library (tests/platforms/run.sh calls this).

    python3 compare.py --reference native.txt --library <reference_points binary> \
        linux64=linux64.txt win64=win64.txt aarch64-linux=aarch64.txt

For every platform: the same result lines as the reference, both checks passed
(NaN input refused, forced panic contained), and

- PinJoint, every output, against the reference run: relative difference at most
  --pinjoint-rel (1e-12) where |omega| is outside the zero-speed band (the "default" and
  "mu011_band0" cases set zero_velocity.model = band; the default band 0.01 rad/s for
  "default", every point for "mu011_band0", whose band is off); the largest difference
  inside the band is printed too;
- PinJoint case "presliding" (the default zero-velocity model, the state carried from point
  to point): the outputs the zero-velocity model does not touch as above, at every point;
  torque, power_loss and dissipated_energy, which carry the history, at most --pinjoint-rel
  of the output's peak |value| over the case (as for the rig below);
- PinJoint torque and the other model outputs at fidelity 0 (full), default parameters,
  outside the band, against the library (examples/reference_points), at the same bound;
- PinJointRig, every output, against the reference run: at most --rig-rel of the output's
  peak |value| over the run (the rig integrates with error control over the whole run, so
  the last-bit differences of the C runtimes' exp/log/pow may grow with time; and outputs
  that pass through zero, such as the commanded angle, have no meaningful pointwise
  relative difference there).

Relative difference: |a - b| / max(|a|, |b|), 0 when a == b. Prints the largest of each
kind per platform; exits 1 when any bound is exceeded or a line is missing.
"""

import argparse
import subprocess
import sys

PJ_OUTPUTS = ["torque", "friction_coefficient", "film_thickness", "lambda_ratio", "fluid_load_fraction",
              "asperity_load_fraction", "mean_pressure", "sommerfeld_number", "power_loss", "dissipated_energy"]
RIG_OUTPUTS = ["angle", "angular_velocity", "torque", "friction_torque", "friction_coefficient", "film_thickness",
               "fluid_load_fraction", "commanded_angle", "actuator_work", "friction_dissipation", "kinetic_energy",
               "stuck"]
# Library columns (examples/reference_points) holding the FMU's outputs of the same name;
# the FMU's torque is the library's signed torque.
LIBRARY_COLUMNS = {"torque": "signed_torque", "friction_coefficient": "friction_coefficient",
                   "film_thickness": "film_thickness", "lambda_ratio": "lambda_ratio",
                   "fluid_load_fraction": "fluid_load_fraction", "asperity_load_fraction": "asperity_load_fraction",
                   "mean_pressure": "mean_pressure", "sommerfeld_number": "sommerfeld_number"}
DEFAULT_BAND = 0.01  # rad/s, zero_velocity.speed_band
# Outputs of the presliding case that carry the state's history.
PRESLIDING_HISTORY = {"torque", "power_loss", "dissipated_energy"}
CHECKS = {"nan_input_refused", "panic_contained"}


def rel(a, b):
    if a == b:
        return 0.0
    return abs(a - b) / max(abs(a), abs(b))


def parse(path):
    """{key: values} for the PinJoint and PinJointRig lines, and the set of checks passed."""
    pj, rig, checks = {}, {}, set()
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "PinJoint":
                fid, case, load, omega = int(w[1]), w[2], float(w[3]), float(w[4])
                vals = [float(x) for x in w[5:]]
                assert len(vals) == len(PJ_OUTPUTS), f"{path}: {line!r}"
                pj[(fid, case, load, omega)] = vals
            elif w[0] == "PinJointRig":
                vals = [float(x) for x in w[4:]]
                assert len(vals) == len(RIG_OUTPUTS), f"{path}: {line!r}"
                rig[(int(w[1]), int(w[2]), float(w[3]))] = vals
            elif w[0] == "check" and w[2:] == ["ok"]:
                checks.add(w[1])
            else:
                raise SystemExit(f"{path}: unexpected line {line!r}")
    return pj, rig, checks


def library(binary, points):
    """The library's outputs at the (load, omega) points, by column name."""
    text = "".join(f"{p[0]!r},{p[1]!r}\n" for p in points)
    out = subprocess.run([binary], input=text, capture_output=True, text=True, check=True).stdout.splitlines()
    head = out[0].split(",")
    return {p: dict(zip(head, map(float, row.split(",")))) for p, row in zip(points, out[1:])}


def outside_band(key):
    fid, case, load, omega = key
    band = 0.0 if case in ("mu011_band0", "presliding") else DEFAULT_BAND
    return abs(omega) >= band


class Worst:
    """Largest relative difference seen, and where."""

    def __init__(self):
        self.value, self.where = 0.0, "-"

    def see(self, d, where):
        if d > self.value:
            self.value, self.where = d, where

    def __str__(self):
        return f"{self.value:.3g} ({self.where})" if self.value > 0 else "0 (bit-identical)"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--reference", required=True, help="output of the native host on the native build")
    ap.add_argument("--library", required=True, help="the reference_points example binary")
    ap.add_argument("--pinjoint-rel", type=float, default=1e-12)
    ap.add_argument("--rig-rel", type=float, default=1e-9)
    ap.add_argument("platforms", nargs="+", help="name=output file")
    a = ap.parse_args()

    ref_pj, ref_rig, ref_checks = parse(a.reference)
    failures = []
    if ref_checks != CHECKS:
        failures.append(f"reference: checks passed {sorted(ref_checks)}, expected {sorted(CHECKS)}")
    pre_peak = {}  # output index: largest |value| of the reference run's presliding case
    for key, ref in ref_pj.items():
        if key[1] == "presliding":
            for i, y in enumerate(ref):
                pre_peak[i] = max(pre_peak.get(i, 0.0), abs(y))
    rig_peak = {}  # (fidelity, output index): largest |value| of the reference run
    for key, ref in ref_rig.items():
        for i, y in enumerate(ref):
            rig_peak[(key[0], i)] = max(rig_peak.get((key[0], i), 0.0), abs(y))
    # The library refuses a zero load (the FMU defines it as an unloaded joint): compare the rest.
    lib_keys = [k for k in ref_pj if k[0] == 0 and k[1] == "default" and outside_band(k) and k[2] != 0.0]
    lib = library(a.library, [(k[2], k[3]) for k in lib_keys])
    runs = [("native", a.reference)] + [tuple(p.split("=", 1)) for p in a.platforms]
    print(f"{'platform':<16} {'PinJoint vs native, outside band':<52} {'inside band':<40} "
          f"{'PinJoint vs library':<48} {'presliding history (of peak)':<44} PinJointRig vs native (of peak)")
    for name, path in runs:
        pj, rig, checks = parse(path)
        if checks != CHECKS:
            failures.append(f"{name}: checks passed {sorted(checks)}, expected {sorted(CHECKS)}")
        if set(pj) != set(ref_pj) or set(rig) != set(ref_rig):
            failures.append(f"{name}: {len(pj)} PinJoint and {len(rig)} PinJointRig lines, "
                            f"expected {len(ref_pj)} and {len(ref_rig)} with the same inputs")
            continue
        out_band, in_band, vs_lib, vs_rig, history = Worst(), Worst(), Worst(), Worst(), Worst()
        for key, ref in ref_pj.items():
            worst = out_band if outside_band(key) else in_band
            for i, (out, x, y) in enumerate(zip(PJ_OUTPUTS, pj[key], ref)):
                where = f"{out} at fid {key[0]} {key[1]} P={key[2]:g} w={key[3]:g}"
                if key[1] == "presliding" and out in PRESLIDING_HISTORY:
                    if x != y:
                        history.see(abs(x - y) / (pre_peak[i] or 1.0), where)
                else:
                    worst.see(rel(x, y), where)
        for key in lib_keys:
            for out, col in LIBRARY_COLUMNS.items():
                x = pj[key][PJ_OUTPUTS.index(out)]
                vs_lib.see(rel(x, lib[(key[2], key[3])][col]), f"{out} P={key[2]:g} w={key[3]:g}")
        for key, ref in ref_rig.items():
            for i, (out, x, y) in enumerate(zip(RIG_OUTPUTS, rig[key], ref)):
                if x != y:
                    vs_rig.see(abs(x - y) / (rig_peak[(key[0], i)] or 1.0), f"{out} fid {key[0]} t={key[2]:g}")
        print(f"{name:<16} {str(out_band):<52} {str(in_band):<40} {str(vs_lib):<48} {str(history):<44} {vs_rig}")
        if out_band.value > a.pinjoint_rel:
            failures.append(f"{name}: PinJoint differs from the native run by {out_band} > {a.pinjoint_rel:g}")
        if history.value > a.pinjoint_rel:
            failures.append(f"{name}: PinJoint (presliding) differs from the native run by {history} of peak > {a.pinjoint_rel:g}")
        if vs_lib.value > a.pinjoint_rel:
            failures.append(f"{name}: PinJoint differs from the library by {vs_lib} > {a.pinjoint_rel:g}")
        if vs_rig.value > a.rig_rel:
            failures.append(f"{name}: PinJointRig differs from the native run by {vs_rig} > {a.rig_rel:g}")
    n_out = sum(outside_band(k) for k in ref_pj)
    print(f"({len(ref_pj)} PinJoint points, {n_out} outside the band, {len(lib_keys)} against the library; "
          f"{len(ref_rig)} PinJointRig steps)")
    for f in failures:
        print("FAIL:", f, file=sys.stderr)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
