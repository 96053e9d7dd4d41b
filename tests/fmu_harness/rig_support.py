"""Helpers of the PinJointRig tests: the FMU's path, the library reference (the
example binary target/release/examples/rig_reference) and a low-level slave.

The FMU is target/fmu/PinJointRig.fmu (or $PINJOINT_RIG_FMU); tests/fmu_harness/run.sh
builds it with `cargo run --release -p fmu_build` and the reference with
`cargo build --release -p pinjoint --example rig_reference`."""

import os
import subprocess
from pathlib import Path

import numpy as np

from conftest import TARGET
from host import Slave

RIG_FMU = Path(os.environ.get("PINJOINT_RIG_FMU", TARGET / "fmu" / "PinJointRig.fmu"))
RIG_REFERENCE = TARGET / "release" / "examples" / "rig_reference"

# The FMU's outputs, in table order, and the library columns they equal.
RIG_OUTPUTS = [
    "angle", "angular_velocity", "torque", "friction_torque", "friction_coefficient",
    "film_thickness", "fluid_load_fraction", "stuck", "commanded_angle",
    "actuator_work", "friction_dissipation", "kinetic_energy",
]
LIBRARY_COLUMN = {name: name for name in RIG_OUTPUTS}
LIBRARY_COLUMN["commanded_angle"] = "command_angle"


def toml_text(params):
    """A parameter file from FMU names: `section.key` and `rig.key` go to their
    sections; the stroke parameters `frequency` and `amplitude` to [rig];
    `rig.formulation`/`rig.method` codes to their TOML names."""
    sections = {}
    names = {"rig.formulation": ["hybrid", "regularised"], "rig.method": ["dopri5", "dop853", "rk4", "dopri5-dense"]}
    for name, value in params.items():
        if name in ("frequency", "amplitude"):
            name = "rig." + name
        section, key = name.split(".")
        text = f'"{names[name][int(value)]}"' if name in names else repr(float(value))
        sections.setdefault(section, []).append(f"{key} = {text}")
    return "".join(f"[{s}]\n" + "\n".join(lines) + "\n" for s, lines in sections.items())


def rig_reference(time, load, command=None, params=None):
    """The rig library driven like the FMU: at each row the inputs held over the step
    that ends there (fmpy records exactly those), full precision."""
    assert RIG_REFERENCE.is_file(), f"{RIG_REFERENCE} is missing: cargo build --release -p pinjoint --example rig_reference"
    args = [str(RIG_REFERENCE)]
    if params:
        path = Path(os.environ.get("TMPDIR", "/tmp")) / f"pinjoint-rig-params-{os.getpid()}.toml"
        path.write_text(toml_text(params))
        args.append(str(path))
    cols = [time, load] + ([command] if command is not None else [])
    text = "".join(",".join(repr(float(x)) for x in row) + "\n" for row in zip(*cols))
    out = subprocess.run(args, input=text, capture_output=True, text=True, check=True).stdout
    return np.genfromtxt(out.splitlines(), delimiter=",", names=True)


def expected_outputs(ref):
    """The FMU's documented outputs from library rows: NaN film quantities at zero
    load (no contact) are reported as 0."""
    exp = {}
    for name in RIG_OUTPUTS:
        v = np.array(ref[LIBRARY_COLUMN[name]], float)
        exp[name] = np.where(ref["load"] > 0, v, 0.0) if name in ("film_thickness", "fluid_load_fraction") else v
    return exp


def max_relative_difference(a, b, floor=1e-300):
    """max |a-b| / max(|b|, floor) over all elements (0 when both are equal)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    d = np.abs(a - b)
    return float(np.max(np.where(d == 0, 0.0, d / np.maximum(np.abs(b), floor)), initial=0.0))


class RigSlave(Slave):
    """The shared host (host.py) for PinJointRig, with its outputs in table order."""

    def __init__(self, unzipped, md, state="step", start_values=None):
        super().__init__(unzipped, md, state, start_values=start_values, instance_name="rig")

    def outputs(self):
        reals = [n for n in RIG_OUTPUTS if n != "stuck"]
        values = dict(zip(reals, self.fmu.getReal([self.vr[n] for n in reals])))
        values["stuck"] = float(self.fmu.getBoolean([self.vr["stuck"]])[0])
        return [values[n] for n in RIG_OUTPUTS]
