#!/usr/bin/env python3
"""Drive the PinJoint FMU the way a system-level model would: a side-stay pin
during gear retraction.

The side-stay unlocks and folds through 100 degrees in 6 s with a smooth
(cosine) angle profile, holds, then extends back; the radial load on the pin
falls from 45 kN (gear weight and drag at the start of the stroke) to 12 kN as
the gear swings up, and rises again on extension. The FMU gets angle, angular
velocity and load at every 1 ms communication step and returns the friction
torque the actuator has to overcome.

    cargo run --release -p fmu_build
    .venv/bin/python examples/fmu_retraction.py [path/to/PinJoint.fmu]

Writes out/fmu_retraction.csv and, if matplotlib is installed,
out/fmu_retraction.png (torque and speed against time).
"""

import sys
from pathlib import Path

import numpy as np
from fmpy import simulate_fmu

ROOT = Path(__file__).resolve().parents[1]
FMU = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "target" / "fmu" / "PinJoint.fmu"
OUT = ROOT / "out"

STROKE = np.radians(100.0)  # rad
T_MOVE, T_HOLD = 6.0, 2.0   # s
STOP = 2 * T_MOVE + T_HOLD


def profile(t):
    """Angle (rad), angular velocity (rad/s) and load (N) at times t."""
    up = np.clip(t / T_MOVE, 0.0, 1.0)
    down = np.clip((t - T_MOVE - T_HOLD) / T_MOVE, 0.0, 1.0)
    s = 0.5 * (1 - np.cos(np.pi * up)) - 0.5 * (1 - np.cos(np.pi * down))
    ds = (np.pi / (2 * T_MOVE)) * (np.sin(np.pi * up) * (t < T_MOVE)
                                    - np.sin(np.pi * down) * (t > T_MOVE + T_HOLD))
    load = 45e3 - 33e3 * s
    return STROKE * s, STROKE * ds, load


def main():
    t = np.arange(0.0, STOP + 1e-9, 1e-3)
    angle, omega, load = profile(t)
    signal = np.zeros(len(t), dtype=[("time", float), ("angle", float), ("angular_velocity", float), ("load", float)])
    signal["time"], signal["angle"], signal["angular_velocity"], signal["load"] = t, angle, omega, load

    result = simulate_fmu(str(FMU), stop_time=STOP, output_interval=1e-3, input=signal,
                          output=["angle", "angular_velocity", "load", "torque", "friction_coefficient",
                                  "power_loss", "dissipated_energy"])
    OUT.mkdir(exist_ok=True)
    np.savetxt(OUT / "fmu_retraction.csv", result, delimiter=",", header=",".join(result.dtype.names), comments="")
    peak = np.max(np.abs(result["torque"]))
    print(f"peak friction torque {peak:.1f} N.m, energy dissipated {result['dissipated_energy'][-1]:.1f} J "
          f"-> {OUT / 'fmu_retraction.csv'}")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not installed: no plot")
        return
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(8, 6))
    ax1.plot(result["time"], result["torque"], label="friction torque on the pin")
    ax1.set_ylabel("torque (N·m)")
    ax1.grid(True)
    ax1.legend()
    ax2.plot(result["time"], np.degrees(result["angular_velocity"]), label="angular velocity (deg/s)")
    ax2.plot(result["time"], result["load"] / 1e3, label="load (kN)")
    ax2.set_xlabel("time (s)")
    ax2.grid(True)
    ax2.legend()
    fig.suptitle("PinJoint FMU: side-stay retraction and extension")
    fig.tight_layout()
    fig.savefig(OUT / "fmu_retraction.png", dpi=100)
    print(f"plot -> {OUT / 'fmu_retraction.png'}")


if __name__ == "__main__":
    main()
