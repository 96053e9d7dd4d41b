"""Third importer: the Ecos co-simulation engine (ecospy, pinned in
requirements-test.txt; its native library needs Debian's libtbb12). Ecos loads
PinJoint.fmu, takes its parameters from a parameter set, steps it with a fixed step,
and every output is checked against the library (examples/reference_points).

Ecos does not handle Enumeration variables ("No int property pin::zero_velocity.model"), so
it runs the default zero-velocity model, presliding, driven by the angle input: the torque is
checked against the presliding law at the state Ecos reads back (presliding_torque) with the
library's sliding torque, and against the library's signed torque in steady sliding."""

import math

import numpy as np
import pytest

from conftest import OUTPUTS, assert_close, presliding_torque, reference

try:
    from ecospy import EcosLib, EcosSimulation, EcosSimulationStructure
except OSError as e:  # the native library did not load
    raise RuntimeError(f"ecospy is installed but its native library does not load ({e}); "
                       "install Debian's libtbb12 (scripts/test.sh does)") from e

PARAMS = {"friction.boundary_friction_coefficient": 0.1, "lubricant.viscosity": 0.02}
H = 0.01


def inputs(k):
    """Reversals of growing amplitude (boundary to mixed lubrication), load step at k = 200."""
    omega = (0.2 + 0.2 * k) * math.sin(0.05 * k)
    load = 5e3 if k < 200 else 60e3
    return omega, load


def run(sim, steps):
    rows = []
    angle = 0.0
    for k in range(steps):
        omega, load = inputs(k)
        sim.set_real("pin::angular_velocity", omega)
        sim.set_real("pin::load", load)
        # The angle the host integrates (symplectic Euler): its increments drive the state.
        sim.set_real("pin::angle", angle)
        angle += omega * H
        t = sim.step()
        assert t == pytest.approx((k + 1) * H, rel=1e-12)
        rows.append([omega, load] + [sim.get_real(f"pin::{n}") for n in OUTPUTS + ["presliding_torque"]])
    return np.array(rows)


def simulation(ss):
    ss.add_model("pin", FMU_PATH[0])
    ss.add_parameter_set("init", {f"pin::{k}": v for k, v in PARAMS.items()})
    return EcosSimulation(structure=ss, step_size=H)


FMU_PATH = []


@pytest.fixture(autouse=True)
def _fmu(fmu_path):
    FMU_PATH[:] = [fmu_path]
    EcosLib.set_log_level("warn")


def check(r):
    omega, load = r[:, 0], r[:, 1]
    out = {n: r[:, 2 + i] for i, n in enumerate(OUTPUTS + ["presliding_torque"])}
    ref = reference(load, omega, PARAMS)
    # The state the step committed at this angle; the torque is the law's there (the outputs
    # read after the step use the state committed at the angle set before it).
    torque = presliding_torque(out["presliding_torque"], omega, ref["torque"])
    assert_close(out["torque"], torque, what="torque")
    assert np.all(np.abs(out["presliding_torque"]) <= ref["torque"] * (1 + 1e-12))
    # Steady sliding: 2 degrees of travel since the last reversal or load change, and a step's
    # travel of at least 40 (1 - beta) phi_s = 3e-3 rad, over which the state settles on a
    # sliding torque that moves with omega. The angle set before step k is that after step
    # k - 1, so the state at row k has travelled through step k - 1.
    steady, travel, sign = np.zeros(len(r), bool), 0.0, 0.0
    for k in range(1, len(r)):
        step = omega[k - 1] * H
        if np.sign(step) != sign or load[k] != load[k - 1]:
            travel, sign = 0.0, np.sign(step)
        travel += abs(step)
        steady[k] = travel >= np.radians(2.0) and abs(step) >= 3e-3 and np.sign(omega[k]) == sign
    assert steady.sum() > 0.3 * len(r), steady.sum()
    assert_close(out["torque"][steady], ref["signed_torque"][steady], what="torque in steady sliding")
    for name in ("friction_coefficient", "film_thickness", "lambda_ratio", "fluid_load_fraction",
                 "asperity_load_fraction", "mean_pressure", "sommerfeld_number"):
        assert_close(out[name], ref[name], what=name)
    assert_close(out["power_loss"][steady], np.abs(torque * omega)[steady], what="power_loss in steady sliding")
    assert np.all(out["power_loss"] >= 0.0)
    assert_close(out["dissipated_energy"], np.cumsum(out["power_loss"] * H), what="dissipated_energy")
    return ref


def test_ecos_steps_the_fmu_with_the_library_outputs():
    with EcosSimulationStructure() as ss, simulation(ss) as sim:
        assert sim.init(parameter_set="init")
        assert sim.get_real("pin::friction.boundary_friction_coefficient") == 0.1
        r = run(sim, 400)
        sim.terminate()
    ref = check(r)
    omega = r[:, 0]
    # The run covers what it claims: reversals, both loads, boundary and mixed lubrication.
    assert np.sum(np.diff(np.sign(omega)) != 0) >= 5
    assert ref["fluid_load_fraction"].min() < 0.01 and ref["fluid_load_fraction"].max() > 0.2
    assert set(np.unique(r[:, 1])) == {5e3, 60e3}


def test_ecos_reset_then_a_fresh_run_equals_the_first():
    with EcosSimulationStructure() as ss, simulation(ss) as sim:
        assert sim.init(parameter_set="init")
        first = run(sim, 120)
        sim.reset()
        assert sim.init(parameter_set="init")
        second = run(sim, 120)
        sim.terminate()
    assert np.array_equal(first.view(np.uint64), second.view(np.uint64))
    check(first)


def test_ecos_bad_input_is_refused_and_the_simulation_goes_on():
    """A NaN or infinite load set through Ecos is refused by fmi2SetReal (fmi2Error);
    the FMU keeps the last valid load, its outputs stay finite and the library's."""
    with EcosSimulationStructure() as ss, simulation(ss) as sim:
        assert sim.init(parameter_set="init")
        run(sim, 10)
        for bad in (float("nan"), float("inf"), float("-inf")):
            try:
                sim.set_real("pin::load", bad)
            except Exception:
                pass  # Ecos may or may not pass the FMU's fmi2Error on
            sim.step()
            assert sim.get_real("pin::load") == inputs(9)[1]
            vals = [sim.get_real(f"pin::{n}") for n in OUTPUTS]
            assert all(map(math.isfinite, vals)), vals
        omega, load = inputs(9)
        ref = reference([load], [omega], PARAMS)
        assert sim.get_real("pin::friction_coefficient") == float(ref["friction_coefficient"])
        sim.terminate()


def test_ecos_steps_the_rig_fmu_with_the_rig_library_outputs(rig_fmu_path):
    """PinJointRig under Ecos: 150 steps of 10 ms, the load stepping 5 -> 60 kN at
    t = 0.5 s, every output (the Boolean `stuck` through Ecos' bool getter) equal to the
    rig library driven the same way."""
    from rig_support import RIG_OUTPUTS, expected_outputs, max_relative_difference, rig_reference
    times, loads, rows = [], [], []
    with EcosSimulationStructure() as ss:
        ss.add_model("rig", rig_fmu_path)
        with EcosSimulation(structure=ss, step_size=H) as sim:
            assert sim.init()
            for k in range(150):
                load = 5e3 if k < 50 else 60e3
                sim.set_real("rig::load", load)
                t = sim.step()
                times.append(t)
                loads.append(load)
                rows.append([float(sim.get_bool("rig::stuck")) if n == "stuck" else sim.get_real(f"rig::{n}")
                             for n in RIG_OUTPUTS])
            sim.terminate()
    r = np.array(rows)
    ref = rig_reference(np.array(times), np.array(loads))
    exp = expected_outputs(ref)
    for i, name in enumerate(RIG_OUTPUTS):
        d = max_relative_difference(r[:, i], exp[name])
        assert d <= 1e-12, f"{name}: relative difference {d:e} to the rig library"
    # The run covers stick and slip.
    assert 0 < r[:, RIG_OUTPUTS.index("stuck")].sum() < len(r)
