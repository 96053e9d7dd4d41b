#!/usr/bin/env python3
"""A body on the pin: how a system simulation couples PinJoint to an inertia.

A rigid body (J = 50 kg m^2) turns on the pin under 20 kN; the host integrates

    J dw/dt = T_d(t) + torque,     d angle/dt = w

with symplectic Euler at h = 1 ms, holding the FMU's torque over each step and feeding
it the angle and angular velocity at each step start (the presliding state of the
zero-velocity model is driven by the angle input's increments). The drive:
  0 - 20 s   hold at 0.5 T_s (T_s = mu_c R P, the breakaway torque): the joint must stay put;
 20 - 30 s   ramp to 1.5 T_s: breakaway near T_s;
 30 - 40 s   a sine of 2 T_s at 0.5 Hz: the joint reverses at every half-period.

    cargo run --release -p fmu_build
    .venv/bin/python examples/fmu_host_inertia.py [path/to/PinJoint.fmu] [--band]

--band runs today's zero-speed band law instead (zero_velocity.model = 0), which creeps
under the hold. Prints the angle moved during the hold, the breakaway torque and the
reversals; plots angle, speed and torque if matplotlib is installed (out/fmu_host_inertia.png).
"""

import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
args = [a for a in sys.argv[1:] if not a.startswith("--")]
FMU = Path(args[0]) if args else ROOT / "target" / "fmu" / "PinJoint.fmu"
BAND = "--band" in sys.argv

J, LOAD, H = 50.0, 20e3, 1e-3        # kg m^2, N, s
T_HOLD, T_RAMP, T_END = 20.0, 30.0, 40.0


def main():
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave
    from fmpy.fmi3 import FMU3Slave

    md = read_model_description(str(FMU))
    var = {v.name: v for v in md.modelVariables}
    fmi3 = md.fmiVersion.startswith("3")
    T_s = float(var["friction.boundary_friction_coefficient"].start) * float(var["geometry.pin_radius"].start) * LOAD

    def drive(t):
        if t < T_HOLD:
            return 0.5 * T_s
        if t < T_RAMP:
            return 0.5 * T_s + (t - T_HOLD) / (T_RAMP - T_HOLD) * 1.0 * T_s
        return 2.0 * T_s * math.sin(2 * math.pi * 0.5 * (t - T_RAMP) + math.asin(0.75))

    kw = dict(guid=md.guid, unzipDirectory=extract(str(FMU)), modelIdentifier=md.coSimulation.modelIdentifier,
              instanceName="body")
    fmu = (FMU3Slave if fmi3 else FMU2Slave)(**kw)
    fmu.instantiate()
    if fmi3:
        fmu.enterInitializationMode(startTime=0.0)
    else:
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
    set_real = fmu.setFloat64 if fmi3 else fmu.setReal
    get_real = fmu.getFloat64 if fmi3 else fmu.getReal
    model = var.get("zero_velocity.model")
    if model is not None:
        value = 0 if BAND else 1
        (fmu.setInt64 if fmi3 else fmu.setInteger)([model.valueReference], [value])
        print(f"zero_velocity.model = {value} ({'band' if BAND else 'presliding'})")
    else:
        print("this FMU has no zero_velocity.model: it runs the band law (expect creep under the hold)")
    vr = {n: var[n].valueReference for n in ("angle", "angular_velocity", "load", "torque")}
    set_real([vr["load"]], [LOAD])
    fmu.exitInitializationMode()

    n = int(round(T_END / H))
    t = np.arange(n + 1) * H
    angle, omega, torque = np.zeros(n + 1), np.zeros(n + 1), np.zeros(n + 1)
    for i in range(n):
        set_real([vr["angle"], vr["angular_velocity"], vr["load"]], [angle[i], omega[i], LOAD])
        torque[i] = get_real([vr["torque"]])[0]
        fmu.doStep(t[i], H)
        omega[i + 1] = omega[i] + H * (drive(t[i]) + torque[i]) / J
        angle[i + 1] = angle[i] + H * omega[i + 1]
    torque[n] = torque[n - 1]
    fmu.terminate()
    fmu.freeInstance()

    hold = t <= T_HOLD
    settle = (t >= T_HOLD / 2) & hold
    ramp = (t > T_HOLD) & (t <= T_RAMP)
    moving = ramp & (omega > 1e-3)
    t_break = t[np.argmax(moving)] if moving.any() else math.nan
    drive_at_break = drive(t_break) if moving.any() else math.nan
    s = np.sign(omega[(t > T_RAMP) & (np.abs(omega) > 1e-9)])
    print(f"T_s = {T_s:.1f} N.m at {LOAD / 1e3:g} kN, J = {J:g} kg m^2, h = {H * 1e3:g} ms")
    print(f"hold at 0.5 T_s: moved {math.degrees(np.max(np.abs(angle[hold]))):.4f} deg, "
          f"{math.degrees(angle[settle][-1] - angle[settle][0]):.2e} deg in the last {T_HOLD / 2:g} s")
    print(f"breakaway: w > 1e-3 rad/s at t = {t_break:.3f} s, drive {drive_at_break / T_s:.3f} T_s; "
          f"peak |torque| before {T_RAMP:g} s = {np.max(np.abs(torque[t <= T_RAMP])) / T_s:.4f} T_s")
    print(f"sine of 2 T_s, 5 half-periods: {int(np.sum(s[1:] != s[:-1]))} sign changes of w "
          f"(|w| < 1e-9 rad/s counts as zero)")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(3, 1, sharex=True, figsize=(8, 7))
    ax[0].plot(t, np.degrees(angle))
    ax[0].set_ylabel("angle (deg)")
    ax[1].plot(t, omega)
    ax[1].set_ylabel("w (rad/s)")
    ax[2].plot(t, torque, label="joint torque")
    ax[2].plot(t, [drive(x) for x in t], label="drive")
    ax[2].set_ylabel("torque (N.m)")
    ax[2].set_xlabel("t (s)")
    ax[2].legend()
    out = ROOT / "out"
    out.mkdir(exist_ok=True)
    fig.savefig(out / "fmu_host_inertia.png", dpi=100)
    print(f"-> {out / 'fmu_host_inertia.png'}")


if __name__ == "__main__":
    main()
