"""fmpy.simulate_fmu against the library: every output at every output point (the band,
zero_velocity.model = 0, whose torque is the library's stateless value), and the default
presliding model against the library in steady sliding."""

import numpy as np
from fmpy import simulate_fmu

from conftest import BAND, OUTPUTS, DEFAULT_BAND, assert_close, expected_torque, failed_simulation, reference

DT = 0.005
# The FMU's default fidelity (full) is the library's complete solve, evaluated cold at every
# call, so its outputs are the library's for the same inputs (issue: to 1e-12 relative).
FULL_ACCURACY = 1e-12


def input_signal(stop=4.0):
    """Sine angular velocity through reversals whose amplitude sweeps the boundary and
    the mixed regimes (0.3 -> 80 rad/s), a load step 5 -> 60 kN at t = 2 s (a ramp
    over one output interval, so that fmpy takes no extra input-event steps)."""
    t = np.arange(0.0, stop + DT / 2, DT / 5)
    amplitude = 0.3 + 80.0 * (t / stop) ** 3
    omega = amplitude * np.sin(2 * np.pi * 1.0 * t)
    load = np.interp(t, [0.0, 2.0, 2.0 + DT, stop], [5e3, 5e3, 60e3, 60e3])
    signal = np.zeros(len(t), dtype=[("time", float), ("angular_velocity", float), ("load", float), ("angle", float)])
    signal["time"], signal["angular_velocity"], signal["load"] = t, omega, load
    signal["angle"] = np.cumsum(omega) * DT / 5
    return signal


def simulate(fmu_path, **kw):
    return simulate_fmu(fmu_path, stop_time=4.0, output_interval=DT, input=input_signal(),
                        output=["angular_velocity", "load", "angle"] + OUTPUTS, **kw)


def check_against_library(r, params=None, band=DEFAULT_BAND):
    load, omega = r["load"], r["angular_velocity"]
    ref = reference(load, omega, params)
    torque = expected_torque(load, omega, band, params)
    assert_close(r["torque"], torque, rel=FULL_ACCURACY, what="torque")
    for name in ("friction_coefficient", "film_thickness", "lambda_ratio", "fluid_load_fraction",
                 "asperity_load_fraction", "mean_pressure", "sommerfeld_number"):
        assert_close(r[name], ref[name], rel=FULL_ACCURACY, what=name)
    assert_close(r["power_loss"], np.abs(torque * omega), what="power_loss")
    # Each recorded row holds the inputs of the step that ended there, so the energy
    # is the running sum of the recorded power times the step.
    h = np.diff(r["time"])
    energy = np.concatenate([[0.0], np.cumsum(r["power_loss"][1:] * h)])
    assert_close(r["dissipated_energy"], energy, rel=1e-12, what="dissipated_energy")
    return ref


def test_outputs_equal_the_library_at_every_output_point(fmu_path):
    r = simulate(fmu_path, start_values=BAND)
    assert len(r) == 801
    omega = r["angular_velocity"]
    ref = check_against_library(r)
    # The signal does what it claims: reversals, points inside the band, both loads,
    # boundary and mixed lubrication.
    assert np.sum(np.diff(np.sign(omega[omega != 0])) != 0) >= 7
    assert np.sum((np.abs(omega) < DEFAULT_BAND) & (omega != 0)) >= 2
    assert set(np.unique(r["load"])) >= {5e3, 60e3}
    assert ref["fluid_load_fraction"].max() > 0.3 and ref["fluid_load_fraction"].min() < 0.01
    # Outside the band the torque is the library's signed torque.
    out = np.abs(omega) >= DEFAULT_BAND
    assert_close(r["torque"][out], ref["signed_torque"][out], rel=FULL_ACCURACY, what="torque outside the band")
    assert np.all(r["torque"][omega > 0] < 0) and np.all(r["torque"][omega < 0] > 0)


def test_start_values_change_parameters(fmu_path):
    params = {"friction.boundary_friction_coefficient": 0.08, "geometry.bush_length": 0.05,
              "lubricant.viscosity": 0.03}
    band = 0.05
    r = simulate(fmu_path, start_values={**params, **BAND, "zero_velocity.speed_band": band})
    check_against_library(r, params, band)
    default = simulate(fmu_path, start_values=BAND)
    assert not np.allclose(r["torque"], default["torque"])
    # The boundary torque follows mu_c: at low speed mu -> 0.08.
    slow = (np.abs(r["angular_velocity"]) > band) & (np.abs(r["angular_velocity"]) < 0.2)
    assert slow.any() and np.all(np.abs(r["friction_coefficient"][slow] - 0.08) < 0.005)


def test_invalid_parameter_fails_initialization_with_its_name(fmu_path):
    error, messages = failed_simulation(fmu_path, {"geometry.bush_radius": 0.027})
    assert "fmi2ExitInitializationMode" in error
    assert any("geometry.bush_radius = 0.027 m must exceed geometry.pin_radius = 0.028 m" in m for m in messages), messages


def test_presliding_default_equals_the_library_in_steady_sliding(fmu_path):
    """The default model (presliding), the state driven by the angle input: the outputs the
    zero-velocity model does not touch equal the library's at every point; the torque never
    exceeds the sliding torque plus the documented damping term t_d T |w| / phi_s; in steady
    sliding (2 degrees of travel since the last reversal or load change, and a step's travel of
    at least 40 (1 - beta) phi_s = 3e-3 rad, over which the state settles on a sliding torque
    that moves with w) the torque is the library's signed torque and power_loss |torque w|."""
    r = simulate(fmu_path)
    load, omega, angle = r["load"], r["angular_velocity"], r["angle"]
    ref = reference(load, omega)
    for name in ("friction_coefficient", "film_thickness", "lambda_ratio", "fluid_load_fraction",
                 "asperity_load_fraction", "mean_pressure", "sommerfeld_number"):
        assert_close(r[name], ref[name], rel=FULL_ACCURACY, what=name)
    t_d, phi_s = 0.01, 1.5e-3
    assert np.all(np.abs(r["torque"]) <= ref["torque"] * (1 + t_d * np.abs(omega) / phi_s) * (1 + 1e-12))
    step = np.abs(np.diff(angle, prepend=angle[0]))
    travel, steady, sign, last_load = 0.0, np.zeros(len(r), bool), 0.0, None
    for k in range(len(r)):
        s = np.sign(omega[k])
        if s != sign or load[k] != last_load:
            travel, sign, last_load = 0.0, s, load[k]
        travel += step[k]
        steady[k] = travel >= np.radians(2.0) and step[k] >= 3e-3
    assert steady.sum() > 400, steady.sum()
    assert_close(r["torque"][steady], ref["signed_torque"][steady], rel=FULL_ACCURACY, what="torque in steady sliding")
    assert_close(r["power_loss"][steady], np.abs(r["torque"] * omega)[steady], rel=FULL_ACCURACY, what="power_loss")
    # The presliding torque is not the band's: at the start, from rest, it differs.
    band = expected_torque(load, omega, DEFAULT_BAND)
    assert not np.allclose(r["torque"][~steady], band[~steady], rtol=1e-6)
