"""The fidelity parameters through fmpy: `fidelity` (Integer 0 full, 1 table, 2 boundary,
3 auto), `tolerance` and the envelope. Outputs under table stay within the tolerance of full;
a fallback outside the envelope is logged once; a bad code is refused by name."""

import numpy as np
import pytest
from fmpy import simulate_fmu

from conftest import failed_simulation
from test_simulation import input_signal

NAMES = ["torque", "friction_coefficient", "film_thickness", "fluid_load_fraction"]


def run(fmu_path, **start):
    return simulate_fmu(fmu_path, stop_time=4.0, output_interval=0.005, input=input_signal(),
                        output=["angular_velocity", "load"] + NAMES, start_values=start)


def test_fidelity_is_an_enumeration_parameter(model_description):
    v = {x.name: x for x in model_description.modelVariables}
    # An Enumeration since issue 11 (named choices, the same codes through fmi2SetInteger).
    assert v["fidelity"].type == "Enumeration" and v["fidelity"].causality == "parameter"
    assert [i.name for i in v["fidelity"].declaredType.items] == ["full", "table", "boundary", "auto"]
    assert (v["fidelity"].min, v["fidelity"].max, v["fidelity"].start) == ("0", "3", "0")
    for n in ["tolerance", "envelope.load_min", "envelope.load_max", "envelope.speed_min", "envelope.speed_max"]:
        assert v[n].type == "Real" and v[n].causality == "parameter"


@pytest.mark.parametrize("tol", [1e-3, 1e-4])
def test_table_outputs_stay_within_tolerance_of_full(fmu_path, tol):
    # The input signal sweeps 5 -> 60 kN and speeds up to 80 rad/s: envelope to 10 rad/s (the
    # table reaches beyond its envelope, and from 5 kN at 100 rad/s it would pass the film
    # bound); faster points fall back to the full solve.
    env = {"envelope.load_min": 5e3, "envelope.load_max": 60e3, "envelope.speed_min": 1e-3, "envelope.speed_max": 10.0}
    full = run(fmu_path, fidelity=0, **env)
    table = run(fmu_path, fidelity=1, tolerance=tol, **env)
    w = np.abs(full["angular_velocity"])
    inside = (w >= 1e-3) & (w <= 10.0) & (full["load"] > 0)
    assert inside.sum() > 400
    for n in ["torque", "friction_coefficient", "film_thickness"]:
        a, b = table[n][inside], full[n][inside]
        rel = np.abs(a - b) / np.abs(b)
        assert rel.max() <= tol, f"{n}: {rel.max()} > {tol}"
        assert not np.array_equal(a, b), "table must not be the full solve"
    d = np.abs(table["fluid_load_fraction"] - full["fluid_load_fraction"])[inside]
    assert d.max() <= tol


def test_fallback_outside_the_envelope_is_logged_once(fmu_path):
    messages = []
    simulate_fmu(fmu_path, stop_time=4.0, output_interval=0.005, input=input_signal(),
                 start_values={"fidelity": 1, "tolerance": 1e-3, "envelope.speed_max": 10.0},
                 debug_logging=True, logger=lambda *a: messages.append(a[-1].decode() if isinstance(a[-1], bytes) else str(a[-1])),
                 output=["torque"])
    text = [m for m in messages if "outside the envelope" in m]
    assert len(text) == 1, messages[-5:]
    assert any("fidelity table -> table" in m and "measured error bound" in m for m in messages)


def test_bad_fidelity_code_is_refused_by_name(fmu_path):
    error, messages = failed_simulation(fmu_path, {"fidelity": 7})
    assert "fmi2SetInteger" in error
    assert any("fidelity = 7" in m and "3 (auto)" in m for m in messages), messages
