"""Issue 23 item 1 through fmpy: every declared min/max of the PinJoint FMU (FMI 2.0 and 3.0)
and the ends of the temperature input, one at a time, give outputs inside the model's
invariants with the dissipated energy non-decreasing, or a failed simulation whose logged
messages are short and name the quantity. PinJointRig: its declared load/temperature ends,
few cases (the rig is slow)."""

import numpy as np
import pytest
from fmpy import read_model_description, simulate_fmu

from conftest import FMU, TARGET
from rig_support import RIG_FMU

FMI3 = TARGET / "fmu" / "fmi3" / "PinJoint.fmu"
MESSAGE_CHARS = 1000  # pinjoint_numfmt::MESSAGE_CHARS


def declared_ends(path):
    """(name, value) for every Real parameter or input with a declared min or max."""
    md = read_model_description(str(path))
    for v in md.modelVariables:
        if v.type in ("Real", "Float64") and v.causality in ("parameter", "input"):
            for bound in (v.min, v.max):
                if bound is not None:
                    yield v.name, float(bound)


def run(path, start_values):
    messages = []
    try:
        r = simulate_fmu(str(path), stop_time=0.3, output_interval=0.1, start_values=start_values,
                         input=np.array([(0.0, 2e4, 0.3), (0.3, 2e4, 0.3)],
                                        dtype=[("time", float), ("load", float), ("angular_velocity", float)]),
                         logger=lambda *a: messages.append(a[-1].decode() if isinstance(a[-1], bytes) else str(a[-1])))
    except Exception as e:  # noqa: BLE001 - a refused value: its messages are checked
        return None, [str(e)] + messages
    return r, messages


def check(r, params):
    mu_c = params.get("friction.boundary_friction_coefficient", 0.12)
    tau0 = params.get("lubricant.limiting_shear_stress", 2.28e6)
    beta0 = params.get("lubricant.limiting_shear_stress_slope", 0.047)
    radius = params.get("geometry.pin_radius", 28e-3)
    clearance = params.get("geometry.bush_radius", 28.025e-3) - radius
    for name in ("torque", "friction_coefficient", "film_thickness", "lambda_ratio", "fluid_load_fraction",
                 "asperity_load_fraction", "mean_pressure", "dissipated_energy"):
        assert np.all(np.isfinite(r[name])), name
    pm = r["mean_pressure"]
    mu_max = mu_c + (tau0 + beta0 * pm) / pm
    paper = bool(params.get("model.paper", False))
    if not paper:
        # The complete model adds the clearance's torque (an output) and at most the journal's
        # pressure torque (c/2)·P (sin φ ≤ 1, ε ≤ 1) to the paper's bound.
        mu_max = mu_max + np.asarray(r["clearance_torque"]) / (radius * 2e4) + clearance / (2 * radius)
    assert np.all(r["friction_coefficient"] <= mu_max * (1 + 1e-3))
    assert np.all(np.abs(r["torque"]) <= mu_max * (1 + 1e-3) * radius * 2e4)
    for name in ("fluid_load_fraction", "asperity_load_fraction"):
        assert np.all((r[name] >= -1e-3) & (r[name] <= 1 + 1e-3)), name
    if paper:
        assert np.all((r["film_thickness"] <= 2 * clearance * (1 + 1e-12)) | (r["fluid_load_fraction"] < 0.01))
    assert np.all(np.diff(r["dissipated_energy"]) >= 0)


@pytest.mark.parametrize("path", [FMU, FMI3], ids=["fmi2", "fmi3"])
def test_every_declared_end_answers_inside_the_invariants_or_fails_naming_it(path):
    answered = tried = 0
    for name, value in declared_ends(path):
        if name in ("load", "angular_velocity"):
            continue  # the inputs are driven below
        tried += 1
        r, messages = run(path, {name: value})
        if r is None:
            assert any(" = " in m for m in messages), (name, value, messages)
            assert all(len(m) <= MESSAGE_CHARS + 100 for m in messages), (name, value)
            continue
        check(r, {name: value})
        answered += 1
    assert tried > 10 and answered * 2 > tried, (answered, tried)


@pytest.mark.parametrize("path", [FMU, FMI3], ids=["fmi2", "fmi3"])
def test_the_temperature_input_is_declared_233_to_673_k_and_145_k_is_refused(path):
    md = read_model_description(str(path))
    t = next(v for v in md.modelVariables if v.name == "temperature")
    assert (float(t.min), float(t.max)) == (218.15, 673.15)
    for value in (218.15, 673.15):
        r, messages = run(path, {"temperature": value})
        assert r is not None, messages
        check(r, {})
    r, messages = run(path, {"temperature": 145.0})
    assert r is None and any("temperature = 145 K" in m for m in messages), messages


def test_rig_temperature_ends_answer():
    for value in (238.15, 673.15):
        # A logger is passed (fmpy keeps the previous simulation's otherwise: see conftest).
        r = simulate_fmu(str(RIG_FMU), stop_time=0.2, output_interval=1e-2, start_values={"temperature": value},
                         logger=lambda *a: None)
        for name in r.dtype.names:
            assert np.all(np.isfinite(r[name].astype(float))), name
