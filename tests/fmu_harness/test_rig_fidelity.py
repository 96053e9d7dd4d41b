"""PinJointRig's fidelity parameters through fmpy, as PinJoint's: `fidelity` (Integer 0 full,
1 table, 2 boundary, 3 auto), `tolerance` and the envelope. Three 1 Hz strokes at 20 kN under
table stay within the tolerance of full (torque relative to full's peak torque); auto logs its
pick and the first fallback once; a bad envelope is refused by name, value and unit."""

import numpy as np
import pytest
from fmpy import simulate_fmu

from rig_support import RIG_OUTPUTS


def run(path, **start):
    # No input signal: the load keeps its start value (20 kN) exactly.
    return simulate_fmu(path, stop_time=3.0, output_interval=1e-3, output=RIG_OUTPUTS, start_values=start)


def rel_to_peak(a, b):
    return float(np.max(np.abs(np.asarray(a, float) - b)) / np.max(np.abs(b)))


def test_fidelity_parameters_in_the_model_description(rig_model_description):
    v = {x.name: x for x in rig_model_description.modelVariables}
    # An Enumeration since issue 11 (named choices, the same codes through fmi2SetInteger).
    assert v["fidelity"].type == "Enumeration" and v["fidelity"].causality == "parameter"
    assert [i.name for i in v["fidelity"].declaredType.items] == ["full", "table", "boundary", "auto"]
    assert (v["fidelity"].min, v["fidelity"].max, v["fidelity"].start) == ("0", "3", "0")
    starts = {"tolerance": 1e-4, "envelope.load_min": 5e3, "envelope.load_max": 1e5,
              "envelope.speed_min": 1e-3, "envelope.speed_max": 10.0}
    for n, s in starts.items():
        assert v[n].type == "Real" and v[n].causality == "parameter" and float(v[n].start) == s, n


@pytest.mark.parametrize("tol", [1e-3, 1e-4])
def test_table_stroke_stays_within_tolerance_of_full(rig_fmu_path, tol):
    full = run(rig_fmu_path, fidelity=0)
    table = run(rig_fmu_path, fidelity=1, tolerance=tol, **{"envelope.load_min": 5e3, "envelope.load_max": 1e5,
                                                             "envelope.speed_min": 1e-3, "envelope.speed_max": 10.0})
    assert np.any(full["stuck"]) and not np.all(full["stuck"]), "the run passes reversals and stick phases"
    for name in ["torque", "friction_torque"]:
        e = rel_to_peak(table[name], full[name])
        print(f"tolerance {tol:e}: {name} max |table - full| / peak |full| = {e:.3e}")
        assert e <= tol, f"{name}: {e:e} > {tol:e}"
        assert not np.array_equal(table[name], full[name]), "table must not be the full solve"
    assert rel_to_peak(table["angle"], full["angle"]) <= tol
    d, dref = table["friction_dissipation"][-1], full["friction_dissipation"][-1]
    assert abs(d - dref) <= tol * dref
    # The comparison sees a wrong level: boundary misses the Stribeck fall of mu with speed.
    assert rel_to_peak(run(rig_fmu_path, fidelity=2)["torque"], full["torque"]) > 1e-2


def test_auto_logs_its_pick_and_the_first_fallback_once(rig_fmu_path):
    messages = []
    simulate_fmu(rig_fmu_path, stop_time=2.5, output_interval=1e-3, output=["torque"],
                 start_values={"fidelity": 3, "tolerance": 1e-4}, debug_logging=True,
                 logger=lambda *a: messages.append(a[-1].decode() if isinstance(a[-1], bytes) else str(a[-1])))
    assert any("fidelity auto -> table: measured error bound" in m for m in messages), messages[:8]
    # Reversals pass below envelope.speed_min = 1e-3 rad/s, where the table's low speeds
    # answer, down to rest: no fallback is logged (a load outside the envelope is: the Rust
    # test crates/fmu/tests/rig_fmu_fidelity.rs).
    falls = [m for m in messages if "outside the envelope" in m]
    assert len(falls) == 0, falls


def test_bad_envelope_is_refused_at_initialization_by_name(rig_fmu_path):
    messages = []
    with pytest.raises(Exception) as e:
        simulate_fmu(rig_fmu_path, stop_time=0.1, start_values={"fidelity": 1, "envelope.load_max": 500.0},
                     logger=lambda env, name, status, cat, msg: messages.append(msg.decode()))
    assert "fmi2ExitInitializationMode" in str(e.value)
    assert any("envelope.load_min = 5000 N is invalid: it must be below envelope.load_max = 500 N" in m for m in messages), messages
