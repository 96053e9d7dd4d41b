"""fmpy.simulate_fmu with PinJointRig: independence of the host's step size, and
every output equal to the rig library's at every output point."""

import numpy as np
import pytest
from fmpy import simulate_fmu

from conftest import failed_simulation
from rig_support import RIG_OUTPUTS, expected_outputs, max_relative_difference, rig_reference


def load_step(stop, at=0.5):
    """Load 5 kN, then 60 kN from `at` (a step, both values at `at`: fmpy cuts the
    step there and sets the new value from `at` on)."""
    signal = np.zeros(4, dtype=[("time", float), ("load", float), ("command_angle", float)])
    signal["time"] = [0.0, at, at, stop]
    signal["load"] = [5e3, 5e3, 60e3, 60e3]
    return signal


def simulate(path, interval, stop=1.5, **kw):
    kw.setdefault("input", load_step(stop))
    return simulate_fmu(path, stop_time=stop, output_interval=interval, output=["load", "command_angle"] + RIG_OUTPUTS, **kw)


def check_library(r, params=None, command=None, rel=1e-12):
    ref = rig_reference(r["time"], r["load"], command, params)
    exp = expected_outputs(ref)
    assert np.array_equal(ref["time"], r["time"])
    worst = 0.0
    for name in RIG_OUTPUTS:
        d = max_relative_difference(np.asarray(r[name], float), exp[name])
        assert d <= rel, f"{name}: relative difference {d:e} to the library"
        worst = max(worst, d)
    return worst


def test_1ms_and_100ms_hosts_agree_at_shared_points(rig_fmu_path):
    fine = simulate(rig_fmu_path, 1e-3)
    coarse = simulate(rig_fmu_path, 0.1)
    assert len(coarse) >= 16
    idx = [int(np.argmin(np.abs(fine["time"] - t))) for t in coarse["time"]]
    assert np.allclose(fine["time"][idx], coarse["time"], rtol=0, atol=1e-12)
    same_time = fine["time"][idx] == coarse["time"]
    worst = 0.0
    for name in RIG_OUTPUTS:
        a, b = np.asarray(fine[name][idx], float), np.asarray(coarse[name], float)
        # Identical time bits: identical numbers.
        assert np.array_equal(a[same_time], b[same_time]), name
        worst = max(worst, max_relative_difference(a, b, floor=1e-3))
    # Times that differ in the last bit (300 * 0.001 vs 3 * 0.1): 1e-12 relative.
    assert worst <= 1e-12, worst
    assert same_time.sum() >= 8
    print(f"1 ms vs 100 ms: {same_time.sum()} of {len(coarse)} shared points bit-identical; worst relative difference {worst:.3e}")
    # The run passes reversals, stick phases and the load step.
    assert np.any(fine["stuck"]) and not np.all(fine["stuck"])
    assert set(np.unique(fine["load"])) == {5e3, 60e3}


def test_outputs_equal_the_library_at_every_point(rig_fmu_path):
    for interval in (1e-3, 0.1):
        r = simulate(rig_fmu_path, interval)
        worst = check_library(r)
        print(f"interval {interval}: worst relative difference to the library {worst:.3e}")
    # Energy balance through the FMU outputs: W - D = kinetic energy (from rest).
    w, d, k = r["actuator_work"][-1], r["friction_dissipation"][-1], r["kinetic_energy"][-1]
    assert abs(w - d - k) < 1e-6 * d


def test_start_values_take_effect(rig_fmu_path):
    params = {"frequency": 0.3, "amplitude": np.radians(25.0), "rig.inertia": 0.1, "rig.breakaway_factor": 1.2,
              "rig.method": 1, "friction.boundary_friction_coefficient": 0.1, "lubricant.viscosity": 0.3}
    r = simulate(rig_fmu_path, 0.01, stop=2.0, start_values=params)
    check_library(r, params)
    assert abs(np.max(np.abs(r["commanded_angle"])) - np.radians(25.0) * np.sin(2 * np.pi * 0.3 * 0.83)) < 0.02
    default = simulate(rig_fmu_path, 0.01, stop=2.0)
    assert not np.allclose(r["torque"], default["torque"])


def test_command_input_through_fmpy(rig_fmu_path):
    t = np.linspace(0.0, 1.0, 11)
    signal = np.zeros(len(t), dtype=[("time", float), ("load", float), ("command_angle", float)])
    signal["time"], signal["load"], signal["command_angle"] = t, 20e3, 0.4 * np.sin(3 * t)
    params = {"use_command_input": True}
    r = simulate_fmu(rig_fmu_path, stop_time=1.0, output_interval=0.01, input=signal, start_values=params,
                     output=["load", "command_angle"] + RIG_OUTPUTS)
    # Each row holds the command applied at the previous point (held over the step).
    check_library(r, command=r["command_angle"])
    assert np.array_equal(r["commanded_angle"], r["command_angle"])
    assert abs(r["angle"][-1] - 0.4 * np.sin(3 * 0.99)) < 0.05


@pytest.mark.parametrize("interval,stop", [(1e-5, 0.05), (1.0, 3.0)])
def test_extreme_host_steps(rig_fmu_path, interval, stop):
    # No input signal: the load keeps its start value exactly. (fmpy's linear
    # interpolation of a constant signal wobbles by an ulp, e.g. 19999.999999999996 N,
    # and every new input value restarts the integration, a legitimate difference.)
    r = simulate(rig_fmu_path, interval, stop=stop, input=None)
    ref = simulate(rig_fmu_path, 0.01, stop=stop, input=None)
    idx = [int(np.argmin(np.abs(r["time"] - t))) for t in ref["time"]] if interval < 0.01 else None
    a = r[idx] if idx is not None else r
    b = ref if idx is not None else ref[[int(np.argmin(np.abs(ref["time"] - t))) for t in r["time"]]]
    assert np.allclose(a["time"], b["time"], rtol=0, atol=1e-12)
    for name in RIG_OUTPUTS:
        d = max_relative_difference(np.asarray(a[name], float), np.asarray(b[name], float), floor=1e-3)
        assert d <= 1e-12, f"{name}: {d:e}"
    check_library(r)


def test_invalid_parameter_fails_initialization_with_its_name(rig_fmu_path):
    error, messages = failed_simulation(rig_fmu_path, {"rig.velocity_gain": 10.0})
    assert "fmi2ExitInitializationMode" in error
    assert any("rig.velocity_gain = 10 N.m.s/rad" in m and "Routh" in m for m in messages), messages


def test_zero_load(rig_fmu_path):
    r = simulate(rig_fmu_path, 0.01, stop=0.5, input=None, start_values={"load": 0.0})
    assert np.all(r["friction_torque"] == 0) and np.all(r["film_thickness"] == 0)
    # At rest with no torque at t = 0 the joint counts as stuck; once moving it never sticks.
    assert not np.any(r["stuck"][1:])
    assert r["angle"].max() > 0.6
    check_library(r)


@pytest.mark.parametrize("temperature,load,frequency,stiffer", [(218.15, 5e3, 0.3, 1.0), (233.15, 20e3, 1.0, 1.5)])
def test_the_cold_day_runs_and_equals_the_library(rig_fmu_path, temperature, load, frequency, stiffer):
    """Issue 37, item 6: -55 C at 5 kN, 0.3 Hz (where the rig's event logic chattered and
    refused) and -40 C with a grease 1.5x stiffer (consistency and yield stress, from the
    FMU's own start values): two strokes through fmpy, sticking at the reversals, the
    friction opposing the motion in slip, the energy balance closed, and every output the
    library's."""
    from fmpy import read_model_description
    start = {v.name: float(v.start) for v in read_model_description(rig_fmu_path).modelVariables
             if v.name in ("grease.consistency", "grease.yield_stress")}
    grease = {k: stiffer * v for k, v in start.items()}
    stop = 2.0 / frequency
    r = simulate(rig_fmu_path, 0.01, stop=stop, input=None,
                 start_values={"load": load, "temperature": temperature, "frequency": frequency, **grease})
    check_library(r, {"frequency": frequency, "lubricant.temperature": temperature, **grease})
    assert np.any(r["stuck"]) and not np.all(r["stuck"])
    moving = (r["stuck"] == 0) & (np.abs(r["angular_velocity"]) > 1e-6)
    assert np.all(r["friction_torque"][moving] * r["angular_velocity"][moving] < 0)
    w, d, k = r["actuator_work"][-1], r["friction_dissipation"][-1], r["kinetic_energy"][-1]
    assert d > 0 and abs(w - d - k) < 1e-6 * d
