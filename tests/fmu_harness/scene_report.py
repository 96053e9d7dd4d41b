"""The issue-22 scenes on the PinJoint FMU, measured: prints a Markdown table of hold drift
and displacement, breakaway motion and peak error, reversal counts (drive, motion, sign
changes of omega, chatter) and dither walk, per host and standard (the numbers quoted in
docs/zero-velocity.md).

    .venv/bin/python tests/fmu_harness/scene_report.py [path/to/PinJoint.fmu]
"""

import sys
from pathlib import Path

import scene_host as sh

KN = 1e3


def main(argv):
    fmi2 = Path(argv[0]) if argv else Path(sh.FMI2_PATH)
    fmi3 = fmi2.parent / "fmi3" / fmi2.name
    hosts = [sh.Host("explicit", 1e-3), sh.Host("explicit", 1e-2), sh.Host("implicit", 0.1), sh.Host("me")]
    cases = [(20, 60), (50, 20), (500, 5)]
    print("| FMI | host | J (kg m^2) | load (kN) | hold drift (deg) | hold displacement (deg) | motion below 0.95 T_s (deg) | "
          "breakaway peak error (%) | reversals: drive / motion / sign changes of w / chatter | dither walk (deg) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for label, path in (("2.0", fmi2), ("3.0", fmi3)):
        for host in hosts:
            for J, kn in cases:
                if host.kind == "implicit" and J < 5:
                    continue
                load = kn * KN
                T_s = 0.12 * 0.028 * load

                def joint():
                    if host.kind == "me":
                        return sh.open_me(str(path), model=1, load=load)
                    return sh.open_cosim(str(path), model=1, load=load)

                t_hold = 30.0 if host.kind == "me" else 100.0
                _, hold = sh.hold_scene(joint(), host, J, load, T_s, t_end=t_hold, rise=10.0 if J >= 500 else 0.0)
                _, ramp = sh.ramp_scene(joint(), host, J, load, T_s, rise_time=5.0)
                _, rev = sh.reversal_scene(joint(), host, J, load, T_s, amplitude=2.0,
                                           frequency=0.5 if J <= 50 else 0.2, periods=2)
                _, dither = sh.dither_scene(joint(), host, J, load, T_s, periods=10)
                print(f"| {label} | {host} | {J} | {kn} | {hold['drift_deg']:.1e} | {hold['displacement_deg']:.3f} | "
                      f"{ramp['motion_before_deg']:.3f} | {100 * ramp['peak_error']:+.3f} | "
                      f"{rev['drive_reversals']} / {rev['reversals']} / {rev['sign_changes']} / {rev['chatter']} | "
                      f"{dither['walk_deg']:.1e} |", flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
