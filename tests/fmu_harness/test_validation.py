"""The packaged FMU: validation by fmpy, contents, units and documentation."""

import zipfile

from fmpy.validation import validate_fmu

from conftest import OUTPUTS


def test_validate_fmu_reports_no_problem(fmu_path):
    assert validate_fmu(fmu_path) == []


def test_archive_layout(fmu_path):
    names = set(zipfile.ZipFile(fmu_path).namelist())
    assert {"modelDescription.xml", "binaries/linux64/PinJoint.so", "documentation/index.html"} <= names


def test_interface(model_description):
    md = model_description
    assert md.fmiVersion == "2.0" and md.coSimulation.modelIdentifier == "PinJoint"
    assert md.variableNamingConvention == "structured"
    cs = md.coSimulation
    assert cs.canHandleVariableCommunicationStepSize and cs.canGetAndSetFMUstate and cs.canSerializeFMUstate
    v = {x.name: x for x in md.modelVariables}
    assert [n for n in v if v[n].causality == "input"] == ["angle", "angular_velocity", "load", "temperature"]
    assert [n for n in v if v[n].causality == "output"] == OUTPUTS + ["min_film_thickness", "min_lambda_ratio", "clearance_torque", "journal_weight", "eccentricity_ratio", "grease_yield_torque", "validity", "validity_code"]
    params = [n for n in v if v[n].causality == "parameter"]
    # The 26 parameter-file keys, the band, fidelity, tolerance, the 4 envelope bounds, the
    # zero-velocity model, the 3 presliding parameters, the host inertia and the complete
    # model's ten (model.paper, grease.*, grease.supply_layer_inverse and
    # grease.upper_service_temperature among them), the host coupling and the Integer mirrors
    # of fidelity and zero_velocity.model.
    assert len(params) == 51 and "geometry.pin_radius" in params and "zero_velocity.speed_band" in params
    assert {"zero_velocity.model", "zero_velocity.presliding_angle", "zero_velocity.elastic_limit", "zero_velocity.damping_time",
            "zero_velocity.host_inertia", "model.paper", "grease.enabled"} <= set(params)
    assert v["zero_velocity.model"].type == "Enumeration" and int(v["zero_velocity.model"].start) == 1, "presliding by default"
    # One continuous state (Model Exchange) and directional derivatives in both interfaces.
    assert [d.variable.name for d in md.derivatives] == ["der(presliding_torque)"]
    assert md.derivatives[0].variable.derivative.name == "presliding_torque"
    assert cs.providesDirectionalDerivative and md.modelExchange.providesDirectionalDerivative
    assert {"fidelity", "tolerance", "envelope.load_min", "envelope.load_max", "envelope.speed_min", "envelope.speed_max"} <= set(params)
    assert float(v["geometry.pin_radius"].start) == 0.028
    assert float(v["friction.boundary_friction_coefficient"].start) == 0.12
    assert v["torque"].unit == "N.m" and v["load"].unit == "N" and v["angular_velocity"].unit == "rad/s"
    assert all(x.description for x in md.modelVariables)
    display = {d.name for u in md.unitDefinitions for d in u.displayUnits}
    assert {"deg", "rpm", "kN", "MPa", "um"} <= display
    outputs = {u.variable.name: sorted(d.name for d in u.dependencies) for u in md.outputs}
    # The friction outputs depend on the presliding state and (Co-Simulation) the angle.
    assert outputs["torque"] == ["angle", "angular_velocity", "load", "presliding_torque", "temperature"]
    assert outputs["power_loss"] == outputs["torque"]
    derivatives = {u.variable.name: sorted(d.name for d in u.dependencies) for u in md.derivatives}
    assert derivatives["der(presliding_torque)"] == ["angular_velocity", "load", "presliding_torque", "temperature"]
    assert outputs["min_lambda_ratio"] == ["angular_velocity", "load", "temperature"]
    assert outputs["mean_pressure"] == ["load"]
    assert outputs["dissipated_energy"] == []
    assert outputs["validity"] == ["angular_velocity", "load", "temperature"]
    assert v["validity"].type == "Enumeration" and v["validity"].variability == "discrete"
    assert outputs["validity_code"] == outputs["validity"]
    assert v["validity_code"].type == "Integer" and v["validity_code"].variability == "discrete"


def test_documentation_lists_every_variable(fmu_path, model_description):
    html = zipfile.ZipFile(fmu_path).read("documentation/index.html").decode()
    for v in model_description.modelVariables:
        assert f"<code>{v.name}</code>" in html, v.name
    for text in ("Zero velocity", "Validity", "eq. 11", "201.6"):
        assert text in html, text
