"""Step-size convergence of the host-inertia scenes (issue 22): prints a Markdown table.

J = 50 kg m^2, P = 20 kN. Scenes: breakaway under a ramp (T_s / 5 s up to 1.5 T_s):
breakaway time (w >= 1e-3 rad/s for good) and peak |torque| up to the drive reaching 1.1 T_s;
reversals under 2 T_s sin(2 pi 0.5 t) for 2 periods: the times of the three reversals of
motion (extrema of the angle beyond the 0.5 deg hysteresis); hold (0.5 T_s, 100 s):
displacement. Hosts: explicit h = 10, 5, 2, 1, 0.5 ms; linearly implicit h = 100, 50,
10 ms; the reference is Model Exchange with SciPy's BDF at rtol 1e-6 (Jacobian from the
directional derivatives). Differences are to the reference.

    .venv/bin/python tests/fmu_harness/step_convergence.py [path/to/PinJoint.fmu] [--reference]

--reference runs the Python reference law (presliding_reference.py) instead of the FMU.
"""

import sys

import numpy as np

import presliding_reference as pr
import scene_host as sh

J, LOAD = 50.0, 20e3
HOSTS = ([sh.Host("explicit", h) for h in (10e-3, 5e-3, 2e-3, 1e-3, 0.5e-3)]
         + [sh.Host("implicit", h) for h in (0.1, 0.05, 0.01)])


def measure(make, host, T_s):
    _, ramp = sh.ramp_scene(make(host), host, J, LOAD, T_s, rise_time=5.0)
    run, rev = sh.reversal_scene(make(host), host, J, LOAD, T_s, amplitude=2.0, frequency=0.5, periods=2)
    times = [float(run.t[i]) for i in sh.reversal_indices(run.angle, sh.REVERSAL_HYSTERESIS)]
    _, hold = sh.hold_scene(make(host), host, J, LOAD, T_s, t_end=100.0)
    return {"breakaway": ramp["breakaway_time"], "peak": ramp["peak_torque"], "reversals": times,
            "hold": hold["displacement_deg"]}


def main(argv):
    use_reference = "--reference" in argv
    paths = [a for a in argv if not a.startswith("--")]
    path = paths[0] if paths else sh.FMI2_PATH
    if use_reference:
        T_s = pr.static_torque(LOAD)

        def make(host):
            return pr.ReferenceModelExchange() if host.kind == "me" else pr.ReferenceCoSim()
        source = "Python reference law (presliding_reference.py, defaults)"
    else:
        probe = sh.open_cosim(path, model=sh.PRESLIDING, load=LOAD)
        T_s = probe.static_torque(LOAD)
        probe.close()

        def make(host):
            if host.kind == "me":
                return sh.open_me(path, model=sh.PRESLIDING, load=LOAD)
            return sh.open_cosim(path, model=sh.PRESLIDING, load=LOAD)
        source = f"{path} (presliding model)"
    ref = measure(make, sh.Host("me", rtol=1e-6, jacobian=True), T_s)
    print(f"Step-size convergence, J = {J:g} kg m^2, P = {LOAD / 1e3:g} kN, T_s = {T_s:.2f} N.m; "
          f"{source}; differences to ME BDF rtol 1e-6.\n")
    print("| host | breakaway time (s) | diff (ms) | peak torque (N.m) | diff (%) | reversal times (s) "
          "| max diff (ms) | hold displacement (deg) | diff (deg) |")
    print("|---|---|---|---|---|---|---|---|---|")

    def row(name, m):
        if len(m["reversals"]) == len(ref["reversals"]):
            rd = f"{1e3 * np.max(np.abs(np.subtract(m['reversals'], ref['reversals']))):.2f}"
        else:
            rd = f"{len(m['reversals'])} reversals, reference {len(ref['reversals'])}"
        print(f"| {name} | {m['breakaway']:.4f} | {1e3 * (m['breakaway'] - ref['breakaway']):+.2f} "
              f"| {m['peak']:.3f} | {100 * (m['peak'] / ref['peak'] - 1):+.3f} "
              f"| {', '.join(f'{x:.3f}' for x in m['reversals'])} | {rd} "
              f"| {m['hold']:.5f} | {m['hold'] - ref['hold']:+.1e} |")

    for host in HOSTS:
        row(str(host), measure(make, host, T_s))
    row("ME BDF rtol 1e-6 (reference)", ref)


if __name__ == "__main__":
    main(sys.argv[1:])
