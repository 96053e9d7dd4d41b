"""Temperature as a live input and the `validity` output through fmpy (PinJoint, FMI 2.0 and
3.0; PinJointRig): a warming/cooling run gives at every step the outputs of a fresh instance
started at that temperature, bit for bit; FMI 3.0 equals FMI 2.0; `validity` is the
envelope's at every sample, on both sides of each boundary; one log message per excursion."""

import math

import numpy as np
import pytest
from fmpy import simulate_fmu

from conftest import FMU, TARGET
from host import Slave

FMI3 = TARGET / "fmu" / "fmi3" / "PinJoint.fmu"
RIG_FMU = TARGET / "fmu" / "PinJointRig.fmu"
FMI3_RIG = TARGET / "fmu" / "fmi3" / "PinJointRig.fmu"

# The envelope as docs/validity.md states it.
U_MAX = 2.0 * math.pi * math.radians(40.0) * 0.028


# The model's assumptions (docs/validity.md, "Past the model's assumptions"): the load at which
# the Hertz half-width of eq. 6 reaches the pin radius (Table 1) and the default grease's upper
# service temperature (+121 C).
E_EFF = 2.0 / ((1 - 0.28**2) / 205e9 + (1 - 0.34**2) / 117e9)
LOAD_EDGE = math.pi * E_EFF * 0.0594 * 0.028**2 / (8 * (0.028 * 0.028025 / 0.000025))
T_MAX = 394.15


def expected(load, omega, temp, paper=False):
    """The envelope's code: 0 checked, 1 extrapolation, 2 known-wrong (the paper's model only,
    below 0 C; the complete model, the default, is an extrapolation there), 3 outside (past
    the load edge or the upper service temperature)."""
    load, u, temp = np.abs(np.asarray(load, float)), np.abs(np.asarray(omega, float)) * 0.028, np.asarray(temp, float)
    ok = (load >= 5e3) & (load <= 60e3) & (u <= U_MAX) & (temp >= 288.15) & (temp <= 298.15)
    level = np.where((temp < 273.15) & paper, 2, np.where(ok, 0, 1))
    return np.where((load > LOAD_EDGE) | (temp > T_MAX), 3, level)


@pytest.mark.parametrize("path", [FMU, FMI3], ids=["fmi2", "fmi3"])
def test_past_the_assumptions_validity_is_3(path):
    """Loads across the load edge (96.7 kN) and temperatures across 394.15 K: 3 exactly past
    either, the outputs continuous across them; a lower grease.upper_service_temperature
    moves the temperature edge."""
    t = np.arange(0.0, 1.0 + 5e-4, 1e-3)
    s = np.zeros(len(t), dtype=[("time", float), ("angular_velocity", float), ("load", float), ("temperature", float)])
    s["time"], s["angular_velocity"] = t, 0.5
    s["load"] = np.interp(t, [0.0, 0.5, 1.0], [50e3, 150e3, 50e3])
    s["temperature"] = np.round(np.interp(t, [0.0, 0.5, 1.0], [380.0, 420.0, 380.0]), 3)
    for start, t_max in (({}, T_MAX), ({"grease.upper_service_temperature": 400.0}, 400.0)):
        r = run(path, s, **start)
        v = np.asarray(r["validity"], int)
        want = np.where((np.abs(r["load"]) > LOAD_EDGE) | (r["temperature"] > t_max), 3, 1)
        assert np.array_equal(v, want)
        assert 3 in v and 1 in v
        assert np.all(np.isfinite(r["torque"]))


def signal(seed, stop=2.0, dt=1e-3):
    """Speeds through reversals up to 6 rad/s, loads 2-80 kN, the temperature drifting and
    jumping across 240-330 K (random, so no test sees only its own examples)."""
    rng = np.random.default_rng(seed)
    t = np.arange(0.0, stop + dt / 2, dt)
    omega = 6.0 * np.sin(2 * np.pi * rng.uniform(0.3, 1.5) * t)
    load = np.interp(t, np.linspace(0, stop, 6), rng.uniform(2e3, 80e3, 6))
    temp = np.interp(t, np.sort(rng.uniform(0, stop, 8)), rng.uniform(240.0, 330.0, 8))
    temp = np.round(temp, 3)  # steps of 1e-3 K and holds
    s = np.zeros(len(t), dtype=[("time", float), ("angular_velocity", float), ("load", float), ("temperature", float)])
    s["time"], s["angular_velocity"], s["load"], s["temperature"] = t, omega, load, temp
    return s


def run(path, sig, **start):
    return simulate_fmu(str(path), stop_time=float(sig["time"][-1]), output_interval=1e-3, input=sig, start_values=start,
                        output=["angular_velocity", "load", "temperature", "torque", "friction_coefficient", "film_thickness", "validity"])


@pytest.mark.parametrize("seed", [11, 12])
def test_fmi3_equals_fmi2_and_validity_is_the_envelopes(fmu_path, seed):
    sig = signal(seed)
    a, b = run(FMU, sig), run(FMI3, sig)
    for name in a.dtype.names:
        assert np.array_equal(a[name], b[name]), name
    assert np.array_equal(np.asarray(a["validity"], int), expected(a["load"], a["angular_velocity"], a["temperature"]))
    assert len(np.unique(a["validity"])) == 2
    assert len(np.unique(a["temperature"])) > 100


@pytest.mark.parametrize("seed", [21, 22])
def test_each_step_equals_a_fresh_instance_at_its_temperature(fmu_path, unzipped, model_description, seed):
    rng = np.random.default_rng(seed)
    md = model_description
    # The friction model's temperature path, not the presliding state's history: the band
    # (stateless) in both instances.
    run_ = Slave(unzipped, md, start_values={"zero_velocity.model": 0}, instance_name="warming")
    vr = run_.vr
    t = 0.0
    temp = 290.0
    for k in range(40):
        temp = temp + (1e-3 if rng.uniform() < 0.7 else rng.uniform(-30.0, 30.0))
        # Inside the declared range and the film bound (docs/conventions.md).
        temp = float(np.clip(temp, 250.0, 400.0))
        load, w = float(rng.uniform(1e4, 1e5)), float(rng.uniform(-3.0, 3.0))
        run_.fmu.setReal([vr["temperature"], vr["load"], vr["angular_velocity"]], [temp, load, w])
        run_.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=1e-3)
        t += 1e-3
        fresh = Slave(unzipped, md, start_values={"zero_velocity.model": 0, "temperature": temp, "load": load, "angular_velocity": w},
                      instance_name="fresh")
        fresh.fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=1e-3)
        names = [n for n in ("torque", "friction_coefficient", "film_thickness", "lambda_ratio", "fluid_load_fraction",
                             "asperity_load_fraction", "mean_pressure", "sommerfeld_number", "power_loss",
                             "min_film_thickness", "min_lambda_ratio")]
        got = run_.fmu.getReal([vr[n] for n in names])
        want = fresh.fmu.getReal([vr[n] for n in names])
        assert np.array_equal(np.array(got).view(np.uint64), np.array(want).view(np.uint64)), (k, temp, load, w)
        assert run_.fmu.getInteger([vr["validity"]]) == [int(expected(load, w, temp))]
        fresh.free()
    run_.free()


def test_one_log_message_per_excursion(unzipped, model_description):
    s = Slave(unzipped, model_description, logging_on=True, instance_name="log")
    vr = s.vr
    t = 0.0
    # checked, out (load), out (cold), checked, out (speed), checked
    for load, w, temp in [(20e3, 1.0, 293.15), (70e3, 1.0, 293.15), (70e3, 1.0, 250.0), (20e3, 1.0, 293.15),
                          (20e3, 1.0, 293.15), (20e3, 5.0, 293.15), (20e3, 5.0, 293.15), (20e3, 1.0, 293.15)]:
        s.fmu.setReal([vr["load"], vr["angular_velocity"], vr["temperature"]], [load, w, temp])
        s.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=0.01)
        t += 0.01
    said = [m for (_, _, m) in s.log.messages if m.startswith("validity")]
    assert len(said) == 2, said
    assert "load = 70000 N" in said[0] and "angular_velocity" not in said[0]
    assert "sliding_speed" in said[1]
    s.free()


def test_rig_fmi3_equals_fmi2_with_a_changing_temperature():
    t = np.arange(0.0, 0.6, 1e-3)
    sig = np.zeros(len(t), dtype=[("time", float), ("temperature", float)])
    sig["time"], sig["temperature"] = t, np.round(293.15 + 40.0 * np.sin(7.0 * t), 3)
    kw = dict(stop_time=0.5, output_interval=1e-3, input=sig, start_values={"rig.method": 2},
              output=["angle", "angular_velocity", "friction_torque", "friction_coefficient", "validity"])
    a = simulate_fmu(str(RIG_FMU), **kw)
    b = simulate_fmu(str(FMI3_RIG), **kw)
    for name in a.dtype.names:
        assert np.array_equal(a[name], b[name]), name
    assert set(np.unique(a["validity"])) <= {0, 1}
    assert 1 in set(np.unique(a["validity"]))  # above 25 C part of the time
