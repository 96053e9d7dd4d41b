"""One law, every front end: the PinJoint FMU's presliding torque (FMI 2.0 and 3.0
Co-Simulation, driven through fmpy) equals the core library's, bit for bit, on scenes of
holds, breakaways, reversals and hosts that do or do not set the angle. The reference is
examples/presliding_reference.rs (the library's PreslidingJoint stepped as the FMU steps it);
python/tests/test_presliding.py holds the Python package to the same reference."""

import subprocess

import numpy as np
import pytest
from fmpy import read_model_description
from fmpy.fmi2 import FMU2Slave
from fmpy.fmi3 import FMU3Slave

from conftest import FMU, TARGET

PRESLIDING_REFERENCE = TARGET / "release" / "examples" / "presliding_reference"
FMU3 = FMU.parent / "fmi3" / FMU.name


def scene(seed, n=600, sets_angle=True):
    """A host-inertia run's inputs: a body J on the joint under a random drive (hold, ramp
    past breakaway, reversal), integrated by symplectic Euler with the reference's torque;
    rows (angle, angular_velocity, load, step, sets_angle)."""
    rng = np.random.default_rng(seed)
    h = rng.choice([1e-3, 4e-3, 1e-2])
    load = rng.uniform(5e3, 60e3) * rng.choice([1, -1])
    ts = 0.12 * 0.028 * abs(load)
    amplitude = rng.uniform(0.3, 2.5) * ts
    freq = rng.uniform(0.2, 2.0)
    j = rng.uniform(20, 500)
    rows, angle, omega = [], 0.0, 0.0
    for k in range(n):
        t = k * h
        rows.append((float(angle), float(omega), float(load), float(h), 1.0 if sets_angle else 0.0))
        drive = amplitude * np.sin(2 * np.pi * freq * t)
        # The body moves with a stand-in friction (stiff viscous + Coulomb), enough to make
        # the angles and speeds of a real scene; the FMU and the library see the same rows.
        friction = -np.clip(5e3 * omega, -ts, ts)
        omega += h * (drive + friction) / j
        angle += h * omega
    return rows


def reference(rows):
    text = "".join(f"{a!r},{w!r},{p!r},{h!r},{int(s)}\n" for a, w, p, h, s in rows)
    assert PRESLIDING_REFERENCE.is_file(), f"{PRESLIDING_REFERENCE} is missing: cargo build --release -p pinjoint --example presliding_reference"
    out = subprocess.run([str(PRESLIDING_REFERENCE)], input=text, capture_output=True, text=True, check=True).stdout
    return np.array([[float(x) for x in line.split(",")] for line in out.splitlines()])


def run_fmu(path, rows, fmi3):
    md = read_model_description(str(path))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    from fmpy import extract
    unzipped = extract(str(path))
    if fmi3:
        fmu = FMU3Slave(guid=md.guid, unzipDirectory=unzipped, modelIdentifier=md.coSimulation.modelIdentifier, instanceName="agree")
        fmu.instantiate()
        fmu.enterInitializationMode(startTime=0.0)
        fmu.exitInitializationMode()
        set_real, get_real = fmu.setFloat64, fmu.getFloat64
    else:
        fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipped, modelIdentifier=md.coSimulation.modelIdentifier, instanceName="agree")
        fmu.instantiate()
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
        fmu.exitInitializationMode()
        set_real, get_real = fmu.setReal, fmu.getReal
    out, t = [], 0.0
    for angle, omega, load, h, sets in rows:
        names = (["angle"] if sets else []) + ["angular_velocity", "load"]
        values = ([angle] if sets else []) + [omega, load]
        set_real([vr[n] for n in names], values)
        before = get_real([vr["torque"]])[0]
        fmu.doStep(t, h) if not fmi3 else fmu.doStep(currentCommunicationPoint=t, communicationStepSize=h)
        after, tau = get_real([vr["torque"], vr["presliding_torque"]])
        out.append((before, after, tau))
        t += h
    fmu.terminate()
    fmu.freeInstance()
    return np.array(out)


@pytest.mark.parametrize("fmi3", [False, True], ids=["fmi2", "fmi3"])
@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("sets_angle", [True, False], ids=["angle", "velocity"])
def test_the_fmu_steps_the_librarys_law_bit_for_bit(seed, fmi3, sets_angle):
    rows = scene(seed, sets_angle=sets_angle)
    ref = reference(rows)
    got = run_fmu(FMU3 if fmi3 else FMU, rows, fmi3)
    assert got.shape == ref.shape
    # Bit for bit: the same float64 values.
    assert np.array_equal(got.view(np.int64), ref.view(np.int64)), np.argwhere(got != ref)[:5]
    # The scene visits holding, breaking away and sliding: not a trivial pass.
    assert np.ptp(ref[:, 2]) > 0.5 * 0.12 * 0.028 * abs(rows[0][2])
