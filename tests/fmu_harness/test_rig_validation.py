"""PinJointRig.fmu: validation by fmpy, archive, interface and documentation."""

import zipfile

from fmpy.validation import validate_fmu

from rig_support import RIG_OUTPUTS


def test_validate_fmu_reports_no_problem(rig_fmu_path):
    assert validate_fmu(rig_fmu_path) == []


def test_archive_layout(rig_fmu_path):
    names = set(zipfile.ZipFile(rig_fmu_path).namelist())
    # The host-only build carries linux64; `fmu_build --platforms all` adds win64 and darwin64.
    required = {"modelDescription.xml", "binaries/linux64/PinJointRig.so", "documentation/index.html", "model.png",
                "documentation/licenses/index.html"}
    optional = {"binaries/win64/PinJointRig.dll", "binaries/darwin64/PinJointRig.dylib"}
    assert required <= names
    # Nothing else but the optional platform binaries and the licence notices (issue 11).
    assert all(n.startswith("documentation/licenses/") for n in names - required - optional)


def test_interface(rig_model_description):
    md = rig_model_description
    assert md.fmiVersion == "2.0" and md.coSimulation.modelIdentifier == "PinJointRig"
    cs = md.coSimulation
    assert cs.canHandleVariableCommunicationStepSize and cs.canGetAndSetFMUstate and cs.canSerializeFMUstate
    v = {x.name: x for x in md.modelVariables}
    assert [n for n in v if v[n].causality == "input"] == ["load", "command_angle", "temperature"]
    assert [n for n in v if v[n].causality == "output"] == RIG_OUTPUTS + ["min_film_thickness", "min_lambda_ratio", "validity", "validity_code"]
    assert v["stuck"].type == "Boolean" and v["stuck"].variability == "discrete"
    assert v["use_command_input"].type == "Boolean" and v["use_command_input"].start in ("false", False)
    # Enumerations since issue 11 (same codes as the former Integer parameters).
    assert v["rig.method"].type == "Enumeration" and v["rig.formulation"].type == "Enumeration"
    # Their Integer mirrors (issue 38), for masters without Enumeration support.
    for name in ("rig.method", "rig.formulation", "fidelity", "validity"):
        assert v[name + "_code"].type == "Integer" and v[name + "_code"].causality == v[name].causality
    assert v["amplitude"].unit == "rad" and v["amplitude"].displayUnit == "deg"
    assert abs(float(v["amplitude"].start) - 0.6981317007977318) < 1e-16
    assert v["frequency"].unit == "Hz" and float(v["frequency"].start) == 1.0
    params = [n for n in v if v[n].causality == "parameter"]
    rig = [n for n in params if n.startswith("rig.")]
    # The 14 rig parameters and the Integer mirrors of rig.formulation and rig.method.
    assert len(rig) == 16 and "rig.inertia" in rig and "rig.velocity_gain" in rig
    assert "rig.load" not in rig and "rig.frequency" not in rig
    model = [n for n in params if n.split(".")[0] in ("geometry", "materials", "surface", "lubricant", "friction", "starvation")]
    assert len(model) == 26 and float(v["geometry.pin_radius"].start) == 0.028
    assert v["temperature"].causality == "input" and v["temperature"].unit == "K" and v["temperature"].displayUnit == "degC"
    assert v["torque"].unit == "N.m" and v["load"].unit == "N" and v["angular_velocity"].unit == "rad/s"
    assert v["rig.position_gain"].unit == "N.m/rad" and v["rig.inertia"].unit == "kg.m2"
    assert all(x.description for x in md.modelVariables)
    deps = {u.variable.name: sorted(d.name for d in u.dependencies) for u in md.outputs}
    assert deps["angle"] == [] and deps["torque"] == [] and deps["actuator_work"] == []
    assert deps["friction_torque"] == ["load", "temperature"] and deps["stuck"] == ["load", "temperature"]
    assert deps["commanded_angle"] == ["command_angle"]


def test_documentation_lists_every_variable(rig_fmu_path, rig_model_description):
    html = zipfile.ZipFile(rig_fmu_path).read("documentation/index.html").decode()
    for v in rig_model_description.modelVariables:
        assert f"<code>{v.name}</code>" in html, v.name
    for text in ("Routh", "breakaway", "Defaults and why", "0.05 kg", "tau_s dT_a/dt = T_d - T_a", "67.2"):  # mu_c R P + the grease's yield torque (0.03 N.m) at 20 kN
        assert text in html, text
