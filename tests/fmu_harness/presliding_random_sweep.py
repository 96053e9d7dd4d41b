"""Random scenes over the envelope of issue 22 on the Python reference law (a check with
values nobody picked): random host (explicit 1 / 10 ms, J >= 20; implicit 100 ms, J >= 5),
inertia (log-uniform to 5000 kg m^2), load (5..60 kN) and drive (hold 0.05..0.85 T_s; ramp
0.5..20 s; sine 1.2..3 T_s with a bias, at a frequency that slides the body a few degrees;
dither below breakaway at f_n x [0.05, 1/3] or [3, 6]). A reversal count that differs from
the drive's is arbitrated by Model Exchange (BDF, rtol 1e-8): when the accurate solution has
the host's count, the drive's count was the wrong expectation (the body's momentum carried it
through a reverse excursion of the drive), not a failure.

    .venv/bin/python tests/fmu_harness/presliding_random_sweep.py [seed] [seconds] [phi_s beta t_d]
"""

import math
import random
import sys
import time

import presliding_reference as pr
import scene_host as sh


def main(argv):
    seed = int(argv[0]) if argv else 1
    budget = float(argv[1]) if len(argv) > 1 else 120.0
    law = pr.PreslidingLaw(*map(float, argv[2:5])) if len(argv) >= 5 else pr.PreslidingLaw()
    rng = random.Random(seed)
    cases = failures = arbitrated = 0
    t0 = time.time()
    while time.time() - t0 < budget:
        host = rng.choice([sh.Host("explicit", 1e-3), sh.Host("explicit", 1e-2), sh.Host("implicit", 0.1)])
        j_min = 20 if host.kind == "explicit" else 5
        J = math.exp(rng.uniform(math.log(j_min), math.log(5000)))
        P = rng.uniform(5e3, 60e3)
        T_s = pr.static_torque(P)
        fn = math.sqrt(T_s / (law.phi_s * J)) / (2 * math.pi)
        kind = rng.choice(["reversal", "ramp", "dither", "hold"])
        if kind == "reversal":
            A = rng.uniform(1.2, 3.0)
            b = rng.uniform(-0.5, 0.5) * (A - 1.1)
            f_max = math.sqrt((A - 1) * T_s / (J * 0.05)) / (2 * math.pi)
            f = rng.uniform(0.2, 1.0) * min(f_max, 1.0, 0.02 / host.h)
            desc = f"sine {A:.2f} T_s + {b:.2f} T_s at {f:.3g} Hz"
            _, m = sh.reversal_scene(pr.ReferenceCoSim(law), host, J, P, T_s, amplitude=A, bias=b, frequency=f, periods=2)
            if m["failures"] and not m["chatter"]:
                _, me = sh.reversal_scene(pr.ReferenceModelExchange(law), sh.Host("me", rtol=1e-8), J, P, T_s,
                                          amplitude=A, bias=b, frequency=f, periods=2)
                desc += f" [ME: {me['reversals']} reversals]"
                if me["reversals"] == m["reversals"]:
                    m["failures"], arbitrated = [], arbitrated + 1
        elif kind == "ramp":
            rise = rng.uniform(0.5, 20.0)
            desc = f"ramp to T_s in {rise:.2f} s"
            _, m = sh.ramp_scene(pr.ReferenceCoSim(law), host, J, P, T_s, rise_time=rise)
        elif kind == "dither":
            b = rng.uniform(-0.5, 0.5)
            a = rng.uniform(0.05, max(0.8 - abs(b), 0.06))
            f = rng.choice([rng.uniform(0.05, 1 / 3), rng.uniform(3.0, 6.0)]) * fn
            if f * host.h > 0.1:
                continue
            rise = 5 / fn
            periods = max(8, min(20, int(20 * f))) + math.ceil(rise * f) + 1
            desc = f"dither ({b:.2f} +- {a:.2f}) T_s at {f:.3g} Hz (f_n {fn:.3g})"
            _, m = sh.dither_scene(pr.ReferenceCoSim(law), host, J, P, T_s, bias=b, amplitude=a, frequency=f,
                                   periods=periods, rise=rise)
        else:
            frac = rng.uniform(0.05, 0.85)
            rise = 0.0 if J < 1000 else 10.0
            desc = f"hold {frac:.2f} T_s, rise {rise:g} s"
            _, m = sh.hold_scene(pr.ReferenceCoSim(law), host, J, P, T_s, fraction=frac, t_end=60.0, rise=rise)
        cases += 1
        if m["failures"]:
            failures += 1
            print(f"FAIL {host}, J = {J:.1f} kg m^2, {P / 1e3:.1f} kN, {desc}: {'; '.join(m['failures'])}")
    print(f"{cases} cases, {failures} failures, {arbitrated} reversal counts arbitrated by ME")


if __name__ == "__main__":
    main(sys.argv[1:])
