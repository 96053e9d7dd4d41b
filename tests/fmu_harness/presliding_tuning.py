"""Which presliding parameters (presliding_angle, elastic_limit, damping_time) meet the
host-inertia scenes over the envelope of issue 22 (explicit host J >= 20 kg m^2 at
h <= 10 ms, linearly implicit J >= 5 kg m^2 at 100 ms, loads 5 to 60 kN), run with the
Python reference law (presliding_reference.py) in place of the FMU:

    .venv/bin/python tests/fmu_harness/presliding_tuning.py [--c0=N.m.s/rad] [phi_s beta t_d ...]

(--c0: a load-independent damping coefficient instead of c = k t_d, an alternative studied.)

Prints one line per parameter set: failures per scene and the worst metrics."""

import itertools
import math
import sys
import time

import presliding_reference as pr
import scene_host as sh

LOADS = (5e3, 20e3, 60e3)


def hosts():
    return [(sh.Host("explicit", 1e-3), (20, 50, 500, 5000)),
            (sh.Host("explicit", 1e-2), (20, 50, 500, 5000)),
            (sh.Host("implicit", 0.1), (5, 20, 50, 500, 5000))]


def natural_frequency(T_s, phi_s, J):
    """The presliding ring's frequency (Hz): sqrt(k/J)/(2 pi), k = T_s/phi_s."""
    return math.sqrt(T_s / (phi_s * J)) / (2 * math.pi)


def reversal_frequency(J):
    """A drive frequency (Hz) at which a 2 T_s sine slides the body well beyond the
    reversal hysteresis at inertia J."""
    return 0.5 if J <= 50 else (0.2 if J <= 500 else 0.05)


def scenes(J, load, T_s, phi_s, h):
    """(name, scene function, keyword arguments) of the envelope at one (J, load, h)."""
    fn = natural_frequency(T_s, phi_s, J)
    out = [("hold-step", sh.hold_scene, dict(t_end=100.0)),
           ("hold-rise", sh.hold_scene, dict(t_end=100.0, rise=10.0)),
           ("ramp", sh.ramp_scene, {}),
           ("reversal", sh.reversal_scene, dict(amplitude=2.0, frequency=reversal_frequency(J), periods=2)),
           ("reversal-biased", sh.reversal_scene, dict(amplitude=2.0, bias=0.4, frequency=reversal_frequency(J), periods=2)),
           ("reversal-slow-1.3", sh.reversal_scene, dict(amplitude=1.3, frequency=reversal_frequency(J) / 5, periods=2))]
    rise = 5 / fn
    for tag, f in (("slow", min(1.0, fn / 3)), ("ripple", 3 * fn)):
        if f * h <= 0.1:
            periods = max(8, min(20, int(20 * f))) + math.ceil(rise * f) + 1
            out.append((f"dither-{tag}", sh.dither_scene, dict(frequency=f, periods=periods, rise=rise)))
    return out


def evaluate(phi_s, beta, t_d, c0=None):
    law = pr.PreslidingLaw(phi_s, beta, t_d, damping_coefficient=c0)
    fails, worst, failed = {}, {}, []
    for host, inertias in hosts():
        for J, load in itertools.product(inertias, LOADS):
            T_s = pr.static_torque(load)
            cases = [(name, lambda joint, fn=fn, kw=kw: fn(joint, host, J, load, T_s, **kw))
                     for name, fn, kw in scenes(J, load, T_s, phi_s, host.h)]
            if load == LOADS[1]:
                cases.append(("load-change", lambda joint: sh.load_change_scene(
                    joint, host, J, sh.LoadProfile((20e3, 60e3, 12e3, 40e3)), 0.5 * T_s)))
            for name, case in cases:
                _, m = case(pr.ReferenceCoSim(law))
                for key in ("drift_deg", "oscillation_deg", "displacement_deg", "motion_before_deg", "peak_error",
                            "walk_deg"):
                    if key in m:
                        worst[(name, key)] = max(worst.get((name, key), 0.0), abs(m[key]))
                if m["failures"]:
                    fails[name] = fails.get(name, 0) + 1
                    failed.append(f"{host} J={J} P={load / 1e3:g}kN {name}: {'; '.join(m['failures'])}")
    return fails, worst, failed


def main(argv):
    c0 = None
    if argv and argv[0].startswith("--c0="):  # load-independent damping coefficient (N.m.s/rad)
        c0, argv = float(argv[0][5:]), argv[1:]
    sets = [tuple(float(x) for x in argv[i:i + 3]) for i in range(0, len(argv), 3)] or [(1.5e-3, 0.95, 0.01)]
    for phi_s, beta, t_d in sets:
        t0 = time.time()
        fails, worst, failed = evaluate(phi_s, beta, t_d, c0)
        w = ", ".join(f"{n}.{k} {v:.3g}" for (n, k), v in sorted(worst.items()))
        print(f"phi_s {phi_s:g} rad, beta {beta:g}, " + (f"c0 {c0:g} N.m.s/rad" if c0 else f"t_d {t_d:g} s")
              + f": failures {fails or 'none'} "
              f"({time.time() - t0:.0f} s)\n  worst: {w}")
        for line in failed:
            print("  FAIL", line)


if __name__ == "__main__":
    main(sys.argv[1:])
