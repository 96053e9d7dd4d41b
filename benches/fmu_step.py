"""Cost of one FMU co-simulation step through fmpy, per fidelity, against a pass-through FMU.

Run by `pinjoint-bench` (or by hand):
    .venv/bin/python benches/fmu_step.py PinJoint.fmu PassThrough.fmu [--steps N] [--repeats R]

Every configuration is driven by the same loop: set two Real inputs, fmi2DoStep, get two
Real outputs (PinJoint: angular_velocity, load -> torque, friction_coefficient; PassThrough:
u1, u2 -> y1, y2). PinJoint runs with its default zero-velocity model (presliding; the loop
does not set the angle, so angular_velocity * step drives the state) at every fidelity, and
at full fidelity with the band ("full-band"), the stateless law. The inputs follow a 1 Hz, +-40 deg sine stroke at 20 kN +- 10 %, so the
joint sweeps the speeds of the rig. The configurations are interleaved over the repeats
(round-robin) so that drifts of a busy machine touch all alike; the fastest repeat of each is
kept (the least disturbed), the median too, and the paired ratios: the median over the repeats
of two configurations' ratio within one repeat. Prints one JSON object on standard output.

Two more PinJoint configurations at full fidelity set the `temperature` input too, at every
step: "full-fixed-T" to the same 318.15 K each time (the fixed-temperature step), and
"full-warming" to a temperature rising by 1e-3 K per step from 308.15 K (restarting at each
repeat: 308.15-328.15 K over 20000 steps), so every step sees a new temperature. Their
ratio is the cost of a temperature change.
"""

import json
import math
import sys
import time

from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave

FIDELITIES = ["full", "table", "boundary", "auto"]


def load(path):
    md = read_model_description(path)
    unzipdir = extract(path)
    vrs = {v.name: v.valueReference for v in md.modelVariables}
    return md, unzipdir, vrs


def instance(path, md, unzipdir, ints=None, reals=None):
    s = FMU2Slave(guid=md.guid, unzipDirectory=unzipdir, modelIdentifier=md.coSimulation.modelIdentifier, instanceName="bench")
    s.instantiate()
    s.setupExperiment(startTime=0.0)
    if ints:
        s.setInteger(list(ints.keys()), list(ints.values()))
    if reals:
        s.setReal(list(reals.keys()), list(reals.values()))
    s.enterInitializationMode()
    s.exitInitializationMode()
    return s


def main(argv):
    pin, passthrough = argv[0], argv[1]
    steps = int(argv[argv.index("--steps") + 1]) if "--steps" in argv else 20000
    repeats = int(argv[argv.index("--repeats") + 1]) if "--repeats" in argv else 7
    tolerance = float(argv[argv.index("--tolerance") + 1]) if "--tolerance" in argv else 1e-4
    h = 1e-3
    md_p, dir_p, vr_p = load(pin)
    md_t, dir_t, vr_t = load(passthrough)
    configs = {"passthrough": (instance(passthrough, md_t, dir_t), [vr_t["u1"], vr_t["u2"]], [vr_t["y1"], vr_t["y2"]])}
    env = {vr_p["tolerance"]: tolerance, vr_p["envelope.load_min"]: 15e3, vr_p["envelope.load_max"]: 25e3,
           vr_p["envelope.speed_min"]: 1e-3, vr_p["envelope.speed_max"]: 6.0}
    runs = [(name, {vr_p["fidelity"]: code}) for code, name in enumerate(FIDELITIES)]
    runs.append(("full-band", {vr_p["fidelity"]: 0, vr_p["zero_velocity.model"]: 0}))
    for name, ints in runs:
        t0 = time.perf_counter()
        s = instance(pin, md_p, dir_p, ints=ints, reals=env)
        build = time.perf_counter() - t0
        configs[name] = (s, [vr_p["angular_velocity"], vr_p["load"]], [vr_p["torque"], vr_p["friction_coefficient"]])
        configs[name] += (build,)
    s = instance(pin, md_p, dir_p, ints={vr_p["fidelity"]: 0}, reals=env)
    vin_t = [vr_p["angular_velocity"], vr_p["load"], vr_p["temperature"]]
    configs["full-fixed-T"] = (s, vin_t, [vr_p["torque"], vr_p["friction_coefficient"]], None, 318.15, 0.0)
    s = instance(pin, md_p, dir_p, ints={vr_p["fidelity"]: 0}, reals=env)
    configs["full-warming"] = (s, vin_t, [vr_p["torque"], vr_p["friction_coefficient"]], None, 308.15, 1e-3)
    times = {k: [] for k in configs}
    clocks = {k: 0.0 for k in configs}
    # One warm-up pass, then round-robin repeats.
    for rep in range(repeats + 1):
        for name, c in configs.items():
            s, vin, vout = c[0], c[1], c[2]
            # Keep each instance's own clock continuous.
            temperature = (c[4], c[5]) if len(c) > 4 else None
            s_per_step, _ = drive_from(s, vin, vout, steps, h, clocks, name, temperature)
            if rep > 0:
                times[name].append(s_per_step)
    out = {"steps": steps, "repeats": repeats, "step_size": h, "tolerance": tolerance,
           "fmpy": __import__("fmpy").__version__, "python": sys.version.split()[0], "results": {}}
    # Paired ratios: in each repeat every configuration ran within a few seconds of the others
    # (round-robin), so the ratio of two of them in one repeat cancels the machine's slow
    # drifts; the median over the repeats is the estimate (the fastest of each configuration
    # over independent repeats can pair a calm moment of one with a busy moment of another).
    def paired(a, b):
        r = sorted(x / y for x, y in zip(times[a], times[b]))
        return r[len(r) // 2]
    out["paired"] = {name: paired(name, "passthrough") for name in times}
    out["paired_pairs"] = {f"{a}/{b}": paired(a, b) for a, b in
                           [("full", "boundary"), ("full", "full-band"), ("full-warming", "full-fixed-T")]}
    for name, ts in times.items():
        ts = sorted(ts)
        out["results"][name] = {"min_ns": ts[0] * 1e9, "median_ns": ts[len(ts) // 2] * 1e9,
                                "init_s": configs[name][3] if len(configs[name]) > 3 else None}
    for c in configs.values():
        c[0].terminate()
        c[0].freeInstance()
    print(json.dumps(out))


def drive_from(s, vin, vout, n, h, clocks, name, temperature=None):
    """`temperature`: None, or (start K, rise per step K) for a last input."""
    a = math.radians(40.0)
    amp = a * 2.0 * math.pi
    t = clocks[name]
    ins = [(a * math.sin(2.0 * math.pi * (t + k * h)), amp * math.cos(2.0 * math.pi * (t + k * h)), 20e3 * (1.0 + 0.1 * math.sin(0.3 * (t + k * h))))
           for k in range(n)]
    if temperature is not None:
        t0_k, rise = temperature
        ins = [x + (t0_k + rise * k,) for k, x in enumerate(ins)]
    # The loop sets angular_velocity and load (and temperature): drop the angle.
    ins = [x[1:] for x in ins]
    set_real, do_step, get_real = s.setReal, s.doStep, s.getReal
    t0 = time.perf_counter()
    for k in range(n):
        set_real(vin, ins[k])
        do_step(currentCommunicationPoint=t, communicationStepSize=h)
        t += h
        get_real(vout)
    elapsed = time.perf_counter() - t0
    clocks[name] = t
    return elapsed / n, t


if __name__ == "__main__":
    main(sys.argv[1:])
