"""Scenes of PinJoint.fmu (FMI 2.0) coupled to a leg body FMU (cosim/leg.py, built with
pythonfmu) in two parallel (Jacobi) masters, libcosim (libcosimpy) and Ecos (ecospy): each
master steps both FMUs over [t, t + h] and then passes the leg's angle and angular velocity to
the pin and the pin's torque to the leg, so the leg integrates the torque of the previous
communication point. The pin is set as docs/fmu.md says for these masters:
zero_velocity.host_inertia = J, zero_velocity.host_coupling = 1 (parallel), load 60 kN.

The scene (`Scene`): a hold at `hold`·T_s until 2 s, a ramp to `peak`·T_s by 4 s (breakaway),
then `rest`·T_s: the leg slows under friction, stops and rests. `measure` gives the drift of
the hold and of the rest (rad), the sign changes of w once settled, the travel of the breakaway.

Run as a script it prints the measured table of docs/fmu.md:
    python tests/fmu_harness/cosim_scenes.py target/fmu/PinJoint.fmu"""

import math
import os
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field

import numpy as np
from fmpy import read_model_description

HERE = os.path.dirname(os.path.abspath(__file__))
LEG_SOURCE = os.path.join(HERE, "cosim", "leg.py")
# The paper's joint at 60 kN: mu_c R P = 0.12 * 0.028 * 60e3 (N.m), the scale of the drives.
T_S = 201.6
LOAD = 60e3
W_ZERO = 1e-7  # rad/s: slower motion neither makes nor breaks a sign change (2e-7 rad in 2 s)


def build_leg(directory=None):
    """Leg.fmu built from cosim/leg.py by pythonfmu into `directory` (a temporary one by default)."""
    directory = directory or tempfile.mkdtemp(prefix="pinjoint-leg-")
    subprocess.run([sys.executable, "-m", "pythonfmu", "build", "-f", LEG_SOURCE, "-d", directory],
                   check=True, capture_output=True)
    return os.path.join(directory, "Leg.fmu")


@dataclass
class Scene:
    inertia: float
    step: float
    hold: float = 0.5
    peak: float = 1.5
    rest: float = 0.3
    t_end: float = 8.0
    coupling: int = 1
    pin_parameters: dict = field(default_factory=dict)

    def leg_parameters(self):
        return {"inertia": self.inertia, "drive_hold": self.hold * T_S, "drive_peak": self.peak * T_S,
                "drive_rest": self.rest * T_S, "t_ramp": 2.0, "t_peak": 4.0, "t_release": 4.0}

    def pin_reals(self):
        return {"load": LOAD, "zero_velocity.host_inertia": self.inertia, **{k: v for k, v in self.pin_parameters.items() if isinstance(v, float)}}

    def pin_integers(self):
        return {"zero_velocity.host_coupling": self.coupling, **{k: v for k, v in self.pin_parameters.items() if isinstance(v, int)}}

    @property
    def steps(self):
        return int(round(self.t_end / self.step))


def value_references(fmu):
    return {v.name: v.valueReference for v in read_model_description(fmu).modelVariables}


CONNECTIONS = [("leg", "angle", "pin", "angle"), ("leg", "angular_velocity", "pin", "angular_velocity"), ("pin", "torque", "leg", "torque")]
OBSERVED = [("leg", "angle"), ("leg", "angular_velocity"), ("pin", "torque"), ("pin", "validity_code")]


def run_libcosim(pin_fmu, leg_fmu, scenes, suffixes=None):
    """One libcosim execution with a pin and a leg per scene (all at the first scene's step);
    returns per scene an array of rows (t, angle, w, torque, validity_code) after each step."""
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimObserver import CosimObserver
    from libcosimpy.CosimSlave import CosimLocalSlave
    h = scenes[0].step
    vr = {"pin": value_references(pin_fmu), "leg": value_references(leg_fmu)}
    ex = CosimExecution.from_step_size(step_size=int(round(h * 1e9)))
    idx = []
    for i, sc in enumerate(scenes):
        s = (suffixes or [str(i) for i in range(len(scenes))])[i]
        pin = ex.add_local_slave(CosimLocalSlave(fmu_path=pin_fmu, instance_name=f"pin{s}"))
        leg = ex.add_local_slave(CosimLocalSlave(fmu_path=leg_fmu, instance_name=f"leg{s}"))
        ids = {"pin": pin, "leg": leg}
        idx.append(ids)
        for name, x in sc.pin_reals().items():
            assert ex.real_initial_value(pin, vr["pin"][name], x), name
        for name, x in sc.pin_integers().items():
            assert ex.integer_initial_value(pin, vr["pin"][name], x), name
        for name, x in sc.leg_parameters().items():
            assert ex.real_initial_value(leg, vr["leg"][name], x), name
        for a, va, b, vb in CONNECTIONS:
            assert ex.connect_real_variables(ids[a], vr[a][va], ids[b], vr[b][vb]) == 0, (a, va, b, vb)
    obs = CosimObserver.create_last_value()
    ex.add_observer(obs)
    rows = [[] for _ in scenes]
    n = scenes[0].steps
    for k in range(n):
        assert ex.step(), f"libcosim step {k} failed"
        for i, ids in enumerate(idx):
            th, w = obs.last_real_values(ids["leg"], [vr["leg"]["angle"], vr["leg"]["angular_velocity"]])
            (t,) = obs.last_real_values(ids["pin"], [vr["pin"]["torque"]])
            (v,) = obs.last_integer_values(ids["pin"], [vr["pin"]["validity_code"]])
            rows[i].append(((k + 1) * h, th, w, t, v))
    return [np.array(r) for r in rows]


def run_ecos(pin_fmu, leg_fmu, scenes):
    """As run_libcosim, in Ecos."""
    from ecospy import EcosSimulation, EcosSimulationStructure
    h = scenes[0].step
    rows = [[] for _ in scenes]
    with EcosSimulationStructure() as ss:
        params = {}
        for i, sc in enumerate(scenes):
            ss.add_model(f"pin{i}", pin_fmu)
            ss.add_model(f"leg{i}", leg_fmu)
            for a, va, b, vb in CONNECTIONS:
                ss.make_real_connection(f"{a}{i}::{va}", f"{b}{i}::{vb}")
            params.update({f"pin{i}::{k}": float(v) for k, v in sc.pin_reals().items()})
            params.update({f"pin{i}::{k}": int(v) for k, v in sc.pin_integers().items()})
            params.update({f"leg{i}::{k}": float(v) for k, v in sc.leg_parameters().items()})
        ss.add_parameter_set("scene", params)
        with EcosSimulation(structure=ss, step_size=h) as sim:
            assert sim.init(parameter_set="scene")
            for i, sc in enumerate(scenes):
                assert sim.get_integer(f"pin{i}::zero_velocity.host_coupling") == sc.coupling
                assert sim.get_real(f"pin{i}::zero_velocity.host_inertia") == sc.inertia
            for k in range(scenes[0].steps):
                t = sim.step()
                for i in range(len(scenes)):
                    rows[i].append((t, sim.get_real(f"leg{i}::angle"), sim.get_real(f"leg{i}::angular_velocity"),
                                    sim.get_real(f"pin{i}::torque"), sim.get_integer(f"pin{i}::validity_code")))
            sim.terminate()
    return [np.array(r) for r in rows]


def sign_changes(w, zero=W_ZERO):
    s = np.sign(np.where(np.abs(w) < zero, 0.0, w))
    s = s[s != 0]
    return int(np.sum(s[1:] != s[:-1]))


def measure(r, scene):
    """Drift of the hold (1.5..2 s; from 1 s for J < 100) and of the rest (6 s .. end) in rad,
    the sign changes of w in those windows, the travel of the breakaway (2..4 s, rad), the
    time the leg stopped (last sign change or motion above 1e-4 rad/s after 4 s)."""
    t, th, w = r[:, 0], r[:, 1], r[:, 2]

    def window(a, b):
        m = (t > a - 1e-9) & (t <= b + 1e-9)
        return th[m], w[m]

    hold_from = 1.0 if scene.inertia < 100 else 1.5
    th_h, w_h = window(hold_from, 2.0)
    th_r, w_r = window(6.0, scene.t_end)
    moving = np.nonzero((t > 4.0) & (np.abs(w) > 1e-4))[0]
    return {
        "hold_drift": float(abs(th_h[-1] - th_h[0])),
        "hold_sign_changes": sign_changes(w_h),
        "hold_angle": float(th_h[-1]),
        "breakaway_travel": float(th[np.searchsorted(t, 4.0)] - th[np.searchsorted(t, 2.0)]),
        "stopped_at": float(t[moving[-1]]) if len(moving) else 4.0,
        "rest_drift": float(abs(th_r[-1] - th_r[0])),
        "rest_sign_changes": sign_changes(w_r),
        "sign_changes_after_stop": sign_changes(w[t > 4.0]),
    }


def main(pin_fmu):
    leg = build_leg()
    print("| master | coupling | J (kg.m2) | step (ms) | hold drift 1(1.5)-2 s (rad) | breakaway travel 2-4 s (rad) | stopped at (s) | rest drift 6-8 s (rad) | w sign changes after 4 s |")
    print("|---|---|---|---|---|---|---|---|---|")
    for master, run in (("libcosim", run_libcosim), ("Ecos", run_ecos)):
        for coupling in (1, 0):
            for h in (1e-3, 1e-2):
                for J in (20.0, 50.0, 1400.0):
                    sc = Scene(J, h, coupling=coupling)
                    m = measure(run(pin_fmu, leg, [sc])[0], sc)
                    print(f"| {master} | {'parallel' if coupling else 'sequential'} | {J:g} | {h * 1e3:g} | {m['hold_drift']:.1e} | "
                          f"{m['breakaway_travel']:.3f} | {m['stopped_at']:.2f} | {m['rest_drift']:.1e} | {m['sign_changes_after_stop']} |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "target/fmu/PinJoint.fmu")
