"""The gear-leg scene as a system description users can open, run by libcosim:

    python examples/gear_leg/run.py osp   # OspSystemStructure.xml (this folder) in libcosim
    python examples/gear_leg/run.py ssp   # writes out/gear_leg/GearLeg.ssp (SSP 1.0) and runs it in libcosim

Both put PinJoint.fmu (FMI 2.0, target/fmu; build it with `cargo run --release -p fmu_build`)
and Leg.fmu (tests/fmu_harness/cosim/leg.py, built here by pythonfmu) beside the description in
out/gear_leg/, run 8 s at 10 ms and print the leg's hold, breakaway and rest. Needs
libcosimpy and pythonfmu (pinned in requirements-test.txt)."""

import os
import shutil
import subprocess
import sys
import zipfile
from xml.sax.saxutils import quoteattr

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(ROOT, "out", "gear_leg")
PIN = os.path.join(ROOT, "target", "fmu", "PinJoint.fmu")
STEP, T_END = 0.01, 8.0
J, T_S = 20.0, 201.6  # kg.m2; N.m, mu_c R P at 60 kN

PIN_PARAMETERS = [("load", "Real", 60000.0), ("zero_velocity.host_inertia", "Real", J),
                  ("zero_velocity.host_coupling", "Integer", 1), ("fidelity_code", "Integer", 0)]
LEG_PARAMETERS = [("inertia", "Real", J), ("drive_hold", "Real", 0.5 * T_S), ("drive_peak", "Real", 1.5 * T_S),
                  ("drive_rest", "Real", 0.3 * T_S), ("t_ramp", "Real", 2.0), ("t_peak", "Real", 4.0), ("t_release", "Real", 4.0)]
CONNECTIONS = [("leg", "angle", "pin", "angle"), ("leg", "angular_velocity", "pin", "angular_velocity"),
               ("pin", "torque", "leg", "torque")]
CONNECTORS = {"pin": [("angle", "input"), ("angular_velocity", "input"), ("torque", "output")],
              "leg": [("torque", "input"), ("angle", "output"), ("angular_velocity", "output")]}


def fmus():
    if not os.path.exists(PIN):
        sys.exit(f"{PIN} is missing: cargo run --release -p fmu_build")
    os.makedirs(OUT, exist_ok=True)
    shutil.copy(PIN, os.path.join(OUT, "PinJoint.fmu"))
    subprocess.run([sys.executable, "-m", "pythonfmu", "build", "-f", os.path.join(ROOT, "tests", "fmu_harness", "cosim", "leg.py"), "-d", OUT],
                   check=True, capture_output=True)


def ssv(name, parameters):
    rows = "\n".join(f'    <ssv:Parameter name={quoteattr(n)}><ssv:{t} value="{v:g}"/></ssv:Parameter>' for n, t, v in parameters)
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<ssv:ParameterSet xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="{name}">
  <ssv:Parameters>
{rows}
  </ssv:Parameters>
</ssv:ParameterSet>
"""


def ssd():
    def component(name, source):
        connectors = "\n".join(f'          <ssd:Connector name="{c}" kind="{k}"><ssc:Real/></ssd:Connector>' for c, k in CONNECTORS[name])
        return f"""      <ssd:Component name="{name}" source="resources/{source}" type="application/x-fmu-sharedlibrary">
        <ssd:Connectors>
{connectors}
        </ssd:Connectors>
        <ssd:ParameterBindings>
          <ssd:ParameterBinding source="resources/{name}.ssv"/>
        </ssd:ParameterBindings>
      </ssd:Component>"""
    connections = "\n".join(f'      <ssd:Connection startElement="{a}" startConnector="{va}" endElement="{b}" endConnector="{vb}"/>'
                            for a, va, b, vb in CONNECTIONS)
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<!-- The gear-leg scene (examples/gear_leg/run.py ssp): PinJoint.fmu on a 20 kg.m2 leg at 60 kN, coupled
     in parallel (zero_velocity.host_coupling = 1, zero_velocity.host_inertia = J). -->
<ssd:SystemStructureDescription xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon"
    xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:osp="http://opensimulationplatform.com/SSP/OSPAnnotations" version="1.0" name="GearLeg">
  <ssd:System name="GearLeg">
    <ssd:Elements>
{component("pin", "PinJoint.fmu")}
{component("leg", "Leg.fmu")}
    </ssd:Elements>
    <ssd:Connections>
{connections}
    </ssd:Connections>
  </ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="{T_END:g}">
    <ssd:Annotations>
      <ssc:Annotation type="com.opensimulationplatform">
        <osp:Algorithm><osp:FixedStepAlgorithm baseStepSize="{STEP:g}"/></osp:Algorithm>
      </ssc:Annotation>
    </ssd:Annotations>
  </ssd:DefaultExperiment>
</ssd:SystemStructureDescription>
"""


def build_ssp():
    path = os.path.join(OUT, "GearLeg.ssp")
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("SystemStructure.ssd", ssd())
        z.writestr("resources/pin.ssv", ssv("pin", PIN_PARAMETERS))
        z.writestr("resources/leg.ssv", ssv("leg", LEG_PARAMETERS))
        z.write(os.path.join(OUT, "PinJoint.fmu"), "resources/PinJoint.fmu")
        z.write(os.path.join(OUT, "Leg.fmu"), "resources/Leg.fmu")
    return path


def run(execution):
    from libcosimpy.CosimObserver import CosimObserver
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    log_output_level(CosimLogLevel.ERROR)
    leg = execution.slave_index_from_instance_name("leg")
    refs = {v.name.decode(): v.reference for v in execution.slave_variables(leg)}
    obs = CosimObserver.create_last_value()
    execution.add_observer(obs)
    rows = []
    for k in range(int(round(T_END / STEP))):
        assert execution.step(), f"step {k}"
        rows.append([(k + 1) * STEP] + obs.last_real_values(leg, [refs["angle"], refs["angular_velocity"]]))
    at = {round(t, 6): (th, w) for t, th, w in rows}
    hold, ramp, rest = at[2.0][0] - at[1.0][0], at[4.0][0] - at[2.0][0], at[T_END][0] - at[6.0][0]
    print(f"hold drift 1-2 s {hold:.2e} rad (held at {at[2.0][0]:.5f} rad); breakaway travel 2-4 s {ramp:.3f} rad; "
          f"rest drift 6-8 s {rest:.2e} rad, speed at 8 s {at[T_END][1]:.1e} rad/s")
    return rows


def main(kind):
    from libcosimpy.CosimExecution import CosimExecution
    fmus()
    if kind == "osp":
        shutil.copy(os.path.join(HERE, "OspSystemStructure.xml"), OUT)
        execution = CosimExecution.from_osp_config_file(osp_path=OUT)
    elif kind == "ssp":
        path = build_ssp()
        print(f"wrote {os.path.relpath(path, ROOT)}")
        execution = CosimExecution.from_ssp_file(ssp_path=path)
    else:
        sys.exit("usage: python examples/gear_leg/run.py osp|ssp")
    return run(execution)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "osp")
